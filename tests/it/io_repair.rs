//! Repairs of OBJ/OFF input (`penner::io::repair`): polygon faces triangulated in their
//! plane or as a non-folding fan, orientation made consistent, unreferenced vertices
//! dropped — each only when asked, each reported by line. The checks use exact vector
//! areas computed here, independently of the repair's own predicates: a triangulation of a
//! planar polygon tiles it when its triangles' vector areas are all positive multiples of
//! the polygon's normal and sum to the polygon's vector area (Newell).

use crate::support::{assert_refused, penner, scratch, text, write};
use penner::io::repair::{repair, Repairs};
use penner::io::{obj, off, ReadError};
use rug::Rational;

type P3 = [Rational; 3];

fn point(s: &[&str; 3]) -> P3 {
    s.map(|x| penner::scalar::parse_rational(x).expect("coordinate"))
}

fn minus(a: &P3, b: &P3) -> P3 {
    [
        Rational::from(&a[0] - &b[0]),
        Rational::from(&a[1] - &b[1]),
        Rational::from(&a[2] - &b[2]),
    ]
}

fn cross(a: &P3, b: &P3) -> P3 {
    [
        Rational::from(&a[1] * &b[2]) - Rational::from(&a[2] * &b[1]),
        Rational::from(&a[2] * &b[0]) - Rational::from(&a[0] * &b[2]),
        Rational::from(&a[0] * &b[1]) - Rational::from(&a[1] * &b[0]),
    ]
}

fn dot(a: &P3, b: &P3) -> Rational {
    Rational::from(&a[0] * &b[0]) + Rational::from(&a[1] * &b[1]) + Rational::from(&a[2] * &b[2])
}

/// Twice the vector area of the polygon `p` (shoelace in 3-D).
fn vector_area(p: &[P3]) -> P3 {
    let mut n = [Rational::new(), Rational::new(), Rational::new()];
    for i in 0..p.len() {
        let c = cross(&p[i], &p[(i + 1) % p.len()]);
        for a in 0..3 {
            n[a] += &c[a];
        }
    }
    n
}

/// Whether `triangles` (vertex ids into `pts`) tile the planar polygon `polygon`: every
/// triangle's vector area points along the polygon's (positive dot product, zero cross
/// product) and they sum to the polygon's vector area.
fn tiles(polygon: &[P3], pts: &[P3], triangles: &[[usize; 3]]) -> bool {
    let whole = vector_area(polygon);
    let mut sum = [Rational::new(), Rational::new(), Rational::new()];
    for t in triangles {
        let a = vector_area(&[pts[t[0]].clone(), pts[t[1]].clone(), pts[t[2]].clone()]);
        let parallel = cross(&a, &whole).iter().all(|x| *x == 0);
        if !parallel || dot(&a, &whole) <= 0 {
            return false;
        }
        for k in 0..3 {
            sum[k] += &a[k];
        }
    }
    sum == whole
}

/// A planar hexagon with a reflex corner (an L-shape), in the plane z = x + y.
const L_SHAPE: [[&str; 3]; 6] = [
    ["0", "0", "0"],
    ["2", "0", "2"],
    ["2", "1", "3"],
    ["1", "1", "2"],
    ["1", "2", "3"],
    ["0", "2", "2"],
];

fn off_of(points: &[[&str; 3]], faces: &[Vec<u32>]) -> String {
    use std::fmt::Write;
    let mut s = format!("OFF\n{} {} 0\n", points.len(), faces.len());
    for p in points {
        let _ = writeln!(s, "{} {} {}", p[0], p[1], p[2]);
    }
    for f in faces {
        s += &f.len().to_string();
        for v in f {
            let _ = write!(s, " {v}");
        }
        s += "\n";
    }
    s
}

fn faces_of(soup: &penner::io::soup::PolygonSoup) -> Vec<Vec<u32>> {
    (0..soup.n_faces()).map(|f| soup.face(f).to_vec()).collect()
}

#[test]
fn a_reflex_planar_polygon_is_tiled_and_a_folded_split_is_not() {
    let text = off_of(&L_SHAPE, &[(0..6).collect()]);
    let soup = off::read_polygons(&text).expect("read");
    let (fixed, log) = repair(soup, &Repairs::ALL).expect("repair");
    assert_eq!(log.planar, vec![(9, 6)], "{log}");
    assert!(log.fans.is_empty());
    let pts: Vec<P3> = L_SHAPE.iter().map(point).collect();
    let tris: Vec<[usize; 3]> = faces_of(&fixed)
        .iter()
        .map(|f| [f[0] as usize, f[1] as usize, f[2] as usize])
        .collect();
    assert_eq!(tris.len(), 4);
    assert!(tiles(&pts, &pts, &tris), "{tris:?}");
    // Negative control: the fan from corner 1 passes outside the reflex corner 3 and folds.
    let fan: Vec<[usize; 3]> = (1..5).map(|t| [1, (1 + t) % 6, (2 + t) % 6]).collect();
    assert!(!tiles(&pts, &pts, &fan));
}

#[test]
fn a_convex_planar_quad_is_split_along_its_delaunay_diagonal() {
    // A kite: diagonal 0–2 is long; the angles at 1 and 3 opposite it sum to more than π,
    // so the Delaunay diagonal is 1–3 (its opposite angles at 0 and 2 sum to less than π).
    let kite = [
        ["0", "0", "0"],
        ["2", "-1", "0"],
        ["6", "0", "0"],
        ["2", "1", "0"],
    ];
    let soup = off::read_polygons(&off_of(&kite, &[vec![0, 1, 2, 3]])).expect("read");
    let (fixed, log) = repair(soup, &Repairs::ALL).expect("repair");
    assert_eq!(log.planar.len(), 1);
    let faces = faces_of(&fixed);
    let uses = |a: u32, b: u32| faces.iter().all(|f| f.contains(&a) && f.contains(&b));
    assert!(uses(1, 3), "{faces:?}");
    assert!(!uses(0, 2), "{faces:?}");
    // Independent: the angles opposite 1–3 at 0 and 2 sum to less than π, those opposite
    // 0–2 at 1 and 3 to more (law of cosines on the exact squared lengths).
    let angle = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| {
        let (u, v) = ([a[0] - o[0], a[1] - o[1]], [b[0] - o[0], b[1] - o[1]]);
        ((u[0] * v[0] + u[1] * v[1]) / (u[0].hypot(u[1]) * v[0].hypot(v[1]))).acos()
    };
    let p = [[0.0, 0.0], [2.0, -1.0], [6.0, 0.0], [2.0, 1.0]];
    let opposite_13 = angle(p[0], p[1], p[3]) + angle(p[2], p[1], p[3]);
    let opposite_02 = angle(p[1], p[0], p[2]) + angle(p[3], p[0], p[2]);
    assert!(
        opposite_13 < 3.0 && opposite_02 > 3.3,
        "{opposite_13} {opposite_02}"
    );
}

#[test]
fn a_twisted_quad_is_split_as_a_fan_and_reported_non_planar() {
    let twisted = [
        ["0", "0", "0"],
        ["1", "0", "0"],
        ["1", "1", "1/2"],
        ["0", "1", "0"],
    ];
    let soup = off::read_polygons(&off_of(&twisted, &[vec![0, 1, 2, 3]])).expect("read");
    let (fixed, log) = repair(soup, &Repairs::ALL).expect("repair");
    assert_eq!(log.fans, vec![(7, 4)]);
    assert!(log.planar.is_empty());
    assert_eq!(fixed.n_faces(), 2);
    // The two triangles' normals make an acute angle (no fold), checked here exactly.
    let pts: Vec<P3> = twisted.iter().map(point).collect();
    let n: Vec<P3> = faces_of(&fixed)
        .iter()
        .map(|f| {
            let p = |k: usize| &pts[f[k] as usize];
            cross(&minus(p(1), p(0)), &minus(p(2), p(0)))
        })
        .collect();
    assert!(dot(&n[0], &n[1]) > 0);
}

/// The cube as six quads (OFF), lines 3–10 vertices, 11–16 faces.
fn quad_cube() -> String {
    let v = [
        ["0", "0", "0"],
        ["1", "0", "0"],
        ["1", "1", "0"],
        ["0", "1", "0"],
        ["0", "0", "1"],
        ["1", "0", "1"],
        ["1", "1", "1"],
        ["0", "1", "1"],
    ];
    let f = [
        vec![0, 3, 2, 1],
        vec![4, 5, 6, 7],
        vec![0, 1, 5, 4],
        vec![1, 2, 6, 5],
        vec![2, 3, 7, 6],
        vec![3, 0, 4, 7],
    ];
    off_of(&v, &f)
}

#[test]
fn polygon_faces_are_refused_unless_triangulation_is_asked_for() {
    let text = quad_cube();
    match off::read(&text) {
        Err(ReadError::NotTriangle { element, count }) => {
            assert_eq!((element.as_str(), count), ("line 11", 4));
        }
        other => panic!("expected NotTriangle, got {other:?}"),
    }
    let soup = off::read_polygons(&text).expect("read");
    let (fixed, log) = repair(soup, &Repairs::ALL).expect("repair");
    assert_eq!(log.planar.len(), 6);
    let s = fixed.into_surface().expect("surface").into_surface();
    assert_eq!(s.mesh.n_faces(), 12);
    assert_eq!(s.mesh.euler_characteristic(), 2);
}

#[test]
fn a_reversed_face_is_turned_and_reported_by_its_line() {
    // Tetrahedron, OBJ, face on line 8 written clockwise.
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 3 4\n";
    let err = obj::read(text).expect_err("inconsistent orientation");
    assert!(matches!(err, ReadError::Mesh { .. }), "{err}");
    let soup = obj::read_polygons(text).expect("read");
    let (fixed, log) = repair(soup, &Repairs::ALL).expect("repair");
    assert_eq!(log.reversed, vec![8], "{log}");
    let s = fixed.into_surface().expect("surface").into_surface();
    assert_eq!(s.mesh.euler_characteristic(), 2);
}

#[test]
fn a_moebius_strip_cannot_be_oriented_and_the_error_names_a_cycle() {
    // A triangulated Möbius strip: 6 vertices around, the ends glued with a half twist.
    let text = "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 1\n\
                f 1 2 5\nf 1 5 4\nf 2 3 6\nf 2 6 5\nf 3 4 1\nf 3 1 6\n";
    let soup = obj::read_polygons(text).expect("read");
    let err = repair(soup, &Repairs::ALL).expect_err("non-orientable");
    let msg = err.to_string();
    assert!(matches!(err, ReadError::CannotRepair { .. }), "{msg}");
    assert!(
        msg.contains("not orientable") && msg.contains("lines"),
        "{msg}"
    );
}

#[test]
fn unreferenced_vertices_are_dropped_and_reported() {
    let text = "v 0 0 0\nv 9 9 9\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 4 3\nf 1 3 5\nf 3 4 5\nf 4 1 5\n";
    assert!(obj::read(text).is_err(), "an isolated vertex is refused");
    let soup = obj::read_polygons(text).expect("read");
    let (fixed, log) = repair(soup, &Repairs::ALL).expect("repair");
    assert_eq!(log.dropped, vec![2]);
    let s = fixed.into_surface().expect("surface").into_surface();
    assert_eq!(s.mesh.n_vertices(), 4);
    assert_eq!(s.mesh.euler_characteristic(), 2);
}

#[test]
fn cli_names_the_repair_and_applies_it_only_when_asked() {
    let dir = scratch("repair");
    let cube = write(&dir, "cube.off", quad_cube().as_bytes());
    let path = cube.to_str().expect("path");
    let refused = penner(&["check", path, "--only", "T01", "--precision", "f64"]);
    assert_refused(&refused, 3, &["line 11", "--triangulate"]);
    let fixed = penner(&[
        "check",
        path,
        "--only",
        "T01",
        "--precision",
        "f64",
        "--repair",
    ]);
    let err = text(&fixed.stderr);
    assert_eq!(fixed.status.code(), Some(0), "{err}{}", text(&fixed.stdout));
    assert!(
        err.contains("repaired: triangulated 6 planar polygon face(s)"),
        "{err}"
    );
    let d = penner(&["delaunay", path, "--precision", "f64", "--triangulate"]);
    assert_eq!(d.status.code(), Some(0), "{}", text(&d.stderr));
}

/// A quadrilateral bent by more than 90° along both diagonals (Suzanne's, line 1190 of the
/// OBJ in github.com/alecjacobson/common-3d-test-models: its triangles' normals make 96°
/// along 0–2 and 103° along 1–3) is split along the diagonal bending least and reported
/// as creased; the control, a bow-tie whose two splits both give opposite normals (the
/// triangles on the diagonal overlap), is still refused.
#[test]
fn a_quad_bent_past_ninety_degrees_is_split_along_the_least_bent_diagonal() {
    let bent = [
        ["-2.369062", "1.025123", "4.853892"],
        ["-2.330000", "1.009498", "4.814830"],
        ["-2.369062", "1.150123", "4.916392"],
        ["-2.392500", "1.103248", "4.846080"],
    ];
    let soup = off::read_polygons(&off_of(&bent, &[vec![0, 1, 2, 3]])).expect("read");
    let (fixed, log) = repair(soup, &Repairs::ALL).expect("repair");
    assert_eq!(log.creased, vec![(7, 4)], "{log}");
    assert!(log.fans.is_empty() && log.planar.is_empty());
    assert!(log.to_string().contains("bent by more than 90°"), "{log}");
    // The diagonal 0–2, computed here in binary64 from the coordinates.
    let p: Vec<[f64; 3]> = bent
        .iter()
        .map(|c| c.map(|x| x.parse::<f64>().unwrap()))
        .collect();
    let n = |a: usize, b: usize, c: usize| {
        let (u, v) = (
            [0, 1, 2].map(|k| p[b][k] - p[a][k]),
            [0, 1, 2].map(|k| p[c][k] - p[a][k]),
        );
        [
            u[1] * v[2] - u[2] * v[1],
            u[2] * v[0] - u[0] * v[2],
            u[0] * v[1] - u[1] * v[0],
        ]
    };
    let cos = |x: [f64; 3], y: [f64; 3]| {
        let d: f64 = (0..3).map(|k| x[k] * y[k]).sum();
        let nn = |z: [f64; 3]| (0..3).map(|k| z[k] * z[k]).sum::<f64>().sqrt();
        d / (nn(x) * nn(y))
    };
    let (c02, c13) = (cos(n(0, 1, 2), n(0, 2, 3)), cos(n(1, 2, 3), n(1, 3, 0)));
    assert!(c02 < 0.0 && c13 < 0.0 && c02 > c13, "{c02} {c13}");
    let faces = faces_of(&fixed);
    assert!(
        faces.iter().all(|f| f.contains(&0) && f.contains(&2)),
        "{faces:?}"
    );
    // Control: a bow-tie, whose splits both put opposite normals on the diagonal.
    let bowtie = [
        ["0", "0", "0"],
        ["2", "0", "0"],
        ["1", "1", "0"],
        ["1", "-1", "0"],
    ];
    let soup = off::read_polygons(&off_of(&bowtie, &[vec![0, 1, 2, 3]])).expect("read");
    let err = repair(soup, &Repairs::ALL).expect_err("overlapping triangles");
    assert!(matches!(err, ReadError::CannotRepair { .. }), "{err}");
}

/// Two quadrilaterals sharing two sides and so two opposite corners (Suzanne's eyelid,
/// lines 1170–1171 of the OBJ in github.com/alecjacobson/common-3d-test-models: vertices
/// 71, 197, 139, 138 and 71, 138, 139, 198) are split so that no edge joins the same two
/// vertices twice: each alone is split along the shared corners 0–2 (the control: the two
/// choices made independently give the edge 0→2 twice in one direction, a non-manifold
/// edge), together the second takes its other diagonal and every directed edge is used once.
#[test]
fn two_quads_sharing_opposite_corners_are_not_both_split_between_them() {
    let v = [
        ["-2.494062", "1.064186", "4.900767"],
        ["-2.455000", "1.126686", "4.885142"],
        ["-2.494062", "1.111061", "4.846080"],
        ["-2.494062", "1.056373", "4.853892"],
        ["-2.533125", "1.126686", "4.885142"],
    ];
    let (a, b) = (vec![0, 1, 2, 3], vec![0, 3, 2, 4]);
    let split = |faces: &[Vec<u32>]| {
        let soup = off::read_polygons(&off_of(&v, faces)).expect("read");
        // Triangulation only: vertex numbers kept (no unreferenced vertex dropped).
        let only = Repairs {
            triangulate: true,
            ..Repairs::default()
        };
        faces_of(&repair(soup, &only).expect("repair").0)
    };
    let joins_0_2 = |f: &Vec<u32>| f.contains(&0) && f.contains(&2);
    for q in [&a, &b] {
        let alone = split(std::slice::from_ref(q));
        assert!(alone.iter().all(joins_0_2), "control: {alone:?}");
    }
    let both = split(&[a, b]);
    assert_eq!(both.len(), 4);
    let mut directed: Vec<(u32, u32)> = both
        .iter()
        .flat_map(|f| (0..3).map(move |s| (f[s], f[(s + 1) % 3])))
        .collect();
    directed.sort_unstable();
    let n = directed.len();
    directed.dedup();
    assert_eq!(directed.len(), n, "{both:?}");
    assert_eq!(both.iter().filter(|f| joins_0_2(f)).count(), 2, "{both:?}");
}
