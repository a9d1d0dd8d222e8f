//! Equal-length rows of numbers in one allocation: a run's states, inputs, measurements or targets,
//! one row per sample. A `Vec<Vec<f64>>` costs a heap block and a 24-byte header per sample (about
//! 170 MB of a 10⁶-window learning set); this holds only the numbers.

use std::ops::Index;

/// `len` rows of `width` numbers each, row `k` at `values[k·width .. (k+1)·width]`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Rows {
    width: usize,
    len: usize,
    values: Vec<f64>,
}

impl Rows {
    /// No rows yet, each of `width` numbers.
    pub fn new(width: usize) -> Self {
        Rows {
            width,
            len: 0,
            values: Vec::new(),
        }
    }

    /// Appends a row; it must have `width` numbers.
    pub fn push(&mut self, row: &[f64]) {
        assert_eq!(
            row.len(),
            self.width,
            "a row of {} numbers in rows of {}",
            row.len(),
            self.width
        );
        self.values.extend_from_slice(row);
        self.len += 1;
    }

    /// Rows held.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether there is no row.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Numbers per row.
    pub fn width(&self) -> usize {
        self.width
    }

    /// The rows, in order.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = &[f64]> + Clone + '_ {
        (0..self.len).map(move |k| &self[k])
    }

    /// The rows, to change in place (none when rows are empty: `width` 0).
    pub fn iter_mut(&mut self) -> impl Iterator<Item = &mut [f64]> + '_ {
        self.values.chunks_mut(self.width.max(1))
    }

    /// The last row, if any.
    pub fn last(&self) -> Option<&[f64]> {
        self.len.checked_sub(1).map(|k| &self[k])
    }
}

impl Index<usize> for Rows {
    type Output = [f64];

    fn index(&self, k: usize) -> &[f64] {
        assert!(k < self.len, "row {k} of {}", self.len);
        &self.values[k * self.width..(k + 1) * self.width]
    }
}

impl<'a> IntoIterator for &'a Rows {
    type Item = &'a [f64];
    type IntoIter = Box<dyn ExactSizeIterator<Item = &'a [f64]> + 'a>;

    fn into_iter(self) -> Self::IntoIter {
        Box::new(self.iter())
    }
}

impl FromIterator<Vec<f64>> for Rows {
    /// Collects rows, which must all have the length of the first.
    fn from_iter<I: IntoIterator<Item = Vec<f64>>>(rows: I) -> Self {
        Rows::from(rows.into_iter().collect::<Vec<_>>())
    }
}

impl From<Vec<Vec<f64>>> for Rows {
    /// The rows of `rows`, which must all have the length of the first (width 0 when there is none).
    fn from(rows: Vec<Vec<f64>>) -> Self {
        let mut out = Rows::new(rows.first().map_or(0, Vec::len));
        for row in &rows {
            out.push(row);
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_keep_their_values_and_order_also_when_empty() {
        let rows = Rows::from(vec![vec![1.0, 2.0], vec![3.0, 4.0], vec![5.0, 6.0]]);
        assert_eq!((rows.len(), rows.width()), (3, 2));
        assert_eq!(&rows[1], &[3.0, 4.0]);
        assert_eq!(
            rows.iter().map(<[f64]>::to_vec).collect::<Vec<_>>(),
            [[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]]
        );
        assert_eq!(rows.last(), Some(&[5.0, 6.0][..]));
        // A model without inputs: rows of width 0, still one per sample.
        let mut none = Rows::new(0);
        none.push(&[]);
        none.push(&[]);
        assert_eq!((none.len(), none.iter().count()), (2, 2));
        assert!(none[1].is_empty());
    }
}
