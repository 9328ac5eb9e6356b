//! T06 — cotan weights determine the metric up to scale (notes §1.3.4, Thm 2: the Hodge
//! star is as rigid as the angles).
//!
//! API:
//! - `pub fn check_weights_determine_metric<T: Real>(mesh: &Mesh, lengths: &[T], settings: &Settings) -> Verdict`
//! - `pub fn verify_weights_determine_metric<T: Real>(mesh: &Mesh, lengths: &[T], weights: &[T], settings: &Settings) -> Verdict`
//! - `pub fn verify_weight_boxes<T: Real>(mesh: &Mesh, lengths: &[T], boxes: &[Interval<Mpfr>], settings: &Settings) -> Verdict`
//! - `pub fn weight_enclosures<T: Real>(mesh: &Mesh, lengths: &[T]) -> Option<Vec<Interval<Mpfr>>>`
//!
//! On a metric alone, T06 is certified by the positive definiteness of the weight energy's
//! Hessian with one edge fixed ([`super::t06_weight_rigidity`], proofs/B102). Given
//! weights, the metric is recovered by the convex solve of [`crate::variational::weights`]
//! (gauge `q_0 = 1`) and compared with `ℓ_e²/ℓ_0²` (numerical, B59; also the fallback on
//! small surfaces where B102 does not certify). A refutation is only ever the exact one of
//! proofs/B31: the given metric's weights, enclosed, exclude a given weight.

use super::bounds::{cot_error, eps, eps_shift, EPS_F64, SAFETY};
use super::report::{check_lengths, lengths_out_of_range, Tally};
use super::t06_weight_rigidity::{certify_by_faces, certify_weight_rigidity};
use super::verdict::{Settings, Verdict, Witness};
use crate::geometry::cotan::cotan_weights;
use crate::mesh::Mesh;
use crate::predicates::tolerance::abs_at_most_scaled;
use crate::scalar::{Interval, Mpfr, Precision, Real};
use crate::uniformization::components::Components;
use crate::variational::weights::metric_from_weights;

/// The weight enclosures run at `4p + ENCLOSURE_EXTRA_BITS` bits for working precision
/// `p ≥ 53` (proof: B31): rigorous at any precision, more bits only make them narrower —
/// needed on needles, where `b² + c² − a²` cancels to `10⁻⁴⁸` of its terms at sides `10⁻²⁴`.
pub const ENCLOSURE_EXTRA_BITS: u32 = 64;

/// Edges up to which the metric is recovered from its weights by the dense Newton solve of
/// [`metric_from_weights`] (`O(m³)` per step); above, the recovery is `undecided`.
pub const RECOVERY_MAX_EDGES: usize = 150;

/// Rigorous enclosures of the cotan weights `w_e = ½(cot α + cot β)` of the exact metric
/// `lengths` (each length read as the exact rational it stores), on `Interval<Mpfr>` at
/// four times the working precision plus [`ENCLOSURE_EXTRA_BITS`] (proof: B31, B20).
/// `None` when a length has no exact value (NaN, ±∞).
pub fn weight_enclosures<T: Real>(mesh: &Mesh, lengths: &[T]) -> Option<Vec<Interval<Mpfr>>> {
    let z = lengths.first()?;
    let bits = 4 * T::precision_bits(z.ctx()).max(53) + ENCLOSURE_EXTRA_BITS;
    let p = Precision::new(u64::from(bits)).ok()?;
    let l: Vec<Interval<Mpfr>> = lengths
        .iter()
        .map(|x| x.to_rational().map(|q| Interval::from_rational(&q, p)))
        .collect::<Option<_>>()?;
    Some(cotan_weights(mesh, &l))
}

/// proofs/B31: the edges whose given weight box is disjoint from the enclosure of the
/// metric's own weight, as certified witnesses. Weights are invariant under scaling, so
/// each such edge proves that no scaling of `lengths` has weights in the boxes: the metric
/// they determine (if any) is another one. `None` when no edge is proven different.
fn weights_proven_different<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    boxes: &[Interval<Mpfr>],
) -> Option<Verdict> {
    let enc = weight_enclosures(mesh, lengths)?;
    let bits = T::precision_bits(lengths.first()?.ctx());
    let mut tally = Tally::new(true, bits);
    for (e, (w, given)) in enc.iter().zip(boxes).enumerate() {
        let apart = w.is_valid()
            && given.is_valid()
            && (given.hi().0 < w.lo().0 || given.lo().0 > w.hi().0);
        if apart {
            let (lo, hi) = (w.lo().approx_f64(), w.hi().approx_f64());
            tally.fail(
                format!("e{e}"),
                format!(
                    "the metric's weight lies in [{lo:.17e}, {hi:.17e}], the given one outside: \
                     no scaling of the metric has these weights"
                ),
                given.approx_f64() - 0.5 * (lo + hi),
            );
        }
    }
    (!tally.is_clean()).then(|| tally.verdict())
}

/// T06 on the metric `lengths` (each read as the exact rational it stores): every metric
/// with the same cotan weights is a scaling of it.
///
/// `Holds`, certified, when the Hessian of the weight energy with edge 0 fixed is proved
/// positive definite at the exact lengths (proofs/B102): by a verified Cholesky
/// factorization of its enclosure ([`certify_weight_rigidity`]) or, where that cannot
/// resolve the conditioning, by faces ([`certify_by_faces`], B103: every face a certified
/// strict triangle, the faces connected through edges).
/// Otherwise, up to [`RECOVERY_MAX_EDGES`] edges, the weights computed at the working
/// precision are recovered by [`metric_from_weights`] and compared with `ℓ_e²/ℓ_0²` as in
/// [`verify_weights_determine_metric`] (`holds` numerical, B59), and `undecided` with the
/// certificate's reason beyond that. Never `fails` (proofs/B31): the computed weights are
/// the metric's only up to rounding, so no exact comparison applies, and neither a matrix
/// not proved definite nor a recovered metric beyond the first-order bound of B59 is a
/// proof of a second metric. A disconnected surface is `NotApplicable`: each component
/// scales on its own, so the statement is about connected surfaces.
pub fn check_weights_determine_metric<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    settings: &Settings,
) -> Verdict {
    if let Some(v) = check_lengths(mesh, lengths).or_else(|| lengths_out_of_range(lengths)) {
        return v;
    }
    let components = Components::of(mesh).roots.len();
    if components > 1 {
        return Verdict::NotApplicable {
            reason: format!(
                "{components} components: the cotan weights fix the metric up to one scale \
                 per component (T06 is about a connected surface)"
            ),
        };
    }
    // proof: B102, then B103 where the factorization cannot resolve the conditioning.
    let certified = Verdict::Holds {
        certified: true,
        max_error: 0.0,
    };
    let reasons = match certify_weight_rigidity(mesh, lengths, 0) {
        Ok(_) => return certified,
        Err(n) => match certify_by_faces(mesh, lengths) {
            Ok(()) => return certified,
            Err(by_faces) => {
                // Faces not certified strict are named by both: keep one list.
                let mut r = n.elements;
                if r.iter().all(|(e, _)| e == "surface") {
                    r.extend(by_faces.elements);
                }
                r
            }
        },
    };
    let bits = T::precision_bits(lengths[0].ctx());
    let undecided = |extra: Vec<Witness>| {
        let mut witnesses: Vec<Witness> = reasons
            .iter()
            .map(|(element, detail)| Witness {
                element: element.clone(),
                detail: detail.clone(),
                value: f64::NAN,
            })
            .collect();
        witnesses.extend(extra);
        Verdict::Undecided {
            bits_tried: bits,
            witnesses,
        }
    };
    if mesh.n_edges() > RECOVERY_MAX_EDGES {
        return undecided(Vec::new());
    }
    let w = cotan_weights(mesh, lengths);
    match recover_and_compare(mesh, lengths, &w, settings) {
        Verdict::Undecided { witnesses, .. } => undecided(witnesses),
        v => v,
    }
}

/// The metric with cotan weights `weights` (exact as given) is `lengths` up to scale.
///
/// `Fails`, certified, only by proofs/B31: an edge whose given weight lies outside the
/// rigorous enclosure of the metric's own weight ([`weight_enclosures`]) proves that no
/// scaling of `lengths` has these weights (they determine another metric, or none).
/// Otherwise the squared lengths `q̂` recovered by [`metric_from_weights`] are compared
/// with `q*_e = ℓ_e²/ℓ_0²` within proofs/B59
/// (`SAFETY Σ_j |(H⁻¹)_{ej}| (|r_j| + Δw_j) + 4ε q*_e`, `H` the reduced Hessian at `q̂`,
/// `r` the residual `w − w(q̂)`, `Δw_j` the B44 errors of both weight evaluations):
/// `holds` (numerical) within it, `undecided` beyond it or when the solve does not
/// converge — B59 is first order, so an edge beyond it proves nothing. Defined for closed
/// surfaces and surfaces with boundary alike; the gauge edge is edge 0.
pub fn verify_weights_determine_metric<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    weights: &[T],
    settings: &Settings,
) -> Verdict {
    if let Some(v) = check_lengths(mesh, lengths).or_else(|| lengths_out_of_range(lengths)) {
        return v;
    }
    if weights.len() != mesh.n_edges() {
        return Verdict::NotApplicable {
            reason: format!("{} weights for {} edges", weights.len(), mesh.n_edges()),
        };
    }
    let boxes: Option<Vec<Interval<Mpfr>>> = weight_enclosures(mesh, lengths).and_then(|enc| {
        let p = enc.first()?.ctx();
        weights
            .iter()
            .map(|w| Some(Interval::from_rational(&w.to_rational()?, p)))
            .collect()
    });
    // proof: B31
    if let Some(v) = boxes.and_then(|b| weights_proven_different(mesh, lengths, &b)) {
        return v;
    }
    recover_and_compare(mesh, lengths, weights, settings)
}

/// [`verify_weights_determine_metric`] for weights known as boxes (one enclosure per
/// edge, e.g. of weights computed from another metric): `fails`, certified, when a box is
/// disjoint from the enclosure of the metric's own weight (proofs/B31); otherwise the
/// recovery from the boxes' midpoints (rounded to `T`) compared as there (`holds`
/// numerical or `undecided`).
pub fn verify_weight_boxes<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    boxes: &[Interval<Mpfr>],
    settings: &Settings,
) -> Verdict {
    if let Some(v) = check_lengths(mesh, lengths).or_else(|| lengths_out_of_range(lengths)) {
        return v;
    }
    if boxes.len() != mesh.n_edges() {
        return Verdict::NotApplicable {
            reason: format!("{} weights for {} edges", boxes.len(), mesh.n_edges()),
        };
    }
    // proof: B31
    if let Some(v) = weights_proven_different(mesh, lengths, boxes) {
        return v;
    }
    let ctx = lengths[0].ctx();
    let mid: Option<Vec<T>> = boxes
        .iter()
        .map(|b| {
            let m = (b.lo().0.to_rational()? + b.hi().0.to_rational()?) / 2u32;
            Some(T::from_rational(&m, ctx))
        })
        .collect();
    match mid {
        Some(w) => recover_and_compare(mesh, lengths, &w, settings),
        None => Verdict::Undecided {
            bits_tried: T::precision_bits(ctx),
            witnesses: Vec::new(),
        },
    }
}

/// The recovery and the B59 comparison of [`verify_weights_determine_metric`]: `holds`
/// (numerical) or `undecided`, never `fails` (proof: B31).
fn recover_and_compare<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    weights: &[T],
    settings: &Settings,
) -> Verdict {
    let ctx = lengths[0].ctx();
    let (e, bits) = (eps::<T>(ctx), T::precision_bits(ctx));
    let shift = eps_shift(bits);
    let mut tally = Tally::new(false, bits);
    if mesh.n_edges() > RECOVERY_MAX_EDGES {
        tally.undecided(
            "surface",
            format!(
                "{} edges: the dense recovery runs up to {RECOVERY_MAX_EDGES} edges",
                mesh.n_edges()
            ),
            f64::NAN,
        );
        return tally.verdict();
    }
    let Some(sol) = metric_from_weights(mesh, weights, 0) else {
        tally.undecided("surface", "the Newton system is singular", f64::NAN);
        return tally.verdict();
    };
    if !sol.converged || sol.hessian_inverse.is_empty() {
        tally.undecided(
            "surface",
            format!("no convergence after {} Newton steps", sol.steps),
            f64::NAN,
        );
        return tally.verdict();
    }
    // Δw per edge: B44 for each cotangent, of the given metric and of q̂.
    let lhat: Vec<f64> = sol.q.iter().map(|x| x.approx_f64().sqrt()).collect();
    let lf: Vec<f64> = lengths.iter().map(Real::approx_f64).collect();
    let mut dw = vec![0.0; mesh.n_edges()];
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        for m in 0..3 {
            let idx = hs.map(|h| h.edge().idx());
            let (a, b, c) = (idx[m], idx[(m + 1) % 3], idx[(m + 2) % 3]);
            dw[a] +=
                0.5 * (cot_error(lf[a], lf[b], lf[c], e) + cot_error(lhat[a], lhat[b], lhat[c], e));
        }
    }
    let free: Vec<usize> = (1..mesh.n_edges()).collect();
    // proof: B59 — H⁻¹ is formed in f64: past a condition number of 2⁵⁰ it is no bound.
    let norm_inf = |a: &[Vec<f64>]| {
        a.iter()
            .map(|r| r.iter().copied().map(f64::abs).sum::<f64>())
            .fold(0.0, f64::max)
    };
    let h: Vec<Vec<f64>> = sol.hessian_inverse.clone();
    let kappa = norm_inf(&h) * norm_inf(&sol.hessian);
    if !(kappa.is_finite() && kappa * EPS_F64 <= 0.125) {
        tally.undecided(
            "surface",
            format!("the reduced Hessian is too ill-conditioned (κ ≈ {kappa:.1e})"),
            kappa,
        );
        return tally.verdict();
    }
    // The gauge edge's equation is not imposed by the reduced solve: a result that misses
    // it is no metric with these weights (a solver failure, or unrealizable weights).
    let r0 = sol.residual[0].approx_f64().abs();
    let r0_bound = SAFETY * 64.0 * (dw[0] + 4.0 * e * weights[0].approx_f64().abs());
    if r0.partial_cmp(&r0_bound) != Some(std::cmp::Ordering::Less)
        && r0.partial_cmp(&r0_bound) != Some(std::cmp::Ordering::Equal)
    {
        tally.undecided(
            "e0",
            "the recovered metric misses the gauge edge's weight: no metric found",
            r0,
        );
        return tally.verdict();
    }
    let l0 = lengths[0].clone();
    for (r, &edge) in free.iter().enumerate() {
        let row = &sol.hessian_inverse[r];
        let mut tol = 0.0;
        for (c, &j) in free.iter().enumerate() {
            tol += row[c].abs() * (sol.residual[j].approx_f64().abs() + dw[j]);
        }
        let qstar = (lengths[edge].clone() / &l0) * &(lengths[edge].clone() / &l0);
        let tol = settings.slack * (SAFETY * tol + 4.0 * e * qstar.approx_f64().abs());
        // First order only while the bound is small against the value.
        let tol = if tol <= 0.125 * qstar.approx_f64().abs() {
            tol
        } else {
            f64::INFINITY
        };
        let d = sol.q[edge].clone() - &qstar;
        // proof: B31 — beyond a first-order bound is no refutation.
        if abs_at_most_scaled(&d, tol, shift) == Some(false) {
            tally.undecided(
                format!("e{edge}"),
                format!(
                    "recovered ℓ²/ℓ₀² − given beyond the first-order bound {tol:.3e} \
                     (B59; not a proof of another metric)"
                ),
                d.approx_f64(),
            );
            continue;
        }
        tally.within(format!("e{edge}"), "recovered ℓ²/ℓ₀² − given", &d, tol);
    }
    tally.verdict()
}
