//! The fast paths of the `f64` uniformization solver (B77): scaled lengths without MPFR,
//! cotangents from the cone-angle kernel, the grounded Hessian assembled in place.

use crate::meshgen::jittered_torus;
use crate::support::cases;
use penner::geometry::cone_angles::{cone_angles, cone_angles_and_cotans};
use penner::geometry::cotan::halfedge_cotans;
use penner::geometry::laplacian::cotan_laplacian;
use penner::scalar::exp_length::ExpLength;
use penner::scalar::{Mpfr, Precision, Real};
use penner::uniformization::components::Components;
use penner::uniformization::hessian::GroundedPattern;
use penner::uniformization::scaling::{scaled_fast, SCALED_FAST_ULPS};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

const U: f64 = f64::EPSILON / 2.0;

/// `|a/b − 1|` for two exponent-apart lengths, exactly in rationals (then rounded).
fn relative_error(a: &ExpLength, b: &ExpLength) -> f64 {
    let (a, b) = (a.to_rational(), b.to_rational());
    let d = Rational::from(&a - &b) / &b;
    d.abs().to_f64()
}

/// Scale factors drawn from several ranges: small, moderate, near `2²⁰`, and halves near
/// a tie of `round(s/ln 2)`.
fn random_u(rng: &mut ChaCha8Rng) -> f64 {
    match rng.gen_range(0..4) {
        0 => rng.gen_range(-1.0..1.0),
        1 => rng.gen_range(-800.0..800.0),
        2 => rng.gen_range(-1_048_576.0..=1_048_576.0),
        _ => (f64::from(rng.gen_range(-1000i32..1000)) + 0.5) * std::f64::consts::LN_2,
    }
}

#[test]
fn b77_scaled_fast_within_bound_of_mpfr_scaling() {
    // Oracle: ExpLength::scaled (MPFR exp with 64 guard bits, relative error ≤ u + 2⁻¹¹⁵).
    let bound = (SCALED_FAST_ULPS + 1.0 + 1e-9) * U;
    let mut rng = ChaCha8Rng::seed_from_u64(77);
    let mut worst: f64 = 0.0;
    for _ in 0..cases(4000, 400_000) {
        let l = f64::from_bits(rng.gen_range(1u64..0x7fef_ffff_ffff_ffff));
        let (ui, uj) = (random_u(&mut rng), random_u(&mut rng));
        let fast = scaled_fast(l, ui, uj).unwrap();
        let reference = ExpLength::scaled(l, ui, uj).unwrap();
        let e = relative_error(&fast, &reference);
        worst = worst.max(e);
        assert!(
            e <= bound,
            "ℓ={l:e} u=({ui}, {uj}): error {e:e} > {bound:e}"
        );
    }
    eprintln!("b77: worst relative error of scaled_fast {:.2}u", worst / U);
    // Refused input, as ExpLength::scaled refuses it.
    assert!(scaled_fast(0.0, 0.0, 0.0).is_none());
    assert!(scaled_fast(1.0, f64::NAN, 0.0).is_none());
    assert!(scaled_fast(1.0, 2_000_000.0, 0.0).is_none());
}

#[test]
fn b77_negative_control_perturbed_scale_factor_fails_the_bound() {
    // The same comparison on u_i moved by 10⁻¹² (a relative length change of 5·10⁻¹³).
    let bound = (SCALED_FAST_ULPS + 1.0 + 1e-9) * U;
    let mut rng = ChaCha8Rng::seed_from_u64(78);
    for _ in 0..100 {
        let l = rng.gen_range(0.1..10.0);
        let (ui, uj) = (random_u(&mut rng), random_u(&mut rng));
        if ui.abs() > 1e3 {
            continue; // 10⁻¹² is below an ulp of ui there
        }
        let fast = scaled_fast(l, ui + 1e-12, uj).unwrap();
        let reference = ExpLength::scaled(l, ui, uj).unwrap();
        assert!(relative_error(&fast, &reference) > bound);
    }
}

/// `B77` item 2: `|ĉot − cot| ≤ 10u·(1/sin α + |cot α|)` for the corner of angle `α`.
fn cot_bound(cot: f64) -> f64 {
    // 1/sin α = √(1 + cot²α).
    10.0 * U * ((1.0 + cot * cot).sqrt() + cot.abs())
}

#[test]
fn b77_kernel_cotangents_match_mpfr_cotangents() {
    let p = Precision::new(256).unwrap();
    for seed in 0..cases(4, 40) {
        let (m, l) = jittered_torus(12, 9, seed as u64);
        let mut cot = vec![0.0; m.n_halfedges()];
        let theta = cone_angles_and_cotans(&m, &l, &mut cot);
        // The angles are cone_angles' (the same kernel, bit for bit).
        assert_eq!(theta, cone_angles(&m, &l));
        // Oracle: cot_opposite (Kahan's area formula) at 256 bits.
        let lm: Vec<Mpfr> = l.iter().map(|&x| Mpfr::from_f64(x, p)).collect();
        let exact = halfedge_cotans(&m, &lm);
        let mut worst: f64 = 0.0;
        for h in m.halfedges() {
            let c = exact[h.idx()].approx_f64();
            let e = (cot[h.idx()] - c).abs();
            worst = worst.max(e / cot_bound(c));
            assert!(
                e <= cot_bound(c),
                "seed {seed} h{}: {} vs {c} (error {e:e} > {:e})",
                h.0,
                cot[h.idx()],
                cot_bound(c)
            );
        }
        eprintln!("b77: seed {seed}: worst cotangent error {worst:.3} of the bound");
    }
}

#[test]
fn b77_negative_control_cotangents_of_a_perturbed_metric_fail() {
    let p = Precision::new(256).unwrap();
    let (m, l) = jittered_torus(12, 9, 0);
    let mut moved = l.clone();
    moved[5] *= 1.0 + 1e-9;
    let mut cot = vec![0.0; m.n_halfedges()];
    cone_angles_and_cotans(&m, &moved, &mut cot);
    let lm: Vec<Mpfr> = l.iter().map(|&x| Mpfr::from_f64(x, p)).collect();
    let exact = halfedge_cotans(&m, &lm);
    let caught = m.halfedges().any(|h| {
        let c = exact[h.idx()].approx_f64();
        (cot[h.idx()] - c).abs() > cot_bound(c)
    });
    assert!(caught, "a length moved by 10⁻⁹ relative went unnoticed");
}

#[test]
fn b77_grounded_pattern_assembles_the_cotan_laplacian() {
    // Oracle: −L from cotan_laplacian at 256 bits (another assembly, other cotangents),
    // restricted to the free vertices; tolerance: ½ the B77 cotangent bound per side.
    let p = Precision::new(256).unwrap();
    for seed in 0..cases(3, 30) {
        let (m, l) = jittered_torus(9, 7, 100 + seed as u64);
        let comps = Components::of(&m);
        let (_, free_idx) = comps.free_index();
        let mut cot = vec![0.0; m.n_halfedges()];
        cone_angles_and_cotans(&m, &l, &mut cot);
        let pattern = GroundedPattern::new(&m, &free_idx);
        let mut val = Vec::new();
        pattern.fill(&cot, &mut val);
        let lm: Vec<Mpfr> = l.iter().map(|&x| Mpfr::from_f64(x, p)).collect();
        let lap = cotan_laplacian(&m, &lm);
        let exact_cot = halfedge_cotans(&m, &lm);
        // Per free-position pair: the exact −L entry and its tolerance.
        let n = pattern.dim();
        let mut expect = vec![vec![0.0f64; n]; n];
        let mut tol = vec![vec![0.0f64; n]; n];
        for (i, j, w) in lap.entries() {
            if let (Some(a), Some(b)) = (free_idx[i], free_idx[j]) {
                expect[a][b] = -w.approx_f64();
            }
        }
        for h in m.halfedges() {
            let (i, j) = (m.tail(h).idx(), m.tip(h).idx());
            let t = 0.5 * cot_bound(exact_cot[h.idx()].approx_f64()) * 1.01;
            for (x, y) in [(i, i), (j, j), (i, j), (j, i)] {
                if let (Some(a), Some(b)) = (free_idx[x], free_idx[y]) {
                    tol[a][b] += t;
                }
            }
        }
        let mut seen = vec![vec![false; n]; n];
        for (r, c, v) in pattern.entries(&val) {
            assert!(r >= c, "lower triangle only");
            assert!(
                (v - expect[r][c]).abs() <= tol[r][c],
                "seed {seed} ({r}, {c}): {v} vs {}",
                expect[r][c]
            );
            seen[r][c] = true;
        }
        // Every nonzero of the lower triangle is stored.
        for r in 0..n {
            for c in 0..=r {
                assert!(seen[r][c] || expect[r][c] == 0.0, "({r}, {c}) missing");
            }
        }
    }
}
