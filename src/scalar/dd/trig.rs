//! Sine, cosine and arctangents in double-double.
//!
//! `sin`, `cos`: `x = k·π/2 + r` with π/2 to 161 bits (products by `k` exact through
//! TwoProd), `|r| ≤ π/4`, then the Taylor series of sine (to degree 27) or cosine (to
//! degree 28) in double-double. proof: B12
//!
//! `atan2(y, x)`: reduce to `0 ≤ n ≤ d` by symmetry, `c = j/64` nearest to `n/d`,
//! `atan(n/d) = atan(c) + atan(t)`, `t = (n − c·d)/(d + c·n)`, `|t| ≤ 1/128`, `atan(c)`
//! from a table, `atan(t)` by its series to degree 15. proof: B13
//!
//! `acos(x) = atan2(√((1 − x)(1 + x)), x)`, accurate near ±1. proof: B14

use super::arith::{add, add_f64, div, mul, mul_f64, sqrt, two_prod};
use super::consts::{ATAN_TABLE, INV_FACT, INV_ODD, PI, PI_2, PI_2_PARTS, TWO_OVER_PI};
use super::reduce::reduce_payne_hanek;
use super::Dd;

/// Highest power in the sine series (odd).
const SIN_DEGREE: usize = 27;
/// Highest power in the cosine series (even).
const COS_DEGREE: usize = 28;
/// Highest power in the arctangent series (odd), for `|t| ≤ 1/128`.
const ATAN_TERMS: usize = 8;
/// Table spacing of the arctangent reduction: `c = j/ATAN_STEPS`.
const ATAN_STEPS: f64 = 64.0;

/// Below this `|x_h|` the reduction is Cody–Waite with π/2 in three doubles; from it on,
/// Payne–Hanek. proof: B12, B18
const CODY_WAITE_MAX: f64 = 64.0;

/// `x = k·π/2 + r`, `|r| ≤ π/4 (1 + 2⁻⁴⁰)`: returns `r` and `k mod 4`. proof: B12, B18
fn reduce(x: Dd) -> (Dd, i64) {
    if x.hi.abs() >= CODY_WAITE_MAX {
        return reduce_payne_hanek(x);
    }
    let k = (x.hi * TWO_OVER_PI).round();
    let (a, b) = two_prod(-k, PI_2_PARTS[0]);
    let (c, d) = two_prod(-k, PI_2_PARTS[1]);
    let r = add(x, Dd { hi: a, lo: b });
    let r = add(r, Dd { hi: c, lo: d });
    let r = add_f64(r, -k * PI_2_PARTS[2]);
    (r, (k.rem_euclid(4.0)) as i64)
}

/// Series of `sin r` for `|r| ≤ π/4 (1 + 2⁻⁴⁰)`.
fn sin_series(r: Dd) -> Dd {
    let s = mul(r, r);
    let n = (SIN_DEGREE - 1) / 2;
    let coef = |i: usize| {
        let c = INV_FACT[2 * i + 1];
        if i % 2 == 0 {
            c
        } else {
            -c
        }
    };
    let mut h = coef(n);
    for i in (0..n).rev() {
        h = add(mul(h, s), coef(i));
    }
    mul(h, r)
}

/// Series of `cos r` for `|r| ≤ π/4 (1 + 2⁻⁴⁰)`.
fn cos_series(r: Dd) -> Dd {
    let s = mul(r, r);
    let n = COS_DEGREE / 2;
    let coef = |i: usize| {
        let c = INV_FACT[2 * i];
        if i % 2 == 0 {
            c
        } else {
            -c
        }
    };
    let mut h = coef(n);
    for i in (0..n).rev() {
        h = add(mul(h, s), coef(i));
    }
    h
}

/// `sin x`.
pub(super) fn sin(x: Dd) -> Dd {
    if !x.hi.is_finite() {
        return Dd::from_f64(f64::NAN);
    }
    let (r, q) = reduce(x);
    match q {
        0 => sin_series(r),
        1 => cos_series(r),
        2 => -sin_series(r),
        _ => -cos_series(r),
    }
}

/// `cos x`.
pub(super) fn cos(x: Dd) -> Dd {
    if !x.hi.is_finite() {
        return Dd::from_f64(f64::NAN);
    }
    let (r, q) = reduce(x);
    match q {
        0 => cos_series(r),
        1 => -sin_series(r),
        2 => -cos_series(r),
        _ => sin_series(r),
    }
}

/// `atan(n/d)` for `0 ≤ n ≤ d`, `d > 0`.
fn atan_first_octant(n: Dd, d: Dd) -> Dd {
    let j = (ATAN_STEPS * n.hi / d.hi).round().clamp(0.0, ATAN_STEPS);
    let c = j / ATAN_STEPS;
    let num = add(n, mul_f64(d, -c));
    let den = add(d, mul_f64(n, c));
    let t = div(num, den);
    let s = mul(t, t);
    let coef = |i: usize| {
        let c = INV_ODD[i];
        if i % 2 == 0 {
            c
        } else {
            -c
        }
    };
    let mut h = coef(ATAN_TERMS - 1);
    for i in (0..ATAN_TERMS - 1).rev() {
        h = add(mul(h, s), coef(i));
    }
    add(ATAN_TABLE[j as usize], mul(h, t))
}

fn greater(a: Dd, b: Dd) -> bool {
    a.hi > b.hi || (a.hi == b.hi && a.lo > b.lo)
}

fn abs(a: Dd) -> Dd {
    if a.hi < 0.0 {
        -a
    } else {
        a
    }
}

/// Largest of `|x_h|, |y_h|` outside `[2⁻⁵⁰⁰, 2⁵⁰⁰)`: both are scaled by the same power of
/// two, which leaves `atan2` unchanged, so that `d + c·n` cannot overflow and `n − c·d`
/// keeps its trailing words normal. proof: B13
const ATAN2_DIRECT: std::ops::Range<f64> =
    f64::from_bits((1023 - 500) << 52)..f64::from_bits((1023 + 500) << 52);

/// `(x, y)·2ᵏ` with the larger leading word in `[1, 2)` when it lies outside
/// [`ATAN2_DIRECT`] (nonnegative finite nonzero inputs); otherwise unchanged. proof: B13
fn scaled_to_unit(x: Dd, y: Dd) -> (Dd, Dd) {
    let m = x.hi.max(y.hi);
    if ATAN2_DIRECT.contains(&m) {
        return (x, y);
    }
    // m = 2ᵉ·(1 + f); a subnormal m is first brought up by 2⁶⁰⁰ (exactly).
    let (m, pre) = if m < f64::MIN_POSITIVE {
        (m * f64::from_bits((1023 + 600) << 52), 600)
    } else {
        (m, 0)
    };
    let e = ((m.to_bits() >> 52) & 0x7ff) as i32 - 1023 - pre;
    (x.ldexp(-e), y.ldexp(-e))
}

/// `atan2(y, x)` in (−π, π], with the IEEE conventions for signed zeros.
pub(super) fn atan2(y: Dd, x: Dd) -> Dd {
    if !y.hi.is_finite() || !x.hi.is_finite() {
        return Dd::from_f64(y.hi.atan2(x.hi));
    }
    let y_neg = y.hi.is_sign_negative();
    let x_neg = x.hi.is_sign_negative();
    if y.hi == 0.0 {
        let a = if x_neg { PI } else { Dd::from_f64(0.0) };
        return if y_neg { -a } else { a };
    }
    if x.hi == 0.0 {
        return if y_neg { -PI_2 } else { PI_2 };
    }
    let (ax, ay) = scaled_to_unit(abs(x), abs(y));
    let swap = greater(ay, ax);
    let mut a = if swap {
        add(PI_2, -atan_first_octant(ax, ay))
    } else {
        atan_first_octant(ay, ax)
    };
    if x_neg {
        a = add(PI, -a);
    }
    if y_neg {
        -a
    } else {
        a
    }
}

/// `acos x = atan2(√((1 − x)(1 + x)), x)` for `|x| ≤ 1`, NaN outside.
pub(super) fn acos(x: Dd) -> Dd {
    if x.hi.is_nan() || x.hi.abs() > 1.0 {
        return Dd::from_f64(f64::NAN);
    }
    let one_minus = add_f64(-x, 1.0);
    let one_plus = add_f64(x, 1.0);
    let p = mul(one_minus, one_plus);
    if p.hi < 0.0 {
        // |x| > 1 by less than the double-double spacing.
        return Dd::from_f64(f64::NAN);
    }
    let s = if p.hi == 0.0 {
        Dd::from_f64(0.0)
    } else {
        sqrt(p)
    };
    atan2(s, x)
}
