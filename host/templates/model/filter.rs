{# A Kalman filter type (`Ekf`, or another filter kind's) around its two written-out samples. -#}
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct {{ name }}<T = f32> {
    /// `x̂`: after a sample, the prediction to the next one.
    x: [T; STATES],
    /// The upper triangle of `P`.
    p: [T; COVARIANCE],
{%- if let Some(w) = watch %}
    /// The watched mean of the normalised innovations squared ([`firmware::watch`]).
    chi: T,
{%- endif %}
}

impl<T: Scalar + Maths> Default for {{ name }}<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Scalar + Maths> {{ name }}<T> {
    /// A fresh filter.
    pub fn new() -> Self {
        {{ name }} {
            x: {{ x0 }},
            p: {{ p0 }},
{%- if let Some(w) = watch %}
            chi: {{ w.start }},
{%- endif %}
        }
    }

    /// The current estimate (after a sample, the prediction to the next one).
    pub fn state(&self) -> [T; STATES] {
        self.x
    }

    /// The current covariance `P`.
    pub fn covariance(&self) -> [[T; STATES]; STATES] {
        {{ covariance }}
    }

    /// Takes the sample `(y, u)`; returns the estimate given it, `x̂(k|k)`, or refuses it, or restarts
    /// from the start when its step is not finite{% if watch.is_some() %} or its innovations stay implausible{% endif %} (see the type's docs): the rule every filter follows
    /// ([`firmware::rules::filter_sample`]) over this filter's two written-out samples. The same
    /// operations run for every accepted sample.
    pub fn push(&mut self, y: &[T; OUTPUTS], u: &[T; INPUTS]) -> Result<[T; STATES], firmware::rules::Refused> {
        firmware::rules::filter_sample(
            self,
            u.iter().all(|v| v.is_finite()),
            y.iter().all(|v| v.is_finite()),
{%- if let Some(w) = watch %}
            |filter| {
                let (estimate, x, p, nis) = {{ lower }}_measured(&filter.x, &filter.p, y, u);
                let chi = firmware::watch::watched(filter.chi, nis, {{ w.gain }});
                (estimate, {{ name }} { x, p, chi })
            },
            |filter| {
                let (x, p) = {{ lower }}_unmeasured(&filter.x, &filter.p, u);
                {{ name }} { x, p, chi: filter.chi }
            },
            |filter| finite(&filter.x, &filter.p) && firmware::watch::plausible(filter.chi, {{ w.limit }}),
{%- else %}
            |filter| {
                let (estimate, x, p, _) = {{ lower }}_measured(&filter.x, &filter.p, y, u);
                (estimate, {{ name }} { x, p })
            },
            |filter| {
                let (x, p) = {{ lower }}_unmeasured(&filter.x, &filter.p, u);
                {{ name }} { x, p }
            },
            |filter| finite(&filter.x, &filter.p),
{%- endif %}
            Self::new,
        )
    }
}


