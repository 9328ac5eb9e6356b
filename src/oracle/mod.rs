//! Claims in, verdicts out: the check registry, reports, failure files and the versioned
//! claim protocol (`schema/claim-v1.schema.json`, `docs/oracle.md`).
//!
//! This layer sits on top of `theorems`: it runs checks and predicates and packages their
//! answers. It decides nothing itself: a `delaunay_flip` claim is replayed by
//! [`crate::algorithms::flip_replay`] and its ties searched by
//! [`crate::algorithms::tie_search`].

pub mod answer;
pub mod assertion;
pub mod case;
pub mod certify;
pub mod certify_circles;
pub mod certify_energy;
pub mod certify_hyperbolic;
pub mod check_surface;
pub mod claim;
pub mod claim_circles;
pub mod claim_hyperbolic;
pub mod claim_parse;
pub mod corpus;
pub mod failure;
pub mod flip_claim;
/// The certified replay of a `delaunay_flip` claim, kept here under its former path.
pub use crate::algorithms::flip_replay;
/// The working precisions (moved to [`crate::scalar::prec`]; kept here for the paths users know).
pub use crate::scalar::prec as precision;
#[macro_use]
pub mod check_entry;
pub mod registry;
// After `check_entry`, whose `at_precision!` macro they use.
pub mod checks;
pub mod checks_circles;
pub mod checks_energy;
pub mod checks_extra;
pub mod checks_lobachevsky;
pub mod checks_uniformization;
pub mod controls;
/// Vertex-fixing comparison of triangulations, kept here under its former path.
pub use crate::mesh::relabel;
pub mod report;
pub mod shrink;
/// The tie-flip search of a `delaunay_flip` claim, kept here under its former path.
pub use crate::algorithms::tie_search;

pub use crate::io::{Metric, Surface};
pub use case::MetricOps;
pub use precision::Prec;
pub use registry::{catalogue, Check, Outcome, Row};
