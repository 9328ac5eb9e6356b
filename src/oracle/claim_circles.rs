//! Parsing the claim kinds `circle_packing` and `circle_pattern` (protocol v1,
//! `schema/claim-v1.schema.json`, docs/oracle.md). Both concern the combinatorics of the
//! surface only: its metric is not read and may be left out.

use super::assertion::Assertion;
pub use super::assertion::Packing;
use super::claim_parse::{epsilon, err, numbers, ClaimError};
use crate::circles::maximal::check_simplicial;
use crate::circles::maximal::sphere::ExactCap;
use crate::circles::maximal::tangency::ExactCircle;
use crate::io::json::{exact_number, from_value};
use crate::io::Surface;
use rug::Rational;
use serde_json::Value;

/// The claim's `surface`; without `lengths`, `squared_lengths` and `positions` it gets unit
/// lengths (any metric would do: these kinds read only the triangulation).
pub fn triangulation(v: &Value) -> Result<Surface, ClaimError> {
    let s = v
        .get("surface")
        .ok_or_else(|| err("surface: required (the triangulation the claim is about)"))?;
    let has_metric = ["lengths", "squared_lengths", "positions"]
        .iter()
        .any(|k| s.get(k).is_some());
    let read = |s: &Value| from_value(s).map_err(|e| err(format!("surface: {e}")));
    match (has_metric, s.get("faces").and_then(Value::as_array)) {
        (false, Some(faces)) => {
            let mut with = s.clone();
            with["lengths"] = Value::Array(vec![
                Value::Array(vec![Value::String("1".into()); 3]);
                faces.len()
            ]);
            read(&with)
        }
        _ => read(s),
    }
}

/// The fields of a `circle_packing` or `circle_pattern` claim on `surface`.
pub fn parse(v: &Value, kind: &str, surface: &Surface) -> Result<Assertion, ClaimError> {
    let mesh = &surface.mesh;
    let n = mesh.n_vertices();
    if kind == "circle_pattern" {
        let phi = numbers(
            field(v, "phi_over_pi")?,
            "phi_over_pi",
            mesh.n_edges(),
            "edge",
        )?;
        let half = Rational::from((1, 2));
        if let Some((e, q)) = phi.iter().enumerate().find(|(_, q)| **q < 0 || **q > half) {
            return Err(err(format!(
                "phi_over_pi[{e}]: {q} is outside [0, 1/2] (intersection angles in [0, π/2])"
            )));
        }
        return Ok(Assertion::CirclePattern {
            radii: radii(v, n)?,
            phi_over_pi: phi,
            angles: numbers(field(v, "angles")?, "angles", n, "vertex")?,
            epsilon: epsilon(v)?,
        });
    }
    check_simplicial(mesh).map_err(|e| err(format!("surface: {e}")))?;
    let packing = match (v.get("caps"), v.get("centres"), v.get("radii")) {
        (Some(c), None, None) => Packing::Sphere(caps(c, n)?),
        (None, Some(c), Some(_)) => {
            let r = radii(v, n)?;
            let centres = pairs(c, n)?;
            Packing::Plane(
                centres
                    .into_iter()
                    .zip(r)
                    .map(|(centre, radius)| ExactCircle { centre, radius })
                    .collect(),
            )
        }
        _ => {
            return Err(err(
                "centres, radii, caps: give centres and radii (circles in the plane) or caps (on the sphere)",
            ))
        }
    };
    Ok(Assertion::CirclePacking {
        packing,
        epsilon: epsilon(v)?,
    })
}

fn field<'a>(v: &'a Value, key: &str) -> Result<&'a Value, ClaimError> {
    v.get(key)
        .ok_or_else(|| err(format!("{key}: required for this claim kind")))
}

/// `radii`: one positive number per vertex.
fn radii(v: &Value, n: usize) -> Result<Vec<Rational>, ClaimError> {
    let r = numbers(field(v, "radii")?, "radii", n, "vertex")?;
    if let Some((i, q)) = r.iter().enumerate().find(|(_, q)| q.cmp0().is_le()) {
        return Err(err(format!("radii[{i}]: must be positive, found {q}")));
    }
    Ok(r)
}

fn array<'a>(v: &'a Value, path: &str, n: usize) -> Result<&'a Vec<Value>, ClaimError> {
    let a = v.as_array().ok_or_else(|| {
        err(format!(
            "{path}: expected an array with one entry per vertex"
        ))
    })?;
    if a.len() != n {
        return Err(err(format!(
            "{path}: {} entries, but the surface has {n} vertex(s)",
            a.len()
        )));
    }
    Ok(a)
}

/// Exactly `k` numbers at `path`.
fn tuple(v: &Value, path: &str, k: usize) -> Result<Vec<Rational>, ClaimError> {
    let a = v
        .as_array()
        .filter(|a| a.len() == k)
        .ok_or_else(|| err(format!("{path}: expected an array of {k} numbers")))?;
    a.iter()
        .enumerate()
        .map(|(i, x)| exact_number(x, &format!("{path}[{i}]")).map_err(ClaimError::from))
        .collect()
}

/// `centres`: one `[x, y]` per vertex.
fn pairs(v: &Value, n: usize) -> Result<Vec<[Rational; 2]>, ClaimError> {
    array(v, "centres", n)?
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let [x, y]: [Rational; 2] = tuple(p, &format!("centres[{i}]"), 2)?
                .try_into()
                .map_err(|_| err(format!("centres[{i}]: expected [x, y]")))?;
            Ok([x, y])
        })
        .collect()
}

/// `caps`: one `{"normal": [x, y, z], "height": h}` per vertex with `|N|² > h²`.
fn caps(v: &Value, n: usize) -> Result<Vec<ExactCap>, ClaimError> {
    array(v, "caps", n)?
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let path = format!("caps[{i}]");
            let obj = c.as_object().ok_or_else(|| {
                err(format!(
                    "{path}: expected {{\"normal\": [x, y, z], \"height\": h}}"
                ))
            })?;
            if let Some(k) = obj.keys().find(|k| *k != "normal" && *k != "height") {
                return Err(err(format!(
                    "{path}.{k}: unknown field (a cap has normal, height)"
                )));
            }
            let normal: [Rational; 3] = tuple(
                obj.get("normal")
                    .ok_or_else(|| err(format!("{path}.normal: required")))?,
                &format!("{path}.normal"),
                3,
            )?
            .try_into()
            .map_err(|_| err(format!("{path}.normal: expected [x, y, z]")))?;
            let height = exact_number(
                obj.get("height")
                    .ok_or_else(|| err(format!("{path}.height: required")))?,
                &format!("{path}.height"),
            )?;
            let nn = normal
                .iter()
                .fold(Rational::new(), |acc, x| acc + Rational::from(x * x));
            if nn <= Rational::from(&height * &height) {
                return Err(err(format!(
                    "{path}: not a proper cap (|normal|² ≤ height²: empty or the whole sphere)"
                )));
            }
            Ok(ExactCap { normal, height })
        })
        .collect()
}
