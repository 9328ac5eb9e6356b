//! `penner.intrinsic_delaunay` and `penner.pack`: the flips to the intrinsic Delaunay
//! triangulation ([`intrinsic_delaunay`]) and the maximal circle packing ([`pack_maximal`]),
//! each one library call without the GIL.

use crate::convert::{array1, array2, json_to_py};
use crate::input::{self, InputError as BadInput};
use crate::{faces_array, InputError, PySurface};
use numpy::{PyReadonlyArrayDyn, PyUntypedArrayMethods};
use penner::algorithms::delaunay_pipeline::{
    intrinsic_delaunay as flip, DelaunayOptions, FlipValues,
};
use penner::algorithms::flip_to_delaunay::{FlipCounter, FlipKind};
use penner::circles::maximal::pipeline::{pack_maximal, PackError, PackOptions};
use penner::circles::maximal::tangency::PackingVerdict;
use penner::io::FlipCase;
use penner::scalar::{nearest_f64, parse_rational};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::sync::Arc;

/// Flip the surface to its intrinsic Delaunay triangulation with `flips` (`euclidean` or
/// `ptolemy`) at `precision` (`f64`, `dd`, MPFR bits, `exact`): `(F_out, l_out, info)`,
/// `l_out[f, i]` the side opposite corner `i`, `info` the flips, the certificate and the
/// summary of `penner delaunay --summary`.
#[pyfunction]
#[pyo3(signature = (surface, flips="euclidean".to_string(), precision="f64".to_string(), replay=true))]
pub fn intrinsic_delaunay<'py>(
    py: Python<'py>,
    surface: &PySurface,
    flips: String,
    precision: String,
    replay: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let kind = match flips.as_str() {
        "euclidean" => FlipKind::Euclidean,
        "ptolemy" => FlipKind::Ptolemy,
        other => {
            return Err(InputError::new_err(format!(
                "flips: expected \"euclidean\" or \"ptolemy\", got {other:?}"
            )))
        }
    };
    let precs = penner::scalar::prec::parse_list(&precision)
        .map_err(|e| InputError::new_err(format!("precision: {e}")))?;
    let [prec] = precs[..] else {
        return Err(InputError::new_err(format!(
            "precision: give one precision (f64, dd, exact or MPFR bits), got {precision:?}"
        )));
    };
    let s = Arc::clone(&surface.inner);
    let done = py.detach(move || {
        let mut case = FlipCase::Exact((*s).clone());
        let options = DelaunayOptions {
            kind,
            precision: prec,
            scale_factors: None,
            replay_on_input: replay,
            counter: FlipCounter::default(),
        };
        flip(&mut case, &options)
            .map(|out| (case, out))
            .map_err(|e| e.to_string())
    });
    let (case, out) = done.map_err(InputError::new_err)?;
    let mesh = case.mesh();
    let lengths: Vec<f64> = match &out.lengths {
        FlipValues::Binary64(v) => v.clone(),
        FlipValues::Exact(v) => v.iter().map(nearest_f64).collect(),
    };
    let info = PyDict::new(py);
    info.set_item("flips", out.report.flips)?;
    info.set_item("certificate", out.certificate.name())?;
    info.set_item("holds", out.holds())?;
    info.set_item("words", out.words())?;
    info.set_item("summary", json_to_py(py, &out.summary())?)?;
    info.set_item(
        "flip_sequence",
        array1(
            py,
            out.report
                .sequence
                .iter()
                .map(|e| e.idx() as i64)
                .collect::<Vec<_>>(),
        ),
    )?;
    let f = faces_array(py, mesh)?;
    let l = array2(py, input::per_face(mesh, &lengths), 3)?;
    Ok((f, l, info).into_pyobject(py)?.into_any())
}

/// Pack the triangulation `f` (faces only) maximally: in the unit disk (`sphere` false,
/// a disk) or on the sphere punctured at `puncture` (a sphere), at MPFR `bits`, tangency
/// certified within `epsilon`: a dict.
#[pyfunction]
#[pyo3(signature = (f, sphere=false, puncture=0, bits=128, epsilon="1e-20".to_string(), name="array".to_string()))]
pub fn pack<'py>(
    py: Python<'py>,
    f: PyReadonlyArrayDyn<'_, i64>,
    sphere: bool,
    puncture: usize,
    bits: u32,
    epsilon: String,
    name: String,
) -> PyResult<Bound<'py, PyAny>> {
    if f.shape().len() != 2 || f.shape()[1] != 3 {
        return Err(InputError::new_err(format!(
            "F has shape {:?}: expected (rows, 3)",
            f.shape()
        )));
    }
    let faces: Vec<i64> = f.as_array().iter().copied().collect();
    let eps = parse_rational(&epsilon).map_err(|e| InputError::new_err(format!("epsilon: {e}")))?;
    if !(53..=4096).contains(&bits) {
        return Err(InputError::new_err(format!(
            "bits: expected 53..=4096, got {bits}"
        )));
    }
    let options = PackOptions {
        sphere,
        puncture,
        bits,
        epsilon: eps,
    };
    let done = py.detach(|| -> Result<_, BadInput> {
        let mesh = input::mesh_of_faces(&faces)?;
        let out = pack_maximal(&mesh, &name, &options);
        Ok((mesh, out))
    });
    let (mesh, out) = done?;
    let n = mesh.n_vertices();
    let d = PyDict::new(py);
    d.set_item("mode", if sphere { "sphere" } else { "disk" })?;
    let out = match out {
        Ok(o) => o,
        Err(PackError::Input(e)) => return Err(InputError::new_err(e)),
        Err(PackError::NotComputed(reason)) => {
            not_computed(&d, &mesh, sphere, &reason, bits)?;
            return Ok(d.into_any());
        }
    };
    // Disk vertex w is vertex w of the surface, or w + 1 past the puncture of a sphere.
    let vertex = |w: usize| if sphere && w >= puncture { w + 1 } else { w };
    let mut centres = vec![f64::NAN; 2 * n];
    let mut radii = vec![f64::NAN; n];
    let mut unit = vec![false; n];
    for (w, c) in out.circles.iter().enumerate() {
        let v = vertex(w);
        if v < n {
            centres[2 * v] = nearest_f64(&c.centre[0]);
            centres[2 * v + 1] = nearest_f64(&c.centre[1]);
            radii[v] = nearest_f64(&c.radius);
            unit[v] = out.unit_disk.get(w).copied().unwrap_or(false);
        }
    }
    let disk_faces: Vec<i64> = out
        .disk
        .mesh
        .face_list()
        .iter()
        .flat_map(|t| t.map(|w| vertex(w as usize) as i64))
        .collect();
    d.set_item("centres", array2(py, centres, 2)?)?;
    d.set_item("radii", array1(py, radii))?;
    d.set_item("unit_disk", array1(py, unit))?;
    d.set_item("faces", array2(py, disk_faces, 3)?)?;
    if let Some(caps) = &out.caps {
        let flat: Vec<f64> = caps
            .iter()
            .flat_map(|c| {
                [
                    nearest_f64(&c.normal[0]),
                    nearest_f64(&c.normal[1]),
                    nearest_f64(&c.normal[2]),
                    nearest_f64(&c.height),
                ]
            })
            .collect();
        d.set_item("caps", array2(py, flat, 4)?)?;
    }
    let (word, reason, defect) = match &out.verdict {
        PackingVerdict::Holds { max_defect } => ("holds", None, Some(*max_defect)),
        PackingVerdict::Fails(w) => ("fails", Some(w.join("; ")), None),
        PackingVerdict::Undecided(w) => ("undecided", Some(w.join("; ")), None),
    };
    d.set_item("certified", word == "holds")?;
    d.set_item("verdict", word)?;
    d.set_item("reason", reason)?;
    d.set_item("max_defect", defect)?;
    d.set_item("bits", out.bits)?;
    d.set_item(
        "document",
        json_to_py(py, &out.document(&options, &epsilon))?,
    )?;
    Ok(d.into_any())
}

/// The result of valid input the packing does not reach: undecided, with the reason, the
/// arrays NaN.
fn not_computed(
    d: &Bound<'_, PyDict>,
    mesh: &penner::mesh::Mesh,
    sphere: bool,
    reason: &str,
    bits: u32,
) -> PyResult<()> {
    let py = d.py();
    let n = mesh.n_vertices();
    d.set_item("centres", array2(py, vec![f64::NAN; 2 * n], 2)?)?;
    d.set_item("radii", array1(py, vec![f64::NAN; n]))?;
    d.set_item("unit_disk", array1(py, vec![false; n]))?;
    d.set_item("faces", faces_array(py, mesh)?)?;
    if sphere {
        d.set_item("caps", array2(py, vec![f64::NAN; 4 * n], 4)?)?;
    }
    d.set_item("certified", false)?;
    d.set_item("verdict", "undecided")?;
    d.set_item("reason", reason)?;
    d.set_item("max_defect", py.None())?;
    d.set_item("bits", bits)?;
    d.set_item("document", py.None())?;
    Ok(())
}
