//! Every design's extended Kalman filter on the emulated Cortex-M4F, in a program of its own: the same
//! bits as the host running the same filter in f32 (refused samples included), how far that is from
//! the filter in f64, instructions per `push` + `targets`, stack, flash and RAM, and no reachable
//! panic. Without QEMU the test says so and passes, unless `CI` is set: CI must run it.

use std::collections::BTreeMap;

use integration_tests::on_target::{self, EkfMeasurement, Unavailable};

fn measurements() -> Option<BTreeMap<String, EkfMeasurement>> {
    match on_target::measure_ekf() {
        Ok(measurements) => Some(measurements),
        Err(missing @ Unavailable::Missing { .. }) if std::env::var_os("CI").is_none() => {
            println!("ON-TARGET TESTS DID NOT RUN: {missing}");
            eprintln!("ON-TARGET TESTS DID NOT RUN: {missing}");
            None
        }
        Err(e) => panic!("on-target EKF measurements failed: {e}"),
    }
}

#[test]
fn generated_ekfs_on_the_emulated_cortex_m4f() {
    let Some(measured) = measurements() else { return };

    // Bit for bit with the host running `ekf()` (f32) over the same recorded sequence: the targets of
    // every estimate `push` returns, and the state after every sample, so that the prediction a
    // refused sample still runs is compared too. Both sides must refuse exactly the non-finite
    // samples, and the sequence must hold some.
    macro_rules! same_as_host_f32 {
        ($name:ident) => {{
            use generated::$name as d;
            let on_target = &measured[d::NAME];
            assert_eq!(on_target.samples.len(), d::RECORDED_LEN, "{}", d::NAME);
            let mut filter = d::ekf();
            let mut refused = 0;
            for (k, ((y, u), sample)) in d::RECORDED_Y
                .iter()
                .zip(&d::RECORDED_U)
                .zip(&on_target.samples)
                .enumerate()
            {
                let finite = y.iter().chain(u).all(|v| v.is_finite());
                let pushed = filter.push(y, u);
                assert_eq!(pushed.is_ok(), finite, "{} sample {k}: the host's push", d::NAME);
                assert_eq!(sample.accepted(), finite, "{} sample {k}: the target's push", d::NAME);
                refused += usize::from(!finite);
                let host = pushed.ok().map(|x| d::targets(&x, u).map(f32::to_bits).to_vec());
                assert_eq!(
                    host,
                    sample.targets,
                    "{} sample {k}: host f32 and target targets differ",
                    d::NAME
                );
                assert_eq!(
                    filter.state().map(f32::to_bits).to_vec(),
                    sample.state,
                    "{} sample {k}: host f32 and target states differ",
                    d::NAME
                );
            }
            assert!(refused > 0, "{}: no refused sample in the recorded sequence", d::NAME);
        }};
    }
    generated::for_each_design!(same_as_host_f32);

    for (name, filter) in &measured {
        let largest = on_target::compare_ekf_with_f64(name, filter).unwrap_or_else(|e| panic!("{e}"));
        assert!(largest.is_finite(), "{name}: max |target - host f64| = {largest}");
        assert_eq!(
            filter.instructions.len(),
            filter.samples.len(),
            "{name}: one count per sample"
        );
        let accepted = filter.accepted_instructions();
        let (min, median, max) = on_target::spread(&accepted);
        assert!(
            min > 0 && !accepted.is_empty(),
            "{name}: instruction counts {:?}",
            filter.instructions
        );
        // The painted region (8192 bytes, `PAINTED` in `tests/on-target/src/bin/ekf.rs`) must not have
        // been used up: the deepest word changed is not its last.
        assert!(
            filter.stack_bytes > 0 && filter.stack_bytes < 8192,
            "{name}: stack {} B",
            filter.stack_bytes
        );
        // The probe linked (so no panic is reachable from the filter) and added code.
        assert!(filter.flash_bytes > 0 && filter.filter_bytes > 0, "{name}: {filter:?}");
        println!(
            "{name} EKF: push + targets {min}/{median}/{max} instructions (min/median/max of accepted samples), \
             {} VDIV + VSQRT at most, stack {} B, flash {} B, filter {} B, static RAM {} B, \
             max |target - host f64| = {largest:e}",
            filter.divisions.iter().max().unwrap_or(&0),
            filter.stack_bytes,
            filter.flash_bytes,
            filter.filter_bytes,
            filter.static_ram_bytes
        );
    }
}
