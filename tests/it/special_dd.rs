//! Lobachevsky's function at double-double (B55): the native double-double series
//! against the independent Bernoulli/tangent-number evaluation at more than twice the
//! precision, on double-double arguments with a genuine trailing word.

use crate::support::cases;
use penner::scalar::Dd;
use penner::special::{lobachevsky, lobachevsky_tangent_series};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::float::Constant;
use rug::Float;

/// B55: the double-double evaluation is within this many units of `2^(e−106)` of `Л(x)`.
const DD_ULPS: f64 = 4.0; // proof: B55

/// Negative control of an accuracy test with allowance `allow` units: `y` moved by
/// `3·allow` units up and down is more than `allow` (indeed at least `2·allow − ½`, the
/// half unit for rounding the moved trailing word) from `r`, whichever side of `r` `y` is.
fn assert_bumps_rejected(y: Dd, r: &Float, unit: f64, allow: f64, x: &Dd) {
    for side in [1.0, -1.0] {
        let bumped = Dd::from_parts(y.hi, y.lo + side * 3.0 * allow * unit);
        let moved = dd_ulps(bumped, r);
        assert!(
            moved > allow && moved >= 2.0 * allow - 0.5,
            "control at {x:?}: moved {side:+} by {} units, only {moved} from r",
            3.0 * allow
        );
    }
}

/// `|y − r|` in units of `2^(e−106)`, `r = m·2ᵉ`, `m ∈ [1/2, 1)`; below `2⁻⁹⁶⁸` the unit
/// is `2⁻¹⁰⁷⁵` (a double-double's absolute floor, B09).
fn dd_ulps(y: Dd, r: &Float) -> f64 {
    let yf = Float::with_val(300, y.hi) + y.lo;
    let diff = Float::with_val(600, &yf - r).abs();
    if diff.is_zero() {
        return 0.0;
    }
    let e = r.get_exp().unwrap_or(-1075 + 106);
    (diff >> (e - 106).max(-1075)).to_f64()
}

/// The exact value of a double-double as an MPFR number.
fn exact(x: Dd) -> Float {
    Float::with_val(2200, x.hi) + x.lo
}

/// The double-double nearest to `v`.
fn nearest(v: &Float) -> Dd {
    Dd::from_float(v)
}

/// Double-double arguments: the angles of triangles (0, π), the whole native range
/// `|x| ≤ 3.9` with random trailing words, the reduced-argument boundaries (`2⁻³⁰` from a
/// multiple of π/2, where the MPFR path takes over), the branch points `|t| = 1/2`,
/// `π/4`, tiny, and beyond the native range.
fn arguments(rng: &mut ChaCha8Rng, count: usize) -> Vec<Dd> {
    let hp = Float::with_val(400, Constant::Pi) >> 1u32;
    let mut out = vec![
        Dd::from_f64(0.0),
        nearest(&hp),
        nearest(&Float::with_val(400, &hp * 2u32)),
        nearest(&Float::with_val(400, &hp / 3u32)),
        nearest(&Float::with_val(400, &hp + 0.5)),
        nearest(&Float::with_val(400, &hp - 0.5)),
        Dd::from_f64(3.9),
        Dd::from_f64(4.5),
    ];
    while out.len() < count {
        let lo_word =
            |rng: &mut ChaCha8Rng, hi: f64| hi * 2f64.powi(-54) * rng.gen_range(-1.0..1.0);
        let x = match out.len() % 5 {
            0 => {
                let hi: f64 = rng.gen_range(1e-3..std::f64::consts::PI);
                Dd::from_parts(hi, lo_word(rng, hi))
            }
            1 => {
                let hi: f64 = rng.gen_range(-3.9..3.9);
                Dd::from_parts(hi, lo_word(rng, hi))
            }
            2 => {
                // Next to kπ/2 (k = 1, 2), offsets 2⁻⁴⁰ … 2⁻²: both sides of the 2⁻³⁰ switch.
                let k: u32 = rng.gen_range(1..3);
                let off = Float::with_val(400, rng.gen_range(0.5..1.0)) >> rng.gen_range(2..40u32);
                let v = Float::with_val(400, &hp * k) + if rng.r#gen() { off } else { -off };
                nearest(&v)
            }
            3 => {
                let hi = rng.gen_range(0.5..1.0) * 2f64.powi(-rng.gen_range(1..900));
                Dd::from_parts(hi, lo_word(rng, hi))
            }
            _ => {
                let hi: f64 = rng.gen_range(-40.0..40.0);
                Dd::from_parts(hi, lo_word(rng, hi))
            }
        };
        out.push(if rng.r#gen() { x } else { -x });
    }
    out
}

#[test]
fn b55_dd_within_few_ulps_of_the_tangent_series() {
    let mut rng = ChaCha8Rng::seed_from_u64(100);
    let mut worst = (0.0, 0.0);
    for x in arguments(&mut rng, cases(3000, 100_000)) {
        let y = lobachevsky(&x);
        let r = lobachevsky_tangent_series(&exact(x), 2 * 106 + 16).expect("finite");
        let e = dd_ulps(y, &r);
        if e > worst.0 {
            worst = (e, x.hi);
        }
        assert!(e <= DD_ULPS, "Л({x:?}) = {y:?}: {e} ulps from {r}");
        // Negative control: 3·DD_ULPS units away on either side is rejected by the same
        // measure (at least 2·DD_ULPS from r whatever the sign of y's own error).
        if !r.is_zero() {
            let unit = 2f64.powi((r.get_exp().unwrap_or(0) - 106).max(-1075));
            assert_bumps_rejected(y, &r, unit, DD_ULPS, &x);
        }
    }
    eprintln!("Dd worst {} ulps at {:e}", worst.0, worst.1);
}

/// Arguments beyond the short reduction (`|x| > 3.9`): random magnitudes `2¹ … 2¹⁰²³`
/// with a genuine trailing word, the hardest binary64 case for reduction
/// (`6381956970095103·2⁷⁹⁷`), double-doubles nearest to `nπ/2 ± 2⁻ʲ` for `n` up to `2⁶⁰`
/// (`j = 2 … 95`, both sides of the `2⁻¹⁰⁰` switch to MPFR included), and `2⁻¹⁰⁰⁰`
/// scalings, which stay on the short path.
fn wide_arguments(rng: &mut ChaCha8Rng, count: usize) -> Vec<Dd> {
    let hp = Float::with_val(4000, Constant::Pi) >> 1u32;
    let mut out = vec![
        Dd::from_f64(6381956970095103.0 * 2f64.powi(797)),
        Dd::from_f64(f64::MAX),
        Dd::from_f64(3.9000000000000004),
        Dd::from_parts(2f64.powi(-1000), 2f64.powi(-1060)),
    ];
    while out.len() < count {
        let x = match out.len() % 3 {
            0 => {
                let hi = rng.gen_range(0.5..1.0) * 2f64.powi(rng.gen_range(2..1023));
                Dd::from_parts(hi, hi * 2f64.powi(-54) * rng.gen_range(-1.0..1.0))
            }
            1 => {
                let n: u64 = rng.gen_range(3..1u64 << 60);
                let off = Float::with_val(4000, rng.gen_range(0.5..1.0)) >> rng.gen_range(2..96u32);
                let v = Float::with_val(4000, &hp * n) + if rng.r#gen() { off } else { -off };
                nearest(&v)
            }
            _ => {
                let hi = rng.gen_range(0.5..1.0) * 2f64.powi(-rng.gen_range(900..1000));
                Dd::from_parts(hi, hi * 2f64.powi(-54) * rng.gen_range(-1.0..1.0))
            }
        };
        out.push(if rng.r#gen() { x } else { -x });
    }
    out
}

/// B55 (wide arguments): the Payne–Hanek path adds the reduction's relative error
/// `u²(1 + 2⁻¹⁹)` (B18) to the series' error; measured within this many units.
const DD_WIDE_ULPS: f64 = 5.0; // proof: B55

#[test]
fn b55_dd_wide_arguments_reduced_by_payne_hanek() {
    let mut rng = ChaCha8Rng::seed_from_u64(55);
    let mut worst = (0.0, 0.0);
    for x in wide_arguments(&mut rng, cases(600, 20_000)) {
        let y = lobachevsky(&x);
        let r = lobachevsky_tangent_series(&exact(x), 2 * 106 + 16).expect("finite");
        let e = dd_ulps(y, &r);
        if e > worst.0 {
            worst = (e, x.hi);
        }
        assert!(e <= DD_WIDE_ULPS, "Л({x:?}) = {y:?}: {e} ulps from {r}");
        // Negative control: the value moved by 3·DD_WIDE_ULPS units up and down (at least
        // that many subnormal steps where the unit is below the smallest binary64) is
        // rejected by the same measure whatever the sign of its own error.
        if !r.is_zero() {
            // 2^k exactly, also below 2⁻¹⁰²² (`powi` underflows through 1/2^|k| there).
            let k = (r.get_exp().unwrap_or(0) - 106).max(-1075);
            let unit = (Float::with_val(64, 1u32) << k).to_f64();
            assert_bumps_rejected(y, &r, unit.max(f64::from_bits(1)), DD_WIDE_ULPS, &x);
        }
    }
    eprintln!("Dd wide worst {} ulps at {:e}", worst.0, worst.1);
}
