//! T10 (notes Thm 7; Thurston, Marden–Rodin): on a closed surface of genus 1 with
//! intersection angles `Φ ∈ [0, π/2]` a flat circle pattern (every cone angle `2π`) exists
//! exactly when Thurston's 3- and 4-cycle conditions hold ([`check_thurston`]); otherwise the
//! Chow–Luo flow degenerates (proofs/T10).
//!
//! The check decides both sides on the instance: where the conditions hold it computes and
//! certifies a solution (B94); where they fail it looks for a **vertex obstruction** — a
//! vertex `v` whose target is at least the supremum of its cone angle,
//! `Θ_v ≥ Σ_{corners at v} (π − Φ_opp)` — which proves that no solution exists and that the
//! flow drives `u_v − ū` to `−∞` at speed at least `Θ_v − Σ(π − Φ_opp)`.

use super::t09_circle_pattern_rigidity::BOX_RADIUS;
use super::{Verdict, Witness};
use crate::circles::certify::certify_solution;
use crate::circles::solve::{default_tolerance, newton};
use crate::circles::thurston::check_thurston;
use crate::circles::CirclePattern;
use rug::Rational;

/// `Σ_{corners at v} (1 − Φ_opp/π)` for every vertex whose faces have three distinct
/// vertices: the supremum of `θ_v/π` over all radii. In a face `vab`, `α_v` decreases
/// strictly in `u_v` (`∂α_v/∂u_v = −(w_va + w_vb) < 0`, Chow–Luo Lemma 2.3) and tends to
/// `π − Φ_ab` as `r_v → 0` (the law of cosines with `ℓ_va → r_a`, `ℓ_vb → r_b`).
pub fn cone_angle_suprema(p: &CirclePattern) -> Vec<Option<Rational>> {
    let mesh = &p.mesh;
    let mut sup: Vec<Option<Rational>> = vec![Some(Rational::new()); mesh.n_vertices()];
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_vertices(f);
        let distinct = a != b && b != c && c != a;
        for h in mesh.face_halfedges(f) {
            let v = mesh.opposite_vertex(h).idx();
            if !distinct {
                sup[v] = None;
            } else if let Some(s) = &mut sup[v] {
                *s += Rational::from(1) - &p.phi[h.edge().idx()];
            }
        }
    }
    sup
}

/// Vertices with a target at least the supremum of their cone angle: no radii reach the
/// target there (see [`cone_angle_suprema`]).
pub fn vertex_obstructions(p: &CirclePattern) -> Vec<usize> {
    cone_angle_suprema(p)
        .iter()
        .zip(&p.targets)
        .enumerate()
        .filter_map(|(v, (sup, t))| match (sup, t) {
            (Some(s), Some(t)) if t >= s => Some(v),
            _ => None,
        })
        .collect()
}

/// T10 on a flat torus problem (`χ = 0`, every target `2π`): see the module docs.
pub fn check_thurston_existence(p: &CirclePattern) -> Verdict {
    let mesh = &p.mesh;
    let two = Rational::from(2);
    if !mesh.is_closed()
        || mesh.euler_characteristic() != 0
        || p.targets.iter().any(|t| t.as_ref() != Some(&two))
    {
        return Verdict::NotApplicable {
            reason: "T10 is checked for flat patterns on a torus (χ = 0, every Θ = 2π)".into(),
        };
    }
    let report = match check_thurston(mesh, &p.phi) {
        Ok(r) => r,
        Err(e) => {
            return Verdict::NotApplicable {
                reason: e.to_string(),
            }
        }
    };
    let obstructions = vertex_obstructions(p);
    let obstruction_witnesses = || {
        obstructions
            .iter()
            .map(|v| Witness {
                element: format!("v{v}"),
                detail: "target ≥ supremum of the cone angle: no radii reach it".into(),
                value: 0.0,
            })
            .collect::<Vec<_>>()
    };
    if !report.undecided.is_empty() {
        return Verdict::Undecided {
            bits_tried: 0,
            witnesses: vec![Witness {
                element: "surface".into(),
                detail: "a separating cycle at the threshold on genus ≥ 2".into(),
                value: f64::NAN,
            }],
        };
    }
    if report.violations.is_empty() {
        let n = mesh.n_vertices();
        let start = vec![0.0; n];
        let certificate = newton(p, &start, default_tolerance::<f64>(n, ()), 200)
            .map_err(|e| e.to_string())
            .and_then(|sol| certify_solution(p, &sol.u, 128, BOX_RADIUS));
        return match (certificate, obstructions.is_empty()) {
            (Ok(_), true) => Verdict::Holds {
                certified: true,
                max_error: 0.0,
            },
            // A certified solution and a proof that none exists cannot both stand.
            (Ok(_), false) => Verdict::certified(obstruction_witnesses(), vec![], 128),
            (Err(why), _) => Verdict::Undecided {
                bits_tried: 128,
                witnesses: vec![Witness {
                    element: "surface".into(),
                    detail: format!("Thurston's conditions hold, no certified solution: {why}"),
                    value: f64::NAN,
                }],
            },
        };
    }
    if obstructions.is_empty() {
        return Verdict::Undecided {
            bits_tried: 0,
            witnesses: report
                .violations
                .iter()
                .map(|c| Witness {
                    element: format!("cycle {:?}", c.vertices),
                    detail: "Thurston's condition fails; non-existence not proved".into(),
                    value: c.angle_sum.to_f64(),
                })
                .collect(),
        };
    }
    Verdict::Holds {
        certified: true,
        max_error: 0.0,
    }
}
