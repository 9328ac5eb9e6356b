//! Metric edge flips: the Euclidean flip (planar layout of the two triangles, preserves the
//! cone metric) and the Ptolemy flip (docs/catalogue.md §5, notes Eq. 18), generic over [`Real`],
//! exact over [`rug::Rational`] and outward-rounded over [`Interval<Mpfr>`].
//!
//! Both refuse, with the mesh's [`FlipError`], an edge that cannot be flipped: a boundary
//! edge, or an edge with the same face on both sides (a self-folded triangle around a
//! degree-1 vertex).
//!
//! ```
//! use penner::algorithms::flips::flip_ptolemy_exact;
//! use penner::mesh::{Edge, Mesh};
//! use rug::Rational;
//! let mut m = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
//! let diag = m.edges().find(|&e| !m.is_boundary_edge(e)).unwrap();
//! let mut l: Vec<Rational> = m.edges().map(|e| Rational::from(e.0 + 2)).collect();
//! let before = l.clone();
//! flip_ptolemy_exact(&mut m, &mut l, diag).unwrap();
//! flip_ptolemy_exact(&mut m, &mut l, diag).unwrap();
//! assert_eq!(l, before); // the Ptolemy flip is an involution, exactly
//! ```

use crate::mesh::{Edge, FlipError, Mesh};
use crate::predicates::delaunay::{Quad, QuadEdges};
use crate::predicates::directed::{div_positive, valid};
use crate::scalar::{Interval, IntervalBound, Real};
use rug::Rational;

/// Which flip updates the length of the new diagonal.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum FlipKind {
    /// Planar layout of the two triangles; preserves the cone metric (T23).
    Euclidean,
    /// `ℓ_kl = (ℓ_ik ℓ_jl + ℓ_il ℓ_jk)/ℓ_ij`; preserves the decorated hyperbolic structure
    /// and commutes with scaling (T28).
    Ptolemy,
}

/// The Ptolemy length `ℓ_kl = (ℓ_ik ℓ_jl + ℓ_il ℓ_jk) / ℓ_ij` (docs/catalogue.md §5), evaluated as
/// `ℓ_ki·(ℓ_lj/ℓ_ij) + ℓ_il·(ℓ_jk/ℓ_ij)` so that products of large lengths do not overflow.
pub fn ptolemy_length<T: Real>(q: Quad<&T>) -> T {
    q.ki.clone() * &(q.lj.clone() / q.ij) + &(q.il.clone() * &(q.jk.clone() / q.ij))
}

/// The Ptolemy length in exact rational arithmetic.
pub fn ptolemy_length_exact(q: Quad<&Rational>) -> Rational {
    (Rational::from(q.ki * q.lj) + Rational::from(q.il * q.jk)) / q.ij
}

/// The Ptolemy length of enclosed lengths, rounded outward (proof: B62); `None` if `ℓ_ij`
/// may be ≤ 0.
pub fn ptolemy_length_enclosure<B: IntervalBound>(q: Quad<&Interval<B>>) -> Option<Interval<B>> {
    div_positive(&(q.ki.clone() * q.lj + &(q.il.clone() * q.jk)), q.ij)
}

/// The Euclidean length of the new diagonal `kl`: lay out `i = (0,0)`, `j = (a,0)`, `k`
/// above and `l` below the x-axis; then
///
/// ```text
/// ℓ_kl = √( ((c−b)(c+b) + (e−d)(e+d))² + (S_ijk + S_jil)² ) / (2a),
/// S = 4·Area = √((x+(y+z))(z−(x−y))(z+(x−y))(x+(y−z)))   (x ≥ y ≥ z, Kahan),
/// ```
///
/// with `a = ℓ_ij, b = ℓ_jk, c = ℓ_ki, d = ℓ_il, e = ℓ_lj` (docs/catalogue.md §1, §5). Kahan's
/// ordering keeps the area accurate for needles and caps. When a length lies outside
/// `[2⁻¹⁰⁰, 2¹⁰⁰]` the lengths are first scaled by a power of two near `1/a` so that
/// squares of squares do not overflow; scaling by a power of two commutes with every
/// rounded operation while no intermediate overflows or underflows, so inside that range
/// (all intermediates within `2^±500`) skipping it changes no bit of the result. For
/// triangles that violate the triangle inequality the square root of a negative number is
/// NaN (`f64`): the caller refuses such a flip.
#[inline]
pub fn euclidean_length<T: Real>(q: Quad<&T>) -> T {
    if q.to_array().iter().all(|x| moderate_f64(x.approx_f64())) {
        return euclidean_core([q.ij, q.jk, q.ki, q.il, q.lj].map(Clone::clone));
    }
    let a0 = q.ij.approx_f64();
    let (scale, unscale) = if a0.is_normal() && a0 > 0.0 {
        let k = a0.log2().floor() as i32;
        (q.ij.lit(2f64.powi(-k)), q.ij.lit(2f64.powi(k)))
    } else {
        (q.ij.one_like(), q.ij.one_like())
    };
    euclidean_core(q.to_array().map(|x| x.clone() * &scale)) * &unscale
}

/// Whether `2⁻¹⁰⁰ ≤ x < 2¹⁰⁰`, the range in which [`euclidean_length`] needs no rescaling
/// (every intermediate then lies within `2^±500`).
#[inline]
pub fn moderate_f64(x: f64) -> bool {
    // Biased exponent in [923, 1123) ⇔ 2⁻¹⁰⁰ ≤ x < 2¹⁰⁰ for positive finite x.
    (x.to_bits() >> 52).wrapping_sub(923) < 200
}

/// [`euclidean_length`] without rescaling.
#[inline]
fn euclidean_core<T: Real>([a, b, c, d, e]: [T; 5]) -> T {
    let x = (c.clone() - &b) * &(c.clone() + &b) + &((e.clone() - &d) * &(e.clone() + &d));
    let y = four_area(&a, &b, &c) + &four_area(&a, &d, &e);
    let r = (x.clone() * &x + &(y.clone() * &y)).sqrt();
    r / &(a.clone() * &a.lit(2.0))
}

/// `4·Area` of a triangle by Kahan's formula, ordering the sides by their `f64` images
/// (an ordering error between nearly equal sides changes the result only by rounding).
#[inline]
fn four_area<T: Real>(p: &T, q: &T, r: &T) -> T {
    // Three compare-exchanges sort (x, y, z) into decreasing order of the f64 images.
    let key = |t: &T| t.approx_f64();
    let (mut x, mut y, mut z) = (p, q, r);
    if key(x).total_cmp(&key(y)).is_lt() {
        std::mem::swap(&mut x, &mut y);
    }
    if key(y).total_cmp(&key(z)).is_lt() {
        std::mem::swap(&mut y, &mut z);
    }
    if key(x).total_cmp(&key(y)).is_lt() {
        std::mem::swap(&mut x, &mut y);
    }
    let xy = x.clone() - y;
    let prod = (x.clone() + &(y.clone() + z))
        * &(z.clone() - &xy)
        * &(z.clone() + &xy)
        * &(x.clone() + &(y.clone() - z));
    prod.sqrt()
}

/// The Euclidean length of [`euclidean_length`] on enclosed lengths, rounded outward;
/// `None` if a triangle may violate the triangle inequality (its area factor may be
/// negative) or `ℓ_ij` may be ≤ 0 (proof: B62).
pub fn euclidean_length_enclosure<B: IntervalBound>(q: Quad<&Interval<B>>) -> Option<Interval<B>> {
    let one = Interval::point(q.ij.lo().one_like());
    let b = div_positive(q.jk, q.ij)?;
    let c = div_positive(q.ki, q.ij)?;
    let d = div_positive(q.il, q.ij)?;
    let e = div_positive(q.lj, q.ij)?;
    // 4·Area of the triangle (1, b, c) by Heron's product, scaled by ℓ_ij.
    let four_area = |b: &Interval<B>, c: &Interval<B>| {
        let s = (b.clone() + c - &one)
            * &(one.clone() - b + c)
            * &(one.clone() + b - c)
            * &(one.clone() + b + c);
        valid(s.sqrt())
    };
    let x = (c.clone() - &b) * &(c.clone() + &b) + &((e.clone() - &d) * &(e.clone() + &d));
    let y = four_area(&b, &c)? + &four_area(&d, &e)?;
    let r = valid((x.clone() * &x + &(y.clone() * &y)).sqrt())?;
    valid(r * q.ij * &Interval::point(q.ij.lo().lit(0.5)))
}

fn quad_or_refuse(mesh: &Mesh, e: Edge) -> Result<QuadEdges, FlipError> {
    if e.idx() >= mesh.n_edges() {
        return Err(FlipError::OutOfRange(e));
    }
    if mesh.is_boundary_edge(e) {
        return Err(FlipError::Boundary(e));
    }
    QuadEdges::of(mesh, e).ok_or(FlipError::SameFace(e))
}

/// Flip edge `e` combinatorially and update its length with `kind` (no Delaunay test).
/// `lengths` has one entry per edge.
pub fn flip_metric<T: Real>(
    mesh: &mut Mesh,
    lengths: &mut [T],
    e: Edge,
    kind: FlipKind,
) -> Result<(), FlipError> {
    let q = quad_or_refuse(mesh, e)?;
    let quad = q.lengths(lengths);
    let new = match kind {
        FlipKind::Euclidean => euclidean_length(quad),
        FlipKind::Ptolemy => ptolemy_length(quad),
    };
    mesh.flip(e)?;
    lengths[e.idx()] = new;
    Ok(())
}

/// Euclidean flip of `e` (see [`euclidean_length`]).
pub fn flip_euclidean<T: Real>(
    mesh: &mut Mesh,
    lengths: &mut [T],
    e: Edge,
) -> Result<(), FlipError> {
    flip_metric(mesh, lengths, e, FlipKind::Euclidean)
}

/// Ptolemy flip of `e` (see [`ptolemy_length`]).
pub fn flip_ptolemy<T: Real>(mesh: &mut Mesh, lengths: &mut [T], e: Edge) -> Result<(), FlipError> {
    flip_metric(mesh, lengths, e, FlipKind::Ptolemy)
}

/// Ptolemy flip of `e` in exact rational arithmetic: rational lengths stay rational.
pub fn flip_ptolemy_exact(
    mesh: &mut Mesh,
    lengths: &mut [Rational],
    e: Edge,
) -> Result<(), FlipError> {
    let q = quad_or_refuse(mesh, e)?;
    let new = ptolemy_length_exact(q.lengths(lengths));
    mesh.flip(e)?;
    lengths[e.idx()] = new;
    Ok(())
}
