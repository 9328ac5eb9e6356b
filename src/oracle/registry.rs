//! The check registry: every catalogue check the binary can run on a [`Surface`], and the
//! runner that applies them at a list of precisions.
//!
//! A check that is not implemented is absent from [`catalogue`], never reported with an
//! invented verdict.

pub use super::check_entry::Check;
use super::precision::Prec;
use crate::io::Surface;
use crate::theorems::{Settings, Verdict};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::Arc;
use std::time::Instant;

/// Every check this build can run, in catalogue order.
pub fn catalogue() -> Vec<Check> {
    let mut all = super::checks::entries();
    all.extend(super::checks_circles::entries());
    all.extend(super::checks_lobachevsky::entries());
    all.extend(super::checks_energy::entries());
    all.extend(super::checks_uniformization::entries());
    all.sort_by_key(|c| c.id);
    all
}

/// The checks named in `ids`, or all of them for an empty list. A name selects the check
/// with that ID (case-insensitive) and its variants (`T21` also selects `T21P`); an
/// unknown name is returned as the error.
pub fn select(ids: &[String]) -> Result<Vec<Check>, String> {
    let all = catalogue();
    if ids.is_empty() {
        return Ok(all);
    }
    let mut out: Vec<Check> = Vec::new();
    for id in ids {
        let id = id.trim().to_ascii_uppercase();
        let exact: Vec<Check> = all.iter().filter(|c| c.id == id).copied().collect();
        let chosen: Vec<Check> = if exact.is_empty() || id.len() == 3 {
            all.iter()
                .filter(|c| c.id == id || (c.id.starts_with(&id) && id.len() == 3))
                .copied()
                .collect()
        } else {
            exact
        };
        if chosen.is_empty() {
            return Err(id);
        }
        for c in chosen {
            if !out.iter().any(|o| o.id == c.id) {
                out.push(c);
            }
        }
    }
    Ok(out)
}

/// The check with exactly this ID.
pub fn by_id(id: &str) -> Option<Check> {
    catalogue()
        .into_iter()
        .find(|c| c.id.eq_ignore_ascii_case(id))
}

/// What running one check produced.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// The check's verdict.
    Verdict(Verdict),
    /// The check itself broke (a defect in the library, not a verdict on the surface).
    Crashed(String),
}

/// One row of a report: one check on one case at one precision.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The case's name, shared by every row of the case (stored once however many rows).
    pub case: Arc<str>,
    /// Catalogue ID.
    pub id: &'static str,
    /// Short statement.
    pub title: &'static str,
    /// Working precision.
    pub precision: Prec,
    /// Verdict, or the defect.
    pub outcome: Outcome,
    /// Wall-clock seconds the check took.
    pub seconds: f64,
}

/// Run one check on one case at one precision, timing it; `None` when the check has no
/// form at that precision. A panic inside the check is caught and reported as
/// [`Outcome::Crashed`] so one defect cannot hide other rows.
///
/// The check runs on the case rescaled by an exact power of two when its lengths are far
/// from 1 ([`Surface::normalized_scale`], proofs/B40 "Range"): verdicts are about the
/// user's metric, since every statement is scale invariant.
pub fn run_one(check: &Check, case: &Surface, prec: Prec, settings: &Settings) -> Option<Row> {
    let name: Arc<str> = Arc::from(case.name.as_str());
    match case.normalized_scale() {
        Some((scaled, _)) => run_one_as_is(check, &name, &scaled, prec, settings),
        None => run_one_as_is(check, &name, case, prec, settings),
    }
}

/// [`run_one`] on `input` (the case or its rescaled copy), reported under `name`.
fn run_one_as_is(
    check: &Check,
    name: &Arc<str>,
    input: &Surface,
    prec: Prec,
    settings: &Settings,
) -> Option<Row> {
    // Long checks report their progress over elements under the label `T23 f64`.
    let labelled;
    let settings = if settings.progress.is_on() {
        labelled = Settings {
            progress: settings.progress.for_task(&format!("{} {prec}", check.id)),
            ..settings.clone()
        };
        &labelled
    } else {
        settings
    };
    let start = Instant::now();
    let result = catch_unwind(AssertUnwindSafe(|| (check.run)(input, prec, settings)));
    let seconds = start.elapsed().as_secs_f64();
    let outcome = match result {
        Ok(Some(v)) => Outcome::Verdict(v),
        Ok(None) => return None,
        Err(payload) => Outcome::Crashed(panic_message(payload.as_ref())),
    };
    Some(Row {
        case: Arc::clone(name),
        id: check.id,
        title: check.title,
        precision: prec,
        outcome,
        seconds,
    })
}

/// Run every check in `checks` on `case` at every precision in `precs`.
/// The case is rescaled once, as in [`run_one`]; the checks run in parallel
/// ([`run_case_with`]).
pub fn run_case(case: &Surface, checks: &[Check], precs: &[Prec], settings: &Settings) -> Vec<Row> {
    run_case_with(case, checks, precs, settings, &|_| {})
}

/// [`run_case`], calling `done` with each row as soon as its check finishes (for progress
/// displays; the order of calls is the order of completion). The (check, precision) pairs
/// are independent and read-only, so they run on rayon's thread pool; the rows are returned
/// in catalogue order, then precision order, whatever the order of completion.
pub fn run_case_with(
    case: &Surface,
    checks: &[Check],
    precs: &[Prec],
    settings: &Settings,
    done: &(dyn Fn(&Row) + Sync),
) -> Vec<Row> {
    use rayon::prelude::*;
    let scaled = case.normalized_scale().map(|(s, _)| s);
    let input = scaled.as_ref().unwrap_or(case);
    let name: Arc<str> = Arc::from(case.name.as_str());
    let tasks: Vec<(&Check, Prec)> = checks
        .iter()
        .flat_map(|c| precs.iter().map(move |&p| (c, p)))
        .collect();
    let rows: Vec<Option<Row>> = tasks
        .par_iter()
        .map(|&(check, p)| {
            let row = run_one_as_is(check, &name, input, p, settings);
            if let Some(r) = &row {
                done(r);
            }
            row
        })
        .collect();
    rows.into_iter().flatten().collect()
}

fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "panic with a non-text payload".to_string()
    }
}
