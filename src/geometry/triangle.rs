//! One triangle from its three side lengths: corner angles by the half-angle form, area by
//! Kahan's ordering, cotangents.

use crate::scalar::Real;

/// The angle `A` opposite side `a` of a triangle with sides `a, b, c`, by the half-angle
/// (l'Huilier) form `tan(A/2) = √((a−b+c)(a+b−c) / ((a+b+c)(−a+b+c)))` (docs/catalogue.md §1),
/// stable near 0 and π. The differences are formed directly, never as `s − a`.
///
/// Forward error: proofs/B40. For lengths violating the triangle inequality the result is
/// NaN (f64) — callers validate lengths first (see `predicates`).
///
/// ```
/// use penner::geometry::triangle::corner_angle;
/// let a = corner_angle(&1.0_f64, &1.0, &1.0);
/// assert!((a - std::f64::consts::FRAC_PI_3).abs() < 1e-15);
/// ```
pub fn corner_angle<T: Real>(a: &T, b: &T, c: &T) -> T {
    let num = (a.clone() - b + c) * (a.clone() + b - c);
    let den = (a.clone() + b + c) * (b.clone() + c - a);
    let t = (num / den).sqrt();
    t.atan() * &a.lit(2.0)
}

/// The four Heron factors of a triangle with sides `a ≥ b ≥ c` in Kahan's parenthesisation
/// (docs/catalogue.md §1): `(a+(b+c)), (c−(a−b)), (c+(a−b)), (a+(b−c))`. Their product is
/// `16·Area²` for any order of the sides; the ordering only matters for rounding.
pub fn kahan_factors<T: Real>(a: &T, b: &T, c: &T) -> [T; 4] {
    let amb = a.clone() - b;
    [
        a.clone() + &(b.clone() + c),
        c.clone() - &amb,
        c.clone() + &amb,
        a.clone() + &(b.clone() - c),
    ]
}

/// Area of the triangle with sides `a, b, c` by Kahan's stable form
/// `¼ √((a+(b+c))(c−(a−b))(c+(a−b))(a+(b−c)))` with the sides sorted `a ≥ b ≥ c`
/// (docs/catalogue.md §1; Kahan, *Miscalculating area and angles of a needle-like triangle*).
///
/// The sort uses [`Real::approx_f64`]: it is a rounding heuristic only, since the product
/// of the four factors is the same polynomial `16·Area²` in every order. Forward error:
/// proofs/B44.
///
/// ```
/// use penner::geometry::triangle::kahan_area;
/// assert!((kahan_area(&3.0_f64, &4.0, &5.0) - 6.0).abs() < 1e-15);
/// ```
pub fn kahan_area<T: Real>(a: &T, b: &T, c: &T) -> T {
    let [x, y, z] = sorted_desc(a, b, c);
    let [f1, f2, f3, f4] = kahan_factors(x, y, z);
    (f1 * &f2 * &f3 * &f4).sqrt() * &a.lit(0.25)
}

/// Cotangent of the angle opposite side `a`: `cot A = (b²+c²−a²)/(4·Area)` (docs/catalogue.md §1),
/// with the area from [`kahan_area`]. Forward error: proofs/B44.
///
/// ```
/// use penner::geometry::triangle::cot_opposite;
/// // Right angle opposite the hypotenuse, cot = 0; opposite 3 in a 3-4-5 triangle, 4/3.
/// assert!(cot_opposite(&5.0_f64, &3.0, &4.0).abs() < 1e-15);
/// assert!((cot_opposite(&3.0_f64, &4.0, &5.0) - 4.0 / 3.0).abs() < 1e-15);
/// ```
pub fn cot_opposite<T: Real>(a: &T, b: &T, c: &T) -> T {
    let num = b.clone() * b + &(c.clone() * c) - &(a.clone() * a);
    num / &(kahan_area(a, b, c) * &a.lit(4.0))
}

/// The three sides in decreasing order of their `f64` approximations (a rounding
/// heuristic; see [`kahan_area`]).
fn sorted_desc<'a, T: Real>(a: &'a T, b: &'a T, c: &'a T) -> [&'a T; 3] {
    let mut s = [a, b, c];
    s.sort_by(|x, y| y.approx_f64().total_cmp(&x.approx_f64()));
    s
}
