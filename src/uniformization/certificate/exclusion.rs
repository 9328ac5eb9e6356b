//! The refutation side of the certificate: a proof that *no* exact solution of
//! `θ(u') = Θ` lies in the box `B = {u' : |u'_i − u_i| ≤ r}` (grounded vertices fixed) of a
//! [`CertificateData`]. proof: B73
//!
//! After step 1 of B71 (the final triangulation `T` is Delaunay and every face a strict
//! triangle for every `u' ∈ B`, so the angle sums at `u'` are those of `T`), the angle sum
//! `θ_v` of every vertex is enclosed over the whole box from the box lengths by the kernel
//! of the certificate's residual, one enclosed argument per vertex (B33, per-corner
//! fallback where its quarter count is not certified); across cell boundaries (B35) each
//! edge not certified Delaunay on the box contributes the hull of both configurations'
//! angles. A vertex whose target `Θ_v` (enclosed) is disjoint from that enclosure has
//! `θ_v(u') ≠ Θ_v` for every `u' ∈ B`: the box holds no solution.

use super::certificate::{prepare, Carried, CertificateData, CertificateError, Rung, I};
use crate::geometry::enclosure::angle_sums::enclose_cone_angles;
use crate::scalar::{Interval, Mpfr, Real};

/// A vertex whose target lies outside the enclosure of its angle sum over the box.
#[derive(Clone, Debug, PartialEq)]
pub struct ExcludedVertex {
    /// The vertex.
    pub vertex: usize,
    /// `Θ_v` (midpoint, for display).
    pub target: f64,
    /// `[θ_v(B)]`: lower and upper end of the enclosure (rounded outwards for display).
    pub angle_sum: (f64, f64),
}

/// Every vertex whose target `Θ_v` is certified outside `θ_v(B)` (B73, `θ_v(B)` enclosed by
/// B33's kernel on the box lengths); an empty list when
/// none is (no conclusion). `Ok(Err(reason))` when the box is not certified inside one
/// Penner cell (then nothing is concluded). `base0` as in
/// [`super::certificate::check_certificate_on`].
pub fn excluded_vertices(
    data: &CertificateData,
    base0: Option<&[Interval<Mpfr>]>,
    bits: u32,
) -> Result<Result<Vec<ExcludedVertex>, String>, CertificateError> {
    let carried = Carried::of(data, base0, bits)?;
    let p = match prepare(data, &carried, Rung::Mpfr) {
        Ok(p) => p,
        Err(reason) => return Ok(Err(reason)),
    };
    // One enclosed argument per vertex over the box lengths (B33), as for the residual.
    let box_lengths = p.box_lengths.mpfr();
    let mut theta = enclose_cone_angles(p.mesh, &box_lengths).theta;
    if let Some(b) = &p.boundary {
        // Across cell boundaries the angle sums are those of the Delaunay `T_S` (B35).
        if let Err(reason) = b.correct_angle_sums(p.mesh, &p.boxed, &box_lengths, &mut theta) {
            return Ok(Err(reason));
        }
    }
    let pi = I::pi(p.prec);
    let mut out = Vec::new();
    for (v, th) in theta.iter().enumerate() {
        if !th.is_valid() {
            continue;
        }
        let target = I::from_rational(&data.targets.over_pi()[v], p.prec) * &pi;
        if disjoint(&target, th) {
            out.push(ExcludedVertex {
                vertex: v,
                target: target.approx_f64(),
                angle_sum: (th.lo().approx_f64(), th.hi().approx_f64()),
            });
        }
    }
    Ok(Ok(out))
}

/// Whether two enclosures are certified disjoint: one ends strictly below the other's
/// start. Touching enclosures (a common end point) may hold a common value. proof: B73
fn disjoint(a: &I, b: &I) -> bool {
    a.hi().as_float() < b.lo().as_float() || a.lo().as_float() > b.hi().as_float()
}

#[cfg(test)]
mod terms {
    use super::*;
    use crate::scalar::Precision;

    fn iv(lo: f64, hi: f64) -> I {
        let p = Precision::new(64).expect("precision");
        I::new(Mpfr::from_f64(lo, p), Mpfr::from_f64(hi, p))
    }

    /// B73 term "disjoint, strictly": enclosures that touch at one end may share that
    /// value, so a target there is not excluded; separated ones are, on either side.
    #[test]
    fn term_b73_touching_enclosures_do_not_exclude() {
        assert!(!disjoint(&iv(1.0, 2.0), &iv(2.0, 3.0)));
        assert!(!disjoint(&iv(2.0, 3.0), &iv(1.0, 2.0)));
        assert!(disjoint(&iv(1.0, 1.5), &iv(2.0, 3.0)));
        assert!(disjoint(&iv(2.5, 3.0), &iv(1.0, 2.0)));
        assert!(!disjoint(&iv(1.0, 3.0), &iv(2.0, 2.5)));
    }
}
