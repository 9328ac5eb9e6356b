//! The `penner` binary: argument parsing, dispatch, messages and exit codes.

mod args;
mod certificate_report;
mod certify;
mod check;
mod delaunay;
mod error;
mod files;
mod input;
mod output;
mod pack;
mod pack_maximal;
mod progress;
mod replay;
mod report;
mod uniformize;
mod uniformize_boundary;
mod uniformize_hyperbolic;
mod uniformize_options;
mod uniformize_sphere;
mod uniformize_svg;
mod uniformize_uv;

use args::{Cli, Command};
use clap::Parser;
use error::{code, CliError};
use std::process::ExitCode;

/// Print a usage error (or `--help`, `--version`) and its exit code: 3, or 0 for help.
fn usage_exit(e: &clap::Error) -> ExitCode {
    let _ = e.print();
    ExitCode::from(if e.use_stderr() {
        code::BAD_INPUT
    } else {
        code::HOLDS
    })
}

/// Parse the arguments, run the command, map the outcome to an exit code. Errors are one
/// clear line on standard error, never a panic or a backtrace.
pub fn main() -> ExitCode {
    install_panic_hook();
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => return usage_exit(&e),
    };
    input::set_repairs(cli.repair.repairs());
    // A panic anywhere below is a defect (exit 5), reported with the command line.
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| dispatch(cli)));
    match outcome {
        Ok(Ok(c)) => ExitCode::from(c),
        Ok(Err(e)) => {
            eprintln!("penner: {e}");
            ExitCode::from(e.exit_code())
        }
        Err(_) => {
            let args: Vec<String> = std::env::args().skip(1).collect();
            eprintln!(
                "penner: internal error while running `penner {}` (exit 5)",
                args.join(" ")
            );
            ExitCode::from(code::INTERNAL)
        }
    }
}

/// The environment variable that makes [`dispatch`] panic at once: the test of the
/// defect path (exit 5), never set in normal use.
const PANIC_TEST_VAR: &str = "PENNER_INTERNAL_PANIC_TEST";

/// Run the parsed command.
fn dispatch(cli: Cli) -> Result<u8, CliError> {
    assert!(
        std::env::var_os(PANIC_TEST_VAR).is_none(),
        "{PANIC_TEST_VAR} is set: the defect path is being tested"
    );
    match cli.command {
        None => report::run(penner::oracle::precision::REPORT_LIST, false),
        Some(Command::Report { precision, json }) => report::run(&precision, json),
        Some(Command::Check {
            surfaces,
            precision,
            only,
            json,
            no_failure_files,
            negative_controls,
            lengths,
        }) => check::run(&check::Options {
            paths: &surfaces,
            precision: &precision,
            only: &only,
            json,
            no_failure_files,
            negative_controls,
            lengths: lengths.as_deref(),
        }),
        Some(Command::Replay { file, json }) => replay::run(&file, json),
        Some(Command::Pack {
            surface,
            svg,
            disk,
            sphere,
            puncture,
            bits,
            epsilon,
            output,
        }) => {
            if disk || sphere {
                pack_maximal::run(&pack_maximal::Options {
                    path: &surface,
                    sphere,
                    puncture,
                    bits,
                    epsilon: &epsilon,
                    svg: svg.as_deref(),
                    output: output.as_deref(),
                })
            } else {
                pack::run(&surface, svg.as_deref())
            }
        }
        Some(Command::Certify { claim }) => certify::run(&claim),
        Some(Command::Uniformize {
            surface,
            targets,
            flat,
            precision,
            output,
            extra,
        }) => uniformize::run(&uniformize::Options {
            path: &surface,
            targets: targets.as_deref(),
            flat,
            precision: &precision,
            output: output.as_deref(),
            extra: &extra,
        }),
        Some(Command::Delaunay {
            surface,
            flips,
            precision,
            output,
            scale_factors,
            summary,
            no_input_replay,
            lengths_out,
        }) => delaunay::run(&delaunay::Options {
            path: &surface,
            flips,
            precision: &precision,
            output: output.as_deref(),
            scale_factors: scale_factors.as_deref(),
            summary: summary.as_deref(),
            input_replay: !no_input_replay,
            lengths_out: lengths_out.as_deref(),
        }),
    }
}

/// A panic inside penner is a defect: print one line naming it, no backtrace.
fn install_panic_hook() {
    std::panic::set_hook(Box::new(|info| {
        let msg = info
            .payload()
            .downcast_ref::<&str>()
            .map(ToString::to_string)
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_default();
        let at = info
            .location()
            .map(|l| format!(" at {}:{}", l.file(), l.line()))
            .unwrap_or_default();
        eprintln!(
            "penner: internal error{at}: {msg} (this is a defect in penner; please report it)"
        );
    }));
}

/// Parse a precision list into a typed list, as bad input on error.
fn precisions(s: &str) -> Result<Vec<penner::oracle::Prec>, CliError> {
    penner::oracle::precision::parse_list(s)
        .map_err(|e| CliError::Input(format!("--precision: {e}")))
}

/// The exit code of a report status.
fn status_code(s: penner::oracle::report::Status) -> u8 {
    use penner::oracle::report::Status;
    match s {
        Status::Holds => code::HOLDS,
        Status::Undecided => code::UNDECIDED,
        Status::Fails => code::FAILS,
        Status::Crashed => code::INTERNAL,
    }
}
