//! Double-double division (proofs B07, B17) against the exact rational quotient.
//!
//! Inputs: random operands over the whole exponent range, and adversarial ones — divisors
//! next to powers of two, quotients next to 1, leading words with all-ones significands,
//! trailing words at ±ulp(hi)/2, operands near the overflow and underflow thresholds.

use crate::scalar_dd::{binary_inputs, near, q, rand_dd, rel_err_u2, worst};
use crate::support::cases;
use penner::scalar::{dd_div_jmp17, Dd};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

/// The bound of B17: `u² + 2⁹u³`, in units of u².
fn b17_bound() -> f64 {
    1.0 + 512.0 * 2f64.powi(-53)
}

/// `2ᵉ` exactly for `−1074 ≤ e ≤ 1023` (`powi` alone overflows in `1/2¹⁰⁷⁰`).
fn p2(e: i32) -> f64 {
    2f64.powi(e / 2) * 2f64.powi(e - e / 2)
}

/// `±m·2ᵉ` with a random sign.
fn signed(rng: &mut ChaCha8Rng, m: f64, e: i32) -> f64 {
    let s = if rng.gen_bool(0.5) { 1.0 } else { -1.0 };
    s * m * p2(e)
}

/// A double-double with leading word `hi` and a trailing word of one of the extreme or
/// random kinds: 0, ±ulp(hi)/2 (renormalized, so ties go to even), or uniform.
fn with_lo(rng: &mut ChaCha8Rng, hi: f64) -> Dd {
    // ulp(hi)/2 = 2^(e − 53) for a normal hi of exponent e.
    let e = ((hi.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    let half_ulp = p2(e - 53);
    let lo = match rng.gen_range(0..4) {
        0 => 0.0,
        1 => half_ulp,
        2 => -half_ulp,
        _ => rng.gen_range(-1.0..1.0) * half_ulp,
    };
    Dd::from_parts(hi, lo)
}

/// A leading word at the top of a binade: all 53 significand bits set.
fn all_ones(rng: &mut ChaCha8Rng, e: i32) -> f64 {
    signed(rng, 2.0 - f64::EPSILON, e)
}

/// Divisors and quotients that stress the correction step, `n` pairs per kind.
fn adversarial(seed: u64, n: usize) -> Vec<(Dd, Dd)> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut v = Vec::with_capacity(8 * n);
    for _ in 0..n {
        // Divisor just below or just above a power of two.
        let e = rng.gen_range(-60..60);
        let k = f64::from(rng.gen_range(0..4));
        let below = signed(&mut rng, 1.0 - (k + 1.0) * f64::EPSILON / 2.0, e);
        let above = signed(&mut rng, 1.0 + k * f64::EPSILON, e);
        let x = rand_dd(&mut rng, -20, 20);
        v.push((x, with_lo(&mut rng, below)));
        let x = rand_dd(&mut rng, -20, 20);
        v.push((x, with_lo(&mut rng, above)));
        // Quotient next to 1 (relative distance 2⁻¹ … 2⁻¹¹⁵), both orders.
        let a = rand_dd(&mut rng, -8, 8);
        let b = near(&mut rng, a);
        v.push((a, b));
        v.push((b, a));
        // All-ones significands with extreme trailing words.
        let (ex, ey) = (rng.gen_range(-30..30), rng.gen_range(-30..30));
        let (hx, hy) = (all_ones(&mut rng, ex), all_ones(&mut rng, ey));
        let x = with_lo(&mut rng, hx);
        let y = with_lo(&mut rng, hy);
        v.push((x, y));
        let h1 = signed(&mut rng, 1.0, ey);
        let y2 = with_lo(&mut rng, h1);
        v.push((x, y2));
        // Huge and tiny exponents (the scaled path), quotient kept in [2⁻⁹⁰⁰, 2¹⁰²⁰].
        let ex = rng.gen_range(-1020..1020);
        let eq = rng.gen_range(-890..1015);
        let ey = (ex - eq).clamp(-1022, 1020);
        let (mx, my) = (rng.gen_range(1.0..2.0), rng.gen_range(1.0..2.0));
        let (hx, hy) = (signed(&mut rng, mx, ex), signed(&mut rng, my, ey));
        let x = with_lo(&mut rng, hx);
        let y = with_lo(&mut rng, hy);
        v.push((x, y));
        // Subnormal divisor or dividend leading word.
        let (ms, es) = (rng.gen_range(1.0..2.0), rng.gen_range(-1070..-1023));
        let sub = signed(&mut rng, ms, es);
        let big = rand_dd(&mut rng, -1000, -900);
        v.push(if rng.gen_bool(0.5) {
            (Dd::from_f64(sub), big)
        } else {
            (big, Dd::from_f64(sub))
        });
    }
    v
}

/// Random pairs (binary_inputs: ordinary, wide exponents, near-cancelling, powers of two)
/// plus the adversarial ones.
fn div_inputs(n: usize) -> Vec<(Dd, Dd)> {
    let mut v = binary_inputs(7, n, false);
    v.extend(adversarial(70, n / 8));
    v
}

/// `|x/y|` lies where B17's relative bound applies.
fn in_b17_range(x: Dd, y: Dd) -> bool {
    let r = (q(x) / q(y)).abs();
    r >= Rational::from((1, rug::Integer::from(1) << 900u32))
        && r <= (rug::Integer::from(1) << 1020u32)
}

fn div_err(x: Dd, y: Dd, f: fn(Dd, Dd) -> Dd) -> f64 {
    rel_err_u2(f(x, y), &(q(x) / q(y)))
}

#[test]
fn b17_dd_div_within_u2_plus_2p9u3() {
    let all = div_inputs(cases(4000, 200_000));
    let inputs: Vec<(Dd, Dd)> = all
        .iter()
        .copied()
        .filter(|&(x, y)| in_b17_range(x, y))
        .collect();
    // Only the widest random exponents leave the range.
    assert!(inputs.len() > all.len() * 9 / 10);
    let (max, at) = worst(inputs.iter().copied(), |&(x, y)| {
        div_err(x, y, |a, b| a / b)
    });
    eprintln!(
        "b17 div: max {max:.4} u² over {} pairs at {at:?}",
        inputs.len()
    );
    // proof: B17 (the proven bound, not the measurement).
    assert!(max <= b17_bound(), "max {max} u² at {at:?}");
}

#[test]
fn b17_negative_control_uncorrected_division_exceeds_bound() {
    // JMP17 Alg. 18 alone (the first step of the division) reaches about 5u² on
    // quotients near 1: the check above rejects it.
    let inputs = adversarial(71, 2000);
    let (max, _) = worst(
        inputs
            .iter()
            .copied()
            .filter(|(x, y)| x.hi.abs().log2().abs() < 100.0 && y.hi.abs().log2().abs() < 100.0),
        |&(x, y)| div_err(x, y, dd_div_jmp17),
    );
    assert!(
        max > b17_bound(),
        "the check did not reject the uncorrected division (max {max} u²)"
    );
}

#[test]
fn b07_jmp17_division_within_9_8u2() {
    // The inner step on operands of moderate exponent (JMP17 assumes no underflow).
    let inputs: Vec<(Dd, Dd)> = div_inputs(cases(4000, 200_000))
        .into_iter()
        .filter(|(x, y)| x.hi.abs().log2().abs() < 400.0 && y.hi.abs().log2().abs() < 400.0)
        .collect();
    let (max, at) = worst(inputs.iter().copied(), |&(x, y)| {
        div_err(x, y, dd_div_jmp17)
    });
    eprintln!("b07 JMP17 Alg. 18: max {max:.3} u² at {at:?}");
    // proof: B07
    assert!(max <= 9.8, "max {max} u² at {at:?}");
}

#[test]
fn b17_dd_div_special_values() {
    let one = Dd::from_f64(1.0);
    let zero = Dd::from_f64(0.0);
    assert_eq!(zero / one, zero);
    assert!((one / zero).hi.is_infinite());
    assert!((zero / zero).hi.is_nan());
    assert_eq!(one / Dd::from_f64(f64::INFINITY), zero);
    assert!((Dd::from_f64(f64::NAN) / one).hi.is_nan());
    // Quotients beyond the range: overflow to ∞, underflow to 0.
    let big = Dd::from_f64(p2(1000));
    let small = Dd::from_f64(p2(-1000));
    assert!((big / small).hi.is_infinite());
    assert_eq!((small / big).hi, 0.0);
    // Exact quotients stay exact across the whole range, including subnormal operands.
    for (x, y) in [
        (3.0 * p2(1015), p2(-3)),
        (p2(-1070), p2(-1060)),
        (-6.0 * p2(-1000), p2(-1072)),
    ] {
        let z = Dd::from_f64(x) / Dd::from_f64(y);
        assert_eq!(q(z), q(Dd::from_f64(x)) / q(Dd::from_f64(y)), "{x:e}/{y:e}");
    }
    // Negative control: a quotient of leading words alone is not exact in the low part.
    let third = one / Dd::from_f64(3.0);
    assert_ne!(q(Dd::from_f64(1.0 / 3.0)), q(third));
}
