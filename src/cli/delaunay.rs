//! `penner delaunay SURFACE`: flip to the intrinsic Delaunay triangulation and write it.

use super::args::FlipKind as ArgFlipKind;
use super::error::{code, CliError};
use super::files::read_text;
use super::input::FlipCase;
use super::output::{self, FlipValues};
use penner::algorithms::flip_scaled::flip_to_delaunay_scaled;
use penner::algorithms::flip_to_delaunay::{
    flip_to_delaunay, flip_to_delaunay_exact, ExactLengths, FlipKind, FlipOptions, FlipReport,
};
use penner::oracle::Prec;
use penner::scalar::exp_length::ExpLength;
use penner::scalar::{Dd, Mpfr, Real};
use std::any::Any;
use std::io::IsTerminal;
use std::path::Path;
use std::time::Duration;

/// Bit size (numerator + denominator) past which exact Ptolemy flipping continues on
/// enclosures instead.
const EXACT_GUARD_BITS: u64 = 4096;

/// Options of `penner delaunay`.
pub struct Options<'a> {
    /// The surface file.
    pub path: &'a Path,
    /// Flip kind.
    pub flips: ArgFlipKind,
    /// Precision as typed.
    pub precision: &'a str,
    /// Output file, or stdout.
    pub output: Option<&'a Path>,
    /// Per-vertex log scale factors (JSON array): flip `e^{(u_i+u_j)/2}·ℓ_ij` instead.
    pub scale_factors: Option<&'a Path>,
    /// A lengths file to write next to an OBJ or OFF output.
    pub lengths_out: Option<&'a Path>,
}

/// Read a JSON array of one finite number per vertex (`u_v`), naming the file and the
/// offending entry; scaled flipping runs at `f64` only.
fn read_scale_factors(path: &Path, prec: Prec, n_vertices: usize) -> Result<Vec<f64>, CliError> {
    if prec != Prec::F64 {
        return Err(CliError::Input(
            "--scale-factors: scaled lengths are m·2^k with binary64 significands; use --precision f64"
                .to_string(),
        ));
    }
    let text = read_text(path)?;
    let value: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?;
    let serde_json::Value::Array(items) = value else {
        return Err(CliError::Input(format!(
            "{}: expected a JSON array of log scale factors, one per vertex",
            path.display()
        )));
    };
    if items.len() != n_vertices {
        return Err(CliError::Input(format!(
            "{}: {} scale factors for a surface with {n_vertices} vertices",
            path.display(),
            items.len()
        )));
    }
    items
        .iter()
        .enumerate()
        .map(|(v, x)| {
            x.as_f64().filter(|u| u.is_finite()).ok_or_else(|| {
                CliError::Input(format!(
                    "{}: entry {v} (vertex v{v}) is {x}, not a finite number",
                    path.display()
                ))
            })
        })
        .collect()
}

/// Flip the conformally scaled metric of `case` (lengths kept as `m·2ᵏ`, B67) and return
/// the report and the exact values of the final lengths.
fn flip_scaled(
    case: &mut FlipCase,
    u: &[f64],
    kind: FlipKind,
) -> Result<(FlipReport, FlipValues), CliError> {
    let base: Vec<f64> = case.lengths(());
    let name = case.name().to_string();
    let (report, lengths) =
        flip_to_delaunay_scaled(case.mesh_mut(), &base, u, kind, &FlipOptions::default())
            .map_err(|e| CliError::Input(format!("{name}: {e}")))?;
    Ok((
        report,
        FlipValues::Exact(lengths.iter().map(ExpLength::to_rational).collect()),
    ))
}

/// Flip real lengths of backend `T` and return the report and the exact values of the
/// stored lengths (`f64` values as they are: each is exact).
fn flip_real<T: Real + 'static>(
    case: &mut FlipCase,
    ctx: T::Ctx,
    kind: FlipKind,
) -> Result<(FlipReport, FlipValues), CliError> {
    let mut l: Vec<T> = case.lengths(ctx);
    let name = case.name().to_string();
    let report = flip_to_delaunay(case.mesh_mut(), &mut l, kind, &FlipOptions::default())
        .map_err(|e| CliError::Input(format!("{name}: {e}")))?;
    let l = match (Box::new(l) as Box<dyn Any>).downcast::<Vec<f64>>() {
        Ok(binary64) => return Ok((report, FlipValues::Binary64(*binary64))),
        Err(other) => other
            .downcast::<Vec<T>>()
            .map_err(|_| CliError::Input(format!("{name}: length type")))?,
    };
    let exact = l
        .iter()
        .enumerate()
        .map(|(i, x)| {
            x.to_rational()
                .ok_or_else(|| CliError::Input(format!("{name}: edge {i} overflowed")))
        })
        .collect::<Result<_, _>>()?;
    Ok((report, FlipValues::Exact(exact)))
}

/// Refuse an output file that exists before doing any work (never overwrite).
fn refuse_existing(output: Option<&Path>) -> Result<(), CliError> {
    match output {
        Some(out) if out.exists() => Err(CliError::Write {
            path: out.to_path_buf(),
            reason: "the file exists (penner never overwrites a file; choose another name)"
                .to_string(),
        }),
        _ => Ok(()),
    }
}

/// Run `penner delaunay`.
pub fn run(o: &Options<'_>) -> Result<u8, CliError> {
    let precs = super::precisions(o.precision)?;
    let [prec] = precs[..] else {
        return Err(CliError::Input(
            "--precision: give one precision for `delaunay` (f64, dd, exact or a bit count)"
                .to_string(),
        ));
    };
    refuse_existing(o.output)?;
    refuse_existing(o.lengths_out)?;
    let format = output::format_of(o.output, o.lengths_out)?;
    let mut case = super::input::load_flip_case(o.path)?;
    let kind = match o.flips {
        ArgFlipKind::Euclidean => FlipKind::Euclidean,
        ArgFlipKind::Ptolemy => FlipKind::Ptolemy,
    };
    let bar = std::io::stderr().is_terminal().then(|| {
        let b = indicatif::ProgressBar::new_spinner();
        b.set_message(format!(
            "flipping {} ({} faces) to intrinsic Delaunay",
            o.path.display(),
            case.mesh().n_faces()
        ));
        b.enable_steady_tick(Duration::from_millis(120));
        b
    });
    let scale = match o.scale_factors {
        Some(path) => Some(read_scale_factors(path, prec, case.mesh().n_vertices())?),
        None => None,
    };
    // Cloned only for the exact rung, which consumes them.
    let exact_lengths = if prec == Prec::Exact {
        case.exact_lengths().cloned()
    } else {
        None
    };
    let result = match (prec, kind, exact_lengths, &scale) {
        (.., Some(u)) => flip_scaled(&mut case, u, kind),
        (Prec::Exact, FlipKind::Ptolemy, Some(l), None) => {
            let (report, lengths) =
                flip_to_delaunay_exact(case.mesh_mut(), l, EXACT_GUARD_BITS, &FlipOptions::default())
                    .map_err(|e| CliError::Input(format!("{}: {e}", o.path.display())))?;
            match lengths {
                ExactLengths::Exact(v) => Ok((report, FlipValues::Exact(v))),
                ExactLengths::Enclosed(_) => Err(CliError::Input(format!(
                    "{}: exact lengths outgrew {EXACT_GUARD_BITS} bits after {} flips; use a bit count such as --precision 1024",
                    o.path.display(),
                    report.fell_back_after.unwrap_or(report.flips)
                ))),
            }
        }
        (Prec::Exact, ..) => Err(CliError::Input(
            "--precision exact needs --flips ptolemy and exact (not squared) lengths: Euclidean flips make lengths irrational"
                .to_string(),
        )),
        (Prec::F64, ..) => flip_real::<f64>(&mut case, (), kind),
        (Prec::Dd, ..) => flip_real::<Dd>(&mut case, (), kind),
        (Prec::Mpfr(p), ..) => {
            flip_real::<Mpfr>(&mut case, p, kind)
        }
    };
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    let (report, lengths) = result?;
    // The output is a plain surface file (readable by `penner check`); the flip count
    // and the certificate go to standard error.
    output::write_flipped(&case, &lengths, format, o.output, o.lengths_out)?;
    let summary = format!(
        "{} {} flip(s) at {prec}; {}",
        report.flips,
        match kind {
            FlipKind::Euclidean => "Euclidean",
            FlipKind::Ptolemy => "Ptolemy",
        },
        if report.all_certified_delaunay() {
            "every edge certified intrinsic Delaunay".to_string()
        } else {
            format!(
                "NOT every edge certified Delaunay ({} undecided, {} refused{})",
                report.undecided.len(),
                report.refused.len(),
                if report.hit_cap { ", flip cap hit" } else { "" }
            )
        }
    );
    if let Some(p) = o.output {
        eprintln!("{summary}; written to {}", p.display());
    } else {
        eprintln!("{summary}");
    }
    Ok(if report.all_certified_delaunay() {
        code::HOLDS
    } else {
        code::UNDECIDED
    })
}
