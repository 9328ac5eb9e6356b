//! Discrete conformal maps with Dirichlet values: on a surface (with or without boundary)
//! a set `F` of vertices has prescribed log scale factors `u_a = w_a`, and the other
//! vertices `i` prescribed angle sums `θ_i(u) = Θ_i` (notes §1.5.3; docs/catalogue.md §7; the
//! disk problem of the sphere target, B74).
//!
//! This generalises the grounding of [`super::newton`] (one fixed vertex per closed
//! component, where Gauss–Bonnet makes the grounded equation redundant) to any fixed set:
//! the energy `E(u)` restricted to `{u : u_F = w}` is convex with gradient `Θ_i − θ_i` at
//! the free vertices and Hessian `−L` restricted to them (docs/catalogue.md §7), positive definite
//! when every component has a fixed vertex and the cotan weights are those of a Delaunay
//! triangulation. Boundary edges are never flipped; interior edges are kept intrinsic
//! Delaunay by Ptolemy flips, exactly as in [`super::newton`], whose evaluation
//! ([`super::newton::evaluate`]), sparse Cholesky and line search this solver shares.

use super::components::Components;
use super::error::UniformizeError;
use super::hessian::{grounded_hessian, newton_direction, CholeskyCache};
use super::newton::{evaluate, Evaluation, StepReport, Stop, UniformizeOptions};
use super::newton_driver::{drive, NewtonSystem, Over};
use crate::mesh::{Edge, Mesh};
use crate::scalar::exp_length::MAX_LOG_SCALE;

/// Why a Dirichlet problem was refused.
#[derive(Debug, thiserror::Error)]
pub enum DirichletError {
    /// Lengths, targets or the start are refused.
    #[error(transparent)]
    Input(#[from] UniformizeError),
    /// Wrong number of Dirichlet entries.
    #[error("{expected} Dirichlet entries expected (one per vertex), got {got}")]
    FixedCount {
        /// Vertices.
        expected: usize,
        /// Given.
        got: usize,
    },
    /// A prescribed value is not finite or `|w| > 2²⁰`.
    #[error("prescribed scale factor of vertex v{vertex} is {value}: not finite or |u| > 2²⁰")]
    BadFixed {
        /// The vertex.
        vertex: u32,
        /// The value.
        value: f64,
    },
    /// A component has no fixed vertex: `u` is not determined there.
    #[error("the component of v{vertex} has no vertex with a prescribed scale factor")]
    Unanchored {
        /// The smallest vertex of the component.
        vertex: u32,
    },
}

/// The result of [`solve_dirichlet`]; `u` is a solution only when `stop` is
/// [`Stop::Converged`].
#[derive(Clone, Debug)]
pub struct DirichletSolution {
    /// The final triangulation (interior edges intrinsic Delaunay for the scaled metric).
    pub mesh: Mesh,
    /// The base lengths carried to `mesh` by the Ptolemy flips (rounded, T28).
    pub base: Vec<f64>,
    /// The scaled lengths `e^{(u_i+u_j)/2}·ℓ_ij` on `mesh`, divided by a common power of two.
    pub lengths: Vec<f64>,
    /// Ptolemy flips from the input triangulation to `mesh`, in order.
    pub flip_sequence: Vec<Edge>,
    /// The log scale factors (the prescribed ones at fixed vertices).
    pub u: Vec<f64>,
    /// Accepted Newton steps.
    pub steps: Vec<StepReport>,
    /// Why the solver stopped.
    pub stop: Stop,
    /// `max |Θ_i − θ_i(u)|` over the free vertices.
    pub residual_max: f64,
}

/// The free vertices (no prescribed value) and, per vertex, its index among them.
pub fn free_index(fixed: &[Option<f64>]) -> (Vec<usize>, Vec<Option<usize>>) {
    let mut free = Vec::new();
    let idx = fixed
        .iter()
        .enumerate()
        .map(|(v, w)| {
            w.is_none().then(|| {
                free.push(v);
                free.len() - 1
            })
        })
        .collect();
    (free, idx)
}

fn max_free(grad: &[f64], free: &[usize]) -> f64 {
    Over(Some(free)).max_abs(grad)
}

fn validate(
    mesh: &Mesh,
    base: &[f64],
    fixed: &[Option<f64>],
    theta_target: &[f64],
    start: &[f64],
) -> Result<(), DirichletError> {
    let n = mesh.n_vertices();
    if mesh.n_faces() == 0 {
        return Err(UniformizeError::Empty.into());
    }
    if base.len() != mesh.n_edges() {
        return Err(UniformizeError::LengthCount {
            expected: mesh.n_edges(),
            got: base.len(),
        }
        .into());
    }
    if let Some(e) = base.iter().position(|x| !(x.is_finite() && *x > 0.0)) {
        return Err(UniformizeError::BadLength {
            edge: e as u32,
            value: base[e],
        }
        .into());
    }
    if fixed.len() != n {
        return Err(DirichletError::FixedCount {
            expected: n,
            got: fixed.len(),
        });
    }
    for (v, w) in fixed.iter().enumerate() {
        if let Some(w) = *w {
            if !(w.is_finite() && w.abs() <= MAX_LOG_SCALE) {
                return Err(DirichletError::BadFixed {
                    vertex: v as u32,
                    value: w,
                });
            }
        }
    }
    if theta_target.len() != n {
        return Err(UniformizeError::TargetCount {
            expected: n,
            got: theta_target.len(),
        }
        .into());
    }
    for (v, t) in theta_target.iter().enumerate() {
        if fixed[v].is_none() && !(t.is_finite() && *t > 0.0) {
            return Err(UniformizeError::NonFiniteTarget {
                vertex: v as u32,
                value: *t,
            }
            .into());
        }
    }
    if start.len() != n {
        return Err(UniformizeError::TargetCount {
            expected: n,
            got: start.len(),
        }
        .into());
    }
    if let Some(v) = start
        .iter()
        .position(|x| !(x.is_finite() && x.abs() <= MAX_LOG_SCALE))
    {
        return Err(UniformizeError::BadStart {
            vertex: v as u32,
            value: start[v],
        }
        .into());
    }
    let comps = Components::of(mesh);
    for (c, &root) in comps.roots.iter().enumerate() {
        if comps.vertices_of(c).all(|v| fixed[v].is_none()) {
            return Err(DirichletError::Unanchored {
                vertex: root as u32,
            });
        }
    }
    Ok(())
}

/// Solve `θ_i(u) = Θ_i` at the free vertices with `u_a = w_a` at the fixed ones
/// (`fixed[a] = Some(w_a)`), from `start` (its entries at fixed vertices are replaced by
/// the prescribed values), by Newton with Ptolemy flips and the line search of
/// [`super::newton`]. `theta_target` is read at free vertices only. Bad input is a typed
/// error; a solve that does not reach `opts.tolerance` returns `Ok` with its [`Stop`].
pub fn solve_dirichlet(
    mesh: &Mesh,
    base: &[f64],
    fixed: &[Option<f64>],
    theta_target: &[f64],
    start: &[f64],
    opts: &UniformizeOptions,
) -> Result<DirichletSolution, DirichletError> {
    validate(mesh, base, fixed, theta_target, start)?;
    let (free, free_idx) = free_index(fixed);
    let u: Vec<f64> = start
        .iter()
        .zip(fixed)
        .map(|(s, w)| w.unwrap_or(*s))
        .collect();
    let steps = Vec::new();
    let mut sequence = Vec::new();
    let finish = |ev: Evaluation, u, steps, sequence, stop| DirichletSolution {
        residual_max: max_free(&ev.grad, &free),
        mesh: ev.mesh,
        base: ev.base,
        lengths: ev.lengths,
        flip_sequence: sequence,
        u,
        steps,
        stop,
    };
    let ev = match evaluate(mesh, base, &u, theta_target) {
        Ok(ev) => ev,
        Err(reason) => {
            let ev = Evaluation {
                mesh: mesh.clone(),
                base: base.to_vec(),
                lengths: base.to_vec(),
                grad: vec![f64::NAN; mesh.n_vertices()],
                cot: Vec::new(),
                flips: Vec::new(),
            };
            return Ok(finish(ev, u, steps, sequence, Stop::DegenerateStep(reason)));
        }
    };
    sequence.extend_from_slice(&ev.flips);
    let mut sys = Fixed {
        theta_target,
        free: &free,
        free_idx: &free_idx,
        cache: CholeskyCache::default(),
        sequence,
    };
    let run = drive(
        &mut sys,
        Over(Some(&free)),
        u,
        ev,
        opts.limits(),
        &mut |_| {},
    );
    let stop = Stop::of_driver(run.stop, opts, max_free(&run.eval.grad, &free));
    Ok(finish(run.eval, run.u, run.steps, sys.sequence, stop))
}

/// The Dirichlet Newton system for [`drive`]: evaluation with Ptolemy flips, the Hessian
/// on the free vertices, the flips recorded.
struct Fixed<'a> {
    theta_target: &'a [f64],
    free: &'a [usize],
    free_idx: &'a [Option<usize>],
    cache: CholeskyCache,
    sequence: Vec<Edge>,
}

impl NewtonSystem for Fixed<'_> {
    type Eval = Evaluation;
    type Fault = String;

    fn gradient(ev: &Evaluation) -> &[f64] {
        &ev.grad
    }

    fn evaluate(&mut self, at: &Evaluation, u: &[f64]) -> Result<Evaluation, String> {
        evaluate(&at.mesh, &at.base, u, self.theta_target)
    }

    fn direction(&mut self, ev: &Evaluation) -> Result<Vec<f64>, String> {
        let h = grounded_hessian(&ev.mesh, &ev.lengths, self.free_idx);
        let Some(factor) = self.cache.factor(&h) else {
            return Err(
                "the Hessian on the free vertices is not numerically positive definite".into(),
            );
        };
        Ok(newton_direction(&factor, &ev.grad, self.free))
    }

    fn accept(&mut self, new: &Evaluation) -> usize {
        self.sequence.extend_from_slice(&new.flips);
        new.flips.len()
    }
}
