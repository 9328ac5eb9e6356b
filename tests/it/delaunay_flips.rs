//! Flips and flipping to Delaunay (T21–T23, T27–T29) at f64, Dd, MPFR and exact, each
//! with a negative control; results re-checked with the malachite oracle.

use crate::delaunay::{exact_values, exactly_strict_face, oracle_non_delaunay, to_m};
use crate::meshgen::{icosphere, planar_grid, random_tetrahedron, sheared_torus, Embedded};
use crate::support::case_seeds;
use malachite::rational::Rational as MRational;
use penner::algorithms::flip_to_delaunay::{
    flip_to_delaunay, flip_to_delaunay_exact, ExactLengths, FlipKind, FlipOptions,
    FlipToDelaunayError,
};
use penner::algorithms::flips::{
    euclidean_length, flip_euclidean, flip_ptolemy, flip_ptolemy_exact,
};
use penner::algorithms::naive::flip_to_delaunay_naive;
use penner::mesh::{FlipError, Mesh};
use penner::predicates::delaunay::{edge_delaunay_sign, DelaunayError, EdgeDelaunay, QuadEdges};
use penner::predicates::ladder::Ladder;
use penner::scalar::{Dd, Mpfr, Precision, Real, Sign};
use penner::theorems::t21_delaunay_flipping::{check_all_edges_delaunay, check_delaunay_flipping};
use penner::theorems::t22_delaunay_uniqueness::{
    check_delaunay_uniqueness, check_planar_delaunay_matches_spade, planar_edge_mismatches,
};
use penner::theorems::t23_euclidean_flip_cone_metric::check_euclidean_flips_preserve_cone_metric;
use penner::theorems::t27_shear_log_cross_ratio::check_shear_log_cross_ratio;
use penner::theorems::t28_ptolemy_flip::{check_ptolemy_flip, cluster_rule_violations};
use penner::theorems::t29_euclidean_ptolemy_cocircular::check_euclidean_equals_ptolemy_iff_cocircular;
use penner::theorems::{Settings, Verdict};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

/// One-vertex torus with the lengths of a random flat parallelogram lattice.
fn one_vertex_torus(seed: u64) -> (Mesh, Vec<f64>) {
    let m = Mesh::from_gluing(
        1,
        &[[0, 0, 0], [0, 0, 0]],
        &[((0, 0), (1, 0)), ((0, 1), (1, 1)), ((0, 2), (1, 2))],
    )
    .unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    // Vectors a, b, a+b of a skewed lattice: lengths of a triangle.
    let a = [1.0, 0.0];
    let b = [rng.gen_range(2.0..6.0), rng.gen_range(0.05..0.5)];
    let n = |v: [f64; 2]| v[0].hypot(v[1]);
    let l = vec![n(a), n(b), n([a[0] + b[0], a[1] + b[1]])];
    (m, l)
}

/// Test surfaces: planar disk, jittered sphere, sheared torus, tetrahedron, one-vertex torus.
fn surfaces(seed: u64) -> Vec<(String, Mesh, Vec<f64>)> {
    let mut out = Vec::new();
    let mut add = |name: &str, e: Embedded| {
        let m = e.mesh();
        let l = e.lengths(&m);
        out.push((name.to_string(), m, l));
    };
    add("grid", planar_grid(6, 0.3, seed));
    let mut s = icosphere(3);
    let j = 0.7 * s.mean_edge();
    s.jitter(j, seed);
    add("icosphere", s);
    add("torus", sheared_torus(12, 6, 3));
    add("tetrahedron", random_tetrahedron(seed));
    let (m, l) = one_vertex_torus(seed);
    out.push(("one-vertex torus".into(), m, l));
    out
}

fn settings() -> Settings {
    Settings::default()
}

#[test]
fn t21_flipping_terminates_and_certifies_every_edge_f64() {
    for seed in case_seeds(3, 40) {
        for (name, m, l) in surfaces(seed) {
            for kind in [FlipKind::Euclidean, FlipKind::Ptolemy] {
                let (mut m2, mut l2) = (m.clone(), l.clone());
                let r = flip_to_delaunay(&mut m2, &mut l2, kind, &FlipOptions::default()).unwrap();
                assert!(r.all_certified_delaunay(), "{name} {kind:?}: {r:?}");
                let exact: Vec<MRational> = l2
                    .iter()
                    .map(|&x| MRational::try_from(x).unwrap())
                    .collect();
                assert_eq!(oracle_non_delaunay(&m2, &exact), vec![], "{name} {kind:?}");
                assert!(check_delaunay_flipping(&m, &l, kind, &settings()).holds());
                assert_eq!(m2.euler_characteristic(), m.euler_characteristic());
            }
        }
    }
}

#[test]
fn t21_negative_control_inputs_are_not_delaunay_before_flipping() {
    let mut failing = 0;
    for (name, m, l) in surfaces(1) {
        let v = check_all_edges_delaunay(&m, &l, &settings(), false, 0);
        let exact: Vec<MRational> = l.iter().map(|&x| MRational::try_from(x).unwrap()).collect();
        let bad = oracle_non_delaunay(&m, &exact);
        match &v {
            Verdict::Fails { witnesses, .. } => {
                failing += 1;
                assert_eq!(witnesses.len(), bad.len(), "{name}");
            }
            _ => assert!(bad.is_empty(), "{name}"),
        }
    }
    assert!(failing >= 3, "the check must reject the unflipped inputs");
}

#[test]
fn t21_flipping_at_dd_and_mpfr() {
    let p = Precision::new(128).unwrap();
    for (name, m, l) in surfaces(2) {
        let dd: Vec<Dd> = l.iter().map(|&x| <Dd as Real>::from_f64(x, ())).collect();
        let mp: Vec<Mpfr> = l.iter().map(|&x| Mpfr::from_f64(x, p)).collect();
        for kind in [FlipKind::Euclidean, FlipKind::Ptolemy] {
            let (mut m2, mut l2) = (m.clone(), dd.clone());
            let r = flip_to_delaunay(&mut m2, &mut l2, kind, &FlipOptions::default()).unwrap();
            assert!(r.all_certified_delaunay(), "{name} dd {kind:?} {r:?}");
            let ex = exact_values(&l2);
            assert_eq!(oracle_non_delaunay(&m2, &ex), vec![]);
            let (mut m3, mut l3) = (m.clone(), mp.clone());
            let r = flip_to_delaunay(&mut m3, &mut l3, kind, &FlipOptions::default()).unwrap();
            assert!(r.all_certified_delaunay(), "{name} mpfr {kind:?} {r:?}");
            let ex = exact_values(&l3);
            assert_eq!(oracle_non_delaunay(&m3, &ex), vec![]);
            // Negative control: the unflipped MPFR lengths are not Delaunay for the oracle
            // on the grid, sphere and torus.
            if name != "tetrahedron" && name != "one-vertex torus" {
                let ex = exact_values(&mp);
                assert!(!oracle_non_delaunay(&m, &ex).is_empty(), "{name}");
            }
        }
    }
}

#[test]
fn t21_exact_ptolemy_flipping_reports_bit_growth_and_falls_back() {
    for (name, m, l) in surfaces(3) {
        let q: Vec<Rational> = l.iter().map(|&x| Rational::from_f64(x).unwrap()).collect();
        let mut m2 = m.clone();
        let (r, out) =
            flip_to_delaunay_exact(&mut m2, q.clone(), 1 << 20, &FlipOptions::default()).unwrap();
        assert!(r.all_certified_delaunay(), "{name}");
        assert!(r.fell_back_after.is_none());
        let ExactLengths::Exact(ex) = out else {
            panic!("no fallback expected")
        };
        let mx: Vec<MRational> = ex.iter().map(to_m).collect();
        assert_eq!(oracle_non_delaunay(&m2, &mx), vec![], "{name}");
        assert!(r.max_bits >= 2, "{name}: growth reported {}", r.max_bits);
        if r.flips > 3 {
            // A guard below the observed growth forces the enclosure fallback.
            let guard = r.max_bits - 1;
            let mut m3 = m.clone();
            let (r3, out3) =
                flip_to_delaunay_exact(&mut m3, q, guard, &FlipOptions::default()).unwrap();
            assert!(r3.fell_back_after.is_some(), "{name}");
            assert!(matches!(out3, ExactLengths::Enclosed(_)));
            assert!(!r3.hit_cap);
        }
    }
}

#[test]
fn flips_refuse_boundary_and_self_folded_edges() {
    let mut disk = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
    let mut l = vec![1.0; disk.n_edges()];
    let b = disk.edges().find(|&e| disk.is_boundary_edge(e)).unwrap();
    assert_eq!(
        flip_euclidean(&mut disk, &mut l, b),
        Err(FlipError::Boundary(b))
    );
    assert_eq!(
        flip_ptolemy(&mut disk, &mut l, b),
        Err(FlipError::Boundary(b))
    );
    // A sphere of two self-folded triangles glued along their loops.
    let mut m = Mesh::from_gluing(
        3,
        &[[0, 1, 0], [0, 0, 2]],
        &[((0, 0), (0, 1)), ((1, 1), (1, 2)), ((0, 2), (1, 0))],
    )
    .unwrap();
    assert_eq!(m.euler_characteristic(), 2);
    let mut l = vec![1.0, 1.0, 1.5];
    let mut lq: Vec<Rational> = vec![1.into(), 1.into(), Rational::from((3, 2))];
    for e in m.edges() {
        if QuadEdges::of(&m, e).is_none() && !m.is_boundary_edge(e) {
            assert_eq!(
                flip_euclidean(&mut m, &mut l, e),
                Err(FlipError::SameFace(e))
            );
            assert_eq!(
                flip_ptolemy_exact(&mut m, &mut lq, e),
                Err(FlipError::SameFace(e))
            );
            assert_eq!(
                edge_delaunay_sign(&m, &l, e, &Ladder::default()),
                Ok(EdgeDelaunay::SameFace)
            );
        }
    }
    let r = flip_to_delaunay(&mut m, &mut l, FlipKind::Euclidean, &FlipOptions::default()).unwrap();
    assert!(r.all_certified_delaunay());
}

#[test]
fn t22_planar_flipping_matches_spade() {
    for seed in case_seeds(4, 50) {
        for (n, squash) in [(8u32, 1.0), (6, 1e-6)] {
            let e = planar_grid(n, 0.35, seed);
            let pts: Vec<[f64; 2]> = e.pos.iter().map(|p| [p[0], p[1] * squash]).collect();
            let v = check_planar_delaunay_matches_spade(&pts, &e.faces, &settings());
            assert!(v.holds(), "seed {seed} squash {squash}: {v:?}");
            // Negative control: the unflipped triangulation disagrees with spade.
            let m = e.mesh();
            let l: Vec<f64> = m
                .edges()
                .map(|x| {
                    let h = x.halfedge();
                    let (a, b) = (pts[m.tail(h).idx()], pts[m.tip(h).idx()]);
                    (a[0] - b[0]).hypot(a[1] - b[1])
                })
                .collect();
            assert!(!planar_edge_mismatches(&pts, &m, &l, &settings())
                .unwrap()
                .is_empty());
        }
    }
}

#[test]
fn t22_flip_orders_agree_on_surfaces() {
    for (name, m, l) in surfaces(5) {
        for kind in [FlipKind::Euclidean, FlipKind::Ptolemy] {
            let v = check_delaunay_uniqueness(&m, &l, kind, &[1, 2, 3], &settings());
            assert!(v.holds(), "{name} {kind:?}: {v:?}");
        }
    }
}

#[test]
fn t22_ties_d_zero_both_diagonals_pass() {
    // A 3×4 rectangle grid with diagonals 5 (exact integers): every diagonal is a tie.
    let e = planar_grid(4, 0.0, 9);
    let m = e.mesh();
    let sx = 3.0;
    let sy = 4.0;
    let l: Vec<f64> = m
        .edges()
        .map(|x| {
            let h = x.halfedge();
            let (a, b) = (e.pos[m.tail(h).idx()], e.pos[m.tip(h).idx()]);
            let (dx, dy) = (
                (a[0] - b[0]).abs() * 4.0 * sx,
                (a[1] - b[1]).abs() * 4.0 * sy,
            );
            if dx > 0.0 && dy > 0.0 {
                5.0
            } else {
                dx + dy
            }
        })
        .collect();
    let mut ties = 0;
    for ed in m.edges() {
        if let Ok(EdgeDelaunay::Interior(c)) = edge_delaunay_sign(&m, &l, ed, &Ladder::default()) {
            ties += usize::from(c.value() == Some(Sign::Zero));
        }
    }
    assert_eq!(ties, 16, "every diagonal of the 4×4 grid is cocircular");
    let v = check_delaunay_uniqueness(&m, &l, FlipKind::Euclidean, &[1, 2], &settings());
    assert!(v.holds(), "{v:?}");
    // Negative control: a generic perturbation of one diagonal breaks its tie.
    let mut l2 = l.clone();
    let d = m.edges().find(|&x| l[x.idx()] == 5.0).unwrap();
    l2[d.idx()] = 5.0 * (1.0 + 1e-15);
    assert_eq!(
        edge_delaunay_sign(&m, &l2, d, &Ladder::default())
            .unwrap()
            .is_delaunay(),
        Some(false)
    );
}

#[test]
fn t23_euclidean_flips_preserve_cone_angles() {
    for (name, m, l) in surfaces(6) {
        let v = check_euclidean_flips_preserve_cone_metric(
            &m,
            &l,
            FlipKind::Euclidean,
            200,
            &settings(),
        );
        assert!(v.holds(), "{name}: {v:?}");
    }
    // Negative control: replaying the same flips with the Ptolemy update changes cone
    // angles (the quadrilaterals are not cocircular).
    let (_, m, l) = surfaces(6).swap_remove(1);
    let v = check_euclidean_flips_preserve_cone_metric(&m, &l, FlipKind::Ptolemy, 200, &settings());
    assert!(v.fails(), "{v:?}");
}

#[test]
fn t27_shear_is_log_cross_ratio() {
    let p = Precision::new(160).unwrap();
    for (name, m, l) in surfaces(7) {
        let mp: Vec<Mpfr> = l.iter().map(|&x| Mpfr::from_f64(x, p)).collect();
        let v = check_shear_log_cross_ratio(&m, &mp, &settings());
        assert!(v.holds(), "{name}: {v:?}");
    }
    // Negative control: with no allowance for rounding (slack 0) the check rejects.
    let (_, m, l) = surfaces(7).swap_remove(1);
    let mp: Vec<Mpfr> = l.iter().map(|&x| Mpfr::from_f64(x, p)).collect();
    let strict = Settings {
        slack: 0.0,
        ..Settings::default()
    };
    assert!(check_shear_log_cross_ratio(&m, &mp, &strict).fails());
}

#[test]
fn t28_ptolemy_flip_exact_identities() {
    let mut rng = ChaCha8Rng::seed_from_u64(28);
    for (name, m, _) in surfaces(8) {
        // Arbitrary positive rational lengths: Ptolemy identities need no triangle inequality.
        let l: Vec<Rational> = m
            .edges()
            .map(|_| Rational::from((rng.gen_range(1..50), rng.gen_range(1..50))))
            .collect();
        let s: Vec<Rational> = m
            .vertices()
            .map(|_| Rational::from((rng.gen_range(1..9), rng.gen_range(1..9))))
            .collect();
        let v = check_ptolemy_flip(&m, &l, &s);
        assert!(v.holds(), "{name}: {v:?}");
    }
    // Negative control: perturb one side after the flip: the cluster rule detects it.
    let (_, m, _) = surfaces(8).swap_remove(1);
    let l: Vec<Rational> = m.edges().map(|e| Rational::from(e.0 % 7 + 3)).collect();
    let e = m.edges().find(|&e| QuadEdges::of(&m, e).is_some()).unwrap();
    let q = QuadEdges::of(&m, e).unwrap();
    let (mut m1, mut l1) = (m.clone(), l.clone());
    flip_ptolemy_exact(&mut m1, &mut l1, e).unwrap();
    assert!(cluster_rule_violations(&m, &l, &m1, &l1, e).is_empty());
    l1[q.edges.jk.idx()] += Rational::from((1, 1000));
    assert!(!cluster_rule_violations(&m, &l, &m1, &l1, e).is_empty());
}

#[test]
fn t28_negative_control_euclidean_flip_does_not_commute_with_scaling() {
    let p = Precision::new(256).unwrap();
    let (_, m, l) = surfaces(9).swap_remove(1);
    let e = m.edges().find(|&e| QuadEdges::of(&m, e).is_some()).unwrap();
    let q = QuadEdges::of(&m, e).unwrap();
    let mp: Vec<Mpfr> = l.iter().map(|&x| Mpfr::from_f64(x, p)).collect();
    let s: Vec<Mpfr> = m
        .vertices()
        .map(|v| Mpfr::from_f64(1.0 + f64::from(v.0 % 3) * 0.5, p))
        .collect();
    let scaled: Vec<Mpfr> = m
        .edges()
        .map(|x| {
            let h = x.halfedge();
            s[m.tail(h).idx()].clone() * &s[m.tip(h).idx()] * &mp[x.idx()]
        })
        .collect();
    let [_, _, k, lv] = m.quad_vertices(e);
    let flip_then_scale = euclidean_length(q.lengths(&mp)) * &s[k.idx()] * &s[lv.idx()];
    let scale_then_flip = euclidean_length(q.lengths(&scaled));
    let rel = ((flip_then_scale.clone() - &scale_then_flip) / &scale_then_flip)
        .abs()
        .approx_f64();
    assert!(rel > 1e-6, "relative difference {rel}");
}

#[test]
fn t29_euclidean_equals_ptolemy_iff_cocircular() {
    for (name, m, l) in surfaces(10) {
        let v = check_euclidean_equals_ptolemy_iff_cocircular(&m, &l, &settings());
        assert!(v.holds(), "{name}: {v:?}");
    }
    // Cocircular: the 3-4-5 rectangle: both flips give 5, and D = 0.
    let m = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
    let l: Vec<f64> = m
        .edges()
        .map(|e| {
            let h = e.halfedge();
            match (m.tail(h).0.min(m.tip(h).0), m.tail(h).0.max(m.tip(h).0)) {
                (0, 2) => 5.0,
                (0, 1) | (2, 3) => 4.0,
                _ => 3.0,
            }
        })
        .collect();
    assert!(check_euclidean_equals_ptolemy_iff_cocircular(&m, &l, &settings()).holds());
    // Negative control: the check would fail if the lengths were equal off the circle:
    // stretch the diagonal and the two new lengths separate.
    let d = m.edges().find(|&e| !m.is_boundary_edge(e)).unwrap();
    let q = QuadEdges::of(&m, d).unwrap();
    let mut l2 = l.clone();
    l2[d.idx()] = 5.5;
    let eu = euclidean_length(q.lengths(&l2));
    let pt = penner::algorithms::flips::ptolemy_length(q.lengths(&l2));
    assert!(pt - eu > 1e-3, "Ptolemy {pt} vs Euclidean {eu}");
}

#[test]
fn naive_f64_flipping_leaves_non_delaunay_edges() {
    // A square grid with √2 diagonals is cocircular; tiny perturbations make the signs
    // depend on the last bits. Naive flipping decides with the raw f64 value of P.
    let mut bad_total = 0;
    let mut certified_bad = 0;
    for seed in 0..20u64 {
        let e = planar_grid(12, 0.0, seed);
        let m = e.mesh();
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let l0: Vec<f64> = e
            .lengths(&m)
            .iter()
            .map(|&x| x * (1.0 + rng.gen_range(-1.0..1.0) * 1e-16))
            .collect();
        let (mut mn, mut ln) = (m.clone(), l0.clone());
        let nr = flip_to_delaunay_naive(&mut mn, &mut ln, FlipKind::Ptolemy, 1_000_000);
        assert!(!nr.hit_cap);
        let ex: Vec<MRational> = ln
            .iter()
            .map(|&x| MRational::try_from(x).unwrap())
            .collect();
        bad_total += oracle_non_delaunay(&mn, &ex).len();
        let (mut mc, mut lc) = (m.clone(), l0.clone());
        let r =
            flip_to_delaunay(&mut mc, &mut lc, FlipKind::Ptolemy, &FlipOptions::default()).unwrap();
        assert!(r.all_certified_delaunay());
        let ex: Vec<MRational> = lc
            .iter()
            .map(|&x| MRational::try_from(x).unwrap())
            .collect();
        certified_bad += oracle_non_delaunay(&mc, &ex).len();
    }
    assert_eq!(certified_bad, 0);
    assert!(
        bad_total > 0,
        "naive f64 flipping left no non-Delaunay edge on these inputs"
    );
}

#[test]
fn adversarial_fans_grids_and_slivers_terminate_certified() {
    let p = Precision::new(200).unwrap();
    // Regular n-gon fans from one corner (all vertices cocircular), at 200 bits.
    for n in [5u32, 6, 8, 12, 17] {
        let faces: Vec<[u32; 3]> = (1..n - 1).map(|i| [0, i, i + 1]).collect();
        let m = Mesh::from_faces(n, &faces).unwrap();
        let l: Vec<Mpfr> = m
            .edges()
            .map(|e| {
                let h = e.halfedge();
                let k = (i64::from(m.tail(h).0) - i64::from(m.tip(h).0)).unsigned_abs() as f64;
                let x = Mpfr::from_f64(k, p) * &Mpfr::pi(p) / &Mpfr::from_f64(f64::from(n), p);
                x.sin() * &Mpfr::from_f64(2.0, p)
            })
            .collect();
        for kind in [FlipKind::Euclidean, FlipKind::Ptolemy] {
            let (mut m2, mut l2) = (m.clone(), l.clone());
            let r = flip_to_delaunay(&mut m2, &mut l2, kind, &FlipOptions::default()).unwrap();
            assert!(r.all_certified_delaunay(), "{n}-gon {kind:?}: {r:?}");
            let ex = exact_values(&l2);
            assert_eq!(oracle_non_delaunay(&m2, &ex), vec![]);
        }
    }
    // Sliver meshes: grids squashed to aspect ratio 1e-8 and 1e-6 (marching-cubes-like
    // needles). Rounded f64 lengths of such slivers can violate the triangle inequality;
    // Euclidean flipping then refuses the metric, naming a face that exact arithmetic
    // confirms is not a strict triangle (no Euclidean flip exists there).
    let p128 = Precision::new(128).unwrap();
    let (mut euclidean_runs, mut refused_metrics) = (0, 0);
    for seed in 0..4u64 {
        for squash in [1e-8, 1e-6] {
            let mut e = planar_grid(10, 0.45, seed);
            for q in &mut e.pos {
                q[1] *= squash;
            }
            let m = e.mesh();
            let l = e.lengths(&m);
            let exact_in: Vec<MRational> =
                l.iter().map(|&x| MRational::try_from(x).unwrap()).collect();
            for kind in [FlipKind::Euclidean, FlipKind::Ptolemy] {
                let (mut m2, mut l2) = (m.clone(), l.clone());
                let r = match flip_to_delaunay(&mut m2, &mut l2, kind, &FlipOptions::default()) {
                    Ok(r) => r,
                    Err(FlipToDelaunayError::Lengths(DelaunayError::NotATriangle { face })) => {
                        assert_eq!(kind, FlipKind::Euclidean);
                        assert!(!exactly_strict_face(&m, &exact_in, face), "{face}");
                        refused_metrics += 1;
                        continue;
                    }
                    Err(err) => panic!("{err}"),
                };
                euclidean_runs += usize::from(kind == FlipKind::Euclidean);
                assert!(!r.hit_cap && r.undecided.is_empty());
                // At f64 a Euclidean flip of a sliver may have no f64 result whose new edge
                // is Delaunay: such edges are refused and reported — exactly the oracle's
                // non-Delaunay edges, no more and no fewer.
                let ex: Vec<MRational> = l2
                    .iter()
                    .map(|&x| MRational::try_from(x).unwrap())
                    .collect();
                assert_eq!(
                    oracle_non_delaunay(&m2, &ex),
                    r.refused,
                    "sliver {seed} {kind:?}"
                );
                if kind == FlipKind::Ptolemy {
                    assert!(r.refused.is_empty());
                }
                // At 128 bits: the same honesty.
                let mp: Vec<Mpfr> = l.iter().map(|&x| Mpfr::from_f64(x, p128)).collect();
                let (mut m3, mut l3) = (m.clone(), mp);
                let r = flip_to_delaunay(&mut m3, &mut l3, kind, &FlipOptions::default()).unwrap();
                assert!(!r.hit_cap && r.undecided.is_empty());
                let ex = exact_values(&l3);
                assert_eq!(
                    oracle_non_delaunay(&m3, &ex),
                    r.refused,
                    "sliver {seed} {kind:?} 128"
                );
            }
        }
    }
    assert!(
        euclidean_runs > 0 && refused_metrics > 0,
        "{euclidean_runs} {refused_metrics}"
    );
    // Lengths scaled to 1e-150 and 1e150: the same flips as unscaled (power-of-two scale).
    let (_, m, l) = surfaces(11).swap_remove(1);
    let (mut m0, mut l0) = (m.clone(), l.clone());
    let r0 =
        flip_to_delaunay(&mut m0, &mut l0, FlipKind::Ptolemy, &FlipOptions::default()).unwrap();
    for k in [-498, 498] {
        let s = 2f64.powi(k);
        let (mut m2, mut l2) = (m.clone(), l.iter().map(|x| x * s).collect::<Vec<_>>());
        let r =
            flip_to_delaunay(&mut m2, &mut l2, FlipKind::Ptolemy, &FlipOptions::default()).unwrap();
        assert!(r.all_certified_delaunay());
        assert_eq!(r.flips, r0.flips, "scale 2^{k}");
        assert_eq!(m2, m0);
    }
}
