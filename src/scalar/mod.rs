//! Numbers: the generic [`Real`] trait and its backends, beneath it the [`Field`] and
//! [`Ring`] arithmetic they share with exact rationals ([`field`]).
//!
//! | backend | type | unit roundoff `u` |
//! |---|---|---|
//! | IEEE binary64 | `f64` | 2⁻⁵³ |
//! | double-double | [`Dd`] | 2⁻¹⁰⁴ (proofs B01–B15) |
//! | MPFR | [`Mpfr`] | 2⁻ᵖ |
//!
//! The trait has **no `PartialOrd`**: generic code that must decide something asks
//! [`crate::predicates`], which answers a [`Certified`] sign.

mod approx_impls;
mod certified;
mod dd;
pub mod dense;
pub mod dual;
pub mod exact;
pub mod exp_length;
mod f64_impl;
pub mod field;
pub mod interval;
mod mpfr;
mod nearest;
pub mod parse;
pub mod prec;

pub use certified::{Certified, Sign, Stage};
#[doc(hidden)]
pub use dd::div_jmp17 as dd_div_jmp17;
pub(crate) use dd::reduce_payne_hanek as dd_reduce_payne_hanek;
#[doc(hidden)]
pub use dd::sloppy_add as dd_sloppy_add;
pub use dd::Dd;
#[doc(hidden)]
pub use dd::{PI_2_FIXED as DD_PI_2_FIXED, TWO_OVER_PI_BITS as DD_TWO_OVER_PI_BITS};
pub use dual::Dual;
pub use field::{Field, Ring};
pub use interval::{Interval, IntervalBound};
pub use mpfr::{Mpfr, Precision, PrecisionError};
pub use nearest::nearest_f64;
pub use parse::{parse_rational, NumberError};

use std::fmt::Debug;
use std::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

/// A real-number backend: `f64`, [`Dd`] or [`Mpfr`]: a [`Field`] with `√`, `exp`, `ln` and
/// the trigonometric functions.
///
/// Precision travels with the value ([`Real::Ctx`]); there is no global precision state.
/// Mixing two precisions of [`Mpfr`] is a programming error and panics instead of silently
/// truncating. Generic code writes `a.clone() + &b` (free for `Copy` backends, one
/// allocation for MPFR).
///
/// Every operation is rounded as documented by the backend: correctly rounded for `f64`
/// arithmetic and all [`Mpfr`] operations, within the bounds of proofs B01–B15 for [`Dd`].
///
/// ```
/// use penner::scalar::{Real, Mpfr, Precision};
/// fn hypot<T: Real>(a: &T, b: &T) -> T { (a.clone() * a + &(b.clone() * b)).sqrt() }
/// assert_eq!(hypot(&3.0_f64, &4.0), 5.0);
/// let p = Precision::new(200).unwrap();
/// let h = hypot(&Mpfr::from_f64(3.0, p), &Mpfr::from_f64(4.0, p));
/// assert_eq!(h.approx_f64(), 5.0);
/// ```
pub trait Real:
    Field
    + Send
    + Sync
    + 'static
    + Neg<Output = Self>
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + for<'a> Add<&'a Self, Output = Self>
    + for<'a> Sub<&'a Self, Output = Self>
    + for<'a> Mul<&'a Self, Output = Self>
    + for<'a> Div<&'a Self, Output = Self>
    + for<'a> AddAssign<&'a Self>
    + for<'a> SubAssign<&'a Self>
    + for<'a> MulAssign<&'a Self>
{
    /// The precision context: `()` for `f64` and [`Dd`], [`Precision`] for [`Mpfr`].
    type Ctx: Copy + Debug + PartialEq + Send + Sync + 'static;

    /// The context (precision) this value carries.
    fn ctx(&self) -> Self::Ctx;

    /// A short name of the backend at this precision: `f64`, `dd`, `mpfr-256`.
    fn backend_name(ctx: Self::Ctx) -> String;

    /// Exact conversion of a finite `f64` (every backend holds at least 53 bits).
    fn from_f64(x: f64, ctx: Self::Ctx) -> Self;

    /// Conversion of an exact rational, correctly rounded for [`Mpfr`] and for `f64` (outside
    /// the subnormal range, where it may round twice), within
    /// u²(1 + u) relative for [`Dd`] in the normal range (proofs/B09).
    fn from_rational(q: &rug::Rational, ctx: Self::Ctx) -> Self;

    /// π rounded to the working precision.
    fn pi(ctx: Self::Ctx) -> Self;

    /// Square root.
    fn sqrt(&self) -> Self;
    /// Natural exponential.
    fn exp(&self) -> Self;
    /// Natural logarithm.
    fn ln(&self) -> Self;
    /// Sine.
    fn sin(&self) -> Self;
    /// Cosine.
    fn cos(&self) -> Self;
    /// Arctangent, in (−π/2, π/2).
    fn atan(&self) -> Self;
    /// Two-argument arctangent `atan2(self, x)` of the point (x, self), in (−π, π].
    fn atan2(&self, x: &Self) -> Self;
    /// Arccosine, in [0, π]; accurate near ±1.
    fn acos(&self) -> Self;
    /// Absolute value.
    fn abs(&self) -> Self;

    /// Nearest `f64`, for heuristics and display only: never for a decision.
    fn approx_f64(&self) -> f64;

    /// Unit roundoff `u` of the context: 2⁻⁵³, 2⁻¹⁰⁴ or 2⁻ᵖ.
    fn unit_roundoff(ctx: Self::Ctx) -> f64;

    /// Significand bits of the context: 53, 106 or p.
    fn precision_bits(ctx: Self::Ctx) -> u32;

    /// The constant `x` in this value's context.
    fn lit(&self, x: f64) -> Self {
        Self::from_f64(x, self.ctx())
    }

    /// Zero in this value's context.
    fn zero_like(&self) -> Self {
        self.lit(0.0)
    }

    /// One in this value's context.
    fn one_like(&self) -> Self {
        self.lit(1.0)
    }

    /// `self ← self · 2ᵏ` for any `k`: exact (no rounding) unless the result leaves the
    /// normal range of the backend. The default multiplies by `self.lit(2ʲ)` in steps of
    /// `|j| ≤ 1000`, so no exponent is clamped.
    ///
    /// ```
    /// use penner::scalar::{Dd, Real};
    /// let mut x = Dd::from_f64(3.0);
    /// x.ldexp_assign(-1);
    /// assert_eq!(x.approx_f64(), 1.5);
    /// ```
    fn ldexp_assign(&mut self, k: i32) {
        for step in pow2_steps(k) {
            let f = self.lit(pow2(step));
            *self *= &f;
        }
    }

    /// Exact conversion to a rational, or `None` when the value is not finite.
    fn to_rational(&self) -> Option<rug::Rational>;

    /// Whether a value is one number rather than an enclosure, so that with 53 significand
    /// bits [`Real::approx_f64`] returns it exactly (inside the binary64 exponent range).
    /// `false` for [`Interval`], whose `approx_f64` is a midpoint: f64 filters must not
    /// read it as the value.
    fn is_point() -> bool {
        true
    }
}

/// The exponents `j₁, j₂, …` with `Σ jᵢ = k` and `|jᵢ| ≤ 1000`, so that each `2^{jᵢ}` is a
/// normal `f64` and `x · 2ᵏ` is the product `x · 2^{j₁} · 2^{j₂} ⋯` (exact while every
/// partial product stays normal).
pub(crate) fn pow2_steps(k: i32) -> impl Iterator<Item = i32> {
    let n = k.unsigned_abs().div_ceil(1000).max(1);
    let sign = k.signum();
    let mut rest = k;
    (0..n).map(move |_| {
        let j = if rest.unsigned_abs() > 1000 {
            sign * 1000
        } else {
            rest
        };
        rest -= j;
        j
    })
}

/// `2ᵏ` as an `f64`, for `|k| ≤ 1000` (clamped to the normal exponent range; callers
/// with larger `|k|` go through [`pow2_steps`]).
#[inline]
pub(crate) fn pow2(k: i32) -> f64 {
    f64::from_bits(((i64::from(k.clamp(-1022, 1023)) + 1023) as u64) << 52)
}
