//! `Dual<T>`: forward-mode derivatives of every elementary rule at f64, Dd and MPFR against
//! independent closed forms evaluated in MPFR at 512 bits (B27), and certified derivative
//! enclosures with `Dual<Interval<Mpfr>>`.

use crate::support::cases;
use penner::scalar::{Dd, Dual, Interval, Mpfr, Precision, Real};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Float;

const REF: u32 = 512;

/// One differentiation rule: the function on duals, its closed-form derivative in MPFR,
/// and the argument range.
struct Rule<T: Real> {
    name: &'static str,
    f: fn(&Dual<T>) -> Dual<T>,
    closed: fn(&Float) -> Float,
    range: (f64, f64),
    /// Tolerance in units of the backend's unit roundoff (proofs/B27).
    k: f64,
}

fn f(x: f64) -> Float {
    Float::with_val(REF, x)
}

fn rules<T: Real>() -> Vec<Rule<T>> {
    vec![
        Rule {
            name: "sqrt",
            f: |x| x.sqrt(),
            closed: |x| f(0.5) / x.clone().sqrt(),
            range: (1e-3, 1e3),
            k: 32.0,
        },
        Rule {
            name: "exp",
            f: |x| x.exp(),
            closed: |x| x.clone().exp(),
            range: (-20.0, 20.0),
            k: 32.0,
        },
        Rule {
            name: "ln",
            f: |x| x.ln(),
            closed: |x| f(1.0) / x,
            range: (1e-3, 1e3),
            k: 32.0,
        },
        Rule {
            name: "sin",
            f: |x| x.sin(),
            closed: |x| x.clone().cos(),
            range: (0.1, 1.2),
            k: 32.0,
        },
        Rule {
            name: "cos",
            f: |x| x.cos(),
            closed: |x| -x.clone().sin(),
            range: (0.1, 1.2),
            k: 32.0,
        },
        Rule {
            name: "atan",
            f: |x| x.atan(),
            closed: |x| f(1.0) / (f(1.0) + x.clone().square()),
            range: (-10.0, 10.0),
            k: 32.0,
        },
        Rule {
            name: "acos",
            f: |x| x.acos(),
            closed: |x| -(f(1.0) / (f(1.0) - x.clone().square()).sqrt()),
            range: (-0.999, 0.999),
            k: 32.0,
        },
        Rule {
            // ∂/∂y atan2(y, 1.5) = 1.5 / (1.5² + y²)
            name: "atan2_y",
            f: |y| y.atan2(&y.lit(1.5)),
            closed: |y| f(1.5) / (f(2.25) + y.clone().square()),
            range: (-3.0, 3.0),
            k: 32.0,
        },
        Rule {
            // ∂/∂x atan2(0.75, x) = −0.75 / (x² + 0.75²)
            name: "atan2_x",
            f: |x| x.lit(0.75).atan2(x),
            closed: |x| f(-0.75) / (x.clone().square() + f(0.5625)),
            range: (-3.0, 3.0),
            k: 32.0,
        },
        Rule {
            // quotient rule: ((x² + 1)/(x + 3))′ = (x² + 6x − 1)/(x + 3)²
            name: "quotient",
            f: |x| (x.clone() * x + &x.lit(1.0)) / (x.clone() + &x.lit(3.0)),
            closed: |x| (x.clone().square() + f(6.0) * x - f(1.0)) / (x.clone() + f(3.0)).square(),
            range: (1.0, 2.0),
            k: 64.0,
        },
    ]
}

/// Checks every rule at `n` random points; returns the worst error in units of `u`.
/// `perturb` scales the closed form by `1 + perturb` (a negative control).
fn check<T: Real>(ctx: T::Ctx, seed: u64, n: usize, perturb: f64) -> Result<f64, String> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let u = T::unit_roundoff(ctx);
    let mut worst = 0.0f64;
    for r in rules::<T>() {
        for _ in 0..n {
            let x = rng.gen_range(r.range.0..r.range.1);
            let y = (r.f)(&Dual::variable(T::from_f64(x, ctx)));
            let got = Float::with_val(REF, &y.d.to_rational().ok_or("non-finite derivative")?);
            let want = (r.closed)(&f(x)) * (f(1.0) + f(perturb));
            let err = (Float::with_val(REF, &got - &want) / &want).abs().to_f64() / u;
            if err > r.k {
                return Err(format!(
                    "{} at {x}: derivative off by {err} u (allowed {})",
                    r.name, r.k
                ));
            }
            worst = worst.max(err);
        }
    }
    Ok(worst)
}

fn prec(bits: u64) -> Precision {
    Precision::new(bits).expect("valid")
}

#[test]
fn b27_dual_derivatives_match_closed_forms_at_every_precision() {
    let n = cases(200, 20_000);
    let worst = [
        ("f64", check::<f64>((), 1, n, 0.0)),
        ("dd", check::<Dd>((), 2, n, 0.0)),
        ("mpfr-128", check::<Mpfr>(prec(128), 3, n, 0.0)),
        ("mpfr-256", check::<Mpfr>(prec(256), 4, n, 0.0)),
    ];
    for (name, w) in &worst {
        assert!(w.is_ok(), "{name}: {w:?}");
    }
    eprintln!("worst derivative errors (units of u): {worst:?}");
}

#[test]
fn b27_negative_control_perturbed_closed_form_is_rejected() {
    // A closed form off by 2^12 u (relative) must fail the same check at each precision.
    assert!(check::<f64>((), 1, 20, 4096.0 * f64::EPSILON / 2.0).is_err());
    assert!(check::<Dd>((), 2, 20, 4096.0 * (-104.0f64).exp2()).is_err());
    assert!(check::<Mpfr>(prec(128), 3, 20, (-116.0f64).exp2()).is_err());
}

#[test]
fn b27_dual_interval_derivative_encloses_closed_form() {
    let p = prec(128);
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    for r in rules::<Interval<Mpfr>>() {
        for _ in 0..cases(20, 2000) {
            let x = rng.gen_range(r.range.0..r.range.1);
            let y = (r.f)(&Dual::variable(Interval::point(Mpfr::from_f64(x, p))));
            let want = (r.closed)(&Float::with_val(2048, x));
            let q = want.to_rational().expect("finite");
            assert!(
                y.d.contains_rational(&q),
                "{} at {x}: {:?} misses {want}",
                r.name,
                y.d
            );
            assert!(
                y.d.width_f64() < 1e-30 * (1.0 + want.to_f64().abs()),
                "{}: too wide",
                r.name
            );
        }
    }
}

#[test]
fn b27_chain_rule_through_geometry_matches_closed_form() {
    // d/da of the corner angle opposite a in the triangle (a, 1, 1):
    // A = 2·asin(a/2), dA/da = 1/√(1 − a²/4).
    let p = prec(256);
    for a in [0.3, 1.0, 1.7] {
        let one = Dual::constant(Mpfr::from_f64(1.0, p));
        let da = Dual::variable(Mpfr::from_f64(a, p));
        let ang = penner::geometry::triangle::corner_angle(&da, &one, &one);
        let want = f(1.0) / (f(1.0) - f(a).square() / 4u32).sqrt();
        let got = Float::with_val(REF, ang.d.as_float());
        let rel = (Float::with_val(REF, &got - &want) / &want).abs().to_f64();
        assert!(
            rel < 64.0 * Mpfr::unit_roundoff(p),
            "a = {a}: rel error {rel}"
        );
        // Negative control: the derivative with respect to b (a fixed) differs.
        let db = penner::geometry::triangle::corner_angle(
            &Dual::constant(Mpfr::from_f64(a, p)),
            &Dual::variable(Mpfr::from_f64(1.0, p)),
            &one,
        );
        let other = Float::with_val(REF, db.d.as_float());
        assert!(
            (Float::with_val(REF, &other - &want) / &want)
                .abs()
                .to_f64()
                > 1e-3
        );
    }
}
