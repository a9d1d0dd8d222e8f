//! Helper maps: the map-started kinds (the model-corrected map, the map-started and restarted EKFs)
//! start from the map's estimate of every state, but a design's targets are what its user
//! estimates. A state that no target is (no target's expression is the state's name) gets a map of
//! its own, fitted as a target's is, on the same learning windows: a *helper*, read only by those
//! kinds and never returned by an observer. The maps' rows are the targets' in spec order, then the
//! helpers' in state order ([`state_maps`]).

use crate::spec::Design;

/// The states that no target is, in state order: each needs a helper map.
pub fn helper_states(design: &Design) -> Vec<usize> {
    (0..design.model.states.len())
        .filter(|&i| target_of_state(design, i).is_none())
        .collect()
}

/// The map row of every state: its target's index where a target is the state, else `T + h` for
/// the `h`-th helper ([`helper_states`]) of a design of `T` targets.
pub fn state_maps(design: &Design) -> Vec<usize> {
    let mut helpers = design.targets.len()..;
    (0..design.model.states.len())
        .map(|i| target_of_state(design, i).unwrap_or_else(|| helpers.next().expect("an unbounded range")))
        .collect()
}

/// The target whose expression is state `i`'s name, if any.
fn target_of_state(design: &Design, i: usize) -> Option<usize> {
    let state = &design.model.states[i];
    design.targets.iter().position(|t| t.expr.text().trim() == state)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn design(targets: &str) -> Design {
        let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/specs/vanderpol.toml")).unwrap();
        // The spec's two targets replaced by `targets`.
        let (at, end) = (text.find("[[targets]]").unwrap(), text.find("[scenario]").unwrap());
        let text = format!("{}{targets}\n{}", &text[..at], &text[end..]);
        crate::spec::parse(std::path::Path::new("helpers.toml"), &text).unwrap()
    }

    #[test]
    fn every_state_that_no_target_is_gets_a_row_after_the_targets() {
        let both = design("[[targets]]\nname = \"x2\"\nexpr = \"x2\"\n\n[[targets]]\nname = \"x1\"\nexpr = \"x1\"\n");
        assert_eq!((helper_states(&both), state_maps(&both)), (vec![], vec![1, 0]));
        // `2*x1` is a target but not the state x1: both states need helpers, after the one target.
        let none = design("[[targets]]\nname = \"twice\"\nexpr = \"2*x1\"\n");
        assert_eq!((helper_states(&none), state_maps(&none)), (vec![0, 1], vec![1, 2]));
        let second = design("[[targets]]\nname = \"x2\"\nexpr = \" x2 \"\n");
        assert_eq!((helper_states(&second), state_maps(&second)), (vec![0], vec![1, 0]));
        // E. coli's targets are P and muX of states X, S, P: X and S are helpers 2 and 3.
        let ecoli = crate::spec::load(std::path::Path::new("specs/ecoli_x0_2.toml")).unwrap();
        assert_eq!((helper_states(&ecoli), state_maps(&ecoli)), (vec![0, 1], vec![2, 3, 0]));
    }
}
