//! Surfaces with boundary by the double cover (B79): a planar convex polygon with its own
//! angles stays (u = 0, certified), a grid disk sent to other corner angles moves (u ≠ 0,
//! certified on the double, symmetric), Gauss–Bonnet with boundary decided exactly, and
//! `penner uniformize` on a disk end to end. Wrong targets are the negative controls.

use crate::support::{penner, scratch, text};
use penner::io::{json, Metric, Surface};
use penner::mesh::{builders, Mesh};
use penner::uniformization::boundary::{
    double_targets, flat_with_even_boundary, uniformize_with_boundary, validate_boundary_targets,
    BoundaryError, BoundaryUniformization,
};
use penner::uniformization::certificate::{
    certify_near, check_certificate, prove, CertificateData, CertificateOutcome,
};
use penner::uniformization::{uniformize, Targets, UniformizeOptions};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

/// The `m × n` unit grid disk with every interior vertex moved by a random dyadic offset
/// `k/64`, `|k| ≤ 12`, and every non-corner boundary vertex moved the same way along its
/// side: a planar triangulation of the rectangle, interior angle sums 2π, boundary sums π
/// and π/2 at the corners, no cocircular quadrilateral for a generic draw. Coordinates
/// and squared lengths are exact in binary64; lengths are their correctly rounded roots.
fn jittered_grid(m: u32, n: u32, seed: u64) -> (Mesh, Vec<f64>, [usize; 4]) {
    let g = builders::grid_disk(m, n).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut p: Vec<[f64; 2]> = (0..(m + 1) * (n + 1))
        .map(|v| [f64::from(v % (m + 1)), f64::from(v / (m + 1))])
        .collect();
    for (v, q) in p.iter_mut().enumerate() {
        let (i, j) = (v as u32 % (m + 1), v as u32 / (m + 1));
        let (side_x, side_y) = (i == 0 || i == m, j == 0 || j == n);
        let mut d = || f64::from(rng.gen_range(-12i32..=12)) / 64.0;
        match (side_x, side_y) {
            (true, true) => {}
            (true, false) => q[1] += d(),
            (false, true) => q[0] += d(),
            (false, false) => {
                q[0] += d();
                q[1] += d();
            }
        }
    }
    let l = g
        .mesh
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (p[g.mesh.tail(h).idx()], p[g.mesh.tip(h).idx()]);
            ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
        })
        .collect();
    let corner = |i: u32, j: u32| (i + (m + 1) * j) as usize;
    // Counter-clockwise: (0,0), (m,0), (m,n), (0,n).
    (
        g.mesh,
        l,
        [corner(0, 0), corner(m, 0), corner(m, n), corner(0, n)],
    )
}

/// Targets: 2 inside, 1 on the boundary, `corners[k]` at corner `k`.
fn targets(mesh: &Mesh, corners: [usize; 4], at: [(i64, i64); 4]) -> Targets {
    let b = mesh.boundary_vertices();
    let mut q: Vec<Rational> = b
        .iter()
        .map(|&on| Rational::from(if on { 1 } else { 2 }))
        .collect();
    for (v, r) in corners.into_iter().zip(at) {
        q[v] = Rational::from(r);
    }
    Targets::from_multiples_of_pi(q)
}

fn solve(mesh: &Mesh, l: &[f64], t: &Targets) -> BoundaryUniformization {
    uniformize_with_boundary(mesh, l, t, &UniformizeOptions::default(), &mut |_| {}).unwrap()
}

fn norm2_diff(a: &[f64], b: &[Rational]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, q)| (x - q.to_f64()).powi(2))
        .sum::<f64>()
        .sqrt()
}

/// B79: the computed solution's asymmetry is at most `2(‖u − u_c‖₂ + d)`, `u_c` the
/// certified centre and `d` the certified distance to the exact (symmetric) solution.
fn b79_asymmetry_bound(b: &BoundaryUniformization, data: &CertificateData, d: f64) -> f64 {
    2.0 * (norm2_diff(&b.solution.u, &data.u) + d) * (1.0 + 1e-12)
}

#[test]
fn b79_convex_polygon_with_its_own_angles_has_u_zero_certified() {
    for seed in 0..2 {
        let (m, l, c) = jittered_grid(4, 3, seed);
        let right = [(1, 2); 4];
        let t = targets(&m, c, right);
        let b = solve(&m, &l, &t);
        assert!(b.solution.converged(), "seed {seed}");
        assert!(b.seam_flips.is_empty(), "seed {seed}");
        // Certified at u = 0 itself: an exact solution of the (rounded) input lies within
        // d of 0 (B71 on the double, B79 for the surface).
        let n = b.solution.u.len();
        let zero = vec![Rational::new(); n];
        let p = certify_near(&b.solution, None, &zero, 1e-15, 128).unwrap();
        let CertificateOutcome::Holds { distance, .. } = p.outcome else {
            panic!("seed {seed}: {:?}", p.outcome);
        };
        // B79 (closed form): the binary64 lengths are within 2⁻⁵³ relative of the planar
        // ones, for which u = 0 is exact; 1e-12 bounds the resulting distance here.
        assert!(distance <= 1e-12, "seed {seed}: {distance:e}");
        assert!(
            b.u.iter().all(|x| x.abs() <= 1e-9),
            "seed {seed}: {:?}",
            b.u
        );
        // Negative control: the same u = 0 does not certify the targets π/3, 2π/3.
        let wrong = targets(&m, c, [(1, 3), (2, 3), (1, 3), (2, 3)]);
        let bw = solve(&m, &l, &wrong);
        let pw = certify_near(&bw.solution, None, &zero, 1e-15, 128).unwrap();
        assert!(
            !matches!(pw.outcome, CertificateOutcome::Holds { .. }),
            "seed {seed}"
        );
    }
}

#[test]
fn b79_grid_disk_to_other_corner_angles_moves_and_is_certified_symmetric() {
    let (m, l, c) = jittered_grid(5, 4, 7);
    let t = targets(&m, c, [(1, 3), (2, 3), (1, 3), (2, 3)]);
    let b = solve(&m, &l, &t);
    assert!(b.solution.converged());
    let proof = prove(&b.solution, 128, 1e-30).unwrap();
    let CertificateOutcome::Holds { distance, .. } = proof.outcome else {
        panic!("{:?}", proof.outcome);
    };
    let bound = b79_asymmetry_bound(&b, &proof.data, distance);
    assert!(
        b.mirror_asymmetry <= bound,
        "{:e} > {bound:e}",
        b.mirror_asymmetry
    );
    let umax = b.u.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    assert!(umax > 0.05, "u = {:?}", b.u);
    // The boundary angle sums on copy 1 alone (numerical): the double's Θ = 2φ split
    // evenly by symmetry; tolerance: the solver's 1e-10 plus the asymmetry's effect.
    if let Some(sums) = b.angle_sums_on_original() {
        let on_b = m.boundary_vertices();
        for (v, s) in sums.iter().enumerate() {
            let want = t.over_pi()[v].to_f64() * std::f64::consts::PI;
            assert!(
                (s - want).abs() <= 1e-8,
                "v{v}: {s} vs {want} ({})",
                on_b[v]
            );
        }
    }
    // Negative control: the same certified u does not certify the right-angle targets.
    let mut data = proof.data.clone();
    data.targets = double_targets(&b.double, &targets(&m, c, [(1, 2); 4]));
    let out = check_certificate(&data, 128).unwrap();
    assert!(!matches!(out, CertificateOutcome::Holds { .. }), "{out:?}");
}

#[test]
fn b79_asymmetric_targets_on_the_double_break_the_symmetry() {
    // Negative control of the symmetry check: on the double, move π/8 of cone angle from
    // an interior vertex to its mirror (Gauss–Bonnet kept): the solution is asymmetric.
    let (m, l, c) = jittered_grid(4, 4, 3);
    let t = targets(&m, c, [(1, 2); 4]);
    let b = solve(&m, &l, &t);
    let d = &b.double;
    let dl = d.pull_back_edges(&l).unwrap();
    let mut q = double_targets(d, &t).over_pi().to_vec();
    let v = (0..m.n_vertices())
        .find(|&v| !m.boundary_vertices()[v])
        .unwrap();
    let w = d.vertex_mirror[v].idx();
    q[v] += Rational::from((1, 8));
    q[w] -= Rational::from((1, 8));
    let sol = uniformize(
        &d.mesh,
        &dl,
        &Targets::from_multiples_of_pi(q),
        &UniformizeOptions::default(),
    )
    .unwrap();
    assert!(sol.converged());
    let asym = (sol.u[v] - sol.u[w]).abs();
    assert!(asym > 1e-3, "{asym:e}");
    assert!(b.mirror_asymmetry < 1e-6, "{:e}", b.mirror_asymmetry);
}

#[test]
fn b79_gauss_bonnet_with_boundary_is_decided_exactly() {
    let (m, _, c) = jittered_grid(3, 3, 1);
    assert!(validate_boundary_targets(&m, &targets(&m, c, [(1, 2); 4])).is_ok());
    assert!(
        validate_boundary_targets(&m, &targets(&m, c, [(1, 3), (2, 3), (1, 3), (2, 3)])).is_ok()
    );
    // Violations: one corner off by 1/1000 of π; a boundary vertex given 2π as if interior.
    let off = targets(&m, c, [(1, 2), (1, 2), (1, 2), (501, 1000)]);
    assert!(matches!(
        validate_boundary_targets(&m, &off),
        Err(BoundaryError::GaussBonnet { chi: 1, .. })
    ));
    let mut q = targets(&m, c, [(1, 2); 4]).over_pi().to_vec();
    let bv = (0..m.n_vertices())
        .find(|&v| m.boundary_vertices()[v] && !c.contains(&v))
        .unwrap();
    q[bv] = Rational::from(2);
    let e = validate_boundary_targets(&m, &Targets::from_multiples_of_pi(q.clone())).unwrap_err();
    assert!(e.to_string().contains("Gauss–Bonnet with boundary"), "{e}");
    q[bv] = Rational::from(0);
    assert!(matches!(
        validate_boundary_targets(&m, &Targets::from_multiples_of_pi(q)),
        Err(BoundaryError::NonPositiveTarget {
            kind: "boundary",
            ..
        })
    ));
    assert!(matches!(
        validate_boundary_targets(&m, &Targets::flat(3)),
        Err(BoundaryError::TargetCount { .. })
    ));
    // A closed surface has no boundary to prescribe.
    let torus = builders::one_vertex_torus();
    assert!(matches!(
        validate_boundary_targets(&torus, &Targets::flat(1)),
        Err(BoundaryError::ClosedComponent { .. })
    ));
}

#[test]
fn b79_flat_default_spreads_the_boundary_curvature_evenly() {
    let disk = builders::grid_disk(3, 2).unwrap().mesh;
    let t = flat_with_even_boundary(&disk);
    assert!(validate_boundary_targets(&disk, &t).is_ok());
    let nb = disk.boundary_vertices().iter().filter(|b| **b).count() as i64;
    for (v, q) in t.over_pi().iter().enumerate() {
        let want = if disk.boundary_vertices()[v] {
            Rational::from(1) - Rational::from((2, nb))
        } else {
            Rational::from(2)
        };
        assert_eq!(*q, want, "v{v}");
    }
    let annulus = builders::annulus(5, 2).unwrap().mesh;
    let ta = flat_with_even_boundary(&annulus);
    assert!(validate_boundary_targets(&annulus, &ta).is_ok());
    assert!(ta.over_pi().iter().all(|q| *q == 1 || *q == 2));
}

fn surface_file(dir: &std::path::Path, name: &str, m: Mesh, l: &[f64]) -> String {
    let metric = Metric::Lengths(l.iter().map(|&x| Rational::from_f64(x).unwrap()).collect());
    let s = Surface::new(name, m, metric, None).unwrap();
    let p = dir.join(format!("{name}.json"));
    std::fs::write(&p, json::write(&s)).unwrap();
    p.display().to_string()
}

#[test]
fn b79_cli_uniformize_a_disk_certifies_the_double() {
    let d = scratch("uniformize-disk");
    let (m, l, c) = jittered_grid(5, 4, 11);
    let n = m.n_vertices();
    let t = targets(&m, c, [(1, 3), (2, 3), (1, 3), (2, 3)]);
    let surf = surface_file(&d, "disk", m, &l);
    let tf = d.join("targets.json");
    let list: Vec<String> = t.over_pi().iter().map(|q| format!("\"{q}\"")).collect();
    std::fs::write(&tf, format!("[{}]", list.join(","))).unwrap();
    let cert = d.join("cert.json").display().to_string();
    let svg = d.join("disk.svg").display().to_string();
    let tfs = tf.display().to_string();
    let out = penner(&[
        "uniformize",
        &surf,
        "--targets",
        &tfs,
        "--svg",
        &svg,
        "-o",
        &cert,
    ]);
    let so = text(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{so}{}", text(&out.stderr));
    assert!(so.contains("certified on the double"), "{so}");
    assert!(so.contains("seam intact"), "{so}");
    assert!(
        so.contains("0 faces not certified counterclockwise"),
        "{so}"
    );
    let out = penner(&["certify", &cert]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));
    // --flat: 2π inside, the curvature spread over the boundary.
    let cert2 = d.join("cert-flat.json").display().to_string();
    let out = penner(&["uniformize", &surf, "--flat", "-o", &cert2]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));
    // Negative controls: Gauss–Bonnet violated → typed error, non-zero exit, no file.
    let bad = d.join("bad.json");
    let mut wrong: Vec<String> = list.clone();
    wrong[c[0]] = "\"1/2\"".into();
    std::fs::write(&bad, format!("[{}]", wrong.join(","))).unwrap();
    let cert3 = d.join("cert-bad.json");
    let out = penner(&[
        "uniformize",
        &surf,
        "--targets",
        &bad.display().to_string(),
        "-o",
        &cert3.display().to_string(),
    ]);
    assert_ne!(out.status.code(), Some(0));
    assert!(
        text(&out.stderr).contains("Gauss–Bonnet with boundary"),
        "{}",
        text(&out.stderr)
    );
    assert!(!cert3.exists());
    // Wrong count of targets.
    std::fs::write(
        bad.with_extension("short.json"),
        format!("[{}]", list[..n - 1].join(",")),
    )
    .unwrap();
    let out = penner(&[
        "uniformize",
        &surf,
        "--targets",
        &bad.with_extension("short.json").display().to_string(),
    ]);
    assert_ne!(out.status.code(), Some(0));
    assert!(!text(&out.stderr).contains("panicked"));
}
