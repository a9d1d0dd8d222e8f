//! Bounded fuzzing (proptest) of the two readers of user files: the spec parser and validator, and the
//! recorded-CSV reader. Each must answer every input with a value or an error, never a panic. The case
//! count is `FUZZ_CASES` (default 20 000 each, about five seconds); CI runs the default.

use std::cell::Cell;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};

const VANDERPOL: &str = include_str!("../../specs/vanderpol.toml");
const ECOLI: &str = include_str!("../../specs/ecoli_x0_2.toml");

fn cases() -> u32 {
    std::env::var("FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(20_000)
}

/// Values that stress a spec: huge, tiny, negative, non-finite, wrong types, odd names, operators.
fn hostile_value() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("0".to_owned()),
        Just("-1".to_owned()),
        Just("1e308".to_owned()),
        Just("1e-308".to_owned()),
        Just("nan".to_owned()),
        Just("inf".to_owned()),
        Just("18446744073709551615".to_owned()),
        Just("\"\"".to_owned()),
        Just("\"E\"".to_owned()),
        Just("\"x1 +\"".to_owned()),
        Just("\"-x1^2\"".to_owned()),
        Just("[]".to_owned()),
        Just("{}".to_owned()),
        Just("true".to_owned()),
        any::<i64>().prop_map(|v| v.to_string()),
        any::<f64>().prop_map(|v| format!("{v:?}")),
        "[a-zA-Z_ ]{0,12}".prop_map(|s| format!("\"{s}\"")),
    ]
}

/// A shipped spec with one line's value replaced, one line deleted or duplicated, or bytes flipped.
fn mutated_spec() -> impl Strategy<Value = String> {
    let base = prop_oneof![Just(VANDERPOL), Just(ECOLI)];
    (base, 0usize..200, 0u8..4, hostile_value(), any::<u8>()).prop_map(|(text, line, kind, value, byte)| {
        let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
        let k = line % lines.len();
        match kind {
            0 => {
                if let Some((key, _)) = lines[k].split_once('=') {
                    lines[k] = format!("{key}= {value}");
                }
            }
            1 => {
                lines.remove(k);
            }
            2 => {
                let copy = lines[k].clone();
                lines.insert(k, copy);
            }
            _ => {
                let mut bytes = lines[k].clone().into_bytes();
                if !bytes.is_empty() {
                    let i = byte as usize % bytes.len();
                    bytes[i] = byte;
                }
                lines[k] = String::from_utf8_lossy(&bytes).into_owned();
            }
        }
        lines.join("\n")
    })
}

#[test]
fn the_spec_reader_never_panics() {
    let mut runner = TestRunner::new(Config {
        cases: cases(),
        ..Config::default()
    });
    let (accepted, refused) = (Cell::new(0u32), Cell::new(0u32));
    runner
        .run(&mutated_spec(), |text| {
            let outcome = catch_unwind(AssertUnwindSafe(|| host::spec::parse(Path::new("fuzz.toml"), &text)));
            match outcome {
                Ok(Ok(_)) => accepted.set(accepted.get() + 1),
                Ok(Err(e)) => {
                    prop_assert!(e.to_string().contains("fix:"), "an error without a fix: {e}");
                    refused.set(refused.get() + 1);
                }
                Err(_) => prop_assert!(false, "panic on:\n{text}"),
            }
            Ok(())
        })
        .unwrap();
    let (accepted, refused) = (accepted.get(), refused.get());
    println!(
        "spec reader: {} cases without a panic ({accepted} accepted, {refused} refused with a fix)",
        accepted + refused
    );
}

#[test]
fn the_csv_reader_never_panics() {
    let design = host::spec::parse(Path::new("vanderpol.toml"), VANDERPOL).unwrap();
    let path = std::env::temp_dir().join(format!("host-fuzz-{}.csv", std::process::id()));
    let rows = prop_oneof![
        proptest::collection::vec(any::<u8>(), 0..200),
        "(y|run|note|,|\n|\r|\r\n|\"|0.5|-1e400|nan|inf| ){0,40}".prop_map(String::into_bytes),
    ];
    let mut runner = TestRunner::new(Config {
        cases: cases(),
        ..Config::default()
    });
    let count = Cell::new(0u32);
    runner
        .run(&rows, |bytes| {
            std::fs::write(&path, &bytes).unwrap();
            let outcome = catch_unwind(AssertUnwindSafe(|| host::recording::read(&design, &path)));
            prop_assert!(outcome.is_ok(), "panic on {:?}", String::from_utf8_lossy(&bytes));
            count.set(count.get() + 1);
            Ok(())
        })
        .unwrap();
    let _ = std::fs::remove_file(&path);
    println!("csv reader: {} cases without a panic", count.get());
}
