//! Reading and writing large surfaces: an OFF noisy icosphere (radial noise, 17
//! significant digits, as `examples/noisy_sphere` writes it) read into the compact form
//! with its `f64` lengths (what `penner delaunay --precision f64` does), read into the
//! exact surface (what `penner check` does, 10⁴ faces), and written as compact JSON; the
//! same sphere read in the formattings other tools write (`read-formatting/…`: C's
//! `%.17g`, `%g`, `%.6f`, `%.17e` with mixed exponents, as numpy's `savetxt` writes them,
//! and OBJ with a homogeneous `w`).
//!
//! `cargo bench --bench io` (set `PENNER_BENCH_LARGE=1` for the 10⁶-face sphere).

#![allow(missing_docs)] // criterion_group! generates an undocumented function

#[path = "../tests/it/meshgen.rs"]
mod meshgen;

use criterion::{criterion_group, criterion_main, Criterion};
use penner::io::write::{self, MetricKind, Values};
use penner::io::{obj, off, DecimalSurface};
use std::time::Duration;

/// The OFF text of a noisy icosphere of frequency `k` (20k² faces).
fn sphere_off(k: u32) -> String {
    let mut e = meshgen::icosphere(k);
    let a = e.mean_edge();
    e.jitter_radial(a, 1);
    let mut out = Vec::new();
    e.write_off(&mut out).expect("write to memory");
    String::from_utf8(out).expect("ASCII")
}

/// C's `%.{p}g`: `p` significant digits, scientific when the decimal exponent is below −4
/// or at least `p`, trailing zeros dropped (as `printf` and numpy's `savetxt` write).
fn c_g(x: f64, p: usize) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let sci = format!("{:.*e}", p - 1, x);
    let (mantissa, exp) = sci.split_once('e').expect("exponent form");
    let exp: i32 = exp.parse().expect("integer exponent");
    let trim = |m: &str| -> String {
        if m.contains('.') {
            m.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            m.to_string()
        }
    };
    if exp < -4 || exp >= p as i32 {
        format!(
            "{}e{}{:02}",
            trim(mantissa),
            if exp < 0 { '-' } else { '+' },
            exp.abs()
        )
    } else {
        trim(&format!("{:.*}", (p as i32 - 1 - exp).max(0) as usize, x))
    }
}

/// C's `%.17e`: 18 significant digits, a signed exponent of at least two digits.
fn c_e17(x: f64) -> String {
    let sci = format!("{x:.17e}");
    let (mantissa, exp) = sci.split_once('e').expect("exponent form");
    let exp: i32 = exp.parse().expect("integer exponent");
    format!(
        "{mantissa}e{}{:02}",
        if exp < 0 { '-' } else { '+' },
        exp.abs()
    )
}

/// The sphere as OFF (or OBJ, with `w = 1` when `homogeneous`) with every coordinate
/// written by `fmt`.
fn formatted(e: &meshgen::Embedded, fmt: &dyn Fn(f64) -> String, as_obj: bool, w: bool) -> String {
    use std::fmt::Write as _;
    let mut out = String::new();
    if !as_obj {
        let _ = writeln!(out, "OFF\n{} {} 0", e.pos.len(), e.faces.len());
    }
    for p in &e.pos {
        let [x, y, z] = p.map(fmt);
        let _ = if as_obj {
            writeln!(out, "v {x} {y} {z}{}", if w { " 1" } else { "" })
        } else {
            writeln!(out, "{x} {y} {z}")
        };
    }
    for f in &e.faces {
        let _ = if as_obj {
            writeln!(out, "f {} {} {}", f[0] + 1, f[1] + 1, f[2] + 1)
        } else {
            writeln!(out, "3 {} {} {}", f[0], f[1], f[2])
        };
    }
    out
}

fn read_f64(text: &str) -> (DecimalSurface, Vec<f64>) {
    let s = off::read_decimal(text).expect("valid OFF");
    let l = s.lengths_f64();
    (s, l)
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("io");
    g.sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3));
    let mut sizes = vec![("icosphere-100820", 71)];
    if std::env::var_os("PENNER_BENCH_LARGE").is_some() {
        sizes.push(("icosphere-1003520", 224));
    }
    let small = sphere_off(22);
    g.bench_function("icosphere-9680/read-off-exact", |b| {
        b.iter(|| off::read(&small).expect("valid OFF").mesh.n_edges());
    });
    for (name, k) in sizes {
        let text = sphere_off(k);
        eprintln!("{name}: {} bytes of OFF", text.len());
        g.bench_function(format!("{name}/read-off-f64-lengths"), |b| {
            b.iter(|| read_f64(&text).1.len());
        });
        let mut e = meshgen::icosphere(k);
        let a = e.mean_edge();
        e.jitter_radial(a, 1);
        let formats: [(&str, &dyn Fn(f64) -> String); 4] = [
            ("g17", &|x| c_g(x, 17)),
            ("g", &|x| c_g(x, 6)),
            ("f6", &|x| format!("{x:.6}")),
            ("e17", &c_e17),
        ];
        for (fmt_name, fmt) in formats {
            let text = formatted(&e, fmt, false, false);
            g.bench_function(format!("{name}/read-formatting/{fmt_name}.off"), |b| {
                b.iter(|| read_f64(&text).1.len());
            });
        }
        let text_w = formatted(&e, &|x| c_g(x, 17), true, true);
        g.bench_function(format!("{name}/read-formatting/g17w.obj"), |b| {
            b.iter(|| {
                let s = obj::read_decimal(&text_w).expect("valid OBJ");
                s.lengths_f64().len()
            });
        });
        let (s, l) = read_f64(&text);
        g.bench_function(format!("{name}/write-json-f64"), |b| {
            b.iter(|| {
                let mut out = Vec::with_capacity(64 << 20);
                write::json::<String>(
                    &mut out,
                    "s",
                    &s.mesh,
                    MetricKind::Lengths,
                    Values::Binary64(&l),
                    None,
                )
                .expect("write to memory");
                out.len()
            });
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
