//! Harmonic maps of disks to convex polygons (T36): embeddings with positive weights, a
//! fold with negative cotan weights kept as a fixed instance.

use penner::circles::harmonic::{
    cotan_weights_planar, face_orientations, harmonic_map, regular_polygon,
};
use penner::mesh::builders::{grid_disk, random_planar};
use penner::mesh::Mesh;
use penner::predicates::ladder::Ladder;
use penner::theorems::t36_harmonic_embedding::{check_harmonic_embedding, orientation_counts};
use penner::theorems::Verdict;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn positions(e: &penner::mesh::Embedded) -> Vec<[f64; 2]> {
    e.positions
        .iter()
        .map(|p| [p[0].to_f64(), p[1].to_f64()])
        .collect()
}

/// A wheel: centre v4 = (0, 0), rim v0 = (1/2, 1/2), v1 = (0, 10), v2 = (−1/2, 1/2),
/// v3 = (0, −1). Both angles opposite the spoke v4v1 are obtuse (≈ 132°), so its cotan
/// weight is negative (≈ −0.9).
fn fold_wheel() -> (Mesh, Vec<[f64; 2]>) {
    let mesh = Mesh::from_faces(5, &[[4, 0, 1], [4, 1, 2], [4, 2, 3], [4, 3, 0]]).unwrap();
    let pos = vec![
        [0.5, 0.5],
        [0.0, 10.0],
        [-0.5, 0.5],
        [0.0, -1.0],
        [0.0, 0.0],
    ];
    (mesh, pos)
}

#[test]
fn t36_negative_cotan_weights_fold_fixed_instance() {
    let ladder = Ladder::default();
    let (mesh, pos) = fold_wheel();
    // The wheel itself is embedded (every face counterclockwise, decided exactly).
    assert_eq!(
        orientation_counts(&face_orientations(&mesh, &pos, &ladder)),
        (4, 0, 0)
    );
    let w = cotan_weights_planar(&mesh, &pos);
    let spoke = mesh
        .edges()
        .find(|e| {
            let h = e.halfedge();
            let ends = [mesh.tail(h).idx(), mesh.tip(h).idx()];
            ends.contains(&4) && ends.contains(&1)
        })
        .unwrap();
    // Independent value: at v0 the angle between v0→v4 = (−½, −½) and v0→v1 = (−½, 19/2)
    // has cos = (¼ − 19/4)/(√½·√(90.5)), cot = dot/cross = −4.5/5 = −0.9, twice (symmetry).
    assert!(
        (w[spoke.idx()] - (-0.9)).abs() < 1e-12,
        "{}",
        w[spoke.idx()]
    );
    // Mapped to the convex kite v0 → (1, 0), v1 → (0, 10), v2 → (−1, 0), v3 → (0, −1/100)
    // (same cyclic order), the negative coefficient on v1 pushes the centre below v3,
    // outside the kite: faces fold (certified signs of the computed map).
    let kite = [[1.0, 0.0], [0.0, 10.0], [-1.0, 0.0], [0.0, -0.01]];
    let polygon: Vec<[f64; 2]> = penner::circles::harmonic::boundary_loop(&mesh)
        .unwrap()
        .iter()
        .map(|&v| kite[v])
        .collect();
    let map = harmonic_map(&mesh, &w, &polygon).unwrap();
    let (p, n, z) = orientation_counts(&face_orientations(&mesh, &map, &ladder));
    assert!(p > 0 && n > 0 && z == 0, "{p} {n} {z}: {map:?}");
    // Control: positive (uniform) weights onto the same kite embed the wheel.
    let uniform = harmonic_map(&mesh, &[1.0; 8], &polygon).unwrap();
    let (p, n, z) = orientation_counts(&face_orientations(&mesh, &uniform, &ladder));
    assert!(z == 0 && (p == 0 || n == 0), "{p} {n} {z}");
    // The check refuses negative weights instead of judging them.
    assert!(matches!(
        check_harmonic_embedding(&mesh, &w, &ladder),
        Verdict::NotApplicable { .. }
    ));
    // Control: uniform positive weights on the same wheel embed it.
    let v = check_harmonic_embedding(&mesh, &[1.0; 8], &ladder);
    assert!(
        matches!(
            v,
            Verdict::Holds {
                certified: true,
                ..
            }
        ),
        "{v:?}"
    );
}

#[test]
fn t36_positive_weights_give_embeddings() {
    let ladder = Ladder::default();
    let mut rng = ChaCha8Rng::seed_from_u64(36);
    for case in 0..crate::support::cases(10, 200) {
        let e = if case % 2 == 0 {
            random_planar(12 + case as u32, case as u64).unwrap()
        } else {
            grid_disk(3 + case as u32 % 4, 4).unwrap()
        };
        let mesh = e.mesh.clone();
        // Random positive weights in [10⁻³, 10³] (log-uniform), and the cotan weights of the
        // Delaunay disks (nonnegative there; zeros replaced by 10⁻³).
        let w: Vec<f64> = (0..mesh.n_edges())
            .map(|_| 10f64.powf(rng.gen_range(-3.0..3.0)))
            .collect();
        let v = check_harmonic_embedding(&mesh, &w, &ladder);
        assert!(
            matches!(
                v,
                Verdict::Holds {
                    certified: true,
                    ..
                }
            ),
            "case {case}: {v:?}"
        );
        if case % 2 == 0 {
            let c: Vec<f64> = cotan_weights_planar(&mesh, &positions(&e))
                .into_iter()
                .map(|x| if x > 1e-3 { x } else { 1e-3 })
                .collect();
            let v = check_harmonic_embedding(&mesh, &c, &ladder);
            assert!(
                matches!(
                    v,
                    Verdict::Holds {
                        certified: true,
                        ..
                    }
                ),
                "case {case}: {v:?}"
            );
        }
        // Negative control: the computed map with one interior vertex moved across the
        // polygon folds — the same exact orientation test sees it.
        let m = penner::circles::harmonic::boundary_loop(&mesh)
            .unwrap()
            .len();
        let mut map = harmonic_map(&mesh, &w, &regular_polygon(m)).unwrap();
        let boundary = mesh.boundary_vertices();
        let inner = (0..mesh.n_vertices()).find(|&v| !boundary[v]).unwrap();
        map[inner] = [-3.0 * map[inner][0] - 5.0, -3.0 * map[inner][1] + 7.0];
        let (p, n, _) = orientation_counts(&face_orientations(&mesh, &map, &ladder));
        assert!(p > 0 && n > 0);
    }
}
