//! [`Mpfr`]: a correctly rounded MPFR float (rug) that carries its precision and refuses to
//! mix precisions.

use super::Real;
use rug::float::Constant;
use rug::Float;
use std::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

/// Smallest accepted MPFR precision: every backend holds an `f64` exactly.
pub const MIN_PRECISION_BITS: u32 = 53;
/// Largest accepted MPFR precision. Beyond this a request is treated as absurd input
/// (a million-bit float per edge would exhaust memory on real meshes).
pub const MAX_PRECISION_BITS: u32 = 1 << 16;

/// A validated MPFR precision in bits, in `[53, 65536]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Precision(u32);

/// A precision outside `[53, 65536]` bits.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("precision of {bits} bits is outside the supported range [{MIN_PRECISION_BITS}, {MAX_PRECISION_BITS}]")]
pub struct PrecisionError {
    /// The rejected request.
    pub bits: u64,
}

impl Precision {
    /// A precision of `bits` bits, or an error outside `[53, 65536]`.
    pub fn new(bits: u64) -> Result<Precision, PrecisionError> {
        if (u64::from(MIN_PRECISION_BITS)..=u64::from(MAX_PRECISION_BITS)).contains(&bits) {
            Ok(Precision(bits as u32))
        } else {
            Err(PrecisionError { bits })
        }
    }

    /// The number of significand bits.
    pub fn bits(self) -> u32 {
        self.0
    }
}

/// An MPFR float with its precision. Every operation is correctly rounded to nearest.
///
/// Binary operations require both operands at the same precision and panic otherwise:
/// precision mismatch is a programming error, never silently truncated.
///
/// ```
/// use penner::scalar::{Mpfr, Precision, Real};
/// let p = Precision::new(128).unwrap();
/// let third = Mpfr::from_f64(1.0, p) / Mpfr::from_f64(3.0, p);
/// assert!((third.approx_f64() - 1.0 / 3.0).abs() < 1e-16);
/// ```
#[derive(Debug, PartialEq)]
pub struct Mpfr(pub Float);

impl Clone for Mpfr {
    fn clone(&self) -> Mpfr {
        Mpfr(self.0.clone())
    }
    /// Reuses the allocation of `self` when the precisions agree (no allocation in loops
    /// that copy into scratch values).
    fn clone_from(&mut self, source: &Mpfr) {
        self.0.clone_from(&source.0);
    }
}

impl Mpfr {
    /// The underlying rug float.
    pub fn as_float(&self) -> &Float {
        &self.0
    }

    /// The precision of this value.
    pub fn precision(&self) -> Precision {
        Precision(self.0.prec())
    }

    fn check(&self, o: &Mpfr) {
        assert_eq!(
            self.0.prec(),
            o.0.prec(),
            "MPFR precision mismatch ({} vs {} bits): this is a bug in the caller",
            self.0.prec(),
            o.0.prec()
        );
    }

    fn unary(&self, f: impl FnOnce(&mut Float)) -> Mpfr {
        let mut x = self.0.clone();
        f(&mut x);
        Mpfr(x)
    }
}

impl Neg for Mpfr {
    type Output = Mpfr;
    fn neg(self) -> Mpfr {
        Mpfr(-self.0)
    }
}

macro_rules! binop {
    ($tr:ident, $m:ident, $tra:ident, $ma:ident) => {
        impl $tr for Mpfr {
            type Output = Mpfr;
            fn $m(self, o: Mpfr) -> Mpfr {
                self.check(&o);
                Mpfr($tr::$m(self.0, &o.0))
            }
        }
        impl<'a> $tr<&'a Mpfr> for Mpfr {
            type Output = Mpfr;
            fn $m(self, o: &'a Mpfr) -> Mpfr {
                self.check(o);
                Mpfr($tr::$m(self.0, &o.0))
            }
        }
        impl<'a> $tra<&'a Mpfr> for Mpfr {
            fn $ma(&mut self, o: &'a Mpfr) {
                self.check(o);
                $tra::$ma(&mut self.0, &o.0);
            }
        }
    };
}
binop!(Add, add, AddAssign, add_assign);
binop!(Sub, sub, SubAssign, sub_assign);
binop!(Mul, mul, MulAssign, mul_assign);

impl Div for Mpfr {
    type Output = Mpfr;
    fn div(self, o: Mpfr) -> Mpfr {
        self.check(&o);
        Mpfr(self.0 / &o.0)
    }
}
impl<'a> Div<&'a Mpfr> for Mpfr {
    type Output = Mpfr;
    fn div(self, o: &'a Mpfr) -> Mpfr {
        self.check(o);
        Mpfr(self.0 / &o.0)
    }
}

impl Real for Mpfr {
    type Ctx = Precision;

    fn ctx(&self) -> Precision {
        self.precision()
    }
    fn backend_name(ctx: Precision) -> String {
        format!("mpfr-{}", ctx.0)
    }
    fn from_f64(x: f64, ctx: Precision) -> Mpfr {
        Mpfr(Float::with_val(ctx.0, x))
    }
    fn from_rational(q: &rug::Rational, ctx: Precision) -> Mpfr {
        Mpfr(Float::with_val(ctx.0, q))
    }
    fn pi(ctx: Precision) -> Mpfr {
        Mpfr(Float::with_val(ctx.0, Constant::Pi))
    }
    fn sqrt(&self) -> Mpfr {
        self.unary(Float::sqrt_mut)
    }
    fn exp(&self) -> Mpfr {
        self.unary(Float::exp_mut)
    }
    fn ln(&self) -> Mpfr {
        self.unary(Float::ln_mut)
    }
    fn sin(&self) -> Mpfr {
        self.unary(Float::sin_mut)
    }
    fn cos(&self) -> Mpfr {
        self.unary(Float::cos_mut)
    }
    fn atan(&self) -> Mpfr {
        self.unary(Float::atan_mut)
    }
    fn atan2(&self, x: &Mpfr) -> Mpfr {
        self.check(x);
        self.unary(|y| y.atan2_mut(&x.0))
    }
    fn acos(&self) -> Mpfr {
        self.unary(Float::acos_mut)
    }
    fn abs(&self) -> Mpfr {
        self.unary(Float::abs_mut)
    }
    fn approx_f64(&self) -> f64 {
        self.0.to_f64()
    }
    /// `mpfr_mul_2si`: exact, no allocation.
    fn ldexp_assign(&mut self, k: i32) {
        self.0 <<= k;
    }
    fn unit_roundoff(ctx: Precision) -> f64 {
        (-(f64::from(ctx.0))).exp2()
    }
    fn precision_bits(ctx: Precision) -> u32 {
        ctx.0
    }
    fn to_rational(&self) -> Option<rug::Rational> {
        self.0.to_rational()
    }
}
