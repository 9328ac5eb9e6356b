//! Lobachevsky's function `Л(x) = −∫₀ˣ log|2 sin t| dt = ½ Cl₂(2x)` (MATH.md §7).
//!
//! Evaluated by reduction modulo π to `r ∈ (−π/2, π/2]` and the series
//! `Л(r) = r (1 − log|2r| + Σ_{n≥1} |B₂ₙ| (2r)²ⁿ / (2n (2n+1)!))`, whose terms shrink by at
//! least 4× for `|r| ≤ π/2`.
//!
//! ```
//! use penner::special::lobachevsky;
//! // Л(π/6) = (3/2)·Л(π/3) and Л(π/2) = 0.
//! let a = lobachevsky(&(std::f64::consts::PI / 6.0));
//! let b = lobachevsky(&(std::f64::consts::PI / 3.0));
//! assert!((a - 1.5 * b).abs() < 1e-14);
//! assert!(lobachevsky(&std::f64::consts::FRAC_PI_2).abs() < 1e-15);
//! ```

use crate::scalar::Real;
use rug::{Integer, Rational};
use std::sync::{Mutex, OnceLock};

/// The series coefficients `c_n = |B₂ₙ| / (2n (2n+1)!)`, `n ≥ 1`, computed exactly and
/// cached; index `n − 1`.
fn coefficients(count: usize) -> Vec<Rational> {
    static CACHE: OnceLock<Mutex<(Vec<Rational>, Vec<Rational>)>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| Mutex::new((vec![Rational::from(1)], Vec::new())));
    let mut guard = cache
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    let (bernoulli, coeffs) = &mut *guard;
    while coeffs.len() < count {
        let n = coeffs.len() + 1;
        let m = 2 * n;
        // B_0..B_m by B_k = −1/(k+1) Σ_{j<k} C(k+1, j) B_j.
        while bernoulli.len() <= m {
            let k = bernoulli.len();
            let mut s = Rational::new();
            for (j, b) in bernoulli.iter().enumerate() {
                let c = Integer::from(Integer::binomial_u(k as u32 + 1, j as u32));
                s += Rational::from(c) * b;
            }
            bernoulli.push(-s / Rational::from(k + 1));
        }
        let fact = Integer::from(Integer::factorial(m as u32 + 1));
        let c = Rational::from(bernoulli[m].clone().abs()) / Rational::from(fact * m as u32);
        coeffs.push(c);
    }
    coeffs[..count].to_vec()
}

/// `Л(x)`, Lobachevsky's function (MATH.md §7): odd, π-periodic, `Л(π/2) = 0`,
/// `Л′(x) = −log|2 sin x|`; `Л(kπ) = 0`.
pub fn lobachevsky<T: Real>(x: &T) -> T {
    let ctx = x.ctx();
    let pi = T::pi(ctx);
    let k = (x.approx_f64() / std::f64::consts::PI).round();
    let r = if k == 0.0 {
        x.clone()
    } else {
        x.clone() - &(pi * &x.lit(k))
    };
    if r.to_rational().is_some_and(|q| q == 0) {
        return r.zero_like();
    }
    let two_r = r.clone() * &r.lit(2.0);
    let z = two_r.clone() * &two_r;
    let terms = (T::precision_bits(ctx) as usize) / 2 + 4;
    let mut sum = r.zero_like();
    let mut power = z.clone();
    for c in coefficients(terms) {
        sum += &(T::from_rational(&c, ctx) * &power);
        power *= &z;
    }
    let one = r.one_like();
    r.clone() * &(one - &two_r.abs().ln() + &sum)
}

/// Clausen's function `Cl₂(θ) = Σ_{k≥1} sin(kθ)/k² = 2 Л(θ/2)` (MATH.md §7).
pub fn clausen2<T: Real>(theta: &T) -> T {
    let half = theta.clone() * &theta.lit(0.5);
    lobachevsky(&half) * &theta.lit(2.0)
}

/// Volume `Л(α) + Л(β) + Л(γ)` of the ideal hyperbolic tetrahedron with dihedral angles
/// `α, β, γ`, `α + β + γ = π` (Milnor; MATH.md §7).
pub fn ideal_tetrahedron_volume<T: Real>(alpha: &T, beta: &T, gamma: &T) -> T {
    lobachevsky(alpha) + &lobachevsky(beta) + &lobachevsky(gamma)
}
