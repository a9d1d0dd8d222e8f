//! A small dense convex QP, solved by Clarabel:
//!
//! ```text
//! minimise ½ xᵀ P x + qᵀ x   subject to   E x = e,   G x ≥ g.
//! ```
//!
//! The solution carries the multipliers in the convention `P x + q = Eᵀ ν + Gᵀ λ`, `λ ≥ 0`,
//! `λ ⊙ (G x - g) = 0`, which is what the KKT checks of `identify` use.

use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettingsBuilder, DefaultSettingsBuilderError, DefaultSolver, IPSolver, SolverError, SolverStatus,
    SupportedConeT,
};
use nalgebra::DMatrix;

/// The problem data (dense; `P` symmetric positive semidefinite).
pub struct Problem {
    /// `P`.
    pub p: DMatrix<f64>,
    /// `q`.
    pub q: Vec<f64>,
    /// `E` (may have no rows).
    pub e_matrix: DMatrix<f64>,
    /// `e`.
    pub e: Vec<f64>,
    /// `G`.
    pub g_matrix: DMatrix<f64>,
    /// `g`.
    pub g: Vec<f64>,
}

/// What Clarabel returned.
#[derive(Clone, Debug)]
pub struct Solution {
    /// The minimiser.
    pub x: Vec<f64>,
    /// Multipliers of `E x = e`.
    pub nu: Vec<f64>,
    /// Multipliers of `G x ≥ g` (non-negative).
    pub lambda: Vec<f64>,
    /// Clarabel's status (`Solved` or `AlmostSolved`).
    pub status: SolverStatus,
    /// Interior-point iterations.
    pub iterations: u32,
    /// Clarabel's own solve time, in seconds.
    pub solve_time: f64,
}

/// Why the QP has no usable solution.
#[derive(Debug, thiserror::Error)]
pub enum QpError {
    /// The constraints cannot all hold.
    #[error("the QP is infeasible (Clarabel: {0:?})")]
    Infeasible(SolverStatus),
    /// The objective is unbounded below.
    #[error("the QP is unbounded (Clarabel: {0:?})")]
    Unbounded(SolverStatus),
    /// Clarabel stopped without a solution (iteration limit, numerical trouble).
    #[error("Clarabel stopped without a solution: {0:?}")]
    NotSolved(SolverStatus),
    /// Clarabel refused the settings.
    #[error("Clarabel refused the settings: {0}")]
    Settings(#[from] DefaultSettingsBuilderError),
    /// Clarabel refused the problem data.
    #[error("Clarabel rejected the problem data: {0}")]
    Setup(#[from] SolverError),
}

/// Column-compressed copy of `matrix`, keeping only the upper triangle when `upper` is set.
fn csc(matrix: &DMatrix<f64>, upper: bool) -> CscMatrix<f64> {
    let (mut colptr, mut rowval, mut nzval) = (vec![0], Vec::new(), Vec::new());
    for j in 0..matrix.ncols() {
        for i in 0..matrix.nrows() {
            let v = matrix[(i, j)];
            if v != 0.0 && (!upper || i <= j) {
                rowval.push(i);
                nzval.push(v);
            }
        }
        colptr.push(rowval.len());
    }
    CscMatrix::new(matrix.nrows(), matrix.ncols(), colptr, rowval, nzval)
}

/// Solves the problem.
pub fn solve(problem: &Problem) -> Result<Solution, QpError> {
    let n = problem.p.ncols();
    let (me, mg) = (problem.e_matrix.nrows(), problem.g_matrix.nrows());
    // Clarabel's form: A x + s = b, s ∈ {0}^me × ℝ₊^mg, with A = [E; -G], b = [e; -g].
    let mut a = DMatrix::zeros(me + mg, n);
    a.rows_mut(0, me).copy_from(&problem.e_matrix);
    a.rows_mut(me, mg).copy_from(&(-&problem.g_matrix));
    let b: Vec<f64> = problem.e.iter().copied().chain(problem.g.iter().map(|v| -v)).collect();
    let mut cones = Vec::new();
    if me > 0 {
        cones.push(SupportedConeT::ZeroConeT(me));
    }
    if mg > 0 {
        cones.push(SupportedConeT::NonnegativeConeT(mg));
    }
    let settings = DefaultSettingsBuilder::default().verbose(false).max_iter(500).build()?;
    let mut solver = DefaultSolver::new(
        &csc(&problem.p, true),
        &problem.q,
        &csc(&a, false),
        &b,
        &cones,
        settings,
    )?;
    solver.solve();
    let s = &solver.solution;
    let status = s.status;
    match status {
        SolverStatus::Solved | SolverStatus::AlmostSolved => Ok(Solution {
            x: s.x.clone(),
            nu: s.z[..me].iter().map(|z| -z).collect(),
            lambda: s.z[me..].to_vec(),
            status,
            iterations: s.iterations,
            solve_time: s.solve_time,
        }),
        SolverStatus::PrimalInfeasible | SolverStatus::AlmostPrimalInfeasible => Err(QpError::Infeasible(status)),
        SolverStatus::DualInfeasible | SolverStatus::AlmostDualInfeasible => Err(QpError::Unbounded(status)),
        _ => Err(QpError::NotSolved(status)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_qp_with_known_solution_and_multipliers() {
        // min ½(x² + y²) - x - y  s.t.  x + y = 1,  x ≥ 0.8  ⇒  x = 0.8, y = 0.2.
        // Stationarity: (x - 1, y - 1) = ν (1, 1) + λ (1, 0) ⇒ ν = -0.8, λ = 0.6.
        let problem = Problem {
            p: DMatrix::identity(2, 2),
            q: vec![-1.0, -1.0],
            e_matrix: DMatrix::from_row_slice(1, 2, &[1.0, 1.0]),
            e: vec![1.0],
            g_matrix: DMatrix::from_row_slice(1, 2, &[1.0, 0.0]),
            g: vec![0.8],
        };
        let s = solve(&problem).unwrap();
        assert!((s.x[0] - 0.8).abs() < 1e-7 && (s.x[1] - 0.2).abs() < 1e-7, "{:?}", s.x);
        assert!((s.nu[0] + 0.8).abs() < 1e-6, "{:?}", s.nu);
        assert!((s.lambda[0] - 0.6).abs() < 1e-6, "{:?}", s.lambda);
    }

    #[test]
    fn infeasible_constraints_are_an_error() {
        // x ≥ 1 and -x ≥ 0 cannot both hold.
        let problem = Problem {
            p: DMatrix::identity(1, 1),
            q: vec![0.0],
            e_matrix: DMatrix::zeros(0, 1),
            e: vec![],
            g_matrix: DMatrix::from_row_slice(2, 1, &[1.0, -1.0]),
            g: vec![1.0, 0.0],
        };
        assert!(matches!(solve(&problem), Err(QpError::Infeasible(_))));
    }
}
