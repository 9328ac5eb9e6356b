//! `penner uniformize` end to end, and its certificate re-checked by `penner certify`
//! (claim kind `uniformization`, T24, B71).

use crate::meshgen::jittered_torus;
use crate::support::{penner, scratch, text};
use crate::uniformization::noisy_sphere;
use penner::io::{json, Metric, Surface};
use penner::mesh::Mesh;
use rug::Rational;
use serde_json::Value;
use std::fmt::Write as _;

fn surface_file(dir: &std::path::Path, name: &str, m: Mesh, l: &[f64]) -> String {
    let metric = Metric::Lengths(l.iter().map(|&x| Rational::from_f64(x).unwrap()).collect());
    let s = Surface::new(name, m, metric, None).unwrap();
    let p = dir.join(format!("{name}.json"));
    std::fs::write(&p, json::write(&s)).unwrap();
    p.display().to_string()
}

#[test]
fn t24_cli_uniformize_writes_a_certificate_that_certify_rechecks() {
    let d = scratch("uniformize-torus");
    let (m, l) = jittered_torus(5, 6, 2);
    let surf = surface_file(&d, "torus", m, &l);
    let cert = d.join("cert.json").display().to_string();
    let out = penner(&["uniformize", &surf, "--flat", "-o", &cert]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}{}",
        text(&out.stdout),
        text(&out.stderr)
    );
    assert!(
        text(&out.stdout).contains("certified"),
        "{}",
        text(&out.stdout)
    );
    let out = penner(&["certify", &cert]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}{}",
        text(&out.stdout),
        text(&out.stderr)
    );
    let answer: Value = serde_json::from_str(&text(&out.stdout)).unwrap();
    assert_eq!(answer["verdict"], "holds");
    assert_eq!(answer["kind"], "uniformization");
    assert_eq!(answer["certified"], true);
    // Negative control: u changed at one vertex by 1e-6 → not certified (exit 2).
    let mut claim: Value = serde_json::from_str(&std::fs::read_to_string(&cert).unwrap()).unwrap();
    let old = claim["u"][1].as_str().unwrap().to_string();
    let moved = format!(
        "{}",
        penner::io::json::exact_number(&claim["u"][1], "u")
            .unwrap()
            .to_f64()
            + 1e-6
    );
    assert_ne!(old, moved);
    claim["u"][1] = Value::String(moved);
    let bad = d.join("bad.json");
    std::fs::write(&bad, claim.to_string()).unwrap();
    let out = penner(&["certify", &bad.display().to_string()]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stdout));
    // A flip index out of range is bad input (exit 3), named by field.
    claim["flips"] = serde_json::json!([100000]);
    std::fs::write(&bad, claim.to_string()).unwrap();
    let out = penner(&["certify", &bad.display().to_string()]);
    assert_eq!(out.status.code(), Some(3), "{}", text(&out.stdout));
    assert!(
        text(&out.stderr).contains("flips[0]"),
        "{}",
        text(&out.stderr)
    );
    // The binary never overwrites: a second run to the same file exits 4.
    let out = penner(&["uniformize", &surf, "--flat", "-o", &cert]);
    assert_eq!(out.status.code(), Some(4), "{}", text(&out.stderr));
}

#[test]
fn t24_cli_uniformize_bad_input_is_typed() {
    let d = scratch("uniformize-bad");
    let (m, l) = noisy_sphere(2, 1);
    let n = m.n_vertices();
    let surf = surface_file(&d, "sphere", m, &l);
    // Flat targets on a sphere violate Gauss–Bonnet.
    let out = penner(&["uniformize", &surf, "--flat"]);
    assert_eq!(out.status.code(), Some(3));
    assert!(
        text(&out.stderr).contains("Gauss–Bonnet"),
        "{}",
        text(&out.stderr)
    );
    // No targets at all.
    let out = penner(&["uniformize", &surf]);
    assert_eq!(out.status.code(), Some(3));
    assert!(
        text(&out.stderr).contains("--targets"),
        "{}",
        text(&out.stderr)
    );
    // A target file with a non-positive entry names the vertex.
    let mut t: Vec<String> = vec!["2".into(); n];
    t[0] = "-1".into();
    t[1] = "1".into();
    t[2] = "1".into();
    t[3] = "1".into();
    t[4] = "1".into();
    t[5] = "1".into();
    let tf = d.join("targets.json");
    std::fs::write(&tf, serde_json::to_string(&t).unwrap()).unwrap();
    let out = penner(&["uniformize", &surf, "--targets", &tf.display().to_string()]);
    assert_eq!(out.status.code(), Some(3));
    assert!(text(&out.stderr).contains("v0"), "{}", text(&out.stderr));
    // A wrong count.
    std::fs::write(&tf, "[\"2\", \"2\"]").unwrap();
    let out = penner(&["uniformize", &surf, "--targets", &tf.display().to_string()]);
    assert_eq!(out.status.code(), Some(3));
    assert!(
        text(&out.stderr).contains("2 targets"),
        "{}",
        text(&out.stderr)
    );
    // Admissible targets: four cones of π.
    let mut t: Vec<String> = vec!["2".into(); n];
    for v in [0, 5, 10, 20] {
        t[v] = "1".into();
    }
    std::fs::write(&tf, serde_json::to_string(&t).unwrap()).unwrap();
    let out = penner(&["uniformize", &surf, "--targets", &tf.display().to_string()]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}{}",
        text(&out.stdout),
        text(&out.stderr)
    );
}

/// A regular octahedron written as OFF with every coordinate multiplied by `scale`.
fn octahedron_off(dir: &std::path::Path, name: &str, scale: f64) -> String {
    let pts = [
        [1.0, 0.0, 0.0],
        [-1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, -1.0, 0.0],
        [0.0, 0.0, 1.0],
        [0.0, 0.0, -1.0],
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
        let _ = writeln!(
            t,
            "{:e} {:e} {:e}",
            p[0] * scale,
            p[1] * scale,
            p[2] * scale
        );
    }
    for f in faces {
        let _ = writeln!(t, "3 {} {} {}", f[0], f[1], f[2]);
    }
    let p = dir.join(format!("{name}.off"));
    std::fs::write(&p, t).unwrap();
    p.display().to_string()
}

#[test]
fn t24_cli_uniformize_accepts_surfaces_scaled_by_two_to_the_plus_minus_1000() {
    let d = scratch("uniformize-scaled");
    // Θ_i = 4π/3 at each of the six vertices: Σ(2π − Θ_i) = 4π = 2πχ of the sphere.
    let targets = d.join("targets.json");
    std::fs::write(
        &targets,
        "[\"4/3\",\"4/3\",\"4/3\",\"4/3\",\"4/3\",\"4/3\"]",
    )
    .unwrap();
    let targets = targets.display().to_string();
    for (name, scale) in [
        ("unit", 1.0),
        ("tiny", 2f64.powi(-1000)),
        ("huge", 2f64.powi(1000)),
    ] {
        let surf = octahedron_off(&d, name, scale);
        let out = penner(&["uniformize", &surf, "--targets", &targets]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{name}: {}{}",
            text(&out.stdout),
            text(&out.stderr)
        );
        assert_eq!(text(&out.stdout).contains("divided by 2^"), scale != 1.0);
    }
    // Negative control: targets off Gauss–Bonnet are still refused at the extreme scale.
    let bad = d.join("bad.json");
    std::fs::write(&bad, "[\"1\",\"4/3\",\"4/3\",\"4/3\",\"4/3\",\"4/3\"]").unwrap();
    let surf = octahedron_off(&d, "tiny-bad", 2f64.powi(-1000));
    let out = penner(&["uniformize", &surf, "--targets", &bad.display().to_string()]);
    assert_eq!(out.status.code(), Some(3), "{}", text(&out.stderr));
}

#[test]
fn t24_cli_uniformize_dd_refines_in_double_double_and_says_where_it_certifies() {
    let d = scratch("uniformize-dd");
    let (m, l) = jittered_torus(5, 6, 4);
    let surf = surface_file(&d, "torus", m, &l);
    let cert = d.join("cert.json").display().to_string();
    let out = penner(&[
        "uniformize",
        &surf,
        "--flat",
        "--precision",
        "dd",
        "-o",
        &cert,
    ]);
    let stdout = text(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{stdout}{}", text(&out.stderr));
    assert!(
        stdout.contains("after refinement in double-double")
            && stdout.contains("128-bit MPFR interval arithmetic"),
        "{stdout}"
    );
    // The refined residual meets the dd tolerance of the CLI (1e-28).
    let line = stdout
        .lines()
        .find(|l| l.contains("after refinement in double-double"))
        .unwrap();
    let refined: f64 = line
        .split(", ")
        .nth(1)
        .and_then(|x| x.split_whitespace().next())
        .and_then(|x| x.parse().ok())
        .unwrap();
    assert!(refined <= 1e-28, "{line}");
    let out = penner(&["certify", &cert]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));
    // Negative control: u moved by 1e-20 at one vertex — far below f64's accuracy, far
    // above the double-double solution's — is not certified.
    let mut claim: Value = serde_json::from_str(&std::fs::read_to_string(&cert).unwrap()).unwrap();
    let u1 = penner::io::json::exact_number(&claim["u"][1], "u").unwrap();
    let moved = u1 + Rational::from((1, rug::Integer::from(rug::Integer::u_pow_u(10, 20))));
    claim["u"][1] = Value::String(moved.to_string());
    let bad = d.join("bad.json");
    std::fs::write(&bad, claim.to_string()).unwrap();
    let out = penner(&["certify", &bad.display().to_string()]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stdout));
}

/// `--no-certify` solves in f64 only: the report says the result is numerical and not
/// certified (exit 2, never 0), and a certificate file cannot be asked for with it (usage,
/// exit 3). Control: the same torus without the flag is certified (exit 0).
#[test]
fn uniformize_no_certify_is_numerical_and_says_so() {
    let d = scratch("uniformize-no-certify");
    let (m, l) = jittered_torus(5, 6, 2);
    let surf = surface_file(&d, "torus", m, &l);
    let out = penner(&["uniformize", &surf, "--flat", "--no-certify"]);
    let said = text(&out.stdout);
    assert_eq!(out.status.code(), Some(2), "{said}");
    assert!(said.contains("numerical, not certified"), "{said}");
    assert!(!said.contains("an exact solution lies within"), "{said}");
    let cert = d.join("cert.json").display().to_string();
    let out = penner(&["uniformize", &surf, "--flat", "--no-certify", "-o", &cert]);
    assert_eq!(out.status.code(), Some(3));
    assert!(!std::path::Path::new(&cert).exists());
    let out = penner(&["uniformize", &surf, "--flat"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stdout));
}

/// The octahedron as OFF in `d` and a targets file with four cones of π (vertices 0–3).
fn octahedron_with_four_cones(d: &std::path::Path) -> (String, std::path::PathBuf) {
    let surf = octahedron_off(d, "octahedron", 1.0);
    let tf = d.join("cones.json");
    std::fs::write(&tf, "[\"1\", \"1\", \"1\", \"1\", \"2\", \"2\"]").unwrap();
    (surf, tf)
}

/// `--uv-svg` draws the refinement's UV layout: the input edges' pieces (orange) and the
/// final triangulation's (blue) as lines, each of the four cones marked at least once; a
/// second run refuses the existing picture before the solve (exit 4), and `--uv-svg`
/// without `--uv` is a usage error.
#[test]
fn cli_uniformize_uv_svg_draws_both_edge_sets_and_the_cones() {
    let d = scratch("uniformize-uv-svg");
    let (surf, tf) = octahedron_with_four_cones(&d);
    let (uv, svg) = (d.join("uv.obj"), d.join("uv.svg"));
    let args = [
        "uniformize",
        &surf,
        "--targets",
        tf.to_str().unwrap(),
        "--uv",
        uv.to_str().unwrap(),
        "--uv-svg",
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
    let pic = std::fs::read_to_string(&svg).unwrap();
    let group = |colour: &str| {
        let start = pic
            .find(&format!("stroke=\"{colour}\""))
            .expect("the group");
        let end = start + pic[start..].find("</g>").unwrap();
        pic[start..end].matches("<line ").count()
    };
    assert!(group("#d07020") > 0 && group("#2050a0") > 0, "{pic}");
    assert!(pic.matches("<circle ").count() >= 4, "{pic}");
    // Only the picture exists this time: still refused before the solve.
    let uv2 = d.join("uv2.obj");
    let mut args2 = args;
    let uv2_s = uv2.to_str().unwrap().to_string();
    args2[5] = &uv2_s;
    let out = penner(&args2);
    assert_eq!(out.status.code(), Some(4), "{}", text(&out.stderr));
    assert!(
        text(&out.stderr).contains("uv.svg"),
        "{}",
        text(&out.stderr)
    );
    assert!(text(&out.stdout).is_empty() && !uv2.exists());
    assert_eq!(std::fs::read_to_string(&svg).unwrap(), pic);
    let out = penner(&[
        "uniformize",
        &surf,
        "--flat",
        "--uv-svg",
        d.join("x.svg").to_str().unwrap(),
    ]);
    assert_ne!(out.status.code(), Some(0));
    assert!(!d.join("x.svg").exists());
}

/// B109 through the binary: `--uv` writes the refinement and its sidecar as new files, the
/// exact checks hold on them when re-read, a second run refuses to overwrite (exit 4), a
/// surface with boundary gets the UVs of copy 1 of its double, and `--uv` with `--sphere`
/// is refused as bad input (exit 3).
#[test]
fn b109_cli_uniformize_uv_writes_new_files_that_check() {
    let d = scratch("uniformize-uv");
    let (surf, tf) = octahedron_with_four_cones(&d);
    let uv = d.join("uv.obj");
    let args = [
        "uniformize",
        &surf,
        "--targets",
        tf.to_str().unwrap(),
        "--uv",
        uv.to_str().unwrap(),
    ];
    let out = penner(&args);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}{}",
        text(&out.stdout),
        text(&out.stderr)
    );
    assert!(
        text(&out.stdout).contains("every UV triangle counterclockwise"),
        "{}",
        text(&out.stdout)
    );
    let obj = std::fs::read_to_string(&uv).unwrap();
    let side_path = d.join("uv.obj.json");
    let side: Value = serde_json::from_str(&std::fs::read_to_string(&side_path).unwrap()).unwrap();
    let report = penner::overlay::check_parametrization(&obj, &side).unwrap();
    assert!(report.holds() && report.triangles >= 8, "{report:?}");
    let out = penner(&args);
    assert_eq!(out.status.code(), Some(4), "{}", text(&out.stderr));
    assert_eq!(std::fs::read_to_string(&uv).unwrap(), obj);
    // Refused before the solve: nothing reported.
    assert_eq!(text(&out.stdout), "", "{}", text(&out.stdout));
    // The sidecar alone existing is refused too, before the solve.
    let other = d.join("other.obj");
    std::fs::write(d.join("other.obj.json"), "{}").unwrap();
    let mut args2 = args;
    let other_s = other.to_str().unwrap().to_string();
    args2[5] = &other_s;
    let out = penner(&args2);
    assert_eq!(out.status.code(), Some(4), "{}", text(&out.stderr));
    assert!(
        text(&out.stderr).contains("other.obj.json"),
        "{}",
        text(&out.stderr)
    );
    assert!(!other.exists() && text(&out.stdout).is_empty());
    // A disk, one triangle with boundary: UVs of copy 1 of its double, checked on the
    // written files (the triangle's own shape, flat with its three corners as boundary
    // corners).
    let disk = d.join("disk.off");
    std::fs::write(&disk, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").unwrap();
    let disk_uv = d.join("disk.obj");
    let out = penner(&[
        "uniformize",
        disk.to_str().unwrap(),
        "--flat",
        "--uv",
        disk_uv.to_str().unwrap(),
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}{}",
        text(&out.stdout),
        text(&out.stderr)
    );
    let obj = std::fs::read_to_string(&disk_uv).unwrap();
    let side: Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("disk.obj.json")).unwrap()).unwrap();
    let report = penner::overlay::check_parametrization(&obj, &side).unwrap();
    assert!(report.holds() && report.triangles == 1, "{report:?}");
    // --uv with the sphere target is a usage error (exit 3), before any file is made.
    let out = penner(&[
        "uniformize",
        &surf,
        "--sphere",
        "--uv",
        d.join("sphere.obj").to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(3), "{}", text(&out.stderr));
    assert!(!d.join("sphere.obj").exists());
    assert!(text(&out.stderr).contains("--uv"), "{}", text(&out.stderr));
}
