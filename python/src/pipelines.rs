//! The uniformization pipelines other than the closed surface's: with boundary (B79), to
//! the sphere (B74–B76) and hyperbolic (B38, B39), as dicts for `penner.UniformizeResult`.
//!
//! Each runs one library call ([`uniformize_boundary`], [`uniformize_sphere`],
//! [`uniformize_hyperbolic`]) without the GIL. A [`PipelineError`] that is the input's
//! fault ([`PipelineError::is_bad_input`]) becomes `penner.InputError`; any other (a step
//! of penner's own computation that did not go through) is a result with
//! `certified=False` and the reason: the solve is run again without a certificate for
//! its numbers, and when even the solve does not go through, the arrays are the input's
//! and `u` is NaN.

use crate::convert::{array1, array2, array3, json_to_py};
use crate::input;
use crate::{decimal, faces_array};
use penner::io::Surface;
use penner::mesh::Mesh;
use penner::scalar::nearest_f64;
use penner::uniformization::certificate::CertificateOutcome;
use penner::uniformization::hyperbolic_certificate::Existence;
use penner::uniformization::pipeline::{
    uniformize_boundary, uniformize_hyperbolic, uniformize_sphere, BoundaryOutcome,
    CertifiedMetric, HyperbolicOutcome, Options, PipelineError, SphereOutcome,
};
use penner::uniformization::Targets;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rug::Rational;
use serde_json::Value;

/// Which pipeline.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// A surface with boundary.
    Boundary,
    /// The sphere, with an optional pole.
    Sphere(Option<u32>),
    /// The hyperbolic metric.
    Hyperbolic,
}

/// An outcome of one of the pipelines, or the reason none was computed.
pub enum Done {
    /// [`uniformize_boundary`].
    Boundary(Box<BoundaryOutcome>),
    /// [`uniformize_sphere`].
    Sphere(Box<SphereOutcome>),
    /// [`uniformize_hyperbolic`].
    Hyperbolic(Box<HyperbolicOutcome>),
    /// Penner's own computation did not go through (not the input's fault).
    None,
}

/// A finished run: the outcome and, when a certificate was attempted and failed with an
/// error of penner's own, its message.
pub struct Run {
    /// The outcome.
    pub done: Done,
    /// The error that kept the certificate (or the solve) from going through.
    pub error: Option<String>,
}

/// Run `target` on `surface` (without the GIL: the caller detaches). `Err` is the input's
/// fault (its message).
pub fn run(
    surface: &Surface,
    target: Target,
    targets: Option<&Targets>,
    options: &Options,
) -> Result<Run, String> {
    let once = |o: &Options| -> Result<Done, PipelineError> {
        Ok(match target {
            Target::Boundary => Done::Boundary(Box::new(uniformize_boundary(surface, targets, o)?)),
            Target::Sphere(pole) => Done::Sphere(Box::new(uniformize_sphere(surface, pole, o)?)),
            Target::Hyperbolic => {
                Done::Hyperbolic(Box::new(uniformize_hyperbolic(surface, targets, o)?))
            }
        })
    };
    match once(options) {
        Ok(done) => Ok(Run { done, error: None }),
        Err(e) if e.is_bad_input() => Err(e.to_string()),
        Err(e) => {
            // The solve's numbers without the certificate that did not go through.
            let uncertified = Options {
                certify: false,
                ..options.clone()
            };
            let done = if options.certify {
                match once(&uncertified) {
                    Ok(d) => d,
                    Err(again) if again.is_bad_input() => return Err(again.to_string()),
                    Err(_) => Done::None,
                }
            } else {
                Done::None
            };
            Ok(Run {
                done,
                error: Some(e.to_string()),
            })
        }
    }
}

/// "not certified: …" unless the message says so already.
fn not_certified(reason: &str) -> String {
    if reason.starts_with("not certified") || reason.starts_with("not computed") {
        reason.to_string()
    } else {
        format!("not certified: {reason}")
    }
}

/// The metric's word and reason.
fn metric_words(m: &CertifiedMetric) -> (&'static str, Option<String>) {
    match m {
        CertifiedMetric::Input => ("input", None),
        CertifiedMetric::Rounded { reason } => ("rounded", Some(reason.clone())),
    }
}

/// Exact decimal strings of binary64 values (`"nan"` for NaN).
fn exact_of_f64(u: &[f64]) -> Vec<String> {
    u.iter()
        .map(|&x| Rational::from_f64(x).map_or_else(|| x.to_string(), |q| decimal(&q)))
        .collect()
}

/// Per-corner coordinates of `faces` of `mesh` in `layout` (NaN where not laid out).
fn corners(
    mesh: &Mesh,
    layout: &penner::uniformization::layout::Layout,
    faces: &[penner::mesh::Face],
) -> Vec<f64> {
    let mut uv = Vec::with_capacity(6 * faces.len());
    for &f in faces {
        match layout.face_corners(mesh, f) {
            Some(c) => uv.extend(c.iter().flatten()),
            None => uv.extend([f64::NAN; 6]),
        }
    }
    uv
}

/// The (k, 3) int64 array of the faces `faces` of `mesh`, vertices through `vertex`.
fn faces_of<'py>(
    py: Python<'py>,
    mesh: &Mesh,
    faces: &[penner::mesh::Face],
    vertex: impl Fn(u32) -> i64,
) -> PyResult<Bound<'py, PyAny>> {
    let mut flat = Vec::with_capacity(3 * faces.len());
    for &f in faces {
        for h in mesh.face_halfedges(f) {
            flat.push(vertex(mesh.tail(h).0));
        }
    }
    array2(py, flat, 3)
}

/// Per-face values `l[f, i]` (side opposite corner `i`) of the faces `faces`.
fn per_faces(mesh: &Mesh, values: &[f64], faces: &[penner::mesh::Face]) -> Vec<f64> {
    let mut out = Vec::with_capacity(3 * faces.len());
    for &f in faces {
        let h = mesh.face_halfedges(f);
        for i in 0..3 {
            out.push(values[h[(i + 1) % 3].edge().idx()]);
        }
    }
    out
}

/// The fields every result has, with their defaults.
struct Common {
    certified: bool,
    u: Vec<f64>,
    u_exact: Vec<String>,
    reason: Option<String>,
    converged: bool,
    stop: String,
    newton_steps: usize,
    euclidean_flips: usize,
    ptolemy_flips: usize,
    shift: i64,
    bits: u32,
    residual: f64,
    residual_max_f64: f64,
    radius: Option<f64>,
    distance: Option<f64>,
    metric: Option<&'static str>,
    metric_reason: Option<String>,
    claim: Option<Value>,
}

impl Common {
    fn set(self, d: &Bound<'_, PyDict>, target: &str) -> PyResult<()> {
        let py = d.py();
        d.set_item("target", target)?;
        d.set_item("certified", self.certified)?;
        d.set_item("u", array1(py, self.u))?;
        d.set_item("u_exact", self.u_exact)?;
        d.set_item("reason", self.reason)?;
        d.set_item("converged", self.converged)?;
        d.set_item("stop", self.stop)?;
        d.set_item("newton_steps", self.newton_steps)?;
        d.set_item("euclidean_flips", self.euclidean_flips)?;
        d.set_item("ptolemy_flips", self.ptolemy_flips)?;
        d.set_item("shift", self.shift)?;
        d.set_item("bits", self.bits)?;
        d.set_item("residual", self.residual)?;
        d.set_item("residual_max_f64", self.residual_max_f64)?;
        d.set_item("radius", self.radius)?;
        d.set_item("distance", self.distance)?;
        d.set_item("metric", self.metric)?;
        d.set_item("metric_reason", self.metric_reason)?;
        let claim = match &self.claim {
            Some(v) => Some(json_to_py(py, v)?),
            None => None,
        };
        d.set_item("claim", claim)?;
        Ok(())
    }
}

/// The result dict of a [`Run`] on `surface` (the input, for a run that computed nothing).
pub fn to_py<'py>(
    py: Python<'py>,
    surface: &Surface,
    run: &Run,
    target: Target,
    certify: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let d = PyDict::new(py);
    let error = run.error.as_deref().map(not_certified);
    let not_asked = (!certify).then(|| "no certificate asked for (certify=False)".to_string());
    match &run.done {
        Done::Boundary(o) => boundary(&d, o, error.or(not_asked))?,
        Done::Sphere(o) => sphere(&d, o, error.or(not_asked))?,
        Done::Hyperbolic(o) => hyperbolic(&d, o, error.or(not_asked))?,
        Done::None => nothing(&d, surface, target, error)?,
    }
    Ok(d.into_any())
}

/// A run that computed nothing: the input's arrays, `u` NaN.
fn nothing(
    d: &Bound<'_, PyDict>,
    surface: &Surface,
    target: Target,
    reason: Option<String>,
) -> PyResult<()> {
    let py = d.py();
    let n = surface.mesh.n_vertices();
    let lengths = surface.lengths::<f64>(());
    d.set_item("F_out", faces_array(py, &surface.mesh)?)?;
    d.set_item(
        "l_out",
        array2(py, input::per_face(&surface.mesh, &lengths), 3)?,
    )?;
    d.set_item("uv", py.None())?;
    let name = match target {
        Target::Boundary => "boundary",
        Target::Sphere(_) => "sphere",
        Target::Hyperbolic => "hyperbolic",
    };
    Common {
        certified: false,
        u: vec![f64::NAN; n],
        u_exact: vec!["nan".to_string(); n],
        reason: Some(reason.unwrap_or_else(|| "not computed".to_string())),
        converged: false,
        stop: "NotComputed".to_string(),
        newton_steps: 0,
        euclidean_flips: 0,
        ptolemy_flips: 0,
        shift: 0,
        bits: 0,
        residual: f64::NAN,
        residual_max_f64: f64::NAN,
        radius: None,
        distance: None,
        metric: None,
        metric_reason: None,
        claim: None,
    }
    .set(d, name)
}

/// A surface with boundary: `u` on the surface, the final triangulation, lengths and
/// layout of copy 1 of the double when its seam is intact, else of the whole double.
fn boundary(d: &Bound<'_, PyDict>, o: &BoundaryOutcome, reason: Option<String>) -> PyResult<()> {
    let py = d.py();
    let b = &o.boundary;
    let sol = &b.solution;
    let n = o.surface.mesh.n_vertices();
    let region = b.original_faces();
    let faces: Vec<penner::mesh::Face> = sol
        .mesh
        .faces()
        .filter(|f| region.as_ref().is_none_or(|k| k[f.idx()]))
        .collect();
    let scale = 2f64.powi(o.shift as i32);
    let per_edge: Vec<f64> =
        penner::uniformization::svg::scaled_lengths_f64(&sol.mesh, &sol.base_lengths, &sol.u)
            .into_iter()
            .map(|x| x * scale)
            .collect();
    let drawn = o.layout();
    d.set_item("F_out", faces_of(py, &sol.mesh, &faces, i64::from)?)?;
    d.set_item(
        "l_out",
        array2(py, per_faces(&sol.mesh, &per_edge, &faces), 3)?,
    )?;
    // The layout's coordinates are of the solve's scale: multiply back to the input's.
    let uv: Vec<f64> = corners(&sol.mesh, &drawn.layout, &faces)
        .into_iter()
        .map(|x| x * scale)
        .collect();
    d.set_item("uv", array3(py, uv, 3, 2)?)?;
    d.set_item("layout_of", drawn.what)?;
    d.set_item("folds", drawn.folds)?;
    d.set_item("seam_flips", b.seam_flips.len())?;
    d.set_item("mirror_asymmetry", b.mirror_asymmetry)?;
    let mut c = Common {
        certified: o.certified(),
        u: b.u.clone(),
        u_exact: exact_of_f64(&b.u),
        reason: None,
        converged: sol.converged(),
        stop: format!("{:?}", sol.stop),
        newton_steps: sol.steps.len(),
        euclidean_flips: sol.euclidean_flips,
        ptolemy_flips: sol.flip_sequence.len(),
        shift: o.shift,
        bits: o.bits,
        residual: sol.residual_max,
        residual_max_f64: sol.residual_max,
        radius: None,
        distance: None,
        metric: None,
        metric_reason: None,
        claim: None,
    };
    if !sol.converged() {
        c.reason = Some(format!(
            "not converged ({:?}); max |Θ − θ| = {:e}",
            sol.stop, sol.residual_max
        ));
    } else if let Some(cert) = &o.certification {
        let proof = &cert.proof;
        c.radius = Some(nearest_f64(&proof.data.radius));
        c.residual = proof.residual_max;
        match &proof.outcome {
            CertificateOutcome::Holds {
                distance, residual, ..
            } => {
                // u on copy 1 (the double's vertices 0..n are the surface's).
                let u: Vec<&Rational> = proof.data.u.iter().take(n).collect();
                c.u = u.iter().map(|q| nearest_f64(q)).collect();
                c.u_exact = u.iter().map(|q| decimal(q)).collect();
                c.distance = Some(*distance);
                c.residual = *residual;
                let (m, r) = metric_words(&cert.metric);
                c.metric = Some(m);
                c.metric_reason = r;
                c.claim = o.claim();
            }
            CertificateOutcome::Undecided { reason } => c.reason = Some(not_certified(reason)),
        }
    }
    if c.reason.is_none() && !c.certified {
        c.reason = reason.or_else(|| Some("not certified".to_string()));
    }
    c.set(d, "boundary")
}

/// The sphere: `uv` the inscribed positions (n, 3), `layout` the planar disk per corner;
/// `layout_failure` says why vertices binary64 could not place are NaN there (else `None`).
fn sphere(d: &Bound<'_, PyDict>, o: &SphereOutcome, reason: Option<String>) -> PyResult<()> {
    let py = d.py();
    let s = &o.solution;
    let n = o.surface.mesh.n_vertices();
    let disk = &s.solution.mesh;
    // u of the disk problem, per vertex of the surface (NaN at the pole).
    let mut u = vec![f64::NAN; n];
    for (w, &v) in s.disk.vertex.iter().enumerate() {
        if let Some(x) = s.solution.u.get(w) {
            u[v as usize] = *x;
        }
    }
    let chords: Vec<f64> = s
        .mesh
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (
                s.positions[s.mesh.tail(h).idx()],
                s.positions[s.mesh.tip(h).idx()],
            );
            ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
        })
        .collect();
    let disk_faces: Vec<penner::mesh::Face> = disk.faces().collect();
    d.set_item("F_out", faces_array(py, &s.mesh)?)?;
    d.set_item("l_out", array2(py, input::per_face(&s.mesh, &chords), 3)?)?;
    let flat: Vec<f64> = s.positions.iter().flatten().copied().collect();
    d.set_item("uv", array2(py, flat, 3)?)?;
    d.set_item(
        "layout",
        array3(py, corners(disk, &s.layout, &disk_faces), 3, 2)?,
    )?;
    d.set_item(
        "F_layout",
        faces_of(py, disk, &disk_faces, |w| {
            i64::from(s.disk.vertex.get(w as usize).copied().unwrap_or(u32::MAX))
        })?,
    )?;
    d.set_item("pole", s.pole)?;
    d.set_item("layout_failure", s.layout_failure.clone())?;
    d.set_item("deviation", o.deviation)?;
    let planar = &o.planar;
    d.set_item(
        "planar",
        (
            planar.not_ccw.len(),
            planar.not_delaunay.len(),
            planar.not_convex.len(),
        ),
    )?;
    let (residual, _) = o
        .refinement
        .unwrap_or((s.solution.residual_max, s.solution.steps.len()));
    let mut c = Common {
        certified: o.certified(),
        u_exact: exact_of_f64(&u),
        u,
        reason: None,
        converged: s.solution.stop == penner::uniformization::Stop::Converged,
        stop: format!("{:?}", s.solution.stop),
        newton_steps: s.solution.steps.len(),
        euclidean_flips: s.euclidean_flips,
        ptolemy_flips: s.flip_sequence.len(),
        shift: o.shift,
        bits: o.bits,
        residual,
        residual_max_f64: s.solution.residual_max,
        radius: None,
        distance: None,
        metric: None,
        metric_reason: None,
        claim: o.claim.clone(),
    };
    match &o.certificate {
        Some(CertificateOutcome::Holds {
            distance, residual, ..
        }) => {
            c.distance = Some(*distance);
            c.residual = *residual;
            // B76 on the disk is for the surface's exact metric.
            c.metric = Some("input");
            if !planar.holds() {
                c.reason = Some(format!(
                    "not certified: the planar layout is not certified Delaunay and convex ({} folded or flat faces, {} edges not Delaunay, {} reflex boundary corners)",
                    planar.not_ccw.len(),
                    planar.not_delaunay.len(),
                    planar.not_convex.len()
                ));
            }
        }
        Some(CertificateOutcome::Undecided { reason }) => c.reason = Some(not_certified(reason)),
        None => {}
    }
    if c.reason.is_none() && !c.certified {
        c.reason = reason.or_else(|| Some("not certified".to_string()));
    }
    c.set(d, "sphere")
}

/// The hyperbolic target: `u`, the final triangulation and its hyperbolic lengths; no
/// planar layout (`uv` None).
fn hyperbolic(
    d: &Bound<'_, PyDict>,
    o: &HyperbolicOutcome,
    reason: Option<String>,
) -> PyResult<()> {
    let py = d.py();
    let s = &o.solution;
    d.set_item("F_out", faces_array(py, &s.mesh)?)?;
    d.set_item(
        "l_out",
        array2(py, input::per_face(&s.mesh, &s.scaled_lengths()), 3)?,
    )?;
    d.set_item("uv", py.None())?;
    d.set_item("area", o.area)?;
    d.set_item("gauss_bonnet", o.gauss_bonnet)?;
    let (m, r) = metric_words(&o.metric);
    let mut c = Common {
        certified: o.certified(),
        u: s.u.clone(),
        u_exact: exact_of_f64(&s.u),
        reason: None,
        converged: s.converged(),
        stop: format!("{:?}", s.stop),
        newton_steps: s.steps.len(),
        euclidean_flips: s.input_flips.len(),
        ptolemy_flips: s.flips.len(),
        shift: 0,
        bits: o.bits,
        residual: s.residual_max,
        residual_max_f64: s.residual_max,
        radius: None,
        distance: None,
        metric: None,
        metric_reason: None,
        claim: o.claim(),
    };
    if let Some((u, refined)) = &o.refined {
        c.u = u.iter().map(nearest_f64).collect();
        c.u_exact = u.iter().map(decimal).collect();
        c.residual = *refined;
    }
    if !s.converged() {
        c.reason = Some(format!(
            "not converged ({:?}); max |Θ − θ| = {:e}",
            s.stop, s.residual_max
        ));
    } else if let Some(cert) = &o.certificate {
        match &cert.existence {
            Existence::Holds {
                distance, radius, ..
            } => {
                c.distance = Some(*distance);
                c.radius = Some(*radius);
                c.residual = cert.residual_norm2;
                c.metric = Some(m);
                c.metric_reason = r;
            }
            Existence::Undecided { reason } => c.reason = Some(not_certified(reason)),
        }
    }
    if c.reason.is_none() && !c.certified {
        c.reason = reason.or_else(|| Some("not certified".to_string()));
    }
    c.set(d, "hyperbolic")
}
