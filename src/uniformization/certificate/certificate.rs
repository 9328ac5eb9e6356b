//! An a-posteriori proof that an exact solution `u*` of `θ(u*) = Θ` exists near a computed
//! `u`, re-checkable from scratch from the data of [`CertificateData`]. proof: B71
//!
//! On the box `B = {u' : |u'_i − u_i| ≤ r}` (grounded vertices fixed) the check establishes
//! with interval arithmetic (`Interval<Mpfr>`, directed rounding):
//!
//! 1. the final triangulation `T` (the input `T₀` and its lengths `ℓ⁰` carried by the
//!    recorded Ptolemy flips, enclosed) is intrinsic Delaunay (`P ≥ 0`, B60) and every face a
//!    strict triangle for every `u' ∈ B`, so `B` lies in one Penner cell and `E = E_T` there
//!    — or, across cell boundaries, the hypotheses of B35 ([`super::cell_boundary`]): the
//!    edges not Delaunay on `B` have face-disjoint quadrilaterals and every other edge is
//!    Delaunay whichever of them flip, so some `T_S` is Delaunay at each `u'`;
//! 2. the grounded Hessian `H(u') = −L(u')` satisfies `H(u') ⪰ μI` on `B`, with
//!    `μ = λ_min(H_mid) − ‖H_rad‖_∞`: `H_mid ± H_rad` the interval cotan Laplacian over `B`
//!    and `λ_min(H_mid)` bounded below by a verified Cholesky factorization (B70);
//! 3. the residual `g = Θ − θ(u)` on the free vertices is enclosed, `‖g‖₂ ≤ γ`.
//!
//! If `γ < μ·r` there is a zero `u*` of `∇E` with `‖u* − u‖₂ ≤ γ/μ` (B71: strong convexity
//! on the Euclidean ball of radius `r` inside `B`), and `T` (across boundaries: `T` with
//! the edges of `U` whose `P < 0` at `u*` flipped, B35) is Delaunay for `u*`.
//!
//! The proof attempts for a computed solution ([`prove`], [`prove_on`], [`certify_near`]:
//! the refinement, then boxes of three radii) are in [`super::certificate_prove`].

use super::ball_argument::{ball_outcome_of, box_hessian};
use super::box_f64;
use super::box_values::{BoxLaplacian, BoxLengths};
use super::cell_boundary::{cell_over_box, scale, Boundary};
pub use super::certificate_outcome::CertificateOutcome;
pub(crate) use super::certificate_outcome::I;
pub(crate) use super::certificate_prove::prove_on_owned;
pub use super::certificate_prove::{certify_near, prove, prove_on, Proof, T0Metric};
use super::components::Components;
use super::error::UniformizeError;
use super::newton::validate_input;
use super::refine::{carry_lengths, carry_lengths_from, scaled, RefineError};
use super::targets::Targets;
use crate::geometry::enclosure::angle_sums::enclose_cone_angles;
use crate::mesh::{Edge, Mesh};
use crate::scalar::{Precision, Real, Sign};
use rug::Rational;
use std::borrow::Cow;

/// Everything a certificate states, all exact: `T₀` with its binary64 lengths, the
/// targets, the Ptolemy flip sequence to the final triangulation, `u` (rationals) and the
/// radius `r` of the box.
#[derive(Clone, Debug)]
pub struct CertificateData {
    /// The intrinsic Delaunay input triangulation `T₀`.
    pub t0: Mesh,
    /// Its lengths `ℓ⁰`.
    pub l0: Vec<f64>,
    /// The targets.
    pub targets: Targets,
    /// Ptolemy flips from `T₀` to the final triangulation.
    pub flip_sequence: Vec<Edge>,
    /// The proposed log scale factors.
    pub u: Vec<Rational>,
    /// The radius of the box (sup norm) around `u`.
    pub radius: Rational,
}

/// A malformed certificate (as opposed to one that does not prove its claim).
#[derive(Debug, thiserror::Error)]
pub enum CertificateError {
    /// The surface, lengths or targets are refused.
    #[error(transparent)]
    Input(#[from] UniformizeError),
    /// The flip sequence does not replay.
    #[error(transparent)]
    Replay(#[from] RefineError),
    /// Wrong number of scale factors.
    #[error("{expected} scale factors expected (one per vertex), got {got}")]
    ScaleCount {
        /// Vertices.
        expected: usize,
        /// Given.
        got: usize,
    },
    /// The radius is not positive.
    #[error("radius {0} is not positive")]
    Radius(String),
    /// The precision is out of range.
    #[error("precision of {0} bits out of range")]
    Bits(u64),
}

/// The final triangulation `T` and its base lengths: the lengths of `T₀` carried by the
/// certificate's flip sequence (T28: Ptolemy flips commute with scaling), enclosed. The
/// same for every box around one `u`, so carried once for all of them.
pub(crate) struct Carried {
    /// `T`.
    pub mesh: Mesh,
    /// The base (unscaled) lengths of `T`, enclosed.
    pub base: Vec<I>,
    /// The certificate's interval precision.
    pub prec: Precision,
}

impl Carried {
    /// Validate `data` ([`validate`]) and carry its lengths ([`carry`]).
    pub(crate) fn of(
        data: &CertificateData,
        base0: Option<&[I]>,
        bits: u32,
    ) -> Result<Carried, CertificateError> {
        let prec = validate(data, bits)?;
        carry(data, base0.map(Cow::Borrowed), prec)
    }
}

/// What both certifiers need: the components, the lengths and the interval cotan
/// Laplacian over the box and the enclosed residual at `u` (free vertices, in order), on
/// the final triangulation `mesh`.
pub(crate) struct Prepared<'m> {
    pub mesh: &'m Mesh,
    pub free: Vec<usize>,
    pub free_idx: Vec<Option<usize>>,
    /// Lengths over the box.
    pub box_lengths: BoxLengths,
    /// `L` over the box.
    pub laplacian: BoxLaplacian,
    /// `Θ_v − θ_v(u)` for the free vertices `v`, enclosed.
    pub residual: Vec<I>,
    pub prec: Precision,
    /// The cell boundaries the box crosses (B35), `None` inside one Penner cell.
    pub boundary: Option<Boundary>,
    /// The box, as enclosures of `u'` per vertex (points at the grounded vertices).
    pub boxed: Vec<I>,
}

/// How [`prepare`] encloses step 1 and the Laplacian over the box.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Rung {
    /// Binary64 enclosures first, MPFR per face or edge they leave open, the MPFR path of
    /// B35 when the box is not certified inside one Penner cell (B36).
    Binary64First,
    /// MPFR enclosures at the certificate's precision throughout.
    Mpfr,
}

/// The interval precision of `bits`, once `data` is validated: its surface, lengths and
/// targets, one scale factor per vertex, a positive radius.
pub(crate) fn validate(data: &CertificateData, bits: u32) -> Result<Precision, CertificateError> {
    validate_input(&data.t0, &data.l0, &data.targets)?;
    let n = data.t0.n_vertices();
    if data.u.len() != n {
        return Err(CertificateError::ScaleCount {
            expected: n,
            got: data.u.len(),
        });
    }
    if data.radius <= 0 {
        return Err(CertificateError::Radius(data.radius.to_string()));
    }
    Precision::new(u64::from(bits)).map_err(|_| CertificateError::Bits(u64::from(bits)))
}

/// The lengths of `T₀` carried to the final triangulation by `data.flip_sequence`: the
/// binary64 `data.l0` enclosed at `prec`, or `base0` when given, which encloses the lengths
/// of `T₀` (e.g. an irrational input metric, flipped to `T₀` in intervals) and replaces
/// `data.l0` (which is still validated) in every enclosure. An owned `base0` is carried in
/// place.
pub(crate) fn carry(
    data: &CertificateData,
    base0: Option<Cow<'_, [I]>>,
    prec: Precision,
) -> Result<Carried, CertificateError> {
    let (mesh, base) = match base0 {
        None => carry_lengths::<I>(&data.t0, &data.l0, &data.flip_sequence, prec)?,
        Some(b) => {
            if b.len() != data.t0.n_edges() {
                return Err(CertificateError::Input(UniformizeError::LengthCount {
                    expected: data.t0.n_edges(),
                    got: b.len(),
                }));
            }
            carry_lengths_from(&data.t0, b.into_owned(), &data.flip_sequence)?
        }
    };
    Ok(Carried { mesh, base, prec })
}

/// Check the Penner cell on the box of `data` around its `u` (B71 step 1, across cell
/// boundaries B35), the lengths of `T` carried by [`carry`] (from a `data` that passed
/// [`validate`]); `Err(reason)` when a step is not certified. The angle sums at `u` come
/// first, so that the lengths at `u` are dropped once the binary64 box lengths are formed
/// from them (recomputed on the MPFR path across cell boundaries, whose angle sums need
/// them again).
#[allow(clippy::too_many_lines)] // the three steps of B71, read top to bottom
pub(crate) fn prepare<'m>(
    data: &CertificateData,
    carried: &'m Carried,
    rung: Rung,
) -> Result<Prepared<'m>, String> {
    let Carried { mesh, base, prec } = carried;
    let prec = *prec;
    if let Some(e) = base.iter().position(|x| x.sign() != Some(Sign::Positive)) {
        return Err(format!("carried length of e{e} not enclosed as positive"));
    }
    let comps = Components::of(mesh);
    let (free, free_idx) = comps.free_index();
    let point: Vec<I> = data.u.iter().map(|q| I::from_rational(q, prec)).collect();
    // The lengths at u, enclosed (for the residual, and the binary64 rung's box lengths).
    let lp = scaled(mesh, base, &point);
    // One enclosed argument per vertex, per-corner fallback where not certified (B33).
    let mut theta = enclose_cone_angles(mesh, &lp).theta;
    let binary64_lengths = match rung {
        Rung::Binary64First => box_f64::box_lengths(&lp, &data.radius),
        Rung::Mpfr => None,
    };
    // Kept for the MPFR path only (the angle sums across cell boundaries).
    let mut lp = binary64_lengths.is_none().then_some(lp);
    let boxed: Vec<I> = data
        .u
        .iter()
        .enumerate()
        .map(|(v, q)| {
            if comps.is_root(v) {
                I::from_rational(q, prec)
            } else {
                let lo = I::from_rational(&Rational::from(q - &data.radius), prec);
                let hi = I::from_rational(&Rational::from(q + &data.radius), prec);
                I::new(lo.lo().clone(), hi.hi().clone())
            }
        })
        .collect();
    // 1. One Penner cell, or cell boundaries crossed as B35 allows: strict triangles,
    // Delaunay edges and the Laplacian over the whole box; binary64 first when asked
    // (B36), MPFR for what it leaves open.
    let binary64 = binary64_lengths.and_then(|lb| {
        let exact = |e: Edge| scale(mesh, e.halfedge(), &base[e.idx()], &boxed);
        let matrix = box_f64::cell_over_box(mesh, &lb, exact)?;
        Some((
            BoxLengths::Binary64 { lengths: lb, prec },
            BoxLaplacian::Binary64 { matrix, prec },
            None,
        ))
    });
    let (box_lengths, laplacian, boundary) = if let Some(b) = binary64 {
        b
    } else {
        let lb = scaled(mesh, base, &boxed);
        match cell_over_box(mesh, base, &boxed, &lb) {
            Ok(c) => (
                BoxLengths::Mpfr(lb),
                BoxLaplacian::Mpfr(c.laplacian),
                c.boundary,
            ),
            Err(reason) => return Err(reason),
        }
    };
    if let Some((i, j, _)) = laplacian.entries().find(|(_, _, w)| !w.is_valid()) {
        return Err(format!("cotan Laplacian entry ({i}, {j}) not enclosed"));
    }
    // The residual at u, enclosed.
    if let Some(b) = &boundary {
        // The angle sums of a triangulation Delaunay at the centre (B35).
        let lp = lp.take().unwrap_or_else(|| scaled(mesh, base, &point));
        b.correct_angle_sums(mesh, &point, &lp, &mut theta)?;
    }
    let pi = I::pi(prec);
    let mut residual = Vec::with_capacity(free.len());
    for &v in &free {
        let g = I::from_rational(&data.targets.over_pi()[v], prec) * &pi - &theta[v];
        if !g.is_valid() {
            return Err(format!("angle sum at v{v} not enclosed"));
        }
        residual.push(g);
    }
    Ok(Prepared {
        mesh,
        free,
        free_idx,
        box_lengths,
        laplacian,
        residual,
        prec,
        boundary,
        boxed,
    })
}

/// Check a certificate at `bits` of interval precision. proof: B71
pub fn check_certificate(
    data: &CertificateData,
    bits: u32,
) -> Result<CertificateOutcome, CertificateError> {
    check_certificate_on(data, None, bits)
}

/// [`check_certificate`] for the metric enclosed by `base0` on `T₀` (see [`carry`]'s
/// `base0`): a `Holds` is then a proof for every metric in the enclosure, in particular
/// for an exact input metric that binary64 does not represent. proof: B71
pub fn check_certificate_on(
    data: &CertificateData,
    base0: Option<&[I]>,
    bits: u32,
) -> Result<CertificateOutcome, CertificateError> {
    Ok(check_carried(data, &Carried::of(data, base0, bits)?))
}

/// [`check_certificate_on`] once `data` is validated and its lengths carried. proof: B71
pub(crate) fn check_carried(data: &CertificateData, carried: &Carried) -> CertificateOutcome {
    let p = match prepare(data, carried, Rung::Binary64First) {
        Ok(p) => p,
        Err(reason) => return CertificateOutcome::Undecided { reason },
    };
    // The box's enclosures of `u'` are not needed by the ball argument.
    drop(p.boxed);
    if p.free.is_empty() {
        // Every vertex is grounded (one-vertex components): the box is the point `u`, and
        // Gauss–Bonnet makes the residual at a grounded vertex zero (B71, "The grounded
        // vertex"), so `u` itself is an exact solution.
        return CertificateOutcome::Holds {
            distance: 0.0,
            mu: f64::INFINITY,
            residual: 0.0,
        };
    }
    // 2–3. The Hessian over the box and the residual at u: the ball argument, the
    // Laplacian and the lengths over the box dropped once the Hessian is formed.
    let hessian = box_hessian(p.laplacian.entries(), &p.free_idx, p.residual.len(), p.prec);
    let approx = p.box_lengths.approx_f64();
    drop((p.laplacian, p.box_lengths));
    ball_outcome_of(
        p.mesh,
        &approx,
        &hessian,
        &p.free_idx,
        &p.residual,
        &data.radius,
        p.prec,
    )
}
