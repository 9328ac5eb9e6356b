//! A minimal MPFR interval with directed rounding, for the polynomial predicates of this
//! layer: every endpoint is rounded outward (`Round::Down` for lower, `Round::Up` for upper
//! endpoints), so the exact value of an expression evaluated on enclosed inputs lies in
//! the result (proof: B62).

use crate::scalar::Sign;
use rug::float::Round;
use rug::{Float, Rational};

/// A closed interval `[lo, hi]` of MPFR floats at one precision.
#[derive(Clone, Debug, PartialEq)]
pub struct Enclosure {
    /// Lower endpoint.
    pub lo: Float,
    /// Upper endpoint.
    pub hi: Float,
}

impl Enclosure {
    /// The point interval of a finite `f64` (exact at any precision ≥ 53 bits).
    pub fn from_f64(x: f64, prec: u32) -> Enclosure {
        let p = Float::with_val(prec, x);
        Enclosure {
            lo: p.clone(),
            hi: p,
        }
    }

    /// The tightest enclosure of a rational at `prec` bits.
    pub fn from_rational(q: &Rational, prec: u32) -> Enclosure {
        Enclosure {
            lo: Float::with_val_round(prec, q, Round::Down).0,
            hi: Float::with_val_round(prec, q, Round::Up).0,
        }
    }

    /// The enclosure of `e^{(u_i+u_j)/2} · ℓ` for finite `f64` inputs: the exponent is
    /// rounded down for the lower and up for the upper endpoint (MPFR's `exp` is correctly
    /// rounded in each direction, and monotone; halving is exact).
    pub fn scaled_length(length: f64, u_i: f64, u_j: f64, prec: u32) -> Enclosure {
        let (fi, fj) = (Float::with_val(prec, u_i), Float::with_val(prec, u_j));
        let s_lo = Float::with_val_round(prec, &fi + &fj, Round::Down).0 / 2u32;
        let s_hi = Float::with_val_round(prec, &fi + &fj, Round::Up).0 / 2u32;
        let e_lo = Float::with_val_round(prec, s_lo.exp_ref(), Round::Down).0;
        let e_hi = Float::with_val_round(prec, s_hi.exp_ref(), Round::Up).0;
        let l = Float::with_val(prec, length);
        Enclosure {
            lo: Float::with_val_round(prec, &e_lo * &l, Round::Down).0,
            hi: Float::with_val_round(prec, &e_hi * &l, Round::Up).0,
        }
    }

    fn prec(&self) -> u32 {
        self.lo.prec()
    }

    /// `self + o`, rounded outward.
    pub fn add(&self, o: &Enclosure) -> Enclosure {
        let p = self.prec();
        Enclosure {
            lo: Float::with_val_round(p, &self.lo + &o.lo, Round::Down).0,
            hi: Float::with_val_round(p, &self.hi + &o.hi, Round::Up).0,
        }
    }

    /// `self − o`, rounded outward.
    pub fn sub(&self, o: &Enclosure) -> Enclosure {
        let p = self.prec();
        Enclosure {
            lo: Float::with_val_round(p, &self.lo - &o.hi, Round::Down).0,
            hi: Float::with_val_round(p, &self.hi - &o.lo, Round::Up).0,
        }
    }

    /// `self · o`, rounded outward (all four endpoint products).
    pub fn mul(&self, o: &Enclosure) -> Enclosure {
        let p = self.prec();
        let pairs = [
            (&self.lo, &o.lo),
            (&self.lo, &o.hi),
            (&self.hi, &o.lo),
            (&self.hi, &o.hi),
        ];
        let mut lo: Option<Float> = None;
        let mut hi: Option<Float> = None;
        for (a, b) in pairs {
            let d = Float::with_val_round(p, a * b, Round::Down).0;
            let u = Float::with_val_round(p, a * b, Round::Up).0;
            if lo.as_ref().is_none_or(|l| d < *l) {
                lo = Some(d);
            }
            if hi.as_ref().is_none_or(|h| u > *h) {
                hi = Some(u);
            }
        }
        Enclosure {
            lo: lo.unwrap_or_else(|| Float::new(p)),
            hi: hi.unwrap_or_else(|| Float::new(p)),
        }
    }

    /// `self / o` for `o` strictly positive, rounded outward; `None` if `o` may be ≤ 0.
    pub fn div_positive(&self, o: &Enclosure) -> Option<Enclosure> {
        if o.lo.is_sign_negative() || o.lo.is_zero() {
            return None;
        }
        let p = self.prec();
        let lo_den = if self.lo.is_sign_negative() {
            &o.lo
        } else {
            &o.hi
        };
        let hi_den = if self.hi.is_sign_negative() {
            &o.hi
        } else {
            &o.lo
        };
        Some(Enclosure {
            lo: Float::with_val_round(p, &self.lo / lo_den, Round::Down).0,
            hi: Float::with_val_round(p, &self.hi / hi_den, Round::Up).0,
        })
    }

    /// `√self`, rounded outward; `None` if the interval may contain negative numbers.
    pub fn sqrt(&self) -> Option<Enclosure> {
        if self.lo.is_sign_negative() && !self.lo.is_zero() || self.lo.is_nan() {
            return None;
        }
        let p = self.prec();
        Some(Enclosure {
            lo: Float::with_val_round(p, self.lo.sqrt_ref(), Round::Down).0,
            hi: Float::with_val_round(p, self.hi.sqrt_ref(), Round::Up).0,
        })
    }

    /// `atan(self)`, rounded outward (atan is increasing).
    pub fn atan(&self) -> Enclosure {
        let p = self.prec();
        Enclosure {
            lo: Float::with_val_round(p, self.lo.atan_ref(), Round::Down).0,
            hi: Float::with_val_round(p, self.hi.atan_ref(), Round::Up).0,
        }
    }

    /// π enclosed at `prec` bits.
    pub fn pi(prec: u32) -> Enclosure {
        use rug::float::Constant;
        Enclosure {
            lo: Float::with_val_round(prec, Constant::Pi, Round::Down).0,
            hi: Float::with_val_round(prec, Constant::Pi, Round::Up).0,
        }
    }

    /// `self · 2^k`, exact.
    pub fn mul_pow2(&self, k: i32) -> Enclosure {
        Enclosure {
            lo: self.lo.clone() << k,
            hi: self.hi.clone() << k,
        }
    }

    /// Whether the two intervals share a point.
    pub fn overlaps(&self, o: &Enclosure) -> bool {
        self.lo <= o.hi && o.lo <= self.hi
    }

    /// Width `hi − lo` rounded to the nearest `f64`, for display.
    pub fn width_f64(&self) -> f64 {
        Float::with_val(self.prec(), &self.hi - &self.lo).to_f64()
    }

    /// The sign every point of the interval shares, or `None` when it straddles zero.
    /// A point interval at exactly zero has sign `Zero`. NaN endpoints give `None`.
    pub fn sign(&self) -> Option<Sign> {
        if self.lo.is_nan() || self.hi.is_nan() {
            None
        } else if self.lo > 0 {
            Some(Sign::Positive)
        } else if self.hi < 0 {
            Some(Sign::Negative)
        } else if self.lo.is_zero() && self.hi.is_zero() {
            Some(Sign::Zero)
        } else {
            None
        }
    }

    /// Whether the whole interval is strictly positive.
    pub fn is_positive(&self) -> bool {
        self.sign() == Some(Sign::Positive)
    }
}
