//! The seams of a written parametrization, checked exactly (proof: B110): across every
//! edge of the OBJ whose two sides carry different texture coordinates (a cut edge), the
//! transition is a rotation by a multiple of π/2 and a translation, within a relative `ε`.
//!
//! For a seam segment with ends `a, b`, UVs `p, q` on one side and `p′, q′` on the other,
//! the transition `z ↦ R z + t` maps `p ↦ p′` and `q ↦ q′` exactly when
//! `q′ − p′ = R (q − p)` (then `t = p′ − R p`); the check is
//! `min_R |(q′ − p′) − R (q − p)|² ≤ ε² |q − p|²` over the four rotations `R` by `kπ/2`,
//! decided in ℚ on the written decimals. Cone angles that are multiples of π/2 make every
//! holonomy around a cone such a rotation; on surfaces of genus ≥ 1 the holonomy of the
//! handles is not fixed by the cone angles, and a seam may be reported broken there.

use super::check::{uv_faces, ParametrizationError};
use rug::Rational;
use std::collections::HashMap;

/// What the seam check found.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SeamReport {
    /// Edges of the OBJ with different texture coordinates on their two sides.
    pub seam_segments: usize,
    /// For each broken seam segment, the first of its two triangles (0-based `f` lines).
    pub broken: Vec<usize>,
}

/// `R (x, y)` for the rotation by `k·π/2`.
fn rotate(k: usize, d: &[Rational; 2]) -> [Rational; 2] {
    let (x, y) = (d[0].clone(), d[1].clone());
    match k {
        0 => [x, y],
        1 => [-y, x],
        2 => [-x, -y],
        _ => [y, -x],
    }
}

fn diff(a: &[Rational; 2], b: &[Rational; 2]) -> [Rational; 2] {
    [Rational::from(&a[0] - &b[0]), Rational::from(&a[1] - &b[1])]
}

fn norm2(d: &[Rational; 2]) -> Rational {
    Rational::from(&d[0] * &d[0]) + Rational::from(&d[1] * &d[1])
}

/// Check every seam of the OBJ text `obj` with the relative tolerance `eps` (module
/// documentation).
pub fn check_seams(obj: &str, eps: &Rational) -> Result<SeamReport, ParametrizationError> {
    let uv = uv_faces(obj)?;
    let eps2 = Rational::from(eps * eps);
    // Directed edge (v_a, v_b) → (triangle, uv of a, uv of b).
    let mut side: HashMap<(usize, usize), (usize, usize, usize)> = HashMap::new();
    for (k, (v, _)) in uv.faces.iter().enumerate() {
        for i in 0..3 {
            side.insert((v[i], v[(i + 1) % 3]), (k, i, (i + 1) % 3));
        }
    }
    let mut report = SeamReport::default();
    for (&(a, b), &(k, ia, ib)) in &side {
        let Some(&(k2, jb, ja)) = side.get(&(b, a)) else {
            continue;
        };
        if k2 < k || (k2 == k && b < a) {
            continue;
        }
        let (t, t2) = (uv.uv(k), uv.uv(k2));
        let (p, q) = (t[ia], t[ib]);
        let (p2, q2) = (t2[ja], t2[jb]);
        if p == p2 && q == q2 {
            continue;
        }
        report.seam_segments += 1;
        let (d, d2) = (diff(q, p), diff(q2, p2));
        let bound = Rational::from(&eps2 * &norm2(&d));
        if !(0..4).any(|r| norm2(&diff(&d2, &rotate(r, &d))) <= bound) {
            report.broken.push(k.min(k2));
        }
    }
    report.broken.sort_unstable();
    Ok(report)
}
