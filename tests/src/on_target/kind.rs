//! The kinds of observer a generated design has, read from the generated code itself (which kinds
//! its file declares, which one its `observer()` is, how many estimates take the start-up path), so
//! that the harness measures what the design ships.

use std::any::TypeId;

use firmware::emitted::Follower;
use firmware::Started;

/// A kind of observer a generated design may have.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Kind {
    /// The paper's map (`map_observer()`, every design).
    Map,
    /// The model-corrected map (`CorrectedObserver`).
    Corrected,
    /// The EKF started by the map (`StartedEkfObserver`).
    StartedEkf,
    /// The EKF from the box centre, restarted by the map (`RestartedEkfObserver`).
    RestartedEkf,
    /// The EKF from the centre of the state box (`ekf()`, every design).
    Ekf,
    /// The unscented Kalman filter from the centre of the state box (`UkfObserver`).
    Ukf,
    /// The moving-horizon estimate with fixed Gauss–Newton steps (`MheObserver`).
    Mhe,
    /// The integer map (`fixed_observer()`, where the design has one): `i32` in and out, over the
    /// raw recorded sequence (`RECORDED_RAW_Y`, `RECORDED_RAW_U`).
    Fixed,
}

impl Kind {
    /// Every kind, in the order the report lists them.
    pub const ALL: [Kind; 8] = [
        Kind::Map,
        Kind::Corrected,
        Kind::StartedEkf,
        Kind::RestartedEkf,
        Kind::Ekf,
        Kind::Ukf,
        Kind::Mhe,
        Kind::Fixed,
    ];

    /// Its name for the on-target program (`ON_TARGET_KIND`, `PROBE_KIND`).
    pub fn chip_name(self) -> &'static str {
        match self {
            Kind::Map => "map",
            Kind::Corrected => "corrected",
            Kind::StartedEkf => "started_ekf",
            Kind::RestartedEkf => "restarted_ekf",
            Kind::Ekf => "ekf",
            Kind::Ukf => "ukf",
            Kind::Mhe => "mhe",
            Kind::Fixed => "fixed",
        }
    }

    /// Its name in `report.json` (`observers[].kind`) and `on_target.json`.
    pub fn report_name(self) -> &'static str {
        match self {
            Kind::Map => "map",
            Kind::Corrected => "corrected",
            Kind::StartedEkf => "ekf_map",
            Kind::RestartedEkf => "ekf_restart",
            Kind::Ekf => "ekf_box",
            Kind::Ukf => "ukf_box",
            Kind::Mhe => "mhe",
            Kind::Fixed => "fixed",
        }
    }

    /// How firmware makes one.
    pub fn api(self) -> &'static str {
        match self {
            Kind::Map => "map_observer()",
            Kind::Corrected => "CorrectedObserver::new()",
            Kind::StartedEkf => "StartedEkfObserver::new()",
            Kind::RestartedEkf => "RestartedEkfObserver::new()",
            Kind::Ekf => "ekf()",
            Kind::Ukf => "UkfObserver::new()",
            Kind::Mhe => "MheObserver::new()",
            Kind::Fixed => "fixed_observer()",
        }
    }

    pub(super) fn from_chip_name(name: &str) -> Option<Kind> {
        Kind::ALL.into_iter().find(|k| k.chip_name() == name)
    }
}

/// Every kind design `name` has, in [`Kind::ALL`]'s order: the map, the observers the map starts
/// that its generated file declares, and the EKF from the centre. Empty for an unknown design.
pub fn kinds(name: &str) -> Vec<Kind> {
    let mut kinds = Vec::new();
    if design_names().contains(&name) {
        kinds.push(Kind::Map);
    }
    macro_rules! started {
        ($design:ident, $kind:ident, $type:ident) => {
            if stringify!($design) == name {
                kinds.push(Kind::$kind);
            }
        };
    }
    for_each_started_observer!(started);
    if !kinds.is_empty() {
        kinds.push(Kind::Ekf);
    }
    kinds.extend(has_fixed(name).then_some(Kind::Fixed));
    kinds.extend(has_ukf(name).then_some(Kind::Ukf));
    kinds.sort();
    kinds
}

/// Whether design `name`'s generated file has the integer observer (`fixed_observer()`).
// With no design having one, the macro is never invoked and the list never grows.
#[allow(unused_macros, unused_mut)]
pub fn has_fixed(name: &str) -> bool {
    let mut designs: Vec<&str> = Vec::new();
    macro_rules! fixed {
        ($design:ident) => {
            designs.push(stringify!($design));
        };
    }
    for_each_fixed_observer!(fixed);
    designs.contains(&name)
}

/// Whether design `name`'s generated file has the unscented Kalman filter (`UkfObserver`).
#[allow(unused_macros, unused_mut)]
pub fn has_ukf(name: &str) -> bool {
    let mut designs: Vec<&str> = Vec::new();
    macro_rules! ukf {
        ($design:ident) => {
            designs.push(stringify!($design));
        };
    }
    for_each_ukf_observer!(ukf);
    designs.contains(&name)
}

/// The kinds of design `name` that run on the emulated Cortex-M0 (software floating point): the
/// map, the EKF from the box centre, and the integer observer where the design has one.
pub fn m0_kinds(name: &str) -> Vec<Kind> {
    kinds(name)
        .into_iter()
        .filter(|k| matches!(k, Kind::Map | Kind::Ekf | Kind::Fixed))
        .collect()
}

/// The kind of design `name`'s `observer()` (its type compared with each kind's); `None` for an
/// unknown design, or an `Observer` that is none of the kinds.
pub fn chosen_kind(name: &str) -> Option<Kind> {
    let mut chosen = None;
    macro_rules! map {
        ($design:ident) => {
            if stringify!($design) == name
                && TypeId::of::<generated::$design::Observer>() == TypeId::of::<generated::$design::MapObserver>()
            {
                chosen = Some(Kind::Map);
            }
        };
    }
    generated::for_each_design!(map);
    macro_rules! started {
        ($design:ident, $kind:ident, $type:ident) => {
            if stringify!($design) == name
                && TypeId::of::<generated::$design::Observer>() == TypeId::of::<generated::$design::$type>()
            {
                chosen = Some(Kind::$kind);
            }
        };
    }
    for_each_started_observer!(started);
    // The EKF from the box centre, which every design the host can filter has.
    macro_rules! boxed {
        ($design:ident) => {
            if stringify!($design) == name && generated::$design::KIND == "ekf_box" {
                chosen = Some(Kind::Ekf);
            }
        };
    }
    generated::for_each_design!(boxed);
    #[allow(unused_macros)]
    macro_rules! unscented {
        ($design:ident) => {
            if stringify!($design) == name && generated::$design::KIND == "ukf_box" {
                chosen = Some(Kind::Ukf);
            }
        };
    }
    for_each_ukf_observer!(unscented);
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

impl<D, F, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NT: usize> StartUp
    for Started<f32, D, F, N, NX, NY, NU, NT>
where
    F: Follower<f32, NX, NY, NU, NT>,
{
    const START_UP: usize = F::START_UP;
}

impl<D, F, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NT: usize> StartUp
    for firmware::Restarted<f32, D, F, N, NX, NY, NU, NT>
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

fn follower_start_up<O: StartUp>(_: &O) -> usize {
    O::START_UP
}

/// The estimates after the first that take the start-up path, for design `name`'s observer of
/// `kind`, from the generated code (0 for the map and the EKF); `None` for a kind it does not have.
pub fn start_up(name: &str, kind: Kind) -> Option<usize> {
    if !kinds(name).contains(&kind) {
        return None;
    }
    let mut start_up = Some(0);
    macro_rules! started {
        ($design:ident, $kind:ident, $type:ident) => {
            if kind == Kind::$kind && stringify!($design) == name {
                start_up = Some(follower_start_up(&generated::$design::$type::new()));
            }
        };
    }
    for_each_started_observer!(started);
    start_up
}
