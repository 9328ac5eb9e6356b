//! Exact rational arithmetic: a small [`Field`] trait over three independent big-rational
//! implementations — `rug::Rational` (GMP, the fast default), `malachite::rational::Rational`
//! (pure Rust) and `num_rational::BigRational` (pure Rust, num-bigint) — so that exact
//! results can be cross-checked between implementations that share no code.
//!
//! ```
//! use penner::scalar::exact::Field;
//! fn third<F: Field>() -> F { F::div(&F::one(), &F::from_i64(3)).expect("3 ≠ 0") }
//! let a: rug::Rational = third();
//! let b: malachite::rational::Rational = third();
//! let c: num_rational::BigRational = third();
//! assert_eq!(a, b.to_rug());
//! assert_eq!(a, c.to_rug());
//! ```

use super::Sign;
use malachite::platform::Limb;
use malachite::rational::Rational as MRational;
use malachite::{Integer as MInteger, Natural};
use num_bigint::{BigInt, BigUint};
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use rug::integer::Order;
use rug::{Integer, Rational};
use std::fmt::Debug;

/// An exact field of rationals: ℚ with exact `+ − × ÷`.
///
/// Operations are associated functions (`F::add(&a, &b)`) so they never collide with the
/// implementors' operator methods.
pub trait Field: Clone + Debug + PartialEq + Send + Sync + 'static {
    /// A short name of the implementation: `rug`, `malachite`, `num`.
    const NAME: &'static str;
    /// 0.
    fn zero() -> Self;
    /// 1.
    fn one() -> Self;
    /// The integer `n`.
    fn from_i64(n: i64) -> Self;
    /// The exact value of a finite `f64` (every finite binary64 is a dyadic rational);
    /// `None` for NaN and ±∞.
    fn from_f64(x: f64) -> Option<Self>;
    /// `a + b`.
    fn add(a: &Self, b: &Self) -> Self;
    /// `a − b`.
    fn sub(a: &Self, b: &Self) -> Self;
    /// `a · b`.
    fn mul(a: &Self, b: &Self) -> Self;
    /// `a / b`, or `None` when `b = 0`.
    fn div(a: &Self, b: &Self) -> Option<Self>;
    /// `−a`.
    fn neg(a: &Self) -> Self;
    /// The sign of `self`.
    fn sign(&self) -> Sign;
    /// The same rational as a `rug::Rational` (for comparisons across implementations).
    fn to_rug(&self) -> Rational;
    /// The same rational from a `rug::Rational`.
    fn from_rug(q: &Rational) -> Self;
}

impl Field for Rational {
    const NAME: &'static str = "rug";
    fn zero() -> Self {
        Rational::new()
    }
    fn one() -> Self {
        Rational::from(1)
    }
    fn from_i64(n: i64) -> Self {
        Rational::from(n)
    }
    fn from_f64(x: f64) -> Option<Self> {
        Rational::from_f64(x)
    }
    fn add(a: &Self, b: &Self) -> Self {
        Rational::from(a + b)
    }
    fn sub(a: &Self, b: &Self) -> Self {
        Rational::from(a - b)
    }
    fn mul(a: &Self, b: &Self) -> Self {
        Rational::from(a * b)
    }
    fn div(a: &Self, b: &Self) -> Option<Self> {
        if b.is_zero() {
            None
        } else {
            Some(Rational::from(a / b))
        }
    }
    fn neg(a: &Self) -> Self {
        Rational::from(-a)
    }
    fn sign(&self) -> Sign {
        Sign::of_ordering(self.cmp0())
    }
    fn to_rug(&self) -> Rational {
        self.clone()
    }
    fn from_rug(q: &Rational) -> Self {
        q.clone()
    }
}

fn natural_to_rug(n: &Natural) -> Integer {
    Integer::from_digits::<Limb>(&n.to_limbs_asc(), Order::Lsf)
}

/// The magnitude of `n` as little-endian digits of type `T`.
fn rug_digits<T: rug::integer::UnsignedPrimitive + Default + Copy>(n: &Integer) -> Vec<T> {
    let mut v = vec![T::default(); n.significant_digits::<T>()];
    n.write_digits(&mut v, Order::Lsf);
    v
}

fn rug_to_natural(n: &Integer) -> Natural {
    Natural::from_limbs_asc(&rug_digits::<Limb>(n))
}

impl Field for MRational {
    const NAME: &'static str = "malachite";
    fn zero() -> Self {
        MRational::from(0u32)
    }
    fn one() -> Self {
        MRational::from(1u32)
    }
    fn from_i64(n: i64) -> Self {
        MRational::from(n)
    }
    fn from_f64(x: f64) -> Option<Self> {
        MRational::try_from(x).ok()
    }
    fn add(a: &Self, b: &Self) -> Self {
        a + b
    }
    fn sub(a: &Self, b: &Self) -> Self {
        a - b
    }
    fn mul(a: &Self, b: &Self) -> Self {
        a * b
    }
    fn div(a: &Self, b: &Self) -> Option<Self> {
        if *b == 0u32 {
            None
        } else {
            Some(a / b)
        }
    }
    fn neg(a: &Self) -> Self {
        -a
    }
    fn sign(&self) -> Sign {
        Sign::of_ordering(malachite::base::num::arithmetic::traits::Sign::sign(self))
    }
    fn to_rug(&self) -> Rational {
        let (n, d) = self.to_numerator_and_denominator();
        let mut num = natural_to_rug(&n);
        if *self < 0u32 {
            num = -num;
        }
        Rational::from((num, natural_to_rug(&d)))
    }
    fn from_rug(q: &Rational) -> Self {
        let n = MInteger::from_sign_and_abs(
            q.numer().cmp0().is_ge(),
            rug_to_natural(&q.numer().clone().abs()),
        );
        MRational::from_integers(n, MInteger::from(rug_to_natural(q.denom())))
    }
}

fn bigint_to_rug(n: &BigInt) -> Integer {
    let (s, digits) = n.to_u64_digits();
    let m = Integer::from_digits::<u64>(&digits, Order::Lsf);
    if s == num_bigint::Sign::Minus {
        -m
    } else {
        m
    }
}

fn rug_to_bigint(n: &Integer) -> BigInt {
    let m = BigUint::from_slice(&rug_digits::<u32>(n));
    let s = if n.cmp0().is_lt() {
        num_bigint::Sign::Minus
    } else {
        num_bigint::Sign::Plus
    };
    BigInt::from_biguint(s, m)
}

impl Field for BigRational {
    const NAME: &'static str = "num";
    fn zero() -> Self {
        <BigRational as Zero>::zero()
    }
    fn one() -> Self {
        <BigRational as One>::one()
    }
    fn from_i64(n: i64) -> Self {
        BigRational::from_integer(BigInt::from(n))
    }
    fn from_f64(x: f64) -> Option<Self> {
        BigRational::from_float(x)
    }
    fn add(a: &Self, b: &Self) -> Self {
        a + b
    }
    fn sub(a: &Self, b: &Self) -> Self {
        a - b
    }
    fn mul(a: &Self, b: &Self) -> Self {
        a * b
    }
    fn div(a: &Self, b: &Self) -> Option<Self> {
        if b.is_zero() {
            None
        } else {
            Some(a / b)
        }
    }
    fn neg(a: &Self) -> Self {
        -a
    }
    fn sign(&self) -> Sign {
        if self.is_zero() {
            Sign::Zero
        } else if self.is_negative() {
            Sign::Negative
        } else {
            Sign::Positive
        }
    }
    fn to_rug(&self) -> Rational {
        Rational::from((bigint_to_rug(self.numer()), bigint_to_rug(self.denom())))
    }
    fn from_rug(q: &Rational) -> Self {
        BigRational::new(rug_to_bigint(q.numer()), rug_to_bigint(q.denom()))
    }
}
