//! Collecting per-element comparisons into a [`Verdict`].

use super::verdict::{Verdict, Witness};
use crate::predicates::tolerance::abs_at_most;
use crate::scalar::Real;

/// Accumulates the outcome of every comparison of a check, so that a failing check lists
/// all failing elements.
#[derive(Clone, Debug)]
pub struct Tally {
    certified: bool,
    bits: u32,
    max_error: f64,
    failures: Vec<Witness>,
    undecided: Vec<Witness>,
}

impl Tally {
    /// A tally for a check at `bits` of precision; `certified` says whether its decisions
    /// are rigorous (exact or on enclosures).
    pub fn new(certified: bool, bits: u32) -> Tally {
        Tally {
            certified,
            bits,
            max_error: 0.0,
            failures: Vec::new(),
            undecided: Vec::new(),
        }
    }

    /// Record a numerical comparison: the discrepancy `err` must satisfy `|err| ≤ tol`.
    /// An infinite `tol` (ill-conditioned element) or a non-finite `err` is undecided.
    pub fn within<T: Real>(&mut self, element: impl Into<String>, what: &str, err: &T, tol: f64) {
        let e = err.approx_f64();
        if !tol.is_finite() {
            self.undecided(
                element,
                format!("{what}: no error bound (ill-conditioned)"),
                e,
            );
            return;
        }
        match abs_at_most(err, tol) {
            Some(true) => self.max_error = self.max_error.max(e.abs()),
            Some(false) => self.fail(element, format!("{what}: |error| > tolerance {tol:.3e}"), e),
            None => self.undecided(element, format!("{what}: value is not finite"), e),
        }
    }

    /// Record a failing element.
    pub fn fail(&mut self, element: impl Into<String>, detail: impl Into<String>, value: f64) {
        self.failures.push(Witness {
            element: element.into(),
            detail: detail.into(),
            value,
        });
    }

    /// Record an element that could not be decided.
    pub fn undecided(&mut self, element: impl Into<String>, detail: impl Into<String>, value: f64) {
        self.undecided.push(Witness {
            element: element.into(),
            detail: detail.into(),
            value,
        });
    }

    /// Whether nothing failed or stayed undecided so far.
    pub fn is_clean(&self) -> bool {
        self.failures.is_empty() && self.undecided.is_empty()
    }

    /// `Fails` (listing every failure, then every undecided element) if anything failed,
    /// else `Undecided` if anything stayed undecided, else `Holds`.
    pub fn verdict(mut self) -> Verdict {
        if !self.failures.is_empty() {
            self.failures.append(&mut self.undecided);
            Verdict::Fails {
                certified: self.certified,
                witnesses: self.failures,
            }
        } else if !self.undecided.is_empty() {
            Verdict::Undecided {
                bits_tried: self.bits,
                witnesses: self.undecided,
            }
        } else {
            Verdict::Holds {
                certified: self.certified,
                max_error: self.max_error,
            }
        }
    }
}

/// Basic input validation shared by the checks: one length per edge and a non-empty mesh.
pub fn check_lengths<T>(mesh: &crate::mesh::Mesh, lengths: &[T]) -> Option<Verdict> {
    if lengths.len() != mesh.n_edges() {
        return Some(Verdict::NotApplicable {
            reason: format!(
                "{} lengths given for {} edges",
                lengths.len(),
                mesh.n_edges()
            ),
        });
    }
    if mesh.n_faces() == 0 {
        return Some(Verdict::NotApplicable {
            reason: "the mesh has no faces".to_string(),
        });
    }
    None
}

/// [`check_lengths`] for exact data, plus positivity: a zero or negative rational length is
/// named (`e…`) instead of dividing by it.
pub fn check_rational_lengths(
    mesh: &crate::mesh::Mesh,
    lengths: &[rug::Rational],
) -> Option<Verdict> {
    if let Some(v) = check_lengths(mesh, lengths) {
        return Some(v);
    }
    let bad: Vec<String> = lengths
        .iter()
        .enumerate()
        .filter(|(_, x)| x.cmp0().is_le())
        .map(|(k, _)| format!("e{k}"))
        .collect();
    (!bad.is_empty()).then(|| Verdict::NotApplicable {
        reason: format!("non-positive lengths at {}", bad.join(", ")),
    })
}
