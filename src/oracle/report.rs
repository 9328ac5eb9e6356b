//! Reports: rows of verdicts rendered as a table for people or JSON for programs, and the
//! overall status they add up to.

use super::registry::{Outcome, Row};
use crate::theorems::Verdict;
use serde_json::{json, Value};
use std::fmt::Write as _;

/// What a list of rows adds up to, worst first.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Status {
    /// Every check holds or does not apply.
    Holds,
    /// Some check is undecided and none fails.
    Undecided,
    /// Some check fails.
    Fails,
    /// Some check broke (a library defect).
    Crashed,
}

/// The status of one row.
pub fn row_status(row: &Row) -> Status {
    match &row.outcome {
        Outcome::Crashed(_) => Status::Crashed,
        Outcome::Verdict(Verdict::Fails { .. }) => Status::Fails,
        Outcome::Verdict(Verdict::Undecided { .. }) => Status::Undecided,
        Outcome::Verdict(Verdict::Holds { .. } | Verdict::NotApplicable { .. }) => Status::Holds,
    }
}

/// The worst status over all rows (`Holds` for none).
pub fn status(rows: &[Row]) -> Status {
    rows.iter().map(row_status).max().unwrap_or(Status::Holds)
}

/// The verdict word: `holds`, `fails`, `undecided`, `n/a` or `ERROR`.
pub fn verdict_word(o: &Outcome) -> &'static str {
    match o {
        Outcome::Verdict(Verdict::Holds { .. }) => "holds",
        Outcome::Verdict(Verdict::Fails { .. }) => "fails",
        Outcome::Verdict(Verdict::Undecided { .. }) => "undecided",
        Outcome::Verdict(Verdict::NotApplicable { .. }) => "n/a",
        Outcome::Crashed(_) => "ERROR",
    }
}

/// `certified`, `numerical` or `-` (no claim either way).
fn certified_word(o: &Outcome) -> &'static str {
    match o {
        Outcome::Verdict(Verdict::Holds { certified, .. } | Verdict::Fails { certified, .. }) => {
            if *certified {
                "certified"
            } else {
                "numerical"
            }
        }
        _ => "-",
    }
}

/// The largest error of a row: `max_error` when it holds, the largest witness value
/// when it fails or is undecided.
fn largest_error(o: &Outcome) -> Option<f64> {
    match o {
        Outcome::Verdict(Verdict::Holds { max_error, .. }) => Some(*max_error),
        Outcome::Verdict(
            Verdict::Fails { witnesses, .. } | Verdict::Undecided { witnesses, .. },
        ) => witnesses.iter().map(|w| w.value.abs()).reduce(f64::max),
        _ => None,
    }
}

/// A short note for the last column: the first witness, the reason for `n/a`, the
/// precision an undecided check stopped at, or the defect.
fn note(o: &Outcome) -> String {
    match o {
        Outcome::Verdict(Verdict::Fails { witnesses, .. }) => match witnesses.first() {
            Some(w) => format!(
                "{} witness(es); first {}: {}",
                witnesses.len(),
                w.element,
                w.detail
            ),
            None => String::new(),
        },
        Outcome::Verdict(Verdict::Undecided {
            bits_tried,
            witnesses,
        }) => format!(
            "{} element(s) undecided up to {bits_tried} bits",
            witnesses.len()
        ),
        Outcome::Verdict(Verdict::NotApplicable { reason }) => reason.clone(),
        Outcome::Verdict(Verdict::Holds { .. }) => String::new(),
        Outcome::Crashed(m) => format!("internal error: {m}"),
    }
}

fn sci(x: Option<f64>) -> String {
    match x {
        Some(0.0) => "0".to_string(),
        Some(v) => format!("{v:.1e}"),
        None => "-".to_string(),
    }
}

fn millis(s: f64) -> String {
    if s < 0.001 {
        "<1 ms".to_string()
    } else if s < 10.0 {
        format!("{:.0} ms", s * 1e3)
    } else {
        format!("{s:.1} s")
    }
}

/// Render rows as an aligned text table, grouped by case.
pub fn table(rows: &[Row]) -> String {
    let header = [
        "theorem",
        "precision",
        "verdict",
        "certified",
        "largest error",
        "time",
        "note",
    ];
    let mut out = String::new();
    let mut i = 0;
    while i < rows.len() {
        let case = &rows[i].case;
        let j = rows[i..]
            .iter()
            .position(|r| &r.case != case)
            .map_or(rows.len(), |k| i + k);
        let cells: Vec<[String; 7]> = rows[i..j]
            .iter()
            .map(|r| {
                [
                    format!("{} {}", r.id, r.title),
                    r.precision.to_string(),
                    verdict_word(&r.outcome).to_string(),
                    certified_word(&r.outcome).to_string(),
                    sci(largest_error(&r.outcome)),
                    millis(r.seconds),
                    note(&r.outcome),
                ]
            })
            .collect();
        let mut width = header.map(|h| h.chars().count());
        for c in &cells {
            for (w, s) in width.iter_mut().zip(c) {
                *w = (*w).max(s.chars().count());
            }
        }
        let _ = writeln!(out, "{}", shown_name(case));
        let line = |cols: &[&str]| {
            let mut l = String::from(" ");
            for (k, s) in cols.iter().enumerate() {
                let pad = width[k].saturating_sub(s.chars().count());
                l.push(' ');
                l.push_str(s);
                if k + 1 < cols.len() {
                    l.push_str(&" ".repeat(pad + 1));
                }
            }
            l.trim_end().to_string()
        };
        let _ = writeln!(out, "{}", line(&header));
        for c in &cells {
            let refs: Vec<&str> = c.iter().map(String::as_str).collect();
            let _ = writeln!(out, "{}", line(&refs));
        }
        out.push('\n');
        i = j;
    }
    out
}

/// Longest case name printed in full in a report; longer names are cut there (with the
/// byte count), so a huge name cannot multiply into every row.
pub const SHOWN_NAME_CHARS: usize = 256;

/// `name`, or its first [`SHOWN_NAME_CHARS`] characters and the size of the rest.
pub fn shown_name(name: &str) -> std::borrow::Cow<'_, str> {
    match name.char_indices().nth(SHOWN_NAME_CHARS) {
        None => std::borrow::Cow::Borrowed(name),
        Some((cut, _)) => std::borrow::Cow::Owned(format!(
            "{}… ({} more bytes)",
            &name[..cut],
            name.len() - cut
        )),
    }
}

/// One row as JSON: case, theorem, title, precision, verdict (with its fields), time.
pub fn row_json(r: &Row) -> Value {
    let verdict = match &r.outcome {
        Outcome::Verdict(v) => serde_json::to_value(v).unwrap_or(Value::Null),
        Outcome::Crashed(m) => json!({ "verdict": "error", "message": m }),
    };
    json!({
        "case": shown_name(&r.case),
        "theorem": r.id,
        "title": r.title,
        "precision": r.precision.to_string(),
        "precision_bits": r.precision.bits(),
        "result": verdict,
        "seconds": r.seconds,
    })
}

/// Rows as a JSON document `{ "penner_report": 1, "status": …, "rows": [...] }`.
pub fn json(rows: &[Row]) -> Value {
    let st = match status(rows) {
        Status::Holds => "holds",
        Status::Undecided => "undecided",
        Status::Fails => "fails",
        Status::Crashed => "error",
    };
    json!({
        "penner_report": 1,
        "status": st,
        "rows": rows.iter().map(row_json).collect::<Vec<_>>(),
    })
}
