//! A surface: a Δ-complex with an exact discrete metric, optional vertex positions and a
//! name — what every reader returns and every layer above consumes.

use crate::mesh::builders::{Embedded, Intrinsic};
use crate::mesh::{Edge, Face, Mesh};
use crate::scalar::Real;
use rug::Rational;
use std::cmp::Ordering;

/// An exact discrete metric: one positive rational per edge, indexed by `Edge.idx()`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Metric {
    /// Edge lengths ℓ_e.
    Lengths(Vec<Rational>),
    /// Squared edge lengths ℓ_e², as arise from rational vertex positions (where ℓ itself
    /// is in general irrational).
    SquaredLengths(Vec<Rational>),
}

impl Metric {
    /// Number of edges covered.
    pub fn len(&self) -> usize {
        self.values().len()
    }
    /// Whether no edge is covered.
    pub fn is_empty(&self) -> bool {
        self.values().is_empty()
    }
    /// The stored values (lengths or squared lengths).
    pub fn values(&self) -> &[Rational] {
        match self {
            Metric::Lengths(v) | Metric::SquaredLengths(v) => v,
        }
    }
    /// The squared lengths ℓ_e², exact.
    pub fn squared(&self) -> Vec<Rational> {
        match self {
            Metric::Lengths(v) => v.iter().map(|l| Rational::from(l * l)).collect(),
            Metric::SquaredLengths(v) => v.clone(),
        }
    }
}

/// Why a metric is not a valid discrete metric on its mesh.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum MetricError {
    /// The metric does not have one value per edge.
    #[error("the metric has {got} values for {edges} edges")]
    Count {
        /// Values given.
        got: usize,
        /// Edges of the mesh.
        edges: usize,
    },
    /// A length (or squared length) is zero or negative.
    #[error("edge e{edge}: length {value} is not positive")]
    NonPositive {
        /// The edge.
        edge: u32,
        /// The value, as an exact rational.
        value: String,
    },
    /// A face violates the strict triangle inequality (or is degenerate: equality).
    #[error("face f{face}: sides {sides:?} {}", if *.degenerate { "are degenerate (one equals the sum of the others)" } else { "violate the triangle inequality" })]
    TriangleInequality {
        /// The face.
        face: u32,
        /// Its three lengths (or squared lengths), exact, in side order.
        sides: [String; 3],
        /// Equality instead of violation.
        degenerate: bool,
    },
    /// The number of positions differs from the number of vertices.
    #[error("{got} positions for {vertices} vertices")]
    PositionCount {
        /// Positions given.
        got: usize,
        /// Vertices of the mesh.
        vertices: usize,
    },
}

/// A named Δ-complex with an exact metric and optional exact vertex positions.
///
/// The metric is what the geometry uses; positions, when present, are carried along (they
/// describe the original embedding and need not match the metric after flips).
///
/// ```
/// use penner::io::{Metric, Surface};
/// use penner::mesh::builders;
/// let s = Surface::from_embedded("tetrahedron", builders::tetrahedron()).unwrap();
/// assert!(matches!(s.metric, Metric::SquaredLengths(_)));
/// let l: Vec<f64> = s.lengths::<f64>(());
/// assert!(l.iter().all(|&x| x == 8f64.sqrt()));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Surface {
    /// The triangulation.
    pub mesh: Mesh,
    /// The exact metric, one value per edge.
    pub metric: Metric,
    /// Exact vertex positions in ℝ³, if known.
    pub positions: Option<Vec<[Rational; 3]>>,
    /// A name for reports.
    pub name: String,
}

impl Surface {
    /// A validated surface ([`Surface::validate`]).
    pub fn new(
        name: impl Into<String>,
        mesh: Mesh,
        metric: Metric,
        positions: Option<Vec<[Rational; 3]>>,
    ) -> Result<Surface, MetricError> {
        let s = Surface {
            mesh,
            metric,
            positions,
            name: name.into(),
        };
        s.validate()?;
        Ok(s)
    }

    /// The surface of an embedded builder: squared lengths from the exact positions.
    pub fn from_embedded(name: impl Into<String>, e: Embedded) -> Result<Surface, MetricError> {
        let metric = Metric::SquaredLengths(squared_lengths_from_positions(&e.mesh, &e.positions));
        Surface::new(name, e.mesh, metric, Some(e.positions))
    }

    /// The surface of an intrinsic builder (e.g. the flat torus).
    pub fn from_intrinsic(name: impl Into<String>, i: Intrinsic) -> Result<Surface, MetricError> {
        Surface::new(
            name,
            i.mesh,
            Metric::SquaredLengths(i.squared_lengths),
            None,
        )
    }

    /// The lengths in backend `T`: `T::from_rational(ℓ)` (one rounding: correctly rounded
    /// for `f64` and MPFR) for [`Metric::Lengths`], `√(T::from_rational(ℓ²))` (two
    /// roundings: within 1.5 u relative for `f64` and MPFR) for [`Metric::SquaredLengths`].
    pub fn lengths<T: Real>(&self, ctx: T::Ctx) -> Vec<T> {
        match &self.metric {
            Metric::Lengths(v) => v.iter().map(|q| T::from_rational(q, ctx)).collect(),
            Metric::SquaredLengths(v) => {
                v.iter().map(|q| T::from_rational(q, ctx).sqrt()).collect()
            }
        }
    }

    /// The binary exponent `k` with the largest length within a factor 2 of `2ᵏ`: from the
    /// bit lengths of the largest value's numerator and denominator (halved for squared
    /// lengths). `0` for an empty metric.
    pub fn length_exponent(&self) -> i64 {
        let bits = |q: &Rational| {
            i64::from(q.numer().significant_bits()) - i64::from(q.denom().significant_bits())
        };
        let k = self.metric.values().iter().map(bits).max().unwrap_or(0);
        match self.metric {
            Metric::Lengths(_) => k,
            Metric::SquaredLengths(_) => k.div_euclid(2),
        }
    }

    /// The same surface with every length multiplied by the exact power of two `2⁻ᵏ`
    /// (squared lengths by `2⁻²ᵏ`, positions by `2⁻ᵏ`), so that its largest length is
    /// within a factor 4 of 1 — or `None` when it already is within `2^±8`. Every statement
    /// of the catalogue is invariant under a uniform scaling (angles, cross ratios, cotan
    /// weights, flips) or scales with it, and the error bounds of the numerical checks are
    /// proved for lengths in `[2⁻¹⁰⁰, 2¹⁰⁰]` (proofs/B40, "Range"): checks run on this copy.
    ///
    /// ```
    /// use penner::io::{Metric, Surface};
    /// use penner::mesh::Mesh;
    /// use rug::Rational;
    /// let tri = Mesh::from_faces(3, &[[0, 1, 2]]).unwrap();
    /// let tiny = Rational::from(1) >> 300u32;
    /// let s = Surface::new("t", tri, Metric::Lengths(vec![tiny.clone(), tiny.clone(), tiny]), None).unwrap();
    /// let (n, k) = s.normalized_scale().unwrap();
    /// assert_eq!(k, -300);
    /// assert_eq!(n.metric.values()[0], 1);
    /// ```
    pub fn normalized_scale(&self) -> Option<(Surface, i64)> {
        let k = self.length_exponent();
        if k.abs() <= 8 {
            return None;
        }
        let k32 = i32::try_from(k).ok()?;
        let shift = |q: &Rational, by: i32| Rational::from(q >> by);
        let metric = match &self.metric {
            Metric::Lengths(v) => Metric::Lengths(v.iter().map(|q| shift(q, k32)).collect()),
            Metric::SquaredLengths(v) => {
                Metric::SquaredLengths(v.iter().map(|q| shift(q, 2 * k32)).collect())
            }
        };
        let positions = self.positions.as_ref().map(|ps| {
            ps.iter()
                .map(|p| [shift(&p[0], k32), shift(&p[1], k32), shift(&p[2], k32)])
                .collect()
        });
        Some((
            Surface {
                mesh: self.mesh.clone(),
                metric,
                positions,
                name: self.name.clone(),
            },
            k,
        ))
    }

    /// Check, exactly in ℚ: one value per edge, every value > 0, and every face strictly
    /// satisfies the triangle inequality — for lengths a + b > c (each side), for squared
    /// lengths A = a², B = b², C = c² the equivalent
    /// 16·area² = 2(AB + BC + CA) − (A² + B² + C²) > 0 (Heron; with positive sides
    /// 16·area² = (a+b+c)(−a+b+c)(a−b+c)(a+b−c)). Also one position per vertex when
    /// positions are present.
    pub fn validate(&self) -> Result<(), MetricError> {
        validate_metric(&self.mesh, &self.metric)?;
        if let Some(p) = &self.positions {
            if p.len() != self.mesh.n_vertices() {
                return Err(MetricError::PositionCount {
                    got: p.len(),
                    vertices: self.mesh.n_vertices(),
                });
            }
        }
        Ok(())
    }
}

/// Exact squared edge lengths |p_tip − p_tail|² from vertex positions.
pub fn squared_lengths_from_positions(mesh: &Mesh, positions: &[[Rational; 3]]) -> Vec<Rational> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (
                &positions[mesh.tail(h).idx()],
                &positions[mesh.tip(h).idx()],
            );
            let mut s = Rational::new();
            for k in 0..3 {
                let d = Rational::from(&b[k] - &a[k]);
                s += Rational::from(&d * &d);
            }
            s
        })
        .collect()
}

/// The checks of [`Surface::validate`] on a mesh and metric.
pub fn validate_metric(mesh: &Mesh, metric: &Metric) -> Result<(), MetricError> {
    let v = metric.values();
    if v.len() != mesh.n_edges() {
        return Err(MetricError::Count {
            got: v.len(),
            edges: mesh.n_edges(),
        });
    }
    for (e, x) in v.iter().enumerate() {
        if x.cmp0() != Ordering::Greater {
            return Err(MetricError::NonPositive {
                edge: Edge(e as u32).0,
                value: x.to_string(),
            });
        }
    }
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_halfedges(f).map(|h| &v[h.edge().idx()]);
        let sign = match metric {
            Metric::Lengths(_) => [(a, b, c), (b, c, a), (c, a, b)]
                .into_iter()
                .map(|(x, y, z)| Rational::from(x + y) - z)
                .map(|d| d.cmp0())
                .min()
                .unwrap_or(Ordering::Less),
            Metric::SquaredLengths(_) => heron16(a, b, c).cmp0(),
        };
        if sign != Ordering::Greater {
            return Err(triangle_error(f, [a, b, c], sign == Ordering::Equal));
        }
    }
    Ok(())
}

/// 16·area² from squared sides: 2(AB + BC + CA) − (A² + B² + C²).
pub fn heron16(a: &Rational, b: &Rational, c: &Rational) -> Rational {
    let ab = Rational::from(a * b);
    let bc = Rational::from(b * c);
    let ca = Rational::from(c * a);
    let sq = Rational::from(a * a) + Rational::from(b * b) + Rational::from(c * c);
    (ab + bc + ca) * 2u32 - sq
}

fn triangle_error(f: Face, s: [&Rational; 3], degenerate: bool) -> MetricError {
    MetricError::TriangleInequality {
        face: f.0,
        sides: s.map(ToString::to_string),
        degenerate,
    }
}
