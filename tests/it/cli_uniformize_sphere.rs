//! `penner uniformize --sphere` end to end (notes Thm 9; B74–B76, B90): the inscribed
//! polyhedron as OBJ, the `sphere_uniformization` claim re-checked by `penner certify`,
//! the planar disk as SVG, typed refusals, no overwriting.

use crate::support::{penner, scratch, text};
use serde_json::Value;
use std::fmt::Write as _;

/// A square bipyramid (apexes at heights `top`, `−bottom` over the unit square's corners
/// on the unit circle), written as OFF.
fn bipyramid_off(dir: &std::path::Path, name: &str, top: f64, bottom: f64) -> String {
    let pts = [
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [-1.0, 0.0, 0.0],
        [0.0, -1.0, 0.0],
        [0.0, 0.0, top],
        [0.0, 0.0, -bottom],
    ];
    let mut t = String::from("OFF\n6 8 0\n");
    for p in pts {
        let _ = writeln!(t, "{} {} {}", p[0], p[1], p[2]);
    }
    for k in 0..4 {
        let _ = writeln!(t, "3 {} {} 4", k, (k + 1) % 4);
        let _ = writeln!(t, "3 {} {} 5", (k + 1) % 4, k);
    }
    let p = dir.join(format!("{name}.off"));
    std::fs::write(&p, t).unwrap();
    p.display().to_string()
}

/// The `v` lines of an OBJ file.
fn obj_vertices(s: &str) -> Vec<[f64; 3]> {
    s.lines()
        .filter_map(|l| l.strip_prefix("v "))
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|x| x.parse().unwrap()).collect();
            [v[0], v[1], v[2]]
        })
        .collect()
}

#[test]
fn t24_cli_sphere_writes_an_inscribed_octahedron() {
    let d = scratch("uniformize-sphere");
    let surf = bipyramid_off(&d, "bip", 0.5, 2.0);
    let (res, obj, svg) = (d.join("r.json"), d.join("o.obj"), d.join("d.svg"));
    let args = [
        "uniformize",
        &surf,
        "--sphere",
        "-o",
        res.to_str().unwrap(),
        "--obj",
        obj.to_str().unwrap(),
        "--svg",
        svg.to_str().unwrap(),
    ];
    let out = penner(&args);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}{}",
        text(&out.stdout),
        text(&out.stderr)
    );
    let s = text(&out.stdout);
    assert!(
        s.contains("disk problem certified") && s.contains("numerical:"),
        "{s}"
    );
    // The closed form (B74): a regular octahedron, every edge √2 (tolerance B75).
    let objtext = std::fs::read_to_string(&obj).unwrap();
    let v = obj_vertices(&objtext);
    assert_eq!(v.len(), 6);
    let faces: Vec<Vec<usize>> = objtext
        .lines()
        .filter_map(|l| l.strip_prefix("f "))
        .map(|l| {
            l.split_whitespace()
                .map(|x| x.parse::<usize>().unwrap() - 1)
                .collect()
        })
        .collect();
    assert_eq!(faces.len(), 8);
    for f in &faces {
        for k in 0..3 {
            let (a, b) = (v[f[k]], v[f[(k + 1) % 3]]);
            let c = ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt();
            assert!((c - 2f64.sqrt()).abs() <= 1e-8, "chord {c}");
        }
    }
    // Negative control of that comparison: the input's own vertices (not inscribed).
    assert!((0.5f64.hypot(1.0) - 2f64.sqrt()).abs() > 1e-8);
    let doc: Value = serde_json::from_str(&std::fs::read_to_string(&res).unwrap()).unwrap();
    assert_eq!(doc["kind"], "sphere_uniformization");
    assert_eq!(doc["penner_claim"], 1);
    assert!(s.contains("certificate written"), "{s}");
    recheck_and_controls(&d, &res, &doc);
    let picture = std::fs::read_to_string(&svg).unwrap();
    assert!(picture.starts_with("<svg") && picture.matches("<polygon").count() == 4);
    // Never overwrite.
    let again = penner(&args);
    assert_eq!(again.status.code(), Some(4));
    assert!(text(&again.stderr).contains("exists"));
}

/// `penner certify` re-checks the written claim (B90): holds; a free `u` moved by `10⁻⁴`
/// is not certified (exit 2, never `fails`); a value at the pole or a flip of a star edge
/// is bad input naming the field (exit 3).
fn recheck_and_controls(d: &std::path::Path, res: &std::path::Path, doc: &Value) {
    let out = penner(&["certify", res.to_str().unwrap()]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}{}",
        text(&out.stdout),
        text(&out.stderr)
    );
    let answer: Value = serde_json::from_str(&text(&out.stdout)).unwrap();
    assert_eq!(answer["verdict"], "holds");
    assert_eq!(answer["kind"], "sphere_uniformization");
    let free = doc["u"]
        .as_array()
        .unwrap()
        .iter()
        .position(|x| !x.is_null())
        .expect("a free vertex");
    let pole = doc["pole"].as_u64().unwrap() as usize;
    let bad = d.join("bad.json");
    let mut moved = doc.clone();
    let x = penner::io::json::exact_number(&doc["u"][free], "u")
        .unwrap()
        .to_f64();
    moved["u"][free] = Value::String(format!("{}", x + 1e-4));
    std::fs::write(&bad, moved.to_string()).unwrap();
    let out = penner(&["certify", bad.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stdout));
    let answer: Value = serde_json::from_str(&text(&out.stdout)).unwrap();
    assert_eq!(answer["verdict"], "undecided");
    let mut at_pole = doc.clone();
    at_pole["u"][pole] = Value::String("0".into());
    std::fs::write(&bad, at_pole.to_string()).unwrap();
    let out = penner(&["certify", bad.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stdout));
    assert!(
        text(&out.stdout).contains(&format!("u[{pole}]")),
        "{}",
        text(&out.stdout)
    );
    let mut range = doc.clone();
    range["flips"] = serde_json::json!([100000]);
    std::fs::write(&bad, range.to_string()).unwrap();
    let out = penner(&["certify", bad.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(3), "{}", text(&out.stdout));
    assert!(
        text(&out.stderr).contains("flips[0]"),
        "{}",
        text(&out.stderr)
    );
}

/// `--precision 256`: refined in MPFR and certified at 256 bits for the exact input
/// (positions of an OFF file); the claim re-checks at 256 bits. `--precision dd` is refused
/// by name.
#[test]
fn b91_cli_sphere_refines_and_certifies_at_256_bits() {
    let d = scratch("uniformize-sphere-256");
    let surf = bipyramid_off(&d, "bip", 0.7, 1.3);
    let res = d.join("c.json");
    let out = penner(&[
        "uniformize",
        &surf,
        "--sphere",
        "--precision",
        "256",
        "-o",
        res.to_str().unwrap(),
    ]);
    let s = text(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{s}{}", text(&out.stderr));
    assert!(
        s.contains("refined at 256 bits") && s.contains("(256-bit intervals)"),
        "{s}"
    );
    let doc: Value = serde_json::from_str(&std::fs::read_to_string(&res).unwrap()).unwrap();
    assert_eq!(doc["max_bits"], 256);
    let out = penner(&["certify", res.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));
    let answer: Value = serde_json::from_str(&text(&out.stdout)).unwrap();
    assert!(
        answer["max_discrepancy"].as_f64().unwrap() < 1e-50,
        "{answer}"
    );
    let out = penner(&["uniformize", &surf, "--sphere", "--precision", "dd"]);
    assert_eq!(out.status.code(), Some(3));
    assert!(
        text(&out.stderr).contains("--precision dd"),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn t24_cli_sphere_bad_input_is_typed() {
    let d = scratch("uniformize-sphere-bad");
    let surf = bipyramid_off(&d, "bip", 1.0, 1.0);
    let out = penner(&["uniformize", &surf, "--sphere", "--pole", "99"]);
    assert_eq!(out.status.code(), Some(3));
    assert!(
        text(&out.stderr).contains("pole v99"),
        "{}",
        text(&out.stderr)
    );
    let (m, l) = crate::meshgen::jittered_torus(5, 5, 1);
    let metric = penner::io::Metric::Lengths(
        l.iter()
            .map(|&x| rug::Rational::from_f64(x).unwrap())
            .collect(),
    );
    let s = penner::io::Surface::new("torus", m, metric, None).unwrap();
    let p = d.join("torus.json");
    std::fs::write(&p, penner::io::json::write(&s)).unwrap();
    let out = penner(&["uniformize", p.to_str().unwrap(), "--sphere"]);
    assert_eq!(out.status.code(), Some(3));
    assert!(
        text(&out.stderr).contains("genus 0"),
        "{}",
        text(&out.stderr)
    );
}
