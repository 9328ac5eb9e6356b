//! The claim kind `parametrization` (protocol v1, docs/oracle.md): a UV mesh written by
//! `penner uniformize … --uv` (or any OBJ with `vt` per corner and the same sidecar) is a
//! parametrization of the claim's surface. Re-checked from the files alone by the exact
//! checks of [`super::check`] (B109) and, when the claim asks for it, [`super::seams`]
//! (B110). Every check is exact on the written decimals, so a failure is proven: the
//! answer is `holds` or `refuted`, never undecided; a file that cannot be read is a
//! typed error naming its line or element.

use super::check::{check_parametrization, ParametrizationError};
use super::seams::check_seams;
use crate::io::Surface;
use rug::Rational;
use serde_json::Value;

/// A `parametrization` claim: the OBJ text, its sidecar, and the seam requirement.
#[derive(Clone, Debug, PartialEq)]
pub struct ParametrizationClaim {
    /// The OBJ text (`v`, `vt` per corner, `f v/vt`).
    pub obj: String,
    /// The sidecar (`input_faces`, and per `f` line its `input_face` and `barycentric`).
    pub sidecar: Value,
    /// When present, every seam is also claimed to be a rotation by a multiple of π/2
    /// plus a translation, within this relative tolerance.
    pub seam_epsilon: Option<Rational>,
}

/// One proven failure: the element (an `f` line or an input face) and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Failure {
    /// `face k` (0-based `f` line) or `input face f`.
    pub element: String,
    /// What fails there.
    pub detail: String,
}

/// The outcome of the re-check.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ParametrizationVerdict {
    /// Every check passes exactly.
    Holds {
        /// Triangles checked.
        triangles: usize,
        /// Seam segments checked (0 without a seam requirement).
        seam_segments: usize,
    },
    /// Every failure found, each proven on the given files.
    Refuted(Vec<Failure>),
}

/// Refuse files that do not fit `surface`: the sidecar's `input_faces` must be the
/// surface's face count and every `input_face` one of its faces.
fn fits(surface: &Surface, c: &ParametrizationClaim) -> Result<(), ParametrizationError> {
    let side = |m: String| ParametrizationError::Sidecar(m);
    let n = surface.mesh.n_faces() as u64;
    match c.sidecar["input_faces"].as_u64() {
        Some(k) if k == n => {}
        Some(k) => {
            return Err(side(format!(
                "input_faces: {k}, but the surface has {n} faces"
            )))
        }
        None => return Err(side("input_faces: required, the input face count".into())),
    }
    if let Some(faces) = c.sidecar["faces"].as_array() {
        for (k, f) in faces.iter().enumerate() {
            if let Some(i) = f["input_face"].as_u64().filter(|&i| i >= n) {
                return Err(side(format!(
                    "faces[{k}].input_face: {i}, but the surface has {n} faces"
                )));
            }
        }
    }
    Ok(())
}

/// Read the files of `c` and check them exactly against `surface` (module documentation).
pub fn recheck(
    surface: &Surface,
    c: &ParametrizationClaim,
) -> Result<ParametrizationVerdict, ParametrizationError> {
    fits(surface, c)?;
    let report = check_parametrization(&c.obj, &c.sidecar)?;
    let seams = match &c.seam_epsilon {
        Some(eps) => Some(check_seams(&c.obj, eps)?),
        None => None,
    };
    let mut failures: Vec<Failure> = Vec::new();
    let mut push = |element: String, detail: &str| {
        failures.push(Failure {
            element,
            detail: detail.to_string(),
        });
    };
    for &k in &report.uv_folds {
        push(
            format!("face {k}"),
            "UV triangle not counterclockwise (folded or degenerate)",
        );
    }
    for &k in &report.input_folds {
        push(
            format!("face {k}"),
            "barycentric triangle in its input face not counterclockwise",
        );
    }
    for &f in &report.untiled_faces {
        push(
            format!("input face {f}"),
            "not tiled: its triangles' barycentric areas do not sum to 1, or a barycentric row does not sum to 1",
        );
    }
    if let Some(s) = &seams {
        for &k in &s.broken {
            push(
                format!("face {k}"),
                "seam segment: the transition is no rotation by a multiple of π/2 plus a translation within ε",
            );
        }
    }
    Ok(if failures.is_empty() {
        ParametrizationVerdict::Holds {
            triangles: report.triangles,
            seam_segments: seams.map_or(0, |s| s.seam_segments),
        }
    } else {
        ParametrizationVerdict::Refuted(failures)
    })
}

/// Refuse files that cannot be read or do not fit `surface` (the error names the OBJ line
/// or the sidecar element). Reads the files as [`recheck`] does, so a claim parsed after
/// this check is answered without error.
pub fn validate(surface: &Surface, c: &ParametrizationClaim) -> Result<(), ParametrizationError> {
    recheck(surface, c).map(|_| ())
}
