//! Verdicts shared by the checks, the replays and the claim answers: a [`Witness`] (one
//! element where something failed or stayed open), the three-valued [`ClaimVerdict`] and
//! its [`tally`] from witnesses. Plain data: the layers above (`theorems`, `oracle`)
//! re-export them under their former paths.

/// One element where a check failed (or could not decide), with the offending value.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Witness {
    /// The element, as `v3`, `e7`, `f2`, `h5`, or `surface`.
    pub element: String,
    /// What is wrong there, in words.
    pub detail: String,
    /// The offending quantity (an error, a sign, a residual), for display.
    pub value: f64,
}

/// The verdict on a claim.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClaimVerdict {
    /// The claim holds.
    Holds,
    /// The claim is false; a counterexample is given.
    Refuted,
    /// Neither could be established up to the precision cap.
    Undecided,
}

impl ClaimVerdict {
    /// The protocol word: `holds`, `refuted`, `undecided`.
    pub fn word(self) -> &'static str {
        match self {
            ClaimVerdict::Holds => "holds",
            ClaimVerdict::Refuted => "refuted",
            ClaimVerdict::Undecided => "undecided",
        }
    }
}

/// The verdict of a re-check from its witnesses: `refuted` when one is proven, else
/// `undecided` when one is left open, else `holds`; with the witnesses that decide it.
pub fn tally(refuted: Vec<Witness>, open: Vec<Witness>) -> (ClaimVerdict, Vec<Witness>) {
    if !refuted.is_empty() {
        (ClaimVerdict::Refuted, refuted)
    } else if !open.is_empty() {
        (ClaimVerdict::Undecided, open)
    } else {
        (ClaimVerdict::Holds, Vec::new())
    }
}
