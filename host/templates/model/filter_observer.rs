{# The filter from the centre of the state box (or the spec's start) as an observer. #}
/// {{ what }} ([`{{ name }}`], the same filter and constants) with the
/// observers' interface ([`firmware::FilterObserver`], [`firmware::Estimator`]): `push` takes a
/// sample, `estimate` gives the targets of the latest accepted one (each `Inside`: the filter does
/// not saturate), `reset` starts again. It has an estimate from the first accepted sample on; a
/// refused sample keeps the previous one, and so does a sample on which the filter restarted.
pub type {{ observer }} = firmware::FilterObserver<f32, {{ name }}, STATES, OUTPUTS, INPUTS, TARGETS>;

impl firmware::emitted::Filter<f32, STATES, OUTPUTS, INPUTS, TARGETS> for {{ name }}<f32> {
    const FRESH: Self = {{ name }} { x: {{ x0 }}, p: {{ p0 }}{% if let Some(start) = chi %}, chi: {{ start }}{% endif %} };

    #[inline(always)]
    fn push(&mut self, y: &[f32; OUTPUTS], u: &[f32; INPUTS]) -> Result<[f32; STATES], firmware::rules::Refused> {
        {{ name }}::push(self, y, u)
    }

    #[inline(always)]
    fn targets(x: &[f32; STATES], u: &[f32; INPUTS]) -> [f32; TARGETS] {
        {{ targets }}(x, u)
    }
}

/// [`{{ observer }}`]'s `push` and `estimate` in `f32`, compiled in this crate as when every design
/// wrote its own observer type: measured on the chip, without them the whole-program optimisation
/// inlines this design's filter samples differently, and every observer over them runs other
/// instruction counts. Not for calling: use the observer's methods.
#[doc(hidden)]
pub fn {{ lower }}_observer_push(observer: &mut {{ observer }}, y: [f32; OUTPUTS], u: [f32; INPUTS]) -> Result<(), firmware::RejectedSample> {
    observer.push(y, u)
}

/// See [`{{ lower }}_observer_push`].
#[doc(hidden)]
pub fn {{ lower }}_observer_estimate(observer: &{{ observer }}) -> Option<[Estimate<f32>; TARGETS]> {
    observer.estimate()
}

