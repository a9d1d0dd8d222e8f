//! The χ² watch's constants of a filter from the box centre, as tuned and emitted
//! (`firmware::watch` is the rule on the chip).

/// The χ² watch's constants (`firmware::watch`): the filter restarts when the mean of its normalised
/// innovations squared over about `window` samples exceeds `threshold` times the number of outputs.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Watch {
    /// `W`, in samples: the watched mean's gain is `1 / W`.
    pub window: usize,
    /// `τ`: `+∞` (`null` in JSON) where the filter is not watched.
    #[serde(with = "infinite_as_null")]
    pub threshold: f64,
}

impl Watch {
    /// Not watched.
    pub const OFF: Watch = Watch {
        window: 1,
        threshold: f64::INFINITY,
    };

    /// The firmware's constants of a watch whose quantity has mean `m` when the model is right (a
    /// filter's NIS: its outputs; the moving-horizon estimate's window cost: `N` times its outputs):
    /// the start `m`, the gain `1 / W` and the limit `τ m`; `None` where it is not watched (`τ = ∞`:
    /// the emitted code has no watch). Every emitter and the host's runs read them here.
    pub fn constants(&self, m: usize) -> Option<firmware::watch::Watch<f64>> {
        self.threshold.is_finite().then(|| firmware::watch::Watch {
            start: m as f64,
            gain: 1.0 / self.window as f64,
            limit: self.threshold * m as f64,
        })
    }
}

impl Default for Watch {
    fn default() -> Self {
        Watch::OFF
    }
}

/// `+∞` as JSON's `null` (JSON has no infinity), and back.
mod infinite_as_null {
    pub fn serialize<S: serde::Serializer>(value: &f64, serializer: S) -> Result<S::Ok, S::Error> {
        match value.is_finite() {
            true => serializer.serialize_some(value),
            false => serializer.serialize_none(),
        }
    }

    pub fn deserialize<'de, D: serde::Deserializer<'de>>(deserializer: D) -> Result<f64, D::Error> {
        let value: Option<f64> = serde::Deserialize::deserialize(deserializer)?;
        Ok(value.unwrap_or(f64::INFINITY))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_unwatched_filter_has_no_constants_and_is_null_in_json() {
        assert_eq!(Watch::OFF.constants(2), None);
        let text = serde_json::to_string(&Watch::OFF).unwrap();
        assert_eq!(text, r#"{"window":1,"threshold":null}"#);
        let back: Watch = serde_json::from_str(&text).unwrap();
        assert_eq!(back, Watch::OFF);
        // Watched: over 10 samples, τ = 16 for 2 outputs: gain 0.1, limit 32.
        let watched = Watch {
            window: 10,
            threshold: 16.0,
        };
        assert_eq!(
            watched.constants(2),
            Some(firmware::watch::Watch {
                start: 2.0,
                gain: 0.1,
                limit: 32.0
            })
        );
        let back: Watch = serde_json::from_str(&serde_json::to_string(&watched).unwrap()).unwrap();
        assert_eq!(back, watched);
    }
}
