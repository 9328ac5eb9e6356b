//! Lobachevsky's function `Л(x) = −∫₀ˣ log|2 sin t| dt = ½ Cl₂(2x)` (docs/catalogue.md §7), generic
//! over [`Real`].
//!
//! Reduction `x = k·π/2 + t` with enough bits of π that `t` keeps its relative accuracy
//! (an adaptive precision, so also for `x` next to a multiple of π), then one of two series
//! (proofs/B52):
//! `Л(t) = t (1 − log|2t| + Σ aₙ t²ⁿ)`, `aₙ = ζ(2n)/(n(2n+1)π²ⁿ)`, for even `k` (and for odd
//! `k` with `|t| > 1/2`, after `t ↦ t ∓ π/2`), and
//! `Л(π/2 + t) = −t (log 2 − Σ (4ⁿ − 1) aₙ t²ⁿ)` for odd `k`, `|t| ≤ 1/2`; each converges
//! at least 8.5× per term. The coefficients are enclosed in MPFR once per precision.
//!
//! Per backend: `f64` has a dedicated binary64 path (B53); `Dd` a double-double path for
//! every finite argument (B55, Payne–Hanek beyond `|x| ≤ 3.9`); `Mpfr` (and `Dd` within
//! `2⁻³⁰`, resp. `2⁻¹⁰⁰`, of a multiple of π/2) evaluate in MPFR at `p + 32..p + 95`
//! bits and round once; `Dual<T>` adds the derivative
//! `Л′(x) = −log|2 sin x|`; `Interval<Mpfr>` and `Interval<f64>` return the rigorous
//! enclosure of [`lobachevsky_enclosure`](super::lobachevsky_enclosure).
//!
//! ```
//! use penner::special::lobachevsky;
//! // Л(π/6) = (3/2)·Л(π/3) and Л(π/2) = 0.
//! let a = lobachevsky(&(std::f64::consts::PI / 6.0));
//! let b = lobachevsky(&(std::f64::consts::PI / 3.0));
//! assert!((a - 1.5 * b).abs() < 1e-15);
//! assert!(lobachevsky(&std::f64::consts::FRAC_PI_2).abs() < 1e-16);
//! ```

use super::coefficients::{pass_working_precision, table, working_precision, Table};
use super::elementary_table::{ElementaryTable, MAX_TABLE_BITS};
use super::enclosure::lobachevsky_enclosure;
use super::eval::{point, point_in};
use super::fast_dd::lobachevsky_dd;
use super::fast_f64::lobachevsky_f64;
use crate::scalar::{Dd, Interval, Mpfr, Precision, Real};
use rug::{Float, Rational};
use std::any::Any;
use std::sync::Arc;

/// `Some(b)` when `A` and `B` are the same type.
fn cast<A: 'static, B: 'static + Clone>(a: &A) -> Option<B> {
    (a as &dyn Any).downcast_ref::<B>().cloned()
}

/// NaN (or the invalid interval) in the context of `x`.
fn nan_like<T: Real>(x: &T) -> T {
    x.zero_like() / x.zero_like()
}

/// An exact MPFR copy of a binary rational `q = m/2ᵏ` (any other `q` rounded to 256 bits).
fn exact_float(q: &Rational) -> Float {
    let bits = q.numer().significant_bits().max(53);
    Float::with_val(bits, q)
}

/// `Л(x)` for an `f64`: the binary64 path, or MPFR rounded once when it declines.
#[inline]
fn lobachevsky_f64_any(x: f64) -> f64 {
    if let Some(y) = lobachevsky_f64(x) {
        return y;
    }
    if !x.is_finite() {
        return f64::NAN;
    }
    match point(&Float::with_val(53, x), 53) {
        Some((v, _, _)) => v.to_f64(),
        None => f64::NAN,
    }
}

fn interval_f64(x: &Interval<f64>) -> Interval<f64> {
    let p = Precision::new(64).unwrap_or_else(|_| unreachable!("64 bits is in range"));
    if !x.is_valid() {
        return Interval::invalid(());
    }
    let xi = Interval::new(Mpfr::from_f64(*x.lo(), p), Mpfr::from_f64(*x.hi(), p));
    let y = lobachevsky_enclosure(&xi);
    if !y.is_valid() {
        return Interval::invalid(());
    }
    y.to_f64_outward()
}

/// `Л(x)`, Lobachevsky's function (docs/catalogue.md §7): odd, π-periodic, `Л(π/2) = 0`,
/// `Л′(x) = −log|2 sin x|`, `Л(x) ≈ x(1 − log|2x|)` near 0; the maximum is
/// `Л(π/6) = 0.50747080…`.
///
/// Accuracy (proofs/B52, B53, B55): `f64` within a few ulps (measured), `Dd` within 4
/// units of `2⁻¹⁰⁶` for `|x| ≤ 3.9` and 5 beyond (measured), `Dd` next to multiples of
/// π/2 and `Mpfr`-p within
/// one ulp plus `2⁻³⁰` ulp, for every finite argument whose reduction needs at most 2²⁰
/// bits of π (otherwise NaN). On `Interval<Mpfr>` / `Interval<f64>` the result is a
/// rigorous enclosure; on `Dual<T>` the derivative part is `d·Л′(v)` (second order exact
/// for nested duals).
pub fn lobachevsky<T: Real>(x: &T) -> T {
    if let Some(v) = cast::<T, f64>(x) {
        return cast::<f64, T>(&lobachevsky_f64_any(v)).unwrap_or_else(|| nan_like(x));
    }
    if let Some(v) = cast::<T, Dd>(x) {
        if let Some(y) = lobachevsky_dd(v) {
            return cast::<Dd, T>(&y).unwrap_or_else(|| nan_like(x));
        }
    }
    if let Some(v) = cast::<T, Mpfr>(x) {
        let y = Mpfr(MpfrLobachevsky::new(Mpfr::precision_bits(v.ctx())).eval(&v.0));
        return cast::<Mpfr, T>(&y).unwrap_or_else(|| nan_like(x));
    }
    if let Some(v) = cast::<T, Interval<Mpfr>>(x) {
        return cast::<Interval<Mpfr>, T>(&lobachevsky_enclosure(&v))
            .unwrap_or_else(|| nan_like(x));
    }
    if let Some(v) = cast::<T, Interval<f64>>(x) {
        return cast::<Interval<f64>, T>(&interval_f64(&v)).unwrap_or_else(|| nan_like(x));
    }
    if let Some(y) = super::dual_fast::lobachevsky_dual(x, lobachevsky::<f64>, lobachevsky::<Dd>) {
        return y;
    }
    let ctx = x.ctx();
    let Some(a) = x.to_rational() else {
        return nan_like(x);
    };
    let bits = T::precision_bits(ctx);
    let Some((value, t, odd)) = point(&exact_float(&a), bits) else {
        return nan_like(x);
    };
    let y = T::from_rational(&value.to_rational().unwrap_or_default(), ctx);
    let plain = (x as &dyn Any).is::<Mpfr>() || (x as &dyn Any).is::<Dd>();
    if plain {
        return y;
    }
    // Dual numbers: h = x − a carries the derivative parts (value 0);
    // Л(a + h) = Л(a) + h·Л′(a + h/2) up to h³, Л′(a + s) = −log|2 sin(t + s)| or
    // −log|2 cos(t + s)| for even or odd k.
    let h = x.clone() - &T::from_rational(&a, ctx);
    let half = h.clone() * &x.lit(0.5);
    let arg = T::from_rational(&t.to_rational().unwrap_or_default(), ctx) + &half;
    let trig = if odd { arg.cos() } else { arg.sin() };
    let deriv = -(trig * &x.lit(2.0)).abs().ln();
    y + &(h * &deriv)
}

/// `Л` on MPFR numbers of one precision, its series table looked up once: the numbers of
/// [`lobachevsky`] on [`Mpfr`] (one ulp plus `2⁻³⁰` ulp, proof: B52), for passes that
/// evaluate it many times.
pub(crate) struct MpfrLobachevsky {
    bits: u32,
    table: Arc<Table>,
    /// The table logarithm of the energy pass (B101), `None` for MPFR's `log`.
    ln: Option<Arc<ElementaryTable>>,
}

impl MpfrLobachevsky {
    /// For results of `bits` bits.
    pub(crate) fn new(bits: u32) -> Self {
        MpfrLobachevsky {
            bits,
            table: table(working_precision(bits)),
            ln: None,
        }
    }

    /// For results of `bits` bits in the MPFR energy pass: the series at `q = bits + 16`
    /// bits instead of [`lobachevsky`]'s `bits + 32..bits + 95`, and `log 2t` from a table
    /// (B101, up to `q = 1040`) instead of MPFR's `log`; within one rounding plus `2⁻¹⁰` of
    /// `2⁻ᵇⁱᵗˢ|Л|` (proof: B100).
    pub(crate) fn for_energy_pass(bits: u32) -> Self {
        let q = pass_working_precision(bits);
        MpfrLobachevsky {
            bits,
            table: table(q),
            ln: (q <= MAX_TABLE_BITS).then(|| ElementaryTable::of_precision(q)),
        }
    }

    /// The tables of the energy pass's logarithm and arctangent (B101), `None` for
    /// [`MpfrLobachevsky::new`].
    pub(crate) fn elementary(&self) -> Option<&ElementaryTable> {
        self.ln.as_deref()
    }

    /// `Л(x)` rounded once to the precision of this evaluator, NaN where `x` is not finite
    /// or its reduction does not resolve. The stored number is exact: it is evaluated on
    /// directly (the generic path of [`lobachevsky`] without its rational round trips).
    pub(crate) fn eval(&self, x: &Float) -> Float {
        let found = if x.is_finite() {
            point_in(x, &self.table, self.ln.as_deref())
        } else {
            None
        };
        match found {
            Some((value, _, _)) => Float::with_val(self.bits, &value),
            None => Float::with_val(self.bits, f64::NAN),
        }
    }
}

/// Clausen's function `Cl₂(θ) = Σ_{k≥1} sin(kθ)/k² = 2 Л(θ/2)` (docs/catalogue.md §7).
pub fn clausen2<T: Real>(theta: &T) -> T {
    let half = theta.clone() * &theta.lit(0.5);
    lobachevsky(&half) * &theta.lit(2.0)
}

/// Volume `Л(α) + Л(β) + Л(γ)` of the ideal hyperbolic tetrahedron with dihedral angles
/// `α, β, γ`, `α + β + γ = π` (Milnor; docs/catalogue.md §7). The regular one (`α = β = γ = π/3`)
/// has the largest volume, `3Л(π/3) = 1.01494160640965362502…`.
pub fn ideal_tetrahedron_volume<T: Real>(alpha: &T, beta: &T, gamma: &T) -> T {
    lobachevsky(alpha) + &lobachevsky(beta) + &lobachevsky(gamma)
}

#[cfg(test)]
mod tests {
    use super::super::reference::lobachevsky_tangent_series;
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// `|y − Л(x)| / (2⁻ᵖ|Л(x)|)` against the tangent-number series at `2p + 64` bits.
    fn relative_units(y: &Float, x: &Float, p: u32) -> f64 {
        let r = lobachevsky_tangent_series(x, 2 * p + 64).expect("reducible");
        let w = 2 * p + 128;
        let d = Float::with_val(w, y - &r).abs();
        if d.is_zero() {
            return 0.0;
        }
        (Float::with_val(w, d / r.abs()) << p).to_f64()
    }

    /// Angles of a face and their neighbourhoods: random in (0, π), next to 0, π/2 and π
    /// (closer than 2⁻ᵖ), at the switches of the two series (π/2 ± 1/2) and at π/4, π/6.
    fn angles(p: u32) -> Vec<Float> {
        let mut rng = ChaCha8Rng::seed_from_u64(100);
        let pi = Float::with_val(2 * p, rug::float::Constant::Pi);
        let mut out: Vec<Float> = (0..400)
            .map(|_| {
                Float::with_val(p, rng.gen_range(1e-6..std::f64::consts::PI))
                    + (Float::with_val(p, rng.gen_range(0.0..1.0)) >> 60u32)
            })
            .collect();
        for (num, den) in [(1u32, 2u32), (1, 4), (1, 6), (5, 6), (1, 1)] {
            let c = Float::with_val(2 * p, &pi * num) / den;
            for k in [-3i32, 0, 3] {
                let off = Float::with_val(p, k) >> (p + 4);
                out.push(Float::with_val(p, &c + &off));
            }
        }
        let half_pi = Float::with_val(p, &pi >> 1u32);
        for s in [-0.5, 0.5] {
            let c = Float::with_val(p, &half_pi + s);
            let ulp = Float::with_val(p, 1) >> p;
            out.push(Float::with_val(p, &c - &ulp));
            out.push(Float::with_val(p, &c + &ulp));
            out.push(c);
        }
        out.extend([1e-3, 1e-30].map(|v| Float::with_val(p, v)));
        out.push(Float::with_val(p, 1) >> 2000u32);
        out
    }

    #[test]
    fn b100_energy_pass_lobachevsky_within_one_rounding_of_tangent_series() {
        for p in [53u32, 128, 256, 512] {
            let pass = MpfrLobachevsky::for_energy_pass(p);
            let coarse = MpfrLobachevsky::for_energy_pass(p - 12);
            let bound = 1.0 + 1.0 / 1024.0; // proof: B100
            let mut coarse_rejected = false;
            for x in angles(p) {
                let y = pass.eval(&x);
                assert_eq!(y.prec(), p);
                let e = relative_units(&y, &x, p);
                assert!(e <= bound, "p = {p}: Л({x}) off by {e}·2⁻ᵖ|Л|");
                // Negative control: a change of two units of 2⁻ᵖ|Л| is rejected.
                let shift = Float::with_val(p + 64, &y * 2u32) >> p;
                let moved = Float::with_val(p + 64, &y + &shift);
                assert!(y.is_zero() || relative_units(&moved, &x, p) > bound);
                // Negative control: the pass's evaluation at 12 bits less is rejected
                // somewhere on the grid.
                coarse_rejected |= relative_units(&coarse.eval(&x), &x, p) > bound;
            }
            assert!(coarse_rejected, "p = {p}: 12 bits less went unnoticed");
        }
    }

    #[test]
    fn b100_energy_pass_lobachevsky_uses_the_table_logarithm() {
        // The pass's evaluator carries the tables (B101) at p + 16 bits; the generic one
        // does not, so its numbers stay those of `lobachevsky`.
        let pass = MpfrLobachevsky::for_energy_pass(256);
        assert_eq!(pass.table.prec, 272);
        assert!(pass.elementary().is_some_and(|t| t.prec() == 272));
        let generic = MpfrLobachevsky::new(256);
        assert!(generic.elementary().is_none());
        assert_eq!(generic.table.prec, 320);
        let x = Float::with_val(256, 0.7);
        assert_eq!(generic.eval(&x), lobachevsky(&Mpfr(x.clone())).0);
        // Beyond the tables' range the pass keeps MPFR's log.
        assert!(MpfrLobachevsky::for_energy_pass(2048)
            .elementary()
            .is_none());
    }
}
