//! Waveforms as CSV: a header `time,<probe names>`, then one row per recorded time point.
//! Numbers are written with the shortest text that reads back to the same `f64`; signals are
//! their numbers (booleans and enumerations as positions). Names are quoted per RFC 4180 when
//! they hold a comma or a quote.

use std::io::{self, Write};

use vams_simulation::waveform::{Column, Waveforms};

/// The shortest text that parses back to exactly `v`: plain decimals for ordinary magnitudes,
/// scientific notation for very small and very large ones.
pub fn format_number(v: f64) -> String {
    let mut s = String::new();
    push_number(&mut s, v);
    s
}

/// [`format_number`] appended to `out` (no allocation once `out` has grown: a CSV row of a
/// large design is thousands of numbers). The text has the form of Rust's `{}` (plain) and
/// `{:e}` (scientific), with the shortest digits that read back exactly, from `zmij`
/// (Schubfach, already in the build for serde_json), faster than `core::fmt` on a wide CSV.
pub fn push_number(out: &mut String, v: f64) {
    // Integers (signal values, enumeration positions) as integers: most cells of a wide CSV.
    if v.fract() == 0.0 && v.abs() < 1e15 {
        if v == 0.0 && v.is_sign_negative() {
            out.push('-');
        }
        out.push_str(itoa::Buffer::new().format(v as i64));
        return;
    }
    if v == 0.0 || !v.is_finite() {
        use std::fmt::Write as _;
        // Writing to a String cannot fail.
        let _ = write!(out, "{v}");
        return;
    }
    let mut buffer = zmij::Buffer::new();
    let mut digits = [0u8; 24];
    let (len, exponent) = shortest_digits(buffer.format_finite(v.abs()), &mut digits);
    let digits = &digits[..len];
    if v < 0.0 {
        out.push('-');
    }
    if (1e-5..1e16).contains(&v.abs()) {
        push_plain(out, digits, exponent);
    } else {
        push_ascii(out, &digits[..1]);
        if digits.len() > 1 {
            out.push('.');
            push_ascii(out, &digits[1..]);
        }
        out.push('e');
        out.push_str(itoa::Buffer::new().format(exponent));
    }
}

/// The significant digits (no leading or trailing zeros) of a positive number as `zmij`
/// prints it (`12.34`, `0.001234`, `12340000000.0`, `1.234e+33`, `5e-7`), into `digits`: how
/// many, and the decimal exponent of the first one. (At most 17 significant digits.)
fn shortest_digits(text: &str, digits: &mut [u8; 24]) -> (usize, i32) {
    let (mantissa, exp) = match text.split_once(['e', 'E']) {
        Some((m, e)) => (m, e.trim_start_matches('+').parse::<i32>().unwrap_or(0)),
        None => (text, 0),
    };
    let int_len = mantissa.find('.').unwrap_or(mantissa.len()) as i32;
    let mut len = 0;
    let mut leading = 0;
    for b in mantissa.bytes().filter(|&b| b != b'.') {
        if len == 0 && b == b'0' {
            leading += 1;
        } else if len < digits.len() {
            digits[len] = b;
            len += 1;
        }
    }
    while len > 1 && digits[len - 1] == b'0' {
        len -= 1;
    }
    (len, exp + int_len - 1 - leading)
}

/// ASCII digits appended to `out`.
fn push_ascii(out: &mut String, digits: &[u8]) {
    // ASCII digits are UTF-8; one copy instead of a push per character.
    if let Ok(text) = std::str::from_utf8(digits) {
        out.push_str(text);
    }
}

/// `digits` with the first at decimal `exponent`, written without an exponent.
fn push_plain(out: &mut String, digits: &[u8], exponent: i32) {
    if exponent < 0 {
        out.push_str("0.");
        out.extend(std::iter::repeat_n('0', (-exponent - 1) as usize));
        push_ascii(out, digits);
        return;
    }
    let int_len = exponent as usize + 1;
    if digits.len() <= int_len {
        push_ascii(out, digits);
        out.extend(std::iter::repeat_n('0', int_len - digits.len()));
    } else {
        push_ascii(out, &digits[..int_len]);
        out.push('.');
        push_ascii(out, &digits[int_len..]);
    }
}

fn field(name: &str) -> String {
    if name.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", name.replace('"', "\"\""))
    } else {
        name.to_string()
    }
}

/// CSV written row by row as a run accepts its points ([`write_csv`] for a whole record):
/// the header on creation, one line per [`row`](Self::row), an optional closing comment line
/// (a partial run's `# partial: ...`) on [`finish`](Self::finish).
pub struct CsvWriter<W: Write> {
    out: W,
    /// The line being built, reused.
    line: String,
    /// Per cell of a line (the time, then each column): the bits of the last value written
    /// and its text, reused while the value repeats (most cells of an event-heavy run: the
    /// before/after rows of an event share their time and quantities, and most signals keep
    /// their values).
    cells: Vec<(Option<u64>, String)>,
}

impl<W: Write> CsvWriter<W> {
    /// Writes the header `time,<names>` for `columns`.
    pub fn new(mut out: W, columns: &[Column]) -> io::Result<Self> {
        let mut header = String::from("time");
        for column in columns {
            header.push(',');
            header.push_str(&field(&column.name));
        }
        header.push('\n');
        out.write_all(header.as_bytes())?;
        Ok(CsvWriter {
            out,
            line: String::new(),
            cells: vec![(None, String::new()); columns.len() + 1],
        })
    }

    /// One line: the time, then `values` in column order.
    pub fn row(&mut self, time: f64, values: impl IntoIterator<Item = f64>) -> io::Result<()> {
        let line = &mut self.line;
        line.clear();
        let mut cells = self.cells.iter_mut();
        for (k, v) in std::iter::once(time).chain(values).enumerate() {
            if k > 0 {
                line.push(',');
            }
            match cells.next() {
                Some((bits, text)) => {
                    if *bits != Some(v.to_bits()) {
                        text.clear();
                        push_number(text, v);
                        *bits = Some(v.to_bits());
                    }
                    line.push_str(text);
                }
                None => push_number(line, v),
            }
        }
        line.push('\n');
        self.out.write_all(line.as_bytes())
    }

    /// Writes `# <comment>` as the last line, if given, and gives the output back.
    pub fn finish(mut self, comment: Option<&str>) -> io::Result<W> {
        if let Some(c) = comment {
            writeln!(self.out, "# {c}")?;
        }
        Ok(self.out)
    }
}

/// Writes `waveforms` as CSV.
pub fn write_csv(out: &mut impl Write, waveforms: &Waveforms) -> io::Result<()> {
    let mut writer = CsvWriter::new(out, &waveforms.columns)?;
    for (k, &t) in waveforms.times.iter().enumerate() {
        // `Waveforms`' invariant: every column has one value per time point.
        let values = waveforms.columns.iter().map(|c| c.values.get(k).copied());
        writer.row(t, values.map(|v| v.unwrap_or(f64::NAN)))?;
    }
    writer.finish(None).map(|_| ())
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use vams_design::Type;
    use vams_simulation::waveform::ColumnKind;

    /// A small record: a decaying voltage, a boolean, a std_ulogic and a three-state enum.
    pub(crate) fn synthetic() -> Waveforms {
        let times: Vec<f64> = vec![0.0, 1e-3, 2e-3, 2e-3, 0.1, 1.0 / 3.0];
        let n = times.len();
        let std = [
            "'U'", "'X'", "'0'", "'1'", "'Z'", "'W'", "'L'", "'H'", "'-'",
        ];
        Waveforms {
            columns: vec![
                Column {
                    name: "vout".into(),
                    kind: ColumnKind::Quantity {
                        unit: Some("V".into()),
                    },
                    values: times.iter().map(|t| 12.0 * (-t / 0.05f64).exp()).collect(),
                },
                Column {
                    name: "dut.u_ic.ov".into(),
                    kind: ColumnKind::Signal { ty: Type::Boolean },
                    values: vec![0.0, 0.0, 0.0, 1.0, 1.0, 0.0],
                },
                Column {
                    name: "dut.u_ic.en".into(),
                    kind: ColumnKind::Signal {
                        ty: Type::Enum {
                            name: "std_ulogic".into(),
                            literals: std.iter().map(|s| s.to_string()).collect(),
                        },
                    },
                    values: vec![0.0, 2.0, 3.0, 4.0, 7.0, 7.0],
                },
                Column {
                    name: "dut.state".into(),
                    kind: ColumnKind::Signal {
                        ty: Type::Enum {
                            name: "state_t".into(),
                            literals: vec!["idle".into(), "up".into(), "down".into()],
                        },
                    },
                    values: vec![0.0, 1.0, 1.0, 2.0, 0.0, 0.0],
                },
                Column {
                    name: "dut.u_motor.i".into(),
                    kind: ColumnKind::Quantity {
                        unit: Some("A".into()),
                    },
                    values: (0..n).map(|k| 1e-9 * k as f64 - 2e-9).collect(),
                },
            ],
            times,
        }
    }

    #[test]
    fn numbers_round_trip_exactly() {
        for v in [
            0.0,
            1.0,
            -2.5,
            1.0 / 3.0,
            1e-300,
            6.02214076e23,
            1e-5,
            9.999999e-6,
            123456.789,
            f64::MIN_POSITIVE,
            f64::MAX,
        ] {
            let text = format_number(v);
            assert_eq!(text.parse::<f64>().unwrap(), v, "{text}");
        }
        assert_eq!(format_number(1.0), "1");
        assert_eq!(format_number(0.0125), "0.0125");
        assert_eq!(format_number(1e-9), "1e-9");
    }

    /// The text Rust's formatting gives, which `push_number` reproduces faster (up to the
    /// choice between two shortest digit strings).
    fn reference_format(v: f64) -> String {
        if v == 0.0 || !v.is_finite() || (1e-5..1e16).contains(&v.abs()) {
            format!("{v}")
        } else {
            format!("{v:e}")
        }
    }

    #[test]
    fn numbers_are_written_as_rust_formats_them() {
        let mut samples = vec![
            1e-5,
            9.999999999999999e-6,
            1e16,
            9999999999999998.0,
            0.1,
            0.3,
            5e-324,
            1e300,
            123456789.125,
            1e15,
            2.5e-7,
            100.0,
            1e21,
            -0.0,
            f64::NAN,
            f64::INFINITY,
        ];
        // Every binade, with random mantissas, and short decimals of every magnitude
        // (a fixed linear congruential sequence: the same cases on every run).
        let mut state: u64 = 0x2545_f491_4f6c_dd1d;
        let mut next = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1);
            state
        };
        for _ in 0..200_000 {
            let bits = next();
            let v = f64::from_bits(bits & !(0x7ff << 52) | ((next() % 2046 + 1) << 52));
            samples.push(if bits % 2 == 0 { v } else { -v });
            let short = (next() % 100_000) as f64 * 10f64.powi((next() % 60) as i32 - 30);
            samples.push(short);
        }
        let mut same = 0;
        let total = samples.len();
        for v in samples {
            let (text, rust) = (format_number(v), reference_format(v));
            if v.is_nan() {
                assert_eq!(text, "NaN");
                continue;
            }
            // Reads back exactly, in the same form (plain or scientific), as short as Rust's.
            // Where two shortest digit strings read back alike (`...592.2` and `...592.3`),
            // zmij and core::fmt may pick differently.
            assert_eq!(
                text.parse::<f64>().unwrap().to_bits(),
                v.to_bits(),
                "{v:?}: {text}"
            );
            assert_eq!(
                text.contains('e'),
                rust.contains('e'),
                "{v:?}: {text} vs {rust}"
            );
            assert!(text.len() <= rust.len(), "{v:?}: {text} vs {rust}");
            same += usize::from(text == rust);
        }
        assert!(
            same * 1000 >= total * 999,
            "{same} of {total} as Rust writes them"
        );
    }

    #[test]
    fn header_then_one_row_per_time_point() {
        let wf = synthetic();
        let mut out = Vec::new();
        write_csv(&mut out, &wf).unwrap();
        let text = String::from_utf8(out).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines[0],
            "time,vout,dut.u_ic.ov,dut.u_ic.en,dut.state,dut.u_motor.i"
        );
        assert_eq!(lines.len(), 1 + wf.times.len());
        for (k, line) in lines[1..].iter().enumerate() {
            let cells: Vec<f64> = line.split(',').map(|c| c.parse().unwrap()).collect();
            assert_eq!(cells[0], wf.times[k]);
            for (c, column) in wf.columns.iter().enumerate() {
                assert_eq!(cells[c + 1], column.values[k], "row {k} column {c}");
            }
        }
        assert!(lines[4].starts_with("0.002,") && lines[4].contains(",1,4,2,"));
    }

    /// Cells whose values repeat reuse their text; the lines are what formatting each number
    /// gives (including -0 after 0, which compare equal but print differently).
    #[test]
    fn repeated_values_are_written_as_formatted() {
        let wf = synthetic();
        let values = [
            [0.5, 1.0],
            [0.5, 1.0],
            [0.0, 2.0],
            [-0.0, 2.0],
            [f64::NAN, 2.0],
        ];
        let mut writer = CsvWriter::new(Vec::new(), &wf.columns[..2]).unwrap();
        let mut expected = String::from("time,vout,dut.u_ic.ov\n");
        for (k, row) in values.iter().enumerate() {
            let t = (k / 2) as f64 * 1e-3;
            writer.row(t, row.iter().copied()).unwrap();
            let cells: Vec<String> = [t, row[0], row[1]].map(format_number).into();
            expected.push_str(&format!("{}\n", cells.join(",")));
        }
        let out = writer.finish(Some("partial: x")).unwrap();
        expected.push_str("# partial: x\n");
        assert_eq!(String::from_utf8(out).unwrap(), expected);
    }

    #[test]
    fn names_with_commas_or_quotes_are_quoted() {
        assert_eq!(field("a,b"), "\"a,b\"");
        assert_eq!(field("say \"hi\""), "\"say \"\"hi\"\"\"");
        assert_eq!(field("plain"), "plain");
    }
}
