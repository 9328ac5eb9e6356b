//! The exact fold count of the UV triangles of OBJ files, whoever wrote them (B109's fold
//! test on the written decimals, `overlay::check::uv_orientation`): used to count folds in
//! a peer's overlay output with the same test as penner's own.
//!
//! `cargo run --release --example uv_folds -- A.obj [B.obj …]`

use penner::overlay::check::uv_orientation;

fn main() {
    let paths: Vec<String> = std::env::args().skip(1).collect();
    if paths.is_empty() {
        eprintln!("usage: uv_folds FILE.obj [FILE.obj …]");
        std::process::exit(2);
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
