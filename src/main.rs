//! The `penner` command line, seven subcommands: `penner report` (also `penner` alone: the
//! report on the built-in corpus), `penner check`, `penner certify`, `penner delaunay`,
//! `penner replay`, `penner uniformize` and `penner pack`. See README.md for exit codes.

mod cli;

fn main() -> std::process::ExitCode {
    cli::main()
}
