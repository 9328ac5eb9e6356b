//! Circle packings on the unit sphere from a maximal packing of the punctured sphere
//! (proofs/T11): the inverse stereographic projection from the south pole,
//! `σ⁻¹(x, y) = (2x, 2y, 1 − |z|²)/(1 + |z|²)`, maps the disk `|z − c| < ρ` to the cap
//! `{P ∈ S²: N·P > H}` with `N = (2c_x, 2c_y, 1 + ρ² − |c|²)` and `H = 1 + |c|² − ρ²`
//! (substitute `x = P_x/(1 + P_z)`, `|z|² = (1 − P_z)/(1 + P_z)` in `|z − c|² < ρ²`). The
//! punctured vertex gets the outside of the unit disk, the southern hemisphere
//! `N = (0, 0, −1)`, `H = 0`.
//!
//! Two caps `(N, H)`, `(N', H')` are tangent from outside when their inversive distance
//! `I = (HH' − N·N')/√((|N|² − H²)(|N'|² − H'²))` is 1 (`I = (cos a cos a' − cos δ)/(sin a
//! sin a')` for angular radii `a, a'` and centre angle `δ`, proofs/B96), a Möbius invariant.

use super::tangency::{check_precision, face_and_winding_violations, PackingVerdict, Tally};
use super::violation::Violation;
use crate::mesh::{Mesh, Vertex};
use crate::scalar::{Interval, Mpfr, Precision, Real};
use rug::Rational;

type I = Interval<Mpfr>;

/// A spherical cap `{P: n·P > h}` on the unit sphere, `|n| = 1` (up to rounding).
#[derive(Clone, Debug)]
pub struct Cap<T> {
    /// The unit normal: the cap's centre on the sphere.
    pub normal: [T; 3],
    /// `cos` of the angular radius.
    pub height: T,
}

/// The cap of the plane disk of centre `c` and radius `ρ` (module docs), normalised.
pub fn cap_of_disk<T: Real>(c: &[T; 2], rho: &T) -> Cap<T> {
    let one = rho.one_like();
    let cc = c[0].clone() * &c[0] + &(c[1].clone() * &c[1]);
    let rr = rho.clone() * rho;
    let n = [
        c[0].clone() * &one.lit(2.0),
        c[1].clone() * &one.lit(2.0),
        one.clone() + &rr - &cc,
    ];
    let h = one + &cc - &rr;
    let len = (n[0].clone() * &n[0] + &(n[1].clone() * &n[1]) + &(n[2].clone() * &n[2])).sqrt();
    Cap {
        normal: n.map(|x| x / &len),
        height: h / &len,
    }
}

/// The southern hemisphere: the cap of the outside of the unit disk.
pub fn outer_cap<T: Real>(like: &T) -> Cap<T> {
    Cap {
        normal: [like.zero_like(), like.zero_like(), -like.one_like()],
        height: like.zero_like(),
    }
}

/// A cap with exact rational normal and height (not necessarily unit).
#[derive(Clone, Debug, PartialEq)]
pub struct ExactCap {
    /// Normal `N`.
    pub normal: [Rational; 3],
    /// Height `H`.
    pub height: Rational,
}

fn dot(a: &[Rational; 3], b: &[Rational; 3]) -> Rational {
    Rational::from(&a[0] * &b[0]) + Rational::from(&a[1] * &b[1]) + Rational::from(&a[2] * &b[2])
}

fn det(a: &[Rational; 3], b: &[Rational; 3], c: &[Rational; 3]) -> Rational {
    let m = |x: &Rational, y: &Rational| Rational::from(x * y);
    m(&a[0], &(m(&b[1], &c[2]) - m(&b[2], &c[1]))) - m(&a[1], &(m(&b[0], &c[2]) - m(&b[2], &c[0])))
        + m(&a[2], &(m(&b[0], &c[1]) - m(&b[1], &c[0])))
}

/// Check that `caps` (one per vertex) realize the closed triangulation `mesh` as a packing
/// on the sphere within `ε`: every edge `|I − 1| ≤ ε` (inversive distance on `bits`-bit
/// MPFR enclosures), every face `det(N_a, N_b, N_c) > 0` (exact), and around every vertex
/// the neighbours' normals wind once (exact, measured in the plane orthogonal to `N_v`
/// from a coordinate axis). `Fails` only on a proved violation.
pub fn check_sphere_packing(
    mesh: &Mesh,
    caps: &[ExactCap],
    eps: &Rational,
    bits: u32,
) -> PackingVerdict {
    let prec = match check_precision(mesh, caps.len(), "caps", bits) {
        Ok(p) => p,
        Err(v) => return v,
    };
    let mut tally = Tally::new(I::from_rational(eps, prec));
    let mut proper = true;
    for (v, c) in caps.iter().enumerate() {
        // |N|² − H² > 0: a proper cap (neither empty nor the whole sphere).
        let s = dot(&c.normal, &c.normal) - Rational::from(&c.height * &c.height);
        if s <= 0 {
            tally.fail(format!("v{v}: not a proper cap (|N|² ≤ H²)"));
            proper = false;
        }
    }
    if !proper {
        return tally.verdict();
    }
    for (edge, d) in mesh.edges().zip(inversive_defects(mesh, caps, prec)) {
        let h = edge.halfedge();
        let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        tally.defect(
            &d,
            &format!("edge e{} (v{i}, v{j}) inversive distance", edge.idx()),
        );
    }
    tally.violations(orientation_violations(mesh, caps));
    tally.verdict()
}

/// Enclosures of `I_ij − 1` per edge of `mesh` (mesh edge order) at precision `p`, with
/// `I_ij = (H_i H_j − N_i·N_j)/√((|N_i|² − H_i²)(|N_j|² − H_j²))` (module docs,
/// proofs/B96): numerator and radicand exact in ℚ, then enclosed. An improper cap
/// (`|N|² ≤ H²`) gives an invalid enclosure.
pub fn inversive_defects(mesh: &Mesh, caps: &[ExactCap], p: Precision) -> Vec<I> {
    let spread: Vec<Rational> = caps
        .iter()
        .map(|c| dot(&c.normal, &c.normal) - Rational::from(&c.height * &c.height))
        .collect();
    mesh.edges()
        .map(|edge| {
            let h = edge.halfedge();
            let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
            if spread[i] <= 0 || spread[j] <= 0 {
                return I::invalid(p);
            }
            let num = Rational::from(&caps[i].height * &caps[j].height)
                - dot(&caps[i].normal, &caps[j].normal);
            let den = Rational::from(&spread[i] * &spread[j]);
            I::from_rational(&num, p) / &I::from_rational(&den, p).sqrt() - &I::from_f64(1.0, p)
        })
        .collect()
}

/// Faces whose cap centres are not positively oriented (`det(N_a, N_b, N_c) ≤ 0`, exact)
/// and, when there is none, vertices around which the neighbours' normals do not wind
/// exactly once ([`winding`], exact).
pub fn orientation_violations(mesh: &Mesh, caps: &[ExactCap]) -> Vec<Violation> {
    face_and_winding_violations(
        mesh,
        |[a, b, c]| det(&caps[a].normal, &caps[b].normal, &caps[c].normal) > 0,
        |v| Some(winding(mesh, v, caps)),
    )
}

/// Winding of the neighbours' normals around `N_v` (counter-clockwise seen from outside),
/// counted as turns from the lower into the upper half of the plane orthogonal to `N_v`,
/// the half-planes split by the projection of the coordinate axis `R` least aligned with
/// `N_v`: upper when `det(N_v, R, N_k) > 0`, or `= 0` with a positive component along `R`.
fn winding(mesh: &Mesh, v: Vertex, caps: &[ExactCap]) -> usize {
    let nv = &caps[v.idx()].normal;
    let axis = (0..3)
        .min_by(|&a, &b| nv[a].clone().abs().cmp(&nv[b].clone().abs()))
        .unwrap_or(0);
    let mut r: [Rational; 3] = [Rational::new(), Rational::new(), Rational::new()];
    r[axis] = Rational::from(1);
    let nn = dot(nv, nv);
    let rn = dot(&r, nv);
    let upper = |nk: &[Rational; 3]| {
        let s = det(nv, &r, nk);
        s > 0 || (s == 0 && Rational::from(&nn * &dot(&r, nk)) > Rational::from(&rn * &dot(nv, nk)))
    };
    let mut ups: Vec<bool> = mesh
        .outgoing(v)
        .map(|h| upper(&caps[mesh.tip(h).idx()].normal))
        .collect();
    ups.reverse();
    let n = ups.len();
    (0..n).filter(|&k| !ups[k] && ups[(k + 1) % n]).count()
}

/// Exact caps from computed ones (any point backend).
pub fn exact_caps<T: Real>(caps: &[Cap<T>]) -> Option<Vec<ExactCap>> {
    caps.iter()
        .map(|c| {
            Some(ExactCap {
                normal: [
                    c.normal[0].to_rational()?,
                    c.normal[1].to_rational()?,
                    c.normal[2].to_rational()?,
                ],
                height: c.height.to_rational()?,
            })
        })
        .collect()
}

/// Tests in which one condition of B96 (3) decides the verdict (proofs/B96, "Terms").
#[cfg(test)]
mod terms {
    use super::*;

    /// A bipyramid: north `v0`, rim `v1 … vk`, south `v(k+1)`, faces `(v0, vi, vi+1)` and
    /// `(v(k+1), vi+1, vi)`; normals `±e_z` at the poles and, on the rim, `(1 + i/k)` times
    /// the quarter turn `turns·4i/k` of `e_x` in the equator (exact).
    fn bipyramid(k: u32, turns: u32) -> (Mesh, Vec<ExactCap>) {
        let south = k + 1;
        let mut faces: Vec<[u32; 3]> = (1..=k).map(|i| [0, i, i % k + 1]).collect();
        faces.extend((1..=k).map(|i| [south, i % k + 1, i]));
        let mesh = Mesh::from_faces(k + 2, &faces).expect("a bipyramid");
        let cap = |n: [i64; 3], s: Rational| ExactCap {
            normal: n.map(|x| Rational::from(&s * x)),
            height: Rational::new(),
        };
        let quarter = [[1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]];
        let mut caps = vec![cap([0, 0, 1], Rational::from(1))];
        for i in 0..k {
            let q = quarter[((turns * 4 * i / k) % 4) as usize];
            caps.push(cap(q, Rational::from((k + i, k))));
        }
        caps.push(cap([0, 0, -1], Rational::from(1)));
        (mesh, caps)
    }

    /// B96 term "the neighbours of every vertex wind once": a bipyramid whose faces are all
    /// positively oriented but whose rim goes around the poles twice is refuted at the poles
    /// by the winding alone; the one whose rim goes around once is not.
    #[test]
    fn term_b96_neighbours_of_every_vertex_wind_once() {
        let (mesh, caps) = bipyramid(8, 2);
        let v = orientation_violations(&mesh, &caps);
        let at: Vec<&str> = v.iter().map(|w| w.element.as_str()).collect();
        assert_eq!(at, ["v0", "v9"], "{v:?}");
        assert!(v.iter().all(|w| w.detail.contains("wind 2 times")), "{v:?}");
        let (mesh, caps) = bipyramid(4, 1);
        assert!(orientation_violations(&mesh, &caps).is_empty());
    }
}
