//! `log x` and `atan τ` at `q` bits from tables (proofs/B101), for the MPFR energy pass
//! (`log 2t` in the point values of `Л`, the half angles `atan τ`, `0 ≤ τ < 1`):
//!
//! * `x = 2ᵏ·m`, `m ∈ [1, 2)`, `c_j = 1 + j/2¹⁰ ≤ m < c_{j+1}`:
//!   `log x = k·log 2 + log c_j + 2 atanh w`, `w = (m − c_j)/(m + c_j) ∈ [0, 2⁻¹¹)`,
//!   `atanh w = w·Σ_{i≥0} w²ⁱ/(2i+1)`;
//! * `c_j = j/2¹⁰ ≤ τ < c_{j+1}`: `atan τ = atan c_j + atan z`,
//!   `z = (τ − c_j)/(1 + τc_j) ∈ [0, 2⁻¹⁰)`, `atan z = z·Σ_{i≥0} (−z²)ⁱ/(2i+1)`;
//!
//! each series summed by Horner's rule, level `i` at `max(q + 8 − 20i, 64)` bits. A table
//! lookup, one division and about `(q + 8)/20` short multiply-adds replace MPFR's AGM
//! logarithm resp. its `atan` (or B29's `sin_cos`).
//!
//! Accuracy (B101): `log` within `2⁻q·(5.3 + 2.1|k|)` absolutely, `atan` within
//! `5.3·2⁻q·atan τ`; neither is correctly rounded.

use rug::float::{Constant, Round};
use rug::ops::{AddAssignRound, MulAssignRound, NegAssign};
use rug::Float;
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

/// Largest precision with tables: beyond, the series grow long and the tables' `2¹¹` MPFR
/// evaluations costly, and MPFR's `log` and `atan` are used instead (proof: B101).
pub(crate) const MAX_TABLE_BITS: u32 = 1040;

/// Bits of the table index: `2¹⁰` entries `log(1 + j/2¹⁰)` (proof: B101).
const INDEX_BITS: u32 = 10;

/// Bits gained per term of either series: `w² < 2⁻²²`, `z² < 2⁻²⁰` (proof: B101).
const BITS_PER_TERM: u32 = 20;

/// Extra bits of the series' levels and of its truncation (proof: B101).
const SERIES_GUARD_BITS: u32 = 8;

/// The tables of one precision: `log 2`, `log(1 + j/2¹⁰)`, `atan(j/2¹⁰)` and `1/(2i+1)`,
/// all rounded to nearest.
#[derive(Debug)]
pub(crate) struct ElementaryTable {
    /// Precision of every entry and of the result, bits.
    prec: u32,
    /// `log 2`.
    ln2: Float,
    /// `log(1 + j/2¹⁰)`, `j = 0 … 2¹⁰ − 1`.
    logs: Vec<Float>,
    /// `atan(j/2¹⁰)`, `j = 0 … 2¹⁰ − 1`.
    atans: Vec<Float>,
    /// `1/(2i + 1)`, `i = 0 … K`, `K + 1 = ⌈(q + 8)/20⌉` terms.
    inv_odd: Vec<Float>,
}

impl ElementaryTable {
    fn build(prec: u32) -> Self {
        let entries = 1usize << INDEX_BITS;
        let logs = (0..entries)
            .map(|j| {
                let c = Float::with_val(prec, 1) + (Float::with_val(prec, j) >> INDEX_BITS);
                Float::with_val(prec, c.ln_ref())
            })
            .collect();
        let atans = (0..entries)
            .map(|j| {
                let c = Float::with_val(prec, j) >> INDEX_BITS;
                Float::with_val(prec, c.atan_ref())
            })
            .collect();
        let terms = (prec + SERIES_GUARD_BITS).div_ceil(BITS_PER_TERM) as usize;
        let inv_odd = (0..terms)
            .map(|i| Float::with_val(prec, 1) / Float::with_val(prec, 2 * i + 1))
            .collect();
        ElementaryTable {
            prec,
            ln2: Float::with_val(prec, Constant::Log2),
            logs,
            atans,
            inv_odd,
        }
    }

    /// The table for results of `prec` bits, built once per precision and shared.
    pub(crate) fn of_precision(prec: u32) -> Arc<ElementaryTable> {
        static CACHE: OnceLock<Mutex<HashMap<u32, Arc<ElementaryTable>>>> = OnceLock::new();
        let cache = CACHE.get_or_init(|| Mutex::new(HashMap::new()));
        if let Some(t) = cache
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .get(&prec)
        {
            return Arc::clone(t);
        }
        let built = Arc::new(ElementaryTable::build(prec));
        let mut guard = cache
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        Arc::clone(guard.entry(prec).or_insert(built))
    }

    /// The precision of the results, bits.
    pub(crate) fn prec(&self) -> u32 {
        self.prec
    }

    /// `log x` for a finite `x > 0` at this table's precision `q`, within
    /// `2⁻q·(5.3 + 2.1|k|)` absolutely, `k = ⌊log₂ x⌋` (proof: B101); `None` for any other
    /// `x`.
    pub(crate) fn ln(&self, x: &Float) -> Option<Float> {
        if !x.is_finite() || x.cmp0() != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        let q = self.prec;
        // x = m'·2ᵉ, m' ∈ [1/2, 1): m = 2m' ∈ [1, 2), k = e − 1 (m rounded once to q bits).
        let e = x.get_exp()?;
        let mut m = Float::with_val(q, x);
        m >>= e - 1;
        let mut k = i64::from(e) - 1;
        // Rounding to q bits may carry m up to 2 (then m = 2 exactly): halve it.
        if m >= 2 {
            m >>= 1u32;
            k += 1;
        }
        let below = m.to_f64_round(Round::Down);
        let j = (((below - 1.0) * f64::from(1u32 << INDEX_BITS)).floor() as usize)
            .min((1 << INDEX_BITS) - 1);
        let c = 1.0 + j as f64 / f64::from(1u32 << INDEX_BITS);
        // m − c_j is exact: both on the grid 2^(1−q), the difference below 2⁻¹⁰.
        let d = Float::with_val(q, &m - c);
        let s = Float::with_val(q, &m + c);
        let w = Float::with_val(q, &d / &s);
        let v = Float::with_val(q, w.square_ref());
        let series = self.odd_series(&v, false);
        let mut log_m = Float::with_val(q, &w * &series);
        log_m <<= 1u32;
        log_m += &self.logs[j];
        if k == 0 {
            return Some(log_m);
        }
        let mut out = Float::with_val(q, &self.ln2 * k);
        out += &log_m;
        Some(out)
    }

    /// `atan τ` for `0 ≤ τ < 1` at this table's precision `q`, within `5.3·2⁻q·atan τ`
    /// (proof: B101); `None` for any other `τ`.
    pub(crate) fn atan(&self, tau: &Float) -> Option<Float> {
        if tau.is_zero() {
            return Some(Float::new(self.prec));
        }
        if !(tau.is_finite() && *tau > 0 && *tau < 1) {
            return None;
        }
        let q = self.prec;
        let below = tau.to_f64_round(Round::Down);
        let j =
            ((below * f64::from(1u32 << INDEX_BITS)).floor() as usize).min((1 << INDEX_BITS) - 1);
        if j == 0 {
            let t = Float::with_val(q, tau);
            let v = Float::with_val(q, t.square_ref());
            return Some(Float::with_val(q, &t * &self.odd_series(&v, true)));
        }
        let c = j as f64 / f64::from(1u32 << INDEX_BITS);
        // τ − c_j and τ·c_j are exact at q bits when τ has at most q − 10 bits; otherwise
        // each rounds once (B101).
        let num = Float::with_val(q, tau - c);
        let mut den = Float::with_val(q, tau * c);
        den += 1u32;
        let z = Float::with_val(q, &num / &den);
        let v = Float::with_val(q, z.square_ref());
        let mut out = Float::with_val(q, &z * &self.odd_series(&v, true));
        out += &self.atans[j];
        Some(out)
    }

    /// `Σ_{i≤K} (±v)ⁱ/(2i+1)` (minus signs for `alternating`) by Horner's rule, level `i`
    /// at `max(q + 8 − 20i, 64)` bits (proof: B101).
    fn odd_series(&self, v: &Float, alternating: bool) -> Float {
        let q = self.prec;
        let bits = |i: usize| -> u32 {
            let drop = (i as u64).saturating_mul(u64::from(BITS_PER_TERM));
            (u64::from(q + SERIES_GUARD_BITS).saturating_sub(drop)).max(64) as u32
        };
        let last = self.inv_odd.len() - 1;
        let mut acc = Float::with_val(bits(last), &self.inv_odd[last]);
        for i in (0..last).rev() {
            // Raising the precision is exact.
            acc.set_prec(bits(i));
            acc.mul_assign_round(v, Round::Nearest);
            if alternating {
                acc.neg_assign();
            }
            acc.add_assign_round(&self.inv_odd[i], Round::Nearest);
        }
        acc
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// `|got − exact|·2^q` as an `f64` (the error in units of `2⁻q`).
    fn in_units(got: &Float, exact: &Float, q: u32) -> f64 {
        let d = Float::with_val(exact.prec() + 64, got - exact).abs();
        (d << q).to_f64()
    }

    /// Arguments of `log`: random over 2⁻⁶⁰ … 8, exact powers of two, table points and
    /// their neighbours, next to 1 and 2, tiny and huge.
    fn log_arguments(q: u32) -> Vec<Float> {
        let mut rng = ChaCha8Rng::seed_from_u64(101);
        let mut out: Vec<Float> = (0..300)
            .map(|_| {
                let m = Float::with_val(q, rng.gen_range(1.0..2.0));
                let mut x = m + (Float::with_val(q, rng.gen_range(0.0..1.0)) >> 60u32);
                x >>= rng.gen_range(-3..60);
                x
            })
            .collect();
        let ulp = Float::with_val(q, 1) >> (q - 1);
        for j in [1u32, 2, 511, 512, 1023] {
            let c = Float::with_val(q, 1) + (Float::with_val(q, j) >> INDEX_BITS);
            out.push(Float::with_val(q, &c - &ulp));
            out.push(Float::with_val(q, &c + &ulp));
            out.push(c);
        }
        out.push(Float::with_val(q, 1));
        out.push(Float::with_val(q, 1) + &ulp);
        out.push(Float::with_val(q, 2) - &ulp);
        // More bits than q: rounds up to 2 (m = 2 is halved).
        out.push(Float::with_val(2 * q, 2) - (Float::with_val(2 * q, 1) >> (2 * q - 2)));
        out.push(Float::with_val(q, 1) >> 3000u32);
        out.push(Float::with_val(q, 3) << 5000u32);
        out
    }

    #[test]
    fn b101_table_log_within_bound_of_mpfr_log() {
        for q in [80u32, 144, 272, 528, 1040] {
            let tab = ElementaryTable::build(q);
            let mut one_term_rejected = false;
            for x in log_arguments(q) {
                let got = tab.ln(&x).expect("positive finite");
                let exact = Float::with_val(2 * q + 64, x.ln_ref());
                let k = f64::from(x.get_exp().unwrap() - 1).abs();
                let bound = 5.3 + 2.1 * k; // proof: B101
                let err = in_units(&got, &exact, q);
                assert!(err <= bound, "q = {q}, x = {x}: {err} > {bound}");
                assert_eq!(got.prec(), q);
                // Negative control: moved by twice the bound, the same check rejects it.
                let moved = Float::with_val(q + 64, &got) + (Float::with_val(64, 2.0 * bound) >> q);
                assert!(in_units(&moved, &exact, q) > bound);
                // Negative control: atanh w ≈ w (the series cut to its first term) is
                // rejected wherever w is not tiny.
                let m = Float::with_val(q, &x) >> (x.get_exp().unwrap() - 1);
                if m < 2 {
                    let j = (((m.to_f64_round(Round::Down) - 1.0) * 1024.0).floor()) as usize;
                    let c = 1.0 + j as f64 / 1024.0;
                    let w =
                        Float::with_val(q, Float::with_val(q, &m - c) / Float::with_val(q, &m + c));
                    let mut cut = Float::with_val(q, &w << 1u32) + &tab.logs[j];
                    cut += Float::with_val(q, &tab.ln2 * (x.get_exp().unwrap() - 1));
                    one_term_rejected |= in_units(&cut, &exact, q) > bound;
                }
            }
            assert!(
                one_term_rejected,
                "q = {q}: the one-term series went unnoticed"
            );
            // Not in the domain: no value.
            assert!(tab.ln(&Float::with_val(q, 0)).is_none());
            assert!(tab.ln(&Float::with_val(q, -1)).is_none());
            assert!(tab.ln(&Float::with_val(q, f64::NAN)).is_none());
        }
    }

    #[test]
    fn b101_table_atan_within_bound_of_mpfr_atan() {
        let mut rng = ChaCha8Rng::seed_from_u64(1010);
        for q in [80u32, 144, 272, 528, 1040] {
            let tab = ElementaryTable::build(q);
            // τ with at most q − 16 bits, as the pass gives (p bits, q = p + 16).
            let p = q - 16;
            let ulp = Float::with_val(p, 1) >> p;
            let mut taus: Vec<Float> = (0..300)
                .map(|_| {
                    Float::with_val(p, rng.gen_range(0.0..1.0))
                        + (Float::with_val(p, rng.gen_range(0.0..1.0)) >> 60u32)
                })
                .collect();
            for j in [1u32, 2, 511, 512, 1023] {
                let c = Float::with_val(p, j) >> INDEX_BITS;
                taus.push(Float::with_val(p, &c - &ulp));
                taus.push(Float::with_val(p, &c + &ulp));
                taus.push(c);
            }
            taus.push(Float::with_val(p, 1) - &ulp);
            taus.push(Float::with_val(p, 1e-30));
            taus.push(Float::with_val(p, 1) >> 3000u32);
            for tau in taus {
                let got = tab.atan(&tau).expect("0 ≤ τ < 1");
                let exact = Float::with_val(2 * q + 64, tau.atan_ref());
                let rel = |v: &Float| {
                    let d = Float::with_val(2 * q + 64, v - &exact).abs();
                    (Float::with_val(2 * q + 64, d / &exact) << q).to_f64()
                };
                let bound = 5.3; // proof: B101
                let err = rel(&got);
                assert!(err <= bound, "q = {q}, τ = {tau}: {err} > {bound}");
                // Negative control: the table entry alone (atan z dropped) is rejected
                // off the table points, and a value moved by twice the bound everywhere.
                let shift = Float::with_val(q + 64, &got * (2.0 * bound)) >> q;
                let moved = Float::with_val(q + 64, &got + &shift);
                assert!(rel(&moved) > bound);
                let j = (tau.to_f64_round(Round::Down) * 1024.0).floor() as usize;
                let c = Float::with_val(q, j) >> INDEX_BITS;
                if j > 0 && tau != c {
                    assert!(
                        rel(&tab.atans[j]) > bound,
                        "q = {q}, τ = {tau}: table alone passed"
                    );
                }
            }
            assert!(tab.atan(&Float::with_val(q, 1)).is_none());
            assert!(tab.atan(&Float::with_val(q, -0.5)).is_none());
            assert!(tab
                .atan(&Float::with_val(q, 0))
                .is_some_and(|v| v.is_zero()));
        }
    }
}
