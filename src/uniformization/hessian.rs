//! The grounded Hessian of the uniformization energy and its sparse Cholesky factorization.
//!
//! On a fixed triangulation the Hessian of `E(u)` is `H = −L`, `L` the cotan Laplacian of the
//! scaled metric (MATH.md §7: `H_ij = −w_ij`, `H_ii = Σ_j w_ij`); it is positive
//! semidefinite with the constants per component in its kernel. Fixing `u` at one vertex
//! per component (the *grounded* vertices, [`Components`]) leaves a positive definite
//! matrix on the free vertices when all weights are positive, factored by faer's sparse
//! `LLᵀ`. The symbolic factorization depends only on the sparsity pattern and is reused
//! while flips leave the pattern unchanged.

use super::components::Components;
use crate::geometry::laplacian::{cotan_laplacian, SparseMatrix};
use crate::mesh::Mesh;
use faer::linalg::solvers::Solve;
use faer::sparse::linalg::solvers::{Llt, SymbolicLlt};
use faer::sparse::{SparseColMat, Triplet};
use faer::{Mat, Side};

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

/// The Newton direction on all vertices: `d = −H⁻¹ g` on the free vertices, `0` on the
/// grounded ones.
pub fn newton_direction(factor: &Factor, grad: &[f64], comps: &Components) -> Vec<f64> {
    let (free, _) = comps.free_index();
    let b: Vec<f64> = free.iter().map(|&v| -grad[v]).collect();
    let x = factor.solve(&b);
    let mut d = vec![0.0; grad.len()];
    for (k, &v) in free.iter().enumerate() {
        d[v] = x[k];
    }
    d
}
