//! Double-double at the ends of the binary64 exponent range (proofs B04–B14, B17): inputs
//! and results between 2⁻¹⁰⁷⁴ and 2⁻⁹⁰⁰ (trailing words subnormal, leading words subnormal
//! at the bottom), between 2⁹⁰⁰ and the overflow threshold, `exp` arguments in
//! `[−745, −700]` and `[700, 709.8]`, logarithms of subnormals.
//!
//! Every returned pair must be normalized (`hi = RN(hi + lo)`, finite `lo`), and every
//! finite result must meet `|z − f| ≤ ε·|f| + η·2⁻¹⁰⁷⁴`: the relative bound ε of the
//! operation's proof plus, where the trailing word of a result below 2⁻⁹⁶⁸ can only hold
//! multiples of 2⁻¹⁰⁷⁴, an absolute term η (0 where every result has a normal trailing
//! word). References are MPFR at 512 bits of the exact input value, or exact in ℚ.

use crate::scalar_dd::{fl, mixed_err, q, u2, worst};
use crate::support::cases;
use penner::scalar::{Dd, Real};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::{Float, Rational};

/// The smallest positive subnormal, 2⁻¹⁰⁷⁴.
const SUBNORMAL: f64 = f64::from_bits(1);

/// `2ᵉ` exactly for `−1074 ≤ e ≤ 1023`.
fn p2(e: i32) -> f64 {
    2f64.powi(e / 2) * 2f64.powi(e - e / 2)
}

/// `ulp(x)` of a finite `x` (2⁻¹⁰⁷⁴ for subnormals and zero).
fn ulp(x: f64) -> f64 {
    let e = ((x.to_bits() >> 52) & 0x7ff) as i32;
    if e <= 1 {
        SUBNORMAL
    } else {
        p2(e - 1023 - 52)
    }
}

/// A normalized double-double `±m·2ᵉ`, `m ∈ [1, 2)`, `e` uniform in `[emin, emax]`
/// (leading word subnormal below −1022), with a trailing word as in [`with_lo`].
fn edge_dd(rng: &mut ChaCha8Rng, emin: i32, emax: i32) -> Dd {
    let e = rng.gen_range(emin..=emax);
    let s = if rng.gen_bool(0.5) { 1.0 } else { -1.0 };
    let hi = s * rng.gen_range(1.0..2.0) * p2(e);
    with_lo(rng, hi)
}

/// `hi` with a trailing word that is zero, `±ulp(hi)/2` (a tie, renormalized to even) or
/// uniform in the half-ulp, rounded to the binary64 grid.
fn with_lo(rng: &mut ChaCha8Rng, hi: f64) -> Dd {
    let half = ulp(hi) / 2.0;
    let lo = match rng.gen_range(0..8) {
        0 => 0.0,
        1 => half,
        2 => -half,
        _ => rng.gen_range(-1.0..1.0) * half,
    };
    Dd::from_parts(hi, lo)
}

/// Positive [`edge_dd`].
fn edge_pos(rng: &mut ChaCha8Rng, emin: i32, emax: i32) -> Dd {
    edge_dd(rng, emin, emax).abs()
}

/// The double-double invariant: `lo` finite and `hi = RN(hi + lo)` (so `|lo| ≤ ulp(hi)/2`,
/// ties to even); a NaN leading word carries no invariant.
fn normalized(z: Dd) -> bool {
    z.hi.is_nan() || (z.lo.is_finite() && z.hi + z.lo == z.hi)
}

/// `ε·|f| + η·2⁻¹⁰⁷⁴` with `ε = eps_u2·u²`, exactly (η·2⁻¹⁰⁷⁴ itself may not be a double).
fn allowed(f: &Rational, eps_u2: f64, eta: f64) -> Rational {
    Rational::from_f64(eps_u2 * u2()).expect("finite") * f.clone().abs()
        + (Rational::from_f64(eta).expect("finite") >> 1074u32)
}

/// `|z − f| / (ε·|f| + η·2⁻¹⁰⁷⁴)` with `ε = eps_u2·u²` (∞ for a non-finite `z`).
fn bound_ratio(z: Dd, f: &Rational, eps_u2: f64, eta: f64) -> f64 {
    let Some(zq) = z.to_rational() else {
        return f64::INFINITY;
    };
    let allowed = allowed(f, eps_u2, eta);
    if allowed == 0 {
        return if zq == *f { 0.0 } else { f64::INFINITY };
    }
    ((zq - f).abs() / allowed).to_f64()
}

/// `z` moved away from `f` by `k` times the allowed error (the negative control of
/// [`bound_ratio`]), as the double-double nearest to the moved value.
fn perturbed(z: Dd, f: &Rational, eps_u2: f64, eta: f64, k: f64) -> Dd {
    let allowed = allowed(f, eps_u2, eta);
    let moved = q(z) + allowed * Rational::from_f64(k).expect("finite");
    Dd::from_rational(&moved, ())
}

/// `2¹⁰²⁴ − 2⁹⁷⁰`: from here on the nearest binary64 is +∞ (IEEE overflow under
/// round-to-nearest), and no normalized double-double is finite.
fn overflow_threshold() -> Rational {
    Rational::from(rug::Integer::from(1) << 1024) - Rational::from(rug::Integer::from(1) << 970)
}

/// Checks one result: normalized, and within `ε|f| + η·2⁻¹⁰⁷⁴` when `|f|` is below the
/// overflow threshold, `±∞` of the sign of `f` above it. Returns the bound ratio (0 for an
/// overflow). Panics naming the case otherwise.
fn check(what: &str, z: Dd, f: &Rational, eps_u2: f64, eta: f64) -> f64 {
    assert!(normalized(z), "{what}: not normalized: {z:?}");
    if f.clone().abs() >= overflow_threshold() {
        let inf = if *f > 0 {
            f64::INFINITY
        } else {
            f64::NEG_INFINITY
        };
        assert_eq!(z.hi, inf, "{what}: {z:?} for an overflowing result");
        return 0.0;
    }
    bound_ratio(z, f, eps_u2, eta)
}

/// The reference `f(x)` at 512 bits as an exact rational.
fn reference(x: Dd, f: impl Fn(Float) -> Float) -> Rational {
    f(fl(x)).to_rational().expect("finite reference")
}

/// Runs [`check`] over `inputs`, asserts the maximum ratio ≤ 1, and returns it; on the
/// first 64 cases, also checks that a result moved by 4× the allowed error, or
/// with its trailing word pushed past ulp(hi)/2, is rejected.
fn assert_within<I: std::fmt::Debug + Copy>(
    what: &str,
    inputs: &[I],
    eval: impl Fn(I) -> (Dd, Rational),
    eps_u2: f64,
    eta: f64,
) -> f64 {
    let (max, at) = worst(inputs.iter().copied(), |&x| {
        let (z, f) = eval(x);
        check(&format!("{what}({x:?})"), z, &f, eps_u2, eta)
    });
    eprintln!("{what} at the range edges: max {max:.3} of the bound at {at:?}");
    assert!(max <= 1.0, "{what}: {max} × the bound at {at:?}");
    // Negative controls on the same cases: the checks reject a wrong result.
    let mut rejected = 0;
    for &x in inputs.iter().take(64) {
        let (z, f) = eval(x);
        if !z.hi.is_finite() || f == 0 {
            continue;
        }
        let bad = perturbed(z, &f, eps_u2, eta, 4.0);
        if bad.hi.is_finite() && q(bad) != q(z) {
            assert!(
                bound_ratio(bad, &f, eps_u2, eta) > 1.0,
                "{what}: control {bad:?} accepted for {x:?}"
            );
            rejected += 1;
        }
        let h = ulp(z.hi);
        let unnormal = Dd { hi: z.hi, lo: h };
        assert!(
            !normalized(unnormal),
            "{what}: {unnormal:?} passed as normalized"
        );
    }
    assert!(rejected > 0, "{what}: no negative control ran");
    max
}

// ------------------------------------------------------------------------------ sqrt

fn sqrt_inputs(n: usize) -> Vec<Dd> {
    let mut rng = ChaCha8Rng::seed_from_u64(801);
    (0..n)
        .map(|i| match i % 3 {
            0 => edge_pos(&mut rng, -1074, -900),
            1 => edge_pos(&mut rng, 900, 1023),
            // Around the bottom of the direct range.
            _ => edge_pos(&mut rng, -1000, -940),
        })
        .collect()
}

#[test]
fn b08_dd_sqrt_relative_at_range_edges() {
    // Every square root of a positive finite double-double lies in [2⁻⁵³⁷, 2⁵¹²): normal
    // with a normal trailing word, so the bound is purely relative (η = 0).
    let inputs = sqrt_inputs(cases(1500, 100_000));
    assert_within(
        "sqrt",
        &inputs,
        |x| (x.sqrt(), reference(x, Float::sqrt)),
        4.0,
        0.0,
    );
}

// ------------------------------------------------------------------------------- exp

fn exp_inputs(n: usize) -> Vec<Dd> {
    let mut rng = ChaCha8Rng::seed_from_u64(1001);
    let ln2 = std::f64::consts::LN_2;
    (0..n)
        .map(|i| match i % 4 {
            0 => crate::scalar_dd::uniform(&mut rng, -745.0, -700.0),
            1 => crate::scalar_dd::uniform(&mut rng, 700.0, 709.8),
            // Where the result crosses 2ᵏ for k from −1075 to −969 (trailing word
            // subnormal) and near the overflow threshold ln(2¹⁰²⁴) ≈ 709.78.
            2 => {
                let k = f64::from(rng.gen_range(-1075..=-969));
                Dd::from_f64(k * ln2) + Dd::from_f64(rng.gen_range(-0.5..0.5))
            }
            _ => {
                let d = rng.gen_range(-1.0..1.0) * 2f64.powi(-rng.gen_range(1..50));
                Dd::from_f64(1024.0 * ln2) + Dd::from_f64(d)
            }
        })
        .collect()
}

#[test]
fn b10_dd_exp_normalized_and_bounded_at_range_edges() {
    let inputs = exp_inputs(cases(2000, 100_000));
    assert_within(
        "exp",
        &inputs,
        |x| (x.exp(), reference(x, Float::exp)),
        16.0,
        1.0,
    );
}

// -------------------------------------------------------------------------------- ln

#[test]
fn b11_dd_ln_relative_at_range_edges() {
    // |ln x| ≥ 623 on these inputs: the bound is purely relative.
    let mut rng = ChaCha8Rng::seed_from_u64(1101);
    let inputs: Vec<Dd> = (0..cases(1500, 100_000))
        .map(|i| match i % 2 {
            0 => edge_pos(&mut rng, -1074, -900),
            _ => edge_pos(&mut rng, 900, 1023),
        })
        .collect();
    assert_within(
        "ln",
        &inputs,
        |x| (x.ln(), reference(x, Float::ln)),
        16.0,
        0.0,
    );
}

// ------------------------------------------------------------------ + − × ÷ on pairs

/// Pairs whose results, or whose operands, sit at the ends of the range.
fn edge_pairs(seed: u64, n: usize) -> Vec<(Dd, Dd)> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..n)
        .map(|i| match i % 6 {
            // Products and quotients down to the subnormals.
            0 => (edge_dd(&mut rng, -600, -450), edge_dd(&mut rng, -600, -450)),
            1 => (edge_dd(&mut rng, -1074, -900), edge_dd(&mut rng, -80, 80)),
            // Operands at opposite ends, results moderate (products) or extreme (quotients).
            2 => (edge_dd(&mut rng, -1074, -900), edge_dd(&mut rng, 900, 1023)),
            // Products and quotients up to the overflow threshold.
            3 => (edge_dd(&mut rng, 450, 530), edge_dd(&mut rng, 450, 530)),
            4 => (edge_dd(&mut rng, 900, 1023), edge_dd(&mut rng, -80, 80)),
            // Sums with cancellation at both ends.
            _ => {
                let (lo, hi) = if rng.gen_bool(0.5) {
                    (-1074, -900)
                } else {
                    (900, 1023)
                };
                let a = edge_dd(&mut rng, lo, hi);
                // −b within a relative 2⁻ᵏ of a (formed in f64, |b_h| ≤ |a_h|).
                let d = -rng.gen_range(0.0..1.0) * 2f64.powi(-rng.gen_range(1..60));
                let b = with_lo(&mut rng, -a.hi * (1.0 + d));
                (a, b)
            }
        })
        .collect()
}

#[test]
fn b04_dd_add_sub_at_range_edges() {
    let inputs = edge_pairs(401, cases(3000, 120_000));
    assert_within("add", &inputs, |(a, b)| (a + b, q(a) + q(b)), 4.0, 0.0);
    assert_within("sub", &inputs, |(a, b)| (a - (-b), q(a) + q(b)), 4.0, 0.0);
    // Two operands of the same sign near the top overflow to ±∞.
    let max = Dd::from_f64(f64::MAX);
    assert_eq!((max + max).hi, f64::INFINITY);
    assert_eq!((-max - max).hi, f64::NEG_INFINITY);
}

#[test]
fn b03_b05_dd_with_f64_at_range_edges() {
    let inputs = edge_pairs(301, cases(3000, 120_000));
    assert_within(
        "add_f64",
        &inputs,
        |(a, b)| (a.add_f64(b.hi), q(a) + q(Dd::from_f64(b.hi))),
        2.0,
        0.0,
    );
    assert_within(
        "mul_f64",
        &inputs,
        |(a, b)| (a.mul_f64(b.hi), q(a) * q(Dd::from_f64(b.hi))),
        2.0,
        3.0,
    );
}

#[test]
fn b06_dd_mul_at_range_edges() {
    let inputs = edge_pairs(601, cases(3000, 120_000));
    assert_within("mul", &inputs, |(a, b)| (a * b, q(a) * q(b)), 4.0, 4.0);
}

#[test]
fn b17_dd_div_normalized_at_range_edges() {
    let inputs = edge_pairs(1701, cases(3000, 120_000));
    let eps = 1.0 + 512.0 * 2f64.powi(-53);
    assert_within("div", &inputs, |(a, b)| (a / b, q(a) / q(b)), eps, 1.0);
}

// --------------------------------------------------------------------- conversions

/// Rationals between 2⁻¹⁰⁷⁶ and 2⁻⁹⁰⁰, half of them just above a midpoint between two
/// subnormals, `(k + ½ + δ)·2⁻¹⁰⁷⁴` with `k` even and `0 < δ < 2⁻⁵⁰`: rounding to 53
/// bits first lands on the midpoint and the second rounding goes to the even `k`, not the
/// nearest `k + 1`.
fn tiny_rationals(n: usize) -> Vec<Rational> {
    let mut rng = ChaCha8Rng::seed_from_u64(901);
    (0..n)
        .map(|i| {
            let s = if rng.gen_bool(0.5) { 1 } else { -1 };
            let r = if i % 2 == 0 {
                let k = 2 * rng.gen_range(0..(1u64 << 40));
                let delta = Rational::from((1 + rng.gen_range(0..1000u32), 1u64 << 60));
                (Rational::from(k) + Rational::from((1, 2)) + delta) >> 1074u32
            } else {
                let num = rug::Integer::from(rng.r#gen::<u64>()) * rng.r#gen::<u64>() + 1u32;
                let den = rug::Integer::from(rng.r#gen::<u64>()) + 1u32;
                Rational::from((num, den)) >> rng.gen_range(900..1150u32)
            };
            r * s
        })
        .collect()
}

#[test]
fn b09_dd_from_rational_and_float_at_range_bottom() {
    // The nearest double-double errs by ≤ u²|q| while the trailing word is normal and by
    // half a subnormal unit (η = ½) below.
    let inputs = tiny_rationals(cases(2000, 100_000));
    assert_within(
        "from_rational",
        &inputs.iter().collect::<Vec<_>>(),
        |r| (Dd::from_rational(r, ()), r.clone()),
        1.0 + f64::EPSILON,
        0.5,
    );
    assert_within(
        "from_float",
        &inputs.iter().collect::<Vec<_>>(),
        |r| (Dd::from_float(&Float::with_val(2048, r)), r.clone()),
        1.0 + f64::EPSILON,
        0.5,
    );
}

// ---------------------------------------------------------------------- trigonometry

#[test]
fn b12_dd_sin_cos_at_range_edges() {
    let mut rng = ChaCha8Rng::seed_from_u64(1201);
    let tiny: Vec<Dd> = (0..cases(1000, 100_000))
        .map(|_| edge_dd(&mut rng, -1074, -900))
        .collect();
    assert_within(
        "sin (tiny)",
        &tiny,
        |x| (x.sin(), reference(x, Float::sin)),
        16.0,
        1.0,
    );
    assert_within(
        "cos (tiny)",
        &tiny,
        |x| (x.cos(), reference(x, Float::cos)),
        16.0,
        0.0,
    );
    // Huge arguments (Payne–Hanek): B12's bound relative to max(|f|, 2⁻⁴⁴).
    let huge: Vec<Dd> = (0..cases(500, 100_000))
        .map(|_| edge_dd(&mut rng, 900, 1023))
        .collect();
    for &x in &huge {
        for (z, f) in [
            (x.sin(), Float::sin as fn(Float) -> Float),
            (x.cos(), Float::cos),
        ] {
            assert!(normalized(z), "sin/cos({x:?}) = {z:?} not normalized");
            let e = mixed_err(x, z, 2f64.powi(-44), f);
            assert!(e <= 16.0, "sin/cos({x:?}): {e} u²");
        }
    }
}

/// Pairs `(y, x)` for `atan2` at the ends of the range, both words of both signs.
fn atan2_pairs(n: usize) -> Vec<(Dd, Dd)> {
    let mut rng = ChaCha8Rng::seed_from_u64(1301);
    (0..n)
        .map(|i| {
            let (ey, ex) = match i % 5 {
                0 => ((-1074, -900), (-1074, -900)),
                1 => ((900, 1023), (900, 1023)),
                2 => ((-1074, -900), (900, 1023)),
                3 => ((900, 1023), (-1074, -900)),
                // Same magnitude at the very top: n and d close, n + d overflows.
                _ => ((1015, 1023), (1015, 1023)),
            };
            (edge_dd(&mut rng, ey.0, ey.1), edge_dd(&mut rng, ex.0, ex.1))
        })
        .collect()
}

#[test]
fn b13_dd_atan2_atan_at_range_edges() {
    let inputs = atan2_pairs(cases(2000, 100_000));
    assert_within(
        "atan2",
        &inputs,
        |(y, x)| {
            (
                y.atan2(&x),
                fl(y).atan2(&fl(x)).to_rational().expect("finite"),
            )
        },
        16.0,
        2.0,
    );
    let singles: Vec<Dd> = inputs.iter().map(|&(y, _)| y).collect();
    assert_within(
        "atan",
        &singles,
        |x| (x.atan(), reference(x, Float::atan)),
        16.0,
        2.0,
    );
}

#[test]
fn b14_dd_acos_of_tiny_arguments() {
    let mut rng = ChaCha8Rng::seed_from_u64(1401);
    let inputs: Vec<Dd> = (0..cases(1000, 100_000))
        .map(|_| edge_dd(&mut rng, -1074, -900))
        .collect();
    assert_within(
        "acos",
        &inputs,
        |x| (x.acos(), reference(x, Float::acos)),
        16.0,
        0.0,
    );
}

// --------------------------------------------------------------------------- scaling

#[test]
fn b10_dd_ldexp_keeps_pairs_normalized_into_the_subnormals() {
    // Scaling by 2ᵏ is exact while both words stay normal; below, each word rounds once
    // (≤ 2⁻¹⁰⁷⁵ each, η = 1) and the pair must come back normalized.
    let mut rng = ChaCha8Rng::seed_from_u64(1002);
    let inputs: Vec<(Dd, i32)> = (0..cases(2000, 100_000))
        .map(|_| (edge_dd(&mut rng, -30, 30), -rng.gen_range(900..1110)))
        .collect();
    let pow = |k: i32| Rational::from(1) >> (-k) as u32;
    assert_within(
        "ldexp",
        &inputs,
        |(x, k)| (x.ldexp(k), q(x) * pow(k)),
        0.0,
        1.0,
    );
    assert_within(
        "ldexp_assign",
        &inputs,
        |(x, k)| {
            let mut z = x;
            z.ldexp_assign(k);
            (z, q(x) * pow(k))
        },
        0.0,
        1.0,
    );
}
