//! The strict JSON reader (`penner::io::strict_json`) on random documents: without a
//! repeated key it gives exactly `serde_json`'s value; with one it names the first repeated
//! key in text order, its object and its line. The documents are built here as trees and
//! written out by hand, so where the first repeat sits is known without parsing.

use crate::support::cases;
use penner::io::strict_json::{parse, JsonError};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::fmt::Write as _;

/// A JSON value as written: objects keep their entries in order, repeats included.
enum Doc {
    Num(i64),
    Str(String),
    Arr(Vec<Doc>),
    Obj(Vec<(String, Doc)>),
}

fn random_doc(rng: &mut ChaCha8Rng, depth: u32) -> Doc {
    match rng.gen_range(0..if depth == 0 { 2 } else { 4 }) {
        0 => Doc::Num(rng.gen_range(-1000..1000)),
        1 => Doc::Str(["x", "y", "é", "a\\\"b"][rng.gen_range(0..4)].to_string()),
        2 => Doc::Arr(
            (0..rng.gen_range(0..4))
                .map(|_| random_doc(rng, depth - 1))
                .collect(),
        ),
        _ => Doc::Obj(
            (0..rng.gen_range(0..5))
                .map(|_| {
                    // Five keys, so repeats are common but not the rule.
                    let key = ["a", "b", "c", "lengths", "epsilon"][rng.gen_range(0..5)];
                    (key.to_string(), random_doc(rng, depth - 1))
                })
                .collect(),
        ),
    }
}

/// The first repeated key in text order: (object path, key, 1-based line).
type Repeat = (String, String, usize);

/// Write `doc` at `path`, every object key on a new line; record the first repeat.
fn write(doc: &Doc, path: &str, out: &mut String, first: &mut Option<Repeat>) {
    match doc {
        Doc::Num(n) => out.push_str(&n.to_string()),
        Doc::Str(s) => {
            out.push('"');
            out.push_str(s);
            out.push('"');
        }
        Doc::Arr(items) => {
            out.push('[');
            for (i, x) in items.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                write(x, &format!("{path}[{i}]"), out, first);
            }
            out.push(']');
        }
        Doc::Obj(entries) => {
            out.push('{');
            for (i, (k, v)) in entries.iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                out.push('\n');
                if first.is_none() && entries[..i].iter().any(|(j, _)| j == k) {
                    let line = out.matches('\n').count() + 1;
                    *first = Some((path.to_string(), k.clone(), line));
                }
                write!(out, "{k:?}: ").expect("writing to a String");
                let child = if path.is_empty() {
                    k.clone()
                } else {
                    format!("{path}.{k}")
                };
                write(v, &child, out, first);
            }
            out.push('}');
        }
    }
}

#[test]
fn strict_json_equals_serde_json_or_names_the_first_repeated_key() {
    let mut rng = ChaCha8Rng::seed_from_u64(0x150);
    let (mut clean, mut repeated) = (0, 0);
    for _ in 0..cases(3000, 200_000) {
        let doc = Doc::Obj(vec![
            ("surface".to_string(), random_doc(&mut rng, 3)),
            ("kind".to_string(), random_doc(&mut rng, 3)),
        ]);
        let mut text = String::new();
        let mut first = None;
        write(&doc, "", &mut text, &mut first);
        // serde_json accepts every document, repeats or not (the last value wins).
        let loose: serde_json::Value = serde_json::from_str(&text).expect("valid JSON");
        match (parse(&text), first) {
            (Ok(v), None) => {
                clean += 1;
                assert_eq!(v, loose, "{text}");
            }
            (Err(JsonError::DuplicateKey(d)), Some((object, key, line))) => {
                repeated += 1;
                assert_eq!((d.object, d.key, d.line), (object, key, line), "{text}");
            }
            (got, want) => panic!("{text}\ngot {got:?}, want repeat {want:?}"),
        }
    }
    assert!(
        clean > 300 && repeated > 300,
        "{clean} clean, {repeated} repeated"
    );
}

#[test]
fn strict_json_refuses_what_serde_json_refuses() {
    for text in [
        "",
        "{",
        r#"{"a": 1,}"#,
        r#"{"a": 1} x"#,
        "[1, 2",
        r#"{"a" 1}"#,
        "nan",
        &"[".repeat(200),
    ] {
        assert!(serde_json::from_str::<serde_json::Value>(text).is_err());
        assert!(matches!(parse(text), Err(JsonError::Syntax(_))), "{text}");
    }
    // Negative control: the same reader accepts well-formed text, with the repeat elsewhere.
    assert!(parse(r#"{"a": {"a": 1}, "b": [{"a": 2}, {"a": 3}]}"#).is_ok());
}
