//! `penner uniformize --sphere` end to end (notes Thm 9; B74–B76): the inscribed polyhedron
//! as OBJ, the result JSON, the planar disk as SVG, typed refusals, no overwriting.

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
    assert_eq!(doc["disk_certificate"]["certified"], true);
    assert_eq!(doc["planar_delaunay"]["certified"], true);
    let picture = std::fs::read_to_string(&svg).unwrap();
    assert!(picture.starts_with("<svg") && picture.matches("<polygon").count() == 4);
    // Never overwrite.
    let again = penner(&args);
    assert_eq!(again.status.code(), Some(4));
    assert!(text(&again.stderr).contains("exists"));
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
