//! The shared prologue of the checks that compare two metrics `ℓ, ℓ̃` on one mesh (T03,
//! T15, T16, T17, T19): both length lists are validated ([`check_lengths`], one length per
//! edge on a mesh with faces), then the numerical ones read the precision of the backend
//! (`ε = 16u`, proofs/B40) from the data.

use super::bounds::eps;
use super::report::{check_lengths, check_rational_lengths, lengths_out_of_range, Tally};
use super::verdict::Verdict;
use crate::mesh::Mesh;
use crate::scalar::Real;
use rug::Rational;

/// The precision a numerical check runs at, read from its data.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Numerics {
    /// `ε = 16u` for that context (proofs/B40), the unit of every tolerance of B40–B47.
    pub eps: f64,
    /// Significand bits of the context, reported by an undecided verdict.
    pub bits: u32,
}

impl Numerics {
    /// The precision of `x`'s context: `ε = 16u` (proofs/B40) and `p` bits.
    // proof: B40
    pub fn of<T: Real>(x: &T) -> Numerics {
        let ctx = x.ctx();
        Numerics {
            eps: eps::<T>(ctx),
            bits: T::precision_bits(ctx),
        }
    }

    /// An empty tally for a numerical (not certified) check at these bits.
    pub fn tally(&self) -> Tally {
        Tally::new(false, self.bits)
    }
}

/// Validate two metrics `l`, `lt` on `mesh` (each one length per edge, the mesh has faces;
/// `l` is checked first) and read their precision from `l[0]`. `Err` carries the
/// `NotApplicable` verdict the check returns as is.
pub fn two_metrics<T: Real>(mesh: &Mesh, l: &[T], lt: &[T]) -> Result<Numerics, Verdict> {
    if let Some(v) = check_lengths(mesh, l)
        .or_else(|| check_lengths(mesh, lt))
        .or_else(|| lengths_out_of_range(l))
        .or_else(|| lengths_out_of_range(lt))
    {
        return Err(v);
    }
    // A mesh with faces has edges, so `l` is not empty after `check_lengths`.
    l.first()
        .map(Numerics::of)
        .ok_or_else(|| Verdict::NotApplicable {
            reason: "no lengths given".to_string(),
        })
}

/// [`two_metrics`] for exact data: both lists pass [`check_rational_lengths`] (one positive
/// rational length per edge), `l` first; otherwise the `NotApplicable` verdict to return.
pub fn two_rational_metrics(mesh: &Mesh, l: &[Rational], lt: &[Rational]) -> Option<Verdict> {
    check_rational_lengths(mesh, l).or_else(|| check_rational_lengths(mesh, lt))
}

/// `NotApplicable` when `given` values (`what`, e.g. "corner factors") are not one per
/// element of a mesh with `expected` of them (`per`, e.g. "half-edges").
pub fn count_mismatch(given: usize, what: &str, expected: usize, per: &str) -> Option<Verdict> {
    (given != expected).then(|| Verdict::NotApplicable {
        reason: format!("{given} {what} for {expected} {per}"),
    })
}
