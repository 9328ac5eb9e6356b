//! The registry's circle-pattern entries (T08, T09). They read only the case's
//! combinatorics: the radii, angles and targets come from fixed rules stated here, so every
//! run is reproducible.

use super::check_entry::Check;
use super::precision::Prec;
use crate::circles::CirclePattern;
use crate::io::Surface;
use crate::mesh::Mesh;
use crate::scalar::{Dd, Mpfr};
use crate::theorems::t08_circle_pattern_lengths::{check_circle_pattern_lengths, fixed_pattern};
use crate::theorems::t09_circle_pattern_rigidity::{fixed_starts, runs, verify_rigidity};
use crate::theorems::{Settings, Verdict};
use rug::Rational;

/// Largest vertex count of the dense T09 solver in the registry.
pub const T09_MAX_VERTICES: usize = 100;

/// Targets with the curvature spread in proportion to the degree,
/// `K_v = 2πχ·d_v/(2E)`, i.e. `Θ_v/π = 2 − χ d_v/E` (interior vertices of closed surfaces):
/// Gauss–Bonnet holds exactly, and regular solids get equal radii.
pub fn degree_targets(mesh: &Mesh) -> Vec<Rational> {
    let e = mesh.n_edges() as i64;
    let chi = mesh.euler_characteristic();
    mesh.vertices()
        .map(|v| Rational::from(2) - Rational::from((chi * mesh.degree(v) as i64, e)))
        .collect()
}

/// The T09 problem of a case: tangency (`Φ = 0`) and [`degree_targets`], on closed surfaces
/// of at most [`T09_MAX_VERTICES`] vertices whose faces have three distinct vertices.
pub fn t09_problem(mesh: &Mesh) -> Result<CirclePattern, String> {
    if !mesh.is_closed() {
        return Err("T09 is checked on closed surfaces".into());
    }
    if mesh.n_vertices() > T09_MAX_VERTICES {
        return Err(format!(
            "the dense solver is limited to {T09_MAX_VERTICES} vertices"
        ));
    }
    if mesh.faces().any(|f| {
        let [a, b, c] = mesh.face_vertices(f);
        a == b || b == c || c == a
    }) {
        return Err("a face meets one vertex twice (Δ-complex): no circle pattern".into());
    }
    if mesh.n_vertices() < 3 {
        return Err("fewer than three vertices".into());
    }
    CirclePattern::uniform(mesh.clone(), &Rational::new(), degree_targets(mesh))
        .map_err(|e| e.to_string())
}

fn t08(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    let bits = match prec {
        Prec::Exact => return None,
        p => p.bits(),
    };
    let (r, phi) = fixed_pattern(&case.mesh);
    Some(check_circle_pattern_lengths(&case.mesh, &r, &phi, bits, s))
}

fn t09(case: &Surface, prec: Prec, _: &Settings) -> Option<Verdict> {
    let p = match t09_problem(&case.mesh) {
        Ok(p) => p,
        Err(reason) => return Some(Verdict::NotApplicable { reason }),
    };
    let starts = fixed_starts(case.mesh.n_vertices());
    let all = match prec {
        Prec::F64 => runs::<f64>(&p, &starts, ()),
        Prec::Dd => runs::<Dd>(&p, &starts, ()),
        Prec::Mpfr(bits) => runs::<Mpfr>(&p, &starts, bits),
        Prec::Exact => return None,
    };
    Some(verify_rigidity(&p, &all))
}

/// The entries of this module.
pub fn entries() -> Vec<Check> {
    vec![
        Check {
            id: "T08",
            title: "circle-pattern lengths are triangles",
            run: t08,
        },
        Check {
            id: "T09",
            title: "circle-pattern rigidity",
            run: t09,
        },
    ]
}
