//! Shared helpers for the integration tests.

/// Number of cases for a randomized test: `default` normally, `long` when the
/// `PENNER_LONG` environment variable is set (the deep search, see README).
pub fn cases(default: usize, long: usize) -> usize {
    if std::env::var_os("PENNER_LONG").is_some() {
        long
    } else {
        default
    }
}
