//! T13 (notes §1.4.3; Chow–Luo 2003, Thm 1.1): where a circle pattern with the target cone
//! angles exists, the combinatorial Ricci flow `du/dt = θ − Θ` converges to it,
//! exponentially fast (proofs/T13).
//!
//! The check runs the flow ([`ricci_flow`]) and, independently, Newton's method with a
//! certified box ([`certify_solution`], B94); it holds when the flow ends inside the box
//! (the solution is unique there). The flow is computed, not enclosed: the verdict is
//! numerical (`certified: false`); a flow that does not converge within the step budget is
//! `Undecided`, never `Fails`.

use super::t09_circle_pattern_rigidity::BOX_RADIUS;
use super::{Verdict, Witness};
use crate::circles::certify::certify_solution;
use crate::circles::solve::{convergence_rate, default_tolerance, newton, ricci_flow};
use crate::circles::CirclePattern;
use crate::scalar::Real;

/// What the flow did.
#[derive(Clone, Debug)]
pub struct FlowReport {
    /// The verdict.
    pub verdict: Verdict,
    /// Euler steps taken.
    pub steps: usize,
    /// Flow time reached.
    pub time: f64,
    /// Fitted exponential rate `λ` of `max|Θ − θ| ≈ C e^{−λt}`.
    pub rate: Option<f64>,
}

/// Run the flow from `start` (at most `max_steps` steps, stopping residual `tol`) and compare
/// with the certified Newton solution.
pub fn check_flow_converges<T: Real>(
    p: &CirclePattern,
    start: &[f64],
    ctx: T::Ctx,
    tol: f64,
    max_steps: usize,
) -> FlowReport {
    let u0: Vec<T> = start.iter().map(|&x| T::from_f64(x, ctx)).collect();
    let undecided = |detail: String| Verdict::Undecided {
        bits_tried: 0,
        witnesses: vec![Witness {
            element: "surface".into(),
            detail,
            value: f64::NAN,
        }],
    };
    let flow = match ricci_flow(p, &u0, tol, max_steps, false) {
        Ok(f) => f,
        Err(e) => {
            return FlowReport {
                verdict: undecided(e.to_string()),
                steps: max_steps,
                time: f64::NAN,
                rate: None,
            }
        }
    };
    let rate = convergence_rate(&flow.history, &flow.times);
    let time = flow.times.last().copied().unwrap_or(0.0);
    let verdict = verify_flow_end(p, &flow.u);
    FlowReport {
        verdict,
        steps: flow.iterations,
        time,
        rate,
    }
}

/// Compare the end `u` of a flow of `p` with the certified Newton solution of `p` (B94):
/// `Holds` (numerical) when `u` lies in the certified box, `Undecided` otherwise.
pub fn verify_flow_end<T: Real>(p: &CirclePattern, u: &[T]) -> Verdict {
    let n = p.mesh.n_vertices();
    let undecided = |detail: String| Verdict::Undecided {
        bits_tried: 0,
        witnesses: vec![Witness {
            element: "surface".into(),
            detail,
            value: f64::NAN,
        }],
    };
    let reference = newton(p, &vec![0.0_f64; n], default_tolerance::<f64>(n, ()), 200)
        .map_err(|e| e.to_string())
        .and_then(|sol| certify_solution(p, &sol.u, 128, BOX_RADIUS));
    match reference {
        Err(why) => undecided(format!("no certified reference solution: {why}")),
        Ok(c) => {
            let mut err = 0.0_f64;
            let mut inside = true;
            for (x, q) in u.iter().zip(&c.center) {
                let d = x
                    .to_rational()
                    .map_or(f64::INFINITY, |x| (x - q).abs().to_f64());
                err = err.max(d);
                inside &= d < c.radius;
            }
            if inside {
                Verdict::Holds {
                    certified: false,
                    max_error: err,
                }
            } else {
                undecided(format!(
                    "the flow ended {err:e} from the certified solution (box {:e})",
                    c.radius
                ))
            }
        }
    }
}
