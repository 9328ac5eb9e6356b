//! `penner.parametrize`: texture coordinates on the input mesh (the common refinement of
//! the input and the final triangulation, `uniformization::pipeline::{uv_closed,
//! uv_boundary}`), with the exact checks of its written text (`check_written_uv`: B109,
//! B110).

use crate::convert::{array1, array2, array3, json_to_py};
use crate::{parse_targets, InputError, PySurface};
use penner::overlay::UvMesh;
use penner::uniformization::boundary::flat_with_even_boundary;
use penner::uniformization::pipeline::{
    check_written_uv, uniformize_boundary, uniformize_closed, uv_boundary, uv_closed, Options,
    PipelineError, Precision, UvCones,
};
use penner::uniformization::Targets;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rug::Rational;
use std::sync::Arc;

/// What the solve and the UV mesh gave: the mesh, or why there is none, and its cones.
struct Done {
    uv: Option<UvMesh>,
    reason: Option<String>,
    cones: UvCones,
}

/// Solve (binary64, no certificate) and build the UV mesh; `Err` is the input's fault.
fn compute(s: &penner::io::Surface, targets: Option<Targets>) -> Result<Done, String> {
    let options = Options {
        precision: Precision::F64,
        certify: false,
    };
    let (uv, cones): (Result<UvMesh, PipelineError>, UvCones) = if s.mesh.is_closed() {
        let t = targets.unwrap_or_else(|| Targets::flat(s.mesh.n_vertices()));
        let out = uniformize_closed(s, &t, &options, &mut |_| {}).map_err(|e| e.to_string())?;
        (uv_closed(s, &out), UvCones::of_closed(&out))
    } else {
        let t = targets.unwrap_or_else(|| flat_with_even_boundary(&s.mesh));
        let out = uniformize_boundary(s, Some(&t), &options).map_err(|e| e.to_string())?;
        (uv_boundary(s, &out), UvCones::of_boundary(&out))
    };
    match uv {
        Ok(uv) => Ok(Done {
            uv: Some(uv),
            reason: None,
            cones,
        }),
        Err(e) if e.is_bad_input() => Err(e.to_string()),
        Err(e) => Ok(Done {
            uv: None,
            reason: Some(e.to_string()),
            cones,
        }),
    }
}

/// The UV mesh of a surface with vertex positions, for flat or cone targets (closed) or
/// interior cone angles and boundary angle sums (with boundary, copy 1 of the double): a
/// dict with the refinement's positions `V`, triangles `F`, per-corner `uv`, each
/// triangle's `input_face` and `final_face`, the barycentric coordinates of its corners in
/// its input face, the OBJ text and sidecar, and the exact checks of that text (`holds`,
/// folds, untiled input faces, and the seams when every cone angle is a multiple of π/2).
#[pyfunction]
#[pyo3(signature = (surface, targets=None, flat=false))]
pub fn parametrize<'py>(
    py: Python<'py>,
    surface: &PySurface,
    targets: Option<Vec<String>>,
    flat: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let s = Arc::clone(&surface.inner);
    let n = s.mesh.n_vertices();
    let parsed = parse_targets(targets, flat, n)?;
    if parsed.is_none() && !flat {
        return Err(InputError::new_err(
            "the target angles are required: targets (Θ_i/π, one per vertex; with boundary φ_v/π at boundary vertices) or flat=True",
        ));
    }
    let surface = Arc::clone(&s);
    let done = py
        .detach(move || compute(&surface, parsed))
        .map_err(InputError::new_err)?;
    let d = PyDict::new(py);
    d.set_item("reason", done.reason.clone())?;
    let Some(uv) = done.uv else {
        for k in [
            "V",
            "F",
            "uv",
            "input_face",
            "final_face",
            "barycentric",
            "obj",
            "sidecar",
            "checks",
        ] {
            d.set_item(k, py.None())?;
        }
        return Ok(d.into_any());
    };
    let obj = uv.obj();
    let sidecar = uv.sidecar();
    let eps = Rational::from((1, 1_000_000_000u32));
    let text = uv
        .sidecar_text()
        .map_err(|e| InputError::new_err(format!("the UV sidecar: {e}")))?;
    let checked = check_written_uv(&obj, &text, &done.cones, &eps)
        .map_err(|e| InputError::new_err(format!("the written UV mesh does not read back: {e}")))?;
    let report = &checked.parametrization;
    let checks = PyDict::new(py);
    checks.set_item("holds", report.holds())?;
    checks.set_item("triangles", report.triangles)?;
    checks.set_item("uv_folds", report.uv_folds.clone())?;
    checks.set_item("input_folds", report.input_folds.clone())?;
    checks.set_item("untiled_faces", report.untiled_faces.clone())?;
    checks.set_item(
        "seam_segments",
        checked.seams.as_ref().map(|r| r.seam_segments),
    )?;
    checks.set_item(
        "broken_seams",
        checked.seams.as_ref().map(|r| r.broken.clone()),
    )?;
    let tris = &uv.refinement.triangles;
    let faces: Vec<i64> = tris
        .iter()
        .flat_map(|t| t.vertices.map(i64::from))
        .collect();
    let bary: Vec<f64> = uv
        .barycentric
        .iter()
        .flat_map(|corners| {
            corners.iter().flat_map(|&(r, sigma)| {
                let mut row = [0.0; 3];
                row[r] = 1.0 - sigma;
                row[(r + 1) % 3] += sigma;
                row
            })
        })
        .collect();
    d.set_item(
        "V",
        array2(py, uv.positions.iter().flatten().copied().collect(), 3)?,
    )?;
    d.set_item("F", array2(py, faces, 3)?)?;
    d.set_item(
        "uv",
        array3(
            py,
            uv.uv.iter().flatten().flatten().copied().collect(),
            3,
            2,
        )?,
    )?;
    d.set_item(
        "input_face",
        array1(py, tris.iter().map(|t| i64::from(t.input_face.0)).collect()),
    )?;
    d.set_item(
        "final_face",
        array1(py, tris.iter().map(|t| i64::from(t.final_face.0)).collect()),
    )?;
    d.set_item("barycentric", array3(py, bary, 3, 3)?)?;
    d.set_item("obj", obj)?;
    d.set_item("sidecar", json_to_py(py, &sidecar)?)?;
    d.set_item("checks", checks)?;
    Ok(d.into_any())
}
