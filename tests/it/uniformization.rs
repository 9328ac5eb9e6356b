//! Discrete uniformization with Ptolemy flips (T24–T26): the `f64` Newton solver, its
//! typed errors, the mixed-precision refinement and the certificate.

use crate::meshgen::{icosphere, jittered_torus};
use penner::mesh::Mesh;
use penner::uniformization::{uniformize, Stop, Targets, UniformizeError, UniformizeOptions};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

/// A noisy icosphere with `20k²` faces and its Euclidean lengths.
pub fn noisy_sphere(k: u32, seed: u64) -> (Mesh, Vec<f64>) {
    let mut s = icosphere(k);
    let amount = 0.2 * s.mean_edge();
    s.jitter(amount, seed);
    let m = s.mesh();
    let l = s.lengths(&m);
    (m, l)
}

/// Random admissible targets on a connected closed surface of Euler characteristic `chi`:
/// `q_i = 2 − 2χ/V + δ_i` with `Σ δ_i = 0` exactly, `δ_i = (r_i − r_{i+1})`, `|r_i| ≤ spread`.
pub fn random_targets(n: usize, chi: i64, spread: i64, seed: u64) -> Targets {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let base = Rational::from(2) - Rational::from((2 * chi, n as i64));
    let r: Vec<Rational> = (0..n)
        .map(|_| Rational::from((rng.gen_range(-spread..=spread), 100 * n as i64)))
        .collect();
    let q = (0..n)
        .map(|i| Rational::from(&base + &r[i]) - &r[(i + 1) % n])
        .collect();
    Targets::from_multiples_of_pi(q)
}

#[test]
fn t24_flat_torus_converges() {
    let (m, l) = jittered_torus(8, 10, 3);
    let sol = uniformize(
        &m,
        &l,
        &Targets::flat(m.n_vertices()),
        &UniformizeOptions::default(),
    )
    .unwrap();
    assert_eq!(sol.stop, Stop::Converged, "{:?}", sol.steps);
    assert!(sol.residual_max <= 1e-10);
    assert!(sol.steps.len() < 30);
}

#[test]
fn t24_sphere_random_targets_converges() {
    for seed in 0..3 {
        let (m, l) = noisy_sphere(3, seed);
        let t = random_targets(m.n_vertices(), 2, 50, seed);
        let sol = uniformize(&m, &l, &t, &UniformizeOptions::default()).unwrap();
        assert_eq!(sol.stop, Stop::Converged, "seed {seed}: {:?}", sol.steps);
    }
}

#[test]
fn t24_gauss_bonnet_violation_is_typed_error() {
    let (m, l) = noisy_sphere(2, 1);
    // Flat targets on a sphere: Σ(2π − Θ) = 0 ≠ 4π.
    let err = uniformize(
        &m,
        &l,
        &Targets::flat(m.n_vertices()),
        &UniformizeOptions::default(),
    )
    .unwrap_err();
    assert!(
        matches!(err, UniformizeError::GaussBonnet { chi: 2, .. }),
        "{err}"
    );
    assert!(err.to_string().contains("Σ(2π − Θ_i) = 0·π"), "{err}");
    // Admissible targets are accepted (the control of the negative case).
    let ok = random_targets(m.n_vertices(), 2, 10, 1);
    assert!(uniformize(&m, &l, &ok, &UniformizeOptions::default()).is_ok());
}

#[test]
fn t24_bad_targets_are_typed_errors() {
    let (m, l) = jittered_torus(4, 4, 1);
    let n = m.n_vertices();
    let opts = UniformizeOptions::default();
    let e = uniformize(&m, &l, &Targets::flat(n - 1), &opts).unwrap_err();
    assert!(
        matches!(e, UniformizeError::TargetCount { expected, got } if expected == n && got == n - 1)
    );
    let mut q = vec![Rational::from(2); n];
    q[3] = Rational::from(0);
    q[4] = Rational::from(4);
    let e = uniformize(&m, &l, &Targets::from_multiples_of_pi(q), &opts).unwrap_err();
    assert!(
        matches!(e, UniformizeError::NonPositiveTarget { vertex: 3, .. }),
        "{e}"
    );
    let mut f = vec![2.0; n];
    f[5] = f64::NAN;
    let e = Targets::from_f64_multiples_of_pi(&f).unwrap_err();
    assert!(
        matches!(e, UniformizeError::NonFiniteTarget { vertex: 5, .. }),
        "{e}"
    );
    let mut bad = l.clone();
    bad[7] = -1.0;
    let e = uniformize(&m, &bad, &Targets::flat(n), &opts).unwrap_err();
    assert!(
        matches!(e, UniformizeError::BadLength { edge: 7, .. }),
        "{e}"
    );
}

#[test]
fn t24_iteration_cap_is_reported_not_converged() {
    let (m, l) = noisy_sphere(3, 7);
    let t = random_targets(m.n_vertices(), 2, 50, 7);
    let opts = UniformizeOptions {
        max_iterations: 1,
        ..UniformizeOptions::default()
    };
    let sol = uniformize(&m, &l, &t, &opts).unwrap();
    assert_eq!(sol.stop, Stop::IterationCap);
    assert!(!sol.converged());
    assert!(sol.residual_max > opts.tolerance);
}

use penner::scalar::{Dd, Mpfr, Precision, Real};
use penner::uniformization::certificate::{check_certificate, CertificateData, CertificateOutcome};
use penner::uniformization::krawczyk::{krawczyk, KrawczykOutcome};
use penner::uniformization::refine::refine;
use penner::uniformization::Uniformization;

fn solve_sphere(k: u32, seed: u64) -> Uniformization {
    let (m, l) = noisy_sphere(k, seed);
    let t = random_targets(m.n_vertices(), 2, 50, seed);
    let sol = uniformize(&m, &l, &t, &UniformizeOptions::default()).unwrap();
    assert!(sol.converged(), "{:?}", sol.stop);
    sol
}

fn solve_torus(seed: u64) -> Uniformization {
    let (m, l) = jittered_torus(6, 8, seed);
    let sol = uniformize(
        &m,
        &l,
        &Targets::flat(m.n_vertices()),
        &UniformizeOptions::default(),
    )
    .unwrap();
    assert!(sol.converged(), "{:?}", sol.stop);
    sol
}

fn certificate_data(sol: &Uniformization, u: Vec<Rational>, radius: Rational) -> CertificateData {
    CertificateData {
        t0: sol.initial_mesh.clone(),
        l0: sol.initial_lengths.clone(),
        targets: sol.targets.clone(),
        flip_sequence: sol.flip_sequence.clone(),
        u,
        radius,
    }
}

#[test]
fn t24_refinement_reaches_1e60_at_mpfr_256() {
    let p = Precision::new(256).unwrap();
    for sol in [solve_sphere(3, 11), solve_torus(5)] {
        let r = refine::<Mpfr>(&sol, p, 1e-60, 12).unwrap();
        assert!(r.reached, "history {:?}", r.history);
        assert!(r.residual_max() <= 1e-60);
        // The f64 start was ≥ 1e-16 away: the refinement did the work.
        assert!(r.history[0] > 1e-20, "{:?}", r.history);
        // Newton steps with the Hessian of the iterate (refine_newton): the residual
        // squares from the second step on, so three corrections reach 1e-60 from the f64
        // solution's 1e-12 (with the f64 factor alone each step gains about the f64
        // solution's accuracy, r₂ ≈ 10⁻¹³·r₁ > r₁^1.8, and it takes five).
        assert!(r.history.len() <= 4, "{:?}", r.history);
        assert!(r.history[2] <= r.history[1].powf(1.8), "{:?}", r.history);
    }
}

#[test]
fn t24_refinement_in_double_double() {
    let sol = solve_sphere(2, 4);
    let r = refine::<Dd>(&sol, (), 1e-28, 8).unwrap();
    assert!(r.residual_max() <= 1e-28, "{:?}", r.history);
}

/// The refined u as exact rationals.
fn exact_u(u: &[Mpfr]) -> Vec<Rational> {
    u.iter().map(|x| x.to_rational().unwrap()).collect()
}

#[test]
fn t24_certificate_holds_after_refinement() {
    let p = Precision::new(256).unwrap();
    for sol in [solve_sphere(3, 2), solve_torus(9)] {
        let r = refine::<Mpfr>(&sol, p, 1e-60, 12).unwrap();
        let u = exact_u(&r.u);
        let data = certificate_data(&sol, u.clone(), tiny(50));
        match check_certificate(&data, 256).unwrap() {
            CertificateOutcome::Holds { distance, mu, .. } => {
                assert!(distance < 1e-50 && mu > 0.0, "{distance} {mu}");
            }
            CertificateOutcome::Undecided { reason } => panic!("not certified: {reason}"),
        }
        // Negative control: u moved by 1e-6 at one free vertex is not certified.
        let mut bad = u.clone();
        bad[1] += Rational::from((1, 1_000_000));
        let data = certificate_data(&sol, bad, tiny(50));
        assert!(matches!(
            check_certificate(&data, 256).unwrap(),
            CertificateOutcome::Undecided { .. }
        ));
    }
}

#[test]
fn t24_certificate_cross_checked_by_dense_krawczyk() {
    let p = Precision::new(256).unwrap();
    for sol in [solve_sphere(2, 8), solve_torus(1)] {
        let r = refine::<Mpfr>(&sol, p, 1e-60, 12).unwrap();
        let u = exact_u(&r.u);
        let radius = tiny(50);
        let data = certificate_data(&sol, u.clone(), radius.clone());
        let a = check_certificate(&data, 256).unwrap();
        let b = krawczyk(&data, 256).unwrap();
        let (CertificateOutcome::Holds { distance, .. }, KrawczykOutcome::Holds { width }) =
            (&a, &b)
        else {
            panic!("{a:?} {b:?}");
        };
        assert!(*distance < 1e-50 && *width < 1e-50, "{distance} {width}");
        // Both refuse a u moved by 1e-30 (far outside the 1e-50 box).
        let mut bad = u;
        bad[2] += tiny(30);
        let data = certificate_data(&sol, bad, radius);
        assert!(matches!(
            check_certificate(&data, 256).unwrap(),
            CertificateOutcome::Undecided { .. }
        ));
        assert!(matches!(
            krawczyk(&data, 256).unwrap(),
            KrawczykOutcome::Undecided { .. }
        ));
    }
}

/// `10⁻ᵏ` exactly.
fn tiny(k: u32) -> Rational {
    Rational::from((1, rug::Integer::from(rug::Integer::u_pow_u(10, k))))
}

use penner::theorems::t24_uniformization_exists::check_existence;
use penner::theorems::t25_uniformization_unique::{check_uniqueness, compare_normalized};
use penner::theorems::t26_flips_keep_metric::check_flip_path;

#[test]
fn t24_existence_certified_on_random_surfaces_and_targets() {
    // Random closed surfaces of genus 0 and 1 with lengths from a jittered embedding, and
    // random admissible targets.
    for seed in 0..crate::support::cases(2, 20) as u64 {
        let (m, l) = noisy_sphere(2, 100 + seed);
        let t = random_targets(m.n_vertices(), 2, 80, seed);
        let ex = check_existence(&m, &l, &t, 256, 1e-60).unwrap();
        assert!(ex.verdict.holds(), "seed {seed}: {:?}", ex.verdict);
        let (m, l) = jittered_torus(5, 6, seed);
        let t = random_targets(m.n_vertices(), 0, 80, seed);
        let ex = check_existence(&m, &l, &t, 256, 1e-60).unwrap();
        assert!(ex.verdict.holds(), "torus seed {seed}: {:?}", ex.verdict);
    }
    // Negative control: Gauss–Bonnet violated by 1/100·π at one vertex → typed error.
    let (m, l) = noisy_sphere(2, 1);
    let mut q = random_targets(m.n_vertices(), 2, 80, 1).over_pi().to_vec();
    q[0] += Rational::from((1, 100));
    let e = check_existence(&m, &l, &Targets::from_multiples_of_pi(q), 256, 1e-60).unwrap_err();
    assert!(matches!(e, UniformizeError::GaussBonnet { .. }), "{e}");
}

#[test]
fn t25_two_starts_agree_after_normalisation() {
    let (m, l) = noisy_sphere(2, 5);
    let t = random_targets(m.n_vertices(), 2, 50, 5);
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let start: Vec<f64> = (0..m.n_vertices())
        .map(|_| rng.gen_range(-0.5..0.5))
        .collect();
    let v = check_uniqueness(&m, &l, &t, start, 256, 1e-60).unwrap();
    assert!(v.holds(), "{v:?}");
    // Negative control: the same comparison refutes two solutions that differ by 1e-20 at one
    // vertex after normalisation (distances 1e-50 certified).
    let u1: Vec<Rational> = (0..m.n_vertices())
        .map(|i| Rational::from((i as i64, 7)))
        .collect();
    let mut u2: Vec<Rational> = u1.iter().map(|x| Rational::from(x + 3)).collect();
    assert!(compare_normalized(&m, &u1, 1e-50, &u2, 1e-50).holds());
    u2[4] += tiny(20);
    assert!(compare_normalized(&m, &u1, 1e-50, &u2, 1e-50).fails());
}

#[test]
fn t26_flip_path_commutes_with_scaling() {
    // A pillowcase: four cones of angle π, flat elsewhere; the conformal factors vary
    // strongly and the Delaunay triangulation changes along the solve.
    let (m, l) = noisy_sphere(2, 3);
    let mut q = vec![Rational::from(2); m.n_vertices()];
    for v in [0, 5, 10, 20] {
        q[v] = Rational::from(1);
    }
    let sol = uniformize(
        &m,
        &l,
        &Targets::from_multiples_of_pi(q),
        &UniformizeOptions::default(),
    )
    .unwrap();
    assert!(sol.converged(), "{:?}", sol.stop);
    assert!(!sol.flip_sequence.is_empty(), "the solve should flip");
    // Scale factors s_i ≈ e^{u_i/2} as exact binary64 rationals.
    let s: Vec<Rational> = sol
        .u
        .iter()
        .map(|&x| Rational::from_f64((0.5 * x).exp()).unwrap())
        .collect();
    let v = check_flip_path(
        &sol.initial_mesh,
        &sol.initial_lengths,
        &sol.flip_sequence,
        &sol.mesh,
        &s,
        &s,
    );
    assert!(v.holds(), "{v:?}");
    // The per-step flip counts add up to the recorded sequence (the first evaluation at
    // the start may flip too).
    let steps: usize = sol.steps.iter().map(|r| r.flips).sum();
    assert!(steps <= sol.flip_sequence.len());
    // Negative control: scaling after the flips by a factor changed at one vertex.
    let mut t = s.clone();
    t[0] *= Rational::from((101, 100));
    assert!(check_flip_path(
        &sol.initial_mesh,
        &sol.initial_lengths,
        &sol.flip_sequence,
        &sol.mesh,
        &s,
        &t
    )
    .fails());
    // And a sequence that does not reach the final triangulation is refused.
    let short = &sol.flip_sequence[..sol.flip_sequence.len() - 1];
    assert!(check_flip_path(
        &sol.initial_mesh,
        &sol.initial_lengths,
        short,
        &sol.mesh,
        &s,
        &s
    )
    .fails());
}

use penner::uniformization::verified_cholesky::{lambda_min_lower_bound, SymmetricLower};

/// Eigenvalues of a small dense symmetric matrix by cyclic Jacobi rotations (an oracle
/// independent of any Cholesky factorization).
#[allow(clippy::needless_range_loop)] // the rotations index rows and columns
fn jacobi_eigenvalues(mut a: Vec<Vec<f64>>) -> Vec<f64> {
    let n = a.len();
    for _sweep in 0..100 {
        let off: f64 = (0..n)
            .flat_map(|i| (0..n).filter(move |&j| j != i).map(move |j| (i, j)))
            .map(|(i, j)| a[i][j] * a[i][j])
            .sum();
        if off < 1e-30 {
            break;
        }
        for p in 0..n {
            for q in p + 1..n {
                if a[p][q].abs() < 1e-300 {
                    continue;
                }
                let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let t = if theta == 0.0 { 1.0 } else { t };
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                for k in 0..n {
                    let (akp, akq) = (a[k][p], a[k][q]);
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for k in 0..n {
                    let (apk, aqk) = (a[p][k], a[q][k]);
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
            }
        }
    }
    (0..n).map(|i| a[i][i]).collect()
}

#[test]
fn b70_lower_bound_matches_dense_eigenvalues() {
    use penner::geometry::laplacian::cotan_laplacian;
    for seed in 0..crate::support::cases(3, 30) as u64 {
        let (m, l) = noisy_sphere(2, 40 + seed);
        let lap = cotan_laplacian(&m, &l);
        // Ground vertex 0: −L on vertices 1..n.
        let n = m.n_vertices() - 1;
        let mut dense = vec![vec![0.0; n]; n];
        let mut entries = Vec::new();
        for (i, j, w) in lap.entries() {
            if i == 0 || j == 0 {
                continue;
            }
            dense[i - 1][j - 1] = -*w;
            if i >= j {
                entries.push((i - 1, j - 1, -*w));
            }
        }
        let lambda = jacobi_eigenvalues(dense)
            .into_iter()
            .fold(f64::INFINITY, f64::min);
        assert!(lambda > 0.0);
        let a = SymmetricLower { n, entries };
        let b = lambda_min_lower_bound(&a, 0.99 * lambda).expect("A − 0.99λ I is definite");
        assert!(b.lambda_min <= lambda, "{b:?} vs {lambda}");
        assert!(b.lambda_min >= 0.98 * lambda, "{b:?} vs {lambda}");
        // Negative control: a shift 1% above λ_min leaves an indefinite matrix.
        assert!(lambda_min_lower_bound(&a, 1.01 * lambda).is_none());
    }
}

#[test]
fn b71_box_beyond_the_cell_boundaries_is_undecided() {
    // The flat grid torus: every diagonal is (up to the rounding of √2) a cocircular tie,
    // so on a box of radius 1e-3 the Delaunay sign of the diagonals is not constant.
    let flat = penner::mesh::builders::flat_torus(4, 4).unwrap();
    let l: Vec<f64> = flat
        .squared_lengths
        .iter()
        .map(|q| q.to_f64().sqrt())
        .collect();
    let sol = uniformize(
        &flat.mesh,
        &l,
        &Targets::flat(flat.mesh.n_vertices()),
        &UniformizeOptions::default(),
    )
    .unwrap();
    assert!(sol.converged());
    let r = refine::<Mpfr>(&sol, Precision::new(256).unwrap(), 1e-60, 12).unwrap();
    let u = exact_u(&r.u);
    // A small box is certified (the rounded metric is a strict Delaunay cell around u) …
    let small = certificate_data(&sol, u.clone(), tiny(40));
    assert!(matches!(
        check_certificate(&small, 256).unwrap(),
        CertificateOutcome::Holds { .. }
    ));
    // … a box of radius 1e-6 crosses the diagonals' cell boundaries, which B35 covers …
    let crossing = certificate_data(&sol, u.clone(), tiny(6));
    let o = check_certificate(&crossing, 256).unwrap();
    assert!(matches!(o, CertificateOutcome::Holds { .. }), "{o:?}");
    // … a box of radius 1 is no proof (its faces are not certified strict triangles):
    // undecided, naming a face.
    let big = certificate_data(&sol, u, Rational::from(1));
    match check_certificate(&big, 256).unwrap() {
        CertificateOutcome::Undecided { reason } => {
            assert!(
                reason.contains("not certified a strict triangle"),
                "{reason}"
            );
        }
        h @ CertificateOutcome::Holds { .. } => panic!("{h:?}"),
    }
}
