//! `penner pack SURFACE (--disk | --sphere)`: the Koebe–Andreev–Thurston maximal packing
//! (`penner::circles::maximal`, proofs/T11), refined at `--bits`, tangency certified within
//! `--epsilon` (B95, B96), written as JSON (`-o`) and drawn as SVG (`--svg`: the unit disk,
//! or for `--sphere` the caps on the sphere in an orthographic view).

use super::error::{code, CliError};
use super::files::{emit, write_new};
use super::input::load_case;
use penner::circles::maximal::pipeline::{pack_maximal, PackError, PackOptions};
use penner::circles::maximal::tangency::PackingVerdict;
use penner::scalar::parse_rational;
use std::fmt::Write as _;
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

/// Run the maximal packing: exit 0 when tangency is certified within ε, 2 when undecided
/// (including a computed packing proved to miss ε at the largest precision tried, or valid
/// input the computation does not reach), 3 on bad input, 4 when an output cannot be
/// written.
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
    let options = PackOptions {
        sphere: o.sphere,
        puncture: o.puncture,
        bits: o.bits,
        epsilon: eps,
    };
    let outcome = pack_maximal(&case.mesh, &shown, &options).map_err(|e| match e {
        PackError::Input(m) => CliError::Input(m),
        PackError::NotComputed(m) => CliError::NotConverged(m),
    })?;
    let disk = &outcome.disk;
    let mut text = format!(
        "{}: maximal packing ({}), {} vertices, {} Newton iterations (f64, residual {:.1e}), {} refinement steps at {} bits\n",
        case.name,
        if o.sphere { "sphere punctured at v".to_string() + &o.puncture.to_string() } else { "disk".into() },
        case.mesh.n_vertices(),
        disk.newton_iterations,
        disk.f64_residual,
        disk.refinement_steps,
        outcome.bits
    );
    let exit = match &outcome.verdict {
        PackingVerdict::Holds { max_defect } => {
            let _ = writeln!(
                text,
                "certified (B95{}): every tangency within ε = {} (largest defect ≤ {max_defect:.1e}), every face positively oriented, every vertex wound once",
                if o.sphere { ", B96" } else { "" },
                o.epsilon
            );
            code::HOLDS
        }
        PackingVerdict::Fails(w) => {
            let _ = writeln!(text, "fails: {}", w.join("; "));
            code::FAILS
        }
        PackingVerdict::Undecided(w) => {
            let _ = writeln!(text, "undecided: {}", w.join("; "));
            code::UNDECIDED
        }
    };
    if let Some(out) = o.output {
        write_new(
            out,
            (outcome.document(&options, o.epsilon).to_string() + "\n").as_bytes(),
        )?;
        let _ = writeln!(text, "wrote {}", out.display());
    }
    if let Some(out) = o.svg {
        write_new(out, outcome.svg().as_bytes())?;
        let _ = writeln!(text, "wrote {}", out.display());
    }
    emit(&text)?;
    Ok(exit)
}
