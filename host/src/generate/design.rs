//! One design searched, fitted and emitted in memory: the design's own part of `gen`, before
//! anything is reported or written.

use std::path::Path;

use indicatif::ProgressBar;

use super::emitted::{Emitted, Fixed};
use super::error::GenerateError;
use super::shipped::workspace_root;
use crate::data::{self, Runs};
use crate::emit;
use crate::fit::{self, DesignResult};
use crate::spec::{Design, SpecError};

/// Searches (when the spec asks), fits and emits `design`, loaded from `spec` (nothing is written):
/// as a module of the `generated` crate, or with `standalone = Some(crate name)` as the module of a
/// crate of its own.
pub fn emit_design(
    design: Design,
    spec: &Path,
    standalone: Option<&str>,
    progress: &ProgressBar,
) -> Result<Emitted, GenerateError> {
    // What the spec's observer kind rules out is refused before the search and the fit.
    crate::observers::check_before_fit(&design, &model_code(&design)?)?;
    let (design, search, runs) = settle(design, progress)?;
    if search.is_some() {
        progress.set_length(fit::steps(&design));
        progress.set_position(0);
    }
    let result = fit::run(&design, runs, progress)?;
    let taps = crate::search::sparsity::accuracy_vs_taps(&design, &result.runs.learning, &result.runs.validation)
        .map_err(|e| {
            design.error(
                "map.taps",
                format!("a pruned fit failed: {e}"),
                "offer fewer counts in `map.taps`, or leave it out",
            )
        })?;
    // Relative to the checkout when there is one, so that the text does not depend on where it lives.
    let spec_path = match workspace_root() {
        Ok(workspace) => emit::portable_spec_path(spec, &workspace),
        Err(_) => spec.display().to_string(),
    };
    let placement = match standalone {
        None => emit::Placement::Generated { spec: &spec_path },
        Some(crate_name) => emit::Placement::Standalone {
            crate_name,
            source: &spec_path,
        },
    };
    let (comparison, source, c_source, fixed) = design_source(&design, &result, &placement, spec, progress)?;
    Ok(Emitted {
        design,
        result,
        comparison,
        source,
        c_source,
        fixed,
        search,
        taps,
    })
}

/// `design` settled by its search (when the spec has one: [`crate::search::settle`]) and every run it
/// is fitted, tuned and judged on ([`Runs`]), each simulated once: the search's learning and tuning
/// runs are the fit's and the observers'.
pub fn settle(
    design: Design,
    progress: &ProgressBar,
) -> Result<(Design, Option<crate::search::Outcome>, Runs), SpecError> {
    if let Some(search) = &design.search {
        crate::search::check_size(&design, search)?;
    }
    progress.set_message(format!("{}: simulating the runs", design.name));
    let learning = data::learning_set(&design)?;
    let tuning = data::tuning_set(&design)?;
    let (design, search) = crate::search::settle(design, &learning, &tuning, progress)?;
    let long_samples = crate::observers::Drift::long_samples(&design);
    let runs = Runs::complete(&design, learning, tuning, long_samples)?;
    Ok((design, search, runs))
}

/// The runs of `design` simulated ([`Runs::simulate`]) and its maps fitted on them, at the spec's
/// map settings as they are (no design search: [`settle`] runs it).
pub fn simulate_and_fit(design: &Design, progress: &ProgressBar) -> Result<DesignResult, SpecError> {
    let runs = Runs::simulate(design, crate::observers::Drift::long_samples(design))?;
    fit::run(design, runs, progress)
}

/// The design's model written as programs, or an error naming the spec field that cannot be.
pub fn model_code(design: &Design) -> Result<crate::plant::ModelCode, SpecError> {
    crate::plant::ModelCode::new(design).map_err(|e| {
        design.error(
            e.field,
            format!("the model cannot be written as Rust for the chip: {}", e.construct),
            "rewrite the expression as the message says",
        )
    })
}

/// The largest proven distance of the integer map to the float map accepted, as a fraction of the
/// target's learning range (the shipped designs' are below 0.1 %).
pub const MAX_FIXED_BOUND: f64 = 0.02;

/// The map of a fitted design in integers and its validation figures, when its spec asks for it
/// (`[chip] arithmetic = "fixed"`), or an error naming `[chip]` when the map cannot be.
pub fn fixed_point(design: &Design, result: &DesignResult) -> Result<Option<Fixed>, SpecError> {
    let Some(spec) = &design.fixed else { return Ok(None) };
    let maps: Vec<_> = result.targets.iter().map(|t| t.fit.map.clone()).collect();
    let point = crate::fixed_point::quantise(design, spec, &result.runs.learning, &maps)
        .map_err(|e| design.error("chip.arithmetic", e.to_string(), e.fix()))?;
    // A proof so loose that the integer map could be anywhere in its target's range is no
    // integer map to ship: wide converters leave a 32-bit sum too few bits of the gains.
    for (target, spec_target) in point.targets.iter().zip(&design.targets) {
        let relative = target.bound.total() / target.range;
        if relative > MAX_FIXED_BOUND {
            let widest = spec
                .outputs
                .iter()
                .zip(&design.model.outputs)
                .map(|(s, o)| (s, o.name.as_str()))
                .chain(
                    spec.inputs
                        .iter()
                        .zip(&design.model.inputs)
                        .map(|(s, i)| (s, i.as_str())),
                )
                .filter_map(|(s, name)| s.as_ref().map(|s| (i64::from(s.max) - i64::from(s.min), name)))
                .max();
            let field = widest.map_or("chip.raw".to_owned(), |(_, name)| format!("chip.raw.{name}"));
            return Err(design.error(
                field,
                format!(
                    "target `{}`: the integer map's proven distance to the float map is {:.3e}, {:.1} % of the target's learning range (at most {:.0} % is accepted): \
                     the declared raw ranges are too wide for a 32-bit sum to keep enough bits of the gains",
                    spec_target.name,
                    target.bound.total(),
                    relative * 100.0,
                    MAX_FIXED_BOUND * 100.0
                ),
                "declare fewer raw bits (e.g. a 24-bit reading shifted right by 8: `min`/`max` over 256 and `scale` times 256), or set `arithmetic = \"float\"`",
            ));
        }
    }
    let validation = crate::fixed_point::compare(&point, &maps, &result.runs.validation);
    // The proof is checked on every validation window of every design: a window beyond it is a bug.
    for (target, figures) in point.targets.iter().zip(&validation.targets) {
        if let Some(window) = figures.beyond_bound.first() {
            return Err(design.error(
                "chip.arithmetic",
                format!(
                    "the fixed-point map is beyond its proven bound {:.3e} on validation window {window} (a bug in the tool)",
                    target.bound.total()
                ),
                "report it; set `arithmetic = \"float\"` meanwhile",
            ));
        }
    }
    Ok(Some(Fixed { point, validation }))
}

/// The observers of a fitted design compared (the EKF tuned on new runs), the text of its
/// `generated/src/<design>.rs` (maps, model and the model-based observers), its C source and its
/// map in integers (when the spec asks for it).
pub fn design_source(
    design: &Design,
    result: &DesignResult,
    placement: &emit::Placement<'_>,
    spec: &Path,
    progress: &ProgressBar,
) -> Result<(crate::observers::Comparison, String, emit::c::CSource, Option<Fixed>), GenerateError> {
    let code = model_code(design)?;
    let emit_error = |source| GenerateError::Emit {
        file: spec.to_owned(),
        design: design.name.clone(),
        source,
    };
    // Data the chip's f32 cannot hold is refused before minutes of tuning, not after.
    emit::within_f32(result).map_err(emit_error)?;
    let fixed = fixed_point(design, result)?;
    let comparison = crate::observers::compare(design, result, &code, progress)?;
    let state_targets = result.helpers.is_ok().then(|| crate::fit::helpers::state_maps(design));
    let instructions: Vec<(&'static str, f64)> =
        comparison.observers.iter().map(|o| (o.kind, o.instructions)).collect();
    let constants = comparison.tuned.constants();
    let observers = emit::model::Observers {
        constants: &constants,
        state_targets: state_targets.as_deref(),
        kind: comparison.chosen.0,
        instructions: &instructions,
        tables_sha256: &crate::tables::Tables::new(design, result, Some(&comparison)).tables_sha256,
        fixed: fixed.as_ref().map(|f| &f.point),
    };
    let source = emit::design_file(design, result, placement, &code, &observers).map_err(emit_error)?;
    let c_source = emit::c::c_source(design, result, Some((&code, &observers))).map_err(emit_error)?;
    Ok((comparison, source, c_source, fixed))
}
