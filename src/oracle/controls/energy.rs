//! Negative controls of the variational checks: T06 (cotan weights), T31 (Schläfli), T32 (energy gradient),
//! T33 (hyperbolic energy gradient). Each compares against data raised by 1/1000 at one
//! element (T06: `10⁻³·(1 + |w|)`), far above the tolerances (B56–B58 are a few thousand
//! units of `u` at `f64`; B31's enclosures are narrower still).

// The `at_precision!` bodies are generic code that is also instantiated at `f64`.
#![allow(clippy::clone_on_copy, clippy::op_ref, clippy::let_unit_value)]

use crate::io::Surface;
use crate::oracle::checks_energy::{
    beyond_caps, energy_probe, T06_CAPS, T31_CAPS, T32_CAPS, T33_CAPS,
};
use crate::oracle::precision::Prec;
use crate::oracle::registry::Check;
use crate::scalar::Real;
use crate::theorems::t06_cotan_weights_metric::{verify_weight_boxes, weight_enclosures};
use crate::theorems::t31_schlafli::{half_angles, verify_schlafli};
use crate::theorems::t32_energy::{verify_gradient, EnergyInput};
use crate::theorems::t33_hyperbolic::verify_hyperbolic_gradient;
use crate::theorems::{Settings, Verdict};
use crate::variational::{energy, hyperbolic};

/// T06-NC: enclosures of the case's own cotan weights (which contain the exact weights,
/// so without the raise nothing can be refuted) with the box of `w_1` moved up by
/// `10⁻³·(1 + |w_1|)`, far beyond its width (proofs/B31), whichever the sign of `w_1`.
/// No scaling of the case's metric has such weights, which the comparison of
/// [`verify_weight_boxes`] proves (`fails`, certified, witness `e1`).
fn t06_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if case.mesh.n_edges() < 2 {
        return Some(super::not_applicable("T06 runs from 2 edges"));
    }
    if let Some(v) = beyond_caps(case, prec, &T06_CAPS) {
        return Some(v);
    }
    at_precision!(prec, case, |l: T| {
        let mut w = weight_enclosures(&case.mesh, &l)?;
        let bump = (w[1].abs() + &w[1].one_like()) * &w[1].lit(1e-3);
        w[1] += &bump;
        Some(verify_weight_boxes(&case.mesh, &l, &w, s))
    })
}

/// T31-NC: the half-angle of the first face's first corner raised by 1/1000.
fn t31_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if let Some(v) = beyond_caps(case, prec, &T31_CAPS) {
        return Some(v);
    }
    at_precision!(prec, case, |l: T| {
        let mut h = half_angles(&case.mesh, &l);
        let first = case.mesh.faces().next()?;
        let k = case.mesh.face_halfedges(first)[0].idx();
        let d = h[k].lit(1e-3);
        h[k] += &d;
        Some(verify_schlafli(&case.mesh, &l, &h, s))
    })
}

/// T32-NC: the gradient `Θ − θ` with `∂E/∂u_0` raised by 1/1000 (the first direction is
/// `e_0`).
fn t32_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if let Some(v) = beyond_caps(case, prec, &T32_CAPS) {
        return Some(v);
    }
    at_precision!(prec, case, |l: T| {
        let n = case.mesh.n_vertices();
        let z = l.first()?;
        let (u, t, d) = energy_probe(n, z);
        let lambda = energy::log_lengths(&l);
        let mut g = energy::gradient(&case.mesh, &lambda, &u, &t);
        let bump = g[0].lit(1e-3);
        g[0] += &bump;
        let input = EnergyInput {
            mesh: &case.mesh,
            lengths: &l,
            u: &u,
            targets: &t,
        };
        Some(verify_gradient(&input, &g, &d[..1], s))
    })
}

/// T33-NC: the hyperbolic gradient `Θ − θ_hyp` with its first entry raised by 1/1000.
fn t33_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if let Some(v) = beyond_caps(case, prec, &T33_CAPS) {
        return Some(v);
    }
    at_precision!(prec, case, |l: T| {
        let n = case.mesh.n_vertices();
        let z = l.first()?;
        let (u, t, d) = energy_probe(n, z);
        let mut g = hyperbolic::gradient(&case.mesh, &l, &u, &t);
        let bump = g[0].lit(1e-3);
        g[0] += &bump;
        Some(verify_hyperbolic_gradient(
            &case.mesh,
            &l,
            &u,
            &t,
            &g,
            &d[..1],
            s,
        ))
    })
}

/// The controls of this module.
pub fn controls() -> Vec<Check> {
    vec![
        Check {
            id: "T06-NC",
            title: "metric from a raised cotan weight",
            run: t06_nc,
        },
        Check {
            id: "T31-NC",
            title: "Schläfli vs a raised half-angle",
            run: t31_nc,
        },
        Check {
            id: "T32-NC",
            title: "∇E vs a raised ∂E/∂u₀",
            run: t32_nc,
        },
        Check {
            id: "T33-NC",
            title: "hyperbolic ∇E vs a raised entry",
            run: t33_nc,
        },
    ]
}
