//! Reading oscilloscope exports: CSV text in, three sample vectors (time, voltage, current) out.
//!
//! Tolerates what scope exports contain: metadata lines before the header, a units row after
//! it (whose SI prefixes, e.g. `mA`, `ms`, scale the samples), `;`, tab or `,` separators
//! (with `;` and tab, a decimal comma is accepted), quoted fields, trailing empty columns.
//! Columns are found by name, case-insensitively, also as `name (unit)` or `name[unit]`.
//! It never interprets the samples: offsets, noise and physics are the caller's business.

use super::error::{BadRow, ExtractError, MissingColumn};
use miette::NamedSource;
use std::path::{Path, PathBuf};

/// The fewest samples a capture may have.
pub const MIN_SAMPLES: usize = 32;

/// The column names of a capture file.
#[derive(Debug, Clone)]
pub struct Columns {
    /// Name of the time column (seconds).
    pub time: String,
    /// Name of the voltage column (volts).
    pub voltage: String,
    /// Name of the current column (amperes).
    pub current: String,
}

impl Default for Columns {
    fn default() -> Self {
        Columns {
            time: "time".into(),
            voltage: "voltage".into(),
            current: "current".into(),
        }
    }
}

/// One capture: samples in SI units, time increasing.
#[derive(Debug, Clone, Default)]
pub struct Capture {
    /// Which experiment: `inrush`, `blocked`, `speed` or `coast`.
    pub role: &'static str,
    /// The file it came from (for diagnostics).
    pub path: PathBuf,
    /// Time, s.
    pub t: Vec<f64>,
    /// Terminal voltage, V.
    pub v: Vec<f64>,
    /// Current, A.
    pub i: Vec<f64>,
}

impl Capture {
    /// Number of samples.
    pub fn len(&self) -> usize {
        self.t.len()
    }

    /// Whether there are no samples.
    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }

    /// The mean sampling interval, s.
    pub fn dt(&self) -> f64 {
        match (self.t.first(), self.t.last()) {
            (Some(a), Some(b)) if self.t.len() > 1 => (b - a) / (self.t.len() - 1) as f64,
            _ => 0.0,
        }
    }
}

/// Reads and parses a capture file.
pub fn read_capture(
    role: &'static str,
    path: &Path,
    cols: &Columns,
) -> Result<Capture, ExtractError> {
    let text = std::fs::read_to_string(path).map_err(|source| ExtractError::Io {
        role,
        path: path.to_path_buf(),
        source,
    })?;
    parse_capture(role, path, &text, cols)
}

fn clean(field: &str) -> String {
    field
        .trim()
        .trim_matches('"')
        .trim_matches('\'')
        .trim()
        .to_lowercase()
}

/// Whether a header field names `wanted` (exactly, or followed by a unit).
fn names(field: &str, wanted: &str) -> bool {
    let f = clean(field);
    let w = wanted.trim().to_lowercase();
    f == w
        || f.strip_prefix(&w)
            .is_some_and(|rest| rest.starts_with([' ', '(', '[', '/']))
}

fn split(line: &str, sep: char) -> Vec<&str> {
    line.split(sep).collect()
}

fn number(field: &str, decimal_comma: bool) -> Option<f64> {
    let f = field.trim().trim_matches('"').trim();
    if f.is_empty() {
        return None;
    }
    let v = if decimal_comma {
        f.replace(',', ".").parse::<f64>().ok()
    } else {
        f.parse::<f64>().ok()
    };
    v.filter(|x| x.is_finite())
}

/// Scale of an SI-prefixed unit (`ms` -> 1e-3); 1 when unknown.
fn unit_scale(unit: &str) -> f64 {
    let u = unit.trim().trim_matches(['"', '(', ')', '[', ']']).trim();
    let mut chars = u.chars();
    let (Some(first), rest) = (chars.next(), chars.as_str()) else {
        return 1.0;
    };
    if !matches!(rest, "s" | "V" | "A") {
        return 1.0;
    }
    match first {
        'm' => 1e-3,
        'u' | 'µ' | 'μ' => 1e-6,
        'n' => 1e-9,
        'k' => 1e3,
        _ => 1.0,
    }
}

/// The unit written in a header field, as in `current (mA)` or `current[mA]`.
fn header_unit(field: &str) -> Option<String> {
    let f = field.trim().trim_matches('"');
    let open = f.find(['(', '['])?;
    Some(f[open..].to_string())
}

/// The first line that is a data row for some separator, with that separator.
fn find_data(lines: &[(usize, &str)]) -> Option<(usize, char, bool)> {
    for (idx, (_, line)) in lines.iter().enumerate() {
        for (sep, comma) in [(';', true), ('\t', true), (',', false)] {
            let fields = split(line, sep);
            let nonempty: Vec<&&str> = fields.iter().filter(|f| !f.trim().is_empty()).collect();
            if nonempty.len() >= 2 && nonempty.iter().all(|f| number(f, comma).is_some()) {
                return Some((idx, sep, comma));
            }
        }
    }
    None
}

/// Parses the text of a capture (see the module header for what is tolerated).
pub fn parse_capture(
    role: &'static str,
    path: &Path,
    text: &str,
    cols: &Columns,
) -> Result<Capture, ExtractError> {
    let path_buf = path.to_path_buf();
    // Lines with their byte offsets, for labels.
    let mut lines = Vec::new();
    let mut offset = 0;
    for raw in text.split_inclusive('\n') {
        let line = raw.trim_end_matches(['\n', '\r']);
        lines.push((offset, line));
        offset += raw.len();
    }
    if lines.iter().all(|(_, l)| l.trim().is_empty()) {
        return Err(ExtractError::Empty {
            role,
            path: path_buf,
        });
    }
    let src = || NamedSource::new(path.display().to_string(), text.to_string());
    let wanted = [
        (&cols.time, "--time-col"),
        (&cols.voltage, "--voltage-col"),
        (&cols.current, "--current-col"),
    ];

    let Some((first_data, sep, comma)) = find_data(&lines) else {
        // A header without samples is a truncated record; text without either is empty.
        let has_header = lines.iter().any(|(_, l)| {
            [',', ';', '\t']
                .iter()
                .any(|&s| split(l, s).iter().any(|f| names(f, &cols.time)))
        });
        return Err(if has_header {
            ExtractError::Truncated {
                role,
                path: path_buf,
                rows: 0,
                min: MIN_SAMPLES,
            }
        } else {
            ExtractError::Empty {
                role,
                path: path_buf,
            }
        });
    };

    // The header: the nearest line above the data holding the time column, else the line
    // above the units row (for the diagnostic).
    let header_idx = (0..first_data)
        .rev()
        .find(|&k| split(lines[k].1, sep).iter().any(|f| names(f, &cols.time)))
        .or_else(|| {
            (0..first_data).rev().find(|&k| {
                let fields = split(lines[k].1, sep);
                fields.len() >= 2 && !fields.iter().all(|f| f.trim().len() <= 3)
            })
        });
    let header: Vec<&str> = header_idx
        .map(|k| split(lines[k].1, sep))
        .unwrap_or_default();
    let mut idx = [0usize; 3];
    for (slot, (name, flag)) in wanted.iter().enumerate() {
        match header.iter().position(|f| names(f, name)) {
            Some(p) => idx[slot] = p,
            None => {
                let found: Vec<String> = header
                    .iter()
                    .map(|f| f.trim().trim_matches('"').to_string())
                    .filter(|f| !f.is_empty())
                    .collect();
                let used: Vec<usize> = idx[..slot].to_vec();
                let suggestion = header
                    .iter()
                    .enumerate()
                    .find(|(p, f)| !used.contains(p) && !f.trim().is_empty())
                    .map(|(_, f)| f.trim().trim_matches('"').to_string())
                    .unwrap_or_else(|| "NAME".into());
                let (off, len) = header_idx
                    .map(|k| (lines[k].0, lines[k].1.len()))
                    .unwrap_or((lines[first_data].0, 0));
                return Err(ExtractError::MissingColumn(Box::new(MissingColumn {
                    role,
                    path: path_buf,
                    column: name.to_string(),
                    found: if found.is_empty() {
                        "no header line".into()
                    } else {
                        found.join(", ")
                    },
                    flag,
                    suggestion,
                    src: src(),
                    span: (off, len).into(),
                })));
            }
        }
    }

    // Units: from the header (`current (mA)`) or from a units row between header and data.
    let mut scale = [1.0f64; 3];
    let header_line = header_idx.unwrap_or(0);
    for (slot, &p) in idx.iter().enumerate() {
        if let Some(u) = header.get(p).and_then(|f| header_unit(f)) {
            scale[slot] = unit_scale(&u);
        }
        for (_, line) in &lines[header_line + 1..first_data] {
            if let Some(f) = split(line, sep).get(p) {
                let s = unit_scale(f);
                if s != 1.0 {
                    scale[slot] = s;
                }
            }
        }
    }

    let mut cap = Capture {
        role,
        path: path_buf.clone(),
        ..Capture::default()
    };
    let needed = idx.iter().copied().max().unwrap_or(0) + 1;
    for (k, &(off, line)) in lines.iter().enumerate().skip(first_data) {
        if line.trim().is_empty() {
            continue;
        }
        let fields = split(line, sep);
        let bad = |reason: String| {
            ExtractError::BadRow(Box::new(BadRow {
                role,
                path: path_buf.clone(),
                line: k + 1,
                reason,
                src: src(),
                span: (off, line.len()).into(),
            }))
        };
        if fields.len() < needed {
            return Err(bad(format!(
                "{} fields where {needed} are needed (truncated line?)",
                fields.len()
            )));
        }
        // A last line without a line end and shorter than its predecessor was cut off.
        let is_last = off + line.len() >= text.trim_end_matches(['\r', '\n']).len();
        if is_last
            && !text.ends_with('\n')
            && k > first_data
            && line.len() + 2 < lines[k - 1].1.len()
        {
            return Err(bad(
                "the last line is shorter than the others and has no line end (truncated file?)"
                    .into(),
            ));
        }
        let mut vals = [0.0; 3];
        for slot in 0..3 {
            vals[slot] = number(fields[idx[slot]], comma)
                .ok_or_else(|| bad(format!("`{}` is not a number", fields[idx[slot]].trim())))?
                * scale[slot];
        }
        if let Some(&last) = cap.t.last() {
            if vals[0] <= last {
                return Err(bad("time does not increase".into()));
            }
        }
        cap.t.push(vals[0]);
        cap.v.push(vals[1]);
        cap.i.push(vals[2]);
    }
    if cap.len() < MIN_SAMPLES {
        return Err(ExtractError::Truncated {
            role,
            path: path_buf,
            rows: cap.len(),
            min: MIN_SAMPLES,
        });
    }
    Ok(cap)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rows(n: usize, sep: &str, dec_comma: bool) -> String {
        (0..n)
            .map(|k| {
                let s = format!("{}{sep}{}{sep}{}{sep}{sep}\n", k as f64 * 1e-3, 1.5, 0.25);
                if dec_comma { s.replace('.', ",") } else { s }
            })
            .collect()
    }

    #[test]
    fn plain_csv() {
        let text = format!("time,voltage,current\n{}", rows(40, ",", false));
        let c = parse_capture("speed", Path::new("a.csv"), &text, &Columns::default()).unwrap();
        assert_eq!(c.len(), 40);
        assert_eq!(c.v[3], 1.5);
    }

    #[test]
    fn metadata_units_semicolons_decimal_comma() {
        let text = format!(
            "Model;DS1054Z\nSample rate;1000\n\"Time\";\"Voltage\";\"Current\";\ns;V;mA;\n{}",
            rows(40, ";", true)
        );
        let c = parse_capture("speed", Path::new("a.csv"), &text, &Columns::default()).unwrap();
        assert_eq!(c.len(), 40);
        assert!((c.t[2] - 2e-3).abs() < 1e-12);
        assert!((c.i[0] - 0.25e-3).abs() < 1e-12);
    }

    #[test]
    fn custom_column_names_with_units() {
        let text = format!("X (s),CH1 [V],CH2 [A]\n{}", rows(40, ",", false));
        let cols = Columns {
            time: "x".into(),
            voltage: "ch1".into(),
            current: "ch2".into(),
        };
        let c = parse_capture("speed", Path::new("a.csv"), &text, &cols).unwrap();
        assert_eq!(c.i[1], 0.25);
    }

    fn render(e: ExtractError) -> String {
        let mut out = String::new();
        let handler =
            miette::GraphicalReportHandler::new_themed(miette::GraphicalTheme::unicode_nocolor())
                .with_width(100);
        handler.render_report(&mut out, &e).unwrap();
        out
    }

    #[test]
    fn missing_column_diagnostic_snapshot() {
        let text = "Model,DS1054Z\nTime,CH1,CH2\ns,V,A\n0,1,2\n1,1,2\n";
        let e = parse_capture(
            "blocked",
            Path::new("blocked.csv"),
            text,
            &Columns::default(),
        )
        .unwrap_err();
        insta::assert_snapshot!(render(e));
    }

    #[test]
    fn truncated_line_diagnostic_snapshot() {
        let text = format!(
            "time,voltage,current\n{}0.04,1.5,0",
            rows(40, ",", false).replace(",,", "")
        );
        let e = parse_capture(
            "inrush",
            Path::new("inrush.csv"),
            &text,
            &Columns::default(),
        )
        .unwrap_err();
        insta::assert_snapshot!(render(e));
    }

    #[test]
    fn diagnoses_missing_column_empty_and_truncated() {
        let p = Path::new("a.csv");
        let cols = Columns::default();
        let text = format!("time,CH1,current\n{}", rows(40, ",", false));
        let e = parse_capture("speed", p, &text, &cols).unwrap_err();
        assert!(matches!(e, ExtractError::MissingColumn(ref m) if m.column == "voltage"));
        assert!(matches!(
            parse_capture("speed", p, "", &cols),
            Err(ExtractError::Empty { .. })
        ));
        let short = format!("time,voltage,current\n{}", rows(5, ",", false));
        assert!(matches!(
            parse_capture("speed", p, &short, &cols),
            Err(ExtractError::Truncated { .. })
        ));
        let cut = format!("time,voltage,current\n{}0.5,1.", rows(40, ",", false));
        assert!(matches!(
            parse_capture("speed", p, &cut, &cols),
            Err(ExtractError::BadRow(ref b)) if b.line == 42
        ));
    }
}
