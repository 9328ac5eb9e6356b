//! The compact OBJ/OFF path (`io::decimal`, `io::DecimalSurface`) against the exact one:
//! literals against `parse_rational` (values and errors), rounding to `f64` against MPFR,
//! and whole surfaces against the surface built in ℚ from the same text (positions,
//! squared lengths, validation errors, lengths in every backend bit for bit).

use crate::meshgen;
use crate::support::cases;
use penner::io::decimal::{decimal_to_f64, parse_coordinate, squared_distance, Coordinate};
use penner::io::surface::squared_lengths_from_positions;
use penner::io::{obj, off, ReadError, Surface};
use penner::mesh::Mesh;
use penner::scalar::{parse_rational, Dd, Mpfr, Real};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::{Integer, Rational};
use std::fmt::Write as _;

/// A random literal of the decimal grammar, or near it: signs, digit runs of 0–25
/// characters, optional point and exponent, and now and then a malformed piece.
fn literal(rng: &mut ChaCha8Rng) -> String {
    let digits = |rng: &mut ChaCha8Rng, n: usize| -> String {
        (0..n)
            .map(|_| char::from(b'0' + rng.gen_range(0..10u8)))
            .collect()
    };
    let mut s = String::new();
    match rng.gen_range(0..4) {
        0 => s.push('-'),
        1 => s.push('+'),
        _ => {}
    }
    let int_len = rng.gen_range(0..=20);
    s += &digits(rng, int_len);
    if rng.gen_bool(0.7) {
        s.push('.');
        let frac_len = rng.gen_range(0..=20);
        s += &digits(rng, frac_len);
    }
    if rng.gen_bool(0.4) {
        s.push(if rng.gen_bool(0.5) { 'e' } else { 'E' });
        match rng.gen_range(0..3) {
            0 => s.push('-'),
            1 => s.push('+'),
            _ => {}
        }
        let exp_len = rng.gen_range(0..=5);
        s += &digits(rng, exp_len);
    }
    if rng.gen_bool(0.05) {
        let junk = ["x", ".", "e", "-", "/3", "/0", " ", "1/7"];
        let k = rng.gen_range(0..junk.len());
        let at = rng.gen_range(0..=s.len());
        s.insert_str(at, junk[k]);
    }
    s
}

const EDGE_CASES: [&str; 40] = [
    "0",
    "-0",
    "+0",
    "0.",
    ".0",
    ".",
    "-",
    "+",
    "",
    "e5",
    "1e",
    "1e+",
    "1e-",
    "--1",
    "+-1",
    "1.2.3",
    "1e5e5",
    "1e99999",
    "1e-99999",
    "1e4000",
    "1e4001",
    "-1e-4000",
    "0x10",
    "nan",
    "-inf",
    "Infinity",
    "1/3",
    "-6/4",
    "1/0",
    "1.5/2",
    " 1",
    "1 ",
    "1_0",
    "١",
    "123456789012345678",
    "1234567890123456789",
    "0.000000000000000001",
    "-999999999999999999e-4000",
    "5.2573111211913359e-1",
    "1.0000000000000000e0",
];

#[test]
fn decimal_literals_match_parse_rational_in_value_and_error() {
    let mut rng = ChaCha8Rng::seed_from_u64(12);
    let mut fast = 0;
    let generated: Vec<String> = (0..cases(20_000, 2_000_000))
        .map(|_| literal(&mut rng))
        .collect();
    for s in EDGE_CASES.iter().map(ToString::to_string).chain(generated) {
        let ours = parse_coordinate(&s);
        let exact = parse_rational(&s);
        match (&ours, &exact) {
            (Ok(c), Ok(q)) => {
                assert_eq!(&c.to_rational(), q, "value of {s:?}");
                // The written form reads back to the same value.
                assert_eq!(&parse_rational(&c.to_string()).unwrap(), q, "{s:?} as {c}");
                fast += usize::from(matches!(c, Coordinate::Decimal { .. }));
            }
            (Err(a), Err(b)) => assert_eq!(a, b, "error of {s:?}"),
            _ => panic!("{s:?}: fast {ours:?}, exact {exact:?}"),
        }
    }
    // The fast path is taken for most literals (else this compared the exact parser with
    // itself).
    assert!(fast > 5_000, "only {fast} literals took the fast path");
}

#[test]
fn decimal_fast_path_limits() {
    let dec = |s: &str| matches!(parse_coordinate(s), Ok(Coordinate::Decimal { .. }));
    assert!(dec("123456789012345678"));
    assert!(dec("-0.12345678901234567e-4000"));
    // 19 digits, a fraction, an exponent past the fast range: exact rationals, same value.
    for s in ["1234567890123456789", "1/3", "1e4001"] {
        assert!(!dec(s), "{s}");
        assert_eq!(
            parse_coordinate(s).unwrap().to_rational(),
            parse_rational(s).unwrap()
        );
    }
}

/// `Real::from_rational` for `f64` (53-bit MPFR, then to f64).
fn mpfr_f64(q: &Rational) -> f64 {
    f64::from_rational(q, ())
}

#[test]
fn decimal_to_f64_rounds_like_the_exact_conversion() {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let mut checked = 0;
    for i in 0..cases(20_000, 1_000_000) {
        let bits = rng.gen_range(1..=127);
        let n: u128 = rng.r#gen::<u128>() >> (128 - bits);
        let e: i32 = rng.gen_range(-340..=300);
        // Halfway cases: n·10^e just at a midpoint of two binary64 values.
        let (n, e) = if i % 10 == 0 {
            let x: f64 = rng.gen_range(1e-200..1e200);
            let mid = Rational::from_f64(x).unwrap()
                + Rational::from_f64(f64::from_bits(x.to_bits() + 1) - x).unwrap() / 2u32;
            // mid = m / 2^k exactly = m·5^k / 10^k; keep only those that fit u128.
            let (num, den) = mid.into_numer_denom();
            let k = den.significant_bits() - 1;
            let scaled = num * Integer::from(Integer::u_pow_u(5, k));
            match scaled.to_u128() {
                Some(m) => (m, -(k as i32)),
                None => continue,
            }
        } else {
            (n, e)
        };
        let q = if e >= 0 {
            Rational::from(Integer::from(n) * Integer::from(Integer::u_pow_u(10, e as u32)))
        } else {
            Rational::from((
                Integer::from(n),
                Integer::from(Integer::u_pow_u(10, e.unsigned_abs())),
            ))
        };
        if let Some(x) = decimal_to_f64(n, e) {
            assert_eq!(x.to_bits(), mpfr_f64(&q).to_bits(), "{n}e{e}");
            checked += 1;
        }
    }
    assert!(checked > 1000, "{checked}");
}

#[test]
fn squared_distance_is_exact() {
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    for _ in 0..cases(2_000, 200_000) {
        let mut p = || -> [Coordinate; 3] {
            std::array::from_fn(|_| {
                let m: i64 = rng.gen_range(-999_999_999_999_999_999..=999_999_999_999_999_999);
                let m = m >> rng.gen_range(0..60);
                parse_coordinate(&format!("{m}e{}", rng.gen_range(-20..=3))).unwrap()
            })
        };
        let (a, b) = (p(), p());
        let mut exact = Rational::new();
        for k in 0..3 {
            let d = b[k].to_rational() - a[k].to_rational();
            exact += Rational::from(&d * &d);
        }
        if let Some((n, e)) = squared_distance(&a, &b) {
            let p = Integer::from(Integer::u_pow_u(10, (2 * e).unsigned_abs()));
            let ours = if e >= 0 {
                Rational::from(Integer::from(n) * p)
            } else {
                Rational::from((Integer::from(n), p))
            };
            assert_eq!(ours, exact);
        }
    }
}

/// The surface of OFF `text` built in ℚ without the compact path: `parse_rational`
/// coordinates, `squared_lengths_from_positions`, `Surface::new`.
fn exact_off(text: &str) -> Result<Surface, penner::io::MetricError> {
    let lines: Vec<&str> = text.lines().filter(|l| !l.trim().is_empty()).collect();
    let counts: Vec<usize> = lines[1]
        .split_whitespace()
        .map(|t| t.parse().unwrap())
        .collect();
    let (nv, nf) = (counts[0], counts[1]);
    let positions: Vec<[Rational; 3]> = lines[2..2 + nv]
        .iter()
        .map(|l| {
            let t: Vec<&str> = l.split_whitespace().collect();
            std::array::from_fn(|k| parse_rational(t[k]).unwrap())
        })
        .collect();
    let faces: Vec<[u32; 3]> = lines[2 + nv..2 + nv + nf]
        .iter()
        .map(|l| {
            let t: Vec<u32> = l.split_whitespace().map(|x| x.parse().unwrap()).collect();
            [t[1], t[2], t[3]]
        })
        .collect();
    let mesh = Mesh::from_faces(nv as u32, &faces).unwrap();
    let metric =
        penner::io::Metric::SquaredLengths(squared_lengths_from_positions(&mesh, &positions));
    Surface::new("", mesh, metric, Some(positions))
}

fn noisy_sphere_off(k: u32, seed: u64) -> String {
    let mut s = meshgen::icosphere(k);
    let a = s.mean_edge();
    s.jitter_radial(a, seed);
    let mut out = Vec::new();
    s.write_off(&mut out).unwrap();
    String::from_utf8(out).unwrap()
}

/// Rewrite some coordinates of an OFF text in other exact forms: fractions, 25-digit
/// literals, integers, other exponents (the slow paths of the compact reader).
fn mixed_forms(text: &str, seed: u64) -> String {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let nv: usize = lines[1].split_whitespace().next().unwrap().parse().unwrap();
    for l in &mut lines[2..2 + nv] {
        let t: Vec<String> = l
            .split_whitespace()
            .map(|x| {
                let q = parse_rational(x).unwrap();
                match rng.gen_range(0..4) {
                    0 => q.to_string(),
                    1 => match x.split_once('e') {
                        Some((m, e)) => format!("{m}0000000E{e}"),
                        None => format!("{x}0000000"),
                    },
                    2 => format!("+{}", x.replace('e', "E")).replace("+-", "-"),
                    _ => x.to_string(),
                }
            })
            .collect();
        *l = t.join(" ");
    }
    lines.join("\n") + "\n"
}

#[test]
fn off_reader_equals_the_exact_surface_and_its_lengths_bit_for_bit() {
    for (i, text) in [
        noisy_sphere_off(6, 1),
        mixed_forms(&noisy_sphere_off(5, 2), 3),
        mixed_forms(&noisy_sphere_off(3, 4), 5),
    ]
    .iter()
    .enumerate()
    {
        let exact = exact_off(text).unwrap();
        let compact = off::read_decimal(text).unwrap();
        let l64 = compact.lengths::<f64>(());
        let ldd = compact.lengths::<Dd>(());
        let l256 = compact.lengths::<Mpfr>(p256());
        assert_eq!(&off::read(text).unwrap(), &exact, "case {i}");
        assert_eq!(compact.into_surface(), exact, "case {i}");
        let e64: Vec<f64> = exact.lengths(());
        assert_eq!(
            l64.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
            e64.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
            "case {i}"
        );
        assert_eq!(ldd, exact.lengths::<Dd>(()), "case {i}");
        assert_eq!(l256, exact.lengths::<Mpfr>(p256()), "case {i}");
    }
    // Negative control: one coordinate moved in its last digit changes a length.
    let text = noisy_sphere_off(4, 9);
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let first = lines[2].clone();
    let (head, tail) = first.split_once('e').unwrap();
    let last = head.chars().last().unwrap();
    let bumped = if last == '9' {
        '8'
    } else {
        char::from(last as u8 + 1)
    };
    lines[2] = format!("{}{bumped}e{tail}", &head[..head.len() - 1]);
    let moved = lines.join("\n");
    assert_ne!(
        off::read_decimal(&moved).unwrap().lengths::<Mpfr>(p256()),
        exact_off(&text).unwrap().lengths::<Mpfr>(p256())
    );
}

#[test]
fn obj_reader_equals_the_off_reader() {
    let text = mixed_forms(&noisy_sphere_off(4, 11), 12);
    let s = off::read(&text).unwrap();
    let mut obj_text = String::new();
    let lines: Vec<&str> = text.lines().collect();
    let nv = s.mesh.n_vertices();
    for l in &lines[2..2 + nv] {
        obj_text.push_str(&["v ", l, "\n"].concat());
    }
    for l in &lines[2 + nv..] {
        let t: Vec<u32> = l.split_whitespace().map(|x| x.parse().unwrap()).collect();
        let f = [t[1] + 1, t[2] + 1, t[3] + 1].map(|x| x.to_string());
        obj_text.push_str(&["f ", &f.join(" "), "\n"].concat());
    }
    assert_eq!(obj::read(&obj_text).unwrap(), s);
    assert_eq!(
        obj::read_decimal(&obj_text).unwrap().lengths::<f64>(()),
        s.lengths::<f64>(())
    );
}

#[test]
fn degenerate_and_coincident_vertices_give_the_exact_errors() {
    // A tetrahedron whose vertex 3 is moved onto the line through 0 and 1 (face 0 1 3
    // degenerate), then onto vertex 0 (edge of zero length); coordinates in mixed forms
    // so both the integer test and the rational one run.
    let faces = "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";
    for (v3, what) in [
        ("2.5 0 0", "degenerate"),
        ("5/2 0.0 0e7", "degenerate"),
        ("12345678901234567890123e-22 0 0", "degenerate"),
        ("0 0 0", "coincident"),
        ("0/7 0.000 -0", "coincident"),
        ("0.5 0.5 1", "valid"),
    ] {
        let text = format!("OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n{v3}\n{faces}");
        let expected = exact_off(&text);
        match (off::read(&text), expected) {
            (Ok(a), Ok(b)) => {
                assert_eq!(what, "valid");
                assert_eq!(a, b);
            }
            (Err(ReadError::Metric { source, .. }), Err(b)) => {
                assert_ne!(what, "valid");
                assert_eq!(source, b, "{v3}");
            }
            (a, b) => panic!("{v3}: {a:?} vs {b:?}"),
        }
    }
}

fn p256() -> penner::scalar::Precision {
    penner::scalar::Precision::new(256).expect("valid precision")
}

/// A sphere written with `%.17g`-style literals: coordinates below 10⁻⁴ in exponent form,
/// so that aligning mantissas to the smallest exponent outgrows `u128` for the squared
/// lengths (the wide-integer path of the `f64` lengths).
fn sphere_with_tiny_coordinates(n: u32) -> String {
    let mut text = String::new();
    let (nv, nf) = (n * n + 2, 2 * n * n);
    let _ = writeln!(text, "OFF\n{nv} {nf} 0");
    // A UV sphere: poles plus n rings of n vertices; some coordinates tiny but nonzero.
    let mut pts = vec![[0.0_f64, 0.0, 1.0]];
    for r in 0..n {
        let th = std::f64::consts::PI * f64::from(r + 1) / f64::from(n + 1);
        for k in 0..n {
            let ph = 2.0 * std::f64::consts::PI * f64::from(k) / f64::from(n) + 1e-6 * f64::from(r);
            pts.push([th.sin() * ph.cos(), th.sin() * ph.sin(), th.cos()]);
        }
    }
    pts.push([0.0, 1.2345678901234567e-5, -1.0]);
    for p in &pts {
        let _ = writeln!(text, "{:e} {:e} {:e}", p[0], p[1], p[2]);
    }
    let v = |r: u32, k: u32| 1 + r * n + (k % n);
    for k in 0..n {
        let _ = writeln!(text, "3 0 {} {}", v(0, k), v(0, k + 1));
        let _ = writeln!(text, "3 {} {} {}", nv - 1, v(n - 1, k + 1), v(n - 1, k));
    }
    for r in 0..n - 1 {
        for k in 0..n {
            let _ = writeln!(text, "3 {} {} {}", v(r, k), v(r + 1, k), v(r + 1, k + 1));
            let _ = writeln!(text, "3 {} {} {}", v(r, k), v(r + 1, k + 1), v(r, k + 1));
        }
    }
    text
}

#[test]
fn f64_lengths_past_u128_equal_the_exact_conversion() {
    let text = sphere_with_tiny_coordinates(12);
    let exact = exact_off(&text).unwrap();
    let compact = off::read_decimal(&text).unwrap();
    let l64 = compact.lengths::<f64>(());
    let e64: Vec<f64> = exact.lengths(());
    assert_eq!(
        l64.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
        e64.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
    );
    // The family does reach the wide path: some squared length does not fit u128 after
    // alignment (a coordinate of 17 digits at 10⁻⁵ next to one at 10⁻¹).
    assert!(
        text.contains("e-5") || text.contains("e-6"),
        "no tiny coordinate"
    );
}

/// `n·10^e` in ℚ for `n` given as little-endian 64-bit limbs.
fn limbs_rational(n: &[u64; 4], e: i32) -> Rational {
    let n = Integer::from_digits(n, rug::integer::Order::Lsf);
    let p = Integer::from(Integer::u_pow_u(10, e.unsigned_abs()));
    if e >= 0 {
        Rational::from(n * p)
    } else {
        Rational::from((n, p))
    }
}

/// B19: `wide_to_f64` (fixed-width limbs, no big numbers) rounds `n·10^e` with `n < 2²⁵⁶`
/// to the binary64 that 53-bit MPFR rounding of the exact rational gives, and answers
/// `None` exactly where that value is neither zero nor a normal `f64`. Halfway cases (a midpoint of two
/// binary64 values written as `m·5^k·10^(−k)`) decide the ties-to-even rule; the control
/// counts cases where nearest differs from truncation, so a truncating conversion fails.
#[test]
fn b19_wide_to_f64_rounds_256_bit_integers_like_mpfr() {
    use penner::io::decimal::wide_to_f64;
    let mut rng = ChaCha8Rng::seed_from_u64(19);
    let (mut normal, mut rounded_up, mut ties) = (0, 0, 0);
    for i in 0..cases(20_000, 500_000) {
        let (n, e): ([u64; 4], i32) = if i % 8 == 0 {
            // A midpoint m/2^k = m·5^k/10^k of two neighbouring binary64 values, with x
            // where m·5^k fits 256 bits (k ≤ 87: x ≥ 2^-34; x < 2^200).
            let x: f64 = rng.gen_range(1.0..10.0) * 10f64.powi(rng.gen_range(-10..60));
            let next = f64::from_bits(x.to_bits() + 1);
            let mid = (Rational::from_f64(x).unwrap() + Rational::from_f64(next).unwrap()) / 2u32;
            let (num, den) = mid.into_numer_denom();
            let k = den.significant_bits() - 1;
            let scaled = num * Integer::from(Integer::u_pow_u(5, k));
            if scaled.significant_bits() > 256 {
                continue;
            }
            let mut limbs = [0u64; 4];
            scaled.write_digits(&mut limbs, rug::integer::Order::Lsf);
            ties += 1;
            (limbs, -(k as i32))
        } else {
            let bits = rng.gen_range(1..=256u32);
            let mut limbs: [u64; 4] = rng.r#gen();
            for (j, limb) in limbs.iter_mut().enumerate() {
                let lo = 64 * j as u32;
                if bits <= lo {
                    *limb = 0;
                } else if bits < lo + 64 {
                    *limb >>= lo + 64 - bits;
                }
            }
            (limbs, rng.gen_range(-420..=420))
        };
        let q = limbs_rational(&n, e);
        let oracle = mpfr_f64(&q);
        let ours = wide_to_f64(&n, e);
        // Zero is exact; otherwise `None` exactly where the value is not a normal binary64.
        let expected = oracle.is_normal() || q == 0;
        assert_eq!(
            ours.is_some(),
            expected,
            "{n:?}e{e}: {ours:?} vs {oracle:e}"
        );
        if let Some(x) = ours {
            assert_eq!(x.to_bits(), oracle.to_bits(), "{n:?}e{e}");
            normal += 1;
            let truncated = rug::Float::with_val_round(53, &q, rug::float::Round::Zero).0;
            rounded_up += usize::from(truncated.to_f64() != x);
        }
    }
    assert!(normal > 5_000, "{normal} normal results");
    assert!(ties > 1_000, "{ties} halfway cases");
    // Control: about half the inexact cases round up, so truncation is not accepted.
    assert!(
        rounded_up > normal / 5,
        "{rounded_up} of {normal} rounded up"
    );
}

/// `squared_distance_wide` is `|b − a|²` exactly (against ℚ) on coordinates whose
/// mantissas, aligned to their smallest exponent, outgrow `u128`.
#[test]
fn squared_distance_wide_is_exact_past_u128() {
    use penner::io::decimal::squared_distance_wide;
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let mut past_u128 = 0;
    for _ in 0..cases(2_000, 100_000) {
        let mut p = || -> [Coordinate; 3] {
            std::array::from_fn(|_| {
                let m: i64 = rng.gen_range(-99_999_999_999_999_999..=99_999_999_999_999_999);
                parse_coordinate(&format!("{m}e{}", rng.gen_range(-22..=0))).unwrap()
            })
        };
        let (a, b) = (p(), p());
        let mut exact = Rational::new();
        for k in 0..3 {
            let d = b[k].to_rational() - a[k].to_rational();
            exact += Rational::from(&d * &d);
        }
        if let Some((n, e)) = squared_distance_wide(&a, &b) {
            assert_eq!(limbs_rational(&n, 2 * e), exact);
            past_u128 += usize::from(squared_distance(&a, &b).is_none());
        }
    }
    // The family reaches the wide path (else this compared the u128 path only).
    assert!(past_u128 > 100, "{past_u128} cases past u128");
}
