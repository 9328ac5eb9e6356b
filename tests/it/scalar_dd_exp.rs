//! `Dd::exp` at the bottom of its range (proof B10): a relative bound down to −669, then
//! an absolute term of one subnormal unit, exact zero below ln 2⁻¹⁰⁷⁵, never negative.

use crate::scalar_dd::{q, u2, uniform, worst};
use crate::support::cases;
use penner::scalar::{Dd, Real};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::{Float, Rational};

/// The smallest positive subnormal, 2⁻¹⁰⁷⁴.
const SUBNORMAL: f64 = f64::from_bits(1);

/// `e^x` at 512 bits (MPFR's exponent range holds it exactly enough down to any `x` here).
fn exp_ref(x: Dd) -> Rational {
    Float::with_val(512, q(x))
        .exp()
        .to_rational()
        .expect("finite")
}

/// `x` near `c`: the double-double `c + δ`, `|δ| ≤ 2⁻ʲ` for a random `j` in `[1, 60]`.
fn around(rng: &mut ChaCha8Rng, c: f64) -> Dd {
    let d = rng.gen_range(-1.0..1.0) * 2f64.powi(-rng.gen_range(1..60));
    Dd::from_f64(c) + Dd::from_f64(d)
}

/// Where the words of the result cross the normal and subnormal thresholds:
/// ln 2⁻⁹⁶⁹ (low word subnormal), ln 2⁻¹⁰²² (high word subnormal), ln 2⁻¹⁰⁷⁴, ln 2⁻¹⁰⁷⁵.
fn thresholds() -> [f64; 4] {
    let ln2 = std::f64::consts::LN_2;
    [-969.0 * ln2, -1022.0 * ln2, -1074.0 * ln2, -1075.0 * ln2]
}

#[test]
fn b10_dd_exp_relative_down_to_minus_669() {
    let mut rng = ChaCha8Rng::seed_from_u64(101);
    let inputs: Vec<Dd> = (0..cases(2000, 100_000))
        .map(|i| match i % 3 {
            0 => uniform(&mut rng, -669.0, -600.0),
            1 => around(&mut rng, -669.0 + 0.5),
            _ => uniform(&mut rng, -669.0, -668.0),
        })
        .filter(|x| x.hi >= -669.0)
        .collect();
    let (max, at) = worst(inputs.iter().copied(), |&x| {
        let r = exp_ref(x);
        ((q(x.exp()) - &r).abs() / r).to_f64() / u2()
    });
    eprintln!("b10 exp on [−669, −600]: max {max:.3} u² at {at:?}");
    assert!(max <= 16.0, "max {max} u² at {at:?}");
}

/// `(|z − eˣ| − 16u²·eˣ) / 2⁻¹⁰⁷⁴`: at most 1 under B10's absolute contract.
fn excess(x: Dd, z: Dd) -> f64 {
    let r = exp_ref(x);
    let rel = Rational::from_f64(16.0 * u2()).expect("finite") * &r;
    let e = (q(z) - &r).abs() - rel;
    (e / Rational::from_f64(SUBNORMAL).expect("finite")).to_f64()
}

fn low_inputs(n: usize) -> Vec<Dd> {
    let mut rng = ChaCha8Rng::seed_from_u64(102);
    let t = thresholds();
    (0..n)
        .map(|i| match i % 3 {
            0 => uniform(&mut rng, -760.0, -669.0),
            1 => around(&mut rng, t[i % 4]),
            _ => uniform(&mut rng, -746.0, -744.0),
        })
        .collect()
}

#[test]
fn b10_dd_exp_absolute_subnormal_unit_below_minus_669() {
    let inputs = low_inputs(cases(3000, 100_000));
    for &x in &inputs {
        let z = x.exp();
        assert!(z.hi >= 0.0 && z.lo.abs() <= z.hi, "exp({x:?}) = {z:?}");
        // Normalized: hi = RN(hi + lo), so |lo| ≤ ulp(hi)/2 with ties to an even hi (a
        // subnormal hi has ulp 2⁻¹⁰⁷⁴, so lo = 0 there).
        assert!(z.hi + z.lo == z.hi, "not normalized: {z:?}");
    }
    let (max, at) = worst(inputs.iter().copied(), |&x| excess(x, x.exp()));
    eprintln!("b10 exp below −669: max excess {max:.3} × 2⁻¹⁰⁷⁴ at {at:?}");
    assert!(max <= 1.0, "max excess {max} × 2⁻¹⁰⁷⁴ at {at:?}");
    // Exact zero below ln 2⁻¹⁰⁷⁵ (the nearest double of eˣ is 0) and for −∞.
    for x in [-745.2, -800.0, -1e300, f64::NEG_INFINITY] {
        assert_eq!(Dd::from_f64(x).exp(), Dd::from_f64(0.0), "exp({x})");
    }
    // The smallest subnormal is reached: e^{ln 2⁻¹⁰⁷⁴} rounds to 2⁻¹⁰⁷⁴.
    let z = Dd::from_f64(thresholds()[2]).exp();
    assert_eq!(z.hi, SUBNORMAL);
}

#[test]
fn b10_negative_control_flush_to_zero_exceeds_subnormal_unit() {
    // An exponential that flushes results below 2⁻¹⁰²² to zero violates the contract.
    let inputs = low_inputs(300);
    let flushed = |x: Dd| {
        let z = x.exp();
        if z.hi < f64::MIN_POSITIVE {
            Dd::from_f64(0.0)
        } else {
            z
        }
    };
    let (max, _) = worst(inputs.iter().copied(), |&x| excess(x, flushed(x)));
    assert!(
        max > 1.0,
        "the check did not reject flush-to-zero (max {max})"
    );
}
