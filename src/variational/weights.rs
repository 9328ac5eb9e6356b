//! The metric from its cotan weights (notes §1.3.4, Thm 2): a convex solve.
//!
//! With squared lengths `q_e = ℓ_e²`, a triangle's area satisfies
//! `∂A/∂q_e = cot α_e / 4` (`α_e` the angle opposite `e`; from `∂A/∂ℓ = ℓ cot α / 2`), so the
//! total area `𝒜(q) = Σ_t A_t(q)` has `∂𝒜/∂q_e = w_e/2` with the cotan weight
//! `w_e = ½(cot α + cot β)`. `A_t = ¼√Q(q)` with `Q = 2(ab + bc + ca) − a² − b² − c²` a
//! Lorentzian quadratic form, so `A_t` is concave on the cone of triangles (reverse
//! Cauchy–Schwarz) and homogeneous of degree 1. Hence
//! `G(q) = Σ_e w*_e q_e − 2𝒜(q)` is convex with `∇G = w* − w(q)`: the metrics with weights
//! `w*` are its minimisers, a ray (scale) by the theorem. The solver fixes the gauge
//! `q_g = 1` on one edge and runs damped Newton on the others; the Hessian
//! `∇²G = −∂w/∂q` comes from dual numbers, one direction per free edge (dense: for small
//! surfaces).
//!
//! ```
//! use penner::mesh::Mesh;
//! use penner::geometry::cotan::cotan_weights;
//! use penner::variational::weights::metric_from_weights;
//! // A tetrahedron with edges of lengths 1 … 1.5: recover ℓ²/ℓ₀² from the weights.
//! let m = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]).unwrap();
//! let l: Vec<f64> = (0..6).map(|e| 1.0 + 0.1 * e as f64).collect();
//! let w = cotan_weights(&m, &l);
//! let s = metric_from_weights(&m, &w, 0).unwrap();
//! assert!(s.converged);
//! for e in 0..6 { assert!((s.q[e] - l[e] * l[e]).abs() < 1e-9); }
//! ```

use super::triangle::{shape, Shape};
use crate::geometry::cotan::cotan_weights;
use crate::geometry::triangle::kahan_area;
use crate::mesh::Mesh;
use crate::scalar::dense::lu_solve;
use crate::scalar::{Dual, Real};

/// The most Newton steps [`metric_from_weights`] takes.
pub const MAX_NEWTON_STEPS: usize = 100;

/// The cotan weights of the metric with squared lengths `q`.
pub fn weights_of_squared<T: Real>(mesh: &Mesh, q: &[T]) -> Vec<T> {
    let l: Vec<T> = q.iter().map(Real::sqrt).collect();
    cotan_weights(mesh, &l)
}

/// `G(q) = Σ_e w*_e q_e − 2 Σ_t A_t(q)` (module doc); `None` without edges.
pub fn weight_energy<T: Real>(mesh: &Mesh, q: &[T], target: &[T]) -> Option<T> {
    let z = q.first()?;
    let l: Vec<T> = q.iter().map(Real::sqrt).collect();
    let mut g = z.zero_like();
    for (w, x) in target.iter().zip(q) {
        g += &(w.clone() * x);
    }
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_halfedges(f).map(|h| &l[h.edge().idx()]);
        g -= &(kahan_area(a, b, c) * &z.lit(2.0));
    }
    Some(g)
}

/// Whether every face of the squared lengths `q` is a proper triangle (decided on the
/// computed square roots, [`shape`]).
fn all_proper<T: Real>(mesh: &Mesh, q: &[T]) -> bool {
    mesh.faces().all(|f| {
        let l = mesh.face_halfedges(f).map(|h| q[h.edge().idx()].sqrt());
        shape(&l) == Shape::Proper
    })
}

/// The outcome of [`metric_from_weights`].
#[derive(Clone, Debug)]
pub struct WeightSolve<T> {
    /// Squared lengths with `q_gauge = 1`.
    pub q: Vec<T>,
    /// Newton steps taken.
    pub steps: usize,
    /// Whether the reduced gradient fell below the stopping threshold.
    pub converged: bool,
    /// `w* − w(q)` at the result (all edges).
    pub residual: Vec<T>,
    /// The reduced Hessian `−∂w/∂q` at the result, rows and columns over the free edges
    /// (index `e` for `e < gauge`, `e − 1` after), in `f64`.
    pub hessian: Vec<Vec<f64>>,
    /// Its inverse (empty when singular).
    pub hessian_inverse: Vec<Vec<f64>>,
}

/// The reduced Hessian `−∂w_i/∂q_j` over the free edges, by dual numbers.
fn reduced_hessian<T: Real>(mesh: &Mesh, q: &[T], free: &[usize]) -> Vec<Vec<T>> {
    let mut h = vec![Vec::with_capacity(free.len()); free.len()];
    for &k in free {
        let qd: Vec<Dual<T>> = q
            .iter()
            .enumerate()
            .map(|(e, x)| {
                let d = if e == k { x.one_like() } else { x.zero_like() };
                Dual::new(x.clone(), d)
            })
            .collect();
        let wd = weights_of_squared(mesh, &qd);
        for (r, &i) in free.iter().enumerate() {
            h[r].push(-wd[i].d.clone());
        }
    }
    h
}

/// Solve `a x = b` ([`lu_solve`], partial pivoting on the `f64` approximations, a
/// heuristic); `None` on a zero pivot.
fn solve<T: Real>(a: Vec<Vec<T>>, b: Vec<T>) -> Option<Vec<T>> {
    lu_solve(a, vec![b], 0.0)?.pop()
}

/// The inverse of an `f64` matrix (columns by [`solve`]); `None` when singular.
fn inverse(a: &[Vec<f64>]) -> Option<Vec<Vec<f64>>> {
    let n = a.len();
    let mut cols = Vec::with_capacity(n);
    for k in 0..n {
        let e: Vec<f64> = (0..n).map(|i| if i == k { 1.0 } else { 0.0 }).collect();
        cols.push(solve(a.to_vec(), e)?);
    }
    Some(
        (0..n)
            .map(|i| (0..n).map(|k| cols[k][i]).collect())
            .collect(),
    )
}

/// Squared lengths with cotan weights `target` (one per edge), `q_gauge = 1`, by damped
/// Newton on `G` (module doc) from the equilateral metric `q = 1`. Steps are halved until
/// every face stays a proper triangle and the reduced gradient's largest entry decreases.
/// Stops when that entry is below `2^{10−p}·(1 + max|w*|)` (a stopping rule, read in
/// `f64`) or after [`MAX_NEWTON_STEPS`]. `None` on malformed input (wrong count, gauge out
/// of range, no edges) or a singular Newton system.
pub fn metric_from_weights<T: Real>(
    mesh: &Mesh,
    target: &[T],
    gauge: usize,
) -> Option<WeightSolve<T>> {
    let m = mesh.n_edges();
    if target.len() != m || gauge >= m {
        return None;
    }
    let z = target.first()?;
    let free: Vec<usize> = (0..m).filter(|&e| e != gauge).collect();
    let mut q = vec![z.one_like(); m];
    let scale = 1.0
        + target
            .iter()
            .fold(0.0_f64, |a, w| a.max(w.approx_f64().abs()));
    let stop = (10.0 - f64::from(T::precision_bits(z.ctx()))).exp2() * scale;
    let norm = |q: &[T]| -> (Vec<T>, f64) {
        let w = weights_of_squared(mesh, q);
        let r: Vec<T> = target.iter().zip(&w).map(|(a, b)| a.clone() - b).collect();
        let n = free
            .iter()
            .fold(0.0_f64, |a, &e| a.max(r[e].approx_f64().abs()));
        (r, n)
    };
    let (mut r, mut rn) = norm(&q);
    let mut steps = 0;
    let mut converged = rn <= stop;
    while !converged && steps < MAX_NEWTON_STEPS {
        steps += 1;
        let h = reduced_hessian(mesh, &q, &free);
        // ∇G = w* − w = r; Newton: H s = −r.
        let rhs: Vec<T> = free.iter().map(|&e| -r[e].clone()).collect();
        let s = solve(h, rhs)?;
        let mut t = 1.0;
        let mut accepted = false;
        for _ in 0..60 {
            let mut qn = q.clone();
            for (k, &e) in free.iter().enumerate() {
                qn[e] += &(s[k].clone() * &s[k].lit(t));
            }
            if all_proper(mesh, &qn) {
                let (rr, nn) = norm(&qn);
                if nn < rn {
                    q = qn;
                    r = rr;
                    rn = nn;
                    accepted = true;
                    break;
                }
            }
            t *= 0.5;
        }
        converged = rn <= stop;
        if !accepted {
            break;
        }
    }
    let h: Vec<Vec<f64>> = reduced_hessian(mesh, &q, &free)
        .iter()
        .map(|row| row.iter().map(Real::approx_f64).collect())
        .collect();
    let hessian_inverse = inverse(&h).unwrap_or_default();
    Some(WeightSolve {
        q,
        steps,
        converged,
        residual: r,
        hessian: h,
        hessian_inverse,
    })
}
