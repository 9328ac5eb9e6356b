//! `penner check --negative-controls` end to end: every applicable control fails, a new
//! failure file is written for each (never over an existing file), and `penner replay`
//! reproduces each failure.

use crate::support::{penner, scratch, text, write};
use std::fmt::Write as _;
use std::path::Path;

const TET_OBJ: &str =
    "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n";

/// The 2 × 2 grid of unit squares in the plane z = 0, each cut by a diagonal.
fn grid_obj() -> String {
    let mut s = String::new();
    for j in 0..3 {
        for i in 0..3 {
            let _ = writeln!(s, "v {i} {j} 0");
        }
    }
    let idx = |i: u32, j: u32| j * 3 + i + 1;
    for j in 0..2 {
        for i in 0..2 {
            let (a, b, c, d) = (idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1));
            let _ = writeln!(s, "f {a} {b} {c}\nf {a} {c} {d}");
        }
    }
    s
}

fn failure_files(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(Result::ok)
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains(".penner-failure-"))
        .collect();
    v.sort();
    v
}

#[test]
fn negative_controls_write_fresh_failure_files_that_replay_reproduces() {
    let d = scratch("controls");
    let p = write(&d, "tet.obj", TET_OBJ.as_bytes());
    // A file in the way: the first fresh name is taken and must survive untouched.
    let blocker = d.join("tet.penner-failure-1.json");
    std::fs::write(&blocker, "not mine").unwrap();
    let out = penner(&["check", &p.display().to_string(), "--negative-controls"]);
    let stdout = text(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{stdout}\n{}",
        text(&out.stderr)
    );
    for id in ["T01-NC", "T05-NC", "T16-NC", "T20-NC"] {
        assert!(
            stdout.contains(&format!("{id} (")) && stdout.contains("rejected as expected"),
            "{id}: {stdout}"
        );
    }
    assert_eq!(std::fs::read_to_string(&blocker).unwrap(), "not mine");
    let rejected = stdout
        .lines()
        .filter(|l| l.contains("-NC (") && l.contains("rejected as expected"))
        .count();
    let first = failure_files(&d);
    // The blocker and one per failing control.
    assert_eq!(first.len(), 1 + rejected, "{first:?}");
    // A second run adds new files and changes none of the old ones.
    let before: Vec<String> = first
        .iter()
        .map(|n| std::fs::read_to_string(d.join(n)).unwrap())
        .collect();
    let again = penner(&["check", &p.display().to_string(), "--negative-controls"]);
    assert_eq!(again.status.code(), Some(0));
    let second = failure_files(&d);
    assert_eq!(second.len(), 1 + 2 * rejected, "{second:?}");
    for (n, b) in first.iter().zip(&before) {
        assert_eq!(
            &std::fs::read_to_string(d.join(n)).unwrap(),
            b,
            "{n} changed"
        );
    }
    // Each written file replays to the same failure (exit 1, "still fails").
    for n in second.iter().filter(|n| !n.ends_with("-1.json")) {
        let r = penner(&["replay", &d.join(n).display().to_string()]);
        let o = text(&r.stdout);
        assert_eq!(r.status.code(), Some(1), "{n}: {o}");
        assert!(
            o.contains("-NC at ") && o.contains("still fails"),
            "{n}: {o}"
        );
    }
}

#[test]
fn t04_negative_control_on_a_planar_grid_fails_and_replays() {
    let d = scratch("controls-grid");
    let p = write(&d, "grid.obj", grid_obj().as_bytes());
    let out = penner(&[
        "check",
        &p.display().to_string(),
        "--negative-controls",
        "--only",
        "T04",
    ]);
    let stdout = text(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{stdout}");
    assert!(
        stdout.contains("T04-NC") && stdout.contains("rejected as expected"),
        "{stdout}"
    );
    let files = failure_files(&d);
    assert_eq!(files, ["grid.penner-failure-1.json"]);
    let r = penner(&["replay", &d.join(&files[0]).display().to_string()]);
    assert_eq!(r.status.code(), Some(1), "{}", text(&r.stdout));
    // The unperturbed check holds on the same grid: the control's failure is the
    // perturbation's doing.
    let ok = penner(&[
        "check",
        &p.display().to_string(),
        "--only",
        "T04",
        "--no-failure-files",
    ]);
    assert_eq!(ok.status.code(), Some(0), "{}", text(&ok.stdout));
}

#[test]
fn negative_controls_refuse_an_unknown_id() {
    let d = scratch("controls-bad");
    let p = write(&d, "tet.obj", TET_OBJ.as_bytes());
    let out = penner(&[
        "check",
        &p.display().to_string(),
        "--negative-controls",
        "--only",
        "T99",
    ]);
    assert_eq!(out.status.code(), Some(3));
    assert!(text(&out.stderr).contains("T99"));
    assert!(failure_files(&d).is_empty());
}

/// The two-triangle sphere and the one-vertex torus with lengths 4, 5, 6 (JSON).
const SPHERE_JSON: &str =
    r#"{"vertices": 3, "faces": [[0, 1, 2], [0, 2, 1]], "lengths": ["4", "5", "6"]}"#;
const TORUS_JSON: &str = r#"{"vertices": 1, "faces": [[0, 0, 0], [0, 0, 0]],
  "gluing": [[[0, 0], [1, 0]], [[0, 1], [1, 1]], [[0, 2], [1, 2]]], "lengths": ["4", "5", "6"]}"#;

/// Run every control on `file` in `dir`: exit 0, every control line either rejected or not
/// applicable, one failure file per rejecting control, each replayed as "still fails".
/// Returns the IDs rejected.
fn all_controls_fail_and_replay(dir: &Path, file: &str, body: &str) -> Vec<String> {
    let p = write(dir, file, body.as_bytes());
    let out = penner(&["check", &p.display().to_string(), "--negative-controls"]);
    let stdout = text(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{stdout}\n{}",
        text(&out.stderr)
    );
    let mut rejected = Vec::new();
    for line in stdout.lines().filter(|l| l.contains("-NC (")) {
        assert!(
            line.contains("rejected as expected") || line.contains("not applicable"),
            "{line}"
        );
        if line.contains("rejected as expected") {
            rejected.push(line.split_whitespace().next().unwrap().to_string());
        }
    }
    let files = failure_files(dir);
    assert_eq!(files.len(), rejected.len(), "{files:?} vs {rejected:?}");
    for n in &files {
        let r = penner(&["replay", &dir.join(n).display().to_string()]);
        let o = text(&r.stdout);
        assert_eq!(r.status.code(), Some(1), "{n}: {o}");
        assert!(
            o.contains("-NC at ") && o.contains("still fails"),
            "{n}: {o}"
        );
    }
    rejected
}

#[test]
fn every_applicable_control_fails_and_replays_on_a_grid_and_the_three_edge_surfaces() {
    let grid = all_controls_fail_and_replay(&scratch("controls-all-grid"), "grid.obj", &grid_obj());
    for id in [
        "T01-NC", "T03-NC", "T04-NC", "T05-NC", "T07-NC", "T15-NC", "T16-NC", "T17-NC", "T20-NC",
        "T21-NC", "T22-NC", "T23-NC", "T27-NC", "T29-NC",
    ] {
        assert!(
            grid.iter().any(|x| x == id),
            "{id} not rejected on the grid: {grid:?}"
        );
    }
    let sphere =
        all_controls_fail_and_replay(&scratch("controls-all-sphere"), "s.json", SPHERE_JSON);
    assert!(sphere.iter().any(|x| x == "T18-NC"), "{sphere:?}");
    let torus = all_controls_fail_and_replay(&scratch("controls-all-torus"), "t.json", TORUS_JSON);
    assert!(
        torus.iter().any(|x| x == "T19-NC") && torus.iter().any(|x| x == "T28-NC"),
        "{torus:?}"
    );
}
