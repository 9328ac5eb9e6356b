//! T09 (notes Thm 6): prescribed cone angles determine the radii of a circle pattern with
//! fixed intersection angles `Φ ∈ [0, π/2]` up to one global scale (proofs/T09).
//!
//! The check solves the problem from several starts ([`newton`]), certifies each computed
//! solution by a box that provably holds a solution, unique in the box
//! ([`certify_solution`], proofs/B94), and compares the boxes exactly: nested boxes prove
//! that the runs found one and the same solution (`Holds`, certified); two disjoint boxes
//! would prove two different normalised solutions (`Fails`, certified). Anything else —
//! a run that does not converge, a box that cannot be certified, overlapping boxes that do
//! not nest — is `Undecided`.

use super::{Verdict, Witness};
use crate::circles::certify::{certify_solution, Certificate};
use crate::circles::solve::{default_tolerance, newton};
use crate::circles::CirclePattern;
use crate::scalar::{Mpfr, Precision, Real};

/// Half-width of the certified boxes: `2⁻³⁰` in `u = log r` (radii to 10⁻⁹ relative), so
/// that boxes of runs agreeing to working precision nest (proofs/B94).
pub const BOX_RADIUS: f64 = 9.313225746154785e-10;

/// Newton iterations allowed per start.
pub const MAX_NEWTON: usize = 200;

/// One certified run.
#[derive(Clone, Debug)]
pub struct Run {
    /// Which start (index into the list given).
    pub start: usize,
    /// Backend name (`f64`, `dd`, `mpfr-256`).
    pub backend: String,
    /// Newton iterations.
    pub iterations: usize,
    /// The normalised solution (`u_ground = 0`), for display.
    pub u: Vec<f64>,
    /// The certificate, or why there is none.
    pub certificate: Result<Certificate, String>,
}

/// Solve `p` from every start at the precision of `ctx` and certify each result with MPFR
/// intervals of `T`'s precision plus 64 bits.
pub fn runs<T: Real>(p: &CirclePattern, starts: &[Vec<f64>], ctx: T::Ctx) -> Vec<Run> {
    let n = p.mesh.n_vertices();
    let tol = default_tolerance::<T>(n, ctx);
    starts
        .iter()
        .enumerate()
        .map(|(k, s)| {
            let u0: Vec<T> = s.iter().map(|&x| T::from_f64(x, ctx)).collect();
            match newton(p, &u0, tol, MAX_NEWTON) {
                Ok(sol) => Run {
                    start: k,
                    backend: T::backend_name(ctx),
                    iterations: sol.iterations,
                    u: sol.u.iter().map(Real::approx_f64).collect(),
                    certificate: certify_solution(
                        p,
                        &sol.u,
                        T::precision_bits(ctx) + 64,
                        BOX_RADIUS,
                    ),
                },
                Err(e) => Run {
                    start: k,
                    backend: T::backend_name(ctx),
                    iterations: 0,
                    u: Vec::new(),
                    certificate: Err(e.to_string()),
                },
            }
        })
        .collect()
}

/// The verdict on a set of runs of `p` (of one or several precisions): see the module docs.
/// Disjoint certified boxes fail the check. Otherwise a reference box of half-width
/// `2·BOX_RADIUS` is certified around the run certified with the most bits, and every run's
/// box must nest in it. `max_error` is the largest difference of normalised `u` between runs.
pub fn verify_rigidity(p: &CirclePattern, runs: &[Run]) -> Verdict {
    let bits = runs
        .iter()
        .filter_map(|r| r.certificate.as_ref().ok().map(|c| c.bits))
        .max()
        .unwrap_or(0);
    let mut open: Vec<Witness> = runs
        .iter()
        .filter_map(|r| {
            r.certificate.as_ref().err().map(|why| Witness {
                element: format!("start {} ({})", r.start, r.backend),
                detail: why.clone(),
                value: f64::NAN,
            })
        })
        .collect();
    let certs: Vec<(&Run, &Certificate)> = runs
        .iter()
        .filter_map(|r| r.certificate.as_ref().ok().map(|c| (r, c)))
        .collect();
    let mut fails = Vec::new();
    for (a, (ra, ca)) in certs.iter().enumerate() {
        for (rb, cb) in &certs[a + 1..] {
            if ca.disjoint_from(cb) {
                fails.push(Witness {
                    element: format!(
                        "starts {} ({}) and {} ({})",
                        ra.start, ra.backend, rb.start, rb.backend
                    ),
                    detail: "two certified solutions with different normalised radii".into(),
                    value: max_diff(&ra.u, &rb.u),
                });
            }
        }
    }
    if fails.is_empty() && open.is_empty() {
        let Some((_, best)) = certs.iter().max_by_key(|x| x.1.bits) else {
            return Verdict::NotApplicable {
                reason: "no runs".into(),
            };
        };
        let Ok(prec) = Precision::new(u64::from(best.bits) + 64) else {
            return Verdict::NotApplicable {
                reason: "precision out of range".into(),
            };
        };
        let center: Vec<Mpfr> = best
            .center
            .iter()
            .map(|q| Mpfr::from_rational(q, prec))
            .collect();
        let reference = match certify_solution(p, &center, best.bits, 2.0 * BOX_RADIUS) {
            Ok(c) => c,
            Err(why) => {
                return Verdict::Undecided {
                    bits_tried: best.bits,
                    witnesses: vec![Witness {
                        element: "surface".into(),
                        detail: format!("reference box not certified: {why}"),
                        value: f64::NAN,
                    }],
                }
            }
        };
        for (r, c) in &certs {
            if !reference.contains(c) {
                open.push(Witness {
                    element: format!("start {} ({})", r.start, r.backend),
                    detail: "certified box overlaps the reference box without nesting".into(),
                    value: f64::NAN,
                });
            }
        }
        if open.is_empty() {
            let err = certs
                .iter()
                .flat_map(|(a, _)| certs.iter().map(|(b, _)| max_diff(&a.u, &b.u)))
                .fold(0.0, f64::max);
            return Verdict::Holds {
                certified: true,
                max_error: err,
            };
        }
    }
    Verdict::certified(fails, open, bits)
}

fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// Two fixed starts for the registry and the tests: `u = 0` and
/// `u_v = ((7v + 3) mod 11)/5 − 1` (radii between e⁻¹ and e).
pub fn fixed_starts(n: usize) -> Vec<Vec<f64>> {
    vec![
        vec![0.0; n],
        (0..n)
            .map(|v| ((7 * v + 3) % 11) as f64 / 5.0 - 1.0)
            .collect(),
    ]
}
