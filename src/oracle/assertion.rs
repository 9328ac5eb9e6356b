//! What a claim asserts (protocol v1, `schema/claim-v1.schema.json`, `docs/oracle.md`): one
//! variant per claim kind, with the claimed values. Parsed by [`super::claim`] and the
//! per-kind parsers [`super::claim_circles`] and [`super::claim_hyperbolic`].

use crate::circles::maximal::sphere::ExactCap;
use crate::circles::maximal::tangency::ExactCircle;
use crate::io::Surface;
use rug::Rational;

/// What is claimed.
#[derive(Clone, Debug, PartialEq)]
pub enum Assertion {
    /// `intrinsic_delaunay`: every interior edge of the surface satisfies the intrinsic
    /// Delaunay condition (docs/catalogue.md §5, Eq. 13: cot α + cot β ≥ 0).
    IntrinsicDelaunay,
    /// `delaunay_flip`: flipping the surface to intrinsic Delaunay with this kind of flip
    /// (notes §1.5.2, docs/catalogue.md §5) gives `result`: the same triangulation up to renumbering
    /// of edges and faces (same gluing, vertices keep their ids) with every length within
    /// `epsilon` (meaning and tie rule: [`super::flip_claim`]).
    DelaunayFlip {
        /// `true` for Ptolemy flips, `false` for Euclidean flips.
        ptolemy: bool,
        /// The claimed Delaunay surface.
        result: Surface,
        /// Absolute tolerance ε ≥ 0 on each length (on each squared length when `result`
        /// gives `squared_lengths`); 0 when absent.
        epsilon: Rational,
    },
    /// `cone_angles`: the cone angle θ_v (sum of corner angles, docs/catalogue.md §2) of every
    /// vertex is within `epsilon` of `angles[v]`.
    ConeAngles {
        /// One claimed angle per vertex, radians.
        angles: Vec<Rational>,
        /// Absolute tolerance ε ≥ 0.
        epsilon: Rational,
    },
    /// `cotan_laplacian`: the cotan weight w_e = ½(cot α + cot β) (docs/catalogue.md §3, one term on
    /// a boundary edge) of every edge is within `epsilon` of `weights[e]`.
    CotanLaplacian {
        /// One claimed weight per edge.
        weights: Vec<Rational>,
        /// Absolute tolerance ε ≥ 0.
        epsilon: Rational,
    },
    /// `conformal_equivalence`: the surface's metric ℓ and `target` ℓ̃ on the same
    /// triangulation satisfy ℓ̃_ij = e^{(u_i+u_j)/2} ℓ_ij (docs/catalogue.md §4, Eq. 10) for the given
    /// `u`, within `epsilon` on the log lengths: |log ℓ̃_ij − log ℓ_ij − (u_i+u_j)/2| ≤ ε.
    ConformalEquivalence {
        /// The second metric (same triangulation).
        target: Surface,
        /// One log scale factor per vertex.
        u: Vec<Rational>,
        /// Absolute tolerance ε ≥ 0 on log lengths.
        epsilon: Rational,
    },
    /// `energy`: the discrete-uniformization energy (docs/catalogue.md §7, notes Eq. 16) of the
    /// surface's triangulation at the log scale factors `u` with target angles `targets`
    /// is within `epsilon` of `energy`, and each `∂E/∂u_i = Θ_i − θ_i(u)` is within
    /// `epsilon` of `gradient[i]` ([`crate::variational::energy`]).
    Energy {
        /// One log scale factor per vertex.
        u: Vec<Rational>,
        /// One target cone angle per vertex, or `None` for `2π` at every vertex.
        targets: Option<Vec<Rational>>,
        /// The claimed `E(u)`.
        energy: Rational,
        /// The claimed gradient, one entry per vertex.
        gradient: Vec<Rational>,
        /// Absolute tolerance ε ≥ 0 on `E` and on each gradient entry.
        epsilon: Rational,
    },
    /// `lobachevsky`: `|Л(x) − y| ≤ epsilon` for Lobachevsky's function
    /// (docs/catalogue.md §7, [`crate::special::lobachevsky`]); about no surface.
    Lobachevsky {
        /// The argument.
        x: Rational,
        /// The claimed value.
        y: Rational,
        /// Absolute tolerance ε ≥ 0.
        epsilon: Rational,
    },
    /// `uniformization`: an exact solution `u*` of `θ(u*) = Θ` exists within `radius` (sup
    /// norm) of the given `u`, with the surface's lengths carried by the given Ptolemy flips
    /// (notes §1.5.3 Thm 12; certificate and re-check: `uniformization::claim_form`, B71).
    Uniformization(crate::uniformization::claim_form::UniformizationClaim),
    /// `sphere_uniformization`: the surface (genus 0, its exact metric) is discretely
    /// conformally equivalent to a convex polyhedron inscribed in the unit sphere: after
    /// the given Euclidean flips, the disk problem of the pole has an exact solution within
    /// `radius` of `u` whose flat disk is Delaunay with a convex boundary (notes §1.5.3
    /// Thm 9; re-check: `uniformization::sphere_claim`, B90, B76, B74).
    SphereUniformization(crate::uniformization::sphere_claim::SphereClaim),
    /// `hyperbolic_uniformization`: an exact solution `u*` of `θ_hyp(u*) = Θ` (sinh
    /// scaling, the surface's lengths read as hyperbolic lengths; its own triangulation, or
    /// with optional `flips` the one their λ-Ptolemy flips reach, Delaunay at `u*`) exists
    /// within `radius` (sup norm) of the given `u`, and `‖Θ − θ_hyp(u)‖₂ ≤ residual_bound`
    /// (notes Thm 11; `uniformization::hyperbolic_claim`, B39, B87, B89).
    HyperbolicUniformization(crate::uniformization::hyperbolic_claim::HyperbolicClaim),
    /// `parametrization`: the embedded UV OBJ and its sidecar are a parametrization of the
    /// surface: no UV fold, every input face tiled exactly, and, when asked, seams that
    /// are rotations by multiples of π/2 within ε ([`crate::overlay::claim`], B109, B110).
    Parametrization(crate::overlay::claim::ParametrizationClaim),
    /// `circle_packing`: the circles (plane) or caps (sphere) realize the surface's
    /// triangulation as a tangency packing within `epsilon`: every edge's tangency defect
    /// is at most ε, every face's centres are positively oriented and every interior
    /// vertex's neighbours wind once around it ([`crate::circles::realize`], proofs/B98).
    CirclePacking {
        /// The claimed circles or caps, one per vertex.
        packing: Packing,
        /// Absolute tolerance ε ≥ 0 on each tangency defect.
        epsilon: Rational,
    },
    /// `circle_pattern`: the radii and the intersection angles `Φ_e = q_e π` give, through
    /// Eq. 9 (notes §1.4), cone angles within `epsilon` of `angles`
    /// ([`crate::circles::realize::pattern_cone_angles`], proofs/B98).
    CirclePattern {
        /// One radius per vertex, positive.
        radii: Vec<Rational>,
        /// `Φ_e / π ∈ [0, 1/2]` per edge, in the surface's edge order.
        phi_over_pi: Vec<Rational>,
        /// One claimed cone angle per vertex, radians.
        angles: Vec<Rational>,
        /// Absolute tolerance ε ≥ 0 on each cone angle.
        epsilon: Rational,
    },
}

impl Assertion {
    /// The protocol name of the claim kind.
    pub fn kind(&self) -> &'static str {
        match self {
            Assertion::IntrinsicDelaunay => "intrinsic_delaunay",
            Assertion::DelaunayFlip { .. } => "delaunay_flip",
            Assertion::ConeAngles { .. } => "cone_angles",
            Assertion::CotanLaplacian { .. } => "cotan_laplacian",
            Assertion::ConformalEquivalence { .. } => "conformal_equivalence",
            Assertion::Energy { .. } => "energy",
            Assertion::Lobachevsky { .. } => "lobachevsky",
            Assertion::Uniformization(_) => "uniformization",
            Assertion::SphereUniformization(_) => "sphere_uniformization",
            Assertion::HyperbolicUniformization(_) => "hyperbolic_uniformization",
            Assertion::Parametrization(_) => "parametrization",
            Assertion::CirclePacking { .. } => "circle_packing",
            Assertion::CirclePattern { .. } => "circle_pattern",
        }
    }
}

/// The circles of a `circle_packing` claim, one per vertex.
#[derive(Clone, Debug, PartialEq)]
pub enum Packing {
    /// Circles in the plane (`centres`, `radii`).
    Plane(Vec<ExactCircle>),
    /// Caps `{P ∈ S²: N·P > H}` on the unit sphere (`caps`).
    Sphere(Vec<ExactCap>),
}
