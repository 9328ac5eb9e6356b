//! The `penner` command line: `penner` (report on the built-in corpus), `penner check`,
//! `penner certify`, `penner delaunay`, `penner replay`. See README.md for exit codes.

mod cli;

fn main() -> std::process::ExitCode {
    cli::main()
}
