//! Parsing the claim kind `hyperbolic_uniformization` (protocol v1,
//! `schema/claim-v1.schema.json`, docs/oracle.md; the claim and its re-check:
//! [`crate::uniformization::hyperbolic_claim`]).

use super::claim_parse::{edge_indices, err, numbers, ClaimError};
use crate::io::json::exact_number;
use crate::io::Surface;
use crate::uniformization::hyperbolic_claim::{validate, HyperbolicClaim};
use serde_json::Value;

/// The fields of a `hyperbolic_uniformization` claim about `surface`, checked
/// ([`validate`]): malformed fields are errors naming the field. `flips` is optional (a
/// claim without it is the fixed-triangulation claim).
pub fn parse(v: &Value, surface: &Surface) -> Result<HyperbolicClaim, ClaimError> {
    let n = surface.mesh.n_vertices();
    let required = |key: &str| v.get(key).ok_or_else(|| err(format!("{key}: required")));
    let claim = HyperbolicClaim {
        targets_over_pi: numbers(required("targets")?, "targets", n, "vertex")?,
        u: numbers(required("u")?, "u", n, "vertex")?,
        radius: exact_number(required("radius")?, "radius")?,
        residual_bound: exact_number(required("residual_bound")?, "residual_bound")?,
        flips: match v.get("flips") {
            None => None,
            Some(_) => Some(edge_indices(v, "flips")?),
        },
    };
    validate(&surface.mesh, &claim).map_err(|e| err(e.to_string()))?;
    Ok(claim)
}
