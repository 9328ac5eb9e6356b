//! The `f64` Newton solver for discrete uniformization with Ptolemy flips (notes §1.5.3
//! Thm 12; docs/catalogue.md §7; S20, GSC21).
//!
//! Convention: the input is first made intrinsic Delaunay by Euclidean flips (which keep
//! its cone metric, T23); that triangulation `T₀` with its lengths `ℓ⁰` is the metric being
//! uniformized. Then `u` moves, and at every `u` the scaled metric
//! `ℓ̃_ij = e^{(u_i+u_j)/2}·ℓ_ij` is flipped to an intrinsic Delaunay triangulation with
//! Ptolemy flips ([`flip_to_delaunay_scaled`]); Ptolemy flips commute with scaling (T28),
//! so the base lengths are carried along by the same flips.
//!
//! Newton: `∇E = Θ − θ(u)` and `H = −L` on the current Delaunay triangulation, grounded at
//! one vertex per component; `d = −H⁻¹∇E` by sparse Cholesky; a step `t ∈ {1, ½, ¼, …}` is
//! accepted when `|∇E(u+td)|₂ < |∇E(u)|₂` and either the projected gradient
//! `∇E(u+td)·d ≤ 0` (no overshoot of the minimum along `d`) or the residual at least halves
//! (the overshoot of a Newton step near the solution is at the level of rounding). No
//! energy-decrease test (it stalls at the working precision, docs/catalogue.md §7).

use super::components::Components;
use super::error::UniformizeError;
use super::hessian::{CholeskyCache, GroundedPattern};
pub use super::newton_driver::StepReport;
use super::newton_driver::{drive, DriverStop, Limits, NewtonSystem, Over};
use super::scaling::scaled_fast;
use super::targets::Targets;
use crate::algorithms::flip_scaled::flip_to_delaunay_exp;
use crate::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use crate::algorithms::flips::flip_ptolemy;
use crate::geometry::cone_angles::cone_angles_and_cotans;
use crate::mesh::{Edge, Mesh};
use crate::scalar::exp_length::{ExpLength, MAX_LOG_SCALE};

/// Solver options.
#[derive(Clone, Debug)]
pub struct UniformizeOptions {
    /// Stop when `max_i |Θ_i − θ_i| ≤ tolerance` (radians).
    pub tolerance: f64,
    /// At most this many Newton steps.
    pub max_iterations: usize,
    /// At most this many halvings of the step in one line search.
    pub max_halvings: usize,
    /// A starting `u` (default 0).
    pub start: Option<Vec<f64>>,
    /// Stop as stalled after this many consecutive steps of at most `2⁻¹⁰` that together
    /// reduce `max |Θ − θ|` by less than 0.1 % (the Newton driver's stall rule); `None`
    /// (the default): run to the iteration cap.
    pub stall_window: Option<usize>,
}

impl Default for UniformizeOptions {
    fn default() -> Self {
        UniformizeOptions {
            tolerance: 1e-10,
            max_iterations: 100,
            max_halvings: 40,
            start: None,
            stall_window: None,
        }
    }
}

impl UniformizeOptions {
    /// The Newton driver's limits (tolerance, iteration cap, halvings).
    pub(crate) fn limits(&self) -> Limits {
        Limits {
            tolerance: self.tolerance,
            max_iterations: self.max_iterations,
            max_halvings: self.max_halvings,
            stall_window: self.stall_window,
        }
    }
}

/// Why the solver stopped.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub enum Stop {
    /// `max |Θ − θ| ≤ tolerance`.
    Converged,
    /// The iteration cap was reached first.
    IterationCap,
    /// No acceptable step: the Hessian could not be factored, or the line search found
    /// no decrease or stalled (`UniformizeOptions::stall_window`), or the metric
    /// degenerated (a face not a triangle, lengths out of range).
    DegenerateStep(String),
}

impl Stop {
    /// The stop of a Euclidean solve (closed surface or Dirichlet problem) from the
    /// driver's, `residual_max` the last `max |Θ − θ|` (for the line search's message).
    pub(crate) fn of_driver(
        stop: DriverStop<String>,
        opts: &UniformizeOptions,
        residual_max: f64,
    ) -> Stop {
        match stop {
            DriverStop::Converged => Stop::Converged,
            DriverStop::IterationCap => Stop::IterationCap,
            DriverStop::Factor(reason) => Stop::DegenerateStep(reason),
            DriverStop::LineSearch(last) => Stop::DegenerateStep(format!(
                "line search: {} after {} halvings at max residual {residual_max:e}",
                last.unwrap_or_else(|| "no decrease of |∇E|".into()),
                opts.max_halvings,
            )),
            DriverStop::Stalled(window) => Stop::DegenerateStep(format!(
                "line search stalled: {window} steps of at most 2^-10 reduced the max residual \
                 by less than 0.1 % (now {residual_max:e})"
            )),
        }
    }
}

/// The result of [`uniformize`]. `u` is meaningful only with [`Uniformization::converged`];
/// otherwise it is the last accepted iterate, labelled as such.
#[derive(Clone, Debug)]
pub struct Uniformization {
    /// `T₀`: the input made intrinsic Delaunay by Euclidean flips.
    pub initial_mesh: Mesh,
    /// `ℓ⁰`: the lengths of `T₀` (the metric being uniformized).
    pub initial_lengths: Vec<f64>,
    /// Euclidean flips from the input to `T₀`.
    pub euclidean_flips: usize,
    /// The final triangulation (intrinsic Delaunay for the scaled metric at `u`).
    pub mesh: Mesh,
    /// `ℓ⁰` carried to the final triangulation by the Ptolemy flips (rounded).
    pub base_lengths: Vec<f64>,
    /// The Ptolemy flips from `T₀` to the final triangulation, in order.
    pub flip_sequence: Vec<Edge>,
    /// The log scale factors.
    pub u: Vec<f64>,
    /// The targets.
    pub targets: Targets,
    /// Accepted steps.
    pub steps: Vec<StepReport>,
    /// Why the solver stopped.
    pub stop: Stop,
    /// `max_i |Θ_i − θ_i(u)|` at the returned `u` (`f64`).
    pub residual_max: f64,
    /// Symbolic and numeric factorizations computed.
    pub factorizations: (usize, usize),
}

impl Uniformization {
    /// Whether the residual reached the tolerance.
    pub fn converged(&self) -> bool {
        self.stop == Stop::Converged
    }
}

/// The scaled metric at one `u`, flipped to Delaunay, with its angle sums and the
/// cotangents of its corners (one kernel pass, [`cone_angles_and_cotans`]).
pub(crate) struct Evaluation {
    pub mesh: Mesh,
    pub base: Vec<f64>,
    /// The scaled lengths on `mesh`, shifted by a power of two (angles are scale-invariant).
    pub lengths: Vec<f64>,
    pub grad: Vec<f64>,
    /// `cot` of the corner opposite each half-edge (the Hessian's weights).
    pub cot: Vec<f64>,
    pub flips: Vec<Edge>,
}

/// Flip the scaled metric at `u` from `(mesh, base)` to Delaunay and evaluate `Θ − θ`.
/// `Err` with the reason when the metric is degenerate.
pub(crate) fn evaluate(
    mesh: &Mesh,
    base: &[f64],
    u: &[f64],
    theta_target: &[f64],
) -> Result<Evaluation, String> {
    if let Some(v) = u.iter().position(|x| x.is_nan() || x.abs() > MAX_LOG_SCALE) {
        return Err(format!("u at v{v} is {} (beyond 2²⁰)", u[v]));
    }
    let mut m = mesh.clone();
    let opts = FlipOptions {
        record: true,
        ..FlipOptions::default()
    };
    let start = mesh
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
            scaled_fast(base[e.idx()], u[i], u[j])
                .ok_or_else(|| format!("scaled length of e{} undefined", e.0))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let (rep, scaled) =
        flip_to_delaunay_exp(&mut m, start, FlipKind::Ptolemy, &opts).map_err(|e| e.to_string())?;
    if rep.hit_cap {
        return Err("Ptolemy flipping hit its flip cap".into());
    }
    // Base lengths on the new triangulation: the same Ptolemy flips on ℓ (T28).
    let mut b = base.to_vec();
    if !rep.sequence.is_empty() {
        let mut bm = mesh.clone();
        for &e in &rep.sequence {
            flip_ptolemy(&mut bm, &mut b, e).map_err(|e| e.to_string())?;
        }
        if let Some(e) = b.iter().position(|x| !(x.is_finite() && *x > 0.0)) {
            return Err(format!("carried base length of e{e} is {}", b[e]));
        }
    }
    // Angles are invariant under a global scale: shift by the largest exponent.
    let top = scaled.iter().map(ExpLength::exponent).max().unwrap_or(0);
    let lengths: Vec<f64> = scaled.iter().map(|l| l.shifted(top)).collect();
    if let Some(e) = lengths.iter().position(|x| !x.is_normal()) {
        return Err(format!(
            "scaled length of e{e} spans more than binary64's range relative to the longest"
        ));
    }
    let mut cot = vec![0.0; m.n_halfedges()];
    let theta = cone_angles_and_cotans(&m, &lengths, &mut cot);
    let mut grad = Vec::with_capacity(theta.len());
    for (v, (t, th)) in theta_target.iter().zip(&theta).enumerate() {
        if !th.is_finite() {
            return Err(format!(
                "angle sum at v{v} undefined (a face violates the triangle inequality)"
            ));
        }
        grad.push(t - th);
    }
    Ok(Evaluation {
        mesh: m,
        base: b,
        lengths,
        grad,
        cot,
        flips: rep.sequence,
    })
}

fn max_abs(x: &[f64]) -> f64 {
    Over::ALL.max_abs(x)
}

/// Check the inputs shared by the solver and the certificate.
pub(crate) fn validate_input(
    mesh: &Mesh,
    lengths: &[f64],
    targets: &Targets,
) -> Result<(), UniformizeError> {
    if mesh.n_faces() == 0 {
        return Err(UniformizeError::Empty);
    }
    if !mesh.is_closed() {
        return Err(UniformizeError::NotClosed {
            edges: mesh.n_boundary_edges(),
        });
    }
    if lengths.len() != mesh.n_edges() {
        return Err(UniformizeError::LengthCount {
            expected: mesh.n_edges(),
            got: lengths.len(),
        });
    }
    if let Some(e) = lengths.iter().position(|x| !(x.is_finite() && *x > 0.0)) {
        return Err(UniformizeError::BadLength {
            edge: e as u32,
            value: lengths[e],
        });
    }
    targets.validate(mesh)
}

/// Solve `θ(u) = Θ` for the log scale factors `u` of a closed surface with edge lengths
/// `lengths` (one per edge, `f64`), with Ptolemy flips to the intrinsic Delaunay
/// triangulation along the way (notes Thm 12). See the module documentation for the
/// convention and the line search. Bad input is a typed error; a solve that does not
/// reach `opts.tolerance` returns `Ok` with [`Stop::IterationCap`] or
/// [`Stop::DegenerateStep`], never a panic.
pub fn uniformize(
    mesh: &Mesh,
    lengths: &[f64],
    targets: &Targets,
    opts: &UniformizeOptions,
) -> Result<Uniformization, UniformizeError> {
    uniformize_with_progress(mesh, lengths, targets, opts, &mut |_| {})
}

/// [`uniformize`], calling `progress` after every accepted step (the Newton loop and line
/// search of [`super::newton_driver`]).
#[allow(clippy::too_many_lines)] // validation, T₀ by Euclidean flips, the driver, the stop
pub fn uniformize_with_progress(
    mesh: &Mesh,
    lengths: &[f64],
    targets: &Targets,
    opts: &UniformizeOptions,
    progress: &mut dyn FnMut(&StepReport),
) -> Result<Uniformization, UniformizeError> {
    validate_input(mesh, lengths, targets)?;
    let u = match &opts.start {
        None => vec![0.0; mesh.n_vertices()],
        Some(s) => {
            if s.len() != mesh.n_vertices() {
                return Err(UniformizeError::TargetCount {
                    expected: mesh.n_vertices(),
                    got: s.len(),
                });
            }
            if let Some(v) = s.iter().position(|x| x.is_nan() || x.abs() > MAX_LOG_SCALE) {
                return Err(UniformizeError::BadStart {
                    vertex: v as u32,
                    value: s[v],
                });
            }
            s.clone()
        }
    };
    // T₀: Euclidean flips to intrinsic Delaunay (T21, T23).
    let mut t0 = mesh.clone();
    let mut l0 = lengths.to_vec();
    let rep = flip_to_delaunay(
        &mut t0,
        &mut l0,
        FlipKind::Euclidean,
        &FlipOptions::default(),
    )?;
    if !rep.all_certified_delaunay() {
        return Err(UniformizeError::InitialNotDelaunay {
            undecided: rep.undecided.len() + rep.refused.len(),
        });
    }
    let comps = Components::of(&t0);
    let (free, free_idx) = comps.free_index();
    let theta_target = targets.radians_f64();
    let cache = CholeskyCache::default();
    let steps = Vec::new();
    let mut sequence = Vec::new();
    let finish = |ev: Evaluation,
                  u: Vec<f64>,
                  steps: Vec<StepReport>,
                  sequence: Vec<Edge>,
                  stop: Stop,
                  cache: &CholeskyCache| Uniformization {
        initial_mesh: t0.clone(),
        initial_lengths: l0.clone(),
        euclidean_flips: rep.flips,
        residual_max: max_abs(&ev.grad),
        mesh: ev.mesh,
        base_lengths: ev.base,
        flip_sequence: sequence,
        u,
        targets: targets.clone(),
        steps,
        stop,
        factorizations: (cache.symbolic_count, cache.numeric_count),
    };
    let ev = match evaluate(&t0, &l0, &u, &theta_target) {
        Ok(ev) => ev,
        Err(reason) => {
            // Degenerate at the start: report the unflipped T₀.
            let ev = Evaluation {
                mesh: t0.clone(),
                base: l0.clone(),
                lengths: l0.clone(),
                grad: vec![f64::NAN; t0.n_vertices()],
                cot: Vec::new(),
                flips: Vec::new(),
            };
            return Ok(finish(
                ev,
                u,
                steps,
                sequence,
                Stop::DegenerateStep(reason),
                &cache,
            ));
        }
    };
    sequence.extend_from_slice(&ev.flips);
    // The Hessian's pattern on the current triangulation and its value buffer, rebuilt
    // only after flips (its symbolic factorization kept when the pattern is unchanged).
    let mut sys = Ptolemy {
        theta_target: &theta_target,
        free: &free,
        free_idx: &free_idx,
        pattern: GroundedPattern::new(&ev.mesh, &free_idx),
        values: Vec::new(),
        cache,
        sequence,
    };
    let run = drive(&mut sys, Over::ALL, u, ev, opts.limits(), progress);
    let stop = Stop::of_driver(run.stop, opts, max_abs(&run.eval.grad));
    Ok(finish(
        run.eval,
        run.u,
        run.steps,
        sys.sequence,
        stop,
        &sys.cache,
    ))
}

/// The Euclidean Newton system for [`drive`]: evaluation with Ptolemy flips, the grounded
/// Hessian on the current triangulation (pattern rebuilt after flips, its symbolic
/// factorization adopted), the flips recorded.
struct Ptolemy<'a> {
    theta_target: &'a [f64],
    free: &'a [usize],
    free_idx: &'a [Option<usize>],
    pattern: GroundedPattern,
    values: Vec<f64>,
    cache: CholeskyCache,
    sequence: Vec<Edge>,
}

impl NewtonSystem for Ptolemy<'_> {
    type Eval = Evaluation;
    type Fault = String;

    fn gradient(ev: &Evaluation) -> &[f64] {
        &ev.grad
    }

    fn evaluate(&mut self, at: &Evaluation, u: &[f64]) -> Result<Evaluation, String> {
        evaluate(&at.mesh, &at.base, u, self.theta_target)
    }

    fn direction(&mut self, ev: &Evaluation) -> Result<Vec<f64>, String> {
        self.pattern.fill(&ev.cot, &mut self.values);
        if !self.pattern.factor(&self.values, &mut self.cache) {
            return Err("the grounded Hessian is not numerically positive definite".into());
        }
        Ok(self.pattern.newton_direction(&ev.grad, self.free))
    }

    fn accept(&mut self, new: &Evaluation) -> usize {
        self.sequence.extend_from_slice(&new.flips);
        if !new.flips.is_empty() {
            let mut p = GroundedPattern::new(&new.mesh, self.free_idx);
            p.adopt_symbolic(&mut self.pattern);
            self.pattern = p;
        }
        new.flips.len()
    }
}
