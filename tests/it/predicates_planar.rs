//! Certified planar and triangle predicates: on random and adversarial inputs the certified
//! sign never contradicts the exact sign computed independently (malachite and
//! num-rational, with different expansions); the filters decide most random cases; a
//! filter with a too-small bound contradicts the exact sign (negative control).

use crate::planar_gen::{adversarial_quad, adversarial_triple, pow10, pt, q, qf};
use crate::support::cases;
use malachite::rational::Rational as MQ;
use num_rational::BigRational as NQ;
use penner::predicates::ladder::{decide, Ladder, SignPredicate};
use penner::predicates::planar::{point_from_f64, InCircle, Orient2d, Point};
use penner::predicates::triangle::{
    strict_triangle, strict_triangle_sq, TriangleAreaSq, TriangleSlack,
};
use penner::scalar::exact::Field;
use penner::scalar::{Certified, Precision, Sign, Stage};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

fn mq(q: &Rational) -> MQ {
    MQ::from_rug(q)
}

fn msign(x: &MQ) -> Sign {
    x.sign()
}

/// Orientation by cofactor expansion of det [[ax, ay, 1], [bx, by, 1], [cx, cy, 1]] in
/// malachite (a different expansion and library than the predicate's).
fn oracle_orient(a: &Point, b: &Point, c: &Point) -> Sign {
    let [ax, ay, bx, by, cx, cy] = [&a[0], &a[1], &b[0], &b[1], &c[0], &c[1]].map(mq);
    let d = &ax * (&by - &cy) - &ay * (&bx - &cx) + (&bx * &cy - &by * &cx);
    msign(&d)
}

/// Incircle as the 4×4 determinant det [[x, y, x²+y², 1]] over a, b, c, d by Laplace
/// expansion along the last column, in num-rational.
fn oracle_incircle(p: [&Point; 4]) -> Sign {
    let rows: Vec<[NQ; 3]> = p
        .iter()
        .map(|q| {
            let x = NQ::from_rug(&q[0]);
            let y = NQ::from_rug(&q[1]);
            let l = &x * &x + &y * &y;
            [x, y, l]
        })
        .collect();
    let det3 = |r: [&[NQ; 3]; 3]| -> NQ {
        &r[0][0] * (&r[1][1] * &r[2][2] - &r[1][2] * &r[2][1])
            - &r[0][1] * (&r[1][0] * &r[2][2] - &r[1][2] * &r[2][0])
            + &r[0][2] * (&r[1][0] * &r[2][1] - &r[1][1] * &r[2][0])
    };
    // det4 = Σ_i (−1)^(i+3) · minor_i3 (0-based; the last column is all ones).
    let mut det = <NQ as Field>::zero();
    for i in 0..4 {
        let minor: Vec<&[NQ; 3]> = (0..4).filter(|&j| j != i).map(|j| &rows[j]).collect();
        let m = det3([minor[0], minor[1], minor[2]]);
        if (i + 3) % 2 == 0 {
            det += m;
        } else {
            det -= m;
        }
    }
    det.sign()
}

#[derive(Default, Debug)]
struct Stages {
    filter: usize,
    interval: usize,
    exact: usize,
}

impl Stages {
    fn add(&mut self, c: &Certified<Sign>) {
        match c {
            Certified::Known {
                stage: Stage::Filter,
                ..
            } => self.filter += 1,
            Certified::Known {
                stage: Stage::Interval { .. },
                ..
            } => self.interval += 1,
            Certified::Known {
                stage: Stage::Exact,
                ..
            } => self.exact += 1,
            Certified::Undecided { .. } => {}
        }
    }
    fn total(&self) -> usize {
        self.filter + self.interval + self.exact
    }
}

/// Every rung that answers agrees with `want`, and the full ladder answers.
fn check<P: SignPredicate>(p: &P, want: Sign, what: &dyn Fn() -> String, stages: &mut Stages) {
    if let Some(s) = p.filter() {
        assert_eq!(s, want, "filter contradicts the exact sign on {}", what());
    }
    for bits in [53u64, 128] {
        if let Some(s) = p.enclosure_sign(Precision::new(bits).expect("valid")) {
            assert_eq!(s, want, "{bits}-bit enclosure contradicts on {}", what());
        }
    }
    let c = decide(p, &Ladder::default());
    assert_eq!(c.value(), Some(want), "ladder answer {c:?} on {}", what());
    stages.add(&c);
}

/// Of `n` inputs of each kind, the filter decides at least 60% of the random ones (f64
/// and fraction coordinates; grid points are often exactly degenerate and go further up)
/// and more than a quarter of the adversarial ones climb to an enclosure or exact rung.
fn assert_stage_shares(what: &str, n: usize, random: &Stages, adversarial: &Stages) {
    eprintln!("{what} stages: random {random:?}, adversarial {adversarial:?}");
    assert!(
        random.filter * 10 >= n * 6,
        "{what}: filter decided only {random:?}"
    );
    assert!(
        adversarial.exact + adversarial.interval > n / 4,
        "{what}: {adversarial:?}"
    );
}

#[test]
fn b25_orient2d_certified_sign_never_contradicts_exact_sign() {
    let mut rng = ChaCha8Rng::seed_from_u64(101);
    let n = cases(1500, 100_000);
    let mut random = Stages::default();
    let mut adversarial = Stages::default();
    for i in 0..n {
        let kind = (i % 3) as u32;
        let [a, b, c] = [pt(&mut rng, kind), pt(&mut rng, kind), pt(&mut rng, kind)];
        let o = Orient2d::new(&a, &b, &c);
        check(
            &o,
            oracle_orient(&a, &b, &c),
            &|| format!("{a:?} {b:?} {c:?}"),
            &mut random,
        );
        let [a, b, c] = adversarial_triple(&mut rng);
        let o = Orient2d::new(&a, &b, &c);
        check(
            &o,
            oracle_orient(&a, &b, &c),
            &|| format!("{a:?} {b:?} {c:?}"),
            &mut adversarial,
        );
    }
    assert_eq!(random.total(), n);
    assert_stage_shares("orient2d", n, &random, &adversarial);
}

#[test]
fn b26_incircle_certified_sign_never_contradicts_exact_sign() {
    let mut rng = ChaCha8Rng::seed_from_u64(102);
    let n = cases(800, 100_000);
    let mut random = Stages::default();
    let mut adversarial = Stages::default();
    for i in 0..n {
        let kind = (i % 3) as u32;
        let p = [
            pt(&mut rng, kind),
            pt(&mut rng, kind),
            pt(&mut rng, kind),
            pt(&mut rng, kind),
        ];
        let ic = InCircle::new(&p[0], &p[1], &p[2], &p[3]);
        let want = oracle_incircle([&p[0], &p[1], &p[2], &p[3]]);
        check(&ic, want, &|| format!("{p:?}"), &mut random);
        let p = adversarial_quad(&mut rng);
        let ic = InCircle::new(&p[0], &p[1], &p[2], &p[3]);
        let want = oracle_incircle([&p[0], &p[1], &p[2], &p[3]]);
        check(&ic, want, &|| format!("{p:?}"), &mut adversarial);
    }
    assert_stage_shares("incircle", n, &random, &adversarial);
}

#[test]
fn b23_b24_triangle_predicates_never_contradict_exact_sign() {
    let mut rng = ChaCha8Rng::seed_from_u64(103);
    let n = cases(1500, 100_000);
    let mut slack = Stages::default();
    let mut area = Stages::default();
    for i in 0..n {
        let s = pow10(rng.gen_range(-150..=150));
        let len = |rng: &mut ChaCha8Rng| q(rng.gen_range(1..1000), rng.gen_range(1..1000));
        let (a, b) = (len(&mut rng), len(&mut rng));
        // c random, or exactly |a − b| / a + b (degenerate), or those rounded to f64.
        let mut c = match i % 4 {
            0 => len(&mut rng),
            1 => Rational::from(&a + &b),
            2 => Rational::from(&a - &b).abs(),
            _ => Rational::from(&a + &b) - pow10(-rng.gen_range(5..30)),
        };
        let (mut a, mut b) = (a, b);
        if i % 3 == 1 {
            (a, b, c) = (
                Rational::from(&a * &s),
                Rational::from(&b * &s),
                Rational::from(&c * &s),
            );
        }
        if i % 5 == 2 {
            (a, b, c) = (qf(a.to_f64()), qf(b.to_f64()), qf(c.to_f64()));
        }
        // Independent oracle: (b − a) + c in num-rational.
        let want = {
            let [na, nb, nc] = [&a, &b, &c].map(NQ::from_rug);
            ((nb - na) + nc).sign()
        };
        let what = || format!("slack {a} {b} {c}");
        check(
            &TriangleSlack::new(&c, &a, &b),
            want_perm(&c, &a, &b),
            &what,
            &mut slack,
        );
        check(&TriangleSlack::new(&a, &b, &c), want, &what, &mut slack);
        // Squared lengths; oracle 16·Area² = 4AB − (A + B − C)² in malachite.
        let [a2, b2, c2] = [&a, &b, &c].map(|x| Rational::from(x * x));
        let want = {
            let [ma, mb, mc] = [&a2, &b2, &c2].map(mq);
            let t = &ma + &mb - &mc;
            msign(&(MQ::from(4u32) * &ma * &mb - &t * &t))
        };
        check(
            &TriangleAreaSq::new(&a2, &b2, &c2),
            want,
            &|| format!("area {a2} {b2} {c2}"),
            &mut area,
        );
        // The strict forms agree with each other (lengths vs squares) and with the oracle.
        let l = Ladder::default();
        let strict = strict_triangle(&a, &b, &c, &l).value();
        assert_eq!(strict, Some(want == Sign::Positive), "strict {a} {b} {c}");
        assert_eq!(strict_triangle_sq(&a2, &b2, &c2, &l).value(), strict);
    }
    eprintln!("slack stages {slack:?}, area² stages {area:?}");
    assert!(
        slack.filter > n / 2 && area.filter > n / 4,
        "{slack:?} {area:?}"
    );
    assert!(slack.exact + slack.interval > n / 4, "{slack:?}");
}

fn want_perm(a: &Rational, b: &Rational, c: &Rational) -> Sign {
    let [na, nb, nc] = [a, b, c].map(NQ::from_rug);
    ((nb - na) + nc).sign()
}

/// Negative control: the filters without their error bound (factor 0, the plain f64 sign)
/// contradict the exact sign on adversarial inputs; with the proven bound they never do.
#[test]
fn b25_b26_b23_too_small_filter_bound_contradicts_exact_sign() {
    let mut rng = ChaCha8Rng::seed_from_u64(104);
    let (mut orient_bad, mut incircle_bad, mut slack_bad) = (0, 0, 0);
    for _ in 0..2000 {
        let [a, b, c] = adversarial_triple(&mut rng);
        let o = Orient2d::new(&a, &b, &c);
        let want = oracle_orient(&a, &b, &c);
        if o.filter_scaled(0.0).is_some_and(|s| s != want) {
            orient_bad += 1;
        }
        assert!(o.filter_scaled(1.0).is_none_or(|s| s == want));
        let p = adversarial_quad(&mut rng);
        let ic = InCircle::new(&p[0], &p[1], &p[2], &p[3]);
        let want = oracle_incircle([&p[0], &p[1], &p[2], &p[3]]);
        if ic.filter_scaled(0.0).is_some_and(|s| s != want) {
            incircle_bad += 1;
        }
        let (x, y) = (q(rng.gen_range(1..1000), 3), q(rng.gen_range(1..1000), 7));
        let sum = Rational::from(&x + &y);
        let s = TriangleSlack::new(&sum, &x, &y); // exactly 0
        if s.filter_scaled(0.0).is_some_and(|s| s != Sign::Zero) {
            slack_bad += 1;
        }
    }
    eprintln!("unbounded filter contradictions: orient {orient_bad}, incircle {incircle_bad}, slack {slack_bad}");
    assert!(orient_bad > 0 && incircle_bad > 0 && slack_bad > 0);
}

#[test]
fn b25_b26_agree_with_robust_on_f64_inputs() {
    let mut rng = ChaCha8Rng::seed_from_u64(105);
    let rs = |v: f64| {
        if v > 0.0 {
            Sign::Positive
        } else if v < 0.0 {
            Sign::Negative
        } else {
            Sign::Zero
        }
    };
    for i in 0..cases(1000, 100_000) {
        let f = |rng: &mut ChaCha8Rng| {
            if i % 2 == 0 {
                rng.gen_range(-1.0..1.0)
            } else {
                f64::from(rng.gen_range(-4..4)) * 0.125
            }
        };
        let xs: [f64; 8] = std::array::from_fn(|_| f(&mut rng));
        let c = |k: usize| robust::Coord {
            x: xs[2 * k],
            y: xs[2 * k + 1],
        };
        let p = |k: usize| [qf(xs[2 * k]), qf(xs[2 * k + 1])];
        let o = decide(&Orient2d::new(&p(0), &p(1), &p(2)), &Ladder::default()).value();
        assert_eq!(o, Some(rs(robust::orient2d(c(0), c(1), c(2)))), "{xs:?}");
        let ic = decide(
            &InCircle::new(&p(0), &p(1), &p(2), &p(3)),
            &Ladder::default(),
        )
        .value();
        assert_eq!(
            ic,
            Some(rs(robust::incircle(c(0), c(1), c(2), c(3)))),
            "{xs:?}"
        );
    }
}

/// The filter constants dominate the error coefficients of proofs/B23–B26, recomputed in
/// MPFR: `((1+e)^m (1+u)^k − 1) / (1−u)^j` with `e = u` (rounded inputs) or `e = u(2+u)`
/// (differences of rounded inputs), `m` the degree, `k` the roundings on a monomial's
/// path and `j` the roundings in the computed majorant.
#[test]
fn b23_b24_b25_b26_filter_constants_cover_the_error_lemma() {
    use penner::predicates::planar::{INCIRCLE_FILTER, ORIENT2D_FILTER};
    use penner::predicates::triangle::{AREA_SQ_FILTER, SLACK_FILTER};
    use rug::ops::Pow;
    use rug::Float;
    let p = 256;
    let u = Float::with_val(p, f64::EPSILON / 2.0);
    let one = Float::with_val(p, 1);
    let e_diff = Float::with_val(p, &u * (Float::with_val(p, 2) + &u));
    let coeff = |e: &Float, m: u32, k: u32, j: u32| -> Float {
        let a = Float::with_val(p, &one + e).pow(m) * Float::with_val(p, &one + &u).pow(k) - &one;
        a / Float::with_val(p, &one - &u).pow(j)
    };
    let cases = [
        ("B23 slack", coeff(&u, 1, 2, 3), SLACK_FILTER),
        ("B24 area²", coeff(&u, 2, 4, 7), AREA_SQ_FILTER),
        ("B25 orient2d", coeff(&e_diff, 2, 2, 6), ORIENT2D_FILTER),
        ("B26 incircle", coeff(&e_diff, 4, 7, 15), INCIRCLE_FILTER),
    ];
    for (name, need, have) in cases {
        assert!(
            need < have,
            "{name}: constant {have:e} below the needed {need}"
        );
        // Negative control: half the constant would not cover the coefficient.
        assert!(
            need > have / 2.0,
            "{name}: constant {have:e} is needlessly loose"
        );
    }
}

/// `2^{-k}` exactly.
fn two_to_minus(k: u32) -> Rational {
    Rational::from((1, rug::Integer::from(1) << k))
}

/// B23/B24 through every rung: a slack (or `16·Area²`) of `2⁻²⁰⁰⁰` relative is beyond
/// every enclosure up to 1024 bits and is decided by the exact rung, as positive; one of
/// `2⁻⁸⁰` is decided by the first interval rung (the binary64 inputs cannot see it). The
/// combined verdict of `strict_triangle` carries the highest rung used, whichever slack
/// needed it (its first here; the other two are decided by the filter).
#[test]
fn term_b23_b24_each_rung_decides_and_the_verdict_carries_the_highest() {
    let l = Ladder::default();
    let (third, two_thirds) = (q(1, 3), q(2, 3));
    // a = b + c − ε: slack b + c − a = ε.
    for (k, stage) in [(2000, Stage::Exact), (80, Stage::Interval { bits: 128 })] {
        let eps = two_to_minus(k);
        let a = Rational::from(&third + &two_thirds) - &eps;
        let s = TriangleSlack::new(&a, &third, &two_thirds);
        assert_eq!(s.exact_value(), eps);
        assert_eq!(
            decide(&s, &l),
            Certified::Known {
                value: Sign::Positive,
                stage
            },
            "slack 2^-{k}"
        );
        assert_eq!(
            strict_triangle(&a, &third, &two_thirds, &l),
            Certified::Known { value: true, stage },
            "strict 2^-{k}"
        );
        // The same triangle from its squares: 16·Area² = (a+b+c)(−a+b+c)(a−b+c)(a+b−c) is
        // of the order of ε.
        let sq = |x: &Rational| Rational::from(x * x);
        let area = TriangleAreaSq::new(&sq(&a), &sq(&third), &sq(&two_thirds));
        assert!(area.exact_value() > 0);
        assert_eq!(
            decide(&area, &l),
            Certified::Known {
                value: Sign::Positive,
                stage
            },
            "area 2^-{k}"
        );
        assert_eq!(
            strict_triangle_sq(&sq(&a), &sq(&third), &sq(&two_thirds), &l),
            Certified::Known { value: true, stage }
        );
    }
}

/// B24's filter bound scales with `(A + B + C)²`: a flat triangle (`16·Area² = 0` exactly,
/// sides `2/7·s`, `5/7·s`, `s`) whose squared sides are near `2⁸⁰` rounds in binary64 to a
/// value of the order of `u·2¹⁶⁰` (−3·10³²), which only a bound of that size keeps from
/// being read as a sign; the verdict
/// is `Zero`, from the exact rung. The same at `2⁻⁸⁰` (a bound of `u·2⁻¹⁶⁰`).
#[test]
fn term_b24_area_filter_bound_scales_with_the_squared_sides() {
    let l = Ladder::default();
    for shift in [40i32, -40] {
        let scale = if shift > 0 {
            Rational::from(rug::Integer::from(1) << shift as u32)
        } else {
            two_to_minus((-shift) as u32)
        };
        let a = Rational::from(&scale * 2u32) / 7u32;
        let b = Rational::from(&scale - &a);
        let c = scale.clone();
        let sq = |x: &Rational| Rational::from(x * x);
        let area = TriangleAreaSq::new(&sq(&a), &sq(&b), &sq(&c));
        assert_eq!(area.exact_value(), 0);
        assert_eq!(area.filter(), None, "shift {shift}");
        assert_eq!(decide(&area, &l).value(), Some(Sign::Zero), "shift {shift}");
        // Control: without its bound the filter reads the rounding as a sign.
        assert!(area.filter_scaled(0.0).is_some(), "shift {shift}");
    }
}

/// B25's filter bound `8u·T`, `T = (|bx|+|ax|)(|cy|+|ay|) + (|by|+|ay|)(|cx|+|ax|)`: each
/// factor and each sum of `T` is needed. These exactly collinear rational triples (found by
/// a search over lines through points far from the origin, with small steps along them)
/// round in binary64 to a determinant that a bound with one of `T`'s eight operations
/// changed (a product read as a sum or a quotient, a sum as a product) would read as a
/// sign; with `T` the filter declines and the exact rung answers `Zero`. Control: without
/// its bound the filter reads a sign on every triple.
#[test]
fn term_b25_each_factor_of_the_orientation_bound_is_needed() {
    let witnesses: [[(&str, &str); 3]; 6] = [
        [
            ("-11/15728640", "3200/231"),
            ("-2503/7864320", "24179/231"),
            ("-1/2621440", "289/21"),
        ],
        [
            ("-9/10485760", "3145822/3"),
            ("-10995116277760000063/73400320", "4145822/3"),
            ("-10995116277823/73400320", "3145823/3"),
        ],
        [
            ("36283883716847/33", "1/10485760"),
            ("36283883716858/33", "17/73400320"),
            ("36283894716847/33", "10000007/73400320"),
        ],
        [
            ("3145750/3", "1/2097152"),
            ("34603550/33", "209715213/27262976"),
            ("34603253/33", "2097165/27262976"),
        ],
        [
            ("-524288/5", "43980465111043/3298534883328"),
            ("-11815744/65", "3299018668444221473/36283883716608"),
            ("-6815749/65", "487083651104801/36283883716608"),
        ],
        [
            ("3/10485760", "74766790688771/3298534883328"),
            ("10995116277811/178257920", "825733232459809/36283883716608"),
            (
                "1099511627776051/178257920",
                "1152288185909281/36283883716608",
            ),
        ],
    ];
    let l = Ladder::default();
    for w in witnesses {
        let p = parse_points(w);
        let o = Orient2d::new(&p[0], &p[1], &p[2]);
        assert_eq!(o.exact_value(), 0, "{w:?}");
        assert_eq!(o.filter(), None, "{w:?}");
        assert_eq!(decide(&o, &l).value(), Some(Sign::Zero), "{w:?}");
        assert!(o.filter_scaled(0.0).is_some(), "{w:?}");
    }
}

/// B25/B20 through every rung of the orientation: a point `2⁻²⁰⁰⁰` off the line is decided
/// by the exact rung, one `2⁻⁸⁰` off by the first interval rung; `point_from_f64` takes
/// binary64 coordinates exactly and refuses NaN and infinities.
#[test]
fn term_b25_each_rung_of_the_orientation_decides() {
    let l = Ladder::default();
    let (a, c) = (
        point_from_f64(0.0, 0.0).unwrap(),
        point_from_f64(1.0, 1.0).unwrap(),
    );
    for (k, stage) in [(2000u32, Stage::Exact), (80, Stage::Interval { bits: 128 })] {
        let third = q(1, 3);
        let eps = Rational::from((1, rug::Integer::from(1) << k));
        let b: Point = [third.clone(), Rational::from(&third + &eps)];
        let o = Orient2d::new(&a, &b, &c);
        assert_eq!(o.exact_value(), Rational::from(-&eps), "2^-{k}");
        assert_eq!(
            decide(&o, &l),
            Certified::Known {
                value: Sign::Negative,
                stage
            },
            "2^-{k}"
        );
    }
    assert_eq!(
        point_from_f64(0.1, -2.5),
        Some([Rational::from_f64(0.1).unwrap(), q(-5, 2)])
    );
    assert_eq!(point_from_f64(f64::NAN, 0.0), None);
    assert_eq!(point_from_f64(0.0, f64::INFINITY), None);
}

/// B26's filter bound `16u·P`, `P` built from the sums `|a·| + |d·|` of each coordinate: each
/// of the six sums is needed. These exactly cocircular rational quadruples (points of a
/// circle with a rational parametrization, far below 1 in size, found by a search) round in
/// binary64 to a determinant that a bound with one sum read as a product would read as a
/// sign; with `P` the filter declines and the exact rung answers `Zero`. Control: without
/// its bound the filter reads a sign on every quadruple.
#[test]
fn term_b26_each_sum_of_the_incircle_bound_is_needed() {
    let witnesses: [[(&str, &str); 4]; 6] = [
        // `ax + dx` read as a product
        [
            ("509/37580963840", "-1/5368709120"),
            ("321/18790481920", "33/1342177280"),
            ("951/97710505984", "423/13958643712"),
            ("-6511/729070698496", "87/104152956928"),
        ],
        // `ay + dy` read as a product
        [
            ("-2027/5894045696", "689/133955584"),
            ("1427/343146496", "745/124780544"),
            ("1871/403701760", "-1/4587520"),
            ("-293/7831814144", "-1/177995776"),
        ],
        // `bx + dx` read as a product
        [
            ("185/398358216704", "19615/1877974450176"),
            ("457/37580963840", "-49/177167400960"),
            ("4261/383325831168", "2671/200789721088"),
            ("4175/2187212095488", "217/1145682526208"),
        ],
        // `by + dy` read as a product
        [
            ("163/7168", "29/1536"),
            ("-1/65408", "4423/224256"),
            ("7439/293888", "419/31488"),
            ("419/347648", "-233/297984"),
        ],
        // `cx + dx` read as a product
        [
            ("-6297/611319808", "4847/166723584"),
            ("1757/59113472", "719/32243712"),
            ("1239/57671680", "-1/15728640"),
            ("-7133/1118830592", "367/305135616"),
        ],
        // `cy + dy` read as a product
        [
            ("109/37580963840", "-49/88583700480"),
            ("251/95831457792", "623/200789721088"),
            ("-67/1646046216192", "1127/431107342336"),
            ("307/2187212095488", "-245/572841263104"),
        ],
    ];
    incircle_witnesses_are_exact_zeros_the_filter_declines(&witnesses);
}

/// The rungs of the incircle test: `d` moved `2⁻²⁰⁰⁰` off the unit circle through
/// `a, b, c` is decided by the exact rung, `2⁻⁸⁰` off by the first interval rung.
#[test]
fn term_b26_each_rung_of_the_incircle_decides() {
    let l = Ladder::default();
    let p = |x: Rational, y: Rational| -> Point { [x, y] };
    // (3/5, 4/5), (−1, 0), (0, −1) on the unit circle; d = (5/13, 12/13) pushed outward.
    let (a, b, c) = (
        p(q(3, 5), q(4, 5)),
        p(q(-1, 1), q(0, 1)),
        p(q(0, 1), q(-1, 1)),
    );
    for (k, stage) in [(2000u32, Stage::Exact), (80, Stage::Interval { bits: 128 })] {
        let eps = Rational::from((1, rug::Integer::from(1) << k));
        let d = p(Rational::from(&q(5, 13) + &eps), q(12, 13));
        let ic = InCircle::new(&a, &b, &c, &d);
        let want = Sign::of_ordering(ic.exact_value().cmp0());
        assert_ne!(want, Sign::Zero);
        assert_eq!(
            decide(&ic, &l),
            Certified::Known { value: want, stage },
            "2^-{k}"
        );
    }
}

/// The cocircular witnesses of [`term_b26_the_products_and_sums_of_the_incircle_bound_are_needed`].
const B26_BOUND_WITNESSES: [[(&str, &str); 4]; 22] = [
    [
        ("-3401114900138/1159458643", "40940008028/1159458643"),
        ("1585446742/595", "1849708124/595"),
        (
            "-37238580949354/1479619177715",
            "7126353367876/211374168245",
        ),
        (
            "-31843918845218/4580325067255",
            "154422425730476/4580325067255",
        ),
    ],
    [
        ("111625964032/1523426723", "1378868685711/1523426723"),
        (
            "99742376141312/1363664696695",
            "-18853679896269/1363664696695",
        ),
        ("1079017984/455", "-1387265853/455"),
        (
            "183707468212736/2511625240915",
            "19730008480767/2511625240915",
        ),
    ],
    [
        ("5/7", "3489661013/416"),
        ("-81002579988411/548969658055", "519350525097/2509575579680"),
        ("-6852120056359/97259959139", "1184503450473/5780020428832"),
        (
            "410947076525481/6831597209171",
            "83126102353977/405992062716448",
        ),
    ],
    [
        (
            "2940057/3059739617320960",
            "33241814197471/4812554293457914429440",
        ),
        ("-9/71680", "28314667/450971566080"),
        (
            "-4978485/8773388781903872",
            "95316371771675/13799347373060451729408",
        ),
        (
            "-237861/80108655205376",
            "6962596976863/1008000158887588134912",
        ),
    ],
    [
        ("130862344251/7633038418439569408", "-15/1249902592"),
        (
            "77940258119823/10006744979953769115339980800",
            "82869/1433770384346316800",
        ),
        (
            "59126957847423/7591349959304296433232904192",
            "1633203/34806132130000666624",
        ),
        (
            "211135077158223/27107906791482816313950208000",
            "272787/7768063244763136000",
        ),
    ],
    [
        (
            "1127987/3403470848917504",
            "480398989905/9814194084404931854336",
        ),
        (
            "35149709/67446782077173760",
            "9520684110417/194488461649225019555840",
        ),
        ("35/3407872", "504627681/9826885173248"),
        (
            "-37481031/76690368313425920",
            "10825358986597/221143119022701968097280",
        ),
    ],
    [
        (
            "482729663875862441/1152335878560927492306108416",
            "-584840615363/1754536902144",
        ),
        (
            "88690866256940313/383764442070449395632091168768",
            "-194772208220179/584316506906112",
        ),
        ("88664617663858641/29255383179398742016", "-14533/44544"),
        (
            "17733109407239013/2717555609890776626977832960",
            "-1379243904041/4137727280640",
        ),
    ],
    [
        ("-524330/3", "-4/7"),
        ("-6392502940426/456607334163", "-814002207820/3196251339141"),
        (
            "-4148470037026/296318370855",
            "-6894399918236/2074228595985",
        ),
        (
            "-15992648421226/1142332011363",
            "-6170686311820/7996324079541",
        ),
    ],
    [
        ("-85010397698048/290562879621", "-7967630671/41508982803"),
        (
            "-6038412236290048/20639104015929",
            "-278785801337/982814476949",
        ),
        ("-1841152/21", "1/3"),
        (
            "-5671113995155456/19383690406857",
            "223726359031/923032876517",
        ),
    ],
    [
        (
            "9056153044057769/3316548776275",
            "89217710987884/5211719505575",
        ),
        ("5/7", "2952790204/11"),
        ("-18184960083751/655645795", "20561562796/1030300535"),
        (
            "732933720944409/2121212425507",
            "56971181537196/3333333811511",
        ),
    ],
    [
        (
            "-131435657482672/357162080669",
            "-22906436265571/2500134564683",
        ),
        ("-2621808", "1/7"),
        ("-15318249542512/41625646049", "-7900279802911/291379522343"),
        ("-36341503829680/98754085069", "-2480122117939/691278595483"),
    ],
    [
        (
            "17400181132793/1205100011983",
            "12223803187215/3787457180518",
        ),
        (
            "3942852378981/1394173364675",
            "98986493441301/30671814022850",
        ),
        ("1/7", "184549873/154"),
        (
            "3803830879305/2385890713087",
            "169398332903865/52489595687914",
        ),
    ],
    [
        ("-596413360/1937", "-224788331/1043"),
        ("-57851843312/3125727085", "246709769441/1683083815"),
        (
            "-38838647795952/2103758635277",
            "2902193440001/1132793111303",
        ),
        ("-18489108057008/1001493191569", "707288638613/539265564691"),
    ],
    [
        (
            "-270818200675657/947864415251712",
            "3021115130120095/1191071938427835727875145728",
        ),
        (
            "-148453741776923/519588133919904",
            "140928824751623/5223252067651363900760260608",
        ),
        ("-2609/8960", "20524217051857/11258999068426240"),
        (
            "-61224796667379/214286592638720",
            "1006603412256133/269269257466024738611527680",
        ),
    ],
    [
        (
            "-22431417518748385/22668958438942761798915325952",
            "-6159951/49560811526272",
        ),
        (
            "-3450304518826613/2671710256816618548917960704",
            "1347885/9491821575184",
        ),
        ("-44824890041174565/3102980143258271744", "-7/1696"),
        (
            "-954557090628657/47510624284191950327565516800",
            "-28151/1622996584450",
        ),
    ],
    [
        (
            "2230778027613/1117271715790270603722752",
            "252011/508076352976",
        ),
        ("439804651110501/3553621580972032", "-5/404"),
        (
            "107927655204793/6175409089125470269603840",
            "4147353/2808250923920",
        ),
        (
            "19936565218637/5114256727764097835204608",
            "-1617531/2325694698704",
        ),
    ],
    [
        ("-11852735347428937/31507182993083990016", "-35/325632"),
        (
            "-727095028415339/12211330179030773794605105152",
            "-620605/126206137493504",
        ),
        (
            "-48437840066369/511149069973216314576076800",
            "-683/110058563200",
        ),
        (
            "-271483533576889/254943472506547856211833782272",
            "545725/878294460213248",
        ),
    ],
    [
        (
            "1776005/24214118862368",
            "50256016258013/27455696034446403270868992",
        ),
        ("49/38400", "8102455805029/907097092915200"),
        (
            "-4311419/97114560229888",
            "3341221854423/2294071230840351609585664",
        ),
        (
            "770623/9117887533840",
            "41848970296733/20677023188685015660625920",
        ),
    ],
    [
        ("-40/303", "14073748835535931/10660864742916096"),
        (
            "-10321570/815317402611",
            "3456493411199183/28686430863965470800740352",
        ),
        (
            "-258986/513319575",
            "3448073769007811/18060826927281104486400",
        ),
        ("-41914/658793775", "70375551713339/23179245309406268620800"),
    ],
    [
        (
            "-1319967437468737/3673004342952220482863104",
            "747985/238612713536",
        ),
        ("-336725436006417/16747761114284032", "-105/8704"),
        (
            "-13478788761269/9626338240982815078350848",
            "978565/5002916358656",
        ),
        (
            "-13744917873201/271806737781788238382366720",
            "-5199831/141261021667840",
        ),
    ],
    [
        ("-1549727447/44506547583", "2373685749024/103848611027"),
        ("-19660055/447", "65559840/1043"),
        ("129248344495/13679914857", "104230871840/4559971619"),
        ("-195139109/6390208797", "48687370656/2130069599"),
    ],
    [
        ("3875540447/4664", "37748471/159"),
        (
            "11004647640341/14453138377832",
            "-3712301236963/492720626517",
        ),
        ("12934635907/11898518104", "-220147203269/405631299"),
        (
            "111835766695729/146888404607560",
            "-1828735492967/5007559247985",
        ),
    ],
];

/// B26's bound `P = Σ (s_ax² + s_ay²)(s_bx s_cy + s_cx s_by) + …` (the `s` the sums of
/// absolute coordinates): its products and sums are needed. These exactly cocircular
/// rational quadruples (a point far from the other three, on circles of radius `2⁻⁴⁰` to
/// `2⁶⁰`, found by a search and chosen to cover the operations) round in binary64 to a
/// determinant that a bound with one operation of `P` changed (a product read as a sum or
/// a quotient, a sum as a product) would read as a sign, for 40 of the 45 such changes;
/// with `P` the filter declines and the exact rung answers `Zero`. Control: without its
/// bound the filter reads a sign on every quadruple.
#[test]
fn term_b26_the_products_and_sums_of_the_incircle_bound_are_needed() {
    incircle_witnesses_are_exact_zeros_the_filter_declines(&B26_BOUND_WITNESSES);
}

/// Points from decimal or fraction strings.
fn parse_points<const K: usize>(w: [(&str, &str); K]) -> [Point; K] {
    w.map(|(x, y)| -> Point { [x.parse().unwrap(), y.parse().unwrap()] })
}

/// Each quadruple is exactly cocircular, the B26 filter declines it, the ladder answers
/// `Zero`, and the filter without its bound reads a sign (the control).
fn incircle_witnesses_are_exact_zeros_the_filter_declines(ws: &[[(&str, &str); 4]]) {
    let l = Ladder::default();
    for &w in ws {
        let p = parse_points(w);
        let ic = InCircle::new(&p[0], &p[1], &p[2], &p[3]);
        assert_eq!(ic.exact_value(), 0, "{w:?}");
        assert_eq!(ic.filter(), None, "{w:?}");
        assert_eq!(decide(&ic, &l).value(), Some(Sign::Zero), "{w:?}");
        assert!(ic.filter_scaled(0.0).is_some(), "{w:?}");
    }
}

/// B26's majorant, term by term: the filter's bound `next_up(16u·P̃)` against `16u·P` with
/// `P = Σ_cyc (Σ_ax² + Σ_ay²)(Σ_bx·Σ_cy + Σ_cx·Σ_by)` evaluated exactly (num-rational) on
/// the binary64 sums `Σ_ax = fl(|a_x| + |d_x|)`, …: `P̃` is `P` after 7 roundings per
/// monomial and the product with `16u` and `next_up` add two more, so the bound lies in
/// `16u·P·[1 − 8u, 1 + 12u]`. Points with coordinates of random sign and magnitudes
/// `2⁻¹⁸⁰ … 2²⁴⁰` (each point within a factor 2¹⁰ of the others, so the three cyclic
/// terms and both products of each cross factor are comparable): a bound without one
/// product of a cross factor (read as a sum or a quotient) falls below `16u·P·(1 − 8u)`.
#[test]
fn term_b26_incircle_bound_is_the_majorant_of_every_cross_product() {
    let mut rng = ChaCha8Rng::seed_from_u64(2626);
    let sixteen_u = NQ::new(16.into(), num_bigint::BigInt::from(1) << 53);
    let u = NQ::new(1.into(), num_bigint::BigInt::from(1) << 53);
    let exact = |x: f64| NQ::from_float(x).unwrap();
    let one = NQ::from_integer(1.into());
    for i in 0..400 {
        let scale = rng.gen_range(-180..230);
        let coord = |rng: &mut ChaCha8Rng| {
            let m: f64 = rng.gen_range(1.0..2.0);
            let e = scale + rng.gen_range(0..10);
            let s = if rng.gen_bool(0.5) { -1.0 } else { 1.0 };
            s * m * 2f64.powi(e)
        };
        let c: [f64; 8] = std::array::from_fn(|_| coord(&mut rng));
        let p = |k: usize| point_from_f64(c[2 * k], c[2 * k + 1]).unwrap();
        let ic = InCircle::new(&p(0), &p(1), &p(2), &p(3));
        let bound = ic.filter_bound().expect("coordinates inside B26's window");
        let [ax, ay, bx, by, cx, cy, dx, dy] = c.map(f64::abs);
        let s = [ax + dx, ay + dy, bx + dx, by + dy, cx + dx, cy + dy].map(exact);
        let [sax, say, sbx, sby, scx, scy] = [&s[0], &s[1], &s[2], &s[3], &s[4], &s[5]];
        let lift = |x: &NQ, y: &NQ| x * x + y * y;
        let maj = lift(sax, say) * (sbx * scy + scx * sby)
            + lift(sbx, sby) * (scx * say + sax * scy)
            + lift(scx, scy) * (sax * sby + sbx * say);
        let b = exact(bound);
        let target = &sixteen_u * &maj;
        assert!(
            b >= &target * (&one - &u * NQ::from_integer(8.into())),
            "case {i}: {c:?}"
        );
        assert!(
            b <= &target * (&one + &u * NQ::from_integer(12.into())),
            "case {i}: {c:?}"
        );
    }
}
