//! `gen`'s report of a design as a page: `report.html` holds the same tables as `report.md`, embeds
//! the same figures, and every figure it shows is a PNG written beside it (what a browser needs to
//! render it; `docs/guide.md`, *Reading the report*, shows the headless-browser command that was run
//! on it).

use host::generate::{self, Destinations};
use host::report::html;
use indicatif::ProgressBar;

#[test]
fn the_html_report_shows_the_markdown_tables_and_only_figures_that_exist() {
    let scratch = std::env::temp_dir().join(format!("report-html-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&scratch);
    let to = Destinations {
        reports: scratch.join("designs"),
        generated: scratch.join("generated"),
    };
    let spec = integration_tests::specs_folder().join("two_tanks.toml");
    let outcomes = generate::run(&[spec], &to, false, |_| ProgressBar::hidden(), |_, _| {}).unwrap();
    let folder = &outcomes[0].folder;
    let markdown = std::fs::read_to_string(folder.join("report.md")).unwrap();
    let page = std::fs::read_to_string(folder.join("report.html")).unwrap();
    assert_eq!(outcomes[0].report_files[2], folder.join("report.html"));

    // The same figures, in the same order: the Markdown's image links are the page's images.
    let linked: Vec<&str> = markdown
        .lines()
        .filter_map(|l| l.strip_prefix("!["))
        .filter_map(|l| l.split_once("](").map(|(_, target)| target.trim_end_matches(')')))
        .collect();
    assert_eq!(html::images(&page), linked);
    // Every figure the report draws is shown (two_tanks has an input: the measurements figure shows
    // it), and each is a PNG on disk.
    for stem in ["measurements", "identification", "estimation", "validation"] {
        assert!(
            linked.contains(&format!("{stem}.png").as_str()),
            "{stem} is not embedded"
        );
    }
    for image in &linked {
        let bytes = std::fs::read(folder.join(image)).unwrap_or_else(|e| panic!("{image}: {e}"));
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "{image} is not a PNG");
    }
    // The same tables: one <table> per Markdown table (a header row followed by its rule), with
    // every target's row.
    let tables = markdown
        .lines()
        .zip(markdown.lines().skip(1))
        .filter(|(head, rule)| head.starts_with('|') && rule.starts_with("|---"))
        .count();
    assert!(tables >= 3, "{tables} tables");
    assert_eq!(page.matches("<table>").count(), tables);
    assert!(page.contains("<td>h1</td>") && page.contains("<td>h2</td>"));
    assert!(page.starts_with("<!DOCTYPE html>") && page.contains("<meta charset=\"utf-8\">"));
    std::fs::remove_dir_all(&scratch).unwrap();
}
