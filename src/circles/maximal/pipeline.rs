//! The Koebe–Andreev–Thurston maximal packing (T11) as one library call, the pipeline
//! behind `penner pack --disk | --sphere`: computed at the working precision of B99,
//! tangency certified within `ε` (B95, B96) by exact predicates on the exact values of the
//! computed circles, refined at twice the bits up to [`MAX_BITS`] while the computed
//! packing misses `ε`. The packing exists, so a miss is `undecided` (a limit of the
//! computation), never `fails`.
//!
//! ```
//! use penner::circles::maximal::pipeline::{pack_maximal, PackOptions};
//! use penner::circles::maximal::tangency::PackingVerdict;
//! use penner::mesh::builders;
//! use penner::scalar::parse_rational;
//! // The octahedron punctured at v0, packed on the sphere within ε = 10⁻²⁰ at 128 bits.
//! let mesh = builders::octahedron().mesh;
//! let options = PackOptions {
//!     sphere: true,
//!     puncture: 0,
//!     bits: 128,
//!     epsilon: parse_rational("1e-20").unwrap(),
//! };
//! let out = pack_maximal(&mesh, "octahedron", &options).unwrap();
//! assert!(matches!(out.verdict, PackingVerdict::Holds { .. }));
//! assert_eq!(out.caps.as_ref().map(Vec::len), Some(6));
//! ```

use super::layout::Circle;
use super::sphere::{check_sphere_packing, exact_caps, Cap, ExactCap};
use super::stopping::bits_for;
use super::svg::{render_disk_svg, render_sphere_svg};
use super::tangency::{check_packing, exact_circles, ExactCircle, PackingVerdict};
use super::Options as Opts;
use super::{maximal_disk, maximal_disk_within, maximal_sphere, DiskPacking, MaximalError};
use crate::mesh::Mesh;
use crate::scalar::{Mpfr, Precision, Real};
use rug::Rational;
use serde_json::{json, Value};
use std::fmt::Write as _;

/// What is packed and how.
#[derive(Clone, Debug, PartialEq)]
pub struct PackOptions {
    /// On the sphere (punctured at `puncture`); else in the unit disk.
    pub sphere: bool,
    /// The puncture vertex of a sphere.
    pub puncture: usize,
    /// MPFR bits (53: binary64, no refinement).
    pub bits: u32,
    /// The tangency tolerance `ε ≥ 0` (0 cannot be certified).
    pub epsilon: Rational,
}

/// Errors of [`pack_maximal`]: the input refused, or valid input the computation does not
/// reach (no interior vertex, a solver or layout failure: not computed, undecided).
#[derive(Debug, thiserror::Error)]
pub enum PackError {
    /// The surface or an option is refused.
    #[error("{0}")]
    Input(String),
    /// Valid input that this computation does not reach.
    #[error("{0}")]
    NotComputed(String),
}

/// The outcome of [`pack_maximal`].
#[derive(Clone, Debug)]
pub struct PackOutcome {
    /// The disk packing (of the punctured sphere for `sphere`) at the bits reached.
    pub disk: DiskPacking<Mpfr>,
    /// The caps on the sphere, exact (for `sphere`).
    pub caps: Option<Vec<ExactCap>>,
    /// The working precision reached.
    pub bits: u32,
    /// The exact values of the computed circles.
    pub circles: Vec<ExactCircle>,
    /// Per vertex, whether its circle is internally tangent to the unit circle.
    pub unit_disk: Vec<bool>,
    /// The verdict on the computed packing (never `Fails`: see the module documentation).
    pub verdict: PackingVerdict,
}

impl PackOutcome {
    /// The JSON document of `penner pack -o` (`status` the verdict's word, `epsilon` as
    /// the user wrote it).
    pub fn document(&self, options: &PackOptions, epsilon: &str) -> Value {
        let status = match self.verdict {
            PackingVerdict::Holds { .. } => "holds",
            PackingVerdict::Fails(_) => "fails",
            PackingVerdict::Undecided(_) => "undecided",
        };
        let mut doc = json!({
            "penner_pack": 1,
            "mode": if options.sphere { "sphere" } else { "disk" },
            "status": status,
            "epsilon": epsilon,
            "faces": self.disk.mesh.face_list(),
            "centres": self.circles.iter().map(|c| json!([exact_string(&c.centre[0]), exact_string(&c.centre[1])])).collect::<Vec<_>>(),
            "radii": self.circles.iter().map(|c| exact_string(&c.radius)).collect::<Vec<_>>(),
            "unit_disk": self.unit_disk,
        });
        if let Some(c) = &self.caps {
            doc["puncture"] = json!(options.puncture);
            doc["caps"] = c
                .iter()
                .map(|c| {
                    json!({
                        "normal": c.normal.iter().map(exact_string).collect::<Vec<_>>(),
                        "height": exact_string(&c.height),
                    })
                })
                .collect();
        }
        doc
    }

    /// The SVG picture: the unit disk and its circles, or the caps on the sphere.
    pub fn svg(&self) -> String {
        match &self.caps {
            Some(c) => render_sphere_svg(&caps_f64(c)),
            None => render_disk_svg(&self.disk.mesh, &to_f64(&self.disk.circles)),
        }
    }
}

/// Pack `mesh` (named `shown` in messages) maximally with `options` (module
/// documentation).
pub fn pack_maximal(
    mesh: &Mesh,
    shown: &str,
    options: &PackOptions,
) -> Result<PackOutcome, PackError> {
    if options.epsilon < 0 {
        return Err(PackError::Input("ε must be ≥ 0".into()));
    }
    let eps = &options.epsilon;
    // proof: B99 — above f64 the working precision grows with n and 1/ε, and the
    // refinement aims at defects below ε/2⁴ (ε = 0 cannot be certified: no aim).
    let eps_f64 = (*eps > 0).then(|| eps.to_f64()).filter(|e| *e > 0.0);
    // The packing exists (Koebe–Andreev–Thurston), so a computed one that misses ε is a
    // limit of the computation: refine at twice the bits, up to MAX_BITS, then undecided.
    let mut asked_bits = options.bits;
    loop {
        let (disk, caps, bits) = compute(mesh, options, asked_bits, eps_f64, shown)?;
        let circles = exact_circles(&disk.circles)
            .ok_or_else(|| PackError::NotComputed(format!("{shown}: a circle is not finite")))?;
        let cert_bits = 2 * bits.max(64);
        let unit_disk: Vec<bool> = disk.interior.iter().map(|b| !b).collect();
        let verdict = match &caps {
            Some(c) => check_sphere_packing(mesh, c, eps, cert_bits),
            None => check_packing(&disk.mesh, &circles, eps, cert_bits, Some(&unit_disk)),
        };
        let refine = eps_f64.is_some() && options.bits > 53 && bits < MAX_BITS;
        if matches!(verdict, PackingVerdict::Holds { .. }) || !refine {
            return Ok(PackOutcome {
                verdict: own_packing_verdict(verdict, bits),
                disk,
                caps,
                bits,
                circles,
                unit_disk,
            });
        }
        asked_bits = (2 * bits).min(MAX_BITS);
    }
}

type Computed = (DiskPacking<Mpfr>, Option<Vec<ExactCap>>, u32);

/// The packing (and caps) at the working precision of B99, and the bits used.
fn compute(
    mesh: &Mesh,
    o: &PackOptions,
    asked_bits: u32,
    eps_f64: Option<f64>,
    shown: &str,
) -> Result<Computed, PackError> {
    let bad = |e: &MaximalError| match e {
        // Valid input that this computation does not reach: not computed (exit 2).
        MaximalError::NoInteriorVertex => {
            let hint = if o.sphere {
                " (the sphere needs a vertex outside the star of the puncture)"
            } else {
                ""
            };
            PackError::NotComputed(format!("{shown}: not computed: {e}{hint}"))
        }
        MaximalError::Solve(_) | MaximalError::Layout(_) => {
            PackError::NotComputed(format!("{shown}: not computed: {e}"))
        }
        _ => PackError::Input(format!("{shown}: {e}")),
    };
    let mut bits = match eps_f64 {
        Some(e) if o.bits > 53 => asked_bits.max(bits_for(e, mesh.n_vertices())),
        _ => asked_bits,
    };
    let prec = Precision::new(u64::from(bits))
        .map_err(|e| PackError::Input(format!("--bits {}: {e}", o.bits)))?;
    let opts = Opts {
        epsilon: eps_f64,
        ..Opts::default()
    };
    // The sphere's caps (exact) next to the disk packing.
    let (disk, caps): (DiskPacking<Mpfr>, Option<Vec<_>>) = if o.sphere {
        let s = maximal_sphere::<Mpfr>(mesh, o.puncture, prec, &opts).map_err(|e| bad(&e))?;
        let caps = exact_caps(&s.caps)
            .ok_or_else(|| PackError::NotComputed(format!("{shown}: a cap is not finite")))?;
        (s.disk, Some(caps))
    } else if let (Some(e), true) = (eps_f64, o.bits > 53) {
        let (d, used) = maximal_disk_within(mesh, e, bits, &opts).map_err(|e| bad(&e))?;
        bits = used;
        (d, None)
    } else {
        (
            maximal_disk::<Mpfr>(mesh, prec, &opts).map_err(|e| bad(&e))?,
            None,
        )
    };
    Ok((disk, caps, bits))
}

/// The largest working precision the refinement of a packing that misses ε goes to.
pub const MAX_BITS: u32 = 4096;

/// Witnesses listed in a message before only their count is given.
const LISTED: usize = 20;

/// `items` joined, the first [`LISTED`] of them and a count of the rest.
fn listed(items: &[String]) -> String {
    let mut s = items
        .iter()
        .take(LISTED)
        .cloned()
        .collect::<Vec<_>>()
        .join("; ");
    if items.len() > LISTED {
        let _ = write!(s, "; and {} more", items.len() - LISTED);
    }
    s
}

/// The verdict on a packing penner computed itself. Such a packing exists by
/// Koebe–Andreev–Thurston (T11), so a proved miss of ε refutes only the computation, not
/// the input: it is `undecided`, with the witnesses and the precision reached. `fails` is
/// kept for circles a user states (`penner certify`).
fn own_packing_verdict(v: PackingVerdict, bits: u32) -> PackingVerdict {
    match v {
        PackingVerdict::Fails(w) => PackingVerdict::Undecided(vec![format!(
            "the packing computed at {bits} bits misses: {} (the packing exists, T11: a limit of the computation, not a property of the input)",
            listed(&w)
        )]),
        PackingVerdict::Undecided(w) => PackingVerdict::Undecided(vec![listed(&w)]),
        holds @ PackingVerdict::Holds { .. } => holds,
    }
}

fn to_f64<T: Real>(circles: &[Circle<T>]) -> Vec<Circle<f64>> {
    circles
        .iter()
        .map(|c| Circle {
            centre: [c.centre[0].approx_f64(), c.centre[1].approx_f64()],
            radius: c.radius.approx_f64(),
        })
        .collect()
}

/// The caps as `f64` for the picture, normals rescaled to unit length.
fn caps_f64(caps: &[ExactCap]) -> Vec<Cap<f64>> {
    caps.iter()
        .map(|c| {
            let n = [
                c.normal[0].to_f64(),
                c.normal[1].to_f64(),
                c.normal[2].to_f64(),
            ];
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            Cap {
                normal: n.map(|x| x / len),
                height: c.height.to_f64() / len,
            }
        })
        .collect()
}

fn exact_string(q: &Rational) -> Value {
    Value::String(q.to_string())
}
