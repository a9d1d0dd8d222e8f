//! Observers emitted by `cargo run -p host -- gen` (host 0.1.0). Do not edit: regenerate.
//! Licence: emitted by mho from your spec, this file is yours: you may use, copy, modify and
//! distribute it under any terms, including MIT OR Apache-2.0, with or without this notice.
//!
//! One module per design spec; each holds constant tables, an `Observer` type and `observer()`.
//!
//! ```
//! use generated::ecoli_x0_0p5 as design;
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
#![no_std]

pub use firmware;

// Emitted files keep the layout `gen` gives them (regeneration is compared byte for byte).
#[rustfmt::skip]
pub mod ecoli_x0_0p5;
#[rustfmt::skip]
pub mod ecoli_x0_2;
#[rustfmt::skip]
pub mod two_tanks;
#[rustfmt::skip]
pub mod vanderpol;
#[rustfmt::skip]
pub mod vanderpol_searched;
#[rustfmt::skip]
pub mod vanderpol_sparse;
#[rustfmt::skip]
pub mod vanderpol_uncertain;

/// Family `ecoli`: one design per value of output `X_meas` at the start of a batch
/// (`ecoli_x0_0p5` at 0.5, `ecoli_x0_2` at 2.0). Its observer
/// uses the member whose value is nearest the batch's first accepted measurement of that output.
#[rustfmt::skip]
pub mod ecoli {
    use super::ecoli_x0_0p5 as first;

    /// Horizon, outputs, inputs and targets, shared by every member.
    pub use first::{HORIZON, INPUTS, OUTPUTS, TARGETS};

    /// The members, by increasing value.
    pub static MEMBERS: [firmware::emitted::Member<f32, HORIZON, OUTPUTS, INPUTS, TARGETS>; 2] = [
        firmware::emitted::Member {
            value: 0.5,
            estimate: <super::ecoli_x0_0p5::Design as firmware::Design<f32, HORIZON, OUTPUTS, INPUTS, TARGETS>>::estimate,
        },
        firmware::emitted::Member {
            value: 2.0,
            estimate: <super::ecoli_x0_2::Design as firmware::Design<f32, HORIZON, OUTPUTS, INPUTS, TARGETS>>::estimate,
        },
    ];

    /// Index of the output that selects the member.
    pub const SELECTING_OUTPUT: usize = 0;

    /// The family's observer.
    pub type Observer = firmware::FamilyObserver<
        'static,
        f32,
        HORIZON,
        OUTPUTS,
        INPUTS,
        TARGETS,
        2,
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

/// The family modules, for code that treats them all alike (the on-target size probes).
#[rustfmt::skip]
pub const FAMILIES: [&str; 1] = ["ecoli"];

/// Invokes `$callback!(design)` for every design module, for code that treats them all alike
/// (the generated-vs-library tests, the on-target runner).
#[macro_export]
macro_rules! for_each_design {
    ($callback:ident) => {
        $callback!(ecoli_x0_0p5);
        $callback!(ecoli_x0_2);
        $callback!(two_tanks);
        $callback!(vanderpol);
        $callback!(vanderpol_searched);
        $callback!(vanderpol_sparse);
        $callback!(vanderpol_uncertain);
    };
}

/// Invokes `$callback!(design, kind, Type)` for every observer of every design module: `kind` named as
/// the spec and the report name it (`ekf_box`), `Type` its type in the design's module (`Type::new()`
/// makes one). The list `gen` wrote: what the tests and the on-target runner iterate.
#[macro_export]
macro_rules! for_each_observer {
    ($callback:ident) => {
        $crate::ecoli_x0_0p5_observers!(each $callback);
        $crate::ecoli_x0_2_observers!(each $callback);
        $crate::two_tanks_observers!(each $callback);
        $crate::vanderpol_observers!(each $callback);
        $crate::vanderpol_searched_observers!(each $callback);
        $crate::vanderpol_sparse_observers!(each $callback);
        $crate::vanderpol_uncertain_observers!(each $callback);
    };
}

/// Invokes `$callback!(design, FixedObserver)` for every design module with the integer map.
#[macro_export]
macro_rules! for_each_fixed_observer {
    ($callback:ident) => {
        $crate::ecoli_x0_0p5_observers!(fixed $callback);
        $crate::ecoli_x0_2_observers!(fixed $callback);
        $crate::two_tanks_observers!(fixed $callback);
        $crate::vanderpol_observers!(fixed $callback);
        $crate::vanderpol_searched_observers!(fixed $callback);
        $crate::vanderpol_sparse_observers!(fixed $callback);
        $crate::vanderpol_uncertain_observers!(fixed $callback);
    };
}
