//! Lobachevsky's function `Л` (src/special): accuracy of every backend against the
//! independent Bernoulli/tangent-number evaluation at about twice the precision (B52, B53),
//! rigour and tightness of the interval enclosure (B52), regular ideal tetrahedron.

use crate::support::cases;
use penner::scalar::{Dd, Dual, Interval, Mpfr, Precision, Real};
use penner::special::reference::tangent_numbers;
use penner::special::{
    clausen2, ideal_tetrahedron_volume, lobachevsky, lobachevsky_enclosure,
    lobachevsky_tangent_series,
};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::float::Constant;
use rug::{Float, Integer, Rational};

/// `|y − r|` in units of `2^(e−bits)`, `r = m·2ᵉ`, `m ∈ [1/2, 1)` (ulps of a `bits`-bit
/// result; below `min_exp` the ulp is `2^(min_exp)`, the subnormal spacing of binary64).
fn ulps(y: &Float, r: &Float, bits: u32, min_exp: i32) -> f64 {
    let diff = Float::with_val(4 * bits.max(y.prec()) + 256, y - r).abs();
    if diff.is_zero() {
        return 0.0;
    }
    let e = r.get_exp().unwrap_or(min_exp + bits as i32);
    let ulp_exp = (e - bits as i32).max(min_exp);
    (diff >> ulp_exp).to_f64()
}

/// Arguments of every kind: moderate, tiny, next to multiples of π/2 and π/6, large.
fn arguments(rng: &mut ChaCha8Rng, count: usize) -> Vec<f64> {
    let mut out = vec![
        0.0,
        -0.0,
        5e-324,
        1e-300,
        -1e-300,
        std::f64::consts::FRAC_PI_2,
        std::f64::consts::PI,
        -std::f64::consts::PI,
        std::f64::consts::PI / 6.0,
        std::f64::consts::PI / 3.0,
        0.5,
        std::f64::consts::FRAC_PI_4,
        1e22,
        1e300,
        -1.7976931348623157e308,
        6381956970095103.0 * 2f64.powi(797),
    ];
    let hp = Float::with_val(2000, Constant::Pi) >> 1u32;
    while out.len() < count {
        let x = match out.len() % 5 {
            0 => rng.gen_range(-20.0..20.0),
            1 => rng.gen_range(0.5..1.0) * 2f64.powi(-rng.gen_range(1..1074)),
            2 => {
                let top: u32 = rng.gen_range(1..30);
                let k: u32 = rng.gen_range(1..1 << top);
                let base = Float::with_val(2000, &hp * k).to_f64();
                let steps = rng.gen_range(-3i64..=3);
                f64::from_bits((base.to_bits() as i64 + steps) as u64)
            }
            3 => {
                let k = f64::from(rng.gen_range(-50i32..50));
                (k + 1.0 / 6.0) * std::f64::consts::PI + rng.gen_range(-1e-6..1e-6)
            }
            _ => rng.gen_range(0.5..1.0) * 2f64.powi(rng.gen_range(20..1023)),
        };
        out.push(if rng.r#gen() { x } else { -x });
    }
    out
}

fn reference(x: f64, bits: u32) -> Float {
    lobachevsky_tangent_series(&Float::with_val(53, x), bits).expect("finite argument")
}

/// B53: the binary64 path is within [`F64_ULPS`] ulps of the reference.
const F64_ULPS: f64 = 4.0; // proof: B53

#[test]
fn b53_f64_within_few_ulps_of_the_tangent_series() {
    let mut rng = ChaCha8Rng::seed_from_u64(53);
    let mut worst = (0.0, 0.0);
    for x in arguments(&mut rng, cases(3000, 100_000)) {
        let y = lobachevsky(&x);
        let r = reference(x, 2 * 53 + 16);
        let e = ulps(&Float::with_val(53, y), &r, 53, -1074);
        if e > worst.0 {
            worst = (e, x);
        }
        assert!(e <= F64_ULPS, "Л({x:e}) = {y:e}, {e} ulps from {r}");
        // Negative control: 8 ulps away is rejected by the same measure.
        if !r.is_zero() {
            let ulp_exp = (r.get_exp().unwrap_or(0) - 53).max(-1074);
            let bumped = Float::with_val(64, y) + (Float::with_val(64, 8) << ulp_exp);
            assert!(
                ulps(&bumped, &r, 53, -1074) > F64_ULPS,
                "negative control at {x:e}"
            );
        }
    }
    eprintln!("f64 worst {} ulps at {:e}", worst.0, worst.1);
}

/// Exact binary arguments at `p` bits: moderate, tiny (down to 2⁻³⁰⁰⁰), next to multiples
/// of π/2 (closer than `2^(−p)`), large.
fn mpfr_arguments(rng: &mut ChaCha8Rng, p: u32, count: usize) -> Vec<Float> {
    let hp = Float::with_val(4 * p + 64, Constant::Pi) >> 1u32;
    let mut out = vec![
        Float::with_val(p, 1) >> 3000u32,
        Float::with_val(p, Float::with_val(p + 8, &hp * 3u32)),
        Float::with_val(p, &hp),
    ];
    while out.len() < count {
        let m = Float::with_val(p, rng.gen_range(0.5..1.0));
        let x = match out.len() % 4 {
            0 => Float::with_val(p, rng.gen_range(-20.0..20.0)) + (m >> (p / 2)),
            1 => m >> rng.gen_range(1..3000u32),
            2 => {
                let k: u32 = rng.gen_range(1..1000);
                Float::with_val(p, &hp * k)
            }
            _ => m << rng.gen_range(10..400u32),
        };
        out.push(if rng.r#gen() { x } else { -x });
    }
    out
}

#[test]
fn b52_mpfr_and_dd_within_one_ulp_of_the_tangent_series() {
    let mut rng = ChaCha8Rng::seed_from_u64(52);
    let precisions: &[u32] = if std::env::var_os("PENNER_LONG").is_some() {
        &[64, 128, 256, 1024, 4096]
    } else {
        &[64, 256, 1024]
    };
    for &p in precisions {
        let count = cases(
            if p > 512 { 8 } else { 60 },
            if p > 1024 { 200 } else { 5000 },
        );
        let prec = Precision::new(u64::from(p)).unwrap();
        for x in mpfr_arguments(&mut rng, p, count) {
            let y = lobachevsky(&Mpfr(x.clone()));
            let r = lobachevsky_tangent_series(&x, 2 * p).unwrap();
            let e = ulps(&y.0, &r, p, i32::MIN / 2);
            assert!(e <= 1.0, "p = {p}: Л({x}) off by {e} ulps");

            assert_eq!(y.precision(), prec);
            // Negative control: a 2-ulp change is rejected.
            let bumped = Float::with_val(p + 8, &y.0)
                + (Float::with_val(8, 2) << (r.get_exp().unwrap_or(0) - p as i32));
            assert!(r.is_zero() || ulps(&bumped, &r, p, i32::MIN / 2) > 1.0);
        }
    }
    for x in arguments(&mut rng, cases(300, 20_000)) {
        let y = lobachevsky(&Dd::from_f64(x));

        let r = reference(x, 2 * 106 + 16);
        let yf = Float::with_val(200, y.hi) + y.lo;
        // Below 2⁻⁹⁶⁸ a Dd carries an absolute 2⁻¹⁰⁷⁵ (B09).
        let e = ulps(&yf, &r, 106, -1075);
        // The native double-double series (B55) is within 4 units after the short
        // reduction (|x| ≤ 3.9) and within 5 after Payne–Hanek (beyond); the MPFR path,
        // taken within 2⁻³⁰ (resp. 2⁻¹⁰⁰) of multiples of π/2, within one.
        let bound = if x.abs() <= 3.9 { 4.0 } else { 5.0 }; // proof: B55
        assert!(e <= bound, "Dd: Л({x:e}) off by {e} ulps");
    }
}

#[test]
fn b52_tiny_arguments_follow_x_times_one_minus_log_2x() {
    // Л(x) = x(1 − log 2x) + x³/18 + O(x⁵): at 2⁻³⁰⁰⁰ the cubic term is far below an ulp.
    let p = Precision::new(200).unwrap();
    let x = Float::with_val(200, 1) >> 3000u32;
    let y = lobachevsky(&Mpfr(x.clone()));
    let two_x = Float::with_val(400, &x << 1u32);
    let expect = Float::with_val(400, 1 - two_x.ln()) * &x;
    assert!(ulps(&y.0, &expect, 200, i32::MIN / 2) <= 1.0);
    assert!(y.0 > 0 && y.precision() == p);
    let y = lobachevsky(&1e-300_f64);
    let expect = 1e-300 * (1.0 - (2e-300_f64).ln());
    assert!((y - expect).abs() <= 2.0 * f64::EPSILON * expect);
    assert!(lobachevsky(&-1e-300_f64) == -y);
    // Negative control: dropping the logarithm is far off.
    assert!((1e-300 - y).abs() > 0.5 * y);
}

#[test]
fn b52_enclosure_contains_the_reference_and_is_a_few_ulps_wide() {
    let mut rng = ChaCha8Rng::seed_from_u64(5252);
    for &p in &[64u32, 256, 1024] {
        let prec = Precision::new(u64::from(p)).unwrap();
        for x in mpfr_arguments(&mut rng, p, cases(if p > 512 { 6 } else { 40 }, 2000)) {
            let enc = lobachevsky_enclosure(&Interval::point(Mpfr(x.clone())));
            let r = lobachevsky_tangent_series(&x, 2 * p).unwrap();
            let (lo, hi) = (&enc.lo().0, &enc.hi().0);
            assert!(
                *lo <= r && r <= *hi,
                "p = {p}: [{lo}, {hi}] misses Л({x}) = {r}"
            );
            let w = ulps(hi, lo, p, i32::MIN / 2);
            let scale = ulps(hi, &r, p, i32::MIN / 2) + ulps(&r, lo, p, i32::MIN / 2);
            assert!(scale <= 4.0 && w <= 4.0, "p = {p}: width {w} ulps at {x}");
            assert_eq!(enc.lo().precision(), prec);
            // Negative control: the enclosure moved by its width plus one ulp misses.
            let shift = Float::with_val(p, hi - lo)
                + (Float::with_val(p, 1) << (r.get_exp().unwrap_or(0) - p as i32));
            let moved_lo = Float::with_val(p, lo + &shift);
            assert!(r.is_zero() || moved_lo > r || hi == lo);
        }
    }
}

#[test]
fn b52_enclosure_of_wide_intervals_contains_every_sampled_value() {
    let mut rng = ChaCha8Rng::seed_from_u64(99);
    let p = Precision::new(128).unwrap();
    let m = 0.5074708; // Л(π/6) rounded down
    for _ in 0..cases(200, 20_000) {
        let a: f64 = rng.gen_range(-10.0..10.0);
        let b = a + rng.gen_range(0.0..2.0f64).powi(3);
        let enc = lobachevsky_enclosure(&Interval::new(Mpfr::from_f64(a, p), Mpfr::from_f64(b, p)));
        for i in 0..=16 {
            let x = a + (b - a) * f64::from(i) / 16.0;
            let r = reference(x, 200);
            assert!(enc.lo().0 <= r && r <= enc.hi().0, "[{a}, {b}] at {x}");
        }
        // Never wider than the range of Л.
        assert!(enc.lo().0 >= -m - 1e-6 && enc.hi().0 <= m + 1e-6);
    }
    // An interval around π/6 reaches the maximum, one on (π/6, π/2) is the endpoint hull.
    let pi = std::f64::consts::PI;
    let enc = lobachevsky_enclosure(&Interval::new(
        Mpfr::from_f64(0.5, p),
        Mpfr::from_f64(0.6, p),
    ));
    assert!(enc.hi().0 >= m);
    let enc = lobachevsky_enclosure(&Interval::new(
        Mpfr::from_f64(0.6, p),
        Mpfr::from_f64(pi / 2.0 - 0.1, p),
    ));
    let top = reference(0.6, 200);
    assert!(enc.hi().0 >= top && Float::with_val(128, &enc.hi().0 - &top) < 1e-30);
    // Negative control: the hull of the endpoints alone misses the maximum inside [0.5, 0.6].
    assert!(reference(0.5, 200).max(&reference(0.6, 200)) < m);
    // Unbounded and invalid.
    let all = lobachevsky_enclosure(&Interval::new(
        Mpfr::from_f64(0.0, p),
        Mpfr::from_f64(f64::INFINITY, p),
    ));
    assert!(all.hi().0 >= m && all.lo().0 <= -m);
    assert!(!lobachevsky_enclosure(&Interval::invalid(p)).is_valid());
}

#[test]
fn b52_generic_interval_and_dual_paths() {
    // Interval<f64> through the generic function is an outward-rounded enclosure.
    let x = Interval::new(1.0_f64, 1.0);
    let y = lobachevsky(&x);
    let r = reference(1.0, 200);
    assert!(Float::with_val(53, *y.lo()) <= r && r <= Float::with_val(53, *y.hi()));
    assert!(y.hi() - y.lo() <= 4.0 * f64::EPSILON);
    // Dual: the derivative is −log|2 sin x| (computed here in MPFR).
    for &x in &[0.3, 1.0, 2.5, -7.0, 1e6] {
        let d = lobachevsky(&Dual::variable(x));
        let s = Float::with_val(200, x).sin() * 2u32;
        let expect = -s.abs().ln().to_f64();
        assert!(
            (d.d - expect).abs() <= 8.0 * f64::EPSILON * (1.0 + expect.abs()),
            "{x}"
        );
        assert!((d.v - lobachevsky(&x)).abs() <= F64_ULPS * f64::EPSILON * d.v.abs());
        // Nested duals: Л″(x) = −cot x.
        let dd = lobachevsky(&Dual::variable(Dual::variable(x)));
        let cot = (Float::with_val(200, x).cos() / Float::with_val(200, x).sin()).to_f64();
        assert!(
            (dd.d.d + cot).abs() <= 1e-9 * (1.0 + cot.abs()),
            "{x}: {} vs {}",
            dd.d.d,
            -cot
        );
        // Negative control: the derivative of sin instead is rejected.
        assert!((x.cos() - expect).abs() > 1e-3);
    }
    let dd = lobachevsky(&Dual::variable(Dd::from_f64(0.4)));
    let s = Float::with_val(300, 0.4).sin() * 2u32;
    let expect = Float::with_val(300, -s.ln());
    let got = Float::with_val(300, dd.d.hi) + dd.d.lo;
    assert!(ulps(&got, &expect, 100, i32::MIN / 2) <= 8.0);
}

#[test]
fn b52_tangent_numbers_and_bernoulli() {
    let t = tangent_numbers(6);
    let known = [1u32, 2, 16, 272, 7936, 353792];
    for (a, b) in t.iter().zip(known) {
        assert_eq!(*a, b);
    }
    // |B₂ₙ| = 2n Tₙ / (4ⁿ (4ⁿ − 1)): B₂ = 1/6, B₄ = 1/30, B₆ = 1/42, B₁₂ = 691/2730.
    let b = |n: u32| {
        let four = Integer::from(1) << (2 * n);
        Rational::from((
            Integer::from(&t[n as usize - 1] * (2 * n)),
            &four * (four.clone() - 1u32),
        ))
    };
    assert_eq!(b(1), Rational::from((1, 6)));
    assert_eq!(b(2), Rational::from((1, 30)));
    assert_eq!(b(3), Rational::from((1, 42)));
    assert_eq!(b(6), Rational::from((691, 2730)));
    assert_ne!(b(5), Rational::from((5, 67)));
}

#[test]
fn t30_identities_hold_at_every_precision_and_the_control_fails() {
    use penner::theorems::t30_lobachevsky::{check_lobachevsky, check_lobachevsky_certified};
    let mut rng = ChaCha8Rng::seed_from_u64(30);
    let xs: Vec<f64> = (0..cases(6, 200))
        .map(|i| match i % 3 {
            0 => rng.gen_range(-4.0..4.0),
            1 => rng.gen_range(0.5..1.0) * 2f64.powi(-rng.gen_range(1..900)),
            _ => rng.gen_range(-1e4..1e4),
        })
        .collect();
    assert!(check_lobachevsky(&xs, false).holds());
    let dd: Vec<Dd> = xs.iter().map(|&x| Dd::from_f64(x)).collect();
    assert!(check_lobachevsky(&dd, false).holds());
    let p = Precision::new(512).unwrap();
    let mp: Vec<Mpfr> = xs.iter().map(|&x| Mpfr::from_f64(x, p)).collect();
    assert!(check_lobachevsky(&mp, false).holds());
    let q: Vec<Rational> = xs.iter().map(|&x| Rational::from_f64(x).unwrap()).collect();
    let v = check_lobachevsky_certified(&q, 128, false);
    assert!(
        matches!(
            v,
            penner::theorems::Verdict::Holds {
                certified: true,
                ..
            }
        ),
        "{v:?}"
    );
    // Negative control: one side's argument × 1.01 is refuted, certified, at every precision.
    for v in [
        check_lobachevsky(&xs, true),
        check_lobachevsky(&dd, true),
        check_lobachevsky(&mp, true),
        check_lobachevsky_certified(&q, 128, true),
    ] {
        assert!(
            matches!(
                v,
                penner::theorems::Verdict::Fails {
                    certified: true,
                    ..
                }
            ),
            "{v:?}"
        );
    }
}

/// `ζ(2, a) = Σ_{m≥0} (m + a)⁻²` by Euler–Maclaurin with exact Bernoulli numbers from the
/// classical recurrence: `Σ_{m<N} (m+a)⁻² + 1/(N+a) + 1/(2(N+a)²) + Σ_{k=1}^{K} B₂ₖ/(N+a)^{2k+1}`.
fn hurwitz_zeta2(a: &Rational, prec: u32) -> Float {
    const N: u32 = 60;
    const K: usize = 40;
    let mut bern = vec![Rational::from(1)];
    for k in 1..=2 * K {
        let mut s = Rational::new();
        for (j, b) in bern.iter().enumerate() {
            s += Rational::from(Integer::from(Integer::binomial_u(k as u32 + 1, j as u32))) * b;
        }
        bern.push(-s / Rational::from(k + 1));
    }
    let mut sum = Float::new(prec);
    for m in 0..N {
        let x = Float::with_val(prec, Rational::from(a + m));
        sum += Float::with_val(prec, x.square_ref()).recip();
    }
    let na = Float::with_val(prec, Rational::from(a + N));
    sum += Float::with_val(prec, na.recip_ref());
    sum += Float::with_val(prec, na.square_ref()).recip() / 2u32;
    for k in 1..=K {
        let pow = Float::with_val(prec, rug::ops::Pow::pow(&na, 2 * k as u32 + 1));
        sum += Float::with_val(prec, &bern[2 * k]) / pow;
    }
    sum
}

#[test]
fn regular_ideal_tetrahedron_volume_to_60_digits() {
    // V = 3Л(π/3) = (3/2) Cl₂(2π/3), Cl₂(2π/3) = (√3/2) Σ_{k≢0 (3)} ±1/k² = (ψ₁(1/3) − ψ₁(2/3))/(6√3),
    // ψ₁(a) = ζ(2, a): V = (ζ(2, 1/3) − ζ(2, 2/3)) / (4√3).
    let prec = 260; // > 60 digits
    let z =
        hurwitz_zeta2(&Rational::from((1, 3)), prec) - hurwitz_zeta2(&Rational::from((2, 3)), prec);
    let expect = z / (Float::with_val(prec, 3).sqrt() * 4u32);
    let p = Precision::new(256).unwrap();
    let third = Mpfr::pi(p) / Mpfr::from_f64(3.0, p);
    let v = ideal_tetrahedron_volume(&third, &third, &third);
    let err = Float::with_val(prec, &v.0 - &expect).abs();
    assert!(err < 1e-70, "V = {}, ψ₁ form {expect}, error {err}", v.0);
    let c = clausen2(&(Mpfr::pi(p) * &Mpfr::from_f64(2.0, p) / &Mpfr::from_f64(3.0, p)));
    let err_c = Float::with_val(prec, Float::with_val(prec, &c.0 * 3u32) / 2u32 - &expect).abs();
    assert!(err_c < 1e-70);
    // The published value to 20 digits.
    assert!((v.approx_f64() - 1.0149416064096536).abs() < 1e-15);
    // Negative control: Л(π/3)·3 at an argument off by 2⁻²⁰⁰ is seen at this accuracy.
    let off = third.clone() + &Mpfr(Float::with_val(256, 1) >> 200u32);
    let w = ideal_tetrahedron_volume(&off, &third, &third);
    assert!(Float::with_val(prec, &w.0 - &expect).abs() > 1e-70);
}

#[test]
fn regular_ideal_tetrahedron_is_the_maximum() {
    // On α + β + γ = π: V(α, β) = Л(α) + Л(β) − Л(α + β). ∂V/∂α = log|2 sin(α+β)| − log|2 sin α|,
    // with Л″ = −cot the Hessian is H = [[−cot α + cot(α+β), cot(α+β)],
    // [cot(α+β), −cot β + cot(α+β)]]. Certified at α = β = π/3 with intervals.
    let p = Precision::new(128).unwrap();
    let pi = Interval::<Mpfr>::pi(p);
    let three = Interval::point(Mpfr::from_f64(3.0, p));
    let a = pi.clone() / &three;
    let s = a.clone() + &a;
    let two = Interval::point(Mpfr::from_f64(2.0, p));
    let grad = (s.sin() * &two).ln() - &(a.sin() * &two).ln();
    assert!(grad.contains_zero() && grad.width_f64() < 1e-30);
    let cot = |x: &Interval<Mpfr>| x.cos() / &x.sin();
    let h11 = cot(&s) - &cot(&a);
    let h12 = cot(&s);
    let det = h11.clone() * &h11 - &(h12.clone() * &h12);
    assert_eq!(h11.sign(), Some(penner::scalar::Sign::Negative));
    assert_eq!(det.sign(), Some(penner::scalar::Sign::Positive));
    // Negative control: at α = β = 1 the gradient enclosure excludes 0 (V is concave on
    // the whole simplex, so only the gradient singles out the regular point).
    let b = Interval::point(Mpfr::from_f64(1.0, p));
    let s2 = b.clone() + &b;
    let grad_b = (s2.sin() * &two).ln() - &(b.sin() * &two).ln();
    assert!(!grad_b.contains_zero());
    // Elsewhere on the simplex (numerical): V < V_reg.
    let vreg = ideal_tetrahedron_volume(
        &(std::f64::consts::PI / 3.0),
        &(std::f64::consts::PI / 3.0),
        &(std::f64::consts::PI / 3.0),
    );
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    for _ in 0..cases(2000, 200_000) {
        let x: f64 = rng.gen_range(0.0..std::f64::consts::PI);
        let y: f64 = rng.gen_range(0.0..std::f64::consts::PI - x);
        let z = std::f64::consts::PI - x - y;
        assert!(ideal_tetrahedron_volume(&x, &y, &z) <= vreg + 1e-15);
    }
}
