//! The hyperbolic certificate as a `penner certify` claim of kind
//! `hyperbolic_uniformization` (protocol v1, `docs/oracle.md`): writing it, and re-checking
//! it from scratch without the solver (B39).
//!
//! A kind of its own rather than a field of `uniformization`: the equation (`θ_hyp`, sinh
//! scaling), the flips (hyperbolic λ-Ptolemy, Leibon's Delaunay condition), no grounded
//! vertex, and the proof (B39, B89, not B71) all differ, and so do the fields. Fields
//! besides the common ones: `targets` (`Θ_i/π`, exact, one per vertex), optional `flips`
//! (below), `u` (exact decimal strings), `radius` (the
//! sup-norm box) and `residual_bound` (a claimed upper bound on `‖Θ − θ_hyp(u)‖₂`). The
//! surface's lengths are read as *hyperbolic* lengths, exactly (any metric of the surface
//! format; `penner uniformize --hyperbolic` writes the binary64 lengths it solved for).
//!
//! The claim: an exact solution `u*` of `θ_hyp(u*) = Θ` on the surface's triangulation with
//! `|u* − u|_∞ ≤ radius`, and `‖Θ − θ_hyp(u)‖₂ ≤ residual_bound`.
//!
//! **With `flips`** (optional; edge indices of the surface in order, an edge keeping its
//! index when flipped, as the `uniformization` claim): the surface must be hyperbolic
//! Delaunay for its lengths (certified on enclosures, else `undecided`); the λ-lengths
//! `λ = 2 sinh(ℓ/2)` are carried through the flips by the hyperbolic Ptolemy relation
//! (replayed on enclosures, B89) to a triangulation `T_k`, and the claim is that
//! `θ_hyp(u*) = Θ` on `T_k` with its scaled λ-lengths `e^{(u*_i+u*_j)/2}λ_ij`, `T_k` being
//! hyperbolic Delaunay at `u*`: a metric discretely conformal to the surface's (Thm 11 with
//! flips, Gu–Guo–Luo–Sun–Wu; B87) with the angles `Θ`. `holds` additionally needs every
//! edge of `T_k` certified Delaunay on the whole box (B89); an edge not certified leaves
//! the claim `undecided`. Without `flips` the claim is the fixed-triangulation one above. It is refuted only by a
//! proof: hyperbolic Gauss–Bonnet leaves no area (no hyperbolic metric has the angles Θ at
//! all), or the residual enclosed over the whole box excludes 0 at a vertex (no solution in
//! the box), or the residual at `u` is enclosed above `residual_bound`.

use super::claim_form::exact_decimal;
use super::hyperbolic::{hyperbolic_gauss_bonnet, validate_hyperbolic_targets, HyperbolicError};
use super::hyperbolic_certificate::{
    base_log_i, box_around, enclosed_residual, existence_on_box, existence_with_flips,
    norm2_bounds, Existence,
};
use super::hyperbolic_flips::{delaunay_on_box, replay_ptolemy};
use super::targets::Targets;
use crate::io::json::{edge_order, to_value};
use crate::io::{Metric, Surface};
use crate::mesh::{Edge, Mesh};
use crate::scalar::{Interval, Mpfr, Precision, Real, Sign};
use rug::Rational;
use serde_json::{json, Value};

/// The claim-specific fields of a `hyperbolic_uniformization` claim, parsed.
#[derive(Clone, Debug, PartialEq)]
pub struct HyperbolicClaim {
    /// `Θ_i/π`, one per vertex.
    pub targets_over_pi: Vec<Rational>,
    /// The proposed `u`.
    pub u: Vec<Rational>,
    /// The sup-norm radius of the box.
    pub radius: Rational,
    /// The claimed bound on `‖Θ − θ_hyp(u)‖₂`.
    pub residual_bound: Rational,
    /// The Ptolemy flips from the surface's triangulation, as indices into its edge order
    /// (`None`: the fixed-triangulation claim).
    pub flips: Option<Vec<usize>>,
}

/// A malformed `hyperbolic_uniformization` claim, named by field.
#[derive(Debug, thiserror::Error)]
pub enum HyperbolicClaimError {
    /// The surface is refused (not closed).
    #[error("surface: {0}")]
    Surface(HyperbolicError),
    /// The targets are refused (count, a non-positive entry).
    #[error("targets: {0}")]
    Targets(HyperbolicError),
    /// Not one `u` per vertex.
    #[error("u: {got} entries, but the surface has {expected} vertices")]
    ScaleCount {
        /// Vertices.
        expected: usize,
        /// Given.
        got: usize,
    },
    /// The radius is not positive.
    #[error("radius: must be positive, found {0}")]
    Radius(String),
    /// The residual bound is negative.
    #[error("residual_bound: must be ≥ 0, found {0}")]
    ResidualBound(String),
    /// The precision is out of range.
    #[error("max_bits: {0} bits out of range")]
    Bits(u32),
    /// A flip index is out of range.
    #[error("flips[{position}]: edge index {index} out of range (the surface has {edges} edges)")]
    FlipIndex {
        /// Position in `flips`.
        position: usize,
        /// The index.
        index: usize,
        /// Edges.
        edges: usize,
    },
    /// A flip cannot be made on the triangulation reached so far.
    #[error("flips[{position}]: edge index {index}: {reason}")]
    Flip {
        /// Position in `flips`.
        position: usize,
        /// The index.
        index: usize,
        /// Why.
        reason: String,
    },
}

/// The verdict of [`recheck`].
#[derive(Clone, Debug, PartialEq)]
pub enum HyperbolicVerdict {
    /// Certified (B39): an exact solution within `distance` (2-norm) of `u`, inside the box.
    Holds {
        /// `‖Θ − θ(u)‖₂/μ`, rounded up.
        distance: f64,
        /// The Gershgorin lower bound of the Hessian on the box.
        mu: f64,
        /// The upper bound of `‖Θ − θ(u)‖₂`.
        residual: f64,
    },
    /// Proved false; the first counterexample.
    Refuted {
        /// What is wrong: `targets`, `vN`, `residual_bound`.
        element: String,
        /// Why, with the proof's reason.
        detail: String,
        /// The discrepancy proved (display only).
        value: f64,
    },
    /// Neither, with the reason.
    Undecided {
        /// Why.
        reason: String,
    },
}

/// The claim's checks that need no arithmetic beyond ℚ: a closed surface, one positive
/// target and one `u` per vertex, a positive radius, a residual bound `≥ 0`.
pub fn validate(mesh: &Mesh, claim: &HyperbolicClaim) -> Result<(), HyperbolicClaimError> {
    if !mesh.is_closed() {
        return Err(HyperbolicClaimError::Surface(
            super::error::UniformizeError::NotClosed {
                edges: mesh.n_boundary_edges(),
            }
            .into(),
        ));
    }
    let targets = Targets::from_multiples_of_pi(claim.targets_over_pi.clone());
    validate_hyperbolic_targets(mesh, &targets).map_err(HyperbolicClaimError::Targets)?;
    if claim.u.len() != mesh.n_vertices() {
        return Err(HyperbolicClaimError::ScaleCount {
            expected: mesh.n_vertices(),
            got: claim.u.len(),
        });
    }
    if claim.radius <= 0 {
        return Err(HyperbolicClaimError::Radius(claim.radius.to_string()));
    }
    if claim.residual_bound < 0 {
        return Err(HyperbolicClaimError::ResidualBound(
            claim.residual_bound.to_string(),
        ));
    }
    flip_edges(mesh, claim).map(|_| ())
}

/// The claim's flips as edges of `mesh` (user order, [`edge_order`]); empty without flips.
fn flip_edges(mesh: &Mesh, claim: &HyperbolicClaim) -> Result<Vec<Edge>, HyperbolicClaimError> {
    let order = edge_order(mesh);
    let mut out = Vec::new();
    for (position, &index) in claim.flips.iter().flatten().enumerate() {
        let Some(&e) = order.get(index) else {
            return Err(HyperbolicClaimError::FlipIndex {
                position,
                index,
                edges: order.len(),
            });
        };
        out.push(Edge(e as u32));
    }
    Ok(out)
}

/// What a `hyperbolic_uniformization` claim states (`to_claim`'s input): the surface
/// `T₀` with binary64 hyperbolic `lengths`, the Ptolemy `flips` from it, the targets, `u`,
/// the box `radius` and the `residual_bound`.
pub struct ClaimData<'a> {
    /// `T₀` (hyperbolic Delaunay for `lengths`).
    pub mesh: &'a Mesh,
    /// Its binary64 hyperbolic lengths.
    pub lengths: &'a [f64],
    /// The Ptolemy flips from `T₀`.
    pub flips: &'a [Edge],
    /// The targets.
    pub targets: &'a Targets,
    /// The proposed `u`.
    pub u: &'a [Rational],
}

/// A certified hyperbolic uniformization as a `hyperbolic_uniformization` claim at `bits`:
/// the surface with the binary64 hyperbolic `lengths` (exactly), the flips (indices in the
/// written surface's edge order), the targets, `u` as exact decimal strings (dyadic), the
/// box `radius` and the `residual_bound`.
pub fn to_claim(data: &ClaimData<'_>, radius: f64, residual_bound: f64, bits: u32) -> Value {
    let ClaimData {
        mesh,
        lengths,
        flips,
        targets,
        u,
    } = *data;
    let order = edge_order(mesh);
    let mut user = vec![0usize; order.len()];
    for (k, &e) in order.iter().enumerate() {
        user[e] = k;
    }
    let surface = Surface {
        mesh: mesh.clone(),
        metric: Metric::Lengths(
            lengths
                .iter()
                .map(|&x| Rational::from_f64(x).unwrap_or_default())
                .collect(),
        ),
        positions: None,
        name: "hyperbolic uniformization input (hyperbolic lengths)".into(),
    };
    let dec = |q: &Rational| exact_decimal(q).unwrap_or_else(|| q.to_string());
    let exact = |x: f64| dec(&Rational::from_f64(x).unwrap_or_default());
    json!({
        "penner_claim": 1,
        "kind": "hyperbolic_uniformization",
        "max_bits": bits,
        "surface": to_value(&surface),
        "targets": targets.over_pi().iter().map(ToString::to_string).collect::<Vec<_>>(),
        "flips": flips.iter().map(|e| user[e.idx()]).collect::<Vec<_>>(),
        "u": u.iter().map(dec).collect::<Vec<_>>(),
        "radius": exact(radius),
        "residual_bound": exact(residual_bound),
    })
}

/// Re-check a `hyperbolic_uniformization` claim about `surface` from scratch at `bits` of
/// MPFR interval arithmetic (module doc): Gauss–Bonnet exactly, the residual enclosed over
/// the box and at `u`, then B39's existence argument on the claimed box
/// ([`existence_on_box`]). Malformed claims are errors; a refutation is always proved.
pub fn recheck(
    surface: &Surface,
    claim: &HyperbolicClaim,
    bits: u32,
) -> Result<HyperbolicVerdict, HyperbolicClaimError> {
    let mesh = &surface.mesh;
    validate(mesh, claim)?;
    let targets = Targets::from_multiples_of_pi(claim.targets_over_pi.clone());
    if let Some(refuted) = gauss_bonnet_refutation(mesh, &targets) {
        return Ok(refuted);
    }
    let prec = Precision::new(u64::from(bits)).map_err(|_| HyperbolicClaimError::Bits(bits))?;
    let lengths: Vec<Interval<Mpfr>> = surface.lengths(prec);
    let base0 = base_log_i(&lengths);
    let flips = flip_edges(mesh, claim)?;
    let (tk, base) =
        replay_ptolemy(mesh, &base0, &flips).map_err(|e| HyperbolicClaimError::Flip {
            position: e.position,
            index: claim.flips.as_ref().map_or(0, |f| f[e.position]),
            reason: e.reason.to_string(),
        })?;
    if claim.flips.is_some() {
        let zero = vec![Interval::from_f64(0.0, prec); mesh.n_vertices()];
        if let Err(reason) = delaunay_on_box(mesh, &base0, &zero) {
            return Ok(HyperbolicVerdict::Undecided {
                reason: format!(
                    "surface: {reason} at u = 0 (the flips start from a hyperbolic Delaunay triangulation)"
                ),
            });
        }
    }
    let mesh = &tk;
    let radius_f = claim.radius.to_f64();
    // No solution in the box: some vertex's residual is enclosed away from 0 on all of it.
    let boxed = box_around(&claim.u, &claim.radius, prec);
    match enclosed_residual(mesh, &base, &targets, &boxed, prec) {
        Err(reason) => {
            return Ok(HyperbolicVerdict::Undecided {
                reason: format!("{reason} on the box of radius {radius_f:e}"),
            })
        }
        Ok(g) => {
            let away = g
                .iter()
                .enumerate()
                .find(|(_, x)| matches!(x.sign(), Some(Sign::Positive | Sign::Negative)));
            if let Some((v, x)) = away {
                return Ok(HyperbolicVerdict::Refuted {
                    element: format!("v{v}"),
                    detail: format!(
                        "Θ − θ_hyp is enclosed away from 0 at v{v} on the whole box of radius {radius_f:e}: no solution there"
                    ),
                    value: x.approx_f64().abs(),
                });
            }
        }
    }
    let point: Vec<Interval<Mpfr>> = claim
        .u
        .iter()
        .map(|q| Interval::from_rational(q, prec))
        .collect();
    let g = match enclosed_residual(mesh, &base, &targets, &point, prec) {
        Ok(g) => g,
        Err(reason) => {
            return Ok(HyperbolicVerdict::Undecided {
                reason: format!("{reason} at u"),
            })
        }
    };
    let (lower, upper) = norm2_bounds(&g, prec);
    let bound = &claim.residual_bound;
    if Rational::from_f64(lower).is_some_and(|l| l > *bound) {
        return Ok(HyperbolicVerdict::Refuted {
            element: "residual_bound".into(),
            detail: format!(
                "‖Θ − θ_hyp(u)‖₂ ≥ {lower:e} exceeds the claimed residual_bound {:e}",
                bound.to_f64()
            ),
            value: lower,
        });
    }
    if Rational::from_f64(upper).is_none_or(|h| h > *bound) {
        return Ok(HyperbolicVerdict::Undecided {
            reason: format!(
                "the enclosed residual ‖Θ − θ_hyp(u)‖₂ ≤ {upper:e} is not below the claimed residual_bound {:e}",
                bound.to_f64()
            ),
        });
    }
    let found = if claim.flips.is_some() {
        existence_with_flips(mesh, &base, &claim.u, &claim.radius, upper, prec)
    } else {
        existence_on_box(mesh, &base, &claim.u, &claim.radius, upper, prec)
    };
    Ok(match found {
        Existence::Holds { distance, mu, .. } => HyperbolicVerdict::Holds {
            distance,
            mu,
            residual: upper,
        },
        Existence::Undecided { reason } => HyperbolicVerdict::Undecided { reason },
    })
}

/// The refutation by hyperbolic Gauss–Bonnet (B38, B39): targets leaving no area on a
/// component admit no hyperbolic metric at all; `None` when they leave area everywhere.
fn gauss_bonnet_refutation(mesh: &Mesh, targets: &Targets) -> Option<HyperbolicVerdict> {
    let e = hyperbolic_gauss_bonnet(mesh, targets).err()?;
    let (element, value) = match &e {
        HyperbolicError::NoArea {
            root,
            sum_over_pi,
            chi,
        } => {
            let sum: f64 = sum_over_pi
                .parse::<Rational>()
                .as_ref()
                .map_or(f64::NAN, Rational::to_f64);
            (
                format!("targets (component of v{root})"),
                (sum - 2.0 * *chi as f64) * std::f64::consts::PI,
            )
        }
        _ => ("targets".to_string(), f64::NAN),
    };
    Some(HyperbolicVerdict::Refuted {
        element,
        detail: format!("no hyperbolic metric has these angles: {e}"),
        value,
    })
}
