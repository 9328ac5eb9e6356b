//! The benchmark meshes of discrete uniformization (T24) and the figures of docs/benchmarks.md:
//! wall time of the `f64` Newton solve, of the refinement to max |Θ − θ| ≤ 10⁻³⁰ (MPFR-128
//! residuals, the `f64` factor), of the refinement to 10⁻⁶⁰ at MPFR-256 and of its
//! certificate (B70, B71, B36), each also in CPU seconds, their ratios to the `f64` solve,
//! and the peak resident memory.
//!
//! ```sh
//! cargo run --release --example uniformize_targets -- sphere 100000   # noisy icosphere
//! cargo run --release --example uniformize_targets -- torus 100000    # sheared torus
//! cargo run --release --example uniformize_targets -- sphere 100000 f64   # the f64 solve only
//! cargo run --release --example uniformize_targets -- sphere 100000 write DIR # the OBJ and targets
//! ```
//!
//! `write DIR` writes `DIR/KIND-FACES.obj` (positions as shortest round-trip decimals) and
//! `DIR/KIND-FACES-targets.json` (`Θ_i/π`) for timing the whole `penner uniformize` command.
//!
//! `sphere FACES`: the frequency-ν icosphere (20ν² faces closest to FACES), every vertex
//! moved by up to 0.2 × the mean edge length, four cones of angle π at the vertices nearest
//! (1,1,1), (1,−1,−1), (−1,1,−1), (−1,−1,1), 2π elsewhere. `torus FACES`: a torus of radii 1
//! and 0.3 from an n × n/2 grid sheared by 5 columns per row (long thin triangles), all
//! targets 2π.

#[path = "../tests/it/meshgen.rs"]
mod meshgen;

use penner::scalar::{Mpfr, Precision, Real};
use penner::uniformization::certificate::{certify_near, CertificateOutcome};
use penner::uniformization::refine::{refine, refine_with_flips};
use penner::uniformization::{uniformize, Targets, UniformizeOptions};
use rug::Rational;
use std::process::ExitCode;
use std::time::Instant;

/// Peak resident set size in MiB (`VmHWM` of /proc/self/status), if readable.
fn peak_mib() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = s.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb / 1024.0)
}

/// CPU time of this process (user + system, all threads) in seconds, from /proc/self/stat
/// (clock ticks of 10 ms), if readable: on a loaded machine the wall time of a stage
/// includes the time other processes ran.
fn cpu_seconds() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/self/stat").ok()?;
    // Fields after the parenthesized command name; utime and stime are fields 14 and 15.
    let rest = &s[s.rfind(')')? + 2..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks: f64 = f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?;
    Some(ticks / 100.0)
}

/// The CPU seconds elapsed since `start`, formatted, or nothing.
fn cpu_since(start: Option<f64>) -> String {
    match (start, cpu_seconds()) {
        (Some(a), Some(b)) => format!(", CPU {:.2} s", b - a),
        _ => String::new(),
    }
}

fn sphere(faces: u64) -> (meshgen::Embedded, Targets) {
    let nu = ((faces as f64 / 20.0).sqrt().round().max(1.0)) as u32;
    let mut s = meshgen::icosphere(nu);
    let amount = 0.2 * s.mean_edge();
    s.jitter(amount, u64::from(nu));
    let mut q = vec![Rational::from(2); s.pos.len()];
    for c in [
        [1.0, 1.0, 1.0],
        [1.0, -1.0, -1.0],
        [-1.0, 1.0, -1.0],
        [-1.0, -1.0, 1.0],
    ] {
        let d = |p: &[f64; 3]| (0..3).map(|i| (p[i] - c[i]).powi(2)).sum::<f64>();
        let v = (0..s.pos.len())
            .min_by(|&a, &b| d(&s.pos[a]).total_cmp(&d(&s.pos[b])))
            .unwrap_or(0);
        q[v] = Rational::from(1);
    }
    (s, Targets::from_multiples_of_pi(q))
}

fn torus(faces: u64) -> (meshgen::Embedded, Targets) {
    // 2·n·(n/2) = n² faces.
    let n = ((faces as f64).sqrt().round().max(4.0)) as u32;
    let s = meshgen::sheared_torus(n, n / 2, 5);
    let t = Targets::flat(s.pos.len());
    (s, t)
}

/// Write `s` as `DIR/NAME.obj` and its targets as `DIR/NAME-targets.json` (new files only).
fn write_case(
    dir: &std::path::Path,
    name: &str,
    s: &meshgen::Embedded,
    targets: &Targets,
) -> std::io::Result<()> {
    use std::fmt::Write as _;
    let mut obj = String::new();
    for p in &s.pos {
        let _ = writeln!(obj, "v {} {} {}", p[0], p[1], p[2]);
    }
    for f in &s.faces {
        let _ = writeln!(obj, "f {} {} {}", f[0] + 1, f[1] + 1, f[2] + 1);
    }
    let q: Vec<String> = targets.over_pi().iter().map(ToString::to_string).collect();
    let write_new = |path: std::path::PathBuf, text: &str| {
        use std::io::Write as _;
        std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(path)?
            .write_all(text.as_bytes())
    };
    write_new(dir.join(format!("{name}.obj")), &obj)?;
    write_new(
        dir.join(format!("{name}-targets.json")),
        &(serde_json::to_string(&q).unwrap_or_default() + "\n"),
    )
}

#[allow(clippy::too_many_lines)] // the three stages and their report, read top to bottom
fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let kind = args.first().map_or("sphere", String::as_str);
    let Ok(faces) = args.get(1).map_or(Ok(10_000u64), |s| s.parse()) else {
        eprintln!("uniformize_targets: FACES must be a number");
        return ExitCode::from(3);
    };
    let (s, targets) = match kind {
        "sphere" => sphere(faces),
        "torus" => torus(faces),
        other => {
            eprintln!("uniformize_targets: expected `sphere` or `torus`, got `{other}`");
            return ExitCode::from(3);
        }
    };
    if args.get(2).map(String::as_str) == Some("write") {
        let dir = std::path::Path::new(args.get(3).map_or(".", String::as_str));
        return match write_case(dir, &format!("{kind}-{faces}"), &s, &targets) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("uniformize_targets: {e}");
                ExitCode::from(4)
            }
        };
    }
    let mesh = s.mesh();
    let lengths = s.lengths(&mesh);
    let t = Instant::now();
    let c = cpu_seconds();
    let sol = match uniformize(&mesh, &lengths, &targets, &UniformizeOptions::default()) {
        Ok(sol) => sol,
        Err(e) => {
            eprintln!("uniformize_targets: {e}");
            return ExitCode::from(3);
        }
    };
    let t_f64 = t.elapsed().as_secs_f64();
    let cpu = cpu_since(c);
    println!(
        "{kind} {} faces, {} vertices: f64 solve {t_f64:.3} s{cpu} ({} Newton steps, {} Euclidean + {} Ptolemy flips, {} symbolic / {} numeric factorizations), max |Θ − θ| = {:.2e}, stop {:?}",
        mesh.n_faces(),
        mesh.n_vertices(),
        sol.steps.len(),
        sol.euclidean_flips,
        sol.flip_sequence.len(),
        sol.factorizations.0,
        sol.factorizations.1,
        sol.residual_max,
        sol.stop
    );
    let history: Vec<String> = sol
        .steps
        .iter()
        .map(|s| {
            format!(
                "{:.1e}{}",
                s.residual_max,
                if s.step < 1.0 { "*" } else { "" }
            )
        })
        .collect();
    println!(
        "  max |Θ − θ| after each step (* a shortened step): {}",
        history.join(", ")
    );
    if !sol.converged() {
        return ExitCode::from(2);
    }
    if args.get(2).map(String::as_str) == Some("f64") {
        return ExitCode::SUCCESS;
    }
    let t = Instant::now();
    let c = cpu_seconds();
    let p128 = Precision::new(128).expect("128 bits");
    let r30 = match refine::<Mpfr>(&sol, p128, 1e-30, 30) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("uniformize_targets: {e}");
            return ExitCode::from(2);
        }
    };
    let t_30 = t.elapsed().as_secs_f64();
    let cpu = cpu_since(c);
    println!(
        "refine to 1e-30 (MPFR-128): {t_30:.3} s{cpu} = {:.2}× the f64 solve, {} iterations, max |Θ − θ| = {:.2e}, reached {}",
        t_30 / t_f64,
        r30.history.len() - 1,
        r30.residual_max(),
        r30.reached
    );
    // The refinement to 1e-60 at MPFR-256 (keeping the triangulation Delaunay, B69), then
    // the certificate on its u (the two halves of `prove`, timed apart).
    let t = Instant::now();
    let c = cpu_seconds();
    let p256 = Precision::new(256).expect("256 bits");
    let l0: Vec<Mpfr> = sol
        .initial_lengths
        .iter()
        .map(|&x| Mpfr::from_f64(x, p256))
        .collect();
    let r60 = match refine_with_flips::<Mpfr>(&sol, l0, p256, 1e-60, 30) {
        Ok((r, _)) => r,
        Err(e) => {
            eprintln!("uniformize_targets: {e}");
            return ExitCode::from(2);
        }
    };
    let t_refine = t.elapsed().as_secs_f64();
    let cpu_refine = cpu_since(c);
    let u: Vec<Rational> = r60
        .u
        .iter()
        .map(|x| x.to_rational().unwrap_or_default())
        .collect();
    let t = Instant::now();
    let c = cpu_seconds();
    let proof = match certify_near(&sol, None, &u, r60.residual_max(), 256) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("uniformize_targets: {e}");
            return ExitCode::from(2);
        }
    };
    let t_cert = t.elapsed().as_secs_f64();
    let cpu_cert = cpu_since(c);
    let verdict = match &proof.outcome {
        CertificateOutcome::Holds { distance, .. } => {
            format!("certified, distance ≤ {distance:.2e}")
        }
        CertificateOutcome::Undecided { reason } => format!("not certified: {reason}"),
    };
    println!(
        "refine to 1e-60 at MPFR-256: {t_refine:.3} s{cpu_refine} = {:.2}× the f64 solve, {} iterations, max |Θ − θ| = {:.2e}",
        t_refine / t_f64,
        r60.history.len() - 1,
        r60.residual_max()
    );
    println!(
        "certificate (256 bits): {t_cert:.3} s{cpu_cert} = {:.2}× the f64 solve, {verdict}",
        t_cert / t_f64
    );
    println!(
        "refine to 1e-60 at MPFR-256 + certificate: {:.3} s = {:.2}× the f64 solve",
        t_refine + t_cert,
        (t_refine + t_cert) / t_f64
    );
    if let Some(m) = peak_mib() {
        println!("peak resident memory: {m:.0} MiB");
    }
    ExitCode::SUCCESS
}
