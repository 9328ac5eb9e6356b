//! T28 (Ptolemy flip identities) and T23 (Euclidean flips keep the cone metric) on
//! Δ-complexes — loops, multi-edges, self-folded triangles, quadrilaterals whose sides play
//! several roles — each identity with a negative control that the same comparison rejects.
//! T28's cross ratios are recomputed by an independent oracle in malachite (a face-by-face
//! product, not the crate's edge-by-edge one).

use crate::delaunay::to_m;
use crate::support::case_seeds;
use malachite::rational::Rational as MRational;
use penner::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use penner::algorithms::flips::{flip_euclidean, flip_ptolemy_exact};
use penner::mesh::{builders, Edge, Face, Mesh};
use penner::predicates::delaunay::{Quad, QuadEdges};
use penner::predicates::directed::enclose_f64;
use penner::scalar::{Interval, Mpfr, Precision};
use penner::theorems::t23_euclidean_flip_cone_metric::{
    check_euclidean_flips_preserve_cone_metric, cone_angle_enclosures, flip_hypotheses_certified,
    verify_flip_sequence,
};
use penner::theorems::t28_ptolemy_flip::{
    check_ptolemy_flip, cluster_rule_prediction, cluster_rule_violations, cross_ratios,
    verify_cluster_rule, verify_involution, verify_scaling_commutes, verify_vertex_products,
    vertex_product_violations,
};
use penner::theorems::{Settings, Verdict};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;
use std::collections::BTreeSet;

/// Whether `v` is `Verdict::Fails { certified: true, .. }`.
fn certified_fails(v: &Verdict) -> bool {
    matches!(
        v,
        Verdict::Fails {
            certified: true,
            ..
        }
    )
}

/// Whether `v` is `Verdict::Holds { certified: true, .. }`.
fn certified_holds(v: &Verdict) -> bool {
    matches!(
        v,
        Verdict::Holds {
            certified: true,
            ..
        }
    )
}

/// Whether `v` is `Verdict::Holds { certified: false, .. }`.
fn numerical_holds(v: &Verdict) -> bool {
    matches!(
        v,
        Verdict::Holds {
            certified: false,
            ..
        }
    )
}

/// The perturbation of the negative controls: a factor 101/100.
fn bump() -> Rational {
    Rational::from((101, 100))
}

/// Small Δ-complexes, named: the one-vertex torus, the two-triangle sphere and that sphere
/// with one edge flipped (two self-folded triangles), genus 2 with one vertex, the flat
/// tori 2×1 and 3×1 (multi-edges), a one-vertex torus with a vertex inserted, an annulus
/// (boundary), and seeded random Δ-complexes of genus 0–2 (random flips of a split sphere
/// or polygon, [`builders::random_surface`]).
fn delta_complexes(seed: u64) -> Vec<(String, Mesh)> {
    let mut folded = builders::two_triangle_sphere();
    folded.flip(Edge(0)).unwrap();
    let mut split = builders::one_vertex_torus();
    split.split_face(Face(0)).unwrap();
    let mut out = vec![
        ("one-vertex torus".to_string(), builders::one_vertex_torus()),
        (
            "two-triangle sphere".into(),
            builders::two_triangle_sphere(),
        ),
        ("self-folded sphere".into(), folded),
        ("genus 2, one vertex".into(), builders::genus(2).unwrap()),
        (
            "flat torus 2x1".into(),
            builders::flat_torus(2, 1).unwrap().mesh,
        ),
        (
            "flat torus 3x1".into(),
            builders::flat_torus(3, 1).unwrap().mesh,
        ),
        ("split one-vertex torus".into(), split),
        ("annulus 3x1".into(), builders::annulus(3, 1).unwrap().mesh),
    ];
    for (g, n) in [(0, 3), (0, 4), (0, 5), (1, 2), (1, 3), (2, 2)] {
        out.push((
            format!("random genus {g}, {n} vertices, seed {seed}"),
            builders::random_surface(g, n, seed).unwrap(),
        ));
    }
    out
}

/// Positive rational lengths `p/q`, `1 ≤ p, q < 50` (Ptolemy identities need no triangle
/// inequality).
fn rational_lengths(m: &Mesh, rng: &mut ChaCha8Rng) -> Vec<Rational> {
    m.edges()
        .map(|_| Rational::from((rng.gen_range(1..50), rng.gen_range(1..50))))
        .collect()
}

/// The oracle: every edge's cross ratio as the product, over the faces, of
/// `ℓ(next h)/ℓ(prev h)` for each of the face's half-edges `h`, in malachite; `None` unless
/// both sides of the edge lie in faces.
fn oracle_cross_ratios(m: &Mesh, l: &[MRational]) -> Vec<Option<MRational>> {
    let mut acc = vec![MRational::from(1u32); m.n_edges()];
    let mut sides = vec![0u8; m.n_edges()];
    for f in m.faces() {
        let hs = m.face_halfedges(f);
        for p in 0..3 {
            let e = hs[p].edge().idx();
            let num = &l[hs[(p + 1) % 3].edge().idx()];
            let den = &l[hs[(p + 2) % 3].edge().idx()];
            acc[e] = &acc[e] * num / den;
            sides[e] += 1;
        }
    }
    acc.into_iter()
        .zip(sides)
        .map(|(x, n)| (n == 2).then_some(x))
        .collect()
}

fn to_m_all(v: &[Option<Rational>]) -> Vec<Option<MRational>> {
    v.iter().map(|x| x.as_ref().map(to_m)).collect()
}

/// The four side roles of the quadrilateral of `q` with their cluster factors.
fn roles(q: &QuadEdges, c: &Rational) -> [(Edge, Rational); 4] {
    let up = Rational::from(c + 1u32);
    let down = Rational::from(c / &up);
    let s = q.edges;
    [
        (s.jk, up.clone()),
        (s.il, up),
        (s.ki, down.clone()),
        (s.lj, down),
    ]
}

/// Whether `m` is a sphere of two faces (the two-triangle sphere or its flip, two
/// self-folded triangles).
fn two_face_sphere(m: &Mesh) -> bool {
    m.n_faces() == 2 && m.euler_characteristic() == 2
}

/// Whether some side of the quadrilateral of `q` is one edge in two roles.
fn has_repeated_side(q: &QuadEdges) -> bool {
    let s = q.edges;
    let v = [s.jk, s.ki, s.il, s.lj];
    v.iter().collect::<BTreeSet<_>>().len() < v.len()
}

#[test]
fn t28_cluster_rule_with_multiplicity_on_delta_complexes() {
    let (mut flips, mut repeated, mut once_rejected, mut length_rejected) = (0, 0, 0, 0);
    for seed in case_seeds(3, 30) {
        let mut rng = ChaCha8Rng::seed_from_u64(2828 + seed);
        for (name, m) in delta_complexes(seed) {
            let l = rational_lengths(&m, &mut rng);
            // The crate's cross ratios agree with the face-by-face oracle.
            assert_eq!(
                to_m_all(&cross_ratios(&m, &l)),
                oracle_cross_ratios(&m, &l.iter().map(to_m).collect::<Vec<_>>()),
                "{name}"
            );
            for e in m.edges() {
                let Some(q) = QuadEdges::of(&m, e) else {
                    continue;
                };
                flips += 1;
                let (mut m1, mut l1) = (m.clone(), l.clone());
                flip_ptolemy_exact(&mut m1, &mut l1, e).unwrap();
                // Independent Ptolemy length in malachite from the roles of the quadrilateral.
                let r = q.lengths(&l).map(to_m);
                assert_eq!(
                    to_m(&l1[e.idx()]),
                    (&r.ki * &r.lj + &r.il * &r.jk) / &r.ij,
                    "{name} {e}"
                );
                let lm: Vec<MRational> = l1.iter().map(to_m).collect();
                let predicted = cluster_rule_prediction(&m, &l, e).unwrap();
                // The rule with multiplicity equals the cross ratios recomputed after the flip
                // by the oracle, on every edge (not only the five of the quadrilateral).
                assert_eq!(
                    to_m_all(&predicted),
                    oracle_cross_ratios(&m1, &lm),
                    "{name} {e}"
                );
                assert!(
                    verify_cluster_rule(&m1, &l1, e, &predicted).is_empty(),
                    "{name} {e}"
                );
                assert!(cluster_rule_violations(&m, &l, &m1, &l1, e).is_empty());
                // Negative control 1: the rule applied once per distinct side (the first
                // role's factor only) instead of once per role.
                if has_repeated_side(&q) {
                    repeated += 1;
                    let cb = cross_ratios(&m, &l);
                    let c = cb[e.idx()].clone().unwrap();
                    let mut wrong = cb.clone();
                    let mut seen = BTreeSet::new();
                    for (side, f) in roles(&q, &c) {
                        if seen.insert(side) {
                            if let Some(x) = wrong[side.idx()].as_mut() {
                                *x *= f;
                            }
                        }
                    }
                    wrong[e.idx()] = Some(c.recip());
                    let w = verify_cluster_rule(&m1, &l1, e, &wrong);
                    assert!(!w.is_empty(), "{name} {e}: the once-per-side rule passed");
                    once_rejected += 1;
                }
                // Negative control 2: one length after the flip × 101/100, for the first edge
                // whose perturbation moves some cross ratio by the oracle.
                let moved = m1.edges().find_map(|f| {
                    let mut lp = l1.clone();
                    lp[f.idx()] *= bump();
                    let pm: Vec<MRational> = lp.iter().map(to_m).collect();
                    (oracle_cross_ratios(&m1, &pm) != oracle_cross_ratios(&m1, &lm)).then_some(lp)
                });
                if let Some(lp) = moved {
                    assert!(!verify_cluster_rule(&m1, &lp, e, &predicted).is_empty());
                    assert!(!cluster_rule_violations(&m, &l, &m1, &lp, e).is_empty());
                    length_rejected += 1;
                } else {
                    // Only on a sphere of two faces, where every cross ratio is 1 whatever the
                    // lengths (the two triangles glued, or two self-folded triangles).
                    assert!(
                        two_face_sphere(&m),
                        "{name} {e}: no length moves a cross ratio"
                    );
                }
            }
        }
    }
    assert!(
        flips > 100 && repeated > 20,
        "{flips} flips, {repeated} with a repeated side"
    );
    assert_eq!(once_rejected, repeated);
    assert!(length_rejected > flips / 2, "{length_rejected} of {flips}");
}

#[test]
fn t28_check_holds_on_delta_complexes() {
    for seed in case_seeds(2, 20) {
        let mut rng = ChaCha8Rng::seed_from_u64(28 + seed);
        for (name, m) in delta_complexes(seed) {
            let l = rational_lengths(&m, &mut rng);
            let s: Vec<Rational> = m
                .vertices()
                .map(|_| Rational::from((rng.gen_range(1..9), rng.gen_range(1..9))))
                .collect();
            let v = check_ptolemy_flip(&m, &l, &s);
            assert_eq!(
                v,
                Verdict::Holds {
                    certified: true,
                    max_error: 0.0
                },
                "{name}"
            );
        }
    }
}

#[test]
fn t28_involution_rejects_a_wrong_length_between_the_flips() {
    let mut rng = ChaCha8Rng::seed_from_u64(281);
    let mut controls = 0;
    for (name, m) in delta_complexes(1) {
        let l = rational_lengths(&m, &mut rng);
        for e in m.edges().filter(|&e| QuadEdges::of(&m, e).is_some()) {
            let (mut m1, mut l1) = (m.clone(), l.clone());
            flip_ptolemy_exact(&mut m1, &mut l1, e).unwrap();
            let (mut m2, mut l2) = (m1.clone(), l1.clone());
            flip_ptolemy_exact(&mut m2, &mut l2, e).unwrap();
            assert!(
                verify_involution(&m, &l, e, &m2, &l2).is_empty(),
                "{name} {e}"
            );
            // Control: the new diagonal × 101/100 before flipping back; the second Ptolemy
            // length is then ℓ_ij · 100/101.
            l1[e.idx()] *= bump();
            flip_ptolemy_exact(&mut m1, &mut l1, e).unwrap();
            let w = verify_involution(&m, &l, e, &m1, &l1);
            assert!(
                w.iter().any(|x| x.element == e.to_string()),
                "{name} {e}: {w:?}"
            );
            controls += 1;
        }
    }
    assert!(controls > 30, "{controls}");
}

#[test]
fn t28_scaling_by_other_factors_does_not_commute() {
    let mut rng = ChaCha8Rng::seed_from_u64(282);
    let mut controls = 0;
    for (name, m) in delta_complexes(2) {
        let l = rational_lengths(&m, &mut rng);
        let s: Vec<Rational> = m
            .vertices()
            .map(|_| Rational::from((rng.gen_range(1..9), rng.gen_range(1..9))))
            .collect();
        // Control: flip then scale with s_0 doubled.
        let mut t = s.clone();
        t[0] *= 2u32;
        for e in m.edges().filter(|&e| QuadEdges::of(&m, e).is_some()) {
            assert!(
                verify_scaling_commutes(&m, &l, e, &s, &s).is_empty(),
                "{name} {e}"
            );
            assert!(
                !verify_scaling_commutes(&m, &l, e, &s, &t).is_empty(),
                "{name} {e}"
            );
            controls += 1;
        }
    }
    assert!(controls > 30, "{controls}");
}

#[test]
fn t28_vertex_products_reject_a_cross_ratio_from_a_perturbed_length() {
    let mut rng = ChaCha8Rng::seed_from_u64(283);
    let mut controls = 0;
    for seed in 0..3 {
        for (name, m) in delta_complexes(seed) {
            let l = rational_lengths(&m, &mut rng);
            let c = cross_ratios(&m, &l);
            assert!(verify_vertex_products(&m, &c).is_empty(), "{name}");
            assert!(vertex_product_violations(&m, &l).is_empty(), "{name}");
            // Any lengths keep every vertex product 1, so the control perturbs the
            // comparison's input: edge e's cross ratio taken from the lengths with one side
            // of its quadrilateral × 101/100, the other edges' from the true lengths.
            let boundary = m.boundary_vertices();
            let mixed = m.edges().find_map(|e| {
                let q = QuadEdges::of(&m, e)?;
                let h = e.halfedge();
                if boundary[m.tail(h).idx()] && boundary[m.tip(h).idx()] {
                    return None;
                }
                [q.edges.jk, q.edges.ki, q.edges.il, q.edges.lj]
                    .into_iter()
                    .find_map(|side| {
                        let mut lp = l.clone();
                        lp[side.idx()] *= bump();
                        let x = cross_ratios(&m, &lp)[e.idx()].clone();
                        (x != c[e.idx()]).then(|| {
                            let mut cp = c.clone();
                            cp[e.idx()] = x;
                            (e, cp)
                        })
                    })
            });
            let Some((e, cp)) = mixed else {
                // Every cross ratio of a two-face sphere is 1 whatever the lengths; without
                // an interior vertex there is no product to break.
                assert!(
                    two_face_sphere(&m) || boundary.iter().all(|&b| b),
                    "{name}: no cross ratio moves"
                );
                continue;
            };
            let w = verify_vertex_products(&m, &cp);
            let h = e.halfedge();
            let ends = [m.tail(h), m.tip(h)];
            assert!(!w.is_empty(), "{name} {e}");
            assert!(
                w.iter()
                    .all(|x| ends.iter().any(|v| x.element == v.to_string())),
                "{name} {e}: {w:?}"
            );
            controls += 1;
        }
    }
    assert!(controls > 20, "{controls}");
}

#[test]
fn t28_comparisons_refuse_bad_input_without_panicking() {
    let m = builders::one_vertex_torus();
    let l: Vec<Rational> = [2, 3, 4].iter().map(|&x| Rational::from(x)).collect();
    let zero: Vec<Rational> = [2, 0, 4].iter().map(|&x| Rational::from(x)).collect();
    let short = &l[..2];
    let (mut m1, mut l1) = (m.clone(), l.clone());
    flip_ptolemy_exact(&mut m1, &mut l1, Edge(0)).unwrap();
    // Lengths of the wrong count or not positive: a witness, never a panic.
    assert!(!cluster_rule_violations(&m, short, &m1, &l1, Edge(0)).is_empty());
    assert!(!cluster_rule_violations(&m, &zero, &m1, &l1, Edge(0)).is_empty());
    assert!(!cluster_rule_violations(&m, &l, &m1, &zero, Edge(0)).is_empty());
    assert!(cluster_rule_prediction(&m, &zero, Edge(0)).is_none());
    assert!(cluster_rule_prediction(&m, &l, Edge(7)).is_none());
    // A non-existent edge: nothing to check.
    assert!(cluster_rule_violations(&m, &l, &m1, &l1, Edge(7)).is_empty());
    let p = cluster_rule_prediction(&m, &l, Edge(0)).unwrap();
    assert!(!verify_cluster_rule(&m1, &l1, Edge(0), &p[..1]).is_empty());
    assert!(cross_ratios(&m, short).iter().any(Option::is_none));
    assert!(!vertex_product_violations(&m, &zero).is_empty());
    assert!(!verify_vertex_products(&m, &[None]).is_empty());
    assert!(!verify_involution(&m, &l, Edge(0), &m1, short).is_empty());
    assert!(!verify_involution(&m, &l, Edge(9), &m1, &l1).is_empty());
    let one = [Rational::from(1)];
    assert!(!verify_scaling_commutes(&m, &l, Edge(0), &one, &[Rational::from(0)]).is_empty());
    assert!(verify_scaling_commutes(&m, &l, Edge(9), &one, &one).is_empty());
    assert!(matches!(
        check_ptolemy_flip(&m, &zero, &one),
        Verdict::NotApplicable { .. }
    ));
}

// ---------------------------------------------------------------------------------------
// T23

/// Random lengths in `[1, 1.8]` (every triangle strictly valid: the longest side is below
/// the sum of the other two, at least 2).
fn cone_metric(m: &Mesh, rng: &mut ChaCha8Rng) -> Vec<f64> {
    m.edges().map(|_| rng.gen_range(1.0..1.8)).collect()
}

/// A quadrilateral `0 = i, 1 = j, 2 = k, 3 = l` with vertices at the given points: faces
/// `ijk = [0, 1, 2]` and `jil = [1, 0, 3]`; the diagonal `ij` and its edge.
fn planar_quad(p: [[f64; 2]; 4]) -> (Mesh, Vec<f64>, Edge) {
    let m = Mesh::from_faces(4, &[[0, 1, 2], [1, 0, 3]]).unwrap();
    let l: Vec<f64> = m
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (p[m.tail(h).idx()], p[m.tip(h).idx()]);
            (a[0] - b[0]).hypot(a[1] - b[1])
        })
        .collect();
    let e = m.edges().find(|&e| QuadEdges::of(&m, e).is_some()).unwrap();
    (m, l, e)
}

fn enclosures(l: &[f64], prec: Precision) -> Vec<Interval<Mpfr>> {
    l.iter().map(|&x| enclose_f64(x, prec)).collect()
}

/// `(m, l)` moved away from Delaunay by up to `n` Euclidean flips of random edges whose
/// quadrilaterals are convex with a margin (read in `f64`: `cos α + cos α' > 1/10` at both
/// ends of the diagonal) — the same cone metric, rounded, on another triangulation.
fn scramble(m: &mut Mesh, l: &mut [f64], n: usize, rng: &mut ChaCha8Rng) {
    for _ in 0..n {
        let e = Edge(rng.gen_range(0..m.n_edges() as u32));
        let Some(q) = QuadEdges::of(m, e) else {
            continue;
        };
        let x = q.lengths(l);
        let (a, b, c, d, ee) = (*x.ij, *x.jk, *x.ki, *x.il, *x.lj);
        let cos = |p: f64, q: f64, r: f64| (p * p + q * q - r * r) / (2.0 * p * q);
        let at_i = cos(a, c, b) + cos(a, d, ee);
        let at_j = cos(a, b, c) + cos(a, ee, d);
        if at_i > 0.1 && at_j > 0.1 {
            flip_euclidean(m, l, e).unwrap();
        }
    }
}

/// The Δ-complexes of `seed` with a random cone metric, scrambled by `3·|E|` Euclidean
/// flips (rng seeded `salt + seed`), each with the recorded Euclidean flip sequence that
/// makes it Delaunay again: `(name, mesh, lengths, sequence)`.
fn scrambled_delta_complexes(salt: u64, seed: u64) -> Vec<(String, Mesh, Vec<f64>, Vec<Edge>)> {
    let mut rng = ChaCha8Rng::seed_from_u64(salt + seed);
    let mut out = Vec::new();
    for (name, m0) in delta_complexes(seed) {
        let (mut m, mut l) = (m0.clone(), cone_metric(&m0, &mut rng));
        let n = 3 * m.n_edges();
        scramble(&mut m, &mut l, n, &mut rng);
        let (mut md, mut ld) = (m.clone(), l.clone());
        let opts = FlipOptions {
            record: true,
            ..FlipOptions::default()
        };
        let seq = flip_to_delaunay(&mut md, &mut ld, FlipKind::Euclidean, &opts)
            .unwrap()
            .sequence;
        out.push((name, m, l, seq));
    }
    out
}

#[test]
fn t23_certified_on_delta_complexes_and_refuted_with_ptolemy_replay() {
    let (mut flipped, mut refuted) = (0, 0);
    for seed in case_seeds(2, 20) {
        for (name, m, l, flips) in scrambled_delta_complexes(23, seed) {
            let v = check_euclidean_flips_preserve_cone_metric(
                &m,
                &l,
                FlipKind::Euclidean,
                128,
                &Settings::default(),
            );
            // Every flip's lemma hypotheses are certified: a proof, not an overlap.
            assert!(
                matches!(v, Verdict::Holds { certified: true, max_error } if max_error < 1e-30),
                "{name}: {v:?}"
            );
            flipped += usize::from(!flips.is_empty());
            // Negative control: the same flips replayed with the Ptolemy update.
            let p = check_euclidean_flips_preserve_cone_metric(
                &m,
                &l,
                FlipKind::Ptolemy,
                128,
                &Settings::default(),
            );
            match p {
                Verdict::Fails {
                    certified: true, ..
                } => refuted += 1,
                // With flips, the Ptolemy replay is never certified to hold.
                Verdict::Holds { certified, .. } => assert_eq!(certified, flips.is_empty()),
                // A Ptolemy length can break a triangle inequality: not enclosed.
                Verdict::Undecided { .. } => {}
                other => panic!("{name}: {other:?}"),
            }
        }
    }
    assert!(
        flipped > 15 && refuted > 10,
        "{flipped} with flips, {refuted} refuted"
    );
}

#[test]
fn t23_two_triangle_sphere_flip_into_self_folded_triangles() {
    // An obtuse triangle doubled: the edge opposite the obtuse corner is not Delaunay, and
    // its flip gives a loop of length twice the height and two self-folded triangles.
    let m = builders::two_triangle_sphere();
    let l = [3.5, 2.0, 2.0];
    let e = Edge(0);
    assert!(QuadEdges::of(&m, e).is_some());
    let prec = Precision::new(128).unwrap();
    assert!(flip_hypotheses_certified(
        QuadEdges::of(&m, e).unwrap().lengths(&enclosures(&l, prec))
    ));
    let v = verify_flip_sequence(&m, &l, &[e], FlipKind::Euclidean, 128);
    assert!(certified_holds(&v), "{v:?}");
    let v = check_euclidean_flips_preserve_cone_metric(
        &m,
        &l,
        FlipKind::Euclidean,
        128,
        &Settings::default(),
    );
    assert!(certified_holds(&v), "{v:?}");
    // Control: the Ptolemy length (2·2 + 2·2)/3.5 ≠ 2·height moves the cone angles.
    let v = verify_flip_sequence(&m, &l, &[e], FlipKind::Ptolemy, 128);
    assert!(certified_fails(&v), "{v:?}");
}

#[test]
fn t23_lemma_hypotheses_and_their_negative_controls() {
    let prec = Precision::new(128).unwrap();
    // Convex kite: certified, and the explicit flip holds with a certificate.
    let (m, l, e) = planar_quad([[0.0, 0.0], [4.0, 0.0], [1.0, 2.0], [2.0, -1.0]]);
    let q = QuadEdges::of(&m, e).unwrap();
    assert!(flip_hypotheses_certified(q.lengths(&enclosures(&l, prec))));
    let v = verify_flip_sequence(&m, &l, &[e], FlipKind::Euclidean, 128);
    assert!(certified_holds(&v), "{v:?}");
    // Control: reflex at i (α_i^{ijk} + α_i^{jil} = 270°): the hypotheses are refused, and
    // the Euclidean "flip" moves the cone angle at i from 3π/2 to π/2, refuted.
    let (m, l, e) = planar_quad([[0.0, 0.0], [4.0, 0.0], [-1.0, 1.0], [-1.0, -1.0]]);
    let q = QuadEdges::of(&m, e).unwrap();
    assert!(!flip_hypotheses_certified(q.lengths(&enclosures(&l, prec))));
    let v = verify_flip_sequence(&m, &l, &[e], FlipKind::Euclidean, 128);
    match &v {
        Verdict::Fails {
            certified: true,
            witnesses,
        } => assert!(witnesses.iter().any(|w| w.element == "v0"), "{v:?}"),
        other => panic!("{other:?}"),
    }
    // Control: a degenerate triangle (1, 1, 2 exactly) is not strictly valid.
    let one = enclose_f64(1.0, prec);
    let two = enclose_f64(2.0, prec);
    let deg = Quad {
        ij: &two,
        jk: &one,
        ki: &one,
        il: &one,
        lj: &two,
    };
    assert!(!flip_hypotheses_certified(deg));
    // The 3-4-5 rectangle (cocircular): the Ptolemy and Euclidean diagonals are both 5, so
    // the Ptolemy replay is not refuted — but the lemma is about Euclidean flips, so that
    // verdict is numerical, while the Euclidean replay is certified.
    let (m, l, e) = planar_quad([[0.0, 0.0], [4.0, 3.0], [0.0, 3.0], [4.0, 0.0]]);
    let v = verify_flip_sequence(&m, &l, &[e], FlipKind::Ptolemy, 128);
    assert!(numerical_holds(&v), "{v:?}");
    let v = verify_flip_sequence(&m, &l, &[e], FlipKind::Euclidean, 128);
    assert!(certified_holds(&v), "{v:?}");
}

#[test]
fn t23_comparisons_refuse_bad_input_without_panicking() {
    let (m, l, e) = planar_quad([[0.0, 0.0], [4.0, 0.0], [1.0, 2.0], [2.0, -1.0]]);
    let prec = Precision::new(128).unwrap();
    assert!(matches!(
        verify_flip_sequence(&m, &l[..2], &[e], FlipKind::Euclidean, 128),
        Verdict::NotApplicable { .. }
    ));
    assert!(matches!(
        verify_flip_sequence(&m, &l, &[e], FlipKind::Euclidean, 0),
        Verdict::NotApplicable { .. }
    ));
    let mut nan = l.clone();
    nan[0] = f64::NAN;
    assert!(matches!(
        verify_flip_sequence(&m, &nan, &[e], FlipKind::Euclidean, 128),
        Verdict::NotApplicable { .. }
    ));
    assert!(matches!(
        check_euclidean_flips_preserve_cone_metric(
            &m,
            &nan,
            FlipKind::Euclidean,
            128,
            &Settings::default()
        ),
        Verdict::NotApplicable { .. }
    ));
    // A boundary edge or a non-existent edge in the sequence: undecided, not a panic.
    let b = m.edges().find(|&x| m.is_boundary_edge(x)).unwrap();
    for bad in [b, Edge(99)] {
        assert!(matches!(
            verify_flip_sequence(&m, &l, &[bad], FlipKind::Euclidean, 128),
            Verdict::Undecided { .. }
        ));
    }
    assert!(matches!(
        cone_angle_enclosures(&m, &enclosures(&l[..2], prec), prec),
        Err(0)
    ));
}

/// The lengths of a planar quadrilateral with rational corners `p` (`planar_quad`'s mesh),
/// as square roots of the exact squared lengths in MPFR at 256 bits.
fn planar_quad_mpfr(p: &[[Rational; 2]; 4]) -> (Mesh, Vec<Mpfr>, Edge) {
    use penner::scalar::Real;
    let prec = Precision::new(256).unwrap();
    let m = Mesh::from_faces(4, &[[0, 1, 2], [1, 0, 3]]).unwrap();
    let l: Vec<Mpfr> = m
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (&p[m.tail(h).idx()], &p[m.tip(h).idx()]);
            let dx = Rational::from(&a[0] - &b[0]);
            let dy = Rational::from(&a[1] - &b[1]);
            let sq = Rational::from(&dx * &dx) + Rational::from(&dy * &dy);
            Mpfr::from_rational(&sq, prec).sqrt()
        })
        .collect();
    let e = m.edges().find(|&e| QuadEdges::of(&m, e).is_some()).unwrap();
    (m, l, e)
}

#[test]
fn b84_first_rung_verdicts_equal_the_mpfr_comparison() {
    use penner::theorems::progress::Progress;
    use penner::theorems::t23_euclidean_flip_cone_metric::verify_flip_sequence_on_mpfr;
    use penner::theorems::t23_first_rung::proved;
    let quiet = Progress::default();
    let mut by_rung = 0;
    for seed in case_seeds(2, 20) {
        for (name, m, l, seq) in scrambled_delta_complexes(84, seed) {
            for bits in [64, 128] {
                let p = proved(&m, &l, &seq, Precision::new(bits).unwrap(), &quiet);
                let fast = verify_flip_sequence(&m, &l, &seq, FlipKind::Euclidean, bits as u32);
                let slow = verify_flip_sequence_on_mpfr(
                    &m,
                    &l,
                    &seq,
                    FlipKind::Euclidean,
                    bits as u32,
                    &quiet,
                );
                // The oracle: the whole comparison on MPFR enclosures.
                if p {
                    by_rung += 1;
                    assert!(certified_holds(&slow), "{name}: {slow:?}");
                    assert_eq!(
                        fast,
                        Verdict::Holds {
                            certified: true,
                            max_error: 0.0
                        }
                    );
                } else {
                    assert_eq!(fast, slow, "{name}");
                }
            }
        }
    }
    assert!(by_rung > 20, "{by_rung} decided by the first rung");
    // A quadrilateral whose triangle (i, j, k) is nearly flat (k at (2, 2⁻³⁰) over the
    // diagonal from (0, 0) to (4, 0), so ℓ_jk + ℓ_ki − ℓ_ij ≈ 2⁻⁶¹): its strict triangle
    // inequality is open on f64 enclosures of the 256-bit lengths and certified on the
    // lazily built MPFR ones.
    let r = |n: i64| Rational::from(n);
    let tiny = Rational::from(1) >> 30u32;
    let corners = |dy: &Rational| {
        [
            [r(0), r(0)],
            [r(4), r(0)],
            [r(2), dy.clone()],
            [r(2), r(-1)],
        ]
    };
    let (m, l, e) = planar_quad_mpfr(&corners(&tiny));
    let q = QuadEdges::of(&m, e).unwrap();
    let as_f64: Vec<Interval<f64>> = l
        .iter()
        .map(|x| {
            use penner::scalar::Real;
            Interval::<f64>::from_rational(&x.to_rational().unwrap(), ())
        })
        .collect();
    assert!(!flip_hypotheses_certified(q.lengths(&as_f64)));
    assert!(proved(&m, &l, &[e], Precision::new(128).unwrap(), &quiet));
    let slow = verify_flip_sequence_on_mpfr(&m, &l, &[e], FlipKind::Euclidean, 128, &quiet);
    assert!(certified_holds(&slow), "{slow:?}");
    // Negative controls: the same quadrilateral with k on the diagonal (a degenerate
    // triangle), and a reflex kite: the rung proves nothing, and the verdict is the MPFR
    // comparison's.
    let (m, l, e) = planar_quad_mpfr(&corners(&r(0)));
    assert!(!proved(&m, &l, &[e], Precision::new(128).unwrap(), &quiet));
    let slow = verify_flip_sequence_on_mpfr(&m, &l, &[e], FlipKind::Euclidean, 128, &quiet);
    assert!(!certified_holds(&slow), "{slow:?}");
    assert_eq!(
        verify_flip_sequence(&m, &l, &[e], FlipKind::Euclidean, 128),
        slow
    );
    // Convex at i by about 2⁻⁶¹ (k at (−1, 1), l at (1 + 2⁻⁶⁰, −1)): the hypotheses hold,
    // but i lies almost on the new edge kl, whose flat triangle's corners are not enclosed.
    let tiny = Rational::from(1) >> 60u32;
    let (m, l, e) = planar_quad_mpfr(&[
        [r(0), r(0)],
        [r(4), r(0)],
        [r(-1), r(1)],
        [r(1) + &tiny, r(-1)],
    ]);
    assert!(!proved(&m, &l, &[e], Precision::new(128).unwrap(), &quiet));
    assert_eq!(
        verify_flip_sequence(&m, &l, &[e], FlipKind::Euclidean, 128),
        verify_flip_sequence_on_mpfr(&m, &l, &[e], FlipKind::Euclidean, 128, &quiet)
    );
    let (m, l, e) = planar_quad([[0.0, 0.0], [4.0, 0.0], [-1.0, 1.0], [-1.0, -1.0]]);
    assert!(!proved(&m, &l, &[e], Precision::new(128).unwrap(), &quiet));
    assert!(certified_fails(&verify_flip_sequence(
        &m,
        &l,
        &[e],
        FlipKind::Euclidean,
        128
    )));
}
