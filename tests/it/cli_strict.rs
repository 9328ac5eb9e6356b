//! Strict reading end to end: a misspelt or foreign field and a repeated key are bad input
//! (exit 3, a message naming the key) in claims, in surface files, in failure files and in
//! scale-factor files. Each refusal is paired with the same input made correct, which
//! passes.
//! The claim schema closes the same objects as the reader.

use crate::cli::tetrahedron_json;
use crate::support::{assert_refused, certify_expecting, penner, scratch, text, write};
use penner::io::json::from_value;
use penner::oracle::claim::parse_value;
use serde_json::{json, Value};
use std::path::Path;

/// The rhombus with unit sides and diagonal v0–v2 of 19/10: Euclidean flipping to
/// Delaunay gives the diagonal v1–v3 of length √(4 − 1.9²) = √0.39.
fn rhombus_flip_claim(eps_key: &str) -> Value {
    let mut c = json!({"penner_claim": 1, "kind": "delaunay_flip", "flips": "euclidean",
        "surface": {"vertices": 4, "faces": [[0,1,2],[0,2,3]], "lengths": ["1","1","19/10","1","1"]},
        // √0.39 to 30 digits (Python decimal): within 1e-25 of the flipped diagonal.
        "result": {"vertices": 4, "faces": [[0,1,3],[1,2,3]],
                   "lengths": ["1", "0.624499799839839820584689312094", "1", "1", "1"]}});
    c[eps_key] = json!("1e-25");
    c
}

#[test]
fn certify_refuses_a_misspelt_optional_field() {
    let d = scratch("strict-misspelt");
    // The true claim holds; with `epsilon` misspelt, ε would silently be 0 and the
    // irrational diagonal would refute it.
    certify_expecting(&d, "good.json", &rhombus_flip_claim("epsilon"), 0, "holds");
    let (_, err) = certify_expecting(
        &d,
        "misspelt.json",
        &rhombus_flip_claim("epsilom"),
        3,
        "bad_input",
    );
    assert!(
        err.contains("epsilom") && err.contains("unknown field") && err.contains("misspelt.json"),
        "{err}"
    );
    // A field of another kind, and a tolerance on the exact kind that has none.
    let mut c =
        json!({"penner_claim": 1, "kind": "intrinsic_delaunay", "surface": tetrahedron_json()});
    certify_expecting(&d, "delaunay.json", &c, 0, "holds");
    c["epsilon"] = json!("1e-9");
    let (_, err) = certify_expecting(&d, "delaunay-eps.json", &c, 3, "bad_input");
    assert!(
        err.contains("epsilon") && err.contains("not a field of intrinsic_delaunay"),
        "{err}"
    );
    // An unknown field inside an embedded surface names the surface.
    let mut c = rhombus_flip_claim("epsilon");
    c["result"]["lenghts"] = c["result"]["lengths"].clone();
    let (_, err) = certify_expecting(&d, "surface-field.json", &c, 3, "bad_input");
    assert!(err.contains("result") && err.contains("lenghts"), "{err}");
}

/// Run `penner certify` on raw claim text; (exit code, answer, stderr).
fn certify_text(dir: &Path, name: &str, claim: &str) -> (Option<i32>, Value, String) {
    let p = write(dir, name, claim.as_bytes());
    let out = penner(&["certify", &p.display().to_string()]);
    let answer = serde_json::from_slice(&out.stdout).unwrap_or(Value::Null);
    (out.status.code(), answer, text(&out.stderr))
}

const TET: &str = r#"{"vertices": 4, "faces": [[0,1,2],[0,2,3],[0,3,1],[1,3,2]], "lengths": ["1","1","1","1","1","1"]}"#;
const PI: &str = "3.14159265358979323846264338327950288";

#[test]
fn certify_refuses_a_repeated_key() {
    let d = scratch("strict-duplicate");
    let angles = format!(r#"["{PI}", "{PI}", "{PI}", "{PI}"]"#);
    // Top level: a second `epsilon` of 0 would refute what the first lets hold.
    let good = format!(
        r#"{{"penner_claim": 1, "kind": "cone_angles", "surface": {TET}, "angles": {angles}, "epsilon": "1e-30"}}"#
    );
    let (code, a, err) = certify_text(&d, "good.json", &good);
    assert_eq!(
        (code, a["verdict"].as_str()),
        (Some(0), Some("holds")),
        "{err}"
    );
    let twice = good.replace(
        r#""epsilon": "1e-30""#,
        r#""epsilon": "1e-30", "epsilon": "0""#,
    );
    let (code, a, err) = certify_text(&d, "twice.json", &twice);
    assert_eq!(
        (code, a["verdict"].as_str()),
        (Some(3), Some("bad_input")),
        "{err}"
    );
    assert!(
        err.contains("duplicate key \"epsilon\"") && err.contains("twice.json"),
        "{err}"
    );
    assert!(!err.contains("panicked"), "{err}");
    // Inside the surface, on a later line: the message names the key, the object and the line.
    let nested = good.replace(
        r#""lengths": ["1","1","1","1","1","1"]}"#,
        "\"lengths\": [\"1\",\"1\",\"1\",\"1\",\"1\",\"1\"],\n\"lengths\": [\"2\",\"2\",\"2\",\"2\",\"2\",\"2\"]}",
    );
    assert_ne!(nested, good);
    let (code, _, err) = certify_text(&d, "nested.json", &nested);
    assert_eq!(code, Some(3), "{err}");
    assert!(
        err.contains("\"lengths\"") && err.contains("in surface") && err.contains("line 2"),
        "{err}"
    );
}

#[test]
fn surface_failure_and_scale_factor_files_refuse_repeated_keys_and_unknown_fields() {
    let d = scratch("strict-files");
    let tet = serde_json::to_string(&tetrahedron_json()).unwrap();
    let good = write(&d, "tet.json", tet.as_bytes());
    let out = penner(&["check", &good.display().to_string(), "--precision", "f64"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let body = &tet[1..];
    for (name, bytes, mentions) in [
        (
            "twice.json",
            format!("{{\"vertices\": 9,\n{body}"),
            vec!["twice.json", "duplicate key \"vertices\"", "line 2"],
        ),
        (
            "misspelt.json",
            tet.replace("\"lengths\"", "\"length\""),
            vec!["misspelt.json", "length", "unknown field"],
        ),
    ] {
        let p = write(&d, name, bytes.as_bytes());
        for cmd in ["check", "delaunay"] {
            let out = penner(&[cmd, &p.display().to_string()]);
            assert_refused(&out, 3, &mentions);
            assert!(
                text(&out.stdout).is_empty(),
                "{cmd} {name}: {}",
                text(&out.stdout)
            );
        }
    }
    // Failure files (`penner replay`) and scale factors (`penner delaunay --scale-factors`).
    let p = write(
        &d,
        "f.penner-failure-1.json",
        br#"{"penner_failure": 1, "check": "T01", "check": "T05"}"#,
    );
    assert_refused(
        &penner(&["replay", &p.display().to_string()]),
        3,
        &["duplicate key \"check\""],
    );
    let p = write(
        &d,
        "g.penner-failure-1.json",
        br#"{"penner_failure": 1, "chekc": "T01"}"#,
    );
    assert_refused(
        &penner(&["replay", &p.display().to_string()]),
        3,
        &["chekc", "unknown field"],
    );
    let u = write(&d, "u.json", br#"[0, 0, {"a": 1, "a": 2}, 0]"#);
    let out = penner(&[
        "delaunay",
        &good.display().to_string(),
        "--precision",
        "f64",
        "--scale-factors",
        &u.display().to_string(),
    ]);
    assert_refused(&out, 3, &["u.json", "duplicate key \"a\"", "[2]"]);
}

/// The claim schema, parsed.
fn schema() -> Value {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/schema/claim-v1.schema.json");
    serde_json::from_str(&std::fs::read_to_string(path).expect("schema file")).expect("schema JSON")
}

/// The schema and the reader close the same objects: for every claim kind, a field is
/// refused by name exactly when the schema's `propertyNames` for that kind leave it out,
/// and a surface field exactly when the surface definition does not list it.
#[test]
fn schema_and_reader_agree_on_the_fields_of_every_kind_and_of_surfaces() {
    let s = schema();
    assert_eq!(s["additionalProperties"], json!(false));
    // A surface is a triangulation (closed object) with a metric; circle claims need only the
    // triangulation, every other kind the metric too (the one extra `allOf` entry below).
    assert_eq!(
        s["$defs"]["surface"]["allOf"][0]["$ref"],
        json!("#/$defs/triangulation")
    );
    assert_eq!(
        s["$defs"]["triangulation"]["additionalProperties"],
        json!(false)
    );
    let every: Vec<String> = s["properties"]
        .as_object()
        .unwrap()
        .keys()
        .cloned()
        .chain(["epsilom".to_string(), "weight".to_string()])
        .collect();
    let kinds = s["properties"]["kind"]["enum"].as_array().unwrap();
    // The per-kind rules; the one rule over several kinds (`enum`) is the metric requirement.
    let per_kind = s["allOf"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|rule| rule["if"]["properties"]["kind"]["const"].is_string());
    for rule in per_kind {
        let kind = rule["if"]["properties"]["kind"]["const"].as_str().unwrap();
        let allowed: Vec<&str> = rule["then"]["propertyNames"]["enum"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_str().unwrap())
            .collect();
        assert!(kinds.contains(&json!(kind)));
        for field in &every {
            let mut c = json!({"penner_claim": 1, "kind": kind, "surface": tetrahedron_json()});
            if c.get(field).is_none() {
                c[field] = json!("0");
            }
            let refused = match parse_value(&c) {
                Ok(_) => false,
                Err(e) => {
                    let e = e.to_string();
                    e.starts_with(&format!("{field}: unknown field"))
                        || e.starts_with(&format!("{field}: not a field of {kind}"))
                }
            };
            assert_eq!(
                refused,
                !allowed.contains(&field.as_str()),
                "{kind}: {field}"
            );
        }
    }
    assert_eq!(s["allOf"].as_array().unwrap().len(), kinds.len() + 1);
    // Surfaces: every listed field is read, an unlisted one is refused by name.
    let listed = s["$defs"]["triangulation"]["properties"]
        .as_object()
        .unwrap();
    for field in listed
        .keys()
        .map(String::as_str)
        .chain(["lenghts", "gluings"])
    {
        let mut surface = tetrahedron_json();
        if surface.get(field).is_none() {
            surface[field] = json!(null);
        }
        let refused = match from_value(&surface) {
            Ok(_) => false,
            Err(e) => e
                .to_string()
                .starts_with(&format!("{field}: unknown field")),
        };
        assert_eq!(
            refused,
            !listed.contains_key(field),
            "surface field {field}"
        );
    }
}
