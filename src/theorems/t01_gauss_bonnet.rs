//! T01 — discrete Gauss–Bonnet with boundary (notes §1.2, Eq. 1; docs/catalogue.md §2):
//! `Σ_{i interior} K_i + Σ_{i ∈ ∂M} k_i = 2πχ(M)`.
//!
//! API:
//! - `pub fn check_gauss_bonnet<T: Real>(mesh: &Mesh, lengths: &[T], settings: &Settings) -> Verdict`
//!   (numerical, tolerance proofs/B42);
//! - `pub fn verify_gauss_bonnet<T: Real>(mesh: &Mesh, lengths: &[T], curvature: &[T], settings: &Settings) -> Verdict`
//!   (the comparison, for claimed curvatures);
//! - `pub fn check_gauss_bonnet_certified<B: IntervalBound>(mesh: &Mesh, squared_lengths: &[Rational], ctx: B::Ctx) -> Verdict`
//!   (certified: the same generic code on `Interval<B>`, e.g. `B = Mpfr`, proofs/B50);
//! - `pub fn verify_gauss_bonnet_certified<B: IntervalBound>(mesh: &Mesh, curvature: &[Interval<B>]) -> Verdict`.

use super::bounds::{corner_angle_error, eps, sum_error};
use super::inputs::count_mismatch;
use super::report::{check_lengths, lengths_out_of_range, Tally};
use super::verdict::{Settings, Verdict};
use crate::geometry::curvature::{curvature, gauss_bonnet_target};
use crate::mesh::Mesh;
use crate::scalar::{Interval, IntervalBound, Real};
use rug::Rational;

/// B42: bound on `|fl(Σ K + Σ k) − (Σ K + Σ k)|` plus the rounding of `2πχ`, for the
/// computation of [`curvature`] and a recursive sum, from the `f64` approximations of the
/// lengths: corner errors (B40) + per-vertex angle sums (B41) + `2π` and `K_i = 2π − θ_i`
/// roundings + the sum over vertices (B41) + `2πχ`.
pub fn gauss_bonnet_error_bound<T: Real>(mesh: &Mesh, lengths: &[T]) -> f64 {
    let Some(l0) = lengths.first() else {
        return 0.0;
    };
    let e = eps::<T>(l0.ctx());
    let l: Vec<f64> = lengths.iter().map(Real::approx_f64).collect();
    let mut corners: Vec<Vec<f64>> = vec![Vec::new(); mesh.n_vertices()];
    let mut corner_err = 0.0;
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        for i in 0..3 {
            let (a, b, c) = (
                l[hs[i].edge().idx()],
                l[hs[(i + 1) % 3].edge().idx()],
                l[hs[(i + 2) % 3].edge().idx()],
            );
            corner_err += corner_angle_error(a, b, c, e);
            let alpha = crate::geometry::triangle::corner_angle(&a, &b, &c);
            corners[mesh.tail(hs[(i + 2) % 3]).idx()].push(alpha);
        }
    }
    let boundary = mesh.boundary_vertices();
    let pi = std::f64::consts::PI;
    let mut k_abs = Vec::with_capacity(mesh.n_vertices());
    let mut vertex_err = 0.0;
    for (v, cs) in corners.iter().enumerate() {
        let theta: f64 = cs.iter().sum();
        let base = if boundary[v] { pi } else { 2.0 * pi };
        let k = base - theta;
        vertex_err += sum_error(cs.iter().copied(), e) + 2.0 * e * base + 2.0 * e * k.abs();
        k_abs.push(k.abs());
    }
    let chi = mesh.euler_characteristic() as f64;
    let target_err = 2.0 * e * 2.0 * pi * chi.abs();
    corner_err + vertex_err + sum_error(k_abs, e) + target_err
}

/// T01, numerical: computes `K`/`k` by [`curvature`] and compares `Σ K + Σ k` with `2πχ`
/// within `settings.slack ×` [`gauss_bonnet_error_bound`] (proofs/B42).
///
/// ```
/// use penner::mesh::Mesh;
/// use penner::theorems::{t01_gauss_bonnet::check_gauss_bonnet, Settings};
/// let tet = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]).unwrap();
/// assert!(check_gauss_bonnet(&tet, &[1.0_f64; 6], &Settings::default()).holds());
/// ```
pub fn check_gauss_bonnet<T: Real>(mesh: &Mesh, lengths: &[T], settings: &Settings) -> Verdict {
    if let Some(v) = check_lengths(mesh, lengths).or_else(|| lengths_out_of_range(lengths)) {
        return v;
    }
    let k = curvature(mesh, lengths);
    verify_gauss_bonnet(mesh, lengths, &k, settings)
}

/// The comparison of T01 for claimed per-vertex curvatures `curvature` (interior `K_i`,
/// boundary `k_i`): `|Σ curvature − 2πχ| ≤ slack × B42(lengths)`. A perturbed curvature is
/// rejected with the witness `surface`.
pub fn verify_gauss_bonnet<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    curvature: &[T],
    settings: &Settings,
) -> Verdict {
    if let Some(v) = check_lengths(mesh, lengths).or_else(|| lengths_out_of_range(lengths)) {
        return v;
    }
    if let Some(v) = curvature_count(mesh, curvature.len()) {
        return v;
    }
    let ctx = lengths[0].ctx();
    let mut total = lengths[0].zero_like();
    for k in curvature {
        total += k;
    }
    let err = total - &gauss_bonnet_target::<T>(mesh, ctx);
    let tol = settings.slack * gauss_bonnet_error_bound(mesh, lengths);
    let mut tally = Tally::new(false, T::precision_bits(ctx));
    tally.within("surface", "Σ K + Σ k − 2πχ", &err, tol);
    tally.verdict()
}

/// `NotApplicable` unless `n` curvatures are one per vertex.
fn curvature_count(mesh: &Mesh, n: usize) -> Option<Verdict> {
    count_mismatch(n, "curvatures given", mesh.n_vertices(), "vertices")
}

/// The slack exponent `c` of the certified width bound `2^(−p+c)` (proofs/B50):
/// `c = 10 + ⌈log₂(3F + 2V + 2)⌉` — at most `3F + 2V + 2` rounded terms (corners, `2π` and
/// `K_i` per vertex, the target), each enclosed within `2^8` ulps of a magnitude `< 4`.
pub fn certified_width_exponent(mesh: &Mesh) -> i32 {
    let terms = 3 * mesh.n_faces() + 2 * mesh.n_vertices() + 2;
    10 + (terms as f64).log2().ceil() as i32
}

/// T01, certified: encloses the lengths `√(ℓ²)` from exact rational squared lengths at
/// `ctx`, runs the generic [`curvature`] on `Interval<B>` and decides with
/// [`verify_gauss_bonnet_certified`]. Rational lengths `ℓ` are passed as `ℓ²`.
///
/// ```
/// use penner::mesh::Mesh;
/// use penner::scalar::{Mpfr, Precision};
/// use penner::theorems::t01_gauss_bonnet::check_gauss_bonnet_certified;
/// use penner::theorems::Verdict;
/// use rug::Rational;
/// let tet = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]).unwrap();
/// let sq: Vec<Rational> = (1..=6).map(|k| Rational::from((10 + k, 10))).collect();
/// let v = check_gauss_bonnet_certified::<Mpfr>(&tet, &sq, Precision::new(256).unwrap());
/// assert!(matches!(v, Verdict::Holds { certified: true, .. }));
/// ```
pub fn check_gauss_bonnet_certified<B: IntervalBound>(
    mesh: &Mesh,
    squared_lengths: &[Rational],
    ctx: B::Ctx,
) -> Verdict {
    if let Some(v) = super::report::check_rational_lengths(mesh, squared_lengths) {
        return v;
    }
    let l: Vec<Interval<B>> = squared_lengths
        .iter()
        .map(|q| Interval::<B>::from_rational(q, ctx).sqrt())
        .collect();
    verify_gauss_bonnet_certified(mesh, &curvature(mesh, &l))
}

/// The certified comparison of T01 on enclosures of the per-vertex curvatures: with `d` the
/// enclosure of `Σ curvature − 2πχ`,
/// - `Holds { certified: true, max_error: width }` when `0 ∈ d` (the enclosure of
///   `Σ K + Σ k` meets that of `2πχ`) and `width(d) ≤ 2^(−p+c)`,
///   `c` = [`certified_width_exponent`];
/// - `Fails { certified: true }` when `0 ∉ d` (a rigorous refutation);
/// - `Undecided` when `d` is invalid (a face violates the triangle inequality, so an angle
///   is undefined) or wider than `2^(−p+c)`.
pub fn verify_gauss_bonnet_certified<B: IntervalBound>(
    mesh: &Mesh,
    curvature: &[Interval<B>],
) -> Verdict {
    let Some(k0) = curvature.first() else {
        return Verdict::NotApplicable {
            reason: "no vertices".to_string(),
        };
    };
    if let Some(v) = curvature_count(mesh, curvature.len()) {
        return v;
    }
    let ctx = k0.ctx();
    let mut total = k0.zero_like();
    for x in curvature {
        total += x;
    }
    let d = total - &gauss_bonnet_target::<Interval<B>>(mesh, ctx);
    let bits = <Interval<B> as Real>::precision_bits(ctx);
    let width = d.width_f64();
    let c = certified_width_exponent(mesh);
    let limit = f64::from(c - bits as i32).exp2();
    let witness = |detail: String| super::verdict::Witness {
        element: "surface".to_string(),
        detail,
        value: width,
    };
    if !d.is_valid() {
        return Verdict::Undecided {
            bits_tried: bits,
            witnesses: vec![witness(
                "enclosure invalid (a face violates the triangle inequality?)".to_string(),
            )],
        };
    }
    if !d.contains_zero() {
        return Verdict::Fails {
            certified: true,
            witnesses: vec![witness(format!(
                "enclosure of Σ K + Σ k − 2πχ excludes 0 (lower end {:e})",
                d.lo().approx_f64()
            ))],
        };
    }
    if width <= limit {
        Verdict::Holds {
            certified: true,
            max_error: width,
        }
    } else {
        Verdict::Undecided {
            bits_tried: bits,
            witnesses: vec![witness(format!(
                "enclosure contains 0 but is wider than 2^(−{bits}+{c})"
            ))],
        }
    }
}
