//! Rivin angle systems (T14): the circumcircle intersection angles of a planar Delaunay
//! triangulation (spade, certified by exact predicates) reproduce it up to similarity;
//! perturbed angles do not (B86).

use crate::support::case_indices;
use penner::circles::face_pattern::{
    angle_sum_bound, angle_sum_defect, intersection_angles, solve_face_pattern, FacePatternError,
};
use penner::mesh::builders::random_planar;
use penner::mesh::Mesh;
use penner::theorems::t14_rivin_angles::{check_rivin_angles, compare_reconstruction};
use penner::theorems::Verdict;
use std::f64::consts::PI;

fn positions(e: &penner::mesh::Embedded) -> Vec<[f64; 2]> {
    e.positions
        .iter()
        .map(|p| [p[0].to_f64(), p[1].to_f64()])
        .collect()
}

/// Two interior edges of `mesh` that share no face (for the compensated perturbation).
fn two_interior_edges(mesh: &Mesh) -> Option<(usize, usize)> {
    let interior: Vec<_> = mesh
        .edges()
        .filter(|e| {
            let h = e.halfedge();
            mesh.face(h).is_some() && mesh.face(h.twin()).is_some()
        })
        .collect();
    let faces = |e: &penner::mesh::Edge| {
        let h = e.halfedge();
        [mesh.face(h), mesh.face(h.twin())]
    };
    for a in &interior {
        for b in &interior {
            let (fa, fb) = (faces(a), faces(b));
            if a != b && fa.iter().all(|f| !fb.contains(f)) {
                return Some((a.idx(), b.idx()));
            }
        }
    }
    None
}

#[test]
fn t14_delaunay_angles_reproduce_random_triangulations() {
    for k in case_indices(12, 200) {
        let n = 6 + (k % 5) as u32 * 10;
        let emb = random_planar(n, 1400 + k as u64).unwrap();
        let pts = positions(&emb);
        let r = check_rivin_angles(&emb.mesh, &pts);
        assert!(
            matches!(
                r.verdict,
                Verdict::Holds {
                    certified: false,
                    ..
                }
            ),
            "case {k} (n = {n}): {:?}",
            r.verdict
        );
        assert!(r.angle_ratio <= 1.0 && r.position_error <= r.position_bound);
        // The bounds are not vacuous: positions within 2¹⁰ = 2⁻¹⁰ of the coordinate range
        // 2²⁰, angles within 10⁻⁶ rad.
        assert!(
            r.position_bound < 1024.0,
            "case {k}: bound {:e}",
            r.position_bound
        );
        assert!(r.angle_error < 1e-6, "case {k}: {:e}", r.angle_error);

        // Control 1: one angle changed — the face equations' sum identity fails, proved.
        let mut phi = intersection_angles(&emb.mesh, &pts);
        let e = (0..phi.len()).find(|&e| phi[e] < 3.0).unwrap();
        phi[e] += 1e-3;
        let c = compare_reconstruction(&emb.mesh, &pts, &phi);
        assert!(
            matches!(
                c.verdict,
                Verdict::Fails {
                    certified: true,
                    ..
                }
            ),
            "case {k}: {:?}",
            c.verdict
        );

        // Control 2: two angles changed by ±0.05 (the sum kept): the system still solves,
        // but the reconstruction is a different triangulation.
        if let Some((a, b)) = two_interior_edges(&emb.mesh) {
            let mut phi = intersection_angles(&emb.mesh, &pts);
            let d = 0.05_f64.min(phi[a].min(PI - phi[b]) / 2.0);
            phi[a] -= d;
            phi[b] += d;
            let c = compare_reconstruction(&emb.mesh, &pts, &phi);
            assert!(
                !c.verdict.holds(),
                "case {k}: perturbed angles still reproduce"
            );
        }
    }
}

#[test]
fn t14_two_triangles_cocircular_non_delaunay_and_delaunay() {
    // The four corners of a unit square are cocircular: Φ = 0 on the diagonal.
    let mesh = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
    let pts = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let r = check_rivin_angles(&mesh, &pts);
    assert!(
        matches!(&r.verdict, Verdict::NotApplicable { reason } if reason.contains("cocircular")),
        "{:?}",
        r.verdict
    );
    // Moving the far corner inward makes the diagonal strictly Delaunay (the angles at v1
    // and v3 sum to ≈ 143° < 180°): T14 applies and holds.
    let pts = [[0.0, 0.0], [4.0, 0.0], [3.0, 3.0], [0.0, 4.0]];
    let r = check_rivin_angles(&mesh, &pts);
    assert!(r.verdict.holds(), "{:?}", r.verdict);
    // Moving it outward makes the diagonal not locally Delaunay (≈ 233°): refused.
    let pts = [[0.0, 0.0], [1.0, 0.0], [2.0, 2.0], [0.0, 1.0]];
    let r = check_rivin_angles(&mesh, &pts);
    assert!(
        matches!(&r.verdict, Verdict::NotApplicable { reason } if reason.contains("not locally Delaunay")),
        "{:?}",
        r.verdict
    );
    // Non-integer coordinates are outside the bound's hypotheses: refused, not guessed.
    let pts = [[0.0, 0.0], [4.0, 0.0], [3.0, 3.5], [0.0, 4.0]];
    assert!(matches!(
        check_rivin_angles(&mesh, &pts).verdict,
        Verdict::NotApplicable { .. }
    ));
}

#[test]
fn b86_angle_sum_bound_separates_exact_sums_from_perturbed_ones() {
    for k in 0..20u64 {
        let emb = random_planar(30, 9000 + k).unwrap();
        let pts = positions(&emb);
        let phi = intersection_angles(&emb.mesh, &pts);
        let (ne, nf) = (phi.len(), emb.mesh.n_faces());
        let bound = angle_sum_bound(ne, nf);
        // The angles of a triangulation satisfy the identity: the computed defect is rounding.
        assert!(angle_sum_defect(&phi, nf).abs() <= bound);
        // 2¹⁰ bounds off (a perturbation of one angle) is refused.
        let mut bad = phi.clone();
        bad[0] += 1024.0 * bound;
        assert!(matches!(
            solve_face_pattern(&emb.mesh, &bad, 1e-12, 50),
            Err(FacePatternError::AngleSum { .. })
        ));
    }
}

#[test]
fn t14_bad_angles_are_typed_errors() {
    let emb = random_planar(10, 3).unwrap();
    let pts = positions(&emb);
    let mut phi = intersection_angles(&emb.mesh, &pts);
    assert!(matches!(
        solve_face_pattern(&emb.mesh, &phi[1..], 1e-12, 50),
        Err(FacePatternError::Count { .. })
    ));
    phi[2] = f64::NAN;
    assert!(matches!(
        solve_face_pattern(&emb.mesh, &phi, 1e-12, 50),
        Err(FacePatternError::AngleOutOfRange { edge: 2, .. })
    ));
    phi[2] = PI;
    assert!(matches!(
        solve_face_pattern(&emb.mesh, &phi, 1e-12, 50),
        Err(FacePatternError::AngleOutOfRange { edge: 2, .. })
    ));
}
