//! Series coefficients of `Л`, enclosed with directed rounding and cached per precision
//! (proofs/B52).
//!
//! * around 0: `a_n = ζ(2n) / (n (2n+1) π²ⁿ)`, so that
//!   `Л(t) = t (1 − log|2t|) + Σ_{n≥1} a_n t^{2n+1}` for `|t| < π`;
//! * around π/2: `b_n = (4ⁿ − 1) a_n`, so that
//!   `Л(π/2 + t) = −t (log 2 − Σ_{n≥1} b_n t^{2n})` for `|t| < π/2`.
//!
//! `ζ(2n)` and π come from MPFR rounded down or up, the products and quotients are rounded
//! outward, so `a_lo[n−1] ≤ a_n ≤ a_hi[n−1]` (and likewise `b`) hold exactly.

use rug::float::{Constant, Round};
use rug::Float;
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

/// Enclosures of the coefficients `a_n`, `b_n` (`n = 1…len`) at one precision, with
/// enclosures of π and log 2.
#[derive(Debug)]
pub(crate) struct Table {
    /// Precision of every entry, bits.
    pub prec: u32,
    /// Lower bounds of `a_n`, index `n − 1`.
    pub a_lo: Vec<Float>,
    /// Upper bounds of `a_n`.
    pub a_hi: Vec<Float>,
    /// Lower bounds of `b_n`.
    pub b_lo: Vec<Float>,
    /// Upper bounds of `b_n`.
    pub b_hi: Vec<Float>,
    /// π rounded down and up.
    pub pi: (Float, Float),
    /// log 2 rounded down and up.
    pub ln2: (Float, Float),
    /// The point-evaluation coefficients (`a_lo`, `b_hi`) rounded to nearest at each
    /// precision of [`NEAR_TIERS`] below `prec` (proofs/B28), for MPFR's one- to
    /// three-limb fast paths.
    pub near_tiers: Vec<NearTier>,
}

/// Precisions of the graded Horner levels below the working precision: one bit below one,
/// two and three limbs, where MPFR multiplies and adds operands of equal precision without
/// its general code path (proofs/B28).
pub(crate) const NEAR_TIERS: [u32; 3] = [63, 127, 191];

/// The point-evaluation coefficients at one precision of [`NEAR_TIERS`].
#[derive(Debug)]
pub(crate) struct NearTier {
    /// Bits of every entry.
    pub prec: u32,
    /// `a_lo` rounded to nearest at `prec`.
    pub a: Vec<Float>,
    /// `b_hi` rounded to nearest at `prec`.
    pub b: Vec<Float>,
}

/// Working precisions are rounded up to a multiple of this, so that tables are shared.
pub(crate) const PREC_STEP: u32 = 64;

/// Number of terms for a table of precision `prec`: the tail bound of B52 at the largest
/// ratio `θ ≤ 0.117` used by the evaluation (`|t| ≤ 1.0708` around 0, `|t| ≤ 1/2` around
/// π/2) is below `2^(−prec−8)` with this many terms (`log₂(1/0.117) > 3.09`).
pub(crate) fn terms_for(prec: u32) -> usize {
    ((f64::from(prec) + 8.0) / 3.09).ceil() as usize + 1
}

fn build(prec: u32) -> Table {
    let len = terms_for(prec);
    let pi_lo = Float::with_val_round(prec, Constant::Pi, Round::Down).0;
    let pi_hi = Float::with_val_round(prec, Constant::Pi, Round::Up).0;
    let pi2_lo = Float::with_val_round(prec, pi_lo.square_ref(), Round::Down).0;
    let pi2_hi = Float::with_val_round(prec, pi_hi.square_ref(), Round::Up).0;
    let mut pow_lo = Float::with_val(prec, 1);
    let mut pow_hi = Float::with_val(prec, 1);
    let mut table = Table {
        prec,
        a_lo: Vec::with_capacity(len),
        a_hi: Vec::with_capacity(len),
        b_lo: Vec::with_capacity(len),
        b_hi: Vec::with_capacity(len),
        ln2: (
            Float::with_val_round(prec, Constant::Log2, Round::Down).0,
            Float::with_val_round(prec, Constant::Log2, Round::Up).0,
        ),
        pi: (pi_lo, pi_hi),
        near_tiers: Vec::new(),
    };
    for n in 1..=len as u32 {
        pow_lo = Float::with_val_round(prec, &pow_lo * &pi2_lo, Round::Down).0;
        pow_hi = Float::with_val_round(prec, &pow_hi * &pi2_hi, Round::Up).0;
        let z_lo = Float::with_val_round(prec, Float::zeta_u(2 * n), Round::Down).0;
        let z_hi = Float::with_val_round(prec, Float::zeta_u(2 * n), Round::Up).0;
        let d = n * (2 * n + 1);
        let q_lo = Float::with_val_round(prec, &z_lo / d, Round::Down).0;
        let q_hi = Float::with_val_round(prec, &z_hi / d, Round::Up).0;
        let a_lo = Float::with_val_round(prec, &q_lo / &pow_hi, Round::Down).0;
        let a_hi = Float::with_val_round(prec, &q_hi / &pow_lo, Round::Up).0;
        // (4ⁿ − 1)·a: the shift by 2n bits is exact.
        let (s_lo, s_hi) = (a_lo.clone() << (2 * n), a_hi.clone() << (2 * n));
        let b_lo = Float::with_val_round(prec, &s_lo - &a_lo, Round::Down).0;
        let b_hi = Float::with_val_round(prec, &s_hi - &a_hi, Round::Up).0;
        table.a_lo.push(a_lo);
        table.a_hi.push(a_hi);
        table.b_lo.push(b_lo);
        table.b_hi.push(b_hi);
    }
    table.near_tiers = NEAR_TIERS
        .iter()
        .filter(|&&bits| bits < prec)
        .map(|&bits| NearTier {
            prec: bits,
            a: table
                .a_lo
                .iter()
                .map(|c| Float::with_val(bits, c))
                .collect(),
            b: table
                .b_hi
                .iter()
                .map(|c| Float::with_val(bits, c))
                .collect(),
        })
        .collect();
    table
}

/// The table for working precision `prec` (a multiple of [`PREC_STEP`]), built once per
/// precision and shared.
pub(crate) fn table(prec: u32) -> Arc<Table> {
    static CACHE: OnceLock<Mutex<HashMap<u32, Arc<Table>>>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| Mutex::new(HashMap::new()));
    if let Some(t) = cache
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .get(&prec)
    {
        return Arc::clone(t);
    }
    // Built outside the lock: two threads may build the same table once each.
    let built = Arc::new(build(prec));
    let mut guard = cache
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    Arc::clone(guard.entry(prec).or_insert(built))
}

/// The working precision for a result of `bits` significand bits: `bits + 32` rounded up to
/// a multiple of [`PREC_STEP`].
pub(crate) fn working_precision(bits: u32) -> u32 {
    (bits + 32).div_ceil(PREC_STEP) * PREC_STEP
}

/// Guard bits of `Л` in the MPFR energy pass: the series is evaluated at `bits + 16`
/// bits, within one rounding plus `2⁻¹⁰·2⁻ᵇⁱᵗˢ|Л|` (proof: B100).
pub(crate) const PASS_GUARD_BITS: u32 = 16;

/// The working precision of `Л` in the MPFR energy pass for results of `bits` bits:
/// `bits + PASS_GUARD_BITS`, not rounded to a multiple of [`PREC_STEP`] (proof: B100).
pub(crate) fn pass_working_precision(bits: u32) -> u32 {
    bits.saturating_add(PASS_GUARD_BITS)
}
