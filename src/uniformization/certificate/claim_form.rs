//! The certificate as a `penner certify` claim of kind `uniformization` (protocol v1,
//! `docs/oracle.md`): writing it, and re-checking it from scratch (B71).
//!
//! Fields besides the common ones: `targets` (`Θ_i/π`, exact strings, one per vertex),
//! `flips` (the Ptolemy flips from the surface to the final triangulation, as indices into
//! the surface's edge order — an edge keeps its index when flipped), `u` (exact decimal
//! strings), `radius` (the sup-norm box), `final_faces` (the final triangulation's vertex
//! triples, checked) and `residual_bound` (a claimed upper bound on `‖Θ − θ(u)‖₂` over the
//! free vertices, checked). `max_bits` is the interval precision of the re-check.
//!
//! Two forms. Without `euclidean_flips`, `surface` is `T₀` itself with binary64 lengths
//! (the binary64-rounded metric, as written for inputs whose exact metric was not
//! certified). With `euclidean_flips` (the flips from `surface` to its intrinsic Delaunay
//! triangulation `T₀`, indices into the surface's edge order), `surface` is the input as
//! given — exact lengths, squared lengths or positions — and the re-check replays those
//! flips on enclosures of its exact lengths, each admitted only on a certified strictly
//! convex quadrilateral (B73 (a)), so a `holds` is about the input's own metric.

use super::certificate::{
    check_certificate, CertificateData, CertificateError, CertificateOutcome,
};
use super::certificate::{check_certificate_on, I};
use super::input_metric::{replay_enclosed, t0_delaunay_on_input};
use super::refine::{carry_lengths, carry_lengths_from};
use super::targets::Targets;
use crate::io::json::{edge_order, ExactString, SeqOf, SurfaceJson};
use crate::io::{Metric, Surface};
use crate::mesh::Edge;
use crate::predicates::delaunay::{delaunay_sign_squared, QuadEdges};
use crate::scalar::{Mpfr, Precision, Real, Sign};
use rug::{Integer, Rational};
use serde_json::Value;
use std::borrow::Cow;

/// The claim-specific fields of a `uniformization` claim, parsed.
#[derive(Clone, Debug, PartialEq)]
pub struct UniformizationClaim {
    /// `Θ_i/π`, one per vertex.
    pub targets_over_pi: Vec<Rational>,
    /// Flips as indices into the surface's edge order.
    pub flips: Vec<usize>,
    /// The proposed `u`.
    pub u: Vec<Rational>,
    /// The radius of the box.
    pub radius: Rational,
    /// The final triangulation's faces, as claimed.
    pub final_faces: Vec<[u32; 3]>,
    /// The claimed bound on `‖Θ − θ(u)‖₂`.
    pub residual_bound: Rational,
    /// The Euclidean flips from the surface to `T₀` (the input-metric form), or `None`
    /// (the surface is `T₀` with binary64 lengths).
    pub euclidean_flips: Option<Vec<usize>>,
}

/// A malformed `uniformization` claim.
#[derive(Debug, thiserror::Error)]
pub enum ClaimFormError {
    /// The certificate data are refused.
    #[error(transparent)]
    Certificate(#[from] CertificateError),
    /// The surface's metric is not given by binary64 lengths.
    #[error("surface: length {index} is not a binary64 number (a uniformization certificate gives its lengths as written by penner uniformize)")]
    NotBinary64 {
        /// Position in the surface's edge order.
        index: usize,
    },
    /// Squared lengths were given.
    #[error("surface: a uniformization certificate needs `lengths`, not `squared_lengths`")]
    SquaredLengths,
    /// A flip index is out of range.
    #[error("flips[{position}]: edge index {index} out of range (the surface has {edges} edges)")]
    FlipIndex {
        /// Position in `flips`.
        position: usize,
        /// The index.
        index: usize,
        /// Edges.
        edges: usize,
    },
    /// A Euclidean flip index is out of range.
    #[error("euclidean_flips[{position}]: edge index {index} out of range (the surface has {edges} edges)")]
    EuclideanFlipIndex {
        /// Position in `euclidean_flips`.
        position: usize,
        /// The index.
        index: usize,
        /// Edges.
        edges: usize,
    },
    /// The surface is not intrinsic Delaunay.
    #[error("surface: edge {index} is not intrinsic Delaunay (the flips of a certificate start from the Delaunay triangulation of the input)")]
    NotDelaunay {
        /// Position in the surface's edge order.
        index: usize,
    },
    /// The flips do not reach `final_faces`.
    #[error("final_faces: the flips reach a different triangulation")]
    FinalFaces,
}

/// A dyadic rational `n/2ᵏ` as an exact decimal string; `None` for other denominators.
pub fn exact_decimal(q: &Rational) -> Option<String> {
    let d = q.denom();
    let k = d.find_one(0)?;
    if Integer::from(d >> k) != 1 {
        return None;
    }
    // n/2ᵏ = n·5ᵏ/10ᵏ.
    let digits = Integer::from(q.numer().abs_ref()) * Integer::from(Integer::u_pow_u(5, k));
    let mut s = digits.to_string();
    let k = k as usize;
    if k > 0 {
        if s.len() <= k {
            s = format!("{}{s}", "0".repeat(k + 1 - s.len()));
        }
        s.insert(s.len() - k, '.');
    }
    Some(if *q < 0 { format!("-{s}") } else { s })
}

/// The certificate `data` as a `uniformization` claim at `bits`, with the final faces and
/// a residual bound.
pub fn to_claim(
    data: &CertificateData,
    final_faces: &[[u32; 3]],
    residual_bound: f64,
    bits: u32,
) -> Value {
    claim_value(&ClaimJson::rounded(
        data,
        final_faces.to_vec(),
        residual_bound,
        bits,
    ))
}

/// The certificate `data` (whose `t0` is `input`'s mesh after the Euclidean flips
/// `euclidean`) as a `uniformization` claim about `input`'s own exact metric at `bits`:
/// `surface` is `input` as given and `euclidean_flips` the flips to `T₀` (module
/// documentation), with the final faces and a residual bound.
pub fn to_claim_on_input(
    data: &CertificateData,
    input: &Surface,
    euclidean: &[Edge],
    final_faces: &[[u32; 3]],
    residual_bound: f64,
    bits: u32,
) -> Value {
    claim_value(&ClaimJson::on_input(
        data,
        input,
        euclidean,
        final_faces.to_vec(),
        residual_bound,
        bits,
    ))
}

/// The claim as a JSON value ([`ClaimJson`] converted; its keys are strings, so the
/// conversion cannot fail).
fn claim_value(c: &ClaimJson<'_>) -> Value {
    serde_json::to_value(c).unwrap_or(Value::Null)
}

/// A `uniformization` claim as a view that serde serializes straight from the certificate
/// data (no value tree; [`SurfaceJson`] for the surface): `serde_json::to_writer_pretty`
/// streams a 10⁵-face claim into its file with the text of [`to_claim`]'s value. Keys are
/// emitted in sorted order, the order of serde_json's maps.
#[derive(Clone, Debug)]
pub struct ClaimJson<'a> {
    data: &'a CertificateData,
    surface: Cow<'a, Surface>,
    euclidean: Option<&'a [Edge]>,
    final_faces: Vec<[u32; 3]>,
    residual_bound: f64,
    bits: u32,
}

impl<'a> ClaimJson<'a> {
    /// The claim about `T₀` with its binary64 lengths (the binary64-rounded metric).
    pub fn rounded(
        data: &'a CertificateData,
        final_faces: Vec<[u32; 3]>,
        residual_bound: f64,
        bits: u32,
    ) -> ClaimJson<'a> {
        let lengths: Vec<Rational> = data
            .l0
            .iter()
            .map(|&x| Rational::from_f64(x).unwrap_or_default())
            .collect();
        let surface = Surface {
            mesh: data.t0.clone(),
            metric: Metric::Lengths(lengths),
            positions: None,
            name: "uniformization input (intrinsic Delaunay)".into(),
        };
        ClaimJson {
            data,
            surface: Cow::Owned(surface),
            euclidean: None,
            final_faces,
            residual_bound,
            bits,
        }
    }

    /// The claim about `input`'s exact metric, with the Euclidean flips `euclidean` from
    /// `input` to `T₀`.
    pub fn on_input(
        data: &'a CertificateData,
        input: &'a Surface,
        euclidean: &'a [Edge],
        final_faces: Vec<[u32; 3]>,
        residual_bound: f64,
        bits: u32,
    ) -> ClaimJson<'a> {
        ClaimJson {
            data,
            surface: Cow::Borrowed(input),
            euclidean: Some(euclidean),
            final_faces,
            residual_bound,
            bits,
        }
    }
}

impl ClaimJson<'_> {
    /// The claim as a JSON value (its keys are strings, so the conversion cannot fail).
    pub fn value(&self) -> Value {
        claim_value(self)
    }
}

/// A dyadic rational as its exact decimal ([`exact_decimal`]), other rationals as `n/d`.
struct Decimal<'a>(&'a Rational);

impl serde::Serialize for Decimal<'_> {
    fn serialize<S: serde::Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        match exact_decimal(self.0) {
            Some(d) => ser.serialize_str(&d),
            None => ser.collect_str(self.0),
        }
    }
}

impl serde::Serialize for ClaimJson<'_> {
    fn serialize<S: serde::Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let data = self.data;
        let order = edge_order(&self.surface.mesh);
        let mut user = vec![0usize; order.len()];
        for (k, &e) in order.iter().enumerate() {
            user[e] = k;
        }
        let indices = |flips: &[Edge]| flips.iter().map(|e| user[e.idx()]).collect::<Vec<_>>();
        let targets = data.targets.over_pi();
        let residual = Rational::from_f64(self.residual_bound).unwrap_or_default();
        let mut m = ser.serialize_map(None)?;
        // Sorted keys: euclidean_flips, final_faces, flips, kind, max_bits, penner_claim,
        // radius, residual_bound, surface, targets, u.
        if let Some(flips) = self.euclidean {
            m.serialize_entry("euclidean_flips", &indices(flips))?;
        }
        m.serialize_entry("final_faces", &self.final_faces)?;
        m.serialize_entry("flips", &indices(&data.flip_sequence))?;
        m.serialize_entry("kind", "uniformization")?;
        m.serialize_entry("max_bits", &self.bits)?;
        m.serialize_entry("penner_claim", &1)?;
        m.serialize_entry("radius", &Decimal(&data.radius))?;
        m.serialize_entry("residual_bound", &Decimal(&residual))?;
        m.serialize_entry("surface", &SurfaceJson(&self.surface))?;
        m.serialize_entry("targets", &SeqOf(|| targets.iter().map(ExactString)))?;
        m.serialize_entry("u", &SeqOf(|| data.u.iter().map(Decimal)))?;
        m.end()
    }
}

/// The checks of a claim that need no arithmetic beyond ℚ: binary64 lengths, flip indices
/// in range, the targets (count, positivity, Gauss–Bonnet), one `u` per vertex, a positive
/// radius. A failure is bad input, named by field.
pub fn validate(surface: &Surface, claim: &UniformizationClaim) -> Result<(), ClaimFormError> {
    let order = edge_order(&surface.mesh);
    if claim.euclidean_flips.is_none() {
        let Metric::Lengths(l) = &surface.metric else {
            return Err(ClaimFormError::SquaredLengths);
        };
        for (k, &e) in order.iter().enumerate() {
            let q = &l[e];
            if Rational::from_f64(q.to_f64()).as_ref() != Some(q) {
                return Err(ClaimFormError::NotBinary64 { index: k });
            }
        }
    }
    if let Some((position, &index)) = claim
        .flips
        .iter()
        .enumerate()
        .find(|&(_, &i)| i >= order.len())
    {
        return Err(ClaimFormError::FlipIndex {
            position,
            index,
            edges: order.len(),
        });
    }
    let mut euclidean = claim.euclidean_flips.iter().flatten().enumerate();
    if let Some((position, &index)) = euclidean.find(|&(_, &i)| i >= order.len()) {
        return Err(ClaimFormError::EuclideanFlipIndex {
            position,
            index,
            edges: order.len(),
        });
    }
    if !surface.mesh.is_closed() {
        return Err(
            CertificateError::from(super::error::UniformizeError::NotClosed {
                edges: surface.mesh.n_boundary_edges(),
            })
            .into(),
        );
    }
    Targets::from_multiples_of_pi(claim.targets_over_pi.clone())
        .validate(&surface.mesh)
        .map_err(CertificateError::from)?;
    if claim.u.len() != surface.mesh.n_vertices() {
        return Err(CertificateError::ScaleCount {
            expected: surface.mesh.n_vertices(),
            got: claim.u.len(),
        }
        .into());
    }
    if claim.radius <= 0 {
        return Err(CertificateError::Radius(claim.radius.to_string()).into());
    }
    Ok(())
}

/// Re-check a `uniformization` claim about `surface` from scratch at `bits`: the surface
/// is intrinsic Delaunay (exact signs, B63), the flips reach `final_faces`, then
/// [`check_certificate`] (B71) and the residual bound. `Undecided` outcomes carry the
/// reason; malformed claims are errors.
pub fn recheck(
    surface: &Surface,
    claim: &UniformizationClaim,
    bits: u32,
) -> Result<CertificateOutcome, ClaimFormError> {
    if let Some(euclidean) = &claim.euclidean_flips {
        return recheck_on_input(surface, claim, euclidean, bits);
    }
    let mesh = &surface.mesh;
    let Metric::Lengths(l) = &surface.metric else {
        return Err(ClaimFormError::SquaredLengths);
    };
    let order = edge_order(mesh);
    let mut user = vec![0usize; order.len()];
    for (k, &e) in order.iter().enumerate() {
        user[e] = k;
    }
    let mut l0 = Vec::with_capacity(l.len());
    for (e, q) in l.iter().enumerate() {
        let x = q.to_f64();
        if Rational::from_f64(x).as_ref() != Some(q) {
            return Err(ClaimFormError::NotBinary64 { index: user[e] });
        }
        l0.push(x);
    }
    let sq = surface.metric.squared();
    for e in mesh.edges() {
        if let Some(q) = QuadEdges::of(mesh, e) {
            if delaunay_sign_squared(q.lengths(&sq)) == Sign::Negative {
                return Err(ClaimFormError::NotDelaunay {
                    index: user[e.idx()],
                });
            }
        }
    }
    let mut flips = Vec::with_capacity(claim.flips.len());
    for (position, &index) in claim.flips.iter().enumerate() {
        let Some(&e) = order.get(index) else {
            return Err(ClaimFormError::FlipIndex {
                position,
                index,
                edges: order.len(),
            });
        };
        flips.push(Edge(e as u32));
    }
    let data = CertificateData {
        t0: mesh.clone(),
        l0,
        targets: Targets::from_multiples_of_pi(claim.targets_over_pi.clone()),
        flip_sequence: flips,
        u: claim.u.clone(),
        radius: claim.radius.clone(),
    };
    let prec =
        Precision::new(u64::from(bits)).map_err(|_| CertificateError::Bits(u64::from(bits)))?;
    let (final_mesh, _) = carry_lengths::<Mpfr>(&data.t0, &data.l0, &data.flip_sequence, prec)
        .map_err(CertificateError::from)?;
    if !same_faces(&final_mesh.face_list(), &claim.final_faces) {
        return Err(ClaimFormError::FinalFaces);
    }
    let outcome = check_certificate(&data, bits)?;
    Ok(within_residual_bound(outcome, claim))
}

/// [`recheck`] of the input-metric form (module documentation): the Euclidean flips
/// replayed on enclosures of `surface`'s exact lengths (B73 (a)), `T₀` certified
/// intrinsic Delaunay for them, the Ptolemy flips reaching `final_faces`, then
/// [`check_certificate_on`] with the enclosures (B71) and the residual bound.
fn recheck_on_input(
    surface: &Surface,
    claim: &UniformizationClaim,
    euclidean: &[usize],
    bits: u32,
) -> Result<CertificateOutcome, ClaimFormError> {
    let undecided = |reason: String| Ok(CertificateOutcome::Undecided { reason });
    let prec =
        Precision::new(u64::from(bits)).map_err(|_| CertificateError::Bits(u64::from(bits)))?;
    let mesh = &surface.mesh;
    let order = edge_order(mesh);
    let edges = order.len();
    let mut sequence = Vec::with_capacity(euclidean.len());
    for (position, &index) in euclidean.iter().enumerate() {
        let &e = order.get(index).ok_or(ClaimFormError::EuclideanFlipIndex {
            position,
            index,
            edges,
        })?;
        sequence.push(Edge(e as u32));
    }
    let (t0, l0) = match replay_enclosed(mesh, surface.lengths::<I>(prec), &sequence) {
        Ok(x) => x,
        Err(reason) => return undecided(reason),
    };
    if let Err(e) = t0_delaunay_on_input(surface, &t0, &l0, &sequence) {
        let k = order.iter().position(|&x| x == e.idx()).unwrap_or(e.idx());
        return undecided(format!(
            "edge {k} of T₀ is not certified intrinsic Delaunay for the surface's metric"
        ));
    }
    let mut flips = Vec::with_capacity(claim.flips.len());
    for (position, &index) in claim.flips.iter().enumerate() {
        let &e = order.get(index).ok_or(ClaimFormError::FlipIndex {
            position,
            index,
            edges,
        })?;
        flips.push(Edge(e as u32));
    }
    let (final_mesh, _) =
        carry_lengths_from(&t0, l0.clone(), &flips).map_err(CertificateError::from)?;
    if !same_faces(&final_mesh.face_list(), &claim.final_faces) {
        return Err(ClaimFormError::FinalFaces);
    }
    let data = CertificateData {
        t0,
        l0: l0.iter().map(Real::approx_f64).collect(),
        targets: Targets::from_multiples_of_pi(claim.targets_over_pi.clone()),
        flip_sequence: flips,
        u: claim.u.clone(),
        radius: claim.radius.clone(),
    };
    let outcome = check_certificate_on(&data, Some(&l0), bits)?;
    Ok(within_residual_bound(outcome, claim))
}

/// `outcome`, made undecided when it holds with an enclosed residual above the claim's
/// `residual_bound`.
fn within_residual_bound(
    outcome: CertificateOutcome,
    claim: &UniformizationClaim,
) -> CertificateOutcome {
    if let CertificateOutcome::Holds { residual, .. } = &outcome {
        let enclosed = Rational::from_f64(*residual).unwrap_or_default();
        if enclosed > claim.residual_bound {
            return CertificateOutcome::Undecided {
                reason: format!(
                    "the enclosed residual {residual:e} is not below the claimed residual_bound {:e}",
                    claim.residual_bound.to_f64()
                ),
            };
        }
    }
    outcome
}

/// Whether two face lists are the same triangle faces up to the order of the faces and the
/// starting corner of each (orientation kept): a triangulation re-read from a claim and
/// flipped may number its faces' slots and corners differently from the writer's, while
/// every flip acts on the same faces (the re-check computes on its own replay; this field
/// is the claim's statement of where the flips end).
pub fn same_faces(a: &[[u32; 3]], b: &[[u32; 3]]) -> bool {
    let canonical = |faces: &[[u32; 3]]| {
        let mut v: Vec<[u32; 3]> = faces
            .iter()
            .map(|&[x, y, z]| {
                if x <= y && x <= z {
                    [x, y, z]
                } else if y <= z {
                    [y, z, x]
                } else {
                    [z, x, y]
                }
            })
            .collect();
        v.sort_unstable();
        v
    };
    a.len() == b.len() && canonical(a) == canonical(b)
}

#[cfg(test)]
mod same_faces_tests {
    use super::same_faces;

    /// Face order and starting corners do not matter; orientation, a vertex and a missing
    /// or repeated face do.
    #[test]
    fn same_faces_up_to_order_and_rotation_only() {
        let a = [[0, 1, 2], [2, 1, 3]];
        assert!(same_faces(&a, &[[1, 3, 2], [2, 0, 1]]));
        assert!(!same_faces(&a, &[[0, 2, 1], [2, 1, 3]]), "orientation");
        assert!(!same_faces(&a, &[[0, 1, 2], [2, 1, 4]]), "a vertex");
        assert!(!same_faces(&a, &[[0, 1, 2]]), "a face missing");
        assert!(!same_faces(&a, &[[0, 1, 2], [0, 1, 2]]), "a face repeated");
    }
}
