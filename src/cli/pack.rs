//! `penner pack SURFACE [--svg FILE]`: the tangency circle packing of a surface's
//! combinatorics (`penner::circles::pack`), certified (B94), optionally drawn as SVG.

use super::error::{code, CliError};
use super::files::{emit, write_new};
use super::input::load_case;
use penner::circles::pack::pack;
use penner::circles::svg::render_svg;
use std::fmt::Write as _;
use std::path::Path;

/// Run `penner pack`: exit 0 when the packing is certified, 2 when it is computed but not
/// certified, 3 on bad input or when no packing is computed, 4 when the SVG cannot be
/// written (an existing file is never overwritten).
pub fn run(path: &Path, svg: Option<&Path>) -> Result<u8, CliError> {
    let case = load_case(path)?;
    let p = pack(&case.mesh).map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?;
    let mut text = format!(
        "{}: tangency packing ({}), {} vertices, {} Newton iterations, residual {:.1e}\n",
        case.name,
        p.kind,
        p.pattern.mesh.n_vertices(),
        p.iterations,
        p.residual
    );
    match &p.certificate {
        Ok(c) => {
            let _ = writeln!(
                text,
                "certified (B94): the exact packing is within {:.1e} in log-radius (λ ≥ {:.2e})",
                c.radius, c.lambda
            );
        }
        Err(why) => {
            let _ = writeln!(text, "not certified: {why}");
        }
    }
    if let Some(out) = svg {
        let doc = render_svg(&p.pattern.mesh, &p.lengths(), &p.radii());
        write_new(out, doc.as_bytes())?;
        let _ = writeln!(text, "wrote {}", out.display());
    }
    emit(&text)?;
    Ok(if p.certificate.is_ok() {
        code::HOLDS
    } else {
        code::UNDECIDED
    })
}
