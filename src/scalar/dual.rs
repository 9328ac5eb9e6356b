//! [`Dual<T>`]: forward-mode automatic differentiation over any [`Real`].
//!
//! A dual number `v + d·ε` with `ε² = 0` carries a value and a directional derivative;
//! every operation applies the chain rule, so a generic function `f::<Dual<T>>` evaluated at
//! `Dual::variable(x)` returns `f(x)` and `f′(x)` to the working precision of `T`
//! (proofs/B27). Over [`Interval`](super::Interval) bounds the derivative part is a
//! certified enclosure.
//!
//! ```
//! use penner::scalar::{Dual, Real};
//! fn f<T: Real>(x: &T) -> T { x.clone() * &x.sin() }
//! let y = f(&Dual::variable(2.0_f64));
//! assert!((y.d - (2.0_f64.sin() + 2.0 * 2.0_f64.cos())).abs() < 1e-15);
//! ```

use super::Real;
use std::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

/// `v + d·ε` with `ε² = 0`: a value and its derivative along one direction.
#[derive(Clone, Debug, PartialEq)]
pub struct Dual<T> {
    /// The value.
    pub v: T,
    /// The derivative.
    pub d: T,
}

impl<T: Real> Dual<T> {
    /// `v + d·ε`.
    pub fn new(v: T, d: T) -> Dual<T> {
        Dual { v, d }
    }

    /// The independent variable at `x`: derivative 1.
    pub fn variable(x: T) -> Dual<T> {
        let d = x.one_like();
        Dual { v: x, d }
    }

    /// A constant: derivative 0.
    pub fn constant(x: T) -> Dual<T> {
        let d = x.zero_like();
        Dual { v: x, d }
    }

    /// The chain rule for a unary function with value `fv` and derivative `dfv` at `v`.
    fn chain(&self, fv: T, dfv: &T) -> Dual<T> {
        Dual {
            v: fv,
            d: self.d.clone() * dfv,
        }
    }

    fn mul_d(&self, o: &Dual<T>) -> Dual<T> {
        // (v + dε)(w + eε) = vw + (dw + ve)ε
        Dual {
            v: self.v.clone() * &o.v,
            d: self.d.clone() * &o.v + &(self.v.clone() * &o.d),
        }
    }

    fn div_d(&self, o: &Dual<T>) -> Dual<T> {
        // (v/w)′ = (d − (v/w)·e) / w
        let q = self.v.clone() / &o.v;
        let d = (self.d.clone() - &(q.clone() * &o.d)) / &o.v;
        Dual { v: q, d }
    }
}

impl<T: Real> Neg for Dual<T> {
    type Output = Dual<T>;
    fn neg(self) -> Dual<T> {
        Dual {
            v: -self.v,
            d: -self.d,
        }
    }
}

impl<T: Real> Add for Dual<T> {
    type Output = Dual<T>;
    fn add(self, o: Dual<T>) -> Dual<T> {
        self + &o
    }
}
impl<'a, T: Real> Add<&'a Dual<T>> for Dual<T> {
    type Output = Dual<T>;
    fn add(self, o: &'a Dual<T>) -> Dual<T> {
        Dual {
            v: self.v + &o.v,
            d: self.d + &o.d,
        }
    }
}
impl<'a, T: Real> AddAssign<&'a Dual<T>> for Dual<T> {
    fn add_assign(&mut self, o: &'a Dual<T>) {
        self.v += &o.v;
        self.d += &o.d;
    }
}
impl<T: Real> Sub for Dual<T> {
    type Output = Dual<T>;
    fn sub(self, o: Dual<T>) -> Dual<T> {
        self - &o
    }
}
impl<'a, T: Real> Sub<&'a Dual<T>> for Dual<T> {
    type Output = Dual<T>;
    fn sub(self, o: &'a Dual<T>) -> Dual<T> {
        Dual {
            v: self.v - &o.v,
            d: self.d - &o.d,
        }
    }
}
impl<'a, T: Real> SubAssign<&'a Dual<T>> for Dual<T> {
    fn sub_assign(&mut self, o: &'a Dual<T>) {
        self.v -= &o.v;
        self.d -= &o.d;
    }
}
impl<T: Real> Mul for Dual<T> {
    type Output = Dual<T>;
    fn mul(self, o: Dual<T>) -> Dual<T> {
        self.mul_d(&o)
    }
}
impl<'a, T: Real> Mul<&'a Dual<T>> for Dual<T> {
    type Output = Dual<T>;
    fn mul(self, o: &'a Dual<T>) -> Dual<T> {
        self.mul_d(o)
    }
}
impl<'a, T: Real> MulAssign<&'a Dual<T>> for Dual<T> {
    fn mul_assign(&mut self, o: &'a Dual<T>) {
        *self = self.mul_d(o);
    }
}
impl<T: Real> Div for Dual<T> {
    type Output = Dual<T>;
    fn div(self, o: Dual<T>) -> Dual<T> {
        self.div_d(&o)
    }
}
impl<'a, T: Real> Div<&'a Dual<T>> for Dual<T> {
    type Output = Dual<T>;
    fn div(self, o: &'a Dual<T>) -> Dual<T> {
        self.div_d(o)
    }
}

// proof: B27
impl<T: Real> Real for Dual<T> {
    type Ctx = T::Ctx;

    fn ctx(&self) -> T::Ctx {
        self.v.ctx()
    }
    fn backend_name(ctx: T::Ctx) -> String {
        format!("dual-{}", T::backend_name(ctx))
    }
    /// A constant (derivative 0).
    fn from_f64(x: f64, ctx: T::Ctx) -> Self {
        Dual::constant(T::from_f64(x, ctx))
    }
    /// A constant (derivative 0).
    fn from_rational(q: &rug::Rational, ctx: T::Ctx) -> Self {
        Dual::constant(T::from_rational(q, ctx))
    }
    fn pi(ctx: T::Ctx) -> Self {
        Dual::constant(T::pi(ctx))
    }
    /// `(√v)′ = d / (2√v)`.
    fn sqrt(&self) -> Self {
        let s = self.v.sqrt();
        let two_s = s.clone() + &s;
        Dual {
            d: self.d.clone() / &two_s,
            v: s,
        }
    }
    /// `(exp v)′ = d·exp v`.
    fn exp(&self) -> Self {
        let e = self.v.exp();
        self.chain(e.clone(), &e)
    }
    /// `(ln v)′ = d / v`.
    fn ln(&self) -> Self {
        Dual {
            v: self.v.ln(),
            d: self.d.clone() / &self.v,
        }
    }
    /// `(sin v)′ = d·cos v`.
    fn sin(&self) -> Self {
        self.chain(self.v.sin(), &self.v.cos())
    }
    /// `(cos v)′ = −d·sin v`.
    fn cos(&self) -> Self {
        self.chain(self.v.cos(), &-self.v.sin())
    }
    /// `(atan v)′ = d / (1 + v²)`.
    fn atan(&self) -> Self {
        let den = self.v.one_like() + &(self.v.clone() * &self.v);
        Dual {
            v: self.v.atan(),
            d: self.d.clone() / &den,
        }
    }
    /// `atan2(y, x)′ = (x·dy − y·dx) / (x² + y²)`.
    fn atan2(&self, x: &Self) -> Self {
        let (y, dy) = (&self.v, &self.d);
        let num = x.v.clone() * dy - &(y.clone() * &x.d);
        let den = x.v.clone() * &x.v + &(y.clone() * y);
        Dual {
            v: y.atan2(&x.v),
            d: num / &den,
        }
    }
    /// `(acos v)′ = −d / √((1 − v)(1 + v))` (the factored form keeps accuracy near ±1).
    fn acos(&self) -> Self {
        let one = self.v.one_like();
        let s = ((one.clone() - &self.v) * &(one + &self.v)).sqrt();
        Dual {
            v: self.v.acos(),
            d: -(self.d.clone() / &s),
        }
    }
    /// `|v|′ = d·|v|/v` (undefined at `v = 0`, where it is NaN; no branch on the value).
    fn abs(&self) -> Self {
        let a = self.v.abs();
        Dual {
            d: self.d.clone() * &(a.clone() / &self.v),
            v: a,
        }
    }
    /// The value part, for display only.
    fn approx_f64(&self) -> f64 {
        self.v.approx_f64()
    }
    fn unit_roundoff(ctx: T::Ctx) -> f64 {
        T::unit_roundoff(ctx)
    }
    fn precision_bits(ctx: T::Ctx) -> u32 {
        T::precision_bits(ctx)
    }
    /// The exact value part (the derivative is dropped).
    fn to_rational(&self) -> Option<rug::Rational> {
        self.v.to_rational()
    }
}
