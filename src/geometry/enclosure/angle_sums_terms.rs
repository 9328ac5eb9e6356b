//! B33's terms, one deciding test each (proofs/B33, "Terms"): the quarter count, the
//! fallback where a running product meets an axis or a face is not strict, the choice of
//! the last rotation, and the outward rounding of the arctangent and of `mπ/2`.

use super::*;
use crate::scalar::Precision;

fn prec(bits: u64) -> Precision {
    Precision::new(bits).expect("precision")
}

/// A fan around apex 0 with rim vertices `1..=n`, faces `[0, i, i+1]` (cyclically), unit
/// spokes and rim edges `2·sin(α_i/2)` rounded to binary64: apex corners of about `α_i`.
fn fan(apex: &[f64]) -> (Mesh, Vec<f64>) {
    let n = apex.len() as u32;
    let faces: Vec<[u32; 3]> = (0..n).map(|i| [0, 1 + i, 1 + (i + 1) % n]).collect();
    let mesh = Mesh::from_faces(n + 1, &faces).expect("valid fan");
    let mut len = vec![1.0; mesh.n_edges()];
    for e in mesh.edges() {
        let h = e.halfedge();
        let (a, b) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        if a != 0 && b != 0 {
            let (lo, hi) = (a.min(b), a.max(b));
            let i = if hi - lo == 1 { lo - 1 } else { hi - 1 };
            len[e.idx()] = 2.0 * (apex[i] / 2.0).sin();
        }
    }
    (mesh, len)
}

/// The apex angle of the binary64 lengths: the sum of its corner angles at 512 bits (the
/// per-corner formula, a different computation from the product of directions).
fn reference_apex(mesh: &Mesh, len: &[f64]) -> Mpfr {
    let p = prec(512);
    let mut sum = Mpfr::from_f64(0.0, p);
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        for i in 0..3 {
            if mesh.tail(hs[(i + 2) % 3]).idx() == 0 {
                let l = |k: usize| Mpfr::from_f64(len[hs[(i + k) % 3].edge().idx()], p);
                sum += &corner_angle(&l(0), &l(1), &l(2));
            }
        }
    }
    sum
}

fn enclose(mesh: &Mesh, len: &[f64], bits: u64) -> EnclosedConeAngles {
    let l: Vec<I> = len.iter().map(|&x| I::from_f64(x, prec(bits))).collect();
    enclose_cone_angles(mesh, &l)
}

fn contains(x: &I, r: &Mpfr) -> bool {
    x.lo().as_float() <= r.as_float() && r.as_float() <= x.hi().as_float()
}

/// Term "quarter count": apex angles beyond one and two full turns (11 corners of 0.9,
/// 16 of 0.7: θ ≈ 9.9 and 11.2) are enclosed by the product path itself (no fallback), and
/// the enclosure holds the per-corner reference. Without the count the argument is only
/// known modulo 2π and the enclosure misses by whole turns.
#[test]
fn term_b33_quarter_count_decides_apex_angles_beyond_a_full_turn() {
    for (k, a) in [(11, 0.9), (16, 0.7), (7, 1.3)] {
        let (m, l) = fan(&vec![a; k]);
        let e = enclose(&m, &l, 128);
        let r = reference_apex(&m, &l);
        assert!(!e.fallback.contains(&0), "{k} corners of {a}: fell back");
        assert!(
            contains(&e.theta[0], &r),
            "{k} corners of {a}: {:?}",
            e.theta[0]
        );
        assert!(e.theta[0].width_f64() < 1e-30, "{k}×{a}: width");
        assert!(r.as_float().to_f64() > 2.0 * std::f64::consts::PI);
    }
}

/// Term "last corner": `m = Q_{n−1} + 1` or `Q_{n−1} + 2`, the first leaving the rotated
/// box in the open right half-plane. Three corners of `α` for `α` from 0.2 to 3.0: the
/// last corner ends in every position relative to the quarter before it, so both
/// rotations are needed (a rotation tried alone, or the other order, misses some `α`).
#[test]
fn term_b33_last_rotation_is_the_one_with_a_positive_real_part() {
    let (mut first, mut second) = (0, 0);
    let quarter = std::f64::consts::FRAC_PI_2;
    for k in 3..=6 {
        for j in 0..57 {
            let a = 0.2 + 0.05 * f64::from(j) + 1e-3;
            let (m, l) = fan(&vec![a; k]);
            let e = enclose(&m, &l, 128);
            let r = reference_apex(&m, &l);
            assert!(contains(&e.theta[0], &r), "{k}×{a}: {:?}", e.theta[0]);
            // Every partial sum off the axes by 10⁻⁴: the count is certified, so the
            // product path must decide (a wrong quarter or rotation falls back instead).
            let off_axes = (1..k).all(|i| {
                let t = i as f64 * a / quarter;
                (t - t.round()).abs() > 1e-4
            });
            if off_axes {
                assert!(!e.fallback.contains(&0), "{k}×{a}: fell back");
            }
            // Which rotation the reference needs: Q_{n−1} = ⌊(k−1)α/(π/2)⌋, and
            // m = Q_{n−1} + 1 exactly when θ − (Q_{n−1}+1)π/2 < π/2.
            let q = ((k - 1) as f64 * a / quarter).floor();
            if r.as_float().to_f64() - (q + 1.0) * quarter < quarter {
                first += 1;
            } else {
                second += 1;
            }
        }
    }
    assert!(first >= 40 && second >= 40, "{first} {second}");
}

/// Term "not guessed on an axis": apex corners of exactly π/2, π/2, π/2 (3-4-5 right
/// triangles, exact in binary64) and then 2: the first three running products lie on the
/// axes, so their quarters are not certified and the apex takes the per-corner fallback,
/// which holds `3π/2 + 2`. Counting on from a stale quarter would miss a whole turn (the
/// three unknown steps span 3π/2, the fourth closes past 2π).
#[test]
fn term_b33_products_on_an_axis_fall_back() {
    let faces = [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]];
    let m = Mesh::from_faces(5, &faces).expect("fan");
    let spoke = [3.0, 4.0, 3.0, 4.0];
    let mut len = vec![0.0; m.n_edges()];
    for e in m.edges() {
        let h = e.halfedge();
        let (a, b) = (m.tail(h).idx(), m.tip(h).idx());
        len[e.idx()] = match (a.min(b), a.max(b)) {
            (0, v) => spoke[v - 1],
            (1, 4) => (25.0 - 24.0 * 2f64.cos()).sqrt(),
            _ => 5.0,
        };
    }
    let e = enclose(&m, &len, 128);
    assert!(e.fallback.contains(&0), "the apex must fall back");
    let r = reference_apex(&m, &len);
    assert!(r.as_float().to_f64() > 6.7, "3π/2 + 2");
    assert!(contains(&e.theta[0], &r), "{:?}", e.theta[0]);
    // Control: the same fan with apex corners off the axes takes the product path.
    let (m, l) = fan(&[1.4, 1.7, 1.6, 1.5]);
    assert!(!enclose(&m, &l, 128).fallback.contains(&0));
}

/// Term "strict faces": a face with sides `1, 1, 2` (degenerate) is not a certified strict
/// triangle, so its vertices take the fallback, whose enclosure holds the exact angles
/// (`0, 0, π`) or is invalid; never a narrow product-path value.
#[test]
fn term_b33_a_degenerate_face_is_not_taken_by_the_product_path() {
    let m = Mesh::from_faces(3, &[[0, 1, 2]]).expect("triangle");
    let len = vec![1.0, 1.0, 2.0];
    let e = enclose(&m, &len, 128);
    assert_eq!(e.fallback.len(), 3, "{:?}", e.fallback);
    // Control: sides 1, 1, 1.5 are strict and take the product path at every corner.
    assert!(enclose(&m, &[1.0, 1.0, 1.5], 128).fallback.is_empty());
}

/// A winding state with the running product `x + iy` (points) and the quarter before the
/// last corner.
fn winding(x: f64, y: f64, quarter_before_last: i64, bits: u32) -> Winding {
    let pt = |v: f64| Bounds {
        lo: Float::with_val(bits, v),
        hi: Float::with_val(bits, v),
    };
    Winding {
        x: pt(x),
        y: pt(y),
        quarter: quarter_before_last,
        quarter_before_last,
        quadrant_known: true,
        corners: 2,
        failed: false,
    }
}

/// Term "atan rounded outward": for the exact point `1 + i/2` and the identity rotation
/// (`m = 0`, `mπ/2 = 0` exactly) the result is `[atan↓(1/2), atan↑(1/2)]`, which holds the
/// 512-bit `atan(1/2)` (irrational) strictly inside at every precision tried; a bound
/// rounded to nearest or the wrong way leaves it outside.
#[test]
fn term_b33_arctangent_rounded_outward() {
    let reference = Float::with_val(512, 0.5).atan();
    for bits in [24, 53, 64, 100, 128] {
        let t = unwrap_final(&winding(1.0, 0.5, -1, bits), &pi_bounds(bits), bits)
            .expect("right half-plane");
        assert!(t.lo().as_float() < &reference && &reference < t.hi().as_float());
    }
}

/// Term "`mπ/2` rounded outward": for the exact points `−1` (m = 2) and `−i` (m = 3) the
/// arctangent is 0 exactly, so the result is the enclosure of `π` or `3π/2` alone; it
/// holds the 512-bit value at every precision tried (bounds of `π` rounded outward, and
/// `3π↓` rounded down, `3π↑` up).
#[test]
fn term_b33_quarter_turns_rounded_outward() {
    let pi = Float::with_val(512, Constant::Pi);
    for bits in 20..140 {
        let t = unwrap_final(&winding(-1.0, 0.0, 1, bits), &pi_bounds(bits), bits).expect("m = 2");
        assert!(
            t.lo().as_float() < &pi && &pi < t.hi().as_float(),
            "π at {bits}"
        );
        let three_halves = Float::with_val(512, &pi * 3u32) / 2u32;
        let t = unwrap_final(&winding(0.0, -1.0, 2, bits), &pi_bounds(bits), bits).expect("m = 3");
        assert!(
            t.lo().as_float() < &three_halves && &three_halves < t.hi().as_float(),
            "3π/2 at {bits}"
        );
    }
}
