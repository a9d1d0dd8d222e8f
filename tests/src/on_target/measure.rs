//! Measuring every design: building its programs and size probes and running them under QEMU
//! (on a second thread while cargo builds the next), then checking that running kinds together
//! counts what each counts alone, and that the no-panic proof catches a reachable panic.

use std::collections::BTreeMap;
use std::path::PathBuf;

use super::board::Board;
use super::elf::{sizes, Program};
use super::kind::{design_names, kinds, m0_kinds, Kind, ObserverKind};
use super::measurement::{Boards, Measurements};
use super::qemu::{run_counted, Count};
use super::semihosting::{parse, parse_ekf};
use super::unavailable::{failed, require_tools, Unavailable};

/// A program built and waiting for QEMU: the design, whether it is the EKF's, and its ELF.
type Built = (String, bool, PathBuf);

/// What QEMU reported for a [`Built`] program: the design, whether it is the EKF's, what the program
/// printed and what each measured call executed.
type Ran = (String, bool, String, Vec<Count>);

/// Builds and runs, per design, the programs on the emulated Cortex-M4F: one that runs the map and
/// every observer the map starts ([`kinds`]) one after the other, and one that runs the EKF from the
/// box centre; then the size probes (one per design and kind, the families, a baseline). Then the
/// same on the emulated Cortex-M0 for the kinds it runs ([`m0_kinds`]: the map and the EKF in
/// software floating point, and the integer observer). QEMU runs on a second thread while cargo
/// builds the next program. `Err(Unavailable::Missing)` when QEMU or binutils are missing.
pub fn measure() -> Result<Boards, Unavailable> {
    Ok(Boards {
        m4f: measure_board(Board::Mps2An386)?,
        m0: measure_board(Board::Microbit)?,
    })
}

/// [`measure`] on one board: every kind of every design and the families on the Cortex-M4F, the
/// kinds it runs ([`m0_kinds`]) on the Cortex-M0.
pub fn measure_board(board: Board) -> Result<Measurements, Unavailable> {
    let families: &[&str] = match board {
        Board::Mps2An386 => &generated::FAMILIES,
        Board::Microbit => &[],
    };
    let designs: Vec<(String, Vec<Kind>)> = design_names()
        .into_iter()
        .map(|name| {
            let kinds = match board {
                Board::Mps2An386 => kinds(name),
                Board::Microbit => m0_kinds(name),
            };
            (name.to_owned(), kinds)
        })
        .collect();
    measure_designs(&Program::project(), board, &designs, families)
}

/// [`measure`] on `board` of `designs` (each with its kinds, the EKF from the centre among them)
/// and `families` (probes only) as `program` links them.
pub fn measure_designs(
    program: &Program,
    board: Board,
    designs: &[(String, Vec<Kind>)],
    families: &[&str],
) -> Result<Measurements, Unavailable> {
    require_tools()?;
    let (ran, probes) = std::thread::scope(|scope| {
        let (send, receive) = std::sync::mpsc::channel::<Built>();
        let qemu = scope.spawn(move || -> Result<Vec<Ran>, Unavailable> {
            receive
                .into_iter()
                .map(|(name, ekf, elf)| {
                    let (text, counts) = run_counted(board, &elf)?;
                    Ok((name, ekf, text, counts))
                })
                .collect()
        });
        let built = (|| -> Result<Probes, Unavailable> {
            for (name, kinds) in designs {
                let name = name.as_str();
                for (group, suffix) in programs(kinds) {
                    let kinds: Vec<&str> = group.iter().map(|k| k.name()).collect();
                    let elf = program
                        .build(
                            board,
                            "on-target",
                            &[("ON_TARGET_DESIGN", name), ("ON_TARGET_KIND", &kinds.join(","))],
                            &format!("runs/{name}{suffix}.elf"),
                        )
                        .map_err(|e| failed(format!("on-target program of {name}: {e}")))?;
                    // The QEMU thread has stopped only after an error, which its result reports.
                    let _ = send.send((name.to_owned(), false, elf));
                }
                let elf = program
                    .build(
                        board,
                        "ekf",
                        &[("ON_TARGET_DESIGN", name)],
                        &format!("runs/{name}.ekf.elf"),
                    )
                    .map_err(|e| failed(format!("EKF program of {name}: {e}")))?;
                let _ = send.send((name.to_owned(), true, elf));
            }
            drop(send);
            probe_all(program, board, designs, families)
        })();
        let ran = qemu
            .join()
            .unwrap_or_else(|_| Err(failed("the thread running QEMU panicked")));
        (ran, built)
    });
    let (ran, probes) = (ran?, probes?);

    let mut all = Measurements {
        board,
        family_flash_bytes: probes.families,
        ..Measurements::default()
    };
    for (name, ekf, text, counts) in ran {
        let cost = |kind: Kind| {
            probes
                .kinds
                .get(&(name.clone(), kind))
                .copied()
                .ok_or_else(|| failed(format!("{name}: no size probe of {kind:?}")))
        };
        if ekf {
            let mut filter = parse_ekf(&text)?;
            if counts.len() != filter.samples.len() {
                return Err(failed(format!(
                    "{name} EKF: {} measured calls for {} samples",
                    counts.len(),
                    filter.samples.len()
                )));
            }
            (filter.instructions, filter.divisions, filter.cycles) = split(counts);
            (filter.flash_bytes, filter.static_ram_bytes) = cost(Kind::Of(ObserverKind::EkfBox))?;
            all.filters.insert(name, filter);
        } else {
            let observers = parse(&text)?;
            let samples: usize = observers.iter().map(|o| o.samples.len()).sum();
            if counts.len() != samples {
                return Err(failed(format!(
                    "{name}: {} measured calls for {samples} samples of {} observers",
                    counts.len(),
                    observers.len()
                )));
            }
            let mut counts = counts.into_iter();
            let by_kind = all.observers.entry(name.clone()).or_default();
            for mut observer in observers {
                (observer.instructions, observer.divisions, observer.cycles) =
                    split(counts.by_ref().take(observer.samples.len()).collect());
                (observer.flash_bytes, observer.static_ram_bytes) = cost(observer.kind)?;
                if by_kind.insert(observer.kind, observer).is_some() {
                    return Err(failed(format!("{name}: one kind ran twice")));
                }
            }
        }
    }
    Ok(all)
}

/// Instructions, divisions and cycles of each call, apart.
fn split(counts: Vec<Count>) -> (Vec<u64>, Vec<u64>, Vec<u64>) {
    let instructions = counts.iter().map(|c| c.instructions).collect();
    let divisions = counts.iter().map(|c| c.divisions).collect();
    (instructions, divisions, counts.iter().map(|c| c.cycles).collect())
}

/// The `on-target` programs that measure `kinds` (the EKF from the box centre has a program of its
/// own, `ekf`), each with its file name's suffix: the map and the observers it starts together, and
/// the restarted EKF alone, since it shares the filter's code with the map-started EKF and linked
/// together the compiler would inline it differently ([`same_alone`] checks that it does not), and the
/// moving-horizon observer and the UKF alone (they share the model's code with the others).
fn programs(kinds: &[Kind]) -> Vec<(Vec<Kind>, &'static str)> {
    let started: Vec<Kind> = kinds
        .iter()
        .copied()
        .filter(|&k| {
            k != Kind::Of(ObserverKind::EkfBox)
                && k != Kind::Of(ObserverKind::EkfRestart)
                && k != Kind::Of(ObserverKind::Mhe)
                && k != Kind::Of(ObserverKind::UkfBox)
        })
        .collect();
    let mut programs = vec![(started, "")];
    if kinds.contains(&Kind::Of(ObserverKind::EkfRestart)) {
        programs.push((vec![Kind::Of(ObserverKind::EkfRestart)], ".ekf_restart"));
    }
    if kinds.contains(&Kind::Of(ObserverKind::Mhe)) {
        programs.push((vec![Kind::Of(ObserverKind::Mhe)], ".mhe"));
    }
    if kinds.contains(&Kind::Of(ObserverKind::UkfBox)) {
        programs.push((vec![Kind::Of(ObserverKind::UkfBox)], ".ukf_box"));
    }
    programs
}

/// What the size probes measured: `(flash, static RAM)` added over the baseline per design and
/// kind, and the families' flash.
struct Probes {
    kinds: BTreeMap<(String, Kind), (u64, u64)>,
    families: BTreeMap<String, u64>,
}

/// Builds the baseline probe, one probe per design and kind, and one per family, for `board`.
fn probe_all(
    program: &Program,
    board: Board,
    designs: &[(String, Vec<Kind>)],
    families: &[&str],
) -> Result<Probes, Unavailable> {
    let baseline = sizes(
        &program
            .build(board, "probe", &[], "probes/baseline.elf")
            .map_err(|e| failed(format!("baseline probe: {e}")))?,
    )?;
    let mut kinds = BTreeMap::new();
    for (name, design_kinds) in designs {
        for &kind in design_kinds {
            let probe = program
                .build(
                    board,
                    "probe",
                    &[("PROBE_DESIGN", name), ("PROBE_KIND", kind.name())],
                    &format!("probes/{name}.{}.elf", kind.name()),
                )
                .map_err(|e| {
                    failed(format!(
                        "probe of {name}'s {} (a panic path would show here): {e}",
                        kind.api()
                    ))
                })?;
            let (text, data, bss) = sizes(&probe)?;
            let cost = (
                (text + data).saturating_sub(baseline.0 + baseline.1),
                (data + bss).saturating_sub(baseline.1 + baseline.2),
            );
            kinds.insert((name.clone(), kind), cost);
        }
    }
    let mut family_flash = BTreeMap::new();
    for &family in families {
        let probe = program
            .build(
                board,
                "probe",
                &[("PROBE_DESIGN", family)],
                &format!("probes/{family}.elf"),
            )
            .map_err(|e| failed(format!("probe of family {family}: {e}")))?;
        let (text, data, _) = sizes(&probe)?;
        family_flash.insert(family.to_owned(), (text + data).saturating_sub(baseline.0 + baseline.1));
    }
    Ok(Probes {
        kinds,
        families: family_flash,
    })
}

/// Builds the runner of design `name` with `kind` alone and returns the instructions of each of its
/// measured calls: the report checks that running several kinds in one program ([`measure`]) counts
/// what each kind counts when linked alone ([`same_alone`]).
pub fn instructions_alone(program: &Program, name: &str, kind: Kind) -> Result<Vec<u64>, Unavailable> {
    require_tools()?;
    if kind == Kind::Of(ObserverKind::EkfBox) {
        return Err(failed("the EKF from the box centre runs alone already"));
    }
    let elf = program
        .build(
            Board::Mps2An386,
            "on-target",
            &[("ON_TARGET_DESIGN", name), ("ON_TARGET_KIND", kind.name())],
            &format!("runs/{name}.{}.elf", kind.name()),
        )
        .map_err(|e| failed(format!("on-target program of {name}'s {} alone: {e}", kind.api())))?;
    let (_, counts) = run_counted(Board::Mps2An386, &elf)?;
    Ok(counts.into_iter().map(|c| c.instructions).collect())
}

/// Checks that every kind of every design that ran with others counts, built alone, the same
/// instructions: the program that runs them together measures what a firmware with one kind runs.
pub fn same_alone(program: &Program, all: &Measurements) -> Result<(), String> {
    for (name, observers) in &all.observers {
        let kinds: Vec<Kind> = observers.keys().copied().collect();
        let shared: Vec<Kind> = programs(&kinds)
            .into_iter()
            .filter(|(group, _)| group.len() > 1)
            .flat_map(|(group, _)| group)
            .collect();
        for (&kind, observer) in observers.iter().filter(|(k, _)| shared.contains(k)) {
            let alone = instructions_alone(program, name, kind).map_err(|e| e.to_string())?;
            if alone != observer.instructions {
                return Err(format!(
                    "{name} {}: linked with the other kinds it counts {:?}, alone {alone:?}: the program that runs them together does not measure what a firmware with this kind alone runs",
                    kind.api(),
                    observer.instructions
                ));
            }
        }
    }
    Ok(())
}

/// Builds the probe that indexes out of bounds: it must fail to link, naming the missing symbol.
pub fn panic_check_catches_a_reachable_panic() -> Result<bool, Unavailable> {
    match Program::project().build(
        Board::Mps2An386,
        "probe",
        &[("PROBE_DESIGN", "__reachable_panic")],
        "probes/reachable_panic.elf",
    ) {
        Ok(_) => Ok(false),
        Err(stderr) => Ok(stderr.contains("observer_code_can_panic")),
    }
}
