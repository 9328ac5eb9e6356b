//! Accuracy of the double-double backend against MPFR (proofs B01–B15).
//!
//! Every reference is computed from the exact value of the `Dd` inputs: exactly in ℚ for
//! `+ − ×`, with MPFR at 512 bits otherwise. Errors are reported in units of
//! u² = 2⁻¹⁰⁶ (u = 2⁻⁵³).

use crate::support::cases;
use penner::scalar::{dd_sloppy_add, Dd, Real};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::{Float, Rational};

/// Reference precision in bits.
pub(crate) const REF_BITS: u32 = 512;
/// u² = 2⁻¹⁰⁶.
pub(crate) fn u2() -> f64 {
    (-106.0_f64).exp2()
}

pub(crate) fn q(x: Dd) -> Rational {
    x.to_rational().expect("finite")
}

pub(crate) fn fl(x: Dd) -> Float {
    Float::with_val(REF_BITS, q(x))
}

/// |computed − exact| / |exact| in units of u²; `exact` must be nonzero.
pub(crate) fn rel_err_u2(c: Dd, exact: &Rational) -> f64 {
    let e = (q(c) - exact).abs() / exact.clone().abs();
    e.to_f64() / u2()
}

pub(crate) fn exact_of(f: &Float) -> Rational {
    f.to_rational().expect("finite reference")
}

/// A normalized double-double with `hi` of exponent in `[emin, emax]`, random sign,
/// and `lo` uniformly filling the half-ulp of `hi`.
pub(crate) fn rand_dd(rng: &mut ChaCha8Rng, emin: i32, emax: i32) -> Dd {
    let m: f64 = rng.gen_range(1.0..2.0);
    let e = rng.gen_range(emin..=emax);
    let hi = m * 2f64.powi(e) * if rng.gen_bool(0.5) { 1.0 } else { -1.0 };
    let ulp = hi.abs() * f64::EPSILON;
    let lo = rng.gen_range(-0.5..0.5) * ulp;
    Dd::from_parts(hi, lo)
}

/// Positive version of [`rand_dd`].
fn rand_pos(rng: &mut ChaCha8Rng, emin: i32, emax: i32) -> Dd {
    rand_dd(rng, emin, emax).abs()
}

/// `x` perturbed by a relative amount ≈ 2^-k (k up to 110): near-cancellation partner.
pub(crate) fn near(rng: &mut ChaCha8Rng, x: Dd) -> Dd {
    let k = rng.gen_range(1..=115);
    let d: f64 = rng.gen_range(-1.0..1.0) * 2f64.powi(-k);
    x + x * Dd::from_f64(d)
}

/// Checks `err(case) ≤ bound` over all cases; returns the maximum error.
pub(crate) fn worst<I, F>(inputs: I, mut err: F) -> (f64, Option<String>)
where
    I: IntoIterator,
    I::Item: std::fmt::Debug,
    F: FnMut(&I::Item) -> f64,
{
    let mut max = 0.0_f64;
    let mut arg = None;
    for x in inputs {
        let e = err(&x);
        assert!(!e.is_nan(), "NaN error at {x:?}");
        if e > max {
            max = e;
            arg = Some(format!("{x:?}"));
        }
    }
    (max, arg)
}

pub(crate) fn binary_inputs(seed: u64, n: usize, cancel: bool) -> Vec<(Dd, Dd)> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut v = Vec::with_capacity(n);
    for i in 0..n {
        let (a, b) = match i % 4 {
            0 => (rand_dd(&mut rng, -30, 30), rand_dd(&mut rng, -30, 30)),
            1 => (rand_dd(&mut rng, -480, 480), rand_dd(&mut rng, -480, 480)),
            2 => {
                let a = rand_dd(&mut rng, -10, 10);
                let b = near(&mut rng, a);
                (a, if cancel { -b } else { b })
            }
            _ => {
                // Powers of two and their neighbours, where rounding boundaries sit.
                let e = rng.gen_range(-40..40);
                let a = Dd::from_parts(2f64.powi(e), rng.gen_range(-1.0..1.0) * 2f64.powi(e - 54));
                (a, rand_dd(&mut rng, -3, 3))
            }
        };
        v.push((a, b));
    }
    v
}

// ---------------------------------------------------------------- arithmetic (B01–B09)

#[test]
fn b01_two_sum_is_exact() {
    let inputs = binary_inputs(1, cases(4000, 100_000), true);
    for (a, b) in inputs {
        let (x, y) = (a.hi, b.hi * 2f64.powi((a.hi.abs().log2() as i32) % 60));
        // from_parts is TwoSum; Dd(x) + Dd(y) reduces to TwoSum and Fast2Sum.
        let exact = q(Dd::from_f64(x)) + q(Dd::from_f64(y));
        assert_eq!(q(Dd::from_parts(x, y)), exact, "TwoSum({x:e}, {y:e})");
        assert_eq!(
            q(Dd::from_f64(x) + Dd::from_f64(y)),
            exact,
            "Dd({x:e}) + Dd({y:e})"
        );
        let s = Dd::from_parts(x, y);
        assert!(
            s.lo.abs() <= s.hi.abs() * f64::EPSILON / 2.0,
            "not normalized: {s:?}"
        );
    }
}

#[test]
fn b01_negative_control_plain_sum_is_inexact() {
    let (x, y) = (1.0, 2f64.powi(-60));
    assert_ne!(
        q(Dd::from_f64(x + y)),
        q(Dd::from_f64(x)) + q(Dd::from_f64(y))
    );
}

#[test]
fn b02_two_prod_is_exact() {
    let inputs = binary_inputs(2, cases(4000, 100_000), false);
    for (a, b) in inputs {
        // With zero low parts DWTimesDW3 reduces to TwoProd followed by Fast2Sum.
        let p = Dd::from_f64(a.hi) * Dd::from_f64(b.hi);
        assert_eq!(
            q(p),
            q(Dd::from_f64(a.hi)) * q(Dd::from_f64(b.hi)),
            "{a:?} {b:?}"
        );
    }
    // Negative control: the rounded product alone is not exact.
    let x = 1.0 + f64::EPSILON;
    assert_ne!(
        q(Dd::from_f64(x * x)),
        q(Dd::from_f64(x)) * q(Dd::from_f64(x))
    );
}

#[test]
fn b03_dd_plus_f64_within_2u2() {
    let inputs = binary_inputs(3, cases(4000, 100_000), true);
    let (max, at) = worst(inputs.iter().copied(), |&(a, b)| {
        let exact = q(a) + q(Dd::from_f64(b.hi));
        if exact == 0 {
            return if q(a.add_f64(b.hi)) == 0 {
                0.0
            } else {
                f64::INFINITY
            };
        }
        rel_err_u2(a.add_f64(b.hi), &exact)
    });
    eprintln!("b03 dd+f64: max {max:.3} u² at {at:?}");
    assert!(max <= 2.0, "max {max} u² at {at:?}");
}

#[test]
fn b05_dd_times_f64_within_2u2() {
    let inputs = binary_inputs(5, cases(4000, 100_000), false);
    let (max, at) = worst(inputs.iter().copied(), |&(a, b)| {
        rel_err_u2(a.mul_f64(b.hi), &(q(a) * q(Dd::from_f64(b.hi))))
    });
    eprintln!("b05 dd×f64: max {max:.3} u² at {at:?}");
    assert!(max <= 2.0, "max {max} u² at {at:?}");
}

#[test]
fn b04_dd_add_sub_within_4u2() {
    let n = cases(4000, 200_000);
    let inputs = binary_inputs(4, n, true);
    for sub in [false, true] {
        let (max, at) = worst(inputs.iter().copied(), |&(a, b)| {
            let exact = if sub { q(a) - q(b) } else { q(a) + q(b) };
            let c = if sub { a - b } else { a + b };
            if exact == 0 {
                return if q(c) == 0 { 0.0 } else { f64::INFINITY };
            }
            rel_err_u2(c, &exact)
        });
        eprintln!(
            "b04 {}: max {max:.3} u² at {at:?}",
            if sub { "sub" } else { "add" }
        );
        assert!(max <= 4.0, "max {max} u² at {at:?}");
    }
}

#[test]
fn b04_negative_control_sloppy_add_fails_on_cancellation() {
    let inputs = binary_inputs(41, 2000, true);
    let (max, _) = worst(inputs.iter().copied(), |&(a, b)| {
        let exact = q(a) + q(b);
        if exact == 0 {
            return 0.0;
        }
        rel_err_u2(dd_sloppy_add(a, b), &exact)
    });
    eprintln!("sloppy add: max {max:.3e} u²");
    assert!(
        max > 4.0,
        "the check did not reject the sloppy add (max {max} u²)"
    );
}

#[test]
fn b06_dd_mul_within_4u2() {
    let n = cases(4000, 200_000);
    let inputs = binary_inputs(6, n, false);
    let (max, at) = worst(inputs.iter().copied(), |&(a, b)| {
        rel_err_u2(a * b, &(q(a) * q(b)))
    });
    eprintln!("b06 mul: max {max:.3} u² at {at:?}");
    assert!(max <= 4.0, "max {max} u² at {at:?}");
}

#[test]
fn b06_negative_control_f64_product_fails() {
    let inputs = binary_inputs(61, 500, false);
    let (max, _) = worst(inputs.iter().copied(), |&(a, b)| {
        rel_err_u2(Dd::from_f64(a.hi * b.hi), &(q(a) * q(b)))
    });
    assert!(
        max > 4.0,
        "the check did not reject an f64 product (max {max} u²)"
    );
}

#[test]
fn b08_dd_sqrt_within_4u2() {
    let n = cases(4000, 200_000);
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    let mut inputs: Vec<Dd> = (0..n)
        .map(|i| {
            rand_pos(
                &mut rng,
                if i % 2 == 0 { -30 } else { -900 },
                if i % 2 == 0 { 30 } else { 900 },
            )
        })
        .collect();
    for _ in 0..n / 4 {
        // Perfect squares nudged by one unit of the low part, and values near 1 and 4ᵏ.
        let s = rand_pos(&mut rng, -10, 10);
        let sq = s * s;
        inputs.push(Dd::from_parts(
            sq.hi,
            sq.lo + rng.gen_range(-2.0..2.0) * sq.hi.abs() * 2f64.powi(-106),
        ));
        let k = rng.gen_range(-30..30);
        inputs.push(Dd::from_parts(
            4f64.powi(k),
            rng.gen_range(-1.0..1.0) * 4f64.powi(k) * 2f64.powi(-60),
        ));
    }
    let (max, at) = worst(inputs.iter().copied(), |&a| {
        rel_err_u2(a.sqrt(), &exact_of(&fl(a).sqrt()))
    });
    eprintln!("b08 sqrt: max {max:.3} u² at {at:?}");
    assert!(max <= 4.0, "max {max} u² at {at:?}");
}

#[test]
fn b09_dd_from_rational_within_u2() {
    let n = cases(3000, 100_000);
    let mut rng = ChaCha8Rng::seed_from_u64(9);
    let mut max = 0.0_f64;
    for i in 0..n {
        let num =
            rug::Integer::from(rng.r#gen::<u64>()) * rug::Integer::from(rng.r#gen::<u64>()) + 1u32;
        let den =
            rug::Integer::from(rng.r#gen::<u64>()) * rug::Integer::from(rng.r#gen::<u32>()) + 1u32;
        let shift = (i % 400) as i32 - 200;
        let mut r = Rational::from((num, den));
        if shift >= 0 {
            r <<= shift as u32;
        } else {
            r >>= (-shift) as u32;
        }
        if rng.gen_bool(0.5) {
            r = -r;
        }
        let d = Dd::from_rational(&r, ());
        assert!(
            d.lo.abs() <= d.hi.abs() * f64::EPSILON / 2.0,
            "not normalized: {d:?}"
        );
        max = max.max(rel_err_u2(d, &r));
    }
    // The bound of B09 is u²(1 + u).
    let max_u2 = max;
    eprintln!("b09 from_rational: max {max_u2:.3} u²");
    assert!(max_u2 <= 1.0 + f64::EPSILON, "max {max_u2} u²");
}

#[test]
fn b09_negative_control_truncating_conversion_fails() {
    // Rounding once to f64 is off by up to u, far beyond u².
    let r = Rational::from((1, 3));
    let once = Dd::from_f64(Float::with_val(53, &r).to_f64());
    assert!(rel_err_u2(once, &r) > 1.0);
}

#[test]
fn b09_dd_constants_are_nearest() {
    let p = Float::with_val(REF_BITS, rug::float::Constant::Pi);
    let nearest = Dd::from_float(&p);
    assert_eq!(Dd::pi(()), nearest);
    assert_eq!(Dd::from_rational(&exact_of(&p), ()), nearest);
}

// ---------------------------------------------------------------- functions (B10–B14)

/// A double-double uniform in `[a, b]` (hi uniform, lo filling its half-ulp).
pub(crate) fn uniform(rng: &mut ChaCha8Rng, a: f64, b: f64) -> Dd {
    let hi: f64 = rng.gen_range(a..b);
    Dd::from_parts(hi, rng.gen_range(-0.5..0.5) * hi.abs() * f64::EPSILON)
}

/// `±2^-k (1 + tiny)` for k in `[kmin, kmax]`.
pub(crate) fn tiny(rng: &mut ChaCha8Rng, kmin: i32, kmax: i32) -> Dd {
    let m: f64 = rng.gen_range(1.0..2.0);
    let s = if rng.gen_bool(0.5) { 1.0 } else { -1.0 };
    let hi = s * m * 2f64.powi(-rng.gen_range(kmin..=kmax));
    Dd::from_parts(hi, rng.gen_range(-0.5..0.5) * hi.abs() * f64::EPSILON)
}

/// Relative error in u² of a unary function against MPFR at 512 bits; `None` when the
/// reference is exactly zero.
pub(crate) fn unary_err(x: Dd, c: Dd, f: impl Fn(Float) -> Float) -> f64 {
    let r = exact_of(&f(fl(x)));
    if r == 0 {
        return if q(c) == 0 { 0.0 } else { f64::INFINITY };
    }
    rel_err_u2(c, &r)
}

/// Error in units of u² relative to `max(|f(x)|, floor)`: a relative bound away from the
/// zeros of `f`, an absolute one (`floor · 16u²`) near them.
pub(crate) fn mixed_err(x: Dd, c: Dd, floor: f64, f: impl Fn(Float) -> Float) -> f64 {
    let r = exact_of(&f(fl(x)));
    let scale = std::cmp::max(r.clone().abs(), Rational::from_f64(floor).expect("finite"));
    ((q(c) - r).abs() / scale).to_f64() / u2()
}

fn exp_inputs(n: usize) -> Vec<Dd> {
    let mut rng = ChaCha8Rng::seed_from_u64(10);
    let ln2 = std::f64::consts::LN_2;
    (0..n)
        .map(|i| match i % 4 {
            // Below about −669 the low part of e^x is subnormal (outside B10's range).
            0 => uniform(&mut rng, -660.0, 709.0),
            1 => uniform(&mut rng, -2.0, 2.0),
            2 => tiny(&mut rng, 1, 100),
            // Near the reduction boundaries (k + 1/2)·ln 2 and near k·ln 2.
            _ => {
                let k = f64::from(rng.gen_range(-900..900)) / 2.0;
                Dd::from_parts(
                    k * ln2,
                    rng.gen_range(-1.0..1.0) * 2f64.powi(-rng.gen_range(10..60)),
                )
            }
        })
        .collect()
}

#[test]
fn b10_dd_exp_within_16u2() {
    let inputs = exp_inputs(cases(3000, 100_000));
    let (max, at) = worst(inputs.iter().copied(), |&x| {
        unary_err(x, x.exp(), Float::exp)
    });
    eprintln!("b10 exp: max {max:.3} u² at {at:?}");
    assert!(max <= 16.0, "max {max} u² at {at:?}");
}

#[test]
fn b10_negative_control_f64_exp_fails() {
    let inputs = exp_inputs(400);
    let (max, _) = worst(inputs.iter().copied(), |&x| {
        unary_err(x, Dd::from_f64(x.hi.exp()), Float::exp)
    });
    assert!(
        max > 16.0,
        "the check did not reject the f64 exponential (max {max} u²)"
    );
}

fn ln_inputs(n: usize) -> Vec<Dd> {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    (0..n)
        .map(|i| match i % 4 {
            0 => rand_pos(&mut rng, -900, 900),
            1 => uniform(&mut rng, 0.25, 4.0),
            // 1 + δ, δ down to 2⁻¹¹⁰: ln has a zero at 1.
            2 => Dd::from_f64(1.0) + tiny(&mut rng, 1, 110),
            // Near √2·2ᵏ, the reduction boundary.
            _ => {
                let k = rng.gen_range(-50..50);
                Dd::from_parts(
                    std::f64::consts::SQRT_2 * 2f64.powi(k),
                    rng.gen_range(-1.0..1.0) * 2f64.powi(k - 56),
                )
            }
        })
        .collect()
}

#[test]
fn b11_dd_ln_within_16u2() {
    let inputs = ln_inputs(cases(3000, 100_000));
    let (max, at) = worst(inputs.iter().copied(), |&x| unary_err(x, x.ln(), Float::ln));
    eprintln!("b11 ln: max {max:.3} u² at {at:?}");
    assert!(max <= 16.0, "max {max} u² at {at:?}");
}

#[test]
fn b11_negative_control_f64_ln_fails() {
    let inputs = ln_inputs(400);
    let (max, _) = worst(inputs.iter().copied(), |&x| {
        unary_err(x, Dd::from_f64(x.hi.ln()), Float::ln)
    });
    assert!(
        max > 16.0,
        "the check did not reject the f64 logarithm (max {max} u²)"
    );
}

fn trig_inputs(n: usize) -> Vec<Dd> {
    let mut rng = ChaCha8Rng::seed_from_u64(12);
    let half_pi = Float::with_val(REF_BITS, rug::float::Constant::Pi) / 2u32;
    (0..n)
        .map(|i| match i % 4 {
            0 => uniform(&mut rng, -4.0, 4.0),
            1 => uniform(&mut rng, -1e4, 1e4),
            2 => tiny(&mut rng, 1, 200),
            // The double-double nearest to k·π/2, moved by up to 2⁻ʲ.
            _ => {
                let k = rng.gen_range(-2000..2000);
                let t = Dd::from_float(&(half_pi.clone() * k));
                t + Dd::from_f64(rng.gen_range(-1.0..1.0) * 2f64.powi(-rng.gen_range(20..110)))
            }
        })
        .collect()
}

/// Absolute floor of the sine and cosine bound (proofs: B12, B18): for `|x_h| < 64` the
/// Cody–Waite reduction `x − k·π/2` (`|k| ≤ 41`) carries an absolute error below 2⁻¹⁵⁰,
/// and from 64 on the Payne–Hanek reduction one below 2⁻²⁵², so near a zero of the function
/// the bound is `16u² · 2⁻⁴⁴ = 2⁻¹⁴⁶` absolute, for every finite argument.
fn trig_floor(_x: Dd) -> f64 {
    2f64.powi(-44)
}

#[test]
fn b12_dd_sin_cos_within_16u2_or_absolute_floor() {
    let inputs = trig_inputs(cases(3000, 100_000));
    let (smax, sat) = worst(inputs.iter().copied(), |&x| {
        mixed_err(x, x.sin(), trig_floor(x), Float::sin)
    });
    let (cmax, cat) = worst(inputs.iter().copied(), |&x| {
        mixed_err(x, x.cos(), trig_floor(x), Float::cos)
    });
    eprintln!("b12 sin: max {smax:.3} u² at {sat:?}\nb12 cos: max {cmax:.3} u² at {cat:?}");
    assert!(smax <= 16.0, "sin: max {smax} u² at {sat:?}");
    assert!(cmax <= 16.0, "cos: max {cmax} u² at {cat:?}");
}

#[test]
fn b12_dd_sin_relative_away_from_multiples_of_pi() {
    // Where |sin x| ≥ 2⁻⁴⁴·max(1,|x|) the floor is inactive: the bound is relative.
    let mut rng = ChaCha8Rng::seed_from_u64(121);
    let inputs: Vec<Dd> = (0..cases(2000, 100_000))
        .map(|_| uniform(&mut rng, -100.0, 100.0))
        .collect();
    let (max, at) = worst(inputs.iter().copied(), |&x| {
        unary_err(x, x.sin(), Float::sin)
    });
    eprintln!("b12 sin (relative): max {max:.3} u² at {at:?}");
    assert!(max <= 16.0, "max {max} u² at {at:?}");
}

#[test]
fn b12_negative_control_f64_sin_fails() {
    let inputs = trig_inputs(400);
    let (max, _) = worst(inputs.iter().copied(), |&x| {
        mixed_err(x, Dd::from_f64(x.hi.sin()), trig_floor(x), Float::sin)
    });
    assert!(
        max > 16.0,
        "the check did not reject the f64 sine (max {max} u²)"
    );
}

fn atan2_inputs(n: usize) -> Vec<(Dd, Dd)> {
    let mut rng = ChaCha8Rng::seed_from_u64(13);
    (0..n)
        .map(|i| match i % 4 {
            0 => (uniform(&mut rng, -1.0, 1.0), uniform(&mut rng, -1.0, 1.0)),
            1 => (rand_dd(&mut rng, -300, 300), rand_dd(&mut rng, -300, 300)),
            // Near the axes: one coordinate tiny relative to the other.
            2 => {
                let a = rand_dd(&mut rng, -5, 5);
                let b = a * tiny(&mut rng, 1, 120);
                if rng.gen_bool(0.5) {
                    (a, b)
                } else {
                    (b, a)
                }
            }
            // Near the diagonals and near the table nodes y/x = j/64.
            _ => {
                let x = rand_dd(&mut rng, -5, 5);
                let j = f64::from(rng.gen_range(-64..=64)) / 64.0;
                let y = x * Dd::from_f64(j) + x * tiny(&mut rng, 20, 110);
                if rng.gen_bool(0.5) {
                    (y, x)
                } else {
                    (x, y)
                }
            }
        })
        .collect()
}

#[test]
fn b13_dd_atan2_atan_within_16u2() {
    let inputs = atan2_inputs(cases(3000, 100_000));
    let (max, at) = worst(inputs.iter().copied(), |&(y, x)| {
        let r = exact_of(&fl(y).atan2(&fl(x)));
        rel_err_u2(y.atan2(&x), &r)
    });
    eprintln!("b13 atan2: max {max:.3} u² at {at:?}");
    assert!(max <= 16.0, "atan2: max {max} u² at {at:?}");
    let (amax, aat) = worst(inputs.iter().map(|&(y, x)| y / x), |&t| {
        unary_err(t, t.atan(), Float::atan)
    });
    eprintln!("b13 atan: max {amax:.3} u² at {aat:?}");
    assert!(amax <= 16.0, "atan: max {amax} u² at {aat:?}");
}

#[test]
fn b13_negative_control_f64_atan2_fails() {
    let inputs = atan2_inputs(400);
    let (max, _) = worst(inputs.iter().copied(), |&(y, x)| {
        let r = exact_of(&fl(y).atan2(&fl(x)));
        rel_err_u2(Dd::from_f64(y.hi.atan2(x.hi)), &r)
    });
    assert!(
        max > 16.0,
        "the check did not reject the f64 atan2 (max {max} u²)"
    );
}

fn acos_inputs(n: usize) -> Vec<Dd> {
    let mut rng = ChaCha8Rng::seed_from_u64(14);
    (0..n)
        .map(|i| match i % 3 {
            0 => uniform(&mut rng, -1.0, 1.0),
            // ±(1 − δ), δ down to 2⁻¹⁰⁵: acos has a zero at 1 and a square-root branch.
            1 => {
                let d = tiny(&mut rng, 1, 105).abs();
                let x = Dd::from_f64(1.0) - d;
                if rng.gen_bool(0.5) {
                    x
                } else {
                    -x
                }
            }
            _ => tiny(&mut rng, 1, 200),
        })
        .collect()
}

#[test]
fn b14_dd_acos_within_16u2_near_pm1() {
    let inputs = acos_inputs(cases(3000, 100_000));
    let (max, at) = worst(inputs.iter().copied(), |&x| {
        unary_err(x, x.acos(), Float::acos)
    });
    eprintln!("b14 acos: max {max:.3} u² at {at:?}");
    assert!(max <= 16.0, "max {max} u² at {at:?}");
}

#[test]
fn b14_negative_control_acos_of_rounded_argument_fails() {
    // acos(x_h) in f64 ignores x_l: near 1 that loses most digits.
    let inputs = acos_inputs(400);
    let (max, _) = worst(inputs.iter().copied(), |&x| {
        unary_err(x, Dd::from_f64(x.hi.acos()), Float::acos)
    });
    assert!(
        max > 16.0,
        "the check did not reject the f64 arccosine (max {max} u²)"
    );
}
