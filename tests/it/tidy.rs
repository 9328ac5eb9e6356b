//! Tidy: `proofs/`, the code that cites it and the tests that check it stay consistent.
//!
//! Rules (proofs/README.md):
//! - every cited ID — a `proof: B07` comment in `src/` or a test named `b07_…` / `t21_…` —
//!   has a file `proofs/B07-slug.md`;
//! - every proofs file has one row in the index table of `proofs/README.md`, and every row
//!   names a file that exists;
//! - every test listed under a file's **Checked by** heading exists as a `fn` in `tests/`
//!   or `src/`;
//! - no ID has two files or two index rows.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt;
use std::path::{Path, PathBuf};

/// One inconsistency found by [`check_consistency`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Problem {
    /// An ID is cited (at `place`) but no `proofs/ID-*.md` file exists.
    CitedWithoutFile { id: String, place: String },
    /// A proofs file has no row in the index.
    FileNotIndexed { file: String },
    /// An index row names a file that does not exist, or whose ID differs from the row's.
    IndexedFileMissing { id: String, file: String },
    /// A test listed under **Checked by** does not exist.
    UnknownCheckingTest { file: String, test: String },
    /// An ID has more than one file, or more than one index row.
    DuplicateId { id: String, places: Vec<String> },
    /// A file in proofs/ whose name is not `Xnn-slug.md` with X ∈ {B, T}.
    BadFileName { file: String },
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Problem::CitedWithoutFile { id, place } => {
                write!(f, "{id} is cited at {place} but proofs/ has no {id}-*.md file")
            }
            Problem::FileNotIndexed { file } => {
                write!(f, "proofs/{file} has no row in the proofs/README.md index")
            }
            Problem::IndexedFileMissing { id, file } => write!(
                f,
                "the index row for {id} names `{file}`, which is not a proofs/ file of that ID"
            ),
            Problem::UnknownCheckingTest { file, test } => write!(
                f,
                "proofs/{file} lists `{test}` under Checked by, but no such fn exists in tests/ or src/"
            ),
            Problem::DuplicateId { id, places } => {
                write!(f, "{id} is defined more than once: {}", places.join(", "))
            }
            Problem::BadFileName { file } => write!(
                f,
                "proofs/{file} is not named like `B07-short-slug.md` or `T21-short-slug.md`"
            ),
        }
    }
}

/// A text file: a path (for messages) and its contents.
pub struct Source {
    pub path: String,
    pub text: String,
}

/// Whether `s` is an ID: `B` or `T` followed by two or three digits (`B07`, `B104`).
fn is_id(s: &str) -> bool {
    let b = s.as_bytes();
    (b.len() == 3 || b.len() == 4)
        && (b[0] == b'B' || b[0] == b'T')
        && b[1..].iter().all(u8::is_ascii_digit)
}

/// The ID a proofs file name starts with (`B07-slug.md` → `B07`).
fn id_of_file_name(name: &str) -> Option<String> {
    let stem = name.strip_suffix(".md")?;
    let (id, slug) = stem.split_once('-')?;
    (is_id(id) && !slug.is_empty()).then(|| id.to_string())
}

/// Identifiers `name` of every `fn name` in `text`.
fn fn_names(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(pos) = rest.find("fn ") {
        let before_ok = pos == 0 || !is_ident_byte(rest.as_bytes()[pos - 1]);
        rest = &rest[pos + 3..];
        if !before_ok {
            continue;
        }
        let name: String = rest
            .trim_start()
            .chars()
            .take_while(|&c| c.is_ascii_alphanumeric() || c == '_')
            .collect();
        if !name.is_empty() {
            out.push(name);
        }
    }
    out
}

fn is_ident_byte(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

/// The ID a test name starts with (`t21_flip_terminates` → `T21`, `b104_…` → `B104`).
fn id_of_test_name(name: &str) -> Option<String> {
    let b = name.as_bytes();
    let digits = b.iter().skip(1).take_while(|c| c.is_ascii_digit()).count();
    let ok = (digits == 2 || digits == 3)
        && b.len() > digits + 2
        && (b[0] == b'b' || b[0] == b't')
        && b[digits + 1] == b'_';
    ok.then(|| name[..=digits].to_ascii_uppercase())
}

/// IDs cited by `proof:` comments in `text`, with their 1-based line numbers. A citation
/// may list several IDs: `// proof: B07, B08`.
fn proof_citations(text: &str) -> Vec<(String, usize)> {
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let mut rest = line;
        while let Some(pos) = rest.find("proof:") {
            rest = &rest[pos + "proof:".len()..];
            for word in rest
                .split([',', ' ', ';', ')', '('])
                .filter(|w| !w.is_empty())
            {
                let w = word.trim_end_matches(['.', ':']);
                if is_id(w) {
                    out.push((w.to_string(), i + 1));
                } else if w != "and" {
                    break;
                }
            }
        }
    }
    out
}

/// The test names listed in the **Checked by** section of a proofs file: every
/// back-quoted identifier (the last `::` segment of a path) up to the next heading.
fn checking_tests(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut inside = false;
    for line in text.lines() {
        let t = line.trim();
        let is_heading = t.starts_with('#') || (t.starts_with("**") && t.len() > 4);
        if is_heading {
            let lower = t.to_ascii_lowercase();
            let this = lower.trim_start_matches('#').trim_start();
            inside = this.starts_with("checked by") || this.starts_with("**checked by");
            if !inside {
                continue;
            }
        }
        if !inside {
            continue;
        }
        for (i, chunk) in t.split('`').enumerate() {
            if i % 2 == 0 {
                continue;
            }
            let last = chunk.rsplit("::").next().unwrap_or(chunk);
            let ident = !last.is_empty()
                && last.contains('_')
                && last
                    .bytes()
                    .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_');
            if ident {
                out.push(last.to_string());
            }
        }
    }
    out
}

/// The rows of the index table: (ID, file named in the row, 1-based line).
fn index_rows(index: &str) -> Vec<(String, String, usize)> {
    let mut out = Vec::new();
    for (i, line) in index.lines().enumerate() {
        let t = line.trim();
        if !t.starts_with('|') {
            continue;
        }
        let cells: Vec<&str> = t.trim_matches('|').split('|').map(str::trim).collect();
        let id = cells.first().copied().unwrap_or("").trim_matches('`');
        if !is_id(id) {
            continue; // header or separator row
        }
        let file_cell = cells.last().copied().unwrap_or("");
        let file = match file_cell.split_once("](") {
            Some((_, rest)) => rest.split(')').next().unwrap_or(""),
            None => file_cell.trim_matches(['`', '[', ']']),
        };
        let file = file.trim().trim_start_matches("./").to_string();
        out.push((id.to_string(), file, i + 1));
    }
    out
}

/// Check `index` (proofs/README.md), the proofs `files` (name without directory, text) and
/// the code `sources` (src/ and tests/ files) against the rules in the module docs.
pub fn check_consistency(index: &str, files: &[Source], sources: &[Source]) -> Vec<Problem> {
    let mut problems = Vec::new();

    // IDs that have a file; duplicates.
    let mut file_ids: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for f in files {
        match id_of_file_name(&f.path) {
            Some(id) => file_ids.entry(id).or_default().push(f.path.clone()),
            None => problems.push(Problem::BadFileName {
                file: f.path.clone(),
            }),
        }
    }
    for (id, places) in &file_ids {
        if places.len() > 1 {
            problems.push(Problem::DuplicateId {
                id: id.clone(),
                places: places.iter().map(|p| format!("proofs/{p}")).collect(),
            });
        }
    }

    // Index rows: duplicates, rows naming missing files, files without rows.
    let rows = index_rows(index);
    let mut row_ids: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut indexed_files = BTreeSet::new();
    for (id, file, line) in &rows {
        row_ids
            .entry(id.clone())
            .or_default()
            .push(format!("proofs/README.md:{line}"));
        let exists = files.iter().any(|f| &f.path == file);
        if !exists || id_of_file_name(file).as_deref() != Some(id.as_str()) {
            problems.push(Problem::IndexedFileMissing {
                id: id.clone(),
                file: file.clone(),
            });
        }
        indexed_files.insert(file.clone());
    }
    for (id, places) in &row_ids {
        if places.len() > 1 {
            problems.push(Problem::DuplicateId {
                id: id.clone(),
                places: places.clone(),
            });
        }
    }
    for f in files {
        if !indexed_files.contains(&f.path) {
            problems.push(Problem::FileNotIndexed {
                file: f.path.clone(),
            });
        }
    }

    // Citations in code and test names.
    let mut all_fns = BTreeSet::new();
    let mut reported = BTreeSet::new();
    for s in sources {
        for (id, line) in proof_citations(&s.text) {
            if !file_ids.contains_key(&id) && reported.insert((id.clone(), s.path.clone())) {
                problems.push(Problem::CitedWithoutFile {
                    id,
                    place: format!("{}:{line}", s.path),
                });
            }
        }
        for name in fn_names(&s.text) {
            if let Some(id) = id_of_test_name(&name) {
                if !file_ids.contains_key(&id) && reported.insert((id.clone(), s.path.clone())) {
                    problems.push(Problem::CitedWithoutFile {
                        id,
                        place: format!("fn {name} in {}", s.path),
                    });
                }
            }
            all_fns.insert(name);
        }
    }

    // Checked-by tests exist.
    for f in files {
        for test in checking_tests(&f.text) {
            if !all_fns.contains(&test) {
                problems.push(Problem::UnknownCheckingTest {
                    file: f.path.clone(),
                    test,
                });
            }
        }
    }
    problems
}

/// Every `.rs` file under `dir`, recursively, with its path relative to `root`.
fn rust_sources(root: &Path, dir: &Path, out: &mut Vec<Source>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut paths: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
    paths.sort();
    for p in paths {
        if p.is_dir() {
            rust_sources(root, &p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            let text = std::fs::read_to_string(&p).unwrap_or_default();
            let path = p.strip_prefix(root).unwrap_or(&p).display().to_string();
            out.push(Source { path, text });
        }
    }
}

#[test]
fn proofs_index_code_and_tests_are_consistent() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let proofs = root.join("proofs");
    let index = std::fs::read_to_string(proofs.join("README.md")).expect("proofs/README.md");
    let mut files = Vec::new();
    for entry in std::fs::read_dir(&proofs).expect("proofs/") {
        let p = entry.expect("proofs/ entry").path();
        let name = p
            .file_name()
            .unwrap_or_default()
            .to_string_lossy()
            .to_string();
        let is_md = p.extension().is_some_and(|x| x.eq_ignore_ascii_case("md"));
        if name == "README.md" || !is_md {
            continue;
        }
        let text = std::fs::read_to_string(&p).expect("proofs file");
        files.push(Source { path: name, text });
    }
    let mut sources = Vec::new();
    for d in ["src", "tests", "examples", "benches"] {
        rust_sources(root, &root.join(d), &mut sources);
    }
    // This file quotes citations in its negative control; it is not a citation itself.
    sources.retain(|s| !s.path.ends_with("tests/it/tidy.rs"));
    assert!(
        sources.iter().any(|s| s.path.starts_with("src")),
        "no sources found"
    );
    let problems = check_consistency(&index, &files, &sources);
    let listing: Vec<String> = problems.iter().map(ToString::to_string).collect();
    assert!(
        problems.is_empty(),
        "proofs/ is inconsistent:\n{}",
        listing.join("\n")
    );
}

/// Negative control: a synthetic broken tree, where each rule is violated once, is
/// rejected with exactly the expected problems.
#[test]
fn tidy_rejects_a_broken_synthetic_tree() {
    let index = "\
| ID | Statement | Status | File |
|---|---|---|---|
| B01 | a bound | proved here | [B01-a.md](B01-a.md) |
| B02 | a missing file | proved here | [B02-gone.md](B02-gone.md) |
| B01 | twice | proved here | B01-a.md |
";
    let files = vec![
        Source {
            path: "B01-a.md".into(),
            text: "**Status** proved here\n\n**Checked by** `b01_exists`, `tests/it/x.rs::b01_missing`\n\n**Limits** none `not_a_test_here`\n".into(),
        },
        Source {
            path: "T05-unindexed.md".into(),
            text: "**Checked by**\n- `t05_ok`\n".into(),
        },
        Source {
            path: "T05-again.md".into(),
            text: String::new(),
        },
        Source {
            path: "notes.md".into(),
            text: String::new(),
        },
    ];
    let sources = vec![
        Source {
            path: "src/a.rs".into(),
            text: "// proof: B01, B09\nfn f() {}\n".into(),
        },
        Source {
            path: "tests/it/x.rs".into(),
            text: "#[test]\nfn b01_exists() {}\n#[test]\nfn t05_ok() {}\nfn t33_orphan() {}\n"
                .into(),
        },
    ];
    let got = check_consistency(index, &files, &sources);
    let expected = vec![
        Problem::BadFileName {
            file: "notes.md".into(),
        },
        Problem::DuplicateId {
            id: "T05".into(),
            places: vec![
                "proofs/T05-unindexed.md".into(),
                "proofs/T05-again.md".into(),
            ],
        },
        Problem::IndexedFileMissing {
            id: "B02".into(),
            file: "B02-gone.md".into(),
        },
        Problem::DuplicateId {
            id: "B01".into(),
            places: vec!["proofs/README.md:3".into(), "proofs/README.md:5".into()],
        },
        Problem::FileNotIndexed {
            file: "T05-unindexed.md".into(),
        },
        Problem::FileNotIndexed {
            file: "T05-again.md".into(),
        },
        Problem::FileNotIndexed {
            file: "notes.md".into(),
        },
        Problem::CitedWithoutFile {
            id: "B09".into(),
            place: "src/a.rs:1".into(),
        },
        Problem::CitedWithoutFile {
            id: "T33".into(),
            place: "fn t33_orphan in tests/it/x.rs".into(),
        },
        Problem::UnknownCheckingTest {
            file: "B01-a.md".into(),
            test: "b01_missing".into(),
        },
    ];
    assert_eq!(got, expected);
}

/// The same checker accepts a consistent synthetic tree (so the negative control above
/// fails for the right reasons, not because the checker rejects everything).
#[test]
fn tidy_accepts_a_consistent_synthetic_tree() {
    let index = "| ID | S | St | File |\n|---|---|---|---|\n| B01 | s | proved here | [B01-a.md](B01-a.md) |\n";
    let files = vec![Source {
        path: "B01-a.md".into(),
        text: "## Checked by\n`b01_exists`\n## Limits\n`other_thing`\n".into(),
    }];
    let sources = vec![Source {
        path: "tests/it/x.rs".into(),
        text: "// proof: B01\n#[test]\nfn b01_exists() {}\n".into(),
    }];
    assert_eq!(check_consistency(index, &files, &sources), vec![]);
}
