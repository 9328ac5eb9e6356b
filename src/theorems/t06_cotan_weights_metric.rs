//! T06 — cotan weights determine the metric up to scale (notes §1.3.4, Thm 2: the Hodge
//! star is as rigid as the angles).
//!
//! API:
//! - `pub fn check_weights_determine_metric<T: Real>(mesh: &Mesh, lengths: &[T], settings: &Settings) -> Verdict`
//! - `pub fn verify_weights_determine_metric<T: Real>(mesh: &Mesh, lengths: &[T], weights: &[T], settings: &Settings) -> Verdict`
//!
//! The metric is recovered from the weights by the convex solve of
//! [`crate::variational::weights`] (gauge `q_0 = 1`) and compared with `ℓ_e²/ℓ_0²`.

use super::bounds::{cot_error, eps, EPS_F64, SAFETY};
use super::report::{check_lengths, lengths_out_of_range, Tally};
use super::verdict::{Settings, Verdict};
use crate::geometry::cotan::cotan_weights;
use crate::mesh::Mesh;
use crate::scalar::Real;
use crate::variational::weights::metric_from_weights;

/// T06, numerical: [`verify_weights_determine_metric`] with the metric's own weights.
pub fn check_weights_determine_metric<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    settings: &Settings,
) -> Verdict {
    if let Some(v) = check_lengths(mesh, lengths) {
        return v;
    }
    let w = cotan_weights(mesh, lengths);
    verify_weights_determine_metric(mesh, lengths, &w, settings)
}

/// The metric with cotan weights `weights` is `lengths` up to scale: the squared lengths
/// `q̂` recovered by [`metric_from_weights`] must equal `q*_e = ℓ_e²/ℓ_0²` within
/// proofs/B59: `SAFETY Σ_j |(H⁻¹)_{ej}| (|r_j| + Δw_j) + 4ε q*_e`, `H` the reduced Hessian
/// at `q̂`, `r` the residual `w − w(q̂)` and `Δw_j` the B44 errors of both weight
/// evaluations. An edge beyond it is a witness (the weights then determine another metric,
/// or none); a solve that does not converge is undecided. Defined for closed surfaces and
/// surfaces with boundary alike; the gauge edge is edge 0.
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
    let ctx = lengths[0].ctx();
    let (e, bits) = (eps::<T>(ctx), T::precision_bits(ctx));
    let mut tally = Tally::new(false, bits);
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
        tally.within(format!("e{edge}"), "recovered ℓ²/ℓ₀² − given", &d, tol);
    }
    tally.verdict()
}
