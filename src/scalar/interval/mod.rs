//! [`Interval<B>`]: rigorous enclosures `[lo, hi]` of a real number, with bounds in `f64` or
//! [`Mpfr`](super::Mpfr).
//!
//! Every operation returns an interval that contains the exact result of the operation
//! applied to every point of its arguments (the *inclusion property*), proofs/B20. The
//! bounds are computed with directed rounding: MPFR's `Round::Down`/`Round::Up` for
//! [`Mpfr`](super::Mpfr) bounds (correctly rounded, so exact to the last bit), and for `f64`
//! bounds by widening the round-to-nearest result one ulp outward (arithmetic and `sqrt`,
//! proofs/B21) or [`F64_LIBM_ULPS`] ulps outward (libm functions, proofs/B22).
//!
//! `Interval<B>` implements [`Real`] with `Ctx = B::Ctx`, so every generic geometry
//! function evaluated on intervals yields a certified enclosure of its exact value.
//!
//! # Domain errors and invalid intervals
//!
//! An operation whose argument interval is not entirely inside the function's domain
//! (`sqrt` or `ln` of an interval reaching below 0 or, for `ln`, touching 0; division by
//! an interval containing 0; `acos` outside `[-1, 1]`; `atan2` of a box containing the
//! origin) returns the **invalid** interval with NaN bounds: [`Interval::is_valid`] is
//! `false` and [`Interval::sign`] is `None`, and every later operation stays invalid. No
//! operation ever returns a finite enclosure that misses the exact value; an invalid
//! result means "not certified at this precision" (more bits may help, or the exact value
//! is genuinely undefined).

mod f64;
mod mpfr;

pub(crate) use self::f64::next_down as next_down_f64;
pub(crate) use self::f64::next_up as next_up_f64;
pub use self::f64::F64_LIBM_ULPS;

use super::{Real, Sign};
use std::cmp::Ordering;
use std::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

/// A bound type for [`Interval`]: a [`Real`] with directed-rounding primitives.
///
/// Each `*_down` returns a value `≤` the exact result and each `*_up` a value `≥` it
/// (proofs/B20, B21, B22). Implemented for `f64` and [`Mpfr`](super::Mpfr).
pub trait IntervalBound: Real {
    /// `a + b` rounded down.
    fn add_down(&self, o: &Self) -> Self;
    /// `a + b` rounded up.
    fn add_up(&self, o: &Self) -> Self;
    /// `a − b` rounded down.
    fn sub_down(&self, o: &Self) -> Self;
    /// `a − b` rounded up.
    fn sub_up(&self, o: &Self) -> Self;
    /// `a · b` rounded down.
    fn mul_down(&self, o: &Self) -> Self;
    /// `a · b` rounded up.
    fn mul_up(&self, o: &Self) -> Self;
    /// `a / b` rounded down.
    fn div_down(&self, o: &Self) -> Self;
    /// `a / b` rounded up.
    fn div_up(&self, o: &Self) -> Self;
    /// `√a` rounded down (`a ≥ 0`).
    fn sqrt_down(&self) -> Self;
    /// `√a` rounded up (`a ≥ 0`).
    fn sqrt_up(&self) -> Self;
    /// `exp a` rounded down.
    fn exp_down(&self) -> Self;
    /// `exp a` rounded up.
    fn exp_up(&self) -> Self;
    /// `ln a` rounded down (`a > 0`).
    fn ln_down(&self) -> Self;
    /// `ln a` rounded up (`a > 0`).
    fn ln_up(&self) -> Self;
    /// `sin a` rounded down.
    fn sin_down(&self) -> Self;
    /// `sin a` rounded up.
    fn sin_up(&self) -> Self;
    /// `cos a` rounded down.
    fn cos_down(&self) -> Self;
    /// `cos a` rounded up.
    fn cos_up(&self) -> Self;
    /// `atan a` rounded down.
    fn atan_down(&self) -> Self;
    /// `atan a` rounded up.
    fn atan_up(&self) -> Self;
    /// `acos a` rounded down (`|a| ≤ 1`).
    fn acos_down(&self) -> Self;
    /// `acos a` rounded up (`|a| ≤ 1`).
    fn acos_up(&self) -> Self;
    /// `atan2(self, x)` rounded down (not both zero).
    fn atan2_down(&self, x: &Self) -> Self;
    /// `atan2(self, x)` rounded up (not both zero).
    fn atan2_up(&self, x: &Self) -> Self;
    /// π rounded down.
    fn pi_down(ctx: Self::Ctx) -> Self;
    /// π rounded up.
    fn pi_up(ctx: Self::Ctx) -> Self;
    /// `q` rounded down.
    fn rational_down(q: &rug::Rational, ctx: Self::Ctx) -> Self;
    /// `q` rounded up.
    fn rational_up(q: &rug::Rational, ctx: Self::Ctx) -> Self;
    /// `+∞` (or `−∞` when `positive` is false).
    fn infinity(positive: bool, ctx: Self::Ctx) -> Self;
    /// A NaN.
    fn nan(ctx: Self::Ctx) -> Self;
    /// Whether this is a NaN.
    fn is_nan(&self) -> bool;
    /// Whether this is `±∞`.
    fn is_infinite(&self) -> bool;
    /// Numerical order (`None` when a NaN is involved); `−0 == +0`.
    fn cmp_bound(&self, o: &Self) -> Option<Ordering>;
    /// The order against zero (`None` for a NaN; `−0` is zero), without building a zero.
    fn cmp_zero(&self) -> Option<Ordering> {
        self.cmp_bound(&self.zero_like())
    }
    /// `⌊a⌋` (exact).
    fn floor_bound(&self) -> Self;
    /// `⌈a⌉` (exact).
    fn ceil_bound(&self) -> Self;
    /// The smallest `f64 ≥ a`.
    fn to_f64_up(&self) -> f64;
}

/// A rigorous enclosure `[lo, hi]` of a real number, `lo ≤ hi`, bounds in `B`
/// (`f64` or [`Mpfr`](super::Mpfr)); see the [module docs](self) for the guarantees.
///
/// ```
/// use penner::scalar::{Interval, Mpfr, Precision, Real, Sign};
/// let p = Precision::new(128).unwrap();
/// let two = Interval::point(Mpfr::from_f64(2.0, p));
/// let r = two.sqrt();                      // encloses √2
/// let q = r.clone() * &r - &two;           // encloses 0, but is not the point 0
/// assert!(q.contains_rational(&rug::Rational::from(0)));
/// assert_eq!(q.sign(), None);
/// assert!(q.width_f64() < 1e-36);
/// assert_eq!(r.sign(), Some(Sign::Positive));
/// ```
#[derive(Clone, Debug)]
pub struct Interval<B> {
    lo: B,
    hi: B,
}

fn min_b<B: IntervalBound>(a: B, b: B) -> B {
    if b.cmp_bound(&a) == Some(Ordering::Less) {
        b
    } else {
        a
    }
}

fn max_b<B: IntervalBound>(a: B, b: B) -> B {
    if b.cmp_bound(&a) == Some(Ordering::Greater) {
        b
    } else {
        a
    }
}

/// The least of four bounds, NaN if any is NaN.
fn min4<B: IntervalBound>(v: [B; 4]) -> B {
    let [a, b, c, d] = v;
    if [&a, &b, &c, &d].iter().any(|x| x.is_nan()) {
        return B::nan(a.ctx());
    }
    min_b(min_b(a, b), min_b(c, d))
}

/// The greatest of four bounds, NaN if any is NaN.
fn max4<B: IntervalBound>(v: [B; 4]) -> B {
    let [a, b, c, d] = v;
    if [&a, &b, &c, &d].iter().any(|x| x.is_nan()) {
        return B::nan(a.ctx());
    }
    max_b(max_b(a, b), max_b(c, d))
}

fn is_zero<B: IntervalBound>(x: &B) -> bool {
    x.cmp_zero() == Some(Ordering::Equal)
}

fn lt<B: IntervalBound>(a: &B, b: &B) -> bool {
    a.cmp_bound(b) == Some(Ordering::Less)
}

fn le<B: IntervalBound>(a: &B, b: &B) -> bool {
    matches!(a.cmp_bound(b), Some(Ordering::Less | Ordering::Equal))
}

/// A product bound where `0 · ∞` counts as 0 (the exact product of a zero bound and any
/// finite point of the other interval).
fn prod<B: IntervalBound>(a: &B, b: &B, up: bool) -> B {
    if is_zero(a) || is_zero(b) {
        return a.zero_like();
    }
    if up {
        a.mul_up(b)
    } else {
        a.mul_down(b)
    }
}

impl<B: IntervalBound> Interval<B> {
    /// The point interval `[x, x]`.
    pub fn point(x: B) -> Interval<B> {
        Interval {
            lo: x.clone(),
            hi: x,
        }
    }

    /// The interval `[lo, hi]`; invalid (NaN bounds) unless `lo ≤ hi`.
    pub fn new(lo: B, hi: B) -> Interval<B> {
        if le(&lo, &hi) {
            Interval { lo, hi }
        } else {
            Interval::invalid(lo.ctx())
        }
    }

    /// The invalid interval (NaN bounds): the result of a domain error.
    pub fn invalid(ctx: B::Ctx) -> Interval<B> {
        Interval {
            lo: B::nan(ctx),
            hi: B::nan(ctx),
        }
    }

    /// The whole line `[−∞, +∞]`.
    pub fn entire(ctx: B::Ctx) -> Interval<B> {
        Interval {
            lo: B::infinity(false, ctx),
            hi: B::infinity(true, ctx),
        }
    }

    /// The smallest interval of `B` values enclosing the rational `q`.
    pub fn from_rational(q: &rug::Rational, ctx: B::Ctx) -> Interval<B> {
        Interval {
            lo: B::rational_down(q, ctx),
            hi: B::rational_up(q, ctx),
        }
    }

    /// Lower bound.
    pub fn lo(&self) -> &B {
        &self.lo
    }

    /// Upper bound.
    pub fn hi(&self) -> &B {
        &self.hi
    }

    /// Whether the bounds are numbers with `lo ≤ hi` (false after a domain error).
    pub fn is_valid(&self) -> bool {
        le(&self.lo, &self.hi)
    }

    /// The sign of every point of the interval: `Positive` when `lo > 0`, `Negative` when
    /// `hi < 0`, `Zero` when `lo = hi = 0`, otherwise (or when invalid) `None`.
    pub fn sign(&self) -> Option<Sign> {
        if !self.is_valid() {
            return None;
        }
        if self.lo.cmp_zero() == Some(Ordering::Greater) {
            Some(Sign::Positive)
        } else if self.hi.cmp_zero() == Some(Ordering::Less) {
            Some(Sign::Negative)
        } else if is_zero(&self.lo) && is_zero(&self.hi) {
            Some(Sign::Zero)
        } else {
            None
        }
    }

    /// Whether `lo ≤ q ≤ hi`, compared exactly (false when invalid).
    pub fn contains_rational(&self, q: &rug::Rational) -> bool {
        if !self.is_valid() {
            return false;
        }
        let below = match self.lo.to_rational() {
            Some(l) => l <= *q,
            None => self.lo.is_infinite() && lt(&self.lo, &self.lo.zero_like()),
        };
        let above = match self.hi.to_rational() {
            Some(h) => *q <= h,
            None => self.hi.is_infinite() && lt(&self.hi.zero_like(), &self.hi),
        };
        below && above
    }

    /// An upper bound on `hi − lo` as an `f64` (`+∞` for unbounded, NaN for invalid).
    pub fn width_f64(&self) -> f64 {
        if !self.is_valid() {
            return f64::NAN;
        }
        self.hi.sub_up(&self.lo).to_f64_up()
    }

    /// Whether `0` lies in the interval (false when invalid).
    pub fn contains_zero(&self) -> bool {
        self.is_valid()
            && matches!(self.lo.cmp_zero(), Some(Ordering::Less | Ordering::Equal))
            && matches!(
                self.hi.cmp_zero(),
                Some(Ordering::Greater | Ordering::Equal)
            )
    }

    fn ctx_b(&self) -> B::Ctx {
        self.lo.ctx()
    }

    // proof: B20
    fn add_i(&self, o: &Self) -> Self {
        Interval {
            lo: self.lo.add_down(&o.lo),
            hi: self.hi.add_up(&o.hi),
        }
    }

    fn sub_i(&self, o: &Self) -> Self {
        Interval {
            lo: self.lo.sub_down(&o.hi),
            hi: self.hi.sub_up(&o.lo),
        }
    }

    fn mul_i(&self, o: &Self) -> Self {
        if !self.is_valid() || !o.is_valid() {
            return Interval::invalid(self.ctx_b());
        }
        // [a,b]·[c,d] = [min, max] of the four endpoint products (proofs/B20).
        let (a, b, c, d) = (&self.lo, &self.hi, &o.lo, &o.hi);
        let nonnegative = |x: &B| matches!(x.cmp_zero(), Some(Ordering::Greater | Ordering::Equal));
        if nonnegative(a) && nonnegative(c) && !b.is_infinite() && !d.is_infinite() {
            // 0 ≤ a ≤ b and 0 ≤ c ≤ d (finite): ac and bd are the least and the greatest of
            // the four products, and rounding is monotone, so the same bounds as below
            // from two products instead of eight.
            return Interval {
                lo: prod(a, c, false),
                hi: prod(b, d, true),
            };
        }
        let lo = min4([
            prod(a, c, false),
            prod(a, d, false),
            prod(b, c, false),
            prod(b, d, false),
        ]);
        let hi = max4([
            prod(a, c, true),
            prod(a, d, true),
            prod(b, c, true),
            prod(b, d, true),
        ]);
        Interval { lo, hi }
    }

    fn div_i(&self, o: &Self) -> Self {
        if !self.is_valid() || !o.is_valid() || o.contains_zero() {
            return Interval::invalid(self.ctx_b());
        }
        // 0 ∉ [c,d]: the quotient is monotone in each argument, extremes at endpoints.
        let (a, b, c, d) = (&self.lo, &self.hi, &o.lo, &o.hi);
        let lo = min4([a.div_down(c), a.div_down(d), b.div_down(c), b.div_down(d)]);
        let hi = max4([a.div_up(c), a.div_up(d), b.div_up(c), b.div_up(d)]);
        Interval { lo, hi }
    }

    /// Whether the interval may contain a point `x` with `x/(2π) − turn ∈ ℤ`, decided with
    /// an enclosure of π (so it may answer `true` spuriously, never `false` wrongly).
    fn may_contain_critical(&self, turn: f64) -> bool {
        if self.lo.is_infinite() || self.hi.is_infinite() {
            return true;
        }
        let ctx = self.ctx_b();
        let two_pi = Interval::<B>::pi(ctx) * &Interval::point(B::from_f64(2.0, ctx));
        let shift = Interval::point(B::from_f64(turn, ctx));
        let t_lo = Interval::point(self.lo.clone()) / &two_pi - &shift;
        let t_hi = Interval::point(self.hi.clone()) / &two_pi - &shift;
        if !t_lo.is_valid() || !t_hi.is_valid() {
            return true;
        }
        le(&t_lo.lo.ceil_bound(), &t_hi.hi.floor_bound())
    }

    /// sin or cos over the interval: the extremes are at the endpoints unless a maximum
    /// (`turn_max`) or minimum (`turn_max + 1/2`) point lies inside (proofs/B20).
    fn periodic(&self, turn_max: f64, down: fn(&B) -> B, up: fn(&B) -> B) -> Self {
        let ctx = self.ctx_b();
        if !self.is_valid() {
            return Interval::invalid(ctx);
        }
        let one = B::from_f64(1.0, ctx);
        let m_one = B::from_f64(-1.0, ctx);
        let hi = if self.may_contain_critical(turn_max) {
            one.clone()
        } else {
            max_b(up(&self.lo), up(&self.hi))
        };
        let lo = if self.may_contain_critical(turn_max + 0.5) {
            m_one.clone()
        } else {
            min_b(down(&self.lo), down(&self.hi))
        };
        Interval {
            lo: max_b(lo, m_one),
            hi: min_b(hi, one),
        }
    }

    fn atan2_i(&self, x: &Self) -> Self {
        let ctx = self.ctx_b();
        if !self.is_valid() || !x.is_valid() || (self.contains_zero() && x.contains_zero()) {
            return Interval::invalid(ctx);
        }
        let z = self.lo.zero_like();
        if lt(&x.lo, &z) && le(&self.lo, &z) && le(&z, &self.hi) {
            // The box meets the branch cut {y = 0, x < 0}.
            if is_zero(&self.lo) && is_zero(&self.hi) {
                return Interval::pi(ctx);
            }
            if !is_zero(&self.lo) {
                // y crosses (or ends at) 0 from below: values near −π and π.
                return Interval {
                    lo: -B::pi_up(ctx),
                    hi: B::pi_up(ctx),
                };
            }
        }
        // θ is continuous on the box (closed upper half-plane when y.lo = 0) and monotone
        // along each edge, with no interior critical point: extremes at the corners.
        let ylo = if is_zero(&self.lo) {
            z
        } else {
            self.lo.clone()
        };
        let ys = [&ylo, &self.hi];
        let xs = [&x.lo, &x.hi];
        let mut lo: Option<B> = None;
        let mut hi: Option<B> = None;
        for y in ys {
            for xx in xs {
                let d = y.atan2_down(xx);
                let u = y.atan2_up(xx);
                lo = Some(match lo {
                    Some(l) => min_b(l, d),
                    None => d,
                });
                hi = Some(match hi {
                    Some(h) => max_b(h, u),
                    None => u,
                });
            }
        }
        match (lo, hi) {
            (Some(lo), Some(hi)) => Interval {
                lo: max_b(lo, -B::pi_up(ctx)),
                hi: min_b(hi, B::pi_up(ctx)),
            },
            _ => Interval::invalid(ctx),
        }
    }
}

impl<B: IntervalBound> Neg for Interval<B> {
    type Output = Interval<B>;
    fn neg(self) -> Interval<B> {
        Interval {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

macro_rules! interval_binop {
    ($tr:ident, $m:ident, $tra:ident, $ma:ident, $f:ident) => {
        impl<B: IntervalBound> $tr for Interval<B> {
            type Output = Interval<B>;
            fn $m(self, o: Interval<B>) -> Interval<B> {
                self.$f(&o)
            }
        }
        impl<'a, B: IntervalBound> $tr<&'a Interval<B>> for Interval<B> {
            type Output = Interval<B>;
            fn $m(self, o: &'a Interval<B>) -> Interval<B> {
                self.$f(o)
            }
        }
        impl<'a, B: IntervalBound> $tra<&'a Interval<B>> for Interval<B> {
            fn $ma(&mut self, o: &'a Interval<B>) {
                *self = self.$f(o);
            }
        }
    };
}
interval_binop!(Add, add, AddAssign, add_assign, add_i);
interval_binop!(Sub, sub, SubAssign, sub_assign, sub_i);
interval_binop!(Mul, mul, MulAssign, mul_assign, mul_i);

impl<B: IntervalBound> Div for Interval<B> {
    type Output = Interval<B>;
    fn div(self, o: Interval<B>) -> Interval<B> {
        self.div_i(&o)
    }
}
impl<'a, B: IntervalBound> Div<&'a Interval<B>> for Interval<B> {
    type Output = Interval<B>;
    fn div(self, o: &'a Interval<B>) -> Interval<B> {
        self.div_i(o)
    }
}

impl<B: IntervalBound> Real for Interval<B> {
    type Ctx = B::Ctx;

    fn ctx(&self) -> B::Ctx {
        self.lo.ctx()
    }
    /// An enclosure, not a number: its `approx_f64` is a midpoint.
    fn is_point() -> bool {
        false
    }
    fn backend_name(ctx: B::Ctx) -> String {
        format!("interval-{}", B::backend_name(ctx))
    }
    /// The point interval (exact).
    fn from_f64(x: f64, ctx: B::Ctx) -> Self {
        Interval::point(B::from_f64(x, ctx))
    }
    /// The enclosing interval [`Interval::from_rational`].
    fn from_rational(q: &rug::Rational, ctx: B::Ctx) -> Self {
        Interval::from_rational(q, ctx)
    }
    fn pi(ctx: B::Ctx) -> Self {
        Interval {
            lo: B::pi_down(ctx),
            hi: B::pi_up(ctx),
        }
    }
    fn sqrt(&self) -> Self {
        let z = self.lo.zero_like();
        if !self.is_valid() || lt(&self.lo, &z) {
            return Interval::invalid(self.ctx_b());
        }
        Interval {
            lo: self.lo.sqrt_down(),
            hi: self.hi.sqrt_up(),
        }
    }
    fn exp(&self) -> Self {
        let z = self.lo.zero_like();
        Interval {
            lo: max_b(self.lo.exp_down(), z),
            hi: self.hi.exp_up(),
        }
    }
    fn ln(&self) -> Self {
        let z = self.lo.zero_like();
        if !self.is_valid() || !lt(&z, &self.lo) {
            return Interval::invalid(self.ctx_b());
        }
        Interval {
            lo: self.lo.ln_down(),
            hi: self.hi.ln_up(),
        }
    }
    fn sin(&self) -> Self {
        // Maxima at x = 2π(k + 1/4), minima at 2π(k + 3/4).
        self.periodic(0.25, B::sin_down, B::sin_up)
    }
    fn cos(&self) -> Self {
        // Maxima at x = 2πk, minima at 2π(k + 1/2).
        self.periodic(0.0, B::cos_down, B::cos_up)
    }
    fn atan(&self) -> Self {
        let ctx = self.ctx_b();
        let half_pi = B::pi_up(ctx) / &B::from_f64(2.0, ctx);
        Interval {
            lo: max_b(self.lo.atan_down(), -half_pi.clone()),
            hi: min_b(self.hi.atan_up(), half_pi),
        }
    }
    fn atan2(&self, x: &Self) -> Self {
        self.atan2_i(x)
    }
    fn acos(&self) -> Self {
        let ctx = self.ctx_b();
        let one = B::from_f64(1.0, ctx);
        if !self.is_valid() || lt(&self.lo, &-one.clone()) || lt(&one, &self.hi) {
            return Interval::invalid(ctx);
        }
        // acos is decreasing on [−1, 1].
        Interval {
            lo: max_b(self.hi.acos_down(), self.lo.zero_like()),
            hi: min_b(self.lo.acos_up(), B::pi_up(ctx)),
        }
    }
    fn abs(&self) -> Self {
        let z = self.lo.zero_like();
        if !self.is_valid() {
            return self.clone();
        }
        if le(&z, &self.lo) {
            self.clone()
        } else if le(&self.hi, &z) {
            -self.clone()
        } else {
            Interval {
                hi: max_b(-self.lo.clone(), self.hi.clone()),
                lo: z,
            }
        }
    }
    /// The midpoint, for display only.
    fn approx_f64(&self) -> f64 {
        let (l, h) = (self.lo.approx_f64(), self.hi.approx_f64());
        if l == h {
            l
        } else {
            l / 2.0 + h / 2.0
        }
    }
    fn unit_roundoff(ctx: B::Ctx) -> f64 {
        B::unit_roundoff(ctx)
    }
    fn precision_bits(ctx: B::Ctx) -> u32 {
        B::precision_bits(ctx)
    }
    /// The exact value of a point interval `[x, x]`; `None` for any wider interval (the
    /// interval does not know which of its points is meant).
    fn to_rational(&self) -> Option<rug::Rational> {
        if self.lo.cmp_bound(&self.hi) == Some(Ordering::Equal) {
            self.lo.to_rational()
        } else {
            None
        }
    }
}
