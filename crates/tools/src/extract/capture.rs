//! The captures of `vams extract`: three sample vectors (time, voltage, current) and the
//! experiment they belong to.
//!
//! [`crate::capture`] reads the file (every layout it accepts, units and their prefixes);
//! this module picks the time, voltage and current columns by name and turns the reader's
//! diagnostics into extraction's, which name the experiment and the flag to give. Clipping
//! is not looked for (the paper's method uses every sample); a scope's infinities are read
//! as the rail. It never interprets the samples: offsets, noise and physics are the caller's
//! business.

use super::error::{BadRow, ExtractError, MissingColumn};
use crate::capture::{self as scope, CaptureError, ReadOptions};
use miette::NamedSource;
use std::path::{Path, PathBuf};

/// The fewest samples a capture may have.
pub const MIN_SAMPLES: usize = scope::MIN_SAMPLES;

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

/// Parses the text of a capture (see [`crate::capture`] for the layouts accepted).
pub fn parse_capture(
    role: &'static str,
    path: &Path,
    text: &str,
    cols: &Columns,
) -> Result<Capture, ExtractError> {
    let opts = ReadOptions {
        time_column: Some(cols.time.clone()),
        required: vec![cols.voltage.clone(), cols.current.clone()],
        detect_clipping: false,
        ..ReadOptions::default()
    };
    let cap = scope::parse(path, text, &opts).map_err(|e| diagnose(role, path, text, cols, e))?;
    let values = |name: &str| {
        cap.channel_or_error(name)
            .map(|c| c.values.clone())
            .map_err(|e| ExtractError::Capture(Box::new(e)))
    };
    let (v, i) = (values(&cols.voltage)?, values(&cols.current)?);
    Ok(Capture {
        role,
        path: path.to_path_buf(),
        t: cap.time,
        v,
        i,
    })
}

#[allow(clippy::too_many_arguments)]
fn missing_column(
    role: &'static str,
    path: &Path,
    text: &str,
    column: &str,
    found: &[String],
    flag: &'static str,
    suggestion: String,
    span: (usize, usize),
) -> ExtractError {
    ExtractError::MissingColumn(Box::new(MissingColumn {
        role,
        path: path.to_path_buf(),
        column: column.to_string(),
        found: if found.is_empty() {
            "no header line".into()
        } else {
            found.join(", ")
        },
        flag,
        suggestion,
        src: NamedSource::new(path.display().to_string(), text.to_string()),
        span: span.into(),
    }))
}

/// The reader's diagnostic as extraction's, naming the experiment.
fn diagnose(
    role: &'static str,
    path: &Path,
    text: &str,
    cols: &Columns,
    e: CaptureError,
) -> ExtractError {
    let path_buf = path.to_path_buf();
    match e {
        CaptureError::Empty { .. }
        | CaptureError::NoData {
            has_header: false, ..
        } => ExtractError::Empty {
            role,
            path: path_buf,
        },
        CaptureError::NoData { .. } => ExtractError::Truncated {
            role,
            path: path_buf,
            rows: 0,
            min: MIN_SAMPLES,
        },
        CaptureError::TooFewSamples { rows, min, .. } => ExtractError::Truncated {
            role,
            path: path_buf,
            rows,
            min,
        },
        CaptureError::MissingChannel(m) => {
            // The columns are looked for in this order; suggest the first header field the
            // ones before the missing one do not take.
            let slots = [
                (&cols.time, "--time-col"),
                (&cols.voltage, "--voltage-col"),
                (&cols.current, "--current-col"),
            ];
            let slot = slots
                .iter()
                .position(|(name, _)| scope::same_name(name, &m.channel))
                .unwrap_or(0);
            let used: Vec<usize> = slots[..slot]
                .iter()
                .filter_map(|(name, _)| m.found.iter().position(|f| scope::same_name(f, name)))
                .collect();
            let suggestion = (0..m.found.len())
                .find(|p| !used.contains(p))
                .map_or_else(|| "NAME".to_string(), |p| m.found[p].clone());
            let span = m.span.map_or((0, 0), |s| (s.offset(), s.len()));
            missing_column(
                role,
                path,
                text,
                &m.channel,
                &m.found,
                slots[slot].1,
                suggestion,
                span,
            )
        }
        CaptureError::BadRow(b) => ExtractError::BadRow(Box::new(BadRow {
            role,
            path: path_buf,
            line: b.line,
            reason: b.reason,
            src: b.src,
            span: b.span,
        })),
        CaptureError::TimeNotIncreasing(n) => ExtractError::BadRow(Box::new(BadRow {
            role,
            path: path_buf,
            line: n.line,
            reason: "time does not increase".into(),
            src: n.src,
            span: n.span,
        })),
        other => ExtractError::Capture(Box::new(other)),
    }
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
