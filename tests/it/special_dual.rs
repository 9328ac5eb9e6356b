//! B30: `Л` on `Dual<f64>` and `Dual<Dd>` (the fast path without MPFR) against the generic
//! path on `Dual<Mpfr>` at 200 bits.

use crate::support::cases;
use penner::scalar::{Dd, Dual, Mpfr, Precision, Real};
use penner::special::lobachevsky;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The reference `Л′(x)` at 200 bits, from the generic path (MPFR reduction, then the
/// backend's sine and logarithm at 200 bits), for an exact argument `x = hi + lo`.
fn reference_slope(hi: f64, lo: f64) -> (f64, f64) {
    let p = Precision::new(200).unwrap();
    let x = Mpfr::from_f64(hi, p) + &Mpfr::from_f64(lo, p);
    let y = lobachevsky(&Dual::variable(x));
    let l = y.d.approx_f64().abs();
    (y.d.approx_f64(), l)
}

/// The derivative `d̂` is within B30's bound `tol` of the reference `r` (computed in f64
/// from an MPFR difference, so the comparison itself is exact enough), and `d̂ ± 3·tol` is
/// not (negative control, either side).
fn assert_slope(d: f64, r: f64, tol: f64, what: &str) {
    assert!((d - r).abs() <= tol, "{what}: Л′ {d} vs {r} (tol {tol:e})");
    for side in [1.0, -1.0] {
        let moved = d + side * 3.0 * tol;
        assert!((moved - r).abs() > tol, "control {what} {side}");
    }
}

#[test]
fn b30_dual_fast_path_matches_the_mpfr_derivative() {
    let mut rng = ChaCha8Rng::seed_from_u64(30);
    let u64_ = f64::EPSILON / 2.0;
    let udd = 2f64.powi(-106);
    let mut xs: Vec<f64> = (0..cases(400, 20_000))
        .map(|_| rng.gen_range(-12.0..12.0))
        .collect();
    xs.extend([
        std::f64::consts::PI,
        std::f64::consts::FRAC_PI_2,
        1e-300,
        3.0e8,
        std::f64::consts::FRAC_PI_6,
    ]);
    for &x in &xs {
        // Dual<f64>: the value is the scalar path's, bit for bit; Л′ within 6u + 5uL.
        let y = lobachevsky(&Dual::variable(x));
        assert_eq!(y.v.to_bits(), lobachevsky(&x).to_bits(), "Л({x})");
        let (r, l) = reference_slope(x, 0.0);
        // |r − Л′| ≤ 2⁻¹⁹⁰ and one rounding to f64 of r: u·L more.
        let tol = (6.0 * u64_ + 6.0 * u64_ * l).max(f64::MIN_POSITIVE);
        assert_slope(y.d, r, tol, &format!("f64 {x}"));
        // Dual<Dd>: a genuine trailing word; value the Dd path's, Л′ within 18u + 17uL.
        let lo = x * 2f64.powi(-60);
        let xd = Dd::from_parts(x, lo);
        if xd.sin().approx_f64().abs() < 2f64.powi(-30) {
            continue;
        }
        let yd = lobachevsky(&Dual::variable(xd));
        assert_eq!(yd.v, lobachevsky(&xd), "Л({xd:?})");
        let (r, l) = reference_slope(x, lo);
        let p = Precision::new(200).unwrap();
        let exact = Mpfr::from_f64(yd.d.hi, p) + &Mpfr::from_f64(yd.d.lo, p);
        let reference = {
            let xm = Mpfr::from_f64(x, p) + &Mpfr::from_f64(lo, p);
            lobachevsky(&Dual::variable(xm)).d
        };
        let diff = (exact - &reference).approx_f64();
        let tol = 18.0 * udd + 18.0 * udd * l + f64::MIN_POSITIVE;
        assert!(
            diff.abs() <= tol,
            "Dd {x}: Л′ off by {diff:e} (tol {tol:e}), {r}"
        );
        assert!((diff + 3.0 * tol).abs() > tol && (diff - 3.0 * tol).abs() > tol);
    }
}
