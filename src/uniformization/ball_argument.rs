//! Steps 2–3 of the certificate, shared by the closed surfaces ([`super::certificate`],
//! B71) and the disk problem of the sphere target ([`super::dirichlet_certificate`], B76):
//! from the interval cotan Laplacian over the box and the enclosed residual at its centre,
//! the strong-convexity ball argument. proof: B71
//!
//! With `H_mid ± H_rad` enclosing `H = −L` on the free vertices over the box,
//! `μ = λ_min(H_mid) − ‖H_rad‖_∞` (the eigenvalue bound by a verified Cholesky
//! factorization, B70; Weyl for the radius) and `γ ≥ ‖Θ − θ(u)‖₂`: if `γ/μ < r` (rounded
//! up), a zero `u*` of the free gradient exists with `‖u* − u‖₂ ≤ γ/μ`.

use super::certificate::{to_f64_up, CertificateOutcome, I};
use super::hessian::{grounded_hessian, CholeskyCache};
use super::verified_cholesky::{lambda_min_lower_bound, up, SymmetricLower};
use crate::geometry::laplacian::SparseMatrix;
use crate::mesh::Mesh;
use crate::scalar::{IntervalBound, Mpfr, Precision, Real};
use rug::Rational;

/// Whether `x` is a valid enclosure certified `≥ 0`.
pub(crate) fn certified_nonnegative(x: &I) -> bool {
    let lo = x.lo().as_float();
    x.is_valid() && (lo.is_zero() || lo.is_sign_positive())
}

/// The ball argument (module documentation) for the interval Laplacian `laplacian` over
/// the box of radius `radius`, the free vertices `free_idx` (`None` at fixed vertices) and
/// the enclosed residuals `residual` at the centre (one per free vertex). `mesh` and
/// `box_lengths` only pick the verified shift (an estimate of `λ_min(H_mid)`); the
/// entries of `laplacian` must be valid enclosures. proof: B71, B76
pub(crate) fn ball_outcome(
    mesh: &Mesh,
    box_lengths: &[I],
    laplacian: &SparseMatrix<I>,
    free_idx: &[Option<usize>],
    residual: &[I],
    radius: &Rational,
    prec: Precision,
) -> CertificateOutcome {
    let undecided = |reason: String| CertificateOutcome::Undecided { reason };
    let n_free = residual.len();
    // The Hessian over the box: midpoint and radius matrices of −L.
    let mut entries = Vec::new();
    let mut rad_row = vec![0.0f64; n_free];
    for (i, j, w) in laplacian.entries() {
        let (Some(a), Some(b)) = (free_idx[i], free_idx[j]) else {
            continue;
        };
        let h = -w.clone();
        let mid = ((h.lo().clone() + h.hi()) * &h.lo().lit(0.5)).approx_f64();
        let m = Mpfr::from_f64(mid, prec);
        let rad = to_f64_up(&h.hi().sub_up(&m)).max(to_f64_up(&m.sub_up(h.lo())));
        rad_row[a] = up(rad_row[a] + rad);
        if a >= b {
            entries.push((a, b, mid));
        }
    }
    let rad_norm = rad_row.iter().copied().fold(0.0, f64::max);
    let mid = SymmetricLower { n: n_free, entries };
    // An estimate of λ_min(H_mid) by inverse iteration, then verified shifts below it.
    let estimate = smallest_eigenvalue_estimate(mesh, box_lengths, free_idx);
    let bound = [0.5, 0.25, 0.0625]
        .into_iter()
        .filter_map(|frac| lambda_min_lower_bound(&mid, estimate * frac))
        .find(|b| b.lambda_min > 0.0);
    let Some(bound) = bound else {
        return undecided("no verified positive lower bound on the Hessian's eigenvalues".into());
    };
    let mu = -up(rad_norm - bound.lambda_min); // μ ≤ λ_min − ‖H_rad‖ (rounded down)
    if mu.is_nan() || mu <= 0.0 {
        return undecided(format!(
            "the Hessian's variation over the box ({rad_norm:e}) exceeds its eigenvalue bound ({:e})",
            bound.lambda_min
        ));
    }
    // ‖residual‖₂, rounded up.
    let mut sum = Mpfr::from_f64(0.0, prec);
    for g in residual {
        let (lo, hi) = (g.lo().abs(), g.hi().abs());
        let mag = if lo.as_float() > hi.as_float() {
            lo
        } else {
            hi
        };
        sum = sum.add_up(&mag.mul_up(&mag));
    }
    let gamma = sum.sqrt_up();
    let distance = gamma.div_up(&Mpfr::from_f64(mu, prec));
    let r = Mpfr::from_rational(radius, prec);
    // Strict: γ/μ < r (rounded up) implies γ < μr.
    if distance.as_float() >= r.as_float() {
        return undecided(format!(
            "residual bound {:e} / μ {mu:e} = {:e} is not below the radius {:e}",
            to_f64_up(&gamma),
            to_f64_up(&distance),
            r.approx_f64()
        ));
    }
    CertificateOutcome::Holds {
        distance: to_f64_up(&distance),
        mu,
        residual: to_f64_up(&gamma),
    }
}

/// `λ_min` of the Hessian on the free vertices at the midpoint lengths, by inverse
/// iteration (a heuristic that only picks the shift; the bound itself is verified).
fn smallest_eigenvalue_estimate(mesh: &Mesh, lengths: &[I], free_idx: &[Option<usize>]) -> f64 {
    let top = lengths.iter().map(Real::approx_f64).fold(0.0, f64::max);
    let lf: Vec<f64> = lengths.iter().map(|x| x.approx_f64() / top).collect();
    let h = grounded_hessian(mesh, &lf, free_idx);
    let Some(f) = CholeskyCache::default().factor(&h) else {
        return 0.0;
    };
    let m = free_idx.iter().flatten().count();
    let mut x: Vec<f64> = (0..m).map(|k| 1.0 + (k % 7) as f64 / 7.0).collect();
    let mut lambda = 0.0;
    // ‖x‖/‖H⁻¹x‖ decreases towards λ_min; stop once it moves by less than 10⁻³ of itself
    // (the shifts below are at most half of it, so a slightly high estimate still works).
    for k in 0..30 {
        let y = f.solve(&x);
        let ny = y.iter().map(|a| a * a).sum::<f64>().sqrt();
        let nx = x.iter().map(|a| a * a).sum::<f64>().sqrt();
        if ny.is_nan() || ny <= 0.0 {
            return 0.0;
        }
        let previous = lambda;
        lambda = nx / ny;
        x = y.iter().map(|a| a / ny).collect();
        if k >= 3 && (previous - lambda).abs() <= 1e-3 * lambda {
            break;
        }
    }
    lambda
}
