//! One triangle from its three side lengths: corner angles by the half-angle form.

use crate::scalar::Real;

/// The angle `A` opposite side `a` of a triangle with sides `a, b, c`, by the half-angle
/// (l'Huilier) form `tan(A/2) = √((a−b+c)(a+b−c) / ((a+b+c)(−a+b+c)))` (MATH.md §1),
/// stable near 0 and π. The differences are formed directly, never as `s − a`.
///
/// For lengths violating the triangle inequality the result is NaN (f64) — callers
/// validate lengths first (see `predicates`).
pub fn corner_angle<T: Real>(a: &T, b: &T, c: &T) -> T {
    let num = (a.clone() - b + c) * (a.clone() + b - c);
    let den = (a.clone() + b + c) * (b.clone() + c - a);
    let t = (num / den).sqrt();
    t.atan() * &a.lit(2.0)
}
