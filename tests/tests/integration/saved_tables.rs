//! `estimate` by the design `gen` saved (`design.json`): the tables survive the file bit for bit, the
//! estimates are those of the design in memory for every observer kind, and tables of another spec
//! are refused.

use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::OnceLock;

use host::commands::{self, Estimation, Provenance, Simulation};
use host::observers::kind::KindConstants;
use host::recording::Precision;
use host::spec::{Design, ObserverKind};
use host::tables::Tables;
use indicatif::ProgressBar;

/// Example 1 emitted as `gen` emits it, its tables saved to `design.json` in a temporary folder, and a
/// recording of the plant: once per process, for every case below (which write files of their own
/// beside them, never over them).
struct Saved {
    spec: PathBuf,
    design: Design,
    in_memory: Tables,
    scratch: PathBuf,
    /// `design.json`, as saved.
    saved: PathBuf,
    /// A run of the plant from (2, 0.5), 120 samples.
    recording: PathBuf,
    /// Cases that have finished: the last of [`Saved::CASES`] removes the scratch folder.
    finished: AtomicUsize,
}

impl Saved {
    const CASES: usize = 5;

    fn finish(&self) {
        if self.finished.fetch_add(1, Ordering::SeqCst) + 1 == Self::CASES {
            std::fs::remove_dir_all(&self.scratch).unwrap();
        }
    }
}

fn saved() -> &'static Saved {
    static SAVED: OnceLock<Saved> = OnceLock::new();
    SAVED.get_or_init(|| {
        let root = integration_tests::workspace_root();
        let spec = root.join("host/specs/vanderpol.toml");
        let design = host::spec::load(&spec).unwrap();
        let emitted = integration_tests::shipped("vanderpol");
        let in_memory = Tables::of(&emitted.design, &emitted.result, &emitted.comparison, &emitted.source);
        let scratch = std::env::temp_dir().join(format!("saved-tables-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&scratch);
        std::fs::create_dir_all(&scratch).unwrap();
        let saved = scratch.join(host::tables::FILE);
        std::fs::write(&saved, in_memory.to_json()).unwrap();
        let recording = scratch.join("run.csv");
        let simulation = Simulation {
            x0: Some(vec![2.0, 0.5]),
            samples: Some(120),
            seed: Some(11),
        };
        commands::simulate(&design, &simulation, &recording).unwrap();
        Saved {
            spec,
            design,
            in_memory,
            scratch,
            saved,
            recording,
            finished: AtomicUsize::new(0),
        }
    })
}

#[test]
fn saved_tables_hold_every_kind_and_survive_the_file_bit_for_bit() {
    let Saved { in_memory, saved, .. } = saved();
    assert!([
        ObserverKind::Corrected,
        ObserverKind::EkfBox,
        ObserverKind::EkfMap,
        ObserverKind::Mhe
    ]
    .into_iter()
    .all(|kind| in_memory.constants.has(kind)));

    // Every number survives the JSON bit for bit.
    let read = Tables::read(saved).unwrap().unwrap();
    assert_eq!(read.to_json(), in_memory.to_json());
    for (a, b) in read.maps.iter().zip(&in_memory.maps) {
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&a.gains), bits(&b.gains));
        assert_eq!(bits(&a.mu), bits(&b.mu));
    }

    self::saved().finish();
}

#[test]
fn estimates_from_saved_tables_are_the_design_in_memorys_for_every_kind() {
    let Saved {
        design,
        in_memory,
        scratch,
        saved,
        recording,
        ..
    } = saved();
    let rows = host::recording::read(design, recording).unwrap();
    let code = host::generate::model_code(design).unwrap();
    let names: Vec<&str> = design.targets.iter().map(|t| t.name.as_str()).collect();
    let csv = host::recording::EstimatesCsv::new(&names, false, design.tau);
    for kind in [
        ObserverKind::Auto,
        ObserverKind::Map,
        ObserverKind::Corrected,
        ObserverKind::EkfMap,
        ObserverKind::EkfBox,
        ObserverKind::UkfBox,
        ObserverKind::EkfRestart,
        ObserverKind::Mhe,
    ] {
        let out = scratch.join(format!("{kind:?}.csv"));
        let how = Estimation {
            kind,
            precision: Precision::F64,
            tables: Some(saved),
        };
        let provenance = commands::estimate(design, recording, &out, how, &ProgressBar::hidden()).unwrap();
        assert_eq!(provenance, Provenance::Saved(saved.clone()));
        // The design in memory (no file), through the same observers.
        let expected =
            host::observers::recorded::estimate(design, in_memory, &code, kind, Precision::F64, &rows).unwrap();
        assert_eq!(
            std::fs::read_to_string(&out).unwrap(),
            host::recording::estimates_csv(&csv, &rows, &expected),
            "{kind:?}"
        );
    }

    self::saved().finish();
}

/// `--precision f32` is the generated observer (the emitted code, compiled for this host) bit for
/// bit, flags included, over the recording with a refused sample.
#[test]
fn f32_estimates_from_saved_tables_are_the_generated_observers_bits() {
    let Saved {
        design,
        scratch,
        saved,
        recording,
        ..
    } = saved();
    let text = std::fs::read_to_string(recording).unwrap();
    let with_nan: String = text
        .lines()
        .enumerate()
        .map(|(i, line)| {
            if i == 40 {
                let cells: Vec<&str> = line.split(',').collect();
                format!("{},nan\n", cells[..cells.len() - 1].join(","))
            } else {
                format!("{line}\n")
            }
        })
        .collect();
    let refused = scratch.join("refused.csv");
    std::fs::write(&refused, with_nan).unwrap();
    let rows = host::recording::read(design, &refused).unwrap();
    assert!(rows[39].y[0].is_nan());
    use generated::vanderpol as d;
    fn chip<O>(
        rows: &[host::recording::Row],
        mut push: impl FnMut(&mut O, [f32; d::OUTPUTS]) -> bool,
        estimate: impl Fn(&O) -> Option<[firmware::Estimate<f32>; d::TARGETS]>,
        mut observer: O,
    ) -> Vec<String> {
        rows.iter()
            .map(|row| {
                let y: [f32; d::OUTPUTS] = core::array::from_fn(|i| row.y[i] as f32);
                let accepted = push(&mut observer, y);
                integration_tests::estimates_row(accepted, estimate(&observer).as_ref().map(|e| &e[..]), d::TARGETS)
            })
            .collect()
    }
    let map = chip(
        &rows,
        |o: &mut d::MapObserver, y| o.push(y, []).is_ok(),
        d::MapObserver::estimate,
        d::MapObserver::new(),
    );
    let corrected = chip(
        &rows,
        |o: &mut d::CorrectedObserver, y| o.push(y, []).is_ok(),
        d::CorrectedObserver::estimate,
        d::CorrectedObserver::new(),
    );
    let started_ekf = chip(
        &rows,
        |o: &mut d::EkfMapObserver, y| o.push(y, []).is_ok(),
        d::EkfMapObserver::estimate,
        d::EkfMapObserver::new(),
    );
    let box_ekf = chip(
        &rows,
        |o: &mut d::EkfBoxObserver, y| o.push(y, []).is_ok(),
        d::EkfBoxObserver::estimate,
        d::EkfBoxObserver::new(),
    );
    let ukf = chip(
        &rows,
        |o: &mut d::UkfBoxObserver, y| o.push(y, []).is_ok(),
        d::UkfBoxObserver::estimate,
        d::UkfBoxObserver::new(),
    );
    let restarted_ekf = chip(
        &rows,
        |o: &mut d::EkfRestartObserver, y| o.push(y, []).is_ok(),
        d::EkfRestartObserver::estimate,
        d::EkfRestartObserver::new(),
    );
    let mhe = chip(
        &rows,
        |o: &mut d::MheObserver, y| o.push(y, []).is_ok(),
        d::MheObserver::estimate,
        d::MheObserver::new(),
    );
    // From x(0) = (2, 0.5) (the paper's scenario) the filter from the box centre runs as the box EKF
    // until the map, which watches it from its first estimate (sample N − 1) on, disagrees and
    // restarts it: that estimate is the map's, the ones before the box filter's, so both of its paths
    // are compared below.
    let n = d::HORIZON;
    let restart = (n - 1..restarted_ekf.len())
        .find(|&k| restarted_ekf[k] != box_ekf[k])
        .expect("the map restarts the filter");
    assert_eq!(restarted_ekf[restart], map[restart], "a restart from the map");
    assert_eq!(restarted_ekf[..restart], box_ekf[..restart]);
    for (kind, expected) in [
        (ObserverKind::Map, map),
        (ObserverKind::Corrected, corrected),
        (ObserverKind::EkfMap, started_ekf),
        (ObserverKind::EkfBox, box_ekf),
        (ObserverKind::UkfBox, ukf),
        (ObserverKind::EkfRestart, restarted_ekf),
        (ObserverKind::Mhe, mhe),
    ] {
        let out = scratch.join(format!("{kind:?}-f32.csv"));
        let how = Estimation {
            kind,
            precision: Precision::F32,
            tables: Some(saved),
        };
        commands::estimate(design, &refused, &out, how, &ProgressBar::hidden()).unwrap();
        let written = std::fs::read_to_string(&out).unwrap();
        let lines: Vec<&str> = written.lines().skip(1).collect();
        assert_eq!(lines.len(), expected.len());
        let mut ok = 0;
        for (k, (line, expected)) in lines.iter().zip(&expected).enumerate() {
            // After `time,`.
            let (_, rest) = line.split_once(',').unwrap();
            assert_eq!(rest, expected, "{kind:?} row {k}");
            ok += usize::from(expected.starts_with("ok"));
        }
        assert!(ok > 100, "{kind:?}: {ok} estimates compared");
        // And f32 is not f64: the default precision differs somewhere.
        let f64_out = scratch.join(format!("{kind:?}-f64.csv"));
        let how = Estimation {
            precision: Precision::F64,
            ..how
        };
        commands::estimate(design, &refused, &f64_out, how, &ProgressBar::hidden()).unwrap();
        assert_ne!(std::fs::read_to_string(&f64_out).unwrap(), written, "{kind:?}");
    }

    self::saved().finish();
}

/// Tables edited by hand are refused on every read; tables whose hash was fixed up after an edit
/// that breaks them (fewer maps than targets, an empty K, a short start) are refused by name, not by
/// a panic.
#[test]
fn tables_edited_by_hand_or_broken_by_an_edit_are_refused() {
    let Saved {
        design,
        in_memory,
        scratch,
        recording,
        ..
    } = saved();
    // A file of their own (the saved one stays as saved for the other cases).
    let folder = scratch.join("edited");
    std::fs::create_dir_all(&folder).unwrap();
    let saved = folder.join(host::tables::FILE);
    let mut edited = in_memory.clone();
    edited.maps[0].gains[0] *= 1.01;
    std::fs::write(&saved, edited.to_json()).unwrap();
    let error = Tables::read(&saved).unwrap_err().to_string();
    assert!(
        error.contains("design.json") && error.contains("changed since"),
        "{error}"
    );
    type Break = fn(&mut Tables);
    let breaks: [(&str, Break); 3] = [
        ("`maps`", |t| {
            t.maps.pop();
        }),
        ("`constants.corrected.k`", |t| {
            match t.constants.get_mut(ObserverKind::Corrected) {
                Some(KindConstants::Corrected(c)) => c.k.clear(),
                _ => panic!("Example 1 has a corrected map"),
            }
        }),
        ("`constants.ekf_map.p0`", |t| {
            match t.constants.get_mut(ObserverKind::EkfMap) {
                Some(KindConstants::EkfMap(s)) => {
                    s.p0.pop();
                }
                _ => panic!("Example 1 has a map-started EKF"),
            }
        }),
    ];
    for (field, edit) in breaks {
        let mut broken = in_memory.clone();
        edit(&mut broken);
        broken.tables_sha256 = broken.content_sha256();
        std::fs::write(&saved, broken.to_json()).unwrap();
        let how = Estimation {
            kind: ObserverKind::EkfMap,
            precision: Precision::F64,
            tables: Some(&saved),
        };
        let out = folder.join("broken.csv");
        let error = commands::estimate(design, recording, &out, how, &ProgressBar::hidden())
            .unwrap_err()
            .to_string();
        assert!(
            error.contains(field) && error.contains("run `gen` again"),
            "{field}: {error}"
        );
        assert!(!out.exists());
    }
    self::saved().finish();
}

/// Tables of another spec text (a comment added) are refused, naming both files.
#[test]
fn tables_of_another_spec_text_are_refused() {
    let Saved {
        spec,
        scratch,
        saved,
        recording,
        ..
    } = saved();
    let edited = scratch.join("vanderpol.toml");
    std::fs::write(&edited, std::fs::read_to_string(spec).unwrap() + "# edited\n").unwrap();
    let other = host::spec::load(&edited).unwrap();
    let how = Estimation {
        kind: ObserverKind::Map,
        precision: Precision::F64,
        tables: Some(saved),
    };
    let error = commands::estimate(&other, recording, &scratch.join("x.csv"), how, &ProgressBar::hidden())
        .unwrap_err()
        .to_string();
    assert!(
        error.contains("design.json") && error.contains("vanderpol.toml") && error.contains("gen"),
        "{error}"
    );
    self::saved().finish();
}
