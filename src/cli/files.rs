//! Reading inputs and writing outputs: size limits, text decoding, never overwriting.

use super::error::CliError;
use std::fs::OpenOptions;
use std::io::{ErrorKind, Read, Write};
use std::path::{Path, PathBuf};

/// Largest input file read (bytes). Larger files are refused before reading, so a huge
/// or endless input cannot exhaust memory.
pub const MAX_INPUT_BYTES: u64 = 256 << 20;

/// Largest surface JSON file read that starts as penner writes them
/// ([`penner::io::write::JSON_MARKER`]): penner's own output of a large mesh at high
/// precision exceeds [`MAX_INPUT_BYTES`] and must read back.
pub const MAX_PENNER_JSON_BYTES: u64 = 4 << 30;

/// Read a text file (or standard input for `-`), refusing what is not a regular file
/// (before opening it), files over [`MAX_INPUT_BYTES`] ([`MAX_PENNER_JSON_BYTES`] for
/// surface JSON as penner writes it) and bytes that are not UTF-8 (naming the line).
pub fn read_text(path: &Path) -> Result<String, CliError> {
    let read_err = |source| CliError::Read {
        path: path.to_path_buf(),
        source,
    };
    let mut bytes = Vec::new();
    let marker = penner::io::write::JSON_MARKER.as_bytes();
    let limit = if path == Path::new("-") {
        let mut input = std::io::stdin().lock();
        (&mut input)
            .take(marker.len() as u64)
            .read_to_end(&mut bytes)
            .map_err(read_err)?;
        let limit = input_limit(&bytes);
        input
            .take(limit + 1 - bytes.len() as u64)
            .read_to_end(&mut bytes)
            .map_err(read_err)?;
        limit
    } else {
        penner::io::regular_file(path).map_err(|e| CliError::Input(e.to_string()))?;
        let mut file = std::fs::File::open(path).map_err(read_err)?;
        (&mut file)
            .take(marker.len() as u64)
            .read_to_end(&mut bytes)
            .map_err(read_err)?;
        let limit = input_limit(&bytes);
        if let Ok(meta) = file.metadata() {
            bytes.reserve(meta.len().min(limit + 1) as usize);
        }
        file.take(limit + 1 - bytes.len() as u64)
            .read_to_end(&mut bytes)
            .map_err(read_err)?;
        limit
    };
    if bytes.len() as u64 > limit {
        return Err(CliError::Input(format!(
            "{}: larger than the {} MiB input limit",
            path.display(),
            limit >> 20
        )));
    }
    String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let line = e.as_bytes()[..at].split(|&b| b == b'\n').count();
        CliError::Input(format!(
            "{}:{line}: not UTF-8 text (binary data at byte {at})",
            path.display()
        ))
    })
}

/// The size limit of an input starting with `head`.
fn input_limit(head: &[u8]) -> u64 {
    if head == penner::io::write::JSON_MARKER.as_bytes() {
        MAX_PENNER_JSON_BYTES
    } else {
        MAX_INPUT_BYTES
    }
}

/// Create `path` for writing, refusing to overwrite an existing file.
pub fn create_new(path: &Path) -> Result<std::fs::File, CliError> {
    OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)
        .map_err(|e| CliError::Write {
            path: path.to_path_buf(),
            reason: if e.kind() == ErrorKind::AlreadyExists {
                "the file exists (penner never overwrites a file; choose another name)".to_string()
            } else {
                e.to_string()
            },
        })
}

/// Write `bytes` to the new file `path` (never over an existing one) and flush it; every
/// error is an output error naming the path (exit 4).
pub fn write_new(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    use std::io::Write as _;
    let mut f = create_new(path)?;
    f.write_all(bytes)
        .and_then(|()| f.flush())
        .map_err(|e| CliError::Write {
            path: path.to_path_buf(),
            reason: e.to_string(),
        })
}

/// Write `contents` to a fresh file `<dir>/<stem>.penner-failure-N.json`, the smallest
/// N ≥ 1 whose file does not exist (checked atomically by `create_new`).
pub fn write_fresh_failure(input: &Path, contents: &str) -> Result<PathBuf, CliError> {
    let dir = input.parent().unwrap_or(Path::new("."));
    let stem = input.file_stem().map_or_else(
        || "surface".to_string(),
        |s| s.to_string_lossy().to_string(),
    );
    let stem = stem.split(".penner-failure-").next().unwrap_or("surface");
    for n in 1..=10_000u32 {
        let path = dir.join(format!("{stem}.penner-failure-{n}.json"));
        match OpenOptions::new().write(true).create_new(true).open(&path) {
            Ok(mut f) => {
                f.write_all(contents.as_bytes())
                    .and_then(|()| f.flush())
                    .map_err(|e| CliError::Write {
                        path: path.clone(),
                        reason: e.to_string(),
                    })?;
                return Ok(path);
            }
            Err(e) if e.kind() == ErrorKind::AlreadyExists => {}
            Err(e) => {
                return Err(CliError::Write {
                    path,
                    reason: e.to_string(),
                })
            }
        }
    }
    Err(CliError::Write {
        path: dir.join(format!("{stem}.penner-failure-N.json")),
        reason: "10000 failure files exist already".to_string(),
    })
}

/// Print to standard output. A failed write (a full disk, a closed standard output or
/// pipe) is an output error (exit code 4): the output is incomplete.
pub fn emit(text: &str) -> Result<(), CliError> {
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| stdout_error(&e))
}

/// The output error of a failed write to standard output.
pub fn stdout_error(e: &std::io::Error) -> CliError {
    CliError::Write {
        path: PathBuf::from("standard output"),
        reason: e.to_string(),
    }
}

/// A surface file to check, or the path and error of an entry that gives none.
pub type SurfaceFile = Result<PathBuf, (PathBuf, CliError)>;

/// The surface files named by `paths`, in order: a file as given; a directory as its
/// `.json`, `.obj` and `.off` entries (any case, not recursing into subdirectories, failure
/// files `*.penner-failure-N.json` left out), sorted by name. A directory that cannot be
/// listed, or holds no surface file, is an error entry; the others still run.
pub fn surface_files(paths: &[PathBuf]) -> Vec<SurfaceFile> {
    let mut out = Vec::new();
    for p in paths {
        if !p.is_dir() {
            out.push(Ok(p.clone()));
            continue;
        }
        let entries = match std::fs::read_dir(p) {
            Ok(entries) => entries,
            Err(source) => {
                let e = CliError::Read {
                    path: p.clone(),
                    source,
                };
                out.push(Err((p.clone(), e)));
                continue;
            }
        };
        let mut found: Vec<PathBuf> = entries
            .filter_map(Result::ok)
            .map(|e| e.path())
            .filter(|f| !f.is_dir() && is_surface_name(f))
            .collect();
        found.sort();
        if found.is_empty() {
            let e = CliError::Input(format!(
                "{}: a directory without .json, .obj or .off files",
                p.display()
            ));
            out.push(Err((p.clone(), e)));
        }
        out.extend(found.into_iter().map(Ok));
    }
    out
}

/// Whether a directory entry is a surface file to check: a `.json`, `.obj` or `.off`
/// name (any case) that is not a failure file penner wrote.
fn is_surface_name(f: &Path) -> bool {
    let ext = f
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let failure = f
        .file_name()
        .and_then(|n| n.to_str())
        .is_some_and(|n| n.contains(".penner-failure-"));
    matches!(ext.as_deref(), Some("json" | "obj" | "off")) && !failure
}
