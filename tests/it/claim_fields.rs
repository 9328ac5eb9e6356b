//! Every field a claim's re-check must use is used: a certificate written by `penner
//! uniformize -o` holds under `penner certify`, and the same claim with one field altered
//! — the radius, the residual bound, a flip, a final face, the targets, the pole — is never
//! `holds` (issue: the claim re-checks of every kind).

use crate::meshgen::jittered_torus;
use crate::support::{penner, scratch, text};
use crate::uniformization::noisy_sphere;
use penner::io::{json, Metric, Surface};
use penner::mesh::Mesh;
use rug::Rational;
use serde_json::Value;
use std::path::Path;

fn surface_file(dir: &Path, name: &str, m: Mesh, l: &[f64]) -> String {
    let metric = Metric::Lengths(l.iter().map(|&x| Rational::from_f64(x).unwrap()).collect());
    let s = Surface::new(name, m, metric, None).unwrap();
    let p = dir.join(format!("{name}.json"));
    std::fs::write(&p, json::write(&s)).unwrap();
    p.display().to_string()
}

/// The verdict of `penner certify` on `claim` (written to a scratch file), and its exit.
fn certify(dir: &Path, claim: &Value) -> (String, Option<i32>) {
    let p = dir.join("altered.json");
    let _ = std::fs::remove_file(&p);
    std::fs::write(&p, claim.to_string()).unwrap();
    let out = penner(&["certify", &p.display().to_string()]);
    let verdict = serde_json::from_str::<Value>(&text(&out.stdout))
        .ok()
        .and_then(|v| v["verdict"].as_str().map(str::to_string))
        .unwrap_or_else(|| format!("(no answer: {})", text(&out.stderr)));
    (verdict, out.status.code())
}

/// Write the certificate of `penner uniformize SURFACE ARGS -o cert.json` and read it.
fn certificate(dir: &Path, surface: &str, args: &[&str]) -> Value {
    let cert = dir.join("cert.json").display().to_string();
    let mut a = vec!["uniformize", surface];
    a.extend_from_slice(args);
    a.extend_from_slice(&["-o", &cert]);
    let out = penner(&a);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}{}",
        text(&out.stdout),
        text(&out.stderr)
    );
    serde_json::from_str(&std::fs::read_to_string(&cert).unwrap()).unwrap()
}

/// Assert that every alteration of `claim` is not `holds`, and the claim itself is.
fn each_field_is_used(dir: &Path, claim: &Value, alterations: &[(&str, Value)]) {
    for field in ["radius", "residual_bound", "final_faces", "u"] {
        assert!(claim.get(field).is_some(), "the claim has no `{field}`");
    }
    let (v, code) = certify(dir, claim);
    assert_eq!(
        (v.as_str(), code),
        ("holds", Some(0)),
        "the unaltered claim"
    );
    for (what, altered) in alterations {
        let (v, code) = certify(dir, altered);
        assert_ne!(v, "holds", "{what}: altered claim still holds");
        assert_ne!(code, Some(0), "{what}: exit 0");
    }
}

fn with(claim: &Value, f: impl FnOnce(&mut Value)) -> Value {
    let mut c = claim.clone();
    f(&mut c);
    c
}

#[test]
fn uniformization_claim_fields_radius_residual_flips_faces_targets_are_each_used() {
    let d = scratch("claim-fields-torus");
    let (m, l) = jittered_torus(5, 6, 2);
    let surf = surface_file(&d, "torus", m, &l);
    let claim = certificate(&d, &surf, &["--flat"]);
    let flips = claim["flips"].as_array().cloned().unwrap_or_default();
    let mut alterations = vec![
        (
            "radius shrunk to 1e-200",
            with(&claim, |c| c["radius"] = Value::String("1e-200".into())),
        ),
        (
            "residual bound 0",
            with(&claim, |c| c["residual_bound"] = Value::String("0".into())),
        ),
        (
            "a final face's corners swapped",
            with(&claim, |c| {
                let f = &mut c["final_faces"][0];
                let (a, b) = (f[0].clone(), f[1].clone());
                f[0] = b;
                f[1] = a;
            }),
        ),
        (
            "targets moved by π/100 between two vertices",
            with(&claim, |c| {
                c["targets"][0] = Value::String("201/100".into());
                c["targets"][1] = Value::String("199/100".into());
            }),
        ),
    ];
    if flips.is_empty() {
        alterations.push((
            "a flip added",
            with(&claim, |c| c["flips"] = serde_json::json!([0])),
        ));
    } else {
        alterations.push((
            "the last flip dropped",
            with(&claim, |c| {
                c["flips"].as_array_mut().unwrap().pop();
            }),
        ));
    }
    each_field_is_used(&d, &claim, &alterations);
}

#[test]
fn sphere_uniformization_claim_fields_pole_flips_radius_residual_faces_are_each_used() {
    let d = scratch("claim-fields-sphere");
    let (m, l) = noisy_sphere(1, 7);
    let surf = surface_file(&d, "sphere", m, &l);
    let claim = certificate(&d, &surf, &["--sphere"]);
    let n = claim["u"].as_array().map_or(0, Vec::len);
    let pole = claim["pole"].as_u64().expect("the claim names its pole");
    let other_pole = (0..n as u64).find(|&v| v != pole).unwrap();
    let mut alterations = vec![
        (
            "radius shrunk to 1e-200",
            with(&claim, |c| c["radius"] = Value::String("1e-200".into())),
        ),
        (
            "residual bound 0",
            with(&claim, |c| c["residual_bound"] = Value::String("0".into())),
        ),
        (
            "another pole",
            with(&claim, |c| c["pole"] = serde_json::json!(other_pole)),
        ),
        (
            "a final face's corners swapped",
            with(&claim, |c| {
                let f = &mut c["final_faces"][0];
                let (a, b) = (f[0].clone(), f[1].clone());
                f[0] = b;
                f[1] = a;
            }),
        ),
    ];
    for field in ["flips", "euclidean_flips"] {
        if claim[field].as_array().is_some_and(|a| !a.is_empty()) {
            alterations.push((
                field,
                with(&claim, |c| {
                    c[field].as_array_mut().unwrap().pop();
                }),
            ));
        }
    }
    each_field_is_used(&d, &claim, &alterations);
}

/// The views that stream a claim and its surface into a file (`ClaimJson`,
/// `SurfaceJson`) write the format of their values: the streamed text, read by
/// serde_json into a value (whose maps sort their keys) and printed again, is the same
/// text, so the keys were emitted in sorted order and nothing else differs; the streamed
/// claim holds under `penner certify`, and the streamed surface reads back through the
/// project's reader to the same surface. Control: the text with two keys swapped does not
/// survive the same round trip.
#[test]
fn streamed_claim_and_surface_views_write_the_sorted_value_text() {
    use penner::io::json::SurfaceJson;
    use penner::mesh::builders;
    use penner::uniformization::pipeline::{uniformize_closed, Options, Precision};
    use penner::uniformization::targets::Targets;
    let s = Surface::from_embedded("icosahedron", builders::icosahedron()).unwrap();
    let mut t = vec![Rational::from(2); s.mesh.n_vertices()];
    for v in [0, 3, 6, 9] {
        t[v] = Rational::from(1);
    }
    let opts = Options {
        precision: Precision::Mpfr(128),
        certify: true,
    };
    let out = uniformize_closed(&s, &Targets::from_multiples_of_pi(t), &opts, &mut |_| {}).unwrap();
    let claim = out.claim_json().expect("certified");
    let reprinted = |text: &str| {
        serde_json::to_string_pretty(&serde_json::from_str::<Value>(text).unwrap()).unwrap()
    };
    let streamed = serde_json::to_string_pretty(&claim).unwrap();
    assert_eq!(reprinted(&streamed), streamed);
    let surface = serde_json::to_string_pretty(&SurfaceJson(&s)).unwrap();
    assert_eq!(reprinted(&surface), surface);
    assert!(surface.contains("\"positions\"") && surface.contains("\"squared_lengths\""));
    let back = json::from_value(&serde_json::from_str(&surface).unwrap()).unwrap();
    assert_eq!(back.mesh.face_list(), s.mesh.face_list());
    assert_eq!(back.metric, s.metric);
    assert_eq!(back.positions, s.positions);
    let d = scratch("claim-streamed");
    let (v, code) = certify(&d, &serde_json::from_str(&streamed).unwrap());
    assert_eq!((v.as_str(), code), ("holds", Some(0)));
    // Control: "version" and "vertices" swapped.
    let swapped = surface
        .replacen("\"version\": 1,", "\"@\"", 1)
        .replacen("\"vertices\"", "\"version\": 1,\n    \"vertices\"", 1)
        .replacen("\"@\"\n", "", 1);
    assert_ne!(swapped, surface);
    assert_ne!(reprinted(&swapped), swapped);
}
