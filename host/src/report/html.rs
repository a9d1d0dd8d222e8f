//! `report.html`: `report.md` rendered for a browser (CommonMark with tables, by pulldown-cmark), in a
//! page of its own that needs nothing but the figures beside it. The Markdown stays the one source of
//! the report's content; this only changes how it is shown.

/// The page of `markdown` (a report), titled `title`.
pub fn page(title: &str, markdown: &str) -> String {
    let parser = pulldown_cmark::Parser::new_ext(markdown, pulldown_cmark::Options::ENABLE_TABLES);
    let mut body = String::new();
    pulldown_cmark::html::push_html(&mut body, parser);
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{}</title>\n<style>\n{STYLE}</style>\n</head>\n<body>\n{body}</body>\n</html>\n",
        escape(title)
    )
}

/// Readable tables (wide ones scroll), figures no wider than the page.
const STYLE: &str =
    "body { font-family: sans-serif; max-width: 1600px; margin: 2em auto; padding: 0 1em; line-height: 1.45; }\n\
table { border-collapse: collapse; margin: 1em 0; display: block; overflow-x: auto; }\n\
th, td { border: 1px solid #bbb; padding: 0.25em 0.6em; text-align: right; white-space: nowrap; }\n\
th { background: #eee; }\n\
td:first-child, td:nth-child(2) { text-align: left; }\n\
img { max-width: 100%; height: auto; border: 1px solid #ddd; }\n\
code { background: #f4f4f4; padding: 0 0.2em; }\n";

fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

/// The `src` of every `<img>` of `html`, in order (what a page needs beside it).
pub fn images(html: &str) -> Vec<&str> {
    html.split("<img src=\"")
        .skip(1)
        .filter_map(|rest| rest.split('"').next())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_and_figures_become_html() {
        let html = page(
            "a <b>",
            "# a\n\n| target | RMSE |\n|---|---|\n| x1 | 0.25 |\n\n![estimation](estimation.png)\n",
        );
        assert!(html.starts_with("<!DOCTYPE html>"));
        assert!(html.contains("<title>a &lt;b&gt;</title>"));
        assert!(html.contains("<th>target</th>") && html.contains("<td>0.25</td>"));
        assert_eq!(images(&html), ["estimation.png"]);
        assert!(html.contains("alt=\"estimation\""));
    }

    #[test]
    fn a_spec_description_is_text_in_the_page() {
        // As the report writes it (`emit::doc_prose`): no tag, no table, no entity of the spec's.
        let description = "a <script>alert(1)</script> | b & c &lt; *d*";
        let html = page("t", &format!("# t\n\n{}\n", crate::emit::doc_prose(description)));
        assert!(
            !html.contains("<script>") && !html.contains("<table>") && !html.contains("<em>"),
            "{html}"
        );
        assert!(
            html.contains("<p>a &lt;script&gt;alert(1)&lt;/script&gt; | b &amp; c &amp;lt; *d*</p>"),
            "{html}"
        );
    }
}
