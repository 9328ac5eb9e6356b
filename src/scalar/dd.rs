//! [`Dd`]: double-double arithmetic (placeholder: to be replaced by the JMP17 implementation).

use super::Real;
use std::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

/// A double-double number `hi + lo` with `|lo| ≤ ulp(hi)/2`.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Dd {
    /// Leading part.
    pub hi: f64,
    /// Trailing part.
    pub lo: f64,
}

fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let ap = s - b;
    let bp = s - ap;
    (s, (a - ap) + (b - bp))
}
fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

impl Dd {
    /// A double-double from one f64.
    pub const fn from_f64(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }
}

impl Neg for Dd {
    type Output = Dd;
    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}
impl Add for Dd {
    type Output = Dd;
    fn add(self, y: Dd) -> Dd {
        let (sh, sl) = two_sum(self.hi, y.hi);
        let (th, tl) = two_sum(self.lo, y.lo);
        let c = sl + th;
        let (vh, vl) = fast_two_sum(sh, c);
        let w = tl + vl;
        let (zh, zl) = fast_two_sum(vh, w);
        Dd { hi: zh, lo: zl }
    }
}
impl Sub for Dd {
    type Output = Dd;
    fn sub(self, y: Dd) -> Dd {
        self + (-y)
    }
}
impl Mul for Dd {
    type Output = Dd;
    fn mul(self, y: Dd) -> Dd {
        let (ch, cl1) = two_prod(self.hi, y.hi);
        let tl0 = self.lo * y.lo;
        let tl1 = self.hi.mul_add(y.lo, tl0);
        let cl2 = self.lo.mul_add(y.hi, tl1);
        let cl3 = cl1 + cl2;
        let (zh, zl) = fast_two_sum(ch, cl3);
        Dd { hi: zh, lo: zl }
    }
}
impl Div for Dd {
    type Output = Dd;
    fn div(self, y: Dd) -> Dd {
        let th = 1.0 / y.hi;
        let rh = 1.0 - y.hi * th;
        let rl = -(y.lo * th);
        let (eh, el) = fast_two_sum(rh, rl);
        let d = Dd { hi: eh, lo: el } * Dd::from_f64(th);
        let m = d + Dd::from_f64(th);
        self * m
    }
}
macro_rules! by_ref {
    ($tr:ident, $m:ident, $tra:ident, $ma:ident) => {
        impl<'a> $tr<&'a Dd> for Dd {
            type Output = Dd;
            fn $m(self, o: &'a Dd) -> Dd {
                $tr::$m(self, *o)
            }
        }
        impl<'a> $tra<&'a Dd> for Dd {
            fn $ma(&mut self, o: &'a Dd) {
                *self = $tr::$m(*self, *o);
            }
        }
    };
}
by_ref!(Add, add, AddAssign, add_assign);
by_ref!(Sub, sub, SubAssign, sub_assign);
by_ref!(Mul, mul, MulAssign, mul_assign);
impl<'a> Div<&'a Dd> for Dd {
    type Output = Dd;
    fn div(self, o: &'a Dd) -> Dd {
        self / *o
    }
}

fn via_f64(x: &Dd, f: impl Fn(f64) -> f64) -> Dd {
    Dd::from_f64(f(x.hi))
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
    fn from_rational(q: &rug::Rational, (): ()) -> Dd {
        let hi = q.to_f64();
        let rest = q.clone() - rug::Rational::from_f64(hi).unwrap_or_default();
        let (h, l) = fast_two_sum(hi, rest.to_f64());
        Dd { hi: h, lo: l }
    }
    fn pi((): ()) -> Dd {
        Dd {
            hi: std::f64::consts::PI,
            lo: 1.2246467991473532e-16,
        }
    }
    fn sqrt(&self) -> Dd {
        if self.hi <= 0.0 {
            return Dd::from_f64(self.hi.sqrt());
        }
        let s = self.hi.sqrt();
        let (p, e) = two_prod(s, s);
        let r = ((self.hi - p) - e + self.lo) / (2.0 * s);
        let (h, l) = fast_two_sum(s, r);
        Dd { hi: h, lo: l }
    }
    fn exp(&self) -> Dd {
        via_f64(self, f64::exp)
    }
    fn ln(&self) -> Dd {
        via_f64(self, f64::ln)
    }
    fn sin(&self) -> Dd {
        via_f64(self, f64::sin)
    }
    fn cos(&self) -> Dd {
        via_f64(self, f64::cos)
    }
    fn atan(&self) -> Dd {
        via_f64(self, f64::atan)
    }
    fn atan2(&self, x: &Dd) -> Dd {
        Dd::from_f64(self.hi.atan2(x.hi))
    }
    fn acos(&self) -> Dd {
        via_f64(self, f64::acos)
    }
    fn abs(&self) -> Dd {
        if self.hi < 0.0 {
            -*self
        } else {
            *self
        }
    }
    fn approx_f64(&self) -> f64 {
        self.hi + self.lo
    }
    fn unit_roundoff((): ()) -> f64 {
        (-106.0_f64).exp2()
    }
    fn precision_bits((): ()) -> u32 {
        106
    }
    fn to_rational(&self) -> Option<rug::Rational> {
        Some(rug::Rational::from_f64(self.hi)? + rug::Rational::from_f64(self.lo)?)
    }
}
