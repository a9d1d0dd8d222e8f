//! The whitened QP in `μ` handed to Clarabel, re-solved with points added to the monotonicity grid
//! until `Γ' ≥ ε` holds on the fine check grid (steps 3 and 4 of the method above).

use clarabel::solver::SolverStatus;
use nalgebra::{DMatrix, DVector};

use super::reduce::{Columns, Reduced};
use super::FitError;
use crate::fit::monotonicity::{check_grid, monotonicity_grid};
use crate::fit::qp::{self, Problem};

/// At most this many re-solves with points added to the monotonicity grid.
const REFINEMENT_ROUNDS: usize = 6;

/// A solution of the reduced QP with its multipliers in `μ` space.
pub(super) struct Solved {
    pub(super) mu: DVector<f64>,
    pub(super) grid: Vec<f64>,
    pub(super) lambda: Vec<f64>,
    pub(super) nu: Option<f64>,
    pub(super) status: SolverStatus,
    pub(super) iterations: u32,
    pub(super) solve_time: f64,
    pub(super) rounds: usize,
}

/// Solves the whitened QP, re-solving with the worst points of [`check_grid`] added to the grid
/// while `Γ' < ε` somewhere (at most [`REFINEMENT_ROUNDS`] times).
pub(super) fn solve_refined(
    reduced: &Reduced,
    columns: &Columns<'_>,
    epsilon: f64,
    equality: Option<f64>,
    grid_points: usize,
) -> Result<Solved, FitError> {
    let n = reduced.hessian.ncols();
    let check = check_grid();
    let mut grid = monotonicity_grid(grid_points);
    let (mut iterations, mut solve_time, mut rounds) = (0, 0.0, 0);
    loop {
        // Rows B'(η_q) T, each scaled to unit norm (the right-hand side with it).
        let rows: Vec<DVector<f64>> = grid
            .iter()
            .map(|&eta| reduced.transform.tr_mul(&columns.slopes(eta)))
            .collect();
        let norms: Vec<f64> = rows.iter().map(|r| r.norm()).collect();
        let integral_row = reduced.transform.tr_mul(&columns.integrals());
        let integral_norm = integral_row.norm();
        let problem = Problem {
            p: reduced.hessian.clone(),
            q: vec![0.0; n],
            e_matrix: match equality {
                Some(_) => DMatrix::from_row_slice(1, n, (&integral_row / integral_norm).as_slice()),
                None => DMatrix::zeros(0, n),
            },
            e: equality.map(|mean| mean / integral_norm).into_iter().collect(),
            g_matrix: DMatrix::from_fn(rows.len(), n, |i, j| rows[i][j] / norms[i]),
            g: norms.iter().map(|norm| epsilon / norm).collect(),
        };
        let solution = qp::solve(&problem)?;
        iterations += solution.iterations;
        solve_time += solution.solve_time;
        let mu = &reduced.transform * DVector::from_column_slice(&solution.x);
        let mut violations: Vec<(f64, f64)> = check
            .iter()
            .map(|&eta| (eta, columns.slope(eta, &mu)))
            .filter(|&(_, slope)| slope < epsilon * (1.0 - 1e-3))
            .collect();
        if violations.is_empty() || rounds == REFINEMENT_ROUNDS {
            // Row q was divided by its norm, so its multiplier in μ space is λ_q / norm_q.
            return Ok(Solved {
                mu,
                lambda: solution.lambda.iter().zip(&norms).map(|(l, norm)| l / norm).collect(),
                nu: equality.map(|_| solution.nu[0] / integral_norm),
                grid,
                status: solution.status,
                iterations,
                solve_time,
                rounds,
            });
        }
        violations.sort_by(|a, b| a.1.total_cmp(&b.1));
        grid.extend(violations.iter().take(50).map(|v| v.0));
        rounds += 1;
    }
}
