//! The two series of `Л` after reduction, bounded with directed rounding (proofs/B52):
//!
//! * `Л(t) = t (1 − log 2t + P(t²))`, `P(s) = Σ_{n=1}^{N} a_n sⁿ`, for `0 < t ≤ 1.0708`;
//! * `Л(π/2 + t) = −g(t)`, `g(t) = t (log 2 − Q(t²))`, `Q(s) = Σ_{n=1}^{N} b_n sⁿ`, for
//!   `0 < t ≤ 1/2`;
//!
//! each with the tail bound `τ = h · (16/7) · θ^(N+1) / ((N+1)(2N+3))`, `θ = (c·h/π)²`
//! (`c = 1` resp. `2`, `θ ≤ 1/8`), for `t ≤ h`. On `0 < l ≤ t ≤ h` every factor is
//! positive, so the lower bound `l (1 − log 2h + P(l²))` and the upper bound
//! `h (1 − log 2l + P(h²))` (and likewise for `g`) need only outward rounding of each
//! operation.

use super::coefficients::Table;
use rug::float::Round;
use rug::Float;

/// A rounding direction of one bound: down, up, or to nearest (point evaluation).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Dir {
    /// Toward −∞.
    Down,
    /// Toward +∞.
    Up,
    /// To nearest (no guarantee, point evaluation).
    Near,
}

impl Dir {
    fn round(self) -> Round {
        match self {
            Dir::Down => Round::Down,
            Dir::Up => Round::Up,
            Dir::Near => Round::Nearest,
        }
    }
    fn opposite(self) -> Dir {
        match self {
            Dir::Down => Dir::Up,
            Dir::Up => Dir::Down,
            Dir::Near => Dir::Near,
        }
    }
}

/// Which expansion: around 0 (`a_n`) or around π/2 (`b_n`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Expansion {
    /// `Л(t)`, `0 < t ≤ 1.0708`.
    AtZero,
    /// `g(t) = −Л(π/2 + t)`, `0 < t ≤ 1/2`.
    AtHalfPi,
}

impl Expansion {
    /// Largest `t` for which the evaluation is used; `θ ≤ 0.117` there (proofs/B52).
    pub(crate) fn radius(self) -> f64 {
        match self {
            Expansion::AtZero => 1.0708,
            Expansion::AtHalfPi => 0.5,
        }
    }
}

/// `θ = (c·h/π)²` rounded up, `c = 1` or `2`.
fn theta_up(h: &Float, e: Expansion, t: &Table) -> Float {
    let mut ch = Float::with_val_round(t.prec, h, Round::Up).0;
    if e == Expansion::AtHalfPi {
        ch <<= 1u32;
    }
    let ratio = Float::with_val_round(t.prec, &ch / &t.pi.0, Round::Up).0;
    Float::with_val_round(t.prec, ratio.square_ref(), Round::Up).0
}

/// Number of terms for a relative tail below `2^(−prec−8)` at the ratio `θ`, at most the
/// table length. The choice is a heuristic; the tail bound is computed for the `N` chosen.
fn terms(theta: &Float, t: &Table) -> usize {
    let len = t.a_lo.len();
    let log2_theta = match theta.get_exp() {
        None => return 1,
        // θ = m·2ᵉ with m ∈ [1/2, 1): log₂θ < e.
        Some(e) if e < -1000 => f64::from(e),
        Some(_) => theta.to_f64().log2(),
    };
    if log2_theta >= -1.0 {
        return len;
    }
    let n = ((f64::from(t.prec) + 8.0) / -log2_theta).ceil() as usize;
    n.clamp(1, len)
}

/// The tail bound `τ` (rounded up) for `N` terms, or `None` when `θ > 1/8`.
pub(crate) fn tail_bound(h: &Float, e: Expansion, t: &Table, n: usize) -> Option<Float> {
    let theta = theta_up(h, e, t);
    if theta > 0.125 {
        return None;
    }
    let p = t.prec;
    let pow = Float::with_val_round(p, rug::ops::Pow::pow(&theta, n as u32 + 1), Round::Up).0;
    let d = ((n + 1) * (2 * n + 3)) as u64;
    let mut tau = Float::with_val_round(p, &pow * 16u32, Round::Up).0;
    tau = Float::with_val_round(p, &tau / (7 * d), Round::Up).0;
    Some(Float::with_val_round(p, &tau * h, Round::Up).0)
}

/// `Σ_{n=1}^{N} c_n sⁿ` by Horner, every coefficient and `s` positive, rounded `dir`.
fn horner(coeffs: &[Float], s: &Float, dir: Dir, p: u32) -> Float {
    let r = dir.round();
    let mut acc = coeffs[coeffs.len() - 1].clone();
    for c in coeffs[..coeffs.len() - 1].iter().rev() {
        let prod = Float::with_val_round(p, &acc * s, r).0;
        acc = Float::with_val_round(p, &prod + c, r).0;
    }
    Float::with_val_round(p, &acc * s, r).0
}

/// One bound (`dir`) of the truncated series (`N` terms, no tail) over `0 < l ≤ t ≤ h`:
/// of `Л(t)` for [`Expansion::AtZero`], of `g(t)` for [`Expansion::AtHalfPi`].
pub(crate) fn bound(l: &Float, h: &Float, e: Expansion, dir: Dir, t: &Table, n: usize) -> Float {
    let p = t.prec;
    // The factor t and the argument of P are the low end for a lower bound.
    let (tt, other) = if dir == Dir::Up { (h, l) } else { (l, h) };
    match e {
        Expansion::AtZero => {
            let s = Float::with_val_round(p, tt.square_ref(), dir.round()).0;
            let coeffs = if dir == Dir::Up { &t.a_hi } else { &t.a_lo };
            let poly = horner(&coeffs[..n], &s, dir, p);
            let two = Float::with_val(other.prec(), other << 1u32);
            let lg = Float::with_val_round(p, two.ln_ref(), dir.opposite().round()).0;
            let one_minus = Float::with_val_round(p, 1 - &lg, dir.round()).0;
            let inner = Float::with_val_round(p, &one_minus + &poly, dir.round()).0;
            Float::with_val_round(p, &inner * tt, dir.round()).0
        }
        Expansion::AtHalfPi => {
            // The lower bound of g takes Q at the high end and log 2 rounded down.
            let s_q = Float::with_val_round(p, other.square_ref(), dir.opposite().round()).0;
            let coeffs = if dir == Dir::Up { &t.b_lo } else { &t.b_hi };
            let poly = horner(&coeffs[..n], &s_q, dir.opposite(), p);
            let ln2 = if dir == Dir::Up { &t.ln2.1 } else { &t.ln2.0 };
            let inner = Float::with_val_round(p, ln2 - &poly, dir.round()).0;
            Float::with_val_round(p, &inner * tt, dir.round()).0
        }
    }
}

/// The number of terms for `t ≤ h` in expansion `e`.
pub(crate) fn terms_for_bound(h: &Float, e: Expansion, t: &Table) -> usize {
    terms(&theta_up(h, e, t), t)
}
