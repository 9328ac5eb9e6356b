//! The `penner` command line.

fn main() {}
