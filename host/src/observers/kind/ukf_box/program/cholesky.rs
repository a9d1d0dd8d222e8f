//! The Cholesky factors the UKF's programs write out for their size (of `P` for the sigma points, of
//! `S` for the gain), every pivot floored ([`pivot`]) so that a factor stays finite.

use crate::plant::program::Builder;
use crate::spec::ast::Binary;

/// The lower Cholesky factor of the symmetric `m` (read from `r ≤ c`), each pivot at least
/// [`pivot`]'s floor.
pub(super) fn cholesky(b: &mut Builder<'_>, m: &[Vec<usize>]) -> Vec<Vec<usize>> {
    let n = m.len();
    let zero = b.number(0.0);
    let one = b.number(1.0);
    let mut l = vec![vec![zero; n]; n];
    let mut inverse = vec![one; n];
    for j in 0..n {
        let row: Vec<usize> = l[j][..j].to_vec();
        let squares = b.dot(zero, &row, &row);
        let left = b.sub(m[j][j], squares);
        let diagonal = pivot(b, left, m[j][j]);
        l[j][j] = b.call("sqrt", diagonal);
        inverse[j] = b.binary(Binary::Div, one, l[j][j]);
        for i in j + 1..n {
            let (a, c) = (l[i][..j].to_vec(), l[j][..j].to_vec());
            let products = b.dot(zero, &a, &c);
            let left = b.sub(m[j][i], products);
            l[i][j] = b.mul(left, inverse[j]);
        }
    }
    l
}

/// `d`, or `ε · |diagonal| + MIN_POSITIVE` (ε and the smallest normal number of `f32`) where `d` is
/// below it: the pivot that keeps a factor finite where rounding made the matrix slightly indefinite
/// (positive even where the diagonal entry itself is not), by a select (a NaN `d` goes to the floor;
/// the sample is then refused by its other entries).
pub fn pivot(b: &mut Builder<'_>, d: usize, diagonal: usize) -> usize {
    let epsilon = b.number(f64::from(f32::EPSILON));
    let size = b.call("abs", diagonal);
    let relative = b.mul(epsilon, size);
    let smallest = b.number(f64::from(f32::MIN_POSITIVE));
    let floor = b.add(relative, smallest);
    b.at_least(d, floor)
}
