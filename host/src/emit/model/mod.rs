//! The model of a design written out as Rust: one `let` per operation of its straight-line programs
//! ([`crate::plant::Program`]), in their order, generic over the firmware's [`firmware::Scalar`] so
//! that the chip runs it in `f32` and the host's tests in `f64`; and the design's EKF over it.
//!
//! Every number is written once for both precisions (`T::literal(f32, f64)`, each rounded here), every
//! function is the firmware's `Maths::…` (libm), every name a local of the spec's name with a prefix
//! (`x_` states, `u_` inputs; parameters are constants of module `parameters`), so nothing of the
//! spec's text is pasted into code.
//!
//! One submodule per piece: `rust_text` (literals, lists, a program's `let`s), `plant` (the model and
//! the EKF), `filter` (the frame every Kalman filter shares); each model-based kind's own part comes
//! from its entry in the registry ([`crate::observers::kind::Kind::rust`]).

pub(crate) mod filter;
pub mod observers;
mod plant;
pub(crate) mod rust_text;

pub use observers::Observers;

use crate::emit::EmitError;
use crate::observers::kind::REGISTRY;
use crate::plant::ModelCode;
use crate::spec::Design;
use plant::model_and_ekf;

/// The Rust source of the design's model (`parameters`, `Plant`, `targets`), its EKF (`ekf`), its
/// model-based followers of the map, and `Observer` / `observer()` of the chosen kind.
pub fn model_source(design: &Design, code: &ModelCode, observers: &Observers<'_>) -> Result<String, EmitError> {
    let mut text = model_and_ekf(design, code, observers.ekf())?;
    for rust in REGISTRY.iter().filter_map(|entry| entry.rust) {
        if let Some(part) = rust(design, code, observers)? {
            text.push_str(&part);
        }
    }
    let entry = crate::observers::kind::of(observers.kind);
    let (ty, kind) = (entry.observer_type, entry.kind.name());
    let what = format!("{} ([`{ty}`])", entry.what);
    text.push_str(&askama::Template::render(&KindText {
        kind,
        what: &what,
        ty,
        tables: observers.tables_sha256,
    })?);
    Ok(text)
}

/// `KIND`, `Observer` and `observer()` of the chosen kind (`ty`: its type), and `TABLES_SHA256`.
#[derive(askama::Template)]
#[template(path = "model/kind.rs", escape = "none")]
struct KindText<'a> {
    kind: &'a str,
    what: &'a str,
    ty: &'a str,
    tables: &'a str,
}
