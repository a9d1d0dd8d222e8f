//! Observers emitted by `cargo run -p host -- gen` (host {{ version }}). Do not edit: regenerate.
//!
//! One module per design spec; each holds constant tables, an `Observer` type and `observer()`.
{%- if let Some(first) = designs.first() %}
//!
//! ```
//! use generated::{{ first }} as design;
//!
//! let mut observer = design::observer(); // fixed memory: the last HORIZON samples
//! for k in 0..20 {
//!     let y = [0.1 * k as f32; design::OUTPUTS]; // this instant's outputs, in OUTPUT_NAMES order
//!     let u = [0.0; design::INPUTS]; // and inputs, in INPUT_NAMES order
//!     if observer.push(y, u).is_err() {
//!         continue; // a NaN or infinite sample is refused; nothing stored changes
//!     }
//!     if let Some(estimates) = observer.estimate() {
//!         // One per target, in TARGET_NAMES order; `saturation` says if it was clamped.
//!         assert_eq!(estimates.len(), design::TARGETS);
//!         assert!(estimates[0].value.is_finite());
//!     }
//! }
//! ```
{%- endif %}
#![no_std]

pub use firmware;
{% for name in designs %}
pub mod {{ name }};
{%- endfor %}

/// Invokes `$callback!(design)` for every design module, for code that treats them all alike
/// (the generated-vs-library tests, the on-target runner).
#[macro_export]
macro_rules! for_each_design {
    ($callback:ident) => {
{%- for name in designs %}
        $callback!({{ name }});
{%- endfor %}
    };
}
