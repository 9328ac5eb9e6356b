//! `penner replay FILE`: re-run a failure file written by `penner check`.

use super::error::{code, CliError};
use super::files::{emit, read_text};
use penner::oracle::failure::Failure;
use penner::oracle::registry::{self, Outcome};
use penner::oracle::report;
use penner::theorems::{Settings, Verdict};
use std::path::Path;

/// Run `penner replay`.
pub fn run(path: &Path, json: bool) -> Result<u8, CliError> {
    let text = read_text(path)?;
    let name = path.display().to_string();
    let failure = Failure::parse(&text, &name).map_err(|e| CliError::Input(e.to_string()))?;
    let check = registry::by_id(&failure.check)
        .or_else(|| penner::oracle::controls::by_id(&failure.check))
        .ok_or_else(|| {
            CliError::Input(format!(
                "{name}: check `{}` is not in this build of penner",
                failure.check
            ))
        })?;
    let checks = [check];
    let settings = Settings::default();
    let rows = registry::run_case(&failure.surface, &checks, &[failure.precision], &settings);
    if rows.is_empty() {
        return Err(CliError::Input(format!(
            "{name}: check `{}` has no form at {}: nothing to replay",
            failure.check, failure.precision
        )));
    }
    let still = rows
        .iter()
        .any(|r| matches!(r.outcome, Outcome::Verdict(Verdict::Fails { .. })));
    if json {
        let mut doc = report::json(&rows);
        doc["still_fails"] = serde_json::Value::Bool(still);
        emit(&format!("{doc:#}\n"))?;
    } else {
        emit(&report::table(&rows))?;
        emit(&format!(
            "{} at {}: {}\n",
            failure.check,
            failure.precision,
            if still {
                "still fails"
            } else {
                "no longer fails"
            }
        ))?;
    }
    Ok(match report::status(&rows) {
        report::Status::Holds => code::HOLDS,
        s => super::status_code(s),
    })
}
