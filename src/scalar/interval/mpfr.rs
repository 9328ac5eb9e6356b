//! [`Mpfr`] bounds: every operation correctly rounded toward −∞ or +∞ by MPFR
//! (`Round::Down` / `Round::Up`), proofs/B20.

use super::{Interval, IntervalBound};
use crate::scalar::{Mpfr, Precision};
use rug::float::{Constant, Round, Special};
use rug::Float;
use std::cmp::Ordering;

fn dir(up: bool) -> Round {
    if up {
        Round::Up
    } else {
        Round::Down
    }
}

fn same(a: &Mpfr, b: &Mpfr) -> u32 {
    assert_eq!(
        a.0.prec(),
        b.0.prec(),
        "MPFR interval precision mismatch ({} vs {} bits): this is a bug in the caller",
        a.0.prec(),
        b.0.prec()
    );
    a.0.prec()
}

macro_rules! bin {
    ($down:ident, $up:ident, $op:tt) => {
        fn $down(&self, o: &Mpfr) -> Mpfr {
            let p = same(self, o);
            Mpfr(Float::with_val_round(p, &self.0 $op &o.0, Round::Down).0)
        }
        fn $up(&self, o: &Mpfr) -> Mpfr {
            let p = same(self, o);
            Mpfr(Float::with_val_round(p, &self.0 $op &o.0, Round::Up).0)
        }
    };
}

macro_rules! un {
    ($down:ident, $up:ident, $f:ident) => {
        fn $down(&self) -> Mpfr {
            Mpfr(Float::with_val_round(self.0.prec(), self.0.$f(), Round::Down).0)
        }
        fn $up(&self) -> Mpfr {
            Mpfr(Float::with_val_round(self.0.prec(), self.0.$f(), Round::Up).0)
        }
    };
}

fn pi_dir(ctx: Precision, up: bool) -> Mpfr {
    Mpfr(Float::with_val_round(ctx.bits(), Constant::Pi, dir(up)).0)
}

fn rational_dir(q: &rug::Rational, ctx: Precision, up: bool) -> Mpfr {
    Mpfr(Float::with_val_round(ctx.bits(), q, dir(up)).0)
}

// proof: B20
impl IntervalBound for Mpfr {
    bin!(add_down, add_up, +);
    bin!(sub_down, sub_up, -);
    bin!(mul_down, mul_up, *);
    bin!(div_down, div_up, /);
    un!(sqrt_down, sqrt_up, sqrt_ref);
    un!(exp_down, exp_up, exp_ref);
    un!(ln_down, ln_up, ln_ref);
    un!(sin_down, sin_up, sin_ref);
    un!(cos_down, cos_up, cos_ref);
    un!(atan_down, atan_up, atan_ref);
    un!(acos_down, acos_up, acos_ref);

    fn atan2_down(&self, x: &Mpfr) -> Mpfr {
        let p = same(self, x);
        Mpfr(Float::with_val_round(p, self.0.atan2_ref(&x.0), Round::Down).0)
    }
    fn atan2_up(&self, x: &Mpfr) -> Mpfr {
        let p = same(self, x);
        Mpfr(Float::with_val_round(p, self.0.atan2_ref(&x.0), Round::Up).0)
    }
    fn pi_down(ctx: Precision) -> Mpfr {
        pi_dir(ctx, false)
    }
    fn pi_up(ctx: Precision) -> Mpfr {
        pi_dir(ctx, true)
    }
    fn rational_down(q: &rug::Rational, ctx: Precision) -> Mpfr {
        rational_dir(q, ctx, false)
    }
    fn rational_up(q: &rug::Rational, ctx: Precision) -> Mpfr {
        rational_dir(q, ctx, true)
    }
    fn infinity(positive: bool, ctx: Precision) -> Mpfr {
        let s = if positive {
            Special::Infinity
        } else {
            Special::NegInfinity
        };
        Mpfr(Float::with_val(ctx.bits(), s))
    }
    fn nan(ctx: Precision) -> Mpfr {
        Mpfr(Float::with_val(ctx.bits(), Special::Nan))
    }
    fn is_nan(&self) -> bool {
        self.0.is_nan()
    }
    fn is_infinite(&self) -> bool {
        self.0.is_infinite()
    }
    fn cmp_bound(&self, o: &Mpfr) -> Option<Ordering> {
        self.0.partial_cmp(&o.0)
    }
    fn cmp_zero(&self) -> Option<Ordering> {
        self.0.cmp0()
    }
    fn floor_bound(&self) -> Mpfr {
        Mpfr(Float::with_val(self.0.prec(), self.0.floor_ref()))
    }
    fn ceil_bound(&self) -> Mpfr {
        Mpfr(Float::with_val(self.0.prec(), self.0.ceil_ref()))
    }
    fn to_f64_up(&self) -> f64 {
        self.0.to_f64_round(Round::Up)
    }
}

impl Interval<Mpfr> {
    /// The binary64 interval `[RD(lo), RU(hi)]`: each bound converted by MPFR with
    /// directed rounding, so it contains `self` (B20, B21); invalid when `self` is.
    ///
    /// ```
    /// use penner::scalar::{Interval, Mpfr, Precision, Real};
    /// let p = Precision::new(128).unwrap();
    /// let third = Interval::point(Mpfr::from_f64(1.0, p)) / Interval::point(Mpfr::from_f64(3.0, p));
    /// let f = third.to_f64_outward();
    /// // It contains 1/3 (compared exactly), and is one binary64 ulp wide.
    /// let q = rug::Rational::from((1, 3));
    /// let (lo, hi) = (rug::Rational::from_f64(*f.lo()).unwrap(), rug::Rational::from_f64(*f.hi()).unwrap());
    /// assert!(lo < q && q < hi);
    /// assert!(f.hi() - f.lo() <= f64::EPSILON / 2.0);
    /// ```
    pub fn to_f64_outward(&self) -> Interval<f64> {
        Interval::new(
            self.lo().0.to_f64_round(Round::Down),
            self.hi().0.to_f64_round(Round::Up),
        )
    }
}
