//! Tidy: `docs/catalogue.md` has one row for every theorem T01–T36 and for every
//! `proofs/Tnn-*.md` entry, and no row for a theorem that does not exist.

use std::collections::BTreeSet;
use std::path::Path;

/// The IDs of the catalogue table's rows: lines starting `| Tnn |`.
fn catalogue_rows(catalogue: &str) -> Vec<String> {
    catalogue
        .lines()
        .filter_map(|line| {
            let cell = line.strip_prefix('|')?.split('|').next()?.trim();
            let b = cell.as_bytes();
            (b.len() == 3 && b[0] == b'T' && b[1..].iter().all(u8::is_ascii_digit))
                .then(|| cell.to_string())
        })
        .collect()
}

/// What is wrong with the catalogue given the theorem IDs that must have a row: missing
/// rows, rows given twice, and rows for IDs outside `expected`.
fn catalogue_problems(catalogue: &str, expected: &BTreeSet<String>) -> Vec<String> {
    let rows = catalogue_rows(catalogue);
    let mut problems = Vec::new();
    let mut seen = BTreeSet::new();
    for id in &rows {
        if !seen.insert(id.clone()) {
            problems.push(format!("{id} has two rows in docs/catalogue.md"));
        }
        if !expected.contains(id) {
            problems.push(format!(
                "{id} has a row but is not a theorem of the catalogue"
            ));
        }
    }
    for id in expected.difference(&seen) {
        problems.push(format!("{id} has no row in docs/catalogue.md"));
    }
    problems
}

/// T01–T36 and every `proofs/Tnn-*.md`.
fn theorem_ids(root: &Path) -> BTreeSet<String> {
    let mut ids: BTreeSet<String> = (1..=36).map(|k| format!("T{k:02}")).collect();
    for entry in std::fs::read_dir(root.join("proofs")).expect("proofs/") {
        let name = entry.expect("proofs/ entry").file_name();
        let name = name.to_string_lossy();
        if let Some((id, _)) = name.split_once('-') {
            if id.starts_with('T') {
                ids.insert(id.to_string());
            }
        }
    }
    ids
}

#[test]
fn catalogue_has_one_row_per_theorem() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let catalogue = std::fs::read_to_string(root.join("docs/catalogue.md")).expect("catalogue");
    let problems = catalogue_problems(&catalogue, &theorem_ids(root));
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn catalogue_rule_rejects_missing_duplicate_and_unknown_rows() {
    let expected: BTreeSet<String> = ["T01", "T02"].iter().map(ToString::to_string).collect();
    let good = "| ID | Statement |\n|---|---|\n| T01 | a |\n| T02 | b |\n";
    assert!(catalogue_problems(good, &expected).is_empty());
    let broken = "| T01 | a |\n| T01 | again |\n| T99 | unknown |\n";
    let problems = catalogue_problems(broken, &expected);
    assert_eq!(problems.len(), 3, "{problems:?}");
    assert!(problems.iter().any(|p| p.contains("T02 has no row")));
    assert!(problems.iter().any(|p| p.contains("T01 has two rows")));
    assert!(problems.iter().any(|p| p.contains("T99 has a row")));
}
