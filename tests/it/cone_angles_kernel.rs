//! The fast cone-angle kernel (proofs B15, B16) against the per-corner sum in MPFR-512.

use crate::meshgen::jittered_torus;
use crate::support::cases;
use penner::geometry::cone_angles::{
    cone_angles, cone_angles_per_corner, quarter_step, unwrap_angle, unwrap_quarter,
};
use penner::mesh::Mesh;
use penner::scalar::{Dd, Mpfr, Precision, Real};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::{FRAC_PI_2, PI};

/// A closed fan: apex 0, rim 1..=n, faces `[0, i, i+1]`, apex angles `alpha[i]`; spokes
/// have length 1 and rim edges `2 sin(α/2)`. Returns the mesh and f64 edge lengths.
fn fan(alpha: &[f64]) -> (Mesh, Vec<f64>) {
    let n = alpha.len() as u32;
    let faces: Vec<[u32; 3]> = (0..n).map(|i| [0, 1 + i, 1 + (i + 1) % n]).collect();
    let mesh = Mesh::from_faces(n + 1, &faces).expect("valid fan");
    let mut len = vec![1.0; mesh.n_edges()];
    for f in mesh.faces() {
        for h in mesh.face_halfedges(f) {
            let (t, p) = (mesh.tail(h).idx(), mesh.tip(h).idx());
            if t != 0 && p != 0 {
                // Rim edge between rim vertices t and t+1 (cyclically): face index t−1.
                let i = if (t % n as usize) + 1 == p {
                    t - 1
                } else {
                    p - 1
                };
                len[h.edge().idx()] = 2.0 * (alpha[i] / 2.0).sin();
            }
        }
    }
    (mesh, len)
}

/// Reference cone angles: per-corner sum in MPFR-512 of the exact f64 lengths.
fn reference(mesh: &Mesh, len: &[f64]) -> Vec<Mpfr> {
    let p = Precision::new(512).expect("valid precision");
    let l: Vec<Mpfr> = len.iter().map(|&x| Mpfr::from_f64(x, p)).collect();
    cone_angles_per_corner(mesh, &l)
}

fn err(x: &impl Real, r: &Mpfr) -> f64 {
    let d = x.to_rational().expect("finite") - r.to_rational().expect("finite");
    d.abs().to_f64()
}

/// Corners per vertex.
fn valence(mesh: &Mesh) -> Vec<usize> {
    let mut k = vec![0; mesh.n_vertices()];
    for f in mesh.faces() {
        for v in mesh.face_vertices(f) {
            k[v.idx()] += 1;
        }
    }
    k
}

/// B16's bound for a vertex with `n` corners and cone angle `θ` at unit roundoff `u`.
fn b16_bound(n: usize, theta: f64, u: f64) -> f64 {
    (16.0 * n as f64 + 16.0) * u * theta.abs().max(1.0)
}

/// Fans whose apex sum sits on or next to the places where the winding is decided:
/// multiples of 2π, odd multiples of π (the branch cut), and the quarter-turn rounding
/// boundaries (m + ½)·π/2; with 3 to 2000 corners.
fn winding_fans(count: usize) -> Vec<Vec<f64>> {
    let mut rng = ChaCha8Rng::seed_from_u64(15);
    (0..count)
        .map(|i| {
            let n = [3usize, 7, 12, 50, 200, 2000][i % 6];
            let kmax = (n as f64 * 0.9 / 2.0).floor().max(1.0) as i32; // α < π
            let k = f64::from(rng.gen_range(1..=kmax.min(40)));
            let target = match i % 3 {
                0 => 2.0 * PI * k,
                1 => PI * (2.0 * k - 1.0),
                _ => (4.0 * k + 0.5) * PI / 2.0,
            } + rng.gen_range(-1.0..1.0) * 10f64.powi(-rng.gen_range(3..15));
            let mut alpha = vec![target / n as f64; n];
            // Unequal corners with the same sum.
            for j in 0..n / 2 {
                let d = rng.gen_range(-0.3..0.3) * alpha[j].min(PI - alpha[j]);
                alpha[j] += d;
                alpha[n - 1 - j] -= d;
            }
            alpha
        })
        .collect()
}

/// Checks every vertex of `mesh` in backend `T` against the MPFR-512 reference within
/// B16's bound; returns the worst error in units of the bound.
fn check_backend<T: Real>(mesh: &Mesh, len: &[f64], ctx: T::Ctx, refs: &[Mpfr]) -> f64 {
    let l: Vec<T> = len.iter().map(|&x| T::from_f64(x, ctx)).collect();
    let got = cone_angles(mesh, &l);
    let u = T::unit_roundoff(ctx);
    let val = valence(mesh);
    let mut worst = 0.0_f64;
    for (v, (g, r)) in got.iter().zip(refs).enumerate() {
        let e = err(g, r) / b16_bound(val[v], r.approx_f64(), u);
        worst = worst.max(e);
    }
    worst
}

/// Independent quarter-turn index of an angle: `⌊φ/(π/2)⌋`.
fn floor_quarter(phi: f64) -> i64 {
    (phi / FRAC_PI_2).floor() as i64
}

/// Random pairs (Φ, δ) with δ in `[lo, hi)`, keeping Φ and Φ + δ at least 10⁻⁹ away from
/// the quarter-turn boundaries (where the f64 point (cos, sin) could fall on either side).
fn steps(count: usize, lo: f64, hi: f64, seed: u64) -> Vec<(f64, f64)> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let near = |x: f64| {
        let r = x / FRAC_PI_2;
        (r - r.round()).abs() < 1e-9
    };
    let mut out = Vec::with_capacity(count);
    while out.len() < count {
        let phi = rng.gen_range(-40.0..40.0);
        // Half of the steps hug the window ends.
        let delta = match rng.gen_range(0..4) {
            0 => lo + rng.gen_range(0.0..1e-6),
            1 => hi - rng.gen_range(1e-12..1e-6),
            _ => rng.gen_range(lo..hi),
        };
        if !near(phi) && !near(phi + delta) {
            out.push((phi, delta));
        }
    }
    out
}

#[test]
fn b15_quarter_step_is_the_floor_of_the_continuous_argument() {
    let n = cases(20_000, 1_000_000);
    // Non-obtuse steps: δ ∈ (−π/2, π); obtuse steps: δ ∈ [0, 3π/2).
    for (obtuse, lo, hi, seed) in [(false, -FRAC_PI_2, PI, 151), (true, 0.0, 1.5 * PI, 152)] {
        for (phi, delta) in steps(n, lo, hi, seed) {
            let next = phi + delta;
            let got = quarter_step(floor_quarter(phi), next.cos(), next.sin(), obtuse);
            assert_eq!(
                got,
                floor_quarter(next),
                "Φ = {phi}, δ = {delta}, obtuse = {obtuse}"
            );
        }
    }
}

#[test]
fn b15_negative_control_steps_outside_the_window_lose_a_turn() {
    // A step of more than π read as non-obtuse, or a step backwards read as obtuse, is
    // off by a full turn (four quarters) whenever its true quarter change leaves the window.
    let n = cases(2_000, 100_000);
    for (obtuse, lo, hi, seed) in [(false, PI, 1.5 * PI, 153), (true, -FRAC_PI_2, 0.0, 154)] {
        let mut outside = 0;
        for (phi, delta) in steps(n, lo, hi, seed) {
            let next = phi + delta;
            let (q, want) = (floor_quarter(phi), floor_quarter(next));
            let got = quarter_step(q, next.cos(), next.sin(), obtuse);
            let window = if obtuse { 0..=3 } else { -1..=2 };
            if window.contains(&(want - q)) {
                assert_eq!(got, want);
            } else {
                assert_eq!((got - want).abs(), 4, "Φ = {phi}, δ = {delta}");
                outside += 1;
            }
        }
        assert!(outside > n / 10, "only {outside} steps left the window");
    }
}

#[test]
fn b15_winding_recovered_near_multiples_of_2pi_and_the_cut() {
    let fans = winding_fans(cases(60, 3000));
    let p128 = Precision::new(128).expect("valid precision");
    for alpha in &fans {
        let (mesh, len) = fan(alpha);
        let refs = reference(&mesh, &len);
        // A wrong winding is off by ≥ 2π − tiny; B16's bound is far below 1.
        for w in [
            check_backend::<f64>(&mesh, &len, (), &refs),
            check_backend::<Dd>(&mesh, &len, (), &refs),
            check_backend::<Mpfr>(&mesh, &len, p128, &refs),
        ] {
            assert!(
                w <= 1.0,
                "{} corners, θ = {}: error {w} × bound",
                alpha.len(),
                refs[0].approx_f64()
            );
        }
    }
}

/// Fans whose apex corners are nearly flat (π − 10⁻ᵏ, or exactly π: rim length 2) or
/// nearly zero (10⁻ᵏ), alternating so that the partial sums sit next to multiples of π.
fn degenerate_fans(count: usize) -> Vec<Vec<f64>> {
    let mut rng = ChaCha8Rng::seed_from_u64(155);
    (0..count)
        .map(|_| {
            let n = rng.gen_range(3..40);
            (0..n)
                .map(|j| {
                    let eps = 10f64.powi(-rng.gen_range(3..13));
                    match (j % 2, rng.gen_range(0..4)) {
                        (0, 0) => PI,
                        (0, _) => PI - eps,
                        (_, 0) => rng.gen_range(0.1..3.0),
                        _ => eps,
                    }
                })
                .collect()
        })
        .collect()
}

#[test]
fn b15_winding_recovered_with_flat_and_needle_corners() {
    // Steps of (almost) π and of almost 0 are where a quarter count could slip; B16 claims
    // no accuracy for such triangles, but a lost turn would be off by about 2π.
    let p128 = Precision::new(128).expect("valid precision");
    for alpha in degenerate_fans(cases(40, 2000)) {
        let (mesh, len) = fan(&alpha);
        let refs = reference(&mesh, &len);
        let f = cone_angles(&mesh, &len);
        let l: Vec<Dd> = len.iter().map(|&x| Dd::from_f64(x)).collect();
        let d = cone_angles(&mesh, &l);
        let l: Vec<Mpfr> = len.iter().map(|&x| Mpfr::from_f64(x, p128)).collect();
        let m = cone_angles(&mesh, &l);
        for v in 0..refs.len() {
            let e = [
                err(&f[v], &refs[v]),
                err(&d[v], &refs[v]),
                err(&m[v], &refs[v]),
            ];
            assert!(
                e.iter().all(|&x| x < 1e-5),
                "vertex {v} of {alpha:?}: errors {e:?}"
            );
        }
    }
}

#[test]
fn b15_negative_control_wrong_quarter_is_rejected() {
    // The kernel's result unwrapped around a quarter turn off by four (a lost turn) is off
    // by 2π; around the right one it meets B16's bound.
    let alpha = vec![2.0 * PI * 3.0 / 20.0 + 1e-9; 20];
    let (mesh, len) = fan(&alpha);
    let refs = reference(&mesh, &len);
    let l: Vec<Dd> = len.iter().map(|&x| Dd::from_f64(x)).collect();
    let good = cone_angles(&mesh, &l)[0];
    let bound = b16_bound(20, 6.0 * PI, Dd::unit_roundoff(()));
    assert!(err(&good, &refs[0]) <= bound);
    let (re, im) = (good.cos(), good.sin());
    let m = (good.approx_f64() / FRAC_PI_2).floor() as i64;
    let half_pi = Dd::pi(()) * Dd::from_f64(0.5);
    let right = unwrap_quarter(&re, &im, m, &half_pi);
    assert!(err(&right, &refs[0]) <= 2.0 * bound);
    let wrong = unwrap_quarter(&re, &im, m + 4, &half_pi);
    assert!(err(&wrong, &refs[0]) > 6.0, "a lost turn was not detected");
    assert!(
        err(
            &unwrap_angle(&re, &im, good.approx_f64() + 2.0 * PI),
            &refs[0]
        ) > 6.0
    );
}

#[test]
fn b16_cone_angles_accuracy_comparable_to_per_corner_sum() {
    let (mesh, len) = jittered_torus(12, 10, 16);
    let mut meshes = vec![(mesh, len)];
    for alpha in winding_fans(cases(12, 300)) {
        meshes.push(fan(&alpha));
    }
    for (mesh, len) in &meshes {
        let refs = reference(mesh, len);
        let p128 = Precision::new(128).expect("valid precision");
        let p256 = Precision::new(256).expect("valid precision");
        let w = [
            check_backend::<f64>(mesh, len, (), &refs),
            check_backend::<Dd>(mesh, len, (), &refs),
            check_backend::<Mpfr>(mesh, len, p128, &refs),
            check_backend::<Mpfr>(mesh, len, p256, &refs),
        ];
        assert!(
            w.iter().all(|&x| x <= 1.0),
            "errors in units of B16's bound: {w:?}"
        );
    }
}

#[test]
fn b16_measured_errors_of_kernel_and_per_corner_sum() {
    // Reports both errors in units of n·u (the per-corner sum is the comparison baseline).
    let (mesh, len) = jittered_torus(16, 12, 161);
    let refs = reference(&mesh, &len);
    let val = valence(&mesh);
    let report = |name: &str, fast: &[f64], slow: &[f64]| {
        let fm = fast.iter().copied().fold(0.0, f64::max);
        let sm = slow.iter().copied().fold(0.0, f64::max);
        eprintln!("b16 {name}: kernel {fm:.3} n·u, per-corner {sm:.3} n·u");
        fm
    };
    let rel = |e: f64, v: usize, u: f64| e / (val[v] as f64 * u);
    // Errors of the kernel and of the per-corner sum at one backend, in units of n·u.
    let errors = |f: Vec<f64>, s: Vec<f64>, u: f64| -> (Vec<f64>, Vec<f64>) {
        let scaled =
            |x: &[f64]| -> Vec<f64> { x.iter().enumerate().map(|(v, &e)| rel(e, v, u)).collect() };
        (scaled(&f), scaled(&s))
    };
    let l: Vec<f64> = len.clone();
    let (f, s) = (cone_angles(&mesh, &l), cone_angles_per_corner(&mesh, &l));
    let (fe, se) = errors(
        f.iter().zip(&refs).map(|(x, r)| err(x, r)).collect(),
        s.iter().zip(&refs).map(|(x, r)| err(x, r)).collect(),
        f64::unit_roundoff(()),
    );
    let m64 = report("f64", &fe, &se);
    let l: Vec<Dd> = len.iter().map(|&x| Dd::from_f64(x)).collect();
    let (f, s) = (cone_angles(&mesh, &l), cone_angles_per_corner(&mesh, &l));
    let (fe, se) = errors(
        f.iter().zip(&refs).map(|(x, r)| err(x, r)).collect(),
        s.iter().zip(&refs).map(|(x, r)| err(x, r)).collect(),
        Dd::unit_roundoff(()),
    );
    let mdd = report("dd", &fe, &se);
    assert!(m64 <= 16.0 && mdd <= 16.0);
}

#[test]
fn b16_negative_control_f64_result_fails_the_dd_bound() {
    let (mesh, len) = jittered_torus(8, 8, 162);
    let refs = reference(&mesh, &len);
    let val = valence(&mesh);
    let f = cone_angles(&mesh, &len);
    let worst = f
        .iter()
        .zip(&refs)
        .enumerate()
        .map(|(v, (x, r))| err(x, r) / b16_bound(val[v], r.approx_f64(), Dd::unit_roundoff(())))
        .fold(0.0, f64::max);
    assert!(worst > 1.0, "the Dd bound accepted an f64 result ({worst})");
}
