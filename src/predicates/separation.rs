//! Exact signs of algebraic numbers built from rationals by `+ − × ÷ √`, by a separation
//! bound (proof: B107): an expression `E` that is not zero is at least `2^{−B(E)}` in
//! magnitude, with `B(E)` computed from the expression alone (Burnikel, Funke, Mehlhorn,
//! Schirra and Schmitt's bound); an outward-rounded enclosure of `E` at a precision where
//! it fits strictly inside `(−2^{−B}, 2^{−B})` therefore proves `E = 0`, and one that
//! excludes 0 proves the sign. This decides the ties no enclosure can: the Delaunay sign of
//! a quadrilateral whose lengths are square roots of earlier Euclidean flips, exactly zero
//! by a symmetry of the input.
//!
//! ```
//! use penner::predicates::separation::Expr;
//! use penner::scalar::Sign;
//! use rug::Rational;
//! // √2 + √3 − √(5 + 2√6) is exactly 0; adding 2⁻²⁰⁰ makes it positive.
//! let mut e = Expr::new();
//! let q = |e: &mut Expr, n: i32| e.rational(Rational::from(n));
//! let (two, three, five, six) = (q(&mut e, 2), q(&mut e, 3), q(&mut e, 5), q(&mut e, 6));
//! let (r2, r3, r6) = (e.sqrt(two), e.sqrt(three), e.sqrt(six));
//! let two_r6 = e.add(r6, r6);
//! let inner = e.add(five, two_r6);
//! let nested = e.sqrt(inner);
//! let sum = e.add(r2, r3);
//! let zero = e.sub(sum, nested);
//! assert_eq!(e.sign(zero, 1 << 16), Some(Sign::Zero));
//! let tiny = e.rational(Rational::from((1, rug::Integer::from(1) << 200u32)));
//! let near = e.add(zero, tiny);
//! assert_eq!(e.sign(near, 1 << 16), Some(Sign::Positive));
//! ```

use crate::scalar::Sign;
use rug::float::Round;
use rug::{Float, Integer, Rational};
use std::cmp::Ordering;

/// A node of an [`Expr`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Id(u32);

#[derive(Clone, Debug)]
enum Op {
    Rational(Rational),
    Add(Id, Id),
    Sub(Id, Id),
    Mul(Id, Id),
    Div(Id, Id),
    Sqrt(Id),
}

/// A node with upper bounds on `log₂ u` and `log₂ l` of B107's recursion.
#[derive(Clone, Debug)]
struct Node {
    op: Op,
    log_u: f64,
    log_l: f64,
}

/// An arithmetic expression DAG over exact rationals (nodes are created children first,
/// so the index order is a topological order). Square roots take non-negative arguments.
#[derive(Clone, Debug, Default)]
pub struct Expr {
    nodes: Vec<Node>,
}

/// Round a `log₂` bound up by more than the `f64` rounding of the few operations that
/// produced it (each relative `2⁻⁵³`): the bounds of B107 stay upper bounds.
fn up(x: f64) -> f64 {
    x + x.abs() * 2f64.powi(-40) + 2f64.powi(-20)
}

/// An outward-rounded interval `[lo, hi]` of `rug` floats at one precision.
#[derive(Clone, Debug)]
struct Enc {
    lo: Float,
    hi: Float,
}

impl Enc {
    fn of(q: &Rational, prec: u32) -> Enc {
        Enc {
            lo: Float::with_val_round(prec, q, Round::Down).0,
            hi: Float::with_val_round(prec, q, Round::Up).0,
        }
    }
    fn add(&self, o: &Enc, prec: u32) -> Enc {
        Enc {
            lo: Float::with_val_round(prec, &self.lo + &o.lo, Round::Down).0,
            hi: Float::with_val_round(prec, &self.hi + &o.hi, Round::Up).0,
        }
    }
    fn sub(&self, o: &Enc, prec: u32) -> Enc {
        Enc {
            lo: Float::with_val_round(prec, &self.lo - &o.hi, Round::Down).0,
            hi: Float::with_val_round(prec, &self.hi - &o.lo, Round::Up).0,
        }
    }
    /// The product: for two non-negative enclosures `[lo·lo′, hi·hi′]`, otherwise the
    /// smallest and largest of the four end products, each rounded in its direction.
    fn mul(&self, o: &Enc, prec: u32) -> Enc {
        if self.lo >= 0 && o.lo >= 0 {
            return Enc {
                lo: Float::with_val_round(prec, &self.lo * &o.lo, Round::Down).0,
                hi: Float::with_val_round(prec, &self.hi * &o.hi, Round::Up).0,
            };
        }
        let ends = [
            (&self.lo, &o.lo),
            (&self.lo, &o.hi),
            (&self.hi, &o.lo),
            (&self.hi, &o.hi),
        ];
        let down = ends.map(|(a, b)| Float::with_val_round(prec, a * b, Round::Down).0);
        let upw = ends.map(|(a, b)| Float::with_val_round(prec, a * b, Round::Up).0);
        let lo = down.into_iter().reduce(|a, b| if b < a { b } else { a });
        let hi = upw.into_iter().reduce(|a, b| if b > a { b } else { a });
        Enc {
            lo: lo.unwrap_or_else(|| Float::with_val(prec, f64::NAN)),
            hi: hi.unwrap_or_else(|| Float::with_val(prec, f64::NAN)),
        }
    }
    /// The quotient, `None` unless the divisor excludes 0.
    fn div(&self, o: &Enc, prec: u32) -> Option<Enc> {
        let positive = o.lo > 0;
        let negative = o.hi < 0;
        if !positive && !negative {
            return None;
        }
        let ends = [
            (&self.lo, &o.lo),
            (&self.lo, &o.hi),
            (&self.hi, &o.lo),
            (&self.hi, &o.hi),
        ];
        let down = ends.map(|(a, b)| Float::with_val_round(prec, a / b, Round::Down).0);
        let upw = ends.map(|(a, b)| Float::with_val_round(prec, a / b, Round::Up).0);
        let lo = down.into_iter().reduce(|a, b| if b < a { b } else { a })?;
        let hi = upw.into_iter().reduce(|a, b| if b > a { b } else { a })?;
        Some(Enc { lo, hi })
    }
    /// The square root of an enclosure of a non-negative number; `None` when `lo < 0`.
    fn sqrt(&self, prec: u32) -> Option<Enc> {
        if self.lo.is_sign_negative() && !self.lo.is_zero() {
            return None;
        }
        Some(Enc {
            lo: Float::with_val_round(prec, self.lo.sqrt_ref(), Round::Down).0,
            hi: Float::with_val_round(prec, self.hi.sqrt_ref(), Round::Up).0,
        })
    }
    fn is_number(&self) -> bool {
        !self.lo.is_nan() && !self.hi.is_nan() && self.lo <= self.hi
    }
}

impl Expr {
    /// An empty expression.
    pub fn new() -> Expr {
        Expr::default()
    }

    /// The number of nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Whether there is no node.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    fn push(&mut self, op: Op, log_u: f64, log_l: f64) -> Id {
        let id = Id(u32::try_from(self.nodes.len()).unwrap_or(u32::MAX));
        self.nodes.push(Node {
            op,
            log_u: up(log_u),
            log_l: up(log_l),
        });
        id
    }

    fn bounds(&self, a: Id) -> (f64, f64) {
        let n = &self.nodes[a.0 as usize];
        (n.log_u, n.log_l)
    }

    /// The rational `p/q` (`q > 0`): B107's `u = max(|p|, 1)`, `l = q`, their `log₂` bounded
    /// by bit lengths (`0` for `1`: an integer leaf adds nothing to any `l`).
    pub fn rational(&mut self, q: Rational) -> Id {
        let bits = |n: &Integer| {
            if *n == 1 || *n == -1 || n.is_zero() {
                0.0
            } else {
                f64::from(n.significant_bits())
            }
        };
        let (log_u, log_l) = (bits(q.numer()), bits(q.denom()));
        self.push(Op::Rational(q), log_u, log_l)
    }

    /// `a + b`: `u = u_a l_b + l_a u_b`, `l = l_a l_b`.
    pub fn add(&mut self, a: Id, b: Id) -> Id {
        let ((ua, la), (ub, lb)) = (self.bounds(a), self.bounds(b));
        self.push(Op::Add(a, b), (ua + lb).max(la + ub) + 1.0, la + lb)
    }

    /// `a − b`: the bounds of [`Expr::add`].
    pub fn sub(&mut self, a: Id, b: Id) -> Id {
        let ((ua, la), (ub, lb)) = (self.bounds(a), self.bounds(b));
        self.push(Op::Sub(a, b), (ua + lb).max(la + ub) + 1.0, la + lb)
    }

    /// `a · b`: `u = u_a u_b`, `l = l_a l_b`.
    pub fn mul(&mut self, a: Id, b: Id) -> Id {
        let ((ua, la), (ub, lb)) = (self.bounds(a), self.bounds(b));
        self.push(Op::Mul(a, b), ua + ub, la + lb)
    }

    /// `a / b` (`b ≠ 0`): `u = u_a l_b`, `l = l_a u_b`.
    pub fn div(&mut self, a: Id, b: Id) -> Id {
        let ((ua, la), (ub, lb)) = (self.bounds(a), self.bounds(b));
        self.push(Op::Div(a, b), ua + lb, la + ub)
    }

    /// `√a` (`a ≥ 0`): `u = √(u_a l_a)`, `l = l_a` when `u_a ≥ l_a`, otherwise `u = u_a`,
    /// `l = √(u_a l_a)`; the `+1` of an integer square root is one more bit.
    pub fn sqrt(&mut self, a: Id) -> Id {
        let (ua, la) = self.bounds(a);
        let half = f64::midpoint(ua, la) + 1.0;
        let (u, l) = if ua >= la { (half, la) } else { (ua, half) };
        self.push(Op::Sqrt(a), u, l)
    }

    /// The nodes `root` depends on (itself included), in index order.
    fn cone(&self, root: Id) -> Vec<bool> {
        let mut used = vec![false; root.0 as usize + 1];
        used[root.0 as usize] = true;
        for i in (0..=root.0 as usize).rev() {
            if !used[i] {
                continue;
            }
            match self.nodes[i].op {
                Op::Rational(_) => {}
                Op::Add(a, b) | Op::Sub(a, b) | Op::Mul(a, b) | Op::Div(a, b) => {
                    used[a.0 as usize] = true;
                    used[b.0 as usize] = true;
                }
                Op::Sqrt(a) => used[a.0 as usize] = true,
            }
        }
        used
    }

    /// B107's `B(E) = (D − 1)·log₂ u(E) + log₂ l(E)` rounded up, with `D = 2^m` for the `m`
    /// distinct square roots `root` depends on: `E ≠ 0` implies `|E| ≥ 2^{−B}`. `None`
    /// past 2⁴⁰ radicals' degree.
    pub fn separation_bits(&self, root: Id) -> Option<f64> {
        let used = self.cone(root);
        let m = used
            .iter()
            .zip(&self.nodes)
            .filter(|(u, n)| **u && matches!(n.op, Op::Sqrt(_)))
            .count();
        if m > 40 {
            return None;
        }
        let d_minus_1 = 2f64.powi(i32::try_from(m).ok()?) - 1.0;
        let (u, l) = self.bounds(root);
        Some(up(d_minus_1 * u.max(0.0) + l.max(0.0)))
    }

    /// An outward-rounded enclosure of `root` at `prec` bits, `None` where a divisor or a
    /// radicand is not separated from 0 (or negative) at this precision.
    fn enclose(&self, root: Id, prec: u32) -> Option<Enc> {
        let used = self.cone(root);
        let mut val: Vec<Option<Enc>> = vec![None; used.len()];
        for (i, node) in self.nodes.iter().enumerate().take(used.len()) {
            if !used[i] {
                continue;
            }
            let get = |a: Id| val[a.0 as usize].as_ref();
            let v = match &node.op {
                Op::Rational(q) => Enc::of(q, prec),
                Op::Add(a, b) => get(*a)?.add(get(*b)?, prec),
                Op::Sub(a, b) => get(*a)?.sub(get(*b)?, prec),
                Op::Mul(a, b) => get(*a)?.mul(get(*b)?, prec),
                Op::Div(a, b) => get(*a)?.div(get(*b)?, prec)?,
                Op::Sqrt(a) => get(*a)?.sqrt(prec)?,
            };
            if !v.is_number() {
                return None;
            }
            val[i] = Some(v);
        }
        val.pop().flatten()
    }

    /// The exact sign of `root` (proof: B107): an enclosure at 256 bits, then at `B + 64`
    /// bits and doublings up to `max_bits`, until one excludes 0 (the sign) or, at a
    /// precision of at least `B + 64`, lies strictly inside `(−2^{−B}, 2^{−B})` (then
    /// `root = 0`). `None` when neither happens by `max_bits`, or by [`SIGN_ONLY_BITS`]
    /// when `B + 64` exceeds `max_bits` (no zero can be proved).
    pub fn sign(&self, root: Id, max_bits: u32) -> Option<Sign> {
        // The precision at which the zero rule applies, if within `max_bits`.
        let bound = self
            .separation_bits(root)
            .filter(|&b| b + 64.0 <= f64::from(max_bits));
        let zero_at = bound.and_then(|b| exponent(b + 64.0));
        let mut prec: u32 = 256;
        loop {
            if let Some(x) = self.enclose(root, prec) {
                if x.lo > 0 {
                    return Some(Sign::Positive);
                }
                if x.hi < 0 {
                    return Some(Sign::Negative);
                }
                if let Some(b) = bound.filter(|&b| f64::from(prec) >= b + 64.0) {
                    // |E| ≤ max(|lo|, |hi|) < 2^{−B} ≤ sep(E) proves E = 0.
                    let limit = Float::with_val(64, 1) >> exponent(b)?;
                    let inside =
                        |f: &Float| f.clone().abs().partial_cmp(&limit) == Some(Ordering::Less);
                    if inside(&x.lo) && inside(&x.hi) {
                        return Some(Sign::Zero);
                    }
                }
            }
            // Without the zero rule in reach only a sign can come out: doublings up to
            // `SIGN_ONLY_BITS`. With it, the next try is at its precision `B + 64` (a
            // number no smaller enclosure separated from 0 is likely a zero), then
            // doublings up to `max_bits`.
            let cap = if zero_at.is_some() {
                max_bits
            } else {
                max_bits.min(SIGN_ONLY_BITS)
            };
            if prec >= cap {
                return None;
            }
            let next = prec.saturating_mul(2);
            prec = zero_at.map_or(next, |z| z.max(next)).min(cap);
        }
    }
}

/// Largest precision of [`Expr::sign`] when no zero can be proved.
pub const SIGN_ONLY_BITS: u32 = 1 << 13;

/// `⌈b⌉` as a shift, `None` past `i32` range.
fn exponent(b: f64) -> Option<u32> {
    let c = b.ceil();
    (c >= 0.0 && c < f64::from(i32::MAX)).then_some(c as u32)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn q(e: &mut Expr, n: i64, d: i64) -> Id {
        e.rational(Rational::from((n, d)))
    }

    /// The exact sign of `p + q√r` (`r ≥ 0`) by squaring with sign tracking in ℚ: the
    /// oracle of the single-radical test.
    fn squaring_sign(p: &Rational, q: &Rational, r: &Rational) -> Sign {
        let s = |x: &Rational| Sign::of_ordering(x.cmp0());
        let (sp, sq) = (s(p), if r.is_zero() { Sign::Zero } else { s(q) });
        match (sp, sq) {
            (Sign::Zero, t) | (t, Sign::Zero) => t,
            (a, b) if a == b => a,
            _ => match Rational::from(p * p).cmp(&(Rational::from(q * q) * r)) {
                Ordering::Greater => sp,
                Ordering::Less => sq,
                Ordering::Equal => Sign::Zero,
            },
        }
    }

    /// proof: B107 — on 400 random `p + q√r` (a third of them with `r` a square and `p`
    /// chosen to cancel, so exactly 0), the separation-bound sign equals the squaring
    /// oracle's.
    #[test]
    fn b107_single_radical_signs_agree_with_exact_squaring() {
        let mut rng = ChaCha8Rng::seed_from_u64(107);
        let mut zeros = 0;
        for case in 0..400 {
            let qq = Rational::from((rng.gen_range(-50i64..50), rng.gen_range(1i64..30)));
            let (r, p) = if case % 3 == 0 {
                let t = Rational::from((rng.gen_range(0i64..40), rng.gen_range(1i64..20)));
                (Rational::from(&t * &t), -Rational::from(&qq * &t))
            } else {
                (
                    Rational::from((rng.gen_range(0i64..400), rng.gen_range(1i64..40))),
                    Rational::from((rng.gen_range(-900i64..900), rng.gen_range(1i64..40))),
                )
            };
            let mut e = Expr::new();
            let (pi, qi, ri) = (
                e.rational(p.clone()),
                e.rational(qq.clone()),
                e.rational(r.clone()),
            );
            let root = e.sqrt(ri);
            let term = e.mul(qi, root);
            let x = e.add(pi, term);
            let want = squaring_sign(&p, &qq, &r);
            zeros += usize::from(want == Sign::Zero);
            assert_eq!(e.sign(x, 1 << 16), Some(want), "{p} + {qq}·√{r}");
        }
        assert!(zeros > 100, "the zero cases occur ({zeros})");
    }

    /// proof: B107 — denesting identities `√(a + √b) = √((a + c)/2) + √((a − c)/2)` with
    /// `b = a² − c²` are exactly 0 (three radicals under one), and the same plus or minus
    /// `2⁻ᵏ` (k up to 2 000, far below any enclosure the identity's 256-bit first try
    /// sees) is decided with the sign of the perturbation.
    #[test]
    fn b107_denesting_identities_are_zero_and_their_perturbations_are_not() {
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        for _ in 0..40 {
            let c = rng.gen_range(1i64..60);
            let a = c + rng.gen_range(1i64..60);
            let mut e = Expr::new();
            let (ai, ci) = (q(&mut e, a, 1), q(&mut e, c, 1));
            let bi = q(&mut e, a * a - c * c, 1);
            let rb = e.sqrt(bi);
            let inner = e.add(ai, rb);
            let lhs = e.sqrt(inner);
            let half = q(&mut e, 1, 2);
            let (s, d) = (e.add(ai, ci), e.sub(ai, ci));
            let (s2, d2) = (e.mul(s, half), e.mul(d, half));
            let (r1, r2) = (e.sqrt(s2), e.sqrt(d2));
            let rhs = e.add(r1, r2);
            let zero = e.sub(lhs, rhs);
            assert_eq!(e.sign(zero, 1 << 16), Some(Sign::Zero), "a = {a}, c = {c}");
            for k in [10u32, 300, 2000] {
                let eps = e.rational(Rational::from((1, Integer::from(1) << k)));
                let up = e.add(zero, eps);
                let down = e.sub(zero, eps);
                assert_eq!(e.sign(up, 1 << 16), Some(Sign::Positive), "+2^-{k}");
                assert_eq!(e.sign(down, 1 << 16), Some(Sign::Negative), "-2^-{k}");
            }
        }
    }

    /// Control of the zero rule: at a precision cap below `B + 64` a true zero is not
    /// proved (`None`, never a sign), and a number `2^{−B−10}` away from 0 — below the
    /// bound the rule relies on only if the bound were wrong — is never called zero.
    #[test]
    fn b107_no_zero_without_the_precision_the_bound_asks_for() {
        let mut e = Expr::new();
        let (two, three, six) = (q(&mut e, 2, 1), q(&mut e, 3, 1), q(&mut e, 6, 1));
        let (r2, r3, r6) = (e.sqrt(two), e.sqrt(three), e.sqrt(six));
        let p = e.mul(r2, r3);
        let zero = e.sub(p, r6);
        let b = e.separation_bits(zero).expect("a bound");
        assert!(b > 0.0);
        assert_eq!(e.sign(zero, 1 << 12), Some(Sign::Zero));
        // A cap of 256 bits is enough here only when B + 64 ≤ 256.
        assert_eq!(b + 64.0 <= 256.0, e.sign(zero, 256) == Some(Sign::Zero));
        let k = b.ceil() as u32 + 10;
        let eps = e.rational(Rational::from((1, Integer::from(1) << k)));
        let near = e.add(zero, eps);
        assert_eq!(e.sign(near, 1 << 16), Some(Sign::Positive));
    }

    /// B107's rounding margin: `up(x)` exceeds `x` by more than the `f64` rounding of the
    /// few operations behind a bound, at every scale (relative `2⁻⁴⁰`, absolute `2⁻²⁰`).
    #[test]
    fn term_b107_bounds_are_rounded_up_at_every_scale() {
        for x in [0.0, 1.0, 1e12, -5.0, 3.5e-8] {
            let y = up(x);
            assert!(
                y >= x + x.abs() * 2f64.powi(-41) + 2f64.powi(-21),
                "{x:e} -> {y:e}"
            );
        }
    }

    /// The interval product encloses every product of the two enclosures' points, for
    /// every sign pattern: the end products in ℚ are the oracle (the extremes are among
    /// them), and with exactly representable ends the enclosure is those extremes.
    #[test]
    fn term_b107_interval_product_encloses_all_sign_patterns() {
        let r = |n: i64| Rational::from(n);
        let cases = [
            ((-2, 3), (-5, 1)),
            ((-3, -1), (2, 4)),
            ((1, 2), (-4, -3)),
            ((0, 1), (0, 2)),
            ((-1, 0), (2, 3)),
            ((-4, -2), (-3, -1)),
            ((2, 5), (3, 7)),
        ];
        for ((a, b), (c, d)) in cases {
            let x = Enc {
                lo: Float::with_val(64, a),
                hi: Float::with_val(64, b),
            };
            let y = Enc {
                lo: Float::with_val(64, c),
                hi: Float::with_val(64, d),
            };
            let z = x.mul(&y, 64);
            let ends = [r(a) * r(c), r(a) * r(d), r(b) * r(c), r(b) * r(d)];
            let (lo, hi) = (ends.iter().min().unwrap(), ends.iter().max().unwrap());
            assert_eq!(z.lo.to_rational().unwrap(), *lo, "[{a},{b}]·[{c},{d}]");
            assert_eq!(z.hi.to_rational().unwrap(), *hi, "[{a},{b}]·[{c},{d}]");
        }
    }

    /// Division decides: `√2/2 − 1/√2` is exactly 0 and `1/√2 − 7/10` positive, each
    /// decided through an enclosed quotient (a quotient whose divisor straddles 0 is no
    /// number, so the sign is refused, not guessed).
    #[test]
    fn term_b107_quotients_are_enclosed_and_decide() {
        let mut e = Expr::new();
        let two = q(&mut e, 2, 1);
        let one = q(&mut e, 1, 1);
        let r2 = e.sqrt(two);
        let half_r2 = e.div(r2, two);
        let inv_r2 = e.div(one, r2);
        let zero = e.sub(half_r2, inv_r2);
        assert_eq!(e.sign(zero, 1 << 12), Some(Sign::Zero));
        let seven_tenths = q(&mut e, 7, 10);
        let pos = e.sub(inv_r2, seven_tenths);
        assert_eq!(e.sign(pos, 1 << 12), Some(Sign::Positive));
        // Control: dividing by the exact zero above is refused.
        let bad = e.div(one, zero);
        assert_eq!(e.sign(bad, 1 << 12), None);
        // The interval quotient itself: a divisor with 0 in it or at an end is refused,
        // one of either sign is divided (ends in ℚ as the oracle).
        let enc = |a: i64, b: i64| Enc {
            lo: Float::with_val(64, a),
            hi: Float::with_val(64, b),
        };
        let x = enc(3, 6);
        for (a, b) in [(0, 1), (-1, 0), (-1, 1), (0, 0)] {
            assert!(x.div(&enc(a, b), 64).is_none(), "[3, 6] / [{a}, {b}]");
        }
        for ((a, b), (lo, hi)) in [((1, 2), ((3, 2), (6, 1))), ((-2, -1), ((-6, 1), (-3, 2)))] {
            let z = x.div(&enc(a, b), 64).expect("a divisor of one sign");
            assert_eq!(
                z.lo.to_rational().unwrap(),
                Rational::from(lo),
                "[3, 6] / [{a}, {b}]"
            );
            assert_eq!(
                z.hi.to_rational().unwrap(),
                Rational::from(hi),
                "[3, 6] / [{a}, {b}]"
            );
        }
    }

    /// The enclosure guards: `is_number` refuses NaN ends and `lo > hi`; the square root
    /// refuses an enclosure reaching below 0 (`−0` is 0) and encloses `√` of the ends.
    #[test]
    fn term_b107_enclosure_guards() {
        let enc = |a: f64, b: f64| Enc {
            lo: Float::with_val(64, a),
            hi: Float::with_val(64, b),
        };
        assert!(enc(1.0, 2.0).is_number() && enc(-1.0, -1.0).is_number());
        for (a, b) in [(f64::NAN, 1.0), (1.0, f64::NAN), (2.0, 1.0)] {
            assert!(!enc(a, b).is_number(), "[{a}, {b}]");
        }
        assert!(enc(-1.0, 4.0).sqrt(64).is_none());
        assert!(enc(-1e-300, 4.0).sqrt(64).is_none());
        let r = enc(-0.0, 4.0).sqrt(64).expect("−0 is 0");
        assert_eq!((r.lo.to_f64(), r.hi.to_f64()), (0.0, 2.0));
    }

    /// The expression's size, and the leaves `±1` adding nothing to the bound: with one
    /// radical (`D − 1 = 1`, so `log₂ u` counts), the bound of `√x·(−1)` equals that of
    /// `√x·1`.
    #[test]
    fn term_b107_unit_leaves_add_nothing_to_the_bound() {
        let mut e = Expr::new();
        assert!(e.is_empty());
        assert_eq!(e.len(), 0);
        let five_sevenths = q(&mut e, 5, 7);
        let (one, minus_one) = (q(&mut e, 1, 1), q(&mut e, -1, 1));
        assert!(!e.is_empty() && e.len() == 3);
        let x = e.sqrt(five_sevenths);
        let (a, b) = (e.mul(x, one), e.mul(x, minus_one));
        assert_eq!(e.separation_bits(a), e.separation_bits(b));
        // Control: a leaf 2 is not a unit and raises the bound.
        let two = q(&mut e, 2, 1);
        let c = e.mul(x, two);
        assert!(e.separation_bits(c) > e.separation_bits(a));
    }

    /// B107's bound against an independent evaluation of the same recursion: `log₂ u` and
    /// `log₂ l` of every node from the exact leaves (`log₂ max(|p|, 1)`, `log₂ q`) and the
    /// exact `log₂(2^x + 2^y)` of a sum, without the rounding up and the integer-root bit;
    /// on 300 random expressions over `+ − × ÷ √` the computed `B(E)` is never below it.
    #[test]
    fn term_b107_bound_is_never_below_the_exact_recursion() {
        let mut rng = ChaCha8Rng::seed_from_u64(1107);
        let lse = |x: f64, y: f64| x.max(y) + (1.0 + (-(x - y).abs()).exp2()).log2();
        for _ in 0..300 {
            let mut e = Expr::new();
            // (log₂ u, log₂ l, is a square root) per node, the reference.
            let mut r: Vec<(f64, f64, bool)> = Vec::new();
            let mut ids: Vec<Id> = Vec::new();
            for _ in 0..3 {
                let (p, d) = (
                    rng.gen_range(1..40) * if rng.gen_bool(0.5) { 1 } else { -1 },
                    rng.gen_range(1..40),
                );
                let x = Rational::from((p, d));
                r.push((
                    x.numer()
                        .clone()
                        .abs()
                        .max(Integer::from(1))
                        .to_f64()
                        .log2(),
                    x.denom().to_f64().log2(),
                    false,
                ));
                ids.push(e.rational(x));
            }
            for _ in 0..rng.gen_range(2..9) {
                let (a, b) = (rng.gen_range(0..ids.len()), rng.gen_range(0..ids.len()));
                let ((ua, la, _), (ub, lb, _)) = (r[a], r[b]);
                let (id, node) = match rng.gen_range(0..5) {
                    0 => (
                        e.add(ids[a], ids[b]),
                        (lse(ua + lb, la + ub), la + lb, false),
                    ),
                    1 => (
                        e.sub(ids[a], ids[b]),
                        (lse(ua + lb, la + ub), la + lb, false),
                    ),
                    2 => (e.mul(ids[a], ids[b]), (ua + ub, la + lb, false)),
                    3 => (e.div(ids[a], ids[b]), (ua + lb, la + ub, false)),
                    _ => {
                        let half = f64::midpoint(ua, la);
                        let (u, l) = if ua >= la { (half, la) } else { (ua, half) };
                        (e.sqrt(ids[a]), (u, l, true))
                    }
                };
                ids.push(id);
                r.push(node);
            }
            let root = *ids.last().unwrap();
            let used = e.cone(root);
            let m = used.iter().zip(&r).filter(|(u, n)| **u && n.2).count();
            let (u, l, _) = r[root.0 as usize];
            let reference = (2f64.powi(m as i32) - 1.0) * u.max(0.0) + l.max(0.0);
            let got = e.separation_bits(root).expect("few radicals");
            assert!(
                got >= reference * (1.0 - 1e-12),
                "B = {got} below {reference}"
            );
        }
        // A sum whose larger term is the second one's: `1 + √(10³⁰)` (`l_a = 0`, `u_b` about
        // 50 bits), where `u = max(u_a l_b, l_a u_b)` must take `l_a + u_b`, not `l_a·u_b`.
        let mut e = Expr::new();
        let one = e.rational(Rational::from(1));
        let big = e.rational(Rational::from(rug::ops::Pow::pow(Integer::from(10), 30u32)));
        let r = e.sqrt(big);
        let sum = e.add(one, r);
        let reference = lse(0.0, 30.0 * 10f64.log2() / 2.0);
        let got = e.separation_bits(sum).unwrap();
        assert!(got >= reference, "B = {got} below {reference}");
    }

    /// The zero rule's threshold is `2^{−B}`, applied only to an enclosure inside it: for
    /// `b = 2¹⁵⁰`, `E = √(b² + 1) − b ≈ 2⁻¹⁵¹` is positive, and its 256-bit enclosure
    /// (width about `2⁻¹⁰⁶`) contains 0 while `B ≈ 152` already allows the rule there. A
    /// threshold of `2^{+B}` (or of 1) would call it zero. Control: `√(b²) − b` is zero.
    #[test]
    fn term_b107_zero_rule_threshold_is_two_to_the_minus_b() {
        let b = Rational::from(Integer::from(1) << 150u32);
        let b2 = Rational::from(&b * &b);
        for (radicand, want) in [
            (Rational::from(&b2 + 1u32), Sign::Positive),
            (b2.clone(), Sign::Zero),
        ] {
            let mut e = Expr::new();
            let (r, bb) = (e.rational(radicand), e.rational(b.clone()));
            let root = e.sqrt(r);
            let diff = e.sub(root, bb);
            let bits = e.separation_bits(diff).unwrap();
            assert!(
                bits + 64.0 <= 256.0,
                "B = {bits}: the rule applies at 256 bits"
            );
            assert_eq!(e.sign(diff, 1 << 12), Some(want));
        }
    }
}
