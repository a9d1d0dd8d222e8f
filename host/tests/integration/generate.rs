//! `gen` is all or nothing: names, families and every design are checked before any file is written,
//! so a failing run leaves `generated/` and the reports exactly as they were.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use host::generate::{self, Destinations, GenerateError};
use indicatif::ProgressBar;

/// A scratch folder with a copy of the shipped `generated/src` and the specs written into it.
struct Scratch {
    root: PathBuf,
}

impl Scratch {
    fn new(name: &str) -> Self {
        let root = std::env::temp_dir().join(format!("host-generate-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&root);
        let sources = root.join("generated/src");
        std::fs::create_dir_all(&sources).unwrap();
        let shipped = Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated/src");
        for entry in std::fs::read_dir(shipped).unwrap() {
            let path = entry.unwrap().path();
            std::fs::copy(&path, sources.join(path.file_name().unwrap())).unwrap();
        }
        Scratch { root }
    }

    /// An empty scratch folder (no generated crate yet).
    fn empty(name: &str) -> Self {
        let root = std::env::temp_dir().join(format!("host-generate-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&root);
        std::fs::create_dir_all(&root).unwrap();
        Scratch { root }
    }

    /// Writes a shipped spec, edited, as `file`.
    fn spec(&self, shipped: &str, file: &str, edits: &[(&str, &str)]) -> PathBuf {
        let mut text =
            std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("specs/{shipped}.toml")))
                .unwrap();
        for (from, to) in edits {
            assert!(text.contains(from), "`{from}` not in {shipped}.toml");
            text = text.replacen(from, to, 1);
        }
        let path = self.root.join(file);
        std::fs::write(&path, text).unwrap();
        path
    }

    fn destinations(&self) -> Destinations {
        Destinations {
            reports: self.root.join("reports"),
            generated: self.root.join("generated"),
        }
    }

    /// Every file under the scratch folder's `generated/` and `reports/`, with its bytes.
    fn files(&self) -> BTreeMap<PathBuf, Vec<u8>> {
        fn walk(dir: &Path, into: &mut BTreeMap<PathBuf, Vec<u8>>) {
            let Ok(entries) = std::fs::read_dir(dir) else { return };
            for entry in entries {
                let path = entry.unwrap().path();
                if path.is_dir() {
                    walk(&path, into);
                } else {
                    into.insert(path.clone(), std::fs::read(&path).unwrap());
                }
            }
        }
        let mut files = BTreeMap::new();
        walk(&self.root.join("generated"), &mut files);
        walk(&self.root.join("reports"), &mut files);
        files
    }

    fn run(&self, specs: &[PathBuf]) -> Result<Vec<generate::Outcome>, GenerateError> {
        generate::run(specs, &self.destinations(), false, |_| ProgressBar::hidden(), |_, _| {})
    }

    /// `gen` (`--strict` with `strict`) on one spec, with what each design ended in: the spec errors
    /// (field and problem) and the quality gates' warnings.
    fn run_one(&self, spec: PathBuf, strict: bool) -> Ended {
        let mut ended = Ended::default();
        ended.run = Some(generate::run(
            &[spec],
            &self.destinations(),
            strict,
            |_| ProgressBar::hidden(),
            |_, done: Result<&generate::Prepared, &GenerateError>| match done {
                Ok(prepared) => ended.warnings.extend(prepared.warnings.iter().map(ToString::to_string)),
                Err(GenerateError::Spec(e)) => ended.errors.push((e.field.clone(), e.problem.clone())),
                Err(_) => {}
            },
        ));
        ended
    }
}

/// What [`Scratch::run_one`] saw.
#[derive(Default)]
struct Ended {
    run: Option<Result<Vec<generate::Outcome>, GenerateError>>,
    errors: Vec<(String, String)>,
    warnings: Vec<String>,
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.root);
    }
}

/// Example 1's edits to 8 validation and 8 tuning runs (of 64): for the cases whose point is not a
/// figure, a third of the time.
const FEW_RUNS: [(&str, &str); 2] = [
    ("\ntrajectories = 64", "\ntrajectories = 8"),
    ("[tuning]", "[tuning]\ntrajectories = 8"),
];

#[test]
fn a_design_that_breaks_its_family_writes_nothing() {
    // E. coli X0 = 2 with N = 4 no longer shares its family's observer type (N = 3): refused before
    // its file is rewritten (it used to be rewritten, leaving lib.rs declaring an N = 3 family).
    let scratch = Scratch::new("family");
    let spec = scratch.spec("ecoli_x0_2", "ecoli_x0_2.toml", &[("horizon = 3", "horizon = 4")]);
    let before = scratch.files();
    match scratch.run(&[spec]) {
        Err(GenerateError::Family(e)) => assert!(e.to_string().contains("ecoli_x0_2"), "{e}"),
        other => panic!("expected a family error, got {:?}", other.map(|_| ())),
    }
    assert!(scratch.files() == before, "a failed gen changed files");
}

#[test]
fn regenerating_one_member_of_a_family_keeps_the_others() {
    // `gen --spec a --spec b --generated g`, then `gen --spec a --generated g`: b's spec is not in the
    // second run, its file is; the family keeps both members (b used to leave it silently).
    let scratch = Scratch::empty("family-regenerated");
    let member = |name: &str, value: &str| {
        scratch.spec(
            "vanderpol",
            &format!("{name}.toml"),
            &[
                ("name = \"vanderpol\"", &format!("name = \"{name}\"")),
                ("\ntrajectories = 64", "\ntrajectories = 8"),
                ("[tuning]", "[tuning]\ntrajectories = 8"),
                (
                    "[observer]",
                    &format!("[family]\nname = \"fam\"\noutput = \"y\"\nvalue = {value}\n\n[observer]"),
                ),
            ],
        )
    };
    let (a, b) = (member("fam_a", "1.0"), member("fam_b", "2.5"));
    scratch.run(&[a.clone(), b]).unwrap();
    let lib = scratch.root.join("generated/src/lib.rs");
    let both = std::fs::read_to_string(&lib).unwrap();
    assert!(
        both.contains("pub mod fam {") && both.contains("(`fam_a` at 1.0, `fam_b` at 2.5)"),
        "{both}"
    );
    scratch.run(&[a]).unwrap();
    assert_eq!(std::fs::read_to_string(&lib).unwrap(), both);
}

#[test]
fn a_design_named_like_a_family_is_refused_before_anything_is_written() {
    // A design `ecoli` would write ecoli.rs beside the family module `ecoli` of lib.rs.
    let scratch = Scratch::new("family-name");
    let spec = scratch.spec(
        "vanderpol",
        "ecoli.toml",
        &[("name = \"vanderpol\"", "name = \"ecoli\"")],
    );
    let before = scratch.files();
    match scratch.run(&[spec]) {
        Err(GenerateError::Family(e)) => assert!(e.to_string().contains("ecoli"), "{e}"),
        other => panic!("expected a name clash, got {:?}", other.map(|_| ())),
    }
    assert!(scratch.files() == before, "a failed gen changed files");
}

#[test]
fn two_specs_naming_one_design_are_refused() {
    let scratch = Scratch::new("duplicate");
    let first = scratch.spec("vanderpol", "a.toml", &[]);
    let second = scratch.spec("vanderpol", "b.toml", &[("beta = 0.5", "beta = 1.0")]);
    let before = scratch.files();
    match scratch.run(&[first, second]) {
        Err(GenerateError::DuplicateName { name, .. }) => assert_eq!(name, "vanderpol"),
        other => panic!("expected a duplicate name, got {:?}", other.map(|_| ())),
    }
    assert!(scratch.files() == before, "a failed gen changed files");
}

/// Issue 48: `vdp` and `vdp_map` in one run would both declare `vdp_map_init` (the map observer of
/// `vdp`, the storage call of `vdp_map`) and a C program could not link both; refused before anything
/// is fitted, naming both spec files, the field and the fix. Names that only share a prefix
/// (`vanderpol`, `vanderpol_uncertain`) stay free.
#[test]
fn two_specs_whose_c_names_would_clash_are_refused() {
    let scratch = Scratch::new("c-names");
    let first = scratch.spec("vanderpol", "vdp.toml", &[("name = \"vanderpol\"", "name = \"vdp\"")]);
    let second = scratch.spec(
        "vanderpol",
        "vdp_map.toml",
        &[("name = \"vanderpol\"", "name = \"vdp_map\"")],
    );
    let before = scratch.files();
    match scratch.run(&[first, second]) {
        Err(e @ GenerateError::CNameClash { .. }) => {
            let text = e.to_string();
            for part in [
                "vdp.toml",
                "vdp_map.toml",
                "field `name`",
                "vdp_map_init",
                "rename one",
                "vdpmap",
            ] {
                assert!(text.contains(part), "{part} missing: {text}");
            }
        }
        other => panic!("expected a C name clash, got {:?}", other.map(|_| ())),
    }
    assert!(scratch.files() == before, "a refused gen changed files");
    // Every kind and every word the C interface appends, either way round; not a mere shared prefix.
    use host::emit::c::{c_name_clash, C_SUFFIX_WORDS};
    for kind in [
        "map",
        "fixed",
        "ekf_box",
        "ekf_map",
        "ekf_restart",
        "ukf_box",
        "corrected",
        "mhe",
        "observer",
    ] {
        assert!(c_name_clash("vdp", &format!("vdp_{kind}")).is_some(), "{kind}");
        assert!(c_name_clash(&format!("vdp_{kind}_2"), "vdp").is_some(), "{kind}");
    }
    for word in C_SUFFIX_WORDS {
        assert_eq!(c_name_clash("vdp", &format!("vdp_{word}")).as_deref(), Some(*word));
    }
    for (a, b) in [
        ("vanderpol", "vanderpol_uncertain"),
        ("vanderpol", "vanderpol_searched"),
        ("vdp", "vdpmap"),
        ("ecoli_x0_0p5", "ecoli_x0_2"),
        ("vdp", "vdp2_map"),
    ] {
        assert_eq!(c_name_clash(a, b), None, "{a} {b}");
    }
}

#[test]
fn one_failing_design_writes_nothing_for_any_design() {
    // x2's target made constant: the fit refuses it. The other design fits, but nothing is written:
    // no report, no observer, no lib.rs (it used to write lib.rs even when every spec failed).
    let scratch = Scratch::empty("one-fails");
    let good = scratch.spec("vanderpol", "vanderpol.toml", &FEW_RUNS);
    let bad = scratch.spec(
        "vanderpol",
        "constant.toml",
        &[
            ("name = \"vanderpol\"", "name = \"constant_target\""),
            ("expr = \"x2\"", "expr = \"x1 - x1 + 1.0\""),
            FEW_RUNS[0],
            FEW_RUNS[1],
        ],
    );
    let mut heard = Vec::new();
    let result = generate::run(
        &[good, bad.clone()],
        &scratch.destinations(),
        false,
        |_| ProgressBar::hidden(),
        |spec, outcome| heard.push((spec.to_owned(), outcome.is_ok())),
    );
    assert!(
        matches!(result, Err(GenerateError::Failed { failed: 1, total: 2 })),
        "{:?}",
        result.map(|_| ())
    );
    assert_eq!(heard.len(), 2);
    assert!(heard.contains(&(bad, false)), "the failing spec is named: {heard:?}");
    assert!(
        scratch.files().is_empty(),
        "files written: {:?}",
        scratch.files().keys().collect::<Vec<_>>()
    );
}

#[test]
fn a_sample_period_that_underflows_in_f32_is_refused_naming_the_field() {
    // τ = 1e-300 used to be emitted as `SAMPLE_PERIOD: f32 = 0.0` with exit 0, then refused only
    // once fitted: now when the spec is read, before anything is fitted.
    let scratch = Scratch::empty("underflow");
    let spec = scratch.spec("vanderpol", "vanderpol.toml", &[("tau = 0.1", "tau = 1e-300")]);
    let error = match host::spec::load(&spec) {
        Err(e) => e.to_string(),
        Ok(_) => panic!("τ = 1e-300 was accepted"),
    };
    assert!(
        error.contains("vanderpol.toml")
            && error.contains("sampling.tau")
            && error.contains("f32")
            && error.contains("time_unit"),
        "{error}"
    );
    assert!(scratch.run(&[spec]).is_err());
    assert!(scratch.files().is_empty());
}

#[test]
fn a_description_cannot_open_a_code_fence_in_the_generated_docs() {
    // `description = "```"` made the generated file start a doctest that failed.
    let scratch = Scratch::empty("fence");
    let spec = scratch.spec(
        "vanderpol",
        "vanderpol.toml",
        &[
            (
                "description = \"Van der Pol",
                "description = \"```\\n    fn injected() {} <b> [x] Van der Pol",
            ),
            FEW_RUNS[0],
            FEW_RUNS[1],
        ],
    );
    let design = host::spec::load(&spec).unwrap();
    let emitted = generate::emit_design(design, &spec, None, &ProgressBar::hidden()).unwrap();
    let first = emitted.source.lines().next().unwrap();
    assert_eq!(
        first,
        r"//! \`\`\`     fn injected() {} \<b\> \[x\] Van der Pol oscillator, x1 and x2 from y = x1 + x2 + w (paper Example 1)"
    );
}

#[test]
fn a_target_the_measurements_do_not_show_is_named_in_a_warning() {
    // A third state `z` that nothing measures (z' = 0, drawn from a grid): its map can only return about
    // the mean, and gen used to emit it without a word.
    let scratch = Scratch::empty("weak");
    let spec = scratch.spec(
        "vanderpol",
        "vanderpol.toml",
        &[
            ("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\", \"z\"]"),
            (
                "x2 = \"4*x1 + (1 - x1^2)*x2\"",
                "x2 = \"4*x1 + (1 - x1^2)*x2\"\nz = \"0\"",
            ),
            (
                "grid.x2 = { min = -5.0, max = 5.0, points = 4 }",
                "grid.x2 = { min = -5.0, max = 5.0, points = 4 }\ngrid.z = { min = 0.0, max = 1.0, points = 3 }",
            ),
            ("x0 = { x1 = 2.0, x2 = 0.5 }", "x0 = { x1 = 2.0, x2 = 0.5, z = 0.5 }"),
            (
                "observer_x0 = { x1 = 1.0, x2 = 0.7 }",
                "observer_x0 = { x1 = 1.0, x2 = 0.7, z = 0.5 }",
            ),
            (
                "[[targets]]\nname = \"x2\"",
                "[[targets]]\nname = \"z\"\nexpr = \"z\"\n\n[[targets]]\nname = \"x2\"",
            ),
        ],
    );
    let design = host::spec::load(&spec).unwrap();
    let emitted = generate::emit_design(design, &spec, None, &ProgressBar::hidden()).unwrap();
    let gates = host::report::gates::check(&emitted.design, &emitted.result, &emitted.comparison);
    let warnings: Vec<String> = gates.iter().map(ToString::to_string).collect();
    let weak = gates
        .iter()
        .position(|g| matches!(g, host::report::gates::Gate::Weak { target, .. } if target == "z"));
    assert!(
        weak.is_some_and(|i| warnings[i].contains("may not be observable")),
        "{warnings:?}"
    );
    // Every other warning is about `z` too: its own, runs every kind lost (nothing observes `z`, so
    // no kind does better than its mean on the runs that start far from it), or a filter better on
    // another target than the kind `auto` took, where `z` (weight 1) weighed in the score.
    assert!(
        gates.iter().zip(&warnings).all(|(g, w)| w.starts_with("target `z`")
            || matches!(
                g,
                host::report::gates::Gate::LostRuns { .. } | host::report::gates::Gate::EkfBetter { .. }
            )),
        "{warnings:?}"
    );
}

#[test]
fn measurements_beyond_f32_are_blamed_on_their_scale_not_on_beta() {
    // A noise variance of 1e300 used to end in an f32 mismatch advising a lower β.
    let scratch = Scratch::empty("huge-noise");
    let spec = scratch.spec(
        "vanderpol",
        "vanderpol.toml",
        &[("noise_variance = 0.2", "noise_variance = 1e300")],
    );
    let design = host::spec::load(&spec).unwrap();
    let error = match generate::emit_design(design, &spec, None, &ProgressBar::hidden()) {
        Err(e) => e.to_string(),
        Ok(_) => panic!("measurements of 1e150 were emitted"),
    };
    assert!(
        error.contains("beyond the range of f32") && !error.contains("map.beta"),
        "{error}"
    );
}

#[test]
fn every_observer_is_judged_on_every_named_scenario_and_auto_tunes_on_each() {
    // Example 1 with three scenarios: the paper's, the same again under another name (its figures
    // must be the paper's to the bit: the index of a scenario, not its place, picks its run), and a
    // start-up elsewhere in the box, without an observer start.
    let scratch = Scratch::empty("scenarios");
    let spec = scratch.spec(
        "vanderpol",
        "vanderpol.toml",
        &[
            FEW_RUNS[0],
            FEW_RUNS[1],
            ("[scenario]", "[[scenario]]\nname = \"paper\""),
            (
                "kind = \"auto\"",
                "kind = \"auto\"\n\n[[scenario]]\nname = \"again\"\nx0 = { x1 = 2.0, x2 = 0.5 }\nobserver_x0 = { x1 = 1.0, x2 = 0.7 }\nsamples = 101\nseed = 7\n\n[[scenario]]\nname = \"start_up\"\nx0 = { x1 = -1.5, x2 = 3.0 }\nsamples = 60\nseed = 11",
            ),
        ],
    );
    let design = host::spec::load(&spec).unwrap();
    let names: Vec<&str> = design.scenarios.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["paper", "again", "start_up"]);
    let emitted = generate::emit_design(design, &spec, None, &ProgressBar::hidden()).unwrap();
    let (design, result, comparison) = (&emitted.design, &emitted.result, &emitted.comparison);
    // The tuning runs: 8 from random starts, then 16 from each scenario's start, then 8 from the box's
    // edges (2 n + 2ⁿ for two states).
    let tuning = &result.runs.tuning.runs;
    assert_eq!(tuning.len(), 8 + 3 * host::data::SCENARIO_TUNING_RUNS + 8);
    for (i, scenario) in design.scenarios.iter().enumerate() {
        let first = 8 + i * host::data::SCENARIO_TUNING_RUNS;
        for run in &tuning[first..first + host::data::SCENARIO_TUNING_RUNS] {
            assert_eq!(run.states[0], scenario.x0[..], "{}", scenario.name);
            assert_eq!(run.states.len(), scenario.samples);
        }
    }
    // Each scenario's tuning runs have noise of their own, even where two scenarios start alike.
    assert_ne!(tuning[8].measurements[0], tuning[8 + 16].measurements[0]);
    for o in &comparison.observers {
        for f in &o.targets {
            assert_eq!(f.scenarios.len(), 3, "{}", o.kind);
            // The first scenario is the headline one: the same figures by both routes.
            assert_eq!(f.scenarios[0], (f.rmse_scenario, f.rmse_transient), "{}", o.kind);
            let bits = |(a, b): (f64, f64)| (a.to_bits(), b.to_bits());
            assert_eq!(
                bits(f.scenarios[1]),
                bits(f.scenarios[0]),
                "{}: `again` is `paper`",
                o.kind
            );
            assert_ne!(f.scenarios[2], f.scenarios[0], "{}", o.kind);
        }
    }
    // The box filters from the observer start the first two name (not the third, which names none).
    let from: Vec<(&str, usize)> = comparison
        .from_observer_start
        .iter()
        .map(|f| (f.kind, f.scenario))
        .collect();
    assert_eq!(from, [("ekf_box", 0), ("ekf_box", 1), ("ukf_box", 0), ("ukf_box", 1)]);
    let report = host::report::report(design, result, comparison);
    let markdown = host::report::markdown(&report);
    for line in [
        "## Scenarios",
        "### `paper`: x(0) = (2, 0.5), observer start (1, 0.7), 101 samples, seed 7",
        "### `start_up`: x(0) = (-1.5, 3), 60 samples, seed 11",
        "| ekf_box from the observer start |",
        "| other scenarios | 2 | 60–101 | 7, 11 |",
    ] {
        assert!(markdown.contains(line), "report.md lacks {line:?}:\n{markdown}");
    }
    // The paper's comparison, the EKF from the paper's x̂(0), is the first scenario's entry.
    let (_, rmse) = report.ekf_from_observer_x0.as_ref().unwrap();
    let ekf = &comparison.from_observer_start[0];
    assert_eq!(rmse, &ekf.targets.iter().map(|t| t.0).collect::<Vec<_>>());
}

#[test]
fn a_fixed_filter_start_where_the_model_blows_up_is_named_not_dropped() {
    // `[observer.ekf] x0` far outside the model's domain: every candidate of the EKF's search
    // diverges. The EKF's kinds used to vanish in silence from the report and the crate under `auto`,
    // and with `kind = "ekf_box"` gen refused for the wrong reason ("needs a model the host can filter").
    let scratch = Scratch::empty("fixed-blow-up");
    for kind in ["auto", "ekf_box"] {
        let observer = format!("[observer.ekf]\nx0 = {{ x1 = 1e3, x2 = 1e3 }}\n\n[observer]\nkind = \"{kind}\"\n#");
        let spec = scratch.spec(
            "vanderpol",
            "vanderpol.toml",
            &[FEW_RUNS[0], FEW_RUNS[1], ("[observer]\nkind = \"auto\"", &observer)],
        );
        let ended = scratch.run_one(spec, false);
        assert!(ended.run.is_some_and(|r| r.is_err()), "{kind}: gen went on");
        let [(field, problem)] = &ended.errors[..] else {
            panic!("{kind}: expected the fixed start named, got {:?}", ended.errors)
        };
        assert_eq!(field, "observer.ekf.x0", "{kind}: {problem}");
        assert!(
            problem.contains("x1 = 1e3, x2 = 1e3") && problem.contains("the model is not finite"),
            "{kind}: {problem}"
        );
    }
    assert!(scratch.files().is_empty(), "nothing is written");
}

#[test]
fn converter_ranges_that_miss_the_signal_or_leave_no_bits_are_said() {
    let scratch = Scratch::empty("raw-ranges");
    // A 12-bit converter scaled to 0.001 per count covers [-10.24, -6.145]: y spans about ±7 in the
    // learning runs. The integer map then refuses nearly every sample, and nothing used to say so.
    let short = scratch.spec(
        "vanderpol",
        "vanderpol.toml",
        &[FEW_RUNS[0], FEW_RUNS[1], ("scale = 0.005", "scale = 0.001")],
    );
    let ended = scratch.run_one(short, true);
    assert!(
        matches!(ended.run, Some(Err(GenerateError::Gates { .. }))),
        "--strict refuses it"
    );
    let coverage = ended
        .warnings
        .iter()
        .find(|w| w.starts_with("`chip.raw.y`"))
        .expect("the range gate");
    assert!(
        coverage.contains("stands for [-10.2400, -6.1450]") && coverage.contains("% of their samples outside"),
        "{coverage}"
    );
    // A 24-bit converter over the same span: the proven distance of the integer map to the float
    // map was 16 % of x1's range, accepted. Refused, naming the converter and the fix.
    let wide = scratch.spec(
        "vanderpol",
        "vanderpol.toml",
        &[
            FEW_RUNS[0],
            FEW_RUNS[1],
            ("scale = 0.005", "scale = 1.220703125e-6"),
            ("max = 4095", "max = 16777215"),
        ],
    );
    let ended = scratch.run_one(wide, false);
    assert!(ended.run.is_some_and(|r| r.is_err()));
    let [(field, problem)] = &ended.errors[..] else {
        panic!("{:?}", ended.errors)
    };
    assert_eq!(field, "chip.raw.y");
    assert!(
        problem.contains("proven distance") && problem.contains("(at most 2 % is accepted)"),
        "{problem}"
    );
    assert!(scratch.files().is_empty(), "nothing is written");
}
