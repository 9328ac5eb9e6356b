//! The grounded Hessian of the uniformization energy and its sparse Cholesky factorization.
//!
//! On a fixed triangulation the Hessian of `E(u)` is `H = −L`, `L` the cotan Laplacian of the
//! scaled metric (docs/catalogue.md §7: `H_ij = −w_ij`, `H_ii = Σ_j w_ij`); it is positive
//! semidefinite with the constants per component in its kernel. Fixing `u` at one vertex
//! per component (the *grounded* vertices, [`Components`](super::components::Components)) leaves a positive definite
//! matrix on the free vertices when all weights are positive, factored by faer's sparse
//! `LLᵀ`. The symbolic factorization depends only on the sparsity pattern and is reused
//! while flips leave the pattern unchanged.

use crate::geometry::laplacian::{cotan_laplacian, SparseMatrix};
use crate::mesh::Mesh;
use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::linalg::cholesky::llt::factor::LltRegularization;
use faer::linalg::solvers::Solve;
use faer::perm::PermRef;
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, CholeskySymbolicParams, LltRef, SymbolicCholesky,
    SymmetricOrdering,
};
use faer::sparse::linalg::solvers::{Llt, SymbolicLlt};
use faer::sparse::{SparseColMat, Triplet};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Conj, Mat, Par, Side, Spec};

/// The grounded Hessian `H = −L` on the free vertices, lower triangle, column-compressed.
pub struct GroundedHessian {
    /// The matrix (lower triangle stored).
    pub matrix: SparseColMat<usize, f64>,
}

/// `−L` restricted to the free vertices (`free_idx[v]`), lower triangle, from the cotan
/// Laplacian of `lengths` on `mesh`.
pub fn grounded_hessian(
    mesh: &Mesh,
    lengths: &[f64],
    free_idx: &[Option<usize>],
) -> GroundedHessian {
    let l = cotan_laplacian(mesh, lengths);
    grounded_from_laplacian(&l, free_idx)
}

/// `−L` restricted to the free vertices, lower triangle.
pub fn grounded_from_laplacian(
    l: &SparseMatrix<f64>,
    free_idx: &[Option<usize>],
) -> GroundedHessian {
    let n = free_idx.iter().filter(|x| x.is_some()).count();
    let mut t = Vec::new();
    for (i, j, v) in l.entries() {
        if let (Some(a), Some(b)) = (free_idx[i], free_idx[j]) {
            if a >= b {
                t.push(Triplet::new(a, b, -*v));
            }
        }
    }
    let matrix =
        SparseColMat::try_new_from_triplets(n, n, &t).expect("indices in range by construction");
    GroundedHessian { matrix }
}

/// A sparse Cholesky solver that keeps its symbolic factorization while the pattern of the
/// matrix stays the same.
#[derive(Default)]
pub struct CholeskyCache {
    pattern: Option<(Vec<usize>, Vec<usize>)>,
    symbolic: Option<SymbolicLlt<usize>>,
    /// How many symbolic factorizations were computed.
    pub symbolic_count: usize,
    /// How many numeric factorizations were computed.
    pub numeric_count: usize,
}

/// A numeric factorization ready to solve.
pub struct Factor {
    llt: Llt<usize, f64>,
}

impl CholeskyCache {
    /// Factor `h`; `None` when the matrix is not (numerically) positive definite.
    pub fn factor(&mut self, h: &GroundedHessian) -> Option<Factor> {
        let sym = h.matrix.symbolic();
        let key = (sym.col_ptr().to_vec(), sym.row_idx().to_vec());
        if self.pattern.as_ref() != Some(&key) || self.symbolic.is_none() {
            self.symbolic = Some(SymbolicLlt::try_new(sym, Side::Lower).ok()?);
            self.pattern = Some(key);
            self.symbolic_count += 1;
        }
        let s = self.symbolic.clone()?;
        self.numeric_count += 1;
        let llt = Llt::try_new_with_symbolic(s, h.matrix.as_ref(), Side::Lower).ok()?;
        Some(Factor { llt })
    }
}

impl Factor {
    /// Solve `H x = b`.
    pub fn solve(&self, b: &[f64]) -> Vec<f64> {
        let mut rhs = Mat::<f64>::from_fn(b.len(), 1, |i, _| b[i]);
        self.llt.solve_in_place(rhs.as_mut());
        (0..b.len()).map(|i| rhs[(i, 0)]).collect()
    }
}

/// The Newton direction on all vertices: `d = −H⁻¹ g` on the free vertices `free` (in the
/// order of the factored matrix), `0` on the others (grounded or fixed).
pub fn newton_direction(factor: &Factor, grad: &[f64], free: &[usize]) -> Vec<f64> {
    let b: Vec<f64> = free.iter().map(|&v| -grad[v]).collect();
    let x = factor.solve(&b);
    let mut d = vec![0.0; grad.len()];
    for (k, &v) in free.iter().enumerate() {
        d[v] = x[k];
    }
    d
}

/// The lower-triangle CSC pattern of the grounded Hessian of one triangulation, with the
/// position of every face side's entries, built once per triangulation and reused for
/// every Newton step on it (values are filled in place, nothing sorted per step), and its
/// faer symbolic Cholesky factorization.
///
/// A side `h = i→j` of a face (`i ≠ j`) with opposite angle `α` adds `½ cot α` to `H_ii`
/// and `H_jj` and subtracts it from `H_ij` (docs/catalogue.md §7, `H = −L`); entries at grounded
/// vertices are dropped.
pub struct GroundedPattern {
    n: usize,
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
    /// Per half-edge: the positions of `H_ii`, `H_jj`, `H_ij` (lower triangle) in the
    /// value array, `usize::MAX` where the entry is at a grounded vertex or the half-edge
    /// adds nothing (boundary, loop).
    slots: Vec<[usize; 3]>,
    symbolic: Option<SymbolicCholesky<usize>>,
    /// The fill-reducing ordering (forward and inverse permutation) of the symbolic
    /// factorization, or one adopted from the pattern of the triangulation before a few
    /// flips ([`Self::adopt_symbolic`]): `None` computes AMD.
    ordering: Option<(Vec<usize>, Vec<usize>)>,
    /// The numeric factor's values (reused across steps).
    l_values: Vec<f64>,
    /// Work space of the numeric factorization and the solves (reused).
    scratch: MemBuffer,
}

const NO_SLOT: usize = usize::MAX;

impl GroundedPattern {
    /// The pattern of `mesh` grounded by `free_idx` (the position of each free vertex).
    pub fn new(mesh: &Mesh, free_idx: &[Option<usize>]) -> GroundedPattern {
        let n = free_idx.iter().filter(|x| x.is_some()).count();
        let side = |h: crate::mesh::HalfEdge| {
            let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
            if i == j || mesh.is_boundary_halfedge(h) {
                None
            } else {
                Some((free_idx[i], free_idx[j]))
            }
        };
        // Column c holds the diagonal and the rows r > c joined to it by a side.
        let mut start = vec![1usize; n + 1];
        start[0] = 0;
        for h in mesh.halfedges() {
            if let Some((Some(a), Some(b))) = side(h) {
                start[a.min(b) + 1] += 1;
            }
        }
        for c in 0..n {
            start[c + 1] += start[c];
        }
        let mut rows = vec![0usize; start[n]];
        let mut next = start.clone();
        for (c, slot) in next.iter_mut().take(n).enumerate() {
            rows[*slot] = c;
            *slot += 1;
        }
        for h in mesh.halfedges() {
            if let Some((Some(a), Some(b))) = side(h) {
                let c = a.min(b);
                rows[next[c]] = a.max(b);
                next[c] += 1;
            }
        }
        let mut col_ptr = Vec::with_capacity(n + 1);
        col_ptr.push(0);
        let mut len = 0;
        for c in 0..n {
            let (a, b) = (start[c], start[c + 1]);
            rows[a..b].sort_unstable();
            let mut last = usize::MAX;
            for k in a..b {
                let r = rows[k];
                if r != last {
                    rows[len] = r;
                    len += 1;
                    last = r;
                }
            }
            col_ptr.push(len);
        }
        rows.truncate(len);
        let find = |r: usize, c: usize| -> usize {
            let (a, b) = (col_ptr[c], col_ptr[c + 1]);
            // Present by construction: every looked-up pair was inserted above.
            a + rows[a..b].partition_point(|&x| x < r)
        };
        let slots = mesh
            .halfedges()
            .map(|h| match side(h) {
                None => [NO_SLOT; 3],
                Some((a, b)) => [
                    a.map_or(NO_SLOT, |a| find(a, a)),
                    b.map_or(NO_SLOT, |b| find(b, b)),
                    match (a, b) {
                        (Some(a), Some(b)) => find(a.max(b), a.min(b)),
                        _ => NO_SLOT,
                    },
                ],
            })
            .collect();
        GroundedPattern {
            n,
            col_ptr,
            row_idx: rows,
            slots,
            symbolic: None,
            ordering: None,
            l_values: Vec::new(),
            scratch: MemBuffer::new(StackReq::empty()),
        }
    }

    /// The number of free vertices (the dimension).
    pub fn dim(&self) -> usize {
        self.n
    }

    /// The grounded Hessian's values (pattern order) from the cotangent of the corner
    /// opposite each half-edge (`cot[h]`, as
    /// [`cone_angles_and_cotans`](crate::geometry::cone_angles::cone_angles_and_cotans)
    /// gives it), into `val` (resized).
    pub fn fill(&self, cot: &[f64], val: &mut Vec<f64>) {
        val.clear();
        val.resize(self.row_idx.len(), 0.0);
        for (s, &c) in self.slots.iter().zip(cot) {
            if s[0] == NO_SLOT && s[1] == NO_SLOT {
                continue;
            }
            let w = 0.5 * c;
            if s[0] != NO_SLOT {
                val[s[0]] += w;
            }
            if s[1] != NO_SLOT {
                val[s[1]] += w;
            }
            if s[2] != NO_SLOT {
                val[s[2]] -= w;
            }
        }
    }

    /// Factor the matrix with values `val` (pattern order) sequentially (`Par::Seq`: on a
    /// shared machine a spinning thread pool costs more than it saves), in place of the
    /// previous factor; the symbolic factorization (approximate minimum degree ordering,
    /// faer's supernodal/simplicial choice) is computed on the first call and kept.
    /// `false` when the matrix is not (numerically) positive definite. Counts into `cache`.
    pub fn factor(&mut self, val: &[f64], cache: &mut CholeskyCache) -> bool {
        let sym = SymbolicSparseColMatRef::new_checked(
            self.n,
            self.n,
            &self.col_ptr,
            None,
            &self.row_idx,
        );
        if self.symbolic.is_none() {
            let ordering = match &self.ordering {
                Some((fwd, inv)) => {
                    SymmetricOrdering::Custom(PermRef::new_checked(fwd, inv, self.n))
                }
                None => SymmetricOrdering::Amd,
            };
            let Ok(s) = factorize_symbolic_cholesky(
                sym,
                Side::Lower,
                ordering,
                CholeskySymbolicParams::default(),
            ) else {
                return false;
            };
            if self.ordering.is_none() {
                self.ordering = s.perm().map(|p| {
                    let (fwd, inv) = p.arrays();
                    (fwd.to_vec(), inv.to_vec())
                });
            }
            let req = StackReq::any_of(&[
                s.factorize_numeric_llt_scratch::<f64>(Par::Seq, Spec::default()),
                s.solve_in_place_scratch::<f64>(1, Par::Seq),
            ]);
            self.scratch = MemBuffer::new(req);
            self.l_values = vec![0.0; s.len_val()];
            self.symbolic = Some(s);
            cache.symbolic_count += 1;
        }
        let Some(s) = &self.symbolic else {
            return false;
        };
        cache.numeric_count += 1;
        let mat = SparseColMatRef::new(sym, val);
        s.factorize_numeric_llt(
            &mut self.l_values,
            mat,
            Side::Lower,
            LltRegularization::default(),
            Par::Seq,
            MemStack::new(&mut self.scratch),
            Spec::default(),
        )
        .is_ok()
    }

    /// The Newton direction after a successful [`Self::factor`]: `d = −H⁻¹g` on the free
    /// vertices `free` (in pattern order), `0` on the grounded ones.
    pub fn newton_direction(&mut self, grad: &[f64], free: &[usize]) -> Vec<f64> {
        let mut d = vec![0.0; grad.len()];
        let Some(s) = &self.symbolic else {
            return d;
        };
        let mut rhs = Mat::<f64>::from_fn(free.len(), 1, |k, _| -grad[free[k]]);
        LltRef::new(s, &self.l_values).solve_in_place_with_conj(
            Conj::No,
            rhs.as_mut(),
            Par::Seq,
            MemStack::new(&mut self.scratch),
        );
        for (k, &v) in free.iter().enumerate() {
            d[v] = rhs[(k, 0)];
        }
        d
    }

    /// The stored entries `(row, column, value)` (`row ≥ column`, free-vertex positions)
    /// of the matrix with values `val` (pattern order).
    pub fn entries<'a>(&'a self, val: &'a [f64]) -> impl Iterator<Item = (usize, usize, f64)> + 'a {
        (0..self.n).flat_map(move |c| {
            (self.col_ptr[c]..self.col_ptr[c + 1]).map(move |k| (self.row_idx[k], c, val[k]))
        })
    }

    /// Whether `other` has the same sparsity pattern (then its symbolic factorization can
    /// be taken over).
    pub fn same_pattern(&self, other: &GroundedPattern) -> bool {
        self.col_ptr == other.col_ptr && self.row_idx == other.row_idx
    }

    /// Take over the symbolic factorization of `other` when the pattern is the same
    /// ([`Self::same_pattern`]), else its fill-reducing ordering (same dimension): after a
    /// few Ptolemy flips the AMD ordering of the previous triangulation still reduces fill,
    /// and the symbolic factorization of the new pattern skips AMD.
    pub fn adopt_symbolic(&mut self, other: &mut GroundedPattern) {
        if self.same_pattern(other) {
            self.symbolic = other.symbolic.take();
            self.ordering = other.ordering.take();
            self.l_values = std::mem::take(&mut other.l_values);
            self.scratch = std::mem::replace(&mut other.scratch, MemBuffer::new(StackReq::empty()));
        } else if self.n == other.n {
            self.ordering = other.ordering.take();
        }
    }
}
