//! Positive lengths with the exponent kept apart: `ℓ = m·2ᵏ` with a binary64 significand
//! `m ∈ [1/2, 1)` and an `i32` exponent `k`, so that conformally scaled lengths
//! `e^{(u_i+u_j)/2}·ℓ` (docs/catalogue.md §4) stay representable for any `|u|` up to
//! [`MAX_LOG_SCALE`], far beyond binary64's range (`e^{±709.8}`).
//!
//! Arithmetic on these values is done by the caller on [`ExpLength::shifted`] images:
//! multiplying by `2^{−E}` for a common exponent `E` is exact while no image is subnormal,
//! and every homogeneous formula (the Delaunay polynomial, the flip lengths) commutes with
//! it exactly (proof: B67).
//!
//! ```
//! use penner::scalar::exp_length::ExpLength;
//! // e^{(800 + 800)/2}·1 = e^800 ≈ 2^1154.2: beyond f64, representable here.
//! let l = ExpLength::scaled(1.0, 800.0, 800.0).unwrap();
//! assert!((l.log2() - 800.0 / std::f64::consts::LN_2).abs() < 1e-9);
//! assert_eq!(l.shifted(l.exponent()), l.mantissa());
//! ```

use rug::float::Round;
use rug::{Float, Rational};

/// The largest `|u|` accepted by [`ExpLength::scaled`]: `2²⁰`. Then `(u_i + u_j)/2` is at
/// most `2²⁰` in magnitude and the exponent `k` at most `1.52·2²⁰`, and exact rationals of
/// shifted values within one quadrilateral have at most a few million bits.
pub const MAX_LOG_SCALE: f64 = 1_048_576.0;

/// A positive finite length `m·2ᵏ`, `m ∈ [1/2, 1)` (normalized).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExpLength {
    mantissa: f64,
    exponent: i32,
}

impl ExpLength {
    /// `x = m·2ᵏ` for a positive finite (normal or subnormal) `x`; `None` otherwise.
    pub fn from_f64(x: f64) -> Option<ExpLength> {
        if !(x > 0.0 && x.is_finite()) {
            return None;
        }
        let (m, k) = frexp(x);
        Some(ExpLength {
            mantissa: m,
            exponent: k,
        })
    }

    /// `m·2ᵏ` renormalized; `None` unless `m` is positive and finite and the exponent fits.
    pub fn new(m: f64, k: i64) -> Option<ExpLength> {
        let x = ExpLength::from_f64(m)?;
        let exponent = i32::try_from(i64::from(x.exponent) + k).ok()?;
        Some(ExpLength {
            mantissa: x.mantissa,
            exponent,
        })
    }

    /// `e^{(u_i+u_j)/2}·ℓ` rounded to 53 bits: the exponential and the product evaluated by
    /// MPFR with 64 guard bits, then rounded once (relative error at most `u + 2⁻¹¹⁵`).
    /// `None` unless `ℓ` is positive and finite and `|u_i|, |u_j| ≤` [`MAX_LOG_SCALE`].
    pub fn scaled(length: f64, u_i: f64, u_j: f64) -> Option<ExpLength> {
        if !(length > 0.0 && length.is_finite()) {
            return None;
        }
        if !(u_i.abs() <= MAX_LOG_SCALE && u_j.abs() <= MAX_LOG_SCALE) {
            return None;
        }
        // (u_i + u_j)/2 exactly: two doubles of magnitude ≤ 2²⁰ span at most 1095 bits.
        let mut half = Float::with_val(1200, u_i);
        half += u_j;
        half /= 2;
        // e^half correctly rounded to 117 bits, times ℓ rounded to 117 bits, then once to
        // 53 bits: relative error ≤ u + 2⁻¹¹⁵.
        let mut e = Float::with_val(117, half.exp_ref());
        e *= length;
        ExpLength::from_float(&e)
    }

    /// The nearest `ExpLength` to a positive finite MPFR value (rounded to 53 bits).
    pub fn from_float(x: &Float) -> Option<ExpLength> {
        if !(x.is_finite() && x.is_sign_positive() && !x.is_zero()) {
            return None;
        }
        let (m, k) = x.to_f64_exp_round(Round::Nearest);
        // Rounding may carry to m = 1.
        ExpLength::new(m, i64::from(k))
    }

    /// The exact value as an MPFR float of 53 bits.
    pub fn to_float(&self) -> Float {
        let mut f = Float::with_val(53, self.mantissa);
        f <<= self.exponent;
        f
    }

    /// The significand `m ∈ [1/2, 1)`.
    pub fn mantissa(&self) -> f64 {
        self.mantissa
    }

    /// The exponent `k` of `m·2ᵏ`.
    pub fn exponent(&self) -> i32 {
        self.exponent
    }

    /// `m·2^{k−e}` in binary64 (exact while the result is normal; `0` far below, `∞` far
    /// above).
    #[inline]
    pub fn shifted(&self, e: i32) -> f64 {
        let d = i64::from(self.exponent) - i64::from(e);
        ldexp(self.mantissa, d)
    }

    /// `log₂` of the value (approximate, for display and heuristics).
    pub fn log2(&self) -> f64 {
        self.mantissa.log2() + f64::from(self.exponent)
    }

    /// The exact value `m·2ᵏ` as a rational.
    pub fn to_rational(&self) -> Rational {
        let mut q = Rational::from_f64(self.mantissa).expect("finite mantissa");
        if self.exponent >= 0 {
            q <<= self.exponent.unsigned_abs();
        } else {
            q >>= self.exponent.unsigned_abs();
        }
        q
    }

    /// The exact value `m·2^{k−e}` as a rational (a power-of-two shift of
    /// [`ExpLength::to_rational`]).
    pub fn shifted_rational(&self, e: i32) -> Rational {
        let d = i64::from(self.exponent) - i64::from(e);
        let mut q = Rational::from_f64(self.mantissa).expect("finite mantissa");
        let s = d.unsigned_abs() as u32;
        if d >= 0 {
            q <<= s;
        } else {
            q >>= s;
        }
        q
    }
}

/// `x = m·2ᵏ` with `m ∈ [1/2, 1)` for positive finite `x` (subnormals included).
fn frexp(x: f64) -> (f64, i32) {
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    if biased == 0 {
        // Subnormal: scale up by 2⁶⁴ exactly first.
        let (m, k) = frexp(x * 18_446_744_073_709_551_616.0);
        return (m, k - 64);
    }
    let m = f64::from_bits((bits & !(0x7ff << 52)) | (1022 << 52));
    (m, biased - 1022)
}

/// `m·2ᵈ` for `m ∈ [1/2, 1)`: exact while the result is normal (`−1021 ≤ d ≤ 1024`).
#[inline]
fn ldexp(m: f64, d: i64) -> f64 {
    match d {
        // 2^d is a normal binary64 and m·2^d ∈ [2⁻¹⁰²², 2¹⁰²³).
        -1021..=1023 => m * f64::from_bits(((d + 1023) as u64) << 52),
        // m·2¹⁰²⁴ = (2m)·2¹⁰²³ ∈ [2¹⁰²³, 2¹⁰²⁴).
        1024 => (2.0 * m) * f64::from_bits(2046 << 52),
        d if d > 1024 => f64::INFINITY,
        // Subnormal or zero: rounded (callers decline such images).
        d => m * 2f64.powi(d.max(-1100) as i32),
    }
}
