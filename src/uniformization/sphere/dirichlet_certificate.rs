//! An a-posteriori proof for the disk problem of the sphere target ([`super::sphere`],
//! B74): the argument of B71 with the Dirichlet vertices in place of the grounded one, and
//! one more test that makes the polyhedron convex. proof: B76
//!
//! On the box `B` (free vertices `|u'_i − u_i| ≤ r`; at each link vertex `a` an enclosure of
//! the exact Dirichlet value `w_a = −2 log ℓ_{a v∞}`) the check establishes in
//! `Interval<Mpfr>`:
//!
//! 1. every face of the final disk triangulation is a strict triangle and every interior
//!    edge Delaunay on `B` (one Penner cell);
//! 2. at every link vertex the disk's angle sum is `≤ π` on `B` (the boundary polygon is
//!    convex: the edges from the pole are Delaunay, B74 "Convexity");
//! 3. `H(u') ⪰ μI` on `B` for the Hessian on the free vertices (`μ = λ_min(H_mid) −
//!    ‖H_rad‖_∞`, verified Cholesky, B70), and `‖Θ − θ(u)‖₂ ≤ γ` on the free vertices.
//!
//! If `γ < μ·r`, the exact disk problem has a solution `u*` with `‖u* − u‖₂ ≤ γ/μ` whose
//! flat disk is a Delaunay triangulation of a convex polygon, i.e. the inscribed polyhedron
//! of `u*` is convex and discretely conformally equivalent to the input (B74, B76).

use super::ball_argument::{ball_outcome, certified_nonnegative};
use super::certificate::{CertificateOutcome, I};
use super::dirichlet::free_index;
use super::refine::{carry_lengths, carry_lengths_from, scaled};
use super::sphere::{Disk, SphereUniformization};
use crate::geometry::cone_angles::cone_angles;
use crate::geometry::laplacian::cotan_laplacian;
use crate::mesh::{Edge, Mesh, Vertex};
use crate::predicates::delaunay::{enclose_p, QuadEdges};
use crate::scalar::{Precision, Real, Sign};
use rug::Rational;

/// The data of a disk certificate, all exact: the disk `D = T₀ − star(v∞)` with its
/// binary64 lengths, the pole lengths `ℓ_{a v∞}` of the link vertices (which fix
/// `w_a = −2 log ℓ_{a v∞}`), the targets `Θ_i/π` of the free vertices, the Ptolemy flips of
/// `D`, the free scale factors and the radius.
#[derive(Clone, Debug)]
pub struct DiskCertificateData {
    /// The disk before the flips.
    pub disk: Mesh,
    /// Its lengths `ℓ⁰`.
    pub lengths: Vec<f64>,
    /// `ℓ⁰_{a v∞}` at link vertices, `None` at free vertices.
    pub pole_length: Vec<Option<f64>>,
    /// `Θ_i/π` per vertex (read at free vertices).
    pub over_pi: Vec<Rational>,
    /// Ptolemy flips of the disk, in order.
    pub flip_sequence: Vec<Edge>,
    /// The scale factors (read at free vertices).
    pub u: Vec<Rational>,
    /// The radius of the box.
    pub radius: Rational,
}

impl DiskMetric {
    /// The metric of `sol.disk` from enclosures `l0` of the lengths of `sol`'s `T₀`: `l0`
    /// carried by Ptolemy flips through `sol.flip_sequence[..sol.star_prefix]` (the disk
    /// flips and the flips at the pole before the last disk problem, B93; none when no
    /// edge at the pole flipped), then [`DiskMetric::of`]. Each Ptolemy length is
    /// `(ac + bd)/e` of positive enclosures, so the result encloses the carried exact
    /// lengths of every metric in `l0`. `Err(reason)` when the flips do not replay.
    /// proof: B93, B90
    pub fn of_solution(sol: &SphereUniformization, l0: Vec<I>) -> Result<DiskMetric, String> {
        let prefix = &sol.flip_sequence[..sol.star_prefix.min(sol.flip_sequence.len())];
        let (t, l) =
            carry_lengths_from(&sol.initial_mesh, l0, prefix).map_err(|e| e.to_string())?;
        Ok(DiskMetric::of(&t, &l, &sol.disk, Vertex(sol.pole)))
    }

    /// The metric of `disk` (of `t0` at `pole`, [`super::sphere::disk_of`]) from the
    /// lengths `l0` of `t0`: the disk's edges through its edge map, the pole lengths per
    /// link vertex.
    pub fn of(t0: &Mesh, l0: &[I], disk: &Disk, pole: Vertex) -> DiskMetric {
        let mut slot = vec![None; t0.n_vertices()];
        for (k, &v) in disk.vertex.iter().enumerate() {
            slot[v as usize] = Some(k);
        }
        let mut pole_length = vec![None; disk.vertex.len()];
        for h in t0.outgoing(pole) {
            if let Some(k) = slot[t0.tip(h).idx()] {
                pole_length[k] = Some(l0[h.edge().idx()].clone());
            }
        }
        DiskMetric {
            lengths: disk.edge.iter().map(|e| l0[e.idx()].clone()).collect(),
            pole_length,
        }
    }
}

/// Enclosures of the disk's metric that replace the binary64 `lengths` and
/// `pole_length` of a [`DiskCertificateData`] in every enclosure (e.g. the exact input
/// metric replayed to `T₀`, B73): a `Holds` is then a proof for every metric they enclose.
#[derive(Clone, Debug)]
pub struct DiskMetric {
    /// Enclosures of the disk's lengths `ℓ⁰` (before the flips).
    pub lengths: Vec<I>,
    /// Enclosures of `ℓ⁰_{a v∞}` at link vertices, `None` at free vertices.
    pub pole_length: Vec<Option<I>>,
}

/// Check a disk certificate at `bits` of interval precision (steps 1–3 of the module
/// documentation). Malformed data (counts, a flip that does not replay, bits out of range)
/// is `Undecided` with the reason: this check never claims that no solution exists.
/// proof: B76
pub fn check_disk_certificate(data: &DiskCertificateData, bits: u32) -> CertificateOutcome {
    check_disk_certificate_on(data, None, bits)
}

/// [`check_disk_certificate`] for the metric enclosed by `metric` (see [`DiskMetric`]);
/// its enclosures must have been computed at `bits`. proof: B76, B73
#[allow(clippy::too_many_lines)] // the three steps of B76, read top to bottom
pub fn check_disk_certificate_on(
    data: &DiskCertificateData,
    metric: Option<&DiskMetric>,
    bits: u32,
) -> CertificateOutcome {
    let undecided = |reason: String| CertificateOutcome::Undecided { reason };
    let n = data.disk.n_vertices();
    if data.pole_length.len() != n || data.over_pi.len() != n || data.u.len() != n {
        return undecided("one pole length, target and scale factor per vertex expected".into());
    }
    if data.lengths.len() != data.disk.n_edges() {
        return undecided("one length per edge expected".into());
    }
    if data.radius <= 0 {
        return undecided("the radius is not positive".into());
    }
    let Ok(prec) = Precision::new(u64::from(bits)) else {
        return undecided(format!("precision of {bits} bits out of range"));
    };
    let mut pole_length = Vec::with_capacity(n);
    for (v, l) in data.pole_length.iter().enumerate() {
        let Some(l) = l else {
            pole_length.push(None);
            continue;
        };
        if !(l.is_finite() && *l > 0.0) {
            return undecided(format!("pole length of v{v} is not positive"));
        }
        pole_length.push(Some(I::from_f64(*l, prec)));
    }
    let carried = match metric {
        None => carry_lengths::<I>(&data.disk, &data.lengths, &data.flip_sequence, prec),
        Some(m) => {
            let same_link = m.pole_length.len() == n
                && m.pole_length
                    .iter()
                    .zip(&data.pole_length)
                    .all(|(a, b)| a.is_some() == b.is_some());
            if m.lengths.len() != data.disk.n_edges() || !same_link {
                return undecided(
                    "the enclosed metric does not match the disk (edges or link vertices)".into(),
                );
            }
            pole_length.clone_from(&m.pole_length);
            carry_lengths_from(&data.disk, m.lengths.clone(), &data.flip_sequence)
        }
    };
    let Ok((mesh, base)) = carried else {
        return undecided("the flip sequence does not replay on the disk".into());
    };
    let markers: Vec<Option<f64>> = data.pole_length.iter().map(|l| l.map(|_| 0.0)).collect();
    let (free, free_idx) = free_index(&markers);
    let mut point = Vec::with_capacity(n);
    let mut boxed = Vec::with_capacity(n);
    for (v, pl) in pole_length.iter().enumerate() {
        if let Some(l) = pl {
            if l.sign() != Some(Sign::Positive) {
                return undecided(format!("pole length of v{v} is not enclosed as positive"));
            }
            let w = l.clone().ln() * &I::from_f64(-2.0, prec);
            point.push(w.clone());
            boxed.push(w);
        } else {
            let q = &data.u[v];
            let lo = I::from_rational(&Rational::from(q - &data.radius), prec);
            let hi = I::from_rational(&Rational::from(q + &data.radius), prec);
            point.push(I::from_rational(q, prec));
            boxed.push(I::new(lo.lo().clone(), hi.hi().clone()));
        }
    }
    // 1. One Penner cell on the box.
    let lb = scaled(&mesh, &base, &boxed);
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_halfedges(f).map(|h| &lb[h.edge().idx()]);
        for (x, y, z) in [(a, b, c), (b, c, a), (c, a, b)] {
            if (y.clone() + z - x).sign() != Some(Sign::Positive) {
                return undecided(format!(
                    "disk face f{} not certified a strict triangle on the whole box",
                    f.0
                ));
            }
        }
    }
    for e in mesh.edges() {
        let Some(q) = QuadEdges::of(&mesh, e) else {
            continue;
        };
        if !certified_nonnegative(&enclose_p(&q.lengths(&lb).map(Clone::clone).to_array())) {
            return undecided(format!(
                "disk edge e{} not certified Delaunay on the whole box",
                e.0
            ));
        }
    }
    // 2. A convex boundary: θ_a ≤ π at every link vertex on the box.
    let pi = I::pi(prec);
    let theta_box = cone_angles(&mesh, &lb);
    for (v, theta_v) in theta_box.iter().enumerate() {
        if data.pole_length[v].is_some() && !certified_nonnegative(&(pi.clone() - theta_v)) {
            return undecided(format!(
                "the disk's angle at its link vertex {v} (disk numbering: the surface's, one less after the pole) is not certified ≤ π on the whole box"
            ));
        }
    }
    if free.is_empty() {
        // No unknowns: the box is the exact metric itself, already checked.
        return CertificateOutcome::Holds {
            distance: 0.0,
            mu: f64::INFINITY,
            residual: 0.0,
        };
    }
    // 3. The Hessian over the box and the residual at u (B71's ball argument).
    let laplacian = cotan_laplacian(&mesh, &lb);
    if let Some((i, j, _)) = laplacian.entries().find(|(_, _, w)| !w.is_valid()) {
        return undecided(format!("cotan Laplacian entry ({i}, {j}) not enclosed"));
    }
    let lp = scaled(&mesh, &base, &point);
    let theta = cone_angles(&mesh, &lp);
    let mut residual = Vec::with_capacity(free.len());
    for &v in &free {
        let g = I::from_rational(&data.over_pi[v], prec) * &pi - &theta[v];
        if !g.is_valid() {
            return undecided(format!("angle sum at v{v} not enclosed"));
        }
        residual.push(g);
    }
    let approx: Vec<f64> = lb.iter().map(Real::approx_f64).collect();
    ball_outcome(
        &mesh,
        &approx,
        laplacian.entries(),
        &free_idx,
        &residual,
        &data.radius,
        prec,
    )
}

/// The certificate data of a solved sphere uniformization at the scale factors `u` (one
/// per disk vertex, exact) and radius `radius`.
pub fn disk_data(
    sol: &SphereUniformization,
    u: Vec<Rational>,
    radius: Rational,
) -> DiskCertificateData {
    DiskCertificateData {
        disk: sol.disk.mesh.clone(),
        lengths: sol.disk.lengths.clone(),
        pole_length: sol.disk.pole_length.clone(),
        over_pi: vec![Rational::from(2); sol.disk.mesh.n_vertices()],
        flip_sequence: sol.solution.flip_sequence.clone(),
        u,
        radius,
    }
}

/// Certify the disk problem near the `f64` solution of `sol` ([`certify_disk_near`] at
/// its `u` and residual, at least `4ε`, on the binary64 lengths).
pub fn certify_disk(
    sol: &SphereUniformization,
    bits: u32,
) -> (DiskCertificateData, CertificateOutcome) {
    let u: Vec<Rational> = sol
        .solution
        .u
        .iter()
        .map(|&x| Rational::from_f64(x).unwrap_or_default())
        .collect();
    let residual = sol.solution.residual_max.max(4.0 * f64::EPSILON);
    certify_disk_near(sol, None, &u, residual, bits)
}

/// Certify the disk problem of `sol` at the scale factors `u` (exact, one per disk vertex,
/// read at the free ones), whose `max |Θ − θ|` was estimated as `residual_max`, for the
/// metric `metric` (`None`: the binary64 lengths of `T₀`, carried through the flips at the
/// pole in intervals by [`DiskMetric::of_solution`] when there are any): boxes of radius
/// `10⁶`, `10³`, `10` and `10¹⁰` times `residual_max·√n` (at least `2^(10 − bits)` times
/// those factors) around `u`; the first outcome that holds, or the last, with its data.
/// (The factor `10` serves nearly degenerate triangles, such as the new triangle of a flip
/// at the pole near a tie, B93, whose Hessian varies too fast for the larger boxes.)
pub fn certify_disk_near(
    sol: &SphereUniformization,
    metric: Option<&DiskMetric>,
    u: &[Rational],
    residual_max: f64,
    bits: u32,
) -> (DiskCertificateData, CertificateOutcome) {
    let own = match (metric, Precision::new(u64::from(bits))) {
        (None, Ok(prec)) if sol.star_prefix > 0 => {
            let l0 = sol
                .initial_lengths
                .iter()
                .map(|&x| I::from_f64(x, prec))
                .collect();
            match DiskMetric::of_solution(sol, l0) {
                Ok(m) => Some(m),
                Err(reason) => {
                    let data = disk_data(sol, u.to_vec(), Rational::from(1));
                    return (data, CertificateOutcome::Undecided { reason });
                }
            }
        }
        _ => None,
    };
    let metric = metric.or(own.as_ref());
    let n = u.len().max(1) as f64;
    let floor = 2f64.powi(-(bits.min(1000) as i32) + 10);
    let estimate = (residual_max * n.sqrt()).max(floor);
    let mut last = None;
    for factor in [1e6, 1e3, 1e1, 1e10] {
        let radius = Rational::from_f64(estimate * factor).unwrap_or_else(|| Rational::from(1));
        let data = disk_data(sol, u.to_vec(), radius);
        let outcome = check_disk_certificate_on(&data, metric, bits);
        let done = matches!(outcome, CertificateOutcome::Holds { .. });
        last = Some((data, outcome));
        if done {
            break;
        }
    }
    last.expect("four attempts")
}

/// Inputs in which one term of B76 decides the verdict (proofs/B76, **Terms**): disks
/// whose vertices are all link vertices (pole lengths 1, so `w = 0` exactly and the box is
/// the metric itself), where steps 1 and 2 alone decide.
#[cfg(test)]
mod terms {
    use super::*;

    const BITS: u32 = 128;

    /// The disk `[[0, 1, 3], [1, 2, 3]]` (interior edge 1–3) with the binary64 lengths of
    /// the planar points `p`, every vertex a link vertex.
    fn quad(p: [[f64; 2]; 4]) -> DiskCertificateData {
        quad_with(p, [[0, 1, 3], [1, 2, 3]])
    }

    fn quad_with(p: [[f64; 2]; 4], faces: [[u32; 3]; 2]) -> DiskCertificateData {
        let disk = Mesh::from_faces(4, &faces).expect("a disk of two triangles");
        let lengths = disk
            .edges()
            .map(|e| {
                let h = e.halfedge();
                let [a, b] = [disk.tail(h), disk.tip(h)].map(|v| p[v.idx()]);
                (a[0] - b[0]).hypot(a[1] - b[1])
            })
            .collect();
        DiskCertificateData {
            disk,
            lengths,
            pole_length: vec![Some(1.0); 4],
            over_pi: vec![Rational::from(2); 4],
            flip_sequence: Vec::new(),
            u: vec![Rational::new(); 4],
            radius: Rational::from(1),
        }
    }

    fn reason(outcome: CertificateOutcome) -> String {
        match outcome {
            CertificateOutcome::Undecided { reason } => reason,
            other @ CertificateOutcome::Holds { .. } => panic!("expected undecided, got {other:?}"),
        }
    }

    /// B76 step 2, `π − θ_a ≥ 0` at link vertices: a dart whose vertex 1 is reflex
    /// (`θ_1 = 2·(π/2 + atan 0.2) ≈ 1.13π`, closed form) while its interior edge is Delaunay
    /// (opposite angles `2·(π/4 − atan 0.2) < π`) and both faces strict. Without step 2
    /// the disk would certify a non-convex polygon, i.e. a non-convex polyhedron (B74).
    /// Control: vertex 1 mirrored to the convex side holds.
    #[test]
    fn term_b76_link_angles_at_most_pi_decide() {
        let dart = quad([[-1.0, 0.0], [0.0, 0.2], [1.0, 0.0], [0.0, 1.0]]);
        let why = reason(check_disk_certificate(&dart, BITS));
        assert!(why.contains("link vertex 1"), "{why}");
        let convex = quad([[-1.0, 0.0], [0.0, -0.2], [1.0, 0.0], [0.0, 1.0]]);
        let outcome = check_disk_certificate(&convex, BITS);
        assert!(
            matches!(outcome, CertificateOutcome::Holds { distance, .. } if distance == 0.0),
            "{outcome:?}"
        );
    }

    /// B76 step 1, every interior edge Delaunay (`P ≥ 0`, B60): a kite `(±0.3, 0)`,
    /// `(0, ±1)` split by its long diagonal 1–3, whose opposite angles are each
    /// `2·atan(1/0.3) > π/2` (closed form), so the edge is not Delaunay; every link angle
    /// is below π. The same kite split by its short diagonal 0–2 holds.
    #[test]
    fn term_b76_interior_edges_delaunay_decide() {
        let kite = [[-0.3, 0.0], [0.0, -1.0], [0.3, 0.0], [0.0, 1.0]];
        let why = reason(check_disk_certificate(&quad(kite), BITS));
        assert!(why.contains("not certified Delaunay"), "{why}");
        let short = quad_with(kite, [[0, 1, 2], [0, 2, 3]]);
        let outcome = check_disk_certificate(&short, BITS);
        assert!(
            matches!(outcome, CertificateOutcome::Holds { .. }),
            "{outcome:?}"
        );
    }

    /// B76 step 1, every face a strict triangle on the box: lengths `1, 1, 2` (a flat
    /// triangle, `y + z − x = 0` exactly) are refused by step 1, which names the face.
    /// Control: `1, 1, 1.5` holds.
    #[test]
    fn term_b76_faces_strict_on_the_box() {
        let mut flat = quad([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [1.0, 1.0]]);
        flat.disk = Mesh::from_faces(3, &[[0, 1, 2]]).expect("one triangle");
        flat.lengths = vec![1.0, 1.0, 2.0];
        flat.pole_length.truncate(3);
        flat.over_pi.truncate(3);
        flat.u.truncate(3);
        let why = reason(check_disk_certificate(&flat, BITS));
        assert!(
            why.contains("face f0 not certified a strict triangle"),
            "{why}"
        );
        let mut strict = flat;
        strict.lengths = vec![1.0, 1.0, 1.5];
        let outcome = check_disk_certificate(&strict, BITS);
        assert!(
            matches!(outcome, CertificateOutcome::Holds { .. }),
            "{outcome:?}"
        );
    }

    /// B76's data are checked before any enclosure: wrong counts, a pole length that is not
    /// positive and finite, and an enclosed metric that does not match the disk are
    /// `Undecided` with the reason (never a panic, never `Holds`). Control: the same convex
    /// disk with its own metric enclosed holds.
    #[test]
    fn term_b76_malformed_data_is_undecided() {
        let good = quad([[-1.0, 0.0], [0.0, -0.2], [1.0, 0.0], [0.0, 1.0]]);
        let p = Precision::new(u64::from(BITS)).expect("precision");
        let metric = DiskMetric {
            lengths: good.lengths.iter().map(|&x| I::from_f64(x, p)).collect(),
            pole_length: good
                .pole_length
                .iter()
                .map(|l| l.map(|x| I::from_f64(x, p)))
                .collect(),
        };
        let outcome = check_disk_certificate_on(&good, Some(&metric), BITS);
        assert!(
            matches!(outcome, CertificateOutcome::Holds { .. }),
            "{outcome:?}"
        );
        let mut cases: Vec<(&str, DiskCertificateData)> = Vec::new();
        let with = |f: &dyn Fn(&mut DiskCertificateData)| {
            let mut d = good.clone();
            f(&mut d);
            d
        };
        cases.push(("pole lengths", with(&|d| d.pole_length.truncate(3))));
        cases.push(("targets", with(&|d| d.over_pi.truncate(3))));
        cases.push(("scale factors", with(&|d| d.u.truncate(3))));
        cases.push(("lengths", with(&|d| d.lengths.truncate(4))));
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            cases.push(("pole length", with(&|d| d.pole_length[2] = Some(bad))));
        }
        for (what, d) in &cases {
            let why = reason(check_disk_certificate(d, BITS));
            assert!(
                why.contains("expected") || why.contains("not positive"),
                "{what}: {why}"
            );
        }
        let mut short = metric.clone();
        short.lengths.pop();
        let mut unlinked = metric.clone();
        unlinked.pole_length[1] = None;
        for m in [short, unlinked] {
            let why = reason(check_disk_certificate_on(&good, Some(&m), BITS));
            assert!(why.contains("does not match"), "{why}");
        }
    }

    /// The regular hexagonal wheel (spokes and rim 1) with pole lengths 2 at its six link
    /// vertices and the centre free at scale factor `u_c`, on a box of radius `radius`.
    fn wheel(u_c: f64, radius: f64) -> DiskCertificateData {
        let faces: Vec<[u32; 3]> = (1..=6).map(|i| [0, i, i % 6 + 1]).collect();
        let disk = Mesh::from_faces(7, &faces).expect("a wheel");
        let mut pole_length = vec![Some(2.0); 7];
        pole_length[0] = None;
        DiskCertificateData {
            lengths: vec![1.0; disk.n_edges()],
            disk,
            pole_length,
            over_pi: vec![Rational::from(2); 7],
            flip_sequence: Vec::new(),
            u: vec![Rational::from_f64(u_c).expect("finite"); 7],
            radius: Rational::from_f64(radius).expect("finite"),
        }
    }

    /// B76 with a free vertex: [`wheel`], so `w_a = −2 log 2`, rim lengths `1/4` and
    /// spokes `½e^{u_c/2}`; the centre's angle is `2π` exactly at `u_c = −2 log 2` (the
    /// triangles are equilateral: closed form). The certificate holds at the binary64
    /// `u_c` on a box of radius `10⁻⁹` (the residual is `O(10⁻¹⁶)`); `u_c = 0` (the
    /// Dirichlet values ignored) and `u_c = +2 log 2` (their sign flipped) are refused.
    #[test]
    fn term_b76_dirichlet_values_and_the_free_residual_decide() {
        let solved = -2.0 * 2f64.ln();
        let outcome = check_disk_certificate(&wheel(solved, 1e-9), BITS);
        let CertificateOutcome::Holds { distance, .. } = outcome else {
            panic!("{outcome:?}")
        };
        assert!(distance < 1e-12, "{distance:e}");
        for wrong in [0.0, -solved] {
            let outcome = check_disk_certificate(&wheel(wrong, 1e-9), BITS);
            assert!(
                matches!(outcome, CertificateOutcome::Undecided { .. }),
                "u_c = {wrong}: {outcome:?}"
            );
        }
    }

    /// B76, the box `[q − r, q + r]` with both ends: on [`wheel`] at the solution
    /// `q = −2 log 2` (residual `O(10⁻¹⁶)`), a box of radius `0.2` is refused because the
    /// enclosure of the Hessian over it varies by more than its eigenvalue bound; the box
    /// reduced to either end (`[q + r, q + r]` or `[q − r, q − r]`) is a point where the
    /// variation is 0 and would certify at distance `10⁻¹⁶`. Radius `0.1` is certified.
    /// Radius `1.5` reaches `u < −2 log 4`, where the faces `(s, s, ¼)` (spokes
    /// `s = ½e^{u/2}`) degenerate: refused naming a face, which a box reduced to `q + r`
    /// would not see.
    #[test]
    fn term_b76_box_has_both_ends() {
        let solved = -2.0 * 2f64.ln();
        let why = reason(check_disk_certificate(&wheel(solved, 0.2), BITS));
        assert!(why.contains("variation"), "{why}");
        let outcome = check_disk_certificate(&wheel(solved, 0.1), BITS);
        assert!(
            matches!(outcome, CertificateOutcome::Holds { .. }),
            "{outcome:?}"
        );
        let why = reason(check_disk_certificate(&wheel(solved, 1.5), BITS));
        assert!(why.contains("strict triangle"), "{why}");
    }
}
