//! Planar layouts of flattened uniformizations (T24, B75): a flat torus's fundamental
//! domain has no fold (orientations certified) and tiles by translations; a folded
//! layout and a cone metric are the negative controls.

use crate::meshgen::jittered_torus;
use penner::mesh::Face;
use penner::uniformization::layout::{cut_translation_mismatch, unfold, unproved_faces};
use penner::uniformization::svg::{render_layout_svg, scaled_lengths_f64};
use penner::uniformization::{uniformize, Targets, UniformizeOptions};

/// B75: the tolerance of the numerical layout comparisons.
const B75_TOLERANCE: f64 = 1e-8;

#[test]
fn t24_flat_torus_layout_has_no_fold_and_tiles() {
    for seed in 0..3 {
        let (m, l) = jittered_torus(8, 6, seed);
        let sol = uniformize(
            &m,
            &l,
            &Targets::flat(m.n_vertices()),
            &UniformizeOptions {
                tolerance: 1e-12,
                ..UniformizeOptions::default()
            },
        )
        .unwrap();
        assert!(sol.converged());
        let lengths = scaled_lengths_f64(&sol.mesh, &sol.base_lengths, &sol.u);
        let layout = unfold(&sol.mesh, &lengths, Face(0));
        assert!(unproved_faces(&sol.mesh, &layout).is_empty(), "seed {seed}");
        let gap = cut_translation_mismatch(&sol.mesh, &layout).unwrap();
        assert!(gap <= B75_TOLERANCE, "seed {seed}: {gap:e}");
        assert!(render_layout_svg(&sol.mesh, &layout).contains("<polygon"));
        // Negative control: the input metric (cones, not flat) has rotational holonomy.
        let raw = unfold(&m, &l, Face(0));
        let gap = cut_translation_mismatch(&m, &raw).unwrap();
        assert!(gap > 1e3 * B75_TOLERANCE, "seed {seed}: control {gap:e}");
        // Negative control: one corner mirrored across its face's base folds that face.
        let mut folded = layout.clone();
        let [a, b, c] = sol.mesh.face_halfedges(Face(3));
        let (p, q, r) = (
            folded.corner[a.idx()].unwrap(),
            folded.corner[b.idx()].unwrap(),
            folded.corner[c.idx()].unwrap(),
        );
        // Reflect r across the line pq.
        let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
        let t = ((r[0] - p[0]) * dx + (r[1] - p[1]) * dy) / (dx * dx + dy * dy);
        let foot = [p[0] + t * dx, p[1] + t * dy];
        folded.corner[c.idx()] = Some([2.0 * foot[0] - r[0], 2.0 * foot[1] - r[1]]);
        assert_eq!(unproved_faces(&sol.mesh, &folded), vec![Face(3)]);
    }
}
