//! The triangular factor `R` of a tall data matrix, accumulated block by block.
//!
//! Least squares on `A = Q R` only needs `R`: `‖A x‖ = ‖R x‖` for every `x`. Rows arrive one at a
//! time; every `BLOCK` rows the stack `[R; rows]` is refactored by Householder QR (nalgebra), so memory
//! stays `O(columns²)` whatever the number of rows, and, unlike a Gram matrix `AᵀA`, the condition
//! number is not squared.

use nalgebra::DMatrix;

const BLOCK: usize = 512;

/// Accumulates `R` of the rows pushed so far.
pub struct StreamingQr {
    columns: usize,
    r: DMatrix<f64>,
    pending: Vec<f64>,
    rows: usize,
}

impl StreamingQr {
    /// An empty accumulator for rows of `columns` entries.
    pub fn new(columns: usize) -> Self {
        StreamingQr {
            columns,
            r: DMatrix::zeros(0, columns),
            pending: Vec::with_capacity(BLOCK * columns),
            rows: 0,
        }
    }

    /// Appends one row.
    pub fn push(&mut self, row: &[f64]) {
        assert_eq!(row.len(), self.columns, "row length");
        self.pending.extend_from_slice(row);
        self.rows += 1;
        if self.pending.len() == BLOCK * self.columns {
            self.flush();
        }
    }

    /// Rows pushed so far.
    pub fn rows(&self) -> usize {
        self.rows
    }

    fn flush(&mut self) {
        if self.pending.is_empty() {
            return;
        }
        let block = DMatrix::from_row_slice(self.pending.len() / self.columns, self.columns, &self.pending);
        let mut stacked = DMatrix::zeros(self.r.nrows() + block.nrows(), self.columns);
        stacked.rows_mut(0, self.r.nrows()).copy_from(&self.r);
        stacked.rows_mut(self.r.nrows(), block.nrows()).copy_from(&block);
        self.r = stacked.qr().r();
        self.pending.clear();
    }

    /// The square upper-triangular `R` (`columns × columns`, zero-padded when there are fewer rows).
    pub fn finish(mut self) -> DMatrix<f64> {
        self.flush();
        let mut r = DMatrix::zeros(self.columns, self.columns);
        let rows = self.r.nrows().min(self.columns);
        r.rows_mut(0, rows).copy_from(&self.r.rows(0, rows));
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gram_of_r_equals_gram_of_the_data() {
        let (rows, columns) = (1300, 5);
        let data = DMatrix::from_fn(rows, columns, |i, j| {
            ((i * 7 + j * 13) % 17) as f64 - 8.0 + (i as f64 * 0.01 * j as f64).sin()
        });
        let mut qr = StreamingQr::new(columns);
        for i in 0..rows {
            qr.push(data.row(i).transpose().as_slice());
        }
        assert_eq!(qr.rows(), rows);
        let r = qr.finish();
        let difference = (r.transpose() * &r - data.transpose() * &data).abs().max();
        assert!(
            difference < 1e-9 * (data.transpose() * &data).abs().max(),
            "{difference}"
        );
        for i in 0..columns {
            for j in 0..i {
                assert_eq!(r[(i, j)], 0.0);
            }
        }
    }
}
