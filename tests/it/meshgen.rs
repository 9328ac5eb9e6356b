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
                let u1: f64 = 1.0 - rng.gen::<f64>();
                let u2: f64 = rng.gen();
                *c += sigma * (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos();
            }
        }
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
    let v = |i: u32, j: u32| j * (n + 1) + i;
    let mut faces = Vec::new();
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
    Embedded { pos, faces }
}

/// The boundary of a tetrahedron with random positive vertex positions: closed, genus 0.
pub fn random_tetrahedron(seed: u64) -> Embedded {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let pos = (0..4)
        .map(|_| [rng.gen(), rng.gen(), rng.gen()])
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
