//! The standard surfaces: platonic solids, cubes, triakis solids, Δ-complexes, genus-g
//! polygons, grids, annuli, flat tori, random triangulations and planar point sets.
//!
//! Where a surface has a natural embedding the builder returns an [`Embedded`] surface:
//! the mesh plus exact rational vertex positions, so a metric can come from the embedding
//! (its squared edge lengths are then exact rationals). [`Embedded::exact`] says whether
//! the positions are the ideal ones (integer coordinates) or rounded from an irrational
//! ideal (the icosahedron's golden ratio, the annulus's cos/sin); in the rounded case the
//! positions are still exact rationals (the binary64 values), so the metric they induce is
//! exactly that of a slightly perturbed solid.
//!
//! ```
//! use penner::mesh::builders;
//! let ico = builders::icosahedron();
//! assert_eq!((ico.mesh.n_vertices(), ico.mesh.n_edges(), ico.mesh.n_faces()), (12, 30, 20));
//! let g2 = builders::genus(2).unwrap();
//! assert_eq!(g2.euler_characteristic(), -2);
//! ```

use super::{Edge, Face, Mesh, MeshError};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;
use std::collections::HashMap;
use std::hash::Hash;

/// A mesh with vertex positions in ℝ³ (exact rationals; see the module documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct Embedded {
    /// The triangulation.
    pub mesh: Mesh,
    /// Position of each vertex, indexed by `Vertex.idx()`.
    pub positions: Vec<[Rational; 3]>,
    /// `true` if the positions are the ideal ones, `false` if rounded from irrationals.
    pub exact: bool,
}

/// A mesh with an intrinsic metric given by exact squared edge lengths (no embedding in
/// ℝ³ is implied).
#[derive(Clone, Debug, PartialEq)]
pub struct Intrinsic {
    /// The triangulation.
    pub mesh: Mesh,
    /// Squared length of each edge, indexed by `Edge.idx()`.
    pub squared_lengths: Vec<Rational>,
}

/// Why a parametric builder refused its arguments.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum BuildError {
    /// A size parameter is below the minimum the construction needs.
    #[error("{parameter} = {value} is below the minimum {min}")]
    TooSmall {
        /// Parameter name.
        parameter: &'static str,
        /// Value given.
        value: u64,
        /// Smallest allowed value.
        min: u64,
    },
    /// The surface would have more than [`MAX_FACES`] faces.
    #[error("the surface would have {faces} faces, more than the limit {MAX_FACES}")]
    TooLarge {
        /// Number of faces requested.
        faces: u64,
    },
    /// A planar point is not finite or outside the range the triangulator accepts.
    #[error("point {index} has a non-finite or out-of-range coordinate")]
    BadPoint {
        /// Position in the input.
        index: usize,
    },
    /// A planar point repeats an earlier one.
    #[error("point {index} repeats an earlier point")]
    DuplicatePoint {
        /// Position in the input.
        index: usize,
    },
    /// The planar points span no triangle (fewer than three, or all collinear).
    #[error("the points span no triangle (fewer than three, or all collinear)")]
    Degenerate,
    /// The connectivity was refused (e.g. removing a face would pinch a vertex).
    #[error(transparent)]
    Mesh(#[from] MeshError),
}

/// Largest number of faces a parametric builder produces (2²⁴).
pub const MAX_FACES: u64 = 1 << 24;

fn check_faces(faces: u64) -> Result<(), BuildError> {
    if faces > MAX_FACES {
        Err(BuildError::TooLarge { faces })
    } else {
        Ok(())
    }
}

fn at_least(parameter: &'static str, value: u32, min: u32) -> Result<(), BuildError> {
    if value < min {
        Err(BuildError::TooSmall {
            parameter,
            value: u64::from(value),
            min: u64::from(min),
        })
    } else {
        Ok(())
    }
}

fn int_point(p: [i64; 3]) -> [Rational; 3] {
    p.map(Rational::from)
}

fn f64_point(p: [f64; 3]) -> [Rational; 3] {
    // The builders only produce finite coordinates.
    p.map(|x| Rational::from_f64(x).unwrap_or_default())
}

/// det[a, b, c]: positive iff triangle abc is counter-clockwise seen from outside a
/// convex polyhedron centred at the origin.
fn det_i(a: [i64; 3], b: [i64; 3], c: [i64; 3]) -> i64 {
    a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
        + a[2] * (b[0] * c[1] - b[1] * c[0])
}

fn orient_outward_i(p: &[[i64; 3]], t: [u32; 3]) -> [u32; 3] {
    let [a, b, c] = t.map(|v| p[v as usize]);
    if det_i(a, b, c) > 0 {
        t
    } else {
        [t[0], t[2], t[1]]
    }
}

/// Faces of a centred convex polyhedron whose faces are the triangles of mutually
/// adjacent vertices, adjacency being squared distance `edge2`.
fn triangles_of_adjacency(p: &[[i64; 3]], edge2: i64) -> Vec<[u32; 3]> {
    let d2 = |a: [i64; 3], b: [i64; 3]| (0..3).map(|k| (a[k] - b[k]).pow(2)).sum::<i64>();
    let n = p.len() as u32;
    let adj = |a: u32, b: u32| d2(p[a as usize], p[b as usize]) == edge2;
    let mut faces = Vec::new();
    for a in 0..n {
        for b in a + 1..n {
            for c in b + 1..n {
                if adj(a, b) && adj(b, c) && adj(a, c) {
                    faces.push(orient_outward_i(p, [a, b, c]));
                }
            }
        }
    }
    faces
}

fn embedded_int(p: &[[i64; 3]], faces: &[[u32; 3]]) -> Embedded {
    let mesh = Mesh::from_faces(p.len() as u32, faces).expect("fixed polyhedron is a surface");
    Embedded {
        mesh,
        positions: p.iter().map(|&q| int_point(q)).collect(),
        exact: true,
    }
}

const TET: [[i64; 3]; 4] = [[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]];
const OCT: [[i64; 3]; 6] = [
    [1, 0, 0],
    [-1, 0, 0],
    [0, 1, 0],
    [0, -1, 0],
    [0, 0, 1],
    [0, 0, -1],
];

/// Regular tetrahedron at `(1,1,1), (1,−1,−1), (−1,1,−1), (−1,−1,1)`: V, E, F = 4, 6, 4.
pub fn tetrahedron() -> Embedded {
    embedded_int(&TET, &triangles_of_adjacency(&TET, 8))
}

/// Regular octahedron at `±e_x, ±e_y, ±e_z`: V, E, F = 6, 12, 8.
pub fn octahedron() -> Embedded {
    embedded_int(&OCT, &triangles_of_adjacency(&OCT, 2))
}

/// Regular icosahedron at the cyclic permutations of `(0, ±1, ±φ)`, φ = (1+√5)/2:
/// V, E, F = 12, 30, 20. φ is irrational, so the positions are the binary64 roundings
/// ([`Embedded::exact`] is `false`): exact rationals of a slightly irregular icosahedron.
pub fn icosahedron() -> Embedded {
    // Combinatorics from the exact model with φ ↦ 2 (same adjacency: squared distance 4
    // among the 12 points (0, ±1, ±2)-cyclic is the edge length of that model).
    let mut model = Vec::new();
    let mut pos = Vec::new();
    let phi = f64::midpoint(1.0, 5f64.sqrt());
    for s1 in [1i64, -1] {
        for s2 in [1i64, -1] {
            for k in 0..3 {
                let mut m = [0i64; 3];
                m[(k + 1) % 3] = s1;
                m[(k + 2) % 3] = 2 * s2;
                model.push(m);
                let mut q = [0f64; 3];
                q[(k + 1) % 3] = s1 as f64;
                q[(k + 2) % 3] = s2 as f64 * phi;
                pos.push(q);
            }
        }
    }
    // In the φ ↦ 2 model, icosahedron edges are exactly the pairs at squared distance 4
    // (pairs (0,1,2)–(0,−1,2)) or 6 (pairs (0,1,2)–(1,2,0)); non-edges are at 8 or more.
    let d2 = |a: [i64; 3], b: [i64; 3]| (0..3).map(|k| (a[k] - b[k]).pow(2)).sum::<i64>();
    let n = model.len() as u32;
    let adj = |a: u32, b: u32| matches!(d2(model[a as usize], model[b as usize]), 4 | 6);
    let mut faces = Vec::new();
    for a in 0..n {
        for b in a + 1..n {
            for c in b + 1..n {
                if adj(a, b) && adj(b, c) && adj(a, c) {
                    // Orientation from the true positions: every face plane is at
                    // distance ≈ 1.51 from the centre, so |det| is far from 0.
                    let [pa, pb, pc] = [a, b, c].map(|v| pos[v as usize]);
                    let det = pa[0] * (pb[1] * pc[2] - pb[2] * pc[1])
                        - pa[1] * (pb[0] * pc[2] - pb[2] * pc[0])
                        + pa[2] * (pb[0] * pc[1] - pb[1] * pc[0]);
                    faces.push(if det > 0.0 { [a, b, c] } else { [a, c, b] });
                }
            }
        }
    }
    let mesh = Mesh::from_faces(n, &faces).expect("icosahedron is a surface");
    Embedded {
        mesh,
        positions: pos.into_iter().map(f64_point).collect(),
        exact: false,
    }
}

/// Which diagonal splits each square face of the cube.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CubeDiagonals {
    /// Diagonals join the vertices with even coordinate sum (they form a regular
    /// tetrahedron); those four vertices get degree 6, the others degree 3.
    Even,
    /// Diagonals join the vertices with odd coordinate sum.
    Odd,
}

/// The cube `{−1, 1}³` with each square split into two triangles by the diagonal of the
/// chosen family: V, E, F = 8, 18, 12. Vertex `x + 2y + 4z` (bits) sits at `(2x−1, 2y−1, 2z−1)`.
pub fn cube(diagonals: CubeDiagonals) -> Embedded {
    let p: Vec<[i64; 3]> = (0..8)
        .map(|v: i64| {
            [
                2 * (v & 1) - 1,
                2 * ((v >> 1) & 1) - 1,
                2 * ((v >> 2) & 1) - 1,
            ]
        })
        .collect();
    let quads: [[u32; 4]; 6] = [
        [0, 1, 3, 2],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 3, 7, 6],
        [0, 2, 6, 4],
        [1, 3, 7, 5],
    ];
    let want_even = diagonals == CubeDiagonals::Even;
    let mut faces = Vec::new();
    for q in quads {
        let even = q[0].count_ones() % 2 == 0;
        let [a, b, c, d] = if even == want_even {
            q
        } else {
            [q[1], q[2], q[3], q[0]]
        };
        faces.push(orient_outward_i(&p, [a, b, c]));
        faces.push(orient_outward_i(&p, [a, c, d]));
    }
    embedded_int(&p, &faces)
}

/// Replace every face `abc` of a centred convex solid by `abp, bcp, cap` with apex
/// `p = 2·centroid` (coordinates scaled by 3 to stay integral).
fn triakis(p: &[[i64; 3]], faces: &[[u32; 3]]) -> Embedded {
    let mut pts: Vec<[i64; 3]> = p.iter().map(|q| q.map(|x| 3 * x)).collect();
    let mut out = Vec::new();
    for &[a, b, c] in faces {
        let apex = pts.len() as u32;
        let s = [0, 1, 2].map(|k| p[a as usize][k] + p[b as usize][k] + p[c as usize][k]);
        pts.push(s.map(|x| 2 * x));
        out.extend([[a, b, apex], [b, c, apex], [c, a, apex]]);
    }
    embedded_int(&pts, &out)
}

/// Triakis (stellated) tetrahedron: a degree-3 apex over each face of the tetrahedron,
/// at twice the face centroid (positions scaled by 3): V, E, F = 8, 18, 12.
pub fn triakis_tetrahedron() -> Embedded {
    triakis(&TET, &triangles_of_adjacency(&TET, 8))
}

/// Triakis (stellated) octahedron: a degree-3 apex over each face of the octahedron, at
/// twice the face centroid (positions scaled by 3): V, E, F = 14, 36, 24.
pub fn triakis_octahedron() -> Embedded {
    triakis(&OCT, &triangles_of_adjacency(&OCT, 2))
}

/// The sphere made of two triangles glued along their boundaries (a Δ-complex that is
/// not a simplicial complex): faces `012` and `021`, V, E, F = 3, 3, 2.
pub fn two_triangle_sphere() -> Mesh {
    Mesh::from_faces(3, &[[0, 1, 2], [0, 2, 1]]).expect("two-triangle sphere")
}

/// The one-vertex torus: a square with opposite sides glued, cut by one diagonal.
/// V, E, F = 1, 3, 2; every edge is a loop. Equals [`genus`]`(1)`.
pub fn one_vertex_torus() -> Mesh {
    Mesh::from_gluing(
        1,
        &[[0, 0, 0], [0, 0, 0]],
        &[((0, 0), (1, 0)), ((0, 1), (1, 1)), ((0, 2), (1, 2))],
    )
    .expect("one-vertex torus")
}

/// The closed orientable surface of genus `g ≥ 1` from the 4g-gon with side word
/// `a₁b₁a₁⁻¹b₁⁻¹ ⋯ a_g b_g a_g⁻¹ b_g⁻¹`, fan-triangulated from polygon corner 0. All
/// corners become one vertex: V, E, F = 1, 6g − 3, 4g − 2, χ = 2 − 2g. A Δ-complex whose
/// edges are all loops.
pub fn genus(g: u32) -> Result<Mesh, BuildError> {
    at_least("genus", g, 1)?;
    check_faces(4 * u64::from(g) - 2)?;
    let n = 4 * g; // polygon sides; triangle t = (p0, p_{t+1}, p_{t+2}), t = 0..n-2
    let nt = n - 2;
    let faces = vec![[0u32; 3]; nt as usize];
    // Polygon side i as a face side.
    let side = |i: u32| -> (u32, u8) {
        if i == 0 {
            (0, 0)
        } else if i == n - 1 {
            (nt - 1, 2)
        } else {
            (i - 1, 1)
        }
    };
    let mut gluing = Vec::new();
    for t in 1..nt {
        gluing.push(((t, 0), (t - 1, 2)));
    }
    for k in 0..g {
        gluing.push((side(4 * k), side(4 * k + 2)));
        gluing.push((side(4 * k + 1), side(4 * k + 3)));
    }
    Ok(Mesh::from_gluing(1, &faces, &gluing)?)
}

/// Build a Δ-complex where face sides carrying equal keys are glued (each key on at most
/// two sides, which must run in opposite directions).
fn glue_by_keys<K: Hash + Eq + Copy>(
    n_vertices: u32,
    faces: &[[u32; 3]],
    keys: &[[K; 3]],
) -> Result<Mesh, MeshError> {
    let mut first: HashMap<K, (u32, u8)> = HashMap::new();
    let mut gluing = Vec::new();
    for (f, ks) in keys.iter().enumerate() {
        for (s, &k) in ks.iter().enumerate() {
            let here = (f as u32, s as u8);
            if let Some(other) = first.remove(&k) {
                gluing.push((other, here));
            } else {
                first.insert(k, here);
            }
        }
    }
    Mesh::from_gluing(n_vertices, faces, &gluing)
}

/// Grid keys: horizontal, vertical and diagonal unit segments starting at a grid point.
#[derive(Clone, Copy, Hash, PartialEq, Eq)]
enum Seg {
    H(u32, u32),
    V(u32, u32),
    D(u32, u32),
}

/// The `m × n` grid of unit squares, each cut by the diagonal `(i,j)–(i+1,j+1)`, wrapped
/// `m`-periodically in x if `wrap_x` and `n`-periodically in y if `wrap_y`. Returns
/// faces, side keys and the vertex count; vertex `(i, j)` has id `i + (m or m+1)·j`.
fn grid(m: u32, n: u32, wrap_x: bool, wrap_y: bool) -> (u32, Vec<[u32; 3]>, Vec<[Seg; 3]>) {
    let (cx, cy) = (
        if wrap_x { m } else { m + 1 },
        if wrap_y { n } else { n + 1 },
    );
    let wx = |i: u32| if wrap_x { i % m } else { i };
    let wy = |j: u32| if wrap_y { j % n } else { j };
    let id = |i: u32, j: u32| wx(i) + cx * wy(j);
    let mut faces = Vec::new();
    let mut keys = Vec::new();
    for j in 0..n {
        for i in 0..m {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            faces.push([a, b, c]);
            keys.push([
                Seg::H(wx(i), wy(j)),
                Seg::V(wx(i + 1), wy(j)),
                Seg::D(wx(i), wy(j)),
            ]);
            faces.push([a, c, d]);
            keys.push([
                Seg::D(wx(i), wy(j)),
                Seg::H(wx(i), wy(j + 1)),
                Seg::V(wx(i), wy(j)),
            ]);
        }
    }
    (cx * cy, faces, keys)
}

/// A disk: the `m × n` grid of unit squares in the plane z = 0, each cut by its
/// `(i,j)–(i+1,j+1)` diagonal. Vertex `i + (m+1)j` sits at `(i, j, 0)`. V, E, F =
/// (m+1)(n+1), 3mn + m + n, 2mn. Needs m, n ≥ 1.
pub fn grid_disk(m: u32, n: u32) -> Result<Embedded, BuildError> {
    at_least("m", m, 1)?;
    at_least("n", n, 1)?;
    check_faces(2 * u64::from(m) * u64::from(n))?;
    let (nv, faces, keys) = grid(m, n, false, false);
    let mesh = glue_by_keys(nv, &faces, &keys)?;
    let positions = (0..nv)
        .map(|v| int_point([i64::from(v % (m + 1)), i64::from(v / (m + 1)), 0]))
        .collect();
    Ok(Embedded {
        mesh,
        positions,
        exact: true,
    })
}

/// An annulus: `m ≥ 3` vertices around each of `n + 1 ≥ 2` concentric rings in the plane
/// z = 0 (ring j has radius 1 + j; vertex `i + mj` at angle −2πi/m, so faces are
/// counter-clockwise), consecutive rings
/// joined by `m` squares cut diagonally. V, E, F = m(n+1), m(3n+1), 2mn; two boundary
/// loops. Positions are binary64 roundings of cos/sin ([`Embedded::exact`] is `false`).
pub fn annulus(m: u32, n: u32) -> Result<Embedded, BuildError> {
    at_least("m", m, 3)?;
    at_least("n", n, 1)?;
    check_faces(2 * u64::from(m) * u64::from(n))?;
    let (nv, faces, keys) = grid(m, n, true, false);
    let mesh = glue_by_keys(nv, &faces, &keys)?;
    let positions = (0..nv)
        .map(|v| {
            let (i, j) = (v % m, v / m);
            let t = -std::f64::consts::TAU * f64::from(i) / f64::from(m);
            let r = 1.0 + f64::from(j);
            f64_point([r * t.cos(), r * t.sin(), 0.0])
        })
        .collect();
    Ok(Embedded {
        mesh,
        positions,
        exact: false,
    })
}

/// The flat torus ℝ²/(mℤ × nℤ) triangulated by the unit grid with `(i,j)–(i+1,j+1)`
/// diagonals, with its flat metric: squared lengths 1 (grid edges) and 2 (diagonals).
/// Every vertex has degree 6 and zero curvature. V, E, F = mn, 3mn, 2mn. Any m, n ≥ 1 (for
/// m or n < 3 it is a Δ-complex with loops or multi-edges; `flat_torus(1, 1)` is the
/// one-vertex torus).
pub fn flat_torus(m: u32, n: u32) -> Result<Intrinsic, BuildError> {
    at_least("m", m, 1)?;
    at_least("n", n, 1)?;
    check_faces(2 * u64::from(m) * u64::from(n))?;
    let (nv, faces, keys) = grid(m, n, true, true);
    let mesh = glue_by_keys(nv, &faces, &keys)?;
    let mut squared_lengths = vec![Rational::new(); mesh.n_edges()];
    for (f, ks) in keys.iter().enumerate() {
        let hs = mesh.face_halfedges(Face(f as u32));
        for (h, k) in hs.iter().zip(ks) {
            let l2 = if matches!(k, Seg::D(..)) { 2 } else { 1 };
            squared_lengths[h.edge().idx()] = Rational::from(l2);
        }
    }
    Ok(Intrinsic {
        mesh,
        squared_lengths,
    })
}

/// Apply `n_flips` attempts at flipping a uniformly random edge (seeded ChaCha8);
/// attempts on unflippable edges (boundary, same face on both sides) are skipped. V, E,
/// F, χ and the boundary are unchanged (T02).
pub fn random_flips(base: &Mesh, n_flips: usize, seed: u64) -> Mesh {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut m = base.clone();
    for _ in 0..n_flips {
        let e = Edge(rng.gen_range(0..m.n_edges() as u32));
        let _ = m.flip(e);
    }
    m
}

/// A random closed surface of genus `g` with `n_vertices` vertices: start from the
/// two-triangle sphere (g = 0, needs ≥ 3 vertices) or [`genus`]`(g)` (one vertex), insert
/// vertices in random faces ([`Mesh::split_face`]) and then flip `3E` random edges.
/// Usually a Δ-complex (loops and multi-edges are allowed).
pub fn random_surface(g: u32, n_vertices: u32, seed: u64) -> Result<Mesh, BuildError> {
    let (mut m, min) = if g == 0 {
        (two_triangle_sphere(), 3)
    } else {
        (genus(g)?, 1)
    };
    at_least("n_vertices", n_vertices, min)?;
    check_faces(m.n_faces() as u64 + 2 * u64::from(n_vertices))?;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    while (m.n_vertices() as u32) < n_vertices {
        let f = Face(rng.gen_range(0..m.n_faces() as u32));
        m.split_face(f).map_err(|_| BuildError::TooLarge {
            faces: m.n_faces() as u64,
        })?;
    }
    let flips = 3 * m.n_edges();
    Ok(random_flips(&m, flips, rng.r#gen()))
}

/// Remove face `f`, making a hole (a new boundary loop, or enlarging one). Refused with a
/// [`MeshError`] when the result would not be a surface, e.g. when two corners of `f`
/// are at one vertex or a corner's vertex would be pinched.
pub fn remove_face(mesh: &Mesh, f: Face) -> Result<Mesh, BuildError> {
    let faces = mesh.face_list();
    if f.idx() >= faces.len() {
        return Err(MeshError::GluingOutOfRange {
            index: 0,
            face: f.0,
            side: 0,
        }
        .into());
    }
    let renumber = |g: u32| if g > f.0 { g - 1 } else { g };
    let gluing: Vec<_> = mesh
        .gluing_list()
        .into_iter()
        .filter(|&((a, _), (b, _))| a != f.0 && b != f.0)
        .map(|((a, s), (b, t))| ((renumber(a), s), (renumber(b), t)))
        .collect();
    let mut kept = faces;
    kept.remove(f.idx());
    Ok(Mesh::from_gluing(mesh.n_vertices() as u32, &kept, &gluing)?)
}

/// Delaunay triangulation (by `spade`) of distinct planar points, as a disk with the
/// convex hull as boundary. Vertex `i` is `points[i]`, placed at `(x, y, 0)` with exact
/// rational coordinates. Refuses non-finite or out-of-range coordinates (|x| outside
/// spade's `[2⁻¹⁴², 2²⁰¹]` other than 0), repeated points and collinear sets.
pub fn planar_points(points: &[[f64; 2]]) -> Result<Embedded, BuildError> {
    use spade::{DelaunayTriangulation, Point2, Triangulation};
    check_faces(2 * points.len() as u64)?;
    let mut dt: DelaunayTriangulation<Point2<f64>> = DelaunayTriangulation::new();
    for (index, p) in points.iter().enumerate() {
        let before = dt.num_vertices();
        let h = dt
            .insert(Point2::new(p[0], p[1]))
            .map_err(|_| BuildError::BadPoint { index })?;
        if dt.num_vertices() == before || h.index() != index {
            return Err(BuildError::DuplicatePoint { index });
        }
    }
    let faces: Vec<[u32; 3]> = dt
        .inner_faces()
        .map(|f| f.vertices().map(|v| v.fix().index() as u32))
        .collect();
    if faces.is_empty() {
        return Err(BuildError::Degenerate);
    }
    let mesh = Mesh::from_faces(points.len() as u32, &faces)?;
    let positions = points
        .iter()
        .map(|p| f64_point([p[0], p[1], 0.0]))
        .collect();
    Ok(Embedded {
        mesh,
        positions,
        exact: true,
    })
}

/// `n ≥ 3` random planar points with integer coordinates in `[0, 2²⁰)²` (seeded
/// ChaCha8; repeats redrawn, collinear draws redrawn), triangulated by
/// [`planar_points`].
pub fn random_planar(n: u32, seed: u64) -> Result<Embedded, BuildError> {
    at_least("n", n, 3)?;
    check_faces(2 * u64::from(n))?;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    loop {
        let mut seen = std::collections::HashSet::new();
        let mut pts = Vec::with_capacity(n as usize);
        while pts.len() < n as usize {
            let p: (u32, u32) = (rng.gen_range(0..1 << 20), rng.gen_range(0..1 << 20));
            if seen.insert(p) {
                pts.push([f64::from(p.0), f64::from(p.1)]);
            }
        }
        match planar_points(&pts) {
            Err(BuildError::Degenerate) => {}
            r => return r,
        }
    }
}
