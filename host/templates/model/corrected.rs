{# The model-corrected map: its schedule and clamp as constants, its three programs written out. #}
/// The model-corrected map's constants as `gen` chose them (f64): `G` (no unit), `K` (states ×
/// outputs, row by row, in state unit per output unit), the schedule `T` (in samples), and each
/// state's clamp (in its unit); units in [`STATE_UNITS`] and [`OUTPUT_UNITS`].
pub const CORRECTED_G: [f64; STATES] = {{ g }};
/// See [`CORRECTED_G`].
pub const CORRECTED_K: [f64; STATES * OUTPUTS] = {{ k }};
/// See [`CORRECTED_G`]: the start-up gain `K₀`.
pub const CORRECTED_K_START: [f64; STATES * OUTPUTS] = {{ k0 }};
/// See [`CORRECTED_G`].
pub const CORRECTED_SCHEDULE: f64 = {{ t }};
/// See [`CORRECTED_G`].
pub const CORRECTED_LOWER: [f64; STATES] = {{ lower_f64 }};
/// See [`CORRECTED_G`].
pub const CORRECTED_UPPER: [f64; STATES] = {{ upper_f64 }};

/// Entries of one row of [`CORRECTED_BLENDS`]: a blend per state, then the gain.
const SCHEDULED: usize = STATES + STATES * OUTPUTS;

/// The model-corrected map's start-up schedule, `j = 1 … J`: the blends
/// `g_j = G + (1 − G) / (1 + j / T)` per state, then the gains `K_j = K + (K₀ − K) / (1 + j / T)`
/// (states × outputs, row by row), each as `(f32, f64)`.
#[rustfmt::skip]
static CORRECTED_BLENDS: [[(f32, f64); SCHEDULED]; {{ start_up }}] = [
{{ blends }}
];

/// The model-corrected map on the chip: `x̂(N−1) = F(Z)`, then
/// `x̂ = clamp(x̄ + g_j ⊙ (F(Z) − x̄) + K_j (y − h(x̄, u)))` with `x̄` the model's prediction, as chosen
/// by `gen` on the tuning runs: `G = {{ g }}`, `K = {{ k }}`, `K₀ = {{ k0 }}` (states × outputs, row by row),
/// `T = {{ t }}`, `J = {{ start_up }}`. The clamp is each state's learning range.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Corrector;

impl<T: Scalar + Maths> firmware::emitted::Follower<T, STATES, OUTPUTS, INPUTS, TARGETS> for Corrector {
    type Carried = [T; STATES];
    const START_UP: usize = {{ start_up }};
    const STEADY_READS_MAP: bool = {{ reads }};
    const STATE_TARGETS: [usize; STATES] = {{ state_targets }};

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
        let states = firmware::emitted::clamp(&raw, &pick(&{{ lower }}), &pick(&{{ upper }}));
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

/// One sampling period of the model from `x`, the value alone: `x⁺`, written out by `gen`.
#[allow(unused_variables, non_snake_case)]
fn corrected_predict<T: Scalar + Maths>(x: &[T; STATES], u: &[T; INPUTS]) -> [T; STATES] {
{{ predict_body }}}

/// The correction during the start-up, `g` = (blend `g_j`, gain `K_j`) given: `x̂` before its clamp, written out by `gen`.
#[allow(unused_variables, non_snake_case)]
fn corrected_start_up<T: Scalar + Maths>(x: &[T; STATES], y: &[T; OUTPUTS], u: &[T; INPUTS], f: &[T; STATES], g: &[(f32, f64); SCHEDULED]) -> [T; STATES] {
{{ start_up_body }}}

/// The correction after the start-up (`G` as numbers): `x̂` before its clamp, written out by `gen`.
#[allow(unused_variables, non_snake_case)]
fn corrected_steady<T: Scalar + Maths>(x: &[T; STATES], y: &[T; OUTPUTS], u: &[T; INPUTS], f: &[T; STATES]) -> [T; STATES] {
{{ steady_body }}}

