//! Times on the command line and in `-- vams: stop` comments: parsing (`6 sec`, `10ms`,
//! `1e-3`) and printing (`12.5 ms`) in seconds as `f64`.

/// The accepted forms, for error messages.
pub const TIME_FORMS: &str = "a number of seconds (`1e-3`) or a number and a unit: fs, ps, ns, us, ms, s or sec, min, hr (`6 sec`, `10ms`, `2.5 us`)";

/// Seconds per unit, smallest first (the order [`format_time`] relies on).
const UNITS: [(&str, f64); 9] = [
    ("fs", 1e-15),
    ("ps", 1e-12),
    ("ns", 1e-9),
    ("us", 1e-6),
    ("ms", 1e-3),
    ("s", 1.0),
    ("sec", 1.0),
    ("min", 60.0),
    ("hr", 3600.0),
];

/// Parses a time into seconds: a finite, non-negative number with an optional unit,
/// separated by optional white space; units are case-insensitive as in VHDL.
pub fn parse_time(text: &str) -> Result<f64, String> {
    let text = text.trim();
    let bad = || format!("`{text}` is not a time; expected {TIME_FORMS}");
    // The number ends where the unit's letters begin (an `e` followed by a digit or sign
    // belongs to the number's exponent).
    let bytes = text.as_bytes();
    let mut split = text.len();
    for (k, &b) in bytes.iter().enumerate() {
        if b.is_ascii_alphabetic() {
            let exponent = matches!(b, b'e' | b'E')
                && k > 0
                && (bytes[k - 1].is_ascii_digit() || bytes[k - 1] == b'.')
                && bytes
                    .get(k + 1)
                    .is_some_and(|n| n.is_ascii_digit() || matches!(n, b'+' | b'-'));
            if !exponent {
                split = k;
                break;
            }
        }
    }
    let (number, unit) = text.split_at(split);
    let value: f64 = number.trim().parse().map_err(|_| bad())?;
    let scale = if unit.is_empty() {
        1.0
    } else {
        let unit = unit.to_ascii_lowercase();
        UNITS
            .iter()
            .find(|(name, _)| *name == unit)
            .map(|(_, s)| *s)
            .ok_or_else(bad)?
    };
    let seconds = value * scale;
    if !seconds.is_finite() || seconds < 0.0 {
        return Err(format!(
            "`{text}` is not a time: it must be finite and not negative"
        ));
    }
    Ok(seconds)
}

/// Parses a strictly positive time (for `--stop` and `--max-step`).
pub fn parse_positive_time(text: &str) -> Result<f64, String> {
    let t = parse_time(text)?;
    if t > 0.0 {
        Ok(t)
    } else {
        Err(format!("`{}` is zero; give a positive time", text.trim()))
    }
}

/// Prints a time with the largest unit not above it (`12.5 ms`, `3 s`, `0 s`), to six
/// decimals of that unit with trailing zeros removed.
pub fn format_time(seconds: f64) -> String {
    let magnitude = seconds.abs();
    let (name, scale) = if magnitude == 0.0 || magnitude >= 1.0 || !magnitude.is_finite() {
        ("s", 1.0)
    } else {
        // `UNITS` is ordered, so the last unit not above the magnitude is the one to use.
        UNITS[..5]
            .iter()
            .rev()
            .find(|(_, s)| magnitude >= *s * (1.0 - 1e-12))
            .copied()
            .unwrap_or(UNITS[0])
    };
    let mut number = format!("{:.6}", seconds / scale);
    if number.contains('.') {
        while number.ends_with('0') {
            number.pop();
        }
        if number.ends_with('.') {
            number.pop();
        }
    }
    if number == "-0" {
        number = "0".into();
    }
    format!("{number} {name}")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-12 * b.abs().max(1e-300)
    }

    #[test]
    fn accepts_every_documented_form() {
        let cases = [
            ("6s", 6.0),
            ("6 sec", 6.0),
            ("6 SEC", 6.0),
            ("10ms", 10e-3),
            ("10 ms", 10e-3),
            ("1e-3", 1e-3),
            ("2.5 us", 2.5e-6),
            ("3ns", 3e-9),
            ("4 ps", 4e-12),
            ("5fs", 5e-15),
            ("2 min", 120.0),
            ("1.5 hr", 5400.0),
            ("1e3 ms", 1.0),
            ("2.5E-1s", 0.25),
            (" 7 ", 7.0),
            ("0", 0.0),
        ];
        for (text, want) in cases {
            let got = parse_time(text).unwrap_or_else(|e| panic!("{text}: {e}"));
            assert!(close(got, want), "{text}: {got} != {want}");
        }
    }

    #[test]
    fn rejects_malformed_times_naming_the_accepted_forms() {
        for text in [
            "",
            "ms",
            "6 parsecs",
            "6 s s",
            "1e",
            "-1 s",
            "inf",
            "nan s",
            "1e999",
        ] {
            let err = parse_time(text).expect_err(text);
            assert!(err.contains(text.trim()), "{err}");
        }
        assert!(parse_time("6 weeks").unwrap_err().contains("fs, ps, ns"));
        assert!(parse_positive_time("0 s").is_err());
        assert!(parse_positive_time("1 fs").is_ok());
    }

    #[test]
    fn prints_with_the_largest_unit_not_above() {
        assert_eq!(format_time(0.0125), "12.5 ms");
        assert_eq!(format_time(3.0), "3 s");
        assert_eq!(format_time(0.0), "0 s");
        assert_eq!(format_time(0.6), "600 ms");
        assert_eq!(format_time(1e-3), "1 ms");
        assert_eq!(format_time(2.5e-6), "2.5 us");
        assert_eq!(format_time(7e-15), "7 fs");
        assert_eq!(format_time(120.0), "120 s");
        assert_eq!(format_time(-0.002), "-2 ms");
        // Round trip through the parser.
        for t in [0.0125, 3.0, 2.5e-6, 1e-9] {
            assert!(close(parse_time(&format_time(t)).unwrap(), t));
        }
    }
}
