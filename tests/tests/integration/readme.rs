//! The README and its docs: the README stays a short page (at most 250 lines), the spec that
//! `docs/guide.md` shows (its first TOML block, every field annotated) is a working design, and every
//! `mho` command they show is one the tool accepts.

use integration_tests::{build, design};

#[test]
fn readme_is_at_most_250_lines() {
    let lines = include_str!("../../../README.md").lines().count();
    assert!(lines <= 250, "README.md has {lines} lines: move the detail into docs/");
}

#[test]
fn the_guides_spec_parses_and_builds() {
    let guide = include_str!("../../../docs/guide.md");
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

/// Every `mho` command line the README and docs/ show in a shell block (`cargo run [--release] -p
/// host -- …` or `mho …`) is one the tool's own parser accepts: a renamed option or subcommand
/// fails here, not in a user's terminal.
#[test]
fn every_command_the_docs_show_parses() {
    use clap::Parser;
    let root = integration_tests::workspace_root();
    let mut files = vec![root.join("README.md")];
    let mut docs: Vec<_> = std::fs::read_dir(root.join("docs"))
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    docs.sort();
    files.extend(docs);
    let parse =
        |args: &str| host::cli::args::Cli::try_parse_from(std::iter::once("mho").chain(args.split_whitespace()));
    let mut checked = 0;
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        let mut in_shell = false;
        for (number, line) in text.lines().enumerate() {
            if line.starts_with("```") {
                in_shell = line == "```sh";
                continue;
            }
            if !in_shell {
                continue;
            }
            let command = line.split(" #").next().unwrap_or_default().trim();
            let args = command
                .split_once(" -p host -- ")
                .filter(|(cargo, _)| cargo.starts_with("cargo run"))
                .map(|(_, args)| args)
                .or_else(|| command.strip_prefix("mho "));
            if let Some(args) = args {
                if let Err(e) = parse(args) {
                    panic!("{}:{}: `{command}` does not parse:\n{e}", file.display(), number + 1);
                }
                checked += 1;
            }
        }
    }
    assert!(checked >= 7, "only {checked} commands found in the README and docs/");
    // The check bites: a misspelt option or a subcommand that does not exist is refused.
    assert!(parse("gen --sepc my.toml").is_err() && parse("fit --spec my.toml").is_err());
}
