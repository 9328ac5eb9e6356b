//! Discrete harmonic maps of a disk to a convex polygon (notes §1.3.3, Fig. 7; Tutte 1963,
//! Floater 2003): fix the boundary loop on a convex polygon and solve `Σ_j w_ij (x_j − x_i)
//! = 0` at every interior vertex. With positive weights the map is an embedding (T36);
//! with negative cotan weights a triangle can fold.
//!
//! The map is computed in `f64` ([`lu_solve`], Gaussian elimination with partial pivoting); the
//! orientation of every face of the **computed** map is then decided exactly
//! ([`crate::predicates::planar::orient2d`] on the binary64 positions).

use crate::mesh::Mesh;
use crate::predicates::ladder::Ladder;
use crate::predicates::planar::{orient2d, point_from_f64};
use crate::scalar::dense::lu_solve;
use crate::scalar::{Certified, Sign};

/// The vertices of the boundary loop of a disk in loop order, or `None` unless the mesh has
/// exactly one boundary loop.
pub fn boundary_loop(mesh: &Mesh) -> Option<Vec<usize>> {
    if mesh.n_boundary_loops() != 1 {
        return None;
    }
    let start = mesh.halfedges().find(|&h| mesh.is_boundary_halfedge(h))?;
    let mut out = vec![mesh.tail(start).idx()];
    let mut h = mesh.next(start);
    while h != start {
        out.push(mesh.tail(h).idx());
        h = mesh.next(h);
    }
    Some(out)
}

/// The `m` corners of the regular polygon inscribed in the unit circle, `(cos 2πk/m,
/// sin 2πk/m)` rounded to `f64`.
pub fn regular_polygon(m: usize) -> Vec<[f64; 2]> {
    (0..m)
        .map(|k| {
            let a = 2.0 * std::f64::consts::PI * k as f64 / m as f64;
            [a.cos(), a.sin()]
        })
        .collect()
}

/// Cotan weights `w_ij = ½(cot α + cot β)` of the planar triangulation with vertex
/// positions `pos` (`f64`, one per edge; a boundary edge has one term).
pub fn cotan_weights_planar(mesh: &Mesh, pos: &[[f64; 2]]) -> Vec<f64> {
    let mut w = vec![0.0; mesh.n_edges()];
    for f in mesh.faces() {
        for h in mesh.face_halfedges(f) {
            let (i, j, k) = (
                mesh.tail(h).idx(),
                mesh.tip(h).idx(),
                mesh.opposite_vertex(h).idx(),
            );
            let a = [pos[i][0] - pos[k][0], pos[i][1] - pos[k][1]];
            let b = [pos[j][0] - pos[k][0], pos[j][1] - pos[k][1]];
            let cross = a[0] * b[1] - a[1] * b[0];
            w[h.edge().idx()] += 0.5 * (a[0] * b[0] + a[1] * b[1]) / cross;
        }
    }
    w
}

/// The harmonic map with edge weights `w`, the boundary loop ([`boundary_loop`]) sent in
/// order to the corners `polygon`: interior positions from the dense linear system, `None`
/// when the mesh is not a disk, the corner count differs, or the system is singular.
pub fn harmonic_map(mesh: &Mesh, w: &[f64], polygon: &[[f64; 2]]) -> Option<Vec<[f64; 2]>> {
    let loop_ = boundary_loop(mesh)?;
    if loop_.len() != polygon.len() {
        return None;
    }
    let n = mesh.n_vertices();
    let mut pos = vec![[0.0; 2]; n];
    let mut fixed = vec![false; n];
    for (&v, p) in loop_.iter().zip(polygon) {
        pos[v] = *p;
        fixed[v] = true;
    }
    let interior: Vec<usize> = (0..n).filter(|&v| !fixed[v]).collect();
    let mut index = vec![usize::MAX; n];
    for (k, &v) in interior.iter().enumerate() {
        index[v] = k;
    }
    let m = interior.len();
    let mut a = vec![vec![0.0; m + 2]; m];
    for e in mesh.edges() {
        let h = e.halfedge();
        let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        let wij = w[e.idx()];
        for (p, q) in [(i, j), (j, i)] {
            if fixed[p] {
                continue;
            }
            let r = index[p];
            a[r][r] += wij;
            if fixed[q] {
                a[r][m] += wij * pos[q][0];
                a[r][m + 1] += wij * pos[q][1];
            } else {
                a[r][index[q]] -= wij;
            }
        }
    }
    let x = gauss(a, m)?;
    for (k, &v) in interior.iter().enumerate() {
        pos[v] = x[k];
    }
    Some(pos)
}

/// Solve the `m × m` system with two right-hand sides in columns `m, m + 1` ([`lu_solve`];
/// a pivot below `10⁻³⁰⁰` in magnitude counts as singular).
fn gauss(a: Vec<Vec<f64>>, m: usize) -> Option<Vec<[f64; 2]>> {
    let (mut lhs, mut rhs) = (Vec::with_capacity(m), vec![vec![0.0; m]; 2]);
    for (r, mut row) in a.into_iter().enumerate() {
        rhs[0][r] = row[m];
        rhs[1][r] = row[m + 1];
        row.truncate(m);
        lhs.push(row);
    }
    let x = lu_solve(lhs, rhs, 1e-300)?;
    Some((0..m).map(|r| [x[0][r], x[1][r]]).collect())
}

/// The exact orientation sign of every face of the planar map `pos` (binary64 positions
/// read exactly), through the ladder of `orient2d` (proofs/B25).
pub fn face_orientations(mesh: &Mesh, pos: &[[f64; 2]], ladder: &Ladder) -> Vec<Certified<Sign>> {
    mesh.faces()
        .map(|f| {
            let [a, b, c] = mesh
                .face_vertices(f)
                .map(|v| point_from_f64(pos[v.idx()][0], pos[v.idx()][1]));
            match (a, b, c) {
                (Some(a), Some(b), Some(c)) => orient2d(&a, &b, &c, ladder),
                _ => Certified::Undecided { bits_tried: 0 },
            }
        })
        .collect()
}
