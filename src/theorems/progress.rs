//! Progress of a long check over its elements, for displays: a hook that a check calls
//! with monotone counts `done ≤ total` per stage, under the label of the task (the
//! registry labels each (check, precision) pair, e.g. `T23 f64`). No-op by default; it
//! never changes a verdict (two [`Progress`] values compare equal whatever their hooks).
//!
//! ```
//! use penner::theorems::progress::{Hook, Progress};
//! use std::sync::{Arc, Mutex};
//! #[derive(Default)]
//! struct Record(Mutex<Vec<(String, u64, u64)>>);
//! impl Hook for Record {
//!     fn elements(&self, task: &str, stage: &str, done: u64, total: u64) {
//!         self.0.lock().unwrap().push((format!("{task}: {stage}"), done, total));
//!     }
//! }
//! let rec = Arc::new(Record::default());
//! let progress = Progress::to(rec.clone()).for_task("T29 f64");
//! let mut c = progress.counter("edges", 1000);
//! for _ in 0..1000 {
//!     c.add(1);
//! }
//! c.finish();
//! let calls = rec.0.lock().unwrap();
//! assert_eq!(calls.first().map(|c| c.1), Some(0));
//! assert_eq!(calls.last().map(|c| (c.1, c.2)), Some((1000, 1000)));
//! assert!(calls.windows(2).all(|w| w[0].1 <= w[1].1));
//! assert!(calls.iter().all(|c| c.0 == "T29 f64: edges"));
//! ```

use std::fmt;
use std::sync::Arc;

/// Receives the progress of a check: `done` of `total` elements of `stage` of `task` are
/// finished. Calls for one stage have nondecreasing `done`, starting at `0` and, when the
/// stage completes, ending at `total`.
pub trait Hook: Send + Sync {
    /// `done` of `total` elements of `stage` of `task` are finished.
    fn elements(&self, task: &str, stage: &str, done: u64, total: u64);
}

/// An optional [`Hook`] with the label of the task it reports for, carried by
/// [`super::Settings`] into the long checks.
#[derive(Clone, Default)]
pub struct Progress(Option<(Arc<dyn Hook>, Arc<str>)>);

impl Progress {
    /// Progress reported to `hook` (task label empty).
    pub fn to(hook: Arc<dyn Hook>) -> Progress {
        Progress(Some((hook, Arc::from(""))))
    }

    /// The same hook, reporting under the label `task`.
    pub fn for_task(&self, task: &str) -> Progress {
        Progress(
            self.0
                .as_ref()
                .map(|(h, _)| (Arc::clone(h), Arc::from(task))),
        )
    }

    /// Whether a hook is attached.
    pub fn is_on(&self) -> bool {
        self.0.is_some()
    }

    /// A counter over `total` elements of `stage`; it reports `0` now.
    pub fn counter(&self, stage: &'static str, total: usize) -> Counter<'_> {
        let total = total as u64;
        let hook = self.0.as_ref().map(|(h, t)| (h.as_ref(), t.as_ref()));
        if let Some((h, task)) = hook {
            h.elements(task, stage, 0, total);
        }
        Counter {
            hook,
            stage,
            done: 0,
            total,
            // About 200 reports per stage, whatever its size.
            step: (total / 200).max(1),
            next: (total / 200).max(1),
        }
    }
}

impl fmt::Debug for Progress {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(if self.is_on() {
            "Progress(hook)"
        } else {
            "Progress(none)"
        })
    }
}

impl PartialEq for Progress {
    /// Progress never changes a verdict: any two compare equal.
    fn eq(&self, _other: &Progress) -> bool {
        true
    }
}

/// Counts the elements of one stage ([`Progress::counter`]).
pub struct Counter<'a> {
    hook: Option<(&'a dyn Hook, &'a str)>,
    stage: &'static str,
    done: u64,
    total: u64,
    step: u64,
    next: u64,
}

impl Counter<'_> {
    /// `k` more elements are finished (the count stays at most `total`); reported every
    /// `total/200` elements and on reaching `total`.
    pub fn add(&mut self, k: usize) {
        let Some((h, task)) = self.hook else {
            return;
        };
        self.done = (self.done + k as u64).min(self.total);
        if self.done >= self.next || self.done == self.total {
            h.elements(task, self.stage, self.done, self.total);
            self.next = self.done + self.step;
        }
    }

    /// The stage is complete: reports `total`.
    pub fn finish(self) {
        if let Some((h, task)) = self.hook {
            h.elements(task, self.stage, self.total, self.total);
        }
    }
}
