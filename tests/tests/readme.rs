//! The README and its docs: the README stays a short page (at most 250 lines), and the spec that
//! `docs/guide.md` shows (its first TOML block, every field annotated) is a working design.

use integration_tests::{build, design};

#[test]
fn readme_is_at_most_250_lines() {
    let lines = include_str!("../../README.md").lines().count();
    assert!(lines <= 250, "README.md has {lines} lines: move the detail into docs/");
}

#[test]
fn the_guides_spec_parses_and_builds() {
    let guide = include_str!("../../docs/guide.md");
    let start = guide.find("```toml\n").expect("a TOML block in docs/guide.md") + "```toml\n".len();
    let text = &guide[start..start + guide[start..].find("```").unwrap()];
    let d = design("guide", text);
    assert_eq!(d.model.inputs, ["u"]);
    let result = build(&d);
    let t = &result.targets[0];
    // The outflow sqrt(|h|) is far from linear in the measured level: the map must beat the linear
    // floor clearly, and stay well inside the target's range.
    assert!(
        t.validation.map.rmse < 0.5 * t.validation.linear.rmse,
        "{:?}",
        t.validation
    );
    assert!(
        t.validation.map.rmse < 0.1 * (t.fit.map.r_max - t.fit.map.r_min),
        "{:?}",
        t.validation
    );
}
