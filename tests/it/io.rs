//! Formats: exact number parsing, surface JSON, OBJ, OFF; every malformed input gets a
//! typed error; no input panics.

use penner::scalar::{parse_rational, NumberError};
use proptest::prelude::*;
use rug::ops::Pow;
use rug::{Integer, Rational};

#[test]
fn numbers_parse_exactly() {
    let q = |a: i64, b: i64| Rational::from((a, b));
    assert_eq!(parse_rational("1.25").unwrap(), q(5, 4));
    assert_eq!(parse_rational("-3/2").unwrap(), q(-3, 2));
    assert_eq!(parse_rational("7e-3").unwrap(), q(7, 1000));
    assert_eq!(parse_rational("0.1").unwrap(), q(1, 10));
    let tiny = parse_rational("1e-30").unwrap();
    assert_eq!(
        tiny,
        Rational::from((Integer::from(1), Integer::from(10).pow(30)))
    );
    assert_eq!(
        parse_rational("1e30").unwrap(),
        Rational::from(Integer::from(10).pow(30))
    );
}

#[test]
fn bad_numbers_are_typed_errors() {
    assert_eq!(parse_rational(""), Err(NumberError::Empty));
    assert!(matches!(
        parse_rational("NaN"),
        Err(NumberError::NotFinite(_))
    ));
    assert!(matches!(
        parse_rational("-inf"),
        Err(NumberError::NotFinite(_))
    ));
    assert!(matches!(
        parse_rational("Infinity"),
        Err(NumberError::NotFinite(_))
    ));
    assert!(matches!(
        parse_rational("1e999999999"),
        Err(NumberError::ExponentTooLarge { .. })
    ));
    assert!(matches!(
        parse_rational("1e-999999999999999999999"),
        Err(NumberError::ExponentTooLarge { .. })
    ));
    assert!(matches!(
        parse_rational("3/0"),
        Err(NumberError::ZeroDenominator(_))
    ));
    assert!(matches!(
        parse_rational(&"9".repeat(20_000)),
        Err(NumberError::TooManyDigits)
    ));
    for s in [
        "abc", "1.2.3", "1e", "--2", "0x1p3", "1/2/3", "½", "1_000", "1e5.5",
    ] {
        assert!(
            matches!(parse_rational(s), Err(NumberError::Invalid { .. })),
            "{s}"
        );
    }
    // The error names the offending position.
    assert_eq!(
        parse_rational("12x4"),
        Err(NumberError::Invalid {
            text: "12x4".into(),
            position: 2,
            reason: "unexpected character"
        })
    );
}

proptest! {
    /// Oracle: Rust prints every binary64 value exactly with 800 significant digits; the
    /// parse must equal rug's exact conversion of the same value.
    #[test]
    fn exact_decimal_of_every_f64_parses_to_it(bits in any::<u64>()) {
        let x = f64::from_bits(bits);
        prop_assume!(x.is_finite());
        let s = format!("{x:.800e}");
        let want = Rational::from_f64(x).unwrap();
        prop_assert_eq!(parse_rational(&s).unwrap(), want);
    }

    /// Oracle: `m·10^e` and `p/q` built with integer arithmetic.
    #[test]
    fn scientific_and_fractions(m in any::<i64>(), e in -300i32..300, p in any::<i64>(), q in 1u64..) {
        let want = if e >= 0 {
            Rational::from(Integer::from(m) * Integer::from(10).pow(e as u32))
        } else {
            Rational::from((Integer::from(m), Integer::from(10).pow((-e) as u32)))
        };
        prop_assert_eq!(parse_rational(&format!("{m}e{e}")).unwrap(), want);
        prop_assert_eq!(parse_rational(&format!("{p}/{q}")).unwrap(), Rational::from((Integer::from(p), Integer::from(q))));
    }

    /// No string makes the parser panic.
    #[test]
    fn number_parser_never_panics(s in ".{0,40}") {
        let _ = parse_rational(&s);
    }
}
