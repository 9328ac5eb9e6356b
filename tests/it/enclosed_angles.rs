//! The certificate's enclosures without per-corner trigonometry: cone angles by one
//! argument per vertex (B33) and cotangents from squared lengths (B34), against a 512-bit
//! reference (a different formula: the per-corner arctangent sum, `cot_opposite` with
//! Kahan's area) and against the per-corner enclosures they replace.

use crate::meshgen::{icosphere, jittered_torus};
use penner::geometry::cone_angles::cone_angles_per_corner;
use penner::geometry::cotan::halfedge_cotans;
use penner::geometry::enclosure::angle_sums::enclose_cone_angles;
use penner::geometry::enclosure::cotans::enclose_halfedge_cotans;
use penner::mesh::Mesh;
use penner::scalar::{Interval, Mpfr, Precision, Real};
use penner::uniformization::refine::scaled;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

type I = Interval<Mpfr>;

fn prec(bits: u64) -> Precision {
    Precision::new(bits).expect("valid precision")
}

/// Whether the enclosure `x` contains the value `r` (compared exactly).
fn contains(x: &I, r: &Mpfr) -> bool {
    r.to_rational().is_some_and(|q| x.contains_rational(&q))
}

/// A noisy icosphere and a jittered torus with random log scale factors in `[−0.02, 0.02]`
/// (small enough that every face stays a strict triangle):
/// `(mesh, f64 base lengths, u)`.
fn random_cases() -> Vec<(Mesh, Vec<f64>, Vec<f64>)> {
    let mut out = Vec::new();
    let mut s = icosphere(3);
    let amount = 0.2 * s.mean_edge();
    s.jitter(amount, 7);
    let m = s.mesh();
    let l = s.lengths(&m);
    out.push((m, l));
    out.push(jittered_torus(7, 9, 4));
    let mut rng = ChaCha8Rng::seed_from_u64(33);
    out.into_iter()
        .map(|(m, l)| {
            let u = (0..m.n_vertices())
                .map(|_| rng.gen_range(-0.02..0.02))
                .collect();
            (m, l, u)
        })
        .collect()
}

/// Scaled lengths `e^{(u_i+u_j)/2}ℓ_ij` enclosed at `bits`, and as MPFR numbers at 512 bits
/// (the reference's lengths, within 2⁻⁵⁰⁰ relative of the exact ones).
fn scaled_pair(m: &Mesh, l: &[f64], u: &[f64], bits: u64) -> (Vec<I>, Vec<Mpfr>) {
    let p = prec(bits);
    let bi: Vec<I> = l.iter().map(|&x| I::from_f64(x, p)).collect();
    let ui: Vec<I> = u.iter().map(|&x| I::from_f64(x, p)).collect();
    let r = prec(512);
    let br: Vec<Mpfr> = l.iter().map(|&x| Mpfr::from_f64(x, r)).collect();
    let ur: Vec<Mpfr> = u.iter().map(|&x| Mpfr::from_f64(x, r)).collect();
    (scaled(m, &bi, &ui), scaled(m, &br, &ur))
}

/// A closed fan: apex 0, rim 1..=n, faces `[0, i, i+1]`, spokes `spoke[i]`, rim edges
/// `rim[i]` (between rim vertices `i+1` and `i+2`, cyclically).
fn fan(spoke: &[f64], rim: &[f64]) -> (Mesh, Vec<f64>) {
    let n = spoke.len() as u32;
    let faces: Vec<[u32; 3]> = (0..n).map(|i| [0, 1 + i, 1 + (i + 1) % n]).collect();
    let mesh = Mesh::from_faces(n + 1, &faces).expect("valid fan");
    let mut len = vec![0.0; mesh.n_edges()];
    for e in mesh.edges() {
        let h = e.halfedge();
        let (a, b) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        len[e.idx()] = if a == 0 || b == 0 {
            spoke[a.max(b) - 1]
        } else {
            // Rim edge between rim vertices a and b: face index min unless wrapping.
            let (lo, hi) = (a.min(b), a.max(b));
            let i = if hi - lo == 1 { lo - 1 } else { hi - 1 };
            rim[i]
        };
    }
    (mesh, len)
}

/// Adversarial fans: 3-4-5 triangles with exact right angles at the apex (partial sums
/// exactly at multiples of π/2: the quarter count is not certified there, B33 "Fallback"),
/// needles (apex angles near 10⁻⁸ with one wide corner), a corner near π (a cap), and ties
/// (a regular hexagon of equilateral triangles, θ = 2π exactly at the apex).
fn adversarial_cases() -> Vec<(&'static str, Mesh, Vec<f64>)> {
    let mut out = Vec::new();
    let (m, l) = fan(&[3.0, 4.0, 3.0, 4.0], &[5.0; 4]);
    out.push(("right angles (3-4-5)", m, l));
    let (m, l) = fan(&[1.0; 6], &[1.0; 6]);
    out.push(("equilateral hexagon (ties)", m, l));
    // Apex angles: five of 1e-8 (rim 2 sin(α/2)) and one wide closing the fan almost flat.
    let needle = 2.0 * (0.5e-8_f64).sin();
    let (m, l) = fan(
        &[1.0, 1.0, 1.0, 1.0, 1.0, 1.0],
        &[needle, needle, needle, needle, needle, 1.9],
    );
    out.push(("needles", m, l));
    // A cap: apex corner of about π − 2·10⁻⁶ (rim just below the sum of two spokes).
    let (m, l) = fan(&[1.0, 1.0, 1.0], &[2.0 - 1e-12, 1.0, 1.0]);
    out.push(("cap near π", m, l));
    out
}

fn point_lengths(l: &[f64], bits: u64) -> (Vec<I>, Vec<Mpfr>) {
    let p = prec(bits);
    let r = prec(512);
    (
        l.iter().map(|&x| I::from_f64(x, p)).collect(),
        l.iter().map(|&x| Mpfr::from_f64(x, r)).collect(),
    )
}

/// B33 ("Width"): the product path's width is at most about `(√2)^k` times the
/// per-corner path's for `k` corners (rectangular wrapping, first order); with a factor 2
/// for the second-order terms.
fn b33_wrapping_factor(k: usize) -> f64 {
    2.0 * 2f64.sqrt().powi(k as i32)
}

fn valence(mesh: &Mesh) -> Vec<usize> {
    let mut k = vec![0; mesh.n_vertices()];
    for f in mesh.faces() {
        for v in mesh.face_vertices(f) {
            k[v.idx()] += 1;
        }
    }
    k
}

#[test]
fn b33_enclosed_cone_angles_contain_the_512_bit_reference_on_random_meshes() {
    for (m, l, u) in random_cases() {
        for bits in [64, 256] {
            let (li, lr) = scaled_pair(&m, &l, &u, bits);
            let got = enclose_cone_angles(&m, &li);
            let old = cone_angles_per_corner(&m, &li);
            let reference = cone_angles_per_corner(&m, &lr);
            assert!(
                got.fallback.is_empty(),
                "generic metric, no fallback expected"
            );
            let k = valence(&m);
            for v in 0..m.n_vertices() {
                let (t, o) = (&got.theta[v], &old[v]);
                assert!(contains(t, &reference[v]), "v{v} at {bits} bits: {t:?}");
                assert!(contains(o, &reference[v]), "old path v{v}");
                // Within B33's wrapping factor of the per-corner path.
                let (w, wo) = (t.width_f64(), o.width_f64());
                assert!(
                    w <= b33_wrapping_factor(k[v]) * wo,
                    "v{v}: {w:e} vs old {wo:e}"
                );
            }
        }
    }
}

#[test]
fn b33_enclosed_cone_angles_on_adversarial_fans() {
    for (name, m, l) in adversarial_cases() {
        for bits in [64, 256] {
            let (li, lr) = point_lengths(&l, bits);
            let got = enclose_cone_angles(&m, &li);
            let reference = cone_angles_per_corner(&m, &lr);
            for (v, (t, r)) in got.theta.iter().zip(&reference).enumerate() {
                assert!(
                    contains(t, r),
                    "{name}, v{v} at {bits} bits: {t:?} vs {}",
                    r.approx_f64()
                );
            }
            if name.starts_with("right angles") {
                // Partial sums π/2, π, 3π/2 exactly: the apex takes the fallback.
                assert!(got.fallback.contains(&0), "{name}: {:?}", got.fallback);
            }
        }
    }
}

#[test]
fn b33_negative_control_a_perturbed_length_moves_the_enclosure_off_the_reference() {
    let (m, l, u) = random_cases().swap_remove(0);
    let (mut li, lr) = scaled_pair(&m, &l, &u, 256);
    let reference = cone_angles_per_corner(&m, &lr);
    // One edge 10⁻³⁰ longer: its two ends' angle sums change by far more than the width.
    let e = 5;
    li[e] = li[e].clone()
        * &I::from_rational(
            &Rational::from((
                1_000_000_000_000_000_000_000_000_000_001_i128,
                10_i128.pow(30),
            )),
            prec(256),
        );
    let got = enclose_cone_angles(&m, &li);
    let h = m.edges().nth(e).expect("edge").halfedge();
    let ends = [m.tail(h).idx(), m.tip(h).idx()];
    let missed: Vec<usize> = (0..m.n_vertices())
        .filter(|&v| !contains(&got.theta[v], &reference[v]))
        .collect();
    assert!(!missed.is_empty(), "the perturbation went unseen");
    assert!(missed.iter().all(|v| ends.contains(v) || {
        // Or the far corners of the two faces at the edge.
        m.faces().any(|f| {
            let vs = m.face_vertices(f).map(penner::mesh::Vertex::idx);
            vs.contains(v) && vs.contains(&ends[0]) && vs.contains(&ends[1])
        })
    }));
}

#[test]
fn b34_enclosed_cotangents_contain_the_reference_at_points_of_the_box() {
    let mut rng = ChaCha8Rng::seed_from_u64(34);
    for (m, l, u) in random_cases() {
        let bits = 256;
        let p = prec(bits);
        // A box of relative radius 10⁻²⁰ around each scaled length (as in the certificate).
        let (li, lr) = scaled_pair(&m, &l, &u, bits);
        let rad = I::from_rational(&Rational::from((1, 10_i128.pow(20))), p);
        let one = I::from_f64(1.0, p);
        let wide: Vec<I> = li
            .iter()
            .map(|x| {
                let lo = x.clone() * &(one.clone() - &rad);
                let hi = x.clone() * &(one.clone() + &rad);
                I::new(lo.lo().clone(), hi.hi().clone())
            })
            .collect();
        let got = enclose_halfedge_cotans(&m, &wide);
        let old = halfedge_cotans(&m, &wide);
        for h in m.halfedges() {
            assert!(got[h.idx()].is_valid());
            let (w, o) = (got[h.idx()].width_f64(), old[h.idx()].width_f64());
            // The same polynomials, so the same first-order width (B34, "Width").
            assert!(w <= 1.01 * o, "h{}: {w:e} vs old {o:e}", h.0);
        }
        // Points of the box: the centre and random corners, reference at 512 bits.
        let r = prec(512);
        for trial in 0..4 {
            let pts: Vec<Mpfr> = lr
                .iter()
                .map(|x| {
                    if trial == 0 {
                        return x.clone();
                    }
                    let t: f64 = rng.gen_range(-0.999..0.999);
                    x.clone() * &Mpfr::from_f64(1.0 + t * 1e-20, r)
                })
                .collect();
            let reference = halfedge_cotans(&m, &pts);
            for h in m.halfedges() {
                assert!(
                    contains(&got[h.idx()], &reference[h.idx()]),
                    "h{} trial {trial}",
                    h.0
                );
            }
        }
    }
}

#[test]
fn b34_enclosed_cotangents_on_adversarial_fans() {
    for (name, m, l) in adversarial_cases() {
        let (li, lr) = point_lengths(&l, 256);
        let got = enclose_halfedge_cotans(&m, &li);
        let reference = halfedge_cotans(&m, &lr);
        for h in m.halfedges() {
            assert!(
                contains(&got[h.idx()], &reference[h.idx()]),
                "{name}, h{}: {:?}",
                h.0,
                got[h.idx()]
            );
        }
    }
    // A degenerate face (1, 1, 2) is not a strict triangle: invalid, never a number.
    let (m, l) = fan(&[1.0, 1.0, 1.0], &[2.0, 1.0, 1.0]);
    let (li, _) = point_lengths(&l, 256);
    let got = enclose_halfedge_cotans(&m, &li);
    assert!(got.iter().any(|c| !c.is_valid()));
    let theta = enclose_cone_angles(&m, &li);
    assert!(!theta.fallback.is_empty());
}

#[test]
fn b34_negative_control_points_outside_the_box_leave_the_enclosure() {
    let (m, l, u) = random_cases().swap_remove(1);
    let (li, lr) = scaled_pair(&m, &l, &u, 256);
    let got = enclose_halfedge_cotans(&m, &li);
    // Two thirds of the lengths moved by 10⁻¹⁵ or 2·10⁻¹⁵: far outside the point enclosures.
    let r = prec(512);
    let moved: Vec<Mpfr> = lr
        .iter()
        .enumerate()
        .map(|(e, x)| {
            if e == 0 {
                x.clone()
            } else {
                x.clone() * &Mpfr::from_f64(1.0 + (e % 3) as f64 * 1e-15, r)
            }
        })
        .collect();
    let reference = halfedge_cotans(&m, &moved);
    let outside = m
        .halfedges()
        .filter(|h| !contains(&got[h.idx()], &reference[h.idx()]))
        .count();
    assert!(
        outside > m.n_halfedges() / 2,
        "{outside} of {}",
        m.n_halfedges()
    );
}
