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
    /// Parameter names and values.
    pub parameters: Vec<(String, f64)>,
    /// Helper definitions, each evaluated after those before it.
    pub definitions: Vec<Definition>,
    /// `dx_i/dt`, one per state, in state order.
    pub derivatives: Vec<Expression>,
    /// Measured outputs.
    pub outputs: Vec<Output>,
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
            definitions,
            derivatives,
            outputs,
        })
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
