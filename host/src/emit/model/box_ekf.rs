//! The box-started EKF as an observer (`BoxEkfObserver`, kind `ekf_box`): the design's `Ekf` behind
//! the observers' interface, written beside the filter by `plant::model_and_ekf`.

/// The design's filter type around its written-out sample (`{…}` filled in by [`super::model_source`]).
/// [`Ekf`] as an observer with the map's interface (`{…}` filled in by `plant::model_and_ekf`).
pub(super) const BOX_EKF_TEMPLATE: &str = r#"
/// The EKF from the centre of the state box ([`Ekf`], the same filter and constants) with the
/// observers' interface: `push` takes a sample, `estimate` gives the targets of the latest accepted
/// one (each `Inside`: the filter does not saturate), `reset` starts again. It has an estimate from
/// the first accepted sample on; a refused sample keeps the previous one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoxEkfObserver {
    filter: Ekf<f32>,
    latest: Option<[Estimate<f32>; TARGETS]>,
}

impl Default for BoxEkfObserver {
    fn default() -> Self {
        Self::new()
    }
}

impl BoxEkfObserver {
    /// A fresh observer (the filter at its start), holding no sample yet.
    pub const fn new() -> Self {
        BoxEkfObserver {
            filter: Ekf { x: {X0_F32}, p: {P0_F32} },
            latest: None,
        }
    }

    /// Takes the sample `(y, u)`: [`Ekf::push`], then the targets of its estimate `x̂(k|k)`.
    pub fn push(&mut self, y: [f32; OUTPUTS], u: [f32; INPUTS]) -> Result<(), firmware::RejectedSample> {
        let x = self.filter.push(&y, &u)?;
        let values = targets(&x, &u);
        let mut latest = [Estimate { value: 0.0, saturation: firmware::Saturation::Inside }; TARGETS];
        for (e, value) in latest.iter_mut().zip(values) {
            e.value = value;
        }
        self.latest = Some(latest);
        Ok(())
    }

    /// The targets of the latest accepted sample; `None` before the first.
    pub fn estimate(&self) -> Option<[Estimate<f32>; TARGETS]> {
        self.latest
    }

    /// Back to the start: the filter at the box centre, no estimate.
    pub fn reset(&mut self) {
        *self = Self::new();
    }

    /// Whether it has an estimate.
    pub fn is_ready(&self) -> bool {
        self.latest.is_some()
    }
}
"#;
