//! `delaunay_flip` and `cotan_laplacian` claims: the relabeling of Δ-complexes, the
//! library answer, and `penner certify` end to end with every exit code.
//!
//! Expected values are computed by hand here, never by the code under test: the Ptolemy
//! length of a flipped rhombus diagonal is (1·1 + 1·1)/(19/10) = 20/19 (docs/catalogue.md §5,
//! Eq. 18), the Euclidean one is 2·√(1 − (19/20)²) = √(39/100), and the cotan weight of
//! an equilateral edge is ½(2·cot 60°) = 1/√3.

use crate::cli::tetrahedron_json;
use crate::support::{certify_expecting, counterexample, scratch};
use penner::io::json::to_value;
use penner::mesh::relabel::isomorphisms;
use penner::mesh::Mesh;
use penner::oracle::certify::{certify as answer, ClaimVerdict};
use penner::oracle::claim::parse_value;
use penner::oracle::{Metric, Surface};
use rug::Rational;
use serde_json::{json, Value};

/// 1/√3 to 50 digits.
const INV_SQRT3: &str = "0.57735026918962576450914878050195745564760175127013";

fn one_vertex_torus(l: [Rational; 3]) -> Surface {
    let mesh = Mesh::from_gluing(
        1,
        &[[0, 0, 0], [0, 0, 0]],
        &[((0, 0), (1, 0)), ((0, 1), (1, 1)), ((0, 2), (1, 2))],
    )
    .unwrap();
    Surface::new("torus", mesh, Metric::Lengths(l.into()), None).unwrap()
}

fn q(n: i64, d: i64) -> Rational {
    Rational::from((n, d))
}

fn rhombus() -> Value {
    json!({"vertices": 4, "faces": [[0,1,2],[0,2,3]], "lengths": ["1","1","19/10","1","1"]})
}

fn flip_claim(flips: &str, surface: Value, result: Value, eps: Option<&str>) -> Value {
    let mut c = json!({"penner_claim": 1, "id": "flip", "kind": "delaunay_flip", "flips": flips});
    c["surface"] = surface;
    c["result"] = result;
    if let Some(e) = eps {
        c["epsilon"] = json!(e);
    }
    c
}

#[test]
fn b81_relabeling_matches_renumbered_faces_and_rejects_the_other_diagonal() {
    let a = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
    let renumbered = Mesh::from_faces(4, &[[3, 0, 2], [1, 2, 0]]).unwrap();
    let rels = isomorphisms(&a, &renumbered, 8);
    assert_eq!(rels.len(), 1);
    for h in a.halfedges() {
        let g = rels[0].halfedges[h.idx()];
        assert_eq!(
            (a.tail(h), a.tip(h)),
            (renumbered.tail(g), renumbered.tip(g))
        );
    }
    // Negative controls: the other diagonal, and a vertex renaming.
    let other = Mesh::from_faces(4, &[[0, 1, 3], [1, 2, 3]]).unwrap();
    assert!(isomorphisms(&a, &other, 8).is_empty());
    let renamed = Mesh::from_faces(4, &[[1, 0, 2], [1, 2, 3]]).unwrap();
    assert!(isomorphisms(&a, &renamed, 8).is_empty());
}

#[test]
fn b81_relabeling_of_the_one_vertex_torus_sees_its_symmetries() {
    // Three loops at one vertex: vertex triples say nothing, the gluing decides. The
    // orientation-preserving symmetries are the 3 cyclic edge rotations times the 2
    // face swaps.
    let t = one_vertex_torus([q(1, 1), q(1, 1), q(1, 1)]);
    assert_eq!(isomorphisms(&t.mesh, &t.mesh, 64).len(), 6);
    // Negative control: the two-triangle sphere has other counts.
    let s = Mesh::from_faces(3, &[[0, 1, 2], [0, 2, 1]]).unwrap();
    assert!(isomorphisms(&t.mesh, &s, 64).is_empty());
}

#[test]
fn b80_delaunay_flip_on_the_one_vertex_torus_compares_loops_by_gluing() {
    // Rhombic torus with sides 1, 1 and long diagonal 19/10: one Ptolemy flip gives
    // (1² + 1²)/(19/10) = 20/19 (the quad of a loop edge is a parallelogram).
    let s = one_vertex_torus([q(19, 10), q(1, 1), q(1, 1)]);
    let ask = |result: [Rational; 3]| {
        let c = flip_claim(
            "ptolemy",
            to_value(&s),
            to_value(&one_vertex_torus(result)),
            None,
        );
        answer(&parse_value(&c).unwrap()).unwrap()
    };
    for placed in [[q(20, 19), q(1, 1), q(1, 1)], [q(1, 1), q(1, 1), q(20, 19)]] {
        let a = ask(placed);
        assert_eq!(a.verdict, ClaimVerdict::Holds, "{a:?}");
        assert!(a.certified);
    }
    // Negative controls: the unflipped metric, and a wrong new length.
    for wrong in [[q(19, 10), q(1, 1), q(1, 1)], [q(21, 19), q(1, 1), q(1, 1)]] {
        let a = ask(wrong);
        assert_eq!(a.verdict, ClaimVerdict::Refuted, "{a:?}");
        assert!(a.counterexample.is_some());
    }
}

#[test]
fn b80_certify_delaunay_flip_ptolemy_holds_and_refuted_with_exit_codes() {
    let d = scratch("claims-ptolemy");
    let result = |diag: &str| json!({"vertices": 4, "faces": [[0,1,3],[1,2,3]], "lengths": ["1", diag, "1", "1", "1"]});
    let (a, _) = certify_expecting(
        &d,
        "holds.json",
        &flip_claim("ptolemy", rhombus(), result("20/19"), None),
        0,
        "holds",
    );
    assert_eq!(
        (a["certified"].as_bool(), a["id"].as_str()),
        (Some(true), Some("flip"))
    );
    // Wrong length: refuted at the new diagonal, named in the result's edge order.
    let (a, _) = certify_expecting(
        &d,
        "len.json",
        &flip_claim("ptolemy", rhombus(), result("21/19"), None),
        1,
        "refuted",
    );
    assert_eq!(
        a["counterexample"]["element"], "result edge 1 (v1–v3)",
        "{a}"
    );
    // Wrong triangulation (the input itself): refuted at the non-Delaunay diagonal.
    let (a, _) = certify_expecting(
        &d,
        "tri.json",
        &flip_claim("ptolemy", rhombus(), rhombus(), None),
        1,
        "refuted",
    );
    assert_eq!(
        a["counterexample"]["element"], "result edge 2 (v0–v2)",
        "{a}"
    );
}

#[test]
fn b80_certify_delaunay_flip_euclidean_needs_a_positive_epsilon() {
    let d = scratch("claims-euclid");
    // The Euclidean diagonal is √(39/100), irrational: exact equality is out of reach of
    // enclosures (undecided), a tiny ε decides it.
    let result = json!({"vertices": 4, "faces": [[0,1,3],[1,2,3]],
        "squared_lengths": ["1", "39/100", "1", "1", "1"]});
    let (a, _) = certify_expecting(
        &d,
        "e0.json",
        &flip_claim("euclidean", rhombus(), result.clone(), None),
        2,
        "undecided",
    );
    assert_eq!(a["certified"], false);
    certify_expecting(
        &d,
        "e.json",
        &flip_claim("euclidean", rhombus(), result, Some("1e-40")),
        0,
        "holds",
    );
    // Negative control: the Ptolemy length 20/19 is not the Euclidean one (by ≈ 0.43).
    let ptolemy = json!({"vertices": 4, "faces": [[0,1,3],[1,2,3]], "lengths": ["1", "20/19", "1", "1", "1"]});
    certify_expecting(
        &d,
        "p.json",
        &flip_claim("euclidean", rhombus(), ptolemy, Some("1e-3")),
        1,
        "refuted",
    );
}

#[test]
fn b82_certify_delaunay_flip_at_a_tie_holds_for_either_diagonal() {
    let d = scratch("claims-tie");
    // Unit square with diagonal √2 (squared lengths): the diagonal is an exact tie, and
    // both diagonals give Delaunay triangulations (proofs/B82).
    let square = json!({"vertices": 4, "faces": [[0,1,2],[0,2,3]], "squared_lengths": ["1","1","2","1","1"]});
    let other = |diag: &str| json!({"vertices": 4, "faces": [[0,1,3],[1,2,3]], "squared_lengths": ["1", diag, "1", "1", "1"]});
    for (name, result, code, verdict) in [
        ("same.json", square.clone(), 0, "holds"),
        ("other.json", other("2"), 0, "holds"),
        // Negative control: the other diagonal with squared length 3.
        ("wrong.json", other("3"), 1, "refuted"),
    ] {
        let (a, _) = certify_expecting(
            &d,
            name,
            &flip_claim("euclidean", square.clone(), result, None),
            code,
            verdict,
        );
        assert_eq!(a["certified"], true, "{name}: {a}");
    }
    // A cyclic kite on the unit circle, i = (−1, 0), j = (1, 0), k = (0, 1),
    // l = (1/2, −√3/2): squared sides 2, 2, 3, 1 and diagonal 4 (a tie), but the other
    // diagonal has squared length 2 + √3, not rational: its tie cannot be certified and
    // the search is incomplete.
    let kite = json!({"vertices": 4, "faces": [[0,1,2],[1,0,3]], "squared_lengths": ["4","2","2","3","1"]});
    let flipped = json!({"vertices": 4, "faces": [[3,2,0],[2,3,1]],
        "squared_lengths": ["3732050807568877/1000000000000000", "2", "3", "1", "2"]});
    let (a, _) = certify_expecting(
        &d,
        "kite.json",
        &flip_claim("euclidean", kite.clone(), flipped, Some("1e-12")),
        2,
        "undecided",
    );
    assert!(
        a["witnesses"][0]["detail"]
            .as_str()
            .unwrap()
            .contains("not certified"),
        "{a}"
    );
    // Negative control: the kite itself holds.
    certify_expecting(
        &d,
        "kite-same.json",
        &flip_claim("euclidean", kite.clone(), kite, None),
        0,
        "holds",
    );
}

#[test]
fn certify_delaunay_flip_bad_input_exit_3() {
    let d = scratch("claims-bad");
    let mut no_flips = flip_claim("ptolemy", rhombus(), rhombus(), None);
    no_flips.as_object_mut().unwrap().remove("flips");
    let cases = [
        ("flips.json", no_flips, "flips"),
        (
            "eps.json",
            flip_claim("ptolemy", rhombus(), rhombus(), Some("-1")),
            "epsilon",
        ),
        (
            "result.json",
            flip_claim(
                "ptolemy",
                rhombus(),
                json!({"vertices": 4, "faces": [[0,1,2]], "lengths": ["1","1","5"]}),
                None,
            ),
            "result",
        ),
    ];
    for (name, c, mention) in cases {
        let (_, err) = certify_expecting(&d, name, &c, 3, "bad_input");
        assert!(err.contains(mention), "{name}: {err}");
    }
}

#[test]
fn certify_cotan_laplacian_holds_refuted_undecided_bad_input() {
    let d = scratch("claims-cotan");
    let claim = |w: Vec<&str>, eps: &str| {
        json!({"penner_claim": 1, "kind": "cotan_laplacian", "surface": tetrahedron_json(),
               "weights": w, "epsilon": eps})
    };
    certify_expecting(
        &d,
        "holds.json",
        &claim(vec![INV_SQRT3; 6], "1e-45"),
        0,
        "holds",
    );
    // The 50-digit decimal is ≈ 3.1e-51 from 1/√3; at 128 bits (≈ 38 digits) an ε that
    // close to the true difference cannot be settled either way.
    let mut close = claim(vec![INV_SQRT3; 6], "3.1239813976735e-51");
    close["max_bits"] = json!(128);
    certify_expecting(&d, "close.json", &close, 2, "undecided");
    // One weight off by ≈ 2.6e-3 > ε.
    let mut w = vec![INV_SQRT3; 6];
    w[4] = "0.58";
    let (a, _) = certify_expecting(&d, "refuted.json", &claim(w, "1e-3"), 1, "refuted");
    assert!(counterexample(&a).starts_with("edge 4 "), "{a}");
    let (_, err) = certify_expecting(
        &d,
        "count.json",
        &claim(vec![INV_SQRT3; 5], "1e-3"),
        3,
        "bad_input",
    );
    assert!(err.contains("weights"), "{err}");
}
