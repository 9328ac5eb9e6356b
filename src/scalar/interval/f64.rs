//! `f64` bounds: round to nearest, then move outward.
//!
//! Arithmetic and `sqrt` (proofs/B21): IEEE 754 returns the correctly rounded result `r`;
//! the exact error term (two-sum, or an FMA residual) tells on which side of `r` the exact
//! value lies, so the bound is `r` itself on the exact side and its neighbour on the other.
//! Where the error term might be inexact (overflow, results near the underflow range) both
//! bounds move one ulp outward, which is always valid for a correctly rounded `r`.
//!
//! libm functions (proofs/B22): the platform's `exp, ln, sin, cos, atan, atan2, acos` are
//! not correctly rounded; their results are moved [`F64_LIBM_ULPS`] ulps outward. This rests
//! on the assumption that the libm error is below that allowance, checked against MPFR by
//! `b22_f64_libm_error_within_allowance`.

use super::IntervalBound;
use std::cmp::Ordering;

/// Outward widening, in ulps, of every libm result used as an `f64` interval bound
/// (proofs/B22). glibc documents at most 1–2 ulp for these functions in binary64.
pub const F64_LIBM_ULPS: u32 = 4;

/// Magnitudes where FMA residuals and two-sum errors are exact (no underflow, no
/// overflow): 2⁻⁹⁰⁰ ≤ |x| ≤ 2⁹⁰⁰ for the operands and the result (proofs/B21).
const SAFE_LO: f64 = f64::from_bits((1023 - 900) << 52);
const SAFE_HI: f64 = f64::from_bits((1023 + 900) << 52);

fn safe(x: f64) -> bool {
    let a = x.abs();
    a == 0.0 || (SAFE_LO..=SAFE_HI).contains(&a)
}

/// The next `f64` above `x` (`+∞` stays, NaN stays).
pub(crate) fn next_up(x: f64) -> f64 {
    if x.is_nan() || x == f64::INFINITY {
        return x;
    }
    if x == 0.0 {
        return f64::from_bits(1);
    }
    let b = x.to_bits();
    if x > 0.0 {
        f64::from_bits(b + 1)
    } else {
        f64::from_bits(b - 1)
    }
}

/// The next `f64` below `x` (`−∞` stays, NaN stays).
pub(crate) fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

fn widen(r: f64, up: bool, k: u32) -> f64 {
    let mut v = r;
    for _ in 0..k {
        v = if up { next_up(v) } else { next_down(v) };
    }
    v
}

/// The bound on the requested side of the exact value `r + e`, given the sign of the
/// exact error `e` (or `None` if it is not known exactly).
fn directed(r: f64, err: Option<Ordering>, up: bool) -> f64 {
    match (err, up) {
        (Some(Ordering::Equal), _)
        | (Some(Ordering::Greater), false)
        | (Some(Ordering::Less), true) => r,
        (Some(Ordering::Greater), true) => next_up(r),
        (Some(Ordering::Less), false) => next_down(r),
        (None, _) => widen(r, up, 1),
    }
}

fn sign0(x: f64) -> Option<Ordering> {
    x.partial_cmp(&0.0)
}

// proof: B21
fn add_dir(a: f64, b: f64, up: bool) -> f64 {
    let s = a + b;
    if !s.is_finite() {
        return widen(s, up, 1);
    }
    // Knuth's two-sum: e = a + b − s exactly (no overflow since s is finite).
    let bb = s - a;
    let aa = s - bb;
    let e = (a - aa) + (b - bb);
    if e.is_finite() {
        directed(s, sign0(e), up)
    } else {
        widen(s, up, 1)
    }
}

fn mul_dir(a: f64, b: f64, up: bool) -> f64 {
    let p = a * b;
    if safe(a) && safe(b) && safe(p) && p.is_finite() {
        // a·b − p is exact in the safe range (the FMA residual of a correctly rounded product).
        directed(p, sign0(a.mul_add(b, -p)), up)
    } else {
        widen(p, up, 1)
    }
}

fn div_dir(a: f64, b: f64, up: bool) -> f64 {
    let q = a / b;
    if safe(a) && safe(b) && safe(q) && q.is_finite() && b != 0.0 {
        // a − q·b is exact in the safe range; a/b − q = (a − q·b)/b.
        let rem = (-q).mul_add(b, a);
        let s = match (sign0(rem), sign0(b)) {
            (Some(r), Some(Ordering::Greater)) => Some(r),
            (Some(r), Some(Ordering::Less)) => Some(r.reverse()),
            _ => None,
        };
        directed(q, s, up)
    } else {
        widen(q, up, 1)
    }
}

fn sqrt_dir(a: f64, up: bool) -> f64 {
    let r = a.sqrt();
    if safe(a) && safe(r) && r.is_finite() {
        // a − r² is exact in the safe range.
        directed(r, sign0((-r).mul_add(r, a)), up)
    } else {
        widen(r, up, 1)
    }
}

// proof: B22
fn libm(r: f64, up: bool) -> f64 {
    widen(r, up, F64_LIBM_ULPS)
}

impl IntervalBound for f64 {
    fn add_down(&self, o: &f64) -> f64 {
        add_dir(*self, *o, false)
    }
    fn add_up(&self, o: &f64) -> f64 {
        add_dir(*self, *o, true)
    }
    fn sub_down(&self, o: &f64) -> f64 {
        add_dir(*self, -*o, false)
    }
    fn sub_up(&self, o: &f64) -> f64 {
        add_dir(*self, -*o, true)
    }
    fn mul_down(&self, o: &f64) -> f64 {
        mul_dir(*self, *o, false)
    }
    fn mul_up(&self, o: &f64) -> f64 {
        mul_dir(*self, *o, true)
    }
    fn div_down(&self, o: &f64) -> f64 {
        div_dir(*self, *o, false)
    }
    fn div_up(&self, o: &f64) -> f64 {
        div_dir(*self, *o, true)
    }
    fn sqrt_down(&self) -> f64 {
        sqrt_dir(*self, false)
    }
    fn sqrt_up(&self) -> f64 {
        sqrt_dir(*self, true)
    }
    fn exp_down(&self) -> f64 {
        libm(self.exp(), false)
    }
    fn exp_up(&self) -> f64 {
        libm(self.exp(), true)
    }
    fn ln_down(&self) -> f64 {
        libm(self.ln(), false)
    }
    fn ln_up(&self) -> f64 {
        libm(self.ln(), true)
    }
    fn sin_down(&self) -> f64 {
        libm(self.sin(), false)
    }
    fn sin_up(&self) -> f64 {
        libm(self.sin(), true)
    }
    fn cos_down(&self) -> f64 {
        libm(self.cos(), false)
    }
    fn cos_up(&self) -> f64 {
        libm(self.cos(), true)
    }
    fn atan_down(&self) -> f64 {
        libm(self.atan(), false)
    }
    fn atan_up(&self) -> f64 {
        libm(self.atan(), true)
    }
    fn acos_down(&self) -> f64 {
        libm(f64::acos(*self), false)
    }
    fn acos_up(&self) -> f64 {
        libm(f64::acos(*self), true)
    }
    fn atan2_down(&self, x: &f64) -> f64 {
        libm(f64::atan2(*self, *x), false)
    }
    fn atan2_up(&self, x: &f64) -> f64 {
        libm(f64::atan2(*self, *x), true)
    }
    fn pi_down((): ()) -> f64 {
        // The binary64 nearest π lies below π (π − PI ≈ 1.2e-16): checked by
        // `b21_f64_pi_enclosure`.
        std::f64::consts::PI
    }
    fn pi_up((): ()) -> f64 {
        next_up(std::f64::consts::PI)
    }
    fn rational_down(q: &rug::Rational, (): ()) -> f64 {
        // Round down to 53 bits with an unbounded exponent, then down into binary64's range.
        rug::Float::with_val_round(53, q, rug::float::Round::Down)
            .0
            .to_f64_round(rug::float::Round::Down)
    }
    fn rational_up(q: &rug::Rational, (): ()) -> f64 {
        rug::Float::with_val_round(53, q, rug::float::Round::Up)
            .0
            .to_f64_round(rug::float::Round::Up)
    }
    fn infinity(positive: bool, (): ()) -> f64 {
        if positive {
            f64::INFINITY
        } else {
            f64::NEG_INFINITY
        }
    }
    fn nan((): ()) -> f64 {
        f64::NAN
    }
    fn is_nan(&self) -> bool {
        f64::is_nan(*self)
    }
    fn is_infinite(&self) -> bool {
        f64::is_infinite(*self)
    }
    fn cmp_bound(&self, o: &f64) -> Option<Ordering> {
        self.partial_cmp(o)
    }
    fn cmp_zero(&self) -> Option<Ordering> {
        self.partial_cmp(&0.0)
    }
    fn floor_bound(&self) -> f64 {
        self.floor()
    }
    fn ceil_bound(&self) -> f64 {
        self.ceil()
    }
    fn to_f64_up(&self) -> f64 {
        *self
    }
}
