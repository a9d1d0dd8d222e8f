//! One window's moving-horizon problem solved to convergence: a projected Levenberg–Marquardt over
//! the firmware's Gauss–Newton normal equations ([`firmware::mhe`]).
//!
//! No maintained Rust crate fits: `levenberg-marquardt` (nalgebra) has no bounds, argmin's
//! Gauss–Newton has neither bounds nor damping, and both would rebuild the window's Jacobian through
//! their own traits where the firmware already computes it (the sensitivities `Φ(j)` carried along
//! the window). The method is the textbook one (Nocedal & Wright, *Numerical Optimization*, §10.3,
//! with the bounds handled as in Kelley's projected Newton, *Iterative Methods for Optimization*,
//! §5.5): each iteration
//!
//! ```text
//! freeze every coordinate at a bound whose Gauss–Newton direction points out of the box
//! (A + λ diag(A)) δ = g     on the free coordinates (A, g: the normal equations with the prior)
//! x' = Π(x + δ)             (Π: projection onto the box)
//! accept if C(x') < C(x) (λ ← λ/3), else λ ← 4λ and retry
//! ```
//!
//! until the accepted decrease is below `1e-12 (1 + C)` or every step coordinate is below `1e-10` of
//! its state's spread, or after [`MAX_ITERATIONS`] iterations.

use firmware::emitted::mhe::{normal_equations, solve_cholesky, Normal};
use firmware::Plant;

/// Most iterations (trials, accepted or not) per window.
pub const MAX_ITERATIONS: usize = 100;

/// The box, the output weights and the prior of one window's problem.
pub struct Problem<'a, const NX: usize, const NY: usize> {
    /// Lower bound of each state.
    pub lower: [f64; NX],
    /// Upper bound of each state.
    pub upper: [f64; NX],
    /// `1 / σ²` per output.
    pub weights: [f64; NY],
    /// Each state's spread: the scale of the step test.
    pub spreads: &'a [f64],
    /// `(x̄, p)`: the prior's centre and weight per state, if any.
    pub prior: Option<([f64; NX], [f64; NX])>,
}

/// A window's solution.
#[derive(Clone, Copy, Debug)]
pub struct Solution<const NX: usize> {
    /// The state at the window's start.
    pub start: [f64; NX],
    /// The state at the window's end (the estimate).
    pub end: [f64; NX],
    /// The cost there (output error and prior).
    pub cost: f64,
    /// Iterations taken.
    pub iterations: usize,
}

/// The normal equations at `x` with the prior added: `C += Σ p (x − x̄)²`, `A += diag(p)`,
/// `g −= p (x − x̄)`.
fn evaluate<P, const NX: usize, const NY: usize, const NU: usize>(
    plant: &P,
    problem: &Problem<'_, NX, NY>,
    samples: &[([f64; NY], [f64; NU])],
    x: &[f64; NX],
) -> Normal<f64, NX>
where
    P: Plant<f64, NX, NY, NU>,
{
    let mut normal = normal_equations(plant, x, samples.iter().map(|(y, u)| (y, u)), &problem.weights);
    if let Some((centre, weight)) = &problem.prior {
        for i in 0..NX {
            let d = x[i] - centre[i];
            normal.cost += weight[i] * d * d;
            normal.matrix[i][i] += weight[i];
            normal.gradient[i] -= weight[i] * d;
        }
    }
    normal
}

/// The minimiser from `start` (projected onto the box first) of the window `samples` (oldest first).
pub fn minimise<P, const NX: usize, const NY: usize, const NU: usize>(
    plant: &P,
    problem: &Problem<'_, NX, NY>,
    samples: &[([f64; NY], [f64; NU])],
    start: &[f64; NX],
) -> Solution<NX>
where
    P: Plant<f64, NX, NY, NU>,
{
    let project = |x: &[f64; NX]| firmware::emitted::project(x, &problem.lower, &problem.upper);
    let mut x = project(start);
    let mut at = evaluate(plant, problem, samples, &x);
    let mut damping = 1e-3;
    let mut iterations = 0;
    while iterations < MAX_ITERATIONS && at.cost.is_finite() {
        iterations += 1;
        let mut matrix = at.matrix;
        let mut gradient = at.gradient;
        for i in 0..NX {
            let outward =
                (x[i] <= problem.lower[i] && gradient[i] < 0.0) || (x[i] >= problem.upper[i] && gradient[i] > 0.0);
            if outward {
                matrix[i] = [0.0; NX];
                matrix.iter_mut().for_each(|row| row[i] = 0.0);
                matrix[i][i] = 1.0;
                gradient[i] = 0.0;
            } else {
                // Marquardt's scaling, kept positive where a state does not reach the outputs.
                matrix[i][i] += damping * matrix[i][i].max(1e-12);
            }
        }
        let Some(step) = solve_cholesky(&matrix, &gradient) else {
            damping *= 10.0;
            if damping > 1e12 {
                break;
            }
            continue;
        };
        let next = project(&std::array::from_fn(|i| x[i] + step[i]));
        let tried = evaluate(plant, problem, samples, &next);
        if tried.cost < at.cost {
            let decrease = at.cost - tried.cost;
            let small = (0..NX).all(|i| (next[i] - x[i]).abs() <= 1e-10 * problem.spreads[i]);
            x = next;
            at = tried;
            damping = (damping / 3.0).max(1e-12);
            if decrease <= 1e-12 * (1.0 + at.cost) || small {
                break;
            }
        } else {
            damping *= 4.0;
            if damping > 1e12 {
                break; // no descent left at any damping: a minimum to rounding
            }
        }
    }
    Solution {
        start: x,
        end: at.end,
        cost: at.cost,
        iterations,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Example 1's Van der Pol oscillator, one RK4 step of τ = 0.1 written out here (not the host's
    /// programs), `y = x₁ + x₂`.
    struct VanDerPol;

    fn field(x: [f64; 2]) -> [f64; 2] {
        [-x[1], 4.0 * x[0] + (1.0 - x[0] * x[0]) * x[1]]
    }

    fn rk4(x: [f64; 2]) -> [f64; 2] {
        let h = 0.1;
        let add = |a: [f64; 2], b: [f64; 2], s: f64| [a[0] + s * b[0], a[1] + s * b[1]];
        let k1 = field(x);
        let k2 = field(add(x, k1, h / 2.0));
        let k3 = field(add(x, k2, h / 2.0));
        let k4 = field(add(x, k3, h));
        std::array::from_fn(|i| x[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
    }

    impl Plant<f64, 2, 1, 0> for VanDerPol {
        fn step(&self, x: &[f64; 2], _: &[f64; 0]) -> ([f64; 2], [[f64; 2]; 2]) {
            // The Jacobian by central differences: the minimiser is checked, not the derivatives.
            let e = 1e-7;
            let mut jacobian = [[0.0; 2]; 2];
            for c in 0..2 {
                let (mut up, mut down) = (*x, *x);
                up[c] += e;
                down[c] -= e;
                let (a, b) = (rk4(up), rk4(down));
                for r in 0..2 {
                    jacobian[r][c] = (a[r] - b[r]) / (2.0 * e);
                }
            }
            (rk4(*x), jacobian)
        }
        fn output(&self, x: &[f64; 2], _: &[f64; 0]) -> ([f64; 1], [[f64; 2]; 1]) {
            ([x[0] + x[1]], [[1.0, 1.0]])
        }
    }

    /// A noisy window of `N = 10` from `truth` (noise of variance 0.2, seeded).
    fn window(truth: [f64; 2], seed: u64) -> Vec<([f64; 1], [f64; 0])> {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let mut x = truth;
        (0..10)
            .map(|_| {
                let noise: f64 = rng.sample(rand_distr::StandardNormal);
                let y = x[0] + x[1] + 0.2_f64.sqrt() * noise;
                x = rk4(x);
                ([y], [])
            })
            .collect()
    }

    fn problem(prior: Option<([f64; 2], [f64; 2])>) -> Problem<'static, 2, 1> {
        Problem {
            lower: [-2.0, -5.0],
            upper: [2.0, 5.0],
            weights: [1.0 / 0.2],
            spreads: &[4.0, 10.0],
            prior,
        }
    }

    /// The smallest cost on a grid of `points²` over the box, refined by a second grid around it.
    fn grid_minimum(problem: &Problem<'_, 2, 1>, samples: &[([f64; 1], [f64; 0])]) -> ([f64; 2], f64) {
        let cost = |x: [f64; 2]| evaluate(&VanDerPol, problem, samples, &x).cost;
        let mut best = ([0.0, 0.0], f64::INFINITY);
        let search = |lower: [f64; 2], upper: [f64; 2], points: usize, best: &mut ([f64; 2], f64)| {
            for a in 0..points {
                for b in 0..points {
                    let x = [
                        lower[0] + (upper[0] - lower[0]) * a as f64 / (points - 1) as f64,
                        lower[1] + (upper[1] - lower[1]) * b as f64 / (points - 1) as f64,
                    ];
                    let c = cost(x);
                    if c < best.1 {
                        *best = (x, c);
                    }
                }
            }
        };
        search(problem.lower, problem.upper, 401, &mut best);
        let (centre, cell) = (best.0, [4.0 / 400.0, 10.0 / 400.0]);
        let lower = std::array::from_fn(|i| (centre[i] - cell[i]).max(problem.lower[i]));
        let upper = std::array::from_fn(|i| (centre[i] + cell[i]).min(problem.upper[i]));
        search(lower, upper, 201, &mut best);
        best
    }

    #[test]
    fn the_best_of_the_starts_is_a_dense_grid_search_s_minimum() {
        // Several windows, some with the minimum on a bound: the solver's best of a few starts against a
        // 401² grid over the box refined by a 201² grid around its best cell.
        let starts = [[0.0, 0.0], [-1.0, -2.5], [1.0, -2.5], [-1.0, 2.5], [1.0, 2.5]];
        let problem = problem(None);
        for (seed, truth) in [(1, [1.5, 0.5]), (2, [-0.3, 4.6]), (3, [1.95, -4.9]), (4, [-1.2, -1.0])] {
            let samples = window(truth, seed);
            let solved = starts
                .iter()
                .map(|s| minimise(&VanDerPol, &problem, &samples, s))
                .min_by(|a, b| a.cost.total_cmp(&b.cost))
                .unwrap();
            let (grid, grid_cost) = grid_minimum(&problem, &samples);
            assert!(
                solved.cost <= grid_cost + 1e-9,
                "{seed}: {} > grid {grid_cost}",
                solved.cost
            );
            for i in 0..2 {
                assert!(
                    (solved.start[i] - grid[i]).abs() < 0.01 * problem.spreads[i],
                    "{seed}: {:?} vs grid {grid:?}",
                    solved.start
                );
                assert!(solved.start[i] >= problem.lower[i] && solved.start[i] <= problem.upper[i]);
            }
            assert!(solved.iterations < MAX_ITERATIONS, "{seed}: did not converge");
        }
    }

    #[test]
    fn a_heavy_prior_holds_the_solution_at_its_centre_and_a_light_one_does_not() {
        let samples = window([0.5, 1.0], 5);
        let free = minimise(&VanDerPol, &problem(None), &samples, &[0.0, 0.0]);
        let centre = [-1.0, 2.0];
        let heavy = minimise(&VanDerPol, &problem(Some((centre, [1e9, 1e9]))), &samples, &[0.0, 0.0]);
        let light = minimise(
            &VanDerPol,
            &problem(Some((centre, [1e-9, 1e-9]))),
            &samples,
            &[0.0, 0.0],
        );
        for (i, centre) in centre.iter().enumerate() {
            assert!((heavy.start[i] - centre).abs() < 1e-6, "{heavy:?}");
            assert!((light.start[i] - free.start[i]).abs() < 1e-5, "{light:?} vs {free:?}");
        }
        assert!(
            (free.start[0] - centre[0]).abs() > 0.1,
            "the test shows nothing: {free:?}"
        );
    }
}
