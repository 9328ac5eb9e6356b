//! `penner check` on one surface as a library call: the checks chosen (or their negative
//! controls) at every precision asked, and for each failing check a minimal reproducer
//! (the surface shrunk while the check still fails at that precision, [`shrink`]) ready to
//! be written as a failure file.
//!
//! ```
//! use penner::io::Surface;
//! use penner::mesh::builders;
//! use penner::oracle::check_surface::{check_surface, CheckOptions};
//! use penner::oracle::report::{status, Status};
//! let s = Surface::from_embedded("tetrahedron", builders::tetrahedron()).unwrap();
//! let options = CheckOptions { only: vec!["T01".into(), "T03".into()], ..CheckOptions::default() };
//! let out = check_surface(&s, "tetrahedron", &options, &|_| {}).unwrap();
//! assert!(!out.rows.is_empty() && out.failures.is_empty());
//! assert_eq!(status(&out.rows), Status::Holds);
//! ```

use super::controls;
use super::failure::Failure;
use super::registry::{self, Check, Outcome, Row};
use super::shrink::{shrink, Budget};
use crate::io::Surface;
use crate::scalar::prec::Prec;
use crate::theorems::{Settings, Verdict};

/// What to check and how.
#[derive(Clone, Debug)]
pub struct CheckOptions {
    /// The precisions (negative controls add `exact`: several are exact-only).
    pub precisions: Vec<Prec>,
    /// Check IDs (empty: all); a name selects its variants (`T21` also `T21P`).
    pub only: Vec<String>,
    /// Run the negative controls ([`controls`]) instead of the checks.
    pub negative_controls: bool,
    /// Shrink each failing check's surface to a minimal reproducer.
    pub reproducers: bool,
    /// Tolerances, limits and the progress hook of the checks.
    pub settings: Settings,
}

impl Default for CheckOptions {
    /// Every check at `f64`, double-double and 256-bit MPFR, with reproducers.
    fn default() -> CheckOptions {
        CheckOptions {
            precisions: super::precision::parse_list("f64,dd,256").unwrap_or_default(),
            only: Vec::new(),
            negative_controls: false,
            reproducers: true,
            settings: Settings::default(),
        }
    }
}

/// Why a check run was refused: a name that selects nothing, or a check without a form
/// at the precisions asked.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum CheckError {
    /// No check has this ID in this build.
    #[error("--only: no check `{id}` in this build (available: {known})")]
    UnknownCheck {
        /// The name as given (upper case).
        id: String,
        /// The IDs there are.
        known: String,
    },
    /// No negative control for this ID.
    #[error("--only: no negative control for `{id}` (available: {known})")]
    NoControl {
        /// The name as given (upper case).
        id: String,
        /// The controls there are.
        known: String,
    },
    /// The check named has no form at any precision asked (e.g. exact-only at `f64`).
    #[error("--only {id}: the check has no form at the precisions asked ({precisions}); exact-only checks run with --precision exact")]
    NoForm {
        /// The check.
        id: String,
        /// The precisions asked.
        precisions: String,
    },
}

/// One negative control's result: at how many precisions it was rejected (as it must be),
/// held (the check did not see its perturbation), or crashed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ControlResult {
    /// The control's ID (`T16-NC`).
    pub id: &'static str,
    /// Its title.
    pub title: &'static str,
    /// Precisions at which the control failed, as expected.
    pub rejected: usize,
    /// Precisions at which it held.
    pub held: usize,
    /// Whether it crashed at some precision.
    pub crashed: bool,
}

/// The outcome of [`check_surface`].
#[derive(Clone, Debug)]
pub struct CheckOutcome {
    /// The checks run (or the negative controls).
    pub checks: Vec<Check>,
    /// One row per check and precision with a form there, in catalogue order.
    pub rows: Vec<Row>,
    /// Per failing check, its first failure and a minimal reproducer.
    pub failures: Vec<Failure>,
}

impl CheckOutcome {
    /// Per negative control, its counts (meaningful with `negative_controls`).
    pub fn controls(&self) -> Vec<ControlResult> {
        self.checks
            .iter()
            .map(|c| {
                let mut r = ControlResult {
                    id: c.id,
                    title: c.title,
                    rejected: 0,
                    held: 0,
                    crashed: false,
                };
                for row in self.rows.iter().filter(|row| row.id == c.id) {
                    match &row.outcome {
                        Outcome::Verdict(Verdict::NotApplicable { .. }) => {}
                        Outcome::Verdict(Verdict::Fails { .. }) => r.rejected += 1,
                        Outcome::Crashed(_) => r.crashed = true,
                        Outcome::Verdict(_) => r.held += 1,
                    }
                }
                r
            })
            .collect()
    }
}

/// Run the checks of `options` on `surface` (named `source` in failure files), calling
/// `done` with each row as it finishes (module documentation).
pub fn check_surface(
    surface: &Surface,
    source: &str,
    options: &CheckOptions,
    done: &(dyn Fn(&Row) + Sync),
) -> Result<CheckOutcome, CheckError> {
    let mut precs = options.precisions.clone();
    if options.negative_controls && !precs.contains(&Prec::Exact) {
        precs.push(Prec::Exact);
    }
    let checks = if options.negative_controls {
        select_controls(&options.only)?
    } else {
        select(&options.only)?
    };
    let settings = &options.settings;
    let rows = registry::run_case_with(surface, &checks, &precs, settings, done);
    if !options.only.is_empty() && !options.negative_controls {
        if let Some(c) = checks.iter().find(|c| rows.iter().all(|r| r.id != c.id)) {
            let names: Vec<String> = options.precisions.iter().map(ToString::to_string).collect();
            return Err(CheckError::NoForm {
                id: c.id.to_string(),
                precisions: names.join(","),
            });
        }
    }
    let mut failures = Vec::new();
    if options.reproducers {
        for check in &checks {
            let Some(row) = rows.iter().find(|r| {
                r.id == check.id && matches!(r.outcome, Outcome::Verdict(Verdict::Fails { .. }))
            }) else {
                continue;
            };
            let Outcome::Verdict(Verdict::Fails { witnesses, .. }) = &row.outcome else {
                continue;
            };
            let fails = |c: &Surface| {
                registry::run_one(check, c, row.precision, settings)
                    .is_some_and(|r| matches!(r.outcome, Outcome::Verdict(Verdict::Fails { .. })))
            };
            failures.push(Failure {
                check: check.id.to_string(),
                precision: row.precision,
                source: source.to_string(),
                source_faces: surface.mesh.n_faces(),
                witnesses: witnesses.clone(),
                surface: shrink(surface, witnesses, &fails, Budget::default()),
            });
        }
    }
    Ok(CheckOutcome {
        checks,
        rows,
        failures,
    })
}

/// The checks named by `only`, or all.
pub fn select(only: &[String]) -> Result<Vec<Check>, CheckError> {
    registry::select(only).map_err(|id| {
        let known: Vec<&str> = registry::catalogue().iter().map(|c| c.id).collect();
        CheckError::UnknownCheck {
            id,
            known: if known.is_empty() {
                "none".to_string()
            } else {
                known.join(", ")
            },
        }
    })
}

/// The negative controls whose check IDs are named by `only` (`T16` selects `T16-NC`), or
/// all.
pub fn select_controls(only: &[String]) -> Result<Vec<Check>, CheckError> {
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
            return Err(CheckError::NoControl {
                id,
                known: known.join(", "),
            });
        };
        out.push(*c);
    }
    Ok(out)
}
