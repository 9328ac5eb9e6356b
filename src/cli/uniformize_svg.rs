//! `penner uniformize … --svg OUT.svg` for closed targets: the flattened result laid out by
//! unfolding (a fundamental domain, cut along the edges outside the dual spanning tree),
//! every triangle's orientation certified (exact `orient2d` on the drawn coordinates).

use super::error::CliError;
use super::files::write_new;
use penner::mesh::Face;
use penner::uniformization::layout::{unfold, unproved_faces};
use penner::uniformization::svg::{render_layout_svg, scaled_lengths_f64};
use penner::uniformization::Uniformization;
use std::path::Path;

/// Draw the layout of `sol` (final triangulation, lengths `e^{(u_i+u_j)/2}ℓ_ij`) to the new
/// file `path`; the line to report.
pub fn write(path: &Path, sol: &Uniformization) -> Result<String, CliError> {
    let lengths = scaled_lengths_f64(&sol.mesh, &sol.base_lengths, &sol.u);
    let layout = unfold(&sol.mesh, &lengths, Face(0));
    let folds = unproved_faces(&sol.mesh, &layout).len();
    let picture = render_layout_svg(&sol.mesh, &layout);
    write_new(path, picture.as_bytes())?;
    Ok(format!(
        "layout drawn to {} ({folds} faces not certified counterclockwise)\n",
        path.display()
    ))
}
