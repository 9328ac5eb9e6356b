//! Per-face enclosures with MPFR bounds rounded outward in place (no allocation per
//! operation): the corner directions behind the enclosed cone angles
//! ([`angle_sums`], proof: B33), the corner cotangents from squared lengths and an
//! enclosed area ([`cotans`], proof: B34), and the Hessian of `−2·Area` in the squared
//! lengths ([`area_hessian`], proof: B102).
//!
//! Every bound is computed by one correctly rounded MPFR operation toward −∞ (lower bounds)
//! or +∞ (upper bounds), so each [`Bounds`] encloses the exact value of its formula at every
//! point of the input enclosures (the inclusion property of B20, operation by operation).

pub mod angle_sums;
pub mod area_hessian;
pub mod cotans;

use crate::scalar::{Interval, Mpfr};
use rug::float::Round;
use rug::ops::AssignRound;
use rug::{Assign, Float};
use std::cmp::Ordering;

/// An enclosure `[lo, hi]` with `rug` bounds, updated in place. A NaN bound marks a
/// failed enclosure (every test of a sign then answers "unknown").
#[derive(Clone, Debug)]
pub(crate) struct Bounds {
    pub(crate) lo: Float,
    pub(crate) hi: Float,
}

/// The sign class of an enclosure for interval multiplication: every point `≥ 0`,
/// every point `≤ 0`, or both signs present.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Class {
    NonNegative,
    NonPositive,
    Mixed,
}

impl Bounds {
    /// `[0, 0]` at `bits` of precision.
    pub(crate) fn zero(bits: u32) -> Bounds {
        Bounds {
            lo: Float::new(bits),
            hi: Float::new(bits),
        }
    }

    /// Copies the bounds of `x` (same precision: exact).
    pub(crate) fn set(&mut self, x: &Interval<Mpfr>) {
        self.lo.assign_round(x.lo().as_float(), Round::Down);
        self.hi.assign_round(x.hi().as_float(), Round::Up);
    }

    /// The point `[v, v]` for a small integer `v` (exact).
    pub(crate) fn set_int(&mut self, v: i32) {
        self.lo.assign_round(v, Round::Down);
        self.hi.assign_round(v, Round::Up);
    }

    /// The [`Interval`] with these bounds (invalid when a bound is NaN or `lo > hi`).
    pub(crate) fn to_interval(&self) -> Interval<Mpfr> {
        Interval::new(Mpfr(self.lo.clone()), Mpfr(self.hi.clone()))
    }

    /// Every point is `> 0` (false for NaN bounds).
    pub(crate) fn positive(&self) -> bool {
        self.lo.cmp0() == Some(Ordering::Greater) && !self.hi.is_nan()
    }

    /// Every point is `< 0` (false for NaN bounds).
    pub(crate) fn negative(&self) -> bool {
        self.hi.cmp0() == Some(Ordering::Less) && !self.lo.is_nan()
    }

    /// `+1` or `−1` when every point has that strict sign, `None` otherwise.
    pub(crate) fn strict_sign(&self) -> Option<i8> {
        if self.positive() {
            Some(1)
        } else if self.negative() {
            Some(-1)
        } else {
            None
        }
    }

    fn class(&self) -> Option<Class> {
        let l = self.lo.cmp0()?;
        let h = self.hi.cmp0()?;
        Some(if l != Ordering::Less {
            Class::NonNegative
        } else if h != Ordering::Greater {
            Class::NonPositive
        } else {
            Class::Mixed
        })
    }

    fn set_nan(&mut self) {
        self.lo.assign(f64::NAN);
        self.hi.assign(f64::NAN);
    }

    /// `self = a + b`.
    pub(crate) fn add(&mut self, a: &Bounds, b: &Bounds) {
        self.lo.assign_round(&a.lo + &b.lo, Round::Down);
        self.hi.assign_round(&a.hi + &b.hi, Round::Up);
    }

    /// `self = a − b`.
    pub(crate) fn sub(&mut self, a: &Bounds, b: &Bounds) {
        self.lo.assign_round(&a.lo - &b.hi, Round::Down);
        self.hi.assign_round(&a.hi - &b.lo, Round::Up);
    }

    /// `self = −a` (exact).
    pub(crate) fn neg_of(&mut self, a: &Bounds) {
        self.lo.assign_round(-&a.hi, Round::Down);
        self.hi.assign_round(-&a.lo, Round::Up);
    }

    /// `self = a · b` by the sign cases of interval multiplication: two products unless
    /// both factors contain points of both signs (then four). proof: B20
    pub(crate) fn mul(&mut self, a: &Bounds, b: &Bounds) {
        use Class::{Mixed, NonNegative as P, NonPositive as N};
        let (Some(ca), Some(cb)) = (a.class(), b.class()) else {
            self.set_nan();
            return;
        };
        // (lower = x·y, upper = z·w) for the endpoint pairs of each case.
        let (l, u) = match (ca, cb) {
            (P, P) => ((&a.lo, &b.lo), (&a.hi, &b.hi)),
            (P, N) => ((&a.hi, &b.lo), (&a.lo, &b.hi)),
            (P, Mixed) => ((&a.hi, &b.lo), (&a.hi, &b.hi)),
            (N, P) => ((&a.lo, &b.hi), (&a.hi, &b.lo)),
            (N, N) => ((&a.hi, &b.hi), (&a.lo, &b.lo)),
            (N, Mixed) => ((&a.lo, &b.hi), (&a.lo, &b.lo)),
            (Mixed, P) => ((&a.lo, &b.hi), (&a.hi, &b.hi)),
            (Mixed, N) => ((&a.hi, &b.lo), (&a.lo, &b.lo)),
            (Mixed, Mixed) => {
                let bits = self.lo.prec();
                let lo1 = Float::with_val_round(bits, &a.lo * &b.hi, Round::Down).0;
                let lo2 = Float::with_val_round(bits, &a.hi * &b.lo, Round::Down).0;
                let hi1 = Float::with_val_round(bits, &a.lo * &b.lo, Round::Up).0;
                let hi2 = Float::with_val_round(bits, &a.hi * &b.hi, Round::Up).0;
                self.lo = if lo1 < lo2 { lo1 } else { lo2 };
                self.hi = if hi1 > hi2 { hi1 } else { hi2 };
                return;
            }
        };
        self.lo.assign_round(l.0 * l.1, Round::Down);
        self.hi.assign_round(u.0 * u.1, Round::Up);
    }

    /// `self = a / d` for a divisor `d` whose points are all `> 0`; NaN bounds otherwise.
    pub(crate) fn div_positive(&mut self, a: &Bounds, d: &Bounds) {
        if !d.positive() || a.lo.is_nan() || a.hi.is_nan() {
            self.set_nan();
            return;
        }
        // a/d increases with a; it decreases with d where a ≥ 0 and increases where a < 0.
        let dl = if a.lo.cmp0() == Some(Ordering::Less) {
            &d.lo
        } else {
            &d.hi
        };
        let du = if a.hi.cmp0() == Some(Ordering::Less) {
            &d.hi
        } else {
            &d.lo
        };
        self.lo.assign_round(&a.lo / dl, Round::Down);
        self.hi.assign_round(&a.hi / du, Round::Up);
    }

    /// `self = √a` for `a ≥ 0` (NaN bounds when `a` reaches below 0).
    pub(crate) fn sqrt_of(&mut self, a: &Bounds) {
        if !matches!(a.lo.cmp0(), Some(Ordering::Greater | Ordering::Equal)) {
            self.set_nan();
            return;
        }
        self.lo.assign_round(a.lo.sqrt_ref(), Round::Down);
        self.hi.assign_round(a.hi.sqrt_ref(), Round::Up);
    }

    /// `self ← self · 2^k` (exact in MPFR's exponent range).
    pub(crate) fn scale_pow2(&mut self, k: i32) {
        self.lo <<= k;
        self.hi <<= k;
    }
}

/// The quantities of one triangle with sides enclosed by `l = [l₀, l₁, l₂]` (corner `i`
/// opposite `l_i`) that both the corner directions and the cotangents use: the Heron
/// factors `e_i = l_{i+1} + l_{i+2} − l_i`, the perimeter `s = l₀ + l₁ + l₂`, and
/// `16·Area² = s·e₀·e₁·e₂` (docs/catalogue.md §1).
pub(crate) struct FaceHeron {
    pub(crate) l: [Bounds; 3],
    pub(crate) e: [Bounds; 3],
    pub(crate) s: Bounds,
    /// `16·Area²`.
    pub(crate) area16_sq: Bounds,
    t: Bounds,
    u: Bounds,
}

impl FaceHeron {
    pub(crate) fn new(bits: u32) -> FaceHeron {
        let z = Bounds::zero(bits);
        FaceHeron {
            l: [z.clone(), z.clone(), z.clone()],
            e: [z.clone(), z.clone(), z.clone()],
            s: z.clone(),
            area16_sq: z.clone(),
            t: z.clone(),
            u: z,
        }
    }

    /// Loads the three sides and forms `e_i`, `s`, `16·Area²`. Returns whether the face is
    /// certified a strict triangle (every side and every `e_i` enclosed as positive), i.e.
    /// every triangle of the enclosure is non-degenerate with corner angles in `(0, π)`.
    pub(crate) fn load(&mut self, l: [&Interval<Mpfr>; 3]) -> bool {
        for (b, x) in self.l.iter_mut().zip(l) {
            b.set(x);
        }
        for i in 0..3 {
            self.t.add(&self.l[(i + 1) % 3], &self.l[(i + 2) % 3]);
            self.e[i].sub(&self.t, &self.l[i]);
        }
        self.t.add(&self.l[0], &self.l[1]);
        self.s.add(&self.t, &self.l[2]);
        self.t.mul(&self.s, &self.e[0]);
        self.u.mul(&self.t, &self.e[1]);
        self.area16_sq.mul(&self.u, &self.e[2]);
        self.l.iter().all(Bounds::positive) && self.e.iter().all(Bounds::positive)
    }
}
