//! Files in and out of the `penner` binary at scale: every write error is exit code 4,
//! special files are refused before they are opened, a huge surface name is not copied
//! into every report row, and every format `penner delaunay` writes reads back to the
//! same mesh and bit-identical lengths.

use crate::meshgen;
use crate::support::{assert_refused, penner, scratch, text, write};
use penner::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use penner::io::{json, obj, off, write as writer, Metric, Surface};
use penner::mesh::{builders, Mesh};
use penner::scalar::Mpfr;
use rug::Rational;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::Duration;

const BIN: &str = env!("CARGO_BIN_EXE_penner");

const TETRAHEDRON: &str = r#"{"vertices": 4,
  "faces": [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]],
  "lengths": ["1", "1", "1", "1", "1", "1"]}"#;

/// Run penner with standard output going to `stdout`, to completion or a 60 s deadline
/// (a blocked process is killed and reported).
fn run_with(args: &[&str], stdout: Stdio) -> Output {
    let child = Command::new(BIN)
        .args(args)
        .env_remove("RUST_BACKTRACE")
        .stdin(Stdio::null())
        .stdout(stdout)
        .stderr(Stdio::piped())
        .spawn()
        .expect("run penner");
    let id = child.id();
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(child.wait_with_output());
    });
    let Ok(out) = rx.recv_timeout(Duration::from_secs(60)) else {
        let _ = Command::new("kill").arg("-9").arg(id.to_string()).status();
        panic!("penner {args:?} blocked for 60 s");
    };
    out.expect("output")
}

fn dev_full() -> Stdio {
    Stdio::from(
        std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .expect("/dev/full"),
    )
}

#[test]
fn every_writing_subcommand_exits_4_on_a_full_disk() {
    let d = scratch("io-full");
    let tet = write(&d, "tet.json", TETRAHEDRON.as_bytes())
        .display()
        .to_string();
    let claim = serde_json::json!({"penner_claim": 1, "kind": "intrinsic_delaunay",
        "surface": serde_json::from_str::<serde_json::Value>(TETRAHEDRON).unwrap()});
    let claim = write(&d, "claim.json", claim.to_string().as_bytes())
        .display()
        .to_string();
    let commands: [Vec<&str>; 6] = [
        vec!["delaunay", &tet, "--precision", "f64"],
        vec!["delaunay", &tet],
        vec!["check", &tet, "--json", "--precision", "f64"],
        vec!["check", &tet, "--precision", "f64"],
        vec!["report", "--json", "--precision", "f64"],
        vec!["certify", &claim],
    ];
    for args in &commands {
        // Negative control: to a pipe, the same command succeeds.
        let ok = run_with(args, Stdio::piped());
        assert_eq!(ok.status.code(), Some(0), "{args:?}: {}", text(&ok.stderr));
        assert!(!ok.stdout.is_empty(), "{args:?}");
        let full = run_with(args, dev_full());
        assert_refused(&full, 4, &["standard output"]);
    }
    // A bad claim to a full disk: the refusal could not be written either.
    let bad = write(&d, "bad.json", b"{").display().to_string();
    assert_refused(
        &run_with(&["certify", &bad], dev_full()),
        4,
        &["standard output"],
    );
}

fn mkfifo(path: &Path) {
    let st = Command::new("mkfifo").arg(path).status().expect("mkfifo");
    assert!(st.success());
}

#[test]
fn fifos_and_devices_are_refused_without_blocking() {
    let d = scratch("io-fifo");
    let fifo = d.join("x.json");
    mkfifo(&fifo);
    let fifo_off = d.join("x.off");
    mkfifo(&fifo_off);
    let f = fifo.display().to_string();
    let fo = fifo_off.display().to_string();
    for args in [
        vec!["check", f.as_str()],
        vec!["delaunay", f.as_str()],
        vec!["delaunay", fo.as_str(), "--precision", "f64"],
        vec!["certify", f.as_str()],
        vec!["replay", f.as_str()],
    ] {
        assert_refused(&run_with(&args, Stdio::piped()), 3, &["x.", "FIFO"]);
    }
    assert_refused(
        &run_with(&["certify", "/dev/zero"], Stdio::piped()),
        3,
        &["/dev/zero", "device"],
    );
    // The library refuses it too, with a typed error.
    assert!(matches!(
        penner::io::read_path(&fifo),
        Err(penner::io::ReadError::NotAFile { kind: "a FIFO", .. })
    ));
    // Negative control: a regular file under the same name is read.
    std::fs::remove_file(&fifo).unwrap();
    std::fs::write(&fifo, TETRAHEDRON).unwrap();
    let ok = run_with(&["check", &f, "--precision", "f64"], Stdio::piped());
    assert_eq!(ok.status.code(), Some(0), "{}", text(&ok.stderr));
}

#[test]
fn a_huge_surface_name_is_stored_once_and_shown_cut() {
    let d = scratch("io-name");
    let name = "n".repeat(8 << 20);
    let mut v: serde_json::Value = serde_json::from_str(TETRAHEDRON).unwrap();
    v["name"] = serde_json::Value::String(name.clone());
    let p = write(&d, "named.json", v.to_string().as_bytes());
    let out = penner(&[
        "check",
        &p.display().to_string(),
        "--json",
        "--precision",
        "f64,dd",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let rows = doc["rows"].as_array().unwrap();
    assert!(rows.len() > 10);
    // One copy of the name would already be 8 MiB: each row shows its first 256 chars.
    assert!(out.stdout.len() < 1 << 20, "{} bytes", out.stdout.len());
    for r in rows {
        let shown = r["case"].as_str().unwrap();
        assert!(
            shown.starts_with(&name[..256]) && shown.contains("more bytes"),
            "{shown:.300}"
        );
    }
    // In the library, every row of a case shares the one name.
    let s = json::read(&v.to_string()).unwrap();
    let rows = penner::oracle::registry::run_case(
        &s,
        &penner::oracle::catalogue(),
        &[penner::oracle::Prec::F64],
        &penner::theorems::Settings::default(),
    );
    assert!(rows.len() > 5);
    assert!(rows
        .iter()
        .all(|r| std::sync::Arc::ptr_eq(&r.case, &rows[0].case)));
    assert_eq!(&*rows[0].case, name.as_str());
}

/// A noisy icosphere (frequency `k`) as OFF text, and the flips of its f64 lengths done
/// in the library from the exact surface: the reference the binary's output must match.
fn sphere_and_reference(k: u32, seed: u64) -> (String, Mesh, Vec<f64>) {
    let mut e = meshgen::icosphere(k);
    let a = e.mean_edge();
    e.jitter_radial(a, seed);
    let mut out = Vec::new();
    e.write_off(&mut out).unwrap();
    let text = String::from_utf8(out).unwrap();
    let s = off::read(&text).unwrap();
    let mut mesh = s.mesh.clone();
    let mut l: Vec<f64> = s.lengths(());
    let r = flip_to_delaunay(
        &mut mesh,
        &mut l,
        FlipKind::Euclidean,
        &FlipOptions::default(),
    )
    .unwrap();
    assert!(r.flips > 0, "the noisy sphere needs flips");
    (text, mesh, l)
}

/// The gluing as sorted pairs of face sides, whatever the edge numbering.
fn glued(mesh: &Mesh) -> Vec<((u32, u8), (u32, u8))> {
    let mut g: Vec<_> = mesh
        .gluing_list()
        .into_iter()
        .map(|(p, q)| (p.min(q), p.max(q)))
        .collect();
    g.sort_unstable();
    g
}

/// Lengths in the edge order of surface JSON, exactly.
fn ordered(mesh: &Mesh, l: &[Rational]) -> Vec<Rational> {
    json::edge_order(mesh)
        .iter()
        .map(|&e| l[e].clone())
        .collect()
}

fn exact_f64(l: &[f64]) -> Vec<Rational> {
    l.iter().map(|&x| Rational::from_f64(x).unwrap()).collect()
}

fn delaunay(input: &Path, extra: &[&str]) {
    let mut args = vec!["delaunay", input.to_str().unwrap()];
    args.extend_from_slice(extra);
    let out = penner(&args);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{args:?}: {}",
        text(&out.stderr)
    );
}

/// `delaunay -o b.off|b.obj --lengths-out …` on `input`: the input positions, the
/// flipped faces of `mesh`, and the lengths `want` (edge order of surface JSON), read back
/// by the library and by `penner check --lengths`.
fn off_and_obj_read_back(
    d: &Path,
    input: &Path,
    mesh: &Mesh,
    want: &[Rational],
    positions: &[[Rational; 3]],
) {
    let path = |n: &str| -> PathBuf { d.join(n) };
    // OFF and OBJ with a lengths file: the input positions, the flipped faces.
    for ext in ["off", "obj"] {
        let o = path(&format!("b.{ext}"));
        let lf = path(&format!("b-{ext}.lengths.json"));
        delaunay(
            input,
            &[
                "--precision",
                "f64",
                "-o",
                o.to_str().unwrap(),
                "--lengths-out",
                lf.to_str().unwrap(),
            ],
        );
        let t = std::fs::read_to_string(&o).unwrap();
        let s = if ext == "off" {
            off::read(&t)
        } else {
            obj::read(&t)
        };
        let s = s.unwrap();
        assert_eq!(s.mesh.face_list(), mesh.face_list(), "{ext}");
        assert_eq!(s.positions.as_deref().unwrap(), positions, "{ext}");
        let back = writer::read_lengths(&std::fs::read_to_string(&lf).unwrap(), &s.mesh).unwrap();
        assert_eq!(ordered(&s.mesh, &back), want, "{ext}");
        // `penner check` reads the pair back: the flipped triangulation is Delaunay (T21
        // holds on it), and a lengths file of the wrong size is refused naming it.
        let c = penner(&[
            "check",
            o.to_str().unwrap(),
            "--lengths",
            lf.to_str().unwrap(),
            "--only",
            "T21",
            "--precision",
            "f64",
        ]);
        assert_eq!(c.status.code(), Some(0), "{ext}: {}", text(&c.stderr));
        let short = write(d, "short.json", b"[1, 1, 1]");
        let c = penner(&[
            "check",
            o.to_str().unwrap(),
            "--lengths",
            short.to_str().unwrap(),
        ]);
        assert_refused(&c, 3, &["short.json", "values for"]);
    }
}

#[test]
fn every_format_delaunay_writes_reads_back_bit_identical() {
    let d = scratch("io-roundtrip");
    let (off_text, mesh, l) = sphere_and_reference(7, 5);
    let input = write(&d, "sphere.off", off_text.as_bytes());
    let want = ordered(&mesh, &exact_f64(&l));
    let positions = off::read(&off_text).unwrap().positions.unwrap();
    let path = |n: &str| -> PathBuf { d.join(n) };
    // Compact JSON at f64: lengths as JSON numbers, no gluing needed.
    delaunay(
        &input,
        &["--precision", "f64", "-o", path("a.json").to_str().unwrap()],
    );
    let a_text = std::fs::read_to_string(path("a.json")).unwrap();
    assert!(a_text.starts_with(writer::JSON_MARKER));
    assert!(!a_text.contains("gluing"));
    // One face or one length per line.
    assert!(a_text.lines().count() > mesh.n_faces() + mesh.n_edges());
    let a = json::read(&a_text).unwrap();
    assert_eq!(a.mesh.face_list(), mesh.face_list());
    assert_eq!(glued(&a.mesh), glued(&mesh));
    assert_eq!(ordered(&a.mesh, a.metric.values()), want);
    off_and_obj_read_back(&d, &input, &mesh, &want, &positions);
    // At 256 bits: exact strings; the reference is the library's MPFR flip.
    delaunay(
        &input,
        &["--precision", "256", "-o", path("c.json").to_str().unwrap()],
    );
    let c = json::read(&std::fs::read_to_string(path("c.json")).unwrap()).unwrap();
    let s = off::read(&off_text).unwrap();
    let mut m = s.mesh.clone();
    let mut lm: Vec<Mpfr> = s.lengths(penner::scalar::Precision::new(256).unwrap());
    flip_to_delaunay(
        &mut m,
        &mut lm,
        FlipKind::Euclidean,
        &FlipOptions::default(),
    )
    .unwrap();
    let want256: Vec<Rational> = lm
        .iter()
        .map(|x| penner::scalar::Real::to_rational(x).unwrap())
        .collect();
    assert_eq!(c.mesh.face_list(), m.face_list());
    assert_eq!(ordered(&c.mesh, c.metric.values()), ordered(&m, &want256));
    // Negative control: a length moved by one ulp in the file is seen.
    let moved = a_text.replacen(
        &format!("{:e}", l[json::edge_order(&mesh)[0]]),
        &format!(
            "{:e}",
            f64::from_bits(l[json::edge_order(&mesh)[0]].to_bits() + 1)
        ),
        1,
    );
    assert_ne!(moved, a_text);
    let a2 = json::read(&moved).unwrap();
    assert_ne!(ordered(&a2.mesh, a2.metric.values()), want);
    // A lengths file goes with OBJ/OFF only, and an existing file is never overwritten.
    let out = penner(&[
        "delaunay",
        input.to_str().unwrap(),
        "--lengths-out",
        path("z").to_str().unwrap(),
    ]);
    assert_refused(&out, 3, &["--lengths-out"]);
    let lf = path("b-off.lengths.json");
    let before = std::fs::read(&lf).unwrap();
    let out = penner(&[
        "delaunay",
        input.to_str().unwrap(),
        "-o",
        path("new.off").to_str().unwrap(),
        "--lengths-out",
        lf.to_str().unwrap(),
    ]);
    assert_refused(&out, 4, &["exists"]);
    assert_eq!(std::fs::read(&lf).unwrap(), before);
    assert!(!path("new.off").exists());
}

#[test]
fn compact_json_needs_gluing_only_where_faces_do_not_determine_it() {
    // The one-vertex torus (every side a loop) is not determined by its faces; the
    // tetrahedron is.
    let torus = Surface::new(
        "torus",
        builders::one_vertex_torus(),
        Metric::Lengths(vec![Rational::from(1); 3]),
        None,
    )
    .unwrap();
    let tet = Surface::from_embedded("t", builders::tetrahedron()).unwrap();
    for (s, determined) in [(&torus, false), (&tet, true)] {
        assert_eq!(writer::faces_determine_gluing(&s.mesh), determined);
        let mut out = Vec::new();
        writer::surface_json(&mut out, s).unwrap();
        let t = String::from_utf8(out).unwrap();
        // Loops are written as gluing exceptions (the full gluing is never needed here).
        assert_eq!(t.contains("\"gluing_exceptions\""), !determined);
        assert!(!t.contains("\"gluing\""));
        let back = json::read(&t).unwrap();
        assert_eq!(back.mesh.face_list(), s.mesh.face_list());
        assert_eq!(glued(&back.mesh), glued(&s.mesh));
        assert_eq!(back.positions, s.positions);
        assert_eq!(
            ordered(&back.mesh, back.metric.values()),
            ordered(&s.mesh, s.metric.values())
        );
        assert_eq!(
            matches!(back.metric, Metric::Lengths(_)),
            matches!(s.metric, Metric::Lengths(_))
        );
    }
}

/// Parallel edges (a tetrahedron with one edge flipped: two edges join the same two
/// vertices) and loops (the one-vertex torus) are written as `gluing_exceptions`: only the
/// pairs the vertex triples cannot describe; the file reads back to the same faces, gluing
/// and values; a disk bounded by two parallel edges, which no exception list describes,
/// gets the full gluing. Negative controls: the file without the field is refused with a
/// typed error; without one pair the torus's loops are refused; crossed pairs are refused
/// or glue another surface; `gluing` and `gluing_exceptions` together are refused.
#[test]
fn compact_json_writes_gluing_exceptions_that_read_back_exactly() {
    let mut flipped = builders::tetrahedron().mesh;
    let e = flipped.edges().next().unwrap();
    flipped.flip(e).unwrap();
    let tet = Surface::new(
        "flipped tetrahedron",
        flipped,
        Metric::Lengths(vec![Rational::from(1); 6]),
        None,
    )
    .unwrap();
    let torus = Surface::new(
        "torus",
        builders::one_vertex_torus(),
        Metric::Lengths(vec![Rational::from((3, 2)); 3]),
        None,
    )
    .unwrap();
    for (s, listed) in [(&tet, 2), (&torus, 3)] {
        assert!(!writer::faces_determine_gluing(&s.mesh));
        let pairs = writer::gluing_exceptions(&s.mesh).unwrap();
        assert_eq!(pairs.len(), listed, "{}", s.name);
        let mut out = Vec::new();
        writer::surface_json(&mut out, s).unwrap();
        let t = String::from_utf8(out).unwrap();
        assert!(t.contains("\"gluing_exceptions\":[") && !t.contains("\"gluing\":"));
        let back = json::read(&t).unwrap();
        assert_eq!(back.mesh.face_list(), s.mesh.face_list());
        assert_eq!(glued(&back.mesh), glued(&s.mesh));
        assert_eq!(
            ordered(&back.mesh, back.metric.values()),
            ordered(&s.mesh, s.metric.values())
        );
        // Negative controls on the file's JSON value: without the field the triples are
        // ambiguous (refused); without one pair, the loops of the torus are refused, while
        // one pair of the tetrahedron's two parallel edges still determines the other;
        // pairs crossed between two edges are refused or glue another surface.
        let v: serde_json::Value = serde_json::from_str(&t).unwrap();
        let mut none = v.clone();
        none.as_object_mut().unwrap().remove("gluing_exceptions");
        let err = json::read(&none.to_string()).unwrap_err();
        assert!(matches!(err, penner::io::ReadError::Mesh { .. }), "{err}");
        let mut one_less = v.clone();
        one_less["gluing_exceptions"].as_array_mut().unwrap().pop();
        match json::read(&one_less.to_string()) {
            Ok(b) => {
                assert_eq!(listed, 2);
                assert_eq!(glued(&b.mesh), glued(&s.mesh));
            }
            Err(err) => {
                assert_eq!(listed, 3);
                assert!(matches!(err, penner::io::ReadError::Mesh { .. }), "{err}");
            }
        }
        let mut crossed = v.clone();
        let ex = crossed["gluing_exceptions"].as_array_mut().unwrap();
        let second = ex[0][1].clone();
        ex[0][1] = ex[1][1].clone();
        ex[1][1] = second;
        if let Ok(b) = json::read(&crossed.to_string()) {
            assert_ne!(glued(&b.mesh), glued(&s.mesh), "{}", s.name);
        }
        let mut both = v.clone();
        both["gluing"] = serde_json::to_value(
            s.mesh
                .gluing_list()
                .iter()
                .map(|&((f, a), (g, b))| [[f, u32::from(a)], [g, u32::from(b)]])
                .collect::<Vec<_>>(),
        )
        .unwrap();
        let err = json::read(&both.to_string()).unwrap_err().to_string();
        assert!(err.contains("gluing_exceptions"), "{err}");
    }
    // A disk bounded by two edges between the same vertices (sides 0→1 and 1→0 both on
    // the boundary): the triples would glue them, so no exception list describes it and
    // the full gluing is written.
    let bigon = Surface::new(
        "bigon",
        Mesh::from_gluing(
            3,
            &[[0, 1, 2], [1, 0, 2]],
            &[((0, 1), (1, 2)), ((0, 2), (1, 1))],
        )
        .unwrap(),
        Metric::Lengths(vec![Rational::from(1); 4]),
        None,
    )
    .unwrap();
    assert_eq!(writer::gluing_exceptions(&bigon.mesh), None);
    let mut out = Vec::new();
    writer::surface_json(&mut out, &bigon).unwrap();
    let t = String::from_utf8(out).unwrap();
    assert!(
        t.contains("\"gluing\":[") && !t.contains("gluing_exceptions"),
        "{t}"
    );
    let back = json::read(&t).unwrap();
    assert_eq!(glued(&back.mesh), glued(&bigon.mesh));
    assert_eq!(back.mesh.n_boundary_edges(), 2);
    // The full gluing of older files still reads to the same surface.
    let old = json::write(&tet);
    assert!(old.contains("\"gluing\""));
    let back = json::read(&old).unwrap();
    assert_eq!(glued(&back.mesh), glued(&tet.mesh));
}

#[test]
fn penner_reads_back_its_own_json_past_the_input_limit() {
    // A surface JSON as penner writes it, padded past 256 MiB by a long name (the limit
    // for other files): read. The same bytes without the marker: refused. Half a GiB of
    // files: in the long mode only.
    if crate::support::cases(0, 1) == 0 {
        return;
    }
    let d = scratch("io-limit");
    let mut v: serde_json::Value = serde_json::from_str(TETRAHEDRON).unwrap();
    v["name"] = serde_json::Value::String("x".repeat((256 << 20) + 16));
    let s = json::read(&v.to_string()).unwrap();
    let mut out = Vec::new();
    writer::surface_json(&mut out, &s).unwrap();
    drop((v, s));
    let ours = write(&d, "ours.json", &out);
    let r = penner(&[
        "check",
        ours.to_str().unwrap(),
        "--only",
        "T01",
        "--precision",
        "f64",
    ]);
    assert_eq!(r.status.code(), Some(0), "{}", text(&r.stderr));
    out[2] = b'F'; // "{\"Format\"…": not penner's marker
    let other = write(&d, "other.json", &out);
    drop(out);
    assert_refused(
        &penner(&["check", other.to_str().unwrap()]),
        3,
        &["input limit"],
    );
}
