//! Waveforms as CSV: a header `time,<probe names>`, then one row per recorded time point.
//! Numbers are written with the shortest text that reads back to the same `f64`; signals are
//! their numbers (booleans and enumerations as positions). Names are quoted per RFC 4180 when
//! they hold a comma or a quote.

use std::io::{self, Write};

use crate::waveform::Waveforms;

/// The shortest text that parses back to exactly `v`: plain decimals for ordinary magnitudes,
/// scientific notation for very small and very large ones.
pub fn format_number(v: f64) -> String {
    let mut s = String::new();
    push_number(&mut s, v);
    s
}

/// [`format_number`] appended to `out` (no allocation once `out` has grown: a CSV row of a
/// large design is thousands of numbers).
pub fn push_number(out: &mut String, v: f64) {
    use std::fmt::Write as _;
    let magnitude = v.abs();
    // Writing to a String cannot fail.
    let _ = if v == 0.0 || !v.is_finite() || (1e-5..1e16).contains(&magnitude) {
        write!(out, "{v}")
    } else {
        write!(out, "{v:e}")
    };
}

fn field(name: &str) -> String {
    if name.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", name.replace('"', "\"\""))
    } else {
        name.to_string()
    }
}

/// Writes `waveforms` as CSV.
pub fn write_csv(out: &mut impl Write, waveforms: &Waveforms) -> io::Result<()> {
    let mut header = String::from("time");
    for column in &waveforms.columns {
        header.push(',');
        header.push_str(&field(&column.name));
    }
    writeln!(out, "{header}")?;
    let mut row = String::new();
    for (k, &t) in waveforms.times.iter().enumerate() {
        row.clear();
        push_number(&mut row, t);
        for column in &waveforms.columns {
            row.push(',');
            // `Waveforms`' invariant: every column has one value per time point.
            let v = column.values.get(k).copied().unwrap_or(f64::NAN);
            push_number(&mut row, v);
        }
        row.push('\n');
        out.write_all(row.as_bytes())?;
    }
    Ok(())
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::design::Type;
    use crate::waveform::{Column, ColumnKind};

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

    #[test]
    fn names_with_commas_or_quotes_are_quoted() {
        assert_eq!(field("a,b"), "\"a,b\"");
        assert_eq!(field("say \"hi\""), "\"say \"\"hi\"\"\"");
        assert_eq!(field("plain"), "plain");
    }
}
