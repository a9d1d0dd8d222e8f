//! A filter's covariance constant (`Q`, `P(0)`): a diagonal, as the tuning chooses it, or a full
//! symmetric matrix, as a spec may fix it (`[observer.ekf] p0 = [[…], […]]`).
//!
//! It serialises as it is written: a diagonal as the list of its entries (what `design.json` held
//! before full matrices existed), a full matrix as its rows.

use serde::{Deserialize, Serialize};

/// See the module's documentation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Covariance {
    /// `diag(entries)`.
    Diagonal(Vec<f64>),
    /// The rows of a symmetric matrix.
    Full(Vec<Vec<f64>>),
}

/// Why a covariance cannot be a filter's.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CovarianceError {
    /// It is not `n × n` for the design's `n` states.
    #[error("it is {rows} × {columns}, not {states} × {states} (one row and column per state)")]
    Size {
        /// Its rows.
        rows: usize,
        /// The most columns of a row.
        columns: usize,
        /// The design's states.
        states: usize,
    },
    /// An entry is NaN or infinite.
    #[error("entry ({row}, {column}) is not a finite number")]
    NotFinite {
        /// Row (from 0).
        row: usize,
        /// Column (from 0).
        column: usize,
    },
    /// Entry `(r, c)` differs from `(c, r)`.
    #[error("it is not symmetric: entry ({row}, {column}) = {value} but ({column}, {row}) = {mirror}")]
    NotSymmetric {
        /// Row (from 0).
        row: usize,
        /// Column (from 0).
        column: usize,
        /// The entry.
        value: f64,
        /// Its mirror across the diagonal.
        mirror: f64,
    },
    /// Its Cholesky factorisation fails: some direction has a variance ≤ 0.
    #[error(
        "it is not positive definite (its Cholesky factorisation fails: some combination of states has a variance ≤ 0)"
    )]
    NotPositiveDefinite,
}

impl Covariance {
    /// States it is a covariance of.
    pub fn size(&self) -> usize {
        match self {
            Covariance::Diagonal(d) => d.len(),
            Covariance::Full(rows) => rows.len(),
        }
    }

    /// Entry `(r, c)`.
    pub fn entry(&self, r: usize, c: usize) -> f64 {
        match self {
            Covariance::Diagonal(d) if r == c => d[r],
            Covariance::Diagonal(_) => 0.0,
            Covariance::Full(rows) => rows[r][c],
        }
    }

    /// Its diagonal.
    pub fn diagonal(&self) -> Vec<f64> {
        (0..self.size()).map(|i| self.entry(i, i)).collect()
    }

    /// Whether every entry off the diagonal is zero.
    pub fn is_diagonal(&self) -> bool {
        let n = self.size();
        (0..n).all(|r| (0..n).all(|c| r == c || self.entry(r, c) == 0.0))
    }

    /// Its upper triangle, row by row (how the filters keep `P`).
    pub fn upper(&self) -> Vec<f64> {
        let n = self.size();
        (0..n)
            .flat_map(|r| (r..n).map(move |c| (r, c)))
            .map(|(r, c)| self.entry(r, c))
            .collect()
    }

    /// Its rows.
    pub fn rows(&self) -> Vec<Vec<f64>> {
        let n = self.size();
        (0..n).map(|r| (0..n).map(|c| self.entry(r, c)).collect()).collect()
    }

    /// Checks that it can be a filter's covariance over `states` states: square of that size, finite,
    /// symmetric (to the bit: a spec writes both halves) and positive definite.
    pub fn check(&self, states: usize) -> Result<(), CovarianceError> {
        if let Covariance::Full(rows) = self {
            let columns = rows.iter().map(Vec::len).max().unwrap_or(0);
            if rows.len() != states || rows.iter().any(|row| row.len() != states) {
                return Err(CovarianceError::Size {
                    rows: rows.len(),
                    columns,
                    states,
                });
            }
        } else if self.size() != states {
            return Err(CovarianceError::Size {
                rows: self.size(),
                columns: self.size(),
                states,
            });
        }
        for r in 0..states {
            for c in 0..states {
                let (value, mirror) = (self.entry(r, c), self.entry(c, r));
                if !value.is_finite() {
                    return Err(CovarianceError::NotFinite { row: r, column: c });
                }
                if value != mirror {
                    return Err(CovarianceError::NotSymmetric {
                        row: r,
                        column: c,
                        value,
                        mirror,
                    });
                }
            }
        }
        let matrix = nalgebra::DMatrix::from_fn(states, states, |r, c| self.entry(r, c));
        match matrix.cholesky() {
            Some(_) => Ok(()),
            None => Err(CovarianceError::NotPositiveDefinite),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_diagonal_reads_as_the_full_matrix_it_stands_for() {
        let d = Covariance::Diagonal(vec![1.0, 2.0, 3.0]);
        assert_eq!(d.upper(), vec![1.0, 0.0, 0.0, 2.0, 0.0, 3.0]);
        assert_eq!(
            d.rows(),
            vec![vec![1.0, 0.0, 0.0], vec![0.0, 2.0, 0.0], vec![0.0, 0.0, 3.0]]
        );
        assert!(d.is_diagonal());
        let full = Covariance::Full(vec![vec![4.0, 1.0], vec![1.0, 3.0]]);
        assert_eq!(full.upper(), vec![4.0, 1.0, 3.0]);
        assert_eq!(full.diagonal(), vec![4.0, 3.0]);
        assert!(!full.is_diagonal());
    }

    #[test]
    fn it_serialises_as_written_a_diagonal_as_before() {
        // `design.json` held a diagonal as a plain list before full matrices existed.
        let d = Covariance::Diagonal(vec![0.5, 2.0]);
        assert_eq!(serde_json::to_string(&d).unwrap(), "[0.5,2.0]");
        let full = Covariance::Full(vec![vec![4.0, 1.0], vec![1.0, 3.0]]);
        assert_eq!(serde_json::to_string(&full).unwrap(), "[[4.0,1.0],[1.0,3.0]]");
        for c in [d, full] {
            let back: Covariance = serde_json::from_str(&serde_json::to_string(&c).unwrap()).unwrap();
            assert_eq!(back, c);
        }
    }

    #[test]
    fn the_check_refuses_what_no_filter_can_start_from() {
        let full = |rows: &[[f64; 2]]| Covariance::Full(rows.iter().map(|r| r.to_vec()).collect());
        assert_eq!(full(&[[4.0, 1.0], [1.0, 3.0]]).check(2), Ok(()));
        // det = 4·1 − 2·2 = 0: positive semi-definite only.
        assert_eq!(
            full(&[[4.0, 2.0], [2.0, 1.0]]).check(2),
            Err(CovarianceError::NotPositiveDefinite)
        );
        // Positive diagonal, indefinite: det = 1 − 4 < 0.
        assert_eq!(
            full(&[[1.0, 2.0], [2.0, 1.0]]).check(2),
            Err(CovarianceError::NotPositiveDefinite)
        );
        assert!(matches!(
            full(&[[1.0, 0.5], [0.25, 1.0]]).check(2),
            Err(CovarianceError::NotSymmetric { row: 0, column: 1, .. })
        ));
        assert!(matches!(
            full(&[[1.0, f64::NAN], [f64::NAN, 1.0]]).check(2),
            Err(CovarianceError::NotFinite { row: 0, column: 1 })
        ));
        assert!(matches!(
            full(&[[1.0, 0.0]]).check(2),
            Err(CovarianceError::Size { rows: 1, .. })
        ));
        assert_eq!(
            Covariance::Diagonal(vec![1.0, 0.0]).check(2),
            Err(CovarianceError::NotPositiveDefinite)
        );
        assert!(matches!(
            Covariance::Diagonal(vec![1.0]).check(2),
            Err(CovarianceError::Size { rows: 1, .. })
        ));
    }
}
