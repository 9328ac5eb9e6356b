//! The sign of the Delaunay polynomial `P` (see [`super::delaunay`]) on positive `f64`
//! enclosures of the five lengths, with every operation rounded to nearest and then moved
//! one ulp outward (proof: B83) — no error-term products, so no fused multiply-add: the
//! cheap first rung of the replay on the input metric ([`crate::algorithms::replay`]).
//!
//! ```
//! use penner::predicates::delaunay_widened::{length_from_square, sign_p};
//! use penner::scalar::Sign;
//! // A unit square split along its diagonal, the diagonal's square 2 rounded to nearest:
//! // D = 0 exactly, and no enclosure of √2 decides it.
//! let one = length_from_square(1.0).unwrap();
//! let diag = length_from_square(2.0).unwrap();
//! assert_eq!(sign_p([diag, one, one, one, one]), None);
//! // A longer diagonal makes the edge certified non-Delaunay.
//! let long = length_from_square(2.5).unwrap();
//! assert_eq!(sign_p([long, one, one, one, one]), Some(Sign::Negative));
//! ```

use super::delaunay::in_filter_range;
use crate::scalar::interval::{next_down_f64 as down, next_up_f64 as up};
use crate::scalar::Sign;

/// An enclosure `[lo, hi]` of a positive length, `lo ≤ hi`.
pub type Bounds = [f64; 2];

/// The enclosure of `ℓ = √s` for an exact square `s > 0` whose nearest binary64 value is
/// `nearest` (ties either way): `s` lies strictly between the neighbours of `nearest`, and
/// √ of those, rounded to nearest and moved one ulp outward, encloses `ℓ` (proof: B83).
/// `None` outside `[2⁻²⁰⁰, 2²⁰⁰)` (the range of [`sign_p`]).
pub fn length_from_square(nearest: f64) -> Option<Bounds> {
    if !in_filter_range(nearest) {
        return None;
    }
    // proof: B83 — s ∈ (down(x), up(x)) for x the nearest binary64 value of s.
    let b = [down(down(nearest).sqrt()), up(up(nearest).sqrt())];
    (in_filter_range(b[0]) && in_filter_range(b[1])).then_some(b)
}

/// The widened enclosure of an `f64` interval (e.g. a wider one from MPFR): itself when
/// both ends are in range.
pub fn in_range(b: Bounds) -> Option<Bounds> {
    (in_filter_range(b[0]) && in_filter_range(b[1]) && b[0] <= b[1]).then_some(b)
}

/// `lo·lo'` rounded down and `hi·hi'` rounded up, for positive enclosures.
#[inline]
fn mul_pos(x: Bounds, y: Bounds) -> Bounds {
    [down(x[0] * y[0]), up(x[1] * y[1])]
}

/// `x + y` outward.
#[inline]
fn add(x: Bounds, y: Bounds) -> Bounds {
    [down(x[0] + y[0]), up(x[1] + y[1])]
}

/// `x − y` outward.
#[inline]
fn sub(x: Bounds, y: Bounds) -> Bounds {
    [down(x[0] - y[1]), up(x[1] - y[0])]
}

/// `p·x` outward for a positive `p` and any `x`: the ends are `p_hi·x_lo` or `p_lo·x_lo`
/// below (as `x_lo` is negative or not), `p_hi·x_hi` or `p_lo·x_hi` above.
#[inline]
fn mul_by_pos(p: Bounds, x: Bounds) -> Bounds {
    let lo = if x[0] < 0.0 { p[1] * x[0] } else { p[0] * x[0] };
    let hi = if x[1] < 0.0 { p[0] * x[1] } else { p[1] * x[1] };
    [down(lo), up(hi)]
}

/// The certified sign of `P = d·e·(b² + c² − a²) + b·c·(d² + e² − a²)` for lengths in the
/// enclosures `[a, b, c, d, e]` (`ℓ_ij, ℓ_jk, ℓ_ki, ℓ_il, ℓ_lj`): `Some` only when the
/// widened evaluation excludes zero (proof: B83); `None` when it does not or when a bound
/// lies outside `[2⁻²⁰⁰, 2²⁰⁰)`.
pub fn sign_p(q: [Bounds; 5]) -> Option<Sign> {
    if !q.iter().all(|b| in_range(*b).is_some()) {
        return None;
    }
    let [a, b, c, d, e] = q;
    let a2 = mul_pos(a, a);
    let x = sub(add(mul_pos(b, b), mul_pos(c, c)), a2);
    let y = sub(add(mul_pos(d, d), mul_pos(e, e)), a2);
    let p = add(mul_by_pos(mul_pos(d, e), x), mul_by_pos(mul_pos(b, c), y));
    if p[0] > 0.0 {
        Some(Sign::Positive)
    } else if p[1] < 0.0 {
        Some(Sign::Negative)
    } else {
        None
    }
}
