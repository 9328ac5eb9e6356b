//! Loading a surface file into a [`Case`].

use super::error::CliError;
use super::files::read_text;
use penner::oracle::surface::parse_surface;
use penner::oracle::Case;
use std::path::Path;

/// Read the surface at `path`.
pub fn load_case(path: &Path) -> Result<Case, CliError> {
    let text = read_text(path)?;
    let name = path.display().to_string();
    let v: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| CliError::Input(format!("{name}:{}:{}: {e}", e.line(), e.column())))?;
    parse_surface(&v, &name).map_err(|e| CliError::Input(format!("{name}: {e}")))
}
