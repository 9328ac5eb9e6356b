//! T05 — the cotan Laplacian (notes §1.3.3–1.3.5; MATH.md §3): symmetric, zero row sums,
//! negative semidefinite (`fᵀ L f = −2E_D(f) ≤ 0`, constants in the kernel), linear precision
//! on flat interiors, and `w ≥ 0` on every edge ⇔ Delaunay.
//!
//! API:
//! - `pub fn check_cotan_laplacian<T: Real>(mesh: &Mesh, lengths: &[T], settings: &Settings) -> Verdict`
//! - `pub fn verify_laplacian<T: Real>(mesh: &Mesh, lap: &SparseMatrix<T>, settings: &Settings) -> Verdict`
//! - `pub fn check_linear_precision<T: Real>(mesh: &Mesh, positions: &[[T; 2]], lengths: &[T], settings: &Settings) -> Verdict`
//! - `pub fn check_delaunay_iff_nonnegative_weights(mesh: &Mesh, lengths: &[rug::Rational], settings: &Settings) -> Verdict`
//!   (in [`super::t05_delaunay_weights`]).

use super::bounds::{cot_error, eps, sum_error, SAFETY};
use super::report::{check_lengths, Tally};
use super::verdict::{Settings, Verdict};
use crate::geometry::laplacian::{cotan_laplacian, SparseMatrix};
use crate::mesh::Mesh;
use crate::scalar::Real;

/// T05 (matrix part), numerical: assembles [`cotan_laplacian`] and runs [`verify_laplacian`].
///
/// ```
/// use penner::mesh::Mesh;
/// use penner::theorems::{t05_cotan_laplacian::check_cotan_laplacian, Settings};
/// let tet = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]).unwrap();
/// assert!(check_cotan_laplacian(&tet, &[1.0_f64; 6], &Settings::default()).holds());
/// ```
pub fn check_cotan_laplacian<T: Real>(mesh: &Mesh, lengths: &[T], settings: &Settings) -> Verdict {
    if let Some(v) = check_lengths(mesh, lengths) {
        return v;
    }
    verify_laplacian(mesh, &cotan_laplacian(mesh, lengths), settings)
}

/// Checks a claimed Laplacian `lap` of `mesh` (numerical):
/// - symmetry: every stored `L_ij` has a stored `L_ji` equal to it exactly (witness `L[i,j]`);
/// - zero row sums: `|Σ_j L_ij| ≤` B41 over the row (witness `row i`);
/// - semidefiniteness: the LDLᵀ factorisation of `−L`, grounded at the first vertex of each
///   connected component, has pivots `d_k > τ_k` with `τ_k = (n+1) ε (|L̂||D||L̂ᵀ|)_kk`
///   times [`SAFETY`] (Higham, *Accuracy and Stability*, Thm 10.3; proofs/B46). A pivot
///   `< −τ_k` is a failure (witness `pivot v…`), `|d_k| ≤ τ_k` undecided.
pub fn verify_laplacian<T: Real>(
    mesh: &Mesh,
    lap: &SparseMatrix<T>,
    settings: &Settings,
) -> Verdict {
    let n = lap.dim();
    if n != mesh.n_vertices() {
        return Verdict::NotApplicable {
            reason: format!("{n}×{n} matrix for {} vertices", mesh.n_vertices()),
        };
    }
    let Some((_, _, v0)) = lap.entries().next() else {
        // The zero matrix (e.g. only loops, as on the one-vertex torus) has every property.
        return Verdict::Holds {
            certified: true,
            max_error: 0.0,
        };
    };
    let ctx = v0.ctx();
    let e = eps::<T>(ctx);
    let mut tally = Tally::new(false, T::precision_bits(ctx));
    for (i, j, v) in lap.entries() {
        match lap.get(j, i) {
            Some(w) => tally.within(format!("L[{i},{j}]"), "L_ij − L_ji", &(v.clone() - w), 0.0),
            None => tally.fail(format!("L[{i},{j}]"), "L_ji is not stored", v.approx_f64()),
        }
    }
    for i in 0..n {
        let mut s = v0.zero_like();
        for (_, v) in lap.row(i) {
            s += v;
        }
        let tol = settings.slack * sum_error(lap.row(i).map(|(_, v)| v.approx_f64()), e);
        tally.within(format!("row {i}"), "row sum", &s, tol);
    }
    semidefinite(mesh, lap, e, settings, &mut tally);
    tally.verdict()
}

/// First vertex of each connected component (by edges), to ground the Laplacian.
fn grounded(mesh: &Mesh) -> Vec<bool> {
    fn find(p: &mut [usize], mut x: usize) -> usize {
        while p[x] != x {
            p[x] = p[p[x]];
            x = p[x];
        }
        x
    }
    let n = mesh.n_vertices();
    let mut parent: Vec<usize> = (0..n).collect();
    for e in mesh.edges() {
        let h = e.halfedge();
        let (a, b) = (
            find(&mut parent, mesh.tail(h).idx()),
            find(&mut parent, mesh.tip(h).idx()),
        );
        if a != b {
            parent[a.max(b)] = a.min(b);
        }
    }
    (0..n).map(|v| find(&mut parent, v) == v).collect()
}

/// Dense LDLᵀ of `−L` without the grounded vertices; records every non-positive pivot.
#[allow(clippy::needless_range_loop)]
fn semidefinite<T: Real>(
    mesh: &Mesh,
    lap: &SparseMatrix<T>,
    e: f64,
    settings: &Settings,
    tally: &mut Tally,
) {
    let ground = grounded(mesh);
    let keep: Vec<usize> = (0..lap.dim()).filter(|&v| !ground[v]).collect();
    let m = keep.len();
    if m == 0 {
        return;
    }
    let zero = lap.entries().next().map(|(_, _, v)| v.zero_like());
    let Some(zero) = zero else { return };
    let mut pos = vec![usize::MAX; lap.dim()];
    for (k, &v) in keep.iter().enumerate() {
        pos[v] = k;
    }
    let mut a = vec![vec![zero.clone(); m]; m];
    for (i, j, v) in lap.entries() {
        if pos[i] != usize::MAX && pos[j] != usize::MAX {
            a[pos[i]][pos[j]] = -v.clone();
        }
    }
    // Right-looking LDLᵀ (index loops mirror the textbook algorithm).: after step k, a[k][k] = d_k and a[i][k] = l_ik·d_k (i > k).
    let mut l = vec![vec![0.0_f64; m]; m]; // |l_ik| approximations for the bound
    let mut d_abs = vec![0.0_f64; m];
    for k in 0..m {
        let d = a[k][k].clone();
        let df = d.approx_f64();
        d_abs[k] = df.abs();
        let acc: f64 = (0..k).map(|j| l[k][j] * l[k][j] * d_abs[j]).sum::<f64>() + df.abs();
        let tau = settings.slack * SAFETY * (m as f64 + 1.0) * e * acc;
        let v = keep[k];
        if !tau.is_finite() || !df.is_finite() {
            tally.undecided(format!("pivot v{v}"), "pivot not finite", df);
            return;
        }
        if df < -tau {
            tally.fail(
                format!("pivot v{v}"),
                format!("negative pivot (τ = {tau:.3e}): −L is indefinite"),
                df,
            );
            return;
        }
        if df <= tau {
            tally.undecided(
                format!("pivot v{v}"),
                format!("pivot within its error bound τ = {tau:.3e}"),
                df,
            );
            return;
        }
        for i in k + 1..m {
            let lik = a[i][k].clone() / &d;
            l[i][k] = lik.approx_f64().abs();
            for j in k + 1..=i {
                let t = lik.clone() * &a[j][k];
                a[i][j] -= &t;
                if j != i {
                    a[j][i] = a[i][j].clone();
                }
            }
        }
    }
}

/// T05 linear precision, numerical: for a flat planar mesh with vertex `positions` and the
/// matching `lengths`, `(L x)_i = Σ_j w_ij (x_j − x_i) = 0` and likewise for `y` at every
/// interior vertex (notes §1.3.5). Tolerance (proofs/B47): `Σ_j (Δw_ij + 4ε|w_ij|)|x_j − x_i|`
/// plus B41 over the terms, with `Δw` from B44; witnesses `v…`.
pub fn check_linear_precision<T: Real>(
    mesh: &Mesh,
    positions: &[[T; 2]],
    lengths: &[T],
    settings: &Settings,
) -> Verdict {
    if let Some(v) = check_lengths(mesh, lengths) {
        return v;
    }
    if positions.len() != mesh.n_vertices() {
        return Verdict::NotApplicable {
            reason: format!(
                "{} positions for {} vertices",
                positions.len(),
                mesh.n_vertices()
            ),
        };
    }
    let ctx = lengths[0].ctx();
    let e = eps::<T>(ctx);
    let cots = crate::geometry::cotan::halfedge_cotans(mesh, lengths);
    let lf = |h: crate::mesh::HalfEdge| lengths[h.edge().idx()].approx_f64();
    let boundary = mesh.boundary_vertices();
    let n = mesh.n_vertices();
    let zero = lengths[0].zero_like();
    let mut res = vec![[zero.clone(), zero.clone()]; n];
    let mut terms: Vec<[Vec<f64>; 2]> = vec![[Vec::new(), Vec::new()]; n];
    let mut input: Vec<[f64; 2]> = vec![[0.0; 2]; n];
    let half = lengths[0].lit(0.5);
    for h in mesh.halfedges() {
        if mesh.is_boundary_halfedge(h) {
            continue;
        }
        let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        let c = cots[h.idx()].clone() * &half;
        let dc = 0.5 * cot_error(lf(h), lf(mesh.next(h)), lf(mesh.prev(h)), e);
        for (a, b) in [(i, j), (j, i)] {
            for k in 0..2 {
                let d = positions[b][k].clone() - &positions[a][k];
                let t = c.clone() * &d;
                let (tf, df) = (t.approx_f64(), d.approx_f64());
                terms[a][k].push(tf);
                input[a][k] += (dc + 4.0 * e * c.approx_f64().abs()) * df.abs();
                res[a][k] += &t;
            }
        }
    }
    let mut tally = Tally::new(false, T::precision_bits(ctx));
    for v in 0..n {
        if boundary[v] {
            continue;
        }
        for (k, name) in ["x", "y"].iter().enumerate() {
            let tol =
                settings.slack * (SAFETY * input[v][k] + sum_error(terms[v][k].iter().copied(), e));
            tally.within(format!("v{v}"), &format!("(L {name})_i"), &res[v][k], tol);
        }
    }
    tally.verdict()
}
