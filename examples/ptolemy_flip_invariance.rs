//! Ptolemy-flip invariance (T28): on rational λ-lengths a Ptolemy flip is an involution,
//! commutes with conformal scaling, moves the five affected cross ratios by the cluster
//! rule and keeps every vertex product of cross ratios equal to 1 — all exactly in ℚ.
//!
//! Run: `cargo run --release --example ptolemy_flip_invariance`

use penner::algorithms::flips::flip_ptolemy_exact;
use penner::mesh::{builders, Edge};
use penner::theorems::t28_ptolemy_flip::check_ptolemy_flip;
use penner::theorems::Verdict;
use rug::Rational;

fn main() {
    let mesh = builders::octahedron().mesh;
    // Lengths 1 + e/10 (any positive rationals are valid λ-lengths).
    let l: Vec<Rational> = (0..mesh.n_edges() as i64)
        .map(|e| Rational::from((10 + e, 10)))
        .collect();
    let s: Vec<Rational> = (0..mesh.n_vertices() as i64)
        .map(|v| Rational::from((3 + v, 4)))
        .collect();
    let v = check_ptolemy_flip(&mesh, &l, &s);
    match &v {
        Verdict::Holds { certified, .. } => {
            println!("T28 Ptolemy flip identities on the octahedron, every edge: holds (certified = {certified})");
        }
        other => println!("T28: {other:?}"),
    }

    // Flip edge 0 twice: the lengths come back exactly.
    let (mut m, mut x) = (mesh.clone(), l.clone());
    flip_ptolemy_exact(&mut m, &mut x, Edge(0)).expect("interior edge");
    let once = x[0].clone();
    flip_ptolemy_exact(&mut m, &mut x, Edge(0)).expect("interior edge");
    println!(
        "edge 0: {} → {} → {} (involution: {})",
        l[0],
        once,
        x[0],
        x == l
    );

    if !(v.holds() && x == l) {
        std::process::exit(1);
    }
}
