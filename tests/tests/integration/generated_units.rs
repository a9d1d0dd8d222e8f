//! Every generated design states the units of what it takes and returns as its spec gives them: the
//! spec is read here as plain TOML, independently of the host's validator. And the budget of a spec's
//! EKF kind is checked before the fit by the count the generated design records; the C library's
//! storage holds every kind.

use integration_tests::workspace_root;

/// The units the spec text gives: per output and target its `unit`, per state and input its entry of
/// `[model.units]`; "" where there is none.
fn spec_units(spec: &str) -> [Vec<String>; 4] {
    let text = std::fs::read_to_string(workspace_root().join(spec)).unwrap();
    let spec: toml::Table = text.parse().unwrap();
    let model = spec["model"].as_table().unwrap();
    let text_of = |v: Option<&toml::Value>| v.and_then(|v| v.as_str()).unwrap_or_default().to_owned();
    let units = model.get("units").and_then(|u| u.as_table());
    let named = |list: Option<&toml::Value>| -> Vec<String> {
        list.and_then(|l| l.as_array())
            .map(|names| {
                names
                    .iter()
                    .map(|n| text_of(units.and_then(|u| u.get(n.as_str().unwrap()))))
                    .collect()
            })
            .unwrap_or_default()
    };
    let own = |tables: &toml::Value| -> Vec<String> {
        tables
            .as_array()
            .unwrap()
            .iter()
            .map(|t| text_of(t.get("unit")))
            .collect()
    };
    [
        named(model.get("states")),
        named(model.get("inputs")),
        own(&model["outputs"]),
        own(&spec["targets"]),
    ]
}

macro_rules! check_units {
    ($($design:ident),*) => {
        $(
            {
                use generated::$design as d;
                let [states, inputs, outputs, targets] = spec_units(d::SPEC);
                assert_eq!(d::STATE_UNITS.to_vec(), states, "{}", d::NAME);
                assert_eq!(d::INPUT_UNITS.to_vec(), inputs, "{}", d::NAME);
                assert_eq!(d::OUTPUT_UNITS.to_vec(), outputs, "{}", d::NAME);
                assert_eq!(d::TARGET_UNITS.to_vec(), targets, "{}", d::NAME);
            }
        )*
    };
}

#[test]
fn generated_units_are_the_specs() {
    check_units!(
        ecoli_x0_0p5,
        ecoli_x0_2,
        two_tanks,
        vanderpol,
        vanderpol_searched,
        vanderpol_sparse,
        vanderpol_uncertain
    );
    // The shipped designs do exercise every kind of unit.
    assert_eq!(generated::two_tanks::INPUT_UNITS, ["V"]);
    assert_eq!(generated::ecoli_x0_2::STATE_UNITS, ["g/L"; 3]);
}

/// The spec's EKF kind over `budget.instructions` is refused before anything is fitted
/// (`host::observers::check_before_fit`), by the count the fitted design records: at its recorded
/// `PREDICTED_INSTRUCTIONS` the kind is allowed, one below it refused, for every shipped design with
/// an EKF. Before the fit a filter is counted with its χ² watch (`host::search::cost::WATCH`; the
/// map-started EKF carries the box EKF's), which tuning keeps on every shipped filter: where it did
/// not, the fit would record `WATCH` fewer.
#[test]
fn an_ekf_kind_over_budget_is_refused_before_the_fit_by_the_count_the_fit_records() {
    macro_rules! thresholds {
        ($d:ident) => {
            [
                ("ekf_box", generated::$d::EKF_WATCH_THRESHOLD),
                ("ekf_map", generated::$d::EKF_WATCH_THRESHOLD),
                ("ukf_box", generated::$d::UKF_WATCH_THRESHOLD),
            ]
        };
    }
    /// A design: its name, its recorded predictions and its filters' watch thresholds.
    type Recorded<'a> = (&'a str, &'a [(&'a str, u32)], [(&'a str, f64); 3]);
    let designs: [Recorded<'_>; 3] = [
        (
            "vanderpol",
            &generated::vanderpol::PREDICTED_INSTRUCTIONS,
            thresholds!(vanderpol),
        ),
        (
            "two_tanks",
            &generated::two_tanks::PREDICTED_INSTRUCTIONS,
            thresholds!(two_tanks),
        ),
        (
            "ecoli_x0_2",
            &generated::ecoli_x0_2::PREDICTED_INSTRUCTIONS,
            thresholds!(ecoli_x0_2),
        ),
    ];
    let mut unwatched = 0;
    let mut checked = 0;
    for (name, predicted, thresholds) in designs {
        let mut design = host::generate::shipped_design(name).unwrap();
        let code = host::generate::model_code(&design).unwrap();
        for (named, recorded) in predicted.iter().copied() {
            // A filter the fit left unwatched: counted with its watch before the fit.
            let watch_left_out = thresholds.iter().any(|&(k, t)| k == named && t.is_infinite());
            unwatched += usize::from(watch_left_out);
            let instructions = recorded
                + if watch_left_out {
                    host::search::cost::WATCH as u32
                } else {
                    0
                };
            let kind = named;
            // The kinds whose cost the model predicts before the fit.
            let Some(kind) = host::observers::kind::named(kind)
                .filter(|entry| entry.cost_before_fit.is_some())
                .map(|entry| entry.kind)
            else {
                continue;
            };
            design.observer = kind;
            design.budget.instructions = Some(instructions.into());
            host::observers::check_before_fit(&design, &code).unwrap_or_else(|e| panic!("{name} {kind:?}: {e}"));
            design.budget.instructions = Some((instructions - 1).into());
            let error = host::observers::check_before_fit(&design, &code)
                .expect_err("one instruction over the budget")
                .to_string();
            assert!(
                error.contains("budget.instructions") && error.contains("observer.kind"),
                "{error}"
            );
            checked += 1;
        }
    }
    assert!(checked >= 6, "only {checked} EKF kinds checked");
    assert_eq!(unwatched, 0, "every shipped filter is watched");
}

/// The C library's storage (`STORAGE_SIZE`, [`storage_bound`](host::standalone::c_library::storage_bound))
/// holds every observer kind of every shipped design after its mark: an emitted C crate checks only
/// its own `Observer` when it compiles, and a spec may name any kind.
#[test]
fn the_c_storage_bound_holds_every_kind_of_every_design() {
    use host::standalone::c_library::{storage_bound, MARK_BYTES};
    let mut checked = 0;
    macro_rules! holds {
        ($design:ident, $kind:ident, $type:ident) => {{
            let design = host::generate::shipped_design(stringify!($design)).unwrap();
            let size = std::mem::size_of::<generated::$design::$type>();
            let bound = storage_bound(&design);
            assert!(
                MARK_BYTES + size <= bound,
                "{} {}: {size} B after a {MARK_BYTES} B mark, bound {bound} B",
                stringify!($design),
                stringify!($type)
            );
            checked += 1;
        }};
    }
    generated::for_each_observer!(holds);
    // Every design has its map, and every one the host can filter its EKF, UKF and moving-horizon observer.
    assert!(checked >= 28, "{checked} observers checked");
}
