//! The `energy` claim (protocol v1): `E(u)` and `∇E(u) = Θ − θ(u)` of the
//! discrete-uniformization energy on the surface's triangulation
//! ([`crate::variational::energy`], docs/catalogue.md §7), decided by `Interval<Mpfr>` enclosures at
//! rising precision ([`within_all`]): an entry holds when its enclosure lies within ε of
//! the claimed value, is refuted only when it is farther than ε, and is undecided
//! otherwise.
//!
//! The enclosure of `E` evaluates Lobachevsky's function through the generic
//! [`crate::special::lobachevsky`] on `Interval<Mpfr>`, which returns its rigorous
//! enclosure (proofs/B52); every other operation is directed (B20). A face whose triangle
//! inequality the enclosures cannot decide makes its entries invalid, hence undecided.

use super::answer::{interval_lengths, summarize, Answer, START_BITS};
use super::claim::Claim;
use crate::predicates::within::within_all;
use crate::scalar::{Interval, Mpfr, Precision, Real};
use crate::variational::energy::{energy, gradient, log_lengths};
use rug::Rational;

/// Enclosures of `[E, ∂E/∂u_0, …, ∂E/∂u_{n−1}]` at precision `p`.
fn enclose(
    claim: &Claim,
    u: &[Rational],
    targets: Option<&[Rational]>,
    p: Precision,
) -> Vec<Interval<Mpfr>> {
    let mesh = &claim.surface.mesh;
    let n = mesh.n_vertices();
    let lambda = log_lengths(&interval_lengths(&claim.surface, p));
    let uu: Vec<Interval<Mpfr>> = u.iter().map(|x| Interval::from_rational(x, p)).collect();
    let two_pi = Interval::<Mpfr>::pi(p) * &Interval::from_rational(&Rational::from(2), p);
    let t: Vec<Interval<Mpfr>> = match targets {
        Some(t) => t.iter().map(|x| Interval::from_rational(x, p)).collect(),
        None => vec![two_pi; n],
    };
    let e = energy(mesh, &lambda, &uu, &t).unwrap_or_else(|| Interval::invalid(p));
    let mut out = vec![e];
    out.extend(gradient(mesh, &lambda, &uu, &t));
    out
}

/// Answer an `energy` claim (see the module doc).
pub fn energy_claim(
    claim: &Claim,
    u: &[Rational],
    targets: Option<&[Rational]>,
    energy_claimed: &Rational,
    gradient_claimed: &[Rational],
    epsilon: &Rational,
) -> Answer {
    let mut claimed = vec![energy_claimed.clone()];
    claimed.extend(gradient_claimed.iter().cloned());
    let mut f = |p: Precision| enclose(claim, u, targets, p);
    let b = within_all(&mut f, &claimed, epsilon, START_BITS, claim.max_bits);
    let name = |k: usize| {
        if k == 0 {
            "energy".to_string()
        } else {
            format!("v{} (∂E/∂u)", k - 1)
        }
    };
    summarize(claim, &b, &name, "energy or gradient entry")
}
