//! Rigorous enclosure of `Л` over an interval argument (proofs/B52).
//!
//! A point is reduced and bounded by [`super::eval::enclose_point`]. A wider interval
//! `[a, b]` uses monotonicity: `Л′(x) = −log|2 sin x|` changes sign only at
//! `x ≡ ±π/6 (mod π)`, where `Л` takes its maximum `M = Л(π/6)` or minimum `−M`; so
//! `Л([a, b]) ⊆ hull(Л(a), Л(b), M if some π/6 + jπ may lie in [a, b], −M if some
//! −π/6 + jπ may)`. Unbounded intervals give `[−M, M]`.

use super::coefficients::{table, working_precision};
use super::eval::enclose_point;
use crate::scalar::{Interval, Mpfr, Precision};
use rug::float::{Constant, Round};
use rug::Float;

/// An enclosure of `M = Л(π/6) = max Л` at the working precision `t.prec`.
fn max_value(bits: u32) -> Option<(Float, Float)> {
    let t = table(working_precision(bits));
    let lo = Float::with_val_round(t.prec, &t.pi.0 / 6u32, Round::Down).0;
    let hi = Float::with_val_round(t.prec, &t.pi.1 / 6u32, Round::Up).0;
    let red = super::reduce::Reduced { odd: false, lo, hi };
    super::eval::evaluate_reduced(&red, &t)
}

/// Whether some `c + jπ`, `c = ±π/6`, may lie in `[a, b]` (never a wrong `false`).
fn may_contain(a: &Float, b: &Float, c_sixths: i32) -> bool {
    let e = a
        .get_exp()
        .unwrap_or(0)
        .max(b.get_exp().unwrap_or(0))
        .max(1) as u32;
    let w = e + 16 + 53;
    let pi = Float::with_val(w, Constant::Pi);
    let c = Float::with_val(w, &pi * c_sixths) / 6u32;
    let ua = Float::with_val(w, a - &c) / &pi;
    let ub = Float::with_val(w, b - &c) / &pi;
    // Rounding errors are below 2^(e−w+2) = 2⁻⁶⁷ < δ = 2⁻⁶⁰ (a wider δ only widens
    // enclosures of narrow intervals next to ±π/6 to the whole range [−M, M]).
    let delta = Float::with_val(w, 1) >> 60u32;
    let lo = Float::with_val(w, &ua - &delta).ceil();
    let hi = Float::with_val(w, &ub + &delta).floor();
    hi >= lo
}

fn to_precision(lo: &Float, hi: &Float, p: Precision) -> Interval<Mpfr> {
    Interval::new(
        Mpfr(Float::with_val_round(p.bits(), lo, Round::Down).0),
        Mpfr(Float::with_val_round(p.bits(), hi, Round::Up).0),
    )
}

/// Rigorous enclosure of `Л(x)` for every `x` in the interval, at the interval's
/// precision (proofs/B52). Invalid in, invalid out; an unbounded interval, or a bound the
/// reduction cannot resolve (`|x| ≳ 2^(2²⁰)`), gives `[−M, M]`, `M = Л(π/6) ≈ 0.5074708`.
///
/// ```
/// use penner::scalar::{Interval, Mpfr, Precision, Real};
/// use penner::special::lobachevsky_enclosure;
/// let p = Precision::new(128).unwrap();
/// let x = Interval::point(Mpfr::from_f64(0.5, p));
/// let y = lobachevsky_enclosure(&x);
/// // Л(1/2) = ½ Cl₂(1) = 0.50697956618…
/// assert!(y.lo().approx_f64() > 0.5069795661 && y.hi().approx_f64() < 0.5069795662);
/// ```
pub fn lobachevsky_enclosure(x: &Interval<Mpfr>) -> Interval<Mpfr> {
    let p = x.lo().precision();
    if !x.is_valid() {
        return Interval::invalid(p);
    }
    let bits = p.bits();
    let Some((_, m_hi)) = max_value(bits) else {
        return Interval::invalid(p);
    };
    let everything = to_precision(&Float::with_val(m_hi.prec(), -&m_hi), &m_hi, p);
    let (a, b) = (&x.lo().0, &x.hi().0);
    if !a.is_finite() || !b.is_finite() {
        return everything;
    }
    let Some((mut lo, mut hi)) = enclose_point(a, bits) else {
        return everything;
    };
    if a != b {
        let Some((lb, hb)) = enclose_point(b, bits) else {
            return everything;
        };
        lo = lo.min(&lb);
        hi = hi.max(&hb);
        if may_contain(a, b, 1) {
            hi = hi.max(&m_hi);
        }
        if may_contain(a, b, -1) {
            lo = lo.min(&Float::with_val(m_hi.prec(), -&m_hi));
        }
    }
    to_precision(&lo, &hi, p)
}

/// B52's extremum term (proofs/B52, **Terms**): `±M` joins the hull wherever `±π/6 + jπ`
/// may lie in `[a, b]`, decided with the margin `δ = 2⁻⁶⁰` outward.
#[cfg(test)]
mod terms {
    use super::*;

    const BITS: u32 = 256;

    /// A lower bound of `M = Л(π/6) = ½·Cl₂(π/3)`: the literature value of `Cl₂(π/3)`
    /// (`1.01494160640965362502120255427452028594168930753029979…`, as in
    /// tests/it/claims_energy.rs) halved and truncated to 50 digits.
    fn m_below() -> Float {
        let digits = "0.50747080320482681251060127713726014297084465376514";
        Float::with_val_round(300, Float::parse(digits).expect("digits"), Round::Down).0
    }

    fn interval(a: &Float, b: &Float) -> Interval<Mpfr> {
        Interval::new(
            Mpfr(Float::with_val(BITS, a)),
            Mpfr(Float::with_val(BITS, b)),
        )
    }

    /// B52 term "`±M` where `±π/6 + jπ` may lie in `[a, b]`, margin `δ` outward": `π/6`
    /// inside `[a, b]` by `2⁻⁶²` (below `δ`) at either end, where `Л` at the ends is below
    /// `M` by about `4·10⁻³⁸` (`Л″(π/6) = −√3`), so only the extremum term reaches `M`; the
    /// same for `−π/6` and `−M` by oddness. Control: `π/6` outside by `2⁻⁵⁰`, where `M` is
    /// not attained, gives an upper end below `M`.
    #[test]
    fn term_b52_extremum_kept_within_delta_of_an_end() {
        let p6 = Float::with_val(BITS, Constant::Pi) / 6u32;
        let f = |x: f64| Float::with_val(BITS, x);
        let near = f(1.0) >> 62u32;
        let m = m_below();
        let a = Float::with_val(BITS, &p6 - &near);
        let b = Float::with_val(BITS, &p6 + &near);
        for x in [interval(&a, &f(1.0)), interval(&f(0.2), &b)] {
            let y = lobachevsky_enclosure(&x);
            assert!(y.hi().0 >= m, "{x:?}: {:?}", y.hi());
            let y = lobachevsky_enclosure(&-x.clone());
            assert!(y.lo().0 <= -m.clone(), "−{x:?}: {:?}", y.lo());
        }
        let c = Float::with_val(BITS, &p6 - (f(1.0) >> 50u32));
        let y = lobachevsky_enclosure(&interval(&f(0.2), &c));
        assert!(y.hi().0 < m, "{:?}", y.hi());
    }
}
