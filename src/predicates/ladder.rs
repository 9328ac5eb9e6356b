//! The escalation ladder: f64 filter → MPFR enclosures at rising precision → exact
//! rationals → `Undecided`.

use crate::scalar::{Certified, Precision, Sign, Stage};

/// A sign question that can be asked at each rung of the ladder.
///
/// Implementors must be *rigorous* at every rung they answer: `filter` and
/// `enclosure_sign` return `None` rather than a sign they cannot prove.
pub trait SignPredicate {
    /// An f64 evaluation with a proven error bound; `None` when the bound does not
    /// separate the value from zero (or no filter exists).
    fn filter(&self) -> Option<Sign> {
        None
    }
    /// The sign of a rigorous enclosure computed at `prec` bits, or `None` if the
    /// enclosure contains zero.
    fn enclosure_sign(&self, prec: Precision) -> Option<Sign>;
    /// The exact sign when the inputs are rational, or `None` if exact evaluation is not
    /// available for these inputs.
    fn exact_sign(&self) -> Option<Sign> {
        None
    }
}

/// How far the ladder climbs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Ladder {
    /// First MPFR precision tried.
    pub start_bits: u32,
    /// Highest MPFR precision tried (doubling from `start_bits`).
    pub max_bits: u32,
    /// Whether to fall back to exact arithmetic when available.
    pub exact: bool,
}

impl Default for Ladder {
    /// 128 → 256 → 512 → 1024 bits, then exact.
    fn default() -> Ladder {
        Ladder {
            start_bits: 128,
            max_bits: 1024,
            exact: true,
        }
    }
}

/// Decide the sign of `p` by climbing the ladder; `Undecided` names the highest
/// precision tried.
///
/// ```
/// use penner::predicates::ladder::{decide, Ladder, SignPredicate};
/// use penner::scalar::{Precision, Sign, Stage, Certified};
/// struct Five;
/// impl SignPredicate for Five {
///     fn enclosure_sign(&self, _: Precision) -> Option<Sign> { Some(Sign::Positive) }
/// }
/// assert_eq!(decide(&Five, &Ladder::default()),
///            Certified::Known { value: Sign::Positive, stage: Stage::Interval { bits: 128 } });
/// ```
#[inline]
pub fn decide<P: SignPredicate + ?Sized>(p: &P, ladder: &Ladder) -> Certified<Sign> {
    if let Some(s) = p.filter() {
        return Certified::Known {
            value: s,
            stage: Stage::Filter,
        };
    }
    climb(p, ladder)
}

/// The rungs after the filter, kept out of line so that the filter inlines into loops.
#[cold]
#[inline(never)]
fn climb<P: SignPredicate + ?Sized>(p: &P, ladder: &Ladder) -> Certified<Sign> {
    let mut bits = ladder.start_bits;
    let mut tried = 0;
    while bits <= ladder.max_bits {
        let Ok(prec) = Precision::new(u64::from(bits)) else {
            break;
        };
        tried = bits;
        if let Some(s) = p.enclosure_sign(prec) {
            return Certified::Known {
                value: s,
                stage: Stage::Interval { bits },
            };
        }
        bits = bits.saturating_mul(2);
    }
    if ladder.exact {
        if let Some(s) = p.exact_sign() {
            return Certified::Known {
                value: s,
                stage: Stage::Exact,
            };
        }
    }
    Certified::Undecided { bits_tried: tried }
}
