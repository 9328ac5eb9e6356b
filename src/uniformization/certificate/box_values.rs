//! What step 1 of the certificate hands to steps 2–3 (B71): the lengths of `T` and its
//! cotan Laplacian over the box, held in the form step 1 computed them in: the binary64
//! bounds of the binary64 rung (B36) or MPFR enclosures (the MPFR path, B35). proof: B36
//!
//! The binary64 rung's bounds are read as MPFR enclosures one value at a time, each bound
//! taken exactly at the certificate's precision (`prec ≥ 53` bits): the same enclosures as
//! when they were stored converted, at a sixteenth of the memory (two binary64 numbers
//! against two MPFR numbers with their limbs).

use super::box_f64::F;
use super::certificate_outcome::I;
use crate::geometry::laplacian::SparseMatrix;
use crate::scalar::{Mpfr, Precision, Real};
use std::borrow::Cow;

/// The binary64 interval `x` as an MPFR interval at `prec` (exact: every binary64 number is
/// an MPFR number of at least 53 bits).
fn exactly(x: &F, prec: Precision) -> I {
    I::new(Mpfr::from_f64(*x.lo(), prec), Mpfr::from_f64(*x.hi(), prec))
}

/// The lengths of `T` over the box, one enclosure per edge.
pub(crate) enum BoxLengths {
    /// Binary64 bounds (the binary64 rung), read at the MPFR precision `prec`.
    Binary64 {
        /// The bounds, one interval per edge.
        lengths: Vec<F>,
        /// The certificate's precision.
        prec: Precision,
    },
    /// MPFR enclosures (the MPFR path).
    Mpfr(Vec<I>),
}

impl BoxLengths {
    /// The binary64 approximation ([`Real::approx_f64`]) of every length: the same numbers
    /// for the binary64 bounds as for their exact MPFR conversion.
    pub(crate) fn approx_f64(&self) -> Vec<f64> {
        match self {
            BoxLengths::Binary64 { lengths, .. } => lengths.iter().map(Real::approx_f64).collect(),
            BoxLengths::Mpfr(lengths) => lengths.iter().map(Real::approx_f64).collect(),
        }
    }

    /// The lengths as MPFR enclosures (binary64 bounds converted exactly).
    pub(crate) fn mpfr(&self) -> Cow<'_, [I]> {
        match self {
            BoxLengths::Binary64 { lengths, prec } => {
                Cow::Owned(lengths.iter().map(|x| exactly(x, *prec)).collect())
            }
            BoxLengths::Mpfr(lengths) => Cow::Borrowed(lengths),
        }
    }
}

/// The cotan Laplacian `L` of `T` over the box.
pub(crate) enum BoxLaplacian {
    /// Binary64 bounds (the binary64 rung), read at the MPFR precision `prec`.
    Binary64 {
        /// The bounds.
        matrix: SparseMatrix<F>,
        /// The certificate's precision.
        prec: Precision,
    },
    /// MPFR enclosures (the MPFR path).
    Mpfr(SparseMatrix<I>),
}

impl BoxLaplacian {
    /// All stored entries as `(row, column, value)` in the order of
    /// [`SparseMatrix::entries`], the values as MPFR enclosures (binary64 bounds converted
    /// exactly, one entry at a time).
    pub(crate) fn entries(&self) -> impl Iterator<Item = (usize, usize, Cow<'_, I>)> {
        let (binary64, mpfr) = match self {
            BoxLaplacian::Binary64 { matrix, prec } => (Some((matrix, *prec)), None),
            BoxLaplacian::Mpfr(matrix) => (None, Some(matrix)),
        };
        let converted = binary64.into_iter().flat_map(|(m, prec)| {
            m.entries()
                .map(move |(i, j, w)| (i, j, Cow::Owned(exactly(w, prec))))
        });
        let borrowed = mpfr
            .into_iter()
            .flat_map(|m| m.entries().map(|(i, j, w)| (i, j, Cow::Borrowed(w))));
        converted.chain(borrowed)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::laplacian::cotan_laplacian;
    use crate::mesh::builders;

    /// Both forms read the same: the binary64 Laplacian and lengths of the tetrahedron,
    /// stored as binary64 bounds or converted to MPFR up front, give the same entries,
    /// MPFR enclosures and approximations.
    #[test]
    fn both_forms_read_the_same() {
        let mesh = builders::tetrahedron().mesh;
        let prec = Precision::new(256).unwrap();
        let lengths: Vec<F> = (0..mesh.n_edges())
            .map(|e| F::new(1.0 + e as f64 / 8.0, 1.0 + e as f64 / 7.0))
            .collect();
        let lap = cotan_laplacian(&mesh, &lengths);
        let converted: Vec<I> = lengths.iter().map(|x| exactly(x, prec)).collect();
        let as_f64 = BoxLengths::Binary64 {
            lengths: lengths.clone(),
            prec,
        };
        let as_mpfr = BoxLengths::Mpfr(converted);
        let floats = |x: &I| (x.lo().as_float().clone(), x.hi().as_float().clone());
        assert_eq!(as_f64.approx_f64(), as_mpfr.approx_f64());
        let (a, b) = (as_f64.mpfr(), as_mpfr.mpfr());
        assert!(a.iter().map(floats).eq(b.iter().map(floats)));
        let a = BoxLaplacian::Binary64 {
            matrix: lap.clone(),
            prec,
        };
        let b = BoxLaplacian::Mpfr(lap.map_values(|w| exactly(w, prec)));
        let entry = |(i, j, w): (usize, usize, Cow<'_, I>)| (i, j, floats(&w));
        let ea: Vec<_> = a.entries().map(entry).collect();
        let eb: Vec<_> = b.entries().map(entry).collect();
        assert_eq!(ea.len(), lap.entries().count());
        assert_eq!(ea, eb);
        // The conversion is exact: the bounds come back as the same binary64 numbers.
        for ((_, _, (lo, hi)), (_, _, x)) in ea.iter().zip(lap.entries()) {
            assert_eq!((lo.to_f64(), hi.to_f64()), (*x.lo(), *x.hi()));
        }
    }
}
