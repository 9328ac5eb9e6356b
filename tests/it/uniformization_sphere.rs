//! The sphere target of uniformization (notes Thm 9; T24, B74–B76): a genus-0 surface
//! mapped to a convex polyhedron inscribed in the unit sphere, checked against a closed
//! form, against the input's length cross ratios (T16, T20) and by certified planar
//! predicates, with the disk problem certified (B76). Each check has a negative control.

use crate::meshgen::icosphere;
use crate::support::cases;
use penner::mesh::{Mesh, Vertex};
use penner::scalar::{Interval, Mpfr, Precision};
use penner::uniformization::certificate::CertificateOutcome;
use penner::uniformization::dirichlet_certificate::{
    certify_disk, certify_disk_near, check_disk_certificate,
};
use penner::uniformization::sphere::{
    uniformize_sphere, SphereError, SphereOptions, SphereUniformization,
};
use penner::uniformization::sphere_checks::{
    chord_lengths, cross_ratio_deviation, planar_delaunay,
};
use penner::uniformization::sphere_claim::{claim_of, recheck, to_json};
use penner::uniformization::sphere_refine::{input_disk_metric, prove_disk};
use rug::Rational;

/// B75: tolerance of the numerical comparisons of the output polyhedron (chords, log
/// cross ratios) for surfaces of at most 10³ vertices solved to max |Θ − θ| ≤ 10⁻¹².
const B75_TOLERANCE: f64 = 1e-8;

/// A noisy icosphere (`20k²` faces) and its Euclidean lengths.
fn noisy_sphere(k: u32, seed: u64) -> (Mesh, Vec<f64>) {
    let mut s = icosphere(k);
    let amount = 0.2 * s.mean_edge();
    s.jitter(amount, seed);
    let m = s.mesh();
    let l = s.lengths(&m);
    (m, l)
}

/// The bipyramid over the regular `n`-gon in the unit circle with apexes `(0, 0, top)` and
/// `(0, 0, −bottom)` (vertices `n`, `n + 1`), and its Euclidean lengths.
fn bipyramid(n: u32, top: f64, bottom: f64) -> (Mesh, Vec<f64>) {
    let mut pos: Vec<[f64; 3]> = (0..n)
        .map(|k| {
            let a = 2.0 * std::f64::consts::PI * f64::from(k) / f64::from(n);
            [a.cos(), a.sin(), 0.0]
        })
        .collect();
    pos.push([0.0, 0.0, top]);
    pos.push([0.0, 0.0, -bottom]);
    let mut faces = Vec::new();
    for k in 0..n {
        faces.push([k, (k + 1) % n, n]);
        faces.push([(k + 1) % n, k, n + 1]);
    }
    let m = Mesh::from_faces(n + 2, &faces).unwrap();
    let l = m
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (pos[m.tail(h).idx()], pos[m.tip(h).idx()]);
            ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
        })
        .collect();
    (m, l)
}

/// The largest deviation of the chords of `sol` from the closed form of the bipyramid
/// (B74, "Closed form"): `√2` from an apex, `2 sin(π/n)` along the equator.
fn bipyramid_error(sol: &SphereUniformization, n: u32) -> f64 {
    let c = chord_lengths(sol);
    let equator = 2.0 * (std::f64::consts::PI / f64::from(n)).sin();
    sol.mesh
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let apex = sol.mesh.tail(h).0 >= n || sol.mesh.tip(h).0 >= n;
            let want = if apex { 2f64.sqrt() } else { equator };
            (c[e.idx()] - want).abs()
        })
        .fold(0.0, f64::max)
}

#[test]
fn t24_sphere_bipyramid_matches_the_closed_form() {
    for (n, top, bottom) in [(4, 1.0, 1.0), (5, 0.6, 1.7), (7, 0.3, 2.5)] {
        let (m, l) = bipyramid(n, top, bottom);
        let sol = uniformize_sphere(&m, &l, &SphereOptions::default()).unwrap();
        let err = bipyramid_error(&sol, n);
        assert!(err <= B75_TOLERANCE, "n = {n}: chord error {err:e}");
        // The apexes are antipodal (the result is unique up to rotation).
        let (a, b) = (sol.positions[n as usize], sol.positions[n as usize + 1]);
        let gap = (0..3).map(|k| (a[k] + b[k]).abs()).fold(0.0, f64::max);
        assert!(gap <= B75_TOLERANCE, "n = {n}: |a + b| = {gap:e}");
        // Negative control: without the Möbius normalisation the same polyhedron is
        // inscribed but not centred, and the closed form rejects it.
        let raw = SphereOptions {
            normalize: false,
            ..SphereOptions::default()
        };
        let sol = uniformize_sphere(&m, &l, &raw).unwrap();
        assert!(bipyramid_error(&sol, n) > 1e3 * B75_TOLERANCE, "n = {n}");
    }
}

#[test]
fn t24_sphere_cross_ratios_match_the_input() {
    for seed in 0..cases(2, 8) as u64 {
        let (m, l) = noisy_sphere(3, seed);
        let sol = uniformize_sphere(&m, &l, &SphereOptions::default()).unwrap();
        for p in &sol.positions {
            let r = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
            assert!((r - 1.0).abs() <= 1e-15, "seed {seed}: |x| = {r}");
        }
        let dev = cross_ratio_deviation(&sol, &sol.initial_lengths).unwrap();
        assert!(dev <= B75_TOLERANCE, "seed {seed}: {dev:e}");
        // Negative control: one input length 0.1 % longer changes the cross ratios of its
        // two quadrilaterals' edges by about 10⁻³.
        let mut wrong = sol.initial_lengths.clone();
        wrong[7] *= 1.001;
        let dev = cross_ratio_deviation(&sol, &wrong).unwrap();
        assert!(dev > 1e4 * B75_TOLERANCE, "seed {seed}: control {dev:e}");
    }
}

#[test]
fn t24_sphere_layout_is_certified_planar_delaunay_and_convex() {
    let (m, l) = noisy_sphere(3, 11);
    let sol = uniformize_sphere(&m, &l, &SphereOptions::default()).unwrap();
    let disk = &sol.solution.mesh;
    let ok = planar_delaunay(disk, &sol.planar);
    assert!(ok.holds(), "{ok:?}");
    // Negative control 1: an interior vertex moved onto a far one folds triangles.
    let bv = disk.boundary_vertices();
    let inner: Vec<usize> = (0..disk.n_vertices()).filter(|&v| !bv[v]).collect();
    let mut folded = sol.planar.clone();
    folded[inner[0]] = sol.planar[inner[inner.len() - 1]];
    let bad = planar_delaunay(disk, &folded);
    assert!(!bad.not_ccw.is_empty(), "{bad:?}");
    // Negative control 2: a boundary vertex moved to the centroid of the disk (the origin,
    // inside the convex boundary polygon) makes the boundary reflex there.
    let a = (0..disk.n_vertices()).find(|&v| bv[v]).unwrap();
    let mut dented = sol.planar.clone();
    dented[a] = [0.0, 0.0];
    let bad = planar_delaunay(disk, &dented);
    assert!(bad.not_convex.contains(&Vertex(a as u32)), "{bad:?}");
}

#[test]
fn b76_disk_certificate_holds_and_refuses_a_wrong_u() {
    let (m, l) = noisy_sphere(3, 5);
    let sol = uniformize_sphere(&m, &l, &SphereOptions::default()).unwrap();
    let (data, outcome) = certify_disk(&sol, 128);
    let CertificateOutcome::Holds { distance, .. } = outcome else {
        panic!("{outcome:?}")
    };
    assert!(distance < 1e-9);
    // Negative control: u moved by 10⁻⁴ at a free vertex, far outside the box's radius.
    let free = data.pole_length.iter().position(Option::is_none).unwrap();
    let mut wrong = data.clone();
    wrong.u[free] += Rational::from((1, 10_000));
    assert!(matches!(
        check_disk_certificate(&wrong, 128),
        CertificateOutcome::Undecided { .. }
    ));
    // Negative control: a Dirichlet value of another problem (one pole length doubled).
    let link = data.pole_length.iter().position(Option::is_some).unwrap();
    let mut wrong = data;
    wrong.pole_length[link] = wrong.pole_length[link].map(|x| 2.0 * x);
    assert!(matches!(
        check_disk_certificate(&wrong, 128),
        CertificateOutcome::Undecided { .. }
    ));
}

/// B90: the claim of a sphere uniformization re-checks for the input's exact metric
/// (irrational lengths from rational positions, Euclidean flips replayed on enclosures),
/// survives the claim parser unchanged, and is refused for a perturbed input, a moved `u`
/// and a flip of a star edge.
#[test]
fn b90_sphere_claim_rechecks_for_the_exact_input_metric() {
    // The first seed whose input is not intrinsic Delaunay, so that the replay is
    // exercised, and whose f64 certificate holds.
    let (s, sol, data, residual) = (1..40)
        .find_map(|seed| {
            let mut e = icosphere(2);
            let amount = 0.45 * e.mean_edge();
            e.jitter(amount, seed);
            let s = crate::registry_uniformization::exact_positions("rough sphere", &e);
            let l = s.lengths::<f64>(());
            let sol = uniformize_sphere(&s.mesh, &l, &SphereOptions::default()).ok()?;
            if sol.euclidean_flips == 0 {
                return None;
            }
            // Some rough spheres need a flip at the pole (B93); those certify too.
            // The certificate for the exact metric (the claim's residual bound is its).
            let prec = Precision::new(128).unwrap();
            let metric =
                input_disk_metric(&sol, &s.mesh, s.lengths::<Interval<Mpfr>>(prec)).ok()?;
            let u: Vec<Rational> = sol
                .solution
                .u
                .iter()
                .map(|&x| Rational::from_f64(x).unwrap())
                .collect();
            let (data, outcome) =
                certify_disk_near(&sol, Some(&metric), &u, sol.solution.residual_max, 128);
            let CertificateOutcome::Holds { residual, .. } = outcome else {
                return None;
            };
            Some((s, sol, data, residual))
        })
        .expect("a noisy sphere that needs Euclidean flips");
    let claim = claim_of(&s, &sol, &data, residual);
    let exact = recheck(&s, &claim, 128).unwrap();
    assert!(
        matches!(exact, CertificateOutcome::Holds { distance, .. } if distance < 1e-9),
        "{exact:?}"
    );
    // The document parses back to the same claim.
    let doc = to_json(&s, &claim, 128);
    let parsed = penner::oracle::claim::parse_value(&doc).unwrap();
    assert_eq!(
        parsed.assertion,
        penner::oracle::claim::Assertion::SphereUniformization(claim.clone())
    );
    // Negative control: one input length 1% longer (squared length × 1.0201).
    let mut wrong = s.clone();
    if let penner::io::Metric::SquaredLengths(sq) = &mut wrong.metric {
        sq[0] *= Rational::from((10201, 10000));
    } else {
        panic!("squared lengths expected");
    }
    let out = recheck(&wrong, &claim, 128).unwrap();
    assert!(
        matches!(out, CertificateOutcome::Undecided { .. }),
        "{out:?}"
    );
    // Negative control: u moved by 10⁻⁴ at a free vertex.
    let mut moved = claim.clone();
    let free = moved.u.iter().position(Option::is_some).unwrap();
    if let Some(x) = &mut moved.u[free] {
        *x += Rational::from((1, 10_000));
    }
    let out = recheck(&s, &moved, 128).unwrap();
    assert!(
        matches!(out, CertificateOutcome::Undecided { .. }),
        "{out:?}"
    );
    // Flips that do not reach the claimed final faces (here one flip of an edge at the
    // pole, allowed by B93 but not the claimed triangulation) are malformed, named by field.
    let order = penner::io::json::edge_order(&s.mesh);
    let star = sol
        .initial_mesh
        .outgoing(Vertex(sol.pole))
        .next()
        .unwrap()
        .edge();
    let mut star_flip = claim;
    star_flip.flips = vec![order.iter().position(|&e| e == star.idx()).unwrap()];
    let e = recheck(&s, &star_flip, 128).unwrap_err();
    assert!(e.to_string().contains("final_faces"), "{e}");
}

/// B91: the disk problem refined in MPFR-256 (f64 factor) reaches `max |2π − θ| ≤ 10⁻⁶⁰`
/// and is certified for the exact input metric at 256 bits; its claim re-checks. Negative
/// control: the same `u` is not a solution for the binary64 rounding of the input (the
/// rounding moves `u` by about `10⁻¹⁶`, far beyond the box).
#[test]
fn b91_sphere_refinement_certifies_to_1e_60_at_256_bits() {
    let s = crate::registry_uniformization::irrational_sphere(2, 3);
    let l = s.lengths::<f64>(());
    let sol = uniformize_sphere(&s.mesh, &l, &SphereOptions::default()).unwrap();
    let prec = Precision::new(256).unwrap();
    let metric = input_disk_metric(&sol, &s.mesh, s.lengths::<Interval<Mpfr>>(prec)).unwrap();
    let proof = prove_disk(&sol, Some(&metric), prec, 2f64.powi(-200)).unwrap();
    let last = *proof.history.last().unwrap();
    assert!(last <= 1e-60, "{:?}", proof.history);
    let CertificateOutcome::Holds {
        residual, distance, ..
    } = proof.outcome
    else {
        panic!("{:?}", proof.outcome)
    };
    assert!(
        residual <= 1e-59 && distance < 1e-55,
        "{residual:e} {distance:e}"
    );
    let claim = claim_of(&s, &sol, &proof.data, residual);
    let again = recheck(&s, &claim, 256).unwrap();
    assert!(
        matches!(again, CertificateOutcome::Holds { .. }),
        "{again:?}"
    );
    let rounded = check_disk_certificate(&proof.data, 256);
    assert!(
        matches!(rounded, CertificateOutcome::Undecided { .. }),
        "{rounded:?}"
    );
}

#[test]
fn t24_sphere_bad_input_is_typed() {
    let torus = crate::meshgen::jittered_torus(6, 6, 1);
    assert!(matches!(
        uniformize_sphere(&torus.0, &torus.1, &SphereOptions::default()),
        Err(SphereError::NotASphere { chi: 0, .. })
    ));
    let (m, l) = bipyramid(5, 1.0, 1.0);
    let far = SphereOptions {
        pole: Some(99),
        ..SphereOptions::default()
    };
    assert!(matches!(
        uniformize_sphere(&m, &l, &far),
        Err(SphereError::Pole { vertex: 99, .. })
    ));
    let mut bad = l.clone();
    bad[3] = -1.0;
    assert!(matches!(
        uniformize_sphere(&m, &bad, &SphereOptions::default()),
        Err(SphereError::Input(_))
    ));
    let open = Mesh::from_faces(3, &[[0, 1, 2]]).unwrap();
    assert!(uniformize_sphere(&open, &[1.0; 3], &SphereOptions::default()).is_err());
}

/// The inscribed polyhedron keeps the input's orientation: on the octahedron and the
/// icosahedron (outward faces: positive signed volume `Σ det(p_a, p_b, p_c)/6`), the
/// output's faces are outward too (they were inward: the inverse stereographic projection
/// reverses orientation). Control: the same
/// positions mirrored (`y ↦ −y`) have negative volume.
#[test]
fn b74_inscribed_polyhedron_keeps_the_orientation() {
    use penner::uniformization::sphere::{uniformize_sphere, SphereOptions};
    let volume = |faces: &[[u32; 3]], p: &dyn Fn(usize) -> [f64; 3]| {
        faces
            .iter()
            .map(|f| {
                let [a, b, c] = f.map(|v| p(v as usize));
                a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                    + a[2] * (b[0] * c[1] - b[1] * c[0])
            })
            .sum::<f64>()
            / 6.0
    };
    let cases = [
        ("octahedron", penner::mesh::builders::octahedron()),
        ("icosahedron", penner::mesh::builders::icosahedron()),
    ];
    for (name, e) in cases {
        let input = |v: usize| e.positions[v].clone().map(|q| q.to_f64());
        assert!(
            volume(&e.mesh.face_list(), &input) > 0.0,
            "{name}: input outward"
        );
        let lengths: Vec<f64> = penner::io::Surface::from_embedded(name, e.clone())
            .unwrap()
            .lengths(());
        let sol = uniformize_sphere(&e.mesh, &lengths, &SphereOptions::default()).unwrap();
        let out = |v: usize| sol.positions[v];
        let faces = sol.mesh.face_list();
        assert!(volume(&faces, &out) > 0.0, "{name}: output outward");
        let mirrored = |v: usize| {
            let [x, y, z] = sol.positions[v];
            [x, -y, z]
        };
        assert!(volume(&faces, &mirrored) < 0.0, "{name}: control");
    }
}

/// The pole test of B74 against its definition computed over the whole mesh (the
/// neighbours of `v` by a scan of every half-edge, the star by a scan of every face): the
/// same verdict on every vertex of spheres, randomly flipped spheres (loops and parallel
/// edges appear), the two-triangle sphere (every face holds every vertex) and a torus.
#[test]
fn b74_check_pole_matches_the_whole_mesh_definition() {
    use penner::mesh::{builders, Mesh, Vertex};
    use penner::uniformization::sphere::check_pole;
    let oracle = |m: &Mesh, v: Vertex| -> bool {
        let mut ends: Vec<Vertex> = m
            .halfedges()
            .filter(|&h| m.tail(h) == v)
            .map(|h| m.tip(h))
            .collect();
        let n = ends.len();
        if ends.contains(&v) {
            return false;
        }
        ends.sort_unstable();
        ends.dedup();
        let star = m
            .faces()
            .filter(|&f| m.face_vertices(f).contains(&v))
            .count();
        ends.len() == n && star < m.n_faces()
    };
    let mut meshes = vec![
        builders::tetrahedron().mesh,
        builders::octahedron().mesh,
        builders::icosahedron().mesh,
        builders::two_triangle_sphere(),
        builders::one_vertex_torus(),
    ];
    for seed in 0..20 {
        meshes.push(builders::random_flips(
            &builders::icosahedron().mesh,
            40,
            seed,
        ));
        meshes.push(builders::random_flips(
            &builders::tetrahedron().mesh,
            6,
            seed,
        ));
    }
    let (mut accepted, mut refused) = (0, 0);
    for m in &meshes {
        for v in m.vertices() {
            let ours = check_pole(m, v).is_ok();
            assert_eq!(
                ours,
                oracle(m, v),
                "vertex {v:?} of a mesh with {} faces",
                m.n_faces()
            );
            if ours {
                accepted += 1;
            } else {
                refused += 1;
            }
        }
    }
    // Both verdicts occur (the control: a test that always accepts or refuses fails).
    assert!(
        accepted > 100 && refused > 10,
        "{accepted} accepted, {refused} refused"
    );
}

/// A capsule: a tube of `n` vertices around and `m` rings along, closed by one apex at
/// each end (a closed genus-0 surface whose graph is long and thin, like a limb).
fn capsule(n: u32, m: u32) -> penner::mesh::Mesh {
    let ring = |i: u32, j: u32| 1 + i * n + j % n;
    let (south, north) = (0, 1 + m * n);
    let mut faces = Vec::new();
    for j in 0..n {
        faces.push([south, ring(0, j + 1), ring(0, j)]);
        faces.push([north, ring(m - 1, j), ring(m - 1, j + 1)]);
        for i in 0..m - 1 {
            faces.push([ring(i, j), ring(i, j + 1), ring(i + 1, j + 1)]);
            faces.push([ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)]);
        }
    }
    penner::mesh::Mesh::from_faces(north + 1, &faces).unwrap()
}

/// B74's default pole order starts at a graph centre: on capsules, icospheres and flipped
/// spheres, the eccentricity of [`graph_centre`] is within one hop of the graph radius
/// found by brute force (a breadth-first search from every vertex), and it is the first of
/// [`pole_candidates`]. Control: the capsule's highest-degree vertex (an apex, the default
/// before) has eccentricity near the diameter, so the bound separates the two choices.
#[test]
fn b74_the_first_default_pole_is_a_graph_centre() {
    use penner::mesh::{builders, Mesh, Vertex};
    use penner::uniformization::pole::{graph_centre, hop_distances, pole_candidates};
    let ecc = |m: &Mesh, v: Vertex| *hop_distances(m, v).iter().max().unwrap();
    let mut meshes = vec![
        capsule(8, 30),
        capsule(5, 11),
        capsule(8, 2),
        icosphere(2).mesh(),
    ];
    for seed in 0..6 {
        meshes.push(builders::random_flips(&icosphere(1).mesh(), 60, seed));
    }
    for m in &meshes {
        let radius = m.vertices().map(|v| ecc(m, v)).min().unwrap();
        let c = graph_centre(m).unwrap();
        assert!(ecc(m, c) <= radius + 1, "{} vs radius {radius}", ecc(m, c));
        assert_eq!(pole_candidates(m)[0], c);
    }
    let m = capsule(8, 30);
    let apex = m.vertices().max_by_key(|&v| m.degree(v)).unwrap();
    let radius = m.vertices().map(|v| ecc(&m, v)).min().unwrap();
    assert!(ecc(&m, apex) > radius + 10, "control: {}", ecc(&m, apex));
}

/// A capsule of radius 1 and length `len` (8 vertices around, rings one unit apart, an
/// apex one unit beyond each end ring), positions rounded to binary64 and taken exactly.
fn long_capsule(rings: u32) -> penner::io::Surface {
    use penner::mesh::builders::Embedded;
    let m = capsule(8, rings);
    let q = |x: f64| Rational::from_f64(x).unwrap();
    let mut positions = vec![[q(0.0), q(0.0), q(-1.0)]];
    for i in 0..rings {
        for j in 0..8 {
            let a = std::f64::consts::TAU * (f64::from(j) + 0.5 * f64::from(i % 2)) / 8.0;
            positions.push([q(a.cos()), q(a.sin()), q(f64::from(i))]);
        }
    }
    positions.push([q(0.0), q(0.0), q(f64::from(rings))]);
    let e = Embedded {
        mesh: m,
        positions,
        exact: false,
    };
    penner::io::Surface::from_embedded("capsule", e).unwrap()
}

/// B74/B76 on a long capsule (length 96, radius 1): the conformal map to the sphere
/// crowds each half by about `e^{−48}` relative, below binary64's resolution even from the
/// central pole, so the planar layout cannot place every vertex. That is not a failure of
/// the solve: the disk problem is still certified for the exact metric, the outcome names
/// the layout as incomplete (`layout_failure`), and the result is not `certified()` (exit
/// 2). Control: a capsule of length 12 lays out completely and is certified.
#[test]
fn b76_a_layout_binary64_cannot_hold_keeps_the_certified_disk_problem() {
    use penner::uniformization::pipeline::{uniformize_sphere, Options};
    let long = uniformize_sphere(&long_capsule(96), None, &Options::default()).unwrap();
    assert!(
        matches!(long.certificate, Some(CertificateOutcome::Holds { .. })),
        "{:?}",
        long.certificate
    );
    let why = long
        .solution
        .layout_failure
        .as_deref()
        .expect("an incomplete layout");
    assert!(why.contains("no finite binary64 position"), "{why}");
    assert!(!long.certified());
    assert!(long.claim.is_some());
    let short = uniformize_sphere(&long_capsule(12), None, &Options::default()).unwrap();
    assert_eq!(short.solution.layout_failure, None);
    assert!(short.certified());
}
