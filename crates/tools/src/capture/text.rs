//! The lexical layer of capture reading: lines with their byte offsets, fields of a line
//! (separators, quotes), numbers (decimal commas, the infinities PicoScope writes for
//! over-range samples) and units with SI prefixes.

/// One line of the file: its byte offset in the text and its content without the line end.
#[derive(Debug, Clone, Copy)]
pub(super) struct Line<'a> {
    pub offset: usize,
    pub text: &'a str,
}

impl Line<'_> {
    /// Whether the line holds nothing but whitespace and separators (`,,,`).
    pub fn is_blank(&self) -> bool {
        self.text
            .bytes()
            .all(|b| matches!(b, b' ' | b'\t' | b',' | b';' | b'"'))
    }
}

/// The lines of `text` (after a byte-order mark), offsets counted in `text`.
pub(super) fn lines(text: &str) -> Vec<Line<'_>> {
    let start = if text.starts_with('\u{feff}') { 3 } else { 0 };
    let mut out = Vec::with_capacity(text.len() / 24 + 1);
    let mut offset = start;
    for raw in text[start..].split_inclusive('\n') {
        let line = raw.trim_end_matches(['\n', '\r']);
        out.push(Line { offset, text: line });
        offset += raw.len();
    }
    out
}

/// A field of a line: its byte range in the line.
pub(super) type Field = (usize, usize);

/// Splits `line` at `sep` into `out` (cleared first), honouring double quotes (a separator
/// inside quotes does not split; `""` is a quote).
pub(super) fn split_into(line: &str, sep: u8, out: &mut Vec<Field>) {
    out.clear();
    let bytes = line.as_bytes();
    if !bytes.contains(&b'"') {
        let mut start = 0;
        for (k, &b) in bytes.iter().enumerate() {
            if b == sep {
                out.push((start, k));
                start = k + 1;
            }
        }
        out.push((start, bytes.len()));
        return;
    }
    let mut start = 0;
    let mut quoted = false;
    for (k, &b) in bytes.iter().enumerate() {
        if b == b'"' {
            quoted = !quoted;
        } else if b == sep && !quoted {
            out.push((start, k));
            start = k + 1;
        }
    }
    out.push((start, bytes.len()));
}

/// The fields of `line` as text.
pub(super) fn split(line: &str, sep: u8) -> Vec<&str> {
    let mut f = Vec::new();
    split_into(line, sep, &mut f);
    f.into_iter().map(|(a, b)| &line[a..b]).collect()
}

/// A field without surrounding whitespace and quotes.
pub(super) fn clean(field: &str) -> &str {
    field.trim().trim_matches(['"', '\'']).trim()
}

/// A sample value: a finite number, or an over-range marker.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Value {
    Number(f64),
    /// `∞` (true) or `-∞` (false): PicoScope's over-range samples.
    Infinite(bool),
}

/// The number in `field`; with `decimal_comma`, `1,5` is 1.5.
pub(super) fn value(field: &str, decimal_comma: bool) -> Option<Value> {
    let f = clean(field);
    if f.is_empty() {
        return None;
    }
    match f {
        "∞" | "+∞" | "inf" | "+inf" | "Infinity" | "+Infinity" | "INF" => {
            return Some(Value::Infinite(true));
        }
        "-∞" | "−∞" | "-inf" | "-Infinity" | "-INF" => return Some(Value::Infinite(false)),
        _ => {}
    }
    // Rust's parser takes `inf`, `nan` and `infinity` too: only digits-led text is a number.
    if !f
        .bytes()
        .next()
        .is_some_and(|b| b.is_ascii_digit() || matches!(b, b'+' | b'-' | b'.' | b','))
    {
        return None;
    }
    let v = if decimal_comma && f.contains(',') {
        f.replace(',', ".").parse::<f64>().ok()?
    } else {
        f.parse::<f64>().ok()?
    };
    v.is_finite().then_some(Value::Number(v))
}

/// Whether `field` is a number (or an over-range marker).
pub(super) fn is_number(field: &str, decimal_comma: bool) -> bool {
    value(field, decimal_comma).is_some()
}

/// A unit: its SI symbol and the factor from the written unit to it (`mA` -> (`A`, 1e-3)).
/// `None` for text that is not a unit we know.
pub(super) fn unit(text: &str) -> Option<(&'static str, f64)> {
    let u = text
        .trim()
        .trim_matches(['"', '\''])
        .trim()
        .trim_start_matches(['(', '['])
        .trim_end_matches([')', ']'])
        .trim();
    if let Some(base) = base_unit(u) {
        return Some((base, 1.0));
    }
    let mut chars = u.chars();
    let first = chars.next()?;
    let scale = match first {
        'p' => 1e-12,
        'n' => 1e-9,
        'u' | 'µ' | 'μ' => 1e-6,
        'm' => 1e-3,
        'k' | 'K' => 1e3,
        'M' => 1e6,
        _ => return None,
    };
    base_unit(chars.as_str()).map(|b| (b, scale))
}

fn base_unit(u: &str) -> Option<&'static str> {
    Some(match u.to_ascii_lowercase().as_str() {
        "s" | "sec" | "second" | "seconds" => "s",
        "v" | "volt" | "volts" => "V",
        "a" | "amp" | "amps" | "ampere" | "amperes" => "A",
        "w" | "watt" | "watts" => "W",
        "hz" => "Hz",
        "ohm" | "ohms" | "Ω" => "Ω",
        _ if u == "Ω" => "Ω",
        _ => return None,
    })
}

/// A header field split into its name and the unit written with it (`current (mA)`,
/// `current[mA]`, `current/mA`); the unit only when it is one we know.
pub(super) fn name_and_unit(field: &str) -> (String, Option<(&'static str, f64)>) {
    let f = clean(field);
    if let Some(open) = f.rfind(['(', '[', '/']).filter(|&k| k > 0) {
        if let Some(u) = unit(&f[open..]) {
            return (f[..open].trim().to_string(), Some(u));
        }
    }
    (f.to_string(), None)
}

/// The key names are compared by: lower case without spaces or underscores, `channel` as
/// `ch`, and a bare number `N` as `chN` (Keysight's header `x-axis,1,2`).
pub(super) fn key(name: &str) -> String {
    let (base, _) = name_and_unit(name);
    let mut k: String = base
        .chars()
        .filter(|c| !c.is_whitespace() && *c != '_')
        .flat_map(char::to_lowercase)
        .collect();
    if let Some(rest) = k.strip_prefix("channel") {
        k = format!("ch{rest}");
    }
    if !k.is_empty() && k.bytes().all(|b| b.is_ascii_digit()) {
        k = format!("ch{k}");
    }
    k
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_and_prefixes() {
        assert_eq!(unit("(ms)"), Some(("s", 1e-3)));
        assert_eq!(unit("µs"), Some(("s", 1e-6)));
        assert_eq!(unit("uV"), Some(("V", 1e-6)));
        assert_eq!(unit("[mA]"), Some(("A", 1e-3)));
        assert_eq!(unit("Volt"), Some(("V", 1.0)));
        assert_eq!(unit("second"), Some(("s", 1.0)));
        assert_eq!(unit("CH1"), None);
        assert_eq!(unit("m"), None);
        assert_eq!(name_and_unit("current (mA)").0, "current");
        assert_eq!(name_and_unit("X(CH1)").0, "X(CH1)");
        assert_eq!(key("Channel A"), "cha");
        assert_eq!(key("1"), "ch1");
        assert_eq!(key("CH1 [V]"), "ch1");
    }

    #[test]
    fn numbers_quotes_and_commas() {
        assert_eq!(value(" \"1,5\" ", true), Some(Value::Number(1.5)));
        assert_eq!(value("1,5", false), None);
        assert_eq!(value("+1.0E-03", false), Some(Value::Number(1e-3)));
        assert_eq!(value("-∞", false), Some(Value::Infinite(false)));
        assert_eq!(value("nan", false), None);
        assert_eq!(value("infinity", false), None);
        assert_eq!(split("a,\"b,c\",d", b','), vec!["a", "\"b,c\"", "d"]);
    }
}
