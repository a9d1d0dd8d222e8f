//! How much the chosen kind's figures depend on the model being right: where the design declares
//! uncertain parameters, its RMSE on the nominal plant against its RMSE at each corner of their box
//! (the same validation starts and noise, every observer keeping the nominal model).

use std::fmt::Write;

use super::schema::{MismatchReport, Report};

/// One sentence per target for `observer()`'s kind: nominal, the corners' range, the worst corner
/// over the nominal; empty without uncertain parameters or when the kind has no such figures.
pub fn sentence(report: &Report<'_>, m: &MismatchReport) -> String {
    let kind = report.observer.0.name();
    let Some(o) = report.observers.iter().find(|o| o.kind == kind) else {
        return String::new();
    };
    let mut parts = Vec::new();
    for t in &report.targets {
        let Some(f) = o.targets.get(t.name) else { continue };
        let (Some(nominal), Some(corners)) = (
            f.rmse_nominal,
            f.rmse_corners.iter().copied().collect::<Option<Vec<f64>>>(),
        ) else {
            parts.push(format!("{}: diverged on the nominal plant or at a corner", t.name));
            continue;
        };
        let (low, high) = corners
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(l, h), &c| (l.min(c), h.max(c)));
        let (worst, _) = (m.corners.iter().zip(&corners))
            .max_by(|a, b| a.1.total_cmp(b.1))
            .map_or((String::new(), 0.0), |(c, &v)| {
                let at: Vec<String> = m.parameters.iter().zip(c).map(|(n, v)| format!("{n} = {v}")).collect();
                (at.join(", "), v)
            });
        parts.push(format!(
            "{} {nominal:.4} on the nominal plant, {low:.4} to {high:.4} at the corners ({:.2}× at worst, at {worst})",
            t.name,
            high / nominal
        ));
    }
    let mut s = String::new();
    if !parts.is_empty() {
        let _ = writeln!(
            s,
            "\nWhat depends on the model being right: `observer()` (`{kind}`), validation RMSE {}.",
            parts.join("; ")
        );
    }
    s
}
