//! Estimated cycles of an executed instruction trace: the one place that holds the cores' published
//! timing, so that every cycle figure of the reports comes from the same table.
//!
//! QEMU counts instructions, not cycles. The cycles are estimated per executed instruction from its
//! mnemonic (read from `arm-none-eabi-objdump -d` of the ELF that ran: address → mnemonic, operands,
//! size) and, for an instruction that can branch, whether it branched (the next traced address is not
//! the one after it), with the figures of
//!
//! - **Cortex-M4 (with FPU)**, ARM Cortex-M4 Technical Reference Manual r0p1, Table 3-1 "Processor
//!   instruction set summary" and the FPU's Table 7-1: data processing, `MUL`, `MLA`, `MLS` and the
//!   long multiplies 1 cycle; `LDR`/`STR` (every width) 2, `LDRD`/`STRD` 3, `LDM`/`STM`/`PUSH`/`POP`
//!   1 + N; a taken branch 1 + P with the pipeline refill P taken as **2** (3 cycles for a taken `B`,
//!   `BL`, `BX`, `BLX`, `CBZ`/`CBNZ`; 1 not taken; `TBB`/`TBH` 2 + P; `POP`/`LDM` loading the PC 1 + N + P,
//!   `LDR` to the PC 2 + P); `SDIV`/`UDIV` 2 to 12 by the operands, taken as **12** (the bound: a
//!   register's value is not in the trace); `VADD`, `VSUB`, `VMUL`, `VNMUL`, `VABS`, `VNEG`, `VCMP`,
//!   `VCVT`, `VMRS`/`VMSR` 1, `VMLA`/`VMLS`/`VNMLA`/`VNMLS` and `VFMA`/`VFMS`/`VFNMA`/`VFNMS` 3, `VDIV`
//!   and `VSQRT` 14, `VLDR`/`VSTR` 2 (3 for a double), `VMOV` 1 (2 when it moves two core registers),
//!   `VLDM`/`VSTM`/`VPUSH`/`VPOP` 1 + N words;
//! - **Cortex-M0+**, ARM Cortex-M0+ Technical Reference Manual r0p1, "Instruction set summary": every
//!   instruction 1 cycle except loads and stores 2, `LDM`/`STM`/`PUSH`/`POP` 1 + N, `POP` with the PC
//!   3 + N, a taken branch 2 (not taken 1), `BL` 3, `BX`/`BLX` 2, a write to the PC (`MOV`/`ADD pc`) 2,
//!   `MULS` 1 (the single-cycle multiplier option), `MRS`/`MSR`/barriers 3. The emulated Cortex-M0 runs
//!   the same ARMv6-M instructions; a Cortex-M0 itself (3-stage pipeline) takes one cycle more per
//!   taken branch.
//!
//! Assumed throughout: zero wait-state memory (flash and RAM), no bus contention and no interrupt; a
//! load is not pipelined with its neighbour (the M4's N + 1 for consecutive loads is not modelled, so
//! the M4 estimate is an upper bound there), and an instruction an `IT` block skips costs what it
//! would executed (the trace does not say whether its condition held).

use std::collections::{BTreeMap, HashMap};

/// A core whose timing this file holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Core {
    /// Cortex-M4 with its single-precision FPU (`thumbv7em-none-eabihf`).
    CortexM4F,
    /// Cortex-M0+ with the single-cycle multiplier (`thumbv6m-none-eabi`, soft float).
    CortexM0Plus,
}

/// The M4's pipeline refill after a taken branch (P, 1 to 3 by the TRM): the middle of the range.
pub const M4_REFILL: u64 = 2;
/// The M4's `SDIV`/`UDIV` cycles (2 to 12 by the operands): the bound.
pub const M4_DIVISION: u64 = 12;

/// One instruction of a disassembly.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Instruction {
    /// As objdump writes it, lower case (`vmul.f32`, `beq.n`, `pop`).
    pub mnemonic: String,
    /// Its operands (`{r4, r5, r7, pc}`), comments removed.
    pub operands: String,
    /// Bytes: 2 or 4.
    pub size: u64,
}

impl Instruction {
    /// Whether it is `VDIV` or `VSQRT` (the divisions the reports count).
    pub fn is_division(&self) -> bool {
        matches!(base(&self.mnemonic).as_str(), "vdiv" | "vsqrt")
    }
}

/// Every instruction of `objdump -d` output by address.
pub fn parse_disassembly(text: &str) -> BTreeMap<u64, Instruction> {
    text.lines()
        .filter_map(|line| {
            // "     1a4:\teec0 7a80 \tvdiv.f32\ts15, s1, s0"
            let (address, rest) = line.trim_start().split_once(':')?;
            let address = u64::from_str_radix(address.trim(), 16).ok()?;
            let mut fields = rest.split('\t');
            let (_, hex, mnemonic) = (fields.next()?, fields.next()?, fields.next()?.trim());
            let size = hex.chars().filter(char::is_ascii_hexdigit).count() as u64 / 2;
            if mnemonic.is_empty() || mnemonic.starts_with('.') || !(size == 2 || size == 4) {
                return None;
            }
            let operands = fields.next().unwrap_or("");
            let operands = operands.split([';', '@']).next().unwrap_or("").trim();
            Some((
                address,
                Instruction {
                    mnemonic: mnemonic.to_ascii_lowercase(),
                    operands: operands.to_owned(),
                    size,
                },
            ))
        })
        .collect()
}

/// The condition codes a mnemonic may end with (inside an `IT` block, or a conditional branch).
const CONDITIONS: [&str; 16] = [
    "eq", "ne", "cs", "hs", "cc", "lo", "mi", "pl", "vs", "vc", "hi", "ls", "ge", "lt", "gt", "le",
];

/// What an instruction costs, by kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Class {
    /// Data processing, moves, compares, bit fields, extends, hints.
    Simple,
    /// `MLA`, `MLS`, long multiplies (1 on both cores' tables; kept apart for clarity).
    Multiply,
    /// `SDIV`, `UDIV`.
    Divide,
    /// `LDR`/`STR` of a byte, half-word or word.
    Memory,
    /// `LDRD`, `STRD`.
    Double,
    /// `LDM`, `STM`, `PUSH`, `POP` (N registers).
    Multiple,
    /// `B` (conditional or not).
    Branch,
    /// `BL`.
    BranchLink,
    /// `BX`, `BLX`.
    BranchExchange,
    /// `CBZ`, `CBNZ`.
    CompareBranch,
    /// `TBB`, `TBH`.
    Table,
    /// `DMB`, `DSB`, `ISB`, `MRS`, `MSR`.
    System,
    /// `VADD`, `VSUB`, `VMUL`, `VNMUL`, `VABS`, `VNEG`, `VCMP`, `VCVT`, `VMRS`, `VMSR`.
    Float,
    /// `VMLA`, `VMLS`, `VNMLA`, `VNMLS`, `VFMA`, `VFMS`, `VFNMA`, `VFNMS`.
    FloatAccumulate,
    /// `VDIV`, `VSQRT`.
    FloatDivide,
    /// `VLDR`, `VSTR`.
    FloatMemory,
    /// `VMOV`.
    FloatMove,
    /// `VLDM`, `VSTM`, `VPUSH`, `VPOP` (N words).
    FloatMultiple,
}

/// The class of a mnemonic without its condition, flag-setting `s` or width/type suffix.
fn class_of(name: &str) -> Option<Class> {
    use Class::*;
    Some(match name {
        "mul" => Simple,
        "mla" | "mls" | "umull" | "smull" | "umlal" | "smlal" => Multiply,
        "sdiv" | "udiv" => Divide,
        "ldr" | "ldrb" | "ldrh" | "ldrsb" | "ldrsh" | "str" | "strb" | "strh" | "ldrex" | "strex" => Memory,
        "ldrd" | "strd" => Double,
        "ldm" | "ldmia" | "ldmfd" | "ldmdb" | "stm" | "stmia" | "stmea" | "stmdb" | "stmfd" | "push" | "pop" => {
            Multiple
        }
        "b" => Branch,
        "bl" => BranchLink,
        "bx" | "blx" => BranchExchange,
        "cbz" | "cbnz" => CompareBranch,
        "tbb" | "tbh" => Table,
        "dmb" | "dsb" | "isb" | "mrs" | "msr" => System,
        "vadd" | "vsub" | "vmul" | "vnmul" | "vabs" | "vneg" | "vcmp" | "vcmpe" | "vcvt" | "vcvtr" | "vmrs"
        | "vmsr" => Float,
        "vmla" | "vmls" | "vnmla" | "vnmls" | "vfma" | "vfms" | "vfnma" | "vfnms" => FloatAccumulate,
        "vdiv" | "vsqrt" => FloatDivide,
        "vldr" | "vstr" => FloatMemory,
        "vmov" => FloatMove,
        "vldm" | "vldmia" | "vldmdb" | "vstm" | "vstmia" | "vstmdb" | "vpush" | "vpop" => FloatMultiple,
        "adc" | "add" | "addw" | "adr" | "and" | "asr" | "bfc" | "bfi" | "bic" | "clz" | "cmn" | "cmp" | "eor"
        | "lsl" | "lsr" | "mov" | "movw" | "movt" | "mvn" | "neg" | "orn" | "orr" | "rbit" | "rev" | "rev16"
        | "revsh" | "ror" | "rrx" | "rsb" | "sbc" | "sbfx" | "ssat" | "sub" | "subw" | "sxtb" | "sxth" | "teq"
        | "tst" | "ubfx" | "usat" | "uxtb" | "uxth" | "sxtab" | "sxtah" | "uxtab" | "uxtah" | "nop" | "cpsid"
        | "cpsie" | "sev" | "yield" | "bkpt" | "udf" => Simple,
        it if it.starts_with("it") && it[2..].chars().all(|c| c == 't' || c == 'e') && it.len() <= 5 => Simple,
        _ => return None,
    })
}

/// The mnemonic's base name (`vmovne.f32` → `vmov`, `bls.n` → `b`, `lsls` → `lsl`), as
/// [`class_of`] knows it; the name itself when it knows none.
fn base(mnemonic: &str) -> String {
    let name = mnemonic.split('.').next().unwrap_or(mnemonic);
    let known = |n: &str| class_of(n).is_some();
    let with_s = |n: &str| {
        if known(n) {
            Some(n.to_owned())
        } else {
            n.strip_suffix('s').filter(|n| known(n)).map(str::to_owned)
        }
    };
    if known(name) {
        return name.to_owned();
    }
    let without_condition = CONDITIONS
        .iter()
        .find_map(|c| name.strip_suffix(c).filter(|n| !n.is_empty()).and_then(with_s));
    without_condition
        .or_else(|| with_s(name))
        .unwrap_or_else(|| name.to_owned())
}

/// Registers in a list operand (`{r4, r5, r7, pc}`, `{r4-r11, lr}`, `{s16-s31}`), in 32-bit words
/// (a `d` register is two).
fn words(operands: &str) -> u64 {
    let Some(list) = operands.split('{').nth(1).and_then(|l| l.split('}').next()) else {
        return 1;
    };
    list.split(',')
        .map(|item| {
            let item = item.trim();
            let width = if item.starts_with('d') { 2 } else { 1 };
            let number = |r: &str| {
                r.trim()
                    .trim_start_matches(|c: char| c.is_ascii_alphabetic())
                    .parse::<u64>()
            };
            match item.split_once('-') {
                Some((from, to)) => match (number(from), number(to)) {
                    (Ok(from), Ok(to)) if to >= from => (to - from + 1) * width,
                    _ => width,
                },
                None => width,
            }
        })
        .sum()
}

/// Whether the instruction writes the PC (`pop {…, pc}`, `ldr pc, …`, `mov pc, …`, `add pc, …`).
fn writes_pc(class: Class, operands: &str) -> bool {
    match class {
        Class::Multiple => operands.contains("pc}"),
        _ => operands.split(',').next().is_some_and(|d| d.trim() == "pc"),
    }
}

/// The estimated cycles of `instruction` on `core`; `taken` says whether the next traced address was
/// not the one after it (a taken branch, or a load of the PC). An error for a mnemonic the table
/// does not know (the table must then grow, not guess).
pub fn cycles(core: Core, instruction: &Instruction, taken: bool) -> Result<u64, String> {
    let name = base(&instruction.mnemonic);
    let class = class_of(&name).ok_or_else(|| {
        format!(
            "no {core:?} timing for `{} {}` (tests/src/on_target/timing.rs)",
            instruction.mnemonic, instruction.operands
        )
    })?;
    let operands = instruction.operands.as_str();
    let to_pc = writes_pc(class, operands);
    let n = words(operands);
    let double = instruction.mnemonic.ends_with(".64") || operands.trim_start().starts_with('d');
    Ok(match core {
        Core::CortexM4F => {
            let refill = if taken { M4_REFILL } else { 0 };
            match class {
                Class::Simple | Class::Multiply => 1 + if to_pc { refill } else { 0 },
                Class::Divide => M4_DIVISION,
                Class::Memory => 2 + if to_pc { refill } else { 0 },
                Class::Double => 3,
                Class::Multiple => 1 + n + if to_pc { refill } else { 0 },
                Class::Branch | Class::BranchLink | Class::BranchExchange | Class::CompareBranch => 1 + refill,
                Class::Table => 2 + refill,
                Class::System | Class::Float => 1,
                Class::FloatAccumulate => 3,
                Class::FloatDivide => 14,
                Class::FloatMemory => 2 + u64::from(double),
                Class::FloatMove => 1 + u64::from(operands.split(',').count() >= 3),
                Class::FloatMultiple => 1 + n,
            }
        }
        Core::CortexM0Plus => match class {
            Class::Simple | Class::Multiply => 1 + u64::from(to_pc),
            Class::Memory => 2,
            Class::Multiple => 1 + n + if to_pc { 2 } else { 0 },
            Class::Branch => 1 + u64::from(taken),
            Class::BranchLink => 3,
            Class::BranchExchange => 2,
            Class::System => 3,
            _ => return Err(format!("`{}` is not an ARMv6-M instruction", instruction.mnemonic)),
        },
    })
}

/// Adds up the estimated cycles of executed instructions, one traced address after the other: each
/// instruction's cost is known once the next address shows whether it branched.
#[derive(Debug)]
pub struct Timer<'a> {
    core: Core,
    code: &'a BTreeMap<u64, Instruction>,
    pending: Option<(u64, Cost)>,
    /// Each executed address's cost, worked out from its mnemonic once: a trace runs the same few
    /// hundred instructions millions of times.
    costs: HashMap<u64, Cost>,
}

/// An instruction's cycles not taken and taken, its size, and whether it is a `VDIV`/`VSQRT`.
#[derive(Clone, Copy, Debug)]
struct Cost {
    not_taken: u64,
    taken: u64,
    size: u64,
    division: bool,
}

impl<'a> Timer<'a> {
    /// A timer over the disassembly `code` of the ELF that ran.
    pub fn new(core: Core, code: &'a BTreeMap<u64, Instruction>) -> Self {
        Timer {
            core,
            code,
            pending: None,
            costs: HashMap::new(),
        }
    }

    /// Records that `pc` is the next traced address, to be timed when `timed`; returns the cycles of
    /// the timed instruction traced just before it (0 when there is none), which this address shows
    /// taken or not, and whether `pc` is a `VDIV`/`VSQRT` (when timed).
    pub fn next(&mut self, pc: u64, timed: bool) -> Result<(u64, bool), String> {
        let before = self.finish(Some(pc));
        if !timed {
            return Ok((before, false));
        }
        let cost = match self.costs.get(&pc) {
            Some(&cost) => cost,
            None => {
                let instruction = self
                    .code
                    .get(&pc)
                    .ok_or_else(|| format!("traced address {pc:#x} is no instruction of the disassembly"))?;
                let cost = Cost {
                    not_taken: cycles(self.core, instruction, false)?,
                    taken: cycles(self.core, instruction, true)?,
                    size: instruction.size,
                    division: instruction.is_division(),
                };
                self.costs.insert(pc, cost);
                cost
            }
        };
        self.pending = Some((pc, cost));
        Ok((before, cost.division))
    }

    /// The cycles of the last instruction recorded, taken when `next` is not the address after it;
    /// with no next address (the trace ended), as not taken.
    pub fn finish(&mut self, next: Option<u64>) -> u64 {
        match self.pending.take() {
            Some((pc, cost)) if next.is_some_and(|next| next != pc + cost.size) => cost.taken,
            Some((_, cost)) => cost.not_taken,
            None => 0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A trace line as QEMU's `-d exec` writes it.
    fn line(pc: u64) -> String {
        format!("Trace 0: 0x7f2364000100 [00800400/{pc:08x}/00000510/ff000201] f\n")
    }

    /// The cycles [`super::super::qemu::count_between`] estimates for `path` (indices into the
    /// disassembly's instructions, in address order) run once between two markers.
    fn timed(core: Core, code: &BTreeMap<u64, Instruction>, path: &[usize]) -> (u64, u64) {
        let addresses: Vec<u64> = code.keys().copied().collect();
        let (start, end) = (0xf000, 0xf100);
        let mut trace = line(start);
        for &i in path {
            trace += &line(addresses[i]);
        }
        trace += &line(end);
        let counts = crate::on_target::count_between(trace.as_bytes(), start, end, core, code).unwrap();
        assert_eq!(counts.len(), 1);
        (counts[0].instructions, counts[0].cycles)
    }

    /// Assembles `source` with `arm-none-eabi-as` and disassembles it; `None` (the test then says so)
    /// without binutils, unless `CI` is set.
    fn assembled(source: &str, cpu: &[&str]) -> Option<BTreeMap<u64, Instruction>> {
        use std::process::Command;
        let dir = std::env::temp_dir().join(format!("timing-{}-{}", std::process::id(), cpu.join("")));
        std::fs::create_dir_all(&dir).unwrap();
        let (asm, object) = (dir.join("t.s"), dir.join("t.o"));
        std::fs::write(&asm, source).unwrap();
        let assembler = Command::new("arm-none-eabi-as")
            .args(cpu)
            .arg(&asm)
            .arg("-o")
            .arg(&object)
            .output();
        let Ok(output) = assembler else {
            assert!(std::env::var_os("CI").is_none(), "arm-none-eabi-as is missing");
            println!("TIMING TEST DID NOT RUN: arm-none-eabi-as is missing");
            return None;
        };
        assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
        let text = Command::new("arm-none-eabi-objdump")
            .arg("-d")
            .arg(&object)
            .output()
            .unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        Some(parse_disassembly(&String::from_utf8_lossy(&text.stdout)))
    }

    /// A Cortex-M4F loop timed by hand from the TRM's figures: 26 instructions, 92 cycles.
    #[test]
    fn a_hand_timed_cortex_m4f_sequence() {
        let source = "\t.syntax unified\n\t.cpu cortex-m4\n\t.fpu fpv4-sp-d16\n\t.thumb\n\
            \tpush {r4, r5, lr}\n\tmovs r0, #3\n\
            loop:\n\tvldr s0, [r1]\n\tvmul.f32 s1, s0, s0\n\tvfma.f32 s2, s0, s1\n\tvdiv.f32 s3, s1, s0\n\
            \tldr r2, [r1, #4]\n\tsubs r0, r0, #1\n\tbne loop\n\
            \tvmov r2, r3, d1\n\tcbz r2, done\n\tnop\n\
            done:\n\tpop {r4, r5, pc}\n";
        let Some(code) = assembled(source, &["-mcpu=cortex-m4", "-mfpu=fpv4-sp-d16", "-mthumb"]) else {
            return;
        };
        assert_eq!(code.len(), 13, "{code:#?}");
        // push, movs; the loop three times (its bne taken twice, then not); vmov; cbz taken over the
        // nop; pop to the caller.
        let mut path = vec![0, 1];
        for _ in 0..3 {
            path.extend(2..=8);
        }
        path.extend([9, 10, 12]);
        // push 1+3, movs 1; per pass vldr 2, vmul 1, vfma 3, vdiv 14, ldr 2, subs 1 (23); bne 3 + 3 + 1;
        // vmov of two core registers 2; cbz taken 3; pop with the PC 1+3+2.
        let by_hand = 4 + 1 + 3 * 23 + (3 + 3 + 1) + 2 + 3 + 6;
        assert_eq!(timed(Core::CortexM4F, &code, &path), (26, by_hand));
    }

    /// A Cortex-M0+ loop and call timed by hand from the TRM's figures: 16 instructions, 30 cycles.
    #[test]
    fn a_hand_timed_cortex_m0_plus_sequence() {
        let source = "\t.syntax unified\n\t.cpu cortex-m0\n\t.thumb\n\
            \tpush {r4, lr}\n\tmovs r0, #2\n\
            loop:\n\tldr r1, [r2]\n\tmuls r1, r3, r1\n\tstr r1, [r2]\n\tsubs r0, r0, #1\n\tbne loop\n\
            \tbl func\n\tpop {r4, pc}\n\
            func:\n\tadds r0, r0, r1\n\tbx lr\n";
        let Some(code) = assembled(source, &["-mcpu=cortex-m0", "-mthumb"]) else {
            return;
        };
        assert_eq!(code.len(), 11, "{code:#?}");
        let mut path = vec![0, 1];
        path.extend((2..=6).chain(2..=6));
        path.extend([7, 9, 10, 8]);
        // push 1+2, movs 1; per pass ldr 2, muls 1, str 2, subs 1 (6); bne 2 then 1; bl 3; adds 1,
        // bx 2; pop with the PC 3+2.
        let by_hand = 3 + 1 + 2 * 6 + (2 + 1) + 3 + 1 + 2 + 5;
        assert_eq!(timed(Core::CortexM0Plus, &code, &path), (16, by_hand));
    }

    fn instruction(mnemonic: &str, operands: &str, size: u64) -> Instruction {
        Instruction {
            mnemonic: mnemonic.to_owned(),
            operands: operands.to_owned(),
            size,
        }
    }

    /// A branch is taken when the next traced address is not the one after it: a conditional branch
    /// that falls through costs 1, taken 3 (M4) or 2 (M0+); an instruction that cannot branch costs
    /// the same either way; the last one of a trace counts as not taken.
    #[test]
    fn a_branch_is_taken_when_the_next_address_is_not_the_following_one() {
        let code = BTreeMap::from([
            (0x100, instruction("beq.n", "0x120", 2)),
            (0x102, instruction("adds", "r0, #1", 2)),
            (0x104, instruction("b.n", "0x100", 2)),
        ]);
        for (core, taken) in [(Core::CortexM4F, 3), (Core::CortexM0Plus, 2)] {
            let mut timer = Timer::new(core, &code);
            let mut next = |pc, timed| timer.next(pc, timed).map(|(cycles, _)| cycles);
            assert_eq!(next(0x100, true), Ok(0));
            assert_eq!(next(0x102, true), Ok(1), "{core:?}: beq falls through");
            assert_eq!(next(0x104, true), Ok(1), "{core:?}: adds");
            assert_eq!(next(0x100, true), Ok(taken), "{core:?}: b back");
            assert_eq!(next(0x120, false), Ok(taken), "{core:?}: beq taken");
            // The trace's end: nothing pending, nothing more.
            assert_eq!(timer.finish(None), 0);
            let mut timer = Timer::new(core, &code);
            timer.next(0x100, true).unwrap();
            assert_eq!(timer.finish(None), 1, "{core:?}: the trace ends after the beq");
        }
        // An address outside the disassembly is an error, not a guess.
        assert!(Timer::new(Core::CortexM4F, &code).next(0x200, true).is_err());
    }

    #[test]
    fn mnemonics_lose_their_condition_flag_setting_and_width() {
        for (mnemonic, expected) in [
            ("bls.n", "b"),
            ("bl", "bl"),
            ("blt.w", "b"),
            ("vmovne.f32", "vmov"),
            ("lsls", "lsl"),
            ("movs", "mov"),
            ("muls", "mul"),
            ("bics", "bic"),
            ("ldrbeq", "ldrb"),
            ("ldrhi", "ldr"),
            ("ldrsh.w", "ldrsh"),
            ("mls", "mls"),
            ("vcmpe.f32", "vcmpe"),
            ("itete", "itete"),
            ("addseq", "add"),
        ] {
            assert_eq!(base(mnemonic), expected, "{mnemonic}");
        }
        assert_eq!(words("{r4, r5, r7, pc}"), 4);
        assert_eq!(words("{r4-r11, lr}"), 9);
        assert_eq!(words("{d8-d9}"), 4);
        assert!(cycles(Core::CortexM4F, &instruction("frobnicate", "", 4), false).is_err());
        assert!(cycles(Core::CortexM0Plus, &instruction("vadd.f32", "s0, s0, s1", 4), false).is_err());
    }
}
