//! `penner pack SURFACE (--disk | --sphere)`: the Koebe–Andreev–Thurston maximal packing
//! (`penner::circles::maximal`, proofs/T11), refined at `--bits`, tangency certified within
//! `--epsilon` (B95, B96), written as JSON (`-o`) and drawn as SVG (`--svg`: the unit disk,
//! or for `--sphere` the caps on the sphere in an orthographic view).

use super::error::{code, CliError};
use super::files::{create_new, emit};
use super::input::load_case;
use penner::circles::maximal::layout::Circle;
use penner::circles::maximal::sphere::{check_sphere_packing, exact_caps, Cap, ExactCap};
use penner::circles::maximal::stopping::bits_for;
use penner::circles::maximal::svg::{render_disk_svg, render_sphere_svg};
use penner::circles::maximal::tangency::{check_packing, exact_circles, PackingVerdict};
use penner::circles::maximal::{
    maximal_disk, maximal_disk_within, maximal_sphere, DiskPacking, MaximalError, Options as Opts,
};
use penner::scalar::{parse_rational, Mpfr, Precision, Real};
use rug::Rational;
use serde_json::{json, Value};
use std::fmt::Write as _;
use std::io::Write;
use std::path::Path;

/// What `penner pack --disk/--sphere` was asked.
pub struct Options<'a> {
    /// The surface file.
    pub path: &'a Path,
    /// Sphere (else disk).
    pub sphere: bool,
    /// The puncture vertex of a sphere.
    pub puncture: usize,
    /// MPFR bits (53: f64).
    pub bits: u32,
    /// ε as given.
    pub epsilon: &'a str,
    /// SVG output.
    pub svg: Option<&'a Path>,
    /// JSON output.
    pub output: Option<&'a Path>,
}

fn write_new(path: &Path, text: &str) -> Result<(), CliError> {
    let mut f = create_new(path)?;
    f.write_all(text.as_bytes())
        .and_then(|()| f.flush())
        .map_err(|e| CliError::Write {
            path: path.to_path_buf(),
            reason: e.to_string(),
        })
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

type Computed = (DiskPacking<Mpfr>, Option<Vec<ExactCap>>, u32);

/// The packing (and caps) at the working precision of B99, and the bits used.
fn compute(
    mesh: &penner::mesh::Mesh,
    o: &Options,
    asked_bits: u32,
    eps_f64: Option<f64>,
    shown: &str,
) -> Result<Computed, CliError> {
    let bad = |e: &MaximalError| match e {
        // Valid input that this computation does not reach: not computed (exit 2).
        MaximalError::NoInteriorVertex => {
            let hint = if o.sphere {
                " (the sphere needs a vertex outside the star of the puncture)"
            } else {
                ""
            };
            CliError::NotConverged(format!("{shown}: not computed: {e}{hint}"))
        }
        MaximalError::Solve(_) | MaximalError::Layout(_) => {
            CliError::NotConverged(format!("{shown}: not computed: {e}"))
        }
        _ => CliError::Input(format!("{shown}: {e}")),
    };
    let mut bits = match eps_f64 {
        Some(e) if o.bits > 53 => asked_bits.max(bits_for(e, mesh.n_vertices())),
        _ => asked_bits,
    };
    let prec = Precision::new(u64::from(bits))
        .map_err(|e| CliError::Input(format!("--bits {}: {e}", o.bits)))?;
    let opts = Opts {
        epsilon: eps_f64,
        ..Opts::default()
    };
    // The sphere's caps (exact) next to the disk packing.
    let (disk, caps): (DiskPacking<Mpfr>, Option<Vec<_>>) = if o.sphere {
        let s = maximal_sphere::<Mpfr>(mesh, o.puncture, prec, &opts).map_err(|e| bad(&e))?;
        let caps = exact_caps(&s.caps)
            .ok_or_else(|| CliError::Input(format!("{shown}: a cap is not finite")))?;
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
const MAX_BITS: u32 = 4096;

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

/// Run the maximal packing: exit 0 when tangency is certified within ε, 2 when undecided
/// (including a computed packing proved to miss ε at the largest precision tried), 3 on
/// bad input or when no packing is computed, 4 when an output cannot be written.
pub fn run(o: &Options) -> Result<u8, CliError> {
    let shown = o.path.display().to_string();
    let eps = parse_rational(o.epsilon)
        .map_err(|e| CliError::Input(format!("--epsilon {}: {e}", o.epsilon)))?;
    if eps < 0 {
        return Err(CliError::Input(format!(
            "--epsilon {}: must be ≥ 0",
            o.epsilon
        )));
    }
    let case = load_case(o.path)?;
    // proof: B99 — above f64 the working precision grows with n and 1/ε, and the
    // refinement aims at defects below ε/2⁴ (ε = 0 cannot be certified: no aim).
    let eps_f64 = (eps > 0).then(|| eps.to_f64()).filter(|e| *e > 0.0);
    // The packing exists (Koebe–Andreev–Thurston), so a computed one that misses ε is a
    // limit of the computation: refine at twice the bits, up to MAX_BITS, then undecided.
    let mut asked_bits = o.bits;
    let (disk, caps, bits, circles, marks, verdict) = loop {
        let (disk, caps, bits) = compute(&case.mesh, o, asked_bits, eps_f64, &shown)?;
        let circles = exact_circles(&disk.circles)
            .ok_or_else(|| CliError::Input(format!("{shown}: a circle is not finite")))?;
        let cert_bits = 2 * bits.max(64);
        let marks: Vec<bool> = disk.interior.iter().map(|b| !b).collect();
        let verdict = match &caps {
            Some(c) => check_sphere_packing(&case.mesh, c, &eps, cert_bits),
            None => check_packing(&disk.mesh, &circles, &eps, cert_bits, Some(&marks)),
        };
        let refine = eps_f64.is_some() && o.bits > 53 && bits < MAX_BITS;
        if matches!(verdict, PackingVerdict::Holds { .. }) || !refine {
            break (disk, caps, bits, circles, marks, verdict);
        }
        asked_bits = (2 * bits).min(MAX_BITS);
    };
    let verdict = own_packing_verdict(verdict, bits);
    let mut text = format!(
        "{}: maximal packing ({}), {} vertices, {} Newton iterations (f64, residual {:.1e}), {} refinement steps at {} bits\n",
        case.name,
        if o.sphere { "sphere punctured at v".to_string() + &o.puncture.to_string() } else { "disk".into() },
        case.mesh.n_vertices(),
        disk.newton_iterations,
        disk.f64_residual,
        disk.refinement_steps,
        bits
    );
    let (status, exit) = match &verdict {
        PackingVerdict::Holds { max_defect } => {
            let _ = writeln!(
                text,
                "certified (B95{}): every tangency within ε = {} (largest defect ≤ {max_defect:.1e}), every face positively oriented, every vertex wound once",
                if o.sphere { ", B96" } else { "" },
                o.epsilon
            );
            ("holds", code::HOLDS)
        }
        PackingVerdict::Fails(w) => {
            let _ = writeln!(text, "fails: {}", w.join("; "));
            ("fails", code::FAILS)
        }
        PackingVerdict::Undecided(w) => {
            let _ = writeln!(text, "undecided: {}", w.join("; "));
            ("undecided", code::UNDECIDED)
        }
    };
    if let Some(out) = o.output {
        let mut doc = json!({
            "penner_pack": 1,
            "mode": if o.sphere { "sphere" } else { "disk" },
            "status": status,
            "epsilon": o.epsilon,
            "faces": disk.mesh.face_list(),
            "centres": circles.iter().map(|c| json!([exact_string(&c.centre[0]), exact_string(&c.centre[1])])).collect::<Vec<_>>(),
            "radii": circles.iter().map(|c| exact_string(&c.radius)).collect::<Vec<_>>(),
            "unit_disk": marks,
        });
        if let Some(c) = &caps {
            doc["puncture"] = json!(o.puncture);
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
        write_new(out, &(doc.to_string() + "\n"))?;
        let _ = writeln!(text, "wrote {}", out.display());
    }
    if let Some(out) = o.svg {
        let doc = match &caps {
            Some(c) => render_sphere_svg(&caps_f64(c)),
            None => render_disk_svg(&disk.mesh, &to_f64(&disk.circles)),
        };
        write_new(out, &doc)?;
        let _ = writeln!(text, "wrote {}", out.display());
    }
    emit(&text)?;
    Ok(exit)
}
