//! A surface from vertex positions kept as compact exact coordinates ([`Coordinate`]):
//! what the OBJ and OFF readers build. Its metric is the squared distances of the
//! positions, computed per edge when asked — in integers where they fit, exactly in ℚ
//! otherwise — so a mesh of 10⁶ faces needs no big rational per coordinate or per edge.
//! [`DecimalSurface::into_surface`] gives the exact [`Surface`] (the same value the
//! rational path builds); [`DecimalSurface::lengths`] the lengths in a backend, equal to
//! [`Surface::lengths`] of that surface bit for bit.

use super::decimal::{
    decimal_to_f64, decimal_to_rational, distinct_points, non_degenerate, squared_distance,
    squared_distance_wide, wide_to_f64, Coordinate,
};
use super::surface::{heron16, Metric, MetricError, Surface};
use crate::mesh::{Edge, Face, Mesh, Vertex};
use crate::scalar::Real;
use rug::Rational;
use std::cmp::Ordering;

/// A triangulated surface with exact vertex positions in ℝ³ and the induced metric
/// `ℓ_ij² = |p_j − p_i|²`, validated like [`Surface::validate`].
#[derive(Clone, Debug, PartialEq)]
pub struct DecimalSurface {
    /// The triangulation.
    pub mesh: Mesh,
    /// One exact position per vertex.
    pub positions: Vec<[Coordinate; 3]>,
    /// A name for reports (empty when the file has none).
    pub name: String,
}

impl DecimalSurface {
    /// A validated surface: every edge has positive length and every face is a
    /// non-degenerate triangle — the checks of [`Surface::validate`] on the squared
    /// lengths (for positions, Heron's `16·area² = 4|(b − a) × (c − a)|² > 0`), with the
    /// same errors in the same order.
    pub fn new(
        name: impl Into<String>,
        mesh: Mesh,
        positions: Vec<[Coordinate; 3]>,
    ) -> Result<DecimalSurface, MetricError> {
        let s = DecimalSurface {
            mesh,
            positions,
            name: name.into(),
        };
        if s.positions.len() != s.mesh.n_vertices() {
            return Err(MetricError::PositionCount {
                got: s.positions.len(),
                vertices: s.mesh.n_vertices(),
            });
        }
        for e in s.mesh.edges() {
            let zero = if let Some((n, _)) = s.squared_decimal(e) {
                n == 0
            } else {
                let (a, b) = s.ends(e);
                match distinct_points(a, b) {
                    Some(distinct) => !distinct,
                    None => s.squared_length(e).cmp0() != Ordering::Greater,
                }
            };
            if zero {
                return Err(MetricError::NonPositive {
                    edge: e.0,
                    value: s.squared_length(e).to_string(),
                });
            }
        }
        for f in s.mesh.faces() {
            let [a, b, c] = s.mesh.face_vertices(f).map(|v| &s.positions[v.idx()]);
            if non_degenerate(a, b, c) != Some(true) {
                s.check_face_exactly(f)?;
            }
        }
        Ok(s)
    }

    /// Heron's test of face `f` in ℚ on its exact squared lengths (side order), as in
    /// [`super::surface::validate_metric`].
    fn check_face_exactly(&self, f: Face) -> Result<(), MetricError> {
        let [a, b, c] = self
            .mesh
            .face_halfedges(f)
            .map(|h| self.squared_length(h.edge()));
        let sign = heron16(&a, &b, &c).cmp0();
        if sign == Ordering::Greater {
            return Ok(());
        }
        Err(MetricError::TriangleInequality {
            face: f.0,
            sides: [a, b, c].map(|x| x.to_string()),
            degenerate: sign == Ordering::Equal,
        })
    }

    /// The ends of edge `e`.
    fn ends(&self, e: Edge) -> (&[Coordinate; 3], &[Coordinate; 3]) {
        let h = e.halfedge();
        (
            &self.positions[self.mesh.tail(h).idx()],
            &self.positions[self.mesh.tip(h).idx()],
        )
    }

    /// `ℓ_e² = N·10^(2E)` as `(N, E)` when it is computed in integers.
    fn squared_decimal(&self, e: Edge) -> Option<(u128, i32)> {
        let (a, b) = self.ends(e);
        squared_distance(a, b)
    }

    /// `ℓ_e²` rounded to the nearest `f64` when `N` of `N·10^(2E)` outgrows `u128` (e.g.
    /// coordinates near 0 written with an exponent, whose mantissas are aligned to the
    /// smallest exponent): `N < 2²⁵⁶` exact in four 64-bit limbs
    /// ([`squared_distance_wide`]), then `N·10^(2E)` rounded by [`wide_to_f64`] in
    /// fixed-width integers — the value `f64::from_rational` gives for a normal result
    /// (proof: B19), without a big number or a rational's gcd. `None` when a coordinate is
    /// not a decimal, `N` outgrows 256 bits, or the result is not a normal `f64` (the exact
    /// path decides).
    fn squared_f64_wide(a: &[Coordinate; 3], b: &[Coordinate; 3]) -> Option<f64> {
        let (n, k) = squared_distance_wide(a, b)?;
        wide_to_f64(&n, 2 * k)
    }

    /// The exact squared length `ℓ_e² = |p_tip − p_tail|²`.
    pub fn squared_length(&self, e: Edge) -> Rational {
        let (a, b) = self.ends(e);
        squared_distance_exact(a, b)
    }

    /// The exact squared distance `|p_v − p_u|²` of two vertices (on any triangulation of
    /// these positions, e.g. the input one after the surface's mesh was flipped).
    pub fn squared_distance(&self, u: Vertex, v: Vertex) -> Rational {
        squared_distance_exact(&self.positions[u.idx()], &self.positions[v.idx()])
    }

    /// `|p_v − p_u|²` rounded to the nearest `f64` (the value of
    /// `f64::from_rational(&self.squared_distance(u, v))`, proof: B19), from the integer
    /// form where it fits; `None` where the result is not a normal `f64`.
    pub fn squared_distance_f64(&self, u: Vertex, v: Vertex) -> Option<f64> {
        let (a, b) = (&self.positions[u.idx()], &self.positions[v.idx()]);
        Some(squared_f64(a, b)).filter(|x| x.is_normal())
    }

    /// The lengths in `f64`: `√(fl(ℓ²))` with `fl` rounding to nearest, as
    /// [`Surface::lengths`] computes them, from the integer form where it fits.
    pub fn lengths_f64(&self) -> Vec<f64> {
        self.mesh
            .edges()
            .map(|e| {
                let (a, b) = self.ends(e);
                squared_f64(a, b).sqrt()
            })
            .collect()
    }

    /// The squared lengths `fl(ℓ²)` of which [`DecimalSurface::lengths_f64`] takes the
    /// square roots (rounded to nearest where the result is a normal `f64`, B19).
    pub fn squared_lengths_f64(&self) -> Vec<f64> {
        self.mesh
            .edges()
            .map(|e| {
                let (a, b) = self.ends(e);
                squared_f64(a, b)
            })
            .collect()
    }

    /// The lengths in backend `T`: `√(T::from_rational(ℓ²))`, equal to
    /// [`Surface::lengths`] of [`DecimalSurface::into_surface`] (for `f64` through
    /// [`DecimalSurface::lengths_f64`]).
    pub fn lengths<T: Real + 'static>(&self, ctx: T::Ctx) -> Vec<T> {
        let fast: Box<dyn std::any::Any> =
            if std::any::TypeId::of::<T>() == std::any::TypeId::of::<f64>() {
                Box::new(self.lengths_f64())
            } else {
                Box::new(())
            };
        match fast.downcast::<Vec<T>>() {
            Ok(v) => *v,
            Err(_) => self
                .mesh
                .edges()
                .map(|e| T::from_rational(&self.squared_length(e), ctx).sqrt())
                .collect(),
        }
    }

    /// The exact surface: rational positions and squared lengths (already validated).
    pub fn into_surface(self) -> Surface {
        let squared = self.mesh.edges().map(|e| self.squared_length(e)).collect();
        let positions = self
            .positions
            .iter()
            .map(|p| [p[0].to_rational(), p[1].to_rational(), p[2].to_rational()])
            .collect();
        Surface {
            mesh: self.mesh,
            metric: Metric::SquaredLengths(squared),
            positions: Some(positions),
            name: self.name,
        }
    }
}

/// The exact `|b − a|²`: in integers when it fits, in ℚ otherwise.
fn squared_distance_exact(a: &[Coordinate; 3], b: &[Coordinate; 3]) -> Rational {
    if let Some((n, k)) = squared_distance(a, b) {
        return decimal_to_rational(n, 2 * k);
    }
    if let Some((n, k)) = squared_distance_wide(a, b) {
        return wide_to_rational(&n, 2 * k);
    }
    let mut s = Rational::new();
    for k in 0..3 {
        let d = b[k].to_rational() - a[k].to_rational();
        s += Rational::from(&d * &d);
    }
    s
}

/// The exact rational `n · 10^e` for `n` given as little-endian 64-bit limbs.
fn wide_to_rational(n: &[u64], e: i32) -> Rational {
    let n = rug::Integer::from_digits(n, rug::integer::Order::Lsf);
    let p = rug::Integer::from(rug::Integer::u_pow_u(10, e.unsigned_abs()));
    if e >= 0 {
        Rational::from(n * p)
    } else {
        Rational::from((n, p))
    }
}

/// `|b − a|²` rounded to the nearest `f64`, as `f64::from_rational` of the exact value.
fn squared_f64(a: &[Coordinate; 3], b: &[Coordinate; 3]) -> f64 {
    squared_distance(a, b)
        .and_then(|(n, k)| decimal_to_f64(n, 2 * k))
        .or_else(|| DecimalSurface::squared_f64_wide(a, b))
        .unwrap_or_else(|| f64::from_rational(&squared_distance_exact(a, b), ()))
}
