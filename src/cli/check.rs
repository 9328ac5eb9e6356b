//! `penner check SURFACE…`: every applicable check at the chosen precisions, with failure
//! files for failing checks; several files, or every surface file of a directory, one
//! report each.

use super::error::CliError;
use super::files::{emit, write_fresh_failure};
use penner::oracle::failure::Failure;
use penner::oracle::registry::{self, Check, Outcome};
use penner::oracle::shrink::{shrink, Budget};
use penner::oracle::{controls, report, Prec, Surface};
use penner::theorems::{Settings, Verdict};
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
    let mut precs = super::precisions(o.precision)?;
    // Several controls are exact-only; they always run at `exact` too.
    if o.negative_controls && !precs.contains(&Prec::Exact) {
        precs.push(Prec::Exact);
    }
    let checks = if o.negative_controls {
        select_controls(o.only)?
    } else {
        select(o.only)?
    };
    let mut case = super::input::load_case(path)?;
    if let Some(l) = o.lengths {
        case = super::input::with_lengths(case, l)?;
    }
    let settings = Settings::default();
    let rows = run_with_progress(&case, &checks, &precs, &settings, o.json);
    // A check named by --only that gave no row has no form at the precisions asked.
    if !o.only.is_empty() && !o.negative_controls {
        if let Some(c) = checks.iter().find(|c| rows.iter().all(|r| r.id != c.id)) {
            return Err(CliError::Input(format!(
                "--only {}: the check has no form at the precisions asked ({}); exact-only checks run with --precision exact",
                c.id, o.precision
            )));
        }
    }
    let mut written: Vec<(String, PathBuf, usize)> = Vec::new();
    if !o.no_failure_files {
        for check in &checks {
            let first_fail = rows.iter().find(|r| {
                r.id == check.id && matches!(r.outcome, Outcome::Verdict(Verdict::Fails { .. }))
            });
            if let Some(row) = first_fail {
                let Outcome::Verdict(Verdict::Fails { witnesses, .. }) = &row.outcome else {
                    continue;
                };
                let small = shrink_failure(check, &case, row.precision, witnesses, &settings);
                let faces = small.mesh.n_faces();
                let doc = Failure {
                    check: check.id.to_string(),
                    precision: row.precision,
                    source: path.display().to_string(),
                    source_faces: case.mesh.n_faces(),
                    witnesses: witnesses.clone(),
                    surface: small,
                };
                let file = write_fresh_failure(path, &format!("{:#}\n", doc.to_json()))?;
                written.push((check.id.to_string(), file, faces));
            }
        }
    }
    let mut doc = None;
    if o.json {
        let mut d = report::json(&rows);
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
        emit(&report::table(&rows))?;
        emit(&super::report::summary(&rows))?;
        for (id, p, faces) in &written {
            emit(&format!(
                "{id} fails: witnesses and a reproducing surface ({faces} face(s)) written to {} (re-run with `penner replay {}`)\n",
                p.display(),
                p.display()
            ))?;
        }
    }
    if o.negative_controls {
        return Ok((controls_verdict(&rows, &checks, o.json)?, doc));
    }
    Ok((super::status_code(report::status(&rows)), doc))
}

/// The negative controls whose check IDs are named by `--only` (`T16` selects `T16-NC`),
/// or all.
fn select_controls(only: &[String]) -> Result<Vec<Check>, CliError> {
    let all = controls::controls();
    if only.is_empty() {
        return Ok(all);
    }
    let mut out = Vec::new();
    for id in only {
        let id = id.trim().to_ascii_uppercase();
        let base = id.trim_end_matches("-NC");
        let Some(c) = all.iter().find(|c| c.id.trim_end_matches("-NC") == base) else {
            let known: Vec<&str> = all.iter().map(|c| c.id).collect();
            return Err(CliError::Input(format!(
                "--only: no negative control for `{id}` (available: {})",
                known.join(", ")
            )));
        };
        out.push(*c);
    }
    Ok(out)
}

/// Exit code of `--negative-controls`: 0 when every control that ran (verdict other than
/// not applicable) failed as expected, 1 when one held (the check did not see its
/// perturbation on this surface), 5 when one crashed. Prints a line per control.
fn controls_verdict(rows: &[registry::Row], checks: &[Check], json: bool) -> Result<u8, CliError> {
    let mut code = super::error::code::HOLDS;
    for c in checks {
        let mine: Vec<&registry::Row> = rows.iter().filter(|r| r.id == c.id).collect();
        let ran = mine
            .iter()
            .filter(|r| !matches!(r.outcome, Outcome::Verdict(Verdict::NotApplicable { .. })));
        let (mut failed, mut held) = (0, 0);
        for r in ran {
            match &r.outcome {
                Outcome::Verdict(Verdict::Fails { .. }) => failed += 1,
                Outcome::Crashed(_) => code = super::error::code::INTERNAL,
                Outcome::Verdict(_) => held += 1,
            }
        }
        if held > 0 && code == super::error::code::HOLDS {
            code = super::error::code::FAILS;
        }
        if !json {
            let word = match (failed, held) {
                (0, 0) => "not applicable to this surface".to_string(),
                (f, 0) => format!("rejected as expected at {f} precision(s)"),
                (f, h) => format!("NOT rejected at {h} precision(s) (rejected at {f})"),
            };
            emit(&format!("{} ({}): {word}\n", c.id, c.title))?;
        }
    }
    Ok(code)
}

/// The checks named by `--only`, or all.
pub fn select(only: &[String]) -> Result<Vec<Check>, CliError> {
    registry::select(only).map_err(|id| {
        let known: Vec<&str> = registry::catalogue().iter().map(|c| c.id).collect();
        CliError::Input(format!(
            "--only: no check `{id}` in this build (available: {})",
            if known.is_empty() {
                "none".to_string()
            } else {
                known.join(", ")
            }
        ))
    })
}

/// Shrink `case` while `check` still fails at `prec`.
fn shrink_failure(
    check: &Check,
    case: &Surface,
    prec: Prec,
    witnesses: &[penner::theorems::Witness],
    settings: &Settings,
) -> Surface {
    let fails = |c: &Surface| {
        registry::run_one(check, c, prec, settings)
            .is_some_and(|r| matches!(r.outcome, Outcome::Verdict(Verdict::Fails { .. })))
    };
    shrink(case, witnesses, &fails, Budget::default())
}

/// [`registry::run_case_with`], with progress bars on standard error when it is a terminal
/// and the output is a table: one bar over the (check, precision) pairs, the message naming
/// the last one finished, and one bar per running long check over its elements
/// ([`ElementBars`]). Nothing is drawn on a pipe or with `--json`.
fn run_with_progress(
    case: &Surface,
    checks: &[Check],
    precs: &[Prec],
    settings: &Settings,
    json: bool,
) -> Vec<registry::Row> {
    use std::io::IsTerminal;
    if json || !std::io::stderr().is_terminal() {
        return registry::run_case(case, checks, precs, settings);
    }
    let total = (checks.len() * precs.len()) as u64;
    let multi = indicatif::MultiProgress::new();
    let bar = multi.add(indicatif::ProgressBar::new(total));
    if let Ok(style) =
        indicatif::ProgressStyle::with_template("{bar:30} {pos}/{len} checks  {elapsed}  {msg}")
    {
        bar.set_style(style);
    }
    bar.set_message(format!(
        "{} checks × {} precisions on {} faces",
        checks.len(),
        precs.len(),
        case.mesh.n_faces()
    ));
    bar.enable_steady_tick(std::time::Duration::from_millis(200));
    let hook = std::sync::Arc::new(ElementBars {
        multi: multi.clone(),
        bars: std::sync::Mutex::new(std::collections::HashMap::new()),
    });
    let settings = Settings {
        progress: penner::theorems::progress::Progress::to(hook),
        ..settings.clone()
    };
    let done = |row: &registry::Row| {
        bar.inc(1);
        bar.set_message(format!("{} {} done", row.id, row.precision));
    };
    let rows = registry::run_case_with(case, checks, precs, &settings, &done);
    bar.finish_and_clear();
    rows
}

/// One progress bar per running check over its elements, drawn under the bar of checks;
/// a stage's bar is removed when the stage completes.
struct ElementBars {
    multi: indicatif::MultiProgress,
    bars: std::sync::Mutex<std::collections::HashMap<String, indicatif::ProgressBar>>,
}

impl penner::theorems::progress::Hook for ElementBars {
    fn elements(&self, task: &str, stage: &str, done: u64, total: u64) {
        let Ok(mut bars) = self.bars.lock() else {
            return;
        };
        let key = format!("{task}: {stage}");
        if done >= total {
            if let Some(b) = bars.remove(&key) {
                b.finish_and_clear();
                self.multi.remove(&b);
            }
            return;
        }
        let b = bars.entry(key).or_insert_with(|| {
            let b = self.multi.add(indicatif::ProgressBar::new(total));
            if let Ok(style) =
                indicatif::ProgressStyle::with_template("{bar:30} {pos}/{len}  {prefix}: {msg}")
            {
                b.set_style(style);
            }
            b.set_prefix(task.to_string());
            b.set_message(stage.to_string());
            b
        });
        b.set_length(total);
        b.set_position(done);
    }
}
