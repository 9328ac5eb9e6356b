//! The arithmetic every number type of the crate shares — the rounded backends (`f64`,
//! [`Dd`](super::Dd), [`Mpfr`](super::Mpfr)), their intervals, and exact rationals
//! (`rug::Rational`): a [`Ring`] (`+ − ×`) and a [`Field`] (with `÷`). A kernel that needs
//! no square root, exponential or angle — the Delaunay polynomial on lengths, Heron's
//! `16·Area²` on squared lengths, cross ratios, Lemma 1's scale factors — is written once
//! over these traits and runs exactly in ℚ, with outward rounding on intervals and rounded
//! in each backend; [`Real`](super::Real) adds what ℚ cannot do exactly (`√`, `exp`, `ln`,
//! the trigonometric functions) on top of [`Field`].
//!
//! ```
//! use penner::scalar::{Field, Ring};
//! use rug::Rational;
//! // One kernel, two number types: (a + b)·c / d.
//! fn kernel<T: Field>(a: &T, b: &T, c: &T, d: &T) -> T {
//!     (a.clone() + b) * c / d
//! }
//! assert_eq!(kernel(&1.0_f64, &2.0, &4.0, &3.0), 4.0);
//! let q = |n: i32| Rational::from(n);
//! assert_eq!(kernel(&q(1), &q(2), &q(1), &q(3)), Rational::from(1));
//! ```

use std::fmt::Debug;
use std::ops::{Add, Div, Mul, Sub};

/// Values closed under `+ − ×` taken by reference (`a.clone() + &b`), exactly or rounded
/// as the type documents.
pub trait Ring:
    Clone
    + Debug
    + for<'a> Add<&'a Self, Output = Self>
    + for<'a> Sub<&'a Self, Output = Self>
    + for<'a> Mul<&'a Self, Output = Self>
{
}

impl<T> Ring for T where
    T: Clone
        + Debug
        + for<'a> Add<&'a T, Output = T>
        + for<'a> Sub<&'a T, Output = T>
        + for<'a> Mul<&'a T, Output = T>
{
}

/// A [`Ring`] with division by reference (by a nonzero value).
pub trait Field: Ring + for<'a> Div<&'a Self, Output = Self> {}

impl<T> Field for T where T: Ring + for<'a> Div<&'a T, Output = T> {}
