//! The claim kind `parametrization` through `penner certify`: the files written by
//! `penner uniformize … --uv` hold (B109, and B110 with `seam_epsilon` on the octahedron
//! with cone angles π/2 multiples); a UV corner moved across the opposite edge is refuted
//! naming its face, an altered barycentric row is refuted, a truncated OBJ and a sidecar
//! for another surface are refused as bad input naming the line or element.

use crate::support::{penner, scratch, text};
use penner::io::{json, read_path};
use serde_json::{json, Value};
use std::fmt::Write as _;
use std::path::Path;

/// The regular octahedron as OFF, its surface JSON, and the `--uv` files of its
/// uniformization with cone angles (π/2, π/2, π/2, π/2, π, π).
fn uv_claim(d: &Path) -> Value {
    let pts = [
        [1, 0, 0],
        [-1, 0, 0],
        [0, 1, 0],
        [0, -1, 0],
        [0, 0, 1],
        [0, 0, -1],
    ];
    let faces = [
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];
    let mut t = String::from("OFF\n6 8 0\n");
    for p in pts {
        let _ = writeln!(t, "{} {} {}", p[0], p[1], p[2]);
    }
    for f in faces {
        let _ = writeln!(t, "3 {} {} {}", f[0], f[1], f[2]);
    }
    let off = d.join("octahedron.off");
    std::fs::write(&off, t).unwrap();
    let tf = d.join("cones.json");
    std::fs::write(&tf, "[\"1\", \"1\", \"1\", \"1\", \"2\", \"2\"]").unwrap();
    let uv = d.join("uv.obj");
    let out = penner(&[
        "uniformize",
        off.to_str().unwrap(),
        "--targets",
        tf.to_str().unwrap(),
        "--uv",
        uv.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let surface: Value = serde_json::from_str(&json::write(&read_path(&off).unwrap())).unwrap();
    let sidecar: Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("uv.obj.json")).unwrap()).unwrap();
    json!({
        "penner_claim": 1,
        "id": "uv",
        "kind": "parametrization",
        "surface": surface,
        "obj": std::fs::read_to_string(&uv).unwrap(),
        "sidecar": sidecar,
        "seam_epsilon": "1e-9",
    })
}

/// `penner certify` on `claim`: the answer (or Null), the exit code, stderr.
fn certify(d: &Path, claim: &Value) -> (Value, Option<i32>, String) {
    let p = d.join("claim.json");
    let _ = std::fs::remove_file(&p);
    std::fs::write(&p, claim.to_string()).unwrap();
    let out = penner(&["certify", p.to_str().unwrap()]);
    let answer = serde_json::from_str(&text(&out.stdout)).unwrap_or(Value::Null);
    (answer, out.status.code(), text(&out.stderr))
}

/// The OBJ with the `vt` of corner `i` of `f` line `k` moved across the opposite edge.
fn with_corner_moved(obj: &str, k: usize, i: usize) -> String {
    let vt: Vec<[f64; 2]> = obj
        .lines()
        .filter_map(|l| l.strip_prefix("vt "))
        .map(|l| {
            let x: Vec<f64> = l.split_whitespace().map(|x| x.parse().unwrap()).collect();
            [x[0], x[1]]
        })
        .collect();
    let f = obj.lines().filter(|l| l.starts_with("f ")).nth(k).unwrap();
    let idx: Vec<usize> = f
        .split_whitespace()
        .skip(1)
        .map(|c| c.split('/').nth(1).unwrap().parse::<usize>().unwrap() - 1)
        .collect();
    let tri = [vt[idx[0]], vt[idx[1]], vt[idx[2]]];
    let target = idx[i];
    let (a, b, c) = (tri[i], tri[(i + 1) % 3], tri[(i + 2) % 3]);
    // The point reflection of `a` through the midpoint of the opposite edge `bc`.
    let moved = [b[0] + c[0] - a[0], b[1] + c[1] - a[1]];
    let mut n = 0;
    let mut out = String::new();
    for l in obj.lines() {
        if l.starts_with("vt ") {
            if n == target {
                let _ = writeln!(out, "vt {} {}", moved[0], moved[1]);
            } else {
                out.push_str(l);
                out.push('\n');
            }
            n += 1;
        } else {
            out.push_str(l);
            out.push('\n');
        }
    }
    out
}

#[test]
fn b109_parametrization_claim_holds_on_uv_files_and_controls_are_refuted_or_refused() {
    let d = scratch("claim-parametrization");
    let claim = uv_claim(&d);
    let (a, code, err) = certify(&d, &claim);
    assert_eq!(
        (a["verdict"].as_str(), code),
        (Some("holds"), Some(0)),
        "{a}{err}"
    );
    assert_eq!(a["kind"], json!("parametrization"));

    // A UV corner moved across the opposite edge: face 0 folds.
    let obj = claim["obj"].as_str().unwrap();
    let mut moved = claim.clone();
    moved["obj"] = Value::String(with_corner_moved(obj, 0, 0));
    let (a, code, err) = certify(&d, &moved);
    assert_eq!(a["verdict"], json!("refuted"), "{a}{err}");
    assert_ne!(code, Some(0));
    let named =
        a["witnesses"].as_array().unwrap().iter().any(|w| {
            w["element"] == json!("face 0") && w["detail"].as_str().unwrap().contains("UV")
        });
    assert!(named, "{a}");

    // A barycentric row altered: two rows of face 0 swapped (its triangle reversed in the
    // input face).
    let mut swapped = claim.clone();
    let rows = &mut swapped["sidecar"]["faces"][0]["barycentric"];
    let (r0, r1) = (rows[0].clone(), rows[1].clone());
    rows[0] = r1;
    rows[1] = r0;
    let (a, code, err) = certify(&d, &swapped);
    assert_eq!(a["verdict"], json!("refuted"), "{a}{err}");
    assert_ne!(code, Some(0));
    assert_eq!(a["counterexample"]["element"], json!("face 0"), "{a}");

    // A truncated OBJ: cut inside its last f line.
    let cut = obj.trim_end().rfind('/').unwrap();
    let mut truncated = claim.clone();
    truncated["obj"] = Value::String(obj[..cut].to_string());
    let (a, code, err) = certify(&d, &truncated);
    assert_eq!(
        (a["verdict"].as_str(), code),
        (Some("bad_input"), Some(3)),
        "{a}{err}"
    );
    let last = obj[..cut].lines().count();
    assert!(err.contains(&format!("OBJ line {last}: not v/vt")), "{err}");

    // A sidecar for another surface (one input face fewer): refused naming the element.
    let mut other = claim.clone();
    other["sidecar"]["input_faces"] = json!(7);
    let (a, code, err) = certify(&d, &other);
    assert_eq!(
        (a["verdict"].as_str(), code),
        (Some("bad_input"), Some(3)),
        "{a}{err}"
    );
    assert!(err.contains("input_faces: 7"), "{err}");
}

/// Every field the re-check must use is used: dropping the last `f` line with its sidecar
/// entry (an input face no longer tiled), changing one `vt` by 10⁻⁶ (the seam then broken at
/// ε = 10⁻⁹ or the face folded), and each is never `holds`.
#[test]
fn parametrization_claim_fields_obj_sidecar_and_seam_epsilon_are_each_used() {
    let d = scratch("claim-fields-parametrization");
    let claim = uv_claim(&d);
    let obj = claim["obj"].as_str().unwrap().to_string();
    let mut alterations: Vec<(&str, Value)> = Vec::new();
    let mut dropped = claim.clone();
    let last_f = obj.trim_end().rfind("\nf ").unwrap();
    dropped["obj"] = Value::String(obj[..=last_f].to_string());
    dropped["sidecar"]["faces"].as_array_mut().unwrap().pop();
    alterations.push(("the last face dropped", dropped));
    let mut nudged = claim.clone();
    let first_vt = obj.find("\nvt ").unwrap() + 1;
    let end = first_vt + obj[first_vt..].find('\n').unwrap();
    let w: Vec<f64> = obj[first_vt + 3..end]
        .split_whitespace()
        .map(|x| x.parse().unwrap())
        .collect();
    nudged["obj"] = Value::String(format!(
        "{}vt {} {}{}",
        &obj[..first_vt],
        w[0] + 1e-6,
        w[1],
        &obj[end..]
    ));
    alterations.push(("a vt nudged by 1e-6", nudged));
    for (what, altered) in &alterations {
        let (a, code, err) = certify(&d, altered);
        assert_ne!(a["verdict"], json!("holds"), "{what}: {a}{err}");
        assert_ne!(code, Some(0), "{what}");
    }
}
