//! A second, independent evaluation of `Л` for oracles and T30: reduction modulo π and
//! the Bernoulli series
//! `Л(r) = r (1 − log|2r|) + Σ_{n≥1} Tₙ r^{2n+1} / ((4ⁿ − 1)(2n+1)!)`, `|r| ≤ π/2`,
//! with the tangent numbers `Tₙ` (`tan z = Σ Tₙ z^{2n−1}/(2n−1)!`, so
//! `|B₂ₙ| = 2n Tₙ / (4ⁿ (4ⁿ − 1))`) computed exactly by the integer recurrence of
//! Brent and Harvey. It shares no coefficient, expansion or reduction code with the
//! main evaluation (ζ-coefficients, two expansions, reduction mod π/2).

use rug::float::Constant;
use rug::{Float, Integer, Rational};
use std::collections::HashMap;
use std::sync::{Mutex, OnceLock};

/// `T₁ … T_count`, computed exactly (index `n − 1`).
pub fn tangent_numbers(count: usize) -> Vec<Integer> {
    let mut t: Vec<Integer> = vec![Integer::new(); count + 1];
    if count == 0 {
        return Vec::new();
    }
    t[1] = Integer::from(1);
    for k in 2..=count {
        t[k] = Integer::from(&t[k - 1] * (k as u32 - 1));
    }
    for k in 2..=count {
        for j in k..=count {
            let a = Integer::from(&t[j - 1] * (j - k) as u32);
            let b = Integer::from(&t[j] * (j - k + 2) as u32);
            t[j] = a + b;
        }
    }
    t.remove(0);
    t
}

/// Coefficients `Tₙ / ((4ⁿ − 1)(2n+1)!)` at precision `prec` (a multiple of 64), `n = 1…`.
fn coefficients(prec: u32) -> std::sync::Arc<Vec<Float>> {
    static CACHE: OnceLock<Mutex<HashMap<u32, std::sync::Arc<Vec<Float>>>>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| Mutex::new(HashMap::new()));
    let mut guard = cache
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    if let Some(c) = guard.get(&prec) {
        return std::sync::Arc::clone(c);
    }
    // Terms shrink by at least 4 per step for |r| ≤ π/2.
    let count = (prec as usize) / 2 + 8;
    let t = tangent_numbers(count);
    let mut fact = Integer::from(6); // (2n+1)! for n = 1
    let mut out = Vec::with_capacity(count);
    for (i, tn) in t.iter().enumerate() {
        let n = i as u32 + 1;
        if n > 1 {
            fact *= (2 * n) * (2 * n + 1);
        }
        let four = (Integer::from(1) << (2 * n)) - 1u32;
        let q = Rational::from((tn.clone(), fact.clone() * four));
        out.push(Float::with_val(prec, &q));
    }
    let arc = std::sync::Arc::new(out);
    guard.insert(prec, std::sync::Arc::clone(&arc));
    arc
}

/// `Л(x)` with a relative error below about `2^(−bits)`, `bits ≥ 53`, by the Bernoulli
/// series after reduction modulo π at a precision grown until the reduction and the
/// cancellation near `r = ±π/2` leave `bits + 32` correct bits. `None` for a non-finite
/// `x` or one needing more than 2²⁰ bits.
pub fn lobachevsky_tangent_series(x: &Float, bits: u32) -> Option<Float> {
    if !x.is_finite() {
        return None;
    }
    if x.is_zero() {
        return Some(Float::new(bits));
    }
    let ex = x.get_exp()?.max(0) as u32;
    let mut prec = (bits + 64 + ex).div_ceil(64) * 64;
    loop {
        if prec > 1 << 20 {
            return None;
        }
        let pi = Float::with_val(prec, Constant::Pi);
        let k = Float::with_val(prec, x / &pi).to_integer()?;
        let r = Float::with_val(prec, x - Float::with_val(prec, &pi * &k));
        if r.is_zero() {
            prec *= 2;
            continue;
        }
        let er = r.get_exp()?;
        let half_gap = Float::with_val(prec, (Float::with_val(prec, &pi >> 1u32)) - r.clone().abs());
        let eg = half_gap.get_exp().unwrap_or(i32::MIN / 2);
        // Reduction error ≤ 2^(ex + 2 − prec); cancellation near ±π/2 costs −eg bits.
        let lost = (i64::from(ex) + 2 - i64::from(er)).max(0) + i64::from((-eg).max(0));
        if i64::from(prec) < i64::from(bits) + 40 + lost {
            prec = (bits + 64 + lost as u32).div_ceil(64) * 64;
            continue;
        }
        return Some(series(&r, prec));
    }
}

fn series(r: &Float, prec: u32) -> Float {
    let coeffs = coefficients(prec);
    let s = Float::with_val(prec, r.square_ref());
    let mut pow = Float::with_val(prec, &s * r);
    let mut sum = Float::new(prec);
    let limit = r.get_exp().unwrap_or(0) - prec as i32 - 8;
    for c in coeffs.iter() {
        let term = Float::with_val(prec, c * &pow);
        if term.is_zero() || term.get_exp().unwrap_or(i32::MIN) < limit {
            break;
        }
        sum += &term;
        pow *= &s;
    }
    let two_r = Float::with_val(prec, r << 1u32).abs();
    let lead = Float::with_val(prec, 1 - two_r.ln());
    Float::with_val(prec, &lead * r) + sum
}
