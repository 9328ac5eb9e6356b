//! `penner` / `penner report`: every check of the registry on the built-in corpus.

use super::error::CliError;
use super::files::emit;
use penner::oracle::{catalogue, registry, report};
use penner::theorems::Settings;

/// Run the report at the precisions in `precision` and print it.
pub fn run(precision: &str, json: bool) -> Result<u8, CliError> {
    let precs = super::precisions(precision)?;
    let checks = catalogue();
    let settings = Settings::default();
    let corpus = penner::oracle::corpus::standard();
    let mut rows = Vec::new();
    for case in &corpus {
        rows.extend(registry::run_case(case, &checks, &precs, &settings));
    }
    let st = report::status(&rows);
    if json {
        emit(&format!("{:#}\n", report::json(&rows)))?;
    } else {
        emit(&format!(
            "penner {}: {} check(s) × {} surface(s) × {} precision(s)\n\n",
            env!("CARGO_PKG_VERSION"),
            checks.len(),
            corpus.len(),
            precs.len()
        ))?;
        emit(&report::table(&rows))?;
        emit(&summary(&rows))?;
    }
    Ok(super::status_code(st))
}

/// One line counting verdicts.
pub fn summary(rows: &[registry::Row]) -> String {
    let mut counts = std::collections::BTreeMap::new();
    for r in rows {
        *counts
            .entry(report::verdict_word(&r.outcome))
            .or_insert(0usize) += 1;
    }
    let parts: Vec<String> = counts.iter().map(|(k, v)| format!("{v} {k}")).collect();
    format!("{} row(s): {}\n", rows.len(), parts.join(", "))
}
