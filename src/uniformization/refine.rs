//! Mixed-precision refinement of a converged `f64` solution: the Hessian is factored once
//! in `f64` on the final triangulation, the residual `Θ − θ(u)` is evaluated in a higher
//! precision `T` (double-double or MPFR) with `u` kept in `T`, and `u ← u − H⁻¹(Θ − θ(u))`
//! is iterated. Nothing is factored in `T`.
//!
//! The base lengths on the final triangulation are the input lengths `ℓ⁰` of `T₀`
//! carried through the recorded Ptolemy flips in `T` (T28), not the `f64` ones of the
//! solve.

use super::components::Components;
use super::hessian::{grounded_hessian, newton_direction, CholeskyCache};
use super::newton::Uniformization;
use super::newton_driver::refine_loop;
use crate::algorithms::flips::flip_ptolemy;
use crate::geometry::cone_angles::cone_angles;
use crate::mesh::{Edge, Mesh};
use crate::scalar::Real;

/// The result of [`refine`].
#[derive(Clone, Debug)]
pub struct Refinement<T> {
    /// The refined log scale factors.
    pub u: Vec<T>,
    /// `Θ_i − θ_i(u)` at the refined `u`, in `T`.
    pub residual: Vec<T>,
    /// `max |Θ − θ|` (as `f64`) after each iteration, the first entry at the `f64` solution.
    pub history: Vec<f64>,
    /// Whether `max |Θ − θ| ≤ tolerance` was reached.
    pub reached: bool,
}

impl<T: Real> Refinement<T> {
    /// `max |Θ − θ|` at the refined `u` (as `f64`).
    pub fn residual_max(&self) -> f64 {
        self.history.last().copied().unwrap_or(f64::INFINITY)
    }
}

/// Why a refinement could not run.
#[derive(Debug, thiserror::Error)]
pub enum RefineError {
    /// The flip sequence does not replay (not a sequence of this solution).
    #[error("the recorded flip sequence does not replay at flip {index} (e{edge})")]
    Replay {
        /// Position in the sequence.
        index: usize,
        /// The edge.
        edge: u32,
    },
    /// The grounded Hessian could not be factored.
    #[error(
        "the grounded Hessian on the final triangulation is not numerically positive definite"
    )]
    Hessian,
    /// An angle sum is undefined (a face of the final triangulation is not a triangle).
    #[error("angle sum at v{vertex} undefined at the refined u")]
    Undefined {
        /// The vertex.
        vertex: usize,
    },
}

/// `ℓ⁰` (binary64, taken exactly) on `T₀` carried through `sequence` by Ptolemy flips in
/// `T`: the base lengths of the final triangulation. Returns the flipped mesh too.
pub fn carry_lengths<T: Real>(
    t0: &Mesh,
    l0: &[f64],
    sequence: &[Edge],
    ctx: T::Ctx,
) -> Result<(Mesh, Vec<T>), RefineError> {
    carry_lengths_from(
        t0,
        l0.iter().map(|&x| T::from_f64(x, ctx)).collect(),
        sequence,
    )
}

/// Lengths `l` of `T₀` (in `T`: e.g. the exact input metric enclosed) carried through
/// `sequence` by Ptolemy flips; the flipped mesh too.
pub fn carry_lengths_from<T: Real>(
    t0: &Mesh,
    mut l: Vec<T>,
    sequence: &[Edge],
) -> Result<(Mesh, Vec<T>), RefineError> {
    let mut m = t0.clone();
    for (index, &e) in sequence.iter().enumerate() {
        if e.idx() >= m.n_edges() || flip_ptolemy(&mut m, &mut l, e).is_err() {
            return Err(RefineError::Replay { index, edge: e.0 });
        }
    }
    Ok((m, l))
}

/// The scaled lengths `e^{(u_i+u_j)/2}·ℓ_ij` in `T`.
pub fn scaled<T: Real>(mesh: &Mesh, base: &[T], u: &[T]) -> Vec<T> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let s = (u[mesh.tail(h).idx()].clone() + &u[mesh.tip(h).idx()]) * &base[0].lit(0.5);
            s.exp() * &base[e.idx()]
        })
        .collect()
}

/// `Θ_i = q_i·π` in `T`.
pub fn targets_in<T: Real>(sol: &Uniformization, ctx: T::Ctx) -> Vec<T> {
    let pi = T::pi(ctx);
    sol.targets
        .over_pi()
        .iter()
        .map(|q| T::from_rational(q, ctx) * &pi)
        .collect()
}

/// Refine `sol.u` in precision `ctx` until `max |Θ − θ| ≤ tolerance` or `max_iterations`
/// refinement steps, or until an iteration fails to halve the residual twice in a row (the
/// precision's floor).
pub fn refine<T: Real>(
    sol: &Uniformization,
    ctx: T::Ctx,
    tolerance: f64,
    max_iterations: usize,
) -> Result<Refinement<T>, RefineError> {
    let l0 = sol
        .initial_lengths
        .iter()
        .map(|&x| T::from_f64(x, ctx))
        .collect();
    refine_on(sol, l0, ctx, tolerance, max_iterations)
}

/// [`refine`] for another metric on `T₀`: `l0` are the lengths of `sol.initial_mesh` in
/// `T` (e.g. the exact input lengths, flipped to `T₀` in `T`, where the `f64` solve used
/// their rounding). The `f64` solution is the starting point and its flip sequence the
/// triangulation.
pub fn refine_on<T: Real>(
    sol: &Uniformization,
    l0: Vec<T>,
    ctx: T::Ctx,
    tolerance: f64,
    max_iterations: usize,
) -> Result<Refinement<T>, RefineError> {
    let (mesh, base) = carry_lengths_from(&sol.initial_mesh, l0, &sol.flip_sequence)?;
    let theta_target = targets_in::<T>(sol, ctx);
    let u: Vec<T> = sol.u.iter().map(|&x| T::from_f64(x, ctx)).collect();
    let comps = Components::of(&mesh);
    let (_, free_idx) = comps.free_index();
    // The f64 Hessian once, from the lengths divided by the longest (angles are
    // scale-invariant).
    let l = scaled(&mesh, &base, &u);
    let top = l.iter().map(Real::approx_f64).fold(0.0, f64::max);
    let lf: Vec<f64> = l.iter().map(|x| x.approx_f64() / top).collect();
    let h = grounded_hessian(&mesh, &lf, &free_idx);
    let mut cache = CholeskyCache::default();
    let factor = cache.factor(&h).ok_or(RefineError::Hessian)?;
    let residual = |u: &[T]| -> Vec<T> {
        let theta = cone_angles(&mesh, &scaled(&mesh, &base, u));
        theta_target
            .iter()
            .zip(&theta)
            .map(|(t, th)| t.clone() - th)
            .collect()
    };
    // H d = −∇E = −(Θ − θ): the Newton correction from the f64 factor.
    let correction = |r: &[f64]| newton_direction(&factor, r, &comps);
    match refine_loop(u, ctx, tolerance, max_iterations, residual, correction) {
        (refinement, None) => Ok(refinement),
        (_, Some(vertex)) => Err(RefineError::Undefined { vertex }),
    }
}
