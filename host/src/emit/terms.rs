//! The map's dot product as a list of terms, the one order both emitted languages sum in (the Rust
//! design file, [`super::c`]): `offset`, then `g_i z_i` for every regressor entry with a
//! non-zero gain, in regressor order (every output of lag 0, 1, … N−1, then every input), each added
//! to the sum of the ones before, so that Rust and C round alike.

/// One term `g_i · w[sample].field[entry]` of the dot product (`w`: the window, oldest first).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Term {
    /// `i`, the gain's index in the regressor.
    pub gain: usize,
    /// The sample of the window, oldest first: lag `l` is `N − 1 − l`.
    pub sample: usize,
    /// An output (`y`) or an input (`u`).
    pub input: bool,
    /// Which output or input.
    pub entry: usize,
}

/// The terms of a map with `gains` over windows of `horizon` samples of `outputs` outputs and
/// `inputs` inputs; pruned taps (gain exactly 0) left out, as [`firmware::emitted::estimate_by_loops`] skips
/// them.
pub fn dot_terms(gains: &[f32], horizon: usize, outputs: usize, inputs: usize) -> Vec<Term> {
    let mut terms = Vec::new();
    let mut gain = 0;
    for (count, input) in [(outputs, false), (inputs, true)] {
        for lag in 0..horizon {
            for entry in 0..count {
                if gains[gain] != 0.0 {
                    terms.push(Term {
                        gain,
                        sample: horizon - 1 - lag,
                        input,
                        entry,
                    });
                }
                gain += 1;
            }
        }
    }
    terms
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn terms_follow_the_regressor_and_skip_pruned_gains() {
        // N = 2, one output, one input: z = (y(k), y(k−1), u(k), u(k−1)); y(k−1)'s gain pruned.
        let terms = dot_terms(&[1.0, 0.0, 2.0, 3.0], 2, 1, 1);
        let at = |t: &Term| (t.gain, t.sample, t.input, t.entry);
        assert_eq!(
            terms.iter().map(at).collect::<Vec<_>>(),
            [(0, 1, false, 0), (2, 1, true, 0), (3, 0, true, 0)]
        );
    }
}
