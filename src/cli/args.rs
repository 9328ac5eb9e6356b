//! Command-line arguments (clap derive).

use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;

/// Certified checks of discrete conformal geometry on triangulated surfaces.
///
/// With no command, runs the verification report on the built-in corpus.
#[derive(Debug, Parser)]
#[command(name = "penner", version, about, long_about = None)]
pub struct Cli {
    /// What to do (default: the report on the built-in corpus).
    #[command(subcommand)]
    pub command: Option<Command>,
    /// Repairs of OBJ/OFF input, for every subcommand that reads a surface.
    #[command(flatten)]
    pub repair: RepairArgs,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Run every applicable catalogue check on surfaces (JSON, OBJ or OFF).
    Check {
        /// The surface files, or directories (their .json, .obj and .off files, sorted, not
        /// recursively); one report per file.
        #[arg(required = true, num_args = 1..)]
        surfaces: Vec<PathBuf>,
        /// Comma list of precisions: f64, dd, MPFR bits (53..=65536), exact.
        #[arg(long, default_value = penner::oracle::precision::DEFAULT_LIST)]
        precision: String,
        /// Only these checks (comma list of IDs such as T01,T05).
        #[arg(long, value_delimiter = ',')]
        only: Vec<String>,
        /// Print JSON instead of a table.
        #[arg(long)]
        json: bool,
        /// Do not write failure files.
        #[arg(long)]
        no_failure_files: bool,
        /// Run the negative controls instead: each check's comparison on data made wrong by
        /// a fixed perturbation, expected to fail; failures are written as failure files.
        #[arg(long)]
        negative_controls: bool,
        /// Use these lengths instead of the file's metric: a JSON array, one length per
        /// edge in the edge order of surface JSON (as `delaunay --lengths-out` writes).
        #[arg(long, value_name = "FILE")]
        lengths: Option<PathBuf>,
    },
    /// Answer a JSON claim (protocol v1, schema/claim-v1.schema.json) with a verdict.
    Certify {
        /// The claim file, or `-` for standard input.
        claim: PathBuf,
    },
    /// Flip a surface to its intrinsic Delaunay triangulation and write the result.
    Delaunay {
        /// The surface file.
        surface: PathBuf,
        /// Kind of flip.
        #[arg(long, value_enum, default_value_t = FlipKind::Euclidean)]
        flips: FlipKind,
        /// Working precision for the lengths written out: f64, dd, or MPFR bits.
        #[arg(long, default_value = "256")]
        precision: String,
        /// Output file (must not exist); standard output if absent.
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// Flip the conformally scaled metric e^{(u_i+u_j)/2}·ℓ_ij instead: a JSON array
        /// with one log scale factor u per vertex (|u| ≤ 2^20; lengths kept as m·2^k, so
        /// nothing overflows; f64 significands).
        #[arg(long, value_name = "FILE")]
        scale_factors: Option<PathBuf>,
        /// Write a JSON summary (flips, and what is certified: `input_metric`,
        /// `rounded_metric` or `none`) to this new file.
        #[arg(long, value_name = "FILE")]
        summary: Option<PathBuf>,
        /// Skip replaying the flips on the exact input metric: the result is then certified
        /// for the rounded metric only, and says so.
        #[arg(long)]
        no_input_replay: bool,
        /// With `-o out.obj` or `-o out.off`: also write the lengths (a JSON array, one per
        /// line, in the edge order of surface JSON) to this file (must not exist).
        #[arg(long, value_name = "FILE")]
        lengths_out: Option<PathBuf>,
    },
    /// Re-run a saved failure file and report whether it still fails.
    Replay {
        /// A file written by `penner check` (`*.penner-failure-N.json`).
        file: PathBuf,
        /// Print JSON instead of a table.
        #[arg(long)]
        json: bool,
    },
    /// Discrete uniformization with Ptolemy flips: solve θ(u) = Θ, refine, certify (T24, B71)
    /// and write the certificate as a `uniformization` claim for `penner certify`.
    Uniformize {
        /// The surface file (JSON, OBJ or OFF); with boundary it is solved on its double.
        surface: PathBuf,
        /// Target cone angles: a JSON array with Θ_i/π per vertex (exact strings or numbers);
        /// on a surface with boundary, φ_v/π (the boundary angle sum) at boundary vertices.
        #[arg(long, value_name = "FILE")]
        targets: Option<PathBuf>,
        /// Flat targets (Θ_i = 2π; tori); with boundary, 2π inside and the boundary
        /// curvature 2πχ spread evenly over the boundary vertices of each component.
        #[arg(long)]
        flat: bool,
        /// Refinement and certificate precision: f64, dd, or MPFR bits.
        #[arg(long, default_value = "256")]
        precision: String,
        /// Certificate output (must not exist).
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// The sphere target and the pictures.
        #[command(flatten)]
        extra: UniformizeExtra,
    },
    /// The tangency circle packing of a surface's combinatorics (disk: boundary radii 1;
    /// sphere: punctured at v0), certified, optionally drawn as SVG.
    Pack {
        /// The surface file.
        surface: PathBuf,
        /// Write an SVG picture of the laid-out packing to this new file (`--sphere`: the caps
        /// on the unit sphere, seen orthographically).
        #[arg(long, value_name = "FILE")]
        svg: Option<PathBuf>,
        /// The maximal packing of a disk: horocycles on the boundary, laid out in the unit
        /// disk, tangency certified (T11).
        #[arg(long, conflicts_with = "sphere")]
        disk: bool,
        /// The packing of a sphere by caps: punctured at `--puncture`, maximally packed,
        /// projected stereographically, tangency certified (T11).
        #[arg(long)]
        sphere: bool,
        /// The vertex a sphere is punctured at (`--sphere`).
        #[arg(long, default_value_t = 0)]
        puncture: usize,
        /// MPFR bits of the refined radii and of the certificate (`--disk`, `--sphere`);
        /// 53 computes in f64.
        #[arg(long, default_value_t = 128)]
        bits: u32,
        /// The tangency tolerance ε to certify (`--disk`, `--sphere`), an exact decimal.
        #[arg(long, default_value = "1e-30")]
        epsilon: String,
        /// Write the circles (and caps) as JSON to this new file (`--disk`, `--sphere`).
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
    /// The verification report on the built-in corpus (what `penner` alone runs).
    Report {
        /// Comma list of precisions.
        #[arg(long, default_value = penner::oracle::precision::REPORT_LIST)]
        precision: String,
        /// Print JSON instead of a table.
        #[arg(long)]
        json: bool,
    },
}

/// Which flip carries lengths across an edge flip.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum FlipKind {
    /// Euclidean flip: the new diagonal of the planar layout (preserves the cone metric).
    Euclidean,
    /// Ptolemy flip: ℓ_kl = (ℓ_ki ℓ_lj + ℓ_il ℓ_jk) / ℓ_ij (docs/catalogue.md §5, Eq. 18).
    Ptolemy,
}

/// Options of `penner uniformize` beyond the cone targets: the sphere target and pictures.
#[derive(clap::Args, Debug, Clone)]
pub struct UniformizeExtra {
    /// The sphere target (Thm 9): the convex polyhedron inscribed in the unit sphere.
    #[arg(long, conflicts_with_all = ["targets", "flat"])]
    pub sphere: bool,
    /// The hyperbolic target (Thm 11, genus ≥ 2): the input lengths read as hyperbolic
    /// lengths, all cone angles 2π (or `--targets` with Σ(2π − Θ) > 2πχ), sinh scaling
    /// with λ-Ptolemy flips to the hyperbolic Delaunay triangulation along the way;
    /// residual and existence certified on the final triangulation (B39, B87, B89).
    #[arg(long, conflicts_with_all = ["flat", "sphere"])]
    pub hyperbolic: bool,
    /// The pole v∞ of `--sphere` (default: a graph centre, then the vertices of largest
    /// degree, the first that works).
    #[arg(long, value_name = "V", requires = "sphere")]
    pub pole: Option<u32>,
    /// Write the inscribed polyhedron of `--sphere` as OBJ to this new file.
    #[arg(long, value_name = "FILE", requires = "sphere")]
    pub obj: Option<PathBuf>,
    /// Write the planar layout of the result as SVG to this new file.
    #[arg(long, value_name = "FILE")]
    pub svg: Option<PathBuf>,
    /// Closed flat or cone targets: write the common refinement of the input mesh and the
    /// final triangulation as OBJ to this new file (`v` on the input surface, `vt` the
    /// flattened metric), with the sidecar `FILE.json` (input face and barycentric
    /// coordinates per face, input vertex or crossing per vertex); folds and the tiling of
    /// the input faces are checked exactly on the written decimals.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["sphere", "hyperbolic"])]
    pub uv: Option<PathBuf>,
    /// With `--uv`: draw the UV layout of the refinement as SVG to this new file, the pieces
    /// of the input edges in orange, of the final triangulation's edges in blue, cones red.
    #[arg(long, value_name = "FILE", requires = "uv")]
    pub uv_svg: Option<PathBuf>,
    /// Solve in f64 only and skip the refinement and the certificate: the result is
    /// numerical and says so (exit 2, no claim to write).
    #[arg(long, conflicts_with = "output")]
    pub no_certify: bool,
}

/// Repairs of OBJ/OFF input (`penner::io::repair`), each reported; nothing is changed
/// without them. One flag per repair, as the command line spells them.
#[allow(clippy::struct_excessive_bools)]
#[derive(clap::Args, Debug, Clone, Copy, Default)]
pub struct RepairArgs {
    /// All three repairs: --triangulate, --orient and --drop-unreferenced.
    #[arg(long, global = true)]
    pub repair: bool,
    /// Split polygon faces into triangles: planar ones in their plane (largest smallest
    /// angle, exact predicates), others as the best non-folding fan.
    #[arg(long, global = true)]
    pub triangulate: bool,
    /// Reverse faces to one consistent orientation (a non-orientable surface is an error
    /// naming a cycle of faces).
    #[arg(long, global = true)]
    pub orient: bool,
    /// Remove vertices that belong to no face.
    #[arg(long, global = true)]
    pub drop_unreferenced: bool,
}

impl RepairArgs {
    /// The repairs asked for.
    pub fn repairs(self) -> penner::io::repair::Repairs {
        penner::io::repair::Repairs {
            triangulate: self.repair || self.triangulate,
            orient: self.repair || self.orient,
            drop_unreferenced: self.repair || self.drop_unreferenced,
        }
    }
}
