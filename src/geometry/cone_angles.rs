//! Cone angles θ_v: the sum of corner angles at each vertex.
//!
//! Fast path (proofs B15, B16): instead of one arctangent per corner, each corner
//! contributes the unit complex number `e^{iα} = cos α + i sin α`, formed without any
//! transcendental function from the half-angle quantities of the triangle, and the vertex
//! multiplies them: `Π e^{iα_k} = e^{iθ_v}`. One `atan2` per vertex recovers `θ_v` modulo
//! 2π; the multiple of 2π (more precisely the quarter turn `m` around which `θ_v` lies) is
//! read from an `f64` running sum of the corner angles, which is within a proven margin of
//! the exact sum (B15). The product is rotated by `i^{−m}` before the `atan2`, so the
//! principal value is taken at least 3π/4 away from the branch cut and no fallback is
//! needed.

use crate::mesh::Mesh;
use crate::scalar::Real;

/// The direction `(cos α, sin α)` of the corner angle `α` opposite side `a` in a triangle
/// with sides `a, b, c`, scaled by a positive factor `ρ` close to 1 (the factor does not
/// change the argument), and an `f64` estimate of `α`.
///
/// With `N = (a − b + c)(a + b − c)` and `D = (a + b + c)(−a + b + c)` (the half-angle
/// factors of MATH.md §1, `tan²(α/2) = N/D`): `cos α = (D − N)/(D + N)` and
/// `sin α = 2√(N D)/(D + N)`, since `(√D + i√N)² ∝ e^{iα}`. The normalization `1/(D + N)`
/// is taken in `f64` (it only rescales). proof: B16
pub fn corner_direction<T: Real>(a: &T, b: &T, c: &T) -> (T, T, f64) {
    let apb = a.clone() + b;
    let amb = a.clone() - b;
    let n = (amb + c) * &(apb.clone() - c);
    let d = (apb + c) * &(b.clone() + c - a);
    let (nf, df) = (n.approx_f64(), d.approx_f64());
    let h = 1.0 / (df + nf);
    let root = (n.clone() * &d).sqrt();
    let re = (d - &n) * &a.lit(h);
    let im = root * &a.lit(2.0 * h);
    let est = im.approx_f64().atan2(re.approx_f64());
    (re, im, est)
}

/// The angle `θ` with `e^{iθ} ∝ re + i·im` that lies within 3π/4 of `estimate`, for an
/// `estimate` within `3π/4 − ε` of the true angle (ε: the error of the computed argument):
/// `θ = atan2(i^{−m}(re + i·im)) + m·π/2` with `m = round(estimate / (π/2))`.
///
/// The rotation by `i^{−m}` is exact (swaps and sign changes), and puts the argument within
/// `π/4 + |estimate − θ|` of 0, far from the branch cut of `atan2`. proof: B15
pub fn unwrap_angle<T: Real>(re: &T, im: &T, estimate: f64) -> T {
    let m = (estimate / std::f64::consts::FRAC_PI_2).round();
    let (x, y) = match (m.rem_euclid(4.0)) as u8 {
        0 => (re.clone(), im.clone()),
        1 => (im.clone(), -re.clone()),
        2 => (-re.clone(), -im.clone()),
        _ => (-im.clone(), re.clone()),
    };
    let principal = y.atan2(&x);
    // m·π/2 = (m/2)·π, with m/2 exact in f64.
    principal + &(T::pi(re.ctx()) * &re.lit(0.5 * m))
}

/// Cone angle `θ_v = Σ α_v` over all corners at `v` (MATH.md §2), from per-edge lengths
/// `lengths[e]` (indexed by `Edge::idx`). Corners are counted with multiplicity (a face may
/// have a vertex twice); a vertex without corners gets 0.
///
/// Cost: per corner a few arithmetic operations in `T` and one `f64` arctangent; per
/// vertex one `atan2` in `T` ([`corner_direction`], [`unwrap_angle`]). The error is that of
/// a product of unit complex numbers, comparable to the per-corner sum (proof: B16); the
/// multiple of 2π is exact under the hypotheses of B15 (every corner's direction, read in
/// `f64`, within 10⁻⁶ rad of the true one, and fewer than 10⁶ corners at a vertex).
///
/// Lengths violating the triangle inequality give NaN (f64) — callers validate lengths
/// first (see `predicates`).
///
/// ```
/// use penner::geometry::cone_angles::cone_angles;
/// use penner::mesh::Mesh;
/// // A regular tetrahedron: three equilateral corners (π/3 each) at every vertex.
/// let m = Mesh::from_faces(4, &[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]).unwrap();
/// let theta = cone_angles(&m, &vec![1.0_f64; m.n_edges()]);
/// assert!(theta.iter().all(|t| (t - std::f64::consts::PI).abs() < 1e-14));
/// ```
pub fn cone_angles<T: Real>(mesh: &Mesh, lengths: &[T]) -> Vec<T> {
    assert_eq!(
        lengths.len(),
        mesh.n_edges(),
        "cone_angles: one length per edge is required"
    );
    let nv = mesh.n_vertices();
    let Some(first) = lengths.first() else {
        return Vec::new();
    };
    let mut re = vec![first.one_like(); nv];
    let mut im = vec![first.zero_like(); nv];
    let mut est = vec![0.0_f64; nv];
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        for i in 0..3 {
            // Corner opposite hs[i] is at the tail of hs[(i+2)%3].
            let a = &lengths[hs[i].edge().idx()];
            let b = &lengths[hs[(i + 1) % 3].edge().idx()];
            let c = &lengths[hs[(i + 2) % 3].edge().idx()];
            let v = mesh.tail(hs[(i + 2) % 3]).idx();
            let (wr, wi, alpha) = corner_direction(a, b, c);
            let nr = re[v].clone() * &wr - &(im[v].clone() * &wi);
            let ni = re[v].clone() * &wi + &(im[v].clone() * &wr);
            re[v] = nr;
            im[v] = ni;
            est[v] += alpha;
        }
    }
    re.iter()
        .zip(&im)
        .zip(&est)
        .map(|((r, i), &e)| unwrap_angle(r, i, e))
        .collect()
}

/// The straightforward cone angles: one [`corner_angle`](super::triangle::corner_angle)
/// (an arctangent) per corner, summed in `T`. Slower than [`cone_angles`]; kept as an
/// independent reference for tests and benchmarks.
pub fn cone_angles_per_corner<T: Real>(mesh: &Mesh, lengths: &[T]) -> Vec<T> {
    assert_eq!(
        lengths.len(),
        mesh.n_edges(),
        "cone_angles_per_corner: one length per edge is required"
    );
    let Some(first) = lengths.first() else {
        return Vec::new();
    };
    let mut theta = vec![first.zero_like(); mesh.n_vertices()];
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        for i in 0..3 {
            let a = &lengths[hs[i].edge().idx()];
            let b = &lengths[hs[(i + 1) % 3].edge().idx()];
            let c = &lengths[hs[(i + 2) % 3].edge().idx()];
            let v = mesh.tail(hs[(i + 2) % 3]).idx();
            theta[v] += &super::triangle::corner_angle(a, b, c);
        }
    }
    theta
}
