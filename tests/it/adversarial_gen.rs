//! Adversarial surfaces for the "valid input never fails" sweep (tests/it/never_fails.rs):
//! every generator returns validated [`Surface`]s with exact metrics, named so that a
//! failure report says which family and parameters produced it.
//!
//! Families: cocircular polygons on rational circles (Pythagorean points; fans, zigzags,
//! random triangulations, closed "pillows" of two triangulations of one polygon), regular
//! polygons rounded to binary64 coordinates, needles and caps of aspect 10⁻³ … 10⁻²⁴,
//! nearly collinear integer triangles, closed solids and cocircular hinges perturbed by
//! 10⁻¹² … 10⁻⁴⁰, exact scalings by 2^k, grids and boxes made of unit squares.
#![allow(dead_code)]

use penner::io::{Metric, Surface};
use penner::mesh::builders::{self, CubeDiagonals, Embedded};
use penner::mesh::Mesh;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::{Integer, Rational};
use std::collections::HashMap;

/// `n/d` exactly.
pub fn q(n: i64, d: i64) -> Rational {
    Rational::from((n, d))
}

/// `10^e` exactly (any sign of `e`).
pub fn pow10(e: i32) -> Rational {
    let p = Rational::from(Integer::from(Integer::u_pow_u(10, e.unsigned_abs())));
    if e >= 0 {
        p
    } else {
        p.recip()
    }
}

/// `2^k` exactly (any sign of `k`).
pub fn pow2(k: i32) -> Rational {
    let p = Rational::from(Integer::from(1) << k.unsigned_abs());
    if k >= 0 {
        p
    } else {
        p.recip()
    }
}

/// A surface from exact positions (squared lengths from the positions), or `None` when the
/// metric is not a valid strict one (a degenerate face).
pub fn from_positions(
    name: &str,
    n: u32,
    faces: &[[u32; 3]],
    pos: Vec<[Rational; 3]>,
) -> Option<Surface> {
    let mesh = Mesh::from_faces(n, faces).ok()?;
    Surface::from_embedded(
        name,
        Embedded {
            mesh,
            positions: pos,
            exact: true,
        },
    )
    .ok()
}

/// A surface from exact lengths on `mesh`, `None` when invalid.
pub fn from_lengths(name: &str, mesh: Mesh, l: Vec<Rational>) -> Option<Surface> {
    Surface::new(name, mesh, Metric::Lengths(l), None).ok()
}

/// The point of the circle of radius `r` about `c` with rational parameter `t`:
/// `c + r((1−t²)/(1+t²), 2t/(1+t²))`, an exactly rational point of a rational circle.
pub fn pythagorean_point(t: &Rational, r: &Rational, c: [&Rational; 2]) -> [Rational; 3] {
    let t2 = Rational::from(t * t);
    let den = Rational::from(1 + &t2);
    let x = Rational::from(1 - &t2) / &den * r + c[0];
    let y = Rational::from(2 * t) / den * r + c[1];
    [x, y, Rational::new()]
}

/// `n` increasing rational parameters `t`, so the points [`pythagorean_point`] are in
/// counter-clockwise order (angle `2 atan t` increases with `t`).
fn increasing_parameters(n: u32, rng: &mut ChaCha8Rng) -> Vec<Rational> {
    let mut t: Vec<Rational> = Vec::new();
    while t.len() < n as usize {
        let den = rng.gen_range(1..=12i64);
        let num = rng.gen_range(-8 * den..=8 * den);
        let x = q(num, den);
        if !t.contains(&x) {
            t.push(x);
        }
    }
    t.sort();
    t
}

/// How to triangulate a convex polygon whose vertices `0..n` are counter-clockwise.
#[derive(Clone, Copy, Debug)]
pub enum PolygonSplit {
    /// The fan from vertex 0.
    Fan,
    /// The zigzag strip `0, n−1, 1, n−2, 2, …`.
    Zigzag,
    /// A random triangulation.
    Random(u64),
}

/// Faces of a convex polygon `0..n` (counter-clockwise): each triangle lists its vertices
/// in increasing order, which is counter-clockwise on a convex polygon.
pub fn polygon_faces(n: u32, split: PolygonSplit) -> Vec<[u32; 3]> {
    let sorted = |mut t: [u32; 3]| {
        t.sort_unstable();
        t
    };
    match split {
        PolygonSplit::Fan => (1..n - 1).map(|i| [0, i, i + 1]).collect(),
        PolygonSplit::Zigzag => {
            let mut order = Vec::new();
            let (mut lo, mut hi) = (0u32, n - 1);
            while lo <= hi {
                order.push(lo);
                if lo != hi {
                    order.push(hi);
                }
                lo += 1;
                hi = hi.saturating_sub(1);
                if hi < lo {
                    break;
                }
            }
            order
                .windows(3)
                .map(|w| sorted([w[0], w[1], w[2]]))
                .collect()
        }
        PolygonSplit::Random(seed) => {
            let poly: Vec<u32> = (0..n).collect();
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            let mut faces = Vec::new();
            crate::meshgen::triangulate_convex_polygon(&poly, false, &mut rng, &mut faces);
            faces.into_iter().map(sorted).collect()
        }
    }
}

/// A convex polygon of `n` Pythagorean points on the circle of radius `r` about `c`
/// (every quadrilateral of two adjacent triangles is exactly cocircular: all its edges are
/// Delaunay ties), triangulated by `split`.
pub fn cocircular_polygon(
    n: u32,
    split: PolygonSplit,
    r: &Rational,
    c: [i64; 2],
    seed: u64,
) -> Option<Surface> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let t = increasing_parameters(n, &mut rng);
    let (cx, cy) = (Rational::from(c[0]), Rational::from(c[1]));
    let pos: Vec<[Rational; 3]> = t
        .iter()
        .map(|t| pythagorean_point(t, r, [&cx, &cy]))
        .collect();
    from_positions(
        &format!("cocircular {n}-gon {split:?} r={r} c={c:?} seed {seed}"),
        n,
        &polygon_faces(n, split),
        pos,
    )
}

/// A closed sphere: two triangulations `top`, `bottom` of one cocircular polygon glued along
/// its boundary (the bottom reversed), lengths only (no positions: the doubled disk is not a
/// planar triangulation). Every vertex is a cone point; every edge is a Delaunay tie or
/// strictly Delaunay.
pub fn cocircular_pillow(
    n: u32,
    top: PolygonSplit,
    bottom: PolygonSplit,
    seed: u64,
) -> Option<Surface> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let t = increasing_parameters(n, &mut rng);
    let (z, one) = (Rational::new(), Rational::from(1));
    let pos: Vec<[Rational; 3]> = t
        .iter()
        .map(|t| pythagorean_point(t, &one, [&z, &z]))
        .collect();
    let mut faces = polygon_faces(n, top);
    faces.extend(polygon_faces(n, bottom).iter().map(|f| [f[0], f[2], f[1]]));
    let flat = from_positions("", n, &faces, pos)?;
    Some(Surface {
        name: format!("cocircular pillow {n}-gon {top:?}/{bottom:?} seed {seed}"),
        positions: None,
        ..flat
    })
}

/// A regular `n`-gon with coordinates `cos(2πk/n)`, `sin(2πk/n)` rounded to binary64 (read
/// exactly): nearly, but not exactly, cocircular. With `center` the wheel around an extra
/// vertex at the origin, else the polygon triangulated by `split`.
pub fn rounded_regular_polygon(n: u32, split: PolygonSplit, center: bool) -> Option<Surface> {
    let mut pos: Vec<[Rational; 3]> = (0..n)
        .map(|k| {
            let a = 2.0 * std::f64::consts::PI * f64::from(k) / f64::from(n);
            [
                Rational::from_f64(a.cos()).unwrap_or_default(),
                Rational::from_f64(a.sin()).unwrap_or_default(),
                Rational::new(),
            ]
        })
        .collect();
    let faces: Vec<[u32; 3]> = if center {
        pos.push([Rational::new(), Rational::new(), Rational::new()]);
        (0..n).map(|k| [n, k, (k + 1) % n]).collect()
    } else {
        polygon_faces(n, split)
    };
    let nv = pos.len() as u32;
    let what = if center {
        "wheel".to_string()
    } else {
        format!("{split:?}")
    };
    from_positions(&format!("rounded regular {n}-gon {what}"), nv, &faces, pos)
}

/// A regular `n`-gon with exactly equal sides as an intrinsic metric: the fan from vertex 0
/// with unit sides and diagonals `d_k = sin(πk/n)/sin(π/n)` rounded to `digits` decimal
/// digits (so the diagonals are only nearly the regular ones: near-ties everywhere).
pub fn regular_fan_lengths(n: u32, digits: u32) -> Option<Surface> {
    let mesh = Mesh::from_faces(n, &polygon_faces(n, PolygonSplit::Fan)).ok()?;
    let scale = 10f64.powi(digits as i32);
    let chord = |k: u32| -> Rational {
        let k = k.min(n - k);
        if k == 1 {
            return Rational::from(1);
        }
        let x = (std::f64::consts::PI * f64::from(k) / f64::from(n)).sin()
            / (std::f64::consts::PI / f64::from(n)).sin();
        Rational::from(((x * scale).round() as i64, scale as i64))
    };
    let l: Vec<Rational> = mesh
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (mesh.tail(h).0, mesh.tip(h).0);
            chord(a.abs_diff(b))
        })
        .collect();
    from_lengths(
        &format!("regular {n}-gon fan, diagonals to {digits} digits"),
        mesh,
        l,
    )
}

/// The hinge: triangles `(0, 1, 2)` and `(0, 2, 3)` sharing the edge `0–2`.
pub fn hinge_mesh() -> Mesh {
    Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap()
}

/// Lengths on `mesh` from the vertex-pair rule `f(a, b)` (`a < b`).
pub fn lengths_by_pair(mesh: &Mesh, f: impl Fn(u32, u32) -> Rational) -> Vec<Rational> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (mesh.tail(h).0, mesh.tip(h).0);
            f(a.min(b), a.max(b))
        })
        .collect()
}

/// Needles and caps of aspect `10^-k`: the triangle with sides `(1, 1, 10^-k)` (a needle)
/// and `(1, ½ + 10^-k, ½ + 10^-k)` (a cap, angle near π), each as the two-triangle sphere
/// and as a hinge (needle or cap opposite a well-shaped triangle), plus the tetrahedron
/// whose base is the needle (apex above the needle's midpoint).
pub fn needles_and_caps(k: i32) -> Vec<Surface> {
    let eps = pow10(-k);
    let half = q(1, 2);
    let mut out = Vec::new();
    let needle = [Rational::from(1), Rational::from(1), eps.clone()];
    let cap = [Rational::from(1), half.clone() + &eps, half.clone() + &eps];
    for (what, tri) in [("needle", &needle), ("cap", &cap)] {
        out.extend(from_lengths(
            &format!("two-triangle sphere, {what} 1e-{k}"),
            builders::two_triangle_sphere(),
            tri.to_vec(),
        ));
        // Hinge: face (0,1,2) has sides 01, 12, 02 = tri; face (0,2,3) shares 02.
        let shared = tri[2].clone();
        let hinge = hinge_mesh();
        let l = lengths_by_pair(&hinge, |a, b| match (a, b) {
            (0, 1) => tri[0].clone(),
            (1, 2) => tri[1].clone(),
            (0, 2) => shared.clone(),
            _ => Rational::from(1),
        });
        out.extend(from_lengths(&format!("hinge, {what} 1e-{k}"), hinge, l));
        // Hinge with the short (needle) or long (cap) side shared by two copies.
        let hinge = hinge_mesh();
        let l = lengths_by_pair(&hinge, |a, b| match (a, b) {
            (0, 2) => tri[2].clone(),
            (0, 1 | 3) => tri[0].clone(),
            _ => tri[1].clone(),
        });
        out.extend(from_lengths(
            &format!("symmetric hinge, {what} 1e-{k}"),
            hinge,
            l,
        ));
    }
    // Tetrahedron on the needle with vertices 0, 1 at distance 10^-k, 2 far, apex 3.
    let tet = builders::tetrahedron().mesh;
    let l = lengths_by_pair(&tet, |a, b| match (a, b) {
        (0, 1) => eps.clone(),
        _ => Rational::from(1),
    });
    out.extend(from_lengths(
        &format!("tetrahedron on a needle 1e-{k}"),
        tet,
        l,
    ));
    out
}

/// Nearly collinear integer triangles: `(0,0)`, `(p, p−1)`, `(2p+1, 2p−1)` with
/// `p = 10^k`: the determinant is 1 so the area is ½ while the sides are ~10^k (aspect
/// ~10^-2k). As a single triangle, the two-triangle sphere (lengths from the positions)
/// and a hinge with a fourth point on the far side.
pub fn nearly_collinear(k: u32) -> Vec<Surface> {
    let p = Integer::from(Integer::u_pow_u(10, k));
    let r = |x: &Integer| Rational::from(x);
    let a = [Rational::new(), Rational::new(), Rational::new()];
    let b = [r(&p), r(&(p.clone() - 1)), Rational::new()];
    // det((p, p−1), (2p+1, 2p−1)) = p(2p−1) − (p−1)(2p+1) = 1.
    let c = [
        r(&(2 * p.clone() + 1)),
        r(&(2 * p.clone() - 1)),
        Rational::new(),
    ];
    let d = [r(&p), r(&(p.clone() + 1)), Rational::new()];
    let mut out = Vec::new();
    out.extend(from_positions(
        &format!("nearly collinear triangle p=1e{k}"),
        3,
        &[[0, 1, 2]],
        vec![a.clone(), b.clone(), c.clone()],
    ));
    // Point d = (p, p+1) lies on the other side of segment a–c from b: a convex
    // quadrilateral, both faces counter-clockwise.
    out.extend(from_positions(
        &format!("nearly collinear hinge p=1e{k}"),
        4,
        &[[0, 1, 2], [0, 2, 3]],
        vec![a.clone(), b.clone(), c.clone(), d],
    ));
    if let Some(s) = from_positions("", 3, &[[0, 1, 2]], vec![a, b, c]) {
        out.extend(Surface::new(
            format!("nearly collinear two-triangle sphere p=1e{k}"),
            builders::two_triangle_sphere(),
            reorder_triangle_metric(&s),
            None,
        ));
    }
    out
}

/// The three squared lengths of a one-triangle surface, keyed onto the two-triangle
/// sphere's edges by vertex pair.
fn reorder_triangle_metric(s: &Surface) -> Metric {
    let by_pair = pair_values(s);
    let sphere = builders::two_triangle_sphere();
    Metric::SquaredLengths(lengths_by_pair(&sphere, |a, b| by_pair[&(a, b)].clone()))
}

/// The metric's values keyed by sorted vertex pair (meshes without multi-edges).
pub fn pair_values(s: &Surface) -> HashMap<(u32, u32), Rational> {
    let v = s.metric.values();
    s.mesh
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (s.mesh.tail(h).0, s.mesh.tip(h).0);
            ((a.min(b), a.max(b)), v[e.idx()].clone())
        })
        .collect()
}

/// Closed solids with unit lengths (regular tetrahedron, octahedron, icosahedron) and the
/// cocircular 3-4-5 hinges (a rectangle split by a diagonal: a Delaunay tie), with a random
/// third of their lengths moved by `±10^-k` (exactly).
pub fn perturbed(k: i32, seed: u64) -> Vec<Surface> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ (k as u64).wrapping_mul(0x9e37));
    let d = pow10(-k);
    let mut bump = |l: Vec<Rational>| -> Vec<Rational> {
        l.into_iter()
            .map(|x| match rng.gen_range(0..6) {
                0 => x + &d,
                1 => x - &d,
                _ => x,
            })
            .collect()
    };
    let mut out = Vec::new();
    for (name, mesh) in [
        ("regular tetrahedron", builders::tetrahedron().mesh),
        ("regular octahedron", builders::octahedron().mesh),
        ("regular icosahedron", builders::icosahedron().mesh),
    ] {
        let l = bump(vec![Rational::from(1); mesh.n_edges()]);
        out.extend(from_lengths(
            &format!("{name} ±1e-{k} seed {seed}"),
            mesh,
            l,
        ));
    }
    // The 3-4-5 rectangle 0(0,0) 1(4,0) 2(4,3) 3(0,3), diagonal 0–2 of length 5.
    let hinge = hinge_mesh();
    let base = lengths_by_pair(&hinge, |a, b| match (a, b) {
        (0, 2) => Rational::from(5),
        (0, 1) | (2, 3) => Rational::from(4),
        _ => Rational::from(3),
    });
    out.extend(from_lengths(
        &format!("3-4-5 rectangle hinge ±1e-{k} seed {seed}"),
        hinge.clone(),
        bump(base.clone()),
    ));
    // The same rectangle closed up: the top split by 0–2, the bottom by 1–3 (a sphere of
    // four faces, both diagonals of length 5).
    let pillow = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]);
    if let Ok(pm) = pillow {
        let l = lengths_by_pair(&pm, |a, b| match (a, b) {
            (0, 2) | (1, 3) => Rational::from(5),
            (0, 1) | (2, 3) => Rational::from(4),
            _ => Rational::from(3),
        });
        out.extend(from_lengths(
            &format!("3-4-5 rectangle pillow ±1e-{k} seed {seed}"),
            pm,
            bump(l),
        ));
    }
    out
}

/// The surface scaled exactly by `2^k`: lengths by `2^k`, squared lengths by `2^{2k}`,
/// positions by `2^k`.
pub fn scaled_by_pow2(s: &Surface, k: i32) -> Surface {
    let f = pow2(k);
    let f2 = pow2(2 * k);
    let metric = match &s.metric {
        Metric::Lengths(v) => Metric::Lengths(v.iter().map(|x| Rational::from(x * &f)).collect()),
        Metric::SquaredLengths(v) => {
            Metric::SquaredLengths(v.iter().map(|x| Rational::from(x * &f2)).collect())
        }
    };
    let positions = s
        .positions
        .as_ref()
        .map(|p| p.iter().map(|x| x.clone().map(|c| c * &f)).collect());
    Surface {
        name: format!("{} × 2^{k}", s.name),
        mesh: s.mesh.clone(),
        metric,
        positions,
    }
}

/// The closed surface of the box `[0,a]×[0,b]×[0,c]` made of unit squares, each split by a
/// diagonal (`random` picks each diagonal at random, else all parallel), with integer
/// positions: every square is a cocircular quadrilateral (a Delaunay tie).
pub fn voxel_box(a: i64, b: i64, c: i64, random: Option<u64>) -> Option<Surface> {
    let mut rng = ChaCha8Rng::seed_from_u64(random.unwrap_or(0));
    let mut ids: HashMap<[i64; 3], u32> = HashMap::new();
    let mut pos: Vec<[Rational; 3]> = Vec::new();
    let mut faces: Vec<[u32; 3]> = Vec::new();
    let mut id = |p: [i64; 3], pos: &mut Vec<[Rational; 3]>| -> u32 {
        *ids.entry(p).or_insert_with(|| {
            pos.push(p.map(Rational::from));
            (pos.len() - 1) as u32
        })
    };
    let dims = [a, b, c];
    // For each axis `n` and side (0 or far), the two other axes (u, v) with u × v = ±n.
    for n in 0..3 {
        let (u, v) = ((n + 1) % 3, (n + 2) % 3);
        for far in [false, true] {
            for i in 0..dims[u] {
                for j in 0..dims[v] {
                    let corner = |di: i64, dj: i64| {
                        let mut p = [0i64; 3];
                        p[n] = if far { dims[n] } else { 0 };
                        p[u] = i + di;
                        p[v] = j + dj;
                        p
                    };
                    let q00 = id(corner(0, 0), &mut pos);
                    let q10 = id(corner(1, 0), &mut pos);
                    let q11 = id(corner(1, 1), &mut pos);
                    let q01 = id(corner(0, 1), &mut pos);
                    // e_u × e_v = +e_n: counter-clockwise seen from +n, outward on the far side.
                    let (p0, p1, p2, p3) = if far {
                        (q00, q10, q11, q01)
                    } else {
                        (q00, q01, q11, q10)
                    };
                    let diag = random.is_none_or(|_| rng.gen_bool(0.5));
                    if diag {
                        faces.push([p0, p1, p2]);
                        faces.push([p0, p2, p3]);
                    } else {
                        faces.push([p0, p1, p3]);
                        faces.push([p1, p2, p3]);
                    }
                }
            }
        }
    }
    let what = random.map_or("parallel diagonals".to_string(), |s| {
        format!("random diagonals seed {s}")
    });
    let n = pos.len() as u32;
    let s = from_positions("", n, &faces, pos)?;
    // Positions are not coplanar, so the planar checks do not apply; keep them for T20.
    Some(Surface {
        name: format!("voxel box {a}×{b}×{c}, {what}"),
        ..s
    })
}

/// Planar grids: the builder's grid disk, and integer rectangle grids `n × n` of `wx × wy`
/// cells with random diagonals (every cell a cocircular quadrilateral).
pub fn grids(n: u32, seed: u64) -> Vec<Surface> {
    let mut out = Vec::new();
    if let Ok(g) = builders::grid_disk(n, n) {
        out.extend(Surface::from_embedded(format!("grid disk {n}×{n}"), g).ok());
    }
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (wx, wy) = (rng.gen_range(1..=5i64), rng.gen_range(1..=5i64));
    let side = n + 1;
    let vid = |i: u32, j: u32| j * side + i;
    let pos: Vec<[Rational; 3]> = (0..side)
        .flat_map(|j| {
            (0..side).map(move |i| {
                [
                    Rational::from(i64::from(i) * wx),
                    Rational::from(i64::from(j) * wy),
                    Rational::new(),
                ]
            })
        })
        .collect();
    let faces = crate::meshgen::split_squares(n, vid, &mut rng);
    out.extend(from_positions(
        &format!("rect grid {n}×{n} of {wx}×{wy} cells seed {seed}"),
        side * side,
        &faces,
        pos,
    ));
    out
}

/// The cube of the builders with both diagonal patterns (every square face a tie).
pub fn cubes() -> Vec<Surface> {
    [CubeDiagonals::Even]
        .into_iter()
        .filter_map(|d| Surface::from_embedded(format!("cube {d:?}"), builders::cube(d)).ok())
        .collect()
}
