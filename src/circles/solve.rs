//! Two independent solvers for prescribed cone angles `Θ` of a circle pattern, in
//! `u = log r`:
//!
//! - [`newton`]: Newton's method on the convex energy `E(u)` with `∇E = Θ − θ(u)` and
//!   Hessian `−∂θ/∂u` ([`super::jacobian`]), grounded at one vertex on closed problems, with
//!   a line search that halves the step until `|∇E|₂` decreases (at high precision an
//!   Armijo test on `E` stalls; docs/catalogue.md §7).
//! - [`ricci_flow`]: the combinatorial Ricci flow of Chow–Luo (2003),
//!   `du_i/dt = −(K_i − K̄_i) = θ_i − Θ_i`, the gradient flow of `−E`, by explicit Euler
//!   steps `dt = 1/G` with `G` the Gershgorin bound of the Hessian (a step that keeps the
//!   energy decreasing).
//!
//! The stopping rules read `approx_f64` (a heuristic, never a verdict): proofs of a
//! solution come from [`super::certify`].

use super::jacobian::angle_jacobian;
use super::metric::{cone_angles, lengths_from_radii};
use super::pattern::CirclePattern;
use crate::scalar::dense::solve_spd;
use crate::scalar::Real;

/// Why a solver stopped without a solution.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SolveError {
    /// The start vector does not have one value per vertex.
    #[error("start: expected {expected} values of u, got {got}")]
    StartLength {
        /// Vertices.
        expected: usize,
        /// Values given.
        got: usize,
    },
    /// The Hessian was not numerically positive definite.
    #[error("iteration {iteration}: the grounded Hessian is not positive definite")]
    Singular {
        /// Newton iteration.
        iteration: usize,
    },
    /// No step decreased the gradient norm before the residual reached the target.
    #[error("iteration {iteration}: no step decreases |∇E| (residual {residual:e})")]
    Stalled {
        /// Newton iteration.
        iteration: usize,
        /// `max |Θ − θ|` reached.
        residual: f64,
    },
    /// The iteration cap was reached.
    #[error("{iterations} iterations without convergence (residual {residual:e})")]
    NoConvergence {
        /// Iterations run.
        iterations: usize,
        /// `max |Θ − θ|` reached.
        residual: f64,
    },
}

/// A computed solution `u` (with `u_ground = 0` on closed problems) and its history.
#[derive(Clone, Debug)]
pub struct Solution<T> {
    /// `log r_v` per vertex.
    pub u: Vec<T>,
    /// Iterations (Newton) or steps (flow) taken.
    pub iterations: usize,
    /// `max_v |Θ_v − θ_v|` at the end (display only).
    pub residual: f64,
    /// `max_v |Θ_v − θ_v|` after every iteration or step (display only).
    pub history: Vec<f64>,
    /// Flow time per history entry (Newton: the iteration count).
    pub times: Vec<f64>,
}

/// The gradient `Θ_v − θ_v(u)` on the free vertices of `p`.
pub fn gradient<T: Real>(p: &CirclePattern, u: &[T], cos_phi: &[T], theta_t: &[T]) -> Vec<T> {
    let r: Vec<T> = u.iter().map(Real::exp).collect();
    let l = lengths_from_radii(&p.mesh, &r, cos_phi);
    let theta = cone_angles(&p.mesh, &l);
    p.free()
        .into_iter()
        .map(|v| theta_t[v].clone() - &theta[v])
        .collect()
}

/// The Hessian `−∂θ/∂u` of the energy restricted to the free vertices of `p`.
pub fn hessian<T: Real>(p: &CirclePattern, u: &[T], cos_phi: &[T]) -> Vec<Vec<T>> {
    let r: Vec<T> = u.iter().map(Real::exp).collect();
    let l = lengths_from_radii(&p.mesh, &r, cos_phi);
    let j = angle_jacobian(&p.mesh, &r, cos_phi, &l);
    let free = p.free();
    free.iter()
        .map(|&a| free.iter().map(|&b| -j[a][b].clone()).collect())
        .collect()
}

fn max_abs<T: Real>(g: &[T]) -> f64 {
    g.iter().map(|x| x.approx_f64().abs()).fold(0.0, f64::max)
}

fn norm2<T: Real>(g: &[T]) -> f64 {
    g.iter().map(|x| x.approx_f64().powi(2)).sum::<f64>().sqrt()
}

/// The stopping residual of the solvers at the precision of `ctx`: `2⁶·n·u` radians
/// (a heuristic; certification re-evaluates the gradient with enclosures).
pub fn default_tolerance<T: Real>(n: usize, ctx: T::Ctx) -> f64 {
    64.0 * (n.max(1) as f64) * T::unit_roundoff(ctx)
}

fn grounded_start<T: Real>(p: &CirclePattern, start: &[T]) -> Result<Vec<T>, SolveError> {
    let n = p.mesh.n_vertices();
    if start.len() != n {
        return Err(SolveError::StartLength {
            expected: n,
            got: start.len(),
        });
    }
    let mut u = start.to_vec();
    if let Some(g) = p.ground() {
        let shift = u[g].clone();
        for x in &mut u {
            *x -= &shift;
        }
    }
    Ok(u)
}

/// Newton's method from `start` (one `u` per vertex; shifted so that `u_ground = 0`) until
/// `max |Θ − θ| ≤ tol`, at most `max_iter` iterations.
pub fn newton<T: Real>(
    p: &CirclePattern,
    start: &[T],
    tol: f64,
    max_iter: usize,
) -> Result<Solution<T>, SolveError> {
    let mut u = grounded_start(p, start)?;
    let ctx = u[0].ctx();
    let cos_phi = p.cos_phi::<T>(ctx);
    let theta_t = p.target_angles::<T>(ctx);
    let free = p.free();
    let mut g = gradient(p, &u, &cos_phi, &theta_t);
    let mut history = Vec::new();
    for it in 0..max_iter {
        let res = max_abs(&g);
        history.push(res);
        if res <= tol {
            let times = (0..history.len()).map(|k| k as f64).collect();
            return Ok(Solution {
                u,
                iterations: it,
                residual: res,
                history,
                times,
            });
        }
        let h = hessian(p, &u, &cos_phi);
        let neg_g: Vec<T> = g.iter().map(|x| -x.clone()).collect();
        let d = solve_spd(&h, &neg_g).ok_or(SolveError::Singular { iteration: it })?;
        let g_norm = norm2(&g);
        let mut t = 1.0;
        let mut accepted = None;
        for _ in 0..60 {
            let mut trial = u.clone();
            for (k, &v) in free.iter().enumerate() {
                trial[v] += &(d[k].clone() * &d[k].lit(t));
            }
            let gt = gradient(p, &trial, &cos_phi, &theta_t);
            if norm2(&gt) < g_norm {
                accepted = Some((trial, gt));
                break;
            }
            t *= 0.5;
        }
        match accepted {
            Some((trial, gt)) => {
                u = trial;
                g = gt;
            }
            None => {
                return Err(SolveError::Stalled {
                    iteration: it,
                    residual: res,
                })
            }
        }
    }
    Err(SolveError::NoConvergence {
        iterations: max_iter,
        residual: max_abs(&g),
    })
}

/// The combinatorial Ricci flow `du/dt = θ − Θ` on the free vertices from `start`, by
/// explicit Euler steps `dt = 1/G` (`G` the largest Gershgorin radius `Σ_j |H_ij|` of the
/// Hessian at the current `u`), until `max |Θ − θ| ≤ tol` or `max_steps` steps. On closed
/// problems `u` is re-grounded (`u_ground = 0`) at the end. With `keep_going` the flow runs
/// all `max_steps` steps and returns the last state even without convergence (to watch a
/// degeneration, T10).
pub fn ricci_flow<T: Real>(
    p: &CirclePattern,
    start: &[T],
    tol: f64,
    max_steps: usize,
    keep_going: bool,
) -> Result<Solution<T>, SolveError> {
    let mut u = grounded_start(p, start)?;
    let ctx = u[0].ctx();
    let cos_phi = p.cos_phi::<T>(ctx);
    let theta_t = p.target_angles::<T>(ctx);
    let free_vertices: Vec<usize> = (0..u.len()).filter(|&v| p.targets[v].is_some()).collect();
    let mut history = Vec::new();
    let mut times = Vec::new();
    let mut time = 0.0;
    let mut step = 0;
    loop {
        let r: Vec<T> = u.iter().map(Real::exp).collect();
        let l = lengths_from_radii(&p.mesh, &r, &cos_phi);
        let theta = cone_angles(&p.mesh, &l);
        let res = free_vertices
            .iter()
            .map(|&v| (theta_t[v].clone() - &theta[v]).approx_f64().abs())
            .fold(0.0, f64::max);
        history.push(res);
        times.push(time);
        if (res <= tol && !keep_going) || step == max_steps {
            if res > tol && !keep_going {
                return Err(SolveError::NoConvergence {
                    iterations: step,
                    residual: res,
                });
            }
            if let Some(g) = p.ground() {
                let shift = u[g].clone();
                for x in &mut u {
                    *x -= &shift;
                }
            }
            return Ok(Solution {
                u,
                iterations: step,
                residual: res,
                history,
                times,
            });
        }
        let j = angle_jacobian(&p.mesh, &r, &cos_phi, &l);
        let gersh = free_vertices
            .iter()
            .map(|&a| j[a].iter().map(|x| x.approx_f64().abs()).sum::<f64>())
            .fold(0.0, f64::max);
        let dt = if gersh > 0.0 && gersh.is_finite() {
            1.0 / gersh
        } else {
            0.1
        };
        for &v in &free_vertices {
            let du = (theta[v].clone() - &theta_t[v]) * &theta[v].lit(dt);
            u[v] += &du;
        }
        time += dt;
        step += 1;
    }
}

/// The exponential convergence rate `λ` of a flow history (`res ≈ C e^{−λt}`): the
/// least-squares slope of `−ln res` against `t` over the second half of the entries with
/// `res > 0`. `None` with fewer than 4 such entries.
pub fn convergence_rate(history: &[f64], times: &[f64]) -> Option<f64> {
    let pts: Vec<(f64, f64)> = times
        .iter()
        .zip(history)
        .filter(|&(_, &r)| r > 0.0 && r.is_finite())
        .map(|(&t, &r)| (t, -r.ln()))
        .collect();
    if pts.len() < 4 {
        return None;
    }
    let tail = &pts[pts.len() / 2..];
    let n = tail.len() as f64;
    let (mt, my) = tail
        .iter()
        .fold((0.0, 0.0), |(a, b), (t, y)| (a + t / n, b + y / n));
    let (mut num, mut den) = (0.0, 0.0);
    for (t, y) in tail {
        num += (t - mt) * (y - my);
        den += (t - mt) * (t - mt);
    }
    (den > 0.0).then(|| num / den)
}
