//! Evaluation of `Л` at an exact binary number: reduction ([`super::reduce`]), choice of
//! the expansion, and the series bounds ([`super::series`]); rigorous (outward rounding
//! and tail bound, proofs/B52) or to nearest.

use super::coefficients::{table, working_precision, Table};
use super::elementary_table::ElementaryTable;
use super::reduce::{reduce, Reduced};
use super::series::{bound, tail_bound, terms_for_bound, Dir, Expansion};
use rug::float::Round;
use rug::Float;

/// `Л(x) ∈ [lo, hi]`, both at the working precision of `bits`; `x = 0` gives `[0, 0]`.
/// `None` for a non-finite `x` or one the reduction cannot resolve.
pub(crate) fn enclose_point(x: &Float, bits: u32) -> Option<(Float, Float)> {
    let t = table(working_precision(bits));
    if x.is_zero() {
        return Some((Float::new(t.prec), Float::new(t.prec)));
    }
    evaluate(&reduce(x, t.prec)?, &t, true, None)
}

/// `Л(x)` to nearest at the working precision of `bits` (error below `2^(−bits−20)`
/// relative, proofs/B52), with the reduced argument: `x = k·π/2 + t`, `k` odd or even.
pub(crate) fn point(x: &Float, bits: u32) -> Option<(Float, Float, bool)> {
    point_in(x, &table(working_precision(bits)), None)
}

/// [`point`] with the table of its working precision already at hand; `log 2t` from `ln`
/// when given (the energy pass, proofs/B100), else from MPFR.
pub(crate) fn point_in(
    x: &Float,
    t: &Table,
    ln: Option<&ElementaryTable>,
) -> Option<(Float, Float, bool)> {
    if x.is_zero() {
        return Some((Float::new(t.prec), Float::new(t.prec), false));
    }
    let red = reduce(x, t.prec)?;
    let (v, _) = evaluate(&red, t, false, ln)?;
    Some((v, red.lo, red.odd))
}

/// Rigorous bounds of `Л` over an already reduced interval.
pub(crate) fn evaluate_reduced(red: &Reduced, t: &Table) -> Option<(Float, Float)> {
    evaluate(red, t, true, None)
}

/// Bounds of `Л(u)`, `Л(π/2 + u)` or their negatives over the reduced interval.
fn evaluate(
    red: &Reduced,
    t: &Table,
    rigorous: bool,
    ln: Option<&ElementaryTable>,
) -> Option<(Float, Float)> {
    let p = t.prec;
    let negative = red.lo.is_sign_negative();
    let (l, h) = if negative {
        (
            Float::with_val(red.hi.prec(), -&red.hi),
            Float::with_val(red.lo.prec(), -&red.lo),
        )
    } else {
        (red.lo.clone(), red.hi.clone())
    };
    // Л(x) = σ·F(u) with u ∈ [l, h] positive.
    let (expansion, l, h, sigma_negative) = if !red.odd {
        (Expansion::AtZero, l, h, negative)
    } else if h <= Expansion::AtHalfPi.radius() {
        // Л(π/2 + t) = −g(t), odd in t.
        (Expansion::AtHalfPi, l, h, !negative)
    } else {
        // Л(π/2 + t) = Л(t − π/2) = −Л(π/2 − t) for t > 0, odd in t.
        let (hp_lo, hp_hi) = (t.pi.0.clone() >> 1u32, t.pi.1.clone() >> 1u32);
        let ul = Float::with_val_round(p, &hp_lo - &h, Round::Down).0;
        let uh = Float::with_val_round(p, &hp_hi - &l, Round::Up).0;
        (Expansion::AtZero, ul, uh, !negative)
    };
    if h > expansion.radius() || l <= 0 {
        return None;
    }
    let n = terms_for_bound(&h, expansion, t);
    let (mut lo, mut hi) = if rigorous {
        let tau = tail_bound(&h, expansion, t, n)?;
        let lo = bound(&l, &h, expansion, Dir::Down, t, n, None);
        let hi = bound(&l, &h, expansion, Dir::Up, t, n, None);
        (
            Float::with_val_round(p, &lo - &tau, Round::Down).0,
            Float::with_val_round(p, &hi + &tau, Round::Up).0,
        )
    } else {
        let v = bound(&l, &h, expansion, Dir::Near, t, n, ln);
        (v.clone(), v)
    };
    // For the AtHalfPi expansion F = g and Л = −g for t > 0: the sign flag already says so.
    if sigma_negative {
        std::mem::swap(&mut lo, &mut hi);
        lo = -lo;
        hi = -hi;
    }
    Some((lo, hi))
}
