//! The design search is bounded (issue 30, item 10): its candidates are counted before anything is
//! fitted, a search above `[search] max_candidates` is refused naming the file, the field, the count,
//! the limit and the fix, and without a terminal the search says how far it is in plain lines.
//!
//! Every case runs the CLI as a user would, on spec files in a temporary folder.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn host(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_mho")).args(args).output().unwrap()
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("host-search-bound-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The shipped `vanderpol_searched` spec with its `[map]` candidates replaced by `map` (lines of
/// TOML), run lengths of `samples`, and `extra` appended (e.g. a `[search]` table).
fn spec(dir: &Path, map: &str, samples: usize, extra: &str) -> PathBuf {
    let shipped =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("specs/vanderpol_searched.toml")).unwrap();
    let mut text = String::new();
    for line in shipped.lines() {
        let line = if line.starts_with("horizon = ") || line.starts_with("nm = ") || line.starts_with("beta = ") {
            continue;
        } else if line.starts_with("samples = ") {
            format!("samples = {samples}")
        } else if line == "[map]" {
            format!("[map]\n{map}")
        } else {
            line.to_owned()
        };
        text.push_str(&line);
        text.push('\n');
    }
    text.push_str(extra);
    let path = dir.join("oscillator.toml");
    std::fs::write(&path, text).unwrap();
    path
}

/// `gen --spec FILE --out DIR` with the checkout's runtime.
fn gen(spec: &Path, out: &Path) -> Output {
    let firmware = Path::new(env!("CARGO_MANIFEST_DIR")).join("../firmware");
    host(&[
        "gen",
        "--spec",
        s(spec),
        "--out",
        s(out),
        "--runtime-path",
        s(&firmware),
    ])
}

fn list<T: std::fmt::Display>(values: impl IntoIterator<Item = T>) -> String {
    let items: Vec<String> = values.into_iter().map(|v| v.to_string()).collect();
    format!("[{}]", items.join(", "))
}

fn refused(output: &Output) -> String {
    assert!(
        !output.status.success(),
        "accepted:\n{}",
        String::from_utf8_lossy(&output.stdout)
    );
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// 400 horizons × 10 n_m × 15 β = 60,000 candidates, above the default 5,000: refused before
/// anything is simulated or fitted (the run would take hours at these horizons), naming the file,
/// the field with the most values, the count, the limit and both fixes. `--out` is not created.
#[test]
fn a_search_above_the_default_limit_is_refused_before_fitting() {
    let dir = scratch("default");
    let horizons = list(5..=404);
    let nms = list(2..=11);
    let betas = list((1..=15).map(|k| k as f64 / 10.0));
    let path = spec(
        &dir,
        &format!("horizon = {horizons}\nnm = {nms}\nbeta = {betas}"),
        500,
        "",
    );
    let out = dir.join("out");
    let started = std::time::Instant::now();
    let stderr = refused(&gen(&path, &out));
    println!("{stderr}\n(refused in {:.2} s)", started.elapsed().as_secs_f64());
    assert!(stderr.contains(s(&path)), "{stderr}");
    assert!(stderr.contains("`map.horizon`"), "{stderr}");
    assert!(
        stderr.contains("60000 candidates (400 of `map.horizon` × 10 of `map.nm` × 15 of `map.beta`)"),
        "{stderr}"
    );
    assert!(stderr.contains("above the limit of 5000"), "{stderr}");
    assert!(stderr.contains("offer fewer values in `map.horizon`"), "{stderr}");
    assert!(stderr.contains("`[search]` `max_candidates = 60000`"), "{stderr}");
    // Nothing ran: no progress line, no folder written.
    assert!(!stderr.contains("candidates to fit"), "{stderr}");
    assert!(!out.exists());
}

/// The count is every `(N, n_m, β)` once per distinct tap count its regressor keeps (N entries for
/// this one-output plant): counted by hand, N = 3 keeps min(4, 3) = min(8, 3) = 3 taps (one
/// candidate), N = 8 and N = 12 keep 8 and 4 (two each): (1 + 2 + 2) × 2 n_m × 2 β = 20. One
/// below is refused with that count; at the count, the search runs and its summary counts as many.
/// Piped (no terminal), it prints plain progress lines with "of 20".
#[test]
fn the_count_is_exact_and_a_piped_search_prints_progress_lines() {
    let dir = scratch("count");
    let map = "horizon = [3, 8, 12]\nnm = [3, 5]\nbeta = [0.5, 1.0]\ntaps = [4, 8]";
    let path = spec(&dir, map, 100, "\n[search]\nmax_candidates = 19\n");
    let out = dir.join("out");
    let stderr = refused(&gen(&path, &out));
    assert!(stderr.contains(s(&path)), "{stderr}");
    assert!(stderr.contains("the search has 20 candidates"), "{stderr}");
    assert!(stderr.contains("above the limit of 19"), "{stderr}");
    assert!(stderr.contains("max_candidates = 20"), "{stderr}");
    assert!(!out.exists());

    let path = spec(&dir, map, 100, "\n[search]\nmax_candidates = 20\n");
    let output = host(&["search", "--spec", s(&path)]);
    let stdout = String::from_utf8_lossy(&output.stdout);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{stderr}");
    assert!(stdout.contains("search: 20 candidates"), "{stdout}");
    assert!(stderr.contains("search: 20 candidates to fit (at most 20"), "{stderr}");
    let lines: Vec<&str> = stderr.lines().filter(|l| l.contains(" of 20 candidates")).collect();
    assert!(!lines.is_empty(), "no progress line:\n{stderr}");
    assert!(
        lines.last().unwrap().contains("20 of 20 candidates (100 %)"),
        "{stderr}"
    );
}

/// `search --auto` replaces the spec's candidates by the default ones, 36 N × 3 n_m × 4 β = 432,
/// and still honours the spec's limit.
#[test]
fn search_auto_honours_the_limit_of_a_spec_that_fixes_its_map() {
    let dir = scratch("auto");
    let path = spec(
        &dir,
        "horizon = 10\nnm = 5\nbeta = 0.5",
        100,
        "\n[search]\nmax_candidates = 100\n",
    );
    let stderr = refused(&host(&["search", "--spec", s(&path), "--auto"]));
    assert!(stderr.contains(s(&path)), "{stderr}");
    assert!(
        stderr.contains("432 candidates (36 of `map.horizon` × 3 of `map.nm` × 4 of `map.beta`)"),
        "{stderr}"
    );
    assert!(stderr.contains("above the limit of 100"), "{stderr}");
}

/// A `max_candidates` that is not a whole number ≥ 1, or a misspelt key, is refused by `gen`
/// naming the file and the field, with the fix.
#[test]
fn a_bad_max_candidates_is_refused_naming_the_field() {
    let dir = scratch("bad");
    let map = "horizon = [8, 10]\nnm = 5\nbeta = 0.5";
    for (value, problem) in [
        ("0", "0 allows no candidate"),
        ("-3", "-3 allows no candidate"),
        ("2.5", "`2.5` is not a whole number"),
        ("\"lots\"", "`\"lots\"` is not a whole number"),
    ] {
        let path = spec(&dir, map, 100, &format!("\n[search]\nmax_candidates = {value}\n"));
        let stderr = refused(&gen(&path, &dir.join("out")));
        assert!(stderr.contains(s(&path)), "{value}: {stderr}");
        assert!(stderr.contains("`search.max_candidates`"), "{value}: {stderr}");
        assert!(stderr.contains(problem), "{value}: {stderr}");
        assert!(
            stderr.contains("set `search.max_candidates` to a whole number ≥ 1"),
            "{value}: {stderr}"
        );
        assert!(!dir.join("out").exists());
    }
    let path = spec(&dir, map, 100, "\n[search]\nmax_candiates = 10\n");
    let stderr = refused(&gen(&path, &dir.join("out")));
    assert!(stderr.contains(s(&path)), "{stderr}");
    assert!(stderr.contains("max_candiates"), "{stderr}");
    assert!(stderr.contains("max_candidates"), "{stderr}");
}
