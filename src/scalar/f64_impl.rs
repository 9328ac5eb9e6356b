//! `f64` as a [`Real`]: IEEE binary64, arithmetic correctly rounded, functions from the
//! platform libm (a few ulp).

use super::Real;

impl Real for f64 {
    type Ctx = ();

    fn ctx(&self) {}

    fn backend_name((): ()) -> String {
        "f64".to_string()
    }

    fn from_f64(x: f64, (): ()) -> f64 {
        x
    }

    fn from_rational(q: &rug::Rational, (): ()) -> f64 {
        // `Rational::to_f64` truncates; a 53-bit MPFR float rounds to nearest, and its
        // conversion to f64 is then exact outside the subnormal range.
        rug::Float::with_val(53, q).to_f64()
    }

    fn pi((): ()) -> f64 {
        std::f64::consts::PI
    }

    fn sqrt(&self) -> f64 {
        f64::sqrt(*self)
    }
    fn exp(&self) -> f64 {
        f64::exp(*self)
    }
    fn ln(&self) -> f64 {
        f64::ln(*self)
    }
    fn sin(&self) -> f64 {
        f64::sin(*self)
    }
    fn cos(&self) -> f64 {
        f64::cos(*self)
    }
    fn atan(&self) -> f64 {
        f64::atan(*self)
    }
    fn atan2(&self, x: &f64) -> f64 {
        f64::atan2(*self, *x)
    }
    fn acos(&self) -> f64 {
        // atan2(√((1−x)(1+x)), x): accurate near ±1, unlike acos of a rounded argument.
        f64::atan2(((1.0 - self) * (1.0 + self)).sqrt(), *self)
    }
    fn abs(&self) -> f64 {
        f64::abs(*self)
    }
    fn approx_f64(&self) -> f64 {
        *self
    }
    fn unit_roundoff((): ()) -> f64 {
        f64::EPSILON / 2.0
    }
    fn precision_bits((): ()) -> u32 {
        53
    }
    fn to_rational(&self) -> Option<rug::Rational> {
        rug::Rational::from_f64(*self)
    }
}
