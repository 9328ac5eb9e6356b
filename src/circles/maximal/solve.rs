//! The maximal packing's radii: Newton's method in `f64` on the interior vertices with faer's
//! sparse Cholesky of `H = −∂θ/∂u` ([`super::hyperbolic`]), then mixed-precision refinement
//! in any backend `T` (docs/catalogue.md §7, as in the uniformization): the residual `2π − θ(u)` is
//! evaluated in `T`, the correction solved with the `f64` factor of `H` at the `f64`
//! solution. Each refinement step contracts the residual by about `κ(H)·u_f64` (a
//! simplified Newton iteration), so a few steps reach `2⁻¹⁰⁰` from `10⁻¹³`.
//!
//! The stopping rules read `approx_f64` (heuristics): the packing is certified afterwards,
//! on its circles ([`super::tangency`]).

use super::hyperbolic::{
    angle_jacobian_triplets, angle_sums, corner_angle, for_each_angle_jacobian_entry, radii_from_u,
    residual_by_rotations,
};
use crate::mesh::{Mesh, Vertex};
use crate::scalar::Real;
use faer::linalg::solvers::Solve;
use faer::sparse::linalg::solvers::{Llt, SymbolicLlt};
use faer::sparse::{SparseColMat, SparseColMatRef, Triplet};
use faer::{Mat, Side};

/// Why the radii were not computed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum MaximalSolveError {
    /// The grounded Hessian was not numerically positive definite.
    #[error("iteration {0}: the Hessian −∂θ/∂u is not numerically positive definite")]
    Singular(usize),
    /// No step decreased the residual.
    #[error("iteration {iteration}: no step decreases |2π − θ| (residual {residual:e})")]
    Stalled {
        /// Iteration.
        iteration: usize,
        /// `max |2π − θ|` reached.
        residual: f64,
    },
    /// The iteration cap was reached.
    #[error("{iterations} iterations without convergence (residual {residual:e})")]
    NoConvergence {
        /// Iterations run.
        iterations: usize,
        /// `max |2π − θ|` reached.
        residual: f64,
    },
    /// A working precision out of MPFR's range.
    #[error("{0} bits is not a usable MPFR precision")]
    Precision(u32),
}

/// `H = −∂θ/∂u` on the interior vertices (`index[v]`), lower triangle, duplicates summed.
fn hessian(mesh: &Mesh, t: &[f64], interior: &[bool], index: &[usize]) -> SparseColMat<usize, f64> {
    let n = interior.iter().filter(|&&b| b).count();
    let mut entries: Vec<(usize, usize, f64)> = angle_jacobian_triplets(mesh, t, interior)
        .into_iter()
        .map(|(i, j, v)| (index[i], index[j], -v))
        .filter(|&(a, b, _)| a >= b)
        .map(|(a, b, v)| (b, a, v))
        .collect();
    entries.sort_unstable_by_key(|&(c, r, _)| (c, r));
    let mut t: Vec<Triplet<usize, usize, f64>> = Vec::with_capacity(entries.len());
    for (c, r, v) in entries {
        match t.last_mut() {
            Some(last) if last.row == r && last.col == c => last.val += v,
            _ => t.push(Triplet::new(r, c, v)),
        }
    }
    SparseColMat::try_new_from_triplets(n, n, &t).expect("indices in range by construction")
}

/// The assembly of `H` after its first: the sparsity pattern (fixed, since the mesh and the
/// interior are) and, for each entry of [`angle_jacobian_triplets`] in its order, its slot
/// in the column-major values (`None` above the diagonal), so each later `H` is one pass
/// over the faces with no sort; and the symbolic factorization of that pattern.
struct Assembly {
    pattern: SparseColMat<usize, f64>,
    slots: Vec<Option<usize>>,
    symbolic: SymbolicLlt<usize>,
}

impl Assembly {
    /// From the first `H` (assembled by [`hessian`]) and the triplets' order.
    fn new(mesh: &Mesh, t: &[f64], interior: &[bool], index: &[usize]) -> Option<Self> {
        let pattern = hessian(mesh, t, interior, index);
        let symbolic = SymbolicLlt::try_new(pattern.symbolic(), Side::Lower).ok()?;
        let (col_ptr, row_idx) = (pattern.symbolic().col_ptr(), pattern.symbolic().row_idx());
        let slots = angle_jacobian_triplets(mesh, t, interior)
            .into_iter()
            .map(|(i, j, _)| {
                let (a, b) = (index[i], index[j]);
                if a < b {
                    return Some(None);
                }
                let rows = &row_idx[col_ptr[b]..col_ptr[b + 1]];
                rows.binary_search(&a).ok().map(|k| Some(col_ptr[b] + k))
            })
            .collect::<Option<Vec<_>>>()?;
        Some(Assembly {
            pattern,
            slots,
            symbolic,
        })
    }

    /// The values of `H` at radii `t` in the pattern's column-major order, each entry of
    /// [`for_each_angle_jacobian_entry`] added to its slot in the triplets' order (so the
    /// same sums, in the same order, as a fill from [`angle_jacobian_triplets`]).
    fn values(&self, mesh: &Mesh, t: &[f64], interior: &[bool]) -> Option<Vec<f64>> {
        let mut values = vec![0.0; self.pattern.symbolic().row_idx().len()];
        let mut k = 0usize;
        let mut in_range = true;
        for_each_angle_jacobian_entry(mesh, t, interior, |_, _, v| {
            match self.slots.get(k) {
                Some(Some(slot)) => values[*slot] -= v,
                Some(None) => {}
                None => in_range = false,
            }
            k += 1;
        });
        (in_range && k == self.slots.len()).then_some(values)
    }
}

/// A sparse Cholesky factor of `H` on the interior vertices.
pub struct HessianFactor {
    llt: Llt<usize, f64>,
}

impl HessianFactor {
    /// Solve `H x = b`.
    pub fn solve(&self, b: &[f64]) -> Vec<f64> {
        let mut rhs = Mat::<f64>::from_fn(b.len(), 1, |i, _| b[i]);
        self.llt.solve_in_place(rhs.as_mut());
        (0..b.len()).map(|i| rhs[(i, 0)]).collect()
    }
}

/// Factor `H` at `u` (numerically; `None` when not positive definite). The first call
/// assembles `H` from sorted triplets and keeps its pattern ([`Assembly`]); later calls fill
/// the pattern's values in one pass.
fn factor(
    mesh: &Mesh,
    u: &[f64],
    interior: &[bool],
    index: &[usize],
    assembly: &mut Option<Assembly>,
) -> Option<HessianFactor> {
    let t = radii_from_u(u, interior);
    if assembly.is_none() {
        *assembly = Some(Assembly::new(mesh, &t, interior, index)?);
    }
    let a = assembly.as_ref()?;
    let values = a.values(mesh, &t, interior)?;
    let h = SparseColMatRef::new(a.pattern.symbolic(), &values);
    let llt = Llt::try_new_with_symbolic(a.symbolic.clone(), h, Side::Lower).ok()?;
    Some(HessianFactor { llt })
}

/// `2π − θ_v` on the interior vertices, in interior order.
pub fn residual<T: Real>(mesh: &Mesh, u: &[T], interior: &[bool]) -> Vec<T> {
    let t = radii_from_u(u, interior);
    let theta = angle_sums(mesh, &t);
    let two_pi = T::pi(u[0].ctx()) * &u[0].lit(2.0);
    theta
        .into_iter()
        .zip(interior)
        .filter(|&(_, &i)| i)
        .map(|(th, _)| two_pi.clone() - &th)
        .collect()
}

/// `2π − θ_v` on the interior vertices in `T` for the refinement: the rotation products of
/// [`residual_by_rotations`], guided by the `f64` residual at `u` rounded to `f64`.
fn refinement_residual<T: Real>(mesh: &Mesh, u: &[T], interior: &[bool]) -> Vec<T> {
    let u64: Vec<f64> = u.iter().map(Real::approx_f64).collect();
    let guide = residual_f64(mesh, &u64, interior);
    let t = radii_from_u(u, interior);
    residual_by_rotations(mesh, &t, interior, &guide)
}

/// [`residual`] in `f64`, one interior vertex at a time on rayon's thread pool: `2π` minus
/// the sum of [`corner_angle`] over the vertex's corners in the order of
/// [`Mesh::outgoing`] (the same terms as [`residual`], summed per vertex instead of per
/// face; the result does not depend on the number of threads). Needs a simplicial mesh
/// around the interior vertices, as the maximal packing does.
pub fn residual_f64(mesh: &Mesh, u: &[f64], interior: &[bool]) -> Vec<f64> {
    use rayon::prelude::*;
    let t = radii_from_u(u, interior);
    let vertices: Vec<usize> = (0..interior.len()).filter(|&v| interior[v]).collect();
    vertices
        .par_iter()
        .map(|&v| {
            let theta: f64 = mesh
                .outgoing(Vertex(v as u32))
                .map(|h| {
                    let (y, z) = (mesh.tip(h).idx(), mesh.tip(mesh.next(h)).idx());
                    corner_angle(&t[v], &t[y], &t[z])
                })
                .sum();
            std::f64::consts::TAU - theta
        })
        .collect()
}

fn max_abs<T: Real>(g: &[T]) -> f64 {
    g.iter().map(|x| x.approx_f64().abs()).fold(0.0, f64::max)
}

fn norm2(g: &[f64]) -> f64 {
    g.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// The `f64` solution: `u` per vertex (0 on the boundary, where `t = 1`), the factor of `H`
/// at it, Newton iterations, and the final `max |2π − θ|`.
pub struct F64Solution {
    /// `ln t` per vertex (0 on horocycles).
    pub u: Vec<f64>,
    /// The sparse Cholesky factor of `H` at `u`.
    pub factor: HessianFactor,
    /// Newton iterations.
    pub iterations: usize,
    /// `max |2π − θ|` at `u`.
    pub residual: f64,
}

/// Interior index of every vertex (`usize::MAX` on the boundary).
pub fn interior_index(interior: &[bool]) -> Vec<usize> {
    let mut k = 0;
    interior
        .iter()
        .map(|&i| {
            if i {
                k += 1;
                k - 1
            } else {
                usize::MAX
            }
        })
        .collect()
}

/// The common value `c` of `u` on the interior vertices at which the residuals sum to zero,
/// `S(c) = Σ_v (2π − θ_v(c)) = 0`, a starting point for [`newton_f64`] that has the
/// packing's overall scale (its radii shrink like `n^{−1/2}`, so a fixed start costs several
/// Newton iterations at large `n`).
///
/// `S` is increasing: `S′(c) = 𝟙ᵀH𝟙 > 0` with `H = −∂θ/∂u` positive definite on the
/// interior ([`super::hyperbolic`]). As `c → 0⁻` every angle tends to `0` and
/// `S → 2π·V_int > 0`; as `c → −∞` every face's angles tend to a Euclidean triangle's
/// (a horocycle's corner to `0`), so `Σ θ → πF` and `S → 2πV_int − πF = −π(V_∂ − 2)`
/// (`F = 2V_int + V_∂ − 2` on a disk), negative when the boundary has more than two
/// vertices. The root is bracketed from `hi` (the given start, returned when `S(hi) ≤ 0`)
/// downwards in steps of `ln 4` and located by the Illinois variant of regula falsi to
/// within `0.05` in `c`: a heuristic start, not a bound (Newton decides convergence).
pub fn common_scale_start(mesh: &Mesh, interior: &[bool], hi: f64) -> f64 {
    let s = |c: f64| -> f64 {
        let u: Vec<f64> = interior.iter().map(|&i| if i { c } else { 0.0 }).collect();
        residual_f64(mesh, &u, interior).iter().sum()
    };
    let (mut b, mut sb) = (hi, s(hi));
    if sb.is_nan() || sb <= 0.0 {
        return hi;
    }
    let (mut a, mut sa) = (hi, sb);
    for _ in 0..40 {
        a -= 4f64.ln();
        sa = s(a);
        if sa < 0.0 {
            break;
        }
        (b, sb) = (a, sa);
    }
    if sa.is_nan() || sa >= 0.0 {
        return hi;
    }
    // Illinois: a < root < b, S(a) < 0 < S(b).
    let mut last_side = 0i8;
    for _ in 0..30 {
        if b - a <= 0.05 {
            break;
        }
        let c = (a * sb - b * sa) / (sb - sa);
        let sc = s(c);
        if !sc.is_finite() {
            break;
        }
        if sc < 0.0 {
            (a, sa) = (c, sc);
            if last_side == -1 {
                sb *= 0.5;
            }
            last_side = -1;
        } else {
            (b, sb) = (c, sc);
            if last_side == 1 {
                sa *= 0.5;
            }
            last_side = 1;
        }
    }
    0.5 * (a + b)
}

/// Newton's method in `f64` from `start` (`u = ln tanh(r/2) < 0` per vertex, read on the
/// interior vertices) until `max |2π − θ| ≤ tol`; the step is halved until the residual's
/// 2-norm decreases and every `u` stays negative (`t < 1`). A residual below `tol` but above
/// `tol/10³` that the last step still contracted more than `10³`-fold (Newton's quadratic
/// phase, not yet at the rounding floor) gets one more step: it costs an `f64` iteration and
/// saves a refinement step in the slower backend.
pub fn newton_f64(
    mesh: &Mesh,
    interior: &[bool],
    start: &[f64],
    tol: f64,
    max_iter: usize,
) -> Result<F64Solution, MaximalSolveError> {
    let index = interior_index(interior);
    let mut u: Vec<f64> = start
        .iter()
        .zip(interior)
        .map(|(&x, &i)| if i { x } else { 0.0 })
        .collect();
    let mut assembly = None;
    let mut g = residual_f64(mesh, &u, interior);
    let mut previous = f64::INFINITY;
    for it in 0..=max_iter {
        let res = max_abs(&g);
        let f = factor(mesh, &u, interior, &index, &mut assembly)
            .ok_or(MaximalSolveError::Singular(it))?;
        let at_floor = res <= 1e-3 * tol || res * 1e3 > previous;
        if res <= tol && (at_floor || it == max_iter) {
            return Ok(F64Solution {
                u,
                factor: f,
                iterations: it,
                residual: res,
            });
        }
        if it == max_iter {
            break;
        }
        previous = res;
        let neg: Vec<f64> = g.iter().map(|x| -x).collect();
        let d = f.solve(&neg);
        let g_norm = norm2(&g);
        let mut step = 1.0;
        let mut accepted = None;
        for _ in 0..60 {
            let mut trial = u.clone();
            let mut ok = true;
            for (v, x) in trial.iter_mut().enumerate() {
                if interior[v] {
                    *x += step * d[index[v]];
                    ok &= *x < 0.0 && x.is_finite();
                }
            }
            if ok {
                let gt = residual_f64(mesh, &trial, interior);
                if norm2(&gt) < g_norm {
                    accepted = Some((trial, gt));
                    break;
                }
            }
            step *= 0.5;
        }
        let Some((trial, gt)) = accepted else {
            if res <= tol {
                return Ok(F64Solution {
                    u,
                    factor: f,
                    iterations: it,
                    residual: res,
                });
            }
            return Err(MaximalSolveError::Stalled {
                iteration: it,
                residual: res,
            });
        };
        u = trial;
        g = gt;
    }
    Err(MaximalSolveError::NoConvergence {
        iterations: max_iter,
        residual: max_abs(&g),
    })
}

/// Mixed-precision refinement of the `f64` solution in the backend of `ctx`: `u ← u + d`
/// with `H d = −(2π − θ(u))` solved by the `f64` factor, the residual in `T`, until
/// `max |2π − θ| ≤ tol` or `max_iter` steps. Returns `u` per vertex and the steps taken.
pub fn refine<T: Real>(
    mesh: &Mesh,
    interior: &[bool],
    sol: &F64Solution,
    ctx: T::Ctx,
    tol: f64,
    max_iter: usize,
) -> Result<(Vec<T>, usize), MaximalSolveError> {
    let u: Vec<T> = sol.u.iter().map(|&x| T::from_f64(x, ctx)).collect();
    refine_from(mesh, interior, sol, u, ctx, tol, max_iter)
}

/// [`refine`] from the point `u` of the backend instead of the `f64` solution (continuing
/// a refinement to a tighter `tol`).
pub fn refine_from<T: Real>(
    mesh: &Mesh,
    interior: &[bool],
    sol: &F64Solution,
    mut u: Vec<T>,
    ctx: T::Ctx,
    tol: f64,
    max_iter: usize,
) -> Result<(Vec<T>, usize), MaximalSolveError> {
    let index = interior_index(interior);
    let mut g = refinement_residual(mesh, &u, interior);
    for it in 0..max_iter {
        let res = max_abs(&g);
        if res <= tol {
            return Ok((u, it));
        }
        let neg: Vec<f64> = g.iter().map(|x| -x.approx_f64()).collect();
        let d = sol.factor.solve(&neg);
        for (v, x) in u.iter_mut().enumerate() {
            if interior[v] {
                *x += &T::from_f64(d[index[v]], ctx);
            }
        }
        g = refinement_residual(mesh, &u, interior);
    }
    let res = max_abs(&g);
    if res <= tol {
        return Ok((u, max_iter));
    }
    Err(MaximalSolveError::NoConvergence {
        iterations: max_iter,
        residual: res,
    })
}

#[cfg(test)]
mod tests {
    use super::{hessian, interior_index, Assembly};
    use crate::circles::maximal::hyperbolic::angle_jacobian_triplets;
    use crate::mesh::builders::random_planar;

    /// The pattern-filled `H` of [`Assembly`] equals the one assembled from sorted triplets
    /// entry by entry, up to the reordering of each entry's sum (B41: `k` terms summed in two
    /// orders differ by at most `2(k − 1)·u·Σ|terms| ≤ 2k·u·Σ|terms|`, `u = 2⁻⁵³`); the control: radii moved
    /// at one vertex change its entries far beyond that bound.
    #[test]
    fn pattern_filled_hessian_equals_the_sorted_assembly() {
        let mesh = random_planar(300, 3).unwrap().mesh;
        let interior: Vec<bool> = mesh
            .vertices()
            .map(|v| !mesh.is_boundary_vertex(v))
            .collect();
        let index = interior_index(&interior);
        let t: Vec<f64> = (0..mesh.n_vertices())
            .map(|v| {
                if interior[v] {
                    0.2 + 0.6 * ((v * 37 % 101) as f64 / 101.0)
                } else {
                    1.0
                }
            })
            .collect();
        let a = Assembly::new(&mesh, &t, &interior, &index).expect("assembly");
        // Σ|terms| and the number of terms per slot, for the bound.
        let mut abs = vec![0.0; a.pattern.symbolic().row_idx().len()];
        let mut count = vec![0usize; abs.len()];
        for ((_, _, v), slot) in angle_jacobian_triplets(&mesh, &t, &interior)
            .iter()
            .zip(&a.slots)
        {
            if let Some(k) = *slot {
                abs[k] += v.abs();
                count[k] += 1;
            }
        }
        let bound = |k: usize| 2.0 * count[k] as f64 * f64::EPSILON / 2.0 * abs[k];
        let values = a.values(&mesh, &t, &interior).expect("values");
        let sorted = hessian(&mesh, &t, &interior, &index);
        assert_eq!(sorted.symbolic().row_idx(), a.pattern.symbolic().row_idx());
        for (k, (x, y)) in values.iter().zip(sorted.val()).enumerate() {
            assert!((x - y).abs() <= bound(k), "slot {k}: {x} vs {y}");
        }
        // Control: other radii give other values, far outside the bound.
        let mut moved = t.clone();
        let v = (0..mesh.n_vertices()).find(|&v| interior[v]).unwrap();
        moved[v] *= 0.5;
        let other = a.values(&mesh, &moved, &interior).expect("values");
        assert!(other
            .iter()
            .zip(sorted.val())
            .enumerate()
            .any(|(k, (x, y))| (x - y).abs() > 1e6 * bound(k).max(f64::MIN_POSITIVE)));
    }
}
