//! The sphere view of cap packings (T11 pictures): orthographic ellipses of the caps' rims,
//! one per front-facing cap; a moved cap is caught by the tangency certificate (B96), not by
//! the picture.

use penner::circles::maximal::sphere::{check_sphere_packing, exact_caps, Cap};
use penner::circles::maximal::svg::{cap_ellipse, render_sphere_svg, VIEW_ELEVATION_DEG};
use penner::circles::maximal::tangency::PackingVerdict;
use penner::circles::maximal::{maximal_sphere, Options};
use penner::mesh::builders::{icosahedron, octahedron};
use penner::scalar::{Mpfr, Precision, Real};
use rug::Rational;

/// Tags balance (every `<x …>` closed by `</x>` in order, `<x …/>` self-closed), every
/// attribute value is double-quoted, and there is one root `svg` element.
fn assert_well_formed(doc: &str) {
    let mut stack: Vec<String> = Vec::new();
    let mut rest = doc;
    let mut roots = 0;
    while let Some(open) = rest.find('<') {
        let close = rest[open..].find('>').expect("unclosed tag") + open;
        let tag = &rest[open + 1..close];
        assert!(!tag.contains('<'), "nested '<' in {tag}");
        assert_eq!(
            tag.matches('"').count() % 2,
            0,
            "unbalanced quotes in {tag}"
        );
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(
                stack.pop().as_deref(),
                Some(name.trim()),
                "mismatched </{name}>"
            );
        } else {
            let name = tag
                .split_whitespace()
                .next()
                .unwrap_or("")
                .trim_end_matches('/');
            if stack.is_empty() {
                roots += 1;
                assert_eq!(name, "svg");
            }
            if !tag.ends_with('/') {
                stack.push(name.to_string());
            }
        }
        rest = &rest[close + 1..];
    }
    assert!(stack.is_empty(), "unclosed {stack:?}");
    assert_eq!(roots, 1);
}

fn caps_f64(caps: &[Cap<Mpfr>]) -> Vec<Cap<f64>> {
    caps.iter()
        .map(|c| Cap {
            normal: c.normal.clone().map(|x| x.approx_f64()),
            height: c.height.approx_f64(),
        })
        .collect()
}

/// The view direction, built independently of `view_coordinates`.
fn view_direction() -> [f64; 3] {
    let t = VIEW_ELEVATION_DEG.to_radians();
    [0.0, -t.sin(), t.cos()]
}

#[test]
fn t11_sphere_svg_has_one_ellipse_per_front_facing_cap() {
    let prec = Precision::new(128).unwrap();
    for mesh in [icosahedron().mesh, octahedron().mesh] {
        let s = maximal_sphere::<Mpfr>(&mesh, 0, prec, &Options::default()).unwrap();
        let caps = caps_f64(&s.caps);
        let doc = render_sphere_svg(&caps);
        assert_well_formed(&doc);
        let d = view_direction();
        let front = caps
            .iter()
            .filter(|c| c.normal[0] * d[0] + c.normal[1] * d[1] + c.normal[2] * d[2] > 0.0)
            .count();
        assert!(front > 0 && front < caps.len());
        assert_eq!(doc.matches("<ellipse class=\"front\"").count(), front);
        assert_eq!(
            doc.matches("<ellipse class=\"back\"").count(),
            caps.len() - front
        );
        // The punctured vertex's cap (the southern hemisphere) faces away at this elevation.
        assert!(!cap_ellipse(&caps[0]).front);
    }
}

#[test]
fn t11_cap_ellipse_passes_through_the_projected_rim() {
    // Oracle: points of the rim constructed in 3-space and projected orthographically must
    // satisfy the ellipse's equation.
    let d = view_direction();
    let a = [1.0, 0.0, 0.0];
    let b = [
        d[1] * a[2] - d[2] * a[1],
        d[2] * a[0] - d[0] * a[2],
        d[0] * a[1] - d[1] * a[0],
    ];
    let dot = |x: &[f64; 3], y: &[f64; 3]| x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
    for (normal, h) in [
        ([0.6, 0.0, 0.8], 0.9),
        ([0.0, 0.0, 1.0], 0.5),
        ([-0.48, 0.6, 0.64], 0.7),
        ([0.0, 0.6, -0.8], 0.95),
    ] {
        let cap = Cap { normal, height: h };
        let e = cap_ellipse(&cap);
        // An orthonormal basis (t1, t2) of the cap's plane.
        let t1 = if normal[2].abs() < 0.9 {
            let v = [-normal[1], normal[0], 0.0];
            let l = dot(&v, &v).sqrt();
            v.map(|x| x / l)
        } else {
            [1.0, 0.0, 0.0]
        };
        let t1 = {
            let k = dot(&t1, &normal);
            let v = [
                t1[0] - k * normal[0],
                t1[1] - k * normal[1],
                t1[2] - k * normal[2],
            ];
            let l = dot(&v, &v).sqrt();
            v.map(|x| x / l)
        };
        let t2 = [
            normal[1] * t1[2] - normal[2] * t1[1],
            normal[2] * t1[0] - normal[0] * t1[2],
            normal[0] * t1[1] - normal[1] * t1[0],
        ];
        let r = (1.0 - h * h).sqrt();
        let (ca, sa) = (e.angle.cos(), e.angle.sin());
        for k in 0..24 {
            let t = f64::from(k) * std::f64::consts::PI / 12.0;
            let p: [f64; 3] =
                std::array::from_fn(|i| h * normal[i] + r * (t.cos() * t1[i] + t.sin() * t2[i]));
            assert!((dot(&p, &p) - 1.0).abs() < 1e-12);
            let (x, y) = (dot(&p, &a) - e.centre[0], dot(&p, &b) - e.centre[1]);
            let (u, v) = (ca * x + sa * y, -sa * x + ca * y);
            let q = (u / e.major).powi(2) + (v / e.minor).powi(2);
            assert!((q - 1.0).abs() < 1e-9, "{normal:?}: {q}");
        }
        // A wrong ellipse (semi-minor axis doubled) misses the rim.
        let off = (0..24).any(|k| {
            let t = f64::from(k) * std::f64::consts::PI / 12.0;
            let p: [f64; 3] =
                std::array::from_fn(|i| h * normal[i] + r * (t.cos() * t1[i] + t.sin() * t2[i]));
            let (x, y) = (dot(&p, &a) - e.centre[0], dot(&p, &b) - e.centre[1]);
            let (u, v) = (ca * x + sa * y, -sa * x + ca * y);
            ((u / e.major).powi(2) + (v / (2.0 * e.minor)).powi(2) - 1.0).abs() > 1e-3
        });
        assert!(off);
    }
}

#[test]
fn t11_sphere_cap_moved_is_caught_by_the_certificate_not_the_picture() {
    let prec = Precision::new(128).unwrap();
    let mesh = icosahedron().mesh;
    let s = maximal_sphere::<Mpfr>(&mesh, 0, prec, &Options::default()).unwrap();
    let caps = exact_caps(&s.caps).unwrap();
    let eps = Rational::from((1, 10u128.pow(30)));
    assert!(matches!(
        check_sphere_packing(&mesh, &caps, &eps, 256),
        PackingVerdict::Holds { .. }
    ));
    // Move cap 5: its normal tilted by 10⁻⁶ in x (the cap slides along the sphere).
    let mut moved = caps.clone();
    moved[5].normal[0] += Rational::from((1, 1_000_000));
    let v = check_sphere_packing(&mesh, &moved, &eps, 256);
    assert!(matches!(v, PackingVerdict::Fails(_)), "{v:?}");
    // The picture of the moved packing is still a well-formed picture with 12 caps.
    let f = |c: &penner::circles::maximal::sphere::ExactCap| {
        let n = c.normal.clone().map(|x| x.to_f64());
        let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        Cap {
            normal: n.map(|x| x / l),
            height: c.height.to_f64() / l,
        }
    };
    let doc = render_sphere_svg(&moved.iter().map(f).collect::<Vec<_>>());
    assert_well_formed(&doc);
    assert_eq!(doc.matches("<ellipse").count(), 12);
}

#[test]
fn t11_cli_pack_sphere_svg_draws_the_caps() {
    use crate::support::{penner, scratch, text, write};
    use std::fmt::Write as _;
    let ico = icosahedron();
    let mut obj = String::new();
    for p in &ico.positions {
        let _ = writeln!(
            obj,
            "v {} {} {}",
            p[0].to_f64(),
            p[1].to_f64(),
            p[2].to_f64()
        );
    }
    for f in ico.mesh.face_list() {
        let _ = writeln!(obj, "f {} {} {}", f[0] + 1, f[1] + 1, f[2] + 1);
    }
    let dir = scratch("pack-sphere-svg");
    let input = write(&dir, "ico.obj", obj.as_bytes());
    let svg = dir.join("ico.svg");
    let args = [
        "pack",
        input.to_str().unwrap(),
        "--sphere",
        "--svg",
        svg.to_str().unwrap(),
    ];
    let out = penner(&args);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let doc = std::fs::read_to_string(&svg).unwrap();
    assert_well_formed(&doc);
    assert_eq!(doc.matches("<ellipse").count(), 12);
    assert!(doc.matches("class=\"front\"").count() >= 6);
    // The file exists now: a second run refuses to overwrite it (exit 4), contents kept.
    let again = penner(&args);
    assert_eq!(again.status.code(), Some(4), "{}", text(&again.stderr));
    assert_eq!(std::fs::read_to_string(&svg).unwrap(), doc);
}
