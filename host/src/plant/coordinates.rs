//! The coordinates a filter carries its state in: the plant's, or a logarithm for each state bounded
//! below, which keeps a filter's state and its sigma points inside the bound without a clamp.
//!
//! # Log coordinates
//!
//! A state with a lower bound `m` (`[model.bounds]`) is carried as
//!
//! ```text
//! z = ln(x − m + c),   x = eᶻ + (m − c),   c = LOG_OFFSET · (x_centre − m),
//! ```
//!
//! `x_centre` the centre of the state box (a state whose box centre sits on its bound stays in the
//! plant's coordinates). With `s = eᶻ = x − m + c`, the model becomes
//!
//! ```text
//! żᵢ = fᵢ(x) / sᵢ,   ∂żᵢ/∂zⱼ = (∂fᵢ/∂xⱼ · sⱼ − δᵢⱼ fᵢ) / sᵢ,   ∂h/∂zⱼ = ∂h/∂xⱼ · sⱼ,
//! ```
//!
//! written as programs over the plant's ([`ModelCode::in_coordinates`]): `x` is computed from `z`
//! once (no lower than `m`, where rounding would put it below), and the plant's programs read it. A filter's Gaussian in `z` is a log-normal in `x`: near
//! the bound its spread shrinks with the state, where a Gaussian in `x` would spill across it. On
//! E. coli's runs that start with the substrate nearly gone, the UKF in the plant's coordinates
//! explains the fading light by lowering the product; in log coordinates it does not.
//!
//! A filter's constants given in the plant's units (a start, `Q`, `P(0)` the spec fixes) map by
//! [`Coordinates::to_filter`] and, for covariances, by the slopes `dz/dx = 1/s` at the start
//! ([`Coordinates::covariance`], the delta method).

use super::program::{Builder, Leaf, Names, Program};
use super::ModelCode;
use crate::spec::ast::Binary;
use crate::spec::{Axis, Bounds, Design};

/// `c` as a fraction of the distance from the bound to the box centre (see the module docs).
pub const LOG_OFFSET: f64 = 0.01;

/// One state in log coordinates: its lower bound `m` and offset `c`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Logarithmic {
    /// `m`, the state's lower bound.
    pub min: f64,
    /// `c`, the offset.
    pub offset: f64,
}

impl Logarithmic {
    /// `m − c`: `x = eᶻ + shift`.
    pub fn shift(&self) -> f64 {
        self.min - self.offset
    }

    /// `z` of the plant's `x` (`x` below the bound is read on it).
    pub fn to_filter(&self, x: f64) -> f64 {
        (x.max(self.min) - self.shift()).ln()
    }

    /// The plant's `x` of `z` (no lower than the bound).
    pub fn to_plant(&self, z: f64) -> f64 {
        (z.exp() + self.shift()).max(self.min)
    }
}

/// Per state, `None` (the plant's coordinate) or its log coordinate.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Coordinates(pub Vec<Option<Logarithmic>>);

impl Coordinates {
    /// The plant's coordinates for `states` states.
    pub fn plant(states: usize) -> Self {
        Coordinates(vec![None; states])
    }

    /// Log coordinates for every state of `design` bounded below whose box centre lies above the
    /// bound; the plant's for the others.
    pub fn logarithmic(design: &Design) -> Self {
        Coordinates(
            design
                .state_bounds
                .iter()
                .zip(&design.learning.axes)
                .map(|(bounds, axis)| {
                    let min = bounds.min?;
                    let centre = match *axis {
                        Axis::Range { min, max, .. } => 0.5 * (min + max),
                        Axis::Fixed(value) => value,
                    };
                    (centre > min).then_some(Logarithmic {
                        min,
                        offset: LOG_OFFSET * (centre - min),
                    })
                })
                .collect(),
        )
    }

    /// Whether every state is in the plant's coordinate.
    pub fn is_plant(&self) -> bool {
        self.0.iter().all(Option::is_none)
    }

    /// `z` of the plant's state `x` (a state below its bound is read on it).
    pub fn to_filter(&self, x: &[f64]) -> Vec<f64> {
        x.iter()
            .zip(&self.0)
            .map(|(&x, log)| match log {
                Some(log) => log.to_filter(x),
                None => x,
            })
            .collect()
    }

    /// The plant's state `x` of `z` (no lower than the bound).
    pub fn to_plant(&self, z: &[f64]) -> Vec<f64> {
        z.iter()
            .zip(&self.0)
            .map(|(&z, log)| match log {
                Some(log) => log.to_plant(z),
                None => z,
            })
            .collect()
    }

    /// `dzᵢ/dxᵢ` at the plant's state `x`.
    pub fn slopes(&self, x: &[f64]) -> Vec<f64> {
        x.iter()
            .zip(&self.0)
            .map(|(&x, log)| match log {
                Some(log) => 1.0 / (x.max(log.min) - log.shift()),
                None => 1.0,
            })
            .collect()
    }

    /// A covariance of the plant's state at `x` in these coordinates: `D C D`, `D = diag(dz/dx)`.
    pub fn covariance(&self, covariance: &super::Covariance, x: &[f64]) -> super::Covariance {
        let d = self.slopes(x);
        match covariance {
            super::Covariance::Diagonal(v) => {
                super::Covariance::Diagonal(v.iter().zip(&d).map(|(v, d)| v * d * d).collect())
            }
            super::Covariance::Full(rows) => super::Covariance::Full(
                rows.iter()
                    .enumerate()
                    .map(|(r, row)| row.iter().enumerate().map(|(c, v)| v * d[r] * d[c]).collect())
                    .collect(),
            ),
        }
    }

    /// Each state's bounds in these coordinates (`ln c`, `ln(max − m + c)` for a log coordinate).
    pub fn bounds(&self, bounds: &[Bounds]) -> Vec<Bounds> {
        bounds
            .iter()
            .zip(&self.0)
            .map(|(b, log)| match log {
                Some(log) => Bounds {
                    min: Some(log.offset.ln()),
                    max: b.max.map(|max| (max - log.shift()).ln()),
                },
                None => *b,
            })
            .collect()
    }
}

impl ModelCode {
    /// The model in `coordinates` (see the module docs), from the plant's: its programs read `z`,
    /// their Jacobians are in `z`, its bounds are `z`'s. The plant's coordinates give it unchanged.
    pub fn in_coordinates(&self, coordinates: &Coordinates) -> ModelCode {
        if coordinates.is_plant() || !self.coordinates.is_plant() {
            return self.clone();
        }
        let (nx, ny) = (self.dimensions.states, self.dimensions.outputs);
        let rewrite = |program: &Program, values: usize, jacobian: bool, derivative: bool| -> Program {
            let mut b = Builder::new(Names {
                parameters: &self.parameters,
                states: &[],
                inputs: &[],
            });
            let z: Vec<usize> = (0..nx).map(|i| b.leaf(Leaf::State(i))).collect();
            let s: Vec<Option<usize>> = z
                .iter()
                .zip(&coordinates.0)
                .map(|(&z, log)| log.map(|_| b.call("exp", z)))
                .collect();
            let x: Vec<usize> = (0..nx)
                .map(|i| match (s[i], coordinates.0[i]) {
                    (Some(s), Some(log)) => {
                        // On the bound `eᶻ + (m − c)` may round below `m`; the plant's programs
                        // read it at `m` then (`sqrt(h)` stays defined).
                        let (shift, min) = (b.number(log.shift()), b.number(log.min));
                        let x = b.add(s, shift);
                        b.at_least(x, min)
                    }
                    _ => z[i],
                })
                .collect();
            let results = b.inline(program, &x);
            let mut out: Vec<usize> = results[..values]
                .iter()
                .enumerate()
                .map(|(i, &f)| match (derivative, s.get(i).copied().flatten()) {
                    (true, Some(s)) => b.binary(Binary::Div, f, s),
                    _ => f,
                })
                .collect();
            if jacobian {
                for i in 0..values {
                    for j in 0..nx {
                        let mut d = results[values + i * nx + j];
                        if let Some(sj) = s[j] {
                            d = b.mul(d, sj);
                        }
                        if let (true, Some(si)) = (derivative, s[i]) {
                            if i == j {
                                d = b.sub(d, results[i]);
                            }
                            d = b.binary(Binary::Div, d, si);
                        }
                        out.push(d);
                    }
                }
            }
            for r in out {
                b.result(r);
            }
            let mut program = b.finish();
            program.prune();
            program
        };
        ModelCode {
            derivative: rewrite(&self.derivative, nx, true, true),
            output: rewrite(&self.output, ny, true, false),
            targets: rewrite(&self.targets, self.dimensions.targets, false, false),
            parameters: self.parameters.clone(),
            dimensions: self.dimensions,
            bounds: coordinates.bounds(&self.bounds),
            coordinates: coordinates.clone(),
            log_coordinates: self.log_coordinates.clone(),
        }
    }
}

#[cfg(test)]
mod tests;
