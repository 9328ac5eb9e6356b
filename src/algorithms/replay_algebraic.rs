//! The exact Delaunay sign of a replay's quadrilateral whose lengths are algebraic (proof:
//! B107): the input's squared lengths are rational, and each flip's new squared length is
//! an algebraic function of its quadrilateral's — Euclidean
//! `ℓ_kl² = ((C − B − D + E)² + H_k + H_l + 2√(H_k H_l))/(4A)` with Heron's
//! `H = 2(AB + BC + CA) − A² − B² − C²` on the squares `[A, B, C, D, E]` of
//! `[ij, jk, ki, il, lj]` (the unfolded hinge), or Ptolemy
//! `ℓ_kl² = (CE + BD + 2√(BCDE))/A` — one square root per flip. B63's rule on the five
//! squares, `P = √(DE)·X + √(BC)·Y` with `X = B + C − A`, `Y = D + E − A`, then takes the
//! signs of `X`, `Y` and `DE·X² − BC·Y²`, each decided exactly by the separation bound of
//! [`crate::predicates::separation`], so a tie (`P = 0`) that no enclosure can decide is
//! proved.
//!
//! Every squared length is a quotient `N/M` of division-free expressions with `M > 0`.
//! The five of a quadrilateral are first put over one denominator `M` (the product of
//! their distinct ones), so that the formulas act on numerators only:
//! `ℓ_kl² = (W² + H'_k + H'_l + 2√(H'_k H'_l))/(4A'M)` and `(C'E' + B'D' + 2√(B'C'D'E'))/(A'M)`
//! for numerators `A' … E'`, and the signs of `X`, `Y`, `DE·X² − BC·Y²` are those of the
//! same expressions in numerators. The input squares are scaled by the common
//! denominator `L` of those involved: the flip formulas are homogeneous of degree 1 and
//! the three signs do not change under `s ↦ L·s`, `L > 0`, so the leaves are integers.
//! Both keep B107's bound near the true size of the numbers.

use crate::predicates::separation::{Expr, Id};
use crate::scalar::Sign;
use rug::{Integer, Rational};

/// A squared length of the decision, in an order where every flip follows its parents.
#[derive(Clone, Debug)]
pub enum Item {
    /// An exact rational squared length.
    Leaf(Rational),
    /// The new squared length of a flip whose quadrilateral `[ij, jk, ki, il, lj]` has the
    /// squared lengths of these earlier items.
    Flip([usize; 5]),
}

/// Largest precision of an enclosure in [`delaunay_sign`].
pub const ALGEBRAIC_BITS: u32 = 1 << 18;

/// A quotient `num/den` of division-free expressions, `den > 0` (`None`: 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Quotient {
    num: Id,
    den: Option<Id>,
}

/// The five quotients over one denominator: their numerators and the denominator.
fn common_denominator(ex: &mut Expr, q: [Quotient; 5]) -> ([Id; 5], Option<Id>) {
    let mut dens: Vec<Id> = Vec::new();
    for d in q.iter().filter_map(|x| x.den) {
        if !dens.contains(&d) {
            dens.push(d);
        }
    }
    let nums = q.map(|x| {
        let mut n = x.num;
        for &d in dens.iter().filter(|&&d| Some(d) != x.den) {
            n = ex.mul(n, d);
        }
        n
    });
    let den = dens.into_iter().reduce(|a, b| ex.mul(a, b));
    (nums, den)
}

/// The exact sign of the Delaunay polynomial `P` of the quadrilateral whose five squared
/// lengths are the items `quad` (module docs; proof: B107, B63), flips of the kind given
/// by `ptolemy`; `None` when a sign stays open at [`ALGEBRAIC_BITS`] bits.
pub fn delaunay_sign(items: &[Item], quad: [usize; 5], ptolemy: bool) -> Option<Sign> {
    let mut scale = Integer::from(1);
    for it in items {
        if let Item::Leaf(q) = it {
            scale.lcm_mut(q.denom());
        }
    }
    let mut ex = Expr::new();
    let mut vals: Vec<Quotient> = Vec::with_capacity(items.len());
    for it in items {
        let v = match it {
            Item::Leaf(q) => Quotient {
                num: ex.rational(Rational::from(q * &scale)),
                den: None,
            },
            Item::Flip(p) => {
                let (n, m) = common_denominator(&mut ex, p.map(|i| vals[i]));
                let (num, den) = if ptolemy {
                    ptolemy_squared(&mut ex, n)
                } else {
                    euclidean_squared(&mut ex, n)
                };
                let den = match m {
                    Some(m) => ex.mul(den, m),
                    None => den,
                };
                Quotient {
                    num,
                    den: Some(den),
                }
            }
        };
        vals.push(v);
    }
    let (nums, _) = common_denominator(&mut ex, quad.map(|i| vals[i]));
    let [a, b, c, d, e] = nums;
    let bc = ex.add(b, c);
    let x = ex.sub(bc, a);
    let de = ex.add(d, e);
    let y = ex.sub(de, a);
    let sx = ex.sign(x, ALGEBRAIC_BITS)?;
    let sy = ex.sign(y, ALGEBRAIC_BITS)?;
    match (sx, sy) {
        (Sign::Zero, s) | (s, Sign::Zero) => Some(s),
        (s, t) if s == t => Some(s),
        _ => {
            let (x2, y2) = (ex.mul(x, x), ex.mul(y, y));
            let (de, bc) = (ex.mul(d, e), ex.mul(b, c));
            let (lhs, rhs) = (ex.mul(de, x2), ex.mul(bc, y2));
            let phi = ex.sub(lhs, rhs);
            Some(match ex.sign(phi, ALGEBRAIC_BITS)? {
                Sign::Positive => sx,
                Sign::Negative => sy,
                Sign::Zero => Sign::Zero,
            })
        }
    }
}

/// Heron's `16·area² = 2(AB + BC + CA) − A² − B² − C²` on squared sides.
fn heron(ex: &mut Expr, a: Id, b: Id, c: Id) -> Id {
    let (ab, bc, ca) = (ex.mul(a, b), ex.mul(b, c), ex.mul(c, a));
    let s1 = ex.add(ab, bc);
    let s = ex.add(s1, ca);
    let two_s = ex.add(s, s);
    let (aa, bb, cc) = (ex.mul(a, a), ex.mul(b, b), ex.mul(c, c));
    let q1 = ex.add(aa, bb);
    let q = ex.add(q1, cc);
    ex.sub(two_s, q)
}

/// The Euclidean flip's new squared length on numerators over one denominator `M`
/// (module docs): the numerator `W² + H_k + H_l + 2√(H_k H_l)` and the factor `4A` of
/// the denominator `4A·M`.
fn euclidean_squared(ex: &mut Expr, [a, b, c, d, e]: [Id; 5]) -> (Id, Id) {
    let (hk, hl) = (heron(ex, a, b, c), heron(ex, a, d, e));
    let cb = ex.sub(c, b);
    let cbd = ex.sub(cb, d);
    let w = ex.add(cbd, e);
    let w2 = ex.mul(w, w);
    let h = ex.add(hk, hl);
    let prod = ex.mul(hk, hl);
    let root = ex.sqrt(prod);
    let two_root = ex.add(root, root);
    let n1 = ex.add(w2, h);
    let num = ex.add(n1, two_root);
    let two_a = ex.add(a, a);
    (num, ex.add(two_a, two_a))
}

/// The Ptolemy flip's new squared length on numerators over one denominator `M`: the
/// numerator `CE + BD + 2√(BCDE)` and the factor `A` of the denominator `A·M`.
fn ptolemy_squared(ex: &mut Expr, [a, b, c, d, e]: [Id; 5]) -> (Id, Id) {
    let (ce, bd) = (ex.mul(c, e), ex.mul(b, d));
    let prod = ex.mul(ce, bd);
    let root = ex.sqrt(prod);
    let two_root = ex.add(root, root);
    let s = ex.add(ce, bd);
    (ex.add(s, two_root), a)
}
