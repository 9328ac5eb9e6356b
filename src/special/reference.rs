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
use std::sync::{Arc, Mutex, OnceLock};

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

/// The exact coefficients `Tₙ / ((4ⁿ − 1)(2n+1)!)`, `n = 1…count` (at least), cached
/// and grown by doubling.
fn exact_coefficients(count: usize) -> Arc<Vec<Rational>> {
    static CACHE: OnceLock<Mutex<Arc<Vec<Rational>>>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| Mutex::new(Arc::new(Vec::new())));
    let mut guard = cache
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    if guard.len() >= count {
        return Arc::clone(&guard);
    }
    let t = tangent_numbers(count);
    let mut fact = Integer::from(6); // (2n+1)! for n = 1
    let mut out = Vec::with_capacity(count);
    for (i, tn) in t.iter().enumerate() {
        let n = i as u32 + 1;
        if n > 1 {
            fact *= (2 * n) * (2 * n + 1);
        }
        let four = (Integer::from(1) << (2 * n)) - 1u32;
        out.push(Rational::from((tn.clone(), Integer::from(&fact * &four))));
    }
    *guard = Arc::new(out);
    Arc::clone(&guard)
}

/// The coefficients rounded to precision `prec` (a multiple of 64), cached per precision.
fn coefficients(prec: u32) -> Arc<Vec<Float>> {
    static CACHE: OnceLock<Mutex<HashMap<u32, Arc<Vec<Float>>>>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| Mutex::new(HashMap::new()));
    if let Some(c) = cache
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .get(&prec)
    {
        return Arc::clone(c);
    }
    // Terms shrink by at least 4 per step for |r| ≤ π/2.
    let count = (prec as usize) / 2 + 8;
    let exact = exact_coefficients(count);
    let out: Vec<Float> = exact[..count]
        .iter()
        .map(|q| Float::with_val(prec, q))
        .collect();
    let arc = Arc::new(out);
    cache
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .insert(prec, Arc::clone(&arc));
    arc
}

/// `Л(x)` with a relative error below about `2^(−bits)`, `bits ≥ 53`: reduction
/// `x = k·π/2 + u` at a precision grown until `u` keeps `bits + 40` correct bits, then the
/// Bernoulli series at `bits + 64` bits, directly for even `k` and through the duplication
/// formula `Л(π/2 + u) = Л(2u)/2 − Л(u)` for odd `k` (no cancellation near `π/2`). `None`
/// for a non-finite `x` or one needing more than 2²⁰ bits of π.
pub fn lobachevsky_tangent_series(x: &Float, bits: u32) -> Option<Float> {
    if !x.is_finite() {
        return None;
    }
    let s = (bits + 64).div_ceil(64) * 64;
    if x.is_zero() {
        return Some(Float::new(s));
    }
    let ex = x.get_exp()?.max(0) as u32;
    let mut prec = s + ex;
    loop {
        if prec > 1 << 20 {
            return None;
        }
        let hp = Float::with_val(prec, Constant::Pi) >> 1u32;
        let k = Float::with_val(prec, x / &hp).to_integer()?;
        let u = Float::with_val(prec, x - Float::with_val(prec, &hp * &k));
        // Reduction error ≤ 2^(ex + 2 − prec).
        let eu = if u.is_zero() {
            i32::MIN / 4
        } else {
            u.get_exp()?
        };
        if i64::from(ex) + 2 - i64::from(prec) > i64::from(eu) - i64::from(bits) - 40 {
            prec = prec.saturating_mul(2);
            continue;
        }
        let u = Float::with_val(s, &u);
        if k.is_even() {
            return Some(series(&u, s));
        }
        let two_u = Float::with_val(s, &u << 1u32);
        let half = series(&two_u, s) >> 1u32;
        return Some(half - series(&u, s));
    }
}

fn series(r: &Float, prec: u32) -> Float {
    if r.is_zero() {
        return Float::new(prec);
    }
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
