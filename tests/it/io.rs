//! Formats: exact number parsing, surface JSON, OBJ, OFF; every malformed input gets a
//! typed error; no input panics.

use penner::scalar::{parse_rational, NumberError};
use proptest::prelude::*;
use rug::ops::Pow;
use rug::{Integer, Rational};

#[test]
fn numbers_parse_exactly() {
    let q = |a: i64, b: i64| Rational::from((a, b));
    assert_eq!(parse_rational("1.25").unwrap(), q(5, 4));
    assert_eq!(parse_rational("-3/2").unwrap(), q(-3, 2));
    assert_eq!(parse_rational("7e-3").unwrap(), q(7, 1000));
    assert_eq!(parse_rational("0.1").unwrap(), q(1, 10));
    let tiny = parse_rational("1e-30").unwrap();
    assert_eq!(
        tiny,
        Rational::from((Integer::from(1), Integer::from(10).pow(30)))
    );
    assert_eq!(
        parse_rational("1e30").unwrap(),
        Rational::from(Integer::from(10).pow(30))
    );
}

#[test]
fn bad_numbers_are_typed_errors() {
    assert_eq!(parse_rational(""), Err(NumberError::Empty));
    assert!(matches!(
        parse_rational("NaN"),
        Err(NumberError::NotFinite(_))
    ));
    assert!(matches!(
        parse_rational("-inf"),
        Err(NumberError::NotFinite(_))
    ));
    assert!(matches!(
        parse_rational("Infinity"),
        Err(NumberError::NotFinite(_))
    ));
    assert!(matches!(
        parse_rational("1e999999999"),
        Err(NumberError::ExponentTooLarge { .. })
    ));
    assert!(matches!(
        parse_rational("1e-999999999999999999999"),
        Err(NumberError::ExponentTooLarge { .. })
    ));
    assert!(matches!(
        parse_rational("3/0"),
        Err(NumberError::ZeroDenominator(_))
    ));
    assert!(matches!(
        parse_rational(&"9".repeat(20_000)),
        Err(NumberError::TooManyDigits)
    ));
    for s in [
        "abc", "1.2.3", "1e", "--2", "0x1p3", "1/2/3", "½", "1_000", "1e5.5",
    ] {
        assert!(
            matches!(parse_rational(s), Err(NumberError::Invalid { .. })),
            "{s}"
        );
    }
    // The error names the offending position.
    assert_eq!(
        parse_rational("12x4"),
        Err(NumberError::Invalid {
            text: "12x4".into(),
            position: 2,
            reason: "unexpected character"
        })
    );
}

proptest! {
    /// Oracle: Rust prints every binary64 value exactly with 800 significant digits; the
    /// parse must equal rug's exact conversion of the same value.
    #[test]
    fn exact_decimal_of_every_f64_parses_to_it(bits in any::<u64>()) {
        let x = f64::from_bits(bits);
        prop_assume!(x.is_finite());
        let s = format!("{x:.800e}");
        let want = Rational::from_f64(x).unwrap();
        prop_assert_eq!(parse_rational(&s).unwrap(), want);
    }

    /// Oracle: `m·10^e` and `p/q` built with integer arithmetic.
    #[test]
    fn scientific_and_fractions(m in any::<i64>(), e in -300i32..300, p in any::<i64>(), q in 1u64..) {
        let want = if e >= 0 {
            Rational::from(Integer::from(m) * Integer::from(10).pow(e as u32))
        } else {
            Rational::from((Integer::from(m), Integer::from(10).pow((-e) as u32)))
        };
        prop_assert_eq!(parse_rational(&format!("{m}e{e}")).unwrap(), want);
        prop_assert_eq!(parse_rational(&format!("{p}/{q}")).unwrap(), Rational::from((Integer::from(p), Integer::from(q))));
    }

    /// No string makes the parser panic.
    #[test]
    fn number_parser_never_panics(s in ".{0,40}") {
        let _ = parse_rational(&s);
    }
}

// ---------------------------------------------------------------- surfaces and JSON

use penner::io::{json, obj, off, Metric, MetricError, ReadError, Surface};
use penner::mesh::builders::{self, CubeDiagonals};
use penner::mesh::MeshError;

fn standard_surfaces() -> Vec<Surface> {
    let mut v = vec![
        Surface::from_embedded("tet", builders::tetrahedron()).unwrap(),
        Surface::from_embedded("oct", builders::octahedron()).unwrap(),
        Surface::from_embedded("ico", builders::icosahedron()).unwrap(),
        Surface::from_embedded("cube", builders::cube(CubeDiagonals::Odd)).unwrap(),
        Surface::from_embedded("triakis", builders::triakis_octahedron()).unwrap(),
        Surface::from_embedded("grid", builders::grid_disk(3, 2).unwrap()).unwrap(),
        Surface::from_embedded("annulus", builders::annulus(5, 2).unwrap()).unwrap(),
        Surface::from_intrinsic("torus", builders::flat_torus(1, 1).unwrap()).unwrap(),
        Surface::from_intrinsic("torus23", builders::flat_torus(2, 3).unwrap()).unwrap(),
    ];
    // Exact lengths on a Δ-complex with loops: the one-vertex torus, lengths 1, 1, 3/2.
    let t = builders::one_vertex_torus();
    let l = vec![Rational::from(1), Rational::from(1), Rational::from((3, 2))];
    v.push(Surface::new("1v-torus", t, Metric::Lengths(l), None).unwrap());
    v
}

#[test]
fn json_round_trip_of_every_standard_surface() {
    for s in standard_surfaces() {
        let text = json::write(&s);
        let back = json::read(&text).unwrap_or_else(|e| panic!("{}: {e}", s.name));
        assert_eq!(back, s, "{}", s.name);
        // And through bytes.
        assert_eq!(json::read_bytes(text.as_bytes()).unwrap(), s);
    }
}

const TWO_TRI: &str = r#"{"format": "penner-surface", "version": 1, "name": "t",
  "vertices": 3, "faces": [[0,1,2],[0,2,1]], "lengths": ["1", "3/2", "1.25"]}"#;

fn with(replace: &str, by: &str) -> String {
    assert!(TWO_TRI.contains(replace), "{replace}");
    TWO_TRI.replacen(replace, by, 1)
}

#[test]
fn json_reads_the_documented_forms() {
    let s = json::read(TWO_TRI).unwrap();
    let e = json::edge_order(&s.mesh);
    let want = ["1", "3/2", "1.25"].map(|x| parse_rational(x).unwrap());
    for (k, &edge) in e.iter().enumerate() {
        assert_eq!(s.metric.values()[edge], want[k]);
    }
    // Per-face-side form: the same metric.
    let per_side = with(
        r#""lengths": ["1", "3/2", "1.25"]"#,
        r#""lengths": [["1", "3/2", "1.25"], ["1.25", "3/2", "1"]]"#,
    );
    assert_eq!(json::read(&per_side).unwrap().metric, s.metric);
    // JSON numbers: integers exactly, others as the binary64 value (0.1 is not 1/10).
    let nums = with(r#"["1", "3/2", "1.25"]"#, "[1, 1.5, 0.1e1]");
    let m = json::read(&nums).unwrap().metric;
    assert!(m.values().contains(&Rational::from((3, 2))));
    let tenth = with(r#"["1", "3/2", "1.25"]"#, "[1, 1, 0.1]");
    let m = json::read(&tenth).unwrap().metric;
    assert!(m.values().contains(&Rational::from_f64(0.1).unwrap()));
    assert!(!m.values().contains(&Rational::from((1, 10))));
    // Positions only: squared lengths.
    let pos = r#"{"vertices": 3, "faces": [[0,1,2],[0,2,1]],
        "positions": [["0","0","0"], ["1","0","0"], [0, "1/2", 0]]}"#;
    let s = json::read(pos).unwrap();
    assert!(matches!(s.metric, Metric::SquaredLengths(_)));
    assert!(s.metric.values().contains(&Rational::from((5, 4))));
    // Explicit gluing: the one-vertex torus.
    let torus = r#"{"vertices": 1, "faces": [[0,0,0],[0,0,0]],
        "gluing": [[[0,0],[1,0]], [[0,1],[1,1]], [[0,2],[1,2]]],
        "squared_lengths": ["1", "1", "2"]}"#;
    assert_eq!(json::read(torus).unwrap().mesh.euler_characteristic(), 0);
}

/// Floats in JSON are read as the correctly rounded binary64 value (oracle: Rust's own
/// correctly rounded `str::parse::<f64>`).
#[test]
fn json_numbers_are_correctly_rounded() {
    let mut rng = <rand_chacha::ChaCha8Rng as rand::SeedableRng>::seed_from_u64(5);
    for _ in 0..2000 {
        let x: f64 = rand::Rng::gen_range(&mut rng, 1e-3..1e3);
        let text = format!("{x:.25e}");
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        let got = json::exact_number(&v, "x").unwrap();
        assert_eq!(
            got,
            Rational::from_f64(text.parse::<f64>().unwrap()).unwrap(),
            "{text}"
        );
    }
}

fn expect_err(text: &str) -> ReadError {
    match json::read(text) {
        Ok(s) => panic!("accepted: {text}\n{s:?}"),
        Err(e) => e,
    }
}

/// A malformed input and the error it must get.
type ErrCase = (String, fn(&ReadError) -> bool);

#[test]
#[allow(clippy::too_many_lines)] // one table of cases
fn json_malformed_inputs_get_typed_errors() {
    use NumberError as N;
    let l = r#"["1", "3/2", "1.25"]"#;
    let cases: Vec<ErrCase> = vec![
        (with(l, r#"["1", "0", "1"]"#), |e| {
            matches!(
                e,
                ReadError::Metric {
                    source: MetricError::NonPositive { .. },
                    ..
                }
            )
        }),
        (with(l, r#"["1", "-1", "1"]"#), |e| {
            matches!(
                e,
                ReadError::Metric {
                    source: MetricError::NonPositive { .. },
                    ..
                }
            )
        }),
        (
            with(l, r#"["1", "NaN", "1"]"#),
            |e| matches!(e, ReadError::Number { source: N::NotFinite(_), element } if element == "lengths[1]"),
        ),
        (with(l, r#"["1", "inf", "1"]"#), |e| {
            matches!(e, ReadError::Number { .. })
        }),
        (with(l, r#"["1", "1e999999999", "1"]"#), |e| {
            matches!(
                e,
                ReadError::Number {
                    source: N::ExponentTooLarge { .. },
                    ..
                }
            )
        }),
        (with(l, r#"["1", "", "1"]"#), |e| {
            matches!(
                e,
                ReadError::Number {
                    source: N::Empty,
                    ..
                }
            )
        }),
        (with(l, r#"["1", "abc", "1"]"#), |e| {
            matches!(e, ReadError::Number { .. })
        }),
        (
            with(l, r#"["1", null, "1"]"#),
            |e| matches!(e, ReadError::Schema { element, .. } if element == "lengths[1]"),
        ),
        (with(l, r#"["1", "1", "2"]"#), |e| {
            matches!(
                e,
                ReadError::Metric {
                    source: MetricError::TriangleInequality {
                        degenerate: true,
                        ..
                    },
                    ..
                }
            )
        }),
        (with(l, r#"["1", "1", "5/2"]"#), |e| {
            matches!(
                e,
                ReadError::Metric {
                    source: MetricError::TriangleInequality {
                        degenerate: false,
                        ..
                    },
                    ..
                }
            )
        }),
        (with(l, r#"["1", "1"]"#), |e| {
            matches!(e, ReadError::Schema { .. })
        }),
        (with(l, r#"[["1","1","1"], ["1","1","3/2"]]"#), |e| {
            matches!(e, ReadError::GluedUnequal { .. })
        }),
        (with("[[0,1,2],[0,2,1]]", "[[0,1,2],[0,2,3]]"), |e| {
            matches!(e, ReadError::IndexOutOfRange { index: 3, .. })
        }),
        (with("[[0,1,2],[0,2,1]]", "[[0,1,2],[0,-2,1]]"), |e| {
            matches!(e, ReadError::IndexOutOfRange { index: -2, .. })
        }),
        (with("[[0,1,2],[0,2,1]]", "[[0,1,2],[0,2,1,0]]"), |e| {
            matches!(e, ReadError::NotTriangle { count: 4, .. })
        }),
        // Same orientation twice: non-orientable / non-manifold.
        (with("[[0,1,2],[0,2,1]]", "[[0,1,2],[0,1,2]]"), |e| {
            matches!(
                e,
                ReadError::Mesh {
                    source: MeshError::NonManifoldEdge { .. },
                    ..
                }
            )
        }),
        (with(r#""vertices": 3"#, r#""vertices": 4000000000"#), |e| {
            matches!(
                e,
                ReadError::Mesh {
                    source: MeshError::IsolatedVertex { .. },
                    ..
                }
            )
        }),
        (
            with(r#""vertices": 3"#, r#""vertices": 99999999999"#),
            |e| matches!(e, ReadError::Schema { .. }),
        ),
        (
            with(r#""version": 1"#, r#""version": 2"#),
            |e| matches!(e, ReadError::Schema { element, .. } if element == "version"),
        ),
        (
            with(r#""format": "penner-surface""#, r#""format": "ply""#),
            |e| matches!(e, ReadError::Schema { .. }),
        ),
        (
            with(r#""name": "t""#, r#""nme": "t""#),
            |e| matches!(e, ReadError::Schema { element, .. } if element == "nme"),
        ),
        (
            with(
                r#""lengths""#,
                r#""squared_lengths": ["1","1","1"], "lengths""#,
            ),
            |e| matches!(e, ReadError::Schema { .. }),
        ),
        (
            with(
                r#""lengths": ["1", "3/2", "1.25"]"#,
                r#""gluing": [[[0,0],[1,2]], [[0,1],[1,1]], [[0,2],[1,0]]]"#,
            ),
            |e| matches!(e, ReadError::Schema { element, .. } if element == "surface"),
        ),
        // Inconsistent gluing: sides 0→1 and 0→2 cannot be glued.
        (
            with(r#""lengths""#, r#""gluing": [[[0,0],[1,0]]], "lengths""#),
            |e| {
                matches!(
                    e,
                    ReadError::Mesh {
                        source: MeshError::InconsistentGluing { .. },
                        ..
                    }
                )
            },
        ),
        (
            with(r#""lengths""#, r#""gluing": [[[0,0],[0,0]]], "lengths""#),
            |e| matches!(e, ReadError::Mesh { .. }),
        ),
        (
            with(r#""lengths""#, r#""gluing": [[[0,0],[7,0]]], "lengths""#),
            |e| matches!(e, ReadError::Schema { .. }),
        ),
        (TWO_TRI[..TWO_TRI.len() - 20].to_string(), |e| {
            matches!(e, ReadError::Truncated { .. })
        }),
        ("{\"vertices\": 3,, }".to_string(), |e| {
            matches!(e, ReadError::Syntax { line: 1, .. })
        }),
        ("[".repeat(100_000), |e| {
            matches!(e, ReadError::Syntax { .. } | ReadError::Truncated { .. })
        }),
        ("42".to_string(), |e| matches!(e, ReadError::Schema { .. })),
    ];
    for (text, ok) in cases {
        let e = expect_err(&text);
        assert!(
            ok(&e),
            "wrong error for {}: {e:?}",
            &text[..text.len().min(200)]
        );
        // Every error renders a message naming a place.
        assert!(!e.to_string().is_empty());
    }
    // Loops without an explicit gluing are ambiguous.
    let e = expect_err(r#"{"vertices": 1, "faces": [[0,0,0],[0,0,0]], "lengths": [1,1,1]}"#);
    assert!(
        matches!(
            e,
            ReadError::Mesh {
                source: MeshError::AmbiguousLoop { .. },
                ..
            }
        ),
        "{e}"
    );
    // Binary garbage.
    assert!(matches!(
        json::read_bytes(&[0x7b, 0xff, 0xfe]),
        Err(ReadError::NotText { offset: 1 })
    ));
    // Non-manifold vertex: two triangles sharing a vertex only.
    let e = expect_err(r#"{"vertices": 5, "faces": [[0,1,2],[0,3,4]], "lengths": [1,1,1,1,1,1]}"#);
    assert!(
        matches!(
            e,
            ReadError::Mesh {
                source: MeshError::NonManifoldVertex { vertex: 0 },
                ..
            }
        ),
        "{e}"
    );
}

/// Squared-length triangle inequality decided exactly: a triangle with sides 1, 1 and
/// 2 − 10⁻³⁰ is valid; sides 1, 1, 2 (squared 1, 1, 4) are degenerate.
#[test]
fn triangle_inequality_is_exact() {
    let ok = r#"{"vertices": 3, "faces": [[0,1,2],[0,2,1]], "lengths": ["1", "1", "1.999999999999999999999999999999"]}"#;
    json::read(ok).unwrap();
    let sq = r#"{"vertices": 3, "faces": [[0,1,2],[0,2,1]], "squared_lengths": ["1", "1", "4"]}"#;
    assert!(matches!(
        json::read(sq),
        Err(ReadError::Metric {
            source: MetricError::TriangleInequality {
                degenerate: true,
                ..
            },
            ..
        })
    ));
    let sq_ok = r#"{"vertices": 3, "faces": [[0,1,2],[0,2,1]], "squared_lengths": ["1", "1", "3.999999999999999999999999999999"]}"#;
    json::read(sq_ok).unwrap();
}

// ---------------------------------------------------------------- OBJ and OFF

const TET_OBJ: &str = "# tetrahedron\nv 0 0 0\nv 1.5 0 0\nv 0 1 0\nv 0 0 1e-30\n\
    vn 0 0 1\nf 1 3 2\nf 1/1 2/2 4/4\nf 2//1 3//1 4//1\nf -2 -4 -1\n";
const TET_OFF: &str = "OFF\n# comment\n4 4 6\n0 0 0\n1.5 0 0\n0 1 0\n0 0 1e-30\n\
    3 0 2 1\n3 0 1 3 255 0 0\n3 1 2 3\n3 2 0 3\n";

#[test]
fn obj_and_off_read_exact_coordinates() {
    let a = obj::read(TET_OBJ).unwrap();
    let b = off::read(TET_OFF).unwrap();
    assert_eq!((a.mesh.n_vertices(), a.mesh.n_faces()), (4, 4));
    assert_eq!(a.positions, b.positions);
    assert_eq!(a.mesh.face_list(), b.mesh.face_list());
    let p = a.positions.as_ref().unwrap();
    assert_eq!(p[1][0], Rational::from((3, 2)));
    assert_eq!(p[3][2], parse_rational("1e-30").unwrap());
    // Squared length of edge 1.5 → (0,0,1e-30) exactly 9/4 + 10⁻⁶⁰.
    let want = Rational::from((9, 4)) + parse_rational("1e-60").unwrap();
    assert!(a.metric.values().contains(&want));
}

fn obj_err(t: &str) -> ReadError {
    obj::read(t).err().unwrap_or_else(|| panic!("accepted {t}"))
}
fn off_err(t: &str) -> ReadError {
    off::read(t).err().unwrap_or_else(|| panic!("accepted {t}"))
}

#[test]
fn obj_malformed_inputs_get_typed_errors() {
    let tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    assert!(matches!(
        obj_err(&format!("{tri}f 1 2 3 1\n")),
        ReadError::NotTriangle { count: 4, .. }
    ));
    assert!(matches!(
        obj_err(&format!("{tri}f 1 2 4\n")),
        ReadError::IndexOutOfRange { index: 4, .. }
    ));
    assert!(matches!(
        obj_err(&format!("{tri}f 1 2 0\n")),
        ReadError::IndexOutOfRange { index: 0, .. }
    ));
    assert!(matches!(
        obj_err(&format!("{tri}f 1 2 -4\n")),
        ReadError::IndexOutOfRange { index: -4, .. }
    ));
    assert!(matches!(
        obj_err(&format!("{tri}f 1 2 x\n")),
        ReadError::Syntax { line: 4, .. }
    ));
    assert!(matches!(
        obj_err("v 0 0 nan\n"),
        ReadError::Number {
            source: NumberError::NotFinite(_),
            ..
        }
    ));
    assert!(matches!(
        obj_err("v 0 0\n"),
        ReadError::Syntax { line: 1, .. }
    ));
    assert!(matches!(obj_err("v 0 0 0 2\n"), ReadError::Syntax { .. }));
    assert!(matches!(
        obj_err("bogus 1 2\n"),
        ReadError::Syntax { line: 1, .. }
    ));
    assert!(matches!(
        obj_err(tri),
        ReadError::Mesh {
            source: MeshError::Empty,
            ..
        }
    ));
    // Collinear triangle: degenerate, named by its line.
    let e = obj_err("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    assert!(
        matches!(&e, ReadError::Metric { element, source: MetricError::TriangleInequality { degenerate: true, .. } } if element == "line 4"),
        "{e}"
    );
    // Coincident vertices: zero length.
    let e = obj_err("v 0 0 0\nv 0 0 0\nv 0 1 0\nf 1 2 3\n");
    assert!(
        matches!(
            &e,
            ReadError::Metric {
                source: MetricError::NonPositive { .. },
                ..
            }
        ),
        "{e}"
    );
    // Unused vertex.
    let e = obj_err(&format!("{tri}v 5 5 5\nf 1 2 3\n"));
    assert!(
        matches!(&e, ReadError::Mesh { element, source: MeshError::IsolatedVertex { vertex: 3 } } if element.starts_with("line 4")),
        "{e}"
    );
    // Inconsistent orientation.
    let e = obj_err(&format!("{tri}v 1 1 0\nf 1 2 3\nf 2 3 4\n"));
    assert!(
        matches!(
            &e,
            ReadError::Mesh {
                source: MeshError::NonManifoldEdge { .. },
                ..
            }
        ),
        "{e}"
    );
    assert!(matches!(
        obj::read_bytes(b"v 0 0 0\n\xff\xfe"),
        Err(ReadError::NotText { offset: 8 })
    ));
}

#[test]
fn off_malformed_inputs_get_typed_errors() {
    assert!(matches!(off_err(""), ReadError::Truncated { .. }));
    assert!(matches!(off_err("OFF\n"), ReadError::Truncated { .. }));
    assert!(matches!(
        off_err("PLY\n3 1 0\n"),
        ReadError::Syntax { line: 1, .. }
    ));
    assert!(matches!(
        off_err("OFF\n3 x 0\n"),
        ReadError::Syntax { line: 2, .. }
    ));
    assert!(matches!(
        off_err("OFF\n4000000000 1 0\n"),
        ReadError::HugeCount {
            what: "vertices",
            ..
        }
    ));
    assert!(matches!(
        off_err("OFF\n3 99999999999999 0\n"),
        ReadError::HugeCount { what: "faces", .. }
    ));
    let head = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
    assert!(off::read(&format!("{head}3 0 1 2\n")).is_ok());
    assert!(matches!(off_err(head), ReadError::Truncated { .. }));
    assert!(matches!(
        off_err("OFF\n3 1 0\n0 0 0\n1 0 0\n"),
        ReadError::Truncated { .. }
    ));
    assert!(matches!(
        off_err(&format!("{head}4 0 1 2 0\n")),
        ReadError::NotTriangle { count: 4, .. }
    ));
    assert!(matches!(
        off_err(&format!("{head}3 0 1 3\n")),
        ReadError::IndexOutOfRange { index: 3, .. }
    ));
    assert!(matches!(
        off_err(&format!("{head}3 0 1 -1\n")),
        ReadError::IndexOutOfRange { .. }
    ));
    assert!(matches!(
        off_err(&format!("{head}3 0 1\n")),
        ReadError::Syntax { .. }
    ));
    assert!(matches!(
        off_err(&format!("{head}3 0 1 2\nextra\n")),
        ReadError::Syntax { line: 7, .. }
    ));
    assert!(matches!(
        off_err("OFF\n3 1 0\n0 0 0\n1 0 inf\n0 1 0\n3 0 1 2\n"),
        ReadError::Number { .. }
    ));
    assert!(matches!(
        off_err("OFF\n3 1 0\n0 0 0\n1 0 0 0\n0 1 0\n3 0 1 2\n"),
        ReadError::Syntax { line: 4, .. }
    ));
}

#[test]
fn read_path_dispatches_on_extension() {
    let dir = std::env::temp_dir().join(format!("penner-io-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (name, text) in [("a.obj", TET_OBJ), ("a.OFF", TET_OFF), ("a.json", TWO_TRI)] {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        penner::io::read_path(&p).unwrap();
    }
    assert!(matches!(
        penner::io::read_path(&dir.join("a.ply")),
        Err(ReadError::UnknownFormat { .. })
    ));
    assert!(matches!(
        penner::io::read_path(&dir.join("missing.obj")),
        Err(ReadError::File { .. })
    ));
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---------------------------------------------------------------- no panics

fn mutate(base: &[u8], edits: &[(usize, u8, u8)]) -> Vec<u8> {
    let mut b = base.to_vec();
    for &(pos, kind, byte) in edits {
        if b.is_empty() {
            b.push(byte);
            continue;
        }
        let i = pos % b.len();
        match kind % 4 {
            0 => b[i] = byte,
            1 => b.insert(i, byte),
            2 => {
                b.remove(i);
            }
            _ => b.truncate(i),
        }
    }
    b
}

/// Every reader on `bytes`: no panic, and whatever is accepted is a valid surface.
fn all_readers(bytes: &[u8]) {
    for s in [
        json::read_bytes(bytes),
        obj::read_bytes(bytes),
        off::read_bytes(bytes),
    ]
    .into_iter()
    .flatten()
    {
        assert!(s.mesh.check_invariants().is_ok());
        assert!(s.validate().is_ok());
    }
}

proptest! {
    #![proptest_config(crate::support::proptest_config(256, 100_000))]

    /// Random bytes never make a reader panic.
    #[test]
    fn readers_never_panic_on_random_bytes(bytes in proptest::collection::vec(any::<u8>(), 0..200)) {
        all_readers(&bytes);
    }

    /// Mutated valid files (byte edits, insertions, deletions, truncation) never make a
    /// reader panic; token-level mutations reach deeper code than random bytes.
    #[test]
    fn readers_never_panic_on_mutated_files(
        which in 0usize..3,
        edits in proptest::collection::vec((any::<usize>(), any::<u8>(), prop::sample::select(b"0123456789-./ex\n #[]{}\",:fv3OFnaif".to_vec())), 1..6),
    ) {
        let json_text = json::write(&Surface::from_embedded("oct", builders::octahedron()).unwrap());
        let base: &[u8] = match which {
            0 => json_text.as_bytes(),
            1 => TET_OBJ.as_bytes(),
            _ => TET_OFF.as_bytes(),
        };
        all_readers(&mutate(base, &edits));
    }
}
