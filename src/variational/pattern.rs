//! The sparsity pattern of the uniformization energy's Hessian (the cotan Laplacian of a
//! mesh, docs/catalogue.md §3, §7): one stored entry per vertex pair joined by a side of a face and
//! one per vertex on the diagonal, rows sorted by column, with the position of every
//! half-edge's entry precomputed so that assembly adds each face's cotangents in place.
//!
//! Built in `O(H·d)` for `H` half-edges and vertex degree `d` (a counting sort by tail and a
//! sort of each small row); reused across evaluations on the same mesh.

use crate::geometry::laplacian::SparseMatrix;
use crate::mesh::{HalfEdge, Mesh};
use crate::scalar::Real;

/// Compressed-sparse-row structure of `H = −L` for one mesh, with the entry positions of
/// the face sides.
#[derive(Clone, Debug)]
pub struct HessianPattern {
    n: usize,
    row_ptr: Vec<usize>,
    col: Vec<usize>,
    /// Position of `(i, i)` for each vertex `i`.
    diag: Vec<usize>,
    /// Positions of `(tail h, tip h)` and `(tip h, tail h)` for each half-edge `h` that is
    /// a side of a face (`usize::MAX` for boundary half-edges).
    side: Vec<[usize; 2]>,
}

impl HessianPattern {
    /// The pattern of the cotan Laplacian of `mesh`: the diagonal and `(i, j)`, `(j, i)`
    /// for every side `ij` of a face (loops `i = i` fall on the diagonal).
    pub fn new(mesh: &Mesh) -> HessianPattern {
        let n = mesh.n_vertices();
        // Counting sort by row (two passes over the faces), then sort and deduplicate each
        // (short) row in place.
        let mut start = vec![0usize; n + 1];
        for i in 0..n {
            start[i + 1] = 1;
        }
        for f in mesh.faces() {
            for h in mesh.face_halfedges(f) {
                start[mesh.tail(h).idx() + 1] += 1;
                start[mesh.tip(h).idx() + 1] += 1;
            }
        }
        for i in 0..n {
            start[i + 1] += start[i];
        }
        let mut bucket = vec![0usize; start[n]];
        let mut next = start.clone();
        for (i, slot) in next.iter_mut().take(n).enumerate() {
            bucket[*slot] = i;
            *slot += 1;
        }
        for f in mesh.faces() {
            for h in mesh.face_halfedges(f) {
                let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
                bucket[next[i]] = j;
                next[i] += 1;
                bucket[next[j]] = i;
                next[j] += 1;
            }
        }
        let mut row_ptr = Vec::with_capacity(n + 1);
        let mut len = 0;
        row_ptr.push(0);
        for r in 0..n {
            let (a, b) = (start[r], start[r + 1]);
            bucket[a..b].sort_unstable();
            let mut last = usize::MAX;
            for k in a..b {
                let c = bucket[k];
                if c != last {
                    bucket[len] = c;
                    len += 1;
                    last = c;
                }
            }
            row_ptr.push(len);
        }
        bucket.truncate(len);
        let col = bucket;
        let find = |r: usize, c: usize| -> usize {
            let (a, b) = (row_ptr[r], row_ptr[r + 1]);
            // Present by construction: every looked-up pair was inserted above.
            a + col[a..b].partition_point(|&x| x < c)
        };
        let diag = (0..n).map(|i| find(i, i)).collect();
        let mut side = vec![[usize::MAX; 2]; mesh.n_halfedges()];
        for f in mesh.faces() {
            for h in mesh.face_halfedges(f) {
                let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
                side[h.idx()] = [find(i, j), find(j, i)];
            }
        }
        HessianPattern {
            n,
            row_ptr,
            col,
            diag,
            side,
        }
    }

    /// The number of vertices (the matrix dimension).
    pub fn dim(&self) -> usize {
        self.n
    }

    /// Whether this pattern was built for a mesh of `mesh`'s size (a cheap guard, not a
    /// proof that it is the same mesh).
    pub fn fits(&self, mesh: &Mesh) -> bool {
        self.n == mesh.n_vertices() && self.side.len() == mesh.n_halfedges()
    }

    /// Zero values, one per stored entry.
    pub(crate) fn zeros<T: Real>(&self, zero: &T) -> Vec<T> {
        vec![zero.clone(); self.col.len()]
    }

    /// Adds `w` to `H_ii` and `H_jj` and `−w` to `H_ij` and `H_ji` for the side `h = ij`,
    /// in this order (the order of the triplets of
    /// [`hessian_at`](super::energy::hessian_at)'s definition).
    #[inline]
    pub(crate) fn add_side<T: Real>(&self, mesh: &Mesh, val: &mut [T], h: HalfEdge, w: &T) {
        let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        val[self.diag[i]] += w;
        val[self.diag[j]] += w;
        let [ij, ji] = self.side[h.idx()];
        val[ij] -= w;
        val[ji] -= w;
    }

    /// The matrix with values `val` (one per stored entry, in pattern order).
    pub(crate) fn matrix<T: Real>(&self, val: Vec<T>) -> SparseMatrix<T> {
        SparseMatrix::from_csr_parts(self.n, self.row_ptr.clone(), self.col.clone(), val)
    }
}
