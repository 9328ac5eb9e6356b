//! `delaunay_flip` claims at cocircular ties: the search over tie flips (proofs/B82).
//!
//! Expected values are by hand: a 4 × 3 rectangle has diagonals 5 (both Delaunay, a
//! tie); in a regular hexagon of circumradius 1 the chords over 1, 2, 3 steps have squared
//! lengths 1, 3, 4; grid points have integer squared distances. Every triangulation of a
//! cyclic polygon is Delaunay, so every claimed triangulation of the cells holds.

use penner::oracle::certify::{certify as answer, Answer, ClaimVerdict};
use penner::oracle::claim::parse_value;
use penner::oracle::tie_search::{MAX_STATES, MAX_TIES};
use serde_json::{json, Value};
use std::time::Instant;

fn claim(flips: &str, surface: Value, result: Value) -> Answer {
    let mut c = json!({"penner_claim": 1, "id": "tie", "kind": "delaunay_flip", "flips": flips});
    c["surface"] = surface;
    c["result"] = result;
    answer(&parse_value(&c).unwrap()).unwrap()
}

fn verdict(a: &Answer) -> (ClaimVerdict, bool) {
    (a.verdict, a.certified)
}

/// A `w × h` grid of unit squares from integer positions; `other(x, y)` picks the
/// diagonal (x+1, y)–(x, y+1) of square (x, y) instead of (x, y)–(x+1, y+1).
fn grid(w: u32, h: u32, other: impl Fn(u32, u32) -> bool) -> Value {
    let id = |x: u32, y: u32| y * (w + 1) + x;
    let positions: Vec<Value> = (0..=h)
        .flat_map(|y| (0..=w).map(move |x| json!([x, y, 0])))
        .collect();
    let mut faces = Vec::new();
    for y in 0..h {
        for x in 0..w {
            let (a, b, c, d) = (id(x, y), id(x + 1, y), id(x + 1, y + 1), id(x, y + 1));
            if other(x, y) {
                faces.extend([[a, b, d], [b, c, d]]);
            } else {
                faces.extend([[a, b, c], [a, c, d]]);
            }
        }
    }
    json!({"vertices": (w + 1) * (h + 1), "faces": faces, "positions": positions})
}

/// The regular hexagon with the given faces and exact squared chord lengths per face side.
fn hexagon(faces: &[[u32; 3]]) -> Value {
    let chord = |i: u32, j: u32| match i.abs_diff(j).min(6 - i.abs_diff(j)) {
        1 => "1",
        2 => "3",
        _ => "4",
    };
    let sides: Vec<[&str; 3]> = faces
        .iter()
        .map(|&[a, b, c]| [chord(a, b), chord(b, c), chord(c, a)])
        .collect();
    json!({"vertices": 6, "faces": faces, "squared_lengths": sides})
}

#[test]
fn b82_rectangle_other_diagonal_holds_for_both_flip_kinds() {
    // 0 = (0,0), 1 = (4,0), 2 = (4,3), 3 = (0,3): both diagonals have length 5.
    let ours = json!({"vertices": 4, "faces": [[0,1,2],[0,2,3]], "lengths": ["4","3","5","4","3"]});
    let other = |d: &str| json!({"vertices": 4, "faces": [[0,1,3],[1,2,3]], "lengths": ["4", d, "3", "3", "4"]});
    for flips in ["ptolemy", "euclidean"] {
        let a = claim(flips, ours.clone(), other("5"));
        assert_eq!(verdict(&a), (ClaimVerdict::Holds, true), "{flips}: {a:?}");
        // Negative control: the other diagonal with a wrong length, searched completely.
        let a = claim(flips, ours.clone(), other("51/10"));
        assert_eq!(verdict(&a), (ClaimVerdict::Refuted, true), "{flips}: {a:?}");
        let w = a.counterexample.expect("a counterexample");
        assert_eq!(w.element, "result edge 1 (v1–v3)", "{flips}");
    }
}

#[test]
fn b82_unit_square_by_squared_lengths_other_diagonal_holds() {
    let square = json!({"vertices": 4, "faces": [[0,1,2],[0,2,3]], "squared_lengths": ["1","1","2","1","1"]});
    let other = |d: &str| json!({"vertices": 4, "faces": [[0,1,3],[1,2,3]], "squared_lengths": ["1", d, "1", "1", "1"]});
    let a = claim("euclidean", square.clone(), other("2"));
    assert_eq!(verdict(&a), (ClaimVerdict::Holds, true), "{a:?}");
    // Negative control: diagonal √3 claimed.
    let a = claim("euclidean", square, other("3"));
    assert_eq!(verdict(&a), (ClaimVerdict::Refuted, true), "{a:?}");
}

#[test]
fn b82_regular_hexagon_fan_reaches_every_triangulation() {
    let fan = hexagon(&[[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 5]]);
    let triangle = [[0, 1, 2], [2, 3, 4], [4, 5, 0], [0, 2, 4]];
    let zigzag = [[0, 1, 2], [0, 2, 5], [2, 3, 5], [3, 4, 5]];
    let other_fan = [[3, 4, 5], [3, 5, 0], [3, 0, 1], [3, 1, 2]];
    for faces in [triangle, zigzag, other_fan] {
        let a = claim("euclidean", fan.clone(), hexagon(&faces));
        assert_eq!(verdict(&a), (ClaimVerdict::Holds, true), "{faces:?}: {a:?}");
    }
    // Negative control: the inner triangle 0-2-4 claimed with side 9/5, not √3.
    let mut wrong = hexagon(&triangle);
    wrong["squared_lengths"][3] = json!(["81/25", "81/25", "81/25"]);
    wrong["squared_lengths"][0][2] = json!("81/25");
    wrong["squared_lengths"][1][2] = json!("81/25");
    wrong["squared_lengths"][2][2] = json!("81/25");
    let a = claim("euclidean", fan, wrong);
    assert_eq!(verdict(&a), (ClaimVerdict::Refuted, true), "{a:?}");
}

#[test]
fn b82_grid_with_every_diagonal_flipped_holds() {
    let a = claim(
        "euclidean",
        grid(2, 2, |_, _| false),
        grid(2, 2, |_, _| true),
    );
    assert_eq!(verdict(&a), (ClaimVerdict::Holds, true), "{a:?}");
    let a = claim(
        "euclidean",
        grid(2, 2, |_, _| false),
        grid(2, 2, |x, y| x == y),
    );
    assert_eq!(verdict(&a), (ClaimVerdict::Holds, true), "{a:?}");
}

#[test]
fn b82_claim_that_is_not_delaunay_is_refuted_after_a_complete_search() {
    // 2 × 1 rectangle: 0 = (0,0), 1 = (1,0), 2 = (2,0), 3 = (0,1), 4 = (1,1), 5 = (2,1).
    // Its cells are the two unit squares; the claim uses the long edge 3–2 (√5) across
    // both, which no Delaunay triangulation has.
    let rect = grid(2, 1, |_, _| false);
    let positions = rect["positions"].clone();
    let long =
        json!({"vertices": 6, "faces": [[0,1,3],[1,2,3],[2,4,3],[2,5,4]], "positions": positions});
    let a = claim("euclidean", rect.clone(), long);
    assert_eq!(verdict(&a), (ClaimVerdict::Refuted, true), "{a:?}");
    let w = a.counterexample.expect("a counterexample");
    assert!(
        w.element.contains("v2–v3") || w.element.contains("v3–v2"),
        "{w:?}"
    );
    assert!(w.detail.contains("searched completely"), "{w:?}");
    // A result with other counts (one unit square only) is no flip of the rectangle.
    let a = claim("euclidean", rect.clone(), grid(1, 1, |_, _| true));
    assert_eq!(verdict(&a), (ClaimVerdict::Refuted, true), "{a:?}");
    assert_eq!(
        a.counterexample.map(|w| w.element).as_deref(),
        Some("result")
    );
    // Negative control: a Delaunay triangulation of the same rectangle holds.
    let a = claim("euclidean", rect, grid(2, 1, |x, _| x == 1));
    assert_eq!(verdict(&a), (ClaimVerdict::Holds, true), "{a:?}");
}

#[test]
fn b82_claim_past_the_tie_bound_is_undecided() {
    // 5 × 4 unit squares: 20 ties, more than MAX_TIES.
    const { assert!(20 > MAX_TIES && MAX_STATES >= 1 << 8) };
    let a = claim(
        "euclidean",
        grid(5, 4, |_, _| false),
        grid(5, 4, |_, _| true),
    );
    assert_eq!(verdict(&a), (ClaimVerdict::Undecided, false), "{a:?}");
    assert!(a.witnesses[0].detail.contains("more than the 16"), "{a:?}");
    // Negative control: 4 × 2 squares (8 ties, 2^8 triangulations) are searched.
    let t = Instant::now();
    let a = claim(
        "euclidean",
        grid(4, 2, |_, _| false),
        grid(4, 2, |_, _| true),
    );
    assert_eq!(verdict(&a), (ClaimVerdict::Holds, true), "{a:?}");
    eprintln!("b82: 4 × 2 grid, every tie flipped: {:?}", t.elapsed());
}

/// `n` cocircular points with rational coordinates, `((1 − t²)/(1 + t²), 2t/(1 + t²))` for
/// increasing `t` (counter-clockwise on the unit circle), triangulated by `faces`. The
/// squared chords are rational and so is every tie flip (B82: each vertex occurs twice in
/// the product under the root).
fn rational_polygon(n: u32, faces: &[[u32; 3]]) -> Value {
    let positions: Vec<Value> = (0..n)
        .map(|i| {
            let t = rug::Rational::from((i64::from(i) * 2 - i64::from(n), 3));
            let d = rug::Rational::from(&t * &t) + 1u32;
            let x = (rug::Rational::from(1) - rug::Rational::from(&t * &t)) / &d;
            let y = rug::Rational::from(&t * 2u32) / &d;
            json!([x.to_string(), y.to_string(), "0"])
        })
        .collect();
    json!({"vertices": n, "faces": faces, "positions": positions})
}

fn fan(n: u32, apex: u32) -> Vec<[u32; 3]> {
    (1..n - 1)
        .map(|i| [apex, (apex + i) % n, (apex + i + 1) % n])
        .collect()
}

#[test]
fn b82_cyclic_polygon_fans_and_the_state_cap() {
    // Default: an 8-gon, 5 ties, Catalan(6) = 132 triangulations, searched completely.
    // Long mode: a 14-gon, 11 ties, Catalan(12) = 208 012 > MAX_STATES triangulations.
    let n = crate::support::cases(8, 14) as u32;
    let other = rational_polygon(n, &fan(n, n / 2));
    let a = claim("euclidean", rational_polygon(n, &fan(n, 0)), other.clone());
    if n == 8 {
        assert_eq!(verdict(&a), (ClaimVerdict::Holds, true), "{a:?}");
        // Negative control: the other fan with one chord off, after a complete search.
        let mut wrong = other;
        wrong["positions"][1] = json!(["0", "0", "0"]);
        let a = claim("euclidean", rational_polygon(n, &fan(n, 0)), wrong.clone());
        assert_eq!(verdict(&a), (ClaimVerdict::Refuted, true), "{a:?}");
    } else {
        assert_eq!(verdict(&a), (ClaimVerdict::Undecided, false), "{a:?}");
        assert!(
            a.witnesses[0]
                .detail
                .contains(&format!("more than {MAX_STATES}")),
            "{a:?}"
        );
    }
}

#[test]
fn b82_grid_search_is_complete_up_to_the_tie_bound() {
    // Default 3 × 3 squares (9 ties, 512 triangulations); long mode 4 × 4 (16 ties, the
    // bound: 65 536 = MAX_STATES triangulations, all visited).
    let w = crate::support::cases(3, 4) as u32;
    let t = Instant::now();
    let a = claim(
        "euclidean",
        grid(w, w, |_, _| false),
        grid(w, w, |_, _| true),
    );
    assert_eq!(verdict(&a), (ClaimVerdict::Holds, true), "{a:?}");
    // Negative control: the same claim with one vertex moved, so one square's lengths are
    // off: no Delaunay triangulation matches, the search is complete.
    let mut wrong = grid(w, w, |_, _| true);
    wrong["positions"][0] = json!(["1/10", "0", "0"]);
    let a = claim("euclidean", grid(w, w, |_, _| false), wrong);
    assert_eq!(verdict(&a), (ClaimVerdict::Refuted, true), "{a:?}");
    eprintln!("b82: {w} × {w} grid, holds and refuted: {:?}", t.elapsed());
}
