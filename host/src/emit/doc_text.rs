//! Spec text made safe for the generated crate's doc comments: one line, no markup a spec could use to
//! open a code fence, a link or an HTML tag; and names listed as the docs list them.

/// `text` made safe for a `//!` or `///` comment: control characters (a newline would end the
/// comment and let the rest be read as code) become spaces.
fn comment_text(text: &str) -> String {
    text.chars().map(|c| if c.is_control() { ' ' } else { c }).collect()
}

/// Characters Markdown or rustdoc may read as markup: code spans and fences, emphasis, links, HTML
/// and its entities, headings, tables.
const MARKUP: &str = "\\`*_[]<>#|~&";

/// Spec text for the prose of a doc comment: one line, no leading blanks (an indented code block), and
/// every markup character escaped with a backslash, so that nothing a spec says can open a code fence
/// (a doctest that fails), a link or an HTML tag (rustdoc warnings) in the generated crate.
pub(crate) fn doc_prose(text: &str) -> String {
    let mut inert = String::new();
    for c in comment_text(text).trim_start().chars() {
        if MARKUP.contains(c) {
            inert.push('\\');
        }
        inert.push(c);
    }
    inert
}

/// Spec text inside a code span of a doc comment: one line, a backtick (which would end the span)
/// shown as `'`.
pub(crate) fn doc_code(text: &str) -> String {
    comment_text(text).replace('`', "'")
}

/// Names as the emitted docs list them: comma separated, `none` for none.
pub fn name_list(names: &[String]) -> String {
    if names.is_empty() {
        "none".to_owned()
    } else {
        names.join(", ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn spec_text_cannot_open_markup_in_the_docs() {
        // A code fence in a description made the generated file start a doctest that fails.
        let prose = doc_prose("   ```rust\nfn main() {} <b>[link] *x* # h");
        assert_eq!(prose, "\\`\\`\\`rust fn main() {} \\<b\\>\\[link\\] \\*x\\* \\# h");
        assert!(!doc_code("a`b").contains('`'));
    }

    proptest! {
        #[test]
        fn every_markup_character_of_the_prose_is_escaped(text in ".*") {
            let prose = doc_prose(&text);
            prop_assert!(!prose.contains('\n') && !prose.starts_with(' '));
            let mut escaped = false;
            for c in prose.chars() {
                prop_assert!(escaped || c == '\\' || !MARKUP.contains(c), "{prose}");
                escaped = !escaped && c == '\\';
            }
            prop_assert!(!escaped, "a trailing backslash would escape what follows: {prose}");
        }
    }

    #[test]
    fn comment_text_cannot_end_a_comment() {
        let text = comment_text("line\npub fn injected() {}\r\n");
        assert!(!text.contains('\n') && !text.contains('\r'));
    }
}
