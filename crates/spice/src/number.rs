//! SPICE numbers.
//!
//! Takes the text of one number as a deck writes it (`10k`, `5uH`, `.5`, `-1e-9s`, `2.2MEG`);
//! gives its value as an `f64`, or why it is not a number. Knows nothing of tokens or spans.
//!
//! The grammar is SPICE3's and ngspice's: an optional sign, a decimal mantissa (`1`, `1.`,
//! `1.5`, `.5`), an optional exponent (`e-9`), then an optional scale factor, case-insensitive:
//!
//! | suffix | scale | | suffix | scale |
//! | --- | --- | --- | --- | --- |
//! | `t` | 1e12 | | `m` | 1e-3 |
//! | `g` | 1e9 | | `u` | 1e-6 |
//! | `meg` | 1e6 | | `n` | 1e-9 |
//! | `k` | 1e3 | | `p` | 1e-12 |
//! | `mil` | 25.4e-6 | | `f` | 1e-15 |
//!
//! `meg` and `mil` are tried before `m`. Letters after the number (after its scale factor, if
//! any) are units and ignored, as SPICE ignores them: `5uH` is 5e-6, `2pf` 2e-12, `10Kohm` 1e4,
//! `3.3V` 3.3, and `1F` is one femto (the classic SPICE trap). ngspice 39 has no `a` (atto):
//! `5a` is 5, and so here. Anything else after the number (a digit after a unit, `.`, `*`)
//! makes the text not a number. A power-of-ten scale is applied to the decimal exponent
//! before rounding, so `1.5m` is exactly the `f64` nearest 1.5e-3.

/// Why a text is not a SPICE number.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BadNumber {
    /// It does not have the shape of a number (`abc`, `1k5`, `1.2.3`).
    NotANumber,
    /// It has the shape, but its value is beyond `f64` (`1e999`).
    OutOfRange,
}

/// The value of a SPICE number (see the module doc).
pub fn parse_number(text: &str) -> Result<f64, BadNumber> {
    let bytes = text.as_bytes();
    let mut i = 0;
    if matches!(bytes.first(), Some(b'+' | b'-')) {
        i += 1;
    }
    let int_start = i;
    while bytes.get(i).is_some_and(u8::is_ascii_digit) {
        i += 1;
    }
    let mut digits = i - int_start;
    if bytes.get(i) == Some(&b'.') {
        i += 1;
        let frac_start = i;
        while bytes.get(i).is_some_and(u8::is_ascii_digit) {
            i += 1;
        }
        digits += i - frac_start;
    }
    if digits == 0 {
        return Err(BadNumber::NotANumber);
    }
    let mantissa_end = i;
    // The exponent counts only when digits follow (`1e` is 1 with the unit `e`).
    let mut exponent: i64 = 0;
    if matches!(bytes.get(i), Some(b'e' | b'E')) {
        let mut j = i + 1;
        let negative = bytes.get(j) == Some(&b'-');
        if matches!(bytes.get(j), Some(b'+' | b'-')) {
            j += 1;
        }
        let exp_start = j;
        while bytes.get(j).is_some_and(u8::is_ascii_digit) {
            // Saturating: an exponent this long overflows anyway, checked below.
            exponent = exponent
                .saturating_mul(10)
                .saturating_add(i64::from(bytes[j] - b'0'));
            j += 1;
        }
        if j > exp_start {
            if negative {
                exponent = -exponent;
            }
            i = j;
        }
    }
    let rest = &text[i..];
    if !rest.bytes().all(|b| b.is_ascii_alphabetic()) {
        return Err(BadNumber::NotANumber);
    }
    let (scale_exp, mil) = scale_of(rest);
    let mantissa = &text[..mantissa_end];
    let total = exponent.saturating_add(scale_exp);
    let value = if total == 0 {
        mantissa.parse::<f64>()
    } else {
        format!("{mantissa}e{total}").parse::<f64>()
    }
    // The text up to `mantissa_end` is `[+-]digits[.digits]`, which Rust's parser accepts,
    // as it does the same followed by `e` and an integer.
    .map_err(|_| BadNumber::NotANumber)?;
    let value = if mil { value * 25.4e-6 } else { value };
    if value.is_finite() {
        Ok(value)
    } else {
        Err(BadNumber::OutOfRange)
    }
}

/// The scale factor a unit text starts with: a power of ten, and whether it is `mil` instead.
fn scale_of(unit: &str) -> (i64, bool) {
    let lower = unit.to_ascii_lowercase();
    if lower.starts_with("meg") {
        return (6, false);
    }
    if lower.starts_with("mil") {
        return (0, true);
    }
    let exp = match lower.as_bytes().first() {
        Some(b't') => 12,
        Some(b'g') => 9,
        Some(b'k') => 3,
        Some(b'm') => -3,
        Some(b'u') => -6,
        Some(b'n') => -9,
        Some(b'p') => -12,
        Some(b'f') => -15,
        _ => 0,
    };
    (exp, false)
}

/// Whether a text looks like the start of a number (a digit, or `.`/sign then a digit): what
/// tells a value from a name in a deck.
pub fn starts_like_number(text: &str) -> bool {
    let b = text.as_bytes();
    let skip = usize::from(matches!(b.first(), Some(b'+' | b'-')));
    match b.get(skip) {
        Some(c) if c.is_ascii_digit() => true,
        Some(b'.') => b.get(skip + 1).is_some_and(u8::is_ascii_digit),
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn num(text: &str) -> f64 {
        match parse_number(text) {
            Ok(v) => v,
            Err(e) => panic!("`{text}` did not parse: {e:?}"),
        }
    }

    #[test]
    fn scale_factor_table() {
        let table = [
            ("1t", 1e12),
            ("1T", 1e12),
            ("1g", 1e9),
            ("1meg", 1e6),
            ("1MEG", 1e6),
            ("1Meg", 1e6),
            ("1k", 1e3),
            ("1K", 1e3),
            ("1m", 1e-3),
            ("1M", 1e-3),
            ("1mil", 25.4e-6),
            ("1MIL", 25.4e-6),
            ("1u", 1e-6),
            ("1n", 1e-9),
            ("1p", 1e-12),
            ("1f", 1e-15),
            ("1F", 1e-15),
        ];
        for (text, value) in table {
            assert_eq!(num(text), value, "{text}");
        }
    }

    #[test]
    fn mantissas_exponents_and_signs() {
        assert_eq!(num("1e3"), 1000.0);
        assert_eq!(num("1E3"), 1000.0);
        assert_eq!(num("1e-9"), 1e-9);
        assert_eq!(num("1e+2"), 100.0);
        assert_eq!(num(".5"), 0.5);
        assert_eq!(num("5."), 5.0);
        assert_eq!(num("-10"), -10.0);
        assert_eq!(num("+2.5"), 2.5);
        assert_eq!(num("1.5m"), 1.5e-3);
        assert_eq!(num("1e3k"), 1e6);
        assert_eq!(num("0"), 0.0);
        assert_eq!(num("2.2MEG"), 2.2e6);
    }

    #[test]
    fn units_after_the_scale_are_ignored() {
        assert_eq!(num("5uH"), 5e-6);
        assert_eq!(num("2pf"), 2e-12);
        assert_eq!(num("10Kohm"), 1e4);
        assert_eq!(num("1e-9s"), 1e-9);
        assert_eq!(num("3.3V"), 3.3);
        assert_eq!(num("2.5megohm"), 2.5e6);
        assert_eq!(num("0.3ns"), 0.3e-9);
        assert_eq!(num("5a"), 5.0);
        assert_eq!(num("1x"), 1.0);
        assert_eq!(num("1e"), 1.0);
        assert_eq!(num("4.65k"), 4650.0);
    }

    #[test]
    fn not_numbers() {
        for text in [
            "", "abc", "k", "-", ".", "+.", "1k5", "1.2.3", "1e3.5", "2*3", "1_0",
        ] {
            assert_eq!(parse_number(text), Err(BadNumber::NotANumber), "{text}");
        }
        assert_eq!(parse_number("1e999"), Err(BadNumber::OutOfRange));
        assert_eq!(
            parse_number("1e99999999999999999999999"),
            Err(BadNumber::OutOfRange)
        );
        assert_eq!(parse_number("1e308k"), Err(BadNumber::OutOfRange));
        assert_eq!(parse_number("1e-99999"), Ok(0.0));
    }

    #[test]
    fn number_starts() {
        assert!(starts_like_number("1k"));
        assert!(starts_like_number("-.5"));
        assert!(starts_like_number(".5"));
        assert!(!starts_like_number("n1"));
        assert!(!starts_like_number("."));
        assert!(!starts_like_number("-"));
    }

    proptest! {
        #![proptest_config(crate::test_support::config(2000))]

        #[test]
        fn scientific_text_parses_back(x in any::<f64>().prop_filter("finite", |x| x.is_finite())) {
            prop_assert_eq!(parse_number(&format!("{x:e}")), Ok(x));
            prop_assert_eq!(parse_number(&format!("{x:E}")), Ok(x));
            prop_assert_eq!(parse_number(&format!("{x}")), Ok(x));
        }

        #[test]
        fn never_panics(text in "\\PC{0,12}") {
            let _ = parse_number(&text);
        }
    }
}
