//! Loading a surface file (JSON, OBJ or OFF, by extension) into an [`io::Surface`].

use super::error::CliError;
use super::files::read_text;
use penner::io::{json, obj, off, Surface};
use std::path::Path;

/// Read the surface at `path` (size-limited, UTF-8 checked), choosing the reader by the
/// extension. Messages start with the path and name the line or element.
pub fn load_case(path: &Path) -> Result<Surface, CliError> {
    let shown = path.display().to_string();
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let reader: fn(&str) -> Result<Surface, penner::io::ReadError> = match ext.as_deref() {
        Some("json") => json::read,
        Some("obj") => obj::read,
        Some("off") => off::read,
        _ => {
            return Err(CliError::Input(format!(
                "{shown}: unknown surface format (expected a .json, .obj or .off file)"
            )))
        }
    };
    let text = read_text(path)?;
    let mut s = reader(&text).map_err(|e| CliError::Input(format!("{shown}: {e}")))?;
    if s.name.is_empty() {
        s.name = shown;
    }
    Ok(s)
}
