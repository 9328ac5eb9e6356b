//! The intrinsic Delaunay condition of an edge, decided with certified signs.
//!
//! For an interior edge `ij` between faces `ijk` and `jil` (docs/catalogue.md §5) with lengths
//! `a = ℓ_ij`, `b = ℓ_jk`, `c = ℓ_ki`, `d = ℓ_il`, `e = ℓ_lj`, the edge is Delaunay iff
//!
//! ```text
//! P := d·e·(b² + c² − a²) + b·c·(d² + e² − a²)  ≥ 0,
//! ```
//!
//! which is `2bcde (cos α_k + cos α_l)` and equals `ℓ_ij · D` for GSC21's
//! `D = ℓ_kl(ℓ_il ℓ_ki + ℓ_jk ℓ_lj) − ℓ_ij(ℓ_jk ℓ_ki + ℓ_il ℓ_lj)` with `ℓ_kl` from Ptolemy
//! (proof: B60 derives the identity). `P` is a polynomial in the lengths, so it stays
//! meaningful when a triangle violates the triangle inequality (Ptolemy lengths).
//!
//! Rungs of the ladder ([`crate::predicates::ladder`]):
//! 1. an `f64` filter on `P = K − N`, `K = de(b² + c²) + bc(d² + e²)`, `N = a²(de + bc)`
//!    (both sums of positive terms): `N̂ < fl(K̂·(1 − 2⁻⁴⁹))` proves `P > 0` and the mirror
//!    test proves `P < 0`, after an exact power-of-two rescaling of the quadrilateral
//!    (proof: B61);
//! 2. MPFR intervals with outward rounding (proof: B62);
//! 3. exact rationals (every finite binary float is rational), or, for squared lengths,
//!    the sign-exact form of [`delaunay_sign_squared`] (proof: B63).
//!
//! Lengths given as `ℓ̃ = e^{(u_i+u_j)/2} ℓ` ([`ScaledQuad`]) are enclosed directly in MPFR,
//! whose exponent range makes `|u|` up to 10⁶ safe; nothing is formed in `f64`.
//!
//! Edge classification ([`edge_delaunay_sign`]): boundary edges are Delaunay by definition;
//! an edge with the same face on both sides (a self-folded triangle around a degree-1
//! vertex) is Delaunay by definition too — its two opposite corners are two corners of one
//! triangle, whose sum is below π — and it can never be flipped.
//!
//! ```
//! use penner::mesh::{Edge, Mesh};
//! use penner::predicates::delaunay::{edge_delaunay_sign, EdgeDelaunay};
//! use penner::predicates::ladder::Ladder;
//! use penner::scalar::{Certified, Sign};
//! // A unit square split along a diagonal: cocircular, so D = 0 exactly.
//! let m = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
//! let d = 2f64.sqrt();
//! let lengths: Vec<f64> = m.edges().map(|e| {
//!     let h = e.halfedge();
//!     if (m.tail(h).0 + m.tip(h).0) % 2 == 0 { d } else { 1.0 }
//! }).collect();
//! let diag = m.edges().find(|&e| !m.is_boundary_edge(e)).unwrap();
//! let s = edge_delaunay_sign(&m, &lengths, diag, &Ladder::default()).unwrap();
//! // √2 rounded to f64 is slightly off, so the sign is decided, not Zero:
//! assert!(matches!(s, EdgeDelaunay::Interior(Certified::Known { .. })));
//! ```

use super::directed::scaled_length;
use super::ladder::{decide, Ladder, SignPredicate};
use crate::mesh::{Edge, Face, HalfEdge, Mesh};
use crate::scalar::{Certified, Interval, IntervalBound, Mpfr, Precision, Real, Ring, Sign, Stage};
use rug::Rational;

/// The five lengths of the quadrilateral around edge `ij`: `ij` the edge, `jk, ki` the
/// other sides of face `ijk`, `il, lj` the other sides of face `jil`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Quad<T> {
    /// ℓ_ij (the diagonal being tested).
    pub ij: T,
    /// ℓ_jk.
    pub jk: T,
    /// ℓ_ki.
    pub ki: T,
    /// ℓ_il.
    pub il: T,
    /// ℓ_lj.
    pub lj: T,
}

impl<T> Quad<T> {
    /// The lengths as `[a, b, c, d, e] = [ij, jk, ki, il, lj]`.
    #[inline]
    pub fn to_array(self) -> [T; 5] {
        [self.ij, self.jk, self.ki, self.il, self.lj]
    }
    /// The lengths by reference.
    #[inline]
    pub fn as_refs(&self) -> Quad<&T> {
        Quad {
            ij: &self.ij,
            jk: &self.jk,
            ki: &self.ki,
            il: &self.il,
            lj: &self.lj,
        }
    }
    /// Apply `f` to every length.
    #[inline]
    pub fn map<U>(self, mut f: impl FnMut(T) -> U) -> Quad<U> {
        Quad {
            ij: f(self.ij),
            jk: f(self.jk),
            ki: f(self.ki),
            il: f(self.il),
            lj: f(self.lj),
        }
    }
}

/// The half-edges of the quadrilateral around an interior edge, read from the mesh:
/// `h = i→j` in face `ijk`, `t = j→i` in face `jil`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct QuadEdges {
    /// The edge itself.
    pub edge: Edge,
    /// Edges `ij, jk, ki, il, lj`.
    pub edges: Quad<Edge>,
}

impl QuadEdges {
    /// The quadrilateral of `e`, or `None` if `e` is a boundary edge or has the same face
    /// on both sides. Does not check that `e` exists.
    #[inline]
    pub fn of(mesh: &Mesh, e: Edge) -> Option<QuadEdges> {
        let h = e.side(0);
        let t = e.side(1);
        let (fa, fb) = (mesh.face(h)?, mesh.face(t)?);
        if fa == fb {
            return None;
        }
        let h_jk: HalfEdge = mesh.next(h);
        let h_ki = mesh.next(h_jk);
        let t_il = mesh.next(t);
        let t_lj = mesh.next(t_il);
        Some(QuadEdges {
            edge: e,
            edges: Quad {
                ij: e,
                jk: h_jk.edge(),
                ki: h_ki.edge(),
                il: t_il.edge(),
                lj: t_lj.edge(),
            },
        })
    }

    /// The lengths of the five edges.
    #[inline]
    pub fn lengths<'a, T>(&self, lengths: &'a [T]) -> Quad<&'a T> {
        self.edges.map(|e| &lengths[e.idx()])
    }

    /// The quadrilateral of the flipped edge `kl` (faces `lki`, `klj`, docs/catalogue.md §5 and
    /// [`Mesh::flip`]) in the same `[ij, jk, ki, il, lj]` roles: `[kl, ki, il, lj, jk]`.
    #[inline]
    pub fn flipped(&self) -> Quad<Edge> {
        let q = self.edges;
        Quad {
            ij: q.ij,
            jk: q.ki,
            ki: q.il,
            il: q.lj,
            lj: q.jk,
        }
    }
}

/// Why the Delaunay condition of an edge cannot be evaluated.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum DelaunayError {
    /// The edge id is out of range.
    #[error("edge {0} does not exist")]
    NoSuchEdge(Edge),
    /// The length array does not have one entry per edge.
    #[error("{got} lengths given for a mesh with {expected} edges")]
    LengthCount {
        /// Edges in the mesh.
        expected: usize,
        /// Lengths given.
        got: usize,
    },
    /// The scale-factor array does not have one entry per vertex.
    #[error("{got} scale factors given for a mesh with {expected} vertices")]
    ScaleCount {
        /// Vertices in the mesh.
        expected: usize,
        /// Scale factors given.
        got: usize,
    },
    /// A log scale factor is not finite.
    #[error("vertex v{vertex} has log scale factor {value}, which is not finite")]
    BadScale {
        /// The vertex.
        vertex: u32,
        /// The offending value.
        value: f64,
    },
    /// Euclidean flips need a Euclidean metric: this face is not certified to be a
    /// non-degenerate triangle (strict triangle inequalities, docs/catalogue.md §1).
    #[error("face {face} is not a non-degenerate triangle (Euclidean flips need the strict triangle inequality)")]
    NotATriangle {
        /// The face.
        face: Face,
    },
    /// A log scale factor exceeds [`MAX_LOG_SCALE`](crate::scalar::exp_length::MAX_LOG_SCALE)
    /// in magnitude.
    #[error("vertex v{vertex} has log scale factor {value}, beyond the supported ±2^20")]
    ScaleOutOfRange {
        /// The vertex.
        vertex: u32,
        /// The offending value.
        value: f64,
    },
    /// A length is zero, negative or not finite.
    #[error("edge {edge} has length {value}, but lengths must be finite and positive")]
    BadLength {
        /// The edge.
        edge: Edge,
        /// The offending value (nearest f64, for display).
        value: f64,
    },
}

/// The Delaunay status of one edge.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum EdgeDelaunay {
    /// A boundary edge: Delaunay by definition.
    Boundary,
    /// The same face on both sides: Delaunay by definition, never flippable.
    SameFace,
    /// An interior edge: the certified sign of `P` (Delaunay iff not `Negative`).
    Interior(Certified<Sign>),
}

impl EdgeDelaunay {
    /// `Some(true)` if certified Delaunay, `Some(false)` if certified not, `None` if
    /// undecided.
    pub fn is_delaunay(&self) -> Option<bool> {
        match self {
            EdgeDelaunay::Boundary | EdgeDelaunay::SameFace => Some(true),
            EdgeDelaunay::Interior(c) => c.value().map(|s| s != Sign::Negative),
        }
    }
}

/// Validate `(mesh, lengths, e)` and return the quadrilateral of an interior edge, or the
/// status fixed by definition (boundary edge, same face on both sides).
fn interior_quad(
    mesh: &Mesh,
    n_lengths: usize,
    e: Edge,
) -> Result<Result<QuadEdges, EdgeDelaunay>, DelaunayError> {
    if n_lengths != mesh.n_edges() {
        return Err(DelaunayError::LengthCount {
            expected: mesh.n_edges(),
            got: n_lengths,
        });
    }
    if e.idx() >= mesh.n_edges() {
        return Err(DelaunayError::NoSuchEdge(e));
    }
    if mesh.is_boundary_edge(e) {
        return Ok(Err(EdgeDelaunay::Boundary));
    }
    Ok(QuadEdges::of(mesh, e).ok_or(EdgeDelaunay::SameFace))
}

/// The certified Delaunay status of edge `e` under per-edge `lengths` (docs/catalogue.md §5, Eq. 13).
pub fn edge_delaunay_sign<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    e: Edge,
    ladder: &Ladder,
) -> Result<EdgeDelaunay, DelaunayError> {
    let q = match interior_quad(mesh, lengths.len(), e)? {
        Ok(q) => q,
        Err(status) => return Ok(status),
    };
    let quad = q.lengths(lengths);
    for (edge, l) in q.edges.to_array().into_iter().zip(quad.to_array()) {
        check_length(edge, l)?;
    }
    Ok(EdgeDelaunay::Interior(decide(&RealQuad(quad), ladder)))
}

/// Whether values of `T` at `ctx` are binary64 numbers as read by `approx_f64` (53-bit
/// point values; inside the f64 exponent range they are exact), the precondition of the
/// f64 filter's fast input path (proof: B61).
#[inline]
pub(crate) fn f64_exact<T: Real>(ctx: T::Ctx) -> bool {
    T::precision_bits(ctx) == 53 && T::is_point()
}

/// Check that `l` is finite and positive (exactly, via its rational value when it is not
/// an `f64`-range 53-bit number).
#[inline]
pub fn check_length<T: Real>(edge: Edge, l: &T) -> Result<(), DelaunayError> {
    let x = l.approx_f64();
    if f64_exact::<T>(l.ctx()) && x.is_finite() && x > 0.0 {
        return Ok(());
    }
    match l.to_rational() {
        Some(q) if q > 0 => Ok(()),
        _ => Err(DelaunayError::BadLength { edge, value: x }),
    }
}

// ---------------------------------------------------------------------------------------
// Rung 1: the f64 filter.

/// `2⁻²⁰⁰` and `2²⁰⁰`: the range in which the filter runs without rescaling.
const SAFE_LO: f64 = 6.223015277861142e-61;
const SAFE_HI: f64 = 1.6069380442589903e60;
/// `ρ = 1 − 2⁻⁴⁹ = 1 − 16u`: `N̂ < fl(K̂·ρ)` proves `N < K` (proof: B61).
const FILTER_RHO: f64 = 1.0 - 1.0 / 562_949_953_421_312.0;
/// The relative error constant `8u = 2⁻⁵⁰` of the filter on rounded rational inputs
/// (proof: B61).
const FILTER_REL: f64 = 8.881784197001252e-16;
/// The absolute underflow allowance `2⁻¹⁰⁰⁰` of the filter on rounded rational inputs
/// (proof: B61).
const FILTER_ABS: f64 = 9.332636185032189e-302;

/// Sign of `P` for five positive finite `f64` lengths, or `None` when the proven error
/// bound does not separate it from zero or the lengths span more than 2²⁰⁰ (proof: B61).
#[allow(clippy::inline_always)] // hot path of the flip loop (measured)
#[inline(always)]
pub fn filter_f64(q: [f64; 5]) -> Option<Sign> {
    let in_range = in_filter_range;
    let [a, b, c, d, e] = q;
    if !(in_range(a) & in_range(b) & in_range(c) & in_range(d) & in_range(e)) {
        let lo = a.min(b).min(c).min(d).min(e);
        let hi = a.max(b).max(c).max(d).max(e);
        return filter_rescaled(q, lo, hi);
    }
    filter_core(a, b, c, d, e)
}

/// Whether `2⁻²⁰⁰ ≤ x < 2²⁰⁰`, the range in which [`filter_f64`] runs without rescaling
/// (proof: B61). Zero, negative, subnormal, infinite and NaN values are outside.
#[inline]
pub fn in_filter_range(x: f64) -> bool {
    // Biased exponent in [823, 1222] ⇔ 2⁻²⁰⁰ ≤ x < 2²⁰⁰ for positive x; a set sign bit
    // or an exponent out of range fails.
    (x.to_bits() >> 52).wrapping_sub(823) < 400
}

/// [`filter_f64`] for inputs the caller knows to be in range ([`in_filter_range`] holds
/// for all five): the same decision without the range test (proof: B61).
#[allow(clippy::inline_always)] // hot path of the flip loop (measured)
#[inline(always)]
pub fn filter_f64_in_range(q: [f64; 5]) -> Option<Sign> {
    debug_assert!(q.iter().all(|&x| in_filter_range(x)));
    let [a, b, c, d, e] = q;
    filter_core(a, b, c, d, e)
}

#[cold]
fn filter_rescaled(q: [f64; 5], lo: f64, hi: f64) -> Option<Sign> {
    if !(lo > 0.0 && hi.is_finite()) {
        return None;
    }
    // Scale by 2^-k with 2^k ≤ hi < 2^(k+1): exact while no result is subnormal.
    let k = hi.log2().floor() as i32;
    let s = 2f64.powi(-k);
    let r = q.map(|x| x * s);
    let rlo = r.iter().copied().fold(f64::INFINITY, f64::min);
    if rlo
        .partial_cmp(&SAFE_LO)
        .is_none_or(std::cmp::Ordering::is_lt)
    {
        return None;
    }
    filter_core(r[0], r[1], r[2], r[3], r[4])
}

#[allow(clippy::inline_always)] // hot path of the flip loop (measured)
#[inline(always)]
fn filter_core(a: f64, b: f64, c: f64, d: f64, e: f64) -> Option<Sign> {
    // P = K − N with K = de(b² + c²) + bc(d² + e²) and N = a²(de + bc): two sums of
    // positive terms, each computed to within a few units of rounding.
    let de = d * e;
    let bc = b * c;
    let k = de * (b * b + c * c) + bc * (d * d + e * e);
    let n = (a * a) * (de + bc);
    // proof: B61 — N̂ < fl(K̂·ρ) ⇒ N < K, and K̂ < fl(N̂·ρ) ⇒ K < N.
    if n < k * FILTER_RHO {
        Some(Sign::Positive)
    } else {
        filter_not_positive(k, n)
    }
}

/// The second half of [`filter_core`], out of line: most edges tested in a flip loop are
/// Delaunay, and a real branch there is cheaper than computing both tests (measured).
#[inline(never)]
fn filter_not_positive(k: f64, n: f64) -> Option<Sign> {
    // proof: B61
    if k < n * FILTER_RHO {
        Some(Sign::Negative)
    } else {
        None
    }
}

// ---------------------------------------------------------------------------------------
// Rungs 2 and 3: enclosures and exact rationals.

/// `P = d·e·(b² + c² − a²) + b·c·(d² + e² − a²)` for the lengths `[a, b, c, d, e]` of
/// [`Quad`] (docs/catalogue.md §5, Eq. 13), evaluated in `T`: rounded for point types, an enclosure
/// for intervals ([`enclose_p`]).
pub fn delaunay_p<T: Ring>(q: &[T; 5]) -> T {
    let [a, b, c, d, e] = q;
    let a2 = a.clone() * a;
    let x = b.clone() * b + &(c.clone() * c) - &a2;
    let y = d.clone() * d + &(e.clone() * e) - &a2;
    d.clone() * e * &x + &(b.clone() * c * &y)
}

/// `P` evaluated on interval inputs `[a, b, c, d, e]` with outward rounding (proof: B62).
pub fn enclose_p<B: IntervalBound>(q: &[Interval<B>; 5]) -> Interval<B> {
    delaunay_p(q)
}

/// `P` in exact rational arithmetic: [`delaunay_p`] in ℚ.
pub fn exact_p(q: [&Rational; 5]) -> Rational {
    delaunay_p(&q.map(Clone::clone))
}

fn sign_of(q: &Rational) -> Sign {
    Sign::of_ordering(q.cmp0())
}

/// The Delaunay predicate on five lengths of any [`Real`] backend.
#[derive(Clone, Copy, Debug)]
pub struct RealQuad<'a, T>(pub Quad<&'a T>);

impl<T: Real> SignPredicate for RealQuad<'_, T> {
    #[allow(clippy::inline_always)] // hot path of the flip loop (measured)
    #[inline(always)]
    fn filter(&self) -> Option<Sign> {
        if !f64_exact::<T>(self.0.ij.ctx()) {
            return None;
        }
        // 53-bit values in the f64 range are f64 numbers exactly; others fail the range
        // check inside the filter (infinite or zero images).
        filter_f64(self.0.to_array().map(Real::approx_f64))
    }
    fn enclosure_sign(&self, prec: Precision) -> Option<Sign> {
        let mut ins = Vec::with_capacity(5);
        for l in self.0.to_array() {
            ins.push(Interval::from_rational(&l.to_rational()?, prec));
        }
        let ins: [Interval<Mpfr>; 5] = ins.try_into().ok()?;
        enclose_p(&ins).sign()
    }
    fn exact_sign(&self) -> Option<Sign> {
        let [a, b, c, d, e] = self.0.to_array().map(Real::to_rational);
        Some(sign_of(&exact_p([&a?, &b?, &c?, &d?, &e?])))
    }
}

/// The Delaunay predicate on five exact rational lengths.
#[derive(Clone, Copy, Debug)]
pub struct RationalQuad<'a>(pub Quad<&'a Rational>);

impl RationalQuad<'_> {
    /// The rational filter's evaluation (B61): `(P̂, t)` with `P̂` the binary64 value of `P`
    /// on the inputs converted by `to_f64` (truncated) and `t = 2⁻⁴⁷·M̂ + 2⁻¹⁰⁰⁰` its error
    /// bound, `M̂` the same expression with every `−` read as `+`; `None` when an input's
    /// image leaves `[2⁻²⁰⁰, 2²⁰⁰]`. The filter answers the sign of `P̂` when `|P̂| > t`.
    #[doc(hidden)]
    pub fn filter_terms(&self) -> Option<(f64, f64)> {
        // `to_f64` rounds toward zero: four input errors below 2u per monomial on top of
        // the six roundings of the evaluation; the bound 2⁻⁴⁷·M̂ covers both (proof: B61).
        let q = self.0.to_array().map(Rational::to_f64);
        let [a, b, c, d, e] = q;
        let lo = a.min(b).min(c).min(d).min(e);
        let hi = a.max(b).max(c).max(d).max(e);
        if !(lo >= SAFE_LO && hi <= SAFE_HI) {
            return None;
        }
        let a2 = a * a;
        let (de, bc) = (d * e, b * c);
        let p = de * (b * b + c * c - a2) + bc * (d * d + e * e - a2);
        let m = de * (b * b + c * c + a2) + bc * (d * d + e * e + a2);
        Some((p, 8.0 * FILTER_REL * m + FILTER_ABS))
    }
}

impl SignPredicate for RationalQuad<'_> {
    fn filter(&self) -> Option<Sign> {
        let (p, t) = self.filter_terms()?;
        if p > t {
            Some(Sign::Positive)
        } else if p < -t {
            Some(Sign::Negative)
        } else {
            None
        }
    }
    fn enclosure_sign(&self, prec: Precision) -> Option<Sign> {
        let ins = self
            .0
            .to_array()
            .map(|q| Interval::<Mpfr>::from_rational(q, prec));
        enclose_p(&ins).sign()
    }
    fn exact_sign(&self) -> Option<Sign> {
        Some(sign_of(&exact_p(self.0.to_array())))
    }
}

/// The Delaunay predicate on interval lengths (lengths known only as enclosures, e.g.
/// after exact Ptolemy flipping fell back past its bit-growth guard). No exact rung.
#[derive(Clone, Copy, Debug)]
pub struct EnclosureQuad<'a>(pub Quad<&'a Interval<Mpfr>>);

impl EnclosureQuad<'_> {
    /// The sign of `P` on the enclosures, evaluated once: the enclosures have a fixed
    /// precision, so no rung of the ladder can do better. The stage (or the bits tried)
    /// is the enclosures' own precision, the largest of their endpoints (proof: B62).
    pub fn decide_once(&self) -> Certified<Sign> {
        let bits = self
            .0
            .to_array()
            .iter()
            .map(|x| x.lo().0.prec().max(x.hi().0.prec()))
            .max()
            .unwrap_or(0);
        match self.enclosure_sign_fixed() {
            Some(value) => Certified::Known {
                value,
                stage: Stage::Interval { bits },
            },
            None => Certified::Undecided { bits_tried: bits },
        }
    }

    fn enclosure_sign_fixed(&self) -> Option<Sign> {
        let ins = self.0.to_array().map(Clone::clone);
        enclose_p(&ins).sign()
    }
}

/// Through the ladder every rung evaluates the same fixed-precision enclosure (the rung's
/// bit count is then reported, not the enclosures'); [`EnclosureQuad::decide_once`]
/// evaluates once and reports the enclosures' precision.
impl SignPredicate for EnclosureQuad<'_> {
    fn enclosure_sign(&self, _prec: Precision) -> Option<Sign> {
        self.enclosure_sign_fixed()
    }
}

/// Sign of `P` when only the *squared* lengths `A = a², …, E = e²` are rational (lengths
/// are square roots): `P = √(DE)·X + √(BC)·Y` with `X = B + C − A`, `Y = D + E − A`; when
/// `X` and `Y` differ in sign the sign is that of `DE·X² − BC·Y²` times the sign of `X`
/// (proof: B63). Squared lengths must be positive.
pub fn delaunay_sign_squared(sq: Quad<&Rational>) -> Sign {
    let [a, b, c, d, e] = sq.to_array();
    let x = Rational::from(b + c) - a;
    let y = Rational::from(d + e) - a;
    let (sx, sy) = (sign_of(&x), sign_of(&y));
    match (sx, sy) {
        (Sign::Zero, s) | (s, Sign::Zero) => s,
        (s, t) if s == t => s,
        _ => {
            let lhs = Rational::from(d * e) * Rational::from(&x * &x);
            let rhs = Rational::from(b * c) * Rational::from(&y * &y);
            match lhs.cmp(&rhs) {
                std::cmp::Ordering::Greater => sx,
                std::cmp::Ordering::Less => sy,
                std::cmp::Ordering::Equal => Sign::Zero,
            }
        }
    }
}

/// Lengths given as base lengths and log scale factors: `ℓ̃ = e^{(u_i+u_j)/2} ℓ`
/// (docs/catalogue.md §4). `base` holds `ℓ`, `scale` holds `(u_i, u_j)` of each of the five edges.
/// Only the MPFR rung runs, so no `f64` overflow or underflow can occur; when the four
/// vertices carry one common `u` the scaling is uniform and the exact rung decides on the
/// base lengths.
#[derive(Clone, Copy, Debug)]
pub struct ScaledQuad {
    /// Base lengths ℓ (positive, finite).
    pub base: Quad<f64>,
    /// `(u_i, u_j)` per edge (finite).
    pub scale: Quad<(f64, f64)>,
    /// Whether all four vertices have the same `u` (then `P̃ = e^{2u}·P`).
    pub uniform: bool,
}

impl SignPredicate for ScaledQuad {
    fn enclosure_sign(&self, prec: Precision) -> Option<Sign> {
        let b = self.base.to_array();
        let s = self.scale.to_array();
        let ins: [Interval<Mpfr>; 5] =
            std::array::from_fn(|i| scaled_length(b[i], s[i].0, s[i].1, prec));
        enclose_p(&ins).sign()
    }
    fn exact_sign(&self) -> Option<Sign> {
        if !self.uniform {
            return None;
        }
        let [a, b, c, d, e] = self.base.to_array().map(Rational::from_f64);
        Some(sign_of(&exact_p([&a?, &b?, &c?, &d?, &e?])))
    }
}

/// The certified Delaunay status of edge `e` for lengths `ℓ̃_ij = e^{(u_i+u_j)/2} ℓ_ij`,
/// safe for any finite `u` (no `f64` exponentials are formed).
pub fn edge_delaunay_sign_scaled(
    mesh: &Mesh,
    lengths: &[f64],
    u: &[f64],
    e: Edge,
    ladder: &Ladder,
) -> Result<EdgeDelaunay, DelaunayError> {
    let q = match interior_quad(mesh, lengths.len(), e)? {
        Ok(q) => q,
        Err(status) => return Ok(status),
    };
    let base = q.lengths(lengths).map(|&x| x);
    for (edge, l) in q.edges.to_array().into_iter().zip(base.to_array()) {
        check_length(edge, &l)?;
    }
    if u.len() != mesh.n_vertices() {
        return Err(DelaunayError::ScaleCount {
            expected: mesh.n_vertices(),
            got: u.len(),
        });
    }
    let end_pair = |edge: Edge| {
        let h = edge.halfedge();
        (u[mesh.tail(h).idx()], u[mesh.tip(h).idx()])
    };
    let corners = mesh.quad_vertices(e);
    for v in corners {
        if !u[v.idx()].is_finite() {
            return Err(DelaunayError::BadScale {
                vertex: v.0,
                value: u[v.idx()],
            });
        }
    }
    let u0 = u[corners[0].idx()];
    let uniform = corners.iter().all(|v| u[v.idx()] == u0);
    let pred = ScaledQuad {
        base,
        scale: q.edges.map(end_pair),
        uniform,
    };
    Ok(EdgeDelaunay::Interior(decide(&pred, ladder)))
}
