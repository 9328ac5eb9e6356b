//! `penner._penner`: the Python extension module behind the `penner` package.
//!
//! A binding layer only: every computation is a call into the `penner` library (the
//! checks of `penner check`, the uniformization pipelines, the flips to intrinsic Delaunay,
//! the maximal circle packing, the claim oracle). The
//! pure-Python package `penner` (python/penner/) normalizes the arguments (numpy arrays,
//! exact strings, paths) and wraps the results; this module copies the arrays into Rust
//! data once, releases the GIL for the work (`Python::detach`) and builds numpy arrays and
//! dicts from the results. Bad input raises `penner.InputError` naming the element.

mod convert;
mod delaunay;
mod input;
mod pipelines;
mod uv;

use convert::{array1, array2, array3, json_to_py};
use input::{InputError as BadInput, Numbers, Source};
use numpy::{PyReadonlyArrayDyn, PyUntypedArrayMethods};
use penner::io::{ReadError, Surface};
use penner::oracle::check_surface::{check_surface, CheckOptions};
use penner::oracle::{precision, registry, report};
use penner::scalar::{nearest_f64, parse_rational};
use penner::theorems::Settings;
use penner::uniformization::certificate::{CertificateError, CertificateOutcome};
use penner::uniformization::pipeline::{
    certify_solution, uniformize_closed, CertifiedMetric, Options, PipelineError, Precision,
};
use penner::uniformization::Targets;
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rug::Rational;
use std::path::PathBuf;
use std::sync::Arc;

pyo3::create_exception!(
    penner,
    InputError,
    PyValueError,
    "Bad input: a wrong shape, a number that is not finite, an index out of range, a \
     degenerate triangle, a violated triangle inequality, a malformed file or claim. The \
     message names the element (`V[2, 1]`, `F[3, 0]`, `l[5, 2]`, a face, a line)."
);

impl From<BadInput> for PyErr {
    fn from(e: BadInput) -> PyErr {
        InputError::new_err(e.0)
    }
}

/// A read error as a Python exception: `OSError` when the file cannot be opened,
/// `InputError` (naming the line or element) when its contents are refused.
fn read_error(e: ReadError) -> PyErr {
    match e {
        ReadError::File { .. } | ReadError::NotAFile { .. } => PyOSError::new_err(e.to_string()),
        e => InputError::new_err(e.to_string()),
    }
}

/// A triangulated surface with an exact metric (a Δ-complex with one positive rational
/// length, or squared length, per edge), validated when it was made.
///
/// Made by `penner.surface(V, F)`, `penner.surface(F=F, l=l)` or `penner.surface(path)`;
/// every function of the package accepts one in place of `(V, F)`.
#[pyclass(frozen, name = "Surface", module = "penner")]
pub struct PySurface {
    inner: Arc<Surface>,
}

#[pymethods]
impl PySurface {
    /// The surface's name (the file, or the name given).
    #[getter]
    fn name(&self) -> &str {
        &self.inner.name
    }
    /// Number of vertices.
    #[getter]
    fn n_vertices(&self) -> usize {
        self.inner.mesh.n_vertices()
    }
    /// Number of edges.
    #[getter]
    fn n_edges(&self) -> usize {
        self.inner.mesh.n_edges()
    }
    /// Number of faces.
    #[getter]
    fn n_faces(&self) -> usize {
        self.inner.mesh.n_faces()
    }
    /// The Euler characteristic χ = V − E + F.
    #[getter]
    fn euler_characteristic(&self) -> i64 {
        self.inner.mesh.euler_characteristic()
    }
    /// Whether the surface has no boundary.
    #[getter]
    fn is_closed(&self) -> bool {
        self.inner.mesh.is_closed()
    }
    /// Vertex positions, (n, 3) float64 (each the binary64 number nearest the exact
    /// coordinate), or None when the surface is given by lengths only.
    #[getter]
    #[allow(non_snake_case)]
    fn V<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        let Some(p) = &self.inner.positions else {
            return Ok(None);
        };
        let flat: Vec<f64> = p.iter().flat_map(|x| x.iter().map(nearest_f64)).collect();
        array2(py, flat, 3).map(Some)
    }
    /// Faces, (m, 3) int64, counter-clockwise vertex triples.
    #[getter]
    #[allow(non_snake_case)]
    fn F<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        faces_array(py, &self.inner.mesh)
    }
    /// Per-face edge lengths, (m, 3) float64: `l[f, i]` is the length of the side of face
    /// `f` opposite its corner `i` (libigl's layout), each the binary64 number nearest the
    /// exact length (within 1.5 units in the last place for squared lengths).
    #[getter]
    fn l<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let per_edge = self.inner.lengths::<f64>(());
        array2(py, input::per_face(&self.inner.mesh, &per_edge), 3)
    }
    fn __repr__(&self) -> String {
        format!(
            "penner.Surface({:?}: {} vertices, {} edges, {} faces, χ = {})",
            self.inner.name,
            self.inner.mesh.n_vertices(),
            self.inner.mesh.n_edges(),
            self.inner.mesh.n_faces(),
            self.inner.mesh.euler_characteristic()
        )
    }
}

/// The faces of a mesh as an (m, 3) int64 array.
pub(crate) fn faces_array<'py>(
    py: Python<'py>,
    mesh: &penner::mesh::Mesh,
) -> PyResult<Bound<'py, PyAny>> {
    let flat: Vec<i64> = mesh
        .face_list()
        .iter()
        .flat_map(|t| t.map(i64::from))
        .collect();
    array2(py, flat, 3)
}

/// The values of an (rows, 3) numpy array named `name`, row-major (one copy, whatever the
/// strides).
fn numbers_f64(a: &PyReadonlyArrayDyn<'_, f64>, name: &str) -> Result<Vec<f64>, BadInput> {
    shape_rows3(a.shape(), name)?;
    Ok(a.as_array().iter().copied().collect())
}

/// Refuse an array whose shape is not (rows, 3).
fn shape_rows3(shape: &[usize], name: &str) -> Result<(), BadInput> {
    if shape.len() != 2 || shape[1] != 3 {
        return Err(BadInput(format!(
            "{name} has shape {shape:?}: expected (rows, 3)"
        )));
    }
    Ok(())
}

/// Exact literals given as rows of three strings.
fn numbers_exact(rows: Vec<Vec<String>>, name: &str) -> Result<Vec<String>, BadInput> {
    let mut out = Vec::with_capacity(3 * rows.len());
    for (i, r) in rows.into_iter().enumerate() {
        if r.len() != 3 {
            return Err(BadInput(format!(
                "{name}[{i}] has {} entries: expected 3",
                r.len()
            )));
        }
        out.extend(r);
    }
    Ok(out)
}

/// Make a surface (the package's `penner.surface` normalizes the arguments first).
///
/// Exactly one of `v`/`v_exact` (positions) or `l`/`l_exact` (per-face lengths) goes with
/// the faces `f` (an (m, 3) int64 array). Binary64 values are taken exactly; exact
/// literals are decimal or fraction strings. The surface is validated exactly.
#[pyfunction]
#[pyo3(signature = (*, f, v=None, v_exact=None, l=None, l_exact=None, name="array".to_string()))]
fn make_surface(
    py: Python<'_>,
    f: PyReadonlyArrayDyn<'_, i64>,
    v: Option<PyReadonlyArrayDyn<'_, f64>>,
    v_exact: Option<Vec<Vec<String>>>,
    l: Option<PyReadonlyArrayDyn<'_, f64>>,
    l_exact: Option<Vec<Vec<String>>>,
    name: String,
) -> PyResult<PySurface> {
    shape_rows3(f.shape(), "F")?;
    let faces: Vec<i64> = f.as_array().iter().copied().collect();
    let source =
        match (v, v_exact, l, l_exact) {
            (Some(v), None, None, None) => Source::Positions {
                v: Numbers::F64(numbers_f64(&v, "V")?),
                f: faces,
            },
            (None, Some(v), None, None) => Source::Positions {
                v: Numbers::Exact(numbers_exact(v, "V")?),
                f: faces,
            },
            (None, None, Some(l), None) => Source::FaceLengths {
                f: faces,
                l: Numbers::F64(numbers_f64(&l, "l")?),
            },
            (None, None, None, Some(l)) => Source::FaceLengths {
                f: faces,
                l: Numbers::Exact(numbers_exact(l, "l")?),
            },
            _ => return Err(InputError::new_err(
                "give the faces F with exactly one of the positions V or the per-face lengths l",
            )),
        };
    let s = py.detach(move || input::surface(source, &name))?;
    Ok(PySurface { inner: Arc::new(s) })
}

/// Read a surface file (.json, .obj or .off; coordinates and lengths read exactly).
#[pyfunction]
fn read(py: Python<'_>, path: PathBuf) -> PyResult<PySurface> {
    let s = py
        .detach(move || penner::io::read_path(&path))
        .map_err(read_error)?;
    Ok(PySurface { inner: Arc::new(s) })
}

/// The checks of this build: a list of (id, title).
#[pyfunction]
fn catalogue() -> Vec<(&'static str, &'static str)> {
    registry::catalogue()
        .iter()
        .map(|c| (c.id, c.title))
        .collect()
}

/// Run the checks (`only`: their IDs; empty: all) at the precisions (`f64`, `dd`, MPFR
/// bits, `exact`) on the surface, as `penner check` does ([`check_surface`]): the rows
/// (one per check and precision, as `penner check --json`) and, per failing check, its
/// failure file's document with a minimal reproducer (when `reproducers`).
#[pyfunction]
#[pyo3(signature = (surface, precision, only, reproducers=true, negative_controls=false))]
fn check<'py>(
    py: Python<'py>,
    surface: &PySurface,
    precision: Vec<String>,
    only: Vec<String>,
    reproducers: bool,
    negative_controls: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let precs = precision::parse_list(&precision.join(","))
        .map_err(|e| InputError::new_err(format!("precision: {e}")))?;
    if precs.is_empty() {
        return Err(InputError::new_err("precision: no precision given"));
    }
    let options = CheckOptions {
        precisions: precs,
        only,
        negative_controls,
        reproducers,
        settings: Settings::default(),
    };
    let s = Arc::clone(&surface.inner);
    let out = py
        .detach(|| check_surface(&s, &s.name, &options, &|_| {}))
        .map_err(|e| {
            // The library's words are the command line's: say them in Python's.
            let text = e
                .to_string()
                .replace("--only ", "only: ")
                .replace("--only", "only")
                .replace("--precision exact", "precision=\"exact\"");
            InputError::new_err(text)
        })?;
    let rows: Vec<serde_json::Value> = out.rows.iter().map(report::row_json).collect();
    let failures: Vec<serde_json::Value> = out
        .failures
        .iter()
        .map(penner::oracle::failure::Failure::to_json)
        .collect();
    let rows = json_to_py(py, &serde_json::Value::Array(rows))?;
    let failures = json_to_py(py, &serde_json::Value::Array(failures))?;
    Ok((rows, failures).into_pyobject(py)?.into_any())
}

/// What [`uniformize`] computed, before it becomes Python objects.
struct Uniformized {
    outcome: penner::uniformization::pipeline::ClosedOutcome,
    certification: Option<penner::uniformization::pipeline::Certification>,
    reason: Option<String>,
}

/// The targets given (`Θ_i/π`, exact literals, one per vertex), or `None` for `flat`.
pub(crate) fn parse_targets(
    t: Option<Vec<String>>,
    flat: bool,
    n: usize,
) -> PyResult<Option<Targets>> {
    match (t, flat) {
        (Some(_), true) => Err(InputError::new_err(
            "give either targets or flat=True, not both",
        )),
        (None, _) => Ok(None),
        (Some(t), false) => {
            if t.len() != n {
                return Err(InputError::new_err(format!(
                    "targets: {} values for {n} vertices (one Θ_i/π per vertex)",
                    t.len()
                )));
            }
            let q = t
                .iter()
                .enumerate()
                .map(|(i, x)| {
                    parse_rational(x).map_err(|e| InputError::new_err(format!("targets[{i}]: {e}")))
                })
                .collect::<PyResult<Vec<Rational>>>()?;
            Ok(Some(Targets::from_multiples_of_pi(q)))
        }
    }
}

/// Uniformize the surface, at `precision` (`f64`, `dd` or MPFR bits 128..=4096),
/// certified when `certify`: a closed surface to the cone angles `targets` (Θ_i/π, exact
/// literals) or flat (`flat`); a surface with boundary to `targets` (Θ_v/π inside, φ_v/π
/// on the boundary) or flat with the boundary curvature spread evenly; to the sphere
/// (`sphere`, optional `pole`); or hyperbolic (`hyperbolic`, default targets 2π). A dict
/// (the package wraps it in `penner.UniformizeResult`).
#[pyfunction]
#[pyo3(signature = (surface, targets=None, flat=false, precision="256".to_string(), certify=true, sphere=false, hyperbolic=false, pole=None))]
#[allow(clippy::too_many_arguments, clippy::fn_params_excessive_bools)]
fn uniformize<'py>(
    py: Python<'py>,
    surface: &PySurface,
    targets: Option<Vec<String>>,
    flat: bool,
    precision: String,
    certify: bool,
    sphere: bool,
    hyperbolic: bool,
    pole: Option<u32>,
) -> PyResult<Bound<'py, PyAny>> {
    let precision: Precision = precision
        .parse()
        .map_err(|e| InputError::new_err(format!("precision: {e}")))?;
    let s = Arc::clone(&surface.inner);
    let n = s.mesh.n_vertices();
    if sphere && hyperbolic {
        return Err(InputError::new_err(
            "give at most one of sphere=True and hyperbolic=True",
        ));
    }
    if sphere && (targets.is_some() || flat) {
        return Err(InputError::new_err(
            "sphere=True takes no targets and no flat=True (the sphere's cone angles are 2π)",
        ));
    }
    if pole.is_some() && !sphere {
        return Err(InputError::new_err("pole: only with sphere=True"));
    }
    if pole.is_some_and(|p| p as usize >= n) {
        return Err(InputError::new_err(format!(
            "pole: vertex {} is out of range ({n} vertices)",
            pole.unwrap_or_default()
        )));
    }
    let parsed = parse_targets(targets, flat, n)?;
    let target = if sphere {
        Some(pipelines::Target::Sphere(pole))
    } else if hyperbolic {
        Some(pipelines::Target::Hyperbolic)
    } else if !s.mesh.is_closed() {
        Some(pipelines::Target::Boundary)
    } else {
        None
    };
    if let Some(target) = target {
        if target == pipelines::Target::Boundary && parsed.is_none() && !flat {
            return Err(InputError::new_err(
                "the target angles are required: targets (Θ_v/π at interior vertices, φ_v/π at boundary vertices) or flat=True",
            ));
        }
        let options = Options { precision, certify };
        let surface = Arc::clone(&s);
        let run = py.detach(move || pipelines::run(&surface, target, parsed.as_ref(), &options));
        let run = run.map_err(InputError::new_err)?;
        return pipelines::to_py(py, &s, &run, target, certify);
    }
    let targets = match (parsed, flat) {
        (Some(t), _) => t,
        (None, true) => Targets::flat(n),
        (None, false) => {
            return Err(InputError::new_err(
                "the target angles are required: targets (Θ_i/π, one per vertex) or flat=True",
            ))
        }
    };
    let done = py.detach(move || -> Result<Uniformized, String> {
        let options = Options {
            precision,
            certify: false,
        };
        // Not converging is an outcome; an error here is the input's fault.
        let outcome =
            uniformize_closed(&s, &targets, &options, &mut |_| {}).map_err(|e| e.to_string())?;
        let mut reason = None;
        let mut certification = None;
        if !outcome.solution.converged() {
            reason = Some(format!(
                "not converged ({:?}); max |Θ − θ| = {:e}",
                outcome.solution.stop, outcome.solution.residual_max
            ));
        } else if !certify {
            reason = Some("no certificate asked for (certify=False)".to_string());
        } else {
            let lengths = outcome.surface.lengths::<f64>(());
            match certify_solution(&outcome.surface, &lengths, &outcome.solution, precision) {
                Ok(c) => {
                    if let CertificateOutcome::Undecided { reason: r } = &c.proof.outcome {
                        reason = Some(format!("not certified: {r}"));
                    }
                    certification = Some(c);
                }
                Err(PipelineError::Certificate(CertificateError::Replay(r))) => {
                    reason = Some(format!(
                        "not certified: the refinement did not go through: {r}"
                    ));
                }
                // penner's own computation did not go through: undecided, not bad input.
                Err(e) if !e.is_bad_input() => reason = Some(format!("not certified: {e}")),
                Err(e) => return Err(e.to_string()),
            }
        }
        Ok(Uniformized {
            outcome,
            certification,
            reason,
        })
    });
    let done = done.map_err(InputError::new_err)?;
    uniformized_to_py(py, &done)
}

/// The dict of a [`Uniformized`].
fn uniformized_to_py<'py>(py: Python<'py>, done: &Uniformized) -> PyResult<Bound<'py, PyAny>> {
    let out = &done.outcome;
    let sol = &out.solution;
    let d = PyDict::new(py);
    let (u_exact, u): (Vec<String>, Vec<f64>) = match &done.certification {
        Some(c) => (
            c.proof.data.u.iter().map(decimal).collect(),
            c.proof.data.u.iter().map(nearest_f64).collect(),
        ),
        None => (
            sol.u
                .iter()
                .map(|&x| Rational::from_f64(x).map_or_else(|| x.to_string(), |q| decimal(&q)))
                .collect(),
            sol.u.clone(),
        ),
    };
    let certified = done
        .certification
        .as_ref()
        .is_some_and(|c| matches!(c.proof.outcome, CertificateOutcome::Holds { .. }));
    // The final metric ℓ_ij e^{(u_i + u_j)/2} on the final triangulation, in the input's
    // scale (the solve ran on the input divided by 2^shift).
    let scale = 2f64.powi(out.shift as i32);
    let per_edge: Vec<f64> =
        penner::geometry::scaling::conformal_scaling::<f64>(&sol.mesh, &sol.base_lengths, &u)
            .into_iter()
            .map(|x| x * scale)
            .collect();
    let layout = penner::uniformization::layout::unfold(&sol.mesh, &per_edge, input::face(0));
    let mut uv = Vec::with_capacity(6 * sol.mesh.n_faces());
    for f in sol.mesh.faces() {
        match layout.face_corners(&sol.mesh, f) {
            Some(c) => uv.extend(c.iter().flatten()),
            None => uv.extend([f64::NAN; 6]),
        }
    }
    d.set_item("target", "closed")?;
    d.set_item("certified", certified)?;
    d.set_item("u", array1(py, u))?;
    d.set_item("u_exact", u_exact)?;
    d.set_item("F_out", faces_array(py, &sol.mesh)?)?;
    d.set_item(
        "l_out",
        array2(py, input::per_face(&sol.mesh, &per_edge), 3)?,
    )?;
    d.set_item("uv", array3(py, uv, 3, 2)?)?;
    d.set_item("converged", sol.converged())?;
    d.set_item("stop", format!("{:?}", sol.stop))?;
    d.set_item("newton_steps", sol.steps.len())?;
    d.set_item("euclidean_flips", sol.euclidean_flips)?;
    d.set_item("ptolemy_flips", sol.flip_sequence.len())?;
    d.set_item("shift", out.shift)?;
    d.set_item("bits", out.bits)?;
    d.set_item("reason", done.reason.clone())?;
    let mut residual = sol.residual_max;
    let (mut radius, mut distance, mut metric, mut metric_reason, mut claim) =
        (None, None, None, None, None);
    if let Some(c) = &done.certification {
        radius = Some(nearest_f64(&c.proof.data.radius));
        residual = c.proof.residual_max;
        if let CertificateOutcome::Holds {
            distance: dist,
            residual: r,
            ..
        } = c.proof.outcome
        {
            distance = Some(dist);
            residual = r;
            metric = Some(match &c.metric {
                CertifiedMetric::Input => "input",
                CertifiedMetric::Rounded { .. } => "rounded",
            });
            if let CertifiedMetric::Rounded { reason } = &c.metric {
                metric_reason = Some(reason.clone());
            }
            if let Some(v) = c.claim(&out.surface, out.bits) {
                claim = Some(json_to_py(py, &v)?);
            }
        }
    }
    d.set_item("radius", radius)?;
    d.set_item("distance", distance)?;
    d.set_item("residual", residual)?;
    d.set_item("residual_max_f64", sol.residual_max)?;
    d.set_item("metric", metric)?;
    d.set_item("metric_reason", metric_reason)?;
    d.set_item("claim", claim)?;
    Ok(d.into_any())
}

/// An exact decimal string of a dyadic rational, `p/q` otherwise.
pub(crate) fn decimal(q: &Rational) -> String {
    penner::uniformization::claim_form::exact_decimal(q).unwrap_or_else(|| q.to_string())
}

/// Answer a claim (protocol v1, JSON text) as `penner certify` does: the answer as a dict.
#[pyfunction]
fn certify(py: Python<'_>, claim: String) -> PyResult<Bound<'_, PyAny>> {
    let answer = py.detach(move || {
        let c = penner::oracle::claim::parse(&claim, "claim").map_err(|e| e.to_string())?;
        penner::oracle::certify::certify(&c)
            .map(|a| a.to_json())
            .map_err(|e| e.to_string())
    });
    let answer = answer.map_err(InputError::new_err)?;
    json_to_py(py, &answer)
}

/// Lobachevsky's function `Л(x) = −∫₀ˣ log|2 sin t| dt` of each finite `x`, evaluated at
/// `precision` (`f64`, `dd` or MPFR bits 53..=65536; B52–B55) and rounded to the nearest
/// binary64 number; with `enclosure`, the pairs `(lo, hi)` of binary64 numbers rounded
/// outward from the rigorous MPFR enclosure at `precision` bits (at least 53).
#[pyfunction]
#[pyo3(signature = (x, precision="f64".to_string(), enclosure=false))]
fn lobachevsky(
    py: Python<'_>,
    x: Vec<f64>,
    precision: String,
    enclosure: bool,
) -> PyResult<Bound<'_, PyAny>> {
    use penner::scalar::{Dd, Interval, Mpfr, Precision as Bits, Real};
    use penner::special::{lobachevsky as lob, lobachevsky_enclosure};
    if let Some(i) = x.iter().position(|v| !v.is_finite()) {
        return Err(InputError::new_err(format!(
            "x[{i}] = {}: not a finite number",
            x[i]
        )));
    }
    let bits = match precision.as_str() {
        "f64" => None,
        "dd" => Some(0),
        b => Some(
            b.parse::<u64>()
                .ok()
                .filter(|b| (53..=65536).contains(b))
                .ok_or_else(|| {
                    InputError::new_err(format!(
                        "precision: expected f64, dd or MPFR bits 53..=65536, got {b:?}"
                    ))
                })?,
        ),
    };
    let mpfr_bits =
        |b: u64| Bits::new(b).map_err(|e| InputError::new_err(format!("precision: {e}")));
    if enclosure {
        let p = mpfr_bits(bits.filter(|&b| b >= 53).unwrap_or(53))?;
        let out: Vec<f64> = py.detach(|| {
            x.iter()
                .flat_map(|&v| {
                    let y = lobachevsky_enclosure(&Interval::point(Mpfr::from_f64(v, p)));
                    let outward = |q: Option<Rational>, r: rug::float::Round, inf: f64| {
                        q.map_or(inf, |q| rug::Float::with_val_round(53, &q, r).0.to_f64())
                    };
                    [
                        outward(
                            y.lo().to_rational(),
                            rug::float::Round::Down,
                            f64::NEG_INFINITY,
                        ),
                        outward(y.hi().to_rational(), rug::float::Round::Up, f64::INFINITY),
                    ]
                })
                .collect()
        });
        return array2(py, out, 2);
    }
    let out: Vec<f64> = match bits {
        None => py.detach(|| x.iter().map(lob).collect()),
        Some(0) => py.detach(|| {
            x.iter()
                .map(|&v| lob(&Dd::from_f64(v)).approx_f64())
                .collect()
        }),
        Some(b) => {
            let p = mpfr_bits(b)?;
            py.detach(|| {
                x.iter()
                    .map(|&v| {
                        lob(&Mpfr::from_f64(v, p))
                            .to_rational()
                            .map_or(f64::NAN, |q| nearest_f64(&q))
                    })
                    .collect()
            })
        }
    };
    Ok(array1(py, out))
}

/// The extension module.
#[pymodule]
fn _penner(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("InputError", m.py().get_type::<InputError>())?;
    m.add_class::<PySurface>()?;
    m.add_function(wrap_pyfunction!(make_surface, m)?)?;
    m.add_function(wrap_pyfunction!(read, m)?)?;
    m.add_function(wrap_pyfunction!(catalogue, m)?)?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(uniformize, m)?)?;
    m.add_function(wrap_pyfunction!(certify, m)?)?;
    m.add_function(wrap_pyfunction!(delaunay::intrinsic_delaunay, m)?)?;
    m.add_function(wrap_pyfunction!(delaunay::pack, m)?)?;
    m.add_function(wrap_pyfunction!(lobachevsky, m)?)?;
    m.add_function(wrap_pyfunction!(uv::parametrize, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
