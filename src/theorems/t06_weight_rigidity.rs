//! T06 certified: the Hessian of the weight energy at the user's metric is positive definite
//! once one edge is fixed, so every metric with the same cotan weights is a scaling of it.
//! proof: B102
//!
//! `G(q) = Σ_e w*_e q_e − 2𝒜(q)` is convex on the open cone of metrics with strict triangles
//! and the metrics with weights `w*` are its critical points (proofs/T06). If two such
//! metrics `q*`, `q'` exist, `G` is constant on the segment between them, so `q' − q*`
//! lies in the kernel of `H = ∇²G(q*) = −2∇²𝒜(q*)`; that kernel contains `q*`, and it is
//! `span(q*)` exactly when `H` restricted to `{dq_g = 0}` (the gauge edge fixed) is positive
//! definite. This module proves the latter for the exact input lengths: the per-face
//! Hessians enclosed on MPFR intervals ([`AreaHessianKernel`]), summed with directed
//! rounding into a sparse interval matrix `H_mid ± H_rad`, scaled by powers of two
//! `D H D` (a congruence: definiteness is kept, rounding is exact up to one ulp outward),
//! and `λ_min(D H_mid D) − ‖D H_rad D‖_∞ > 0` from the verified Cholesky factorization of
//! B70 (Weyl's inequality for the radius, as B71).
//!
//! Where the binary64 factorization cannot resolve the conditioning (needles, caps), the
//! face-wise argument of B103 decides: each strict face adds a positive semidefinite term
//! whose kernel is the face's own scaling direction, so on a surface whose faces are
//! connected through edges the grounded sum is positive definite
//! ([`certify_by_faces`]).

use crate::geometry::enclosure::area_hessian::AreaHessianKernel;
use crate::mesh::Mesh;
use crate::scalar::{Interval, Mpfr, Precision, Real};
use crate::uniformization::hessian::{CholeskyCache, GroundedHessian};
use crate::uniformization::verified_cholesky::{down, lambda_min_lower_bound, up, SymmetricLower};
use faer::sparse::{SparseColMat, Triplet};

/// Extra bits of the Hessian enclosure over twice the working precision (at least 53):
/// the squared lengths of the input are then exact and the enclosure's width is far below
/// the eigenvalue margin on the meshes measured (proof: B102).
pub const HESSIAN_EXTRA_BITS: u32 = 64;

/// A proof that the grounded Hessian is positive definite (proofs/B102).
#[derive(Clone, Debug, PartialEq)]
pub struct RigidityCertificate {
    /// A rigorous lower bound on `λ_min(D H_mid D)` (B70), the diagonal `D` of powers of two
    /// scaling the Hessian's diagonal to `[1, 4)`.
    pub lambda_min: f64,
    /// An upper bound on `‖D H_rad D‖_∞`, the radius of the enclosure (`< lambda_min`).
    pub radius_norm: f64,
    /// Free edges (the dimension of the grounded matrix).
    pub free_edges: usize,
    /// MPFR bits of the per-face enclosures.
    pub bits: u32,
}

/// Why the grounded Hessian was not proved positive definite: the element (`f7`, `e3` or
/// `surface`) and the reason in words. Never a refutation of T06 (proofs/B102 "Limits").
#[derive(Clone, Debug, PartialEq)]
pub struct NotCertified {
    /// The elements concerned (every face not certified a strict triangle, or `surface`).
    pub elements: Vec<(String, String)>,
}

impl NotCertified {
    fn surface(reason: impl Into<String>) -> NotCertified {
        NotCertified {
            elements: vec![("surface".into(), reason.into())],
        }
    }
}

/// A symmetric interval matrix by its lower triangle: `(row, column, lo, hi)` with
/// `row ≥ column`, binary64 bounds, no duplicates.
#[derive(Clone, Debug, Default)]
pub struct IntervalLower {
    /// Dimension.
    pub n: usize,
    /// Entries `(row, column, lo, hi)`, `row ≥ column`, `lo ≤ hi`.
    pub entries: Vec<(usize, usize, f64, f64)>,
}

/// Certify that every symmetric matrix with entries in `a` is positive definite: with
/// `mid = ½(lo + hi)` rounded and `rad ≥ max(hi − mid, mid − lo)` rounded up,
/// `λ_min ≥ λ_min(H_mid) − ‖H_rad‖_∞` (Weyl; `‖·‖₂ ≤ ‖·‖_∞` for a symmetric matrix), the
/// first term bounded below by the verified Cholesky factorization of B70 at shifts
/// `σ = λ̂/2, λ̂/4, λ̂/16` of an inverse-iteration estimate `λ̂` (the estimate only picks
/// `σ`). `Ok((λ bound, radius norm))` when the bound exceeds the radius norm. proof: B102, B70
///
/// ```
/// use penner::theorems::t06_weight_rigidity::{certify_positive_definite, IntervalLower};
/// // [[1, ½], [½, 1]] (eigenvalues ½ and 3/2) is certified; [[1, 1], [1, 1]] is singular.
/// let pd = IntervalLower { n: 2, entries: vec![(0, 0, 1.0, 1.0), (1, 0, 0.5, 0.5), (1, 1, 1.0, 1.0)] };
/// assert!(certify_positive_definite(&pd).is_ok());
/// let singular = IntervalLower { n: 2, entries: vec![(0, 0, 1.0, 1.0), (1, 0, 1.0, 1.0), (1, 1, 1.0, 1.0)] };
/// assert!(certify_positive_definite(&singular).is_err());
/// ```
pub fn certify_positive_definite(a: &IntervalLower) -> Result<(f64, f64), String> {
    let n = a.n;
    if n == 0 {
        return Err("an empty matrix".into());
    }
    let mut rad_row = vec![0.0f64; n];
    let mut mids = Vec::with_capacity(a.entries.len());
    for &(i, j, lo, hi) in &a.entries {
        if i >= n || j > i || !(lo <= hi && lo.is_finite() && hi.is_finite()) {
            return Err(format!("entry ({i}, {j}) is not a finite enclosure"));
        }
        let mid = 0.5 * lo + 0.5 * hi;
        let rad = up(hi - mid).max(up(mid - lo)).max(0.0);
        rad_row[i] = up(rad_row[i] + rad);
        if i != j {
            rad_row[j] = up(rad_row[j] + rad);
        }
        mids.push((i, j, mid));
    }
    let radius_norm = rad_row.iter().copied().fold(0.0, f64::max);
    let mid = SymmetricLower { n, entries: mids };
    let estimate = smallest_eigenvalue_estimate(&mid)
        .ok_or("the midpoint matrix is not numerically positive definite")?;
    let bound = [0.5, 0.25, 0.0625]
        .into_iter()
        .filter_map(|frac| lambda_min_lower_bound(&mid, estimate * frac))
        .map(|b| b.lambda_min)
        .find(|&l| l > radius_norm);
    match bound {
        Some(l) => Ok((l, radius_norm)),
        None => Err(format!(
            "no verified eigenvalue bound above the enclosure's radius {radius_norm:.3e} \
             (estimated λ_min {estimate:.3e})"
        )),
    }
}

/// `λ_min` of `a` by inverse iteration on faer's sparse Cholesky factorization (30 steps
/// from a fixed start): a heuristic that only picks the verified shifts. `None` when the
/// factorization fails.
fn smallest_eigenvalue_estimate(a: &SymmetricLower) -> Option<f64> {
    let t: Vec<Triplet<usize, usize, f64>> = a
        .entries
        .iter()
        .map(|&(i, j, v)| Triplet::new(i, j, v))
        .collect();
    let matrix = SparseColMat::try_new_from_triplets(a.n, a.n, &t).ok()?;
    let f = CholeskyCache::default().factor(&GroundedHessian { matrix })?;
    let mut x: Vec<f64> = (0..a.n).map(|k| 1.0 + (k % 7) as f64 / 7.0).collect();
    let mut lambda = 0.0;
    for _ in 0..30 {
        let y = f.solve(&x);
        let ny = y.iter().map(|v| v * v).sum::<f64>().sqrt();
        let nx = x.iter().map(|v| v * v).sum::<f64>().sqrt();
        if !(ny.is_finite() && ny > 0.0) {
            return None;
        }
        lambda = nx / ny;
        x = y.iter().map(|v| v / ny).collect();
    }
    (lambda.is_finite() && lambda > 0.0).then_some(lambda)
}

/// The MPFR bits of the Hessian enclosure at working precision `bits`:
/// `2·max(bits, 53) +` [`HESSIAN_EXTRA_BITS`].
pub fn enclosure_bits(bits: u32) -> u32 {
    2 * bits.max(53) + HESSIAN_EXTRA_BITS
}

/// The grounded interval Hessian `−2∇²𝒜` over the edges other than `gauge` (index `e` for
/// `e < gauge`, `e − 1` after), scaled by powers of two `d_e` so that each diagonal
/// midpoint lies in `[1, 4)`: per face the enclosure of [`AreaHessianKernel::face`] at
/// `bits`, summed per entry with sums rounded down (lower bounds) and up (upper bounds);
/// a face whose edge appears twice adds both of its slots (the chain rule through the
/// repeated variable). Lengths are read as the exact rationals they store. proof: B102
pub fn grounded_area_hessian<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    gauge: usize,
    bits: u32,
) -> Result<IntervalLower, NotCertified> {
    let m = mesh.n_edges();
    if lengths.len() != m || gauge >= m {
        return Err(NotCertified::surface(format!(
            "{} lengths for {m} edges, gauge e{gauge}",
            lengths.len()
        )));
    }
    let p = Precision::new(u64::from(bits))
        .map_err(|_| NotCertified::surface(format!("{bits} bits is not an MPFR precision")))?;
    let mut l = Vec::with_capacity(m);
    for (e, x) in lengths.iter().enumerate() {
        let Some(q) = x.to_rational() else {
            return Err(NotCertified::surface(format!(
                "e{e}: the length has no exact value"
            )));
        };
        l.push(Interval::<Mpfr>::from_rational(&q, p));
    }
    let free = |e: usize| (e != gauge).then(|| if e < gauge { e } else { e - 1 });
    let mut kernel = AreaHessianKernel::new(bits);
    let mut triplets: Vec<(usize, usize, f64, f64)> = Vec::with_capacity(6 * mesh.n_faces());
    let mut bad = Vec::new();
    for f in mesh.faces() {
        let edges = mesh.face_halfedges(f).map(|h| h.edge().idx());
        let Some(h) = kernel.face(edges.map(|e| &l[e])) else {
            bad.push((format!("f{}", f.idx()), NOT_STRICT.to_string()));
            continue;
        };
        for a in 0..3 {
            for b in 0..3 {
                if let (Some(i), Some(j)) = (free(edges[a]), free(edges[b])) {
                    if i >= j {
                        triplets.push((i, j, h[a][b].0, h[a][b].1));
                    }
                }
            }
        }
    }
    if !bad.is_empty() {
        return Err(NotCertified { elements: bad });
    }
    triplets.sort_unstable_by_key(|&(i, j, _, _)| (i, j));
    let mut merged: Vec<(usize, usize, f64, f64)> = Vec::with_capacity(triplets.len());
    for (i, j, lo, hi) in triplets {
        match merged.last_mut() {
            Some(last) if (last.0, last.1) == (i, j) => {
                last.2 = down(last.2 + lo);
                last.3 = up(last.3 + hi);
            }
            _ => merged.push((i, j, lo, hi)),
        }
    }
    // Powers of two bringing each diagonal midpoint into [1, 4): d_i = 2^{−⌊log₂ mid / 2⌋}.
    let n = m - 1;
    let mut scale = vec![1.0f64; n];
    for &(i, j, lo, hi) in &merged {
        if i == j {
            let mid = 0.5 * lo + 0.5 * hi;
            if !(mid.is_finite() && mid > 0.0) {
                return Err(NotCertified::surface(format!(
                    "the Hessian's diagonal at e{} is not positive",
                    if i < gauge { i } else { i + 1 }
                )));
            }
            let k = mid.log2().floor() as i32;
            scale[i] = 2f64.powi(-k.div_euclid(2));
        }
    }
    let entries = merged
        .into_iter()
        .map(|(i, j, lo, hi)| {
            let s = scale[i] * scale[j];
            (i, j, down(lo * s), up(hi * s))
        })
        .collect();
    Ok(IntervalLower { n, entries })
}

/// proofs/B102: a certificate that every metric with the cotan weights of `lengths` (read
/// as exact rationals) is `t·lengths` for some `t > 0`, by positive definiteness of the
/// Hessian of the weight energy with edge `gauge` fixed ([`grounded_area_hessian`] at
/// [`enclosure_bits`] of the working precision, [`certify_positive_definite`]).
/// `Err` names the faces not certified strict triangles, or why the matrix was not
/// certified (also on a disconnected surface, where each component scales on its own).
pub fn certify_weight_rigidity<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    gauge: usize,
) -> Result<RigidityCertificate, NotCertified> {
    let Some(first) = lengths.first() else {
        return Err(NotCertified::surface("no edges"));
    };
    if mesh.n_edges() < 2 {
        return Err(NotCertified::surface("fewer than two edges"));
    }
    let bits = enclosure_bits(T::precision_bits(first.ctx()));
    let h = grounded_area_hessian(mesh, lengths, gauge, bits)?;
    let free_edges = h.n;
    let (lambda_min, radius_norm) = certify_positive_definite(&h).map_err(|r| {
        NotCertified::surface(format!(
            "the Hessian with e{gauge} fixed is not certified positive definite: {r}"
        ))
    })?;
    Ok(RigidityCertificate {
        lambda_min,
        radius_norm,
        free_edges,
        bits,
    })
}

/// proofs/B103: positive definiteness of the grounded Hessian by faces, without a
/// factorization. `−2∇²A_t` is positive semidefinite with kernel exactly `span(J_t q)`
/// (`J_t` picks the face's three squared lengths) when the face is a strict triangle
/// (reverse Cauchy–Schwarz for the Lorentzian form `M`), so `vᵀHv = 0` forces
/// `J_t v = c_t J_t q` on every face; faces sharing an edge `e` have `c_t q_e = v_e =
/// c_{t'} q_e`, so on faces connected through edges `c_t` is one constant `c`, and
/// `v_g = 0` gives `c = 0`. Certified here: every face a strict triangle on MPFR
/// enclosures of the exact lengths (at [`enclosure_bits`]), and the faces connected through
/// shared edges (union–find). `Err` lists the faces not certified strict, or says the faces
/// fall into several pieces.
pub fn certify_by_faces<T: Real>(mesh: &Mesh, lengths: &[T]) -> Result<(), NotCertified> {
    let Some(first) = lengths.first() else {
        return Err(NotCertified::surface("no edges"));
    };
    if lengths.len() != mesh.n_edges() {
        return Err(NotCertified::surface(format!(
            "{} lengths for {} edges",
            lengths.len(),
            mesh.n_edges()
        )));
    }
    let bits = enclosure_bits(T::precision_bits(first.ctx()));
    let p = Precision::new(u64::from(bits))
        .map_err(|_| NotCertified::surface(format!("{bits} bits is not an MPFR precision")))?;
    let mut l = Vec::with_capacity(lengths.len());
    for (e, x) in lengths.iter().enumerate() {
        let Some(q) = x.to_rational() else {
            return Err(NotCertified::surface(format!(
                "e{e}: the length has no exact value"
            )));
        };
        l.push(Interval::<Mpfr>::from_rational(&q, p));
    }
    let mut kernel = AreaHessianKernel::new(bits);
    let bad: Vec<(String, String)> = mesh
        .faces()
        .filter(|&f| {
            let edges = mesh.face_halfedges(f).map(|h| h.edge().idx());
            !kernel.strict(edges.map(|e| &l[e]))
        })
        .map(|f| (format!("f{}", f.idx()), NOT_STRICT.to_string()))
        .collect();
    if !bad.is_empty() {
        return Err(NotCertified { elements: bad });
    }
    // Faces joined through shared edges (union–find over the faces).
    let nf = mesh.n_faces();
    let mut parent: Vec<usize> = (0..nf).collect();
    for e in mesh.edges() {
        let h = e.halfedge();
        if let (Some(a), Some(b)) = (mesh.face(h), mesh.face(h.twin())) {
            let (ra, rb) = (root(&mut parent, a.idx()), root(&mut parent, b.idx()));
            parent[ra.max(rb)] = ra.min(rb);
        }
    }
    let pieces = (0..nf).filter(|&f| root(&mut parent, f) == f).count();
    if pieces != 1 {
        return Err(NotCertified::surface(format!(
            "the faces fall into {pieces} pieces joined by no edge: each piece scales on its own"
        )));
    }
    Ok(())
}

/// The representative of `x` in the union–find forest `p` (with path halving).
fn root(p: &mut [usize], mut x: usize) -> usize {
    while p[x] != x {
        p[x] = p[p[x]];
        x = p[x];
    }
    x
}

/// The reason given for a face not certified a strict triangle.
const NOT_STRICT: &str = "not certified a strict triangle: the metric is not proven interior \
                          to the cone where the area is smooth (B102)";

/// Matrices in which one term of B102's inequality `λ_min(H_mid) − ‖H_rad‖_∞ > 0` decides
/// the verdict (proofs/B102, **Terms**): `[[1, ½], [½, 1]]`, eigenvalues `½` and `3/2`
/// (closed form), with enclosures widened symmetrically so that the midpoint is unchanged.
#[cfg(test)]
mod terms {
    use super::*;

    /// `[[1, ½], [½, 1]]` with the diagonal entries widened by `d0`, `d1` and the
    /// off-diagonal one by `off` on both sides.
    fn widened(d0: f64, d1: f64, off: f64) -> IntervalLower {
        IntervalLower {
            n: 2,
            entries: vec![
                (0, 0, 1.0 - d0, 1.0 + d0),
                (1, 0, 0.5 - off, 0.5 + off),
                (1, 1, 1.0 - d1, 1.0 + d1),
            ],
        }
    }

    /// B102 term `− ‖H_rad‖_∞`: a radius of `0.625` in every row exceeds `λ_min = ½` of
    /// the unchanged midpoint, which alone would be certified; `0.125` is certified with
    /// a bound in `(0.125, ½]`.
    #[test]
    fn term_b102_radius_of_the_enclosure_is_subtracted() {
        let err = certify_positive_definite(&widened(0.625, 0.625, 0.0)).unwrap_err();
        assert!(err.contains("radius"), "{err}");
        let (bound, radius) = certify_positive_definite(&widened(0.125, 0.125, 0.0)).unwrap();
        assert!(
            radius >= 0.125 && bound > radius && bound <= 0.5,
            "{bound} {radius}"
        );
    }

    /// B102 term "an off-diagonal radius counts in both rows": the verified bound is at
    /// most `½·λ̂ ≈ ¼` (the largest shift of B70), so an off-diagonal radius `0.2` and a
    /// diagonal radius `0.1` in row 0 make `‖H_rad‖_∞ = 0.3 > ¼`; counted in row 1 only, the
    /// largest row would be `0.2 < ¼` and certify. Half of each is certified.
    #[test]
    fn term_b102_off_diagonal_radius_counts_in_both_rows() {
        assert!(certify_positive_definite(&widened(0.1, 0.0, 0.2)).is_err());
        assert!(certify_positive_definite(&widened(0.05, 0.0, 0.1)).is_ok());
    }

    /// B102 term `λ_min(H_mid) − ‖H_rad‖_∞ > 0`, strict: `[[1, ½, 0], [½, 1, 0], [0, 0, 1]]`
    /// with the entry `(2, 0)` widened to `[−r, r]` (its midpoint stays exactly 0, so the
    /// verified bound `λ` is the same for every `r`). `‖H_rad‖_∞` is `r` rounded up twice
    /// (the radius, then the row sum; the point entries before it add radii below
    /// half an ulp of `r`), so at `r = λ` lowered by two ulps it equals `λ`
    /// exactly: only semi-definiteness follows, refused; one ulp lower is certified.
    #[test]
    fn term_b102_radius_equal_to_the_bound_is_refused() {
        let with_radius = |r: f64| IntervalLower {
            n: 3,
            entries: vec![
                (0, 0, 1.0, 1.0),
                (1, 0, 0.5, 0.5),
                (1, 1, 1.0, 1.0),
                (2, 2, 1.0, 1.0),
                (2, 0, -r, r),
            ],
        };
        let (bound, _) = certify_positive_definite(&with_radius(0.0)).unwrap();
        let at_bound = down(down(bound));
        assert!(certify_positive_definite(&with_radius(at_bound)).is_err());
        let (again, radius) = certify_positive_definite(&with_radius(down(at_bound))).unwrap();
        assert_eq!((again, radius), (bound, down(bound)));
    }

    /// B102: a matrix that is not a finite lower-triangular enclosure is refused, never
    /// certified (an entry above the diagonal, out of range, `lo > hi`, NaN, infinite).
    #[test]
    fn term_b102_malformed_enclosures_are_refused() {
        let good = widened(0.0, 0.0, 0.0);
        assert!(certify_positive_definite(&good).is_ok());
        for (k, bad) in [
            (1, (0, 1, 0.5, 0.5)),
            (1, (2, 0, 0.5, 0.5)),
            (0, (0, 0, 1.5, 0.5)),
            (0, (0, 0, f64::NAN, 1.0)),
            (0, (0, 0, 1.0, f64::INFINITY)),
            (0, (0, 0, f64::NEG_INFINITY, 1.0)),
        ] {
            let mut m = good.clone();
            m.entries[k] = bad;
            assert!(certify_positive_definite(&m).is_err(), "{bad:?}");
        }
    }
}
