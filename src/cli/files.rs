//! Reading inputs and writing outputs: size limits, text decoding, never overwriting.

use super::error::CliError;
use std::fs::OpenOptions;
use std::io::{ErrorKind, Read, Write};
use std::path::{Path, PathBuf};

/// Largest input file read (bytes). Larger files are refused before reading, so a huge
/// or endless input cannot exhaust memory.
pub const MAX_INPUT_BYTES: u64 = 256 << 20;

/// Read a text file (or standard input for `-`), refusing files over
/// [`MAX_INPUT_BYTES`] and bytes that are not UTF-8 (naming the line).
pub fn read_text(path: &Path) -> Result<String, CliError> {
    let read_err = |source| CliError::Read {
        path: path.to_path_buf(),
        source,
    };
    let mut bytes = Vec::new();
    if path == Path::new("-") {
        std::io::stdin()
            .take(MAX_INPUT_BYTES + 1)
            .read_to_end(&mut bytes)
            .map_err(read_err)?;
    } else {
        let file = std::fs::File::open(path).map_err(read_err)?;
        let meta = file.metadata().map_err(read_err)?;
        if meta.is_dir() {
            return Err(CliError::Input(format!(
                "{} is a directory, not a file",
                path.display()
            )));
        }
        file.take(MAX_INPUT_BYTES + 1)
            .read_to_end(&mut bytes)
            .map_err(read_err)?;
    }
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(CliError::Input(format!(
            "{}: larger than the {} MiB input limit",
            path.display(),
            MAX_INPUT_BYTES >> 20
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

/// Create `path` and write `contents`, refusing to overwrite an existing file.
pub fn write_new(path: &Path, contents: &str) -> Result<(), CliError> {
    let mut f = OpenOptions::new()
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
        })?;
    f.write_all(contents.as_bytes())
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

/// Print to standard output, ignoring a closed pipe (`penner … | head`).
pub fn emit(text: &str) {
    let mut out = std::io::stdout().lock();
    let _ = out.write_all(text.as_bytes());
    let _ = out.flush();
}
