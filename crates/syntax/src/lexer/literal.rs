//! Values of abstract and bit-string literals, and identifier well-formedness.

use super::Tok;

/// Why an identifier is malformed (`a__b`, `a_`), if it is.
pub fn check_identifier(text: &str) -> Option<&'static str> {
    if text.contains("__") {
        Some("two underscores in a row are not allowed in an identifier")
    } else if text.ends_with('_') {
        Some("an identifier cannot end with an underscore")
    } else {
        None
    }
}

/// Value of a decimal (`1_000`, `1.5e-3`) or based (`16#FF#`, `2#1.1#e3`) literal.
pub fn number(text: &str, based: bool) -> Result<Tok<'static>, &'static str> {
    if based {
        based_number(text)
    } else {
        decimal_number(text)
    }
}

fn decimal_number(text: &str) -> Result<Tok<'static>, &'static str> {
    let clean: String = text.chars().filter(|&c| c != '_').collect();
    let (mantissa, exponent) = match clean.find(['e', 'E']) {
        Some(p) => (&clean[..p], Some(&clean[p + 1..])),
        None => (clean.as_str(), None),
    };
    if mantissa.contains('.') {
        return clean
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .map(Tok::Real)
            .ok_or("the real literal is out of range");
    }
    let mut value: i64 = mantissa
        .parse()
        .map_err(|_| "the integer literal is too large (64 bits at most)")?;
    if let Some(exp) = exponent {
        if exp.starts_with('-') {
            return Err(
                "an integer literal cannot have a negative exponent; write a real (1.0e-3)",
            );
        }
        let exp: u32 = exp
            .trim_start_matches('+')
            .parse()
            .map_err(|_| "the exponent is too large")?;
        value = 10i64
            .checked_pow(exp)
            .and_then(|p| value.checked_mul(p))
            .ok_or("the integer literal is too large (64 bits at most)")?;
    }
    Ok(Tok::Int(value))
}

fn based_number(text: &str) -> Result<Tok<'static>, &'static str> {
    let clean: String = text.chars().filter(|&c| c != '_').collect();
    let mut parts = clean.split('#');
    let (Some(base), Some(digits), Some(exp)) = (parts.next(), parts.next(), parts.next()) else {
        return Err("a based literal has the form base#digits#");
    };
    let base: u32 = base.parse().map_err(|_| "the base must be 2 to 16")?;
    if !(2..=16).contains(&base) {
        return Err("the base must be 2 to 16");
    }
    let exp: i32 = match exp.strip_prefix(['e', 'E']) {
        Some(e) => e
            .trim_start_matches('+')
            .parse()
            .map_err(|_| "the exponent is too large")?,
        None if exp.is_empty() => 0,
        None => return Err("unexpected characters after the closing #"),
    };
    let (int_part, frac_part) = match digits.split_once('.') {
        Some((i, f)) => (i, Some(f)),
        None => (digits, None),
    };
    let digit = |c: char| {
        c.to_digit(16)
            .filter(|&d| d < base)
            .ok_or("a digit is not valid in this base")
    };
    match frac_part {
        None => {
            if exp < 0 {
                return Err("an integer literal cannot have a negative exponent");
            }
            let mut value: i64 = 0;
            for c in int_part.chars() {
                value = value
                    .checked_mul(base as i64)
                    .and_then(|v| v.checked_add(digit(c).ok()? as i64))
                    .ok_or("the based literal is too large or has a bad digit")?;
            }
            for _ in 0..exp {
                value = value
                    .checked_mul(base as i64)
                    .ok_or("the based literal is too large")?;
            }
            Ok(Tok::Int(value))
        }
        Some(frac) => {
            let mut value = 0.0f64;
            for c in int_part.chars() {
                value = value * base as f64 + digit(c)? as f64;
            }
            let mut scale = 1.0 / base as f64;
            for c in frac.chars() {
                value += digit(c)? as f64 * scale;
                scale /= base as f64;
            }
            let value = value * (base as f64).powi(exp);
            if value.is_finite() {
                Ok(Tok::Real(value))
            } else {
                Err("the real literal is out of range")
            }
        }
    }
}

/// Expands `X"F0"`, `O"7"`, `B"1010"` into their bits.
pub fn bit_string(text: &str) -> Result<String, &'static str> {
    let (bits_per_digit, radix) = match text.as_bytes()[0].to_ascii_lowercase() {
        b'b' => (1, 2),
        b'o' => (3, 8),
        _ => (4, 16),
    };
    let body = &text[2..text.len() - 1];
    let mut out = String::with_capacity(body.len() * bits_per_digit);
    for c in body.chars().filter(|&c| c != '_') {
        let d = c
            .to_digit(radix)
            .ok_or("a digit is not valid for this bit-string base")?;
        for i in (0..bits_per_digit).rev() {
            out.push(if d >> i & 1 == 1 { '1' } else { '0' });
        }
    }
    Ok(out)
}
