//! Loading a surface file (JSON, OBJ or OFF, by extension) into an [`io::Surface`].

use super::error::CliError;
use super::files::read_text;
use penner::io::repair::{repair, Repairs};
use penner::io::soup::PolygonSoup;
pub use penner::io::FlipCase;
use penner::io::{json, obj, off, DecimalSurface, Metric, ReadError, Surface};
use std::path::Path;
use std::sync::OnceLock;

/// The repairs the command line asked for (set once, before any file is read).
static REPAIRS: OnceLock<Repairs> = OnceLock::new();

/// Record the repairs asked for on the command line.
pub fn set_repairs(r: Repairs) {
    let _ = REPAIRS.set(r);
}

fn repairs() -> Repairs {
    REPAIRS.get().copied().unwrap_or_default()
}

/// The flag that would repair what `e` refuses, as a hint for the message.
fn hint(e: &ReadError) -> &'static str {
    use penner::mesh::MeshError;
    match e {
        ReadError::NotTriangle { count, .. } if *count > 3 => {
            " (--triangulate splits polygon faces, and says how)"
        }
        ReadError::Mesh {
            source: MeshError::NonManifoldEdge { .. },
            ..
        } => " (if the surface is orientable, --orient reverses faces to one orientation)",
        ReadError::Mesh {
            source: MeshError::IsolatedVertex { .. },
            ..
        } => " (--drop-unreferenced removes vertices in no face)",
        _ => "",
    }
}

/// Read an OBJ/OFF text into the compact surface, applying the repairs asked for and
/// reporting them on standard error.
fn read_positions(
    shown: &str,
    text: &str,
    polygons: fn(&str) -> Result<PolygonSoup, ReadError>,
) -> Result<DecimalSurface, CliError> {
    let fail = |e: ReadError| CliError::Input(format!("{shown}: {e}{}", hint(&e)));
    let soup = polygons(text).map_err(fail)?;
    let asked = repairs();
    let soup = if asked.any() {
        let (soup, log) = repair(soup, &asked).map_err(fail)?;
        if !log.is_empty() {
            for line in log.to_string().lines() {
                eprintln!("penner: {shown}: repaired: {line}");
            }
        }
        soup
    } else {
        soup
    };
    soup.into_surface().map_err(fail)
}

/// Read the surface at `path` (size-limited, UTF-8 checked), choosing the reader by the
/// extension. Messages start with the path and name the line or element.
pub fn load_case(path: &Path) -> Result<Surface, CliError> {
    let shown = path.display().to_string();
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let polygons: fn(&str) -> Result<PolygonSoup, ReadError> = match ext.as_deref() {
        Some("json") => {
            let text = read_text(path)?;
            let mut s = json::read(&text).map_err(|e| CliError::Input(format!("{shown}: {e}")))?;
            if s.name.is_empty() {
                s.name = shown;
            }
            return Ok(s);
        }
        Some("obj") => obj::read_polygons,
        Some("off") => off::read_polygons,
        _ => {
            return Err(CliError::Input(format!(
                "{shown}: unknown surface format (expected a .json, .obj or .off file)"
            )))
        }
    };
    let text = read_text(path)?;
    let mut s = read_positions(&shown, &text, polygons)?.into_surface();
    if s.name.is_empty() {
        s.name = shown;
    }
    Ok(s)
}

/// Read the surface at `path` for flipping: OBJ and OFF into the compact form, JSON as in
/// [`load_case`].
pub fn load_flip_case(path: &Path) -> Result<FlipCase, CliError> {
    let shown = path.display().to_string();
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let polygons: fn(&str) -> Result<PolygonSoup, ReadError> = match ext.as_deref() {
        Some("obj") => obj::read_polygons,
        Some("off") => off::read_polygons,
        _ => return load_case(path).map(FlipCase::Exact),
    };
    let text = read_text(path)?;
    let mut s = read_positions(&shown, &text, polygons)?;
    drop(text);
    if s.name.is_empty() {
        s.name = shown;
    }
    Ok(FlipCase::Decimal(s))
}

/// `case` with its metric replaced by the lengths file at `path` (a JSON array in the edge
/// order of surface JSON, `penner::io::write::read_lengths`), validated; messages name the
/// lengths file and the entry or face.
pub fn with_lengths(case: Surface, path: &Path) -> Result<Surface, CliError> {
    let shown = path.display().to_string();
    let text = read_text(path)?;
    let lengths = penner::io::write::read_lengths(&text, &case.mesh)
        .map_err(|e| CliError::Input(format!("{shown}: {e}")))?;
    Surface::new(
        case.name,
        case.mesh,
        Metric::Lengths(lengths),
        case.positions,
    )
    .map_err(|e| CliError::Input(format!("{shown}: {e}")))
}
