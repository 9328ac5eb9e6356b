//! Shared helpers for the integration tests: case counts, and running the built `penner`
//! binary end to end (scratch directories, input files, `penner certify` answers).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Number of cases for a randomized test: `default` normally, `long` when the
/// `PENNER_LONG` environment variable is set (the deep search, see README).
pub fn cases(default: usize, long: usize) -> usize {
    if long_mode() {
        long
    } else {
        default
    }
}

/// Whether the deep search runs (`PENNER_LONG` set).
pub fn long_mode() -> bool {
    std::env::var_os("PENNER_LONG").is_some()
}

/// This run's shard `(i, n)` of the long mode's generated cases: `PENNER_SHARD=i/n` with
/// `0 ≤ i < n` runs only the cases whose index is `i` modulo `n` (docs/testing.md,
/// "Sharding the long search"); `(0, 1)`, every case, when unset or outside the long mode.
///
/// # Panics
/// On a malformed `PENNER_SHARD` (not `i/n` with integers `0 ≤ i < n`), naming it.
pub fn shard() -> (usize, usize) {
    shard_from(std::env::var("PENNER_SHARD").ok().as_deref(), long_mode())
}

/// [`shard`] for the value `v` of `PENNER_SHARD` and the mode.
///
/// # Panics
/// On a malformed value, naming it.
pub fn shard_from(v: Option<&str>, long: bool) -> (usize, usize) {
    let Some(v) = v else {
        return (0, 1);
    };
    let parsed = parse_shard(v).unwrap_or_else(|| {
        panic!("PENNER_SHARD={v:?}: expected i/n with integers 0 <= i < n, e.g. 3/16")
    });
    if long {
        parsed
    } else {
        (0, 1)
    }
}

/// `i/n` with `0 ≤ i < n`, or `None`.
pub fn parse_shard(v: &str) -> Option<(usize, usize)> {
    let (i, n) = v.trim().split_once('/')?;
    let (i, n): (usize, usize) = (i.trim().parse().ok()?, n.trim().parse().ok()?);
    (i < n).then_some((i, n))
}

/// Whether generated case `index` runs in this shard ([`shard`]).
pub fn in_shard(index: usize) -> bool {
    let (i, n) = shard();
    index % n == i
}

/// The indices of `0..cases(default, long)` this shard runs ([`shard`]).
pub fn case_indices(default: usize, long: usize) -> impl Iterator<Item = usize> {
    shard_indices(cases(default, long), shard())
}

/// The cases of a generated batch this shard runs ([`shard`]): those whose index in the
/// batch is in the shard (the whole batch outside the long mode or without
/// `PENNER_SHARD`).
pub fn shard_cases<T: Clone>(all: &[T]) -> Vec<T> {
    shard_cases_of(all, shard())
}

/// The cases of `all` whose index `k` has `k ≡ i (mod n)`.
pub fn shard_cases_of<T: Clone>(all: &[T], (i, n): (usize, usize)) -> Vec<T> {
    shard_indices(all.len(), (i, n))
        .map(|k| all[k].clone())
        .collect()
}

/// The indices `k < count` with `k ≡ i (mod n)`.
pub fn shard_indices(count: usize, (i, n): (usize, usize)) -> impl Iterator<Item = usize> {
    (0..count).skip(i).step_by(n.max(1))
}

/// [`case_indices`] as `u64` seeds.
pub fn case_seeds(default: usize, long: usize) -> impl Iterator<Item = u64> {
    case_indices(default, long).map(|k| k as u64)
}

/// A proptest configuration with `cases(default, long)` cases; in shard `i` of `n` it runs
/// its share of the cases from an RNG seeded by the shard, so that shards explore
/// different streams (proptest has no case index to partition).
pub fn proptest_config(default: usize, long: usize) -> proptest::test_runner::Config {
    let (i, n) = shard();
    let mut c = proptest::test_runner::Config::with_cases(cases(default, long).div_ceil(n) as u32);
    if n > 1 {
        c.rng_seed = proptest::test_runner::RngSeed::Fixed(0x5045_4e4e_4552 + i as u64);
    }
    c
}

const BIN: &str = env!("CARGO_BIN_EXE_penner");

/// A scratch directory unique to one test.
pub(crate) fn scratch(test: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("penner-it-cli-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("scratch dir");
    d
}

/// Run the built `penner` binary with `args` (no backtraces), to completion.
pub(crate) fn penner(args: &[&str]) -> Output {
    Command::new(BIN)
        .args(args)
        .env_remove("RUST_BACKTRACE")
        .output()
        .expect("run penner")
}

/// Bytes of an output stream as text.
pub(crate) fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// Assert a clean refusal: exit code `code`, a message on stderr containing every string
/// in `mentions`, and no sign of a panic.
pub(crate) fn assert_refused(out: &Output, code: i32, mentions: &[&str]) {
    let err = text(&out.stderr);
    assert_eq!(
        out.status.code(),
        Some(code),
        "exit code; stderr: {err}; stdout: {}",
        text(&out.stdout)
    );
    assert!(!err.trim().is_empty(), "no message on stderr");
    for m in mentions {
        assert!(err.contains(m), "stderr does not mention {m:?}: {err}");
    }
    for bad in [
        "panicked",
        "RUST_BACKTRACE",
        "internal error",
        "stack backtrace",
    ] {
        assert!(!err.contains(bad), "stderr shows a panic: {err}");
    }
    assert!(
        err.lines().filter(|l| !l.trim().is_empty()).count() <= 5,
        "message should be short, got: {err}"
    );
}

/// Write `contents` to a new file `name` in `dir`; its path.
pub(crate) fn write(dir: &Path, name: &str, contents: &[u8]) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, contents).expect("write input");
    p
}

/// Run `penner certify` on a claim; return the exit code and the parsed answer.
pub(crate) fn certify(
    dir: &Path,
    name: &str,
    claim: &serde_json::Value,
) -> (Option<i32>, serde_json::Value, String) {
    let p = write(dir, name, claim.to_string().as_bytes());
    let out = penner(&["certify", &p.display().to_string()]);
    let answer = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "answer is not JSON ({e}): {}\nstderr: {}",
            text(&out.stdout),
            text(&out.stderr)
        )
    });
    (out.status.code(), answer, text(&out.stderr))
}

/// [`certify`], asserting the exit code `code` and the answer's `verdict`; the answer and
/// stderr.
pub(crate) fn certify_expecting(
    dir: &Path,
    name: &str,
    claim: &serde_json::Value,
    code: i32,
    verdict: &str,
) -> (serde_json::Value, String) {
    let (got, a, err) = certify(dir, name, claim);
    assert_eq!(
        (got, a["verdict"].as_str()),
        (Some(code), Some(verdict)),
        "{name}: {a}\nstderr: {err}"
    );
    (a, err)
}

/// The counterexample element named by a `penner certify` answer (empty when absent).
pub(crate) fn counterexample(answer: &serde_json::Value) -> &str {
    answer["counterexample"]["element"].as_str().unwrap_or("")
}
