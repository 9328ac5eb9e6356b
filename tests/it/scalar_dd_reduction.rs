//! Payne–Hanek reduction of `Dd::sin`/`Dd::cos` (proof B18) against MPFR at 2400 bits,
//! enough to hold every finite double-double exactly (its words span at most 2100 bits).
//!
//! Inputs: random arguments with leading exponents up to 1023 and trailing words of every
//! size, the double-doubles and doubles nearest to `k·π/2` for random `k` up to 10³⁰⁰, and
//! the known hardest double for reduction, 6381956970095103·2⁷⁹⁷, with its neighbours.

use crate::scalar_dd::{q, u2};
use crate::support::cases;
use penner::scalar::{Dd, Real, DD_PI_2_FIXED, DD_TWO_OVER_PI_BITS};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::{Float, Integer, Rational};

/// Reference precision: exact for any double-double input.
const WIDE: u32 = 2400;

/// Floor of the sine/cosine bound on the Payne–Hanek path (proof B18): the reduced
/// argument carries an absolute error ≤ 2⁻²⁵², so `16u²·max(|f(x)|, 2⁻⁹⁰)` holds with a
/// wide margin (16u²·2⁻⁹⁰ = 2⁻¹⁹²).
const PH_FLOOR: f64 = 1.0 / (1u128 << 90) as f64;

/// Floor of the bound on the Cody–Waite path, `|x_h| < 64` (proof B12).
const CW_FLOOR: f64 = 1.0 / (1u64 << 44) as f64;

/// The floor that applies at `x`.
fn floor_at(x: Dd) -> f64 {
    if x.hi.abs() >= 64.0 {
        PH_FLOOR
    } else {
        CW_FLOOR
    }
}

fn wide(x: Dd) -> Float {
    Float::with_val(WIDE, q(x))
}

/// Error of `c ≈ f(x)` in units of u² relative to `max(|f(x)|, floor)`.
fn err(x: Dd, c: Dd, floor: f64, f: fn(Float) -> Float) -> f64 {
    let r = f(wide(x)).to_rational().expect("finite");
    let scale = std::cmp::max(r.clone().abs(), Rational::from_f64(floor).expect("finite"));
    ((q(c) - r).abs() / scale).to_f64() / u2()
}

/// `2ᵉ` exactly for `−1074 ≤ e ≤ 1023`.
fn p2(e: i32) -> f64 {
    2f64.powi(e / 2) * 2f64.powi(e - e / 2)
}

/// A random double-double with leading exponent in `[emin, emax]` and a trailing word that
/// is 0, fills the half-ulp, or sits far below it (a gap between the words).
fn huge(rng: &mut ChaCha8Rng, emin: i32, emax: i32) -> Dd {
    let e = rng.gen_range(emin..=emax);
    let s = if rng.gen_bool(0.5) { 1.0 } else { -1.0 };
    let hi = s * rng.gen_range(1.0..2.0) * p2(e);
    let lo = match rng.gen_range(0..3) {
        0 => 0.0,
        1 => rng.gen_range(-0.5..0.5) * p2(e - 52),
        _ => rng.gen_range(-1.0..1.0) * p2((e - 53 - rng.gen_range(1..400)).max(-1074)),
    };
    Dd::from_parts(hi, lo)
}

/// The double-double and the double nearest to `k·π/2` for a random `k < 2^kbits`.
fn near_multiple(rng: &mut ChaCha8Rng, kbits: u32) -> [Dd; 2] {
    // k ≥ 64: the Payne–Hanek path.
    let bits = rng.gen_range(7..=kbits);
    let limbs = bits / 64 + 1;
    let mut k = Integer::new();
    for _ in 0..limbs {
        k <<= 64u32;
        k += rng.r#gen::<u64>();
    }
    k >>= 64 * limbs - bits;
    k |= Integer::from(1) << (bits - 1);
    let t = Float::with_val(WIDE, rug::float::Constant::Pi) * k / 2u32;
    let s = if rng.gen_bool(0.5) { 1.0 } else { -1.0 };
    let d = Dd::from_float(&t);
    [d * Dd::from_f64(s), Dd::from_f64(d.hi * s)]
}

fn ph_inputs(n: usize) -> Vec<Dd> {
    let mut rng = ChaCha8Rng::seed_from_u64(18);
    let mut v = Vec::with_capacity(n + 64);
    while v.len() < n {
        match v.len() % 4 {
            0 => v.push(huge(&mut rng, 6, 1023)),
            1 => v.push(huge(&mut rng, 6, 120)),
            // Near k·π/2 up to 10³⁰⁰ ≈ 2⁹⁹⁷.
            _ => v.extend(near_multiple(&mut rng, 995)),
        }
    }
    // The hardest double for reduction mod π/2 and its neighbours, alone and with trailing
    // words; the largest finite double.
    let hard = 6381956970095103.0 * p2(797);
    for h in [
        hard,
        next(hard, 1),
        next(hard, -1),
        f64::MAX,
        64.0,
        next(64.0, -1),
    ] {
        for lo in [0.0, 1.0, -0.5, 1e-300] {
            for s in [1.0, -1.0] {
                v.push(Dd::from_parts(s * h, s * lo));
            }
        }
    }
    v
}

/// The `k`-th neighbour of a positive finite double.
fn next(x: f64, k: i64) -> f64 {
    f64::from_bits((x.to_bits() as i64 + k) as u64)
}

#[test]
fn b18_dd_sin_cos_payne_hanek_against_mpfr_2400() {
    let inputs = ph_inputs(cases(600, 100_000));
    let mut worst = [(0.0_f64, Dd::default()); 2];
    for &x in &inputs {
        for (i, (c, f)) in [
            (x.sin(), Float::sin as fn(Float) -> Float),
            (x.cos(), Float::cos),
        ]
        .into_iter()
        .enumerate()
        {
            let e = err(x, c, floor_at(x), f);
            assert!(e <= 16.0, "{} at {x:?}: {e} u²", ["sin", "cos"][i]);
            if e > worst[i].0 {
                worst[i] = (e, x);
            }
        }
    }
    eprintln!(
        "b18 sin: max {:.3} u² at {:?}\nb18 cos: max {:.3} u² at {:?} ({} inputs)",
        worst[0].0,
        worst[0].1,
        worst[1].0,
        worst[1].1,
        inputs.len()
    );
}

#[test]
fn b18_hardest_double_is_reduced_to_full_relative_accuracy() {
    // 6381956970095103·2⁷⁹⁷ lies within about 2⁻⁶¹ of a multiple of π/2: its sine or cosine
    // is that small, and the reduction must keep its relative accuracy.
    let x = Dd::from_f64(6381956970095103.0 * p2(797));
    let (s, c) = (x.sin(), x.cos());
    let small = if s.hi.abs() < c.hi.abs() { s } else { c };
    assert!(small.hi.abs() < p2(-55), "{small:?}");
    let f = if s.hi.abs() < c.hi.abs() {
        Float::sin as fn(Float) -> Float
    } else {
        Float::cos
    };
    let e = err(x, small, 0.0, f);
    assert!(e <= 16.0, "relative error {e} u²");
    // Negative control: the three-double π/2 of the Cody–Waite path is hopeless here.
    let k = (x.hi * std::f64::consts::FRAC_2_PI).round();
    let naive = x.hi - k * std::f64::consts::FRAC_PI_2;
    assert!(err(x, Dd::from_f64(naive), 0.0, f) > 16.0);
}

#[test]
fn b18_two_over_pi_table_matches_mpfr() {
    let pi = Float::with_val(4000, rug::float::Constant::Pi);
    let two_over_pi = Float::with_val(4000, 2u32) / &pi;
    let scaled = (two_over_pi << 1536u32).floor();
    let want = scaled.to_integer().expect("finite");
    let mut got = Integer::new();
    for w in DD_TWO_OVER_PI_BITS {
        got <<= 64u32;
        got += w;
    }
    assert_eq!(got, want);
    let pio2 = (pi << 126u32).floor().to_integer().expect("finite");
    assert_eq!(Integer::from(DD_PI_2_FIXED), pio2);
    // Negative control: one flipped bit deep in the table is caught.
    let mut bad = DD_TWO_OVER_PI_BITS;
    bad[20] ^= 1 << 17;
    let mut got = Integer::new();
    for w in bad {
        got <<= 64u32;
        got += w;
    }
    assert_ne!(got, want);
}

#[test]
fn b18_negative_control_f64_sin_of_huge_arguments_fails() {
    let inputs = ph_inputs(300);
    let max = inputs
        .iter()
        .map(|&x| err(x, Dd::from_f64(x.hi.sin()), PH_FLOOR, Float::sin))
        .fold(0.0, f64::max);
    assert!(
        max > 16.0,
        "the check did not reject the f64 sine (max {max} u²)"
    );
}
