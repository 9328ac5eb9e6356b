//! The three exact fields (rug, malachite, num-rational) agree exactly on random expression
//! trees, and convert every finite f64 exactly (checked against an independent decoding of
//! the bit pattern).

use crate::support::cases;
use malachite::rational::Rational as MRational;
use num_rational::BigRational;
use penner::scalar::exact::Field;
use penner::scalar::Sign;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::{Integer, Rational};

#[derive(Clone, Debug)]
enum Expr {
    Int(i64),
    Float(f64),
    Neg(Box<Expr>),
    Bin(u8, Box<Expr>, Box<Expr>),
}

fn random_finite_f64(rng: &mut ChaCha8Rng) -> f64 {
    match rng.gen_range(0..4) {
        0 => rng.gen_range(-1e3..1e3),
        1 => f64::from_bits(rng.r#gen::<u64>() & 0x800F_FFFF_FFFF_FFFF), // subnormal or ±0
        _ => loop {
            let x = f64::from_bits(rng.r#gen());
            if x.is_finite() {
                break x;
            }
        },
    }
}

fn gen_expr(rng: &mut ChaCha8Rng, depth: u32) -> Expr {
    if depth == 0 || rng.gen_bool(0.25) {
        return match rng.gen_range(0..4) {
            0 => Expr::Int(rng.gen_range(-5..=5)),
            1 => Expr::Int([i64::MIN, i64::MAX, rng.r#gen()][rng.gen_range(0..3)]),
            _ => Expr::Float(random_finite_f64(rng)),
        };
    }
    if rng.gen_bool(0.15) {
        return Expr::Neg(Box::new(gen_expr(rng, depth - 1)));
    }
    Expr::Bin(
        rng.gen_range(0..4),
        Box::new(gen_expr(rng, depth - 1)),
        Box::new(gen_expr(rng, depth - 1)),
    )
}

/// `None` when a division by zero occurs.
fn eval<F: Field>(e: &Expr) -> Option<F> {
    Some(match e {
        Expr::Int(n) => F::from_i64(*n),
        Expr::Float(x) => F::from_f64(*x)?,
        Expr::Neg(a) => F::neg(&eval::<F>(a)?),
        Expr::Bin(op, a, b) => {
            let (x, y) = (eval::<F>(a)?, eval::<F>(b)?);
            match op {
                0 => F::add(&x, &y),
                1 => F::sub(&x, &y),
                2 => F::mul(&x, &y),
                _ => F::div(&x, &y)?,
            }
        }
    })
}

/// Replace the first leaf by itself plus one.
fn perturb(e: &Expr) -> Expr {
    match e {
        Expr::Int(n) => Expr::Bin(0, Box::new(Expr::Int(*n)), Box::new(Expr::Int(1))),
        Expr::Float(x) => Expr::Bin(0, Box::new(Expr::Float(*x)), Box::new(Expr::Int(1))),
        Expr::Neg(a) => Expr::Neg(Box::new(perturb(a))),
        Expr::Bin(op, a, b) => Expr::Bin(*op, Box::new(perturb(a)), b.clone()),
    }
}

#[test]
fn three_exact_fields_agree_on_random_expression_trees() {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let n = cases(1500, 100_000);
    let (mut agreed, mut div_zero, mut perturbed_differs) = (0, 0, 0);
    for _ in 0..n {
        let e = gen_expr(&mut rng, 5);
        let a = eval::<Rational>(&e);
        let b = eval::<MRational>(&e);
        let c = eval::<BigRational>(&e);
        match (&a, &b, &c) {
            (Some(a), Some(b), Some(c)) => {
                assert_eq!(*a, b.to_rug(), "malachite disagrees on {e:?}");
                assert_eq!(*a, c.to_rug(), "num-rational disagrees on {e:?}");
                assert_eq!(a.sign(), b.sign());
                assert_eq!(a.sign(), c.sign());
                agreed += 1;
                // Negative control: the comparison sees a changed leaf.
                if let Some(p) = eval::<MRational>(&perturb(&e)) {
                    if p.to_rug() != *a {
                        perturbed_differs += 1;
                    }
                }
            }
            (None, None, None) => div_zero += 1,
            _ => panic!("division by zero detected by only some fields on {e:?}"),
        }
    }
    assert!(
        agreed > n / 2,
        "only {agreed}/{n} trees evaluated ({div_zero} divided by 0)"
    );
    assert!(
        perturbed_differs > agreed / 4,
        "perturbation visible in only {perturbed_differs}/{agreed}"
    );
}

/// The exact value of a finite binary64, decoded from its bits without any library
/// conversion: (−1)^s · m · 2^(e − 1075).
fn decode_bits(x: f64) -> Rational {
    let b = x.to_bits();
    let neg = b >> 63 == 1;
    let exp = ((b >> 52) & 0x7ff) as i64;
    let frac = b & ((1u64 << 52) - 1);
    let (m, e) = if exp == 0 {
        (frac, -1074)
    } else {
        (frac | (1u64 << 52), exp - 1075)
    };
    let mut q = Rational::from(Integer::from(m));
    if e >= 0 {
        q <<= e as u32;
    } else {
        q >>= (-e) as u32;
    }
    if neg {
        -q
    } else {
        q
    }
}

#[test]
fn every_finite_f64_converts_exactly_in_all_three_fields() {
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    let mut xs = vec![
        0.0,
        -0.0,
        1.0,
        -1.5,
        0.1,
        f64::MAX,
        f64::MIN,
        f64::MIN_POSITIVE,
        f64::from_bits(1),
        -f64::from_bits(1),
        f64::from_bits(0x000F_FFFF_FFFF_FFFF),
        f64::EPSILON,
        1e-300,
        1e300,
    ];
    xs.extend((0..cases(20_000, 1_000_000)).map(|_| random_finite_f64(&mut rng)));
    for x in xs {
        let want = decode_bits(x);
        let a = <Rational as Field>::from_f64(x).expect("finite");
        let b = <MRational as Field>::from_f64(x).expect("finite");
        let c = <BigRational as Field>::from_f64(x).expect("finite");
        assert_eq!(a, want, "rug converts {x:e} inexactly");
        assert_eq!(b.to_rug(), want, "malachite converts {x:e} inexactly");
        assert_eq!(c.to_rug(), want, "num-rational converts {x:e} inexactly");
        // The value is exact: converting back is the identity.
        assert_eq!(want.to_f64(), x);
    }
    // Negative control: the decoder distinguishes neighbours.
    assert_ne!(
        decode_bits(1.0),
        decode_bits(f64::from_bits(1.0f64.to_bits() + 1))
    );
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(<Rational as Field>::from_f64(bad).is_none());
        assert!(<MRational as Field>::from_f64(bad).is_none());
        assert!(<BigRational as Field>::from_f64(bad).is_none());
    }
}

#[test]
fn rug_round_trips_through_the_other_fields() {
    let mut rng = ChaCha8Rng::seed_from_u64(9);
    for _ in 0..cases(2000, 100_000) {
        let num = random_integer(&mut rng);
        let den = random_integer(&mut rng) + 1u32;
        let mut q = Rational::from((num, den));
        if rng.gen_bool(0.5) {
            q = -q;
        }
        assert_eq!(MRational::from_rug(&q).to_rug(), q);
        assert_eq!(BigRational::from_rug(&q).to_rug(), q);
        let s = Sign::of_ordering(q.cmp0());
        assert_eq!(MRational::from_rug(&q).sign(), s);
        assert_eq!(BigRational::from_rug(&q).sign(), s);
    }
}

fn random_integer(rng: &mut ChaCha8Rng) -> Integer {
    let digits: Vec<u64> = (0..rng.gen_range(1..8)).map(|_| rng.r#gen()).collect();
    Integer::from_digits(&digits, rug::integer::Order::Lsf) >> rng.gen_range(0..64u32)
}

/// `scalar::parse_rational` against values built independently in malachite (decimal and
/// scientific forms) and num-rational's own fraction parser.
#[test]
fn parse_rational_agrees_with_malachite_and_num_rational() {
    use malachite::base::num::arithmetic::traits::Pow;
    use malachite::Integer as MInteger;
    use penner::scalar::parse_rational;
    use std::str::FromStr;
    let mut rng = ChaCha8Rng::seed_from_u64(10);
    let digits = |rng: &mut ChaCha8Rng, lo: usize, hi: usize| -> String {
        let n = rng.gen_range(lo..hi);
        (0..n)
            .map(|_| char::from(b'0' + rng.gen_range(0..10u8)))
            .collect()
    };
    for _ in 0..cases(2000, 100_000) {
        let neg = rng.gen_bool(0.5);
        let int = digits(&mut rng, 1, 25);
        let frac = digits(&mut rng, 0, 25);
        let exp: i64 = rng.gen_range(-300..300);
        let sign = if neg { "-" } else { "" };
        let (text, want) = match rng.gen_range(0..3) {
            0 | 1 => {
                let text = if rng.gen_bool(0.5) {
                    format!("{sign}{int}.{frac}e{exp}")
                } else {
                    format!("{sign}{int}.{frac}")
                };
                let e = if text.contains('e') { exp } else { 0 } - frac.len() as i64;
                let m = MInteger::from_str(&format!("{int}{frac}")).expect("digits");
                let ten = MRational::from(10u32);
                let scale = if e >= 0 {
                    (&ten).pow(e as u64)
                } else {
                    MRational::from(1u32) / (&ten).pow((-e) as u64)
                };
                let v = MRational::from(m) * scale;
                (text, if neg { -v } else { v }.to_rug())
            }
            _ => {
                let den = format!("{}{}", rng.gen_range(1..10u32), digits(&mut rng, 0, 20));
                let text = format!("{sign}{int}/{den}");
                (
                    text.clone(),
                    BigRational::from_str(&text)
                        .expect("num parses p/q")
                        .to_rug(),
                )
            }
        };
        assert_eq!(
            parse_rational(&text).expect("valid literal"),
            want,
            "{text}"
        );
    }
    // The shortest round-trip decimal of an f64 parses to a rational that rounds back to it.
    for case in 0..cases(2000, 100_000) {
        let x = random_finite_f64(&mut rng);
        if !crate::support::in_shard(case) {
            continue; // generated, then left to another shard
        }
        for text in [format!("{x:e}"), format!("{x}")] {
            let q = parse_rational(&text).expect("valid literal");
            // x is a nearest binary64 to q: no neighbour is strictly closer.
            let dist = |y: f64| (&q - Rational::from_f64(y).expect("finite")).abs();
            let d = dist(x);
            for y in [x.next_up(), x.next_down()] {
                if y.is_finite() {
                    assert!(d <= dist(y), "{text} is closer to {y:e} than to {x:e}");
                }
            }
        }
    }
    // Negative control: a changed digit changes the value.
    assert_ne!(parse_rational("1.25").ok(), parse_rational("1.26").ok());
}
