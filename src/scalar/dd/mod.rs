//! [`Dd`]: double-double ("double-word") arithmetic, our own implementation of the
//! algorithms of Joldes, Muller and Popescu (TOMS 2017) with FMA, plus elementary functions
//! by argument reduction and polynomials in double-double.
//!
//! Bounds (u = 2⁻⁵³, so the double-double unit roundoff is 2⁻¹⁰⁴ = 4u²):
//!
//! | operation | algorithm | relative error | proof |
//! |---|---|---|---|
//! | `+`, `−` | JMP17 Alg. 6 (AccurateDWPlusDW) | 3u² + 13u³ | B04 |
//! | `×` | JMP17 Alg. 12 (DWTimesDW3) | 4u² | B06 |
//! | `÷` | JMP17 Alg. 18 (DWDivDW3, B07) + one residual correction | u² + 2⁹u³ | B17 |
//! | `√` | SQRTDWtoDW (Lefèvre et al. 2023) | 25/8 u² | B08 |
//! | `from_rational` | round twice to nearest | u² (1 + u) | B09 |
//! | `+ f64`, `× f64` | JMP17 Alg. 4, Alg. 9 | 2u² | B03, B05 |
//! | exp, ln, sin, cos, atan, atan2, acos | reduction + polynomial / Newton | measured ≤ 16u² | B10–B14 |
//! | reduction mod π/2 for `|x_h| ≥ 64` | Payne–Hanek, 1536 bits of 2/π | 2⁻²⁵² + u²(1 + 2⁻¹⁹)·\|r\| | B18 |

mod arith;
mod consts;
mod exp_ln;
mod reduce;
mod trig;

#[doc(hidden)]
pub use arith::{div_jmp17, sloppy_add};
pub(crate) use reduce::reduce_payne_hanek;
#[doc(hidden)]
pub use reduce::{PI_2_FIXED, TWO_OVER_PI_BITS};

use super::{nearest_f64, Real};
use rug::Float;
use std::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

/// A double-double number: the unevaluated sum `hi + lo` of two `f64` with
/// `|lo| ≤ ulp(hi)/2` (a normalized double-word, JMP17 Definition 1.1).
///
/// About 106 significand bits; the exponent range is that of `f64`. Below 2⁻⁹⁶⁸ the `lo`
/// word holds only multiples of 2⁻¹⁰⁷⁴, so results there carry an absolute error of a few
/// 2⁻¹⁰⁷⁴ on top of the relative bounds (each `Bnn` states it); every operation returns a
/// normalized pair (`hi = RN(hi + lo)`) and overflows to `(±∞, 0)`. Arithmetic follows JMP17 with FMA
/// (docs/catalogue.md §9, proofs B01–B09, division B17); the functions have measured bounds (proofs
/// B10–B14, reduction mod π/2 for large arguments B18).
///
/// ```
/// use penner::scalar::{Dd, Real};
/// let third = Dd::from_f64(1.0) / Dd::from_f64(3.0);
/// // 1/3 to about 32 digits: the residual 1 − 3·(1/3) is of order 2⁻¹⁰⁴.
/// let r = Dd::from_f64(1.0) - third * Dd::from_f64(3.0);
/// assert!(r.approx_f64().abs() < 1e-31);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Dd {
    /// Leading part, `RN(hi + lo)`.
    pub hi: f64,
    /// Trailing part, `|lo| ≤ ulp(hi)/2`.
    pub lo: f64,
}

impl Dd {
    /// The double-double holding one `f64` exactly.
    pub const fn from_f64(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }

    /// The sum `hi + lo` renormalized (Fast2Sum; exact when `|hi| ≥ |lo|`). proof: B01
    pub fn from_parts(hi: f64, lo: f64) -> Dd {
        let (h, l) = arith::two_sum(hi, lo);
        Dd { hi: h, lo: l }
    }

    /// The double-double nearest to an MPFR float, by rounding twice to nearest
    /// (`hi = RN(x)`, `lo = RN(x − hi)`), relative error ≤ u²(1 + u). proof: B09
    pub fn from_float(x: &Float) -> Dd {
        let hi = x.to_f64();
        if !hi.is_finite() {
            return Dd::from_f64(hi);
        }
        let rest = Float::with_val(x.prec().max(64) + 64, x - hi);
        // Renormalized (exact): `lo` may round to exactly ±ulp(hi)/2 next to an odd `hi`.
        Dd::from_parts(hi, rest.to_f64())
    }

    /// `self · 2ᵏ` for any `k`: each word is rounded once (exact while it stays normal),
    /// and a result below `2⁻⁹⁶⁸`, whose trailing word may have rounded on the subnormal
    /// grid, is renormalized by TwoSum (exact). So the result is normalized, within
    /// `2⁻¹⁰⁷⁴` (half a subnormal unit per word) of `self · 2ᵏ`, and `±∞` with a zero
    /// trailing word when the leading word overflows. proof: B10
    pub fn ldexp(self, k: i32) -> Dd {
        let (hi, lo) = if (-1022..=1023).contains(&k) {
            let f = pow2(k);
            (self.hi * f, self.lo * f)
        } else {
            (scale_word(self.hi, k), scale_word(self.lo, k))
        };
        if hi.abs() < LDEXP_RENORMALIZE_BELOW {
            Dd::from_parts(hi, lo)
        } else if hi.is_finite() {
            Dd { hi, lo }
        } else {
            Dd::from_f64(hi)
        }
    }

    /// `self + y` for an `f64` `y` (JMP17 Algorithm 4, DWPlusFP): relative error ≤ 2u².
    /// proof: B03
    pub fn add_f64(self, y: f64) -> Dd {
        arith::add_f64(self, y)
    }

    /// `self · y` for an `f64` `y` (JMP17 Algorithm 9, DWTimesFP3 with FMA): relative
    /// error ≤ 2u². proof: B05
    pub fn mul_f64(self, y: f64) -> Dd {
        arith::mul_f64(self, y)
    }

    /// `hi + lo` rounded to an `f64`.
    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }
}

fn pow2(k: i32) -> f64 {
    f64::from_bits(((i64::from(k.clamp(-1022, 1023)) + 1023) as u64) << 52)
}

/// Below this leading word a scaled trailing word may have been rounded to the subnormal
/// grid (`|lo| ≤ 2⁻⁵³|hi| < 2⁻¹⁰²¹`), so [`Dd::ldexp`] renormalizes. proof: B10
const LDEXP_RENORMALIZE_BELOW: f64 = f64::from_bits((1023 - 968) << 52);

/// `RN(w · 2ᵏ)` for any `k` (one rounding, also into the subnormals): `w = m·2ᵉ` with
/// `1 ≤ |m| < 2` exactly, then `m` times the power of two `2^{e+k}`, itself a subnormal
/// for `−1074 ≤ e + k < −1022`. proof: B10
#[cold]
fn scale_word(w: f64, k: i32) -> f64 {
    if w == 0.0 || !w.is_finite() {
        return w;
    }
    let (w, e0) = if w.abs() < f64::MIN_POSITIVE {
        (w * pow2(64), -64)
    } else {
        (w, 0)
    };
    let bits = w.to_bits();
    let e = ((bits >> 52) & 0x7ff) as i32 - 1023;
    // The significand with the exponent field of 2⁰: exact, sign kept.
    let m = f64::from_bits((bits & !(0x7ff << 52)) | (1023 << 52));
    let t = (e + e0).saturating_add(k.clamp(-4000, 4000));
    if t > 1023 {
        m * f64::INFINITY
    } else if t >= -1022 {
        m * pow2(t)
    } else if t >= -1074 {
        m * f64::from_bits(1u64 << (t + 1074))
    } else {
        // |m·2ᵗ| < 2⁻¹⁰⁷³: m·2^{max(t+1074, −60)} is exact, then one rounding by 2⁻¹⁰⁷⁴.
        (m * pow2((t + 1074).max(-60))) * f64::from_bits(1)
    }
}

impl Neg for Dd {
    type Output = Dd;
    #[inline]
    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl Add for Dd {
    type Output = Dd;
    /// JMP17 Algorithm 6, ≤ 3u² + 13u³. proof: B04
    #[inline]
    fn add(self, y: Dd) -> Dd {
        arith::add(self, y)
    }
}
impl Sub for Dd {
    type Output = Dd;
    /// JMP17 Algorithm 6 on `−y`, ≤ 3u² + 13u³. proof: B04
    #[inline]
    fn sub(self, y: Dd) -> Dd {
        arith::add(self, -y)
    }
}
impl Mul for Dd {
    type Output = Dd;
    /// JMP17 Algorithm 12, ≤ 4u². proof: B06
    #[inline]
    fn mul(self, y: Dd) -> Dd {
        arith::mul(self, y)
    }
}
impl Div for Dd {
    type Output = Dd;
    /// JMP17 Algorithm 18 and one residual correction, ≤ u² + 2⁹u³. proof: B17
    #[inline]
    fn div(self, y: Dd) -> Dd {
        arith::div(self, y)
    }
}

impl<'a> Add<&'a Dd> for Dd {
    type Output = Dd;
    #[inline]
    fn add(self, o: &'a Dd) -> Dd {
        arith::add(self, *o)
    }
}
impl<'a> Sub<&'a Dd> for Dd {
    type Output = Dd;
    #[inline]
    fn sub(self, o: &'a Dd) -> Dd {
        arith::add(self, -*o)
    }
}
impl<'a> Mul<&'a Dd> for Dd {
    type Output = Dd;
    #[inline]
    fn mul(self, o: &'a Dd) -> Dd {
        arith::mul(self, *o)
    }
}
impl<'a> Div<&'a Dd> for Dd {
    type Output = Dd;
    #[inline]
    fn div(self, o: &'a Dd) -> Dd {
        arith::div(self, *o)
    }
}
impl<'a> AddAssign<&'a Dd> for Dd {
    #[inline]
    fn add_assign(&mut self, o: &'a Dd) {
        *self = arith::add(*self, *o);
    }
}
impl<'a> SubAssign<&'a Dd> for Dd {
    #[inline]
    fn sub_assign(&mut self, o: &'a Dd) {
        *self = arith::add(*self, -*o);
    }
}
impl<'a> MulAssign<&'a Dd> for Dd {
    #[inline]
    fn mul_assign(&mut self, o: &'a Dd) {
        *self = arith::mul(*self, *o);
    }
}

impl Real for Dd {
    type Ctx = ();

    fn ctx(&self) {}

    fn backend_name((): ()) -> String {
        "dd".to_string()
    }

    fn from_f64(x: f64, (): ()) -> Dd {
        Dd::from_f64(x)
    }

    /// `hi = RN(q)`, `lo = RN(q − hi)`: relative error ≤ u²(1 + u) in the normal range.
    /// proof: B09
    fn from_rational(q: &rug::Rational, (): ()) -> Dd {
        let hi = nearest_f64(q);
        if !hi.is_finite() {
            return Dd::from_f64(hi);
        }
        let Some(h) = rug::Rational::from_f64(hi) else {
            return Dd::from_f64(hi);
        };
        let rest = rug::Rational::from(q - &h);
        // Renormalized (exact): `lo` may round to exactly ±ulp(hi)/2 next to an odd `hi`.
        Dd::from_parts(hi, nearest_f64(&rest))
    }

    fn pi((): ()) -> Dd {
        consts::PI
    }

    /// proof: B08
    #[inline]
    fn sqrt(&self) -> Dd {
        if self.hi > 0.0 && self.hi.is_finite() {
            arith::sqrt(*self)
        } else {
            // ±0 → ±0, +∞ → +∞, negative or NaN → NaN.
            Dd::from_f64(self.hi.sqrt())
        }
    }
    /// proof: B10
    fn exp(&self) -> Dd {
        exp_ln::exp(*self)
    }
    /// proof: B11
    fn ln(&self) -> Dd {
        exp_ln::ln(*self)
    }
    /// proof: B12
    fn sin(&self) -> Dd {
        trig::sin(*self)
    }
    /// proof: B12
    fn cos(&self) -> Dd {
        trig::cos(*self)
    }
    /// proof: B13
    fn atan(&self) -> Dd {
        trig::atan2(*self, Dd::from_f64(1.0))
    }
    /// proof: B13
    fn atan2(&self, x: &Dd) -> Dd {
        trig::atan2(*self, *x)
    }
    /// `atan2(√((1 − x)(1 + x)), x)`, accurate near ±1. proof: B14
    fn acos(&self) -> Dd {
        trig::acos(*self)
    }
    fn abs(&self) -> Dd {
        if self.hi < 0.0 {
            -*self
        } else {
            *self
        }
    }
    #[inline]
    fn approx_f64(&self) -> f64 {
        self.hi + self.lo
    }
    /// [`Dd::ldexp`]: exact while `lo` stays normal, normalized below. proof: B10
    #[inline]
    fn ldexp_assign(&mut self, k: i32) {
        *self = self.ldexp(k);
    }
    fn unit_roundoff((): ()) -> f64 {
        (-104.0_f64).exp2()
    }
    fn precision_bits((): ()) -> u32 {
        106
    }
    fn to_rational(&self) -> Option<rug::Rational> {
        Some(rug::Rational::from_f64(self.hi)? + rug::Rational::from_f64(self.lo)?)
    }
}
