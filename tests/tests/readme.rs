//! The spec shown in the README is a working design.

use integration_tests::{build, design};

#[test]
fn readme_spec_parses_and_builds() {
    let readme = include_str!("../../README.md");
    let start = readme.find("```toml\n").expect("a TOML block") + "```toml\n".len();
    let text = &readme[start..start + readme[start..].find("```").unwrap()];
    let d = design("readme", text);
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
