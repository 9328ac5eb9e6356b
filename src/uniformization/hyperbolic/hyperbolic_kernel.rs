//! Per-face quantities of the hyperbolic uniformization energy (notes Thm 11; BPS15 §6;
//! proofs/B38): corner angles, the Hessian weights `½ cot β_m` and `t_m² = tanh²(ℓ̃_m/2)`,
//! from the logarithmic lengths `λ̃_m = 2 log sinh(ℓ̃_m/2)` of the three sides.
//!
//! **Hessian (B38).** With `β_m = ½(π + α_m − α_{m+1} − α_{m+2})` (`α_m` opposite side
//! `m`), side `m = ij` adds `½ cot β_m·[(du_i − du_j)² + t_m²(du_i + du_j)²]` to
//! `d²E_hyp`: `½ cot β_m (1 + t_m²)` to `H_ii` and `H_jj`, `½ cot β_m (t_m² − 1)` to
//! `H_ij`, and for a loop (`i = j`) `2 cot β_m t_m²` to `H_ii`. Since
//! `tanh²(ℓ/2) = sinh²/(1 + sinh²)` and `sinh²(ℓ̃/2) = e^{λ̃}`, `t² = 1/(1 + e^{−λ̃})`.
//!
//! The binary64 kernel ([`face_terms`]) works in logarithms so that no `sinh` or `cosh`
//! overflows: `ln sinh x = x − ln 2 + ln(1 − e^{−2x})` for `x > 1`, the half-angle form
//! `tan²(α_i/2) = sinh(s−ℓ_j) sinh(s−ℓ_k)/(sinh s · sinh(s−ℓ_i))` as a sum of those
//! logarithms, and `ℓ = λ + 2 ln(1 + √(1 + e^{−λ}))` for `λ > 0`. [`face_terms_generic`]
//! is the same quantity over any [`Real`] (the refinement and the interval certificate),
//! through [`crate::variational::hyperbolic`].

use crate::scalar::Real;
use crate::variational::hyperbolic::{angles_half_angle, length_from_log as length_generic};
use std::f64::consts::{LN_2, PI};

/// `ln sinh x` for `x > 0` without overflow: `x − ln 2 + ln(1 − e^{−2x})` past 1.
pub fn ln_sinh(x: f64) -> f64 {
    if x > 1.0 {
        x - LN_2 + (-(-2.0 * x).exp()).ln_1p()
    } else {
        x.sinh().ln()
    }
}

/// `λ = 2 log sinh(ℓ/2)` of a hyperbolic length `ℓ > 0` (T33's convention).
pub fn log_length(l: f64) -> f64 {
    2.0 * ln_sinh(0.5 * l)
}

/// `ℓ = 2 arsinh(e^{λ/2})`, for `λ > 0` as `λ + 2 ln(1 + √(1 + e^{−λ}))` (no overflow).
pub fn length_from_log(lambda: f64) -> f64 {
    if lambda > 0.0 {
        lambda + 2.0 * (1.0 + (1.0 + (-lambda).exp()).sqrt()).ln()
    } else {
        2.0 * (0.5 * lambda).exp().asinh()
    }
}

/// `t² = tanh²(ℓ/2) = 1/(1 + e^{−λ})` from `λ = 2 log sinh(ℓ/2)`.
pub fn tanh_half_squared(lambda: f64) -> f64 {
    1.0 / (1.0 + (-lambda).exp())
}

/// One face's angles and Hessian terms (module doc), side `m` opposite angle `m`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FaceTerms {
    /// The corner angles `α_m`.
    pub angles: [f64; 3],
    /// `½ cot β_m`.
    pub weight: [f64; 3],
    /// `t_m² = tanh²(ℓ̃_m/2)`.
    pub t2: [f64; 3],
}

/// The binary64 [`FaceTerms`] of the hyperbolic triangle with logarithmic side lengths
/// `lambda`; `None` unless every `s − ℓ_m` is positive (a strict triangle) and every term
/// finite. proof: B38
pub fn face_terms(lambda: [f64; 3]) -> Option<FaceTerms> {
    let l = lambda.map(length_from_log);
    let d = [0, 1, 2].map(|m| 0.5 * (l[(m + 1) % 3] + l[(m + 2) % 3] - l[m]));
    if !d.iter().all(|x| x.is_finite() && *x > 0.0) {
        return None;
    }
    let ls = ln_sinh(0.5 * (l[0] + l[1] + l[2]));
    let ld = d.map(ln_sinh);
    let angles = [0, 1, 2].map(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        2.0 * (0.5 * (ld[j] + ld[k] - ls - ld[i])).exp().atan()
    });
    let weight = [0, 1, 2].map(|m| {
        let beta = 0.5 * (PI + angles[m] - angles[(m + 1) % 3] - angles[(m + 2) % 3]);
        0.5 / beta.tan()
    });
    let t2 = lambda.map(tanh_half_squared);
    let finite = angles
        .iter()
        .chain(&weight)
        .chain(&t2)
        .all(|x| x.is_finite());
    finite.then_some(FaceTerms { angles, weight, t2 })
}

/// [`FaceTerms`] over any [`Real`] (angles by the half-angle form of
/// [`crate::variational::hyperbolic`]): `(α, ½ cot β, t²)`. On enclosures, an undecided
/// triangle gives invalid enclosures (the caller's certificate is then undecided).
pub fn face_terms_generic<T: Real>(lambda: &[T; 3]) -> ([T; 3], [T; 3], [T; 3]) {
    let l = lambda.clone().map(|x| length_generic(&x));
    let a = angles_half_angle(&l);
    let z = &lambda[0];
    let (half, pi, one) = (z.lit(0.5), T::pi(z.ctx()), z.one_like());
    let weight = [0, 1, 2].map(|m| {
        let beta = (pi.clone() + &a[m] - &a[(m + 1) % 3] - &a[(m + 2) % 3]) * &half;
        beta.cos() * &half / &beta.sin()
    });
    let t2 = lambda
        .clone()
        .map(|x| one.clone() / &(one.clone() + &(-x).exp()));
    (a, weight, t2)
}
