//! Procedural meshes for the Delaunay tests and benchmarks: noisy subdivided icospheres,
//! sheared tori of thin triangles, jittered planar grids. Lengths come from 3D or 2D
//! positions, so every triangle satisfies the triangle inequality.
#![allow(dead_code)]

use penner::mesh::Mesh;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::HashMap;
use std::f64::consts::PI;

/// A triangle mesh with vertex positions.
pub struct Embedded {
    /// Vertex positions.
    pub pos: Vec<[f64; 3]>,
    /// Counter-clockwise faces.
    pub faces: Vec<[u32; 3]>,
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn norm(a: [f64; 3]) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

impl Embedded {
    /// The half-edge mesh.
    pub fn mesh(&self) -> Mesh {
        Mesh::from_faces(self.pos.len() as u32, &self.faces).unwrap()
    }
    /// Euclidean edge lengths of `mesh` (built by [`Embedded::mesh`]).
    pub fn lengths(&self, mesh: &Mesh) -> Vec<f64> {
        mesh.edges()
            .map(|e| {
                let h = e.halfedge();
                norm(sub(
                    self.pos[mesh.tail(h).idx()],
                    self.pos[mesh.tip(h).idx()],
                ))
            })
            .collect()
    }
    /// Mean edge length over face sides.
    pub fn mean_edge(&self) -> f64 {
        let mut s = 0.0;
        for f in &self.faces {
            for k in 0..3 {
                s += norm(sub(
                    self.pos[f[k] as usize],
                    self.pos[f[(k + 1) % 3] as usize],
                ));
            }
        }
        s / (3 * self.faces.len()) as f64
    }
    /// Move every vertex by a uniform random vector of length ≤ `amount`.
    pub fn jitter(&mut self, amount: f64, seed: u64) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        for p in &mut self.pos {
            for c in p.iter_mut() {
                *c += amount * rng.gen_range(-1.0..1.0) / 3f64.sqrt();
            }
        }
    }
    /// Add independent normal noise of standard deviation `sigma` to every coordinate of
    /// every vertex (Box–Muller on a seeded ChaCha stream). With `sigma = 0.3 ×` mean edge
    /// length this is the "noisy icosphere" of the Delaunay benchmarks.
    pub fn jitter_normal(&mut self, sigma: f64, seed: u64) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        for p in &mut self.pos {
            for c in p.iter_mut() {
                // u1 ∈ (0, 1] so that ln u1 is finite.
                let u1: f64 = 1.0 - rng.r#gen::<f64>();
                let u2: f64 = rng.r#gen();
                *c += sigma * (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos();
            }
        }
    }
    /// Move every vertex along its position vector: `p ← p·(1 + amount·U(−1, 1))`, one
    /// uniform draw per vertex from a seeded ChaCha stream (radial noise on a sphere).
    pub fn jitter_radial(&mut self, amount: f64, seed: u64) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        for p in &mut self.pos {
            let r = 1.0 + amount * rng.gen_range(-1.0..1.0);
            *p = p.map(|c| c * r);
        }
    }
    /// Write as OFF to `out`: coordinates with 17 significant digits (`{:.16e}`, which
    /// round-trips every binary64 value), faces `3 a b c`, 0-based.
    pub fn write_off(&self, out: &mut impl std::io::Write) -> std::io::Result<()> {
        writeln!(out, "OFF\n{} {} 0", self.pos.len(), self.faces.len())?;
        for p in &self.pos {
            writeln!(out, "{:.16e} {:.16e} {:.16e}", p[0], p[1], p[2])?;
        }
        for f in &self.faces {
            writeln!(out, "3 {} {} {}", f[0], f[1], f[2])?;
        }
        Ok(())
    }
    /// Write as Wavefront OBJ.
    pub fn obj(&self) -> String {
        use std::fmt::Write;
        let mut s = String::new();
        for p in &self.pos {
            let _ = writeln!(s, "v {} {} {}", p[0], p[1], p[2]);
        }
        for f in &self.faces {
            let _ = writeln!(s, "f {} {} {}", f[0] + 1, f[1] + 1, f[2] + 1);
        }
        s
    }
}

/// Icosahedron subdivided with frequency `k` (20k² faces), projected to the unit sphere.
pub fn icosphere(k: u32) -> Embedded {
    let t = f64::midpoint(1.0, 5f64.sqrt());
    let base = [
        [-1.0, t, 0.0],
        [1.0, t, 0.0],
        [-1.0, -t, 0.0],
        [1.0, -t, 0.0],
        [0.0, -1.0, t],
        [0.0, 1.0, t],
        [0.0, -1.0, -t],
        [0.0, 1.0, -t],
        [t, 0.0, -1.0],
        [t, 0.0, 1.0],
        [-t, 0.0, -1.0],
        [-t, 0.0, 1.0],
    ];
    let tris: [[usize; 3]; 20] = [
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    let mut pos = Vec::new();
    let mut index: HashMap<[i64; 3], u32> = HashMap::new();
    let mut faces = Vec::new();
    let kf = f64::from(k);
    for tri in tris {
        let [a, b, c] = tri.map(|i| base[i]);
        let mut id = |i: u32, j: u32| -> u32 {
            // Point a + (b−a)·i/k + (c−a)·j/k, normalized; deduplicated by quantized key.
            let (fi, fj) = (f64::from(i) / kf, f64::from(j) / kf);
            let p: [f64; 3] =
                std::array::from_fn(|d| a[d] * (1.0 - fi - fj) + b[d] * fi + c[d] * fj);
            let n = norm(p);
            let p = p.map(|x| x / n);
            let key = p.map(|x| (x * 1e9).round() as i64);
            *index.entry(key).or_insert_with(|| {
                pos.push(p);
                (pos.len() - 1) as u32
            })
        };
        for i in 0..k {
            for j in 0..k - i {
                let (p, q, r) = (id(i, j), id(i + 1, j), id(i, j + 1));
                faces.push([p, q, r]);
                if i + j + 1 < k {
                    let s = id(i + 1, j + 1);
                    faces.push([q, s, r]);
                }
            }
        }
    }
    Embedded { pos, faces }
}

/// A torus (radii 1 and 0.3) from an `n × m` grid whose diagonals are sheared by `shear`
/// columns per row: long thin triangles.
pub fn sheared_torus(n: u32, m: u32, shear: u32) -> Embedded {
    let mut pos = Vec::new();
    for j in 0..m {
        for i in 0..n {
            let a = std::f64::consts::TAU * f64::from(i) / f64::from(n);
            let b = std::f64::consts::TAU * f64::from(j) / f64::from(m);
            let r = 1.0 + 0.3 * b.cos();
            pos.push([r * a.cos(), r * a.sin(), 0.3 * b.sin()]);
        }
    }
    let v = |i: u32, j: u32| (j % m) * n + (i % n);
    let mut faces = Vec::new();
    for j in 0..m {
        for i in 0..n {
            // Quadrilateral (i, j), (i+1, j), (i+1+s, j+1), (i+s, j+1) split along a diagonal.
            let (p, q) = (v(i, j), v(i + 1, j));
            let (r, s) = (v(i + 1 + shear, j + 1), v(i + shear, j + 1));
            faces.push([p, q, r]);
            faces.push([p, r, s]);
        }
    }
    Embedded { pos, faces }
}

/// An `n × n` grid on the unit square (boundary points on the square's sides), interior
/// points jittered by `jitter` cells, diagonals chosen at random: a planar triangulation
/// with convex boundary that is generally not Delaunay.
pub fn planar_grid(n: u32, jitter: f64, seed: u64) -> Embedded {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let h = 1.0 / f64::from(n);
    let mut pos = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            let (mut x, mut y) = (f64::from(i) * h, f64::from(j) * h);
            if i > 0 && i < n {
                x += jitter * h * rng.gen_range(-1.0..1.0);
            }
            if j > 0 && j < n {
                y += jitter * h * rng.gen_range(-1.0..1.0);
            }
            pos.push([x, y, 0.0]);
        }
    }
    let faces = split_squares(n, |i, j| j * (n + 1) + i, &mut rng);
    Embedded { pos, faces }
}

/// The boundary of a tetrahedron with random positive vertex positions: closed, genus 0.
pub fn random_tetrahedron(seed: u64) -> Embedded {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let pos = (0..4)
        .map(|_| [rng.r#gen(), rng.r#gen(), rng.r#gen()])
        .collect::<Vec<[f64; 3]>>();
    // Orient faces outward-consistently (the orientation only needs to be consistent).
    Embedded {
        pos,
        faces: vec![[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]],
    }
}

/// A triangulated torus grid `nu × nv` embedded in ℝ³ with jittered vertices; edge
/// lengths are Euclidean distances (so every triangle inequality holds).
pub fn jittered_torus(nu: u32, nv: u32, seed: u64) -> (Mesh, Vec<f64>) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let id = |i: u32, j: u32| (i % nu) * nv + (j % nv);
    let mut faces = Vec::new();
    for i in 0..nu {
        for j in 0..nv {
            faces.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            faces.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    let mesh = Mesh::from_faces(nu * nv, &faces).expect("valid torus");
    let pos: Vec<[f64; 3]> = (0..nu * nv)
        .map(|k| {
            let (i, j) = (k / nv, k % nv);
            let u = 2.0 * PI * (f64::from(i) + rng.gen_range(-0.2..0.2)) / f64::from(nu);
            let v = 2.0 * PI * (f64::from(j) + rng.gen_range(-0.2..0.2)) / f64::from(nv);
            let r = 1.0 + 0.4 * v.cos();
            [r * u.cos(), r * u.sin(), 0.4 * v.sin()]
        })
        .collect();
    let len = mesh
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let (p, q) = (pos[mesh.tail(h).idx()], pos[mesh.tip(h).idx()]);
            ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
        })
        .collect();
    (mesh, len)
}

// ---------------------------------------------------------------------------------------
// Adversarial families (tests/it/delaunay_adversarial.rs): cocircular polygons and lattice
// grids, and marching-tetrahedra sliver surfaces.

/// Append to `faces` a triangulation of the convex polygon `poly` (vertex ids in
/// counter-clockwise order): the triangle on the side `poly[0]–poly[last]` has apex
/// `poly[k]`, `k` random (or `k = 1` when `fan`, a fan around the last vertex), and the
/// two polygons on either side of it are triangulated the same way. Every face is
/// counter-clockwise.
pub fn triangulate_convex_polygon(
    poly: &[u32],
    fan: bool,
    rng: &mut ChaCha8Rng,
    faces: &mut Vec<[u32; 3]>,
) {
    if poly.len() < 3 {
        return;
    }
    let last = poly.len() - 1;
    let k = if fan { 1 } else { rng.gen_range(1..last) };
    faces.push([poly[0], poly[k], poly[last]]);
    triangulate_convex_polygon(&poly[..=k], fan, rng, faces);
    triangulate_convex_polygon(&poly[k..], fan, rng, faces);
}

/// A convex `n`-gon with vertices `0..n` counter-clockwise, triangulated as the fan from
/// vertex 0 (`fan`) or at random: with the vertices on a circle, every quadrilateral of
/// two adjacent triangles is cocircular.
pub fn polygon_mesh(n: u32, fan: bool, seed: u64) -> Mesh {
    let mut faces = Vec::new();
    if fan {
        faces.extend((1..n - 1).map(|i| [0, i, i + 1]));
    } else {
        let poly: Vec<u32> = (0..n).collect();
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        triangulate_convex_polygon(&poly, false, &mut rng, &mut faces);
    }
    Mesh::from_faces(n, &faces).unwrap()
}

/// Rational chord lengths of a cyclic `n`-gon (unit circumradius, vertices `0..n`
/// counter-clockwise): vertex `k` sits at angle `2φ_k` with
/// `cos φ_k = (1−t²)/(1+t²)`, `sin φ_k = 2t/(1+t²)` for the rational `t = t_k ≈
/// tan(π(k+½)/(2n))` (to 1/1000), so the chord `2|sin(φ_k − φ_m)|` between `k` and `m` is
/// rational and every quadrilateral is exactly cocircular. One length per edge of `mesh`.
pub fn rational_cyclic_lengths(mesh: &Mesh, n: u32) -> Vec<rug::Rational> {
    use rug::Rational;
    let t: Vec<Rational> = (0..n)
        .map(|k| {
            let x = (PI * (f64::from(k) + 0.5) / (2.0 * f64::from(n))).tan();
            Rational::from(((x * 1000.0).round() as i64, 1000))
        })
        .collect();
    assert!(t.windows(2).all(|w| w[0] < w[1]), "angles must increase");
    let cs: Vec<(Rational, Rational)> = t
        .iter()
        .map(|t| {
            let t2 = Rational::from(t * t);
            let den = Rational::from(1 + &t2);
            (Rational::from(1 - &t2) / &den, Rational::from(2 * t) / den)
        })
        .collect();
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let ((ca, sa), (cb, sb)) = (&cs[mesh.tail(h).idx()], &cs[mesh.tip(h).idx()]);
            let s = Rational::from(sa * cb) - Rational::from(ca * sb);
            2 * s.abs()
        })
        .collect()
}

/// The lattice whose integer coordinates a [`LatticeMesh`] uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lattice {
    /// Cartesian `(wx·i, wy·j)`: a grid of congruent `wx × wy` rectangles.
    Rect {
        /// Cell width.
        wx: i64,
        /// Cell height.
        wy: i64,
    },
    /// The equilateral triangular lattice `i·(1, 0) + j·(½, √3/2)`.
    Triangular,
}

/// A planar triangulation of lattice points, faces counter-clockwise.
pub struct LatticeMesh {
    /// The lattice of the coordinates.
    pub lattice: Lattice,
    /// Integer lattice coordinates of each vertex.
    pub coords: Vec<[i64; 2]>,
    /// Counter-clockwise faces.
    pub faces: Vec<[u32; 3]>,
}

impl LatticeMesh {
    /// The half-edge mesh.
    pub fn mesh(&self) -> Mesh {
        Mesh::from_faces(self.coords.len() as u32, &self.faces).unwrap()
    }
    /// Integer coordinates `(X, Y)` with Cartesian position `(X, Y·√w)/s`: `w = 1, s = 1`
    /// for rectangles, `X = 2i + j`, `Y = j`, `w = 3`, `s = 2` for the triangular lattice.
    /// Orientation signs are those of the Cartesian points (a positive linear map).
    pub fn scaled(&self, p: [i64; 2]) -> ([i64; 2], i64) {
        match self.lattice {
            Lattice::Rect { wx, wy } => ([wx * p[0], wy * p[1]], 1),
            Lattice::Triangular => ([2 * p[0] + p[1], p[1]], 3),
        }
    }
    /// The exact squared length of the lattice vector from `p` to `q` (an integer: the
    /// triangular lattice's `a² + ab + b²`, a rectangle's `(wx·a)² + (wy·b)²`).
    pub fn norm2(&self, p: [i64; 2], q: [i64; 2]) -> i64 {
        let (a, b) = (q[0] - p[0], q[1] - p[1]);
        match self.lattice {
            Lattice::Rect { wx, wy } => (wx * a).pow(2) + (wy * b).pow(2),
            Lattice::Triangular => a * a + a * b + b * b,
        }
    }
    /// Exact squared edge lengths of `mesh` (built by [`LatticeMesh::mesh`]).
    pub fn squared_lengths(&self, mesh: &Mesh) -> Vec<i64> {
        mesh.edges()
            .map(|e| {
                let h = e.halfedge();
                self.norm2(
                    self.coords[mesh.tail(h).idx()],
                    self.coords[mesh.tip(h).idx()],
                )
            })
            .collect()
    }
    /// Cartesian positions in f64, rotated by `theta` and shifted by `shift`.
    pub fn positions(&self, theta: f64, shift: [f64; 2]) -> Vec<[f64; 2]> {
        let (s, c) = theta.sin_cos();
        self.coords
            .iter()
            .map(|p| {
                let (x, y) = match self.lattice {
                    Lattice::Rect { wx, wy } => ((wx * p[0]) as f64, (wy * p[1]) as f64),
                    Lattice::Triangular => (
                        p[0] as f64 + 0.5 * p[1] as f64,
                        p[1] as f64 * 3f64.sqrt() / 2.0,
                    ),
                };
                [c * x - s * y + shift[0], s * x + c * y + shift[1]]
            })
            .collect()
    }
}

/// Orientation of three lattice points in [`LatticeMesh::scaled`] coordinates (the sign
/// is the Cartesian orientation's).
pub fn lattice_orient(lm: &LatticeMesh, a: u32, b: u32, c: u32) -> i64 {
    let p = |v: u32| lm.scaled(lm.coords[v as usize]).0;
    let (a, b, c) = (p(a), p(b), p(c));
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// The integer incircle determinant of lattice points `a, b, c, d` in
/// [`LatticeMesh::scaled`] coordinates: positive iff `d` lies inside the circle through the
/// counter-clockwise `a, b, c`, zero iff the four are cocircular (for the triangular
/// lattice the Cartesian determinant is `√3/16` times it).
pub fn lattice_incircle(lm: &LatticeMesh, a: u32, b: u32, c: u32, d: u32) -> i128 {
    let (pd, w) = lm.scaled(lm.coords[d as usize]);
    let w = i128::from(w);
    let r = |v: u32| {
        let p = lm.scaled(lm.coords[v as usize]).0;
        let (x, y) = (i128::from(p[0] - pd[0]), i128::from(p[1] - pd[1]));
        (x, y, x * x + w * y * y)
    };
    let (ax, ay, a2) = r(a);
    let (bx, by, b2) = r(b);
    let (cx, cy, c2) = r(c);
    ax * (by * c2 - b2 * cy) - ay * (bx * c2 - b2 * cx) + a2 * (bx * cy - by * cx)
}

/// An `n × n` grid of `wx × wy` rectangles, each cut along a random diagonal (every
/// diagonal is then a cocircular tie).
pub fn rect_lattice_grid(n: i64, wx: i64, wy: i64, seed: u64) -> LatticeMesh {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let coords: Vec<[i64; 2]> = (0..=n).flat_map(|j| (0..=n).map(move |i| [i, j])).collect();
    let v = |i: i64, j: i64| (j * (n + 1) + i) as u32;
    let mut faces = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let (a, b, c, d) = (v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1));
            if rng.gen_bool(0.5) {
                faces.extend([[a, b, c], [a, c, d]]);
            } else {
                faces.extend([[a, b, d], [b, c, d]]);
            }
        }
    }
    LatticeMesh {
        lattice: Lattice::Rect { wx, wy },
        coords,
        faces,
    }
}

/// The equilateral triangulation of the `(n+1) × (n+1)` parallelogram of triangular
/// lattice points (every face equilateral, no quadrilateral cocircular).
pub fn triangular_lattice_grid(n: i64) -> LatticeMesh {
    let coords: Vec<[i64; 2]> = (0..=n).flat_map(|j| (0..=n).map(move |i| [i, j])).collect();
    let v = |i: i64, j: i64| (j * (n + 1) + i) as u32;
    let mut faces = Vec::new();
    for j in 0..n {
        for i in 0..n {
            faces.push([v(i, j), v(i + 1, j), v(i, j + 1)]);
            faces.push([v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)]);
        }
    }
    LatticeMesh {
        lattice: Lattice::Triangular,
        coords,
        faces,
    }
}

/// The honeycomb: the triangular lattice with the sublattice `i ≡ j (mod 3)` removed.
/// Each removed point with `1 ≤ i, j < n` leaves a regular hexagon of its six neighbours
/// (cocircular), triangulated at random; the hexagons tile a region of the plane, so
/// every diagonal inside a hexagon is a tie and every side between two hexagons is
/// strictly Delaunay.
pub fn honeycomb(n: i64, seed: u64) -> LatticeMesh {
    const RING: [[i64; 2]; 6] = [[1, 0], [0, 1], [-1, 1], [-1, 0], [0, -1], [1, -1]];
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut id: HashMap<[i64; 2], u32> = HashMap::new();
    let mut coords = Vec::new();
    let mut faces = Vec::new();
    for j in 1..n {
        for i in 1..n {
            if (i - j).rem_euclid(3) != 0 {
                continue;
            }
            let mut ring: Vec<u32> = RING
                .iter()
                .map(|d| {
                    let p = [i + d[0], j + d[1]];
                    *id.entry(p).or_insert_with(|| {
                        coords.push(p);
                        (coords.len() - 1) as u32
                    })
                })
                .collect();
            ring.rotate_left(rng.gen_range(0..6));
            triangulate_convex_polygon(&ring, false, &mut rng, &mut faces);
        }
    }
    LatticeMesh {
        lattice: Lattice::Triangular,
        coords,
        faces,
    }
}

/// Marching tetrahedra on the `n³` cubes of `[−w, w]³`, each split into the six Kuhn
/// tetrahedra around its main diagonal (a split consistent across cubes), for the level
/// set `field = 0`; the field must be positive on the boundary of the box. As in
/// marching-cubes output, a grid value with `|f| < snap` is replaced by
/// `±tiny·(1 + index mod 10)` (sign kept): the surface then passes within about `tiny`
/// cells of that grid point, and the vertices on its grid edges form clusters of
/// near-coincident points (needles and caps). Faces are oriented consistently by a
/// breadth-first walk (the surface is closed and orientable).
pub fn marching_tetrahedra(
    n: u32,
    w: f64,
    field: &dyn Fn([f64; 3]) -> f64,
    snap: f64,
    tiny: f64,
) -> Embedded {
    // The axis orders of the six Kuhn tetrahedra.
    const PERMS: [[usize; 3]; 6] = [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ];
    let n1 = n + 1;
    let gid = |i: u32, j: u32, k: u32| (k * n1 + j) * n1 + i;
    let gpos = |g: u32| {
        let (i, j, k) = (g % n1, (g / n1) % n1, g / (n1 * n1));
        [i, j, k].map(|c| -w + 2.0 * w * f64::from(c) / f64::from(n))
    };
    let vals: Vec<f64> = (0..n1 * n1 * n1)
        .map(|g| {
            let f = field(gpos(g));
            if f.abs() < snap {
                let s = if f < 0.0 { -1.0 } else { 1.0 };
                s * tiny * (1.0 + f64::from(g % 10))
            } else {
                f
            }
        })
        .collect();
    let mut pos = Vec::new();
    let mut index: HashMap<(u32, u32), u32> = HashMap::new();
    let mut vertex = |a: u32, b: u32| -> u32 {
        let key = (a.min(b), a.max(b));
        *index.entry(key).or_insert_with(|| {
            let (p, q) = (gpos(key.0), gpos(key.1));
            let (fp, fq) = (vals[key.0 as usize], vals[key.1 as usize]);
            let t = fp / (fp - fq);
            pos.push(std::array::from_fn(|d| p[d] + t * (q[d] - p[d])));
            (pos.len() - 1) as u32
        })
    };
    let mut tris: Vec<[u32; 3]> = Vec::new();
    for k in 0..n {
        for j in 0..n {
            for i in 0..n {
                for perm in PERMS {
                    let mut c = [i, j, k];
                    let mut tet = [gid(c[0], c[1], c[2]); 4];
                    for (s, &axis) in perm.iter().enumerate() {
                        c[axis] += 1;
                        tet[s + 1] = gid(c[0], c[1], c[2]);
                    }
                    let (inside, outside): (Vec<u32>, Vec<u32>) =
                        tet.iter().partition(|&&g| vals[g as usize] < 0.0);
                    match (inside.len(), outside.len()) {
                        (1, 3) | (3, 1) => {
                            let (a, o) = if inside.len() == 1 {
                                (inside[0], outside)
                            } else {
                                (outside[0], inside)
                            };
                            tris.push([vertex(a, o[0]), vertex(a, o[1]), vertex(a, o[2])]);
                        }
                        (2, 2) => {
                            let (a, b, c, d) = (inside[0], inside[1], outside[0], outside[1]);
                            let (ac, ad, bd, bc) =
                                (vertex(a, c), vertex(a, d), vertex(b, d), vertex(b, c));
                            tris.push([ac, ad, bd]);
                            tris.push([ac, bd, bc]);
                        }
                        _ => {}
                    }
                }
            }
        }
    }
    let faces = orient_consistently(&tris);
    Embedded { pos, faces }
}

/// The triangles `tris` (each undirected edge in exactly two) reversed where needed so
/// that the two triangles at every edge run through it in opposite directions.
fn orient_consistently(tris: &[[u32; 3]]) -> Vec<[u32; 3]> {
    let key = |a: u32, b: u32| (a.min(b), a.max(b));
    let mut at: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
    for (f, t) in tris.iter().enumerate() {
        for s in 0..3 {
            at.entry(key(t[s], t[(s + 1) % 3])).or_default().push(f);
        }
    }
    assert!(
        at.values().all(|fs| fs.len() == 2),
        "marching tetrahedra surface is not closed and manifold"
    );
    let mut out: Vec<Option<[u32; 3]>> = vec![None; tris.len()];
    for start in 0..tris.len() {
        if out[start].is_some() {
            continue;
        }
        out[start] = Some(tris[start]);
        let mut queue = std::collections::VecDeque::from([start]);
        while let Some(f) = queue.pop_front() {
            let t = out[f].unwrap();
            for s in 0..3 {
                let (a, b) = (t[s], t[(s + 1) % 3]);
                for &g in &at[&key(a, b)] {
                    if g == f || out[g].is_some() {
                        continue;
                    }
                    let u = tris[g];
                    // `g` must run b → a.
                    let same = (0..3).any(|r| u[r] == a && u[(r + 1) % 3] == b);
                    out[g] = Some(if same { [u[0], u[2], u[1]] } else { u });
                    queue.push_back(g);
                }
            }
        }
    }
    out.into_iter().map(Option::unwrap).collect()
}

/// The `n × n` unit squares of a grid whose vertex `(i, j)` is `v(i, j)`, each split into two
/// counter-clockwise triangles along a diagonal chosen at random.
pub fn split_squares(n: u32, v: impl Fn(u32, u32) -> u32, rng: &mut impl Rng) -> Vec<[u32; 3]> {
    let mut faces = Vec::with_capacity(2 * (n * n) as usize);
    for j in 0..n {
        for i in 0..n {
            let (a, b, c, d) = (v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1));
            if rng.gen_bool(0.5) {
                faces.push([a, b, c]);
                faces.push([a, c, d]);
            } else {
                faces.push([a, b, d]);
                faces.push([b, c, d]);
            }
        }
    }
    faces
}
