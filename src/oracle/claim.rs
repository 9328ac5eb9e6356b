//! The claim protocol, version 1: what another implementation asserts about a surface,
//! parsed from JSON (`schema/claim-v1.schema.json`, `docs/oracle.md`).

pub use super::assertion::Assertion;
pub use super::claim_parse::ClaimError;
use super::claim_parse::{edge_indices, epsilon, err, numbers};
use crate::io::json::{exact_number, from_value};
use crate::io::strict_json::{self, JsonError};
use crate::io::Surface;
use rug::Rational;
use serde_json::Value;

/// The protocol version this build reads and answers.
pub const PROTOCOL_VERSION: u64 = 1;

/// Largest MPFR precision a claim may ask the ladder to climb to.
pub const MAX_CLAIM_BITS: u32 = 1 << 14;

/// A parsed claim.
#[derive(Clone, Debug, PartialEq)]
pub struct Claim {
    /// Optional identifier, echoed in the answer.
    pub id: Option<String>,
    /// The surface the claim is about; for `lobachevsky` claims, which concern no surface,
    /// the regular tetrahedron as a placeholder that no evaluation reads.
    pub surface: Surface,
    /// What is claimed.
    pub assertion: Assertion,
    /// Highest MPFR precision the ladder may use (default 1024).
    pub max_bits: u32,
}

/// Read the surface at field `key` of the claim.
fn surface_at(v: &Value, key: &str, what: &str) -> Result<Surface, ClaimError> {
    let s = v
        .get(key)
        .ok_or_else(|| err(format!("{key}: required ({what})")))?;
    from_value(s).map_err(|e| err(format!("{key}: {e}")))
}

/// The fields every claim may carry.
const COMMON_FIELDS: [&str; 5] = ["penner_claim", "id", "kind", "surface", "max_bits"];

/// The claim kinds and the fields each may carry besides [`COMMON_FIELDS`]
/// (`schema/claim-v1.schema.json`).
const KIND_FIELDS: [(&str, &[&str]); 13] = [
    ("intrinsic_delaunay", &[]),
    ("delaunay_flip", &["flips", "result", "epsilon"]),
    ("cone_angles", &["angles", "epsilon"]),
    ("cotan_laplacian", &["weights", "epsilon"]),
    ("conformal_equivalence", &["target", "u", "epsilon"]),
    ("energy", &["u", "targets", "energy", "gradient", "epsilon"]),
    ("lobachevsky", &["x", "y", "epsilon"]),
    (
        "uniformization",
        &[
            "euclidean_flips",
            "targets",
            "flips",
            "u",
            "radius",
            "final_faces",
            "residual_bound",
        ],
    ),
    (
        "sphere_uniformization",
        &[
            "euclidean_flips",
            "pole",
            "flips",
            "u",
            "radius",
            "final_faces",
            "residual_bound",
        ],
    ),
    (
        "hyperbolic_uniformization",
        &["targets", "flips", "u", "radius", "residual_bound"],
    ),
    ("circle_packing", &["centres", "radii", "caps", "epsilon"]),
    ("parametrization", &["obj", "sidecar", "seam_epsilon"]),
    (
        "circle_pattern",
        &["radii", "phi_over_pi", "angles", "epsilon"],
    ),
];

/// The placeholder surface of claims about no surface (see [`Claim::surface`]).
fn no_surface() -> Result<Surface, ClaimError> {
    Surface::from_embedded("no surface", crate::mesh::builders::tetrahedron())
        .map_err(|e| err(format!("internal placeholder surface: {e}")))
}

/// A `lobachevsky` claim (fields already checked): `x`, `y`, `epsilon`, no surface.
fn lobachevsky_claim(v: &Value, id: Option<String>, max_bits: u32) -> Result<Claim, ClaimError> {
    if v.get("surface").is_some() {
        return Err(err(
            "surface: not a field of lobachevsky claims (they concern no surface)",
        ));
    }
    Ok(Claim {
        id,
        surface: no_surface()?,
        assertion: Assertion::Lobachevsky {
            x: number_at(v, "x")?,
            y: number_at(v, "y")?,
            epsilon: epsilon(v)?,
        },
        max_bits,
    })
}

fn number_at(v: &Value, key: &str) -> Result<Rational, ClaimError> {
    let x = v
        .get(key)
        .ok_or_else(|| err(format!("{key}: required for this claim kind")))?;
    Ok(exact_number(x, key)?)
}

/// Refuse any field a claim of `kind` does not have: a misspelt optional field (say
/// `epsilom`) would otherwise be ignored and its default answer a different question.
fn check_fields(
    obj: &serde_json::Map<String, Value>,
    kind: &str,
    own: &[&str],
) -> Result<(), ClaimError> {
    let allowed = || -> String {
        COMMON_FIELDS
            .iter()
            .chain(own)
            .copied()
            .collect::<Vec<_>>()
            .join(", ")
    };
    for key in obj.keys() {
        let key = key.as_str();
        if COMMON_FIELDS.contains(&key) || own.contains(&key) {
            continue;
        }
        let of_other_kind = KIND_FIELDS.iter().any(|(_, f)| f.contains(&key));
        let what = if of_other_kind {
            format!("not a field of {kind} claims")
        } else {
            "unknown field".to_string()
        };
        return Err(err(format!(
            "{key}: {what} (a {kind} claim has {})",
            allowed()
        )));
    }
    Ok(())
}

/// Parse a claim document (JSON text); `name` names the source in messages. A repeated
/// key in any object is refused ([`crate::io::strict_json`]), as is a field the claim's
/// kind does not have.
pub fn parse(text: &str, name: &str) -> Result<Claim, ClaimError> {
    let v = strict_json::parse(text).map_err(|e| match e {
        JsonError::Syntax(e) => err(format!("{name}:{}:{}: {e}", e.line(), e.column())),
        JsonError::DuplicateKey(d) => err(format!("{name}: {d}")),
    })?;
    parse_value(&v).map_err(|e| err(format!("{name}: {e}")))
}

/// The fields of an `energy` claim on a surface with `n` vertices.
fn parse_energy(v: &Value, n: usize) -> Result<Assertion, ClaimError> {
    let targets = match v.get("targets") {
        None => None,
        Some(t) => Some(numbers(t, "targets", n, "vertex")?),
    };
    let energy = exact_number(
        v.get("energy")
            .ok_or_else(|| err("energy: required, the claimed E(u)"))?,
        "energy",
    )?;
    Ok(Assertion::Energy {
        u: numbers(&v["u"], "u", n, "vertex")?,
        targets,
        energy,
        gradient: numbers(&v["gradient"], "gradient", n, "vertex")?,
        epsilon: epsilon(v)?,
    })
}

/// Parse a claim document (JSON value); a field the claim's kind does not have is refused.
#[allow(clippy::too_many_lines)] // the common fields, then one arm per claim kind
pub fn parse_value(v: &Value) -> Result<Claim, ClaimError> {
    let Some(obj) = v.as_object() else {
        return Err(err("a claim is a JSON object"));
    };
    match v.get("penner_claim").and_then(Value::as_u64) {
        Some(PROTOCOL_VERSION) => {}
        Some(other) => {
            return Err(err(format!(
                "penner_claim: protocol version {other} is not supported (this build speaks version {PROTOCOL_VERSION})"
            )))
        }
        None => return Err(err(format!("penner_claim: required, the protocol version ({PROTOCOL_VERSION})"))),
    }
    let id = match v.get("id") {
        None | Some(Value::Null) => None,
        Some(Value::String(s)) => Some(s.clone()),
        Some(other) => return Err(err(format!("id: expected a string, found {other}"))),
    };
    let max_bits = match v.get("max_bits") {
        None => 1024,
        Some(b) => b
            .as_u64()
            .filter(|&b| (128..=u64::from(MAX_CLAIM_BITS)).contains(&b))
            .ok_or_else(|| {
                err(format!(
                    "max_bits: expected an integer in [128, {MAX_CLAIM_BITS}], found {b}"
                ))
            })? as u32,
    };
    let kind = v
        .get("kind")
        .and_then(Value::as_str)
        .ok_or_else(|| err("kind: required, one of intrinsic_delaunay, delaunay_flip, cone_angles, cotan_laplacian, conformal_equivalence, energy, lobachevsky, uniformization, sphere_uniformization, hyperbolic_uniformization, circle_packing, circle_pattern, parametrization"))?;
    let Some((_, own)) = KIND_FIELDS.iter().find(|(k, _)| *k == kind) else {
        return Err(err(format!("kind: unknown claim kind {kind:?}")));
    };
    check_fields(obj, kind, own)?;
    if kind == "lobachevsky" {
        return lobachevsky_claim(v, id, max_bits);
    }
    if kind == "circle_packing" || kind == "circle_pattern" {
        let surface = super::claim_circles::triangulation(v)?;
        let assertion = super::claim_circles::parse(v, kind, &surface)?;
        return Ok(Claim {
            id,
            surface,
            assertion,
            max_bits,
        });
    }
    let surface = surface_at(v, "surface", "the surface the claim is about")?;
    let assertion = match kind {
        "intrinsic_delaunay" => Assertion::IntrinsicDelaunay,
        "delaunay_flip" => {
            let ptolemy = match v.get("flips").and_then(Value::as_str) {
                Some("euclidean") => false,
                Some("ptolemy") => true,
                _ => return Err(err("flips: required, \"euclidean\" or \"ptolemy\"")),
            };
            let result = surface_at(v, "result", "the claimed Delaunay surface")?;
            let epsilon = match v.get("epsilon") {
                None => Rational::new(),
                Some(_) => epsilon(v)?,
            };
            Assertion::DelaunayFlip {
                ptolemy,
                result,
                epsilon,
            }
        }
        "cone_angles" => Assertion::ConeAngles {
            angles: numbers(&v["angles"], "angles", surface.mesh.n_vertices(), "vertex")?,
            epsilon: epsilon(v)?,
        },
        "cotan_laplacian" => Assertion::CotanLaplacian {
            weights: numbers(&v["weights"], "weights", surface.mesh.n_edges(), "edge")?,
            epsilon: epsilon(v)?,
        },
        "conformal_equivalence" => {
            let target = surface_at(v, "target", "the second metric")?;
            if target.mesh != surface.mesh {
                return Err(err(
                    "target: must have the same triangulation (vertices, faces, gluing) as surface",
                ));
            }
            Assertion::ConformalEquivalence {
                u: numbers(&v["u"], "u", surface.mesh.n_vertices(), "vertex")?,
                epsilon: epsilon(v)?,
                target,
            }
        }
        "uniformization" => uniformization_claim(v, &surface)?,
        "sphere_uniformization" => sphere_claim(v, &surface)?,
        "hyperbolic_uniformization" => {
            super::claim_hyperbolic::parse(v, &surface).map(Assertion::HyperbolicUniformization)?
        }
        "energy" => parse_energy(v, surface.mesh.n_vertices())?,
        "parametrization" => parametrization_claim(v, &surface)?,
        other => return Err(err(format!("kind: unknown claim kind {other:?}"))),
    };
    Ok(Claim {
        id,
        surface,
        assertion,
        max_bits,
    })
}

/// The array of vertex triples at `final_faces`.
fn final_faces(v: &Value) -> Result<Vec<[u32; 3]>, ClaimError> {
    v.get("final_faces")
        .ok_or_else(|| err("final_faces: required"))?
        .as_array()
        .ok_or_else(|| err("final_faces: expected an array of vertex triples"))?
        .iter()
        .enumerate()
        .map(|(k, f)| {
            let t = f.as_array().filter(|t| t.len() == 3);
            let ids: Option<Vec<u32>> = t.and_then(|t| {
                t.iter()
                    .map(|x| x.as_u64().and_then(|i| u32::try_from(i).ok()))
                    .collect()
            });
            ids.map(|i| [i[0], i[1], i[2]])
                .ok_or_else(|| err(format!("final_faces[{k}]: expected three vertex ids")))
        })
        .collect()
}

/// The fields of a `sphere_uniformization` claim.
fn sphere_claim(v: &Value, surface: &Surface) -> Result<Assertion, ClaimError> {
    let required = |key: &str| v.get(key).ok_or_else(|| err(format!("{key}: required")));
    let pole = required("pole")?
        .as_u64()
        .and_then(|p| u32::try_from(p).ok())
        .ok_or_else(|| err("pole: expected a vertex id"))?;
    let u = required("u")?
        .as_array()
        .ok_or_else(|| err("u: expected an array with one entry per vertex"))?
        .iter()
        .enumerate()
        .map(|(i, x)| match x {
            Value::Null => Ok(None),
            x => exact_number(x, &format!("u[{i}]"))
                .map(Some)
                .map_err(ClaimError::from),
        })
        .collect::<Result<Vec<_>, _>>()?;
    let claim = crate::uniformization::sphere_claim::SphereClaim {
        euclidean_flips: edge_indices(v, "euclidean_flips")?,
        pole,
        flips: edge_indices(v, "flips")?,
        u,
        radius: exact_number(required("radius")?, "radius")?,
        final_faces: final_faces(v)?,
        residual_bound: exact_number(required("residual_bound")?, "residual_bound")?,
    };
    crate::uniformization::sphere_claim::validate(surface, &claim)
        .map_err(|e| err(e.to_string()))?;
    Ok(Assertion::SphereUniformization(claim))
}

/// The fields of a `uniformization` claim.
fn uniformization_claim(v: &Value, surface: &Surface) -> Result<Assertion, ClaimError> {
    let n = surface.mesh.n_vertices();
    let required = |key: &str| v.get(key).ok_or_else(|| err(format!("{key}: required")));
    let flips = edge_indices(v, "flips")?;
    let final_faces = final_faces(v)?;
    let radius = exact_number(required("radius")?, "radius")?;
    let residual_bound = exact_number(required("residual_bound")?, "residual_bound")?;
    let claim = crate::uniformization::claim_form::UniformizationClaim {
        targets_over_pi: numbers(required("targets")?, "targets", n, "vertex")?,
        flips,
        u: numbers(required("u")?, "u", n, "vertex")?,
        radius,
        final_faces,
        residual_bound,
        euclidean_flips: v
            .get("euclidean_flips")
            .map(|_| edge_indices(v, "euclidean_flips"))
            .transpose()?,
    };
    crate::uniformization::claim_form::validate(surface, &claim).map_err(|e| err(e.to_string()))?;
    Ok(Assertion::Uniformization(claim))
}

/// The fields of a `parametrization` claim: `obj` (the OBJ text), `sidecar` (its JSON),
/// and the optional `seam_epsilon` (a relative tolerance ≥ 0; present: the seams are
/// claimed too). Files that cannot be read, or do not fit the surface, are refused here,
/// naming the OBJ line or the sidecar element.
fn parametrization_claim(v: &Value, surface: &Surface) -> Result<Assertion, ClaimError> {
    let obj = v
        .get("obj")
        .ok_or_else(|| err("obj: required, the text of the UV OBJ file"))?
        .as_str()
        .ok_or_else(|| err("obj: expected a string, the text of the UV OBJ file"))?
        .to_string();
    let sidecar = v
        .get("sidecar")
        .filter(|s| s.is_object())
        .ok_or_else(|| err("sidecar: required, the JSON object of the OBJ's sidecar"))?
        .clone();
    let seam_epsilon = match v.get("seam_epsilon") {
        None => None,
        Some(x) => {
            let e = exact_number(x, "seam_epsilon")?;
            if e.cmp0() == std::cmp::Ordering::Less {
                return Err(err(format!("seam_epsilon: must be ≥ 0, found {e}")));
            }
            Some(e)
        }
    };
    let claim = crate::overlay::claim::ParametrizationClaim {
        obj,
        sidecar,
        seam_epsilon,
    };
    crate::overlay::claim::validate(surface, &claim).map_err(|e| err(e.to_string()))?;
    Ok(Assertion::Parametrization(claim))
}
