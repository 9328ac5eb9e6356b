//! Tidy: every certificate listed in [`REQUIRED`] has a **Terms** section in its `proofs/`
//! entry, a table `| term | in the inequality | deciding test |` whose every row names a
//! test that exists (a `fn` in `src/` or `tests/`, in backticks) or says `equivalent:`
//! with a reason. Cells escape a literal `|` as `\|`.

use std::collections::BTreeSet;
use std::path::Path;

/// The certificates whose terms must each have a deciding test.
const REQUIRED: &[&str] = &[
    "B33", "B35", "B36", "B39", "B52", "B70", "B71", "B72", "B73", "B76", "B87", "B95", "B96",
    "B98", "B102", "B103",
];

/// The cells of a table row, split on unescaped `|`.
fn cells(row: &str) -> Vec<String> {
    let inner = row.trim().trim_start_matches('|');
    let inner = inner.strip_suffix('|').unwrap_or(inner);
    let mut out = vec![String::new()];
    let mut chars = inner.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' if chars.peek() == Some(&'|') => {
                out.last_mut().expect("a cell").push('|');
                chars.next();
            }
            '|' => out.push(String::new()),
            _ => out.last_mut().expect("a cell").push(c),
        }
    }
    out.into_iter().map(|c| c.trim().to_string()).collect()
}

/// Backticked words that look like test names (`term_b71_…`, `b07_…`, any snake case).
fn named_tests(cell: &str) -> Vec<String> {
    cell.split('`')
        .skip(1)
        .step_by(2)
        .filter(|w| {
            !w.is_empty()
                && w.chars()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
                && w.contains('_')
        })
        .map(str::to_string)
        .collect()
}

/// What is wrong with the **Terms** section of one proofs file (`None` when it has none).
fn terms_problems(file: &str, text: &str, fns: &BTreeSet<String>) -> Option<Vec<String>> {
    let start = text.find("**Terms**")?;
    let rest = &text[start + "**Terms**".len()..];
    let end = rest.find("\n**").unwrap_or(rest.len());
    let rows: Vec<&str> = rest[..end]
        .lines()
        .filter(|l| l.trim_start().starts_with('|'))
        .collect();
    let mut problems = Vec::new();
    let header = rows.first().map(|r| cells(r));
    if header.as_deref()
        != Some(
            &[
                "term".to_string(),
                "in the inequality".into(),
                "deciding test".into(),
            ][..],
        )
    {
        problems.push(format!(
            "{file}: the Terms table must start `| term | in the inequality | deciding test |`"
        ));
        return Some(problems);
    }
    let body: Vec<&str> = rows.iter().skip(2).copied().collect();
    if body.is_empty() {
        problems.push(format!("{file}: the Terms table lists no term"));
    }
    for row in body {
        let c = cells(row);
        if c.len() != 3 {
            problems.push(format!("{file}: a Terms row has {} cells: {row}", c.len()));
            continue;
        }
        let decided = &c[2];
        if let Some(reason) = decided.strip_prefix("equivalent:") {
            if reason.split_whitespace().count() < 3 {
                problems.push(format!("{file}: `{}`: equivalent without a reason", c[0]));
            }
            continue;
        }
        let tests = named_tests(decided);
        if tests.is_empty() {
            problems.push(format!("{file}: `{}` names no deciding test", c[0]));
        }
        for t in tests {
            if !fns.contains(&t) {
                problems.push(format!("{file}: `{}`: no test `{t}` exists", c[0]));
            }
        }
    }
    Some(problems)
}

/// Every `fn name` in the Rust files under `dir`.
fn fn_names(dir: &Path, out: &mut BTreeSet<String>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            fn_names(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            let text = std::fs::read_to_string(&p).unwrap_or_default();
            for piece in text.split("fn ").skip(1) {
                let name: String = piece
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                    .collect();
                if !name.is_empty() {
                    out.insert(name);
                }
            }
        }
    }
}

#[test]
fn every_term_of_every_listed_certificate_has_a_deciding_test() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut fns = BTreeSet::new();
    fn_names(&root.join("src"), &mut fns);
    fn_names(&root.join("tests"), &mut fns);
    let mut problems = Vec::new();
    let mut with_terms = BTreeSet::new();
    for e in std::fs::read_dir(root.join("proofs"))
        .expect("proofs/")
        .flatten()
    {
        let name = e.file_name().to_string_lossy().into_owned();
        let text = std::fs::read_to_string(e.path()).unwrap_or_default();
        if let Some(p) = terms_problems(&name, &text, &fns) {
            with_terms.insert(name.split('-').next().unwrap_or("").to_string());
            problems.extend(p);
        }
    }
    for id in REQUIRED {
        if !with_terms.contains(*id) {
            problems.push(format!("{id} has no **Terms** section"));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn terms_rule_rejects_missing_tests_bare_equivalences_and_bad_tables() {
    let fns: BTreeSet<String> = ["term_b01_exists".to_string()].into_iter().collect();
    let good = "**Terms**\n| term | in the inequality | deciding test |\n|---|---|---|\n\
                | `a\\|b` | x | `term_b01_exists` |\n| c | y | equivalent: dominated by a |\n\n**Checked by**\n";
    assert_eq!(terms_problems("B01", good, &fns), Some(vec![]));
    let bad = "**Terms**\n| term | in the inequality | deciding test |\n|---|---|---|\n\
               | a | x | `term_b01_missing` |\n| b | y | equivalent: no |\n| c | z | prose only |\n";
    let p = terms_problems("B01", bad, &fns).expect("has a section");
    assert_eq!(p.len(), 3, "{p:?}");
    let header = "**Terms**\n| term | deciding test |\n|---|---|\n| a | `term_b01_exists` |\n";
    assert_eq!(
        terms_problems("B01", header, &fns).map(|p| p.len()),
        Some(1)
    );
    assert_eq!(terms_problems("B01", "no section", &fns), None);
}
