//! Sharding the long property search (`PENNER_SHARD=i/n`, docs/testing.md, "Sharding the
//! long search"): the shards of a run partition its case indices, and a malformed value stops
//! the test harness with a message naming it.

use crate::support::{parse_shard, shard_cases_of, shard_from, shard_indices};

/// For every `n ≤ 9` and case count up to 40, the shards `0/n … (n−1)/n` together run every
/// index exactly once, each index in the shard of its residue; outside the long mode, or
/// without the variable, one shard runs everything. Negative control: a shard list that
/// misses shard `n − 1` misses indices.
#[test]
fn shards_partition_the_case_indices() {
    for n in 1..=9 {
        for count in 0..=40 {
            let mut seen = vec![0u32; count];
            for i in 0..n {
                for k in shard_indices(count, (i, n)) {
                    assert_eq!(k % n, i);
                    seen[k] += 1;
                }
            }
            assert!(
                seen.iter().all(|&c| c == 1),
                "n = {n}, count = {count}: {seen:?}"
            );
            if n > 1 && count >= n {
                let partial: usize = (0..n - 1)
                    .map(|i| shard_indices(count, (i, n)).count())
                    .sum();
                assert!(partial < count);
            }
        }
    }
    assert_eq!(shard_from(Some("3/16"), true), (3, 16));
    assert_eq!(shard_from(Some("3/16"), false), (0, 1));
    assert_eq!(shard_from(None, true), (0, 1));
    for bad in [
        "", "3", "16/16", "17/16", "-1/4", "a/b", "1/0", "1/2/3", "0.5/2",
    ] {
        assert_eq!(parse_shard(bad), None, "{bad:?}");
    }
    assert_eq!(parse_shard(" 0 / 1 "), Some((0, 1)));
}

/// A malformed `PENNER_SHARD` is a clear panic in the harness, not a silent full run.
#[test]
#[should_panic(expected = "PENNER_SHARD=\"4/4\": expected i/n")]
fn malformed_shard_panics_with_its_value() {
    shard_from(Some("4/4"), true);
}

/// A generated batch (the never-fails families) is split by its case index: the shards
/// together run every case exactly once. Negative control: without shard n − 1 some cases
/// are missed.
#[test]
fn shards_partition_a_generated_batch() {
    for n in 1..=7 {
        for count in 0..=30 {
            let batch: Vec<usize> = (0..count).map(|k| 1000 + k).collect();
            let mut all: Vec<usize> = (0..n)
                .flat_map(|i| shard_cases_of(&batch, (i, n)))
                .collect();
            all.sort_unstable();
            assert_eq!(all, batch, "n = {n}, count = {count}");
            if n > 1 && count >= n {
                let partial: usize = (0..n - 1)
                    .map(|i| shard_cases_of(&batch, (i, n)).len())
                    .sum();
                assert!(partial < count);
            }
        }
    }
}
