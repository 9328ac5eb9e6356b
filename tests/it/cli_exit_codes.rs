//! Exit codes as documented, on every subcommand: 5 for a defect inside penner (a panic,
//! provoked here by the test-only variable `PENNER_INTERNAL_PANIC_TEST`), 3 for bad input
//! or usage — including a check asked for at a precision where it has no form — and never
//! 101 or a backtrace.

use crate::support::{penner, scratch, text, write};
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_penner");

const TETRAHEDRON: &str = r#"{"vertices": 4,
  "faces": [[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]],
  "lengths": ["1", "1", "1", "1", "1", "1"]}"#;

#[test]
fn a_panic_inside_any_subcommand_is_exit_5_with_one_line_naming_the_command() {
    let d = scratch("exit-5");
    let surface = write(&d, "tet.json", TETRAHEDRON.as_bytes());
    let s = surface.to_str().expect("path");
    let claim = write(&d, "claim.json", b"{}");
    let c = claim.to_str().expect("path");
    for args in [
        vec!["check", s],
        vec!["delaunay", s],
        vec!["uniformize", s, "--flat"],
        vec!["pack", s],
        vec!["certify", c],
        vec!["replay", c],
        vec!["report"],
    ] {
        let out = Command::new(BIN)
            .args(&args)
            .env("PENNER_INTERNAL_PANIC_TEST", "1")
            .env_remove("RUST_BACKTRACE")
            .output()
            .expect("run penner");
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(5), "{args:?}: {err}");
        assert!(
            err.contains("internal error while running `penner"),
            "{args:?}: {err}"
        );
        assert!(err.contains(args[0]), "{args:?}: {err}");
        assert!(!err.contains("stack backtrace"), "{args:?}: {err}");
    }
    // Control: without the variable the same command is not a defect.
    let out = penner(&["check", s, "--only", "T01", "--precision", "f64"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
}

#[test]
fn a_check_without_a_form_at_the_precision_asked_is_bad_usage_not_an_empty_report() {
    let d = scratch("exit-no-form");
    let surface = write(&d, "tet.json", TETRAHEDRON.as_bytes());
    let s = surface.to_str().expect("path");
    let out = penner(&["check", s, "--only", "T26", "--precision", "f64"]);
    assert_eq!(out.status.code(), Some(3), "{}", text(&out.stdout));
    assert!(
        text(&out.stderr).contains("no form at the precisions asked"),
        "{}",
        text(&out.stderr)
    );
    // Control: at `exact` the same check runs and holds.
    let out = penner(&["check", s, "--only", "T26", "--precision", "exact"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
}

#[test]
fn replaying_a_check_without_a_form_at_its_precision_says_so() {
    use penner::oracle::failure::Failure;
    use penner::oracle::precision::Prec;
    use penner::theorems::Witness;
    let d = scratch("exit-replay-no-form");
    let surface = penner::io::json::read(TETRAHEDRON).expect("tetrahedron");
    let failure = |precision| Failure {
        check: "T26".into(),
        precision,
        source: "tet.json".into(),
        source_faces: 4,
        witnesses: vec![Witness {
            element: "v0".into(),
            detail: "made up for the test".into(),
            value: 1.0,
        }],
        surface: surface.clone(),
    };
    let f64_file = write(
        &d,
        "f64.json",
        failure(Prec::F64).to_json().to_string().as_bytes(),
    );
    let out = penner(&["replay", f64_file.to_str().expect("path")]);
    assert_eq!(out.status.code(), Some(3), "{}", text(&out.stdout));
    assert!(
        text(&out.stderr).contains("has no form at f64"),
        "{}",
        text(&out.stderr)
    );
    // Control: at `exact` the check runs; it holds on the tetrahedron, so the failure no
    // longer reproduces.
    let exact_file = write(
        &d,
        "exact.json",
        failure(Prec::Exact).to_json().to_string().as_bytes(),
    );
    let out = penner(&["replay", exact_file.to_str().expect("path")]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(
        text(&out.stdout).contains("no longer fails"),
        "{}",
        text(&out.stdout)
    );
}

/// A regular tetrahedron with every length `side` (an exact decimal string).
fn tetrahedron_of_side(side: &str) -> String {
    let l = vec![format!("\"{side}\""); 6].join(", ");
    format!(
        r#"{{"vertices": 4, "faces": [[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]], "lengths": [{l}]}}"#
    )
}

#[test]
fn delaunay_at_binary64_names_lengths_outside_its_range_and_mpfr_takes_them() {
    let d = scratch("exit-binary64-range");
    for (side, word) in [("1e400", "beyond"), ("1e-400", "below")] {
        let surface = write(
            &d,
            &format!("tet{side}.json"),
            tetrahedron_of_side(side).as_bytes(),
        );
        let s = surface.to_str().expect("path");
        for prec in ["f64", "dd"] {
            let out = penner(&["delaunay", s, "--precision", prec]);
            let err = text(&out.stderr);
            assert_eq!(out.status.code(), Some(3), "{side} at {prec}: {err}");
            assert!(
                err.contains(&format!("edge e0 has a length {word} the binary64 range")),
                "{side} at {prec}: {err}"
            );
            assert!(!err.contains("inf"), "{err}");
        }
        // Control: MPFR's exponent range holds the same lengths; the tetrahedron is Delaunay.
        let out = penner(&["delaunay", s, "--precision", "128"]);
        assert_eq!(out.status.code(), Some(0), "{side}: {}", text(&out.stderr));
    }
    // Positions (OBJ): coordinates 1e200 and 1e-200 give lengths inside binary64 whose
    // squares leave it; 1e400 gives lengths beyond it. MPFR takes all three.
    for (scale, word) in [
        ("1e200", "squared length overflows binary64"),
        ("1e-200", "squared length underflows binary64"),
        ("1e400", "has a length beyond the binary64 range"),
    ] {
        let obj = format!(
            "v 0 0 0\nv {scale} 0 0\nv 0 {scale} 0\nv 0 0 {scale}\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n"
        );
        let surface = write(&d, &format!("tet{scale}.obj"), obj.as_bytes());
        let s = surface.to_str().expect("path");
        let out = penner(&["delaunay", s, "--precision", "f64"]);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(3), "{scale}: {err}");
        assert!(
            err.contains(&format!(
                "edge e0{}",
                if word.starts_with("has") { " " } else { "'s " }
            )) && err.contains(word),
            "{scale}: {err}"
        );
        let out = penner(&[
            "delaunay",
            s,
            "--precision",
            "128",
            "-o",
            &format!("{s}.out.json"),
        ]);
        assert_eq!(out.status.code(), Some(0), "{scale}: {}", text(&out.stderr));
    }
    // Control: an ordinary length at binary64 is accepted.
    let surface = write(&d, "tet1.json", tetrahedron_of_side("1").as_bytes());
    let out = penner(&[
        "delaunay",
        surface.to_str().expect("path"),
        "--precision",
        "f64",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
}

/// A maximal packing penner does not reach on valid input is not computed (exit 2), never
/// bad input: the tetrahedron punctured at a vertex leaves one triangle without interior
/// vertex, as does a square of two triangles for `--disk`. Control: the octahedron packs.
#[test]
fn pack_without_an_interior_vertex_is_not_computed_not_bad_input() {
    let d = scratch("exit-pack-no-interior");
    let tet = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    let square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";
    let octa = "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n\
                f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";
    for (name, text_of, mode, expected) in [
        ("tet.obj", tet, "--sphere", 2),
        ("square.obj", square, "--disk", 2),
        ("octa.obj", octa, "--sphere", 0),
    ] {
        let p = write(&d, name, text_of.as_bytes());
        let out = penner(&["pack", p.to_str().expect("path"), mode]);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(expected), "{name}: {err}");
        if expected == 2 {
            assert!(
                err.contains("not computed: no interior vertex"),
                "{name}: {err}"
            );
        }
    }
}
