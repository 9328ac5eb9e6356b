//! The cotan Laplacian as a small compressed-sparse-row matrix (notes §1.3.3–1.3.5;
//! docs/catalogue.md §3).

use super::cotan::halfedge_cotans;
use crate::mesh::Mesh;
use crate::scalar::Real;

/// A square sparse matrix in compressed-sparse-row form. Entries of a row are sorted by
/// column; duplicates given to [`SparseMatrix::from_triplets`] are summed in input order.
#[derive(Clone, Debug, PartialEq)]
pub struct SparseMatrix<T> {
    n: usize,
    row_ptr: Vec<usize>,
    col: Vec<usize>,
    val: Vec<T>,
}

impl<T: Real> SparseMatrix<T> {
    /// Assemble an `n × n` matrix from `(row, column, value)` triplets; entries at the same
    /// position are summed in the order given. Triplets outside `n × n` are a programming
    /// error and panic.
    pub fn from_triplets(n: usize, triplets: &[(usize, usize, T)]) -> SparseMatrix<T> {
        // Counting sort by row (stable), then a stable sort by column within each row:
        // O(len + Σ_rows k log k) and the input order kept among duplicates.
        let mut start = vec![0usize; n + 1];
        for &(r, c, _) in triplets {
            assert!(
                r < n && c < n,
                "triplet ({r}, {c}) outside a {n}×{n} matrix"
            );
            start[r + 1] += 1;
        }
        for i in 0..n {
            start[i + 1] += start[i];
        }
        // (column, input index) pairs bucketed by row, so that the sorts below touch
        // contiguous memory only.
        let mut keyed = vec![(0usize, 0usize); triplets.len()];
        let mut next = start.clone();
        for (t, &(r, c, _)) in triplets.iter().enumerate() {
            keyed[next[r]] = (c, t);
            next[r] += 1;
        }
        for r in 0..n {
            keyed[start[r]..start[r + 1]].sort_unstable();
        }
        // The number of distinct positions, so that the arrays below are allocated once at
        // their final size.
        let distinct: usize = (0..n)
            .map(|r| {
                let row = &keyed[start[r]..start[r + 1]];
                row.len() - row.windows(2).filter(|w| w[0].0 == w[1].0).count()
            })
            .sum();
        let order = keyed.into_iter().map(|(_, t)| t);
        let mut row_ptr = vec![0; n + 1];
        let mut col: Vec<usize> = Vec::with_capacity(distinct);
        let mut val: Vec<T> = Vec::with_capacity(distinct);
        let mut rows: Vec<usize> = Vec::with_capacity(distinct);
        for t in order {
            let (r, c, ref v) = triplets[t];
            match (rows.last(), col.last(), val.last_mut()) {
                (Some(&lr), Some(&lc), Some(last)) if lr == r && lc == c => *last += v,
                _ => {
                    rows.push(r);
                    col.push(c);
                    val.push(v.clone());
                }
            }
        }
        for &r in &rows {
            row_ptr[r + 1] += 1;
        }
        for i in 0..n {
            row_ptr[i + 1] += row_ptr[i];
        }
        SparseMatrix {
            n,
            row_ptr,
            col,
            val,
        }
    }

    /// A matrix from its compressed-sparse-row parts (rows `row_ptr[i]..row_ptr[i+1]` of
    /// `col`/`val`, columns sorted and distinct within a row), as built by a precomputed
    /// pattern. Callers inside the crate guarantee the layout.
    pub(crate) fn from_csr_parts(
        n: usize,
        row_ptr: Vec<usize>,
        col: Vec<usize>,
        val: Vec<T>,
    ) -> SparseMatrix<T> {
        debug_assert!(row_ptr.len() == n + 1 && col.len() == val.len());
        SparseMatrix {
            n,
            row_ptr,
            col,
            val,
        }
    }

    /// The matrix with the same pattern and every stored value mapped by `f`.
    pub fn map_values<U: Real>(&self, f: impl FnMut(&T) -> U) -> SparseMatrix<U> {
        SparseMatrix {
            n: self.n,
            row_ptr: self.row_ptr.clone(),
            col: self.col.clone(),
            val: self.val.iter().map(f).collect(),
        }
    }

    /// The dimension `n`.
    pub fn dim(&self) -> usize {
        self.n
    }

    /// The stored entries of row `i` as `(column, value)`, sorted by column.
    pub fn row(&self, i: usize) -> impl Iterator<Item = (usize, &T)> {
        let (a, b) = (self.row_ptr[i], self.row_ptr[i + 1]);
        self.col[a..b].iter().copied().zip(&self.val[a..b])
    }

    /// The entry at `(i, j)`, or `None` when it is not stored (structurally zero).
    pub fn get(&self, i: usize, j: usize) -> Option<&T> {
        self.row(i).find(|&(c, _)| c == j).map(|(_, v)| v)
    }

    /// Mutable access to a stored entry (for building perturbed matrices in tests).
    pub fn get_mut(&mut self, i: usize, j: usize) -> Option<&mut T> {
        let (a, b) = (self.row_ptr[i], self.row_ptr[i + 1]);
        let k = (a..b).find(|&k| self.col[k] == j)?;
        Some(&mut self.val[k])
    }

    /// The product `M x`; `None` when `x` has the wrong length or is empty.
    pub fn mul_vec(&self, x: &[T]) -> Option<Vec<T>> {
        if x.len() != self.n {
            return None;
        }
        let zero = x.first()?.zero_like();
        Some(
            (0..self.n)
                .map(|i| {
                    let mut s = zero.clone();
                    for (j, v) in self.row(i) {
                        s += &(v.clone() * &x[j]);
                    }
                    s
                })
                .collect(),
        )
    }

    /// All stored entries as `(row, column, value)`.
    pub fn entries(&self) -> impl Iterator<Item = (usize, usize, &T)> {
        (0..self.n).flat_map(move |i| self.row(i).map(move |(j, v)| (i, j, v)))
    }
}

/// The cotan Laplacian `(L f)_i = Σ_j w_ij (f_j − f_i)` (docs/catalogue.md §3, notes Eq. 6): off the
/// diagonal `L_ij = w_ij` summed over the edges between `i` and `j` (multi-edges add), on
/// the diagonal `L_ii = −Σ_j w_ij`. Each half-edge `h = i→j` of a face adds
/// `½ cot α(h)` to `L_ij`, `L_ji` and subtracts it from `L_ii`, `L_jj`; loops (`i = j`)
/// contribute nothing. `L` is negative semidefinite: `fᵀ L f = −2 E_D(f)`.
///
/// ```
/// use penner::geometry::laplacian::cotan_laplacian;
/// use penner::mesh::Mesh;
/// let tri = Mesh::from_faces(3, &[[0, 1, 2]]).unwrap();
/// let l = cotan_laplacian(&tri, &[1.0_f64, 1.0, 1.0]);
/// let w = 0.5 / 3.0_f64.sqrt(); // ½ cot(π/3)
/// assert!((l.get(0, 1).unwrap() - w).abs() < 1e-15);
/// assert!((l.get(0, 0).unwrap() + 2.0 * w).abs() < 1e-15);
/// ```
pub fn cotan_laplacian<T: Real>(mesh: &Mesh, lengths: &[T]) -> SparseMatrix<T> {
    laplacian_from_halfedge_cotans(mesh, &halfedge_cotans(mesh, lengths))
}

/// [`cotan_laplacian`] assembled from given corner cotangents `cots[h]` (one per
/// half-edge, the corner opposite `h`, as [`halfedge_cotans`] returns them), e.g. the
/// enclosures of
/// [`enclose_halfedge_cotans`](super::enclosure::cotans::enclose_halfedge_cotans)
/// (proof: B34). The same entries, in the same order of summation, as [`cotan_laplacian`]
/// on the lengths the cotangents came from.
pub fn laplacian_from_halfedge_cotans<T: Real>(mesh: &Mesh, cots: &[T]) -> SparseMatrix<T> {
    assert_eq!(
        cots.len(),
        mesh.n_halfedges(),
        "laplacian_from_halfedge_cotans: one cotangent per half-edge is required"
    );
    let n = mesh.n_vertices();
    // The half-edges that contribute (a face, two distinct ends) and their ½ cot α.
    let ends = |h: crate::mesh::HalfEdge| (mesh.tail(h).idx(), mesh.tip(h).idx());
    let contributes =
        |h: crate::mesh::HalfEdge| !mesh.is_boundary_halfedge(h) && ends(h).0 != ends(h).1;
    let half: Vec<Option<T>> = mesh
        .halfedges()
        .map(|h| contributes(h).then(|| cots[h.idx()].clone() * &cots[h.idx()].lit(0.5)))
        .collect();
    // Off-diagonal entries bucketed by row as (column, half-edge): row i gets (j, h) and
    // row j gets (i, h) for h = i→j; sorting each row by (column, half-edge) sums
    // duplicates (multi-edges, both sides of an edge) in half-edge order.
    let mut start = vec![0usize; n + 1];
    for h in mesh.halfedges().filter(|&h| half[h.idx()].is_some()) {
        let (i, j) = ends(h);
        start[i + 1] += 1;
        start[j + 1] += 1;
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    let mut keyed = vec![(0u32, 0u32); start[n]];
    let mut next = start.clone();
    let mut diag: Vec<Option<T>> = vec![None; n];
    for h in mesh.halfedges() {
        let Some(c) = &half[h.idx()] else {
            continue;
        };
        let (i, j) = ends(h);
        for (r, col) in [(i, j), (j, i)] {
            keyed[next[r]] = (col as u32, h.0);
            next[r] += 1;
            // L_rr = −Σ ½ cot, accumulated in half-edge order.
            let minus = -c.clone();
            diag[r] = Some(match diag[r].take() {
                None => minus,
                Some(d) => d + &minus,
            });
        }
    }
    let mut row_ptr = vec![0usize; n + 1];
    let mut col = Vec::with_capacity(start[n] + n);
    let mut val: Vec<T> = Vec::with_capacity(start[n] + n);
    for r in 0..n {
        let row = &mut keyed[start[r]..start[r + 1]];
        row.sort_unstable();
        let mut d = diag[r].take();
        for &(c, h) in row.iter() {
            let c = c as usize;
            if c > r {
                if let Some(x) = d.take() {
                    col.push(r);
                    val.push(x);
                }
            }
            let w = half[h as usize]
                .clone()
                .unwrap_or_else(|| cots[0].zero_like());
            match (col.last(), val.last_mut()) {
                (Some(&lc), Some(last)) if lc == c && col.len() > row_ptr[r] => *last += &w,
                _ => {
                    col.push(c);
                    val.push(w);
                }
            }
        }
        if let Some(x) = d {
            col.push(r);
            val.push(x);
        }
        row_ptr[r + 1] = col.len();
    }
    SparseMatrix {
        n,
        row_ptr,
        col,
        val,
    }
}
