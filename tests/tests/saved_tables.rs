//! `estimate` by the design `gen` saved (`design.json`): the tables survive the file bit for bit, the
//! estimates are those of the design in memory for every observer kind, and tables of another spec
//! are refused.

use host::commands::{self, Provenance, Simulation};
use host::spec::ObserverKind;
use host::tables::Tables;
use indicatif::ProgressBar;

#[test]
fn estimates_from_saved_tables_are_the_fitted_designs_and_stale_ones_are_refused() {
    let root = integration_tests::workspace_root();
    let spec = root.join("host/specs/vanderpol.toml");
    let design = host::spec::load(&spec).unwrap();
    let emitted = host::generate::emit_design(design.clone(), &spec, None, &ProgressBar::hidden()).unwrap();
    let in_memory = Tables::of(&emitted);
    assert!(in_memory.corrected.is_some() && in_memory.ekf.is_some() && in_memory.started.is_some());

    let scratch = std::env::temp_dir().join(format!("saved-tables-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&scratch);
    std::fs::create_dir_all(&scratch).unwrap();
    let saved = scratch.join(host::tables::FILE);
    std::fs::write(&saved, in_memory.to_json()).unwrap();
    let read = Tables::read(&saved).unwrap().unwrap();
    // Every number survives the JSON bit for bit.
    assert_eq!(read.to_json(), in_memory.to_json());
    for (a, b) in read.maps.iter().zip(&in_memory.maps) {
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&a.gains), bits(&b.gains));
        assert_eq!(bits(&a.mu), bits(&b.mu));
    }

    let recording = scratch.join("run.csv");
    let simulation = Simulation {
        x0: Some(vec![1.5, -2.0]),
        samples: Some(120),
        seed: Some(11),
    };
    commands::simulate(&design, &simulation, &recording).unwrap();
    let rows = host::recording::read(&design, &recording).unwrap();
    let code = host::generate::model_code(&design).unwrap();
    let names: Vec<&str> = design.targets.iter().map(|t| t.name.as_str()).collect();
    for kind in [
        ObserverKind::Auto,
        ObserverKind::Map,
        ObserverKind::Corrected,
        ObserverKind::Ekf,
    ] {
        let out = scratch.join(format!("{kind:?}.csv"));
        let provenance =
            commands::estimate(&design, &recording, &out, kind, Some(&saved), &ProgressBar::hidden()).unwrap();
        assert_eq!(provenance, Provenance::Saved(saved.clone()));
        // The design in memory (no file), through the same observers.
        let expected = host::observers::recorded::estimate(&design, &in_memory, &code, kind, &rows).unwrap();
        assert_eq!(
            std::fs::read_to_string(&out).unwrap(),
            host::recording::estimates_csv(&names, &expected),
            "{kind:?}"
        );
    }

    // Tables of another spec text (a comment added) are refused, naming both files.
    let edited = scratch.join("vanderpol.toml");
    std::fs::write(&edited, std::fs::read_to_string(&spec).unwrap() + "# edited\n").unwrap();
    let other = host::spec::load(&edited).unwrap();
    let error = commands::estimate(
        &other,
        &recording,
        &scratch.join("x.csv"),
        ObserverKind::Map,
        Some(&saved),
        &ProgressBar::hidden(),
    )
    .unwrap_err()
    .to_string();
    assert!(
        error.contains("design.json") && error.contains("vanderpol.toml") && error.contains("gen"),
        "{error}"
    );
    std::fs::remove_dir_all(&scratch).unwrap();
}
