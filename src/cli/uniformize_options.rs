//! The options of `penner uniformize` and the line of a numerical (uncertified) result:
//! shared by [`super::uniformize`] and the per-target reports it dispatches to.

use std::path::Path;

/// Options of `penner uniformize`.
pub struct Options<'a> {
    /// The surface file.
    pub path: &'a Path,
    /// Targets file (JSON array of Θ_i/π).
    pub targets: Option<&'a Path>,
    /// Flat targets.
    pub flat: bool,
    /// `f64`, `dd` or MPFR bits.
    pub precision: &'a str,
    /// Certificate output.
    pub output: Option<&'a Path>,
    /// `--sphere`, `--pole`, `--obj`, `--svg`.
    pub extra: &'a super::args::UniformizeExtra,
}

/// The line of a converged solve without a certificate (`--no-certify`): numerical.
pub(super) fn numerical_line(residual_max: f64) -> String {
    format!(
        "converged: max |Θ − θ| = {residual_max:e} (f64); numerical, not certified (--no-certify)\n"
    )
}
