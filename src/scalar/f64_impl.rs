//! `f64` as a [`Real`]: IEEE binary64, arithmetic correctly rounded, functions from the
//! platform libm (a few ulp).

use super::Real;

impl Real for f64 {
    type Ctx = ();

    #[inline]
    fn ctx(&self) {}

    fn backend_name((): ()) -> String {
        "f64".to_string()
    }

    #[inline]
    fn from_f64(x: f64, (): ()) -> f64 {
        x
    }

    /// The binary64 nearest to `q`, ties to even, subnormals included
    /// ([`super::nearest_f64`]).
    fn from_rational(q: &rug::Rational, (): ()) -> f64 {
        super::nearest_f64(q)
    }

    #[inline]
    fn pi((): ()) -> f64 {
        std::f64::consts::PI
    }

    #[inline]
    fn sqrt(&self) -> f64 {
        f64::sqrt(*self)
    }
    #[inline]
    fn exp(&self) -> f64 {
        f64::exp(*self)
    }
    #[inline]
    fn ln(&self) -> f64 {
        f64::ln(*self)
    }
    #[inline]
    fn sin(&self) -> f64 {
        f64::sin(*self)
    }
    #[inline]
    fn cos(&self) -> f64 {
        f64::cos(*self)
    }
    #[inline]
    fn atan(&self) -> f64 {
        f64::atan(*self)
    }
    #[inline]
    fn atan2(&self, x: &f64) -> f64 {
        f64::atan2(*self, *x)
    }
    #[inline]
    fn acos(&self) -> f64 {
        // atan2(√((1−x)(1+x)), x): accurate near ±1, unlike acos of a rounded argument.
        f64::atan2(((1.0 - self) * (1.0 + self)).sqrt(), *self)
    }
    #[inline]
    fn abs(&self) -> f64 {
        f64::abs(*self)
    }
    #[inline]
    fn approx_f64(&self) -> f64 {
        *self
    }
    #[inline]
    fn unit_roundoff((): ()) -> f64 {
        f64::EPSILON / 2.0
    }
    #[inline]
    fn precision_bits((): ()) -> u32 {
        53
    }
    #[inline]
    fn ldexp_assign(&mut self, k: i32) {
        for step in super::pow2_steps(k) {
            *self *= super::pow2(step);
        }
    }
    fn to_rational(&self) -> Option<rug::Rational> {
        rug::Rational::from_f64(*self)
    }
}
