//! The model-corrected map (`Corrector`, `CorrectedObserver`, kind `corrected`): its schedule and
//! clamp as constants, its programs written out.

use std::fmt::Write;

use super::rust_text::{body, list};
use crate::emit::{f32_literal, EmitError};
use crate::plant::correction::{self, CorrectionConstants};
use crate::plant::ModelCode;
use crate::spec::Design;

/// The model-corrected map's follower (`Corrector`), its programs and `CorrectedObserver`.
pub(super) fn corrector(
    design: &Design,
    code: &ModelCode,
    constants: &CorrectionConstants,
    state_targets: &[usize],
) -> Result<String, EmitError> {
    let programs = correction::correction_code(code, constants);
    let pairs = |what: &str, values: &[f64]| -> Result<String, EmitError> {
        let entries = values
            .iter()
            .enumerate()
            .map(|(i, v)| Ok(format!("({}, {v:?})", f32_literal(&format!("{what}[{i}]"), *v)?)))
            .collect::<Result<Vec<_>, EmitError>>()?;
        Ok(list(&entries))
    };
    let blends = constants
        .blends()
        .iter()
        .enumerate()
        .map(|(j, row)| pairs(&format!("corrected start-up blend {}", j + 1), row).map(|r| format!("    {r},")))
        .collect::<Result<Vec<_>, _>>()?;
    let mut text = CORRECTED_TEMPLATE
        .replace("{START_UP}", &constants.start_up.to_string())
        .replace("{READS}", &programs.steady_reads_map.to_string())
        .replace("{STATE_TARGETS}", &format!("{state_targets:?}"))
        .replace("{BLENDS}", &blends.join("\n"))
        .replace("{LOWER}", &pairs("corrected lower", &constants.lower)?)
        .replace("{UPPER}", &pairs("corrected upper", &constants.upper)?)
        .replace("{G}", &format!("{:?}", constants.g))
        .replace("{K}", &format!("{:?}", constants.k))
        .replace("{K0}", &format!("{:?}", constants.k_start))
        .replace("{T}", &format!("{:?}", constants.schedule))
        .replace("{LOWER_F64}", &format!("{:?}", constants.lower))
        .replace("{UPPER_F64}", &format!("{:?}", constants.upper));
    let w = &mut text;
    writeln!(
        w,
        "\n/// One sampling period of the model from `x`, the value alone: `x⁺`, written out by `gen`."
    )
    .ok();
    writeln!(w, "#[allow(unused_variables, non_snake_case)]").ok();
    writeln!(
        w,
        "fn corrected_predict<T: Scalar + Maths>(x: &[T; STATES], u: &[T; INPUTS]) -> [T; STATES] {{"
    )
    .ok();
    w.push_str(&body(&programs.predict, code, design, "    ", list)?);
    writeln!(w, "}}\n").ok();
    writeln!(
        w,
        "/// The correction during the start-up, `g` = (blend `g_j`, gain `K_j`) given: `x̂` before its clamp, written out by `gen`."
    )
    .ok();
    writeln!(w, "#[allow(unused_variables, non_snake_case)]").ok();
    writeln!(
        w,
        "fn corrected_start_up<T: Scalar + Maths>(x: &[T; STATES], y: &[T; OUTPUTS], u: &[T; INPUTS], f: &[T; STATES], g: &[(f32, f64); SCHEDULED]) -> [T; STATES] {{"
    )
    .ok();
    w.push_str(&body(&programs.start_up, code, design, "    ", list)?);
    writeln!(w, "}}\n").ok();
    writeln!(
        w,
        "/// The correction after the start-up (`G` as numbers): `x̂` before its clamp, written out by `gen`."
    )
    .ok();
    writeln!(w, "#[allow(unused_variables, non_snake_case)]").ok();
    writeln!(
        w,
        "fn corrected_steady<T: Scalar + Maths>(x: &[T; STATES], y: &[T; OUTPUTS], u: &[T; INPUTS], f: &[T; STATES]) -> [T; STATES] {{"
    )
    .ok();
    w.push_str(&body(&programs.steady, code, design, "    ", list)?);
    writeln!(w, "}}").ok();
    Ok(text)
}

/// The model-corrected map around its written-out programs (`{…}` filled in by [`corrector`]).
const CORRECTED_TEMPLATE: &str = r#"
/// The model-corrected map's constants as `gen` chose them (f64): `G` (no unit), `K` (states ×
/// outputs, row by row, in state unit per output unit), the schedule `T` (in samples), and each
/// state's clamp (in its unit); units in [`STATE_UNITS`] and [`OUTPUT_UNITS`].
pub const CORRECTED_G: [f64; STATES] = {G};
/// See [`CORRECTED_G`].
pub const CORRECTED_K: [f64; STATES * OUTPUTS] = {K};
/// See [`CORRECTED_G`]: the start-up gain `K₀`.
pub const CORRECTED_K_START: [f64; STATES * OUTPUTS] = {K0};
/// See [`CORRECTED_G`].
pub const CORRECTED_SCHEDULE: f64 = {T};
/// See [`CORRECTED_G`].
pub const CORRECTED_LOWER: [f64; STATES] = {LOWER_F64};
/// See [`CORRECTED_G`].
pub const CORRECTED_UPPER: [f64; STATES] = {UPPER_F64};

/// Entries of one row of [`CORRECTED_BLENDS`]: a blend per state, then the gain.
const SCHEDULED: usize = STATES + STATES * OUTPUTS;

/// The model-corrected map's start-up schedule, `j = 1 … J`: the blends
/// `g_j = G + (1 − G) / (1 + j / T)` per state, then the gains `K_j = K + (K₀ − K) / (1 + j / T)`
/// (states × outputs, row by row), each as `(f32, f64)`.
#[rustfmt::skip]
static CORRECTED_BLENDS: [[(f32, f64); SCHEDULED]; {START_UP}] = [
{BLENDS}
];

/// The model-corrected map on the chip: `x̂(N−1) = F(Z)`, then
/// `x̂ = clamp(x̄ + g_j ⊙ (F(Z) − x̄) + K_j (y − h(x̄, u)))` with `x̄` the model's prediction, as chosen
/// by `gen` on the tuning runs: `G = {G}`, `K = {K}`, `K₀ = {K0}` (states × outputs, row by row),
/// `T = {T}`, `J = {START_UP}`. The clamp is each state's learning range.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Corrector;

impl<T: Scalar + Maths> firmware::emitted::Follower<T, STATES, OUTPUTS, INPUTS, TARGETS> for Corrector {
    type Carried = [T; STATES];
    const START_UP: usize = {START_UP};
    const STEADY_READS_MAP: bool = {READS};
    const STATE_TARGETS: [usize; STATES] = {STATE_TARGETS};

    #[inline(always)]
    fn start(first: &[T; STATES], u: &[T; INPUTS]) -> Option<[T; STATES]> {
        let next = corrected_predict(first, u);
        next.iter().all(|v| v.is_finite()).then_some(next)
    }

    #[inline(always)]
    fn follow(
        x: &[T; STATES],
        j: usize,
        start_up: bool,
        f: &[T; STATES],
        y: &[T; OUTPUTS],
        u: &[T; INPUTS],
    ) -> Option<([T; STATES], [Estimate<T>; STATES])> {
        // Loops rather than `array::map`, which the compiler turns into copies at `opt-level = "s"`.
        fn pick<T: Scalar, const M: usize>(pairs: &[(f32, f64); M]) -> [T; M] {
            let mut out = [T::ZERO; M];
            for (out, &(single, double)) in out.iter_mut().zip(pairs) {
                *out = T::literal(single, double);
            }
            out
        }
        let raw = if start_up {
            let row = CORRECTED_BLENDS.get(j.wrapping_sub(1)).unwrap_or(&[(0.0, 0.0); SCHEDULED]);
            corrected_start_up(x, y, u, f, row)
        } else {
            corrected_steady(x, y, u, f)
        };
        let states = firmware::emitted::clamp(&raw, &pick(&{LOWER}), &pick(&{UPPER}));
        let mut estimate = [T::ZERO; STATES];
        for (e, s) in estimate.iter_mut().zip(&states) {
            *e = s.value;
        }
        let next = corrected_predict(&estimate, u);
        next.iter().all(|v| v.is_finite()).then_some((next, states))
    }

    /// A lost output: the model's period from `x̄` (no correction; the next estimate is clamped).
    #[inline(always)]
    fn predict(x: &[T; STATES], u: &[T; INPUTS]) -> Option<[T; STATES]> {
        let next = corrected_predict(x, u);
        next.iter().all(|v| v.is_finite()).then_some(next)
    }

    #[inline(always)]
    fn targets(x: &[T; STATES], u: &[T; INPUTS]) -> [T; TARGETS] {
        targets(x, u)
    }
}

/// The model-corrected map over this design's map.
pub type CorrectedObserver = firmware::Started<f32, Design, Corrector, HORIZON, STATES, OUTPUTS, INPUTS, TARGETS>;
"#;
