//! One Newton driver for the uniformization solvers — the Euclidean solver with Ptolemy
//! flips ([`super::newton`]), the Dirichlet problem ([`super::dirichlet`]) and the
//! hyperbolic target ([`super::hyperbolic`]) — and one mixed-precision refinement loop
//! ([`super::refine`], [`super::hyperbolic_certificate`]).
//!
//! **Newton step and line search** (docs/catalogue.md §7). At `u` with gradient `g = ∇E = Θ − θ(u)`
//! the system gives the direction `d = −H⁻¹g` (zero at grounded or fixed vertices); a step
//! `t ∈ {1, ½, ¼, …}` (at most `max_halvings` halvings) is accepted when
//! `|g(u + td)|₂ < |g(u)|₂` and either the projected gradient `g(u + td)·d ≤ 0` (no
//! overshoot of the minimum along `d`) or the residual at least halves (the overshoot of a
//! Newton step near the solution is at the level of rounding). No energy-decrease test: it
//! stalls at the working precision. Norms and the projection run over the vertices the
//! equations hold at ([`Over`]). The driver stops when `max |g| ≤ tolerance`, at the
//! iteration cap, when the Hessian cannot be factored, or when no step is accepted (with
//! the last reason an evaluation gave). A solver may also ask it to stop when the line
//! search **stalls** ([`Limits::stall_window`]): `w` accepted steps in a row each needed
//! at least [`STALL_HALVINGS`] halvings (`t ≤ 2⁻¹⁰`) and together reduced `max |g|` by less
//! than the fraction [`STALL_DECREASE`] — the minimiser lies where the metric degenerates
//! (e.g. a Dirichlet problem whose boundary faces cannot be flipped), and the remaining
//! iterations would each move `u` by less than `2⁻¹⁰` of a Newton step. It is a stop
//! without a solution, never a weaker test of one.
//!
//! **Refinement.** `u` kept in a higher precision `T`, the residual evaluated in `T`, the
//! correction in double-double from a binary64 factor computed once (as the solver
//! supplies it: the factor alone, or iterative refinement against a Hessian of the
//! iterate); it stops at the tolerance, at the
//! iteration cap, or after two iterations in a row that fail to halve the residual (the
//! precision's floor).

use crate::scalar::{Dd, Real};

/// One accepted Newton step.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct StepReport {
    /// Step number, from 1.
    pub iteration: usize,
    /// `max_i |Θ_i − θ_i|` after the step.
    pub residual_max: f64,
    /// The accepted step length `t`.
    pub step: f64,
    /// Halvings before acceptance.
    pub halvings: usize,
    /// Ptolemy flips performed by this step (T26: finitely many along the solve).
    pub flips: usize,
}

/// The result of [`refine`](super::refine::refine).
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

/// The vertices the equations hold at: all, or a list (the free vertices of a Dirichlet
/// problem, whose gradient entries elsewhere are not equations).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Over<'a>(pub Option<&'a [usize]>);

impl Over<'_> {
    /// All vertices.
    pub(crate) const ALL: Over<'static> = Over(None);

    fn fold(&self, g: &[f64], mut f: impl FnMut(usize)) {
        match self.0 {
            None => (0..g.len()).for_each(&mut f),
            Some(free) => free.iter().for_each(|&v| f(v)),
        }
    }

    /// `max |g_v|`.
    pub(crate) fn max_abs(&self, g: &[f64]) -> f64 {
        let mut m = 0.0f64;
        self.fold(g, |v| m = m.max(g[v].abs()));
        m
    }

    /// `(Σ g_v²)^{1/2}`.
    pub(crate) fn norm2(&self, g: &[f64]) -> f64 {
        let mut s = 0.0;
        self.fold(g, |v| s += g[v] * g[v]);
        s.sqrt()
    }

    /// `Σ g_v d_v`.
    pub(crate) fn dot(&self, g: &[f64], d: &[f64]) -> f64 {
        let mut s = 0.0;
        self.fold(g, |v| s += g[v] * d[v]);
        s
    }
}

/// What a Newton solver supplies to [`drive`].
pub(crate) trait NewtonSystem {
    /// The state at one `u` (gradient, Hessian data, triangulation).
    type Eval;
    /// Why an evaluation failed (a degenerate metric).
    type Fault;
    /// `∇E = Θ − θ(u)` of an evaluation, one entry per vertex.
    fn gradient(ev: &Self::Eval) -> &[f64];
    /// Evaluate at `u`, starting from the accepted state `at`.
    fn evaluate(&mut self, at: &Self::Eval, u: &[f64]) -> Result<Self::Eval, Self::Fault>;
    /// The Newton direction `−H⁻¹∇E` at `ev`; `Err` with the reason when `H` cannot be
    /// factored.
    fn direction(&mut self, ev: &Self::Eval) -> Result<Vec<f64>, String>;
    /// An accepted step's state, before it becomes current; returns its flip count.
    fn accept(&mut self, new: &Self::Eval) -> usize;
}

/// The driver's limits.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Limits {
    /// Stop when `max |∇E| ≤ tolerance`.
    pub tolerance: f64,
    /// At most this many Newton steps.
    pub max_iterations: usize,
    /// At most this many halvings in one line search.
    pub max_halvings: usize,
    /// Stop as stalled after this many accepted steps in a row that each needed at least
    /// [`STALL_HALVINGS`] halvings and together reduced `max |∇E|` by less than
    /// [`STALL_DECREASE`] of its value (module doc); `None`: never.
    pub stall_window: Option<usize>,
}

/// The halvings from which an accepted step counts towards a stall (`t ≤ 2⁻¹⁰`).
pub(crate) const STALL_HALVINGS: usize = 10;
/// The relative decrease of `max |∇E|` over a stall window below which the run stalls.
pub(crate) const STALL_DECREASE: f64 = 1e-3;

/// Whether the last `window` accepted steps stalled (see [`Limits::stall_window`]):
/// each needed at least [`STALL_HALVINGS`] halvings, and `max |∇E|` after them is above
/// `(1 − STALL_DECREASE)` times its value before them (`before` when the window starts at
/// the first step).
pub(crate) fn stalled(steps: &[StepReport], window: usize, before: f64) -> bool {
    if window == 0 || steps.len() < window {
        return false;
    }
    let recent = &steps[steps.len() - window..];
    let start = if steps.len() > window {
        steps[steps.len() - window - 1].residual_max
    } else {
        before
    };
    let end = recent[window - 1].residual_max;
    recent.iter().all(|s| s.halvings >= STALL_HALVINGS) && end > (1.0 - STALL_DECREASE) * start
}

/// Why [`drive`] stopped.
#[derive(Debug)]
pub(crate) enum DriverStop<F> {
    /// `max |∇E| ≤ tolerance`.
    Converged,
    /// The iteration cap was reached first.
    IterationCap,
    /// The Hessian could not be factored (the system's reason).
    Factor(String),
    /// No step was accepted; the last evaluation fault, if any.
    LineSearch(Option<F>),
    /// The line search stalled ([`Limits::stall_window`]) over this many steps.
    Stalled(usize),
}

/// The end state of [`drive`]: the last accepted `u` and its evaluation.
pub(crate) struct DriverRun<E, F> {
    pub u: Vec<f64>,
    pub eval: E,
    pub steps: Vec<StepReport>,
    pub stop: DriverStop<F>,
}

/// An accepted step: `u + td`, its evaluation, `t` and the halvings before it.
pub(crate) type Accepted<E> = (Vec<f64>, E, f64, usize);

/// The line search (module doc) from `u` along `d`, `n0 = |∇E(u)|₂`: the accepted
/// `(u + td, its evaluation, t, halvings)`, or the last fault when no step is accepted.
pub(crate) fn line_search<S: NewtonSystem>(
    sys: &mut S,
    over: Over<'_>,
    at: &S::Eval,
    u: &[f64],
    d: &[f64],
    max_halvings: usize,
) -> Result<Accepted<S::Eval>, Option<S::Fault>> {
    let n0 = over.norm2(S::gradient(at));
    let mut t = 1.0;
    let mut fault = None;
    for halvings in 0..=max_halvings {
        let trial: Vec<f64> = u.iter().zip(d).map(|(a, b)| a + t * b).collect();
        match sys.evaluate(at, &trial) {
            Ok(new) => {
                let g = S::gradient(&new);
                let n1 = over.norm2(g);
                let slope = over.dot(g, d);
                if n1 < n0 && (slope <= 0.0 || n1 <= 0.5 * n0) {
                    return Ok((trial, new, t, halvings));
                }
            }
            Err(f) => fault = Some(f),
        }
        t *= 0.5;
    }
    Err(fault)
}

/// Newton from `u` with evaluation `ev` (module doc), calling `progress` after every
/// accepted step.
pub(crate) fn drive<S: NewtonSystem>(
    sys: &mut S,
    over: Over<'_>,
    mut u: Vec<f64>,
    mut ev: S::Eval,
    limits: Limits,
    progress: &mut dyn FnMut(&StepReport),
) -> DriverRun<S::Eval, S::Fault> {
    let mut steps = Vec::new();
    let initial = over.max_abs(S::gradient(&ev));
    let stop = 'newton: {
        for iteration in 1..=limits.max_iterations + 1 {
            if over.max_abs(S::gradient(&ev)) <= limits.tolerance {
                break 'newton DriverStop::Converged;
            }
            if iteration > limits.max_iterations {
                break;
            }
            let d = match sys.direction(&ev) {
                Ok(d) => d,
                Err(reason) => break 'newton DriverStop::Factor(reason),
            };
            let (trial, new, step, halvings) =
                match line_search(sys, over, &ev, &u, &d, limits.max_halvings) {
                    Ok(accepted) => accepted,
                    Err(fault) => break 'newton DriverStop::LineSearch(fault),
                };
            let flips = sys.accept(&new);
            u = trial;
            let report = StepReport {
                iteration,
                residual_max: over.max_abs(S::gradient(&new)),
                step,
                halvings,
                flips,
            };
            progress(&report);
            steps.push(report);
            ev = new;
            if let Some(window) = limits.stall_window {
                if stalled(&steps, window, initial) {
                    break 'newton DriverStop::Stalled(window);
                }
            }
        }
        DriverStop::IterationCap
    };
    DriverRun {
        u,
        eval: ev,
        steps,
        stop,
    }
}

/// The refinement loop (module doc) from `u` in `T`: `residual(u)` is `Θ − θ(u)` in `T`
/// (or the error that stops the refinement), `correction(r, r₆₄)` the Newton correction
/// `−H⁻¹r` in double-double from the residual in `T` and rounded to binary64 (one entry per
/// vertex; the binary64 correction `−H̃⁻¹r₆₄` is one with zero trailing words), and `over`
/// the vertices whose residual is measured. Returns the refinement and, when the residual
/// stopped being finite at a measured vertex, the first such vertex (then the history ends
/// with `+∞` and the target is not reached).
pub(crate) fn refine_loop<T: Real, E>(
    mut u: Vec<T>,
    ctx: T::Ctx,
    (tolerance, max_iterations): (f64, usize),
    over: Over<'_>,
    mut residual: impl FnMut(&[T]) -> Result<Vec<T>, E>,
    mut correction: impl FnMut(&[T], &[f64]) -> Vec<Dd>,
) -> Result<(Refinement<T>, Option<usize>), E> {
    let mut history = Vec::new();
    let mut stalls = 0;
    let mut iteration = 0;
    loop {
        let r = residual(&u)?;
        let rf: Vec<f64> = r.iter().map(Real::approx_f64).collect();
        let mut not_finite = None;
        over.fold(&rf, |v| {
            if not_finite.is_none() && !rf[v].is_finite() {
                not_finite = Some(v);
            }
        });
        if let Some(vertex) = not_finite {
            history.push(f64::INFINITY);
            let refinement = Refinement {
                u,
                residual: r,
                history,
                reached: false,
            };
            return Ok((refinement, Some(vertex)));
        }
        let rmax = over.max_abs(&rf);
        if let Some(&prev) = history.last() {
            stalls = if rmax > 0.5 * prev { stalls + 1 } else { 0 };
        }
        history.push(rmax);
        let reached = rmax <= tolerance;
        if reached || iteration >= max_iterations || stalls >= 2 {
            let refinement = Refinement {
                u,
                residual: r,
                history,
                reached,
            };
            return Ok((refinement, None));
        }
        let d = correction(&r, &rf);
        for (ui, di) in u.iter_mut().zip(&d) {
            *ui += &T::from_f64(di.hi, ctx);
            if di.lo != 0.0 {
                *ui += &T::from_f64(di.lo, ctx);
            }
        }
        iteration += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::{stalled, StepReport, STALL_HALVINGS};

    fn step(residual_max: f64, halvings: usize) -> StepReport {
        StepReport {
            iteration: 0,
            residual_max,
            step: 0.5f64.powi(halvings as i32),
            halvings,
            flips: 0,
        }
    }

    /// The stall rule on the history of a stalled disk problem (a pole of a scanned statue:
    /// 23 halvings a step, `max |Θ − θ|` 0.36555 → 0.36554) and its controls: one step of
    /// fewer halvings, a decrease of 1 %, or a window not yet full is no stall.
    #[test]
    fn stall_needs_a_full_window_of_tiny_steps_without_progress() {
        let slow: Vec<StepReport> = (0..6)
            .map(|k| step(0.3655495 - 4e-8 * f64::from(k), 23))
            .collect();
        assert!(stalled(&slow, 5, 0.37));
        assert!(stalled(&slow[..5], 5, 0.3655496));
        // Controls.
        let mut one_large = slow.clone();
        one_large[3].halvings = STALL_HALVINGS - 1;
        assert!(!stalled(&one_large, 5, 0.37));
        let progressing: Vec<StepReport> =
            (0..6).map(|k| step(0.36 * 0.99f64.powi(k), 23)).collect();
        assert!(!stalled(&progressing, 5, 0.37));
        assert!(!stalled(&slow[..4], 5, 0.37));
        assert!(
            !stalled(&slow[..5], 5, 0.5),
            "the window's start is `before`"
        );
        assert!(!stalled(&slow, 0, 0.37));
    }
}
