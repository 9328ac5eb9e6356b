//! The oracle layer: surface JSON round trips, failure files, shrinking, and parsers that
//! never panic on mutated input.

use crate::support::cases;
use penner::io::json::{from_value, to_value};
use penner::mesh::Mesh;
use penner::oracle::claim;
use penner::oracle::failure::Failure;
use penner::oracle::shrink::{shrink, sub_case, Budget};
use penner::oracle::{Metric, Prec, Surface};
use penner::theorems::Witness;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

fn one_vertex_torus() -> Surface {
    let mesh = Mesh::from_gluing(
        1,
        &[[0, 0, 0], [0, 0, 0]],
        &[((0, 0), (1, 0)), ((0, 1), (1, 1)), ((0, 2), (1, 2))],
    )
    .unwrap();
    Surface {
        name: "torus".into(),
        mesh,
        positions: None,
        metric: Metric::Lengths(vec![
            Rational::from(4),
            Rational::from((5, 2)),
            Rational::from(6),
        ]),
    }
}

/// A strip of `n` triangles (a disk), with lengths 1 + k/7 on edge k.
fn strip(n: u32) -> Surface {
    let faces: Vec<[u32; 3]> = (0..n)
        .map(|i| {
            if i % 2 == 0 {
                [i, i + 1, i + 2]
            } else {
                [i + 1, i, i + 2]
            }
        })
        .collect();
    let mesh = Mesh::from_faces(n + 2, &faces).unwrap();
    let lengths = (0..mesh.n_edges())
        .map(|k| Rational::from((7 + k as i64, 7)))
        .collect();
    Surface {
        name: "strip".into(),
        mesh,
        positions: None,
        metric: Metric::SquaredLengths(lengths),
    }
}

#[test]
fn surface_json_round_trips_delta_complexes_exactly() {
    for case in [one_vertex_torus(), strip(9)] {
        let v = to_value(&case);
        let back = from_value(&v).unwrap();
        assert_eq!(back.mesh, case.mesh);
        assert_eq!(back.metric, case.metric);
    }
}

#[test]
fn surface_json_edge_order_is_first_appearance() {
    // Face [0,1,2] then [0,2,3]: edges 01, 12, 20, then 23, 30 (02 already seen).
    let v = serde_json::json!({
        "vertices": 4, "faces": [[0,1,2],[0,2,3]],
        "lengths": ["2", "3", "4", "5", "6"]
    });
    let c = from_value(&v).unwrap();
    let Metric::Lengths(l) = &c.metric else {
        panic!()
    };
    for e in c.mesh.edges() {
        let h = e.halfedge();
        let mut ends = [c.mesh.tail(h).0, c.mesh.tip(h).0];
        ends.sort_unstable();
        let expected = match ends {
            [0, 1] => 2,
            [1, 2] => 3,
            [0, 2] => 4,
            [2, 3] => 5,
            [0, 3] => 6,
            _ => unreachable!(),
        };
        assert_eq!(l[e.idx()], expected, "edge {ends:?}");
    }
}

#[test]
fn failure_file_round_trips() {
    let f = Failure {
        check: "T01".into(),
        precision: Prec::Dd,
        source: "in.json".into(),
        source_faces: 2,
        witnesses: vec![Witness {
            element: "v0".into(),
            detail: "angle sum".into(),
            value: 0.5,
        }],
        surface: one_vertex_torus(),
    };
    let text = f.to_json().to_string();
    let back = Failure::parse(&text, "f.json").unwrap();
    assert_eq!(back.check, f.check);
    assert_eq!(back.precision, f.precision);
    assert_eq!(back.witnesses, f.witnesses);
    assert_eq!(back.surface.mesh, f.surface.mesh);
    assert_eq!(back.surface.metric, f.surface.metric);
    // Negative control: a wrong version is refused.
    let wrong = text.replace("\"penner_failure\":1", "\"penner_failure\":2");
    assert!(Failure::parse(&wrong, "f.json").is_err());
}

#[test]
fn sub_case_keeps_lengths_edge_by_edge() {
    let c = strip(6);
    let keep: Vec<_> = c.mesh.faces().skip(2).take(3).collect();
    let sub = sub_case(&c, &keep).unwrap();
    assert_eq!(sub.mesh.n_faces(), 3);
    // Every kept face has the same three lengths in the same side order.
    let (Metric::SquaredLengths(a), Metric::SquaredLengths(b)) = (&c.metric, &sub.metric) else {
        panic!()
    };
    for (k, f) in keep.iter().enumerate() {
        let old = c.mesh.face_halfedges(*f);
        let new = sub.mesh.face_halfedges(penner::mesh::Face(k as u32));
        for s in 0..3 {
            assert_eq!(a[old[s].edge().idx()], b[new[s].edge().idx()]);
        }
    }
}

/// The shrinker reaches the smallest failing sub-surface of a synthetic property ("some
/// edge has squared length 10/7"), and keeps the whole surface when nothing smaller fails.
#[test]
fn shrink_finds_a_small_failing_surface() {
    let c = strip(12);
    let target = Rational::from((10, 7));
    let fails = |x: &Surface| match &x.metric {
        Metric::SquaredLengths(v) => v.contains(&target),
        Metric::Lengths(_) => false,
    };
    assert!(fails(&c));
    let small = shrink(&c, &[], &fails, Budget::default());
    assert!(fails(&small));
    assert_eq!(
        small.mesh.n_faces(),
        1,
        "should shrink to the one face on that edge"
    );
    // Negative control: a property that needs every face cannot be shrunk.
    let n = c.mesh.n_faces();
    let needs_all = |x: &Surface| x.mesh.n_faces() == n;
    assert_eq!(
        shrink(&c, &[], &needs_all, Budget::default())
            .mesh
            .n_faces(),
        n
    );
}

/// Mutated inputs (byte flips, truncations, insertions) never make the parsers panic.
#[test]
fn parsers_never_panic_on_mutated_input() {
    let seeds = [
        to_value(&one_vertex_torus()).to_string(),
        to_value(&strip(5)).to_string(),
        serde_json::json!({
            "penner_claim": 1, "kind": "cone_angles", "epsilon": "1e-9",
            "surface": to_value(&strip(3)), "angles": ["1", "2/3", 0.5, "1e-3", "7", "3"]
        })
        .to_string(),
    ];
    let alphabet = b"{}[]\",:-./0123456789eE aNbsvlfgutin\x00\xff";
    let mut rng = ChaCha8Rng::seed_from_u64(0x9e3779b97f4a7c15);
    for _ in 0..cases(300, 100_000) {
        let seed = seeds[rng.gen_range(0..seeds.len())].as_bytes();
        let mut b = seed.to_vec();
        for _ in 0..rng.gen_range(1..6) {
            let i = rng.gen_range(0..=b.len());
            match rng.gen_range(0..3) {
                0 if i < b.len() => b[i] = alphabet[rng.gen_range(0..alphabet.len())],
                1 => b.insert(i, alphabet[rng.gen_range(0..alphabet.len())]),
                _ => b.truncate(i.max(1)),
            }
        }
        let text = String::from_utf8_lossy(&b);
        let _ = claim::parse(&text, "m.json");
        let _ = Failure::parse(&text, "m.json");
        if let Ok(v) = serde_json::from_str::<serde_json::Value>(&text) {
            let _ = from_value(&v);
        }
    }
}
