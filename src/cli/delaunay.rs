//! `penner delaunay SURFACE`: flip to the intrinsic Delaunay triangulation and write it.

use super::args::FlipKind as ArgFlipKind;
use super::error::{code, CliError};
use super::files::{create_new, read_text};
use super::input::FlipCase;
use super::output::{self, FlipValues};
use penner::algorithms::flip_scaled::flip_to_delaunay_scaled;
use penner::algorithms::flip_to_delaunay::{
    flip_to_delaunay, flip_to_delaunay_exact, ExactLengths, FlipCounter, FlipKind, FlipOptions,
    FlipReport,
};
use penner::algorithms::replay::{replay_escalating_lazy, BrokenStep, FlippedLens, Replayed};
use penner::algorithms::replay_input::PositionMetric;
use penner::mesh::{Edge, Mesh};
use penner::oracle::Prec;
use penner::predicates::delaunay::QuadEdges;
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
    /// JSON summary file (must not exist).
    pub summary: Option<&'a Path>,
    /// Replay the flip sequence on the exact input metric (B80) after a rounded run.
    pub input_replay: bool,
    /// A lengths file to write next to an OBJ or OFF output.
    pub lengths_out: Option<&'a Path>,
}

/// First and last MPFR precision of the replay on the input metric.
const REPLAY_BITS: (u32, u32) = (128, 1024);

/// What the written triangulation is certified to be.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Certificate {
    /// Intrinsic Delaunay for the input metric (exact run, or replay on the input, B80).
    InputMetric,
    /// Intrinsic Delaunay for the rounded lengths the run stored (B65) only.
    RoundedMetric,
    /// Not every edge is certified Delaunay even for the rounded lengths.
    None,
}

impl Certificate {
    fn name(self) -> &'static str {
        match self {
            Certificate::InputMetric => "input_metric",
            Certificate::RoundedMetric => "rounded_metric",
            Certificate::None => "none",
        }
    }
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
    let value = penner::io::strict_json::parse(&text)
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
    opts: &FlipOptions,
) -> Result<(FlipReport, FlipValues), CliError> {
    let base: Vec<f64> = case.lengths(());
    let name = case.name().to_string();
    let (report, lengths) = flip_to_delaunay_scaled(case.mesh_mut(), &base, u, kind, opts)
        .map_err(|e| CliError::Input(format!("{name}: {e}")))?;
    Ok((
        report,
        FlipValues::Exact(lengths.iter().map(ExpLength::to_rational).collect()),
    ))
}

/// Flip real lengths of backend `T` and return the report and the exact values of the
/// stored lengths (`f64` values as they are: each is exact).
/// `squares`, when given, are the `f64` squared lengths of an OBJ/OFF input
/// (`DecimalSurface::squared_lengths_f64`), whose square roots are its `f64` lengths.
fn flip_real<T: Real + 'static>(
    case: &mut FlipCase,
    ctx: T::Ctx,
    kind: FlipKind,
    squares: Option<&[f64]>,
    opts: &FlipOptions,
) -> Result<(FlipReport, FlipValues), CliError> {
    let from_squares = squares.and_then(|s| {
        let l: Box<dyn Any> = Box::new(s.iter().map(|&x| x.sqrt()).collect::<Vec<f64>>());
        l.downcast::<Vec<T>>().ok()
    });
    let mut l: Vec<T> = match from_squares {
        Some(l) => *l,
        None => case.lengths(ctx),
    };
    let name = case.name().to_string();
    binary64_range(case, &l, &name)?;
    let report = flip_to_delaunay(case.mesh_mut(), &mut l, kind, opts)
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

/// A positive finite input length that the binary64 exponent range of `f64` or `Dd`
/// turns into `0` or `∞` names its real cause, not "length inf" (MPFR's range holds it).
/// Exact lengths decide directly; otherwise (positions, squared lengths) the length of
/// the first such edge is recomputed at 128 MPFR bits, whose exponent range holds every
/// length of finite decimal positions (the message only; the run is refused either way).
fn binary64_range<T: Real + 'static>(case: &FlipCase, l: &[T], name: &str) -> Result<(), CliError> {
    let narrow = [std::any::TypeId::of::<f64>(), std::any::TypeId::of::<Dd>()];
    if !narrow.contains(&std::any::TypeId::of::<T>()) {
        return Ok(());
    }
    let Some((i, a)) = l
        .iter()
        .map(Real::approx_f64)
        .enumerate()
        .find(|(_, a)| *a == 0.0 || a.is_infinite())
    else {
        return Ok(());
    };
    // (positive, the length itself in binary64's range)
    let (positive, representable) = match case.exact_lengths() {
        Some(exact) => (exact[i] > 0, false),
        None => penner::scalar::Precision::new(128)
            .ok()
            .and_then(|p| case.lengths::<Mpfr>(p).get(i).cloned())
            .map_or((false, false), |m| {
                let f = m.as_float();
                let x = m.approx_f64();
                (
                    f.is_finite() && f.is_sign_positive() && !f.is_zero(),
                    x > 0.0 && x.is_finite(),
                )
            }),
    };
    if !positive {
        return Ok(());
    }
    let side = if a == 0.0 { "below" } else { "beyond" };
    let cause = if representable {
        let way = if a == 0.0 { "underflows" } else { "overflows" };
        format!("edge e{i}'s squared length {way} binary64")
    } else {
        format!("edge e{i} has a length {side} the binary64 range")
    };
    Err(CliError::Input(format!(
        "{name}: {cause} of this precision; use MPFR bits, e.g. --precision 128"
    )))
}

/// The flip options of every run: default, with the sequence recorded (for the replay)
/// and the flips counted in `progress`.
fn record(progress: &FlipCounter) -> FlipOptions {
    FlipOptions {
        record: true,
        progress: Some(progress.clone()),
        ..FlipOptions::default()
    }
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

/// A progress spinner on a terminal (none otherwise).
fn spinner(path: &Path, faces: usize) -> Option<indicatif::ProgressBar> {
    std::io::stderr().is_terminal().then(|| {
        let b = indicatif::ProgressBar::new_spinner();
        b.set_message(flipping_message(path, faces, 0));
        b.enable_steady_tick(Duration::from_millis(120));
        b
    })
}

/// The spinner's message while flipping.
fn flipping_message(path: &Path, faces: usize, flips: usize) -> String {
    format!(
        "flipping {} ({faces} faces) to intrinsic Delaunay: {flips} flips",
        path.display()
    )
}

/// Run `flip`, showing the flips counted by `counter` on `bar` (if any) while it runs.
fn with_flip_progress<R>(
    bar: Option<&indicatif::ProgressBar>,
    counter: &FlipCounter,
    (path, faces): (&Path, usize),
    flip: impl FnOnce() -> R,
) -> R {
    let Some(bar) = bar else {
        return flip();
    };
    let done = std::sync::atomic::AtomicBool::new(false);
    std::thread::scope(|s| {
        s.spawn(|| {
            while !done.load(std::sync::atomic::Ordering::Relaxed) {
                bar.set_message(flipping_message(path, faces, counter.get()));
                std::thread::sleep(Duration::from_millis(150));
            }
        });
        let r = flip();
        done.store(true, std::sync::atomic::Ordering::Relaxed);
        r
    })
}

/// Flip `case` at `prec` with flips of `kind` (the scaled metric when `scale` is given),
/// from the `f64` `squares` when kept; the report and the stored lengths' values.
fn flip_case(
    case: &mut FlipCase,
    (path, prec, kind): (&Path, Prec, FlipKind),
    scale: Option<&[f64]>,
    squares: Option<&[f64]>,
    opts: &FlipOptions,
) -> Result<(FlipReport, FlipValues), CliError> {
    // Cloned only for the exact rung, which consumes them.
    let exact_lengths = if prec == Prec::Exact {
        case.exact_lengths().cloned()
    } else {
        None
    };
    match (prec, kind, exact_lengths, scale) {
        (.., Some(u)) => flip_scaled(case, u, kind, opts),
        (Prec::Exact, FlipKind::Ptolemy, Some(l), None) => {
            let (report, lengths) =
                flip_to_delaunay_exact(case.mesh_mut(), l, EXACT_GUARD_BITS, opts)
                    .map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?;
            match lengths {
                ExactLengths::Exact(v) => Ok((report, FlipValues::Exact(v))),
                ExactLengths::Enclosed(_) => Err(CliError::Input(format!(
                    "{}: exact lengths outgrew {EXACT_GUARD_BITS} bits after {} flips; use a bit count such as --precision 1024",
                    path.display(),
                    report.fell_back_after.unwrap_or(report.flips)
                ))),
            }
        }
        (Prec::Exact, ..) => Err(CliError::Input(
            "--precision exact needs --flips ptolemy and exact (not squared) lengths: Euclidean flips make lengths irrational"
                .to_string(),
        )),
        (Prec::F64, ..) => flip_real::<f64>(case, (), kind, squares, opts),
        (Prec::Dd, ..) => flip_real::<Dd>(case, (), kind, None, opts),
        (Prec::Mpfr(p), ..) => flip_real::<Mpfr>(case, p, kind, None, opts),
    }
}

/// The flip kind asked for.
fn flip_kind(k: ArgFlipKind) -> FlipKind {
    match k {
        ArgFlipKind::Euclidean => FlipKind::Euclidean,
        ArgFlipKind::Ptolemy => FlipKind::Ptolemy,
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
    refuse_existing(o.summary)?;
    refuse_existing(o.lengths_out)?;
    let format = output::format_of(o.output, o.lengths_out)?;
    let mut case = super::input::load_flip_case(o.path)?;
    // The input triangulation, for the replay of a rounded run on the exact input metric
    // (the squared lengths of positions follow the input mesh's edges).
    let input_mesh = (o.input_replay && prec != Prec::Exact && o.scale_factors.is_none())
        .then(|| case.mesh().clone());
    // The f64 squared lengths of OBJ/OFF input, computed once for the f64 lengths and the
    // replay's first rung.
    let squares = match &case {
        FlipCase::Decimal(s) if input_mesh.is_some() && prec == Prec::F64 => {
            Some(s.squared_lengths_f64())
        }
        _ => None,
    };
    let kind = flip_kind(o.flips);
    let bar = spinner(o.path, case.mesh().n_faces());
    let scale = match o.scale_factors {
        Some(path) => Some(read_scale_factors(path, prec, case.mesh().n_vertices())?),
        None => None,
    };
    let counter = FlipCounter::default();
    let opts = record(&counter);
    let faces = case.mesh().n_faces();
    let result = with_flip_progress(bar.as_ref(), &counter, (o.path, faces), || {
        flip_case(
            &mut case,
            (o.path, prec, kind),
            scale.as_deref(),
            squares.as_deref(),
            &opts,
        )
    });
    let (report, lengths) = match result {
        Ok(r) => r,
        Err(e) => {
            if let Some(b) = bar {
                b.finish_and_clear();
            }
            return Err(e);
        }
    };
    if let (Some(b), Some(_)) = (&bar, &input_mesh) {
        b.set_message(format!(
            "{} flips done; replaying them on the exact input metric",
            report.flips
        ));
    }
    // Exact Ptolemy flipping has no rounding: its certificate is for the input metric.
    let exact_run = prec == Prec::Exact;
    let rounded_ok = report.all_certified_delaunay();
    let replay = input_mesh
        .as_ref()
        .filter(|_| rounded_ok && !exact_run)
        .map(|mesh| replay_on_input(&case, mesh, squares.as_deref(), &report.sequence, kind));
    if let Some(b) = &bar {
        b.set_message(format!("{} flips done; writing", report.flips));
    }
    let (certificate, not_for_input) = certificate_of(rounded_ok, exact_run, replay.as_ref());
    // The output is a plain surface file (readable by `penner check`); the flip count
    // and the certificate go to standard error (and to the summary file).
    let written = output::write_flipped(&case, &lengths, format, o.output, o.lengths_out);
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    written?;
    let what = certificate_words(
        certificate,
        not_for_input,
        replay.as_ref(),
        scale.is_some(),
        &report,
    );
    let summary = format!(
        "{} {} flip(s) at {prec}; {what}",
        report.flips,
        match kind {
            FlipKind::Euclidean => "Euclidean",
            FlipKind::Ptolemy => "Ptolemy",
        },
    );
    if let Some(p) = o.output {
        eprintln!("{summary}; written to {}", p.display());
    } else {
        eprintln!("{summary}");
    }
    if let Some(p) = o.summary {
        write_summary(
            p,
            &summary_json(&report, kind, prec, certificate, not_for_input),
        )?;
    }
    Ok(match (certificate, not_for_input) {
        (Certificate::InputMetric, _) | (Certificate::RoundedMetric, None) => code::HOLDS,
        _ => code::UNDECIDED,
    })
}

/// Replay `sequence` on the exact input metric of `case` (B80), whose input triangulation
/// is `mesh` (with its `f64` squared lengths when kept): exact values are built only for the edges the first rung leaves open (B83).
fn replay_on_input(
    case: &FlipCase,
    mesh: &Mesh,
    squares: Option<&[f64]>,
    sequence: &[Edge],
    kind: FlipKind,
) -> (Replayed<FlippedLens>, u32) {
    let (lo, hi) = REPLAY_BITS;
    match case {
        FlipCase::Exact(s) => replay_escalating_lazy(mesh, &s.metric, sequence, kind, lo, hi),
        FlipCase::Decimal(surface) => {
            let input = PositionMetric {
                mesh,
                surface,
                squares,
            };
            replay_escalating_lazy(mesh, &input, sequence, kind, lo, hi)
        }
    }
}

/// The certificate of a run and the count of edges not certified for the input metric
/// (`None` when not counted: no replay, or the rounded run itself is not certified).
fn certificate_of(
    rounded_ok: bool,
    exact_run: bool,
    replay: Option<&(Replayed<FlippedLens>, u32)>,
) -> (Certificate, Option<usize>) {
    match (replay, rounded_ok) {
        (_, false) => (Certificate::None, None),
        (None, true) if exact_run => (Certificate::InputMetric, Some(0)),
        (None, true) => (Certificate::RoundedMetric, None),
        (Some((r, _)), true) if r.certified_delaunay() => (Certificate::InputMetric, Some(0)),
        (Some((r, _)), true) => (Certificate::RoundedMetric, Some(not_certified(r))),
    }
}

/// Write the `--summary` document to the new file `p` (never overwriting; exit 4 on a
/// write error).
fn write_summary(p: &Path, doc: &serde_json::Value) -> Result<(), CliError> {
    let mut f = create_new(p)?;
    std::io::Write::write_all(&mut f, format!("{doc:#}\n").as_bytes()).map_err(|e| {
        CliError::Write {
            path: p.to_path_buf(),
            reason: e.to_string(),
        }
    })
}

/// The `--summary` document: flips, precision and what is certified.
fn summary_json(
    report: &FlipReport,
    kind: FlipKind,
    prec: Prec,
    certificate: Certificate,
    not_for_input: Option<usize>,
) -> serde_json::Value {
    serde_json::json!({
        "flips": report.flips,
        "flip_kind": match kind { FlipKind::Euclidean => "euclidean", FlipKind::Ptolemy => "ptolemy" },
        "precision": prec.to_string(),
        "certificate": certificate.name(),
        "not_certified_for_input": not_for_input,
        "undecided": report.undecided.len(),
        "refused": report.refused.len(),
        "hit_cap": report.hit_cap,
    })
}

/// What the written triangulation is certified to be, in words.
fn certificate_words(
    certificate: Certificate,
    not_for_input: Option<usize>,
    replay: Option<&(Replayed<FlippedLens>, u32)>,
    scaled: bool,
    report: &FlipReport,
) -> String {
    match (certificate, not_for_input) {
        (Certificate::InputMetric, _) => {
            "every edge certified intrinsic Delaunay, certified for the input metric".to_string()
        }
        (Certificate::RoundedMetric, Some(n)) => format!(
            "every edge certified intrinsic Delaunay for the rounded metric only; {n} edge(s) not certified for the input metric{}",
            replay.map_or(String::new(), |(r, bits)| replay_detail(r, *bits))
        ),
        (Certificate::RoundedMetric, None) => format!(
            "every edge certified intrinsic Delaunay for the rounded metric only ({})",
            if scaled {
                "the scaled input metric is not replayed"
            } else {
                "the replay on the input metric was skipped"
            }
        ),
        (Certificate::None, _) => format!(
            "NOT every edge certified Delaunay ({} undecided, {} refused{})",
            report.undecided.len(),
            report.refused.len(),
            if report.hit_cap { ", flip cap hit" } else { "" }
        ),
    }
}

/// Edges of the written triangulation not certified Delaunay for the input metric: the
/// interior edges certified non-Delaunay or undecided there; when a flip of the sequence is
/// not a certified legal step on the input metric, the triangulation itself is not one of
/// the input's certified flips, and no interior edge is certified.
fn not_certified(r: &Replayed<FlippedLens>) -> usize {
    if r.broken.is_some() {
        return r
            .mesh
            .edges()
            .filter(|&e| QuadEdges::of(&r.mesh, e).is_some())
            .count();
    }
    r.negative.len() + r.undecided.len()
}

/// The first reason of a failed replay, for the message.
fn replay_detail(r: &Replayed<FlippedLens>, bits: u32) -> String {
    match &r.broken {
        Some((n, e, why)) => format!(
            " (flip {n} of the sequence, edge {e}, is {} for the input metric at {bits} bits)",
            match why {
                BrokenStep::StrictlyDelaunay => "certified strictly Delaunay, not a legal flip",
                BrokenStep::Undecided => "undecided",
                BrokenStep::NoLength => "without an enclosed new length",
                BrokenStep::NotFlippable => "not flippable",
            }
        ),
        None => format!(
            " ({} certified non-Delaunay, {} undecided at {bits} bits)",
            r.negative.len(),
            r.undecided.len()
        ),
    }
}
