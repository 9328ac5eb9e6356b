//! T05 — the cotan Laplacian (notes §1.3.3–1.3.5; docs/catalogue.md §3): symmetric, zero row sums,
//! negative semidefinite (`fᵀ L f = −2E_D(f) ≤ 0`, constants in the kernel), linear precision
//! on flat interiors, and `w ≥ 0` on every edge ⇔ Delaunay.
//!
//! API:
//! - `pub fn check_cotan_laplacian<T: Real>(mesh: &Mesh, lengths: &[T], settings: &Settings) -> Verdict`
//! - `pub fn verify_laplacian<T: Real>(mesh: &Mesh, lap: &SparseMatrix<T>, settings: &Settings) -> Verdict`
//! - `pub fn check_linear_precision<T: Real>(mesh: &Mesh, positions: &[[T; 2]], lengths: &[T], settings: &Settings) -> Verdict`
//! - `pub fn check_delaunay_iff_nonnegative_weights(mesh: &Mesh, lengths: &[rug::Rational], settings: &Settings) -> Verdict`
//!   (in [`super::t05_delaunay_weights`]).

use super::bounds::{cot_error, eps, eps_shift, sum_error, SAFETY};
use super::report::{check_lengths, lengths_out_of_range, Tally};
use super::t05_semidefinite::{faces_semidefinite, nonnegative_weights};
use super::verdict::{Settings, Verdict};
use crate::geometry::laplacian::{cotan_laplacian, SparseMatrix};
use crate::mesh::Mesh;
use crate::predicates::tolerance::sign_beyond;
use crate::scalar::Real;
use crate::scalar::Sign;
use rug::Rational;

/// T05 (matrix part), numerical: assembles [`cotan_laplacian`] and checks it as
/// [`verify_laplacian`] does, except that semidefiniteness with a negative weight is decided
/// face by face (proofs/B51), in time linear in the mesh.
///
/// ```
/// use penner::mesh::Mesh;
/// use penner::theorems::{t05_cotan_laplacian::check_cotan_laplacian, Settings};
/// let tet = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]).unwrap();
/// assert!(check_cotan_laplacian(&tet, &[1.0_f64; 6], &Settings::default()).holds());
/// ```
pub fn check_cotan_laplacian<T: Real>(mesh: &Mesh, lengths: &[T], settings: &Settings) -> Verdict {
    if let Some(v) = check_lengths(mesh, lengths).or_else(|| lengths_out_of_range(lengths)) {
        return v;
    }
    let lap = cotan_laplacian(mesh, lengths);
    let mut tally = match symmetric_zero_rows(mesh, &lap, settings) {
        Ok(t) => t,
        Err(v) => return v,
    };
    if nonnegative_weights(&lap) != Some(true) {
        faces_semidefinite(mesh, lengths, settings, &mut tally);
    }
    tally.verdict()
}

/// Checks a claimed Laplacian `lap` of `mesh` (numerical):
/// - symmetry: every stored `L_ij` has a stored `L_ji` equal to it exactly (witness `L[i,j]`);
/// - zero row sums: `|Σ_j L_ij| ≤` B41 over the row (witness `row i`);
/// - semidefiniteness (proofs/B51, B46): with every off-diagonal entry `≥ 0`, `−L` is a graph
///   Laplacian of nonnegative weights plus its bounded row sums; otherwise the LDLᵀ
///   factorisation of `−L`, grounded at the first vertex of each connected component, has
///   pivots `d_k > τ_k` with `τ_k = (n+1) ε (|L̂||D||L̂ᵀ|)_kk` times [`SAFETY`] (Higham,
///   *Accuracy and Stability*, Thm 10.3). A pivot `≤ τ_k` is a failure (witness `pivot v…`)
///   only if the vector `x` it defines has `xᵀ(−L)x < −2ε Σ|x_i||L_ij||x_j|` evaluated
///   exactly (the matrix is then not within `ε` relative rounding of a semidefinite one);
///   otherwise it is undecided. Matrices with a negative weight and more than
///   [`GENERAL_PATH_LIMIT`] non-grounded vertices are undecided (use
///   [`check_cotan_laplacian`], which decomposes by faces).
pub fn verify_laplacian<T: Real>(
    mesh: &Mesh,
    lap: &SparseMatrix<T>,
    settings: &Settings,
) -> Verdict {
    let mut tally = match symmetric_zero_rows(mesh, lap, settings) {
        Ok(t) => t,
        Err(v) => return v,
    };
    match nonnegative_weights(lap) {
        Some(true) => {}
        None => tally.undecided("L", "an entry is not finite", f64::NAN),
        Some(false) => {
            let e = lap
                .entries()
                .next()
                .map_or(0.0, |(_, _, v)| eps::<T>(v.ctx()));
            semidefinite(mesh, lap, e, settings, &mut tally);
        }
    }
    tally.verdict()
}

/// The largest grounded matrix the general (LDLᵀ) path of [`verify_laplacian`] factors.
pub const GENERAL_PATH_LIMIT: usize = 2000;

/// Symmetry and zero row sums of [`verify_laplacian`], into a new tally; `Err` for a matrix
/// of the wrong size or the zero matrix (which has every property).
fn symmetric_zero_rows<T: Real>(
    mesh: &Mesh,
    lap: &SparseMatrix<T>,
    settings: &Settings,
) -> Result<Tally, Verdict> {
    let n = lap.dim();
    if n != mesh.n_vertices() {
        return Err(Verdict::NotApplicable {
            reason: format!("{n}×{n} matrix for {} vertices", mesh.n_vertices()),
        });
    }
    let Some((_, _, v0)) = lap.entries().next() else {
        // The zero matrix (e.g. only loops, as on the one-vertex torus) has every property.
        return Err(Verdict::Holds {
            certified: true,
            max_error: 0.0,
        });
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
    Ok(tally)
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

/// Grounded LDLᵀ of `−L` (the general path of [`verify_laplacian`], at most
/// [`GENERAL_PATH_LIMIT`] non-grounded vertices); proofs/B46 for the pivot tolerance, B51 for
/// the refutation by an exactly evaluated quadratic form.
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
    let Some(zero) = lap.entries().next().map(|(_, _, v)| v.zero_like()) else {
        return;
    };
    if m == 0 {
        return;
    }
    if m > GENERAL_PATH_LIMIT {
        tally.undecided(
            "L",
            format!(
                "a negative weight and {m} vertices: the general path factors at most \
                 {GENERAL_PATH_LIMIT} (check_cotan_laplacian decides by faces)"
            ),
            m as f64,
        );
        return;
    }
    let shift = eps_shift(T::precision_bits(zero.ctx()));
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
    // Right-looking LDLᵀ: after step k, a[k][k] = d_k and a[i][k] = l_ik·d_k (i > k).
    let mut l = vec![vec![0.0_f64; m]; m]; // l_ik approximations, for the bound and witness
    let mut d_abs = vec![0.0_f64; m];
    for k in 0..m {
        let d = a[k][k].clone();
        let df = d.approx_f64();
        d_abs[k] = df.abs();
        let acc: f64 = (0..k).map(|j| l[k][j] * l[k][j] * d_abs[j]).sum::<f64>() + df.abs();
        let tau = settings.slack * SAFETY * (m as f64 + 1.0) * e * acc;
        let pivot_ok = sign_beyond(&d, tau, shift) == Some(Sign::Positive);
        if !pivot_ok {
            refute_or_undecided(lap, &keep, &l, k, e, shift, tally, tau, df);
            return;
        }
        for i in k + 1..m {
            let lik = a[i][k].clone() / &d;
            l[i][k] = lik.approx_f64();
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

/// At a pivot `d_k ≤ τ_k` of the grounded LDLᵀ: the vector `x` with `x_k = 1`, `x_j = 0` for
/// `j > k` and `L̂[0..k,0..k]ᵀ x[0..k] = −L̂[k,0..k]ᵀ` has `xᵀ(−L)x ≈ d_k`. Evaluated exactly
/// in ℚ on the stored entries, `xᵀ(−L)x < −2ε·2⁻ˢ Σ|x_i||L_ij||x_j|` refutes
/// semidefiniteness of every matrix within `ε` relative rounding of `L` (proofs/B51);
/// otherwise the pivot is undecided.
#[allow(clippy::too_many_arguments)]
fn refute_or_undecided<T: Real>(
    lap: &SparseMatrix<T>,
    keep: &[usize],
    l: &[Vec<f64>],
    k: usize,
    e: f64,
    shift: u32,
    tally: &mut Tally,
    tau: f64,
    df: f64,
) {
    let v = keep[k];
    let mut x = vec![0.0_f64; k + 1];
    x[k] = 1.0;
    for j in (0..k).rev() {
        let s: f64 = (j + 1..=k).map(|i| l[i][j] * x[i]).sum();
        x[j] = -s;
    }
    let mut pos = vec![usize::MAX; lap.dim()];
    for (i, &w) in keep.iter().take(k + 1).enumerate() {
        pos[w] = i;
    }
    let mut q = Rational::new();
    let mut mag = Rational::new();
    for (i, j, a) in lap.entries() {
        let (pi, pj) = (pos[i], pos[j]);
        if pi == usize::MAX || pj == usize::MAX {
            continue;
        }
        let (Some(aq), Some(xi), Some(xj)) = (
            a.to_rational(),
            Rational::from_f64(x[pi]),
            Rational::from_f64(x[pj]),
        ) else {
            tally.undecided(format!("pivot v{v}"), "pivot not finite", df);
            return;
        };
        let t = Rational::from(&xi * &xj) * &aq;
        mag += Rational::from(t.abs_ref());
        q -= t;
    }
    let allowance = (mag * Rational::from_f64(2.0 * e).unwrap_or_default()) >> shift;
    if q < -allowance {
        tally.fail(
            format!("pivot v{v}"),
            format!(
                "negative pivot (τ = {tau:.3e}) and xᵀ(−L)x < 0 beyond rounding: −L is indefinite"
            ),
            df,
        );
    } else {
        tally.undecided(
            format!("pivot v{v}"),
            format!("pivot within its error bound τ = {tau:.3e}"),
            df,
        );
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
    if let Some(v) = check_lengths(mesh, lengths).or_else(|| lengths_out_of_range(lengths)) {
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
