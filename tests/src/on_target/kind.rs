//! The kinds of observer a generated design has, from the list `gen` wrote with it
//! (`generated::for_each_observer!`, `for_each_fixed_observer!`): which kinds it has, which one its
//! `observer()` is, how many estimates take the start-up path; so that the harness measures what the
//! design ships, under the names the spec, the report, `design.json` and the C give each kind.

use std::any::TypeId;

use firmware::emitted::Follower;
use firmware::Started;
pub use host::spec::ObserverKind;

/// What the harness measures of a design: one of its observer kinds, or its integer map.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Kind {
    /// An observer kind ([`ObserverKind`]; the box EKF is measured as its filter, `ekf()`).
    Of(ObserverKind),
    /// The integer map (`fixed_observer()`, where the design has one): `i32` in and out, over the
    /// raw recorded sequence (`RECORDED_RAW_Y`, `RECORDED_RAW_U`).
    Fixed,
}

impl Kind {
    /// Its name: the kind's ([`ObserverKind::name`]), `fixed` for the integer map. The on-target
    /// program's `ON_TARGET_KIND` and `PROBE_KIND`, `on_target.json` and the C cases use it.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Of(kind) => kind.name(),
            Kind::Fixed => "fixed",
        }
    }

    /// The kind named `name` ([`Kind::name`]).
    pub fn named(name: &str) -> Option<Kind> {
        match name {
            "fixed" => Some(Kind::Fixed),
            _ => host::observers::kind::named(name).map(|entry| Kind::Of(entry.kind)),
        }
    }

    /// What is measured of it, as the report and the tables name it (`map_observer()`, `ekf()`, a
    /// type `gen` declares).
    pub fn api(self) -> &'static str {
        match self {
            Kind::Of(kind) => host::observers::kind::of(kind).measured_as.trim_matches('`'),
            Kind::Fixed => "fixed_observer()",
        }
    }
}

/// Every kind design `name` has, in [`Kind`]'s order: the observers `gen` listed for it, and its
/// integer map where it has one. Empty for an unknown design.
pub fn kinds(name: &str) -> Vec<Kind> {
    let mut kinds = Vec::new();
    macro_rules! of {
        ($design:ident, $kind:ident, $type:ident) => {
            if stringify!($design) == name {
                kinds.push(Kind::named(stringify!($kind)).expect("a kind gen lists is a kind"));
            }
        };
    }
    generated::for_each_observer!(of);
    kinds.extend(has_fixed(name).then_some(Kind::Fixed));
    kinds.sort();
    kinds
}

/// Whether design `name`'s generated file has the integer observer (`fixed_observer()`).
// With no design having one, the macro is never invoked and the list never grows.
#[allow(unused_macros, unused_mut)]
pub fn has_fixed(name: &str) -> bool {
    let mut designs: Vec<&str> = Vec::new();
    macro_rules! fixed {
        ($design:ident, $type:ident) => {
            designs.push(stringify!($design));
        };
    }
    generated::for_each_fixed_observer!(fixed);
    designs.contains(&name)
}

/// The kinds of design `name` that run on the emulated Cortex-M0 (software floating point): the
/// map, the EKF from the box centre, and the integer observer where the design has one.
pub fn m0_kinds(name: &str) -> Vec<Kind> {
    kinds(name)
        .into_iter()
        .filter(|k| matches!(k, Kind::Of(ObserverKind::Map | ObserverKind::EkfBox) | Kind::Fixed))
        .collect()
}

/// The kind of design `name`'s `observer()`: the kind whose type its `Observer` is. `None` for an
/// unknown design, or an `Observer` that is none of them.
pub fn chosen_kind(name: &str) -> Option<Kind> {
    let mut chosen = None;
    macro_rules! of {
        ($design:ident, $kind:ident, $type:ident) => {
            if stringify!($design) == name
                && TypeId::of::<generated::$design::Observer>() == TypeId::of::<generated::$design::$type>()
            {
                chosen = Kind::named(stringify!($kind));
            }
        };
    }
    generated::for_each_observer!(of);
    chosen
}

/// The generated design modules.
pub fn design_names() -> Vec<&'static str> {
    let mut names = Vec::new();
    macro_rules! push_name {
        ($name:ident) => {
            names.push(stringify!($name));
        };
    }
    generated::for_each_design!(push_name);
    names
}

/// The estimates after the first that take the start-up path of an observer the map starts or checks.
trait StartUp {
    /// `Follower::START_UP` of a started observer's follower; `N − 1` for the restarted EKF, whose
    /// estimate number `N` checks the map.
    const START_UP: usize;
}

impl<D, F, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NM: usize, const NT: usize> StartUp
    for Started<f32, D, F, N, NX, NY, NU, NM, NT>
where
    F: Follower<f32, NX, NY, NU, NT>,
{
    const START_UP: usize = F::START_UP;
}

impl<D, F, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NM: usize, const NT: usize> StartUp
    for firmware::Restarted<f32, D, F, N, NX, NY, NU, NM, NT>
where
    F: firmware::emitted::Restart<f32, NX, NY, NU, NT>,
{
    const START_UP: usize = N - 1;
}

impl<H, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NT: usize> StartUp
    for firmware::mhe::Observer<f32, H, N, NX, NY, NU, NT>
where
    H: firmware::emitted::mhe::Horizon<f32, NX, NY, NU, NT>,
{
    const START_UP: usize = 0;
}

impl<D, const N: usize, const NY: usize, const NU: usize, const NT: usize> StartUp
    for firmware::Observer<f32, D, N, NY, NU, NT>
{
    const START_UP: usize = 0;
}

impl<F, const NX: usize, const NY: usize, const NU: usize, const NT: usize> StartUp
    for firmware::FilterObserver<f32, F, NX, NY, NU, NT>
{
    const START_UP: usize = 0;
}

fn follower_start_up<O: StartUp>(_: &O) -> usize {
    O::START_UP
}

/// The estimates after the first that take the start-up path, for design `name`'s observer of
/// `kind`, from the generated code (0 for the map, the filters and the integer map); `None` for a kind it
/// does not have.
pub fn start_up(name: &str, kind: Kind) -> Option<usize> {
    if !kinds(name).contains(&kind) {
        return None;
    }
    let mut start_up = Some(0);
    macro_rules! of {
        ($design:ident, $kind:ident, $type:ident) => {
            if Kind::named(stringify!($kind)) == Some(kind) && stringify!($design) == name {
                start_up = Some(follower_start_up(&generated::$design::$type::new()));
            }
        };
    }
    generated::for_each_observer!(of);
    start_up
}
