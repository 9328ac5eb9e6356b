//! `penner uniformize SURFACE [--targets FILE | --flat] [--precision P] [-o cert.json]`:
//! discrete uniformization with Ptolemy flips (T24), refined and certified (B71); the
//! certificate is written as a `uniformization` claim that `penner certify` re-checks.

use super::error::{code, pipeline_error, CliError};
use super::files::read_text;
use super::input::{load_flip_case, FlipCase};
use super::uniformize_options::numerical_line;
pub use super::uniformize_options::Options;
use penner::io::json::exact_number;
use penner::uniformization::boundary::flat_with_even_boundary;
use penner::uniformization::pipeline::{
    uniformize_boundary, uniformize_closed_owned, uniformize_hyperbolic, uniformize_sphere,
    CertifiedMetric, ClosedOutcome, Options as ClosedOptions, Precision,
};
use penner::uniformization::Targets;
use std::fmt::Write as _;
use std::io::IsTerminal;
use std::path::Path;

pub(super) fn read_targets(path: &Path, n: usize) -> Result<Targets, CliError> {
    let shown = path.display().to_string();
    let text = read_text(path)?;
    let v: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| CliError::Input(format!("{shown}:{}:{}: {e}", e.line(), e.column())))?;
    let arr = v.as_array().ok_or_else(|| {
        CliError::Input(format!(
            "{shown}: expected a JSON array of Θ_i/π, one per vertex"
        ))
    })?;
    if arr.len() != n {
        return Err(CliError::Input(format!(
            "{shown}: {} targets for {n} vertices (one Θ_i/π per vertex)",
            arr.len()
        )));
    }
    let q = arr
        .iter()
        .enumerate()
        .map(|(i, x)| {
            exact_number(x, &format!("[{i}]")).map_err(|e| CliError::Input(format!("{shown}: {e}")))
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Targets::from_multiples_of_pi(q))
}

/// The targets of `--targets FILE | --flat` (`None` with neither when `optional`, for the
/// targets with a default); both, or neither when required, is a usage error.
fn targets_of(
    o: &Options<'_>,
    n: usize,
    optional: bool,
    flat: impl FnOnce() -> Targets,
    required: &str,
) -> Result<Option<Targets>, CliError> {
    match (o.targets, o.flat) {
        (Some(_), true) => Err(CliError::Input(
            "give either --targets FILE or --flat, not both".into(),
        )),
        (Some(p), false) => read_targets(p, n).map(Some),
        (None, true) => Ok(Some(flat())),
        (None, false) if optional => Ok(None),
        (None, false) => Err(CliError::Input(required.into())),
    }
}

/// Run `penner uniformize`.
pub fn run(o: &Options<'_>) -> Result<u8, CliError> {
    let precision = o
        .precision
        .parse::<Precision>()
        .map_err(|e| CliError::Input(format!("--precision: {e}")))?;
    let options = ClosedOptions {
        precision,
        certify: !o.extra.no_certify,
    };
    let shown = o.path.display().to_string();
    let surface = into_surface(load_flip_case(o.path)?);
    let n = surface.mesh.n_vertices();
    if o.extra.uv.is_some() && (o.extra.sphere || o.extra.hyperbolic) {
        return Err(CliError::Input(format!(
            "{shown}: --uv is for flat or cone targets (closed or with boundary), not --sphere or --hyperbolic"
        )));
    }
    if let Some(path) = o.extra.uv.as_deref() {
        super::uniformize_uv::refuse_existing(path, o.extra.uv_svg.as_deref())?;
    }
    if o.extra.hyperbolic {
        let targets = targets_of(o, n, true, || Targets::flat(n), "")?;
        let outcome = uniformize_hyperbolic(&surface, targets.as_ref(), &options)
            .map_err(|e| pipeline_error(&shown, &e))?;
        return super::uniformize_hyperbolic::report(&shown, &outcome, precision, o.output);
    }
    if o.extra.sphere {
        let outcome = uniformize_sphere(&surface, o.extra.pole, &options)
            .map_err(|e| pipeline_error(&shown, &e))?;
        return super::uniformize_sphere::report(&shown, &outcome, o.output, o.extra);
    }
    if !surface.mesh.is_closed() {
        let targets = targets_of(o, n, false, || flat_with_even_boundary(&surface.mesh), "the target angles are required: --targets FILE (a JSON array: Θ_v/π at interior vertices, φ_v/π at boundary vertices) or --flat")?;
        let outcome = uniformize_boundary(&surface, targets.as_ref(), &options)
            .map_err(|e| pipeline_error(&shown, &e))?;
        return super::uniformize_boundary::report(&shown, &surface, &outcome, o);
    }
    let targets = targets_of(
        o,
        n,
        false,
        || Targets::flat(n),
        "the target angles are required: --targets FILE (a JSON array of Θ_i/π) or --flat",
    )?
    .unwrap_or_else(|| Targets::flat(n));
    let bar = std::io::stderr().is_terminal().then(|| {
        let b = indicatif::ProgressBar::new_spinner();
        b.set_message(format!(
            "uniformizing {shown} ({} faces)",
            surface.mesh.n_faces()
        ));
        b.enable_steady_tick(std::time::Duration::from_millis(120));
        b
    });
    let mut progress = |s: &penner::uniformization::StepReport| {
        if let Some(b) = &bar {
            b.set_message(format!(
                "Newton step {}: max |Θ − θ| = {:.3e}, {} flips",
                s.iteration, s.residual_max, s.flips
            ));
        }
    };
    // The pipeline keeps the surface (not a copy) in its outcome; `--uv` needs the input
    // as given, which differs from the outcome's surface when that is rescaled.
    let input = o.extra.uv.is_some().then(|| surface.clone());
    let outcome = uniformize_closed_owned(surface, &targets, &options, &mut progress)
        .map_err(|e| pipeline_error(&shown, &e))?;
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    let surface = input.as_ref().unwrap_or(&outcome.surface);
    report_closed(&shown, surface, &outcome, precision, o)
}

/// The report of [`uniformize_closed`]'s outcome, the SVG and the claim written.
fn report_closed(
    shown: &str,
    surface: &penner::io::Surface,
    outcome: &ClosedOutcome,
    precision: Precision,
    o: &Options<'_>,
) -> Result<u8, CliError> {
    let sol = &outcome.solution;
    let bits = outcome.bits;
    let mut out = String::new();
    if outcome.shift != 0 {
        let _ = writeln!(
            out,
            "{shown}: lengths divided by 2^{} (exactly) before solving: the cone angles and u do not change with the scale, and the certificate is about the rescaled surface",
            outcome.shift
        );
    }
    let _ = writeln!(
        out,
        "{shown}: {} Euclidean flips to intrinsic Delaunay; {} Newton steps, {} Ptolemy flips (per step: {:?})",
        sol.euclidean_flips,
        sol.steps.len(),
        sol.flip_sequence.len(),
        sol.steps.iter().map(|s| s.flips).collect::<Vec<_>>()
    );
    if !sol.converged() {
        let _ = writeln!(
            out,
            "not converged ({:?}); max |Θ − θ| = {:e}; no certificate",
            sol.stop, sol.residual_max
        );
        super::files::emit(&out)?;
        return Ok(code::UNDECIDED);
    }
    if let Some(path) = o.extra.svg.as_deref() {
        out.push_str(&super::uniformize_svg::write(path, sol)?);
    }
    let mut uv_missing = false;
    if let Some(path) = o.extra.uv.as_deref() {
        let svg = o.extra.uv_svg.as_deref();
        let source = super::uniformize_uv::closed(surface, outcome);
        let (line, written) = super::uniformize_uv::write(path, svg, shown, source)?;
        out.push_str(&line);
        uv_missing = !written;
    }
    let Some(proof) = &outcome.proof else {
        out.push_str(&numerical_line(sol.residual_max));
        super::files::emit(&out)?;
        return Ok(code::UNDECIDED);
    };
    if precision == Precision::Dd {
        let _ = writeln!(
            out,
            "converged: max |Θ − θ| = {:e} (f64), {:e} after refinement in double-double; the certificate runs in {bits}-bit MPFR interval arithmetic (double-double has no directed rounding)",
            sol.residual_max, proof.residual_max
        );
    } else {
        let _ = writeln!(
            out,
            "converged: max |Θ − θ| = {:e} (f64), {:e} after refinement at {bits} bits",
            sol.residual_max, proof.residual_max
        );
    }
    let holds = match &outcome.metric {
        Some(CertifiedMetric::Rounded { reason }) => format!(
            "certified for the binary64-rounded lengths of the input, not its exact metric ({reason})"
        ),
        _ => "certified for the input's exact metric".to_string(),
    };
    let status = super::certificate_report::report_certificate(
        &mut out,
        &proof.outcome,
        outcome.claim_json(),
        o.output,
        &super::certificate_report::Certified {
            holds: &holds,
            written: "certificate",
        },
    )?;
    super::files::emit(&out)?;
    Ok(if uv_missing {
        status.max(code::UNDECIDED)
    } else {
        status
    })
}

/// The exact surface of a loaded case.
fn into_surface(case: FlipCase) -> penner::io::Surface {
    match case {
        FlipCase::Exact(s) => s,
        FlipCase::Decimal(d) => d.into_surface(),
    }
}
