//! A case: one named surface (a Δ-complex with an exact metric) that checks run on.

use crate::mesh::Mesh;
use crate::scalar::Real;
use rug::Rational;

/// An exact metric: one value per edge, indexed by `Edge.idx()`.
#[derive(Clone, Debug, PartialEq)]
pub enum Lengths {
    /// Edge lengths ℓ_e, exact rationals (from a surface file's `"3/2"`, `"1.25"`).
    Exact(Vec<Rational>),
    /// Squared edge lengths ℓ_e², exact rationals (from rational vertex positions, where
    /// ℓ itself is in general irrational).
    Squared(Vec<Rational>),
}

impl Lengths {
    /// Number of edges the metric covers.
    pub fn len(&self) -> usize {
        match self {
            Lengths::Exact(v) | Lengths::Squared(v) => v.len(),
        }
    }

    /// Whether the metric covers no edge.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The squared lengths ℓ_e², exact.
    pub fn squared(&self) -> Vec<Rational> {
        match self {
            Lengths::Exact(v) => v.iter().map(|l| Rational::from(l * l)).collect(),
            Lengths::Squared(v) => v.clone(),
        }
    }

    /// The lengths in backend `T` at context `ctx`: `from_rational(ℓ)` (correctly rounded
    /// for `f64` and MPFR) for exact lengths, `√(from_rational(ℓ²))` (two roundings) for
    /// squared ones.
    pub fn to_real<T: Real>(&self, ctx: T::Ctx) -> Vec<T> {
        match self {
            Lengths::Exact(v) => v.iter().map(|q| T::from_rational(q, ctx)).collect(),
            Lengths::Squared(v) => v.iter().map(|q| T::from_rational(q, ctx).sqrt()).collect(),
        }
    }

    /// The conformal scaling ℓ̃_ij = s_i s_j ℓ_ij with rational s_i = e^{u_i/2} (MATH.md §4,
    /// Eq. 10), exact; squared lengths scale by s_i² s_j².
    pub fn scaled(&self, mesh: &Mesh, s: &[Rational]) -> Lengths {
        let factor = |e: crate::mesh::Edge, squared: bool| {
            let h = e.halfedge();
            let f = Rational::from(&s[mesh.tail(h).idx()] * &s[mesh.tip(h).idx()]);
            if squared {
                Rational::from(&f * &f)
            } else {
                f
            }
        };
        match self {
            Lengths::Exact(v) => Lengths::Exact(
                mesh.edges()
                    .map(|e| factor(e, false) * &v[e.idx()])
                    .collect(),
            ),
            Lengths::Squared(v) => Lengths::Squared(
                mesh.edges()
                    .map(|e| factor(e, true) * &v[e.idx()])
                    .collect(),
            ),
        }
    }

    /// The metric restricted or re-indexed: entry `i` of the result is entry `map[i]` of
    /// `self`. Indices out of range are the caller's error (maps come from the mesh).
    pub fn reindex(&self, map: &[usize]) -> Lengths {
        let pick = |v: &Vec<Rational>| map.iter().map(|&i| v[i].clone()).collect();
        match self {
            Lengths::Exact(v) => Lengths::Exact(pick(v)),
            Lengths::Squared(v) => Lengths::Squared(pick(v)),
        }
    }
}

/// A named surface with an exact metric.
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    /// A short name for reports (`tetrahedron`, a file name, …).
    pub name: String,
    /// The triangulation.
    pub mesh: Mesh,
    /// Its metric, one entry per edge.
    pub lengths: Lengths,
}
