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
use super::elementary_table::ElementaryTable;
use rug::float::Round;
use rug::ops::{AddAssignRound, MulAssignRound};
use rug::{Assign, Float};

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

/// `Σ_{n=1}^{N} c_n sⁿ` by Horner, every coefficient and `s` positive, rounded `dir`, in
/// place (one accumulator, no allocation per operation).
fn horner(coeffs: &[Float], s: &Float, dir: Dir, p: u32) -> Float {
    let r = dir.round();
    let mut acc = Float::with_val_round(p, &coeffs[coeffs.len() - 1], r).0;
    for c in coeffs[..coeffs.len() - 1].iter().rev() {
        acc.mul_assign_round(s, r);
        acc.add_assign_round(c, r);
    }
    acc.mul_assign_round(s, r);
    acc
}

/// Guard bits of the graded Horner evaluation: level `k` runs at `p + G − ⌊kβ⌋` bits
/// (proof: B28).
pub(crate) const GRADED_GUARD_BITS: u32 = 8;

/// `β ≤ ⌊log₂(1/θ)⌋`, less by at most one (at exact powers of two, where the safety margin
/// of the refinement rounds down), from `θ` rounded up: `2^(−β) ≥ θ`, so
/// `θ^k·2^(kβ) ≤ 1` (proof: B28). 0 when `θ` is not below 1/2.
fn graded_beta(theta: &Float) -> u32 {
    // θ = m·2ᵉ, m ∈ [1/2, 1): θ < 2ᵉ, so log₂(1/θ) > −e; ⌊·⌋ ≥ −e. The exponent alone is
    // a lower bound off by less than one bit per level; the f64 logarithm refines it with
    // a margin of 2⁻²⁰ for its own rounding.
    let Some(e) = theta.get_exp() else {
        return 0;
    };
    let from_exp = (-i64::from(e)).max(0);
    let refined = -theta.to_f64_round(Round::Up).log2() - 1.0 / 1048576.0;
    let beta = if refined.is_finite() && refined >= from_exp as f64 {
        refined.floor() as i64
    } else {
        from_exp
    };
    beta.clamp(0, 1 << 20) as u32
}

/// `Σ_{n=1}^{N} c_n sⁿ` to nearest by Horner with graded precision (proofs/B28): the
/// accumulator of level `k` (`c_k + s·acc_{k+1}`, weighted by `s^k ≤ θ^k`-sized terms in
/// the sum) needs `p_k = p + G − ⌊kβ⌋` bits and runs at the smallest tier of `tiers`
/// (precisions below `p`, with `c_k` and `s` rounded to it) holding `p_k`, or at `p` with
/// the exact `c_k` and `s`; precision only grows outward (levels are evaluated from `N`
/// down to 1), so one allocation of `p` bits serves all levels.
fn horner_graded(
    coeffs: &[Float],
    tiers: &[(u32, &[Float])],
    s: &Float,
    beta: u32,
    p: u32,
) -> Float {
    let needed = |k: usize| -> u64 {
        let drop = (k as u64).saturating_mul(u64::from(beta));
        (u64::from(p) + u64::from(GRADED_GUARD_BITS)).saturating_sub(drop)
    };
    // The tier of level k: an index into `tiers`, or None for full precision.
    let tier_of = |k: usize| -> Option<usize> {
        tiers
            .iter()
            .position(|&(bits, _)| u64::from(bits) >= needed(k))
    };
    let s_tiers: Vec<Float> = tiers
        .iter()
        .map(|&(bits, _)| Float::with_val(bits, s))
        .collect();
    let n = coeffs.len();
    let mut acc = Float::new(p);
    let mut current = tier_of(n);
    match current {
        Some(i) => {
            acc.set_prec(tiers[i].0);
            acc.assign(&tiers[i].1[n - 1]);
        }
        None => acc.assign(&coeffs[n - 1]),
    }
    for k in (1..n).rev() {
        let tier = tier_of(k);
        if tier != current {
            // Raising the precision is exact (mpfr_prec_round to more bits); the
            // allocation of `p` bits made above is kept, so no level reallocates.
            acc.set_prec(tier.map_or(p, |i| tiers[i].0));
            current = tier;
        }
        if let Some(i) = tier {
            acc.mul_assign_round(&s_tiers[i], Round::Nearest);
            acc.add_assign_round(&tiers[i].1[k - 1], Round::Nearest);
        } else {
            acc.mul_assign_round(s, Round::Nearest);
            acc.add_assign_round(&coeffs[k - 1], Round::Nearest);
        }
    }
    if current.is_some() {
        acc.set_prec(p);
    }
    acc.mul_assign_round(s, Round::Nearest);
    acc
}

/// One bound (`dir`) of the truncated series (`N` terms, no tail) over `0 < l ≤ t ≤ h`:
/// of `Л(t)` for [`Expansion::AtZero`], of `g(t)` for [`Expansion::AtHalfPi`]. A point
/// value (`Dir::Near`) takes `log 2t` from `ln` when given (proofs/B100, B101), else from
/// MPFR.
pub(crate) fn bound(
    l: &Float,
    h: &Float,
    e: Expansion,
    dir: Dir,
    t: &Table,
    n: usize,
    ln: Option<&ElementaryTable>,
) -> Float {
    let p = t.prec;
    // The factor t and the argument of P are the low end for a lower bound.
    let (tt, other) = if dir == Dir::Up { (h, l) } else { (l, h) };
    match e {
        Expansion::AtZero => {
            let s = Float::with_val_round(p, tt.square_ref(), dir.round()).0;
            let coeffs = if dir == Dir::Up { &t.a_hi } else { &t.a_lo };
            let poly = if dir == Dir::Near {
                let tiers: Vec<(u32, &[Float])> =
                    t.near_tiers.iter().map(|x| (x.prec, &x.a[..n])).collect();
                horner_graded(
                    &coeffs[..n],
                    &tiers,
                    &s,
                    graded_beta(&theta_up(tt, e, t)),
                    p,
                )
            } else {
                horner(&coeffs[..n], &s, dir, p)
            };
            let two = Float::with_val(other.prec(), other << 1u32);
            let table_log = match ln {
                Some(tab) if dir == Dir::Near && tab.prec() == p => tab.ln(&two),
                _ => None,
            };
            let lg = table_log.unwrap_or_else(|| {
                Float::with_val_round(p, two.ln_ref(), dir.opposite().round()).0
            });
            let one_minus = Float::with_val_round(p, 1 - &lg, dir.round()).0;
            let inner = Float::with_val_round(p, &one_minus + &poly, dir.round()).0;
            Float::with_val_round(p, &inner * tt, dir.round()).0
        }
        Expansion::AtHalfPi => {
            // The lower bound of g takes Q at the high end and log 2 rounded down.
            let s_q = Float::with_val_round(p, other.square_ref(), dir.opposite().round()).0;
            let coeffs = if dir == Dir::Up { &t.b_lo } else { &t.b_hi };
            let poly = if dir == Dir::Near {
                let tiers: Vec<(u32, &[Float])> =
                    t.near_tiers.iter().map(|x| (x.prec, &x.b[..n])).collect();
                horner_graded(
                    &coeffs[..n],
                    &tiers,
                    &s_q,
                    graded_beta(&theta_up(other, e, t)),
                    p,
                )
            } else {
                horner(&coeffs[..n], &s_q, dir.opposite(), p)
            };
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

#[cfg(test)]
mod tests {
    use super::super::coefficients::table;
    use super::*;

    /// `|graded − ref|` and B28's bound `2^(−q)·(4S + 6·2^(−G))` for the polynomial of
    /// expansion `e` at `t` (`S` the reference sum, evaluated at `q + 128` bits on the same
    /// `q`-bit coefficients and the same `s`, so only rounding is measured).
    fn graded_error(t_f: f64, e: Expansion, q: u32, beta_extra: u32) -> (Float, Float) {
        let tab = table(q);
        let t = Float::with_val(q, t_f);
        let s = Float::with_val(q, t.square_ref());
        let n = terms_for_bound(&t, e, &tab);
        let (coeffs, tiers): (&[Float], Vec<(u32, &[Float])>) = match e {
            Expansion::AtZero => (
                &tab.a_lo[..n],
                tab.near_tiers.iter().map(|x| (x.prec, &x.a[..n])).collect(),
            ),
            Expansion::AtHalfPi => (
                &tab.b_hi[..n],
                tab.near_tiers.iter().map(|x| (x.prec, &x.b[..n])).collect(),
            ),
        };
        let beta = graded_beta(&theta_up(&t, e, &tab)) + beta_extra;
        let graded = horner_graded(coeffs, &tiers, &s, beta, q);
        let wide = q + 128;
        let s_wide = Float::with_val(wide, &s);
        let reference = horner(coeffs, &s_wide, Dir::Near, wide);
        let err = Float::with_val(wide, &graded - &reference).abs();
        // proof: B28 — (2·1.306 + 1)·S at q bits, 5.62·2^(−G) for the graded levels.
        let graded_part = 6.0 * (-f64::from(GRADED_GUARD_BITS)).exp2();
        let bound = Float::with_val(wide, &reference * 4u32) + graded_part;
        (err, bound >> q)
    }

    fn samples(e: Expansion) -> Vec<f64> {
        let r = e.radius();
        let mut v: Vec<f64> = (1..=60).map(|i| r * f64::from(i) / 60.0).collect();
        v.extend([1e-3, 1e-9, 1e-30, 2f64.powi(-200), r]);
        v
    }

    #[test]
    fn b28_graded_horner_within_bound_of_wide_evaluation() {
        for q in [128, 320, 576, 1088] {
            for e in [Expansion::AtZero, Expansion::AtHalfPi] {
                for t in samples(e) {
                    let (err, bound) = graded_error(t, e, q, 0);
                    assert!(err <= bound, "q = {q}, {e:?}, t = {t:e}: {err} > {bound}");
                }
            }
        }
    }

    #[test]
    fn b28_negative_control_overstated_beta_is_rejected() {
        // β two bits per level too large drops precision faster than the terms shrink: the
        // same bound rejects it somewhere on each grid.
        for q in [320, 576] {
            for e in [Expansion::AtZero, Expansion::AtHalfPi] {
                let rejected = samples(e).into_iter().any(|t| {
                    let (err, bound) = graded_error(t, e, q, 2);
                    err > bound
                });
                assert!(rejected, "q = {q}, {e:?}: an overstated β went unnoticed");
            }
        }
    }

    #[test]
    fn b28_graded_beta_is_a_lower_bound_of_log2_one_over_theta() {
        for th in [0.117_f64, 0.1, 0.0625, 0.03, 1e-5, 1e-300] {
            let theta = Float::with_val(64, th);
            let beta = graded_beta(&theta);
            assert!(f64::from(beta) <= -th.log2(), "θ = {th}: β = {beta}");
            assert!(
                // Within one bit; exact powers of two (θ = 1/16) lose that bit to the margin.
                f64::from(beta) >= -th.log2() - 1.0,
                "θ = {th}: β = {beta} too small"
            );
        }
        // Negative control: θ ≥ 1/2 gives no drop at all.
        assert_eq!(graded_beta(&Float::with_val(64, 0.75)), 0);
    }
}

/// Tests in which the tail bound `τ` (proofs/B52, "Terms") decides: with `N` terms fewer
/// than the precision asks for, the truncated series stays below the true value
/// (positive terms), so `bound(Up) < Л(h)` and only `bound(Up) + τ` encloses it. The true
/// value comes from the independent tangent-number series (`special::reference`).
#[cfg(test)]
mod terms {
    use super::super::coefficients::table;
    use super::super::reference::lobachevsky_tangent_series;
    use super::*;

    #[test]
    fn term_b52_series_tail_bound_is_added() {
        let tab = table(256);
        let mut decided = 0;
        for h in [0.125, 0.25, 0.5] {
            let hf = Float::with_val(tab.prec, h);
            let truth = lobachevsky_tangent_series(&hf, 400).expect("reference");
            for n in 1..=4 {
                let up = bound(&hf, &hf, Expansion::AtZero, Dir::Up, &tab, n, None);
                let down = bound(&hf, &hf, Expansion::AtZero, Dir::Down, &tab, n, None);
                let tau = tail_bound(&hf, Expansion::AtZero, &tab, n).expect("θ ≤ 1/8");
                let hi = Float::with_val_round(tab.prec, &up + &tau, Round::Up).0;
                let lo = Float::with_val_round(tab.prec, &down - &tau, Round::Down).0;
                assert!(lo <= truth && truth <= hi, "h = {h}, N = {n}");
                if up < truth {
                    decided += 1;
                }
            }
        }
        assert!(decided >= 6, "the tail decided only {decided} cases");
    }

    /// B52's tail bound `τ = h·(16/7)·θ^{N+1}/((N+1)(2N+3))`, `θ = (ch/π)²` (`c = 1` at
    /// 0, `2` at π/2), against the formula evaluated exactly in ℚ with `π` replaced by its
    /// lower bound from the table (so `θ` is the largest the rounding allows): never below
    /// it, and above it by at most `2⁻²⁴⁰` relative at 256 bits (the upward roundings of a
    /// dozen operations; the cap checked is `2⁻¹²⁰`). Every factor is pinned: `(2N + 3)`
    /// read as `6N`, or `16·θ^{N+1}` as `16 + θ^{N+1}`, leaves the interval. Control: `16/7`
    /// read as `16/8` falls below.
    #[test]
    fn term_b52_tail_bound_is_the_formula_rounded_up() {
        use rug::Rational;
        let tab = table(256);
        let pi_lo = tab.pi.0.to_rational().expect("finite π");
        let (mut cases, mut rejected) = (0, 0);
        for (e, c) in [(Expansion::AtZero, 1u32), (Expansion::AtHalfPi, 2)] {
            for h in [1.0 / 64.0, 0.1, 0.25, 0.5] {
                let hf = Float::with_val(tab.prec, h);
                let hq = Rational::from_f64(h).unwrap();
                let ratio = Rational::from(&hq * c) / &pi_lo;
                let theta = Rational::from(&ratio * &ratio);
                for n in 1..=12usize {
                    let Some(tau) = tail_bound(&hf, e, &tab, n) else {
                        continue;
                    };
                    let got = tau.to_rational().expect("finite τ");
                    let pow = rug::ops::Pow::pow(theta.clone(), (n + 1) as u32);
                    let d = Rational::from(((n + 1) * (2 * n + 3)) as u64);
                    let exact = Rational::from(&pow * 16u32) * &hq / (d.clone() * 7u32);
                    assert!(got >= exact, "{e:?} h {h} N {n}: τ below the formula");
                    let cap = exact.clone()
                        * (Rational::from(1) + Rational::from((1, 1u64 << 60)).square());
                    assert!(got <= cap, "{e:?} h {h} N {n}: τ above the formula");
                    // Control: `16/8` for `16/7` (τ·7/8) is rejected by the first check.
                    if Rational::from(&got * 7u32) / 8u32 < exact {
                        rejected += 1;
                    }
                    cases += 1;
                }
            }
        }
        assert!(
            cases > 20 && rejected == cases,
            "{rejected} of {cases} controls rejected"
        );
    }

    /// B52 (5) on a wide interval: for `[l, h] = [0.2, 0.3]` the lower end takes the factor
    /// `t` and the polynomial at `l` and the logarithm at `h`, the upper end the reverse;
    /// with `τ(h)` the two enclose `Л(t)` (the independent tangent-number series at 400
    /// bits) at 33 points of `[l, h]`. Control: the ends swapped (`l` for `h`) exclude it.
    #[test]
    fn term_b52_wide_interval_takes_each_factor_at_its_own_end() {
        let tab = table(256);
        let (l, h) = (Float::with_val(256, 0.2), Float::with_val(256, 0.3));
        let n = terms_for_bound(&h, Expansion::AtZero, &tab);
        let tau = tail_bound(&h, Expansion::AtZero, &tab, n).expect("θ ≤ 1/8");
        let lo = bound(&l, &h, Expansion::AtZero, Dir::Down, &tab, n, None);
        let hi = bound(&l, &h, Expansion::AtZero, Dir::Up, &tab, n, None);
        let lo = Float::with_val_round(256, &lo - &tau, Round::Down).0;
        let hi = Float::with_val_round(256, &hi + &tau, Round::Up).0;
        let swapped = bound(&h, &l, Expansion::AtZero, Dir::Down, &tab, n, None);
        let mut excluded = 0;
        for k in 0..=32 {
            let t = Float::with_val(256, 0.2 + 0.1 * f64::from(k) / 32.0);
            let truth = lobachevsky_tangent_series(&t, 400).expect("reference");
            assert!(lo <= truth && truth <= hi, "t = {t}");
            if swapped > truth {
                excluded += 1;
            }
        }
        assert!(excluded > 0, "control: the swapped ends still enclose");
    }

    /// B52 (4)'s tail bound needs `θ ≤ 1/8` (the geometric factor `1/(1 − θ) ≤ 8/7`):
    /// past it (`h = 1.2` at 0, `θ = (1.2/π)² ≈ 0.146`) there is no bound. Control: at
    /// `h = 1` (`θ ≈ 0.101`) there is one.
    #[test]
    fn term_b52_no_tail_bound_past_theta_one_eighth() {
        let tab = table(128);
        let at = |h: f64| tail_bound(&Float::with_val(128, h), Expansion::AtZero, &tab, 4);
        assert!(at(1.2).is_none());
        assert!(at(1.0).is_some());
    }

    /// Horner's sum rounded down and up brackets the exact sum of its `Float` coefficients
    /// at `s`, and the two differ when the sum is not representable (directed rounding is
    /// what makes `P_N^±` bounds, B52 (5)). Control: rounding to nearest would give one
    /// value for both.
    #[test]
    fn horner_is_rounded_in_the_asked_direction() {
        use rug::Rational;
        let p = 64;
        let coeffs: Vec<Float> = [1.0 / 3.0, 0.2, 1.0 / 7.0, 0.1]
            .iter()
            .map(|&c| Float::with_val(p, c))
            .collect();
        let s = Float::with_val(p, 0.3);
        let down = horner(&coeffs, &s, Dir::Down, p);
        let up = horner(&coeffs, &s, Dir::Up, p);
        let sq = s.to_rational().unwrap();
        let mut exact = Rational::new();
        for c in coeffs.iter().rev() {
            exact = (exact + c.to_rational().unwrap()) * &sq;
        }
        let (d, u) = (down.to_rational().unwrap(), up.to_rational().unwrap());
        assert!(d <= exact && exact <= u, "{down} {up}");
        assert!(d < u, "directed roundings coincide");
    }

    /// Each bound of the truncated series is rounded outward at every step (B52): the
    /// lower bound uses the lower coefficients and rounds down, the upper the upper ones
    /// and rounds up, so `bound(Down) − τ ≤ Л(t) ≤ bound(Up) + τ` at 128 bits for 96 points
    /// `t` of each expansion (around 0: `Л(t)`; around π/2: `g(t) = −Л(π/2 + t)`), against
    /// the independent tangent-number series at 400 bits. With every term of the table the
    /// tail `τ` is far below one ulp, so a bound rounded to nearest is on the wrong side of
    /// `Л(t)` for some points. Control: the nearest-rounded point value, taken as a bound,
    /// misses `Л(t)` by more than `τ` at some points.
    #[test]
    fn term_b52_point_bounds_are_rounded_outward_with_their_own_coefficients() {
        let tab = table(128);
        let p = tab.prec;
        let mut nearest_outside = 0;
        for e in [Expansion::AtZero, Expansion::AtHalfPi] {
            for k in 1..=96 {
                let t = Float::with_val(p, e.radius() * f64::from(k) / 97.0);
                // Every term of the table: the tail τ is far below one ulp.
                let n = tab.a_lo.len();
                let tau = tail_bound(&t, e, &tab, n).expect("θ ≤ 1/8");
                let lo = bound(&t, &t, e, Dir::Down, &tab, n, None);
                let hi = bound(&t, &t, e, Dir::Up, &tab, n, None);
                let near = bound(&t, &t, e, Dir::Near, &tab, n, None);
                let lo = Float::with_val_round(p, &lo - &tau, Round::Down).0;
                let hi = Float::with_val_round(p, &hi + &tau, Round::Up).0;
                let truth = match e {
                    Expansion::AtZero => lobachevsky_tangent_series(&t, 400).expect("reference"),
                    Expansion::AtHalfPi => {
                        let pi = Float::with_val(600, rug::float::Constant::Pi);
                        let x = Float::with_val(600, (pi >> 1u32) + &t);
                        -lobachevsky_tangent_series(&x, 400).expect("reference")
                    }
                };
                assert!(
                    lo <= truth && truth <= hi,
                    "{e:?} t = {t}: {lo} {truth} {hi}"
                );
                // The nearest value, taken as either bound, misses Л(t) past the tail.
                let below = Float::with_val(600, &near + &tau) < truth;
                let above = Float::with_val(600, &near - &tau) > truth;
                nearest_outside += usize::from(below || above);
            }
        }
        assert!(
            nearest_outside > 0,
            "control: the nearest value never leaves"
        );
    }

    /// The same outward rounding where the polynomial dominates: a table whose
    /// coefficients enclose `c_n = 1000/3` (each end rounded its own way at 128 bits), so
    /// that `Σ c_n t^{2n}` outweighs `1 − log 2t` and `log 2 − …` and its own rounding and
    /// coefficient ends decide the bounds. The value `t(1 − log 2t + Σ_{n≤N} c_n t^{2n})`
    /// (and `t(log 2 − Σ c_n t^{2n})` around π/2) is computed at 600 bits with the exact
    /// `c_n`. A lower bound made of the upper coefficients, or a bound rounded to nearest,
    /// misses it at some of the 96 points. Control: the nearest-rounded value lies below it
    /// at some points and above it at others (as either bound it would be wrong).
    #[test]
    fn term_b52_bounds_take_their_own_coefficient_ends_where_the_polynomial_dominates() {
        use super::super::coefficients::{NearTier, Table, NEAR_TIERS};
        let p = 128;
        let n = 6;
        let c = rug::Rational::from((1000, 3));
        let end = |r: Round| vec![Float::with_val_round(p, &c, r).0; n];
        let tab = Table {
            prec: p,
            a_lo: end(Round::Down),
            a_hi: end(Round::Up),
            b_lo: end(Round::Down),
            b_hi: end(Round::Up),
            pi: (
                Float::with_val_round(p, rug::float::Constant::Pi, Round::Down).0,
                Float::with_val_round(p, rug::float::Constant::Pi, Round::Up).0,
            ),
            ln2: (
                Float::with_val_round(p, rug::float::Constant::Log2, Round::Down).0,
                Float::with_val_round(p, rug::float::Constant::Log2, Round::Up).0,
            ),
            near_tiers: NEAR_TIERS
                .iter()
                .filter(|&&bits| bits < p)
                .map(|&bits| NearTier {
                    prec: bits,
                    a: vec![Float::with_val(bits, &c); n],
                    b: vec![Float::with_val(bits, &c); n],
                })
                .collect(),
        };
        let (mut below, mut above) = (0, 0);
        for e in [Expansion::AtZero, Expansion::AtHalfPi] {
            for k in 1..=96 {
                let t = Float::with_val(p, 0.3 + 0.2 * f64::from(k) / 97.0);
                let s = Float::with_val(600, t.square_ref());
                let mut poly = Float::with_val(600, 0);
                for _ in 0..n {
                    poly = Float::with_val(600, (poly + &c) * &s);
                }
                let truth = match e {
                    Expansion::AtZero => {
                        let lg = Float::with_val(600, Float::with_val(600, &t << 1u32).ln_ref());
                        Float::with_val(600, (1 - lg + &poly) * &t)
                    }
                    Expansion::AtHalfPi => {
                        let ln2 = Float::with_val(600, rug::float::Constant::Log2);
                        Float::with_val(600, (ln2 - &poly) * &t)
                    }
                };
                let lo = bound(&t, &t, e, Dir::Down, &tab, n, None);
                let hi = bound(&t, &t, e, Dir::Up, &tab, n, None);
                let near = bound(&t, &t, e, Dir::Near, &tab, n, None);
                assert!(
                    lo <= truth && truth <= hi,
                    "{e:?} t = {t}: {lo} {truth} {hi}"
                );
                below += usize::from(near < truth);
                above += usize::from(near > truth);
            }
        }
        assert!(
            below > 0 && above > 0,
            "control: {below} below, {above} above"
        );
    }

    /// The bounds around π/2, `t(log 2 − Σ b_n t^{2n})`, where a one-ulp error of the
    /// polynomial or of the constant decides: a table whose constant encloses `L = 2/97`
    /// in place of `log 2`, whose two coefficients enclose `1/3`, at `t` near `1/4`, where `L − Σ` cancels to about `2⁻⁹` and its own ulp is
    /// about `2⁻¹³⁶`, below the `2⁻¹³³` between the coefficient ends. Both bounds must
    /// enclose `t(L − (s + s²)/3)`, `s = t²`, computed in ℚ. Taking the other end of the
    /// coefficients or of `L`, or Horner rounded to nearest, misses it. Control: the
    /// bounds computed with the ends exchanged exclude it at some point.
    #[test]
    fn term_b52_bounds_around_half_pi_take_their_own_ends() {
        use super::super::coefficients::{NearTier, Table, NEAR_TIERS};
        use rug::Rational;
        let p = 128;
        let third = Rational::from((1, 3));
        let l = Rational::from((2, 97));
        let ends = |c: &Rational| {
            (
                vec![Float::with_val_round(p, c, Round::Down).0; 2],
                vec![Float::with_val_round(p, c, Round::Up).0; 2],
            )
        };
        let (lo_c, hi_c) = ends(&third);
        let table = |swap: bool| Table {
            prec: p,
            a_lo: lo_c.clone(),
            a_hi: hi_c.clone(),
            b_lo: if swap { hi_c.clone() } else { lo_c.clone() },
            b_hi: if swap { lo_c.clone() } else { hi_c.clone() },
            pi: (
                Float::with_val_round(p, rug::float::Constant::Pi, Round::Down).0,
                Float::with_val_round(p, rug::float::Constant::Pi, Round::Up).0,
            ),
            ln2: (
                Float::with_val_round(p, &l, Round::Down).0,
                Float::with_val_round(p, &l, Round::Up).0,
            ),
            near_tiers: NEAR_TIERS
                .iter()
                .filter(|&&bits| bits < p)
                .map(|&bits| NearTier {
                    prec: bits,
                    a: vec![Float::with_val(bits, &third); 2],
                    b: vec![Float::with_val(bits, &third); 2],
                })
                .collect(),
        };
        let (tab, swapped) = (table(false), table(true));
        let mut excluded = 0;
        for k in 0..64 {
            let t = Float::with_val(p, 0.245 + 0.01 * f64::from(k) / 63.0);
            let tq = t.to_rational().expect("finite");
            let sq = Rational::from(&tq * &tq);
            let truth = &tq * (l.clone() - (sq.clone() + Rational::from(&sq * &sq)) * &third);
            let e = Expansion::AtHalfPi;
            let lo = bound(&t, &t, e, Dir::Down, &tab, 2, None)
                .to_rational()
                .expect("finite");
            let hi = bound(&t, &t, e, Dir::Up, &tab, 2, None)
                .to_rational()
                .expect("finite");
            assert!(lo <= truth && truth <= hi, "t = {t}");
            let slo = bound(&t, &t, e, Dir::Down, &swapped, 2, None)
                .to_rational()
                .expect("finite");
            let shi = bound(&t, &t, e, Dir::Up, &swapped, 2, None)
                .to_rational()
                .expect("finite");
            excluded += usize::from(slo > truth || shi < truth);
        }
        assert!(excluded > 0, "control: the exchanged ends still enclose");
    }
}
