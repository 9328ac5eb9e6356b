//! Rivin weights and their infeasibility (T34; notes §1.6.3, Fig. 17; Hodgson–Rivin–Smith
//! 1992). A triangulated sphere is inscribable (an ideal polyhedron) only if its edges carry
//! exterior dihedral angles `w_e ∈ (0, 1/2)` (in units of `2π`) summing to 1 around every
//! vertex: `A w = 1`, `w > 0`, with `A` the vertex–edge incidence matrix.
//!
//! **Farkas certificate.** A vector `y` (one rational per vertex) with `c = Aᵀy ≤ 0`,
//! `c ≠ 0` and `Σ_v y_v ≥ 0` proves that no `w > 0` satisfies `A w = 1`: otherwise
//! `Σ_v y_v = yᵀAw = cᵀw < 0`. Steiner's argument gives one: an independent set `I` of
//! vertices with `2|I| ≥ V` that misses some edge; `y = 1_I − ½` gives `c_e = −1` on the
//! edges not touching `I` and 0 elsewhere, and `Σ y = |I| − V/2 ≥ 0`.
//!
//! Certificates are checked twice, independently: in `rug::Rational` and in
//! `num_rational::BigRational`.

use crate::mesh::Mesh;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use rug::Rational;

/// The endpoints of every edge.
fn edge_ends(mesh: &Mesh) -> Vec<(usize, usize)> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            (mesh.tail(h).idx(), mesh.tip(h).idx())
        })
        .collect()
}

/// Steiner's certificate `y = 1_I − ½` from a greedy independent set `I` (vertices by
/// increasing degree, then index), or `None` when that set is smaller than `V/2` or touches
/// every edge (the greedy search proves nothing either way).
pub fn steiner_certificate(mesh: &Mesh) -> Option<Vec<Rational>> {
    let ends = edge_ends(mesh);
    let n = mesh.n_vertices();
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by_key(|&v| (mesh.degree(crate::mesh::Vertex(v as u32)), v));
    let mut neighbours = vec![Vec::new(); n];
    for &(a, b) in &ends {
        neighbours[a].push(b);
        neighbours[b].push(a);
    }
    let mut chosen = vec![false; n];
    for v in order {
        if !neighbours[v].iter().any(|&w| chosen[w] || w == v) {
            chosen[v] = true;
        }
    }
    let size = chosen.iter().filter(|&&c| c).count();
    let misses = ends.iter().any(|&(a, b)| !chosen[a] && !chosen[b]);
    (2 * size >= n && misses).then(|| {
        chosen
            .iter()
            .map(|&c| Rational::from(if c { (1, 2) } else { (-1, 2) }))
            .collect()
    })
}

/// Whether `y` is a Farkas certificate of infeasibility of Rivin's system on `mesh`,
/// decided in `rug::Rational`.
pub fn verify_certificate_rug(mesh: &Mesh, y: &[Rational]) -> bool {
    if y.len() != mesh.n_vertices() {
        return false;
    }
    let mut some_negative = false;
    for (a, b) in edge_ends(mesh) {
        let c = Rational::from(&y[a] + &y[b]);
        if c > 0 {
            return false;
        }
        some_negative |= c < 0;
    }
    let total: Rational = y.iter().sum();
    some_negative && total >= 0
}

/// The same decision in `num_rational::BigRational` (an independent arithmetic), from the
/// certificate given as `(numerator, denominator)` decimal strings.
pub fn verify_certificate_num(mesh: &Mesh, y: &[(String, String)]) -> bool {
    if y.len() != mesh.n_vertices() {
        return false;
    }
    let parse = |(n, d): &(String, String)| -> Option<BigRational> {
        let n: BigInt = n.parse().ok()?;
        let d: BigInt = d.parse().ok()?;
        (!d.is_zero()).then(|| BigRational::new(n, d))
    };
    let Some(y): Option<Vec<BigRational>> = y.iter().map(parse).collect() else {
        return false;
    };
    let mut some_negative = false;
    for (a, b) in edge_ends(mesh) {
        let c = &y[a] + &y[b];
        if c.is_positive() {
            return false;
        }
        some_negative |= c.is_negative();
    }
    let total = y.iter().fold(BigRational::zero(), |s, x| s + x);
    some_negative && !total.is_negative()
}

/// A certificate as `(numerator, denominator)` decimal strings, for
/// [`verify_certificate_num`].
pub fn certificate_strings(y: &[Rational]) -> Vec<(String, String)> {
    y.iter()
        .map(|q| (q.numer().to_string(), q.denom().to_string()))
        .collect()
}

/// Whether `w` (in units of `2π`) are Rivin weights: `0 < w_e < 1/2` and the sums around
/// every vertex equal 1, exactly.
pub fn are_rivin_weights(mesh: &Mesh, w: &[Rational]) -> bool {
    if w.len() != mesh.n_edges() {
        return false;
    }
    let half = Rational::from((1, 2));
    if w.iter().any(|x| *x <= 0 || *x >= half) {
        return false;
    }
    let mut sums = vec![Rational::new(); mesh.n_vertices()];
    for ((a, b), x) in edge_ends(mesh).into_iter().zip(w) {
        sums[a] += x;
        sums[b] += x;
    }
    sums.iter().all(|s| *s == 1)
}
