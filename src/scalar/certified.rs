//! Certified answers: a decided value with the stage that decided it, or an honest
//! `Undecided`.

use std::fmt;

/// The sign of a real number.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum Sign {
    /// Strictly below zero.
    Negative,
    /// Exactly zero.
    Zero,
    /// Strictly above zero.
    Positive,
}

impl Sign {
    /// The sign of `-x` given the sign of `x`.
    #[must_use]
    pub fn flip(self) -> Sign {
        match self {
            Sign::Negative => Sign::Positive,
            Sign::Zero => Sign::Zero,
            Sign::Positive => Sign::Negative,
        }
    }

    /// Sign of an `i32` comparison-style value.
    pub fn of_ordering(o: std::cmp::Ordering) -> Sign {
        match o {
            std::cmp::Ordering::Less => Sign::Negative,
            std::cmp::Ordering::Equal => Sign::Zero,
            std::cmp::Ordering::Greater => Sign::Positive,
        }
    }
}

impl fmt::Display for Sign {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Sign::Negative => "negative",
            Sign::Zero => "zero",
            Sign::Positive => "positive",
        })
    }
}

/// Which rung of the escalation ladder decided a predicate.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum Stage {
    /// An f64 evaluation with a proven error bound (a filter).
    Filter,
    /// A rigorous interval enclosure at this many bits.
    Interval {
        /// MPFR precision of the enclosure.
        bits: u32,
    },
    /// Exact rational arithmetic.
    Exact,
}

/// A certified answer: either decided rigorously (with the stage that decided it) or
/// `Undecided` after trying up to `bits_tried` bits — never a guess.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Certified<T> {
    /// Rigorously decided.
    Known {
        /// The decided value.
        value: T,
        /// The rung of the ladder that decided it.
        stage: Stage,
    },
    /// No rung could decide; the highest precision tried.
    Undecided {
        /// Highest MPFR precision tried (0 if only the filter ran).
        bits_tried: u32,
    },
}

impl<T: Copy> Certified<T> {
    /// The decided value, if any.
    pub fn value(&self) -> Option<T> {
        match self {
            Certified::Known { value, .. } => Some(*value),
            Certified::Undecided { .. } => None,
        }
    }
}

impl<T> Certified<T> {
    /// Map the decided value.
    pub fn map<U>(self, f: impl FnOnce(T) -> U) -> Certified<U> {
        match self {
            Certified::Known { value, stage } => Certified::Known {
                value: f(value),
                stage,
            },
            Certified::Undecided { bits_tried } => Certified::Undecided { bits_tried },
        }
    }
}
