//! B19: every conversion ℚ → `f64` of the library gives the binary64 nearest, ties to
//! even, subnormals and overflow included. Oracles: an integer-arithmetic rounding written
//! here over `num-bigint` (not GMP), Rust's own correctly rounded decimal parser, and IEEE
//! division of exactly representable integers.

use crate::support::cases;
use num_bigint::{BigInt, BigUint, Sign as BigSign};
use num_traits::{ToPrimitive, Zero};
use penner::io::json::exact_number;
use penner::scalar::{nearest_f64, parse_rational, Dd, Real};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::{Integer, Rational};
use std::cmp::Ordering;
use std::str::FromStr;

/// The binary64 nearest to `q`, ties to even, by integer arithmetic on `num-bigint`
/// values (the rational crosses over as decimal text): find `e` with
/// `2^e ≤ |q| < 2^(e+1)`, take the quantum `2^(E−52)` with `E = max(e, −1022)` (the
/// subnormal spacing `2⁻¹⁰⁷⁴` below the normal range), round `|q|/quantum` to an integer
/// `m ≤ 2⁵³` by comparing twice the remainder with the divisor, and assemble the bits
/// `(E + 1022)·2⁵² + m`; a carry of `m` into the exponent field is the next binade, and
/// into the all-ones field is `∞`.
fn reference(q: &Rational) -> f64 {
    let n = BigInt::from_str(&q.numer().to_string()).expect("numerator");
    let d = BigUint::from_str(&q.denom().to_string()).expect("denominator");
    if n.is_zero() {
        return 0.0;
    }
    let negative = n.sign() == BigSign::Minus;
    let a = n.magnitude().clone();
    // a/d ≥ 2^e ?
    let at_least = |e: i64| -> bool {
        if e >= 0 {
            a >= &d << (e as usize)
        } else {
            (&a << ((-e) as usize)) >= d
        }
    };
    let mut e = a.bits() as i64 - d.bits() as i64;
    if !at_least(e) {
        e -= 1;
    }
    let magnitude = if e > 1023 {
        f64::INFINITY
    } else {
        let big_e = e.max(-1022);
        let k = big_e - 52;
        let (num, den) = if k >= 0 {
            (a.clone(), &d << (k as usize))
        } else {
            (&a << ((-k) as usize), d.clone())
        };
        let mut m = &num / &den;
        let r = num % &den;
        match (r << 1usize).cmp(&den) {
            Ordering::Greater => m += 1u32,
            Ordering::Equal if m.bit(0) => m += 1u32,
            _ => {}
        }
        let m = m.to_u64().expect("m ≤ 2⁵³");
        assert!(m <= 1 << 53);
        let bits = (((big_e + 1022) as u64) << 52) + m;
        if bits >= f64::INFINITY.to_bits() {
            f64::INFINITY
        } else {
            f64::from_bits(bits)
        }
    };
    if negative {
        -magnitude
    } else {
        magnitude
    }
}

/// `m · 2^k` exactly.
fn scaled(m: impl Into<Integer>, k: i32) -> Rational {
    let mut q = Rational::from(m.into());
    if k >= 0 {
        q <<= k as u32;
    } else {
        q >>= (-k) as u32;
    }
    q
}

fn q(s: &str) -> Rational {
    parse_rational(s).expect("literal")
}

/// Same value and same sign of zero.
fn same(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

/// Inputs where rounding is delicate: exact ties on both sides of every kind of binade,
/// values a hair off a tie, powers of two and their neighbours across the whole range,
/// subnormals, the double-rounding trap, and the overflow threshold.
fn edge_cases() -> Vec<Rational> {
    let mut out = Vec::new();
    for k in [
        -1130, -1100, -1076, -1075, -1074, -1073, -1060, -1023, -1022, -1021, -600,
    ]
    .into_iter()
    .chain([
        -60, -53, -1, 0, 1, 52, 53, 60, 500, 970, 971, 1000, 1023, 1024, 1025,
    ]) {
        let p = scaled(1, k);
        let hair = scaled(1, k - 70);
        for x in [
            p.clone(),
            Rational::from(&p + &hair),
            Rational::from(&p - &hair),
            // Midpoints between 2^k and its neighbours above (k−53) and below (k−54).
            (&p + scaled(1, k - 53)),
            (&p - scaled(1, k - 54)),
            (&p + scaled(1, k - 53) + &hair),
            (&p + scaled(1, k - 53) - &hair),
            (&p - scaled(1, k - 54) - &hair),
            // Odd and even significands exactly halfway: 2^k·(1 + (2j+1)·2⁻⁵³).
            (&p + scaled(3, k - 53)),
            (&p + scaled(5, k - 53)),
        ] {
            out.push(-x.clone());
            out.push(x);
        }
    }
    for j in 0..8u32 {
        // Subnormal ties (2j+1)·2⁻¹⁰⁷⁵ and the double-rounding trap (j + ½ ∓ 2⁻⁶⁰)·2⁻¹⁰⁷⁴.
        let tie = scaled(2 * j + 1, -1075);
        out.push(&tie - scaled(1, -1134));
        out.push(&tie + scaled(1, -1134));
        out.push(tie);
    }
    let max = Rational::from_f64(f64::MAX).expect("finite");
    let half_ulp = scaled(1, 970);
    for x in [
        Rational::from(&max + &half_ulp),
        Rational::from(&max + &half_ulp) - scaled(1, 800),
        Rational::from(&max + &half_ulp) + scaled(1, 800),
        max,
        q("1e308"),
        q("1e309"),
        q("1e10000"),
        q("1e-10000"),
        q("4.9406564584124654e-324"),
        q("2.4703282292062327e-324"),
        q("2.4703282292062328e-324"),
        q("2.2250738585072011e-308"),
        q("2.2250738585072012e-308"),
        q("0.1"),
        q("1/3"),
        q("-2/3"),
        q("9007199254740993"),
        q("9007199254740995"),
        q("0"),
    ] {
        out.push(-x.clone());
        out.push(x);
    }
    out
}

#[test]
fn b19_reference_rounds_hand_checked_values() {
    // The oracle itself against values known independently of it: Rust literals (correctly
    // rounded by the compiler), ties worked by hand, the overflow threshold MAX + 2⁹⁷⁰.
    let threshold = Rational::from_f64(f64::MAX).expect("finite") + scaled(1, 970);
    let cases: [(Rational, f64); 12] = [
        (q("0.1"), 0.1),
        (q("1/3"), 1.0 / 3.0),
        (q("9007199254740993"), 9007199254740992.0),
        (q("9007199254740995"), 9007199254740996.0),
        (q("-1e400"), f64::NEG_INFINITY),
        (q("1e-400"), 0.0),
        (q("2.4703282292062327e-324"), 0.0),
        (q("2.4703282292062328e-324"), 5e-324),
        (scaled(3, -1075), 1e-323),
        (scaled(5, -1075), 1e-323),
        ((&threshold - q("1/10")), f64::MAX),
        (threshold, f64::INFINITY),
    ];
    for (x, want) in cases {
        assert!(same(reference(&x), want), "{x}");
    }
}

#[test]
fn b19_nearest_f64_matches_the_integer_reference_on_edge_cases() {
    let cases = edge_cases();
    let mut ties = 0;
    for x in &cases {
        let want = reference(x);
        let got = nearest_f64(x);
        assert!(same(got, want), "{x}: got {got:e}, want {want:e}");
        // Every library conversion ℚ → f64 agrees.
        assert!(same(<f64 as Real>::from_rational(x, ()), want), "{x}");
        let dd = Dd::from_rational(x, ());
        if !dd.hi.is_finite() && want.is_finite() {
            // Renormalizing MAX + ulp(MAX)/2 overflows: Dd reports (±∞, 0) (B09, B10).
            assert_eq!(want.abs(), f64::MAX, "Dd overflowed on {x}");
        } else if want.is_finite() && want != 0.0 {
            let w = Rational::from_f64(want).expect("finite");
            let rest = Rational::from(x - &w);
            // Dd holds RN(x) + RN(x − RN(x)) exactly, renormalized (hi = RN(hi + lo)): when the
            // low word rounds to a tie next to an odd hi, the exact TwoSum moves it (B09).
            let value = |h: f64, l: f64| {
                Rational::from_f64(h).expect("finite") + Rational::from_f64(l).expect("finite")
            };
            assert_eq!(
                value(dd.hi, dd.lo),
                value(want, reference(&rest)),
                "Dd value of {x}"
            );
            assert_eq!(dd.hi + dd.lo, dd.hi, "Dd not normalized for {x}");
            // A tie (as far from the other neighbour as from `want`): even significand.
            let other = if rest > 0 {
                want.next_up()
            } else {
                want.next_down()
            };
            if let Some(o) = Rational::from_f64(other).filter(|_| rest != 0) {
                if Rational::from(x - &o).abs() == rest.clone().abs() {
                    ties += 1;
                    assert_eq!(want.to_bits() & 1, 0, "tie {x} not to even");
                }
            }
        } else {
            assert!(same(dd.hi, want), "Dd hi of {x}");
        }
    }
    assert!(ties >= 40, "only {ties} exact ties among the edge cases");
}

/// A random rational with numerator and denominator of random sizes (up to 200 bits),
/// scaled by a power of two anywhere from far below the subnormals to beyond the range.
fn random_rational(rng: &mut ChaCha8Rng) -> Rational {
    let bits = |rng: &mut ChaCha8Rng| -> Integer {
        let n = rng.gen_range(1..=200u32);
        let mut x = Integer::new();
        for _ in 0..n.div_ceil(64) {
            x = (x << 64u32) + rng.r#gen::<u64>();
        }
        (x >> (n.div_ceil(64) * 64 - n)) | 1u32
    };
    let num = bits(rng);
    let den = if rng.gen_bool(0.3) {
        Integer::from(1)
    } else {
        bits(rng)
    };
    let x = Rational::from((num, den)) * scaled(1, rng.gen_range(-1200..1100));
    if rng.gen_bool(0.5) {
        -x
    } else {
        x
    }
}

#[test]
fn b19_nearest_f64_matches_the_integer_reference_on_random_rationals() {
    let mut rng = ChaCha8Rng::seed_from_u64(19);
    let mut subnormal = 0;
    for case in 0..cases(20_000, 1_000_000) {
        let x = random_rational(&mut rng);
        if !crate::support::in_shard(case) {
            continue; // generated, then left to another shard
        }
        let want = reference(&x);
        assert!(same(nearest_f64(&x), want), "{x}: want {want:e}");
        assert!(same(<f64 as Real>::from_rational(&x, ()), want), "{x}");
        subnormal += usize::from(want != 0.0 && !want.is_normal() && want.is_finite());
    }
    assert!(subnormal > 100, "only {subnormal} subnormal results");
}

#[test]
fn b19_nearest_f64_matches_rusts_parser_on_decimals_and_json_numbers() {
    // Rust's `str::parse::<f64>` and serde_json's reader (feature float_roundtrip) are
    // correctly rounded; a decimal literal read exactly and then rounded must agree, and a
    // JSON number must denote that same binary64 exactly.
    let mut rng = ChaCha8Rng::seed_from_u64(0x19);
    for _ in 0..cases(5_000, 200_000) {
        let digits: String = (0..rng.gen_range(1..=40))
            .map(|_| char::from(b'0' + rng.gen_range(0..10u8)))
            .collect();
        let text = format!(
            "{}{}.{}e{}",
            if rng.gen_bool(0.5) { "-" } else { "" },
            rng.gen_range(0..10u8),
            digits,
            rng.gen_range(-340..=310)
        );
        let want: f64 = text.parse().expect("Rust parses the literal");
        let x = q(&text);
        let got = nearest_f64(&x);
        // A zero rational has no sign; Rust keeps the sign of "-0.0".
        assert!(same(got, want) || (x == 0 && got == want), "{text}");
        if want.is_finite() {
            let v: serde_json::Value = serde_json::from_str(&text).expect("JSON number");
            let exact = exact_number(&v, "x").expect("finite");
            assert_eq!(exact, Rational::from_f64(want).expect("finite"), "{text}");
        }
    }
    // IEEE division of integers below 2⁵³ is correctly rounded.
    for case in 0..cases(5_000, 200_000) {
        let a = rng.gen_range(1..1u64 << 53);
        let b = rng.gen_range(1..1u64 << 53);
        if !crate::support::in_shard(case) {
            continue; // generated, then left to another shard
        }
        let x = Rational::from((a, b));
        assert!(same(nearest_f64(&x), a as f64 / b as f64), "{a}/{b}");
    }
}

#[test]
fn b19_negative_control_truncation_and_double_rounding_are_caught() {
    // Truncation (rug's `Rational::to_f64`) disagrees with the reference on a good share of
    // random rationals and on ties that round up.
    let mut rng = ChaCha8Rng::seed_from_u64(91);
    let n = 2_000;
    let wrong = (0..n)
        .map(|_| random_rational(&mut rng))
        .filter(|x| !same(x.to_f64(), reference(x)))
        .count();
    assert!(wrong > n / 4, "truncation wrong on only {wrong}/{n}");
    let tie_up = scaled((1u64 << 53) + 3, 0);
    assert!(!same(tie_up.to_f64(), reference(&tie_up)));
    // Rounding to 53 bits and then into the subnormal range rounds twice:
    // (3/2 − 2⁻⁶⁰)·2⁻¹⁰⁷⁴ becomes the tie (3/2)·2⁻¹⁰⁷⁴ and then 2·2⁻¹⁰⁷⁴.
    let trap = scaled(3, -1075) - scaled(1, -1134);
    let twice = rug::Float::with_val(53, &trap).to_f64();
    assert_eq!(reference(&trap), 5e-324);
    assert_eq!(twice, 1e-323);
    assert!(!same(twice, reference(&trap)));
}

/// `Real::ldexp_assign` scales by `2ᵏ` exactly for `|k|` beyond one binary64 exponent
/// step: `2⁻¹⁰⁰⁰ · 2¹⁵⁰⁰ = 2⁵⁰⁰` and `2¹⁰⁰⁰ · 2⁻¹⁵⁰⁰ = 2⁻⁵⁰⁰` in f64 and Dd, compared
/// with `f64::powi`-free bit patterns. Negative control: a scaling clamped to one step
/// (`2⁻¹⁰⁰⁰ · 2¹⁰²³`) is a different number.
#[test]
fn ldexp_assign_is_exact_beyond_one_exponent_step() {
    let pow = |e: i64| f64::from_bits(((e + 1023) as u64) << 52);
    let mut x = pow(-1000);
    x.ldexp_assign(1500);
    assert_eq!(x, pow(500));
    let mut y = pow(1000);
    y.ldexp_assign(-1500);
    assert_eq!(y, pow(-500));
    let mut d = Dd::from_f64(pow(-1000));
    d.ldexp_assign(1500);
    assert_eq!(d.approx_f64(), pow(500));
    let mut g = 1.0_f64;
    Real::ldexp_assign(&mut g, 0);
    assert_eq!(g, 1.0);
    assert_ne!(pow(-1000) * pow(1023), pow(500));
}
