//! Prescribed cone angles `Θ_i = q_i·π` (exact rational multiples of π) and their
//! validation: one per vertex, each positive, and discrete Gauss–Bonnet
//! `Σ_i (2π − Θ_i) = 2πχ` on every connected component (notes §1.5.3 Thm 12; docs/catalogue.md §7).

use super::error::UniformizeError;
use crate::mesh::Mesh;
use rug::Rational;

/// Target cone angles, `Θ_i = q_i·π` with `q_i` rational, so that Gauss–Bonnet is decided
/// exactly (no tolerance).
#[derive(Clone, Debug, PartialEq)]
pub struct Targets {
    over_pi: Vec<Rational>,
}

impl Targets {
    /// The flat targets `Θ_i = 2π` at every one of `n` vertices (a flat metric; Gauss–Bonnet
    /// then needs χ = 0 on every component: tori, notes Thm 10).
    pub fn flat(n: usize) -> Targets {
        Targets {
            over_pi: vec![Rational::from(2); n],
        }
    }

    /// Targets from the exact multiples `q_i = Θ_i/π`.
    pub fn from_multiples_of_pi(over_pi: Vec<Rational>) -> Targets {
        Targets { over_pi }
    }

    /// Targets from `Θ_i/π` given as binary64 numbers, each taken exactly; a NaN or
    /// infinite entry is [`UniformizeError::NonFiniteTarget`].
    pub fn from_f64_multiples_of_pi(over_pi: &[f64]) -> Result<Targets, UniformizeError> {
        let q = over_pi
            .iter()
            .enumerate()
            .map(|(v, &x)| {
                Rational::from_f64(x).ok_or(UniformizeError::NonFiniteTarget {
                    vertex: v as u32,
                    value: x,
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Targets { over_pi: q })
    }

    /// The multiples `q_i = Θ_i/π`.
    pub fn over_pi(&self) -> &[Rational] {
        &self.over_pi
    }

    /// The number of targets.
    pub fn len(&self) -> usize {
        self.over_pi.len()
    }

    /// Whether there are no targets.
    pub fn is_empty(&self) -> bool {
        self.over_pi.is_empty()
    }

    /// `Θ_i` rounded to binary64 (for the `f64` solve).
    pub fn radians_f64(&self) -> Vec<f64> {
        self.over_pi
            .iter()
            .map(|q| q.to_f64() * std::f64::consts::PI)
            .collect()
    }

    /// Check the targets against `mesh`: one per vertex, each `Θ_i > 0`, and
    /// `Σ_{i∈C} (2 − q_i) = 2χ(C)` exactly on every connected component `C`.
    pub fn validate(&self, mesh: &Mesh) -> Result<(), UniformizeError> {
        if self.over_pi.len() != mesh.n_vertices() {
            return Err(UniformizeError::TargetCount {
                expected: mesh.n_vertices(),
                got: self.over_pi.len(),
            });
        }
        for (v, q) in self.over_pi.iter().enumerate() {
            if *q <= 0 {
                return Err(UniformizeError::NonPositiveTarget {
                    vertex: v as u32,
                    over_pi: q.to_string(),
                });
            }
        }
        let comps = super::components::Components::of(mesh);
        for (c, &root) in comps.roots.iter().enumerate() {
            let mut sum = Rational::new();
            for v in comps.vertices_of(c) {
                sum += Rational::from(2) - &self.over_pi[v];
            }
            let chi = comps.euler_characteristic(mesh, c);
            if sum != 2 * chi {
                return Err(UniformizeError::GaussBonnet {
                    root: root as u32,
                    sum_over_pi: sum.to_string(),
                    chi,
                });
            }
        }
        Ok(())
    }
}
