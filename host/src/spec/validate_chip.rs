//! `[chip]`: the arithmetic of the chip's map, and for `arithmetic = "fixed"` each signal's raw
//! integer scaling (`[chip.raw.<name>]`), checked here; the formats themselves are chosen, and their
//! error proven, by [`crate::fixed_point`].

use super::raw::{Arithmetic, RawChip, RawScaling};
use super::validate::Validator;
use super::*;

/// The largest raw magnitude a signal may declare: 24-bit converters. Beyond, a 32-bit sum of
/// products could keep too few bits of the gains to be worth it.
pub const MAX_RAW: i64 = 1 << 24;

impl Validator {
    /// `[chip]`: `None` for float arithmetic (the default), else every output's and input's scaling
    /// (declared, or left to the default Q format).
    pub(super) fn chip(&self, raw: Option<&RawChip>, model: &Model) -> Result<Option<FixedSpec>, SpecError> {
        let Some(chip) = raw else { return Ok(None) };
        let signals: Vec<String> = model
            .outputs
            .iter()
            .map(|o| o.name.clone())
            .chain(model.inputs.iter().cloned())
            .collect();
        if chip.arithmetic == Arithmetic::Float {
            if let Some(name) = chip.raw.keys().next() {
                return Err(self.err(
                    format!("chip.raw.{name}"),
                    "raw scalings are for the fixed-point map, and `chip.arithmetic` is \"float\"",
                    "set `arithmetic = \"fixed\"` in `[chip]`, or remove the `[chip.raw]` tables",
                ));
            }
            return Ok(None);
        }
        self.keys_among(
            "chip.raw",
            chip.raw.keys(),
            &signals,
            "an output or an input",
            "name one of the model's outputs or inputs",
        )?;
        let scale = |name: &String| chip.raw.get(name).map(|s| self.scaling(name, s)).transpose();
        Ok(Some(FixedSpec {
            outputs: model.outputs.iter().map(|o| scale(&o.name)).collect::<Result<_, _>>()?,
            inputs: model.inputs.iter().map(scale).collect::<Result<_, _>>()?,
        }))
    }

    fn scaling(&self, name: &str, raw: &RawScaling) -> Result<RawScale, SpecError> {
        let field = |f: &str| format!("chip.raw.{name}.{f}");
        let scale = self.positive(&field("scale"), raw.scale, "the value of one count")?;
        if !raw.offset.is_finite() {
            return Err(self.err(
                field("offset"),
                format!("the value at raw 0 must be finite, got {}", readable(raw.offset)),
                "set it to the signal's value at a raw reading of 0 (0 for a signed Q format)",
            ));
        }
        for (f, v) in [("min", raw.min), ("max", raw.max)] {
            // `unsigned_abs`: `i64::MIN.abs()` overflows (and wrapped to a value that passed, read as 0).
            if v.unsigned_abs() > MAX_RAW.unsigned_abs() {
                return Err(self.err(
                    field(f),
                    format!("{v} is beyond ±2^24 = ±{MAX_RAW}"),
                    "declare the converter's own range (at most 24 bits)",
                ));
            }
        }
        if raw.min >= raw.max {
            return Err(self.err(
                field("max"),
                format!("the raw range [{}, {}] is empty or a single value", raw.min, raw.max),
                "set `min` below `max` (e.g. 0 and 4095 for a 12-bit converter)",
            ));
        }
        Ok(RawScale {
            scale,
            offset: raw.offset,
            // Within ±2^24, checked above.
            min: raw.min as i32,
            max: raw.max as i32,
        })
    }
}
