//! Writing the flipped surface of `penner delaunay`: compact surface JSON (a file or
//! standard output), or OBJ / OFF with an optional lengths file, streamed through a
//! buffer; every write error is an output error (exit code 4).

use super::error::CliError;
use super::files::{create_new, stdout_error};
use super::input::FlipCase;
pub use penner::algorithms::delaunay_pipeline::FlipValues;
use penner::io::write::{self, MetricKind};
use std::io::{BufWriter, Write};
use std::path::Path;

/// What `-o` asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Surface JSON (any name but `.obj` / `.off`, and standard output).
    Json,
    /// OBJ (`-o out.obj`).
    Obj,
    /// OFF (`-o out.off`).
    Off,
}

/// The output format from the `-o` extension; a lengths file goes with OBJ or OFF only.
pub fn format_of(output: Option<&Path>, lengths_out: Option<&Path>) -> Result<Format, CliError> {
    let ext = output
        .and_then(|p| p.extension())
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let format = match ext.as_deref() {
        Some("obj") => Format::Obj,
        Some("off") => Format::Off,
        _ => Format::Json,
    };
    if format == Format::Json && lengths_out.is_some() {
        return Err(CliError::Input(
            "--lengths-out goes with -o FILE.obj or -o FILE.off (surface JSON holds the lengths)"
                .to_string(),
        ));
    }
    Ok(format)
}

/// Stream `body` into a new file at `path` (never overwriting), or into standard output.
fn stream(
    path: Option<&Path>,
    body: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> Result<(), CliError> {
    if let Some(p) = path {
        let file = create_new(p)?;
        let mut w = BufWriter::with_capacity(1 << 20, file);
        body(&mut w)
            .and_then(|()| w.flush())
            .and_then(|()| w.get_ref().sync_all())
            .map_err(|e| CliError::Write {
                path: p.to_path_buf(),
                reason: e.to_string(),
            })
    } else {
        let mut w = BufWriter::with_capacity(1 << 20, std::io::stdout().lock());
        body(&mut w)
            .and_then(|()| w.flush())
            .map_err(|e| stdout_error(&e))
    }
}

/// Write the flipped surface `case` with `lengths` in `format` to `output` (standard
/// output when absent), and the lengths file when asked.
pub fn write_flipped(
    case: &FlipCase,
    lengths: &FlipValues,
    format: Format,
    output: Option<&Path>,
    lengths_out: Option<&Path>,
) -> Result<(), CliError> {
    let mesh = case.mesh();
    let values = lengths.values();
    if format == Format::Json {
        return stream(output, |w| {
            write::json::<String>(w, case.name(), mesh, MetricKind::Lengths, values, None)
        });
    }
    if !write::faces_determine_gluing(mesh) {
        return Err(CliError::Input(format!(
            "{}: the Delaunay triangulation has loops or repeated edges that OBJ/OFF faces cannot describe; write surface JSON (-o FILE.json)",
            case.name()
        )));
    }
    let off = format == Format::Off;
    match case {
        FlipCase::Decimal(s) => stream(output, |w| {
            if off {
                write::off(w, mesh, &s.positions)
            } else {
                write::obj(w, mesh, &s.positions)
            }
        })?,
        FlipCase::Exact(s) => {
            let Some(ps) = &s.positions else {
                return Err(CliError::Input(format!(
                    "{}: the surface has no vertex positions to write as OBJ/OFF; write surface JSON (-o FILE.json)",
                    case.name()
                )));
            };
            stream(output, |w| {
                if off {
                    write::off(w, mesh, ps)
                } else {
                    write::obj(w, mesh, ps)
                }
            })?;
        }
    }
    match lengths_out {
        Some(p) => stream(Some(p), |w| write::lengths(w, mesh, values)),
        None => Ok(()),
    }
}
