//! Observers emitted by `cargo run -p host -- gen` (host {{ version }}). Do not edit: regenerate.
{{ licence }}
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

// Emitted files keep the layout `gen` gives them (regeneration is compared byte for byte).
{%- for name in designs %}
#[rustfmt::skip]
pub mod {{ name }};
{%- endfor %}

{%- for f in families %}
{%- let first = f.members[0].0.clone() %}

/// Family `{{ f.name }}`: one design per value of output `{{ f.output_name }}` at the start of a batch
/// ({% for m in f.members %}`{{ m.0 }}` at {{ m.1 }}{% if !loop.last %}, {% endif %}{% endfor %}). Its observer
/// uses the member whose value is nearest the batch's first accepted measurement of that output.
#[rustfmt::skip]
pub mod {{ f.name }} {
    use super::{{ first }} as first;

    /// Horizon, outputs, inputs and targets, shared by every member.
    pub use first::{HORIZON, INPUTS, OUTPUTS, TARGETS};

    /// The members, by increasing value.
    pub static MEMBERS: [firmware::emitted::Member<f32, HORIZON, OUTPUTS, INPUTS, TARGETS>; {{ f.members.len() }}] = [
{%- for m in f.members %}
        firmware::emitted::Member {
            value: {{ m.1 }},
            estimate: <super::{{ m.0 }}::Design as firmware::Design<f32, HORIZON, OUTPUTS, INPUTS, TARGETS>>::estimate,
        },
{%- endfor %}
    ];

    /// Index of the output that selects the member.
    pub const SELECTING_OUTPUT: usize = {{ f.output }};

    /// The family's observer.
    pub type Observer = firmware::FamilyObserver<
        'static,
        f32,
        HORIZON,
        OUTPUTS,
        INPUTS,
        TARGETS,
        {{ f.members.len() }},
    >;

    /// A fresh family observer; call `reset` at the start of each batch.
    pub const fn observer() -> Observer {
        firmware::FamilyObserver::new(&MEMBERS, SELECTING_OUTPUT)
    }

    /// The family's observer is its members' maps: the same type, named as a design's map.
    pub type MapObserver = Observer;

    /// [`observer`], named as a design's map.
    pub const fn map_observer() -> MapObserver {
        observer()
    }
}
{%- endfor %}

/// The family modules, for code that treats them all alike (the on-target size probes).
#[rustfmt::skip]
pub const FAMILIES: [&str; {{ families.len() }}] = [{% for f in families %}"{{ f.name }}"{% if !loop.last %}, {% endif %}{% endfor %}];

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

/// Invokes `$callback!(design, kind, Type)` for every observer of every design module: `kind` named as
/// the spec and the report name it (`ekf_box`), `Type` its type in the design's module (`Type::new()`
/// makes one). The list `gen` wrote: what the tests and the on-target runner iterate.
#[macro_export]
macro_rules! for_each_observer {
    ($callback:ident) => {
{%- for name in designs %}
        $crate::{{ name }}_observers!(each $callback);
{%- endfor %}
    };
}

/// Invokes `$callback!(design, FixedObserver)` for every design module with the integer map.
#[macro_export]
macro_rules! for_each_fixed_observer {
    ($callback:ident) => {
{%- for name in designs %}
        $crate::{{ name }}_observers!(fixed $callback);
{%- endfor %}
    };
}
