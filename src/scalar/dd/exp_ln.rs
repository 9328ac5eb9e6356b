//! Exponential and logarithm in double-double.
//!
//! `exp`: `x = k·ln 2 + r` with ln 2 to 161 bits, `|r| ≤ ln2/2`; `e^r − 1` by its Taylor
//! polynomial (degree 12) at `r/32`, then five doublings `p ← p(p + 2)` of `p = e^s − 1`,
//! which keep the error relative to `p`. proof: B10
//!
//! `ln`: `x = 2ᵏ·m` with `m ∈ [1/√2, √2)`; one Newton step from `y₀ = RN(ln m_h)`:
//! `ln m = y₀ + ln(1 + ε)`, `ε = (m − e^{y₀})/e^{y₀} = ((m − 1) − p)/(1 + p)` with
//! `p = e^{y₀} − 1` from the same kernel, so `x` near 1 keeps full relative accuracy.
//! proof: B11

use super::arith::{add, add_f64, div, mul, mul_f64, two_prod};
use super::consts::{INV_FACT, LN2_PARTS};
use super::Dd;

/// Degree of the Taylor polynomial of `e^s − 1` on `|s| ≤ ln2/64`.
const EXP_DEGREE: usize = 12;
/// Number of doublings after the polynomial (the argument is divided by 2⁵).
const EXP_DOUBLINGS: i32 = 5;

/// `e^r − 1` for `|r| ≤ 0.35`, with error relative to the result (no cancellation).
pub(super) fn expm1_reduced(r: Dd) -> Dd {
    let s = r.ldexp(-EXP_DOUBLINGS);
    let mut h = INV_FACT[EXP_DEGREE];
    for c in INV_FACT[1..EXP_DEGREE].iter().rev() {
        h = add(mul(h, s), *c);
    }
    let mut p = mul(h, s);
    for _ in 0..EXP_DOUBLINGS {
        // e^{2s} − 1 = p (p + 2).
        p = mul(p, add_f64(p, 2.0));
    }
    p
}

/// `k · ln 2` as a double-double for an integer-valued `k` with `|k| < 2¹¹` (relative
/// error ≤ 3u² + 2u² of its value; used where the result has the magnitude of `k ln 2`).
fn k_ln2(k: f64) -> Dd {
    let (a, b) = two_prod(k, LN2_PARTS[0]);
    let (c, d) = two_prod(k, LN2_PARTS[1]);
    add_f64(
        add(Dd { hi: a, lo: b }, Dd { hi: c, lo: d }),
        k * LN2_PARTS[2],
    )
}

/// `e^x`: relative error ≤ 16u² (measured) for `−669 ≤ x ≤ 709.78`; below, an absolute
/// term of one subnormal unit is added, `|z − eˣ| ≤ 16u²·eˣ + 2⁻¹⁰⁷⁴`, the result is never
/// negative and is exactly 0 below −745.2 (where eˣ < 2⁻¹⁰⁷⁵). +∞ above 709.8. proof: B10
pub(super) fn exp(x: Dd) -> Dd {
    if x.hi.is_nan() {
        return x;
    }
    if x.hi > 709.8 {
        return Dd::from_f64(f64::INFINITY);
    }
    if x.hi < -745.2 {
        return Dd::from_f64(0.0);
    }
    let k = (x.hi / LN2_PARTS[0]).round();
    // Subtract the three parts of k·ln 2 one by one, largest first, so that the
    // cancellation happens before any rounding of a large intermediate.
    let (a, b) = two_prod(-k, LN2_PARTS[0]);
    let (c, d) = two_prod(-k, LN2_PARTS[1]);
    let r = add(x, Dd { hi: a, lo: b });
    let r = add(r, Dd { hi: c, lo: d });
    let r = add_f64(r, -k * LN2_PARTS[2]);
    let p = expm1_reduced(r);
    // Below 2⁻⁹⁶⁸ the words round to the subnormal grid on their own (≤ 2⁻¹⁰⁷⁵ each) and
    // `ldexp` renormalizes the pair, exactly (sums on that grid do not round). proof: B10
    add_f64(p, 1.0).ldexp(k as i32)
}

/// `ln x` for `x > 0`; `ln 0 = −∞`, NaN for negative or NaN input, `ln ∞ = ∞`.
pub(super) fn ln(x: Dd) -> Dd {
    if x.hi.is_nan() || x.hi < 0.0 {
        return Dd::from_f64(f64::NAN);
    }
    if x.hi == 0.0 {
        return Dd::from_f64(f64::NEG_INFINITY);
    }
    if x.hi.is_infinite() {
        return x;
    }
    // Bring subnormal inputs into the normal range first (exact scaling).
    let (x, pre) = if x.hi < 1e-290 {
        (x.ldexp(600), -600)
    } else {
        (x, 0)
    };
    let e = ((x.hi.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    // m_h ∈ [1, 2); move to [1/√2, √2).
    let mut k = e;
    if x.hi.abs() * super::pow2(-e) > std::f64::consts::SQRT_2 {
        k += 1;
    }
    let m = x.ldexp(-k);
    let y0 = m.hi.ln();
    let p = expm1_reduced(Dd::from_f64(y0));
    let num = add(add_f64(m, -1.0), -p);
    let eps = div(num, add_f64(p, 1.0));
    // ln(1 + ε) = ε − ε²/2 + ε³/3 + O(ε⁴), |ε| ≲ 2⁻⁵².
    let e2 = mul(eps, eps);
    let e3 = mul_f64(mul(e2, eps), 1.0 / 3.0);
    let corr = add(add(eps, mul_f64(e2, -0.5)), e3);
    let ln_m = add_f64(corr, y0);
    add(ln_m, k_ln2(f64::from(k + pre)))
}
