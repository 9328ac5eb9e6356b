//! A noisy icosphere as OFF on standard output: the icosahedron subdivided with frequency
//! ν (20ν² faces, 10ν² + 2 vertices), projected to the unit sphere, each vertex moved
//! radially by `p ← p·(1 + a·U(−1, 1))` with `a` = NOISE × the mean edge length, and the
//! coordinates written with 17 significant digits.
//!
//! ```sh
//! cargo run --release --example noisy_sphere -- 1000000 > sphere.off   # ≈ 10⁶ faces
//! cargo run --release --example noisy_sphere -- FACES [SEED] [NOISE]    # NOISE: 1
//! cargo run --example noisy_sphere                                     # 320 faces
//! ```
//!
//! FACES is rounded to the nearest 20ν² (10⁶ → 1 003 520, 10⁵ → 100 820). The example
//! writes nothing but standard output; with no arguments it prints a small sphere.

#[path = "../tests/it/meshgen.rs"]
mod meshgen;

use std::io::Write;
use std::process::ExitCode;

/// The subdivision frequency ν with 20ν² closest to `faces` (at least 1).
fn frequency(faces: u64) -> u32 {
    let nu = (faces as f64 / 20.0).sqrt().round().max(1.0);
    nu.min(f64::from(u16::MAX)) as u32
}

fn arg<T: std::str::FromStr>(args: &[String], i: usize, default: T) -> Result<T, String> {
    args.get(i).map_or(Ok(default), |s| {
        s.parse()
            .map_err(|_| format!("noisy_sphere: argument {} (`{s}`) is not a number", i + 1))
    })
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let parsed = (|| -> Result<(u64, u64, f64), String> {
        Ok((arg(&args, 0, 320)?, arg(&args, 1, 1)?, arg(&args, 2, 1.0)?))
    })();
    let (faces, seed, noise) = match parsed {
        Ok(p) if p.2.is_finite() && (0.0..=4.0).contains(&p.2) => p,
        Ok(_) => {
            eprintln!("noisy_sphere: NOISE must be in [0, 4]");
            return ExitCode::from(3);
        }
        Err(e) => {
            eprintln!("{e}\nusage: noisy_sphere [FACES] [SEED] [NOISE] > sphere.off");
            return ExitCode::from(3);
        }
    };
    let mut sphere = meshgen::icosphere(frequency(faces));
    let amount = noise * sphere.mean_edge();
    sphere.jitter_radial(amount, seed);
    let mut out = std::io::BufWriter::with_capacity(1 << 20, std::io::stdout().lock());
    match sphere.write_off(&mut out).and_then(|()| out.flush()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("noisy_sphere: cannot write standard output: {e}");
            ExitCode::from(4)
        }
    }
}
