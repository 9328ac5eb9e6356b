//! Forward error bounds for the numerical checks (proofs/B40–B47), evaluated in `f64` from
//! the `f64` approximations of the data.
//!
//! Hypothesis shared by all of them (proofs/B40): every primitive operation of the backend
//! (`±`, `×`, `÷`, `√`, `exp`, `ln`, `sin`, `cos`, `atan`, and the constant π) returns the
//! exact result of its rounded arguments times `(1 + δ)` with `|δ| ≤ ε := 16u`, `u` the
//! backend's unit roundoff. Each bound is a first-order bound multiplied by [`SAFETY`] = 2,
//! which covers the second-order terms and the evaluation of the bound in `f64` as long as
//! the first-order relative error stays below 1/8; beyond that the bound is `+∞` (the
//! check then reports the element as undecided rather than guess).

use crate::scalar::Real;

/// Multiplier covering second-order terms (proofs/B40).
pub const SAFETY: f64 = 2.0;

/// Precision (in bits) above which `ε` is carried with part of its exponent apart
/// (proofs/B40, "Range"): `ε = 16·2⁻ᵖ` would leave the `f64` range past about 1070 bits.
pub const EPS_FLOOR_BITS: u32 = 400;

/// The binary exponent `s ≥ 0` by which the tolerances of a `bits`-bit backend are carried
/// scaled (proofs/B40, "Range"): every bound is computed with `ε·2ˢ` in place of `ε`, and
/// the comparison `|err| ≤ tol·2⁻ˢ` is made exactly ([`crate::predicates::tolerance`]).
/// `s = max(0, bits − 400)`, so `ε·2ˢ ≥ 2⁻³⁹⁶` stays a normal `f64` at every precision.
// proof: B40
pub fn eps_shift(bits: u32) -> u32 {
    bits.saturating_sub(EPS_FLOOR_BITS)
}

/// `ε = 16u` for the backend of `ctx`, times `2^s` with `s =` [`eps_shift`] of its bits
/// (proofs/B40). Every bound of B40–B48 is first order in `ε` (linear, times [`SAFETY`]),
/// so a bound computed with this value is the true bound times `2ˢ` — and never underflows.
/// Above [`EPS_FLOOR_BITS`] the backend's unit roundoff is `2⁻ᵖ` (MPFR), so the value is
/// `16·2⁻⁴⁰⁰` exactly.
///
/// ```
/// use penner::scalar::{Mpfr, Precision};
/// use penner::theorems::bounds::{eps, eps_shift};
/// assert_eq!(eps::<f64>(()), 16.0 * f64::EPSILON / 2.0);
/// let p = Precision::new(4096).unwrap();
/// assert_eq!(eps::<Mpfr>(p), (-396.0_f64).exp2());
/// assert_eq!(eps_shift(4096), 3696);
/// ```
// proof: B40
pub fn eps<T: Real>(ctx: T::Ctx) -> f64 {
    let bits = T::precision_bits(ctx);
    if eps_shift(bits) == 0 {
        16.0 * T::unit_roundoff(ctx)
    } else {
        (4.0 - f64::from(EPS_FLOOR_BITS)).exp2()
    }
}

/// Lengths whose `f64` approximations lie in `[2⁻¹⁰⁰, 2¹⁰⁰]` (proofs/B40, "Range"): there,
/// no quantity the checks or their bounds form (products of at most four lengths, their
/// square roots and quotients) leaves the normal range of `f64`, and double-double low words
/// stay normal, so the one-rounding-per-operation model of B40 applies. Outside it every
/// bound is `+∞` and the checks answer `undecided`; `penner check` first rescales a surface
/// by an exact power of two, so this only bites on metrics whose lengths span more than
/// `2²⁰⁰` (or on direct library calls with extreme lengths).
// proof: B40
pub const LENGTH_RANGE: (f64, f64) = (7.888609052210118e-31, 1.2676506002282294e30);

/// Whether a length approximation is inside [`LENGTH_RANGE`] (and finite).
pub fn length_in_range(x: f64) -> bool {
    (LENGTH_RANGE.0..=LENGTH_RANGE.1).contains(&x.abs())
}

/// `ε` of `f64` itself (`16·2⁻⁵³`): the bounds are evaluated in `f64` from the `f64`
/// approximations of the data, so their own evaluation carries this relative error per
/// operation, whatever the backend (proofs/B40, "Evaluation").
pub const EPS_F64: f64 = 16.0 * f64::EPSILON / 2.0;

/// Apply [`SAFETY`], or `+∞` when the first-order relative error is too large for the
/// first-order bound — or for its own evaluation in `f64` — to be trusted (proofs/B40):
/// with `κ = rel/ε` the condition number of the quantity, both `κε ≤ 1/8` (the backend's
/// second-order terms) and `κ·`[`EPS_F64`]` ≤ 1/8` (the bound read from `f64`
/// approximations of the data is within a factor `1 ± 1/4` of the bound at the exact data)
/// are required. The second implies the first, since every backend has `ε ≤ EPS_F64`.
fn finish(abs_first_order: f64, rel: f64, eps: f64) -> f64 {
    let kappa = rel / eps;
    if rel.is_finite() && kappa * EPS_F64.max(eps) <= 0.125 && abs_first_order.is_finite() {
        SAFETY * abs_first_order
    } else {
        f64::INFINITY
    }
}

/// Relative error of `fl(fl(p ± q) ± r)` to first order: `ε(|p ± q| + |x|)/|x|` with
/// `x = p ± q ± r` (proofs/B40).
fn two_step(partial: f64, x: f64, eps: f64) -> f64 {
    eps * (partial.abs() + x.abs()) / x.abs()
}

/// B40: bound on `|fl(α) − α|` for [`crate::geometry::triangle::corner_angle`] with sides
/// `a, b, c` (angle opposite `a`): `sin α (Σρ_i + 5ε) + 2εα`, times [`SAFETY`].
// proof: B40
pub fn corner_angle_error(a: f64, b: f64, c: f64, eps: f64) -> f64 {
    if ![a, b, c].into_iter().all(length_in_range) {
        return f64::INFINITY;
    }
    let x = [a - b + c, a + b - c, a + b + c, b + c - a];
    let p = [a - b, a + b, a + b, b + c];
    let rho: f64 = (0..4).map(|i| two_step(p[i], x[i], eps)).sum();
    let t2 = (x[0] * x[1]) / (x[2] * x[3]);
    let alpha = 2.0 * t2.sqrt().atan();
    let first = alpha.sin() * (rho + 5.0 * eps) + 2.0 * eps * alpha;
    finish(first, rho + 5.0 * eps, eps)
}

/// B41: bound on the rounding error of a recursive sum of `terms` (any summation order):
/// `(n − 1) ε Σ|x_i|`, times [`SAFETY`] (Higham, *Accuracy and Stability*, §4.2).
// proof: B41
pub fn sum_error(terms: impl IntoIterator<Item = f64>, eps: f64) -> f64 {
    let (n, s) = terms
        .into_iter()
        .fold((0usize, 0.0), |(n, s), x| (n + 1, s + x.abs()));
    let first = n.saturating_sub(1) as f64 * eps * s;
    finish(first, n as f64 * eps, eps)
}

/// B44: bound on `|fl(cot α) − cot α|` for [`crate::geometry::triangle::cot_opposite`]
/// with sides `a, b, c` (angle opposite `a`): `(3ε(a²+b²+c²) + |N| ρ_A)/(4A) + ε|cot|`
/// with `ρ_A = ½(Σρ_i + 3ε) + ε` the relative error of Kahan's area.
// proof: B44
pub fn cot_error(a: f64, b: f64, c: f64, eps: f64) -> f64 {
    if ![a, b, c].into_iter().all(length_in_range) {
        return f64::INFINITY;
    }
    let mut s = [a, b, c];
    s.sort_by(|x, y| y.total_cmp(x));
    let [x, y, z] = s;
    let f = [x + (y + z), z - (x - y), z + (x - y), x + (y - z)];
    let p = [y + z, x - y, x - y, y - z];
    let rho: f64 = (0..4).map(|i| two_step(p[i], f[i], eps)).sum();
    let rho_area = 0.5 * (rho + 3.0 * eps) + 2.0 * eps;
    let area = 0.25 * (f[0] * f[1] * f[2] * f[3]).sqrt();
    let n = b * b + c * c - a * a;
    let cot = n / (4.0 * area);
    let first = (3.0 * eps * (a * a + b * b + c * c) + n.abs() * rho_area) / (4.0 * area)
        + 2.0 * eps * cot.abs();
    finish(first, rho_area, eps)
}

/// B45: relative error bound of a product/quotient of `k` factors, each carrying relative
/// error at most `rel_each`, formed with `k − 1` roundings: `k·rel_each + (k − 1)ε`, times
/// [`SAFETY`].
// proof: B45
pub fn product_rel_error(k: usize, rel_each: f64, eps: f64) -> f64 {
    let first = k as f64 * rel_each + k.saturating_sub(1) as f64 * eps;
    finish(first, first, eps)
}

/// B45: relative error of `fl(exp((u_i + u_j)/2))` for exactly stored `u_i, u_j`:
/// `ε(|u_i + u_j|/2 + 3)` (sum, halving exact, exp with a perturbed argument).
// proof: B45
pub fn scale_factor_rel_error(ui: f64, uj: f64, eps: f64) -> f64 {
    let first = eps * (0.5 * (ui + uj).abs() + 3.0);
    finish(first, first, eps)
}
