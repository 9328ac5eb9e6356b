//! Exact checks of a written parametrization, from the files alone (proof: B109): every
//! UV triangle positively oriented, and the triangles tile each input face (every
//! barycentric triangle positively oriented and their signed areas summing to exactly 1
//! per input face). The decimals are read exactly into ℚ; nothing is rounded.

use crate::scalar::parse::parse_rational;
use rug::Rational;
use serde_json::Value;
use std::collections::BTreeMap;

/// What the exact checks found.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ParametrizationReport {
    /// Triangles (0-based `f` lines).
    pub triangles: usize,
    /// Triangles whose UV triangle is not counterclockwise (folded or degenerate).
    pub uv_folds: Vec<usize>,
    /// Triangles whose barycentric triangle in their input face is not counterclockwise.
    pub input_folds: Vec<usize>,
    /// Input faces whose triangles' barycentric areas do not sum to 1 (or whose
    /// barycentric triples do not each sum to 1).
    pub untiled_faces: Vec<u64>,
}

impl ParametrizationReport {
    /// No fold on either side and every input face tiled.
    pub fn holds(&self) -> bool {
        self.uv_folds.is_empty() && self.input_folds.is_empty() && self.untiled_faces.is_empty()
    }
}

/// Why the files could not be read.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ParametrizationError {
    /// A malformed OBJ line.
    #[error("OBJ line {0}: {1}")]
    Obj(usize, String),
    /// A malformed sidecar.
    #[error("sidecar: {0}")]
    Sidecar(String),
}

fn orient(a: &[Rational; 2], b: &[Rational; 2], c: &[Rational; 2]) -> Rational {
    let (ux, uy) = (Rational::from(&b[0] - &a[0]), Rational::from(&b[1] - &a[1]));
    let (vx, vy) = (Rational::from(&c[0] - &a[0]), Rational::from(&c[1] - &a[1]));
    ux * vy - uy * vx
}

/// The 3×3 determinant of barycentric rows: the signed area of the triangle as a fraction
/// of its face's.
fn det3(m: &[[Rational; 3]; 3]) -> Rational {
    let minor = |a: usize, b: usize, c: usize, d: usize| {
        Rational::from(&m[1][a] * &m[2][b]) - Rational::from(&m[1][c] * &m[2][d])
    };
    Rational::from(&m[0][0] * &minor(1, 2, 2, 1)) - Rational::from(&m[0][1] * &minor(0, 2, 2, 0))
        + Rational::from(&m[0][2] * &minor(0, 1, 1, 0))
}

fn number(word: Option<&str>, line: usize) -> Result<Rational, ParametrizationError> {
    let w = word.ok_or_else(|| ParametrizationError::Obj(line, "missing number".into()))?;
    parse_rational(w).map_err(|e| ParametrizationError::Obj(line, e.to_string()))
}

/// The triangles of an OBJ text: per `f` line its vertex indices and its `vt` indices
/// (0-based), and the `vt` coordinates read exactly (each once).
pub(crate) struct UvFaces {
    /// The `vt` lines, read exactly.
    pub vt: Vec<[Rational; 2]>,
    /// Per `f` line: vertex indices and `vt` indices.
    pub faces: Vec<([usize; 3], [usize; 3])>,
}

impl UvFaces {
    /// The texture coordinates of the corners of triangle `k`.
    pub fn uv(&self, k: usize) -> [&[Rational; 2]; 3] {
        self.faces[k].1.map(|t| &self.vt[t])
    }
}

/// The `f` lines of an OBJ text with their texture coordinates, read exactly.
pub(crate) fn uv_faces(obj: &str) -> Result<UvFaces, ParametrizationError> {
    let mut vt = Vec::new();
    let mut faces = Vec::new();
    for (k, line) in obj.lines().enumerate() {
        let mut w = line.split_whitespace();
        match w.next() {
            Some("vt") => vt.push([number(w.next(), k + 1)?, number(w.next(), k + 1)?]),
            Some("f") => {
                let mut c = Vec::with_capacity(3);
                for word in w {
                    let bad = || ParametrizationError::Obj(k + 1, format!("not v/vt: {word:?}"));
                    let mut parts = word.split('/');
                    let v = parts
                        .next()
                        .and_then(|x| x.parse::<usize>().ok())
                        .and_then(|i| i.checked_sub(1))
                        .ok_or_else(bad)?;
                    let t = parts
                        .next()
                        .and_then(|x| x.parse::<usize>().ok())
                        .and_then(|i| i.checked_sub(1))
                        .filter(|&i| i < vt.len())
                        .ok_or_else(bad)?;
                    c.push((v, t));
                }
                let [(a, ta), (b, tb), (c, tc)]: [(usize, usize); 3] = c
                    .try_into()
                    .map_err(|_| ParametrizationError::Obj(k + 1, "not a triangle".into()))?;
                faces.push(([a, b, c], [ta, tb, tc]));
            }
            _ => {}
        }
    }
    Ok(UvFaces { vt, faces })
}

/// The orientation of every UV triangle of an OBJ text, decided exactly on its decimals.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct UvOrientation {
    /// Triangles (0-based `f` lines).
    pub triangles: usize,
    /// Triangles whose UV triangle is clockwise (folded).
    pub clockwise: Vec<usize>,
    /// Triangles whose UV triangle has zero area.
    pub degenerate: Vec<usize>,
}

/// The exact orientation of the UV triangles of any OBJ text with `f v/vt` triangles, such
/// as one written by another tool (the fold test of B109 without a sidecar): the sign of
/// `(b − a) × (c − a)` in ℚ on the written decimals.
///
/// ```
/// use penner::overlay::check::uv_orientation;
/// let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\nf 1/1 3/3 2/2\n";
/// let o = uv_orientation(obj).unwrap();
/// assert_eq!((o.triangles, o.clockwise, o.degenerate), (2, vec![1], vec![]));
/// ```
pub fn uv_orientation(obj: &str) -> Result<UvOrientation, ParametrizationError> {
    let mut o = UvOrientation::default();
    let uv = uv_faces(obj)?;
    for k in 0..uv.faces.len() {
        let t = uv.uv(k);
        match orient(t[0], t[1], t[2]).cmp0() {
            std::cmp::Ordering::Less => o.clockwise.push(k),
            std::cmp::Ordering::Equal => o.degenerate.push(k),
            std::cmp::Ordering::Greater => {}
        }
        o.triangles += 1;
    }
    Ok(o)
}

/// One sidecar face: its input face and the decimal strings of its barycentric rows.
type FaceRows<'a> = (u64, [[&'a str; 3]; 3]);

/// Check the OBJ text `obj` and its `sidecar` exactly (module documentation).
pub fn check_parametrization(
    obj: &str,
    sidecar: &Value,
) -> Result<ParametrizationReport, ParametrizationError> {
    let side = |m: &str| ParametrizationError::Sidecar(m.into());
    let faces = sidecar["faces"]
        .as_array()
        .ok_or_else(|| side("no faces array"))?;
    let rows = faces
        .iter()
        .map(|f| -> Result<FaceRows<'_>, ParametrizationError> {
            let input = f["input_face"]
                .as_u64()
                .ok_or_else(|| side("a face without input_face"))?;
            let rows = f["barycentric"]
                .as_array()
                .filter(|r| r.len() == 3)
                .ok_or_else(|| side("a face without three barycentric rows"))?;
            let mut m = [[""; 3]; 3];
            for (i, row) in rows.iter().enumerate() {
                let row = row
                    .as_array()
                    .filter(|r| r.len() == 3)
                    .ok_or_else(|| side("a barycentric row of other than three numbers"))?;
                for (j, x) in row.iter().enumerate() {
                    m[i][j] = x.as_str().ok_or_else(|| {
                        side("a barycentric coordinate that is not a decimal string")
                    })?;
                }
            }
            Ok((input, m))
        });
    let n_input = sidecar["input_faces"]
        .as_u64()
        .ok_or_else(|| side("no input_faces count"))?;
    check_rows(obj, faces.len(), rows, n_input)
}

/// The sidecar as read from its text, without building a JSON value (the strings borrowed).
#[derive(serde::Deserialize)]
struct SidecarText<'a> {
    input_faces: u64,
    #[serde(borrow)]
    faces: Vec<FaceText<'a>>,
}

/// One face of [`SidecarText`].
#[derive(serde::Deserialize)]
struct FaceText<'a> {
    input_face: u64,
    #[serde(borrow)]
    barycentric: [[&'a str; 3]; 3],
}

/// [`check_parametrization`] from the sidecar's text, read into borrowed strings instead of
/// a JSON value (the same checks and report; much less memory on large meshes).
pub fn check_parametrization_text(
    obj: &str,
    sidecar: &str,
) -> Result<ParametrizationReport, ParametrizationError> {
    let s: SidecarText<'_> =
        serde_json::from_str(sidecar).map_err(|e| ParametrizationError::Sidecar(e.to_string()))?;
    let rows = s.faces.iter().map(|f| Ok((f.input_face, f.barycentric)));
    check_rows(obj, s.faces.len(), rows, s.input_faces)
}

/// The checks on the OBJ's triangles and the sidecar's rows, `n_faces` of them.
fn check_rows<'a>(
    obj: &str,
    n_faces: usize,
    rows: impl Iterator<Item = Result<FaceRows<'a>, ParametrizationError>>,
    n_input: u64,
) -> Result<ParametrizationReport, ParametrizationError> {
    let side = |m: &str| ParametrizationError::Sidecar(m.into());
    let uv = uv_faces(obj)?;
    if n_faces != uv.faces.len() {
        return Err(ParametrizationError::Sidecar(format!(
            "faces: {} entries, but the OBJ has {} f lines",
            n_faces,
            uv.faces.len()
        )));
    }
    let mut report = ParametrizationReport {
        triangles: uv.faces.len(),
        ..Default::default()
    };
    let mut area: BTreeMap<u64, Rational> = BTreeMap::new();
    let mut broken: Vec<u64> = Vec::new();
    for (k, row) in rows.enumerate() {
        let (input, text) = row?;
        let t = uv.uv(k);
        if orient(t[0], t[1], t[2]).cmp0().is_le() {
            report.uv_folds.push(k);
        }
        let mut m: [[Rational; 3]; 3] = Default::default();
        for (i, row) in text.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                m[i][j] = parse_rational(x).map_err(|e| side(&e.to_string()))?;
            }
            let sum = Rational::from(&m[i][0] + &m[i][1]) + &m[i][2];
            if sum != 1 {
                broken.push(input);
            }
        }
        let d = det3(&m);
        if d.cmp0().is_le() {
            report.input_folds.push(k);
        }
        *area.entry(input).or_default() += d;
    }
    for f in 0..n_input {
        area.entry(f).or_default();
    }
    report.untiled_faces = area
        .into_iter()
        .filter(|(_, a)| *a != 1)
        .map(|(f, _)| f)
        .chain(broken)
        .collect();
    report.untiled_faces.sort_unstable();
    report.untiled_faces.dedup();
    Ok(report)
}
