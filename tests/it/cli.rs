//! The `penner` binary end to end: good inputs give verdicts and exit codes, bad inputs
//! give one clear message naming the file (and line or element) and exit code 3 — never a
//! panic or a backtrace.

use crate::support::{
    assert_refused, certify_expecting, counterexample, penner, scratch, text, write,
};

/// A tetrahedron with unit edges in the surface JSON format.
const TETRAHEDRON: &str = r#"{
  "vertices": 4,
  "faces": [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]],
  "lengths": ["1", "1", "1", "1", "1", "1"]
}"#;

#[test]
fn report_on_the_built_in_corpus_runs_and_holds() {
    let out = penner(&[]);
    let stdout = text(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "stdout: {stdout}\nstderr: {}",
        text(&out.stderr)
    );
    assert!(stdout.contains("row(s)"), "no summary line: {stdout}");
    assert!(
        !stdout.contains("fails"),
        "a check fails on the corpus: {stdout}"
    );
}

#[test]
fn report_json_is_json_with_a_status() {
    let out = penner(&["report", "--precision", "f64", "--json"]);
    assert_eq!(out.status.code(), Some(0), "stderr: {}", text(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON report");
    assert_eq!(v["penner_report"], 1);
    assert_eq!(v["status"], "holds");
    assert!(v["rows"].is_array());
}

#[test]
fn help_and_version_exit_zero() {
    let out = penner(&["--help"]);
    assert_eq!(out.status.code(), Some(0));
    let s = text(&out.stdout);
    for cmd in ["check", "certify", "delaunay", "replay"] {
        assert!(s.contains(cmd), "help does not list {cmd}: {s}");
    }
    assert_eq!(penner(&["--version"]).status.code(), Some(0));
}

#[test]
fn unknown_subcommand_and_flag_are_usage_errors() {
    assert_refused(&penner(&["frobnicate"]), 3, &["frobnicate"]);
    assert_refused(
        &penner(&["check", "--no-such-flag", "x.json"]),
        3,
        &["--no-such-flag"],
    );
}

#[test]
fn absurd_precisions_are_refused() {
    for (p, mention) in [
        ("99999999", "99999999"),
        ("99999999999999999999999999", "99999999999999999999999999"),
        ("12", "12"),
        ("f32", "f32"),
        ("", "empty"),
        (",,,", "empty"),
        ("-5", "-5"),
    ] {
        let arg = format!("--precision={p}");
        assert_refused(&penner(&["report", &arg]), 3, &[mention]);
    }
}

#[test]
fn missing_file_and_directory_are_refused() {
    let d = scratch("missing");
    let missing = d.join("nope.json");
    let m = missing.display().to_string();
    assert_refused(&penner(&["check", &m]), 3, &["nope.json"]);
    let dir = d.join("surface.json");
    std::fs::create_dir(&dir).unwrap();
    assert_refused(
        &penner(&["check", &dir.display().to_string()]),
        3,
        &["directory"],
    );
    let unknown = write(&d, "surface.ply", b"ply");
    assert_refused(
        &penner(&["check", &unknown.display().to_string()]),
        3,
        &["surface.ply", "format"],
    );
    assert_refused(&penner(&["replay", &m]), 3, &["nope.json"]);
}

#[test]
fn check_on_a_good_surface_prints_a_table() {
    let d = scratch("good");
    let p = write(&d, "tet.json", TETRAHEDRON.as_bytes());
    let out = penner(&["check", &p.display().to_string(), "--precision", "f64,128"]);
    let s = text(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "stdout: {s}\nstderr: {}",
        text(&out.stderr)
    );
    assert!(s.contains("4 vertices, 6 edges, 4 faces"), "{s}");
    // No failure file appears for a surface on which everything holds.
    let files: Vec<_> = std::fs::read_dir(&d).unwrap().collect();
    assert_eq!(files.len(), 1);
}

/// Hostile JSON: each input must be refused with exit code 3 and a message naming the file
/// and what is wrong.
#[test]
fn hostile_json_is_refused_cleanly() {
    let d = scratch("hostile-json");
    let deep = format!("{}{}", "[".repeat(100_000), "]".repeat(100_000));
    let many_faces = format!(
        r#"{{"vertices": 3, "faces": [{}[0,1,2]], "lengths": ["1","1","1"]}}"#,
        "[0,1,2],".repeat(200_000)
    );
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        ("empty.json", Vec::new(), "empty.json"),
        ("truncated.json", TETRAHEDRON.as_bytes()[..40].to_vec(), ":"),
        ("garbage.json", (0..4096u32).map(|i| (i.wrapping_mul(2_654_435_761) >> 24) as u8).collect(), "garbage.json"),
        ("deep.json", deep.into_bytes(), "deep.json"),
        ("not-object.json", b"[1, 2, 3]".to_vec(), "object"),
        ("neg-vertex.json", br#"{"vertices": 4, "faces": [[0,1,-2]], "lengths": []}"#.to_vec(), "faces[0][2]"),
        ("huge-count.json", br#"{"vertices": 1e300, "faces": [[0,1,2]], "lengths": ["1","1","1"]}"#.to_vec(), "vertices"),
        ("range.json", br#"{"vertices": 3, "faces": [[0,1,7]], "lengths": ["1","1","1"]}"#.to_vec(), "faces[0][2]"),
        ("isolated.json", br#"{"vertices": 4294967295, "faces": [[0,1,2]], "lengths": ["1","1","1"]}"#.to_vec(), "no face"),
        ("zero-length.json", br#"{"vertices": 4, "faces": [[0,1,2],[0,2,3],[0,3,1],[1,3,2]], "lengths": ["1","0","1","1","1","1"]}"#.to_vec(), "not positive"),
        ("neg-length.json", br#"{"vertices": 4, "faces": [[0,1,2],[0,2,3],[0,3,1],[1,3,2]], "lengths": ["1","1","-3/2","1","1","1"]}"#.to_vec(), "not positive"),
        ("nan-length.json", br#"{"vertices": 4, "faces": [[0,1,2],[0,2,3],[0,3,1],[1,3,2]], "lengths": ["1","1","1","NaN","1","1"]}"#.to_vec(), "lengths[3]"),
        ("count.json", br#"{"vertices": 4, "faces": [[0,1,2],[0,2,3],[0,3,1],[1,3,2]], "lengths": ["1","1"]}"#.to_vec(), "edges"),
        ("nonmanifold.json", br#"{"vertices": 5, "faces": [[0,1,2],[0,3,4]], "lengths": ["1","1","1","1","1","1"]}"#.to_vec(), "non-manifold"),
        ("bad-gluing.json", br#"{"vertices": 3, "faces": [[0,1,2],[0,2,1]], "gluing": [[[0,0],[9,9]]], "lengths": ["1","1","1"]}"#.to_vec(), "gluing"),
        ("many-faces.json", many_faces.into_bytes(), "many-faces.json"),
    ];
    for (name, bytes, mention) in cases {
        let p = write(&d, name, &bytes);
        let out = penner(&["check", &p.display().to_string()]);
        assert_refused(&out, 3, &[name, mention]);
    }
}

pub(crate) fn tetrahedron_json() -> serde_json::Value {
    serde_json::from_str(TETRAHEDRON).unwrap()
}

/// 2 log 2 to 50 digits: the log scale factor that multiplies every length by 4.
const TWO_LN_2: &str = "1.3862943611198906188344642429163531361510002687205";

#[test]
fn certify_cone_angles_holds_refuted_and_bad_input() {
    let d = scratch("certify-angles");
    let pi = "3.14159265358979323846264338327950288419716939937510";
    let claim = |angles: serde_json::Value, eps: &str| {
        serde_json::json!({"penner_claim": 1, "id": "t", "kind": "cone_angles",
            "surface": tetrahedron_json(), "angles": angles, "epsilon": eps})
    };
    let (a, _) = certify_expecting(
        &d,
        "holds.json",
        &claim(serde_json::json!([pi, pi, pi, pi]), "1e-40"),
        0,
        "holds",
    );
    assert_eq!(a["certified"], true);
    assert_eq!(a["id"], "t");
    // Off by 1e-47 at vertex 3, epsilon 1e-48: refuted, counterexample v3, needs > 128 bits.
    let off = "3.14159265358979323846264338327950288419716939938510";
    let (a, _) = certify_expecting(
        &d,
        "refuted.json",
        &claim(serde_json::json!([pi, pi, pi, off]), "1e-48"),
        1,
        "refuted",
    );
    assert_eq!(a["counterexample"]["element"], "v3");
    assert!(a["precision_bits"].as_u64().unwrap() > 128, "{a}");
    // Wrong count of angles: bad input, with a JSON answer and a message naming the field.
    let (_, err) = certify_expecting(
        &d,
        "count.json",
        &claim(serde_json::json!([pi]), "1e-9"),
        3,
        "bad_input",
    );
    assert!(
        err.contains("angles") && err.contains("count.json"),
        "{err}"
    );
}

#[test]
fn certify_conformal_equivalence_holds_refuted_and_undecided_at_a_tie() {
    let d = scratch("certify-conformal");
    let tet = tetrahedron_json();
    let mut four = tet.clone();
    four["lengths"] = serde_json::json!(["4", "4", "4", "4", "4", "4"]);
    let claim = |target: &serde_json::Value, u: serde_json::Value, eps: &str| {
        serde_json::json!({"penner_claim": 1, "kind": "conformal_equivalence",
            "surface": tet, "target": target, "u": u, "epsilon": eps})
    };
    let u = serde_json::json!([TWO_LN_2, TWO_LN_2, TWO_LN_2, TWO_LN_2]);
    certify_expecting(&d, "holds.json", &claim(&four, u, "1e-45"), 0, "holds");
    // Negative control: u_2 off by 1e-6; the edges at vertex 2 are refuted.
    let u = serde_json::json!([TWO_LN_2, TWO_LN_2, "1.386295", TWO_LN_2]);
    let (a, _) = certify_expecting(&d, "refuted.json", &claim(&four, u, "1e-9"), 1, "refuted");
    let el = a["counterexample"]["element"].as_str().unwrap();
    assert!(el.contains("v2"), "{el}");
    assert_eq!(a["witnesses"].as_array().unwrap().len(), 3, "{a}");
    // An exact tie (residual exactly 0 = epsilon) cannot be settled by enclosures.
    let (a, _) = certify_expecting(
        &d,
        "tie.json",
        &claim(&tet, serde_json::json!([0, 0, 0, 0]), "0"),
        2,
        "undecided",
    );
    assert_eq!(a["certified"], false);
}

#[test]
fn certify_refuses_hostile_claims() {
    let d = scratch("certify-hostile");
    let tet = tetrahedron_json();
    let cases: Vec<(&str, serde_json::Value, &str)> = vec![
        (
            "version.json",
            serde_json::json!({"penner_claim": 2, "kind": "cone_angles", "surface": tet}),
            "version 2",
        ),
        (
            "kind.json",
            serde_json::json!({"penner_claim": 1, "kind": "world_peace", "surface": tet}),
            "world_peace",
        ),
        (
            "eps.json",
            serde_json::json!({"penner_claim": 1, "kind": "cone_angles", "surface": tet, "angles": [1,1,1,1], "epsilon": "-1"}),
            "epsilon",
        ),
        (
            "bits.json",
            serde_json::json!({"penner_claim": 1, "kind": "cone_angles", "surface": tet, "angles": [1,1,1,1], "epsilon": 1, "max_bits": 99999999}),
            "max_bits",
        ),
        (
            "huge-exp.json",
            serde_json::json!({"penner_claim": 1, "kind": "cone_angles", "surface": tet, "angles": ["1e999999999",1,1,1], "epsilon": 1}),
            "angles[0]",
        ),
        (
            "target.json",
            serde_json::json!({"penner_claim": 1, "kind": "conformal_equivalence", "surface": tet,
            "target": {"vertices": 3, "faces": [[0,1,2],[0,2,1]], "lengths": ["1","1","1"]}, "u": [0,0,0,0], "epsilon": 0}),
            "same triangulation",
        ),
    ];
    for (name, claim, mention) in cases {
        let (_, err) = certify_expecting(&d, name, &claim, 3, "bad_input");
        assert!(err.contains(mention) && err.contains(name), "{name}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
    let out = penner(&["certify", &d.join("missing.json").display().to_string()]);
    assert_refused(&out, 3, &["missing.json"]);
}

const TET_OBJ: &str =
    "# tetrahedron\nv 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n";
const TET_OFF: &str =
    "OFF\n4 4 6\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 0 1 2\n3 0 2 3\n3 0 3 1\n3 1 3 2\n";

#[test]
fn check_reads_obj_and_off_exactly() {
    let d = scratch("obj-off");
    for (name, body) in [("tet.obj", TET_OBJ), ("tet.off", TET_OFF)] {
        let p = write(&d, name, body.as_bytes());
        let out = penner(&["check", &p.display().to_string(), "--precision", "f64"]);
        let s = text(&out.stdout);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{name}: {s}\n{}",
            text(&out.stderr)
        );
        assert!(s.contains("4 vertices, 6 edges, 4 faces"), "{name}: {s}");
    }
}

#[test]
fn hostile_obj_and_off_are_refused_cleanly() {
    let d = scratch("hostile-obj-off");
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        (
            "truncated.off",
            TET_OFF.as_bytes()[..40].to_vec(),
            "truncated.off",
        ),
        (
            "nan.obj",
            TET_OBJ.replace("v 1 1 1", "v nan 1 1").into_bytes(),
            "line 2",
        ),
        (
            "index.obj",
            TET_OBJ.replace("f 2 4 3", "f 2 4 99").into_bytes(),
            "line 9",
        ),
        (
            "garbage.off",
            (0..2048u32)
                .map(|i| (i.wrapping_mul(2_654_435_761) >> 24) as u8)
                .collect(),
            "garbage.off",
        ),
        (
            "huge-header.off",
            b"OFF\n4000000000 4000000000 0\n".to_vec(),
            "huge-header.off",
        ),
        (
            "flat.obj",
            b"v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n".to_vec(),
            "degenerate",
        ),
        ("empty.obj", Vec::new(), "empty.obj"),
    ];
    for (name, bytes, mention) in cases {
        let p = write(&d, name, &bytes);
        assert_refused(
            &penner(&["check", &p.display().to_string()]),
            3,
            &[name, mention],
        );
    }
}

/// The two-triangle sphere with sides 3, 4, 5: both faces are one right triangle, so the
/// hypotenuse is a Delaunay tie (D = 0). T22 decides the tie on the exact input metric
/// (the flip of the tie has the exact Ptolemy length 5 again), never on rounded lengths:
/// it holds at f64 (exit 0) and writes no failure file.
const RIGHT_SPHERE: &str =
    r#"{"vertices": 3, "faces": [[0,1,2],[0,2,1]], "lengths": ["3","4","5"]}"#;

#[test]
fn t22_tie_is_decided_on_the_input_metric_and_writes_no_failure_file() {
    let d = scratch("failure-files");
    let p = write(&d, "right.json", RIGHT_SPHERE.as_bytes());
    let ps = p.display().to_string();
    let out = penner(&["check", &ps, "--only", "T22", "--precision", "f64"]);
    let s = text(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{s}\n{}", text(&out.stderr));
    assert!(s.contains("holds"), "{s}");
    assert!(!d.join("right.penner-failure-1.json").exists());
}

/// A failure file (as `check` writes them) whose surface no longer fails replays as
/// "no longer fails" with exit 0; a truncated failure file is bad input.
#[test]
fn replay_reruns_a_failure_file_and_refuses_a_corrupted_one() {
    use penner::oracle::failure::Failure;
    use penner::oracle::precision::Prec;
    let d = scratch("replay");
    let surface = penner::io::json::read(RIGHT_SPHERE).unwrap();
    let failure = Failure {
        check: "T01".into(),
        precision: Prec::F64,
        source: "right.json".into(),
        source_faces: 2,
        witnesses: vec![],
        surface,
    };
    let body = format!("{:#}", failure.to_json());
    let f = write(&d, "right.penner-failure-1.json", body.as_bytes());
    let r = penner(&["replay", &f.display().to_string()]);
    assert_eq!(r.status.code(), Some(0), "{}", text(&r.stdout));
    assert!(text(&r.stdout).contains("no longer fails"));
    let bad = write(
        &d,
        "bad.penner-failure-1.json",
        &body.as_bytes()[..body.len() / 2],
    );
    assert_refused(
        &penner(&["replay", &bad.display().to_string()]),
        3,
        &["bad.penner-failure-1.json"],
    );
}

#[test]
fn delaunay_writes_a_surface_and_never_overwrites() {
    let d = scratch("delaunay");
    // A thin rhombus split along its long diagonal: one flip makes it Delaunay.
    let rhombus =
        r#"{"vertices": 4, "faces": [[0,1,2],[0,2,3]], "lengths": ["1","1","19/10","1","1"]}"#;
    let p = write(&d, "rhombus.json", rhombus.as_bytes());
    let o = d.join("out.json");
    for (flips, prec) in [("euclidean", "256"), ("ptolemy", "exact")] {
        let _ = std::fs::remove_file(&o);
        let out = penner(&[
            "delaunay",
            &p.display().to_string(),
            "--flips",
            flips,
            "--precision",
            prec,
            "-o",
            &o.display().to_string(),
        ]);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{flips}: {err}");
        assert!(err.contains("1 ") && err.contains("certified"), "{err}");
        // The output is a surface `penner check` reads.
        let c = penner(&[
            "check",
            &o.display().to_string(),
            "--only",
            "T21",
            "--precision",
            "f64",
        ]);
        assert_eq!(c.status.code(), Some(0), "{}", text(&c.stderr));
    }
    // The output file exists now: refused, and left untouched.
    let before = std::fs::read(&o).unwrap();
    let out = penner(&[
        "delaunay",
        &p.display().to_string(),
        "-o",
        &o.display().to_string(),
    ]);
    assert_refused(&out, 4, &["out.json", "exists"]);
    assert_eq!(std::fs::read(&o).unwrap(), before);
    // Exact Euclidean flipping is refused as bad input.
    let out = penner(&["delaunay", &p.display().to_string(), "--precision", "exact"]);
    assert_refused(&out, 3, &["exact"]);
}

#[test]
fn certify_intrinsic_delaunay_exactly() {
    let d = scratch("certify-delaunay");
    let claim = |l: [&str; 5]| {
        serde_json::json!({"penner_claim": 1, "kind": "intrinsic_delaunay",
            "surface": {"vertices": 4, "faces": [[0,1,2],[0,2,3]], "lengths": l}})
    };
    // Unit rhombus with diagonal 1.9 (obtuse opposite angles): refuted at the diagonal.
    let (a, _) = certify_expecting(
        &d,
        "thin.json",
        &claim(["1", "1", "19/10", "1", "1"]),
        1,
        "refuted",
    );
    assert!(counterexample(&a).starts_with("edge 2"), "{a}");
    // The unit square with diagonal √2 given as squared lengths: an exact tie, Delaunay.
    let square = serde_json::json!({"penner_claim": 1, "kind": "intrinsic_delaunay",
        "surface": {"vertices": 4, "faces": [[0,1,2],[0,2,3]], "squared_lengths": ["1","1","2","1","1"]}});
    let (a, _) = certify_expecting(&d, "square.json", &square, 0, "holds");
    assert_eq!(a["certified"].as_bool(), Some(true), "{a}");
}

#[test]
fn delaunay_with_scale_factors_up_to_800() {
    let d = scratch("delaunay-scaled");
    let rhombus =
        r#"{"vertices": 4, "faces": [[0,1,2],[0,2,3]], "lengths": ["1","1","19/10","1","1"]}"#;
    let p = write(&d, "rhombus.json", rhombus.as_bytes());
    let p = p.display().to_string();
    let u = write(&d, "u.json", b"[800, -800, 790.5, -799]");
    let u = u.display().to_string();
    let o = d.join("out.json");
    let out = penner(&[
        "delaunay",
        &p,
        "--flips",
        "ptolemy",
        "--precision",
        "f64",
        "--scale-factors",
        &u,
        "-o",
        &o.display().to_string(),
    ]);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(err.contains("every edge certified"), "{err}");
    // Lengths near e^{±800} are written exactly (binary64 would overflow).
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&o).unwrap()).unwrap();
    let lengths = v["lengths"].as_array().unwrap();
    assert_eq!(lengths.len(), 5);
    assert!(
        lengths.iter().any(|x| x.as_str().unwrap().len() > 300),
        "{lengths:?}"
    );
    // Bad scale-factor files and options are typed errors (exit 3), naming what is wrong.
    let bad = |name: &str, body: &[u8], prec: &str, what: &[&str]| {
        let f = write(&d, name, body);
        let out = penner(&[
            "delaunay",
            &p,
            "--flips",
            "ptolemy",
            "--precision",
            prec,
            "--scale-factors",
            &f.display().to_string(),
        ]);
        assert_refused(&out, 3, what);
    };
    bad("obj.json", br#"{"u": 1}"#, "f64", &["obj.json", "array"]);
    bad(
        "count.json",
        b"[1, 2, 3]",
        "f64",
        &["3 scale factors", "4 vertices"],
    );
    bad(
        "entry.json",
        br#"[0, 0, "x", 0]"#,
        "f64",
        &["entry 2", "v2"],
    );
    bad("huge.json", b"[0, 0, 2e6, 0]", "f64", &["v2", "2^20"]);
    bad("trunc.json", b"[0, 0,", "f64", &["trunc.json"]);
    bad("prec.json", b"[0, 0, 0, 0]", "256", &["--precision f64"]);
}

/// `check` on several files and a directory: one report per file in name order, a bad file
/// reported with its typed error (naming the file and line) while the others run, the exit
/// code the worst over the files; `--json` prints an array of one object per file. Negative
/// control: without the bad file the same run exits 0.
#[test]
fn check_takes_several_files_and_a_directory() {
    let d = scratch("check-many");
    let dir = d.join("meshes");
    std::fs::create_dir(&dir).unwrap();
    write(&dir, "b.off", TET_OFF.as_bytes());
    write(&dir, "a.json", TETRAHEDRON.as_bytes());
    write(&dir, "c.OBJ", TET_OBJ.as_bytes());
    write(&dir, "bad.off", b"OFF\n4 4 0\n1 1 1\n1 -1 -1\n-1 1 x\n");
    write(&dir, "notes.txt", b"not a surface");
    write(&dir, "a.penner-failure-1.json", b"{}");
    std::fs::create_dir(dir.join("sub.json")).unwrap();
    let extra = write(&d, "extra.obj", TET_OBJ.as_bytes());
    let args = |json: bool| {
        let mut a = vec![
            "check".to_string(),
            dir.display().to_string(),
            extra.display().to_string(),
            "--precision".into(),
            "f64".into(),
            "--only".into(),
            "T01".into(),
        ];
        if json {
            a.push("--json".into());
        }
        a
    };
    let run = |a: Vec<String>| penner(&a.iter().map(String::as_str).collect::<Vec<_>>());
    let out = run(args(false));
    let (s, err) = (text(&out.stdout), text(&out.stderr));
    assert_eq!(out.status.code(), Some(3), "{s}\n{err}");
    assert!(err.contains("bad.off") && err.contains("line 5"), "{err}");
    let at = |name: &str| s.find(&format!("{name}: 4 vertices")).unwrap_or(usize::MAX);
    let order = ["a.json", "b.off", "c.OBJ", "extra.obj"].map(at);
    assert!(
        order.windows(2).all(|w| w[0] < w[1] && w[1] != usize::MAX),
        "{s}"
    );
    assert!(!s.contains("notes.txt") && !s.contains("penner-failure") && !s.contains("sub.json"));
    let out = run(args(true));
    assert_eq!(out.status.code(), Some(3));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let files: Vec<&str> = v
        .as_array()
        .unwrap()
        .iter()
        .map(|o| o["file"].as_str().unwrap())
        .collect();
    let names: Vec<&str> = files
        .iter()
        .map(|f| f.rsplit('/').next().unwrap())
        .collect();
    assert_eq!(names, ["a.json", "b.off", "bad.off", "c.OBJ", "extra.obj"]);
    for o in v.as_array().unwrap() {
        if o["file"].as_str().unwrap().ends_with("bad.off") {
            assert_eq!(o["exit_code"], 3);
            assert!(o["error"].as_str().unwrap().contains("line 5"), "{o}");
        } else {
            assert_eq!(o["status"], "holds", "{o}");
        }
    }
    // Negative control: the good files alone hold; one file alone prints one object.
    std::fs::remove_file(dir.join("bad.off")).unwrap();
    assert_eq!(run(args(false)).status.code(), Some(0));
    let one = penner(&[
        "check",
        &extra.display().to_string(),
        "--precision",
        "f64",
        "--only",
        "T01",
        "--json",
    ]);
    let v: serde_json::Value = serde_json::from_slice(&one.stdout).unwrap();
    assert!(v.is_object() && v["status"] == "holds", "{v}");
    // --lengths goes with one file only.
    let l = write(&d, "l.json", b"[1]");
    let out = penner(&[
        "check",
        &extra.display().to_string(),
        &extra.display().to_string(),
        "--lengths",
        &l.display().to_string(),
    ]);
    assert_refused(&out, 3, &["--lengths"]);
}
