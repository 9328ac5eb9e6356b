//! Certifying that given circles realize a triangulation as a packing within `ε`
//! (proofs/B95): for circles with exact rational centres `c_v` and radii `ρ_v > 0`,
//!
//! 1. every edge `ij`: `|‖c_i − c_j‖ − (ρ_i + ρ_j)| ≤ ε`, decided on an `Interval<Mpfr>`
//!    enclosure of the defect (inclusion property, proofs/B20);
//! 2. every face `abc`: the centres are positively oriented — the sign of
//!    `(c_b − c_a) × (c_c − c_a)`, exact in ℚ;
//! 3. every interior vertex: its neighbours' centres wind once around its centre — with
//!    every turn positive (2.), the winding number is the count of turns from the lower
//!    half-plane `[π, 2π)` into the upper `[0, π)`, exact in ℚ;
//! 4. optionally (maximal packings in the unit disk): the marked circles are internally
//!    tangent to the unit circle within `ε` (`|1 − ‖c‖ − ρ| ≤ ε`) and the others lie inside
//!    it (`‖c‖ + ρ < 1`), on enclosures.
//!
//! `Fails` only when a violation is proved (an enclosure beyond `ε`, an exact negative
//! orientation or a wrong winding number); an enclosure straddling the bound is
//! `Undecided`.

use super::violation::Violation;
use crate::mesh::{Mesh, Vertex};
use crate::scalar::{Interval, IntervalBound, Mpfr, Precision, Real, Sign};
use rug::Rational;

type I = Interval<Mpfr>;

/// A circle with exact rational centre and radius.
#[derive(Clone, Debug, PartialEq)]
pub struct ExactCircle {
    /// Centre `(x, y)`.
    pub centre: [Rational; 2],
    /// Radius.
    pub radius: Rational,
}

/// The verdict on a claimed packing.
#[derive(Clone, Debug, PartialEq)]
pub enum PackingVerdict {
    /// Every condition proved; `max_defect` bounds every tangency defect from above.
    Holds {
        /// An upper bound on every `|‖c_i − c_j‖ − (ρ_i + ρ_j)|` (and boundary defect).
        max_defect: f64,
    },
    /// Some condition is proved violated: the witnesses.
    Fails(Vec<String>),
    /// Nothing proved violated, something not proved: the reasons.
    Undecided(Vec<String>),
}

/// `|d| ≤ ε` decided on the enclosure `d`: `Some(true)` proved, `Some(false)` refuted,
/// `None` undecided.
fn within(d: &I, eps: &I) -> Option<bool> {
    let up = (eps.clone() - d).sign();
    let down = (eps.clone() + d).sign();
    if up == Some(Sign::Positive) && down == Some(Sign::Positive) {
        Some(true)
    } else if up == Some(Sign::Negative) || down == Some(Sign::Negative) {
        Some(false)
    } else {
        None
    }
}

fn cross(a: &[Rational; 2], b: &[Rational; 2], c: &[Rational; 2]) -> Rational {
    let (bx, by) = (Rational::from(&b[0] - &a[0]), Rational::from(&b[1] - &a[1]));
    let (cx, cy) = (Rational::from(&c[0] - &a[0]), Rational::from(&c[1] - &a[1]));
    bx * cy - by * cx
}

/// Whether `d` is in the upper half-plane `[0, π)` (`y > 0`, or `y = 0` and `x > 0`).
fn upper(d: &[Rational; 2]) -> bool {
    d[1] > 0 || (d[1] == 0 && d[0] > 0)
}

/// The running verdict of a packing check (plane, or caps on the sphere): defects decided
/// against `ε` on their enclosures, proved violations and open questions.
pub(super) struct Tally {
    eps: I,
    fails: Vec<String>,
    undecided: Vec<String>,
    max_defect: f64,
}

impl Tally {
    /// A check within `ε` (enclosed).
    pub(super) fn new(eps: I) -> Self {
        Tally {
            eps,
            fails: Vec::new(),
            undecided: Vec::new(),
            max_defect: 0.0,
        }
    }

    /// The defect enclosure `d` of `what`: within `ε` proved, exceeding it proved (a
    /// failure), or undecided.
    pub(super) fn defect(&mut self, d: &I, what: &str) {
        self.max_defect = self.max_defect.max(d.abs().hi().to_f64_up());
        let v = d.approx_f64();
        match within(d, &self.eps) {
            Some(true) => {}
            Some(false) => self.fails.push(format!("{what}: defect {v:.3e} > ε")),
            None => self
                .undecided
                .push(format!("{what}: defect {v:.3e} not separated from ε")),
        }
    }

    /// A proved violation.
    pub(super) fn fail(&mut self, what: String) {
        self.fails.push(what);
    }

    /// A condition neither proved nor refuted.
    pub(super) fn undecided(&mut self, what: String) {
        self.undecided.push(what);
    }

    /// Proved violations of exact conditions (orientations, windings).
    pub(super) fn violations(&mut self, v: Vec<Violation>) {
        self.fails.extend(
            v.into_iter()
                .map(|v| format!("{}: {}", v.element, v.detail)),
        );
    }

    /// `Fails` on any proved violation, else `Undecided` on any open question, else `Holds`.
    pub(super) fn verdict(self) -> PackingVerdict {
        if !self.fails.is_empty() {
            PackingVerdict::Fails(self.fails)
        } else if !self.undecided.is_empty() {
            PackingVerdict::Undecided(self.undecided)
        } else {
            PackingVerdict::Holds {
                max_defect: self.max_defect,
            }
        }
    }
}

/// The precision of a check of `count` circles (or caps) on `mesh`: `Undecided` when `bits`
/// is no MPFR precision, `Fails` when the count is not one per vertex.
pub(super) fn check_precision(
    mesh: &Mesh,
    count: usize,
    what: &str,
    bits: u32,
) -> Result<Precision, PackingVerdict> {
    let prec = Precision::new(u64::from(bits))
        .map_err(|e| PackingVerdict::Undecided(vec![e.to_string()]))?;
    if count != mesh.n_vertices() {
        return Err(PackingVerdict::Fails(vec![format!(
            "{count} {what} for {} vertices",
            mesh.n_vertices()
        )]));
    }
    Ok(prec)
}

/// Enclosures of `‖c_i − c_j‖ − (ρ_i + ρ_j)` per edge of `mesh` (mesh edge order) at
/// precision `p`; `circles` has one entry per vertex.
pub fn tangency_defects(mesh: &Mesh, circles: &[ExactCircle], p: Precision) -> Vec<I> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let (xi, yi, ri) = enclose(&circles[mesh.tail(h).idx()], p);
            let (xj, yj, rj) = enclose(&circles[mesh.tip(h).idx()], p);
            let (dx, dy) = ((xi - &xj).abs(), (yi - &yj).abs());
            (dx.clone() * &dx + &(dy.clone() * &dy)).sqrt() - &(ri + &rj)
        })
        .collect()
}

/// Enclosures of the centre and the radius of `c`.
fn enclose(c: &ExactCircle, p: Precision) -> (I, I, I) {
    (
        I::from_rational(&c.centre[0], p),
        I::from_rational(&c.centre[1], p),
        I::from_rational(&c.radius, p),
    )
}

/// Check the packing conditions (module docs) for `circles` (one per vertex) on `mesh`
/// within `eps ≥ 0`, with MPFR intervals of `bits` bits; `unit_disk` marks the circles
/// that must touch the unit circle from inside (`None`: no unit-disk conditions).
pub fn check_packing(
    mesh: &Mesh,
    circles: &[ExactCircle],
    eps: &Rational,
    bits: u32,
    unit_disk: Option<&[bool]>,
) -> PackingVerdict {
    let prec = match check_precision(mesh, circles.len(), "circles", bits) {
        Ok(p) => p,
        Err(v) => return v,
    };
    let mut tally = Tally::new(I::from_rational(eps, prec));
    for (v, c) in circles.iter().enumerate() {
        if c.radius <= 0 {
            tally.fail(format!("v{v}: radius {} is not positive", c.radius));
        }
    }
    for (edge, d) in mesh.edges().zip(tangency_defects(mesh, circles, prec)) {
        let h = edge.halfedge();
        let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        tally.defect(&d, &format!("edge e{} (v{i}, v{j})", edge.idx()));
    }
    if let Some(marks) = unit_disk {
        let one = I::from_f64(1.0, prec);
        for (v, c) in circles.iter().enumerate() {
            let (x, y, r) = enclose(c, prec);
            let reach = (x.abs() * &x.abs() + &(y.abs() * &y.abs())).sqrt() + &r;
            let gap = one.clone() - &reach;
            if marks.get(v).copied().unwrap_or(false) {
                tally.defect(&gap, &format!("v{v} and the unit circle"));
            } else {
                match gap.sign() {
                    Some(Sign::Positive) => {}
                    Some(Sign::Negative) => {
                        tally.fail(format!("v{v}: the circle leaves the unit disk"));
                    }
                    _ => tally.undecided(format!("v{v}: inside the unit disk not proved")),
                }
            }
        }
    }
    tally.violations(orientation_violations(mesh, circles));
    tally.verdict()
}

/// Faces not positively oriented (`positive([a, b, c])` false) and, when there is none, the
/// vertices whose neighbours do not wind exactly once around them (`winding(v)`; `None`
/// for a vertex not checked): conditions 2 and 3 of the module docs, for plane circles and
/// for caps on the sphere alike.
pub(super) fn face_and_winding_violations(
    mesh: &Mesh,
    positive: impl Fn([usize; 3]) -> bool,
    winding: impl Fn(Vertex) -> Option<usize>,
) -> Vec<Violation> {
    let mut out = Vec::new();
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_vertices(f).map(Vertex::idx);
        if !positive([a, b, c]) {
            out.push(Violation {
                element: format!("face f{} (v{a}, v{b}, v{c})", f.idx()),
                detail: "centres not positively oriented".into(),
            });
        }
    }
    if out.is_empty() {
        for v in mesh.vertices() {
            match winding(v) {
                Some(w) if w != 1 => out.push(Violation {
                    element: format!("v{}", v.idx()),
                    detail: format!("the neighbours wind {w} times around it"),
                }),
                _ => {}
            }
        }
    }
    out
}

/// Conditions 2 and 3 of the module docs, exactly: the faces whose centres are not
/// positively oriented and, when there is none, the interior vertices whose neighbours do
/// not wind exactly once around them.
pub fn orientation_violations(mesh: &Mesh, circles: &[ExactCircle]) -> Vec<Violation> {
    let boundary = mesh.boundary_vertices();
    face_and_winding_violations(
        mesh,
        |[a, b, c]| cross(&circles[a].centre, &circles[b].centre, &circles[c].centre) > 0,
        |v| (!boundary[v.idx()]).then(|| winding(mesh, v, circles)),
    )
}

/// The number of turns of the neighbours of interior `v` around its centre from the lower
/// into the upper half-plane, going counter-clockwise (exact; meaningful when every face
/// at `v` is positively oriented).
fn winding(mesh: &Mesh, v: Vertex, circles: &[ExactCircle]) -> usize {
    let c = &circles[v.idx()].centre;
    // `outgoing` turns clockwise: reverse it.
    let mut dirs: Vec<[Rational; 2]> = mesh
        .outgoing(v)
        .map(|h| {
            let p = &circles[mesh.tip(h).idx()].centre;
            [Rational::from(&p[0] - &c[0]), Rational::from(&p[1] - &c[1])]
        })
        .collect();
    dirs.reverse();
    let n = dirs.len();
    (0..n)
        .filter(|&k| !upper(&dirs[k]) && upper(&dirs[(k + 1) % n]))
        .count()
}

/// Exact circles from computed ones (any point backend): `None` if a value has no exact
/// value (an enclosure or a non-finite number).
pub fn exact_circles<T: Real>(circles: &[super::layout::Circle<T>]) -> Option<Vec<ExactCircle>> {
    circles
        .iter()
        .map(|c| {
            Some(ExactCircle {
                centre: [c.centre[0].to_rational()?, c.centre[1].to_rational()?],
                radius: c.radius.to_rational()?,
            })
        })
        .collect()
}

/// Tests in which one side of `|d| ≤ ε` (proofs/B95, "Terms") decides the verdict.
#[cfg(test)]
mod terms {
    use super::*;
    use crate::scalar::{Mpfr, Precision};

    fn iv(lo: f64, hi: f64) -> I {
        let p = Precision::new(64).expect("precision");
        I::new(Mpfr::from_f64(lo, p), Mpfr::from_f64(hi, p))
    }

    /// B95 terms `ε − d > 0` and `ε + d > 0`: a defect above `ε` and one below `−ε` are
    /// each refuted by its own side; one inside is proved; one straddling `±ε` is neither.
    #[test]
    fn term_b95_both_sides_of_the_tangency_tolerance_are_checked() {
        let eps = iv(1e-30, 1e-30);
        assert_eq!(within(&iv(2e-30, 3e-30), &eps), Some(false), "above ε");
        assert_eq!(within(&iv(-3e-30, -2e-30), &eps), Some(false), "below −ε");
        assert_eq!(within(&iv(-5e-31, 5e-31), &eps), Some(true));
        assert_eq!(within(&iv(5e-31, 2e-30), &eps), None, "straddles ε");
        assert_eq!(within(&iv(-2e-30, -5e-31), &eps), None, "straddles −ε");
    }

    /// A wheel: centre `v0` at the origin, rim `v1 … vk` at `(1 + i/k)·(cos, sin)(turns·2πi/k)`
    /// (quarter turns only, so the centres are exact), faces `(v0, vi, vi+1)`.
    fn wheel(k: u32, turns: u32) -> (Mesh, Vec<ExactCircle>) {
        let faces: Vec<[u32; 3]> = (1..=k).map(|i| [0, i, i % k + 1]).collect();
        let mesh = Mesh::from_faces(k + 1, &faces).expect("a wheel");
        let quarter = [(1, 0), (0, 1), (-1, 0), (0, -1)];
        let mut circles = vec![ExactCircle {
            centre: [Rational::new(), Rational::new()],
            radius: Rational::from((1, 100)),
        }];
        for i in 0..k {
            let (x, y) = quarter[((turns * 4 * i / k) % 4) as usize];
            let s = Rational::from((k + i, k));
            circles.push(ExactCircle {
                centre: [Rational::from(&s * x), Rational::from(&s * y)],
                radius: Rational::from((1, 100)),
            });
        }
        (mesh, circles)
    }

    /// B95 term "the neighbours of every interior vertex wind once": a wheel whose eight
    /// faces are all positively oriented but whose rim goes around the centre twice (a
    /// branched configuration) is refuted at `v0` by the winding alone; the four-face
    /// wheel that goes around once is not.
    #[test]
    fn term_b95_neighbours_of_an_interior_vertex_wind_once() {
        let (mesh, circles) = wheel(8, 2);
        let v = orientation_violations(&mesh, &circles);
        assert_eq!(v.len(), 1, "{v:?}");
        assert_eq!(v[0].element, "v0");
        assert!(v[0].detail.contains("wind 2 times"), "{}", v[0].detail);
        let (mesh, circles) = wheel(4, 1);
        assert!(orientation_violations(&mesh, &circles).is_empty());
    }

    /// B95 term "every face positively oriented", strictly: centres on one line
    /// (`cross = 0`, a degenerate face) are a violation, whatever the tangencies; the same
    /// triangle with its apex lifted by 2⁻¹⁰⁰ is not (exact rationals, no tolerance).
    #[test]
    fn term_b95_collinear_centres_are_not_positively_oriented() {
        let mesh = Mesh::from_faces(3, &[[0, 1, 2]]).expect("a triangle");
        let circle = |x: i32, y: Rational| ExactCircle {
            centre: [Rational::from(x), y],
            radius: Rational::from((1, 2)),
        };
        let flat = vec![
            circle(0, Rational::new()),
            circle(1, Rational::new()),
            circle(2, Rational::new()),
        ];
        let v = orientation_violations(&mesh, &flat);
        assert_eq!(v.len(), 1, "{v:?}");
        assert_eq!(v[0].element, "face f0 (v0, v1, v2)");
        let lifted = vec![
            circle(0, Rational::new()),
            circle(1, Rational::new()),
            circle(2, Rational::from(1) >> 100u32),
        ];
        assert!(orientation_violations(&mesh, &lifted).is_empty());
    }

    /// B95 term "the neighbours wind once", measured around the vertex's own centre: the
    /// once-around wheel translated to `(10, 7)` still winds once (directions `p − c`, not
    /// positions), and the twice-around wheel translated there still winds twice.
    #[test]
    fn term_b95_winding_is_measured_around_the_vertex_centre() {
        let shift = |(mesh, mut circles): (Mesh, Vec<ExactCircle>)| {
            for c in &mut circles {
                c.centre[0] += 10;
                c.centre[1] += 7;
            }
            (mesh, circles)
        };
        let (mesh, circles) = shift(wheel(4, 1));
        assert!(orientation_violations(&mesh, &circles).is_empty());
        let (mesh, circles) = shift(wheel(8, 2));
        let v = orientation_violations(&mesh, &circles);
        assert_eq!(v.len(), 1, "{v:?}");
        assert!(v[0].detail.contains("wind 2 times"), "{}", v[0].detail);
    }

    /// One triangle `(v0, v1, v2)`, scaled by `s`: `c1 = (−1, 0)`, `c2 = (1, 0)` of radius 1
    /// and `c0 = (0, 10⁻³)` of radius `r0`. Its defects are `|d₁₂ − 2| = 0` and
    /// `|√(1 + 10⁻⁶) − 1 − r0|` (closed form), below `ε = 10⁻⁶·s` for `0 ≤ r0 ≤ 10⁻⁶`.
    fn needle(r0: Rational, s: &Rational) -> (Mesh, Vec<ExactCircle>) {
        let mesh = Mesh::from_faces(3, &[[0, 1, 2]]).expect("a triangle");
        let c = |x: Rational, y: Rational, r: Rational| ExactCircle {
            centre: [x * s, y * s],
            radius: r * s,
        };
        let circles = vec![
            c(Rational::new(), Rational::from((1, 1000)), r0),
            c(Rational::from(-1), Rational::new(), Rational::from(1)),
            c(Rational::from(1), Rational::new(), Rational::from(1)),
        ];
        (mesh, circles)
    }

    /// B95 term "every radius positive": a circle of radius 0 whose tangencies hold within
    /// `ε = 10⁻⁶` (the defect `√(1 + 10⁻⁶) − 1 ≈ 5·10⁻⁷`, closed form) and whose face is
    /// positively oriented fails on its radius alone; the radius `4·10⁻⁷` holds.
    #[test]
    fn term_b95_radius_must_be_positive() {
        let one = Rational::from(1);
        let eps = Rational::from((1, 1_000_000));
        let (mesh, circles) = needle(Rational::new(), &one);
        match check_packing(&mesh, &circles, &eps, 128, None) {
            PackingVerdict::Fails(w) => {
                assert_eq!(w.len(), 1, "{w:?}");
                assert!(w[0].contains("v0: radius 0 is not positive"), "{w:?}");
            }
            v => panic!("{v:?}"),
        }
        let (mesh, circles) = needle(Rational::from((4, 10_000_000)), &one);
        assert!(matches!(
            check_packing(&mesh, &circles, &eps, 128, None),
            PackingVerdict::Holds { .. }
        ));
    }

    /// B95 term "the unmarked circles lie inside the unit disk" (`‖c‖ + ρ < 1` on
    /// enclosures): the triangle of [`needle`] (radius `r0 = 4·10⁻⁷`) scaled by 1 leaves the
    /// disk (`‖c₁‖ + ρ₁ = 2`, closed form) and fails; scaled by ½ it touches the unit circle
    /// from inside (`= 1` exactly), not proved inside, undecided; scaled by ¼ it holds.
    #[test]
    fn term_b95_unmarked_circles_inside_the_unit_disk() {
        let r0 = Rational::from((4, 10_000_000));
        let marks = [false; 3];
        for (s, expect) in [(1, "fails"), (2, "undecided"), (4, "holds")] {
            let s = Rational::from((1, s));
            let eps = Rational::from((1, 1_000_000)) * &s;
            let (mesh, circles) = needle(r0.clone(), &s);
            let v = check_packing(&mesh, &circles, &eps, 128, Some(&marks));
            let got = match &v {
                PackingVerdict::Fails(w) => {
                    assert!(
                        w.iter().all(|w| w.contains("leaves the unit disk")),
                        "{w:?}"
                    );
                    "fails"
                }
                PackingVerdict::Undecided(w) => {
                    assert!(
                        w.iter().all(|w| w.contains("inside the unit disk")),
                        "{w:?}"
                    );
                    "undecided"
                }
                PackingVerdict::Holds { .. } => "holds",
            };
            assert_eq!(got, expect, "scale {s}: {v:?}");
        }
    }
}
