//! Shared helpers for the integration tests: case counts, and running the built `penner`
//! binary end to end (scratch directories, input files, `penner certify` answers).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Number of cases for a randomized test: `default` normally, `long` when the
/// `PENNER_LONG` environment variable is set (the deep search, see README).
pub fn cases(default: usize, long: usize) -> usize {
    if std::env::var_os("PENNER_LONG").is_some() {
        long
    } else {
        default
    }
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
