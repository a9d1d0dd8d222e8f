//! The report's section on the map in integers (`[chip] arithmetic = "fixed"`): each target's
//! formats, its proven bound by cause and what the validation runs show of it, beside the float map.

use std::fmt::Write as _;

use serde::Serialize;

use crate::fit::DesignResult;
use crate::generate::Fixed;
use crate::spec::{Design, RawScale};

/// `report.json`'s `fixed_point`.
#[derive(Clone, Debug, Serialize)]
pub struct FixedPointReport {
    /// Each output's raw scaling (declared, or the default Q format), in the model's order.
    pub outputs: Vec<RawScale>,
    /// Each input's.
    pub inputs: Vec<RawScale>,
    /// Validation windows compared.
    pub windows: usize,
    /// Samples of those windows a converter of the declared range clamps.
    pub clamped: usize,
    /// One per target, in the spec's order.
    pub targets: Vec<FixedTargetReport>,
}

/// One target's integer map.
#[derive(Clone, Debug, Serialize)]
pub struct FixedTargetReport {
    /// The target.
    pub name: String,
    /// `F`: fractional bits of the table coordinate.
    pub fraction_bits: u32,
    /// `P`: bits of the position in a segment.
    pub product_bits: u32,
    /// `R`: the estimate's LSB is `2^−R` target units.
    pub lsb_bits: i32,
    /// `|C| + Σ|G_i| M_i + K 2^F`, at most `2³¹ − 1`: the overflow proof.
    pub reach: i64,
    /// Proven `|fixed − f64 map|`: the float table's own distance to `Γ⁻¹`.
    pub bound_table: f64,
    /// The gains' rounding times the raw ranges.
    pub bound_gains: f64,
    /// The table in integers.
    pub bound_evaluation: f64,
    /// Their sum, rounded up to the three digits the report shows.
    pub bound: f64,
    /// The bound in percent of the learning range `r_max − r_min`.
    pub bound_percent_of_range: f64,
    /// Largest `|fixed − f64 map|` over the validation windows.
    pub largest_difference_validation: f64,
    /// RMSE against the true target over the validation windows (samples as converter counts).
    pub rmse_validation: f64,
    /// Largest |error| there.
    pub max_error_validation: f64,
    /// The float map's validation RMSE, for comparison.
    pub rmse_validation_float: f64,
}

/// The section's data.
pub fn of(design: &Design, result: &DesignResult, fixed: &Fixed) -> FixedPointReport {
    FixedPointReport {
        outputs: fixed.point.outputs.clone(),
        inputs: fixed.point.inputs.clone(),
        windows: fixed.validation.windows,
        clamped: fixed.validation.clamped,
        targets: fixed
            .point
            .targets
            .iter()
            .zip(&fixed.validation.targets)
            .zip(&result.targets)
            .map(|((target, figures), fit)| FixedTargetReport {
                name: design.targets[fit.index].name.clone(),
                fraction_bits: target.fraction_bits,
                product_bits: target.product_bits,
                lsb_bits: target.lsb_bits,
                reach: target.reach,
                bound_table: target.bound.table,
                bound_gains: target.bound.gains,
                bound_evaluation: target.bound.evaluation,
                bound: target.stated_bound(),
                bound_percent_of_range: 100.0 * target.bound.total() / (fit.fit.map.r_max - fit.fit.map.r_min),
                largest_difference_validation: figures.largest_difference,
                rmse_validation: figures.rmse,
                max_error_validation: figures.max_error,
                rmse_validation_float: fit.validation.map.rmse,
            })
            .collect(),
    }
}

/// The Markdown section.
pub fn section(report: &FixedPointReport) -> String {
    let mut s = String::from("\n## The map in integers (chips without an FPU)\n\n");
    let scaling = |s: &RawScale| format!("{:?} + {:?} · raw, raw ∈ [{}, {}]", s.offset, s.scale, s.min, s.max);
    let _ = writeln!(
        s,
        "Samples as converter counts: {}. Validation: {} windows ({} clamped samples).\n",
        report
            .outputs
            .iter()
            .chain(&report.inputs)
            .map(scaling)
            .collect::<Vec<_>>()
            .join("; "),
        report.windows,
        report.clamped
    );
    s.push_str("| target | F / P / LSB | proven \\|fixed − f64 map\\| (table + gains + integer table) | of the range | largest on validation | RMSE validation (float map) | max error validation |\n");
    s.push_str("|---|---|---|---|---|---|---|\n");
    for t in &report.targets {
        let _ = writeln!(
            s,
            "| {} | {} / {} / 2^{} | {:.2e} ({:.1e} + {:.1e} + {:.1e}) | {:.3} % | {:.2e} | {:.4} ({:.4}) | {:.4} |",
            t.name,
            t.fraction_bits,
            t.product_bits,
            -t.lsb_bits,
            t.bound,
            t.bound_table,
            t.bound_gains,
            t.bound_evaluation,
            t.bound_percent_of_range,
            t.largest_difference_validation,
            t.rmse_validation,
            t.rmse_validation_float,
            t.max_error_validation
        );
    }
    s.push_str(
        "\nThe sums are 32-bit and cannot overflow for samples in the declared ranges (|C| + Σ|G_i| M_i + K 2^F ≤ 2³¹ − 1, \
         checked when the design compiles); a sample outside is refused. The bound holds for every sample in those ranges; \
         the validation runs show how much of it real signals use.\n",
    );
    s
}
