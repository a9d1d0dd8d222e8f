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
    assert!(t.validation.map.rmse.is_finite() && t.validation.map.rmse < t.fit.map.r_max - t.fit.map.r_min);
}
