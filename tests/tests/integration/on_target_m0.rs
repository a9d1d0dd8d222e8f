//! The map and the EKF from the box centre of every generated design (and its integer observer,
//! where it has one) on an emulated Cortex-M0 (QEMU `microbit`, `thumbv6m-none-eabi`, software
//! floating point): bit for bit what the host computes running the same code in f32 over the same
//! recorded sequence, instructions and estimated Cortex-M0+ cycles per sample, stack, flash and RAM,
//! no reachable panic, and `docs/chip.md`'s Cortex-M0 table. Without QEMU the test says so and
//! passes, unless `CI` is set: CI must run it.

use integration_tests::on_target::{self, Board, Kind, Measurements, ObserverKind, Unavailable};

fn measurements() -> Option<Measurements> {
    match on_target::measure_board(Board::Microbit) {
        Ok(measurements) => Some(measurements),
        Err(missing @ Unavailable::Missing { .. }) if std::env::var_os("CI").is_none() => {
            println!("ON-TARGET TESTS DID NOT RUN: {missing}");
            eprintln!("ON-TARGET TESTS DID NOT RUN: {missing}");
            None
        }
        Err(e) => panic!("Cortex-M0 measurements failed: {e}"),
    }
}

/// Bytes the runners paint below their frame on the Cortex-M0 (`PAINTED` and `EKF_PAINTED`, written
/// by `tests/on-target/build.rs`): its 16 KiB of RAM hold 4 KiB of paint for either program.
const M0_PAINTED: usize = 4096;

/// The map and the EKF from the box centre of every design (and its integer observer, where it has
/// one) on the emulated Cortex-M0, in software floating point: the same bits as the host's f32 run
/// of the same code, the costs, and the page's Cortex-M0 table.
#[test]
fn maps_and_filters_on_the_emulated_cortex_m0() {
    let Some(all) = measurements() else { return };
    let mut differences = Vec::new();
    for name in on_target::design_names() {
        let mut measured: Vec<Kind> = all
            .observers
            .get(name)
            .into_iter()
            .flat_map(|o| o.keys().copied())
            .collect();
        measured.extend(all.filters.contains_key(name).then_some(Kind::Of(ObserverKind::EkfBox)));
        measured.sort();
        assert_eq!(
            measured,
            on_target::m0_kinds(name),
            "{name}: the kinds run on the Cortex-M0"
        );
    }
    for (name, observers) in &all.observers {
        for (&kind, observer) in observers {
            let what = format!("{name} {} on the Cortex-M0", kind.api());
            let host = on_target::host_samples(name, kind).unwrap_or_else(|| panic!("{what}: no host run"));
            assert!(host.iter().any(|s| !s.accepted), "{what}: no refused sample");
            differences.extend(on_target::differences(&what, &observer.samples, &host));
            on_target::check_cycles(&what, &observer.instructions, &observer.cycles);
            let phases = observer.phases().unwrap_or_else(|e| panic!("{what}: {e}"));
            let cycles = observer.cycle_phases().unwrap_or_else(|e| panic!("{what}: {e}"));
            assert!(
                observer.stack_bytes > 0 && observer.stack_bytes < M0_PAINTED,
                "{what}: stack {} B",
                observer.stack_bytes
            );
            assert!(observer.flash_bytes > 0, "{what}: {observer:?}");
            assert!(
                observer.divisions.iter().all(|&d| d == 0),
                "{what}: VDIV on a Cortex-M0"
            );
            let (min, median, max) = on_target::spread(&phases.steady);
            // The integer map runs the same instructions for every accepted sample, the recording's
            // last samples included, where every table saturates low and then high (RECORDED_RAW_*).
            assert!(kind != Kind::Fixed || min == max, "{what}: {min} to {max} instructions");
            println!(
                "{what}: {min}/{median}/{max} instructions, {} cycles (median), stack {} B, flash {} B",
                on_target::spread(&cycles.steady).1,
                observer.stack_bytes,
                observer.flash_bytes
            );
        }
    }
    for (name, filter) in &all.filters {
        let what = format!("{name} ekf() on the Cortex-M0");
        let host = on_target::host_ekf::<f32>(name).unwrap_or_else(|| panic!("{what}: no host EKF"));
        differences.extend(on_target::ekf_differences(&what, &filter.samples, &host));
        on_target::check_cycles(&what, &filter.instructions, &filter.cycles);
        filter.phases().unwrap_or_else(|e| panic!("{what}: {e}"));
        assert!(
            filter.stack_bytes > 0 && filter.stack_bytes < M0_PAINTED,
            "{what}: stack {} B",
            filter.stack_bytes
        );
        assert!(filter.flash_bytes > 0, "{what}: {filter:?}");
    }
    assert!(
        differences.is_empty(),
        "the Cortex-M0 and the host (f32) differ:\n{}",
        differences.join("\n")
    );
    // The project's page shows what the Cortex-M0 measures now, figure for figure.
    let path = integration_tests::workspace_root().join(integration_tests::chip_table::PAGE);
    let page = std::fs::read_to_string(&path).unwrap();
    let m4f = |name: &str, kind| integration_tests::chip_table::rust_median(&page, name, kind);
    let table = integration_tests::chip_table::m0_table(&all, &m4f).unwrap();
    assert!(
        integration_tests::chip_table::with_m0_table(&page, &table).unwrap() == page,
        "{} does not show what the Cortex-M0 measures now: run `cargo run -p integration-tests --bin on-target-report` and commit it",
        path.display()
    );
}
