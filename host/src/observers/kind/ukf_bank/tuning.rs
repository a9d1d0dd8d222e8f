//! The bank's layout chosen on the tuning runs: the same runs and score as the box UKF it runs on
//! ([`crate::observers::score::Score`], lost runs first), over a few layouts ([`layouts`]).

use super::run::{self, BankConstants, Layout, Spacing};
use crate::data::{DataSet, Rows};
use crate::observers::score::Scoring;
use crate::plant::kalman::EkfConstants;
use crate::plant::ModelCode;
use crate::spec::{Axis, Design};

/// What a layout scored on the tuning runs: the runs it lost, then its score.
pub type Scored = (usize, f64);

/// The layouts [`choose`] tries: on every axis with a range, four members over equal slices of the
/// filter's coordinate with a third of the box UKF's `P(0)` on it; then, on the best axis, two to
/// four members, either spacing, and the box UKF's `P(0)` or a third of it.
pub fn layouts(axes: &[usize], best: Option<usize>) -> Vec<Layout> {
    match best {
        None => axes
            .iter()
            .map(|&axis| Layout {
                axis,
                members: 4,
                spacing: Spacing::Filter,
                scale: 0.3,
            })
            .collect(),
        Some(axis) => {
            let mut all = Vec::new();
            for members in [2, 3, 4] {
                for spacing in [Spacing::Filter, Spacing::Root, Spacing::Plant] {
                    for scale in [0.3, 1.0] {
                        let layout = Layout {
                            axis,
                            members,
                            spacing,
                            scale,
                        };
                        if layouts(&[axis], None) != [layout] {
                            all.push(layout);
                        }
                    }
                }
            }
            all
        }
    }
}

/// The best bank over the layouts of [`layouts`] around the box UKF `ukf` on `tuning` (first the
/// axis with four members, then the rest on the best axis), with the box UKF's own score there,
/// each target's error over its spread `spreads`; `None` where no state has a range or the model is
/// beyond the host's filters.
pub fn choose(
    design: &Design,
    code: &ModelCode,
    ukf: &EkfConstants,
    tuning: &DataSet,
    spreads: &[f64],
) -> Option<(Scored, (Scored, BankConstants))> {
    let member = crate::observers::kind::ukf_box::program::member_code(code, ukf);
    let scoring = Scoring::of_tuning(design, spreads, tuning.runs.len());
    let score = |estimates: &[Rows]| -> Scored {
        let score = scoring.score(&tuning.runs, estimates);
        (score.lost, score.value)
    };
    let single = score(&crate::observers::kind::ukf_box::run::estimates(
        code, ukf, &ukf.x0, tuning,
    )?);
    let axes: Vec<usize> = (design.learning.axes.iter().enumerate())
        .filter(|(_, axis)| matches!(axis, Axis::Range { min, max, .. } if max > min))
        .map(|(i, _)| i)
        .collect();
    let mut best: Option<(Scored, BankConstants)> = None;
    let consider = |layout: Layout, best: &mut Option<(Scored, BankConstants)>| {
        let Some(bank) = BankConstants::of(layout, design, &code.log_coordinates, ukf) else {
            return;
        };
        let value = score(&run::estimates(code, &member, ukf, &bank, tuning));
        if best.as_ref().is_none_or(|(b, _)| value < *b) {
            *best = Some((value, bank));
        }
    };
    for layout in layouts(&axes, None) {
        consider(layout, &mut best);
    }
    let axis = best.as_ref()?.1.layout.axis;
    for layout in layouts(&axes, Some(axis)) {
        consider(layout, &mut best);
    }
    Some((single, best?))
}

/// Whether a bank that scored `bank` beats one UKF that scored `single`: fewer lost runs, or as many
/// and a score lower by more than [`CHEAPER_WITHIN`](crate::observers::CHEAPER_WITHIN) (it costs `M`
/// UKFs).
pub fn beats(bank: Scored, single: Scored) -> bool {
    bank.0 < single.0 || (bank.0 == single.0 && bank.1 < single.1 * (1.0 - crate::observers::CHEAPER_WITHIN))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_layouts_are_every_axis_then_the_variants_on_the_best() {
        let first = layouts(&[1, 2], None);
        assert_eq!(first.iter().map(|l| l.axis).collect::<Vec<_>>(), [1, 2]);
        assert!(first
            .iter()
            .all(|l| l.members == 4 && l.spacing == Spacing::Filter && l.scale == 0.3));
        // 3 counts × 3 spacings × 2 scales, but the first pass's.
        let then = layouts(&[1, 2], Some(2));
        assert_eq!(then.len(), 17);
        assert!(then.iter().all(|l| l.axis == 2) && !then.contains(&first[1]));
    }

    #[test]
    fn a_bank_beats_one_ufk_by_fewer_lost_runs_or_by_the_margin() {
        assert!(beats((1, 9.0), (2, 0.1)));
        assert!(beats((2, 0.97), (2, 1.0)));
        assert!(!beats((2, 0.99), (2, 1.0)), "within 2 %: one UKF is cheaper");
        assert!(!beats((3, 0.1), (2, 1.0)));
    }
}
