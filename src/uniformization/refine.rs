//! Mixed-precision refinement of a converged `f64` solution: the Hessian is factored once
//! in `f64` on the final triangulation, the residual `Θ − θ(u)` is evaluated in a higher
//! precision `T` (double-double or MPFR) with `u` kept in `T`, and `u ← u − H⁻¹(Θ − θ(u))`
//! is iterated, from the second step on with the Hessian of an iterate in double-double
//! preconditioned by the `f64` factor ([`super::refine_newton`]): the residual squares at
//! each step (`10⁻¹²`, `10⁻²⁴`, `10⁻⁴⁸`, `10⁻⁷²`). Nothing is factored in `T`.
//!
//! The base lengths on the final triangulation are the input lengths `ℓ⁰` of `T₀`
//! carried through the recorded Ptolemy flips in `T` (T28), not the `f64` ones of the
//! solve. At every iterate the triangulation is kept intrinsic Delaunay for the scaled
//! metric by Ptolemy flips decided in `T` ([`flip_to_delaunay_at`]): `∇E = Θ − θ` with `θ`
//! the angle sums of a Delaunay triangulation (T32). On a fixed triangulation `T` the
//! iteration would converge to the zero `u_T` of `∇E_T` instead, and where the solution
//! lies past a Delaunay tie of `T` (by the `f64` solve's error, `|P|/ℓ⁴ ~ 10⁻¹⁶`) the two
//! differ: `E` is only `C²` across the tie, so `∇E(u_T) = ∇E(u_T) − ∇E_T(u_T) = O(P²)`,
//! about `10⁻³¹`, which no precision removes (B69).

use super::components::Components;
use super::hessian::{grounded_hessian, newton_direction, CholeskyCache};
use super::newton::Uniformization;
pub use super::newton_driver::Refinement;
use super::newton_driver::{refine_loop, Over};
use super::refine_newton::{newton_correction, to_dd, IterateLaplacian};
use super::refine_scaling::HalfExp;
use crate::algorithms::flips::flip_ptolemy;
use crate::geometry::cone_angles::cone_angles;
use crate::mesh::{Edge, Mesh};
use crate::predicates::delaunay::{delaunay_p, QuadEdges};
use crate::scalar::{Dd, Real};
use std::cell::RefCell;

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
    /// Ptolemy flipping to the Delaunay triangulation at an iterate failed or hit its cap.
    #[error("Ptolemy flips to the Delaunay triangulation at the refined u failed: {0}")]
    Flips(String),
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

/// The scaled lengths `e^{(u_i+u_j)/2}·ℓ_ij = e^{u_i/2}·e^{u_j/2}·ℓ_ij` in `T`: one
/// exponential per vertex, two products per edge (on intervals, an enclosure by B20).
pub fn scaled<T: Real>(mesh: &Mesh, base: &[T], u: &[T]) -> Vec<T> {
    let Some(first) = base.first() else {
        return Vec::new();
    };
    let half = first.lit(0.5);
    let factor: Vec<T> = u.iter().map(|x| (x.clone() * &half).exp()).collect();
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            factor[mesh.tail(h).idx()].clone() * &factor[mesh.tip(h).idx()] * &base[e.idx()]
        })
        .collect()
}

/// The scaled length `e^{(u_i+u_j)/2}·ℓ_ij` of one edge `e = ij` in `T`.
fn scaled_edge<T: Real>(mesh: &Mesh, base: &[T], u: &[T], e: Edge) -> T {
    let h = e.halfedge();
    let s = (u[mesh.tail(h).idx()].clone() + &u[mesh.tip(h).idx()]) * &base[0].lit(0.5);
    s.exp() * &base[e.idx()]
}

/// Ptolemy-flip `mesh` towards the intrinsic Delaunay triangulation of the scaled metric
/// `e^{(u_i+u_j)/2}·base_ij` in `T` (T21), carrying `base` along by the same flips
/// (Ptolemy flips commute with scaling, T28). `lengths` holds [`scaled`]`(mesh, base, u)`
/// on entry and on return (the flipped edges' recomputed from the carried `base`).
/// Returns the flips in order (empty when `mesh` is already Delaunay at `u`). proof: B69
///
/// A heuristic for the refinement (the certificate decides, B35/B71): an edge whose `P`
/// (B60) evaluated in `f64` exceeds `10⁻⁸` of its magnitude `M = de(b²+c²+a²) +
/// bc(d²+e²+a²)` is kept; the others get `P` in `T`, and an edge is flipped only when it
/// is below `−2^(20−p)·M` (`p` the bits of `T`), so that an edge within rounding of a tie
/// (where either side carries the same angle sums up to `O(P²)`, B69) stays, and no flip
/// is undone by rounding. At most `E + 1024` flips.
pub fn flip_to_delaunay_at<T: Real>(
    mesh: &mut Mesh,
    base: &mut [T],
    lengths: &mut [T],
    u: &[T],
) -> Result<Vec<Edge>, RefineError> {
    let Some(first) = lengths.first() else {
        return Ok(Vec::new());
    };
    let margin = first.lit(2f64.powi(20 - T::precision_bits(first.ctx()).min(1000) as i32));
    // P and its magnitude M in T.
    let p_and_m = |q: [T; 5]| {
        let [a, b, c, d, e] = &q;
        let m = d.clone() * e * &(b.clone() * b + &(c.clone() * c) + &(a.clone() * a))
            + &(b.clone() * c * &(d.clone() * d + &(e.clone() * e) + &(a.clone() * a)));
        (delaunay_p(&q), m)
    };
    let near_tie = |q: [f64; 5]| {
        let [a, b, c, d, e] = q;
        if !q.iter().all(|x| x.is_normal() && (1e-60..1e60).contains(x)) {
            return true;
        }
        let p = delaunay_p(&q);
        let m = d * e * (b * b + c * c + a * a) + b * c * (d * d + e * e + a * a);
        p <= 1e-8 * m
    };
    let mut stack: Vec<Edge> = mesh
        .edges()
        .filter(|&e| {
            QuadEdges::of(mesh, e)
                .is_some_and(|q| near_tie(q.lengths(lengths).to_array().map(Real::approx_f64)))
        })
        .collect();
    let cap = mesh.n_edges() + 1024;
    let mut flips = Vec::new();
    while let Some(e) = stack.pop() {
        let Some(q) = QuadEdges::of(mesh, e) else {
            continue;
        };
        let (p, m) = p_and_m(q.lengths(lengths).to_array().map(Clone::clone));
        // Rounded values: a heuristic decision (the doc above).
        if (p + &(m * &margin)).approx_f64() >= 0.0 {
            continue;
        }
        if flips.len() >= cap {
            return Err(RefineError::Flips("the flip cap was reached".into()));
        }
        if flip_ptolemy(mesh, base, e).is_err() {
            return Err(RefineError::Flips(format!("e{} does not flip", e.0)));
        }
        lengths[e.idx()] = scaled_edge(mesh, base, u, e);
        flips.push(e);
        stack.extend(q.edges.to_array().into_iter().skip(1));
    }
    Ok(flips)
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
/// starting triangulation, kept Delaunay at every iterate ([`refine_with_flips`]).
pub fn refine_on<T: Real>(
    sol: &Uniformization,
    l0: Vec<T>,
    ctx: T::Ctx,
    tolerance: f64,
    max_iterations: usize,
) -> Result<Refinement<T>, RefineError> {
    refine_with_flips(sol, l0, ctx, tolerance, max_iterations).map(|(r, _)| r)
}

/// [`refine_on`], also returning the Ptolemy flips done after `sol.flip_sequence` to keep
/// the triangulation intrinsic Delaunay at the iterates (`sol.flip_sequence` followed by
/// them is the triangulation of the refined `u`). proof: B69
pub fn refine_with_flips<T: Real>(
    sol: &Uniformization,
    l0: Vec<T>,
    ctx: T::Ctx,
    tolerance: f64,
    max_iterations: usize,
) -> Result<(Refinement<T>, Vec<Edge>), RefineError> {
    let (mut mesh, mut base) = carry_lengths_from(&sol.initial_mesh, l0, &sol.flip_sequence)?;
    let theta_target = targets_in::<T>(sol, ctx);
    let u: Vec<T> = sol.u.iter().map(|&x| T::from_f64(x, ctx)).collect();
    let comps = Components::of(&mesh);
    let (free, free_idx) = comps.free_index();
    let every: Vec<usize> = (0..mesh.n_vertices()).collect();
    let problem = Problem {
        mesh: &mut mesh,
        base: &mut base,
        free: &free,
        free_idx: &free_idx,
        theta_target: &theta_target,
        measured: &every,
        keep_delaunay: true,
    };
    refine_problem(problem, u, ctx, tolerance, max_iterations)
}

/// A problem for [`refine_problem`]: the final triangulation with its base lengths in `T`,
/// the free vertices (the others keep their `u`), the targets and the vertices whose
/// residual `max |Θ − θ|` measures.
pub struct Problem<'a, T> {
    /// The final triangulation (Ptolemy-flipped in place when `keep_delaunay`).
    pub mesh: &'a mut Mesh,
    /// Its base lengths (before scaling), carried along by the flips.
    pub base: &'a mut [T],
    /// The free vertices, in order.
    pub free: &'a [usize],
    /// Per vertex, its index among the free ones.
    pub free_idx: &'a [Option<usize>],
    /// `Θ_i` per vertex (read at free vertices and at `measured`).
    pub theta_target: &'a [T],
    /// The vertices whose `|Θ − θ|` enters `max |Θ − θ|`.
    pub measured: &'a [usize],
    /// Keep the triangulation intrinsic Delaunay at every iterate ([`flip_to_delaunay_at`],
    /// B69); `false` keeps it fixed (a problem whose edges may not all flip, e.g. the
    /// sphere target's disk, whose star of `v∞` stays).
    pub keep_delaunay: bool,
}

/// The refinement loop: the Hessian on the free vertices factored once in `f64` at `u`,
/// then `u_free ← u_free − H⁻¹(Θ − θ(u))_free` with the residual in `T` (from the second
/// step on `H` the Hessian of the second iterate in double-double, solved by iterative
/// refinement on the `f64` factor, [`super::refine_newton`]), until
/// `max |Θ − θ| ≤ tolerance` (over `measured`), `max_iterations` steps, or two steps in a
/// row that do not halve it (the precision's floor). With `keep_delaunay` the
/// triangulation is flipped to Delaunay at every iterate and the flips are returned in
/// order (proof: B69); otherwise the returned flips are empty.
pub fn refine_problem<T: Real>(
    p: Problem<'_, T>,
    u: Vec<T>,
    ctx: T::Ctx,
    tolerance: f64,
    max_iterations: usize,
) -> Result<(Refinement<T>, Vec<Edge>), RefineError> {
    let Problem {
        mesh,
        base,
        free,
        free_idx,
        theta_target,
        measured,
        keep_delaunay,
    } = p;
    // The f64 Hessian once, from the lengths divided by the longest (angles are
    // scale-invariant). Flips at near-ties below change it by O(P): a preconditioner.
    let mut half = HalfExp::new(&u);
    let l = half.lengths(mesh, base);
    let top = l.iter().map(Real::approx_f64).fold(0.0, f64::max);
    let lf: Vec<f64> = l.iter().map(|x| x.approx_f64() / top).collect();
    let h = grounded_hessian(mesh, &lf, free_idx);
    let mut cache = CholeskyCache::default();
    let factor = cache.factor(&h).ok_or(RefineError::Hessian)?;
    let mut flips = Vec::new();
    // The first residual is at the same u: its scaled lengths are those of the Hessian.
    let mut at_start = Some(l);
    // The triangulation, the scaled lengths and the flip count of the last residual, for
    // the correction's Hessian at that iterate (refine_newton).
    let state: RefCell<(&mut Mesh, Vec<T>, usize)> = RefCell::new((mesh, Vec::new(), 0));
    let residual = |u: &[T]| -> Result<Vec<T>, RefineError> {
        let mut st = state.borrow_mut();
        let (mesh, last, flip_count) = &mut *st;
        let mut l = at_start.take().unwrap_or_else(|| {
            half.update(u, ctx);
            half.lengths(mesh, base)
        });
        if keep_delaunay {
            flips.extend(flip_to_delaunay_at(mesh, base, &mut l, u)?);
            *flip_count = flips.len();
        }
        let theta = cone_angles(mesh, &l);
        *last = l;
        Ok(theta_target
            .iter()
            .zip(&theta)
            .map(|(t, th)| t.clone() - th)
            .collect())
    };
    // H d = −∇E = −(Θ − θ) on the free vertices, zero at the vertices that keep their
    // `u`. The first correction from the f64 factor (the Hessian at the f64 solution up to
    // its rounding); the later ones solve with the Hessian in double-double at the second
    // iterate (refine_newton), kept while no flip changes the triangulation: it is within
    // the second iterate's error (about 10⁻²⁴ relative) of the Hessian at every later one,
    // so each step gains that much. The f64 correction where that Hessian is not finite.
    let mut calls = 0usize;
    let mut hessian: Option<(usize, Option<IterateLaplacian>)> = None;
    let correction = |r: &[T], rf: &[f64]| {
        calls += 1;
        let st = state.borrow();
        let (mesh, last, flip_count) = &*st;
        if calls > 1
            && hessian
                .as_ref()
                .is_none_or(|(count, _)| count != flip_count)
        {
            hessian = Some((*flip_count, IterateLaplacian::at(mesh, last, ctx)));
        }
        match hessian.as_ref().and_then(|(_, lap)| lap.as_ref()) {
            Some(lap) => {
                let rd: Vec<Dd> = r.iter().map(|x| to_dd(x, ctx)).collect();
                newton_correction(lap, &factor, &rd, free)
            }
            None => newton_direction(&factor, rf, free)
                .into_iter()
                .map(Dd::from_f64)
                .collect(),
        }
    };
    let limits = (tolerance, max_iterations);
    let over = Over(Some(measured));
    match refine_loop(u, ctx, limits, over, residual, correction)? {
        (refinement, None) => Ok((refinement, flips)),
        (_, Some(vertex)) => Err(RefineError::Undefined { vertex }),
    }
}
