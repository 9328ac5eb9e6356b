//! Tolerance tightness: the numerical checks compare against their derived bound, not a
//! multiple of it, and the bounds are neither exceeded nor loose by more than a stated
//! factor.
//!
//! Two kinds of tests:
//! - *position* tests move the computed quantity of a check so that its discrepancy sits at
//!   1.5× the bound (the check must fail) and at 0.5× the bound (it must hold). For T01 and
//!   T05 the bound is recomputed here from its parts with the per-operation `ε = 16u` of B40
//!   written out (`2⁻⁴⁹` at f64, `2⁻¹⁰⁰` at dd, `2⁴⁻ᵖ` at MPFR-p), so a change of `ε`, of the
//!   assembly of B41/B42, or of the comparison is seen;
//! - *measured* tests compare the f64 and dd evaluations of a bounded kernel with an
//!   independent MPFR-1024 reference on random and adversarial inputs: the observed error
//!   never exceeds the bound, and on some input it reaches a stated fraction of it.

use penner::geometry::curvature::{curvature, gauss_bonnet_target};
use penner::geometry::laplacian::cotan_laplacian;
use penner::geometry::triangle::{corner_angle, cot_opposite};
use penner::io::Surface;
use penner::mesh::Mesh;
use penner::oracle::corpus;
use penner::scalar::{Dd, Mpfr, Precision, Real};
use penner::theorems::bounds::{corner_angle_error, cot_error, sum_error};
use penner::theorems::t01_gauss_bonnet::verify_gauss_bonnet;
use penner::theorems::t05_cotan_laplacian::verify_laplacian;
use penner::theorems::t07_conformal_energy::{
    energy_error_bound, verify_conformal_energy, EnergyTerms,
};
use penner::theorems::t27_shear_log_cross_ratio::verify_shear_log_cross_ratio;
use penner::theorems::{Settings, Verdict};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// `ε = 16u` of B40 for the backend of `ctx`, from the unit roundoffs stated in B40
/// (f64: 2⁻⁵³; dd: 2⁻¹⁰⁴; MPFR-p: 2⁻ᵖ), independent of `theorems::bounds::eps`.
fn eps_b40<T: Real>(ctx: T::Ctx) -> f64 {
    let bits = T::precision_bits(ctx);
    let u_exp = match bits {
        53 => -53,
        106 => -104,
        p => -(p as i32),
    };
    16.0 * f64::from(u_exp).exp2()
}

/// B42 assembled from B40 and B41 with the given `ε` (proofs/B42): corner errors, per-vertex
/// angle sums and the `2π`, `K_i` roundings, the sum over vertices, and `2πχ`.
fn b42(mesh: &Mesh, l: &[f64], e: f64) -> f64 {
    let mut corners: Vec<Vec<f64>> = vec![Vec::new(); mesh.n_vertices()];
    let mut corner_err = 0.0;
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        for i in 0..3 {
            let (a, b, c) = (
                l[hs[i].edge().idx()],
                l[hs[(i + 1) % 3].edge().idx()],
                l[hs[(i + 2) % 3].edge().idx()],
            );
            corner_err += corner_angle_error(a, b, c, e);
            // The angle opposite side a, at the vertex between sides b and c.
            corners[mesh.tail(hs[(i + 2) % 3]).idx()].push(corner_angle(&a, &b, &c));
        }
    }
    let boundary = mesh.boundary_vertices();
    let pi = std::f64::consts::PI;
    let (mut vertex_err, mut k_abs) = (0.0, Vec::new());
    for (v, cs) in corners.iter().enumerate() {
        let base = if boundary[v] { pi } else { 2.0 * pi };
        let k = base - cs.iter().sum::<f64>();
        vertex_err += sum_error(cs.iter().copied(), e) + 2.0 * e * base + 2.0 * e * k.abs();
        k_abs.push(k.abs());
    }
    let chi = mesh.euler_characteristic() as f64;
    corner_err + vertex_err + sum_error(k_abs, e) + 4.0 * e * pi * chi.abs()
}

/// Surfaces for the position tests: the corpus (closed solids, tori, a disk).
fn surfaces() -> Vec<Surface> {
    corpus::standard()
}

fn holds(v: &Verdict) -> bool {
    matches!(v, Verdict::Holds { .. })
}

fn fails(v: &Verdict) -> bool {
    matches!(v, Verdict::Fails { .. })
}

/// T01 with the curvature of v0 moved so that `Σ K − 2πχ`, as the check computes it, is
/// `factor ×` B42 (recomputed here).
fn t01_at<T: Real>(s: &Surface, ctx: T::Ctx, factor: f64) -> Verdict {
    let l: Vec<T> = s.lengths(ctx);
    let mut k = curvature(&s.mesh, &l);
    let mut total = l[0].zero_like();
    for x in &k {
        total += x;
    }
    let r = (total - &gauss_bonnet_target::<T>(&s.mesh, ctx)).approx_f64();
    let lf: Vec<f64> = l.iter().map(Real::approx_f64).collect();
    let bound = b42(&s.mesh, &lf, eps_b40::<T>(ctx));
    let shift = k[0].lit(factor * bound - r);
    k[0] += &shift;
    verify_gauss_bonnet(&s.mesh, &l, &k, &Settings::default())
}

fn t01_positions<T: Real>(ctx: T::Ctx) {
    for s in surfaces() {
        let above = t01_at::<T>(&s, ctx, 1.5);
        let below = t01_at::<T>(&s, ctx, 0.5);
        assert!(
            fails(&above),
            "{} at {} bits: 1.5×B42 accepted: {above:?}",
            s.name,
            T::precision_bits(ctx)
        );
        assert!(
            holds(&below),
            "{} at {} bits: 0.5×B42 rejected: {below:?}",
            s.name,
            T::precision_bits(ctx)
        );
    }
}

#[test]
fn t01_tolerance_is_b42_perturbed_above_fails_below_holds() {
    t01_positions::<f64>(());
    t01_positions::<Dd>(());
    t01_positions::<Mpfr>(Precision::new(128).unwrap());
    // Negative control of the test itself: the unperturbed curvature holds, and a shift by
    // 1.5× a bound four times too small would pass (so the factor matters).
    let s = &surfaces()[0];
    assert!(holds(&t01_at::<f64>(s, (), 0.0)));
    assert!(holds(&t01_at::<f64>(s, (), 0.375)));
}

/// T05 with the diagonal entry `L[0][0]` moved so that row 0 sums to `factor ×` B41 of the
/// row (recomputed here); symmetry and semidefiniteness are unaffected.
fn t05_at<T: Real>(s: &Surface, ctx: T::Ctx, factor: f64) -> Verdict {
    let l: Vec<T> = s.lengths(ctx);
    let mut lap = cotan_laplacian(&s.mesh, &l);
    let mut sum = l[0].zero_like();
    for (_, v) in lap.row(0) {
        sum += v;
    }
    let bound = sum_error(lap.row(0).map(|(_, v)| v.approx_f64()), eps_b40::<T>(ctx));
    let shift = sum.lit(factor * bound - sum.approx_f64());
    if let Some(d) = lap.get_mut(0, 0) {
        *d += &shift;
    }
    verify_laplacian(&s.mesh, &lap, &Settings::default())
}

fn t05_positions<T: Real>(ctx: T::Ctx) {
    // Surfaces whose Laplacian is not the zero matrix (the one-vertex torus has only loops).
    for s in surfaces().iter().filter(|s| s.mesh.n_vertices() > 1) {
        let above = t05_at::<T>(s, ctx, 1.5);
        let below = t05_at::<T>(s, ctx, 0.5);
        assert!(fails(&above), "{}: 1.5×B41 accepted: {above:?}", s.name);
        assert!(!fails(&below), "{}: 0.5×B41 rejected: {below:?}", s.name);
    }
}

#[test]
fn t05_row_sum_tolerance_is_b41_perturbed_above_fails_below_holds() {
    t05_positions::<f64>(());
    t05_positions::<Dd>(());
    t05_positions::<Mpfr>(Precision::new(128).unwrap());
}

/// T07 with `E_D` moved so that `E_D − A − E_CR` is `factor ×` B48 (the library's bound).
fn t07_at<T: Real>(s: &Surface, ctx: T::Ctx, factor: f64) -> Option<Verdict> {
    use penner::geometry::cotan::cotan_weights;
    use penner::geometry::energy::{cauchy_riemann_energy, dirichlet_energy, signed_area};
    let l: Vec<T> = s.lengths(ctx);
    let f = penner::oracle::checks_extra::t07_map_at::<T>(s.mesh.n_vertices(), ctx);
    let w = cotan_weights(&s.mesh, &l);
    let mut terms = EnergyTerms {
        error_bound: energy_error_bound(&s.mesh, &l, &f),
        dirichlet: dirichlet_energy(&s.mesh, &w, &f)?,
        area: signed_area(&s.mesh, &f)?,
        cauchy_riemann: cauchy_riemann_energy(&s.mesh, &l, &f)?,
    };
    let d = (terms.dirichlet.clone() - &terms.area - &terms.cauchy_riemann).approx_f64();
    let shift = l[0].lit(factor * terms.error_bound - d);
    terms.dirichlet += &shift;
    Some(verify_conformal_energy(&terms, &Settings::default()))
}

#[test]
fn t07_tolerance_is_b48_perturbed_above_fails_below_holds() {
    let mut n = 0;
    for s in surfaces().iter().filter(|s| s.mesh.n_vertices() > 1) {
        for (bits, above, below) in [
            (53, t07_at::<f64>(s, (), 1.5), t07_at::<f64>(s, (), 0.5)),
            (106, t07_at::<Dd>(s, (), 1.5), t07_at::<Dd>(s, (), 0.5)),
        ] {
            let (Some(above), Some(below)) = (above, below) else {
                continue;
            };
            assert!(
                fails(&above),
                "{} at {bits} bits: 1.5×B48 accepted: {above:?}",
                s.name
            );
            assert!(
                holds(&below),
                "{} at {bits} bits: 0.5×B48 rejected: {below:?}",
                s.name
            );
            n += 1;
        }
    }
    assert!(n >= 10, "only {n} surfaces compared");
}

/// T27 on a hinge (one interior edge) with the cross-ratio side's length `ℓ_il` scaled by
/// `1 + δ`, δ chosen so `|s − log c|` is `factor ×` B64 at MPFR-`bits`.
fn t27_at(bits: u32, factor: f64) -> Verdict {
    let p = Precision::new(u64::from(bits)).unwrap();
    let mesh = crate::adversarial_gen::hinge_mesh();
    let l: Vec<Mpfr> = [3.0, 4.0, 5.0, 4.5, 3.5]
        .iter()
        .map(|&x| Mpfr::from_f64(x, p))
        .collect();
    let quad = |e| penner::predicates::delaunay::QuadEdges::of(&mesh, e);
    let q = mesh
        .edges()
        .find_map(quad)
        .expect("the hinge has an interior edge");
    let u = f64::from(bits).exp2().recip();
    let lnabs = |i: usize| l[i].ln().abs().approx_f64();
    let sum_abs: f64 = [q.edges.jk, q.edges.ki, q.edges.il, q.edges.lj]
        .iter()
        .map(|e| lnabs(e.idx()))
        .sum();
    let c = (l[q.edges.il.idx()].clone() * &l[q.edges.jk.idx()])
        / &(l[q.edges.ki.idx()].clone() * &l[q.edges.lj.idx()]);
    let tol = 8.0 * u * (sum_abs + c.ln().abs().approx_f64() + 1.0);
    // log((1+δ)c) − log c = log(1+δ) ≈ δ.
    let delta = factor * tol;
    let mut r = l.clone();
    let one = r[0].one_like();
    let k = q.edges.il.idx();
    r[k] = r[k].clone() * &(one + &r[k].lit(delta));
    verify_shear_log_cross_ratio(&mesh, &l, &r, &Settings::default())
}

#[test]
fn t27_tolerance_is_b64_perturbed_above_fails_below_holds() {
    for bits in [128, 256, 512] {
        let (above, below) = (t27_at(bits, 1.5), t27_at(bits, 0.5));
        assert!(fails(&above), "MPFR-{bits}: 1.5×B64 accepted: {above:?}");
        assert!(holds(&below), "MPFR-{bits}: 0.5×B64 rejected: {below:?}");
    }
}

// ---------------------------------------------------------------------------------------
// Measured: observed error / bound against an independent MPFR-1024 reference.

const REF_BITS: u64 = 1024;

fn mp(x: f64) -> Mpfr {
    Mpfr::from_f64(x, Precision::new(REF_BITS).unwrap())
}

fn mp_of<T: Real>(x: &T) -> Mpfr {
    let q = x.to_rational().expect("finite");
    Mpfr::from_rational(&q, Precision::new(REF_BITS).unwrap())
}

/// The angle opposite `a` by the law of cosines, `acos((b² + c² − a²)/(2bc))`, at 1024
/// bits: a different formula from the half-angle one under test.
fn angle_ref(a: f64, b: f64, c: f64) -> Mpfr {
    let (a, b, c) = (mp(a), mp(b), mp(c));
    let num = b.clone() * &b + &(c.clone() * &c) - &(a.clone() * &a);
    let den = b.clone() * &c * &b.lit(2.0);
    (num / &den).acos()
}

/// `cot α = (b² + c² − a²)/(4A)` with Heron's area at 1024 bits.
fn cot_ref(a: f64, b: f64, c: f64) -> Mpfr {
    let (a, b, c) = (mp(a), mp(b), mp(c));
    let s = (a.clone() + &b + &c) / &a.lit(2.0);
    let area = (s.clone() * &(s.clone() - &a) * &(s.clone() - &b) * &(s.clone() - &c)).sqrt();
    let num = b.clone() * &b + &(c.clone() * &c) - &(a.clone() * &a);
    num / &(area * &a.lit(4.0))
}

/// Random and adversarial triangles `(a, b, c)` (each a strict triangle in f64): random
/// shapes, needles, caps (angle near π, the side `a` opposite), near-right and
/// near-equilateral ones, with every side in every role.
fn triangles(n: usize, seed: u64) -> Vec<[f64; 3]> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut out = Vec::new();
    while out.len() < n {
        let t: [f64; 3] = match out.len() % 5 {
            0 => [
                rng.gen_range(0.1..1.0),
                rng.gen_range(0.1..1.0),
                rng.gen_range(0.1..1.0),
            ],
            1 => {
                let e = 10f64.powf(-rng.gen_range(1.0..12.0));
                [
                    e * rng.gen_range(0.5..1.0),
                    1.0,
                    1.0 + e * rng.gen_range(-0.4..0.4),
                ]
            }
            2 => {
                let e = 10f64.powf(-rng.gen_range(1.0..12.0));
                let b = rng.gen_range(0.2..0.8);
                [1.0, b, 1.0 - b + e]
            }
            3 => {
                let (b, c) = (rng.gen_range(0.5..1.0), rng.gen_range(0.5..1.0));
                [
                    (b * b + c * c).sqrt() * (1.0 + rng.gen_range(-1e-9..1e-9)),
                    b,
                    c,
                ]
            }
            _ => [
                1.0,
                1.0 + rng.gen_range(-1e-6..1e-6),
                1.0 + rng.gen_range(-1e-6..1e-6),
            ],
        };
        let [a, b, c] = t;
        if a < b + c && b < a + c && c < a + b {
            out.push(t);
            out.push([b, c, a]);
            out.push([c, a, b]);
        }
    }
    out
}

/// `(max ratio, count)` of observed error / bound for `kernel` at backend `T` against
/// `reference`; panics with the input when the bound is exceeded.
fn measure<T: Real>(
    ctx: T::Ctx,
    tris: &[[f64; 3]],
    what: &str,
    kernel: impl Fn(&T, &T, &T) -> T,
    reference: impl Fn(f64, f64, f64) -> Mpfr,
    bound: impl Fn(f64, f64, f64, f64) -> f64,
) -> (f64, usize) {
    let e = eps_b40::<T>(ctx);
    let (mut worst, mut n) = (0.0f64, 0usize);
    for &[a, b, c] in tris {
        let bnd = bound(a, b, c, e);
        if !bnd.is_finite() {
            continue;
        }
        let (ta, tb, tc) = (
            T::from_f64(a, ctx),
            T::from_f64(b, ctx),
            T::from_f64(c, ctx),
        );
        let got = mp_of(&kernel(&ta, &tb, &tc));
        let err = (got - &reference(a, b, c)).abs().approx_f64();
        assert!(
            err <= bnd,
            "{what} at {} bits: error {err:e} > bound {bnd:e} for sides ({a:e}, {b:e}, {c:e})",
            T::precision_bits(ctx)
        );
        worst = worst.max(err / bnd);
        n += 1;
    }
    (worst, n)
}

/// Floors of the largest observed error / bound over the default sample (a prefix of the
/// long one, so the maximum only grows with `PENNER_LONG`). Measured with ε = 16u: B40 f64
/// 1.56e-2 (≈ 1/64), dd 1.41e-3 (≈ 1/700); B44 f64 1.17e-2, dd 1.80e-3 — the bound allows 16u
/// per operation while f64 operations err by at most u and dd ones by a few u. Each floor is
/// half the measured value rounded down to a power of two, so a bound made 4× looser
/// (ε = 64u) falls below it and the test fails; a bound made tighter is caught by the
/// position tests of T01 and T05, which recompute B41/B42 with ε written out.
const B40_FLOOR_F64: f64 = 1.0 / 128.0;
const B40_FLOOR_DD: f64 = 1.0 / 1024.0;
const B44_FLOOR_F64: f64 = 1.0 / 128.0;
const B44_FLOOR_DD: f64 = 1.0 / 1024.0;

#[test]
fn b40_corner_angle_bound_holds_and_is_not_loose() {
    let tris = triangles(crate::support::cases(3000, 300_000), 40);
    let (r64, n64) = measure::<f64>(
        (),
        &tris,
        "B40",
        corner_angle,
        angle_ref,
        corner_angle_error,
    );
    let (rdd, ndd) = measure::<Dd>(
        (),
        &tris,
        "B40",
        corner_angle,
        angle_ref,
        corner_angle_error,
    );
    println!("[B40] max observed/bound: f64 {r64:.3e} over {n64}, dd {rdd:.3e} over {ndd}");
    assert!(
        n64 > tris.len() / 2 && ndd > tris.len() / 2,
        "most bounds finite"
    );
    assert!(r64 >= B40_FLOOR_F64, "B40 at f64 loose: max ratio {r64:e}");
    assert!(rdd >= B40_FLOOR_DD, "B40 at dd loose: max ratio {rdd:e}");
}

#[test]
fn b44_cot_bound_holds_and_is_not_loose() {
    let tris = triangles(crate::support::cases(3000, 300_000), 44);
    let (r64, n64) = measure::<f64>((), &tris, "B44", cot_opposite, cot_ref, cot_error);
    let (rdd, ndd) = measure::<Dd>((), &tris, "B44", cot_opposite, cot_ref, cot_error);
    println!("[B44] max observed/bound: f64 {r64:.3e} over {n64}, dd {rdd:.3e} over {ndd}");
    assert!(
        n64 > tris.len() / 2 && ndd > tris.len() / 2,
        "most bounds finite"
    );
    assert!(r64 >= B44_FLOOR_F64, "B44 at f64 loose: max ratio {r64:e}");
    assert!(rdd >= B44_FLOOR_DD, "B44 at dd loose: max ratio {rdd:e}");
}
