//! The sphere target's certificate as a `penner certify` claim of kind
//! `sphere_uniformization` (protocol v1, `docs/oracle.md`): writing it, and re-checking it
//! from scratch for the surface's own (exact) metric. proof: B90
//!
//! Fields besides the common ones (`surface` is the input as given: exact lengths,
//! squared lengths or positions): `euclidean_flips` (the flips from `surface` to its
//! intrinsic Delaunay triangulation `T₀`, as indices into the surface's edge order — an
//! edge keeps its index when flipped), `pole` (the vertex `v∞`), `flips` (the Ptolemy flips
//! of the whole sphere from `T₀` to the final triangulation `T_F`, same indexing: the
//! disk's and those of edges at the pole, B93), `u` (one entry per vertex: an exact
//! decimal at the free vertices, `null` at the pole and its link in `T_F`, whose values
//! `−2 log ℓ_{a v∞}` are fixed), `radius` (the sup-norm box), `final_faces` (the faces of
//! `T_F`) and `residual_bound` (a claimed upper bound on `‖2π − θ(u)‖₂` over the free
//! vertices).
//!
//! The re-check (B90): the Euclidean flips replayed on enclosures of the exact input
//! lengths, each admitted only on a certified strictly convex quadrilateral (B73 (a));
//! `T₀` certified intrinsic Delaunay; the Ptolemy flips replayed formally on the
//! enclosures of the whole sphere (T28); the pole's final star a disk with a simple link;
//! the disk certificate (B76) on the disk `T_F − star(v∞)` with the carried enclosures; the
//! residual bound. Claims whose flips avoid the star (the only ones written before B93)
//! are re-checked as before: their final star is `T₀`'s.

use super::certificate::{CertificateOutcome, I};
use super::claim_form::exact_decimal;
use super::dirichlet_certificate::{check_disk_certificate_on, DiskCertificateData, DiskMetric};
use super::input_metric::{replay_enclosed, t0_delaunay_on_input};
use super::refine::{carry_lengths_from, RefineError};
use super::sphere::{check_pole, disk_of, SphereUniformization};
use crate::io::json::{edge_order, to_value};
use crate::io::Surface;
use crate::mesh::{Edge, Vertex};
use crate::scalar::{Precision, Real};
use rug::Rational;
use serde_json::{json, Value};

/// The claim-specific fields of a `sphere_uniformization` claim, parsed.
#[derive(Clone, Debug, PartialEq)]
pub struct SphereClaim {
    /// Euclidean flips from the surface to `T₀`, as indices into the surface's edge order.
    pub euclidean_flips: Vec<usize>,
    /// The pole `v∞`.
    pub pole: u32,
    /// Ptolemy flips of the disk, as indices into the surface's edge order.
    pub flips: Vec<usize>,
    /// One entry per vertex: `Some(u_i)` at free vertices, `None` at the pole and its link.
    pub u: Vec<Option<Rational>>,
    /// The radius of the box.
    pub radius: Rational,
    /// The final triangulation's faces, as claimed.
    pub final_faces: Vec<[u32; 3]>,
    /// The claimed bound on `‖2π − θ(u)‖₂` over the free vertices.
    pub residual_bound: Rational,
}

/// A malformed `sphere_uniformization` claim (as opposed to one not proved).
#[derive(Debug, thiserror::Error)]
pub enum SphereClaimError {
    /// Not a closed connected surface of genus 0.
    #[error("surface: the sphere target needs a closed connected surface of genus 0 (χ = {chi}, {components} component(s), {boundary} boundary edge(s))")]
    NotASphere {
        /// Euler characteristic.
        chi: i64,
        /// Connected components.
        components: usize,
        /// Boundary edges.
        boundary: usize,
    },
    /// A flip index is out of range.
    #[error(
        "{field}[{position}]: edge index {index} out of range (the surface has {edges} edges)"
    )]
    FlipIndex {
        /// `euclidean_flips` or `flips`.
        field: &'static str,
        /// Position in the list.
        position: usize,
        /// The index.
        index: usize,
        /// Edges.
        edges: usize,
    },
    /// Wrong number of `u` entries.
    #[error("u: {got} entries, but the surface has {expected} vertices")]
    UCount {
        /// Vertices.
        expected: usize,
        /// Given.
        got: usize,
    },
    /// The radius is not positive.
    #[error("radius: {0} is not positive")]
    Radius(String),
    /// The pole is out of range or its star in `T₀` is not a disk with a simple link.
    #[error("pole: v{vertex}: {reason}")]
    Pole {
        /// The vertex.
        vertex: u32,
        /// Why.
        reason: String,
    },
    /// `u` has a value at the pole or its link, or none at a free vertex.
    #[error("u[{vertex}]: {what}")]
    UPattern {
        /// The vertex.
        vertex: usize,
        /// What is wrong.
        what: &'static str,
    },
    /// The Ptolemy flips do not replay.
    #[error("flips[{position}]: the flip of edge {index} does not replay on the surface")]
    Replay {
        /// Position in `flips`.
        position: usize,
        /// The index.
        index: usize,
    },
    /// The flips do not reach `final_faces`.
    #[error("final_faces: the flips reach a different triangulation")]
    FinalFaces,
    /// The precision is out of range.
    #[error("precision of {0} bits out of range")]
    Bits(u32),
}

/// The checks that need no arithmetic: a closed connected genus-0 surface, flip indices
/// in range, one `u` entry per vertex, the pole in range, a positive radius. A failure is
/// bad input, named by field.
pub fn validate(surface: &Surface, claim: &SphereClaim) -> Result<(), SphereClaimError> {
    let mesh = &surface.mesh;
    let components = super::components::Components::of(mesh).roots.len();
    let chi = mesh.euler_characteristic();
    if !mesh.is_closed() || chi != 2 || components != 1 {
        return Err(SphereClaimError::NotASphere {
            chi,
            components,
            boundary: mesh.n_boundary_edges(),
        });
    }
    let edges = mesh.n_edges();
    for (field, list) in [
        ("euclidean_flips", &claim.euclidean_flips),
        ("flips", &claim.flips),
    ] {
        if let Some((position, &index)) = list.iter().enumerate().find(|&(_, &i)| i >= edges) {
            return Err(SphereClaimError::FlipIndex {
                field,
                position,
                index,
                edges,
            });
        }
    }
    if claim.u.len() != mesh.n_vertices() {
        return Err(SphereClaimError::UCount {
            expected: mesh.n_vertices(),
            got: claim.u.len(),
        });
    }
    if claim.pole as usize >= mesh.n_vertices() {
        return Err(SphereClaimError::Pole {
            vertex: claim.pole,
            reason: format!(
                "out of range (the surface has {} vertices)",
                mesh.n_vertices()
            ),
        });
    }
    if claim.radius <= 0 {
        return Err(SphereClaimError::Radius(claim.radius.to_string()));
    }
    Ok(())
}

/// Re-check a `sphere_uniformization` claim about `surface` from scratch at `bits` (the
/// steps of the module documentation). `Undecided` outcomes carry the reason; malformed
/// claims are errors. Never a refutation. proof: B90
#[allow(clippy::too_many_lines)] // replay, pole, disk, certificate, in order
pub fn recheck(
    surface: &Surface,
    claim: &SphereClaim,
    bits: u32,
) -> Result<CertificateOutcome, SphereClaimError> {
    validate(surface, claim)?;
    let undecided = |reason: String| Ok(CertificateOutcome::Undecided { reason });
    let prec = Precision::new(u64::from(bits)).map_err(|_| SphereClaimError::Bits(bits))?;
    let mesh = &surface.mesh;
    let order = edge_order(mesh);
    let edge = |k: usize| Edge(order[k] as u32);
    // B73 (a): the Euclidean flips on enclosures of the exact input lengths.
    let euclidean: Vec<Edge> = claim.euclidean_flips.iter().map(|&k| edge(k)).collect();
    let (t0, l0) = match replay_enclosed(mesh, surface.lengths::<I>(prec), &euclidean) {
        Ok(x) => x,
        Err(reason) => return undecided(reason),
    };
    if let Err(e) = t0_delaunay_on_input(surface, &t0, &l0, &euclidean) {
        let k = order.iter().position(|&x| x == e.idx()).unwrap_or(e.idx());
        return undecided(format!(
            "edge {k} of T₀ is not certified intrinsic Delaunay for the surface's metric"
        ));
    }
    // The pole, the Ptolemy flips of the whole sphere (B93: edges at the pole included)
    // replayed formally on the enclosures (T28), and the disk T_F − star(v∞).
    let pole = Vertex(claim.pole);
    let pole_err = |reason| SphereClaimError::Pole {
        vertex: claim.pole,
        reason,
    };
    check_pole(&t0, pole).map_err(pole_err)?;
    let flips: Vec<Edge> = claim.flips.iter().map(|&k| edge(k)).collect();
    let (final_mesh, lf) = carry_lengths_from(&t0, l0, &flips).map_err(|e| match e {
        RefineError::Replay { index, .. } => SphereClaimError::Replay {
            position: index,
            index: claim.flips.get(index).copied().unwrap_or_default(),
        },
        _ => SphereClaimError::Replay {
            position: 0,
            index: claim.flips.first().copied().unwrap_or_default(),
        },
    })?;
    if !super::claim_form::same_faces(&final_mesh.face_list(), &claim.final_faces) {
        return Err(SphereClaimError::FinalFaces);
    }
    check_pole(&final_mesh, pole).map_err(pole_err)?;
    let mids: Vec<f64> = lf.iter().map(Real::approx_f64).collect();
    let disk = disk_of(&final_mesh, &mids, pole).map_err(pole_err)?;
    // u per disk vertex; null exactly at the pole and the link.
    let mut u = Vec::with_capacity(disk.vertex.len());
    if claim.u[pole.idx()].is_some() {
        return Err(SphereClaimError::UPattern {
            vertex: pole.idx(),
            what: "the pole has no scale factor in the disk problem: null expected",
        });
    }
    for (k, &v) in disk.vertex.iter().enumerate() {
        let v = v as usize;
        match (&claim.u[v], disk.pole_length[k].is_some()) {
            (Some(_), true) => {
                return Err(SphereClaimError::UPattern {
                    vertex: v,
                    what: "a link vertex of the pole has a fixed value −2 log ℓ: null expected",
                })
            }
            (None, false) => {
                return Err(SphereClaimError::UPattern {
                    vertex: v,
                    what: "a free vertex needs its scale factor",
                })
            }
            (x, _) => u.push(x.clone().unwrap_or_default()),
        }
    }
    let metric = DiskMetric::of(&final_mesh, &lf, &disk, pole);
    let data = DiskCertificateData {
        over_pi: vec![Rational::from(2); disk.vertex.len()],
        disk: disk.mesh,
        lengths: disk.lengths,
        pole_length: disk.pole_length,
        flip_sequence: Vec::new(),
        u,
        radius: claim.radius.clone(),
    };
    let outcome = check_disk_certificate_on(&data, Some(&metric), bits);
    if let CertificateOutcome::Holds { residual, .. } = &outcome {
        let enclosed = Rational::from_f64(*residual).unwrap_or_default();
        if enclosed > claim.residual_bound {
            return undecided(format!(
                "the enclosed residual {residual:e} is not below the claimed residual_bound {:e}",
                claim.residual_bound.to_f64()
            ));
        }
    }
    Ok(outcome)
}

/// The certificate of `sol` (solved from `surface`'s binary64 lengths, on `surface`'s
/// triangulation) as a claim: `data` gives the disk certificate's `u` and radius,
/// `residual_bound` the enclosed residual it reported.
pub fn claim_of(
    surface: &Surface,
    sol: &SphereUniformization,
    data: &DiskCertificateData,
    residual_bound: f64,
) -> SphereClaim {
    let order = edge_order(&surface.mesh);
    let mut user = vec![0usize; order.len()];
    for (k, &e) in order.iter().enumerate() {
        user[e] = k;
    }
    let mut u = vec![None; surface.mesh.n_vertices()];
    for (k, &v) in sol.disk.vertex.iter().enumerate() {
        if sol.disk.pole_length[k].is_none() {
            u[v as usize] = Some(data.u[k].clone());
        }
    }
    // Rounded up to a binary64 number, so that it is not below the enclosed residual.
    let bound = Rational::from_f64(residual_bound).unwrap_or_default();
    SphereClaim {
        euclidean_flips: sol
            .euclidean_sequence
            .iter()
            .map(|e| user[e.idx()])
            .collect(),
        pole: sol.pole,
        flips: sol.flip_sequence.iter().map(|e| user[e.idx()]).collect(),
        u,
        radius: data.radius.clone(),
        final_faces: sol.mesh.face_list(),
        residual_bound: bound,
    }
}

/// `claim` about `surface` as a `sphere_uniformization` claim document at `bits` (exact
/// decimal strings for `u`, `radius` and `residual_bound`).
pub fn to_json(surface: &Surface, claim: &SphereClaim, bits: u32) -> Value {
    let dec = |q: &Rational| exact_decimal(q).unwrap_or_else(|| q.to_string());
    let u: Vec<Value> = claim
        .u
        .iter()
        .map(|x| x.as_ref().map_or(Value::Null, |q| json!(dec(q))))
        .collect();
    json!({
        "penner_claim": 1,
        "kind": "sphere_uniformization",
        "max_bits": bits,
        "surface": to_value(surface),
        "euclidean_flips": claim.euclidean_flips,
        "pole": claim.pole,
        "flips": claim.flips,
        "u": u,
        "radius": dec(&claim.radius),
        "final_faces": claim.final_faces,
        "residual_bound": dec(&claim.residual_bound),
    })
}
