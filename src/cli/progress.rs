//! Progress bars of `penner check` on standard error when it is a terminal and the
//! output is a table: one bar over the (check, precision) pairs, the message naming the
//! last one finished, and one bar per running long check over its elements
//! ([`ElementBars`]). Nothing is drawn on a pipe or with `--json`.

use penner::oracle::check_surface::{select, select_controls, CheckOptions};
use penner::oracle::registry::Row;
use penner::oracle::Surface;

/// Run `run` (a check of `case` with `options` and a row callback), drawing the bars when
/// standard error is a terminal and `json` is off.
pub fn with_check_progress<R>(
    case: &Surface,
    options: &mut CheckOptions,
    json: bool,
    run: impl FnOnce(&CheckOptions, &(dyn Fn(&Row) + Sync)) -> R,
) -> R {
    use std::io::IsTerminal;
    if json || !std::io::stderr().is_terminal() {
        return run(options, &|_| {});
    }
    let precs = options.precisions.len() + usize::from(options.negative_controls);
    let chosen = if options.negative_controls {
        select_controls(&options.only)
    } else {
        select(&options.only)
    };
    let checks = chosen.map_or(0, |c| c.len());
    let total = (checks * precs) as u64;
    let multi = indicatif::MultiProgress::new();
    let bar = multi.add(indicatif::ProgressBar::new(total));
    if let Ok(style) =
        indicatif::ProgressStyle::with_template("{bar:30} {pos}/{len} checks  {elapsed}  {msg}")
    {
        bar.set_style(style);
    }
    bar.set_message(format!(
        "{checks} checks × {precs} precisions on {} faces",
        case.mesh.n_faces()
    ));
    bar.enable_steady_tick(std::time::Duration::from_millis(200));
    let hook = std::sync::Arc::new(ElementBars {
        multi: multi.clone(),
        bars: std::sync::Mutex::new(std::collections::HashMap::new()),
    });
    options.settings.progress = penner::theorems::progress::Progress::to(hook);
    let done = |row: &Row| {
        bar.inc(1);
        bar.set_message(format!("{} {} done", row.id, row.precision));
    };
    let r = run(options, &done);
    bar.finish_and_clear();
    r
}

/// One progress bar per running check over its elements, drawn under the bar of checks;
/// a stage's bar is removed when the stage completes.
struct ElementBars {
    multi: indicatif::MultiProgress,
    bars: std::sync::Mutex<std::collections::HashMap<String, indicatif::ProgressBar>>,
}

impl penner::theorems::progress::Hook for ElementBars {
    fn elements(&self, task: &str, stage: &str, done: u64, total: u64) {
        let Ok(mut bars) = self.bars.lock() else {
            return;
        };
        let key = format!("{task}: {stage}");
        if done >= total {
            if let Some(b) = bars.remove(&key) {
                b.finish_and_clear();
                self.multi.remove(&b);
            }
            return;
        }
        let b = bars.entry(key).or_insert_with(|| {
            let b = self.multi.add(indicatif::ProgressBar::new(total));
            if let Ok(style) =
                indicatif::ProgressStyle::with_template("{bar:30} {pos}/{len}  {prefix}: {msg}")
            {
                b.set_style(style);
            }
            b.set_prefix(task.to_string());
            b.set_message(stage.to_string());
            b
        });
        b.set_length(total);
        b.set_position(done);
    }
}
