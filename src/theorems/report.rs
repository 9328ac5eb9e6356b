//! Collecting per-element comparisons into a [`Verdict`].

use super::bounds::eps_shift;
use super::verdict::{Verdict, Witness};
use crate::predicates::tolerance::{abs_at_most_scaled, sign_beyond};
use crate::scalar::Real;
use crate::scalar::Sign;

/// Accumulates the outcome of every comparison of a check, so that a failing check lists
/// all failing elements.
#[derive(Clone, Debug)]
pub struct Tally {
    certified: bool,
    bits: u32,
    /// Tolerances passed to [`Tally::within`] are `2^shift` times the true bound
    /// ([`eps_shift`], proofs/B40 "Range"); 0 for certified tallies.
    shift: u32,
    max_error: f64,
    failures: Vec<Witness>,
    undecided: Vec<Witness>,
}

impl Tally {
    /// A tally for a check at `bits` of precision; `certified` says whether its decisions
    /// are rigorous (exact or on enclosures). A numerical tally reads its tolerances as
    /// computed with [`super::bounds::eps`], i.e. scaled by `2^s`, `s =` [`eps_shift`]`(bits)`.
    pub fn new(certified: bool, bits: u32) -> Tally {
        Tally {
            certified,
            bits,
            shift: if certified { 0 } else { eps_shift(bits) },
            max_error: 0.0,
            failures: Vec::new(),
            undecided: Vec::new(),
        }
    }

    /// Record a numerical comparison: the discrepancy `err` must satisfy `|err| ≤ tol·2⁻ˢ`,
    /// `tol` a bound computed with [`super::bounds::eps`] (scaled by `2ˢ`, see [`Tally::new`]).
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
        match abs_at_most_scaled(err, tol, self.shift) {
            Some(true) => self.max_error = self.max_error.max(e.abs()),
            Some(false) => {
                let scale = if self.shift == 0 {
                    String::new()
                } else {
                    format!("·2^-{}", self.shift)
                };
                self.fail(
                    element,
                    format!("{what}: |error| > tolerance {tol:.3e}{scale}"),
                    e,
                );
            }
            None => self.undecided(element, format!("{what}: value is not finite"), e),
        }
    }

    /// Record a numerical sign test: the exact value `x` is claimed positive, and its computed
    /// value `x̂` satisfies `|x̂ − x| ≤ tol·2⁻ˢ` (`tol` scaled as in [`Tally::within`]).
    /// `x̂ > tol·2⁻ˢ` proves it; `x̂ < −tol·2⁻ˢ` refutes it; otherwise (or with an infinite
    /// `tol`, or a non-finite `x̂`) the element is undecided.
    pub fn positive<T: Real>(&mut self, element: impl Into<String>, what: &str, x: &T, tol: f64) {
        let v = x.approx_f64();
        match sign_beyond(x, tol, self.shift) {
            Some(Sign::Positive) => {}
            Some(Sign::Negative) => {
                self.fail(element, format!("{what} < 0 beyond its error bound"), v);
            }
            Some(Sign::Zero) => {
                self.undecided(element, format!("{what}: sign within its error bound"), v);
            }
            None => self.undecided(element, format!("{what}: no error bound or not finite"), v),
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

/// `Undecided` when some length's `f64` approximation lies outside
/// [`super::bounds::LENGTH_RANGE`] (`[2⁻¹⁰⁰, 2¹⁰⁰]`), where the error bounds of B40–B48 are
/// not proved (proofs/B40, "Range"): the numerical checks do not guess there. The witnesses
/// name the offending edges (at most eight). Rescaling the metric by an exact power of two
/// (as `penner check` does) brings any metric whose lengths span less than `2²⁰⁰` inside.
///
/// ```
/// use penner::theorems::report::lengths_out_of_range;
/// use penner::theorems::Verdict;
/// assert!(lengths_out_of_range(&[1.0_f64, 2.0]).is_none());
/// assert!(matches!(lengths_out_of_range(&[1.0_f64, 1e-80]), Some(Verdict::Undecided { .. })));
/// ```
pub fn lengths_out_of_range<T: Real>(lengths: &[T]) -> Option<Verdict> {
    let bad: Vec<Witness> = lengths
        .iter()
        .enumerate()
        .filter(|(_, x)| !super::bounds::length_in_range(x.approx_f64()))
        .take(8)
        .map(|(k, x)| Witness {
            element: format!("e{k}"),
            detail: "length outside [2^-100, 2^100], where the error bounds hold (B40)".into(),
            value: x.approx_f64(),
        })
        .collect();
    let bits = lengths.first().map_or(0, |x| T::precision_bits(x.ctx()));
    (!bad.is_empty()).then_some(Verdict::Undecided {
        bits_tried: bits,
        witnesses: bad,
    })
}
