//! Koebe–Andreev–Thurston maximal packings (T11): disks in the unit disk, spheres by caps;
//! certified tangency (B95, B96), the angle formula and its Jacobian against independent
//! computations (B97), uniqueness and dependence on the combinatorics only.

use penner::circles::hexagonal::hex_complex;
use penner::circles::maximal::hyperbolic::{angle_jacobian_triplets, angle_sums, corner_angle};
use penner::circles::maximal::layout::Circle;
use penner::circles::maximal::sphere::{check_sphere_packing, exact_caps};
use penner::circles::maximal::stopping::layout_defect;
use penner::circles::maximal::tangency::{check_packing, exact_circles, PackingVerdict};
use penner::circles::maximal::{maximal_disk, maximal_sphere, MaximalError, Options};
use penner::mesh::builders::{grid_disk, icosahedron, octahedron, random_planar};
use penner::mesh::Mesh;
use penner::scalar::{Mpfr, Precision, Real};
use penner::theorems::t12_rodin_sullivan::{in_half_disk, BASE};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

fn prec(bits: u64) -> Precision {
    Precision::new(bits).unwrap()
}

/// ε = 10⁻³⁰ for 128-bit packings (B95: the refinement stops at `2⁶·n·2⁻¹²⁸` radians).
fn eps30() -> Rational {
    Rational::from((1, 10u128.pow(30)))
}

fn disks() -> Vec<Mesh> {
    vec![
        grid_disk(5, 4).unwrap().mesh,
        random_planar(40, 7).unwrap().mesh,
        random_planar(150, 11).unwrap().mesh,
    ]
}

fn marks(interior: &[bool]) -> Vec<bool> {
    interior.iter().map(|b| !b).collect()
}

#[test]
fn t11_disk_maximal_packings_are_certified_and_perturbations_are_refuted() {
    for mesh in disks() {
        let p = maximal_disk::<Mpfr>(&mesh, prec(128), &Options::default()).unwrap();
        let circles = exact_circles(&p.circles).unwrap();
        let m = marks(&p.interior);
        let v = check_packing(&mesh, &circles, &eps30(), 256, Some(&m));
        assert!(matches!(v, PackingVerdict::Holds { .. }), "{v:?}");
        // Negative controls: one interior radius scaled by 1 + 10⁻²⁰ is a proved tangency
        // defect of about 10⁻²⁰·ρ ≫ ε; two neighbouring centres swapped flip orientations.
        let w = p.interior.iter().position(|&b| b).unwrap();
        let mut bad = circles.clone();
        bad[w].radius *= Rational::from(1) + Rational::from((1, 10u128.pow(20)));
        let v = check_packing(&mesh, &bad, &eps30(), 256, Some(&m));
        assert!(
            matches!(&v, PackingVerdict::Fails(w) if w.iter().any(|s| s.contains("defect"))),
            "{v:?}"
        );
        let h = mesh.vertex_halfedge(penner::mesh::Vertex(w as u32));
        let x = mesh.tip(h).idx();
        let mut swapped = circles.clone();
        swapped.swap(w, x);
        let v = check_packing(&mesh, &swapped, &eps30(), 256, Some(&m));
        assert!(matches!(v, PackingVerdict::Fails(_)), "{v:?}");
        // Mirrored circles (x ↦ −x) keep every tangency and reverse every orientation.
        let mut mirrored = circles.clone();
        for c in &mut mirrored {
            c.centre[0] = -c.centre[0].clone();
        }
        let v = check_packing(&mesh, &mirrored, &eps30(), 256, Some(&m));
        assert!(
            matches!(&v, PackingVerdict::Fails(w) if w.iter().all(|s| s.contains("oriented"))),
            "{v:?}"
        );
        // A circle pulled off the unit circle is refuted there.
        let b = m.iter().position(|&b| b).unwrap();
        let mut off = circles.clone();
        off[b].radius *= Rational::from((999, 1000));
        let v = check_packing(&mesh, &off, &eps30(), 256, Some(&m));
        assert!(matches!(v, PackingVerdict::Fails(_)), "{v:?}");
    }
}

#[test]
fn t11_f64_packing_is_certified_at_its_own_tolerance() {
    // The f64 Newton solution laid out in f64: certified within 10⁻⁹ (B95: residual 10⁻¹³
    // times the layout's growth along the breadth-first tree), not within 10⁻³⁰.
    let mesh = random_planar(60, 5).unwrap().mesh;
    let p = maximal_disk::<f64>(&mesh, (), &Options::default()).unwrap();
    let circles = exact_circles(&p.circles).unwrap();
    let m = marks(&p.interior);
    let v = check_packing(
        &mesh,
        &circles,
        &Rational::from((1, 1_000_000_000)),
        128,
        Some(&m),
    );
    assert!(matches!(v, PackingVerdict::Holds { .. }), "{v:?}");
    let v = check_packing(&mesh, &circles, &eps30(), 128, Some(&m));
    assert!(matches!(v, PackingVerdict::Fails(_)), "{v:?}");
}

/// `cosh` at MPFR precision.
fn cosh(x: &Mpfr) -> Mpfr {
    (x.exp() + &(-x.clone()).exp()) * &x.lit(0.5)
}

fn sinh(x: &Mpfr) -> Mpfr {
    (x.exp() - &(-x.clone()).exp()) * &x.lit(0.5)
}

#[test]
fn b97_corner_angle_matches_the_hyperbolic_law_of_cosines() {
    // Oracle: the hyperbolic law of cosines on the side lengths r₀+r₁, r₀+r₂, r₁+r₂,
    // cos α = (cosh b cosh c − cosh a)/(sinh b sinh c), at 256 bits, against the
    // half-angle formula in t = tanh(r/2) (B95) at 256 bits: agreement to 10⁻⁶⁰ (B97).
    let p = prec(256);
    let mut rng = ChaCha8Rng::seed_from_u64(97);
    for _ in 0..200 {
        let r: Vec<f64> = (0..3)
            .map(|_| 10f64.powf(rng.gen_range(-3.0..1.0)))
            .collect();
        let rm: Vec<Mpfr> = r.iter().map(|&x| Mpfr::from_f64(x, p)).collect();
        let t: Vec<Mpfr> = rm
            .iter()
            .map(|x| (x.clone() * &x.lit(0.5)).exp())
            .map(|e| {
                let e2 = e.clone() * &e;
                (e2.clone() - &e.lit(1.0)) / &(e2 + &e.lit(1.0))
            })
            .collect();
        let alpha = corner_angle(&t[0], &t[1], &t[2]);
        let (b, c, a) = (
            rm[0].clone() + &rm[1],
            rm[0].clone() + &rm[2],
            rm[1].clone() + &rm[2],
        );
        let cos = (cosh(&b) * &cosh(&c) - &cosh(&a)) / &(sinh(&b) * &sinh(&c));
        let oracle = cos.acos();
        let diff = (alpha.clone() - &oracle).approx_f64().abs();
        assert!(diff < 1e-60, "r = {r:?}: {diff:e}");
        // Negative control: the Euclidean angle of the same radii differs.
        let eu = {
            let (x, y, z) = (rm[0].clone(), rm[1].clone(), rm[2].clone());
            let q = y.clone() * &z / &((x.clone() + &y) * &(x + &z));
            q.sqrt().atan2(&(q.one_like() - &q).sqrt()) * &q.lit(2.0)
        };
        assert!((alpha - &eu).approx_f64().abs() > 1e-60);
    }
}

#[test]
fn b97_jacobian_is_symmetric_and_matches_central_differences() {
    // Oracle: central differences of the 256-bit angle sums with step h = 2⁻⁶⁰
    // (truncation ≲ h²·|θ'''| ≈ 10⁻³⁵, rounding 2⁻²⁵⁶/h); the f64 formula is within
    // 2⁻³⁰·(1 + |J_ij|) (B97).
    let mesh = random_planar(30, 3).unwrap().mesh;
    let interior: Vec<bool> = mesh.boundary_vertices().iter().map(|b| !b).collect();
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let t: Vec<f64> = interior
        .iter()
        .map(|&i| if i { rng.gen_range(0.1..0.7) } else { 1.0 })
        .collect();
    let n = mesh.n_vertices();
    let mut j = vec![vec![0.0; n]; n];
    for (a, b, v) in angle_jacobian_triplets(&mesh, &t, &interior) {
        j[a][b] += v;
    }
    let p = prec(256);
    let h = Mpfr::from_f64(2f64.powi(-60), p);
    let mut checked = 0;
    for w in (0..n).filter(|&w| interior[w]) {
        let at = |sign: f64| {
            let tm: Vec<Mpfr> = t
                .iter()
                .enumerate()
                .map(|(v, &x)| {
                    let x = Mpfr::from_f64(x, p);
                    // u_w → u_w ± h: t_w → t_w·e^{±h}.
                    if v == w {
                        x * &(h.clone() * &h.lit(sign)).exp()
                    } else {
                        x
                    }
                })
                .collect();
            angle_sums(&mesh, &tm)
        };
        let (plus, minus) = (at(1.0), at(-1.0));
        for v in (0..n).filter(|&v| interior[v]) {
            let fd = ((plus[v].clone() - &minus[v]) / &(h.clone() * &h.lit(2.0))).approx_f64();
            let tol = 2f64.powi(-30) * (1.0 + j[v][w].abs());
            assert!(
                (fd - j[v][w]).abs() <= tol,
                "∂θ_{v}/∂u_{w}: {} vs {fd}",
                j[v][w]
            );
            assert!(
                (j[v][w] - j[w][v]).abs() <= tol,
                "not symmetric at ({v}, {w})"
            );
            // Negative control: an entry off by 10⁻⁶ relative (or absolute) is caught.
            let wrong = j[v][w] + 1e-6 * (1.0 + j[v][w].abs());
            assert!((fd - wrong).abs() > tol);
            checked += 1;
        }
    }
    assert!(checked > 100, "{checked}");
}

fn max_circle_gap(a: &[Circle<Mpfr>], b: &[Circle<Mpfr>]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| {
            [
                (x.centre[0].clone() - &y.centre[0]).approx_f64().abs(),
                (x.centre[1].clone() - &y.centre[1]).approx_f64().abs(),
                (x.radius.clone() - &y.radius).approx_f64().abs(),
            ]
            .into_iter()
            .fold(0.0, f64::max)
        })
        .fold(0.0, f64::max)
}

#[test]
fn t11_packing_is_unique_up_to_mobius_and_depends_only_on_combinatorics() {
    let mesh = random_planar(80, 13).unwrap().mesh;
    let base = maximal_disk::<Mpfr>(&mesh, prec(128), &Options::default()).unwrap();
    // A different start (random radii), normalised alike: the same packing. Two solutions
    // with residuals ≤ 2⁶·n·2⁻¹²⁸ differ by at most ‖H⁻¹‖ times that (B97); 10⁻²⁵ leaves
    // a factor 10⁷ for ‖H⁻¹‖ and the layout.
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let start: Vec<f64> = (0..mesh.n_vertices())
        .map(|_| rng.gen_range(-4.0..-0.05))
        .collect();
    let opts = Options {
        centre: Some(base.centre),
        direction: Some(base.direction),
        start: Some(start),
        tolerance: None,
        epsilon: None,
    };
    let other = maximal_disk::<Mpfr>(&mesh, prec(128), &opts).unwrap();
    let gap = max_circle_gap(&base.circles, &other.circles);
    assert!(gap < 1e-25, "two starts differ by {gap:e}");
    // The same triangulation with its vertices relabelled (reversed): the same circles at
    // the relabelled vertices.
    let n = mesh.n_vertices();
    let perm = |v: u32| n as u32 - 1 - v;
    let faces: Vec<[u32; 3]> = mesh.face_list().iter().map(|f| f.map(perm)).collect();
    let relabelled = Mesh::from_faces(n as u32, &faces).unwrap();
    let opts = Options {
        centre: Some(perm(base.centre as u32) as usize),
        direction: Some(perm(base.direction as u32) as usize),
        ..Options::default()
    };
    let r = maximal_disk::<Mpfr>(&relabelled, prec(128), &opts).unwrap();
    let back: Vec<Circle<Mpfr>> = (0..n)
        .map(|v| r.circles[perm(v as u32) as usize].clone())
        .collect();
    let gap = max_circle_gap(&base.circles, &back);
    assert!(gap < 1e-25, "relabelled packing differs by {gap:e}");
    // Negative control: another normalisation (another neighbour on the real axis) is a
    // different, rotated layout of the same packing.
    let h = mesh
        .outgoing(penner::mesh::Vertex(base.centre as u32))
        .nth(1)
        .unwrap();
    let opts = Options {
        centre: Some(base.centre),
        direction: Some(mesh.tip(h).idx()),
        ..Options::default()
    };
    let rotated = maximal_disk::<Mpfr>(&mesh, prec(128), &opts).unwrap();
    assert!(max_circle_gap(&base.circles, &rotated.circles) > 1e-3);
    // ... whose radii nevertheless agree (rotation about the centred circle).
    let rad = base
        .circles
        .iter()
        .zip(&rotated.circles)
        .map(|(a, b)| (a.radius.clone() - &b.radius).approx_f64().abs())
        .fold(0.0, f64::max);
    assert!(rad < 1e-25, "{rad:e}");
}

#[test]
fn t11_sphere_packings_by_caps_are_certified() {
    for mesh in [icosahedron().mesh, octahedron().mesh] {
        for puncture in [0, 3] {
            let s =
                maximal_sphere::<Mpfr>(&mesh, puncture, prec(128), &Options::default()).unwrap();
            let caps = exact_caps(&s.caps).unwrap();
            let v = check_sphere_packing(&mesh, &caps, &eps30(), 256);
            assert!(matches!(v, PackingVerdict::Holds { .. }), "{v:?}");
            // The punctured vertex's cap is the southern hemisphere.
            assert_eq!(caps[puncture].normal[2], -1);
            // Negative control: one cap shrunk (its height raised by 10⁻²⁰) is refuted.
            let mut bad = caps.clone();
            let w = (puncture + 1) % mesh.n_vertices();
            bad[w].height += Rational::from((1, 10u128.pow(20)));
            let v = check_sphere_packing(&mesh, &bad, &eps30(), 256);
            assert!(matches!(v, PackingVerdict::Fails(_)), "{v:?}");
            // Mirrored caps (x ↦ −x) reverse every orientation.
            let mut mirrored = caps.clone();
            for c in &mut mirrored {
                c.normal[0] = -c.normal[0].clone();
            }
            let v = check_sphere_packing(&mesh, &mirrored, &eps30(), 256);
            assert!(matches!(v, PackingVerdict::Fails(_)), "{v:?}");
        }
    }
    // Uniqueness up to Möbius transformations: the inversive distances of all pairs of
    // caps (Möbius invariants) agree between packings punctured at different vertices,
    // and on the icosahedron they depend only on the graph distance (its symmetry).
    let mesh = icosahedron().mesh;
    let a = maximal_sphere::<Mpfr>(&mesh, 0, prec(128), &Options::default()).unwrap();
    let b = maximal_sphere::<Mpfr>(&mesh, 7, prec(128), &Options::default()).unwrap();
    let (ia, ib) = (inversive_matrix(&a.caps), inversive_matrix(&b.caps));
    let n = mesh.n_vertices();
    let mut by_distance: Vec<Option<Mpfr>> = Vec::new();
    let gap = |x: &Mpfr, y: &Mpfr| (x.clone() - y).approx_f64().abs();
    let dist = graph_distances(&mesh);
    for i in 0..n {
        for j in 0..n {
            assert!(gap(&ia[i][j], &ib[i][j]) < 1e-25, "I({i},{j})");
            let d = dist[i][j];
            if by_distance.len() <= d {
                by_distance.resize(d + 1, None);
            }
            let first = by_distance[d].get_or_insert_with(|| ia[i][j].clone());
            assert!(gap(&ia[i][j], first) < 1e-25, "I({i},{j}) at distance {d}");
        }
    }
    let one = ia[0][0].one_like();
    assert!(gap(by_distance[1].as_ref().unwrap(), &one) < 1e-25); // tangent
                                                                  // Negative control: one cap changed changes its inversive distances.
    let mut caps = a.caps.clone();
    caps[5].height = caps[5].height.clone() * &caps[5].height.lit(1.001);
    let ic = inversive_matrix(&caps);
    assert!((0..n).any(|j| j != 5 && gap(&ic[5][j], &ia[5][j]) > 1e-6));
}

/// `I = (hh' − n·n')/√((1 − h²)(1 − h'²))` for all pairs of caps (B96), in MPFR
/// (diagonal: −1 by this formula).
fn inversive_matrix(caps: &[penner::circles::maximal::sphere::Cap<Mpfr>]) -> Vec<Vec<Mpfr>> {
    caps.iter()
        .map(|a| {
            caps.iter()
                .map(|b| {
                    let one = a.height.one_like();
                    let dot = a.normal[0].clone() * &b.normal[0]
                        + &(a.normal[1].clone() * &b.normal[1])
                        + &(a.normal[2].clone() * &b.normal[2]);
                    let num = a.height.clone() * &b.height - &dot;
                    let den = ((one.clone() - &(a.height.clone() * &a.height))
                        * &(one - &(b.height.clone() * &b.height)))
                        .sqrt();
                    num / &den
                })
                .collect()
        })
        .collect()
}

fn graph_distances(mesh: &Mesh) -> Vec<Vec<usize>> {
    let n = mesh.n_vertices();
    (0..n)
        .map(|s| {
            let mut d = vec![usize::MAX; n];
            d[s] = 0;
            let mut q = std::collections::VecDeque::from([s]);
            while let Some(v) = q.pop_front() {
                for h in mesh.outgoing(penner::mesh::Vertex(v as u32)) {
                    let w = mesh.tip(h).idx();
                    if d[w] == usize::MAX {
                        d[w] = d[v] + 1;
                        q.push_back(w);
                    }
                }
            }
            d
        })
        .collect()
}

#[test]
fn t11_typed_errors_for_surfaces_without_a_maximal_packing() {
    let ico = icosahedron().mesh;
    assert!(matches!(
        maximal_disk::<f64>(&ico, (), &Options::default()),
        Err(MaximalError::Topology {
            expected: "disk",
            ..
        })
    ));
    let disk = grid_disk(1, 1).unwrap().mesh; // two triangles, no interior vertex
    assert!(matches!(
        maximal_disk::<f64>(&disk, (), &Options::default()),
        Err(MaximalError::NoInteriorVertex)
    ));
    let grid = grid_disk(3, 3).unwrap().mesh;
    assert!(matches!(
        maximal_sphere::<f64>(&grid, 0, (), &Options::default()),
        Err(MaximalError::Topology {
            expected: "sphere",
            ..
        })
    ));
    assert!(matches!(
        maximal_sphere::<f64>(&ico, 12, (), &Options::default()),
        Err(MaximalError::NoSuchVertex(12))
    ));
    let opts = Options {
        centre: Some(0),
        ..Options::default()
    };
    assert!(matches!(
        maximal_disk::<f64>(&grid, (), &opts),
        Err(MaximalError::Layout(_))
    ));
}

/// A hexagonal disk of radius `k` (3k(k+1) + 1 vertices) as OBJ, coordinates scaled by
/// `scale` and sheared by `shear` (the combinatorics does not change).
fn hex_obj(k: i32, scale: f64, shear: f64) -> String {
    use std::fmt::Write as _;
    let mut idx = std::collections::HashMap::new();
    let mut s = String::new();
    for i in -k..=k {
        for j in -k..=k {
            if (i + j).abs() <= k {
                idx.insert((i, j), idx.len() + 1);
                let (x, y) = (f64::from(i) + 0.5 * f64::from(j), f64::from(j) * 0.866);
                let _ = writeln!(s, "v {} {} 0", scale * (x + shear * y), scale * y);
            }
        }
    }
    let mut keys: Vec<_> = idx.keys().copied().collect();
    keys.sort_by_key(|k| idx[k]);
    for (i, j) in keys {
        let a = idx[&(i, j)];
        if let (Some(b), Some(c)) = (idx.get(&(i + 1, j)), idx.get(&(i, j + 1))) {
            let _ = writeln!(s, "f {a} {b} {c}");
        }
        if let (Some(b), Some(c)) = (idx.get(&(i + 1, j - 1)), idx.get(&(i + 1, j))) {
            let _ = writeln!(s, "f {a} {b} {c}");
        }
    }
    s
}

/// The icosahedron as OBJ.
fn ico_obj() -> String {
    use std::fmt::Write as _;
    let ico = penner::mesh::builders::icosahedron();
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
    obj
}

#[test]
fn t11_cli_pack_disk_and_sphere() {
    use crate::support::{assert_refused, penner, scratch, text, write};
    let dir = scratch("pack-maximal");
    let a = write(&dir, "hex.obj", hex_obj(3, 1.0, 0.0).as_bytes());
    let b = write(&dir, "hex-sheared.obj", hex_obj(3, 7.5, 0.4).as_bytes());
    let run = |input: &std::path::Path, name: &str| {
        let json = dir.join(format!("{name}.json"));
        let svg = dir.join(format!("{name}.svg"));
        let out = penner(&[
            "pack",
            input.to_str().unwrap(),
            "--disk",
            "-o",
            json.to_str().unwrap(),
            "--svg",
            svg.to_str().unwrap(),
        ]);
        assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
        assert!(
            text(&out.stdout).contains("certified (B95)"),
            "{}",
            text(&out.stdout)
        );
        let doc: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
        let pic = std::fs::read_to_string(&svg).unwrap();
        // One circle per vertex and the unit circle.
        let n = doc["radii"].as_array().unwrap().len();
        assert_eq!(pic.matches("<circle").count(), n + 1);
        doc
    };
    let da = run(&a, "a");
    let db = run(&b, "b");
    assert_eq!(da["status"], "holds");
    assert_eq!(da["radii"].as_array().unwrap().len(), 37);
    // Different metrics, same triangulation: the same packing, digit for digit.
    assert_eq!(da["centres"], db["centres"]);
    assert_eq!(da["radii"], db["radii"]);
    // Negative control: another triangulation (one more ring) is another packing.
    let c = write(&dir, "hex4.obj", hex_obj(4, 1.0, 0.0).as_bytes());
    let dc = run(&c, "c");
    assert_ne!(dc["radii"], da["radii"]);
    // A sphere: the icosahedron, punctured at v3.
    let s = write(&dir, "ico.obj", ico_obj().as_bytes());
    let js = dir.join("ico.json");
    let out = penner(&[
        "pack",
        s.to_str().unwrap(),
        "--sphere",
        "--puncture",
        "3",
        "-o",
        js.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(text(&out.stdout).contains("B96"));
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&js).unwrap()).unwrap();
    assert_eq!(doc["caps"].as_array().unwrap().len(), 12);
    // Bad input: a sphere as a disk, a disk as a sphere, a puncture out of range, a bad ε,
    // an existing output.
    assert_refused(
        &penner(&["pack", s.to_str().unwrap(), "--disk"]),
        3,
        &["ico.obj", "not a disk"],
    );
    assert_refused(
        &penner(&["pack", a.to_str().unwrap(), "--sphere"]),
        3,
        &["not a sphere"],
    );
    assert_refused(
        &penner(&["pack", s.to_str().unwrap(), "--sphere", "--puncture", "12"]),
        3,
        &["v12"],
    );
    assert_refused(
        &penner(&["pack", a.to_str().unwrap(), "--disk", "--epsilon", "x"]),
        3,
        &["--epsilon"],
    );
    assert_refused(
        &penner(&[
            "pack",
            a.to_str().unwrap(),
            "--disk",
            "-o",
            js.to_str().unwrap(),
        ]),
        4,
        &["exists"],
    );
    // ε below what 64 bits reach: --bits is a minimum, raised to what ε needs (B99).
    let low = penner(&[
        "pack",
        a.to_str().unwrap(),
        "--disk",
        "--bits",
        "64",
        "--epsilon",
        "1e-60",
    ]);
    assert_eq!(low.status.code(), Some(0), "{}", text(&low.stdout));
    assert!(
        !text(&low.stdout).contains("at 64 bits"),
        "{}",
        text(&low.stdout)
    );
}

#[test]
fn b92_layout_defects_grow_with_the_residual_not_with_the_rows() {
    // The hexagonal complex of the upper half-disk at ε = 1/64 (7 487 vertices, up to about
    // 70 lattice steps from the centre to the boundary) packed in f64: placing each face
    // from its parent face's corners keeps every tangency defect below n·(δ + 2⁴u)
    // (proofs/B92; measured 5.5e-13 against a bound of 4e-10). Placing circles from neighbours positioned through
    // different faces gave 6.5e-8 here, and 0.58 at ε = 1/128 (proofs/T12 "Limits").
    let hex = hex_complex(&in_half_disk, BASE, 1.0 / 64.0, 1.2).unwrap();
    let opts = Options {
        centre: Some(hex.centre),
        direction: hex.direction,
        ..Options::default()
    };
    let p = maximal_disk::<f64>(&hex.mesh, (), &opts).unwrap();
    let n = hex.mesh.n_vertices() as f64;
    let bound = n * (p.f64_residual + 16.0 * f64::EPSILON / 2.0);
    let d = layout_defect(&hex.mesh, &p.circles, &p.interior);
    assert!(d <= bound, "defect {d:e} > {bound:e}");
    // Negative control: one interior circle moved by 10⁻⁸ (≫ the bound) is rejected.
    let v = p.interior.iter().position(|&b| b).unwrap();
    let mut moved = p.circles.clone();
    moved[v].centre[0] += 1e-8;
    let d = layout_defect(&hex.mesh, &moved, &p.interior);
    assert!(d > bound, "defect {d:e} ≤ {bound:e}");
}
