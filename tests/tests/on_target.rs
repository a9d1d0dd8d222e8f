//! The generated observers on an emulated Cortex-M4F: the same numbers as the host (bit for bit in
//! f32, within the f32 tolerance of the f64 library), instructions per estimate, flash and RAM, and no
//! reachable panic. Without QEMU the test says so and passes, unless `CI` is set: CI must run it.

use std::collections::BTreeMap;

use integration_tests::on_target::{self, DesignMeasurement, Measurements, Unavailable};

fn measurements() -> Option<Measurements> {
    match on_target::measure() {
        Ok(measurements) => Some(measurements),
        Err(missing @ Unavailable::Missing { .. }) if std::env::var_os("CI").is_none() => {
            println!("ON-TARGET TESTS DID NOT RUN: {missing}");
            eprintln!("ON-TARGET TESTS DID NOT RUN: {missing}");
            None
        }
        Err(e) => panic!("on-target measurements failed: {e}"),
    }
}

macro_rules! same_as_host_f32 {
    ($name:ident) => {{
        use generated::$name as tables;
        let measured = &MEASURED.with(|m| m.borrow().clone()).unwrap()[tables::NAME];
        let mut observer = tables::map_observer();
        assert_eq!(measured.samples.len(), tables::RECORDED_LEN);
        for (k, ((y, u), sample)) in tables::RECORDED_Y
            .iter()
            .zip(&tables::RECORDED_U)
            .zip(&measured.samples)
            .enumerate()
        {
            assert_eq!(
                observer.push(*y, *u).is_ok(),
                sample.accepted,
                "{} sample {k}",
                tables::NAME
            );
            let host: Option<Vec<(u32, char)>> = observer.estimate().map(|estimates| {
                estimates
                    .iter()
                    .map(|e| {
                        let flag = match e.saturation {
                            firmware::Saturation::Low => 'L',
                            firmware::Saturation::Inside => 'I',
                            firmware::Saturation::High => 'H',
                        };
                        (e.value.to_bits(), flag)
                    })
                    .collect()
            });
            assert_eq!(
                host,
                sample.estimates,
                "{} sample {k}: host f32 and target differ",
                tables::NAME
            );
        }
    }};
}

thread_local! {
    static MEASURED: std::cell::RefCell<Option<BTreeMap<String, DesignMeasurement>>> = const { std::cell::RefCell::new(None) };
}

#[test]
fn generated_observers_on_the_emulated_cortex_m4f() {
    let Some(all) = measurements() else { return };
    let measured = all.designs;
    MEASURED.with(|m| *m.borrow_mut() = Some(measured.clone()));
    // Bit for bit with the host running the same firmware code in f32 (IEEE-754 single precision,
    // round to nearest, no fused multiply-add on either side).
    generated::for_each_design!(same_as_host_f32);
    for (name, design) in &measured {
        let largest = on_target::compare_with_library(name, design).unwrap_or_else(|e| panic!("{e}"));
        let steady = design.steady_instructions();
        let (min, median, max) = on_target::spread(&steady);
        assert_eq!(
            design.instructions.len(),
            design.samples.len(),
            "{name}: one count per sample"
        );
        assert!(
            min > 0 && !steady.is_empty(),
            "{name}: instruction counts {:?}",
            design.instructions
        );
        // The same instruction path every sample once the window is full, saturated or not.
        assert_eq!(min, max, "{name}: instruction counts vary from {min} to {max}");
        // No division or square root anywhere in push + estimate, in any sample.
        assert!(
            design.divisions.iter().all(|&d| d == 0),
            "{name}: VDIV/VSQRT executed: {:?}",
            design.divisions
        );
        assert!(design.stack_bytes > 0, "{name}: stack not measured");
        assert!(
            design.flash_bytes > 0 && design.observer_bytes > 0,
            "{name}: {design:?}"
        );
        println!(
            "{name}: push + estimate {min}/{median}/{max} instructions (min/median/max), first estimate {:?}, \
             stack {} B, flash {} B, observer {} B, static RAM {} B, max |target - host f64| = {largest:e}",
            design.first_estimate_instructions(),
            design.stack_bytes,
            design.flash_bytes,
            design.observer_bytes,
            design.static_ram_bytes
        );
    }
    for family in generated::FAMILIES {
        let flash = all.family_flash_bytes[family];
        assert!(flash > 0, "family {family}");
        println!("family {family}: flash {flash} B, its probe links: no reachable panic");
    }
    assert!(
        on_target::panic_check_catches_a_reachable_panic().unwrap(),
        "the no-panic check did not catch a reachable panic"
    );
}
