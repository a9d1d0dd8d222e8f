//! The fixed-point map (`[chip] arithmetic = "fixed"`, `host::fixed_point`): its integers are the
//! f64 map's gains rounded as the proof allows, its proven bound on |fixed − f64 map| holds on every
//! validation window and is not loose by more than 10× (Example 1), it is as accurate as the f32
//! map, and the generated Rust and C give the firmware library's bits (on the host here; on the
//! emulated Cortex-M0 and M4F in `on_target.rs`).

use std::io::Write as _;
use std::process::{Command, Stdio};

use host::fixed_point::{self, FixedPoint};
use host::spec::Design;
use integration_tests::{build, load_relative};

/// Example 1 and its integer map.
fn example_1() -> (Design, std::sync::Arc<host::fit::DesignResult>, FixedPoint) {
    let design = load_relative("host/specs/vanderpol.toml");
    let result = build(&design);
    let spec = design.fixed.clone().expect("Example 1 asks for the fixed-point map");
    let maps: Vec<_> = result.targets.iter().map(|t| t.fit.map.clone()).collect();
    let fixed = fixed_point::quantise(&design, &spec, &result.runs.learning, &maps).expect("it quantises");
    (design, result, fixed)
}

/// `G_i 2^F` and `C 2^F` recomputed here from the f64 table and the declared scaling (independently
/// of the quantiser): every emitted integer must be within half an LSB of it.
fn rounding_excess(
    design: &Design,
    fixed: &FixedPoint,
    table: &host::fit::inverse_table::InverseTable,
    t: usize,
) -> f64 {
    let target = &fixed.targets[t];
    let unit = 2f64.powi(target.fraction_bits as i32);
    let y = fixed.outputs[0];
    assert_eq!(design.model.outputs.len(), 1);
    let offset = table.offset + table.gains.iter().map(|g| g * y.offset).sum::<f64>();
    let mut excess = (f64::from(target.offset) - offset * unit).abs() - 0.5;
    for (g, q) in table.gains.iter().zip(&target.gains) {
        excess = excess.max((f64::from(*q) - g * y.scale * unit).abs() - 0.5);
    }
    excess
}

#[test]
fn example_1s_integers_are_its_gains_rounded_to_the_nearest_and_one_lsb_more_is_caught() {
    let (design, result, fixed) = example_1();
    for (t, target) in result.targets.iter().enumerate() {
        let table = target.fit.map.table.as_ref().unwrap();
        assert!(rounding_excess(&design, &fixed, table, t) <= 1e-6, "target {t}");
        // One LSB further from the exact value than its rounding: half an LSB beyond what is allowed.
        let mut perturbed = fixed.clone();
        let exact = table.gains[0] * fixed.outputs[0].scale * 2f64.powi(fixed.targets[t].fraction_bits as i32);
        perturbed.targets[t].gains[0] += if f64::from(fixed.targets[t].gains[0]) >= exact {
            1
        } else {
            -1
        };
        assert!(
            rounding_excess(&design, &perturbed, table, t) >= 0.5 - 1e-9,
            "target {t}: a gain one LSB off passes"
        );
    }
}

#[test]
fn example_1s_fixed_point_map_is_within_its_proven_bound_on_every_validation_window() {
    let (design, result, fixed) = example_1();
    let maps: Vec<_> = result.targets.iter().map(|t| t.fit.map.clone()).collect();
    let comparison = fixed_point::compare(&fixed, &maps, &result.runs.validation);
    assert_eq!(comparison.windows, result.runs.validation.window_count());
    for (t, (figures, target)) in comparison.targets.iter().zip(&fixed.targets).enumerate() {
        let name = &design.targets[t].name;
        let bound = target.bound.total();
        let range = maps[t].r_max - maps[t].r_min;
        let float_rmse = result.targets[t].validation.map.rmse;
        println!(
            "{name}: bound {bound:.3e} ({:?}), largest {:.3e}, ratio {:.1}, {:.3} % of the range; rmse {:.5} vs f32 {float_rmse:.5}; F {} P {} R {}",
            target.bound,
            figures.largest_difference,
            bound / figures.largest_difference,
            100.0 * bound / range,
            figures.rmse,
            target.fraction_bits,
            target.product_bits,
            target.lsb_bits
        );
        assert!(
            figures.beyond_bound.is_empty(),
            "{name}: windows beyond the bound: {:?}",
            figures.beyond_bound
        );
        assert!(
            bound <= 10.0 * figures.largest_difference,
            "{name}: the bound {bound:e} is loose"
        );
        assert!(
            bound <= 0.01 * range,
            "{name}: the bound {bound:e} is over 1 % of the range {range}"
        );
        assert!(
            figures.rmse <= 1.02 * float_rmse,
            "{name}: RMSE {} against the f32 map's {float_rmse}",
            figures.rmse
        );
    }
    // The window check bites: the offset moved by twice the bound's worth of t (at the table's
    // smallest slope) puts windows beyond the bound.
    for t in 0..fixed.targets.len() {
        let mut perturbed = fixed.clone();
        let target = &mut perturbed.targets[t];
        let slope = target
            .segments
            .iter()
            .map(|[_, b]| f64::from(b.abs()))
            .fold(f64::INFINITY, f64::min)
            * target.lsb();
        let shift = 2.0 * target.bound.total() / slope * 2f64.powi(target.fraction_bits as i32);
        target.offset += shift.ceil() as i32;
        let caught = fixed_point::compare(&perturbed, &maps, &result.runs.validation);
        assert!(
            !caught.targets[t].beyond_bound.is_empty(),
            "target {t}: the perturbed map passes"
        );
    }
}

#[test]
fn example_1s_generated_integers_are_the_proven_ones() {
    let (_, _, fixed) = example_1();
    use firmware::emitted::fixed::FixedDesign;
    let generated = <generated::vanderpol::Fixed as FixedDesign<10, 1, 0, 2>>::MAPS;
    for (emitted, proven) in generated.iter().zip(&fixed.targets) {
        assert_eq!(*emitted, proven.as_firmware());
    }
    for (t, proven) in fixed.targets.iter().enumerate() {
        assert_eq!(generated::vanderpol::FIXED_LSB[t], proven.lsb());
        assert_eq!(generated::vanderpol::FIXED_BOUND[t], proven.stated_bound());
    }
}

/// Every shipped design's fixed-point observer over its recorded raw sequence, then `HORIZON`
/// samples at every signal's raw maximum and at its minimum (which take each table to both ends)
/// and values one past each end (refused): `(accepted, [(value, flag)])` per sample, from the
/// generated straight-line code, and the same from the firmware's loops over the same maps.
macro_rules! run_generated_and_loops {
    ($($d:ident),*) => {{
        let mut all = Vec::new();
        $({
            use generated::$d as d;
            use firmware::emitted::fixed::FixedDesign;
            let mut samples: Vec<([i32; d::OUTPUTS], [i32; d::INPUTS])> = d::RECORDED_RAW_Y
                .iter()
                .zip(d::RECORDED_RAW_U.iter())
                .map(|(y, u)| (*y, *u))
                .collect();
            for end in [1, 0] {
                let y = d::RAW_OUTPUT_RANGES.map(|r| r[end]);
                let u = d::RAW_INPUT_RANGES.map(|r| r[end]);
                samples.extend(std::iter::repeat_n((y, u), d::HORIZON));
                samples.push((d::RAW_OUTPUT_RANGES.map(|r| if end == 1 { r[1] + 1 } else { r[0] - 1 }), u));
            }
            let mut observer = d::fixed_observer();
            let mut window: Vec<firmware::Sample<i32, { d::OUTPUTS }, { d::INPUTS }>> = Vec::new();
            let (mut generated, mut loops) = (Vec::new(), Vec::new());
            for (y, u) in &samples {
                let accepted = observer.push(*y, *u).is_ok();
                let flags = |e: &[firmware::Estimate<i32>]| e.iter().map(|e| (e.value, e.saturation)).collect::<Vec<_>>();
                generated.push((accepted, observer.estimate().map(|e| flags(&e))));
                // The library: the range check and the loops of firmware::fixed over the same maps.
                let inside = y.iter().zip(d::RAW_OUTPUT_RANGES).chain(u.iter().zip(d::RAW_INPUT_RANGES)).all(|(v, [lo, hi])| (lo..=hi).contains(v));
                if inside {
                    window.push(firmware::Sample { y: *y, u: *u });
                }
                let estimate = (window.len() >= d::HORIZON).then(|| {
                    let last: [firmware::Sample<i32, { d::OUTPUTS }, { d::INPUTS }>; d::HORIZON] =
                        window[window.len() - d::HORIZON..].try_into().unwrap();
                    firmware::emitted::fixed::estimate_by_loops(&<d::Fixed as FixedDesign<{ d::HORIZON }, { d::OUTPUTS }, { d::INPUTS }, { d::TARGETS }>>::MAPS, &last)
                });
                loops.push((inside, estimate.map(|e| flags(&e))));
            }
            // The recorded raw sequence alone saturates every target both ways (its last samples), so
            // that the chip's run of it shows the same instructions then.
            for t in 0..d::TARGETS {
                for flag in [firmware::Saturation::Low, firmware::Saturation::High] {
                    assert!(
                        generated[..d::RECORDED_LEN].iter().any(|(_, e)| e.as_ref().is_some_and(|e| e[t].1 == flag)),
                        "{}: target {t} never {flag:?} over RECORDED_RAW",
                        stringify!($d)
                    );
                }
            }
            all.push((stringify!($d), samples.iter().map(|(y, u)| (y.to_vec(), u.to_vec())).collect::<Vec<_>>(), generated, loops));
        })*
        all
    }};
}

/// Per sample: accepted, and every target's `(value, flag)` once there is an estimate.
type Outcome = Vec<(bool, Option<Vec<(i32, firmware::Saturation)>>)>;
/// Raw samples `(y, u)`.
type Samples = Vec<(Vec<i32>, Vec<i32>)>;
/// A design's name, its samples, the generated code's outcome and the library loops'.
type Run = (&'static str, Samples, Outcome, Outcome);

fn every_design() -> Vec<Run> {
    run_generated_and_loops!(
        vanderpol,
        vanderpol_searched,
        vanderpol_sparse,
        vanderpol_uncertain,
        two_tanks,
        ecoli_x0_2,
        ecoli_x0_0p5
    )
}

#[test]
fn every_designs_generated_fixed_point_code_gives_the_librarys_bits_and_saturates_both_ways() {
    for (name, _, generated, loops) in every_design() {
        assert_eq!(generated, loops, "{name}");
        let flags: Vec<firmware::Saturation> = generated
            .iter()
            .flat_map(|(_, e)| e.iter().flatten().map(|(_, f)| *f))
            .collect();
        for flag in [
            firmware::Saturation::Low,
            firmware::Saturation::High,
            firmware::Saturation::Inside,
        ] {
            assert!(flags.contains(&flag), "{name}: no estimate flagged {flag:?}");
        }
        assert!(
            generated.iter().filter(|(accepted, _)| !accepted).count() >= 4,
            "{name}: the refused samples"
        );
    }
}

/// The C fixed-point observer of every shipped design, compiled by `compiler` under the strict flags
/// with a driver that reads raw samples from stdin and prints what the observer returns; `None`
/// when the compiler is missing.
fn run_c(
    compiler: &str,
    name: &str,
    outputs: usize,
    inputs: usize,
    samples: &[(Vec<i32>, Vec<i32>)],
) -> Option<Vec<String>> {
    let folder = integration_tests::workspace_root().join("target/fixed-point-c");
    std::fs::create_dir_all(&folder).unwrap();
    let driver = folder.join(format!("{name}_main.c"));
    std::fs::write(
        &driver,
        format!(
            "#include <stdio.h>\n#include \"{name}.h\"\n\
             int main(void) {{\n\
             \x20   {name}_fixed observer;\n\
             \x20   int32_t y[{outputs}] = {{0}}, u[{inputs} + 1] = {{0}}, values[{upper}_TARGETS];\n\
             \x20   {name}_saturation flags[{upper}_TARGETS];\n\
             \x20   unsigned i;\n\
             \x20   {name}_fixed_init(&observer);\n\
             \x20   for (;;) {{\n\
             \x20       for (i = 0u; i < {outputs}u; ++i) if (scanf(\"%d\", &y[i]) != 1) return 0;\n\
             {read_inputs}\
             \x20       printf(\"%d\", {name}_fixed_push(&observer, y, u) == {upper}_OK);\n\
             \x20       if ({name}_fixed_estimate(&observer, values, flags) == {upper}_OK)\n\
             \x20           for (i = 0u; i < {upper}_TARGETS; ++i) printf(\" %d %d\", (int)values[i], (int)flags[i]);\n\
             \x20       printf(\"\\n\");\n\
             \x20   }}\n\
             }}\n",
            upper = name.to_uppercase(),
            read_inputs = if inputs > 0 {
                format!("\x20       for (i = 0u; i < {inputs}u; ++i) if (scanf(\"%d\", &u[i]) != 1) return 1;\n")
            } else {
                String::new()
            },
        ),
    )
    .unwrap();
    let c = integration_tests::workspace_root().join("generated/c");
    let program = folder.join(format!("{name}_{compiler}"));
    let compiled = Command::new(compiler)
        .args(integration_tests::on_target::STRICT_C_FLAGS)
        .args(["-O2", "-I"])
        .arg(&c)
        .arg(c.join(format!("{name}.c")))
        .arg(&driver)
        .arg("-lm")
        .arg("-o")
        .arg(&program)
        .output()
        .ok()?;
    assert!(
        compiled.status.success(),
        "{compiler} {name}: {}",
        String::from_utf8_lossy(&compiled.stderr)
    );
    let mut child = Command::new(&program)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let input: String = samples
        .iter()
        .map(|(y, u)| y.iter().chain(u).map(|v| format!("{v} ")).collect::<String>() + "\n")
        .collect();
    child.stdin.take().unwrap().write_all(input.as_bytes()).unwrap();
    let output = child.wait_with_output().unwrap();
    assert!(output.status.success());
    Some(
        String::from_utf8(output.stdout)
            .unwrap()
            .lines()
            .map(str::to_owned)
            .collect(),
    )
}

#[test]
fn every_designs_c_fixed_point_observer_gives_the_rust_bits_with_gcc_and_clang() {
    let flag = |f: firmware::Saturation| match f {
        firmware::Saturation::Inside => 0,
        firmware::Saturation::Low => 1,
        firmware::Saturation::High => 2,
    };
    let mut ran = 0;
    for (name, samples, generated, _) in every_design() {
        let expected: Vec<String> = generated
            .iter()
            .map(|(accepted, estimates)| {
                let mut line = u8::from(*accepted).to_string();
                for (value, f) in estimates.iter().flatten() {
                    line += &format!(" {value} {}", flag(*f));
                }
                line
            })
            .collect();
        let (outputs, inputs) = (samples[0].0.len(), samples[0].1.len());
        for compiler in ["cc", "clang"] {
            match run_c(compiler, name, outputs, inputs, &samples) {
                Some(lines) => {
                    assert_eq!(lines, expected, "{compiler} {name}");
                    ran += 1;
                }
                None => assert!(std::env::var_os("CI").is_none(), "CI needs {compiler}"),
            }
        }
    }
    assert!(ran >= 7);
}
