//! The exact fold count of the UV triangles of OBJ files, whoever wrote them (B109's fold
//! test on the written decimals, `overlay::check::uv_orientation`): used to count folds in
//! a peer's overlay output with the same test as penner's own.
//!
//! `cargo run --release --example uv_folds -- A.obj [B.obj …]`; without arguments it
//! counts the folds of penner's own UV mesh of the octahedron with four cones of π, and of
//! a copy with one texture coordinate moved across its triangle (a fold the count finds).

use penner::io::Surface;
use penner::mesh::builders;
use penner::overlay::check::uv_orientation;
use penner::uniformization::pipeline::{uniformize_closed, uv_closed, Options, Precision};
use penner::uniformization::Targets;
use rug::Rational;

/// The demonstration without arguments (module documentation).
fn demo() -> Result<(), String> {
    let s =
        Surface::from_embedded("octahedron", builders::octahedron()).map_err(|e| e.to_string())?;
    let t: Vec<Rational> = [1, 1, 1, 1, 2, 2].map(Rational::from).into();
    let options = Options {
        precision: Precision::F64,
        certify: false,
    };
    let out = uniformize_closed(&s, &Targets::from_multiples_of_pi(t), &options, &mut |_| {})
        .map_err(|e| e.to_string())?;
    let uv = uv_closed(&s, &out).map_err(|e| e.to_string())?;
    let obj = uv.obj();
    let o = uv_orientation(&obj).map_err(|e| e.to_string())?;
    println!(
        "octahedron, four cones of π: {} UV triangles, {} folded, {} of zero area",
        o.triangles,
        o.clockwise.len(),
        o.degenerate.len()
    );
    // Move the first triangle's first corner across the line of the other two.
    let [a, b, c] = uv.uv[0];
    let (dx, dy) = (c[0] - b[0], c[1] - b[1]);
    let lam = ((a[0] - b[0]) * dx + (a[1] - b[1]) * dy) / (dx * dx + dy * dy);
    let m = [
        2.0 * (b[0] + lam * dx) - a[0],
        2.0 * (b[1] + lam * dy) - a[1],
    ];
    let folded = obj.replacen(
        &format!("vt {} {}", a[0], a[1]),
        &format!("vt {} {}", m[0], m[1]),
        1,
    );
    let f = uv_orientation(&folded).map_err(|e| e.to_string())?;
    println!(
        "the same with one corner moved across its triangle: {} folded (first: triangle {})",
        f.clockwise.len(),
        f.clockwise
            .first()
            .map_or("none".to_string(), ToString::to_string)
    );
    if o.clockwise.is_empty() && !f.clockwise.is_empty() {
        Ok(())
    } else {
        Err("the fold count did not tell the two apart".into())
    }
}

fn main() {
    let paths: Vec<String> = std::env::args().skip(1).collect();
    if paths.is_empty() {
        if let Err(e) = demo() {
            eprintln!("uv_folds: {e}");
            std::process::exit(1);
        }
        return;
    }
    let mut code = 0;
    for p in &paths {
        let text = match std::fs::read_to_string(p) {
            Ok(t) => t,
            Err(e) => {
                eprintln!("{p}: {e}");
                code = 1;
                continue;
            }
        };
        match uv_orientation(&text) {
            Ok(o) => println!(
                "{p}: {} UV triangles, {} clockwise (folded), {} of zero area (exact, on the written decimals)",
                o.triangles,
                o.clockwise.len(),
                o.degenerate.len()
            ),
            Err(e) => {
                eprintln!("{p}: {e}");
                code = 1;
            }
        }
    }
    std::process::exit(code);
}
