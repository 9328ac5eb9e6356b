//! `penner check SURFACE…`: every applicable check at the chosen precisions, with failure
//! files for failing checks; several files, or every surface file of a directory, one
//! report each.

use super::error::CliError;
use super::files::{emit, write_fresh_failure};
use penner::oracle::check_surface::{check_surface, CheckOptions, ControlResult};
use penner::oracle::report;
use penner::theorems::Settings;
use std::path::{Path, PathBuf};

/// Options of `penner check`.
pub struct Options<'a> {
    /// The surface files and directories, as given.
    pub paths: &'a [PathBuf],
    /// Precision list as typed.
    pub precision: &'a str,
    /// Check IDs to run (empty: all).
    pub only: &'a [String],
    /// JSON output.
    pub json: bool,
    /// Skip failure files.
    pub no_failure_files: bool,
    /// Run the negative controls ([`penner::oracle::controls`]) instead of the checks.
    pub negative_controls: bool,
    /// A lengths file replacing the surface's metric.
    pub lengths: Option<&'a Path>,
}

/// Run `penner check`: one file as before; several files (or a directory) one report
/// each — a table with a header per file, or with `--json` a JSON array of one object per
/// file (`{"file": …, "rows": …}`, or `{"file": …, "error": …, "exit_code": 3}` for a file
/// that cannot be read). A bad file is reported and the others still run; the exit code
/// is the worst over the files ([`worse`]); a write error ends the command (exit 4).
pub fn run(o: &Options<'_>) -> Result<u8, CliError> {
    let files = super::files::surface_files(o.paths);
    let single =
        o.paths.len() == 1 && files.len() == 1 && files[0].as_ref().is_ok_and(|f| f == &o.paths[0]);
    if single {
        let path = &o.paths[0];
        let (code, doc) = run_file(o, path)?;
        if let Some(doc) = doc {
            emit(&format!("{doc:#}\n"))?;
        }
        return Ok(code);
    }
    if o.lengths.is_some() {
        return Err(CliError::Input(
            "--lengths goes with one surface file, not several".to_string(),
        ));
    }
    let mut worst = super::error::code::HOLDS;
    let mut first = true;
    if o.json {
        emit("[")?;
    }
    for file in files {
        let (path, outcome) = match file {
            Ok(path) => {
                let r = run_file(o, &path);
                (path, r)
            }
            Err((path, e)) => (path, Err(e)),
        };
        let (code, doc) = match outcome {
            Ok(r) => r,
            Err(e @ CliError::Write { .. }) => return Err(e),
            Err(e) => {
                eprintln!("penner: {e}");
                let doc = o.json.then(|| {
                    serde_json::json!({
                        "error": e.to_string(),
                        "exit_code": e.exit_code(),
                    })
                });
                (e.exit_code(), doc)
            }
        };
        worst = worse(worst, code);
        if let Some(mut doc) = doc {
            let mut obj = serde_json::Map::new();
            obj.insert("file".into(), path.display().to_string().into());
            if let serde_json::Value::Object(m) = std::mem::take(&mut doc) {
                obj.extend(m);
            }
            let sep = if first { "\n" } else { ",\n" };
            emit(&format!("{sep}{:#}", serde_json::Value::Object(obj)))?;
        } else if !o.json && code != super::error::code::HOLDS {
            emit(&format!("({}: exit code {code})\n", path.display()))?;
        }
        if !o.json {
            emit("\n")?;
        }
        first = false;
    }
    if o.json {
        emit("\n]\n")?;
    }
    Ok(worst)
}

/// The worse of two exit codes over files: holds (0) < undecided (2) < bad input (3) <
/// fails (1) < a defect (5).
pub fn worse(a: u8, b: u8) -> u8 {
    use super::error::code::{BAD_INPUT, FAILS, HOLDS, INTERNAL, UNDECIDED};
    let rank = |c: u8| match c {
        HOLDS => 0,
        UNDECIDED => 1,
        BAD_INPUT => 2,
        FAILS => 3,
        INTERNAL => 5,
        _ => 4,
    };
    if rank(b) > rank(a) {
        b
    } else {
        a
    }
}

/// Check one surface file: the exit code, and with `--json` the document (not yet
/// printed); the table is printed here.
fn run_file(o: &Options<'_>, path: &Path) -> Result<(u8, Option<serde_json::Value>), CliError> {
    let precisions = super::precisions(o.precision)?;
    let mut case = super::input::load_case(path)?;
    if let Some(l) = o.lengths {
        case = super::input::with_lengths(case, l)?;
    }
    let mut options = CheckOptions {
        precisions,
        only: o.only.to_vec(),
        negative_controls: o.negative_controls,
        reproducers: !o.no_failure_files,
        settings: Settings::default(),
    };
    let source = path.display().to_string();
    let outcome =
        super::progress::with_check_progress(&case, &mut options, o.json, |opts, done| {
            check_surface(&case, &source, opts, done)
        })
        .map_err(|e| CliError::Input(e.to_string()))?;
    let mut written: Vec<(String, PathBuf, usize)> = Vec::new();
    for failure in &outcome.failures {
        let file = write_fresh_failure(path, &format!("{:#}\n", failure.to_json()))?;
        written.push((failure.check.clone(), file, failure.surface.mesh.n_faces()));
    }
    let rows = &outcome.rows;
    let mut doc = None;
    if o.json {
        let mut d = report::json(rows);
        d["failure_files"] = written
            .iter()
            .map(|(id, p, faces)| {
                serde_json::json!({ "check": id, "file": p.display().to_string(), "faces": faces })
            })
            .collect();
        doc = Some(d);
    } else {
        emit(&format!(
            "{}: {} vertices, {} edges, {} faces, χ = {}\n\n",
            path.display(),
            case.mesh.n_vertices(),
            case.mesh.n_edges(),
            case.mesh.n_faces(),
            case.mesh.euler_characteristic()
        ))?;
        emit(&report::table(rows))?;
        emit(&super::report::summary(rows))?;
        for (id, p, faces) in &written {
            emit(&format!(
                "{id} fails: witnesses and a reproducing surface ({faces} face(s)) written to {} (re-run with `penner replay {}`)\n",
                p.display(),
                p.display()
            ))?;
        }
    }
    if o.negative_controls {
        return Ok((controls_verdict(&outcome.controls(), o.json)?, doc));
    }
    Ok((super::status_code(report::status(rows)), doc))
}

/// Exit code of `--negative-controls`: 0 when every control that ran (verdict other than
/// not applicable) failed as expected, 1 when one held (the check did not see its
/// perturbation on this surface), 5 when one crashed. Prints a line per control.
fn controls_verdict(results: &[ControlResult], json: bool) -> Result<u8, CliError> {
    use super::error::code::{FAILS, HOLDS, INTERNAL};
    let mut code = HOLDS;
    for r in results {
        if r.crashed {
            code = INTERNAL;
        }
        if r.held > 0 && code == HOLDS {
            code = FAILS;
        }
        if !json {
            let word = match (r.rejected, r.held) {
                (0, 0) => "not applicable to this surface".to_string(),
                (f, 0) => format!("rejected as expected at {f} precision(s)"),
                (f, h) => format!("NOT rejected at {h} precision(s) (rejected at {f})"),
            };
            emit(&format!("{} ({}): {word}\n", r.id, r.title))?;
        }
    }
    Ok(code)
}
