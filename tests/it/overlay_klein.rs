//! B111: crossings tracked through Ptolemy flips in the Klein picture, and moved to a
//! conformally equivalent metric by the symmedian rule, against independent oracles:
//!
//! - on polygons inscribed in the unit circle every quadrilateral is cyclic, so a Ptolemy
//!   flip is the Euclidean one (T29) and the Klein tracking must reproduce the Euclidean
//!   tracking (B108) and the exact rational intersections of the chords;
//! - a Möbius transformation of the unit disk changes the chord lengths conformally
//!   (`|M(z) − M(w)|² = |M′(z)||M′(w)||z − w|²`) and acts on the Klein model projectively,
//!   so the rescaled crossings must be the exact intersections of the moved chords (the
//!   rule with the wrong sign must not be);
//! - the symmedian rule against the foot of the hyperbolic perpendicular built from an
//!   explicit layout (the line from the vertex through the pole of the opposite chord).
//!
//! Tolerance 10⁻⁹ (B111, Tolerances): a first-order bound for these well-conditioned
//! configurations, measured below 10⁻¹².

use penner::mesh::{Edge, Mesh};
use penner::overlay::tracking::{rescaled_parameter, track_euclidean_then_ptolemy};
use penner::overlay::{
    common_refinement, replay_normal_coordinates, track_flips, TrackError, TrackedOverlay,
};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

type Q2 = [Rational; 2];

const TOL: f64 = 1e-9;

fn q(n: i64, d: i64) -> Rational {
    Rational::from((n, d))
}

/// The point of the unit circle `((1 − m²)/(1 + m²), 2m/(1 + m²))`, exact.
fn on_circle(m: &Rational) -> Q2 {
    let m2 = Rational::from(m * m);
    let d = Rational::from(&m2 + 1);
    [(1 - m2) / d.clone(), Rational::from(m * 2) / d]
}

/// Exact intersection parameters `(s, t)` of segments `ab` and `pq`.
fn exact_params(a: &Q2, b: &Q2, p: &Q2, q: &Q2) -> (f64, f64) {
    let d = |u: &Q2, v: &Q2| [Rational::from(&v[0] - &u[0]), Rational::from(&v[1] - &u[1])];
    let cr = |u: &Q2, v: &Q2| Rational::from(&u[0] * &v[1]) - Rational::from(&u[1] * &v[0]);
    let (r, w, ap) = (d(a, b), d(p, q), d(a, p));
    let den = cr(&r, &w);
    let s = cr(&ap, &w) / den.clone();
    let t = cr(&ap, &r) / den;
    (s.to_f64(), t.to_f64())
}

fn dist(a: &Q2, b: &Q2) -> f64 {
    let dx = Rational::from(&a[0] - &b[0]);
    let dy = Rational::from(&a[1] - &b[1]);
    (Rational::from(&dx * &dx) + Rational::from(&dy * &dy))
        .to_f64()
        .sqrt()
}

fn ends(m: &Mesh, e: Edge) -> (usize, usize) {
    let h = e.side(0);
    (m.tail(h).idx(), m.tip(h).idx())
}

/// A polygon inscribed in the unit circle (vertices counterclockwise at rational
/// parameters, a fan triangulation from vertex 0) and `n_flips` random flips of interior
/// edges (every quadrilateral cyclic, hence strictly convex).
fn inscribed_case(seed: u64, n_flips: usize) -> (Mesh, Vec<Q2>, Vec<f64>, Vec<Edge>) {
    let ms = [
        q(-7, 1),
        q(-3, 1),
        q(-3, 2),
        q(-1, 1),
        q(-1, 2),
        q(-1, 5),
        q(0, 1),
        q(1, 4),
        q(1, 2),
        q(1, 1),
        q(2, 1),
        q(5, 1),
    ];
    let pos: Vec<Q2> = ms.iter().map(on_circle).collect();
    let n = pos.len() as u32;
    let faces: Vec<[u32; 3]> = (1..n - 1).map(|i| [0, i, i + 1]).collect();
    let t_in = Mesh::from_faces(n, &faces).unwrap();
    let l0: Vec<f64> = t_in
        .edges()
        .map(|e| {
            let (a, b) = ends(&t_in, e);
            dist(&pos[a], &pos[b])
        })
        .collect();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut m = t_in.clone();
    let mut flips = Vec::new();
    while flips.len() < n_flips {
        let e = Edge(rng.gen_range(0..m.n_edges() as u32));
        if !m.is_boundary_edge(e) && m.flip(e).is_ok() {
            flips.push(e);
        }
    }
    (t_in, pos, l0, flips)
}

/// On inscribed polygons the Klein tracking through Ptolemy flips gives the crossings of
/// the Euclidean tracking (a different formula, B108) and of the exact intersections of
/// the chords: same half-edges, parameters `t` and `s` within 10⁻⁹; the Ptolemy lengths
/// are the chords (T29).
#[test]
fn b111_klein_tracking_on_cyclic_quadrilaterals_is_the_euclidean_tracking() {
    let mut seen = 0;
    let mut worst = 0.0f64;
    for seed in 0..6u64 {
        let (t_in, pos, l0, flips) = inscribed_case(seed, 40);
        let euclid = track_flips(&t_in, &l0, &flips).unwrap();
        let klein = track_euclidean_then_ptolemy(&t_in, &l0, &[], &flips, None).unwrap();
        assert_eq!(euclid.mesh, klein.mesh);
        let (_, n) = replay_normal_coordinates(&t_in, &flips).unwrap();
        assert_eq!(klein.crossing_counts(), n.values());
        for e in klein.mesh.edges() {
            let (a, b) = ends(&klein.mesh, e);
            let chord = dist(&pos[a], &pos[b]);
            assert!((klein.lengths[e.idx()] - chord).abs() < TOL * chord);
        }
        for (g, (pe, pk)) in euclid.paths.iter().zip(&klein.paths).enumerate() {
            assert_eq!(pe.along, pk.along, "seed {seed} g{g}");
            assert_eq!(pe.crossings.len(), pk.crossings.len(), "seed {seed} g{g}");
            let (a, b) = ends(&t_in, Edge(g as u32));
            for (ce, ck) in pe.crossings.iter().zip(&pk.crossings) {
                assert_eq!(ce.h, ck.h, "seed {seed} g{g}");
                let (p, q) = (klein.mesh.tail(ck.h).idx(), klein.mesh.tip(ck.h).idx());
                let (s, t) = exact_params(&pos[a], &pos[b], &pos[p], &pos[q]);
                for (x, y) in [(ck.t, ce.t), (ck.s, ce.s), (ck.t, t), (ck.s, s)] {
                    assert!((x - y).abs() < TOL, "seed {seed} g{g}: {x} vs {y}");
                    worst = worst.max((x - y).abs());
                }
                seen += 1;
            }
        }
    }
    assert!(seen > 100, "{seen}");
    assert!(worst < 1e-12, "measured {worst:e}");
}

/// The exact Möbius transformation `z ↦ (z − a)/(1 − ā z)` of the unit disk, and
/// `log |M′(z)| = log((1 − |a|²)/|1 − ā z|²)`.
fn mobius(a: &Q2, z: &Q2) -> (Q2, f64) {
    // d = 1 − ā z
    let re = Rational::from(1) - Rational::from(&a[0] * &z[0]) - Rational::from(&a[1] * &z[1]);
    let im = Rational::from(&a[1] * &z[0]) - Rational::from(&a[0] * &z[1]);
    let d2 = Rational::from(&re * &re) + Rational::from(&im * &im);
    let (x, y) = (Rational::from(&z[0] - &a[0]), Rational::from(&z[1] - &a[1]));
    // (x + iy)(re − i im) / |d|²
    let mx = (Rational::from(&x * &re) + Rational::from(&y * &im)) / d2.clone();
    let my = (Rational::from(&y * &re) - Rational::from(&x * &im)) / d2.clone();
    let a2 = Rational::from(&a[0] * &a[0]) + Rational::from(&a[1] * &a[1]);
    let du = (Rational::from(1) - a2) / d2;
    ([mx, my], du.to_f64().ln())
}

/// Rule 2 of B111 against an independent oracle: a Möbius transformation of the disk
/// moves the inscribed polygon to another, with chord lengths `e^{(u_i+u_j)/2} ℓ_ij`
/// (`u = log |M′|`), and maps chords to chords and crossings to crossings (it is a
/// projective map of the Klein model). After [`TrackedOverlay::rescale`] the lengths are
/// the moved chords and every crossing's `t` is the exact intersection of the moved
/// chords; the rule with the sign of `u_a − u_b` reversed misses by more than 10⁻³.
#[test]
fn b111_rescaled_crossings_follow_a_mobius_transformation() {
    let a = [q(1, 3), q(-1, 5)];
    let mut worst_right = 0.0f64;
    let mut worst_wrong = 0.0f64;
    for seed in 0..4u64 {
        let (t_in, pos, l0, flips) = inscribed_case(seed + 10, 30);
        let (moved, u): (Vec<Q2>, Vec<f64>) = pos.iter().map(|z| mobius(&a, z)).unzip();
        let o = track_euclidean_then_ptolemy(&t_in, &l0, &[], &flips, Some(&u)).unwrap();
        let plain = track_euclidean_then_ptolemy(&t_in, &l0, &[], &flips, None).unwrap();
        let mut short = plain.clone();
        assert_eq!(short.rescale(&u[1..]), Err(TrackError::ScaleFactors));
        assert_eq!(short.paths, plain.paths);
        for e in o.mesh.edges() {
            let (x, y) = ends(&o.mesh, e);
            let chord = dist(&moved[x], &moved[y]);
            assert!((o.lengths[e.idx()] - chord).abs() < TOL * chord);
        }
        for (g, (p, p0)) in o.paths.iter().zip(&plain.paths).enumerate() {
            let (ga, gb) = ends(&t_in, Edge(g as u32));
            for (c, c0) in p.crossings.iter().zip(&p0.crossings) {
                let (x, y) = (o.mesh.tail(c.h).idx(), o.mesh.tip(c.h).idx());
                let (_, t) = exact_params(&moved[ga], &moved[gb], &moved[x], &moved[y]);
                assert!((c.t - t).abs() < TOL, "seed {seed} g{g}: {} vs {t}", c.t);
                assert_eq!(c.s, c0.s, "s is a position along the input edge");
                worst_right = worst_right.max((c.t - t).abs());
                let wrong = rescaled_parameter(c0.t, u[y] - u[x]);
                worst_wrong = worst_wrong.max((wrong - t).abs());
            }
        }
    }
    assert!(worst_right < 1e-12, "measured {worst_right:e}");
    assert!(
        worst_wrong > 1e-3,
        "the wrong sign went unnoticed: {worst_wrong:e}"
    );
}

/// The foot of the hyperbolic perpendicular from `k` to `ij` in the circumdisk (Klein
/// model) of the triangle with sides `ij = c`, `jk = a`, `ki = b`, built from an explicit
/// layout: the line from `k` through the pole of the chord `ij` (the meet of the tangents
/// at `i` and `j`), as a parameter from `i`.
fn perpendicular_foot(a: f64, b: f64, c: f64) -> f64 {
    let kx = (b * b + c * c - a * a) / (2.0 * c);
    let ky = (b * b - kx * kx).sqrt();
    // Circumcenter (c/2, oy): equidistant from i = (0, 0) and k.
    let oy = (kx * kx + ky * ky - c * kx) / (2.0 * ky);
    let r2 = c * c / 4.0 + oy * oy;
    // The pole of ij lies on the line from the center through the midpoint (c/2, 0), at
    // distance R²/|oy| from the center, on the far side of the chord.
    let py = oy - r2 / oy;
    let px = c / 2.0;
    // The line k → P meets y = 0.
    let fx = kx + (0.0 - ky) * (px - kx) / (py - ky);
    fx / c
}

/// Rule 2 of B111 against the explicit construction: the foot of the perpendicular from
/// `k` is at `t/(1 − t) = (λ_ki/λ_kj)²` (the symmedian foot), and a conformal change
/// `λ′ = e^{(u_a+u_b)/2} λ` moves it by `t/(1 − t) ↦ e^{u_i − u_j} t/(1 − t)`, from either
/// side of the edge (the apex `k` above, `l` below); the opposite sign does not.
#[test]
fn b111_symmedian_rule_matches_the_perpendicular_foot_of_a_layout() {
    let mut rng = ChaCha8Rng::seed_from_u64(111);
    let (mut tested, mut controls) = (0, 0);
    for _ in 0..200 {
        let c: f64 = rng.gen_range(0.5..2.0);
        let (a, b): (f64, f64) = (rng.gen_range(0.5..2.0), rng.gen_range(0.5..2.0));
        let (d, e): (f64, f64) = (rng.gen_range(0.5..2.0), rng.gen_range(0.5..2.0));
        // Two triangles on ij: ijk (jk = a, ki = b) and ijl (jl = d, li = e).
        let valid = |x: f64, y: f64, z: f64| x + y > 1.05 * z && (x - y).abs() < 0.95 * z;
        if !(valid(a, b, c) && valid(d, e, c)) {
            continue;
        }
        let u: [f64; 4] = std::array::from_fn(|_| rng.gen_range(-1.5..1.5));
        let [ui, uj, uk, ul] = u;
        let sc = |x: f64, p: f64, q: f64| x * (0.5 * (p + q)).exp();
        for (side_a, side_b, ua) in [(a, b, uk), (d, e, ul)] {
            let scaled = [sc(side_a, uj, ua), sc(side_b, ui, ua), sc(c, ui, uj)];
            if !valid(scaled[0], scaled[1], scaled[2]) {
                continue;
            }
            let t = perpendicular_foot(side_a, side_b, c);
            let r = t / (1.0 - t);
            assert!((r - (side_b / side_a).powi(2)).abs() < TOL * r, "symmedian");
            let t2 = perpendicular_foot(scaled[0], scaled[1], scaled[2]);
            let right = rescaled_parameter(t, ui - uj);
            assert!((right - t2).abs() < TOL, "{right} vs {t2}");
            if (ui - uj).abs() > 0.1 {
                let wrong = rescaled_parameter(t, uj - ui);
                assert!((wrong - t2).abs() > 1e-3, "{wrong} vs {t2}");
                controls += 1;
            }
            tested += 1;
        }
    }
    assert!(tested > 100 && controls > 50, "{tested} {controls}");
}

/// A planar mesh spoiled by flips (B105's oracle meshes), flipped by Ptolemy flips of its
/// own metric on random interior edges, many of whose quadrilaterals are not convex in the
/// input metric: the Euclidean tracking refuses such a flip (`NotStraight`, B108), the Klein
/// tracking follows all of them; the crossing counts are the normal coordinates (B105),
/// every crossing is inside its edge, positions along each input edge increase, and the
/// refinement is a triangle mesh with the input's Euler characteristic.
#[test]
fn b111_ptolemy_flips_not_convex_in_the_input_metric_are_followed() {
    let mut nonconvex = 0;
    for seed in 0..6u64 {
        let e = penner::mesh::builders::random_planar(14 + seed as u32, seed).unwrap();
        let t_in = e.mesh;
        let pos: Vec<[f64; 2]> = e
            .positions
            .iter()
            .map(|p| [p[0].to_f64(), p[1].to_f64()])
            .collect();
        let l0: Vec<f64> = t_in
            .edges()
            .map(|e| {
                let (a, b) = ends(&t_in, e);
                (pos[a][0] - pos[b][0]).hypot(pos[a][1] - pos[b][1])
            })
            .collect();
        let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0xb111);
        let mut o = TrackedOverlay::of_input(&t_in, &l0).unwrap();
        let mut flips = Vec::new();
        while flips.len() < 3 * t_in.n_edges() {
            let e = Edge(rng.gen_range(0..t_in.n_edges() as u32));
            if t_in.is_boundary_edge(e) || o.mesh.clone().flip(e).is_err() {
                continue;
            }
            let mut euclid = o.clone();
            if matches!(euclid.flip(e), Err(TrackError::NotStraight { .. })) {
                nonconvex += 1;
            }
            o.flip_ptolemy(e).unwrap();
            flips.push(e);
        }
        let (t, n) = replay_normal_coordinates(&t_in, &flips).unwrap();
        assert_eq!(o.mesh, t);
        assert_eq!(o.crossing_counts(), n.values());
        for p in &o.paths {
            let mut last = 0.0;
            for c in &p.crossings {
                assert!(c.t > 0.0 && c.t < 1.0 && c.s > last && c.s < 1.0, "{c:?}");
                last = c.s;
            }
        }
        let r = common_refinement(&t_in, &o).unwrap();
        let faces: Vec<[u32; 3]> = r.triangles.iter().map(|t| t.vertices).collect();
        let m = Mesh::from_faces(r.vertices.len() as u32, &faces).unwrap();
        assert_eq!(m.euler_characteristic(), t_in.euler_characteristic());
    }
    assert!(
        nonconvex > 10,
        "too few non-convex quadrilaterals: {nonconvex}"
    );
}

/// Four cones of angle π at the vertices `0, n/4, n/2, 3n/4` (Gauss–Bonnet on a sphere:
/// `4 · π = 4π`).
pub fn four_evenly_spaced_cones(n: usize) -> penner::uniformization::Targets {
    let mut t = vec![Rational::from(2); n];
    for v in [0, n / 4, n / 2, 3 * n / 4] {
        t[v] = Rational::from(1);
    }
    penner::uniformization::Targets::from_multiples_of_pi(t)
}

/// End to end on the cow (2 904 vertices, 5 804 faces) with four cones of angle π at
/// vertices 0, 726, 1452, 2178: the solve's Ptolemy flips include quadrilaterals that are
/// not convex in the input metric (the input-metric tracking of B108 stops at Ptolemy flip
/// 167, checked here), and the UVs are written:
/// the crossing counts are the normal coordinates (inside `uv_closed`, B105), no UV
/// triangle folds and every input face is tiled exactly (B109); every seam segment is a
/// quarter turn within 10⁻⁹ (B110) except segments shorter than 10⁻⁶ of the layout
/// (145 of 3 403 measured), where the binary64 coordinates cannot resolve 10⁻⁹.
#[test]
fn b111_cow_uv_through_ptolemy_flips() {
    use penner::overlay::{check_parametrization, check_seams};
    use penner::uniformization::pipeline::{uniformize_closed, uv_closed, Options, Precision};
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/real/cow.obj");
    let s = penner::io::read_path(&path).unwrap();
    let targets = four_evenly_spaced_cones(s.mesh.n_vertices());
    let opts = Options {
        precision: Precision::F64,
        certify: false,
    };
    let out = uniformize_closed(&s, &targets, &opts, &mut |_| {}).unwrap();
    let sol = &out.solution;
    assert!(sol.converged());
    // Some Ptolemy flip is not convex in the input metric: the Euclidean tracking of the
    // whole sequence stops there.
    let euclid = {
        let l = out.surface.lengths::<f64>(());
        let mut t0 = out.surface.mesh.clone();
        let mut l0 = l.clone();
        let opts = penner::algorithms::flip_to_delaunay::FlipOptions {
            record: true,
            ..Default::default()
        };
        let rep = penner::algorithms::flip_to_delaunay::flip_to_delaunay(
            &mut t0,
            &mut l0,
            penner::algorithms::flip_to_delaunay::FlipKind::Euclidean,
            &opts,
        )
        .unwrap();
        let mut flips = rep.sequence;
        flips.extend_from_slice(&sol.flip_sequence);
        track_flips(&out.surface.mesh, &l, &flips)
    };
    assert!(
        matches!(euclid, Err(TrackError::NotStraight { .. })),
        "{:?}",
        euclid.err()
    );
    let uv = uv_closed(&s, &out).unwrap();
    let (obj, side) = (uv.obj(), uv.sidecar());
    let report = check_parametrization(&obj, &side).unwrap();
    assert!(report.holds(), "{report:?}");
    assert!(report.triangles >= s.mesh.n_faces(), "{report:?}");
    // Seams: the conformal factors span e^{−25.7} … e^{2.5} here, so some UV triangles are
    // 10⁻¹³ of the layout. A seam segment of length `d` in coordinates of size `X` carries
    // rounding of a few ulps, ≈ 10 · 2⁻⁵³ X, which exceeds the relative 10⁻⁹ once
    // `d < 10⁻⁶ X`: every broken segment must be that short; the longer ones all hold.
    let eps = Rational::from((1, 1_000_000_000u32));
    let seams = check_seams(&obj, &eps).unwrap();
    // The cut runs through the four cones only (B113): a few hundred seam segments, not one
    // per edge of a dual spanning tree's complement.
    assert!(
        seams.seam_segments > 0 && seams.seam_segments < s.mesh.n_edges() / 10,
        "{seams:?}"
    );
    let extent = uv
        .uv
        .iter()
        .flatten()
        .map(|p| p[0].abs().max(p[1].abs()))
        .fold(0.0, f64::max);
    for &k in &seams.broken {
        let [a, b, c] = uv.uv[k];
        let d = |p: [f64; 2], q: [f64; 2]| (p[0] - q[0]).hypot(p[1] - q[1]);
        let shortest = d(a, b).min(d(b, c)).min(d(c, a));
        assert!(
            shortest < 1e-6 * extent,
            "a seam broken on triangle {k} with sides ≥ {shortest:e} (layout {extent:e})"
        );
    }
    assert!(
        seams.broken.len() * 10 < seams.seam_segments,
        "{} of {} seams broken",
        seams.broken.len(),
        seams.seam_segments
    );
}
