//! A circle-pattern problem: a triangulated surface, an intersection angle `Φ_e = q_e·π`
//! per edge and a target cone angle `Θ_v = t_v·π` per vertex (or a fixed radius), with the
//! fractions `q_e, t_v` exact rationals so that Gauss–Bonnet is checked exactly.

use super::metric::cos_pi;
use crate::mesh::Mesh;
use crate::scalar::Real;
use rug::Rational;

/// Why a circle-pattern problem was refused.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum PatternError {
    /// The number of angles does not match the number of edges or vertices.
    #[error("{what}: expected {expected} values, got {got}")]
    Count {
        /// `intersection angles` or `target cone angles`.
        what: &'static str,
        /// Edges or vertices of the mesh.
        expected: usize,
        /// Values given.
        got: usize,
    },
    /// An intersection angle outside `[0, π/2]` (the range where Eq. 9 gives triangles, T08).
    #[error("edge e{edge}: intersection angle {q}·π is outside [0, π/2]")]
    AngleOutOfRange {
        /// The edge.
        edge: usize,
        /// `Φ_e / π`.
        q: String,
    },
    /// A target cone angle that is not positive.
    #[error("vertex v{vertex}: target cone angle {t}·π is not positive")]
    TargetNotPositive {
        /// The vertex.
        vertex: usize,
        /// `Θ_v / π`.
        t: String,
    },
    /// Targets on every vertex whose curvatures do not sum to `2πχ` (Gauss–Bonnet, T01).
    #[error(
        "target cone angles violate Gauss–Bonnet: the curvatures sum to {total}·π, not 2χ·π = {expected}·π"
    )]
    GaussBonnet {
        /// `Σ K_v / π` of the targets.
        total: String,
        /// `2χ`.
        expected: i64,
    },
    /// No vertex is free.
    #[error("every vertex has a fixed radius: nothing to solve")]
    NothingFree,
}

/// A circle-pattern problem. `targets[v] = Some(t)` asks for the cone angle `Θ_v = tπ`;
/// `None` keeps the radius of `v` at its start value (a Dirichlet vertex). When every
/// vertex has a target, the curvatures `K_v = 2π − Θ_v` (interior) and `π − Θ_v`
/// (boundary) sum to `2πχ` exactly (checked by [`CirclePattern::new`]) and radii are
/// determined up to one global scale (notes Thm 6); the solver then fixes
/// `u_ground = 0` for [`CirclePattern::ground`].
#[derive(Clone, Debug)]
pub struct CirclePattern {
    /// The triangulated surface.
    pub mesh: Mesh,
    /// `Φ_e / π ∈ [0, 1/2]` per edge.
    pub phi: Vec<Rational>,
    /// `Θ_v / π` per vertex, or `None` for a fixed radius.
    pub targets: Vec<Option<Rational>>,
}

impl CirclePattern {
    /// Validate a problem: counts, `Φ ∈ [0, π/2]`, `Θ > 0`, and Gauss–Bonnet exactly when
    /// every vertex has a target.
    pub fn new(
        mesh: Mesh,
        phi: Vec<Rational>,
        targets: Vec<Option<Rational>>,
    ) -> Result<CirclePattern, PatternError> {
        if phi.len() != mesh.n_edges() {
            return Err(PatternError::Count {
                what: "intersection angles",
                expected: mesh.n_edges(),
                got: phi.len(),
            });
        }
        if targets.len() != mesh.n_vertices() {
            return Err(PatternError::Count {
                what: "target cone angles",
                expected: mesh.n_vertices(),
                got: targets.len(),
            });
        }
        let half = Rational::from((1, 2));
        for (edge, q) in phi.iter().enumerate() {
            if *q < 0 || *q > half {
                return Err(PatternError::AngleOutOfRange {
                    edge,
                    q: q.to_string(),
                });
            }
        }
        for (vertex, t) in targets.iter().enumerate() {
            if let Some(t) = t {
                if *t <= 0 {
                    return Err(PatternError::TargetNotPositive {
                        vertex,
                        t: t.to_string(),
                    });
                }
            }
        }
        if targets.iter().all(Option::is_none) {
            return Err(PatternError::NothingFree);
        }
        if targets.iter().all(Option::is_some) {
            let boundary = mesh.boundary_vertices();
            let mut total = Rational::new();
            for (v, t) in targets.iter().enumerate() {
                let full = if boundary[v] { 1 } else { 2 };
                total += Rational::from(full) - t.as_ref().map_or(Rational::new(), Clone::clone);
            }
            let expected = 2 * mesh.euler_characteristic();
            if total != expected {
                return Err(PatternError::GaussBonnet {
                    total: total.to_string(),
                    expected,
                });
            }
        }
        Ok(CirclePattern { mesh, phi, targets })
    }

    /// The same `Φ` on every edge and the targets `Θ_v = t_v π`.
    pub fn uniform(
        mesh: Mesh,
        phi: &Rational,
        targets: Vec<Rational>,
    ) -> Result<CirclePattern, PatternError> {
        let n = mesh.n_edges();
        CirclePattern::new(
            mesh,
            vec![phi.clone(); n],
            targets.into_iter().map(Some).collect(),
        )
    }

    /// The grounded vertex: the first vertex when every vertex has a target (fixing the
    /// global scale), none otherwise.
    pub fn ground(&self) -> Option<usize> {
        self.targets.iter().all(Option::is_some).then_some(0)
    }

    /// The unknowns of the solver: vertices with a target, except [`Self::ground`].
    pub fn free(&self) -> Vec<usize> {
        let g = self.ground();
        (0..self.targets.len())
            .filter(|&v| self.targets[v].is_some() && Some(v) != g)
            .collect()
    }

    /// `cos Φ_e` per edge in the backend of `ctx` (exact for `Φ ∈ {0, π/3, π/2}`).
    pub fn cos_phi<T: Real>(&self, ctx: T::Ctx) -> Vec<T> {
        self.phi.iter().map(|q| cos_pi::<T>(q, ctx)).collect()
    }

    /// `Θ_v` per vertex in the backend of `ctx` (0 for fixed vertices, which have none).
    pub fn target_angles<T: Real>(&self, ctx: T::Ctx) -> Vec<T> {
        let pi = T::pi(ctx);
        self.targets
            .iter()
            .map(|t| match t {
                Some(t) => T::from_rational(t, ctx) * &pi,
                None => T::from_f64(0.0, ctx),
            })
            .collect()
    }
}
