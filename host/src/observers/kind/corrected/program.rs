//! The model-corrected map's sample written out (`crate::observers::kind::corrected::run` says what it
//! estimates and how it is tuned): straight-line programs over the emitted model, so that the chip
//! runs no loop and no multiplication by a zero gain.
//!
//! ```text
//! predict   (x, u)          → x⁺ = f(x, u)                       one sampling period, RK4
//! start_up  (x̄, y, u, F, g) → x̄ + g ⊙ (F − x̄) + K_j (y − h(x̄, u))  the blend g_j, K_j given
//! steady    (x̄, y, u, F)    → x̄ + G ⊙ (F − x̄) + K (y − h(x̄, u))  G a number: F is not read where G = 0
//! ```
//!
//! The firmware's `firmware::Started` clamps the corrected state to the map's range and predicts from
//! it; [`CorrectionCode::run`] does the same on the host, in the same order, so that the host's
//! estimates are the chip's.

use firmware::emitted::Maths;
use firmware::Scalar;

use crate::spec::ast::Binary;

use crate::plant::program::{Builder, Leaf, Names, Program};
use crate::plant::ModelCode;

/// The corrected observer's constants, chosen on the tuning runs.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct CorrectionConstants {
    /// `G`, per state: the blend after the start-up, in `[0, 1]`.
    pub g: Vec<f64>,
    /// `K`, states × outputs, row by row: the innovation gain after the start-up.
    pub k: Vec<f64>,
    /// `K₀`, the same shape: the start-up gain `K_j = K + (K₀ − K) / (1 + j / T)` falls from it to `K`
    /// on the blend's schedule (`K₀ = K` keeps the gain constant).
    pub k_start: Vec<f64>,
    /// `T > 0`: the start-up blend `g_j = G + (1 − G) / (1 + j / T)` falls from 1 (the map's first
    /// estimate, `j = 0`) towards `G` with this time constant, in estimates.
    pub schedule: f64,
    /// `J`: estimates `j = 1 … J` take the start-up blend; from `J + 1` on it is `G`.
    pub start_up: usize,
    /// The clamp of each state: the range of its map (learning data).
    pub lower: Vec<f64>,
    /// See [`CorrectionConstants::lower`].
    pub upper: Vec<f64>,
    /// RK4 substeps per sample on the chip.
    pub substeps: usize,
    /// Width of one substep, `τ / substeps`.
    pub h: f64,
}

impl CorrectionConstants {
    /// The start-up table, `J` rows: row `j − 1` is `g_j` (one per state), then `K_j` (states ×
    /// outputs, row by row); the chip reads them from a table: no division.
    pub fn blends(&self) -> Vec<Vec<f64>> {
        (1..=self.start_up)
            .map(|j| {
                let fall = 1.0 / (1.0 + j as f64 / self.schedule);
                self.g
                    .iter()
                    .map(|g| g + (1.0 - g) * fall)
                    .chain(self.k.iter().zip(&self.k_start).map(|(k, k0)| k + (k0 - k) * fall))
                    .collect()
            })
            .collect()
    }
}

/// The three programs.
#[derive(Clone, Debug)]
pub struct CorrectionCode {
    /// `x⁺` from `x` (leaves `State`, `Input`).
    pub predict: Program,
    /// `x̂` from `x̄` (`State`), `y`, `u`, the map's states (`Map`) and the blend (`Blend`).
    pub start_up: Program,
    /// `x̂` from `x̄`, `y`, `u` and the map's states where `G ≠ 0`.
    pub steady: Program,
    /// Whether [`CorrectionCode::steady`] reads the map (some `G ≠ 0`): if not, the map is not
    /// evaluated after the start-up.
    pub steady_reads_map: bool,
    /// The model's parameters, as the programs read them.
    pub parameters: Vec<(String, f64)>,
}

/// The values a program reads: `x` the state leaves, then the correction's.
pub struct Reading<'a, T> {
    /// `State`.
    pub x: &'a [T],
    /// `Input`.
    pub u: &'a [T],
    /// `Measurement` (empty for `predict`).
    pub y: &'a [T],
    /// `Map` (empty for `predict`).
    pub map: &'a [T],
    /// `Blend` (empty but for `start_up`).
    pub blend: &'a [T],
}

impl CorrectionCode {
    /// Evaluates `program` (one of the three) in `T` exactly as the emitted code does.
    pub fn run<T: Scalar + Maths>(&self, program: &Program, at: &Reading<'_, T>, scratch: &mut Vec<T>) -> Vec<T> {
        program.eval_with(&self.parameters, scratch, |leaf| match leaf {
            Leaf::State(i) => at.x[i],
            Leaf::Input(i) => at.u[i],
            Leaf::Measurement(i) => at.y[i],
            Leaf::Map(i) => at.map[i],
            Leaf::Blend(i) => at.blend[i],
            // Parameters are the program's constants; no covariance is read.
            Leaf::Parameter(_) | Leaf::Covariance(_) => T::literal(f32::NAN, f64::NAN),
        })
    }
}

/// Writes the corrected observer of `code` with `constants` as programs.
#[allow(clippy::needless_range_loop)] // the index runs over several parallel sequences
pub fn correction_code(code: &ModelCode, constants: &CorrectionConstants) -> CorrectionCode {
    let (nx, ny) = (code.dimensions.states, code.dimensions.outputs);
    let values = |program: &Program, n: usize| {
        let mut program = program.clone();
        program.results.truncate(n);
        program.prune();
        program
    };
    let derivative = values(&code.derivative, nx);
    let output = values(&code.output, ny);
    let builder = || {
        Builder::new(Names {
            parameters: &code.parameters,
            states: &[],
            inputs: &[],
        })
    };
    let finish = |b: Builder<'_>| {
        let mut program = b.finish();
        program.prune();
        program
    };

    let mut b = builder();
    let mut x: Vec<usize> = (0..nx).map(|i| b.leaf(Leaf::State(i))).collect();
    for _ in 0..constants.substeps {
        x = substep(&mut b, &derivative, constants.h, &x);
    }
    for e in x {
        b.result(e);
    }
    let predict = finish(b);

    let correct = |blend: &dyn Fn(&mut Builder<'_>, usize) -> usize,
                   gain: &dyn Fn(&mut Builder<'_>, usize) -> usize| {
        let mut b = builder();
        let x: Vec<usize> = (0..nx).map(|i| b.leaf(Leaf::State(i))).collect();
        let h = b.inline(&output, &x);
        let innovations: Vec<usize> = (0..ny)
            .map(|o| {
                let y = b.leaf(Leaf::Measurement(o));
                b.sub(y, h[o])
            })
            .collect();
        for i in 0..nx {
            let g = blend(&mut b, i);
            let map = b.leaf(Leaf::Map(i));
            let towards = b.sub(map, x[i]);
            let moved = b.mul(g, towards);
            let blended = b.add(x[i], moved);
            let gains: Vec<usize> = (0..ny).map(|o| gain(&mut b, i * ny + o)).collect();
            let corrected = b.dot(blended, &gains, &innovations);
            b.result(corrected);
        }
        finish(b)
    };
    let start_up = correct(&|b, i| b.leaf(Leaf::Blend(i)), &|b, e| b.leaf(Leaf::Blend(nx + e)));
    let steady = correct(&|b, i| b.number(constants.g[i]), &|b, e| b.number(constants.k[e]));
    CorrectionCode {
        steady_reads_map: steady
            .ops
            .iter()
            .any(|op| matches!(op, crate::plant::Op::Leaf(Leaf::Map(_)))),
        predict,
        start_up,
        steady,
        parameters: code.parameters.clone(),
    }
}

/// One RK4 step of width `h` of the value-only `derivative` (the value path of `firmware::Rk4`).
fn substep(b: &mut Builder<'_>, derivative: &Program, h: f64, x: &[usize]) -> Vec<usize> {
    // The library's `h / 2` and `h / 6`, computed in the observer's precision.
    let width = b.number(h);
    let (two, six) = (b.number(2.0), b.number(6.0));
    let half = b.unfolded(Binary::Div, width, two);
    let sixth = b.unfolded(Binary::Div, width, six);
    let stage = |b: &mut Builder<'_>, k: &[usize], w: usize| {
        let point: Vec<usize> = x
            .iter()
            .zip(k)
            .map(|(&x, &k)| {
                let moved = b.mul(w, k);
                b.add(x, moved)
            })
            .collect();
        b.inline(derivative, &point)
    };
    let k1 = b.inline(derivative, x);
    let k2 = stage(b, &k1, half);
    let k3 = stage(b, &k2, half);
    let k4 = stage(b, &k3, width);
    (0..x.len())
        .map(|i| {
            let middle = b.add(k2[i], k3[i]);
            let doubled = b.mul(two, middle);
            let sum = b.add(k1[i], doubled);
            let sum = b.add(sum, k4[i]);
            let scaled = b.mul(sixth, sum);
            b.add(x[i], scaled)
        })
        .collect()
}
