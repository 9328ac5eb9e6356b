//! Rigorous reduction `x = k·π/2 + t`, `|t| ≲ π/4`, of an exact binary number with the
//! relative accuracy of `t` guaranteed (proofs/B52, "Reduction").
//!
//! `π/2` is enclosed at `w` bits, `w = q + max(0, e) + 16` for `x = m·2ᵉ`, and `t` is
//! enclosed by `[x − k·(π/2)↑, x − k·(π/2)↓]` with directed rounding. When the enclosure is
//! wider than `2^(−q−8)·|t|` (x within `2^(e−w+q)` of a multiple of π/2) `w` grows and
//! the reduction is repeated: `x` is rational and π/2 irrational, so `t ≠ 0` unless
//! `k = 0`, and the loop ends — at the latest at [`MAX_REDUCTION_BITS`].

use rug::float::{Constant, Round};
use rug::Float;
use std::cell::RefCell;

/// Largest precision used for π in the reduction. An argument `|x| ≥ 2^(2²⁰ − q)` or one
/// closer to a multiple of π/2 than this precision resolves is not reduced (the caller
/// answers NaN or an unbounded enclosure).
pub(crate) const MAX_REDUCTION_BITS: u32 = 1 << 20;

/// `x = k·π/2 + t` with `t` enclosed by `[lo, hi]` (same sign, relative width below
/// `2^(−q−8)`), `k` taken modulo 2.
#[derive(Debug)]
pub(crate) struct Reduced {
    /// Whether `k` is odd.
    pub odd: bool,
    /// Lower bound of `t`.
    pub lo: Float,
    /// Upper bound of `t`.
    pub hi: Float,
}

/// Reduces the exact finite nonzero `x` for a working precision of `q` bits, or `None`
/// when `x` is not finite, is zero, or needs more than [`MAX_REDUCTION_BITS`].
pub(crate) fn reduce(x: &Float, q: u32) -> Option<Reduced> {
    if !x.is_finite() || x.is_zero() {
        return None;
    }
    let e = x.get_exp()?;
    let mut w = (q + 16).saturating_add(e.max(0) as u32);
    while w <= MAX_REDUCTION_BITS {
        if let Some(r) = with_half_pi(w, |hp_lo, hp_hi| reduce_at(x, q, hp_lo, hp_hi, w)) {
            return Some(r);
        }
        w = w.saturating_mul(2);
    }
    None
}

/// Precisions up to which [`with_half_pi`] keeps π/2 (per thread, at most
/// [`HALF_PI_CACHED`] precisions).
const HALF_PI_CACHE_MAX_BITS: u32 = 8192;

/// Number of precisions [`with_half_pi`] keeps per thread.
const HALF_PI_CACHED: usize = 32;

/// `f(π/2↓, π/2↑)` with π rounded down and up at `w` bits (then halved, exactly), kept per
/// thread for the precisions the reduction meets again and again (the same numbers as
/// rounding π afresh).
fn with_half_pi<R>(w: u32, f: impl FnOnce(&Float, &Float) -> R) -> R {
    let make = || {
        (
            Float::with_val_round(w, Constant::Pi, Round::Down).0 >> 1u32,
            Float::with_val_round(w, Constant::Pi, Round::Up).0 >> 1u32,
        )
    };
    thread_local! {
        static CACHE: RefCell<Vec<(u32, Float, Float)>> = const { RefCell::new(Vec::new()) };
    }
    if w > HALF_PI_CACHE_MAX_BITS {
        let (lo, hi) = make();
        return f(&lo, &hi);
    }
    CACHE.with(|c| {
        let mut c = c.borrow_mut();
        let i = match c.iter().position(|e| e.0 == w) {
            Some(i) => i,
            None if c.len() < HALF_PI_CACHED => {
                let (lo, hi) = make();
                c.push((w, lo, hi));
                c.len() - 1
            }
            None => {
                let (lo, hi) = make();
                return f(&lo, &hi);
            }
        };
        f(&c[i].1, &c[i].2)
    })
}

/// One attempt of [`reduce`] with `π/2` enclosed by `[hp_lo, hp_hi]` at `w` bits: the
/// reduction when the enclosure of `t` is tight, `None` when `w` must grow.
fn reduce_at(x: &Float, q: u32, hp_lo: &Float, hp_hi: &Float, w: u32) -> Option<Reduced> {
    let quotient = Float::with_val(w, x / hp_lo);
    let k = quotient.to_integer().unwrap_or_default();
    if k == 0 {
        return Some(Reduced {
            odd: false,
            lo: x.clone(),
            hi: x.clone(),
        });
    }
    // k·π/2 enclosed: the product is monotone in π/2 for a fixed sign of k.
    let (m_lo, m_hi) = if k > 0 {
        (hp_lo, hp_hi)
    } else {
        (hp_hi, hp_lo)
    };
    let kp_lo = Float::with_val_round(w, m_lo * &k, Round::Down).0;
    let kp_hi = Float::with_val_round(w, m_hi * &k, Round::Up).0;
    let lo = Float::with_val_round(w, x - &kp_hi, Round::Down).0;
    let hi = Float::with_val_round(w, x - &kp_lo, Round::Up).0;
    tight(&lo, &hi, q).then(|| Reduced {
        odd: k.is_odd(),
        lo,
        hi,
    })
}

/// Whether `[lo, hi]` has one strict sign and relative width below `2^(−q−8)`.
fn tight(lo: &Float, hi: &Float, q: u32) -> bool {
    if lo.is_zero() || hi.is_zero() || lo.is_sign_negative() != hi.is_sign_negative() {
        return false;
    }
    let width = Float::with_val(hi.prec(), hi - lo);
    if width.is_zero() {
        return true;
    }
    let (Some(ew), Some(el), Some(eh)) = (width.get_exp(), lo.get_exp(), hi.get_exp()) else {
        return false;
    };
    // |t| ≥ 2^(min(el, eh) − 1) and width < 2^ew.
    i64::from(ew) <= i64::from(el.min(eh)) - 1 - i64::from(q) - 8
}
