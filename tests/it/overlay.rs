//! B105: normal coordinates of the input triangulation relative to the intrinsic
//! Delaunay triangulation, against an independent exact oracle on planar meshes (every
//! edge of a flat disk with convex boundary is the straight segment between its ends, so
//! crossings are counted by exact rational orientation tests).

use penner::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use penner::io::surface::squared_lengths_from_positions;
use penner::mesh::{builders, Edge, Mesh};
use penner::overlay::replay_normal_coordinates;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

type P = [Rational; 3];

/// Sign of the exact orientation of `a, b, c` in the plane.
fn orient(a: &P, b: &P, c: &P) -> i32 {
    let d = Rational::from(&b[0] - &a[0]) * Rational::from(&c[1] - &a[1])
        - Rational::from(&b[1] - &a[1]) * Rational::from(&c[0] - &a[0]);
    d.cmp0() as i32
}

/// Ends of `e` as vertex indices.
fn ends(m: &Mesh, e: Edge) -> (usize, usize) {
    let h = e.halfedge();
    (m.tail(h).idx(), m.tip(h).idx())
}

/// The exact oracle: for every edge of `t`, `−1` if it is an edge of `t_in`, else the
/// number of proper crossings of its segment with the segments of `t_in`.
fn oracle(t_in: &Mesh, t: &Mesh, pos: &[P]) -> Vec<i64> {
    t.edges()
        .map(|e| {
            let (p, q) = ends(t, e);
            let mut count = 0;
            for g in t_in.edges() {
                let (a, b) = ends(t_in, g);
                if (a, b) == (p, q) || (a, b) == (q, p) {
                    return -1;
                }
                let s1 = orient(&pos[p], &pos[q], &pos[a]) * orient(&pos[p], &pos[q], &pos[b]);
                let s2 = orient(&pos[a], &pos[b], &pos[p]) * orient(&pos[a], &pos[b], &pos[q]);
                if s1 < 0 && s2 < 0 {
                    count += 1;
                }
            }
            count
        })
        .collect()
}

/// A planar Delaunay triangulation spoiled by random flips of strictly convex quads.
fn spoiled(n: u32, seed: u64) -> (Mesh, Vec<P>) {
    let e = builders::random_planar(n, seed).unwrap();
    let (mut m, pos) = (e.mesh, e.positions);
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x5eed);
    for _ in 0..4 * m.n_edges() {
        let e = Edge(rng.gen_range(0..m.n_edges() as u32));
        if m.is_boundary_edge(e) {
            continue;
        }
        let [i, j, k, l] = m.quad_vertices(e).map(|v| &pos[v.idx()]);
        if orient(k, l, i) * orient(k, l, j) < 0 {
            m.flip(e).unwrap();
        }
    }
    (m, pos)
}

#[test]
fn b105_normal_coordinates_match_exact_planar_crossings() {
    let mut crossed = 0;
    for seed in 0..12u64 {
        let (t_in, pos) = spoiled(12 + 3 * seed as u32, seed);
        let mut t = t_in.clone();
        let mut l: Vec<f64> = squared_lengths_from_positions(&t_in, &pos)
            .iter()
            .map(|s| s.to_f64().sqrt())
            .collect();
        let opts = FlipOptions {
            record: true,
            ..FlipOptions::default()
        };
        let r = flip_to_delaunay(&mut t, &mut l, FlipKind::Euclidean, &opts).unwrap();
        assert!(r.all_certified_delaunay());
        let (replayed, n) = replay_normal_coordinates(&t_in, &r.sequence).unwrap();
        assert_eq!(replayed, t);
        n.check(&t).unwrap();
        let exact = oracle(&t_in, &t, &pos);
        assert_eq!(n.values(), &exact[..], "seed {seed}");
        crossed += exact.iter().filter(|&&v| v > 0).count();
        // Negative control: one coordinate altered is caught by the oracle comparison.
        let mut bad = n.values().to_vec();
        bad[r.sequence[0].idx()] += 2;
        assert_ne!(bad, exact);
    }
    assert!(
        crossed > 20,
        "the spoiled meshes were hardly flipped: {crossed}"
    );
}

#[test]
fn b105_replay_refuses_a_boundary_flip() {
    let (t_in, _) = spoiled(10, 3);
    let b = t_in.edges().find(|&e| t_in.is_boundary_edge(e)).unwrap();
    assert!(replay_normal_coordinates(&t_in, &[b]).is_err());
}

// ---------------------------------------------------------------------------------------
// B108, B109: crossing positions, the refinement, texture coordinates, the exact checks.

use penner::io::Surface;
use penner::mesh::{builders::Embedded, Face};
use penner::overlay::tracking::Crossing;
use penner::overlay::uv::decimal_complement;
use penner::overlay::{
    check_parametrization, common_refinement, track_flips, uv_mesh, RefinementError,
};
use penner::uniformization::pipeline::{uniformize_closed, uv_closed, Options, Precision};
use penner::uniformization::Targets;

/// Exact intersection parameters `(s, t)` of segments `ab` and `pq`.
fn exact_params(a: &P, b: &P, p: &P, q: &P) -> (f64, f64) {
    let d = |u: &P, v: &P| [Rational::from(&v[0] - &u[0]), Rational::from(&v[1] - &u[1])];
    let cr = |u: &[Rational; 2], v: &[Rational; 2]| {
        Rational::from(&u[0] * &v[1]) - Rational::from(&u[1] * &v[0])
    };
    let (r, w, ap) = (d(a, b), d(p, q), d(a, p));
    let den = cr(&r, &w);
    let s = cr(&ap, &w) / den.clone();
    let t = cr(&ap, &r) / den;
    (s.to_f64(), t.to_f64())
}

/// The planar meshes of the B105 oracle, flipped to intrinsic Delaunay by certified
/// Euclidean flips, with the flips.
fn planar_case(seed: u64) -> (Mesh, Vec<P>, Vec<f64>, Vec<Edge>) {
    let (t_in, pos) = spoiled(12 + 3 * seed as u32, seed);
    let mut t = t_in.clone();
    let l0: Vec<f64> = squared_lengths_from_positions(&t_in, &pos)
        .iter()
        .map(|s| s.to_f64().sqrt())
        .collect();
    let mut l = l0.clone();
    let opts = FlipOptions {
        record: true,
        ..FlipOptions::default()
    };
    let r = flip_to_delaunay(&mut t, &mut l, FlipKind::Euclidean, &opts).unwrap();
    (t_in, pos, l0, r.sequence)
}

/// B108 against an independent oracle: every tracked crossing of a planar input edge with
/// an edge of the flipped triangulation lies where the exact rational intersection of the
/// two straight segments does (to binary64 rounding), and the counts are the normal
/// coordinates.
#[test]
fn b108_tracked_crossings_match_exact_planar_intersections() {
    let mut seen = 0;
    for seed in 0..12u64 {
        let (t_in, pos, l0, flips) = planar_case(seed);
        let o = track_flips(&t_in, &l0, &flips).unwrap();
        let (t, n) = replay_normal_coordinates(&t_in, &flips).unwrap();
        assert_eq!(o.mesh, t);
        assert_eq!(o.crossing_counts(), n.values());
        for (g, path) in o.paths.iter().enumerate() {
            let (a, b) = ends(&t_in, Edge(g as u32));
            let mut last = 0.0;
            for c in &path.crossings {
                let (p, q) = (t.tail(c.h).idx(), t.tip(c.h).idx());
                let (s, tt) = exact_params(&pos[a], &pos[b], &pos[p], &pos[q]);
                assert!(
                    (s - c.s).abs() < 1e-9,
                    "seed {seed} g {g}: s {} vs {s}",
                    c.s
                );
                assert!(
                    (tt - c.t).abs() < 1e-9,
                    "seed {seed} g {g}: t {} vs {tt}",
                    c.t
                );
                assert!(c.s > last, "crossings out of order along g{g}");
                last = c.s;
                seen += 1;
            }
        }
    }
    assert!(seen > 20, "{seen}");
}

/// The refinement's size against the normal coordinates alone (B108):
/// `|F_R| = |F| + 2 Σ n̂_e`, `|V_R| = |V| + Σ n̂_e`, and its Euler characteristic is the
/// input's.
#[test]
fn b108_refinement_counts_match_the_normal_coordinate_formula() {
    for seed in 0..8u64 {
        let (t_in, _, l0, flips) = planar_case(seed);
        let o = track_flips(&t_in, &l0, &flips).unwrap();
        let (_, n) = replay_normal_coordinates(&t_in, &flips).unwrap();
        let r = common_refinement(&t_in, &o).unwrap();
        let crossings: i64 = n.values().iter().map(|&v| v.max(0)).sum();
        assert_eq!(
            r.triangles.len() as i64,
            t_in.n_faces() as i64 + 2 * crossings
        );
        assert_eq!(
            r.vertices.len() as i64,
            t_in.n_vertices() as i64 + crossings
        );
        let faces: Vec<[u32; 3]> = r.triangles.iter().map(|t| t.vertices).collect();
        let m = Mesh::from_faces(r.vertices.len() as u32, &faces).unwrap();
        assert_eq!(m.euler_characteristic(), t_in.euler_characteristic());
    }
}

/// A planar mesh laid out with its own metric: the UV map is a rigid motion of the plane,
/// so every UV triangle has the side lengths of its 3-D triangle (an oracle independent of
/// the layout), and the exact checks hold.
#[test]
fn b109_planar_uv_is_a_rigid_motion_and_checks_hold() {
    for seed in 0..6u64 {
        let (t_in, pos, l0, flips) = planar_case(seed);
        let o = track_flips(&t_in, &l0, &flips).unwrap();
        let lengths = o.lengths.clone();
        let mesh = o.mesh.clone();
        let r = common_refinement(&t_in, &o).unwrap();
        let p3: Vec<[f64; 3]> = pos
            .iter()
            .map(|p| [p[0].to_f64(), p[1].to_f64(), 0.0])
            .collect();
        // The layout starts from face 0 of T_F; every face is reached on a disk.
        let uv = uv_mesh(
            &t_in,
            &p3,
            &mesh,
            &lengths,
            r,
            &vec![false; mesh.n_vertices()],
        )
        .unwrap();
        for (k, t) in uv.refinement.triangles.iter().enumerate() {
            for i in 0..3 {
                let (a, b) = (t.vertices[i] as usize, t.vertices[(i + 1) % 3] as usize);
                let d3 = (uv.positions[a][0] - uv.positions[b][0])
                    .hypot(uv.positions[a][1] - uv.positions[b][1]);
                let q = (uv.uv[k][i], uv.uv[k][(i + 1) % 3]);
                let d2 = (q.0[0] - q.1[0]).hypot(q.0[1] - q.1[1]);
                assert!(
                    (d3 - d2).abs() < 1e-9 * d3.max(1.0),
                    "seed {seed} triangle {k}: {d3} vs {d2}"
                );
            }
        }
        let report = check_parametrization(&uv.obj(), &uv.sidecar()).unwrap();
        assert!(report.holds(), "seed {seed}: {report:?}");
        assert_eq!(report.triangles, uv.refinement.triangles.len());
    }
}

/// Negative control of the refinement: two crossings of one edge swapped along it make two
/// input pieces cross inside a face, which is refused.
#[test]
fn b108_swapped_crossings_are_refused() {
    let (t_in, _, l0, flips) = planar_case(5);
    let mut o = track_flips(&t_in, &l0, &flips).unwrap();
    // Two crossings on one edge of T_F by different input edges.
    let mut on: std::collections::BTreeMap<u32, Vec<(usize, usize)>> =
        std::collections::BTreeMap::default();
    for (g, p) in o.paths.iter().enumerate() {
        for (k, c) in p.crossings.iter().enumerate() {
            on.entry(c.h.edge().0).or_default().push((g, k));
        }
    }
    let pair = on
        .values()
        .find_map(|v| {
            v.iter()
                .find_map(|&x| v.iter().find(|&&y| y.0 != x.0).map(|&y| (x, y)))
        })
        .expect("an edge crossed by two input edges");
    let ((g1, k1), (g2, k2)) = pair;
    let c1: Crossing = o.paths[g1].crossings[k1];
    let c2: Crossing = o.paths[g2].crossings[k2];
    let t_of = |c: &Crossing, h| if c.h == h { c.t } else { 1.0 - c.t };
    let (t1, t2) = (t_of(&c1, c1.h), t_of(&c2, c1.h));
    o.paths[g1].crossings[k1].t = t2;
    o.paths[g2].crossings[k2].t = if c2.h == c1.h { t1 } else { 1.0 - t1 };
    assert!(matches!(
        common_refinement(&t_in, &o),
        Err(RefinementError::Face { .. })
    ));
}

/// The exact decimal complement keeps every written barycentric triple summing to 1.
#[test]
fn b109_decimal_complement_is_exact() {
    for (d, c) in [
        ("0.25", "0.75"),
        ("0", "1"),
        ("1", "0"),
        ("0.1", "0.9"),
        ("0.999", "0.001"),
    ] {
        assert_eq!(decimal_complement(d), c);
    }
    let d = 0.1f64 + 0.2;
    let s = d.to_string();
    let sum = penner::scalar::parse::parse_rational(&s).unwrap()
        + penner::scalar::parse::parse_rational(&decimal_complement(&s)).unwrap();
    assert_eq!(sum, 1);
}

/// An icosahedron with the cone angle π at four vertices (Gauss–Bonnet: 4 · π = 4π).
fn four_cone_icosahedron() -> (Surface, Targets) {
    let e: Embedded = builders::icosahedron();
    let s = Surface::from_embedded("icosahedron", e).unwrap();
    let n = s.mesh.n_vertices();
    let mut t = vec![Rational::from(2); n];
    for v in [0, 3, 6, 9] {
        t[v] = Rational::from(1);
    }
    (s, Targets::from_multiples_of_pi(t))
}

/// The UV mesh of the four-cone icosahedron, solved in binary64 without a certificate.
fn four_cone_uv() -> penner::overlay::UvMesh {
    let (s, targets) = four_cone_icosahedron();
    let opts = Options {
        precision: Precision::F64,
        certify: false,
    };
    let out = uniformize_closed(&s, &targets, &opts, &mut |_| {}).unwrap();
    uv_closed(&s, &out).unwrap()
}

/// B109 end to end on a closed surface with cones: the UV areas of each face of `T_F`
/// sum to its area from the final lengths at 256 bits (Heron, an oracle independent of
/// the layout and of the refinement), the exact checks hold, and the negative controls
/// (a UV corner moved across its opposite side, a barycentric corner moved across an input
/// edge) are reported with their faces.
#[test]
fn b109_closed_cones_uv_area_oracle_and_negative_controls() {
    use penner::scalar::{Mpfr, Precision as Bits, Real};
    let (s, targets) = four_cone_icosahedron();
    let opts = Options {
        precision: Precision::Mpfr(128),
        certify: false,
    };
    let out = uniformize_closed(&s, &targets, &opts, &mut |_| {}).unwrap();
    assert!(out.solution.converged());
    let uv = uv_closed(&s, &out).unwrap();
    let sol = &out.solution;
    let prec = Bits::new(256).unwrap();
    let mut area = vec![0.0f64; sol.mesh.n_faces()];
    for (k, t) in uv.refinement.triangles.iter().enumerate() {
        let [a, b, c] = uv.uv[k];
        area[t.final_face.idx()] +=
            0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    }
    // Final lengths at 256 bits, relative to the largest (the layout's scale).
    let logs: Vec<Mpfr> = sol
        .mesh
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let u = sol.u[sol.mesh.tail(h).idx()] + sol.u[sol.mesh.tip(h).idx()];
            Mpfr::from_f64(sol.base_lengths[e.idx()], prec).ln() + Mpfr::from_f64(0.5 * u, prec)
        })
        .collect();
    let top = logs.iter().map(Real::approx_f64).fold(f64::MIN, f64::max);
    let len: Vec<Mpfr> = logs
        .iter()
        .map(|x| (x.clone() - Mpfr::from_f64(top, prec)).exp())
        .collect();
    for f in sol.mesh.faces() {
        let [x, y, z] = sol
            .mesh
            .face_halfedges(f)
            .map(|h| len[h.edge().idx()].clone());
        let p = (x.clone() + y.clone() + z.clone()) * Mpfr::from_f64(0.5, prec);
        let heron = (p.clone() * (p.clone() - x) * (p.clone() - y) * (p - z)).sqrt();
        let h = heron.approx_f64();
        assert!(
            (area[f.idx()] - h).abs() < 1e-9 * h.max(1e-3),
            "face {f:?}: {} vs {h}",
            area[f.idx()]
        );
    }
    let (obj, side) = (uv.obj(), uv.sidecar());
    let report = check_parametrization(&obj, &side).unwrap();
    assert!(report.holds(), "{report:?}");
    // Negative control 1: the first triangle's first UV corner reflected across the line of
    // the other two: a fold, reported with that triangle (and the others sharing that vt).
    let [a, b, c] = uv.uv[0];
    let (dx, dy) = (c[0] - b[0], c[1] - b[1]);
    let lam = ((a[0] - b[0]) * dx + (a[1] - b[1]) * dy) / (dx * dx + dy * dy);
    let foot = [b[0] + lam * dx, b[1] + lam * dy];
    let moved = [2.0 * foot[0] - a[0], 2.0 * foot[1] - a[1]];
    let first_vt = format!("vt {} {}", a[0], a[1]);
    let bad_obj = obj.replacen(&first_vt, &format!("vt {} {}", moved[0], moved[1]), 1);
    // Corners of one wedge share a vt line (B113), so every triangle at that corner moves.
    let r = check_parametrization(&bad_obj, &side).unwrap();
    assert!(r.uv_folds.contains(&0), "{r:?}");
    let moved_vertex = uv.refinement.triangles[0].vertices[0];
    for &k in &r.uv_folds {
        assert!(
            uv.refinement.triangles[k].vertices.contains(&moved_vertex),
            "{r:?}"
        );
    }
    // Negative control 2: a barycentric corner of triangle 0 swapped with another corner's:
    // the triangle turns clockwise in its input face and the face is no longer tiled.
    let mut bad_side = side.clone();
    let rows = bad_side["faces"][0]["barycentric"].as_array_mut().unwrap();
    rows.swap(0, 1);
    let r = check_parametrization(&obj, &bad_side).unwrap();
    assert_eq!(r.input_folds, vec![0], "{r:?}");
    let f_in = u64::from(uv.refinement.triangles[0].input_face.0);
    assert_eq!(r.untiled_faces, vec![f_in], "{r:?}");
    let _ = Face(0);
}

/// The sidecar written face by face (`sidecar_text`) is the same text as the JSON value
/// printed (`sidecar().to_string()`) and as the format built independently here, and the check from text gives the same report as the
/// check from the value, on the good files and on a tampered one (a barycentric row moved).
#[test]
fn b109_sidecar_text_is_the_value_printed_and_checks_the_same() {
    let uv = four_cone_uv();
    let (obj, value, text) = (uv.obj(), uv.sidecar(), uv.sidecar_text().unwrap());
    assert_eq!(text, value.to_string());
    // The format built independently, key by key, from the mesh's fields.
    let rows = |b: &[(usize, f64); 3]| -> Vec<Vec<String>> {
        b.iter()
            .map(|&(r, sigma)| {
                let d = sigma.to_string();
                let mut row = vec!["0".to_string(); 3];
                row[r] = decimal_complement(&d);
                if d != "0" {
                    row[(r + 1) % 3] = d;
                }
                row
            })
            .collect()
    };
    let vertices: Vec<serde_json::Value> = uv
        .refinement
        .vertices
        .iter()
        .map(|v| match *v {
            penner::overlay::refinement::RefinedVertex::Input(w) => {
                serde_json::json!({ "input_vertex": w.0 })
            }
            penner::overlay::refinement::RefinedVertex::Crossing { edge, s, on, t } => {
                serde_json::json!({ "crossing": { "input_edge": edge.0, "s": s.to_string(), "final_edge": on.edge().0, "t": t.to_string() } })
            }
        })
        .collect();
    let faces: Vec<serde_json::Value> = uv
        .refinement
        .triangles
        .iter()
        .zip(&uv.barycentric)
        .map(|(t, b)| serde_json::json!({ "input_face": t.input_face.0, "final_face": t.final_face.0, "barycentric": rows(b) }))
        .collect();
    let oracle = serde_json::json!({ "format": "penner-uv-1", "input_faces": uv.input_faces, "vertices": vertices, "faces": faces });
    assert_eq!(value, oracle);
    assert_eq!(text, oracle.to_string());
    let a = check_parametrization(&obj, &value).unwrap();
    assert!(a.holds());
    assert_eq!(
        penner::overlay::check_parametrization_text(&obj, &text).unwrap(),
        a
    );
    let mut bad = value.clone();
    bad["faces"][0]["barycentric"]
        .as_array_mut()
        .unwrap()
        .swap(0, 1);
    let b = check_parametrization(&obj, &bad).unwrap();
    assert!(!b.holds());
    assert_eq!(
        penner::overlay::check_parametrization_text(&obj, &bad.to_string()).unwrap(),
        b
    );
    // A truncated sidecar is an error, not a report.
    assert!(penner::overlay::check_parametrization_text(&obj, &text[..text.len() / 2]).is_err());
}

/// Typed errors, never panics: a flip whose quadrilateral is not convex in the input metric
/// (what a Ptolemy flip far from a Euclidean one is) is `NotStraight` and changes nothing;
/// a boundary flip is refused; a surface without positions gets no UVs (bad input).
#[test]
fn b108_nonconvex_flip_and_missing_positions_are_typed_errors() {
    use penner::overlay::{TrackError, TrackedOverlay};
    let (t_in, pos, l0, _) = planar_case(2);
    let nonconvex = t_in
        .edges()
        .find(|&e| {
            if t_in.is_boundary_edge(e) {
                return false;
            }
            let [i, j, k, l] = t_in.quad_vertices(e).map(|v| &pos[v.idx()]);
            orient(k, l, i) * orient(k, l, j) > 0
        })
        .expect("a non-convex quadrilateral");
    let mut o = TrackedOverlay::of_input(&t_in, &l0).unwrap();
    let before = o.paths.clone();
    assert!(matches!(
        o.flip(nonconvex),
        Err(TrackError::NotStraight { .. })
    ));
    assert_eq!(o.paths, before);
    assert_eq!(o.mesh, t_in);
    let b = t_in.edges().find(|&e| t_in.is_boundary_edge(e)).unwrap();
    assert!(matches!(o.flip(b), Err(TrackError::Flip(_))));
    assert!(TrackedOverlay::of_input(&t_in, &l0[1..]).is_err());
    // An intrinsic torus: solved, but no 3-D positions to write.
    let t = builders::flat_torus(3, 3).unwrap();
    let s = Surface::from_intrinsic("torus", t).unwrap();
    let n = s.mesh.n_vertices();
    let opts = Options {
        precision: Precision::F64,
        certify: false,
    };
    let out = uniformize_closed(&s, &Targets::flat(n), &opts, &mut |_| {}).unwrap();
    let e = uv_closed(&s, &out).unwrap_err();
    assert!(e.is_bad_input(), "{e}");
}

/// B110: on the four-cone icosahedron (genus 0, cone angles π) every seam segment is a
/// rotation by a multiple of π/2 and a translation within 10⁻⁹; negative control: one
/// UV corner on a seam moved by 10⁻³ of the layout breaks that segment.
#[test]
fn b110_seams_of_quarter_turn_cones_and_a_broken_seam() {
    use penner::overlay::check_seams;
    let uv = four_cone_uv();
    let obj = uv.obj();
    let eps = Rational::from((1, 1_000_000_000u32));
    let r = check_seams(&obj, &eps).unwrap();
    assert!(r.seam_segments > 0 && r.broken.is_empty(), "{r:?}");
    // Move the UV of one corner of a triangle on a seam.
    let faces: Vec<[u32; 3]> = uv.refinement.triangles.iter().map(|t| t.vertices).collect();
    let mut dir = std::collections::BTreeMap::new();
    for (k, f) in faces.iter().enumerate() {
        for i in 0..3 {
            dir.insert((f[i], f[(i + 1) % 3]), (k, i));
        }
    }
    let (k, i) = dir
        .iter()
        .find_map(|(&(a, b), &(k, i))| {
            let &(k2, j) = dir.get(&(b, a))?;
            (uv.uv[k][i] != uv.uv[k2][(j + 1) % 3]).then_some((k, i))
        })
        .expect("a seam");
    let p = uv.uv[k][i];
    let line = format!("vt {} {}", p[0], p[1]);
    let lines: Vec<&str> = obj.lines().collect();
    // One comment line, the v lines, the distinct vt lines, then one f line per triangle:
    // the vt index of corner i of triangle k.
    let f_lines: Vec<&str> = lines
        .iter()
        .copied()
        .filter(|l| l.starts_with("f "))
        .collect();
    let w: usize = f_lines[k]
        .split_whitespace()
        .nth(1 + i)
        .unwrap()
        .split('/')
        .nth(1)
        .unwrap()
        .parse()
        .unwrap();
    let at = 1 + uv.positions.len() + w - 1;
    assert_eq!(lines[at], line, "the vt line of that corner");
    let mut moved: Vec<String> = lines.iter().map(|l| (*l).to_string()).collect();
    moved[at] = format!("vt {} {}", p[0] + 1e-3, p[1]);
    let r = check_seams(&moved.join("\n"), &eps).unwrap();
    assert!(!r.broken.is_empty(), "{r:?}");
}
