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

use super::box_f64;
use super::cell_boundary::{cell_over_box, scale, Boundary, CellOverBox};
pub use super::certificate_outcome::CertificateOutcome;
pub(crate) use super::certificate_outcome::I;
use super::components::Components;
use super::error::UniformizeError;
use super::newton::validate_input;
use super::refine::{carry_lengths, carry_lengths_from, flip_to_delaunay_at, scaled, RefineError};
use super::targets::Targets;
use crate::geometry::enclosure::angle_sums::enclose_cone_angles;
use crate::geometry::laplacian::SparseMatrix;
use crate::mesh::{Edge, Mesh};
use crate::scalar::{Interval, Mpfr, Precision, Real, Sign};
use rug::Rational;

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

/// What both certifiers need: the final triangulation, the components, the interval
/// cotan Laplacian over the box and the enclosed residual at `u` (free vertices, in order).
pub(crate) struct Prepared {
    pub mesh: Mesh,
    pub free: Vec<usize>,
    pub free_idx: Vec<Option<usize>>,
    /// Lengths over the box.
    pub box_lengths: Vec<I>,
    /// `L` over the box.
    pub laplacian: SparseMatrix<I>,
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

/// Validate `data`, carry the lengths, and check the Penner cell on the box (B71 step 1,
/// across cell boundaries B35);
/// `Ok(Err(reason))` when a step is not certified. `base0`, when given, encloses the
/// lengths of `T₀` (e.g. an irrational input metric, flipped to `T₀` in intervals) and
/// replaces the binary64 `data.l0` (which is still validated) in every enclosure.
#[allow(clippy::too_many_lines)] // validation, then the three steps of B71, read top to bottom
pub(crate) fn prepare(
    data: &CertificateData,
    base0: Option<&[I]>,
    bits: u32,
    rung: Rung,
) -> Result<Result<Prepared, String>, CertificateError> {
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
    let prec =
        Precision::new(u64::from(bits)).map_err(|_| CertificateError::Bits(u64::from(bits)))?;
    // Base lengths of T, enclosed (T28: Ptolemy flips commute with scaling).
    let (mesh, base) = match base0 {
        None => carry_lengths::<I>(&data.t0, &data.l0, &data.flip_sequence, prec)?,
        Some(b) => {
            if b.len() != data.t0.n_edges() {
                return Err(CertificateError::Input(UniformizeError::LengthCount {
                    expected: data.t0.n_edges(),
                    got: b.len(),
                }));
            }
            carry_lengths_from(&data.t0, b.to_vec(), &data.flip_sequence)?
        }
    };
    if let Some(e) = base.iter().position(|x| x.sign() != Some(Sign::Positive)) {
        return Ok(Err(format!(
            "carried length of e{e} not enclosed as positive"
        )));
    }
    let comps = Components::of(&mesh);
    let (free, free_idx) = comps.free_index();
    let point: Vec<I> = data.u.iter().map(|q| I::from_rational(q, prec)).collect();
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
    // The lengths at u, enclosed (for the residual, and the binary64 rung's box lengths).
    let lp = scaled(&mesh, &base, &point);
    // 1. One Penner cell, or cell boundaries crossed as B35 allows: strict triangles,
    // Delaunay edges and the Laplacian over the whole box; binary64 first when asked
    // (B36), MPFR for what it leaves open.
    let binary64 = match rung {
        Rung::Binary64First => box_f64::box_lengths(&lp, &data.radius).and_then(|lb| {
            let exact = |e: Edge| scale(&mesh, e.halfedge(), &base[e.idx()], &boxed);
            let laplacian = box_f64::cell_over_box(&mesh, &lb, exact, prec)?;
            let to_mpfr = |x: &f64| Mpfr::from_f64(*x, prec);
            let lb = lb.iter().map(|x| I::new(to_mpfr(x.lo()), to_mpfr(x.hi())));
            Some((lb.collect(), laplacian))
        }),
        Rung::Mpfr => None,
    };
    let (lb, cell) = if let Some((lb, laplacian)) = binary64 {
        let cell = CellOverBox {
            laplacian,
            boundary: None,
        };
        (lb, cell)
    } else {
        let lb = scaled(&mesh, &base, &boxed);
        match cell_over_box(&mesh, &base, &boxed, &lb) {
            Ok(c) => (lb, c),
            Err(reason) => return Ok(Err(reason)),
        }
    };
    let laplacian = cell.laplacian;
    if let Some((i, j, _)) = laplacian.entries().find(|(_, _, w)| !w.is_valid()) {
        return Ok(Err(format!(
            "cotan Laplacian entry ({i}, {j}) not enclosed"
        )));
    }
    // The residual at u, enclosed.
    // One enclosed argument per vertex, per-corner fallback where not certified (B33).
    let mut theta = enclose_cone_angles(&mesh, &lp).theta;
    if let Some(b) = &cell.boundary {
        // The angle sums of a triangulation Delaunay at the centre (B35).
        if let Err(reason) = b.correct_angle_sums(&mesh, &point, &lp, &mut theta) {
            return Ok(Err(reason));
        }
    }
    let pi = I::pi(prec);
    let mut residual = Vec::with_capacity(free.len());
    for &v in &free {
        let g = I::from_rational(&data.targets.over_pi()[v], prec) * &pi - &theta[v];
        if !g.is_valid() {
            return Ok(Err(format!("angle sum at v{v} not enclosed")));
        }
        residual.push(g);
    }
    Ok(Ok(Prepared {
        mesh,
        free,
        free_idx,
        box_lengths: lb,
        laplacian,
        residual,
        prec,
        boundary: cell.boundary,
        boxed,
    }))
}

/// Check a certificate at `bits` of interval precision. proof: B71
pub fn check_certificate(
    data: &CertificateData,
    bits: u32,
) -> Result<CertificateOutcome, CertificateError> {
    check_certificate_on(data, None, bits)
}

/// [`check_certificate`] for the metric enclosed by `base0` on `T₀` (see [`prepare`]'s
/// `base0`): a `Holds` is then a proof for every metric in the enclosure, in particular
/// for an exact input metric that binary64 does not represent. proof: B71
pub fn check_certificate_on(
    data: &CertificateData,
    base0: Option<&[I]>,
    bits: u32,
) -> Result<CertificateOutcome, CertificateError> {
    let p = match prepare(data, base0, bits, Rung::Binary64First)? {
        Ok(p) => p,
        Err(reason) => return Ok(CertificateOutcome::Undecided { reason }),
    };
    if p.free.is_empty() {
        // Every vertex is grounded (one-vertex components): the box is the point `u`, and
        // Gauss–Bonnet makes the residual at a grounded vertex zero (B71, "The grounded
        // vertex"), so `u` itself is an exact solution.
        return Ok(CertificateOutcome::Holds {
            distance: 0.0,
            mu: f64::INFINITY,
            residual: 0.0,
        });
    }
    // 2–3. The Hessian over the box and the residual at u: the ball argument.
    Ok(super::ball_argument::ball_outcome(
        &p.mesh,
        &p.box_lengths,
        &p.laplacian,
        &p.free_idx,
        &p.residual,
        &data.radius,
        p.prec,
    ))
}

/// A proof attempt for a solution: the `u` and radius submitted and the outcome.
#[derive(Clone, Debug)]
pub struct Proof {
    /// The certificate data (exact `u` and radius).
    pub data: CertificateData,
    /// The outcome of [`check_certificate`] on it.
    pub outcome: CertificateOutcome,
    /// `max |Θ − θ|` at the submitted `u` (as computed by the refinement, `f64`).
    pub residual_max: f64,
}

/// The lengths of `T₀` of a metric the `f64` solve saw rounded: at one MPFR precision,
/// as MPFR numbers (for the refinement) and as enclosures (for the certificate).
#[derive(Clone, Debug)]
pub struct T0Metric {
    /// The lengths of `T₀`, rounded to the precision.
    pub values: Vec<Mpfr>,
    /// Enclosures of the exact lengths of `T₀`.
    pub enclosures: Vec<Interval<Mpfr>>,
    /// The Euclidean flips from the input triangulation to `T₀`, in order (an edge keeps
    /// its index when flipped).
    pub euclidean: Vec<Edge>,
}

/// Refine `sol` at `bits` of MPFR precision (to `tolerance`), then try to certify boxes of
/// radius `10⁶`, `10³` and `10¹⁰` times the residual's 2-norm estimate around the refined `u`
/// (exact rationals of the MPFR values); the first that holds, or the last outcome.
pub fn prove(
    sol: &super::newton::Uniformization,
    bits: u32,
    tolerance: f64,
) -> Result<Proof, CertificateError> {
    prove_on(sol, None, bits, tolerance)
}

/// [`prove`] for the metric `metric` on `T₀` instead of the binary64 lengths of the
/// solve: the refinement runs on `metric.values` and the certificate on
/// `metric.enclosures` ([`check_certificate_on`]), so a `Holds` is about that metric.
/// The certificate's flip sequence is the solve's followed by the refinement's (the
/// triangulation Delaunay at the refined `u`, B69).
pub fn prove_on(
    sol: &super::newton::Uniformization,
    metric: Option<&T0Metric>,
    bits: u32,
    tolerance: f64,
) -> Result<Proof, CertificateError> {
    let prec =
        Precision::new(u64::from(bits)).map_err(|_| CertificateError::Bits(u64::from(bits)))?;
    let l0 = match metric {
        None => sol
            .initial_lengths
            .iter()
            .map(|&x| Mpfr::from_f64(x, prec))
            .collect(),
        Some(m) => m.values.clone(),
    };
    let (r, flips) = super::refine::refine_with_flips::<Mpfr>(sol, l0, prec, tolerance, 30)?;
    let u: Vec<Rational> =
        r.u.iter()
            .map(|x| x.to_rational().unwrap_or_default())
            .collect();
    certify_after_flips(sol, &flips, metric, &u, r.residual_max(), bits)
}

/// The certificate half of [`prove_on`] for a `u` refined elsewhere (e.g. in double-double,
/// which has no directed rounding: the proof is in `Interval<Mpfr>` at `bits`), whose
/// `max |Θ − θ|` was estimated as `residual_max`: boxes of radius `10⁶`, `10³` and `10¹⁰`
/// times `residual_max·√n` (at least `2^(10 − bits)`·those factors) around `u`; the first
/// that holds, or the last outcome. The triangulation is the solve's, Ptolemy-flipped to
/// the Delaunay triangulation at `u` (decided on MPFR values at `bits`; B69).
pub fn certify_near(
    sol: &super::newton::Uniformization,
    metric: Option<&T0Metric>,
    u: &[Rational],
    residual_max: f64,
    bits: u32,
) -> Result<Proof, CertificateError> {
    let prec =
        Precision::new(u64::from(bits)).map_err(|_| CertificateError::Bits(u64::from(bits)))?;
    if u.len() != sol.initial_mesh.n_vertices() {
        return Err(CertificateError::ScaleCount {
            expected: sol.initial_mesh.n_vertices(),
            got: u.len(),
        });
    }
    let (mut mesh, mut base) = match metric {
        None => carry_lengths::<Mpfr>(
            &sol.initial_mesh,
            &sol.initial_lengths,
            &sol.flip_sequence,
            prec,
        )?,
        Some(m) => carry_lengths_from(&sol.initial_mesh, m.values.clone(), &sol.flip_sequence)?,
    };
    let um: Vec<Mpfr> = u.iter().map(|q| Mpfr::from_rational(q, prec)).collect();
    let mut l = scaled(&mesh, &base, &um);
    let flips = flip_to_delaunay_at(&mut mesh, &mut base, &mut l, &um)?;
    certify_after_flips(sol, &flips, metric, u, residual_max, bits)
}

/// [`certify_near`] on the solve's triangulation followed by the Ptolemy flips `flips`.
fn certify_after_flips(
    sol: &super::newton::Uniformization,
    flips: &[Edge],
    metric: Option<&T0Metric>,
    u: &[Rational],
    residual_max: f64,
    bits: u32,
) -> Result<Proof, CertificateError> {
    let n = sol.u.len().max(1) as f64;
    let floor = 2f64.powi(-(bits.min(1000) as i32) + 10);
    let estimate = (residual_max * n.sqrt()).max(floor);
    let mut flip_sequence = sol.flip_sequence.clone();
    flip_sequence.extend_from_slice(flips);
    let mut last = None;
    // 10⁶ first; then a smaller box (when the first left the Penner cell, e.g. near a
    // Delaunay tie) and a larger one (when the residual over μ exceeded the radius).
    for factor in [1e6, 1e3, 1e10] {
        let radius = Rational::from_f64(estimate * factor).unwrap_or_else(|| Rational::from(1));
        let data = CertificateData {
            t0: sol.initial_mesh.clone(),
            l0: sol.initial_lengths.clone(),
            targets: sol.targets.clone(),
            flip_sequence: flip_sequence.clone(),
            u: u.to_vec(),
            radius,
        };
        let outcome = check_certificate_on(&data, metric.map(|m| &m.enclosures[..]), bits)?;
        let done = matches!(outcome, CertificateOutcome::Holds { .. });
        last = Some(Proof {
            data,
            outcome,
            residual_max,
        });
        if done {
            break;
        }
    }
    Ok(last.expect("three attempts"))
}
