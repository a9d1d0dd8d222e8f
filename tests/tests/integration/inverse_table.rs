//! The certified tables of `Γ⁻¹` against the exact inverse (f64 bisection), on every shipped design:
//! the proven bound holds on a million points per target, and the check bites on a table with too few
//! segments (on a tenth of the points: its error is far above the tolerance). The designs run on
//! threads of their own.

use host::fit::inverse_table::{InverseTable, RELATIVE_TOLERANCE};
use integration_tests::{build, dense_error, shipped_specs};

const POINTS: usize = 1_000_000;

#[test]
fn proven_bounds_hold_on_a_million_points_and_the_check_bites() {
    std::thread::scope(|scope| {
        let designs: Vec<_> = shipped_specs()
            .into_iter()
            .map(|path| scope.spawn(move || check(&path)))
            .collect();
        for design in designs {
            println!("{}", design.join().expect("the checks above passed"));
        }
    });
}

/// The checks on every target of the design at `path`; what they measured.
fn check(path: &std::path::Path) -> String {
    let mut lines = Vec::new();
    let design = host::spec::load(path).unwrap();
    let result = build(&design);
    for t in &result.targets {
        let map = &t.fit.map;
        let table = map.table.as_ref().expect("every shipped target has a table");
        let span = map.r_max - map.r_min;
        let name = format!("{} {}", design.name, map.target);
        // The bisection resolves η to 2^-52 and f64 rounding of a + b t adds a few ulp.
        let rounding = 1e-12 * (span + map.r_min.abs());
        let error = dense_error(map, table, POINTS);
        assert!(
            error <= table.proven_bound + rounding,
            "{name}: dense error {error:e} above the proven bound {:e}",
            table.proven_bound
        );
        assert!(table.proven_bound <= RELATIVE_TOLERANCE * span, "{name}");
        lines.push(format!(
            "{name}: {} segments, proven {:.3e}, dense {:.3e} ({:.0} % of the bound)",
            table.segments.len(),
            table.proven_bound,
            error,
            100.0 * error / table.proven_bound.max(f64::MIN_POSITIVE)
        ));
        // A table with a third of the segments: its own proven bound still holds, and the same
        // check against the tolerance fails (a curved Γ only: a straight one is exact at any count).
        if table.segments.len() >= 6 {
            let small = InverseTable::with_segments(
                &map.gamma(),
                &map.gains,
                (map.r_min, map.r_max),
                table.segments.len() / 3,
            )
            .unwrap();
            let small_error = dense_error(map, &small, POINTS / 10);
            assert!(
                small_error <= small.proven_bound + rounding,
                "{name}: under-sized table"
            );
            assert!(
                small_error > RELATIVE_TOLERANCE * span,
                "{name}: a table of {} segments passed the tolerance ({small_error:e}): the check cannot fail",
                small.segments.len()
            );
        }
    }
    lines.join("\n")
}
