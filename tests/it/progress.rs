//! Progress of long checks over their elements: the hook carried by `Settings` is called by
//! T08, T22, T23 and T29 with monotone counts ending at each stage's total, under the label of
//! the (check, precision) pair; the binary draws nothing when standard error is a pipe.

use crate::meshgen::icosphere;
use crate::support::{penner, scratch, text, write};
use penner::io::{Metric, Surface};
use penner::oracle::precision::Prec;
use penner::oracle::registry::{run_case, select};
use penner::theorems::progress::{Hook, Progress};
use penner::theorems::Settings;
use rug::Rational;
use std::collections::BTreeMap;
use std::sync::{Arc, Mutex};

/// Every call of the hook, in order: (task, stage, done, total).
#[derive(Default)]
struct Recording(Mutex<Vec<(String, String, u64, u64)>>);

impl Hook for Recording {
    fn elements(&self, task: &str, stage: &str, done: u64, total: u64) {
        self.0
            .lock()
            .unwrap()
            .push((task.to_string(), stage.to_string(), done, total));
    }
}

/// The calls grouped by (task, stage), in order.
type Stages = BTreeMap<(String, String), Vec<(u64, u64)>>;

fn stages(calls: &[(String, String, u64, u64)]) -> Stages {
    let mut by: Stages = BTreeMap::new();
    for (task, stage, done, total) in calls {
        by.entry((task.clone(), stage.clone()))
            .or_default()
            .push((*done, *total));
    }
    by
}

/// Whether one stage's counts start at 0, never decrease, keep one total and end at it.
fn monotone_to_total(counts: &[(u64, u64)]) -> bool {
    let Some(&(_, total)) = counts.first() else {
        return false;
    };
    counts.first().map(|c| c.0) == Some(0)
        && counts.windows(2).all(|w| w[0].0 <= w[1].0)
        && counts.iter().all(|&(d, t)| t == total && d <= total)
        && counts.last().map(|c| c.0) == Some(total)
}

/// A noisy icosphere (frequency `k`) whose exact lengths are its binary64 lengths.
fn noisy_sphere(k: u32) -> Surface {
    let mut e = icosphere(k);
    let sigma = 0.2 * e.mean_edge();
    e.jitter_normal(sigma, u64::from(k));
    let mesh = e.mesh();
    let lengths = e
        .lengths(&mesh)
        .into_iter()
        .map(|x| Rational::from_f64(x).unwrap())
        .collect();
    Surface::new("noisy", mesh, Metric::Lengths(lengths), None).unwrap()
}

#[test]
fn progress_hook_counts_are_monotone_and_end_at_the_total() {
    let case = noisy_sphere(6);
    let rec = Arc::new(Recording::default());
    let settings = Settings {
        progress: Progress::to(rec.clone()),
        ..Settings::default()
    };
    let checks = select(&["T08".into(), "T22".into(), "T23".into(), "T29".into()]).unwrap();
    let rows = run_case(&case, &checks, &[Prec::F64], &settings);
    assert_eq!(rows.len(), 4);
    let calls = rec.0.lock().unwrap().clone();
    let by = stages(&calls);
    for task in ["T08 f64", "T22 f64", "T23 f64", "T29 f64"] {
        assert!(by.keys().any(|(t, _)| t == task), "{task}: {by:?}");
    }
    for (key, counts) in &by {
        assert!(monotone_to_total(counts), "{key:?}: {counts:?}");
        // A stage over many elements moves in many steps, not from 0 straight to the end.
        if counts[0].1 >= 200 {
            assert!(counts.len() > 50, "{key:?}: {counts:?}");
        }
    }
    // The edges of T29 are counted one by one up to E.
    let e = case.mesh.n_edges() as u64;
    assert!(by
        .iter()
        .any(|((t, _), c)| t == "T29 f64" && c.last() == Some(&(e, e))));
    // Negative controls: the same test rejects a count that decreases, one that stops
    // short of its total, and one that does not start at 0.
    let (_, first) = by.iter().find(|(_, c)| c.len() >= 3).unwrap();
    let mut swapped = first.clone();
    let n = swapped.len();
    swapped.swap(n - 2, n - 3);
    swapped[n - 3].0 += 1;
    assert!(!monotone_to_total(&swapped), "{swapped:?}");
    assert!(!monotone_to_total(&first[..n - 1]) || first[n - 2] == first[n - 1]);
    assert!(!monotone_to_total(&first[1..]));
    // Without a hook the verdicts are the same rows.
    let quiet = run_case(&case, &checks, &[Prec::F64], &Settings::default());
    let verdicts = |r: &[penner::oracle::registry::Row]| -> Vec<_> {
        r.iter().map(|x| (x.id, x.outcome.clone())).collect()
    };
    assert_eq!(verdicts(&rows), verdicts(&quiet));
}

#[test]
fn check_draws_no_progress_on_a_pipe() {
    let d = scratch("progress-pipe");
    let mut off = Vec::new();
    let mut e = icosphere(4);
    e.jitter_normal(0.2 * e.mean_edge(), 4);
    e.write_off(&mut off).unwrap();
    let p = write(&d, "sphere.off", &off);
    for extra in [&[][..], &["--json"][..]] {
        let mut args = vec![
            "check".to_string(),
            p.display().to_string(),
            "--precision".into(),
            "f64".into(),
            "--only".into(),
            "T23".into(),
        ];
        args.extend(extra.iter().map(|s| (*s).to_string()));
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = penner(&args);
        assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
        // Standard error is a pipe here: no bar, no escape sequence, nothing at all.
        assert!(out.stderr.is_empty(), "{:?}", text(&out.stderr));
        assert!(!out.stdout.contains(&0x1b), "{}", text(&out.stdout));
    }
}
