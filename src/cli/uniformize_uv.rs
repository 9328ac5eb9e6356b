//! `penner uniformize … --uv OUT.obj` for flat and cone targets: the common refinement of
//! the input mesh and the final triangulation with texture coordinates
//! (`uniformization::pipeline::uv_closed`, or `uv_boundary` on copy 1 of the double of a
//! surface with boundary), written with its sidecar `OUT.obj.json`, both
//! new files; the exact checks (`check_written_uv`) run on the written text.

use super::error::{pipeline_error, CliError};
use super::files::create_new;
use penner::io::Surface;
use penner::overlay::{render_uv_svg, SeamReport, UvMesh};
use penner::uniformization::pipeline::{
    check_written_uv, uv_boundary, uv_closed, BoundaryOutcome, ClosedOutcome, PipelineError,
    UvCones,
};
use rug::Rational;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};

/// The sidecar's path: `OUT.obj.json`.
fn sidecar_path(path: &Path) -> PathBuf {
    let mut s = path.as_os_str().to_owned();
    s.push(".json");
    PathBuf::from(s)
}

/// Refuse `--uv OUT.obj [--uv-svg PIC.svg]` before the solve when OUT.obj, OUT.obj.json or
/// PIC.svg exists (exit 4, as the file creation would refuse after it); the creation still
/// refuses a file made since.
pub fn refuse_existing(path: &Path, svg: Option<&Path>) -> Result<(), CliError> {
    let mut paths = vec![path.to_path_buf(), sidecar_path(path)];
    paths.extend(svg.map(Path::to_path_buf));
    for p in paths {
        if p.exists() {
            return Err(CliError::Write {
                path: p,
                reason: "the file exists (penner never overwrites a file; choose another name)"
                    .to_string(),
            });
        }
    }
    Ok(())
}

fn write_all(path: &Path, mut f: std::fs::File, bytes: &[u8]) -> Result<(), CliError> {
    f.write_all(bytes)
        .and_then(|()| f.flush())
        .map_err(|e| CliError::Write {
            path: path.to_path_buf(),
            reason: e.to_string(),
        })
}

/// The UV mesh or why the pipeline did not compute it, with its cones.
pub struct UvSource {
    /// The UV mesh, or why the pipeline did not compute it.
    pub uv: Result<UvMesh, PipelineError>,
    /// Its cones and whether its seams are checked.
    pub cones: UvCones,
}

/// The UV source of a closed-surface outcome ([`uv_closed`]).
pub fn closed(surface: &Surface, outcome: &ClosedOutcome) -> UvSource {
    UvSource {
        uv: uv_closed(surface, outcome),
        cones: UvCones::of_closed(outcome),
    }
}

/// The UV source of a surface with boundary ([`uv_boundary`], copy 1 of the double).
pub fn boundary(surface: &Surface, outcome: &BoundaryOutcome) -> UvSource {
    UvSource {
        uv: uv_boundary(surface, outcome),
        cones: UvCones::of_boundary(outcome),
    }
}

/// Write and check the UV mesh of `source`; the lines to report and whether the files were
/// written. Bad input is an error; a UV mesh penner could not compute (e.g. a Klein
/// crossing lost to rounding, B111) is a line, so the solve and its certificate are still
/// reported (the command then exits 2).
pub fn write(
    path: &Path,
    svg: Option<&Path>,
    shown: &str,
    source: UvSource,
) -> Result<(String, bool), CliError> {
    let uv = match source.uv {
        Ok(uv) => uv,
        Err(e) if e.is_bad_input() => return Err(pipeline_error(shown, &e)),
        Err(e) => return Ok((format!("{shown}: {e}; no UV mesh written\n"), false)),
    };
    let obj = uv.obj();
    let text = uv
        .sidecar_text()
        .map_err(|e| CliError::NotConverged(format!("{shown}: the UV sidecar: {e}")))?;
    let side_path = sidecar_path(path);
    // Both files are created before either is written: neither overwrites a file.
    let f_obj = create_new(path)?;
    let f_side = match create_new(&side_path) {
        Ok(f) => f,
        Err(e) => {
            drop(f_obj);
            let _ = std::fs::remove_file(path);
            return Err(e);
        }
    };
    write_all(path, f_obj, obj.as_bytes())?;
    write_all(&side_path, f_side, text.as_bytes())?;
    let eps = Rational::from((1, 1_000_000_000u32));
    let checks = check_written_uv(&obj, &text, &source.cones, &eps)
        .map_err(|e| CliError::NotConverged(format!("{}: {e}", path.display())))?;
    let report = &checks.parametrization;
    let mut out = format!(
        "UV mesh written to {} and {} ({} vertices, {} triangles)\n",
        path.display(),
        side_path.display(),
        uv.positions.len(),
        report.triangles
    );
    let first = |v: &[usize]| {
        v.iter()
            .take(5)
            .map(|f| format!("f{f}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    if report.holds() {
        out.push_str("exact checks on the written decimals: every UV triangle counterclockwise, every input face tiled (barycentric areas sum to 1 in ℚ)\n");
    } else {
        let _ = writeln!(
            out,
            "exact checks on the written decimals FAIL: {} UV folds ({}), {} folds in the input faces ({}), {} input faces not tiled",
            report.uv_folds.len(),
            first(&report.uv_folds),
            report.input_folds.len(),
            first(&report.input_folds),
            report.untiled_faces.len()
        );
    }
    out.push_str(&seams_line(checks.seams.as_ref()));
    if let Some(svg) = svg {
        super::files::write_new(svg, render_uv_svg(&uv, &source.cones.cones).as_bytes())?;
        let _ = writeln!(out, "UV layout drawn to {}", svg.display());
    }
    Ok((out, true))
}

/// The seam check's line (B110): `None` when not every cone angle is a multiple of π/2.
fn seams_line(seams: Option<&SeamReport>) -> String {
    let Some(r) = seams else {
        return "seams not checked: not every cone angle is a multiple of π/2\n".into();
    };
    if r.broken.is_empty() {
        format!(
            "seams: all {} cut segments related by rotations by multiples of π/2 and translations, within relative ε = 1e-9 (exact check)\n",
            r.seam_segments
        )
    } else {
        format!(
            "seams: {} of {} cut segments are not rotations by multiples of π/2 within relative ε = 1e-9 (first at f{}; on genus ≥ 1 the handles' holonomy is not fixed by the cone angles; segments far shorter than the layout are below the resolution of its binary64 coordinates)\n",
            r.broken.len(),
            r.seam_segments,
            r.broken[0]
        )
    }
}
