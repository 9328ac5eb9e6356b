//! A certificate that a computed circle pattern is near an exact solution (T09, proofs/B94).
//!
//! Around the computed `ũ` (free coordinates, exact rationals) take the box
//! `U = ũ ± ρ`. With MPFR interval arithmetic:
//! 1. enclose `g = ∇E(ũ) = Θ − θ(ũ)` and bound `‖g‖₂ ≤ γ`;
//! 2. enclose the grounded Hessian `H(u) = −∂θ/∂u` over all of `U` and prove `H − λI`
//!    positive definite for every member by an interval Cholesky factorisation
//!    ([`crate::scalar::dense::interval_cholesky_positive`]);
//! 3. prove `2γ < λρ`.
//!
//! Then `E(u) ≥ E(ũ) + g·(u − ũ) + λ‖u − ũ‖²/2 > E(ũ)` on the sphere `‖u − ũ‖₂ = ρ` (which
//! lies in `U`), so `E` has a minimum inside the ball, where `∇E = 0`: a solution exists in
//! `U`, and it is the only one there (`E` strictly convex on `U`). With the convexity of `E`
//! on all of the grounded space (Chow–Luo 2003, notes Thm 6) it is the unique solution.

use super::pattern::CirclePattern;
use super::solve::{gradient, hessian};
use crate::scalar::dense::{cholesky, interval_cholesky_positive};
use crate::scalar::{Interval, IntervalBound, Mpfr, Precision, Real, Sign};
use rug::Rational;

type I = Interval<Mpfr>;

/// A proved enclosure of the solution of a circle-pattern problem.
#[derive(Clone, Debug)]
pub struct Certificate {
    /// `ũ` per vertex, exactly (the computed solution).
    pub center: Vec<Rational>,
    /// The half-width `ρ` of the box around the free coordinates that holds the solution.
    pub radius: f64,
    /// The proved lower bound `λ` of the Hessian's eigenvalues on the box.
    pub lambda: f64,
    /// The proved upper bound `γ ≥ ‖Θ − θ(ũ)‖₂`.
    pub gradient_norm: f64,
    /// MPFR bits of the interval arithmetic.
    pub bits: u32,
}

impl Certificate {
    /// Whether `other`'s box lies inside this one: `|c − c'|∞ + ρ' ≤ ρ`, compared exactly.
    /// Then the solution proved in `other`'s box is the one proved unique in this box.
    pub fn contains(&self, other: &Certificate) -> bool {
        let (Some(rho), Some(rho2)) = (
            Rational::from_f64(self.radius),
            Rational::from_f64(other.radius),
        ) else {
            return false;
        };
        self.center
            .iter()
            .zip(&other.center)
            .all(|(a, b)| Rational::from(a - b).abs() + &rho2 <= rho)
    }

    /// Whether the two boxes are proved disjoint: some coordinate differs by more than
    /// `ρ₁ + ρ₂`, compared exactly.
    pub fn disjoint_from(&self, other: &Certificate) -> bool {
        let (Some(rho), Some(rho2)) = (
            Rational::from_f64(self.radius),
            Rational::from_f64(other.radius),
        ) else {
            return false;
        };
        let reach = rho + rho2;
        self.center
            .iter()
            .zip(&other.center)
            .any(|(a, b)| Rational::from(a - b).abs() > reach)
    }
}

/// The largest `λ` (to 2⁻¹⁰ relative, by bisection over `[0, trace]`) for which the `f64`
/// Cholesky factorisation of `H − λI` succeeds: an estimate of the smallest eigenvalue.
fn lambda_estimate(h: &[Vec<f64>]) -> f64 {
    let shifted = |lam: f64| {
        let mut a = h.to_vec();
        for (i, row) in a.iter_mut().enumerate() {
            row[i] -= lam;
        }
        cholesky(&a).is_some()
    };
    if !shifted(0.0) {
        return 0.0;
    }
    let (mut lo, mut hi) = (0.0, (0..h.len()).map(|i| h[i][i]).sum::<f64>().max(1e-300));
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if shifted(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

/// Try to certify the computed solution `u` (one value per vertex, `u_ground = 0` on closed
/// problems; any point backend) with MPFR intervals of `bits` bits, on a box of half-width
/// at least `min_radius` (a wider box lets certificates of nearby computations nest,
/// [`Certificate::contains`]). `Err` says why the certificate could not be made (never a
/// refutation: more bits, a smaller box or a better `u` may help).
pub fn certify_solution<T: Real>(
    p: &CirclePattern,
    u: &[T],
    bits: u32,
    min_radius: f64,
) -> Result<Certificate, String> {
    let prec = Precision::new(u64::from(bits)).map_err(|e| e.to_string())?;
    let center: Vec<Rational> = u
        .iter()
        .map(Real::to_rational)
        .collect::<Option<_>>()
        .ok_or("the solution has no exact value (an enclosure)")?;
    let free = p.free();
    if free.is_empty() {
        return Err("no free vertex".into());
    }
    let uc: Vec<I> = center.iter().map(|q| I::from_rational(q, prec)).collect();
    let cos_phi = p.cos_phi::<I>(prec);
    let theta_t = p.target_angles::<I>(prec);
    let g = gradient(p, &uc, &cos_phi, &theta_t);
    let mut sq = I::from_f64(0.0, prec);
    for x in &g {
        // |x|·|x|, not x·x: an enclosure straddling 0 squares to [0, ·], never below 0.
        let a = x.abs();
        sq += &(a.clone() * &a);
    }
    let gamma = sq.sqrt();
    if !gamma.is_valid() {
        return Err("the gradient at the solution has no enclosure".into());
    }
    let gamma_up = gamma.hi().to_f64_up();
    let uf: Vec<f64> = center.iter().map(Rational::to_f64).collect();
    let cf = p.cos_phi::<f64>(());
    let lam_est = lambda_estimate(&hessian(p, &uf, &cf));
    if lam_est <= 0.0 || lam_est.is_nan() {
        return Err("the Hessian at the solution is not numerically positive definite".into());
    }
    let lambda = 0.5 * lam_est;
    let radius = (4.0 * gamma_up / lambda).max(min_radius).max(1e-300);
    let mut ubox = uc.clone();
    let pad = I::new(Mpfr::from_f64(-radius, prec), Mpfr::from_f64(radius, prec));
    for &v in &free {
        ubox[v] = ubox[v].clone() + &pad;
    }
    let lam_i = I::from_f64(lambda, prec);
    if !shifted_positive_definite(hessian(p, &ubox, &cos_phi), &lam_i) {
        return Err(format!(
            "H − {lambda:e}·I not proved positive definite on the box of half-width {radius:e}"
        ));
    }
    let margin = I::from_f64(radius, prec) * &lam_i - &(gamma * &I::from_f64(2.0, prec));
    if margin.sign() != Some(Sign::Positive) {
        return Err("2‖g‖ < λρ not proved".into());
    }
    Ok(Certificate {
        center,
        radius,
        lambda,
        gradient_norm: gamma_up,
        bits,
    })
}

/// Whether `H − λI` is proved positive definite for every symmetric `H` in the interval
/// matrix `h` (step 2 of the module docs, proofs/B94): `λ` subtracted on the diagonal, then
/// the interval Cholesky factorisation ([`interval_cholesky_positive`]).
pub fn shifted_positive_definite(mut h: Vec<Vec<I>>, lambda: &I) -> bool {
    for (i, row) in h.iter_mut().enumerate() {
        row[i] -= lambda;
    }
    interval_cholesky_positive(&h)
}
