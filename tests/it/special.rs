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
use rug::float::{Constant, Round};
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
        0.7853981633974483,
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
        out.push(if rng.gen() { x } else { -x });
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
