//! The matrix product both the filter ([`crate::ekf`]) and the discretised model ([`crate::model`])
//! compute with: a module of its own so that neither has to import the other for it.

use crate::Scalar;

/// `A B` (also what the host composes substeps with).
pub fn product<T: Scalar, const M: usize>(a: &[[T; M]; M], b: &[[T; M]; M]) -> [[T; M]; M] {
    let mut out = [[T::ZERO; M]; M];
    for (r, out_row) in out.iter_mut().enumerate() {
        for (c, entry) in out_row.iter_mut().enumerate() {
            for k in 0..M {
                *entry += a[r][k] * b[k][c];
            }
        }
    }
    out
}
