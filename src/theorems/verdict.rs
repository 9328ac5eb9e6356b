//! The outcome of a theorem check.

use crate::predicates::ladder::Ladder;

pub use crate::algorithms::verdict::Witness;

/// The verdict of a check at one precision.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "verdict", rename_all = "snake_case")]
pub enum Verdict {
    /// The property holds. `certified` is true only when every decision was exact or
    /// made on rigorous enclosures; `max_error` is the largest observed discrepancy.
    Holds {
        /// Whether the verdict is rigorous.
        certified: bool,
        /// Largest discrepancy seen (0 for exact checks).
        max_error: f64,
    },
    /// The property fails at the listed elements.
    Fails {
        /// Whether the refutation is rigorous.
        certified: bool,
        /// Every failing element.
        witnesses: Vec<Witness>,
    },
    /// Neither could be established; `bits_tried` is the highest precision used.
    Undecided {
        /// Highest MPFR precision tried.
        bits_tried: u32,
        /// Elements that stayed undecided.
        witnesses: Vec<Witness>,
    },
    /// The check does not apply to this input (e.g. boundary where the theorem needs a
    /// closed surface).
    NotApplicable {
        /// Why not.
        reason: String,
    },
}

impl Verdict {
    /// Whether the verdict is `Holds`.
    pub fn holds(&self) -> bool {
        matches!(self, Verdict::Holds { .. })
    }
    /// Whether the verdict is `Fails`.
    pub fn fails(&self) -> bool {
        matches!(self, Verdict::Fails { .. })
    }

    /// The verdict of a check whose every decision is exact or certified (an enclosure with
    /// directed rounding): any `failures` make it a certified `Fails`; otherwise any
    /// `undecided` elements make it `Undecided` at `bits_tried`; otherwise it `Holds` with
    /// no discrepancy.
    ///
    /// ```
    /// use penner::theorems::{Verdict, Witness};
    /// let w = Witness { element: "e3".into(), detail: "D < 0".into(), value: -1.0 };
    /// assert!(Verdict::certified(vec![], vec![], 0).holds());
    /// assert!(Verdict::certified(vec![w.clone()], vec![], 0).fails());
    /// assert!(matches!(Verdict::certified(vec![], vec![w], 1024), Verdict::Undecided { bits_tried: 1024, .. }));
    /// ```
    pub fn certified(failures: Vec<Witness>, undecided: Vec<Witness>, bits_tried: u32) -> Verdict {
        if !failures.is_empty() {
            Verdict::Fails {
                certified: true,
                witnesses: failures,
            }
        } else if !undecided.is_empty() {
            Verdict::Undecided {
                bits_tried,
                witnesses: undecided,
            }
        } else {
            Verdict::Holds {
                certified: true,
                max_error: 0.0,
            }
        }
    }
}

/// Settings shared by all checks.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// The ladder used for certified decisions.
    pub ladder: Ladder,
    /// Multiplier `c` on the derived error bound for numerical checks (the bound itself
    /// comes from the precision and a `proofs/` B-ID; `c` is never tuned per test).
    pub slack: f64,
    /// Where long checks report their progress over elements (no-op by default).
    pub progress: super::progress::Progress,
}

impl Default for Settings {
    fn default() -> Settings {
        Settings {
            ladder: Ladder::default(),
            slack: 1.0,
            progress: super::progress::Progress::default(),
        }
    }
}
