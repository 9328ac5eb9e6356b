//! Exact predicates on rational points of ℝ³: the orientation determinant and squared
//! distances, in ℚ (no rounding, so a zero is a true zero: coplanarity is decided).

use rug::Rational;

/// `b − a`.
fn sub(a: &[Rational; 3], b: &[Rational; 3]) -> [Rational; 3] {
    [0, 1, 2].map(|i| Rational::from(&b[i] - &a[i]))
}

/// `det[b − a, c − a, d − a]`: six times the signed volume of the tetrahedron `abcd`,
/// zero exactly when the four points are coplanar.
///
/// ```
/// use penner::geometry::exact3d::orient3d;
/// use rug::Rational;
/// let p = |x: i32, y: i32, z: i32| [Rational::from(x), Rational::from(y), Rational::from(z)];
/// assert_eq!(orient3d(&p(0, 0, 0), &p(1, 0, 0), &p(0, 1, 0), &p(5, 7, 0)), 0);
/// assert_eq!(orient3d(&p(0, 0, 0), &p(1, 0, 0), &p(0, 1, 0), &p(0, 0, 1)), 1);
/// ```
pub fn orient3d(
    a: &[Rational; 3],
    b: &[Rational; 3],
    c: &[Rational; 3],
    d: &[Rational; 3],
) -> Rational {
    let (u, v, w) = (sub(a, b), sub(a, c), sub(a, d));
    let minor = |i: usize, j: usize| Rational::from(&v[i] * &w[j]) - Rational::from(&v[j] * &w[i]);
    Rational::from(&u[0] * &minor(1, 2)) - Rational::from(&u[1] * &minor(0, 2))
        + Rational::from(&u[2] * &minor(0, 1))
}

/// `|b − a|²`.
pub fn squared_distance(a: &[Rational; 3], b: &[Rational; 3]) -> Rational {
    sub(a, b)
        .iter()
        .fold(Rational::new(), |acc, x| acc + Rational::from(x * x))
}

/// `a × b`.
fn cross(a: &[Rational; 3], b: &[Rational; 3]) -> [Rational; 3] {
    let m = |i: usize, j: usize| Rational::from(&a[i] * &b[j]) - Rational::from(&a[j] * &b[i]);
    [m(1, 2), m(2, 0), m(0, 1)]
}

/// Whether `k` and `l` lie in one plane with the line `ij` and strictly on opposite sides
/// of it: `orient3d(i, j, k, l) = 0` and `((j−i)×(k−i))·((j−i)×(l−i)) < 0`. Then the two
/// triangles `ijk`, `jil` unfold in that plane exactly as they sit in ℝ³ (dihedral angle
/// π), and a segment `kl` inside their union is the straight 3-D segment.
///
/// ```
/// use penner::geometry::exact3d::opposite_in_plane;
/// use rug::Rational;
/// let p = |x: i32, y: i32, z: i32| [Rational::from(x), Rational::from(y), Rational::from(z)];
/// let (i, j) = (p(0, 0, 0), p(2, 0, 0));
/// assert!(opposite_in_plane(&i, &j, &p(1, 1, 0), &p(1, -1, 0)));
/// assert!(!opposite_in_plane(&i, &j, &p(1, 1, 0), &p(1, 2, 0))); // folded: same side
/// assert!(!opposite_in_plane(&i, &j, &p(1, 1, 0), &p(1, -1, 1))); // not coplanar
/// ```
pub fn opposite_in_plane(
    i: &[Rational; 3],
    j: &[Rational; 3],
    k: &[Rational; 3],
    l: &[Rational; 3],
) -> bool {
    if orient3d(i, j, k, l) != 0 {
        return false;
    }
    let e = sub(i, j);
    let (a, b) = (cross(&e, &sub(i, k)), cross(&e, &sub(i, l)));
    let dot = (0..3).fold(Rational::new(), |acc, t| {
        acc + Rational::from(&a[t] * &b[t])
    });
    dot < 0
}
