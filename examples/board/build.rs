//! Gives cortex-m-rt the chosen board's memory layout (`memory/<board>.x`) and turns the recorded run
//! `data/run.csv` into constants for the sensor's replay (`recorded.rs`), so that no number in the
//! program is typed by hand.

use std::fmt::Write as _;
use std::path::PathBuf;

/// The boards, by cargo feature; each has `memory/<feature>.x`.
const BOARDS: [&str; 2] = ["nucleo-f401re", "qemu-mps2-an386"];

fn main() {
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("OUT_DIR"));
    let chosen: Vec<&str> = BOARDS
        .into_iter()
        .filter(|board| {
            let feature = format!("CARGO_FEATURE_{}", board.to_uppercase().replace('-', "_"));
            std::env::var_os(feature).is_some()
        })
        .collect();
    let [board] = chosen[..] else {
        panic!(
            "enable exactly one board feature of {BOARDS:?}, not {chosen:?} \
             (for QEMU: --no-default-features --features qemu-mps2-an386)"
        );
    };
    std::fs::copy(format!("memory/{board}.x"), out.join("memory.x")).expect("copy the memory layout");
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rustc-link-arg-bins=-Tlink.x");
    println!("cargo:rerun-if-changed=memory");
    println!("cargo:rerun-if-changed=data/run.csv");

    let csv = std::fs::read_to_string("data/run.csv").expect("read data/run.csv");
    let mut lines = csv.lines().enumerate().filter(|(_, line)| !line.trim().is_empty());
    let (_, header) = lines.next().expect("data/run.csv: a header");
    let columns: Vec<&str> = header.split(',').map(str::trim).collect();
    let mut rows = String::new();
    let mut count = 0;
    for (n, line) in lines {
        let cells: Vec<&str> = line.split(',').map(str::trim).collect();
        assert_eq!(cells.len(), columns.len(), "data/run.csv line {}: cells", n + 1);
        // The f32 nearest each recorded decimal, written as its bits: exactly what a reader of the
        // CSV gets, whatever the compiler does with float literals.
        let values: Vec<String> = cells
            .iter()
            .map(|cell| {
                let value: f32 = cell
                    .parse()
                    .unwrap_or_else(|e| panic!("data/run.csv line {}: {cell:?}: {e}", n + 1));
                format!("f32::from_bits(0x{:08x})", value.to_bits())
            })
            .collect();
        writeln!(rows, "    [{}], // {line}", values.join(", ")).expect("write to a String");
        count += 1;
    }
    let names: Vec<String> = columns.iter().map(|c| format!("{c:?}")).collect();
    let recorded = format!(
        "/// The columns of data/run.csv, in order.\n\
         pub const COLUMNS: [&str; {width}] = [{names}];\n\
         /// Its rows, in time order.\n\
         pub const ROWS: [[f32; {width}]; {count}] = [\n{rows}];\n",
        width = columns.len(),
        names = names.join(", "),
    );
    std::fs::write(out.join("recorded.rs"), recorded).expect("write recorded.rs");
}
