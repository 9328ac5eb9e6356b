//! `penner delaunay SURFACE`: flip to the intrinsic Delaunay triangulation and write it.

use super::args::FlipKind as ArgFlipKind;
use super::error::{code, CliError};
use super::files::{read_text, write_new};
use super::output;
use penner::algorithms::delaunay_pipeline::{intrinsic_delaunay, DelaunayOptions};
use penner::algorithms::flip_to_delaunay::{FlipCounter, FlipKind};
use penner::oracle::Prec;
use std::io::IsTerminal;
use std::path::Path;
use std::time::Duration;

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
    let kind = flip_kind(o.flips);
    let bar = spinner(o.path, case.mesh().n_faces());
    let scale_factors = match o.scale_factors {
        Some(path) => Some(read_scale_factors(path, prec, case.mesh().n_vertices())?),
        None => None,
    };
    let options = DelaunayOptions {
        kind,
        precision: prec,
        scale_factors,
        replay_on_input: o.input_replay,
        counter: FlipCounter::default(),
    };
    let faces = case.mesh().n_faces();
    let result = with_flip_progress(bar.as_ref(), &options.counter, (o.path, faces), || {
        intrinsic_delaunay(&mut case, &options)
    });
    let outcome = match result {
        Ok(r) => r,
        Err(e) => {
            if let Some(b) = bar {
                b.finish_and_clear();
            }
            return Err(CliError::Input(e.to_string()));
        }
    };
    if let Some(b) = &bar {
        b.set_message(format!("{} flips done; writing", outcome.report.flips));
    }
    // The output is a plain surface file (readable by `penner check`); the flip count
    // and the certificate go to standard error (and to the summary file).
    let written = output::write_flipped(&case, &outcome.lengths, format, o.output, o.lengths_out);
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    written?;
    let summary = format!(
        "{} {} flip(s) at {prec}; {}",
        outcome.report.flips,
        match kind {
            FlipKind::Euclidean => "Euclidean",
            FlipKind::Ptolemy => "Ptolemy",
        },
        outcome.words()
    );
    if let Some(p) = o.output {
        eprintln!("{summary}; written to {}", p.display());
    } else {
        eprintln!("{summary}");
    }
    if let Some(p) = o.summary {
        write_summary(p, &outcome.summary())?;
    }
    Ok(if outcome.holds() {
        code::HOLDS
    } else {
        code::UNDECIDED
    })
}

/// Write the `--summary` document to the new file `p` (never overwriting; exit 4 on a
/// write error).
fn write_summary(p: &Path, doc: &serde_json::Value) -> Result<(), CliError> {
    write_new(p, format!("{doc:#}\n").as_bytes())
}
