//! Every figure the README and `docs/` quote is one the tool computes now: each decimal number with at
//! least three decimals in them must be, to its shown decimals, a number of a fresh report of the
//! shipped designs (`report.json`, `report.md`) or of the on-target table (`docs/chip.md`). A number
//! that comes from elsewhere (an experiment the docs describe, a measurement before a change) is
//! listed, with why, in `tests/doc-numbers-elsewhere.txt`; a listed number the docs no longer show
//! fails too, so the list only holds what it must.

use std::collections::BTreeSet;

/// The decimal numbers of `text` with at least `min_decimals` decimals, as written.
pub fn decimals(text: &str, min_decimals: usize) -> Vec<&str> {
    let bytes = text.as_bytes();
    let mut found = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let starts = bytes[i].is_ascii_digit() && (i == 0 || !is_number_part(bytes[i - 1]));
        if !starts {
            i += 1;
            continue;
        }
        let start = i;
        while i < bytes.len() && (bytes[i].is_ascii_digit() || bytes[i] == b'.') {
            i += 1;
        }
        let number = text[start..i].trim_end_matches('.');
        let followed = i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_');
        if let Some((_, fraction)) = number.split_once('.') {
            if !followed && !fraction.contains('.') && fraction.len() >= min_decimals {
                found.push(number);
            }
        }
    }
    found
}

fn is_number_part(byte: u8) -> bool {
    byte.is_ascii_alphanumeric() || byte == b'.' || byte == b'_'
}

/// Every number of `corpus` (plain or with an exponent), rounded to 1 … 6 decimals, as `{:.k}` writes it.
pub fn roundings(corpus: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for token in corpus.split(|c: char| !(c.is_ascii_digit() || matches!(c, '.' | 'e' | 'E' | '-' | '+'))) {
        let token = token.trim_matches(|c: char| matches!(c, '.' | '-' | '+' | 'e' | 'E'));
        if let Ok(value) = token.parse::<f64>() {
            for k in 1..=6 {
                out.insert(format!("{:.k$}", value.abs()));
            }
        }
    }
    out
}

/// The numbers of `docs` (name, text) not in `computed` ([`roundings`] of the fresh reports) nor
/// listed in `elsewhere` (lines `file number  why`); then the listed ones no doc shows any more.
pub fn stale(docs: &[(&str, String)], computed: &BTreeSet<String>, elsewhere: &str) -> (Vec<String>, Vec<String>) {
    let listed: BTreeSet<(String, String)> = elsewhere
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .filter_map(|l| {
            let mut words = l.split_whitespace();
            Some((words.next()?.to_owned(), words.next()?.to_owned()))
        })
        .collect();
    let mut shown = BTreeSet::new();
    let mut unknown = Vec::new();
    for (name, text) in docs {
        for number in decimals(text, 3) {
            shown.insert((name.to_string(), number.to_owned()));
            if !computed.contains(number) && !listed.contains(&(name.to_string(), number.to_owned())) {
                unknown.push(format!("{name}: {number}"));
            }
        }
    }
    let gone = listed
        .difference(&shown)
        .map(|(name, number)| format!("{name} {number}"))
        .collect();
    (unknown, gone)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_read_as_written_and_versions_and_names_are_not_numbers() {
        let text = "RMSE 0.2424 / 0.287, v1.2.345, x0.125, 12.5 %, (0.0436), 1e-4, 3.14159. and 7.000";
        assert_eq!(decimals(text, 3), ["0.2424", "0.287", "0.0436", "3.14159", "7.000"]);
    }

    #[test]
    fn a_doc_number_matches_a_computed_one_at_its_decimals_only() {
        let computed = roundings(r#"{"rmse": 0.196512, "k": [5.81e-3, -0.04719]} | 0.1965 |"#);
        for shown in ["0.197", "0.1965", "0.0058", "0.0472", "0.05"] {
            assert!(computed.contains(shown), "{shown}");
        }
        // A figure off by one in its last shown decimal is stale: the check bites.
        let docs = [("guide.md", "x 0.198 and 0.1966 and 0.0472".to_owned())];
        let (unknown, gone) = stale(
            &docs,
            &computed,
            "guide.md 0.1966  measured by hand\nguide.md 0.999  gone\n",
        );
        assert_eq!(unknown, ["guide.md: 0.198"]);
        assert_eq!(gone, ["guide.md 0.999"]);
    }
}
