//! `Л` for `f64` arguments without MPFR on the common path (proofs/B53): Cody–Waite
//! reduction by `π/2 = P₁ + P₂ + P₃` (three binary64 numbers) with exact products, then the
//! series of B52 in binary64 with [`F64_TERMS`] terms and a first-order correction for
//! the low part of the reduced argument. Arguments with `|x| ≥ 2²⁸` or a reduced argument
//! below `2⁻⁴⁰` go through the MPFR evaluation instead.

use super::coefficients::{table, working_precision};
use rug::float::Constant;
use rug::Float;
use std::sync::OnceLock;

/// Terms of each series in binary64: the B52 tail bound at `θ ≤ 0.117` with 17 terms is
/// below `2⁻⁵⁶` of the result.
pub(crate) const F64_TERMS: usize = 17;

/// Largest `|x|` reduced in binary64.
const FAST_LIMIT: f64 = 268435456.0; // 2²⁸

/// Smallest reduced `|t|` accepted from the binary64 reduction (its absolute error is
/// below `2⁻¹²⁵`, B53).
const MIN_REDUCED: f64 = 9.094947017729282e-13; // 2⁻⁴⁰

struct Consts {
    /// π/2 = p1 + p2 + p3 + O(2⁻¹⁶⁰).
    p: [f64; 3],
    /// 2/π rounded.
    two_over_pi: f64,
    a: [f64; F64_TERMS],
    b: [f64; F64_TERMS],
}

fn consts() -> &'static Consts {
    static C: OnceLock<Consts> = OnceLock::new();
    C.get_or_init(|| {
        let hp = Float::with_val(400, Constant::Pi) >> 1u32;
        let p1 = hp.to_f64();
        let r1 = Float::with_val(400, &hp - p1);
        let p2 = r1.to_f64();
        let r2 = Float::with_val(400, &r1 - p2);
        let p3 = r2.to_f64();
        let t = table(working_precision(53));
        let mut a = [0.0; F64_TERMS];
        let mut b = [0.0; F64_TERMS];
        for n in 0..F64_TERMS {
            a[n] = t.a_lo[n].to_f64();
            b[n] = t.b_lo[n].to_f64();
        }
        Consts {
            p: [p1, p2, p3],
            two_over_pi: Float::with_val(64, 2 / Float::with_val(128, Constant::Pi)).to_f64(),
            a,
            b,
        }
    })
}

#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `Σ_{n=1}^{N} cₙ sⁿ` by Estrin's scheme: pairs `c_{2k} + c_{2k+1}s`, combined with `s²`,
/// `s⁴`, `s⁸` (dependency depth 6 instead of 17 for Horner's rule), separate products
/// and sums (without a hardware FMA in the target features `mul_add` is a library call
/// per term; B53: accuracy measured).
#[inline]
fn estrin(c: &[f64; F64_TERMS], s: f64) -> f64 {
    let s2 = s * s;
    let s4 = s2 * s2;
    let s8 = s4 * s4;
    let p = |k: usize| c[2 * k] + c[2 * k + 1] * s;
    let q = |k: usize| p(2 * k) + p(2 * k + 1) * s2;
    let lo = q(0) + q(1) * s4;
    let hi = q(2) + q(3) * s4;
    (lo + (hi + c[16] * s8) * s8) * s
}

/// `round(y)` for `|y| < 2⁵¹` by adding and subtracting `1.5·2⁵²` (ties to even; any tie
/// choice keeps the reduced argument within `π/4` plus rounding, B53), without a library
/// call.
#[inline]
fn round_small(y: f64) -> f64 {
    const SHIFT: f64 = 6755399441055744.0; // 1.5·2⁵²
    (y + SHIFT) - SHIFT
}

/// `Л(t + e)` for `|t| ≤ 1.0708`, `|e| ≤ ulp(t)`, around 0.
#[inline]
fn at_zero(t: f64, e: f64, c: &Consts) -> f64 {
    if t == 0.0 {
        return 0.0;
    }
    let p = estrin(&c.a, t * t);
    let lg = (2.0 * t).abs().ln();
    let inner = (1.0 - lg) + p;
    // Л′(t) = −log|2t| + P + 2t²P′ ≈ inner − 1.
    t.mul_add(inner, e * (inner - 1.0))
}

/// `Л(π/2 + t + e)` for `|t| ≤ 1/2`.
#[inline]
fn at_half_pi(t: f64, e: f64, c: &Consts) -> f64 {
    let q = estrin(&c.b, t * t);
    let inner = std::f64::consts::LN_2 - q;
    -t.mul_add(inner, e * inner)
}

/// `Л(x)` in binary64, or `None` when the MPFR path must decide (large `|x|`, reduced
/// argument below 2⁻⁴⁰, non-finite `x`).
#[inline]
pub(crate) fn lobachevsky_f64(x: f64) -> Option<f64> {
    let c = consts();
    let ax = x.abs();
    if ax <= std::f64::consts::FRAC_PI_4 {
        return Some(at_zero(x, 0.0, c));
    }
    if ax.is_nan() || ax >= FAST_LIMIT {
        return None;
    }
    let k = round_small(x * c.two_over_pi);
    // x − k·p1 is exact (B53); k·p2 = hi + lo exactly.
    let a = (-k).mul_add(c.p[0], x);
    let hi = k * c.p[1];
    let lo = k.mul_add(c.p[1], -hi);
    let (s, e1) = two_sum(a, -hi);
    let tail = e1 - lo - k * c.p[2];
    let (t, e) = two_sum(s, tail);
    if t.abs() < MIN_REDUCED {
        return None;
    }
    let odd = (k as i64) & 1 == 1;
    if !odd {
        return Some(at_zero(t, e, c));
    }
    if t.abs() <= 0.5 {
        return Some(at_half_pi(t, e, c));
    }
    // Л(π/2 + t) = Л(t ∓ π/2) with the sign of t.
    let sg = t.signum();
    let (r, r1) = two_sum(t, -sg * c.p[0]);
    let (r, r2) = two_sum(r, -sg * c.p[1]);
    Some(at_zero(r, r1 + r2 + e - sg * c.p[2], c))
}
