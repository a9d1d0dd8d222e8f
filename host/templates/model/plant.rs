{# The spec's model on the chip: its parameters, `Plant` (each function the straight-line body `gen`
   writes out), `targets` and the discretisation by RK4. `equations`: the doc's lines of the model. -#}
{% if !parameters.is_empty() -%}
/// The spec's parameters (`[model.parameters]`), each as `(f32, f64)`.
#[allow(non_upper_case_globals)]
pub mod parameters {
{%- for (doc, name, single, double) in parameters %}
    /// `{{ doc }}`.
    pub const {{ name }}: (f32, f64) = ({{ single }}, {{ double }});
{%- endfor %}
}

{% endif -%}
/// The spec's model on the chip, written out from its expression trees by `gen`:
///
/// ```text
{%- for line in equations %}
/// {{ line }}
{%- endfor %}
/// ```
///
/// with the Jacobians `∂f/∂x` and `∂h/∂x` (symbolic, shared subexpressions computed once).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Plant;

impl<T: Scalar + Maths> firmware::Model<T, STATES, OUTPUTS, INPUTS> for Plant {
    #[allow(unused_variables, non_snake_case)]
    fn derivative(&self, x: &[T; STATES], u: &[T; INPUTS]) -> ([T; STATES], [[T; STATES]; STATES]) {
{{ derivative }}    }

    #[allow(unused_variables, non_snake_case)]
    fn output(&self, x: &[T; STATES], u: &[T; INPUTS]) -> ([T; OUTPUTS], [[T; STATES]; OUTPUTS]) {
{{ output }}    }
}

/// The targets at state `x` and input `u`, in [`TARGET_NAMES`] order: what the EKF's estimate
/// gives for each.
#[allow(unused_variables, non_snake_case)]
pub fn targets<T: Scalar + Maths>(x: &[T; STATES], u: &[T; INPUTS]) -> [T; TARGETS] {
{{ targets }}}

/// RK4 steps per sample in the chip's model (the learning simulation takes {{ substeps }}).
pub const CHIP_SUBSTEPS: usize = {{ chip_substeps }};

/// One sampling period of [`Plant`] by [`CHIP_SUBSTEPS`] RK4 steps, the input held.
pub type Discrete<T> = firmware::Rk4<T, Plant, CHIP_SUBSTEPS>;

