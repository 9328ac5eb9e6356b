//! T25 — the uniformization is unique up to scale (notes §1.5.3 Thm 12; S20: `E` is
//! strictly convex on the subspace with one `u` fixed per component): two solves from
//! different starts, each certified (B71), agree after subtracting `u` at the grounded
//! vertex of each component, within the sum of their certified distances.

use super::t24_uniformization_exists::InputOnT0;
use super::verdict::{Verdict, Witness};
use crate::mesh::Mesh;
use crate::uniformization::certificate::{prove_on, CertificateOutcome, Proof};
use crate::uniformization::components::Components;
use crate::uniformization::{uniformize, Targets, UniformizeError, UniformizeOptions};
use rug::Rational;

/// Solve from `start` (or 0) and certify; `Err(reason)` when not certified.
fn certified(
    mesh: &Mesh,
    lengths: &[f64],
    targets: &Targets,
    start: Option<Vec<f64>>,
    bits: u32,
    tolerance: f64,
    input: Option<InputOnT0<'_>>,
) -> Result<Result<(Proof, f64), String>, UniformizeError> {
    let opts = UniformizeOptions {
        start,
        ..UniformizeOptions::default()
    };
    let sol = uniformize(mesh, lengths, targets, &opts)?;
    if !sol.converged() {
        return Ok(Err(format!("the f64 solve stopped: {:?}", sol.stop)));
    }
    let metric = match input.map(|f| f(&sol)).transpose() {
        Ok(m) => m,
        Err(reason) => return Ok(Err(reason)),
    };
    let proof = match prove_on(&sol, metric.as_ref(), bits, tolerance) {
        Ok(p) => p,
        Err(e) => return Ok(Err(e.to_string())),
    };
    match proof.outcome.clone() {
        CertificateOutcome::Holds { distance, .. } => Ok(Ok((proof, distance))),
        CertificateOutcome::Undecided { reason } => Ok(Err(reason)),
    }
}

/// Compare two certified solutions `(u¹, d₁)` and `(u², d₂)` exactly: with `c` the value of
/// `u¹ − u²` at the grounded vertex of each component, every `|u¹_i − u²_i − c|` must be
/// `≤ d₁ + d₂` (B71 bounds `‖u* − u‖₂`, hence every coordinate). A larger difference is a
/// certified refutation (two distinct normalized solutions).
pub fn compare_normalized(
    mesh: &Mesh,
    u1: &[Rational],
    d1: f64,
    u2: &[Rational],
    d2: f64,
) -> Verdict {
    let comps = Components::of(mesh);
    let bound =
        Rational::from_f64(d1).unwrap_or_default() + Rational::from_f64(d2).unwrap_or_default();
    let mut failures = Vec::new();
    let mut max_error: f64 = 0.0;
    for v in 0..mesh.n_vertices() {
        let root = comps.roots[comps.of_vertex[v]];
        let c = Rational::from(&u1[root] - &u2[root]);
        let diff = Rational::from(&u1[v] - &u2[v]) - c;
        let a = diff.clone().abs();
        max_error = max_error.max(a.to_f64());
        if a > bound {
            failures.push(Witness {
                element: format!("v{v}"),
                detail: format!(
                    "normalized solutions differ by {:e}, more than the certified {:e}",
                    a.to_f64(),
                    bound.to_f64()
                ),
                value: a.to_f64(),
            });
        }
    }
    if failures.is_empty() {
        Verdict::Holds {
            certified: true,
            max_error,
        }
    } else {
        Verdict::certified(failures, Vec::new(), 0)
    }
}

/// T25 on one surface: solve from `u = 0` and from `start`, certify both at `bits`, compare
/// ([`compare_normalized`]). `Undecided` when either is not certified.
pub fn check_uniqueness(
    mesh: &Mesh,
    lengths: &[f64],
    targets: &Targets,
    start: Vec<f64>,
    bits: u32,
    tolerance: f64,
) -> Result<Verdict, UniformizeError> {
    let (verdict, _) = check_uniqueness_on(mesh, lengths, targets, start, bits, tolerance, None)?;
    Ok(verdict)
}

/// Two certified solutions of one surface, with their certified distances.
pub type Certified2 = Option<((Proof, f64), (Proof, f64))>;

/// [`check_uniqueness`] about an input metric that `lengths` only round (see
/// [`super::t24_uniformization_exists::check_existence_on`]); also returns the two
/// certified solutions when both were certified.
pub fn check_uniqueness_on(
    mesh: &Mesh,
    lengths: &[f64],
    targets: &Targets,
    start: Vec<f64>,
    bits: u32,
    tolerance: f64,
    input: Option<InputOnT0<'_>>,
) -> Result<(Verdict, Certified2), UniformizeError> {
    let a = certified(mesh, lengths, targets, None, bits, tolerance, input)?;
    let b = certified(mesh, lengths, targets, Some(start), bits, tolerance, input)?;
    match (a, b) {
        (Ok((p1, d1)), Ok((p2, d2))) => {
            let v = compare_normalized(mesh, &p1.data.u, d1, &p2.data.u, d2);
            Ok((v, Some(((p1, d1), (p2, d2)))))
        }
        (Err(r), _) | (_, Err(r)) => Ok((
            Verdict::Undecided {
                bits_tried: bits,
                witnesses: vec![Witness {
                    element: "surface".into(),
                    detail: r,
                    value: f64::NAN,
                }],
            },
            None,
        )),
    }
}
