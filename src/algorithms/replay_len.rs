//! The lengths of a replay ([`super::replay`], proof: B80) and their arithmetic: exact,
//! the square root of an exact rational, or an outward-rounded MPFR enclosure (B62); the
//! certified sign of the Delaunay polynomial on them, the new length of a flip and of a tie
//! flip (B82). The leaf shared by [`super::replay`], [`super::replay_dag`] and
//! [`super::replay_input`].

use super::flip_to_delaunay::rational_bits;
use super::flips::{euclidean_length_enclosure, ptolemy_length_enclosure, ptolemy_length_exact};
use crate::io::Metric;
use crate::mesh::Edge;
use crate::predicates::delaunay::{delaunay_sign_squared, enclose_p, exact_p, Quad};
use crate::predicates::directed::valid;
use crate::scalar::{Interval, Mpfr, Precision, Real, Sign};
use rug::Rational;

/// Bit size (numerator + denominator) past which exact Ptolemy lengths are replaced by
/// enclosures in a replay.
pub const EXACT_GUARD_BITS: u64 = 4096;

/// The outward-rounded MPFR enclosure of the replay (proof: B62).
pub type Enclosure = Interval<Mpfr>;

/// The tightest enclosure of `q` at `bits` bits; `None` for a precision MPFR refuses.
pub fn from_q(q: &Rational, bits: u32) -> Option<Enclosure> {
    let p = Precision::new(u64::from(bits)).ok()?;
    Some(Interval::from_rational(q, p))
}

/// Whether the enclosure is certified positive.
pub fn positive(x: &Enclosure) -> bool {
    x.sign() == Some(Sign::Positive)
}

/// A length in a replay: exact, the square root of an exact rational, or an enclosure.
#[derive(Clone, Debug)]
pub enum Len {
    /// An exact rational length.
    Exact(Rational),
    /// The square root of this exact positive rational.
    Root(Rational),
    /// An outward-rounded enclosure of the length.
    Enclosed(Enclosure),
}

impl Len {
    /// The lengths of `metric`, exact.
    pub fn of_metric(metric: &Metric) -> Vec<Len> {
        match metric {
            Metric::Lengths(l) => l.iter().cloned().map(Len::Exact).collect(),
            Metric::SquaredLengths(s) => s.iter().cloned().map(Len::Root).collect(),
        }
    }
    /// An enclosure at `bits` bits (the stored one for [`Len::Enclosed`]).
    pub fn enclose(&self, bits: u32) -> Option<Enclosure> {
        match self {
            Len::Exact(q) => from_q(q, bits),
            Len::Root(s) => valid(from_q(s, bits)?.sqrt()),
            Len::Enclosed(e) => Some(e.clone()),
        }
    }
    /// The exact length, if rational.
    pub fn exact(&self) -> Option<&Rational> {
        match self {
            Len::Exact(q) => Some(q),
            _ => None,
        }
    }
    /// The exact squared length, if rational.
    pub fn exact_square(&self) -> Option<Rational> {
        match self {
            Len::Exact(q) => Some(Rational::from(q * q)),
            Len::Root(s) => Some(s.clone()),
            Len::Enclosed(_) => None,
        }
    }
}

/// The certified sign of the Delaunay polynomial `D` of the quadrilateral `q` (proof: B80):
/// from the outward-rounded enclosure of `D` when it excludes 0 (proof: B62), otherwise
/// exact when the five lengths (or their squares) are rational (proof: B63, so ties are
/// certified), otherwise `None`.
pub fn sign(lens: &[Len], q: Quad<Edge>, bits: u32) -> Option<Sign> {
    sign_after_f64(lens, None, q, bits)
}

/// An outward `f64` enclosure of a replay length (B21; an MPFR enclosure is widened to the
/// binary64 numbers below and above its ends): `None` for a length `f64` cannot hold.
pub fn f64_enclosure(len: &Len) -> Option<Interval<f64>> {
    let x = match len {
        Len::Exact(q) => Interval::<f64>::from_rational(q, ()),
        Len::Root(s) => valid(Interval::<f64>::from_rational(s, ())).map(|x| x.sqrt())?,
        Len::Enclosed(e) => {
            // Outward to binary64 (directed roundings of each end point).
            let lo = e.lo().0.to_f64_round(rug::float::Round::Down);
            let hi = e.hi().0.to_f64_round(rug::float::Round::Up);
            Interval::<f64>::new(lo, hi)
        }
    };
    valid(x).filter(|x| x.lo().is_finite() && x.hi().is_finite())
}

/// [`sign`], first from `f64` enclosures `fast` of the lengths when given (one per edge,
/// see [`f64_enclosure`]): a sign of `D` certified there is final (B21, B62); otherwise the
/// MPFR and exact rungs of [`sign`] decide.
pub fn sign_after_f64(
    lens: &[Len],
    fast: Option<&[Option<Interval<f64>>]>,
    q: Quad<Edge>,
    bits: u32,
) -> Option<Sign> {
    if let Some(fast) = fast {
        let f = q.map(|e| fast[e.idx()].as_ref()).to_array();
        if let [Some(a), Some(b), Some(c), Some(d), Some(e)] = f {
            let p = enclose_p(&[a.clone(), b.clone(), c.clone(), d.clone(), e.clone()]);
            if let Some(s @ (Sign::Positive | Sign::Negative)) = p.sign() {
                return Some(s);
            }
        }
    }
    sign_of_lens(q.map(|e| &lens[e.idx()]).to_array(), bits)
}

/// The MPFR and exact rungs of [`sign`] on the five lengths `ℓ_ij, ℓ_jk, ℓ_ki, ℓ_il, ℓ_lj`.
pub(super) fn sign_of_lens(arr: [&Len; 5], bits: u32) -> Option<Sign> {
    // The enclosure first: it decides every sign away from zero, and costs less than exact
    // arithmetic on long rationals; only a straddling enclosure goes to the exact rules.
    let [a, b, c, d, e] = arr.map(|x| x.enclose(bits));
    let enclosed = match (a, b, c, d, e) {
        (Some(a), Some(b), Some(c), Some(d), Some(e)) => enclose_p(&[a, b, c, d, e]).sign(),
        _ => None,
    };
    if let Some(s @ (Sign::Positive | Sign::Negative)) = enclosed {
        return Some(s);
    }
    if let [Some(a), Some(b), Some(c), Some(d), Some(e)] = arr.map(Len::exact) {
        return Some(Sign::of_ordering(exact_p([a, b, c, d, e]).cmp0()));
    }
    if let [Some(a), Some(b), Some(c), Some(d), Some(e)] = arr.map(Len::exact_square) {
        let sq = Quad {
            ij: &a,
            jk: &b,
            ki: &c,
            il: &d,
            lj: &e,
        };
        return Some(delaunay_sign_squared(sq));
    }
    enclosed
}

/// The length of the new diagonal after flipping the quadrilateral with lengths `quad`:
/// exact for Ptolemy flips of exact lengths (below the bit guard), otherwise an
/// outward-rounded enclosure (proof: B80); `None` when it cannot be enclosed as positive.
pub fn new_length(quad: Quad<&Len>, ptolemy: bool, bits: u32) -> Option<Len> {
    if ptolemy {
        if let [Some(a), Some(b), Some(c), Some(d), Some(e)] = quad.to_array().map(Len::exact) {
            let l = ptolemy_length_exact(Quad {
                ij: a,
                jk: b,
                ki: c,
                il: d,
                lj: e,
            });
            return if rational_bits(&l) > EXACT_GUARD_BITS {
                from_q(&l, bits).map(Len::Enclosed)
            } else {
                Some(Len::Exact(l))
            };
        }
    }
    let [a, b, c, d, e] = quad.to_array().map(|x| x.enclose(bits));
    let (a, b, c, d, e) = (a?, b?, c?, d?, e?);
    let q = Quad {
        ij: &a,
        jk: &b,
        ki: &c,
        il: &d,
        lj: &e,
    };
    if ptolemy {
        ptolemy_length_enclosure(q)
    } else {
        euclidean_length_enclosure(q)
    }
    .filter(positive)
    .map(Len::Enclosed)
}

/// The exact square root of a non-negative rational, if it is a rational square.
fn rational_sqrt(q: &Rational) -> Option<Rational> {
    let (n, d) = (q.numer(), q.denom());
    if n.cmp0() == std::cmp::Ordering::Less || !n.is_perfect_square() || !d.is_perfect_square() {
        return None;
    }
    Some(Rational::from((n.clone().sqrt(), d.clone().sqrt())))
}

/// The new diagonal of a tie flip (proof: B82): a cyclic quadrilateral's diagonals satisfy
/// Ptolemy's theorem, so the length is exact when the five lengths are rational, or their
/// squares are and the product under the root of
/// `ℓ_kl² = (s_ki s_lj + s_il s_jk + 2√(s_ki s_lj s_il s_jk))/s_ij` is a rational square;
/// otherwise the enclosure of the flip kind.
pub fn tie_length(quad: Quad<&Len>, ptolemy: bool, bits: u32) -> Option<Len> {
    if quad.to_array().iter().all(|l| l.exact().is_some()) {
        return new_length(quad, true, bits);
    }
    if let [Some(ij), Some(jk), Some(ki), Some(il), Some(lj)] =
        quad.to_array().map(Len::exact_square)
    {
        let (p, r) = (Rational::from(&ki * &lj), Rational::from(&il * &jk));
        if let Some(root) = rational_sqrt(&Rational::from(&p * &r)) {
            let s = (p + r + root * 2u32) / ij;
            if rational_bits(&s) <= EXACT_GUARD_BITS {
                return Some(Len::Root(s));
            }
        }
    }
    new_length(quad, ptolemy, bits)
}
