//! A plant model `ẋ = f(x, u)`, `y = h(x, u)` made of compiled expressions.

use crate::spec::expr::{ExprError, Expression};

/// A helper definition (`mu = mu_m*S/(k_s + S)`), usable by every later expression.
#[derive(Clone, Debug)]
pub struct Definition {
    /// Its name.
    pub name: String,
    /// Its expression.
    pub expr: Expression,
}

/// One measured output with its additive Gaussian noise.
#[derive(Clone, Debug)]
pub struct Output {
    /// Its name (the CSV column and regressor channel).
    pub name: String,
    /// `h_i(x, u)`.
    pub expr: Expression,
    /// Variance of the white Gaussian noise added to it.
    pub noise_variance: f64,
    /// Its unit, for plots and reports ("" when dimensionless).
    pub unit: String,
}

/// The continuous-time model. Expressions read one environment
/// `[parameters…, states…, inputs…, definitions…]` ([`Model::scope`]).
#[derive(Clone, Debug)]
pub struct Model {
    /// State names, in state-vector order.
    pub states: Vec<String>,
    /// Input names, in input-vector order (may be empty).
    pub inputs: Vec<String>,
    /// Parameter names and values. For a parameter declared with a range, the value is its nominal
    /// `value`: what the emitted model and the observers use.
    pub parameters: Vec<(String, f64)>,
    /// The parameters declared with a range (`{ value, min, max }`), in the order of
    /// [`Model::parameters`] (so in name order, as TOML tables are read). The simulated plant of a
    /// learning, validation or tuning run draws each of them in its range (see `data`); empty when the
    /// model is known exactly, and for a model compiled from text alone ([`Model::compile`]), which
    /// declares no range: the spec validator fills it.
    pub uncertain: Vec<Uncertain>,
    /// Helper definitions, each evaluated after those before it.
    pub definitions: Vec<Definition>,
    /// `dx_i/dt`, one per state, in state order.
    pub derivatives: Vec<Expression>,
    /// Measured outputs.
    pub outputs: Vec<Output>,
}

/// A parameter whose true value is only known to lie in `[min, max]` (`min < max`, the nominal value
/// in between, all finite: the spec validator checks it).
#[derive(Clone, Debug, PartialEq)]
pub struct Uncertain {
    /// Its index in [`Model::parameters`].
    pub index: usize,
    /// Its name.
    pub name: String,
    /// Smallest value the plant may have.
    pub min: f64,
    /// Largest value the plant may have.
    pub max: f64,
}

/// Where a model expression failed to compile: the spec field and the reason.
#[derive(Debug)]
pub struct ModelError {
    /// Dotted path of the spec field holding the expression.
    pub field: String,
    /// The reason.
    pub error: ExprError,
}

/// The text of a model, before compilation.
pub struct ModelText<'a> {
    /// State names.
    pub states: &'a [String],
    /// Input names.
    pub inputs: &'a [String],
    /// Parameters, in environment order.
    pub parameters: &'a [(String, f64)],
    /// `(name, expression)` of each helper definition, in order.
    pub definitions: &'a [(String, String)],
    /// `dx/dt` text per state, in state order.
    pub derivatives: &'a [String],
    /// `(name, expression, noise variance, unit)` per output.
    pub outputs: &'a [(String, String, f64, String)],
}

impl Model {
    /// Compiles the expressions; each may use parameters, states, inputs and the definitions before it.
    pub fn compile(text: &ModelText<'_>) -> Result<Model, ModelError> {
        let mut scope: Vec<&str> = text.parameters.iter().map(|(n, _)| n.as_str()).collect();
        scope.extend(text.states.iter().map(String::as_str));
        scope.extend(text.inputs.iter().map(String::as_str));
        let mut definitions = Vec::new();
        for (i, (name, expr)) in text.definitions.iter().enumerate() {
            let expr = Expression::compile(expr, &scope).map_err(|error| ModelError {
                field: format!("model.definitions[{i}].expr"),
                error,
            })?;
            definitions.push(Definition {
                name: name.clone(),
                expr,
            });
            scope.push(name);
        }
        let derivatives = text
            .states
            .iter()
            .zip(text.derivatives)
            .map(|(state, expr)| {
                Expression::compile(expr, &scope).map_err(|error| ModelError {
                    field: format!("model.derivatives.{state}"),
                    error,
                })
            })
            .collect::<Result<_, _>>()?;
        let outputs = text
            .outputs
            .iter()
            .enumerate()
            .map(|(i, (name, expr, noise_variance, unit))| {
                let expr = Expression::compile(expr, &scope).map_err(|error| ModelError {
                    field: format!("model.outputs[{i}].expr"),
                    error,
                })?;
                Ok(Output {
                    name: name.clone(),
                    expr,
                    noise_variance: *noise_variance,
                    unit: unit.clone(),
                })
            })
            .collect::<Result<_, _>>()?;
        Ok(Model {
            states: text.states.to_vec(),
            inputs: text.inputs.to_vec(),
            parameters: text.parameters.to_vec(),
            uncertain: Vec::new(),
            definitions,
            derivatives,
            outputs,
        })
    }

    /// The parameter values, in the order of [`Model::parameters`].
    pub fn parameter_values(&self) -> Vec<f64> {
        self.parameters.iter().map(|(_, v)| *v).collect()
    }

    /// The same model with the parameter values `values` (one per parameter, in the order of
    /// [`Model::parameters`]): the plant a run simulates when the true parameters differ from the
    /// nominal ones. The ranges in [`Model::uncertain`] are kept; `values` need not lie in them.
    ///
    /// # Panics
    /// When `values` does not hold one value per parameter.
    pub fn with_parameters(&self, values: &[f64]) -> Model {
        assert_eq!(
            values.len(),
            self.parameters.len(),
            "{} values for the {} parameters",
            values.len(),
            self.parameters.len()
        );
        let mut model = self.clone();
        for ((_, value), new) in model.parameters.iter_mut().zip(values) {
            *value = *new;
        }
        model
    }

    /// The nominal parameter values with those of the uncertain parameters replaced by `values`
    /// (one per entry of [`Model::uncertain`], in its order).
    ///
    /// # Panics
    /// When `values` does not hold one value per uncertain parameter.
    pub fn values_with_uncertain(&self, values: &[f64]) -> Vec<f64> {
        assert_eq!(
            values.len(),
            self.uncertain.len(),
            "{} values for the {} uncertain parameters",
            values.len(),
            self.uncertain.len()
        );
        let mut all = self.parameter_values();
        for (u, value) in self.uncertain.iter().zip(values) {
            all[u.index] = *value;
        }
        all
    }

    /// Names of the environment slots, in order: what a target expression may use.
    pub fn scope(&self) -> Vec<&str> {
        let mut scope: Vec<&str> = self.parameters.iter().map(|(n, _)| n.as_str()).collect();
        scope.extend(self.states.iter().map(String::as_str));
        scope.extend(self.inputs.iter().map(String::as_str));
        scope.extend(self.definitions.iter().map(|d| d.name.as_str()));
        scope
    }

    /// Fills `environment` for state `x` and input `u` (definitions evaluated in order).
    pub fn environment(&self, x: &[f64], u: &[f64], environment: &mut Vec<f64>) {
        environment.clear();
        environment.extend(self.parameters.iter().map(|(_, v)| *v));
        environment.extend_from_slice(x);
        environment.extend_from_slice(u);
        for definition in &self.definitions {
            let value = definition.expr.eval(environment);
            environment.push(value);
        }
    }

    /// `ẋ = f(x, u)` into `dx`, using `environment` as scratch space.
    pub fn derivative(&self, x: &[f64], u: &[f64], environment: &mut Vec<f64>, dx: &mut [f64]) {
        self.environment(x, u, environment);
        for (d, expr) in dx.iter_mut().zip(&self.derivatives) {
            *d = expr.eval(environment);
        }
    }

    /// Noise-free outputs `h(x, u)` into `y`.
    pub fn outputs(&self, x: &[f64], u: &[f64], environment: &mut Vec<f64>, y: &mut [f64]) {
        self.environment(x, u, environment);
        for (value, output) in y.iter_mut().zip(&self.outputs) {
            *value = output.expr.eval(environment);
        }
    }
}
