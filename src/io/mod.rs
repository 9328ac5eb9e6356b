//! Surface files: the penner JSON surface format (any Δ-complex, exact lengths), OBJ and
//! OFF (exact decimal coordinates), into a [`Surface`]. Format reference:
//! `docs/surface-format.md`.
//!
//! Every reader returns a typed [`ReadError`] naming the line (OBJ, OFF, JSON syntax) or
//! the element (JSON paths such as `lengths[3]`, faces, edges) and never panics, whatever
//! the bytes.
//!
//! ```
//! use penner::io::{json, Metric};
//! let s = json::read(r#"{"vertices": 3, "faces": [[0,1,2],[0,2,1]],
//!                        "lengths": ["1", "3/2", "1.25"]}"#).unwrap();
//! assert_eq!(s.mesh.euler_characteristic(), 2);
//! assert!(matches!(s.metric, Metric::Lengths(_)));
//! assert!(json::read(r#"{"vertices": 3, "faces": [[0,1,2],[0,2,1]],
//!                        "lengths": ["1", "1", "2"]}"#).is_err()); // degenerate
//! ```

pub mod decimal;
pub mod decimal_surface;
mod flip_case;
pub mod json;
pub mod obj;
pub mod off;
pub mod repair;
pub mod soup;
pub mod strict_json;
pub mod surface;
pub mod svg;
mod text;
pub mod write;

pub use decimal_surface::DecimalSurface;
pub use flip_case::FlipCase;
pub use surface::{Metric, MetricError, Surface};

use crate::mesh::MeshError;
use crate::scalar::NumberError;
use std::path::Path;

/// Why a surface file was refused.
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    /// The file could not be read.
    #[error("cannot read {path}: {message}")]
    File {
        /// The path.
        path: String,
        /// The operating system's message.
        message: String,
    },
    /// The path is not a regular file (a directory, a FIFO, a device, a socket): refused
    /// before it is opened, since reading a FIFO or a device may block or never end.
    #[error("{path} is {kind}, not a regular file")]
    NotAFile {
        /// The path.
        path: String,
        /// What it is (`a directory`, `a FIFO`, …).
        kind: &'static str,
    },
    /// The bytes are not UTF-8 text (binary data).
    #[error("not UTF-8 text: invalid byte at offset {offset}")]
    NotText {
        /// Byte offset of the first invalid byte.
        offset: usize,
    },
    /// The file name has no known extension.
    #[error("unknown surface format for {path} (expected .json, .obj or .off)")]
    UnknownFormat {
        /// The path.
        path: String,
    },
    /// Malformed syntax at a line.
    #[error("line {line}: {message}")]
    Syntax {
        /// 1-based line.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// A JSON object with a repeated key (readers disagree on which value counts, so
    /// none is chosen: [`strict_json`]).
    #[error("{0}")]
    DuplicateKey(strict_json::DuplicateKey),
    /// A JSON document with the wrong shape (a missing field, a wrong type, …).
    #[error("{element}: {message}")]
    Schema {
        /// JSON path of the element, such as `faces[3][1]`.
        element: String,
        /// What is wrong.
        message: String,
    },
    /// A number that is not an exact finite literal.
    #[error("{element}: {source}")]
    Number {
        /// Line (`line 12`) or JSON path (`lengths[3]`).
        element: String,
        /// The parse error.
        source: NumberError,
    },
    /// The file ended before an element the header or syntax requires.
    #[error("line {line}: file ends early, expected {expected}")]
    Truncated {
        /// 1-based line where the file ended.
        line: usize,
        /// What was still expected.
        expected: String,
    },
    /// A count in a header is larger than the file could hold.
    #[error("header declares {count} {what}, but the file is too short to hold them")]
    HugeCount {
        /// What is counted (vertices, faces).
        what: &'static str,
        /// The declared count.
        count: u64,
    },
    /// A vertex index outside the vertex list.
    #[error("{element}: vertex index {index} is out of range ({n_vertices} vertices)")]
    IndexOutOfRange {
        /// Line or JSON path.
        element: String,
        /// The index as written.
        index: i64,
        /// Number of vertices.
        n_vertices: usize,
    },
    /// A face with other than three corners (only triangles are accepted: no
    /// triangulation is invented).
    #[error("{element}: face with {count} corners; only triangles are accepted")]
    NotTriangle {
        /// Line or JSON path.
        element: String,
        /// Number of corners.
        count: usize,
    },
    /// A repair that was asked for cannot be made (a polygon with no valid triangulation,
    /// a non-orientable surface asked to be oriented).
    #[error("{element}: {message}")]
    CannotRepair {
        /// The line of the face concerned.
        element: String,
        /// What stands in the way.
        message: String,
    },
    /// The connectivity is not an oriented surface (non-manifold, inconsistent or
    /// non-orientable gluing, isolated vertex, …); `element` names the face's line or
    /// path when the error concerns one face.
    #[error("{element}: {source}")]
    Mesh {
        /// Where (a line, a JSON path, or `surface`).
        element: String,
        /// The connectivity error.
        source: MeshError,
    },
    /// The metric is not a valid discrete metric (non-positive length, triangle
    /// inequality, glued sides with different lengths).
    #[error("{element}: {source}")]
    Metric {
        /// Where (a JSON path, or `surface`).
        element: String,
        /// The metric error.
        source: MetricError,
    },
    /// Two glued face sides carry different lengths.
    #[error("{element}: glued sides (f{face_a}, s{side_a}) and (f{face_b}, s{side_b}) have lengths {a} and {b}")]
    GluedUnequal {
        /// JSON path.
        element: String,
        /// First side's face.
        face_a: u32,
        /// First side's index.
        side_a: u8,
        /// Second side's face.
        face_b: u32,
        /// Second side's index.
        side_b: u8,
        /// First length.
        a: String,
        /// Second length.
        b: String,
    },
}

/// Text from bytes, refusing binary data with the offset of the first invalid byte.
pub fn text_of(bytes: &[u8]) -> Result<&str, ReadError> {
    std::str::from_utf8(bytes).map_err(|e| ReadError::NotText {
        offset: e.valid_up_to(),
    })
}

/// Read a surface file, choosing the format by extension (`.json`, `.obj`, `.off`, any
/// case). The surface is named after the file.
pub fn read_path(path: &Path) -> Result<Surface, ReadError> {
    let shown = path.display().to_string();
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let reader: fn(&[u8]) -> Result<Surface, ReadError> = match ext.as_deref() {
        Some("json") => json::read_bytes,
        Some("obj") => obj::read_bytes,
        Some("off") => off::read_bytes,
        _ => return Err(ReadError::UnknownFormat { path: shown }),
    };
    regular_file(path)?;
    let bytes = std::fs::read(path).map_err(|e| ReadError::File {
        path: shown.clone(),
        message: e.to_string(),
    })?;
    let mut s = reader(&bytes)?;
    if s.name.is_empty() {
        s.name = shown;
    }
    Ok(s)
}

/// Refuse a path that is not a regular file (after following symbolic links) without
/// opening it: opening a FIFO blocks until a writer appears, and a device may never end.
pub fn regular_file(path: &Path) -> Result<(), ReadError> {
    let shown = || path.display().to_string();
    let meta = std::fs::metadata(path).map_err(|e| ReadError::File {
        path: shown(),
        message: e.to_string(),
    })?;
    if meta.is_file() {
        return Ok(());
    }
    let kind = if meta.is_dir() {
        "a directory"
    } else {
        file_kind(&meta)
    };
    Err(ReadError::NotAFile {
        path: shown(),
        kind,
    })
}

#[cfg(unix)]
fn file_kind(meta: &std::fs::Metadata) -> &'static str {
    use std::os::unix::fs::FileTypeExt;
    let t = meta.file_type();
    if t.is_fifo() {
        "a FIFO"
    } else if t.is_char_device() || t.is_block_device() {
        "a device"
    } else if t.is_socket() {
        "a socket"
    } else {
        "not a regular file"
    }
}

#[cfg(not(unix))]
fn file_kind(_: &std::fs::Metadata) -> &'static str {
    "a special file"
}
