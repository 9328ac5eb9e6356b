//! UVs on a surface with boundary (issue 29): the common refinement built on the double and
//! restricted to copy 1 (`uv_boundary`, B78, B108, B109).

use penner::io::Surface;
use penner::mesh::builders::{self, Embedded};
use penner::mesh::Face;
use penner::overlay::check_parametrization;
use penner::overlay::refinement::RefinedVertex;
use penner::uniformization::pipeline::{
    check_written_uv, uniformize_boundary, uv_boundary, Options, Precision, UvCones,
};
use rug::Rational;
use std::f64::consts::PI;

/// A 4×4 grid disk lifted off its plane by rational heights `(i·j mod 3)/7`: a curved disk
/// with 16 boundary vertices and 9 interior ones.
fn bumpy_grid() -> Surface {
    let mut e: Embedded = builders::grid_disk(4, 4).unwrap();
    for (k, p) in e.positions.iter_mut().enumerate() {
        let (i, j) = (k % 5, k / 5);
        p[2] = Rational::from((((i * j) % 3) as i64, 7));
    }
    Surface::from_embedded("bumpy grid", e).unwrap()
}

/// The icosahedron with face 0 removed: a curved disk with three boundary vertices and
/// nine interior ones (each of angle 5π/3 in the input metric, flattened by the target).
fn open_icosahedron() -> Surface {
    let ico = builders::icosahedron();
    let mesh = builders::remove_face(&ico.mesh, Face(0)).unwrap();
    let e = Embedded {
        mesh,
        positions: ico.positions,
        exact: ico.exact,
    };
    Surface::from_embedded("open icosahedron", e).unwrap()
}

/// The angle at `a` of the UV triangle `a b c` (binary64, from the coordinates alone).
fn angle(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    let (u, v) = ([b[0] - a[0], b[1] - a[1]], [c[0] - a[0], c[1] - a[1]]);
    (u[0] * v[1] - u[1] * v[0]).atan2(u[0] * v[0] + u[1] * v[1])
}

/// Per input vertex, the sum of the UV angles at it over the refinement triangles.
fn uv_angle_sums(uv: &penner::overlay::UvMesh, n: usize) -> Vec<f64> {
    let mut sums = vec![0.0; n];
    for (t, p) in uv.refinement.triangles.iter().zip(&uv.uv) {
        for i in 0..3 {
            if let RefinedVertex::Input(w) = uv.refinement.vertices[t.vertices[i] as usize] {
                sums[w.idx()] += angle(p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
            }
        }
    }
    sums
}

/// B78 + B109 on copy 1: the UV mesh is the input's (its faces, vertices and crossings use
/// the input's ids), the exact checks hold on the written decimals, and an oracle that
/// reads only the written texture coordinates agrees with the targets: the UV angles
/// around each interior vertex sum to 2π and at each boundary vertex to its target `φ_v`
/// (here the boundary curvature spread evenly, `φ_v = π − 2π/n_∂`). The tolerance, 10⁻⁹,
/// is the solve's stopping residual (below 10⁻¹⁰ in f64) plus the layout's rounding, a
/// numerical check: the exact checks are the certified part. Negative controls: the
/// targets of the double (`2φ_v` at boundary vertices) are not what copy 1 shows, and a
/// UV corner at an interior vertex moved by 10⁻³ breaks that vertex's angle sum.
#[test]
fn b109_boundary_uv_of_copy_1_angle_sums_and_controls() {
    let mut seams_checked = 0;
    for s in [bumpy_grid(), open_icosahedron()] {
        let opts = Options {
            precision: Precision::F64,
            certify: false,
        };
        let out = uniformize_boundary(&s, None, &opts).unwrap();
        assert!(out.boundary.solution.converged(), "{}", s.name);
        let uv = uv_boundary(&s, &out).unwrap();
        let (nv, nf) = (s.mesh.n_vertices(), s.mesh.n_faces());
        assert_eq!(uv.input_faces, nf);
        assert!(uv
            .refinement
            .triangles
            .iter()
            .all(|t| t.input_face.idx() < nf));
        assert!(uv.refinement.vertices.iter().all(|v| match v {
            RefinedVertex::Input(w) => w.idx() < nv,
            RefinedVertex::Crossing { edge, .. } => edge.idx() < s.mesh.n_edges(),
        }));
        assert_eq!(uv.positions.len(), uv.refinement.vertices.len());
        let report = check_parametrization(&uv.obj(), &uv.sidecar()).unwrap();
        assert!(
            report.holds() && report.triangles >= nf,
            "{}: {report:?}",
            s.name
        );
        // The cones are the boundary corners (2φ ≠ 2π on the double). The interior is flat
        // (2π, a multiple of π/2) and 2φ is not a multiple of π/2 here, so the seams are
        // checked exactly when no seam edge was flipped, and then they hold.
        let cones = UvCones::of_boundary(&out);
        for v in s.mesh.vertices() {
            assert_eq!(cones.cones[v.idx()], s.mesh.is_boundary_vertex(v), "{v:?}");
        }
        assert_eq!(
            cones.quarter_turns,
            out.boundary.seam_flips.is_empty(),
            "{}",
            s.name
        );
        let eps = Rational::from((1, 1_000_000_000u32));
        let written =
            check_written_uv(&uv.obj(), &uv.sidecar_text().unwrap(), &cones, &eps).unwrap();
        assert_eq!(written.parametrization, report);
        assert_eq!(written.seams.is_some(), cones.quarter_turns);
        if let Some(seams) = written.seams {
            assert!(seams.broken.is_empty(), "{}: {seams:?}", s.name);
            seams_checked += 1;
        }
        // The oracle: UV angle sums against the targets.
        let n_boundary = s
            .mesh
            .vertices()
            .filter(|&v| s.mesh.is_boundary_vertex(v))
            .count();
        let phi = PI - 2.0 * PI / n_boundary as f64;
        let sums = uv_angle_sums(&uv, nv);
        for v in s.mesh.vertices() {
            let want = if s.mesh.is_boundary_vertex(v) {
                phi
            } else {
                2.0 * PI
            };
            assert!(
                (sums[v.idx()] - want).abs() < 1e-9,
                "{} vertex {v:?}: {} vs {want}",
                s.name,
                sums[v.idx()]
            );
            // Control 1: the double's target at a boundary vertex is 2φ, not what copy 1 shows.
            if s.mesh.is_boundary_vertex(v) {
                assert!((sums[v.idx()] - 2.0 * phi).abs() > 0.1);
            }
        }
        // Control 2: a UV corner at an interior vertex moved by 10⁻³.
        let interior = s
            .mesh
            .vertices()
            .find(|&v| !s.mesh.is_boundary_vertex(v))
            .unwrap();
        let mut moved = uv.clone();
        let (k, i) = moved
            .refinement
            .triangles
            .iter()
            .enumerate()
            .find_map(|(k, t)| {
                t.vertices
                    .iter()
                    .position(|&x| {
                        moved.refinement.vertices[x as usize] == RefinedVertex::Input(interior)
                    })
                    .map(|i| (k, i))
            })
            .unwrap();
        moved.uv[k][i][0] += 1e-3;
        let bad = uv_angle_sums(&moved, nv)[interior.idx()];
        assert!((bad - 2.0 * PI).abs() > 1e-9, "{}: {bad}", s.name);
    }
    assert!(seams_checked > 0, "no surface had its seams checked");
}

/// A surface without positions gets no UVs (bad input, typed), and a closed surface is not
/// a boundary outcome: the boundary pipeline refuses it before any UV is asked for.
#[test]
fn b109_boundary_uv_without_positions_is_bad_input() {
    let e = builders::grid_disk(2, 2).unwrap();
    let lengths = Surface::from_embedded("grid", e.clone()).unwrap();
    let intrinsic = Surface::new("grid", e.mesh, lengths.metric.clone(), None).unwrap();
    let opts = Options {
        precision: Precision::F64,
        certify: false,
    };
    let out = uniformize_boundary(&intrinsic, None, &opts).unwrap();
    let err = uv_boundary(&intrinsic, &out).unwrap_err();
    assert!(err.is_bad_input(), "{err}");
    let closed = Surface::from_embedded("octahedron", builders::octahedron()).unwrap();
    assert!(uniformize_boundary(&closed, None, &opts).is_err());
}
