//! Flipping to the intrinsic Delaunay triangulation as one library call, the pipeline
//! behind `penner delaunay`: the flips at a working precision (exact rationals, MPFR,
//! double-double, binary64; the scaled metric `e^{(u_i+u_j)/2}ℓ_ij` kept as `m·2ᵏ`, B67),
//! every decision certified by the ladder (B61–B63), then, for a rounded run, the flip
//! sequence replayed on the **input's exact metric** (B80, B83) so that the outcome says
//! whether the triangulation is certified intrinsic Delaunay for the input or only for the
//! rounded lengths the run stored.
//!
//! ```
//! use penner::algorithms::delaunay_pipeline::{intrinsic_delaunay, DelaunayCertificate, DelaunayOptions};
//! use penner::io::{FlipCase, Surface};
//! use penner::mesh::{builders::Embedded, Mesh};
//! use penner::scalar::prec::Prec;
//! use rug::Rational;
//! // A flat kite split by its long diagonal (0, 0)–(4, 0): both opposite angles are
//! // obtuse, so one flip, to (2, 1)–(2, −1); at f64, then replayed on the exact metric.
//! let q = |x: i32, y: i32| [Rational::from(x), Rational::from(y), Rational::from(0)];
//! let e = Embedded {
//!     mesh: Mesh::from_faces(4, &[[0, 1, 2], [1, 0, 3]]).unwrap(),
//!     positions: vec![q(0, 0), q(4, 0), q(2, 1), q(2, -1)],
//!     exact: true,
//! };
//! let mut case = FlipCase::Exact(Surface::from_embedded("kite", e).unwrap());
//! let out = intrinsic_delaunay(&mut case, &DelaunayOptions::at(Prec::F64)).unwrap();
//! assert_eq!(out.report.flips, 1);
//! assert_eq!(out.certificate, DelaunayCertificate::InputMetric);
//! assert!(out.holds());
//! ```

use crate::algorithms::flip_scaled::flip_to_delaunay_scaled;
use crate::algorithms::flip_to_delaunay::{
    flip_to_delaunay, flip_to_delaunay_exact, ExactLengths, FlipCounter, FlipKind, FlipOptions,
    FlipReport,
};
use crate::algorithms::replay::{replay_escalating_lazy, BrokenStep, FlippedLens, Replayed};
use crate::algorithms::replay_input::PositionMetric;
use crate::io::write::Values;
use crate::io::FlipCase;
use crate::mesh::{Edge, Mesh};
use crate::predicates::delaunay::QuadEdges;
use crate::scalar::exp_length::ExpLength;
use crate::scalar::prec::Prec;
use crate::scalar::{Dd, Mpfr, Real};
use rug::Rational;
use std::any::Any;

/// Bit size (numerator + denominator) past which exact Ptolemy flipping continues on
/// enclosures instead.
pub const EXACT_GUARD_BITS: u64 = 4096;

/// First and last MPFR precision of the replay on the input metric.
const REPLAY_BITS: (u32, u32) = (128, 1024);

/// The flipped lengths, indexed by `Edge.idx()`.
#[derive(Clone, Debug)]
pub enum FlipValues {
    /// Binary64 lengths (each exactly the value written).
    Binary64(Vec<f64>),
    /// Exact values.
    Exact(Vec<Rational>),
}

impl FlipValues {
    /// The values as the writers take them.
    pub fn values(&self) -> Values<'_> {
        match self {
            FlipValues::Binary64(v) => Values::Binary64(v),
            FlipValues::Exact(v) => Values::Exact(v),
        }
    }
}

/// Options of [`intrinsic_delaunay`].
#[derive(Clone, Debug)]
pub struct DelaunayOptions {
    /// Euclidean or Ptolemy flips.
    pub kind: FlipKind,
    /// The working precision.
    pub precision: Prec,
    /// Per-vertex log scale factors `u`: flip `e^{(u_i+u_j)/2}·ℓ_ij` (binary64 only).
    pub scale_factors: Option<Vec<f64>>,
    /// After a rounded run, replay its flips on the input's exact metric (B80).
    pub replay_on_input: bool,
    /// A counter of the flips done, for a progress display in another thread.
    pub counter: FlipCounter,
}

impl DelaunayOptions {
    /// Euclidean flips at `precision`, replayed on the input metric, not scaled.
    pub fn at(precision: Prec) -> DelaunayOptions {
        DelaunayOptions {
            kind: FlipKind::Euclidean,
            precision,
            scale_factors: None,
            replay_on_input: true,
            counter: FlipCounter::default(),
        }
    }
}

/// What the flipped triangulation is certified to be.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DelaunayCertificate {
    /// Intrinsic Delaunay for the input metric (exact run, or replay on the input, B80).
    InputMetric,
    /// Intrinsic Delaunay for the rounded lengths the run stored (B65) only.
    RoundedMetric,
    /// Not every edge is certified Delaunay even for the rounded lengths.
    None,
}

impl DelaunayCertificate {
    /// The name in `--summary` documents.
    pub fn name(self) -> &'static str {
        match self {
            DelaunayCertificate::InputMetric => "input_metric",
            DelaunayCertificate::RoundedMetric => "rounded_metric",
            DelaunayCertificate::None => "none",
        }
    }
}

/// Errors of [`intrinsic_delaunay`]: every one is the input's or the options' (the run
/// itself never fails on valid input: undecided edges are counted in the outcome).
#[derive(Debug, thiserror::Error)]
pub enum DelaunayError {
    /// The flips refused the input (named by the surface and element).
    #[error("{0}")]
    Flips(String),
    /// A length leaves binary64's exponent range at `f64` or `dd`.
    #[error("{0}")]
    Range(String),
    /// Exact Ptolemy lengths outgrew [`EXACT_GUARD_BITS`].
    #[error("{name}: exact lengths outgrew {EXACT_GUARD_BITS} bits after {flips} flips; use a bit count such as --precision 1024")]
    ExactOutgrew {
        /// The surface.
        name: String,
        /// Flips done when they did.
        flips: usize,
    },
    /// Exact arithmetic with Euclidean flips or squared lengths.
    #[error("--precision exact needs --flips ptolemy and exact (not squared) lengths: Euclidean flips make lengths irrational")]
    ExactNeedsPtolemy,
    /// Scale factors at a precision other than binary64.
    #[error(
        "--scale-factors: scaled lengths are m·2^k with binary64 significands; use --precision f64"
    )]
    ScaledNeedsF64,
    /// Scale factors not one finite number per vertex.
    #[error("{got} scale factors for a surface with {expected} vertices")]
    ScaleCount {
        /// Vertices.
        expected: usize,
        /// Given.
        got: usize,
    },
}

/// The outcome of [`intrinsic_delaunay`]; the flipped triangulation is the case's mesh.
#[derive(Clone, Debug)]
pub struct DelaunayOutcome {
    /// The flips done, their sequence, undecided and refused edges.
    pub report: FlipReport,
    /// The flipped lengths' exact values (binary64 values as stored).
    pub lengths: FlipValues,
    /// What the triangulation is certified to be.
    pub certificate: DelaunayCertificate,
    /// Edges not certified for the input metric (`None`: not counted, no replay or the
    /// rounded run itself not certified).
    pub not_for_input: Option<usize>,
    /// The replay on the input metric and the bits it reached.
    pub replay: Option<(Replayed<FlippedLens>, u32)>,
    /// The flip kind.
    pub kind: FlipKind,
    /// The working precision.
    pub precision: Prec,
    /// Whether the metric was scaled.
    pub scaled: bool,
}

impl DelaunayOutcome {
    /// Certified intrinsic Delaunay for the input metric, or for the rounded one when no
    /// replay was asked for.
    pub fn holds(&self) -> bool {
        matches!(
            (self.certificate, self.not_for_input),
            (DelaunayCertificate::InputMetric, _) | (DelaunayCertificate::RoundedMetric, None)
        )
    }

    /// What the triangulation is certified to be, in words.
    pub fn words(&self) -> String {
        certificate_words(
            self.certificate,
            self.not_for_input,
            self.replay.as_ref(),
            self.scaled,
            &self.report,
        )
    }

    /// The `--summary` document: flips, precision and what is certified.
    pub fn summary(&self) -> serde_json::Value {
        summary_json(
            &self.report,
            self.kind,
            self.precision,
            self.certificate,
            self.not_for_input,
        )
    }
}

/// Flip `case` to the intrinsic Delaunay triangulation (in place: the mesh of `case` is
/// the flipped one afterwards) with `options` (module documentation).
pub fn intrinsic_delaunay(
    case: &mut FlipCase,
    options: &DelaunayOptions,
) -> Result<DelaunayOutcome, DelaunayError> {
    let prec = options.precision;
    let kind = options.kind;
    let scale = options.scale_factors.as_deref();
    if let Some(u) = scale {
        if prec != Prec::F64 {
            return Err(DelaunayError::ScaledNeedsF64);
        }
        if u.len() != case.mesh().n_vertices() {
            return Err(DelaunayError::ScaleCount {
                expected: case.mesh().n_vertices(),
                got: u.len(),
            });
        }
    }
    // The input triangulation, for the replay of a rounded run on the exact input metric
    // (the squared lengths of positions follow the input mesh's edges).
    let input_mesh = (options.replay_on_input && prec != Prec::Exact && scale.is_none())
        .then(|| case.mesh().clone());
    // The f64 squared lengths of OBJ/OFF input, computed once for the f64 lengths and the
    // replay's first rung.
    let squares = match &*case {
        FlipCase::Decimal(s) if input_mesh.is_some() && prec == Prec::F64 => {
            Some(s.squared_lengths_f64())
        }
        _ => None,
    };
    let opts = FlipOptions {
        record: true,
        progress: Some(options.counter.clone()),
        ..FlipOptions::default()
    };
    let (report, lengths) = flip_case(case, (prec, kind), scale, squares.as_deref(), &opts)?;
    // Exact Ptolemy flipping has no rounding: its certificate is for the input metric.
    let exact_run = prec == Prec::Exact;
    let rounded_ok = report.all_certified_delaunay();
    let replay = input_mesh
        .as_ref()
        .filter(|_| rounded_ok && !exact_run)
        .map(|mesh| replay_on_input(case, mesh, squares.as_deref(), &report.sequence, kind));
    let (certificate, not_for_input) = certificate_of(rounded_ok, exact_run, replay.as_ref());
    Ok(DelaunayOutcome {
        report,
        lengths,
        certificate,
        not_for_input,
        replay,
        kind,
        precision: prec,
        scaled: scale.is_some(),
    })
}

/// Flip the conformally scaled metric of `case` (lengths kept as `m·2ᵏ`, B67) and return
/// the report and the exact values of the final lengths.
fn flip_scaled(
    case: &mut FlipCase,
    u: &[f64],
    kind: FlipKind,
    opts: &FlipOptions,
) -> Result<(FlipReport, FlipValues), DelaunayError> {
    let base: Vec<f64> = case.lengths(());
    let name = case.name().to_string();
    let (report, lengths) = flip_to_delaunay_scaled(case.mesh_mut(), &base, u, kind, opts)
        .map_err(|e| DelaunayError::Flips(format!("{name}: {e}")))?;
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
) -> Result<(FlipReport, FlipValues), DelaunayError> {
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
        .map_err(|e| DelaunayError::Flips(format!("{name}: {e}")))?;
    let l = match (Box::new(l) as Box<dyn Any>).downcast::<Vec<f64>>() {
        Ok(binary64) => return Ok((report, FlipValues::Binary64(*binary64))),
        Err(other) => other
            .downcast::<Vec<T>>()
            .map_err(|_| DelaunayError::Flips(format!("{name}: length type")))?,
    };
    let exact = l
        .iter()
        .enumerate()
        .map(|(i, x)| {
            x.to_rational()
                .ok_or_else(|| DelaunayError::Flips(format!("{name}: edge {i} overflowed")))
        })
        .collect::<Result<_, _>>()?;
    Ok((report, FlipValues::Exact(exact)))
}

/// A positive finite input length that the binary64 exponent range of `f64` or `Dd`
/// turns into `0` or `∞` names its real cause, not "length inf" (MPFR's range holds it).
/// Exact lengths decide directly; otherwise (positions, squared lengths) the length of
/// the first such edge is recomputed at 128 MPFR bits, whose exponent range holds every
/// length of finite decimal positions (the message only; the run is refused either way).
fn binary64_range<T: Real + 'static>(
    case: &FlipCase,
    l: &[T],
    name: &str,
) -> Result<(), DelaunayError> {
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
        None => crate::scalar::Precision::new(128)
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
    Err(DelaunayError::Range(format!(
        "{name}: {cause} of this precision; use MPFR bits, e.g. --precision 128"
    )))
}

/// Flip `case` at `prec` with flips of `kind` (the scaled metric when `scale` is given),
/// from the `f64` `squares` when kept; the report and the stored lengths' values.
fn flip_case(
    case: &mut FlipCase,
    (prec, kind): (Prec, FlipKind),
    scale: Option<&[f64]>,
    squares: Option<&[f64]>,
    opts: &FlipOptions,
) -> Result<(FlipReport, FlipValues), DelaunayError> {
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
                    .map_err(|e| DelaunayError::Flips(format!("{}: {e}", case.name())))?;
            match lengths {
                ExactLengths::Exact(v) => Ok((report, FlipValues::Exact(v))),
                ExactLengths::Enclosed(_) => Err(DelaunayError::ExactOutgrew {
                    name: case.name().to_string(),
                    flips: report.fell_back_after.unwrap_or(report.flips),
                }),
            }
        }
        (Prec::Exact, ..) => Err(DelaunayError::ExactNeedsPtolemy),
        (Prec::F64, ..) => flip_real::<f64>(case, (), kind, squares, opts),
        (Prec::Dd, ..) => flip_real::<Dd>(case, (), kind, None, opts),
        (Prec::Mpfr(p), ..) => flip_real::<Mpfr>(case, p, kind, None, opts),
    }
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
) -> (DelaunayCertificate, Option<usize>) {
    match (replay, rounded_ok) {
        (_, false) => (DelaunayCertificate::None, None),
        (None, true) if exact_run => (DelaunayCertificate::InputMetric, Some(0)),
        (None, true) => (DelaunayCertificate::RoundedMetric, None),
        (Some((r, _)), true) if r.certified_delaunay() => {
            (DelaunayCertificate::InputMetric, Some(0))
        }
        (Some((r, _)), true) => (DelaunayCertificate::RoundedMetric, Some(not_certified(r))),
    }
}

/// The `--summary` document: flips, precision and what is certified.
fn summary_json(
    report: &FlipReport,
    kind: FlipKind,
    prec: Prec,
    certificate: DelaunayCertificate,
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
    certificate: DelaunayCertificate,
    not_for_input: Option<usize>,
    replay: Option<&(Replayed<FlippedLens>, u32)>,
    scaled: bool,
    report: &FlipReport,
) -> String {
    match (certificate, not_for_input) {
        (DelaunayCertificate::InputMetric, _) => {
            "every edge certified intrinsic Delaunay, certified for the input metric".to_string()
        }
        (DelaunayCertificate::RoundedMetric, Some(n)) => format!(
            "every edge certified intrinsic Delaunay for the rounded metric only; {n} edge(s) not certified for the input metric{}",
            replay.map_or(String::new(), |(r, bits)| replay_detail(r, *bits))
        ),
        (DelaunayCertificate::RoundedMetric, None) => format!(
            "every edge certified intrinsic Delaunay for the rounded metric only ({})",
            if scaled {
                "the scaled input metric is not replayed"
            } else {
                "the replay on the input metric was skipped"
            }
        ),
        (DelaunayCertificate::None, _) => format!(
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
