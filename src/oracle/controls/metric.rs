//! Negative controls of the metric checks: T01 (Gauss–Bonnet), T03 (angle rigidity), T04
//! (angle integrability), T05 (cotan Laplacian), T07 (conformal energy).

// The `at_precision!` bodies are generic code that is also instantiated at `f64`.
#![allow(clippy::clone_on_copy, clippy::op_ref, clippy::let_unit_value)]

use super::{bump, first_interior_edge, not_applicable};
use crate::geometry::cotan::cotan_weights;
use crate::geometry::curvature::curvature;
use crate::geometry::energy::{cauchy_riemann_energy, dirichlet_energy, signed_area};
use crate::geometry::laplacian::cotan_laplacian;
use crate::io::{Metric, Surface};
use crate::mesh::{Face, Mesh};
use crate::oracle::checks_extra::{coplanar, t04, t07_map_at};
use crate::oracle::precision::Prec;
use crate::oracle::registry::Check;
use crate::scalar::Real;
use crate::theorems::t07_conformal_energy::{energy_error_bound, EnergyTerms};
use crate::theorems::{
    t01_gauss_bonnet, t03_angle_rigidity, t05_cotan_laplacian, t07_conformal_energy, Settings,
    Verdict,
};

/// T01-NC: Gauss–Bonnet compared with the curvature of vertex 0 raised by 1/1000. The
/// tolerance (B42, from B40 and B41) grows like the number of corners times 16u: at `f64`
/// it stays below 10⁻⁷ up to a million faces, far below the 10⁻³ shift.
fn t01_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    at_precision!(prec, case, |l: T| {
        let mut k = curvature(&case.mesh, &l);
        let first = k.first_mut()?;
        let d = first.lit(1e-3);
        *first += &d;
        Some(t01_gauss_bonnet::verify_gauss_bonnet(&case.mesh, &l, &k, s))
    })
}

/// Two disjoint copies of `mesh` (vertices and faces of the second copy numbered after the
/// first), and for each of its edges the case's edge it copies.
fn two_copies(mesh: &Mesh) -> Option<(Mesh, Vec<usize>)> {
    let faces = mesh.face_list();
    let glue = mesh.gluing_list();
    let (nv, nf) = (mesh.n_vertices() as u32, faces.len() as u32);
    let mut tris = faces.clone();
    tris.extend(faces.iter().map(|t| t.map(|v| v + nv)));
    let mut sides = glue.clone();
    sides.extend(
        glue.iter()
            .map(|&((fa, sa), (fb, sb))| ((fa + nf, sa), (fb + nf, sb))),
    );
    let double = Mesh::from_gluing(2 * nv, &tris, &sides).ok()?;
    let mut source = vec![usize::MAX; double.n_edges()];
    for f in mesh.faces() {
        let old = mesh.face_halfedges(f);
        for copy in [f, Face(f.0 + nf)] {
            let new = double.face_halfedges(copy);
            for k in 0..3 {
                source[new[k].edge().idx()] = old[k].edge().idx();
            }
        }
    }
    (!source.contains(&usize::MAX)).then_some((double, source))
}

/// T03-NC: the surface taken twice, as two components, with the second metric the first
/// scaled by 3/2 on one copy and by 2 on the other — the tests' control. Every corner angle
/// is unchanged, yet the scale is not one number (the theorem assumes a connected surface);
/// the ratios differ by 1/3 relative, far above the B45 tolerance.
fn t03_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    let (double, source) = two_copies(&case.mesh)?;
    let nv = case.mesh.n_vertices() as u32;
    at_precision!(prec, case, |l: T| {
        let l2: Vec<T> = source.iter().map(|&k| l[k].clone()).collect();
        let lt: Vec<T> = double
            .edges()
            .map(|e| {
                let x = &l2[e.idx()];
                let first_copy = double.tail(e.halfedge()).0 < nv;
                let factor = if first_copy { 1.5 } else { 2.0 };
                x.clone() * &x.lit(factor)
            })
            .collect();
        Some(t03_angle_rigidity::check_equal_angles_imply_scale(
            &double, &l2, &lt, s,
        ))
    })
}

/// T04-NC: T04 on the planar layout with the value (length or squared length) of its first
/// interior edge scaled by 101/100: the angle sums at the edge's ends move by about 10⁻²
/// rad, far above the B43 tolerances (a few hundred units of roundoff).
fn t04_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if !case.positions.as_deref().is_some_and(coplanar) {
        return Some(not_applicable("T04's control needs a planar layout"));
    }
    let e = first_interior_edge(case)?;
    let mut bent = case.clone();
    let (Metric::Lengths(v) | Metric::SquaredLengths(v)) = &mut bent.metric;
    *v.get_mut(e.idx())? *= bump();
    bent.validate().ok()?;
    t04(&bent, prec, s)
}

/// T05-NC: the cotan Laplacian with one off-diagonal entry of row 0 raised by 1/1000:
/// symmetry (compared exactly) and the zero row sum of row 0 (tolerance B41 over the row, a
/// few units of roundoff times the entries) both break.
fn t05_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    at_precision!(prec, case, |l: T| {
        let mut lap = cotan_laplacian(&case.mesh, &l);
        let j = lap.row(0).map(|(j, _)| j).find(|&j| j != 0)?;
        let x = lap.get_mut(0, j)?;
        let d = x.lit(1e-3);
        *x += &d;
        Some(t05_cotan_laplacian::verify_laplacian(&case.mesh, &lap, s))
    })
}

/// T07-NC: `E_D − A − E_CR` for the registry's map ([`t07_map_at`]) with the Dirichlet energy
/// `E_D` scaled by 101/100. On a closed surface `A = 0` and `E_D = E_CR > 0` for this
/// non-conformal map, so the difference is `E_D/100`, far above the B48 bound (a few
/// hundred units of roundoff times the energies).
fn t07_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if case.mesh.n_vertices() == 1 {
        return Some(not_applicable(
            "one vertex: the map is constant and every energy is 0",
        ));
    }
    at_precision!(prec, case, |l: T| {
        let ctx = l.first()?.ctx();
        let ft: Vec<[T; 2]> = t07_map_at(case.mesh.n_vertices(), ctx);
        let w = cotan_weights(&case.mesh, &l);
        let dirichlet = dirichlet_energy(&case.mesh, &w, &ft)?;
        let terms = EnergyTerms {
            error_bound: energy_error_bound(&case.mesh, &l, &ft),
            dirichlet: dirichlet.clone() * &T::from_rational(&bump(), ctx),
            area: signed_area(&case.mesh, &ft)?,
            cauchy_riemann: cauchy_riemann_energy(&case.mesh, &l, &ft)?,
        };
        Some(t07_conformal_energy::verify_conformal_energy(&terms, s))
    })
}

/// The controls of this module.
pub fn controls() -> Vec<Check> {
    vec![
        Check {
            id: "T01-NC",
            title: "control: curvature of v0 + 1e-3",
            run: t01_nc,
        },
        Check {
            id: "T03-NC",
            title: "control: two copies scaled by 3/2 and 2",
            run: t03_nc,
        },
        Check {
            id: "T04-NC",
            title: "control: one squared length × 1.01",
            run: t04_nc,
        },
        Check {
            id: "T05-NC",
            title: "control: L[0][j] + 1e-3",
            run: t05_nc,
        },
        Check {
            id: "T07-NC",
            title: "control: E_D × 1.01",
            run: t07_nc,
        },
    ]
}
