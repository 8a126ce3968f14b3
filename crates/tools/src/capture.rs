//! Oscilloscope captures: the CSV text scopes export in, a time base and named channels in SI
//! units out, with the samples that sat at the ADC's rails marked.
//!
//! Accepted layouts (samples under `tests/captures/`):
//!
//! * generic `time,voltage,current`, with or without a units row (`s,V,mA`), headers
//!   `name (unit)` or `name[unit]`; SI prefixes of the units scale the samples (`ms`, `mA`,
//!   `uV`, `µs`); metadata lines above the header are skipped;
//! * Rigol (DS1000Z): `X,CH1,CH2,Start,Increment,` then `Sequence,Volt,Volt,START,INC,`, rows
//!   of a sample index and values: time = start + index * increment;
//! * Tektronix, older (TDS, TBS, DPO2000): metadata in the first three columns of each row
//!   (`Record Length,2500,,-0.0005,0.02`), time and value in columns 4 and 5, the channel
//!   named by the `Source` row; newer (MSO4/5/6): metadata lines (`Model,MSO44`,
//!   `Vertical Units,V,A`, ...) then `TIME,CH1,CH2`;
//! * Keysight/Agilent InfiniiVision: `x-axis,1,2` then `second,Volt,Volt` (channel `1` is
//!   also found as `CH1`);
//! * PicoScope: `Time,Channel A,Channel B` then `(ms),(V),(mV)`; `∞` and `-∞` (over-range)
//!   are clipped samples.
//!
//! In all of them: `,`, `;` or tab separators (with `;` and tab a decimal comma is accepted),
//! quoted fields, CRLF line ends, a byte-order mark, trailing empty columns and blank lines.
//!
//! Clipping: a channel's samples are clipped where they sit at its overall maximum or minimum
//! in runs of [`MIN_CLIP_RUN`] or more (a real peak lasts a sample or two; a clipped one is
//! flat), and where the scope wrote an infinity. Their values are the rail (never NaN or
//! infinite), `Channel::clipped` marks them, and a [`CaptureWarning`] says where they are. A
//! noise-free record that settles at its maximum looks clipped too:
//! `ReadOptions::detect_clipping` turns the run test off.
//!
//! It never interprets the samples beyond that: offsets, noise and physics are the caller's.
//! It reads one file and never writes.

mod clip;
pub mod error;
mod layout;
mod ops;
mod text;

pub use error::{BadRow, CaptureError, MissingChannel, NotIncreasing};

use layout::TimeSource;
use miette::NamedSource;
use std::path::{Path, PathBuf};
use text::Value;

/// The fewest samples a capture may have.
pub const MIN_SAMPLES: usize = 32;

/// The shortest run of equal samples at a channel's extreme taken as clipping.
pub const MIN_CLIP_RUN: usize = 3;

/// The fraction of clipped samples above which a channel is unusable.
pub const MAX_CLIPPED_FRACTION: f64 = 0.9;

/// How to read a capture.
#[derive(Debug, Clone)]
pub struct ReadOptions {
    /// The time column's name; `None`: a column named `time`, `t`, `x`, `x-axis` or
    /// `second`, else the one whose unit is seconds, else the first.
    pub time_column: Option<String>,
    /// Factors by channel name (`--scale current=0.1`: a 100 mV/A probe read as volts).
    pub scales: Vec<(String, f64)>,
    /// Channels that must be there: checked against the header before any sample is read,
    /// the error pointing at the header line.
    pub required: Vec<String>,
    /// Whether flat runs at a channel's extremes count as clipped (infinities always do).
    pub detect_clipping: bool,
}

impl Default for ReadOptions {
    fn default() -> Self {
        ReadOptions {
            time_column: None,
            scales: Vec::new(),
            required: Vec::new(),
            detect_clipping: true,
        }
    }
}

/// One capture: a time base and channels sampled on it.
#[derive(Debug, Clone, Default)]
pub struct Capture {
    /// The file it came from (for diagnostics).
    pub path: PathBuf,
    /// Time, s, strictly increasing.
    pub time: Vec<f64>,
    /// The channels, in the file's column order; each has one value per time.
    pub channels: Vec<Channel>,
    /// What the reader accepted with (clipped samples).
    pub warnings: Vec<CaptureWarning>,
    /// The header as written.
    pub header: Header,
}

/// One channel of a capture.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Channel {
    /// Its name in the header, without the unit (`CH1`, `Channel A`, `current`).
    pub name: String,
    /// Its SI unit (`V`, `A`) when the file says, else the unit as written.
    pub unit: Option<String>,
    /// Samples in SI units (unit prefix and `--scale` applied), always finite.
    pub values: Vec<f64>,
    /// Whether each sample sat at the ADC's rail.
    pub clipped: Vec<bool>,
}

/// The header line of a capture file.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Header {
    /// Its non-empty fields as written (the time column's included).
    pub names: Vec<String>,
    /// Its byte offset and length in the file's text, when there is one.
    pub span: Option<(usize, usize)>,
}

/// What a capture was accepted with.
#[derive(Debug, Clone, PartialEq, thiserror::Error, miette::Diagnostic)]
pub enum CaptureWarning {
    /// Samples at the ADC's rails.
    #[error(
        "{samples} samples of `{channel}` in `{}` are clipped (from {from:e} s to {to:e} s) and will be excluded",
        path.display()
    )]
    #[diagnostic(
        code(vams::capture::clipped),
        severity(Warning),
        help("increase the volts/div of that channel so the signal fits the screen")
    )]
    Clipped {
        path: PathBuf,
        channel: String,
        samples: usize,
        from: f64,
        to: f64,
    },
}

/// Reads a `--scale NAME=FACTOR` argument (`current=0.1`), as a clap value parser would.
pub fn parse_scale(arg: &str) -> Result<(String, f64), String> {
    let (name, factor) = arg
        .split_once('=')
        .ok_or_else(|| format!("`{arg}` is not NAME=FACTOR (e.g. current=0.1)"))?;
    let name = name.trim();
    if name.is_empty() {
        return Err(format!("`{arg}` names no channel (e.g. current=0.1)"));
    }
    match factor.trim().parse::<f64>() {
        Ok(f) if f.is_finite() && f != 0.0 => Ok((name.to_string(), f)),
        _ => Err(format!(
            "`{}` is not a finite, non-zero factor (e.g. current=0.1)",
            factor.trim()
        )),
    }
}

/// Reads and parses a capture file.
pub fn read(path: &Path, opts: &ReadOptions) -> Result<Capture, CaptureError> {
    let text = std::fs::read_to_string(path).map_err(|source| CaptureError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    parse(path, &text, opts)
}

/// Whether two column names are the same by [`Capture::channel`]'s rule.
pub fn same_name(a: &str, b: &str) -> bool {
    text::key(a) == text::key(b)
}

/// The closest of `names` to `wanted`, if close enough to suggest.
pub fn closest<'a>(wanted: &str, names: impl Iterator<Item = &'a str>) -> Option<String> {
    let w = text::key(wanted);
    let number = |k: &str| {
        k.trim_start_matches(|c: char| !c.is_ascii_digit())
            .to_string()
    };
    names
        .map(|n| (text::key(n), n))
        // `ch3` is not a misspelt `ch1`.
        .filter(|(k, _)| number(k) == number(&w))
        .map(|(k, n)| (strsim::levenshtein(&w, &k), n))
        .filter(|(d, _)| *d <= (w.chars().count() / 3).max(1))
        .min_by_key(|(d, _)| *d)
        .map(|(_, n)| n.to_string())
}

/// Parses the text of a capture read from `path` (see the module header for the layouts).
pub fn parse(path: &Path, text: &str, opts: &ReadOptions) -> Result<Capture, CaptureError> {
    let lines = text::lines(text);
    if lines.iter().all(|l| l.is_blank()) {
        return Err(CaptureError::Empty {
            path: path.to_path_buf(),
        });
    }
    let layout = layout::layout(path, text, &lines, opts)?;
    if layout.columns.is_empty() {
        return Err(CaptureError::NoData {
            path: path.to_path_buf(),
            what: "a time column but no channel",
            has_header: true,
        });
    }
    for name in &opts.required {
        let k = text::key(name);
        if !layout.columns.iter().any(|c| text::key(&c.name) == k) {
            let names = layout.header.names.iter().map(String::as_str);
            return Err(CaptureError::MissingChannel(Box::new(MissingChannel {
                path: path.to_path_buf(),
                channel: name.clone(),
                found: layout.header.names.clone(),
                suggestion: closest(name, names),
                src: Some(NamedSource::new(
                    path.display().to_string(),
                    text.to_string(),
                )),
                span: Some(layout.header.span.unwrap_or((0, 0)).into()),
            })));
        }
    }
    let mut scales = vec![1.0; layout.columns.len()];
    let mut time_factor = 1.0;
    for (name, factor) in &opts.scales {
        let k = text::key(name);
        if let Some(c) = layout.columns.iter().position(|c| text::key(&c.name) == k) {
            scales[c] *= factor;
        } else if text::key(&layout.time_name) == k {
            time_factor *= factor;
        } else {
            let names: Vec<&str> = layout.columns.iter().map(|c| c.name.as_str()).collect();
            return Err(CaptureError::UnknownScale {
                path: path.to_path_buf(),
                channel: name.clone(),
                found: names.join(", "),
                suggestion: closest(name, names.iter().copied()),
            });
        }
    }

    let mut cap = Capture {
        path: path.to_path_buf(),
        time: Vec::with_capacity(lines.len() - layout.first_data),
        channels: layout
            .columns
            .iter()
            .map(|c| Channel {
                name: c.name.clone(),
                unit: c.unit.clone(),
                values: Vec::with_capacity(lines.len() - layout.first_data),
                clipped: Vec::with_capacity(lines.len() - layout.first_data),
            })
            .collect(),
        warnings: Vec::new(),
        header: layout.header.clone(),
    };
    rows(path, text, &lines, &layout, &scales, time_factor, &mut cap)?;
    if cap.time.len() < MIN_SAMPLES {
        return Err(CaptureError::TooFewSamples {
            path: path.to_path_buf(),
            rows: cap.time.len(),
            min: MIN_SAMPLES,
        });
    }
    clip::mark(&mut cap, opts.detect_clipping)?;
    Ok(cap)
}

/// Reads the data rows into `cap`.
fn rows(
    path: &Path,
    text: &str,
    lines: &[text::Line],
    layout: &layout::Layout,
    scales: &[f64],
    time_factor: f64,
    cap: &mut Capture,
) -> Result<(), CaptureError> {
    let src = || NamedSource::new(path.display().to_string(), text.to_string());
    let needed = layout
        .columns
        .iter()
        .map(|c| c.index)
        .chain([layout.time.index()])
        .max()
        .unwrap_or(0)
        + 1;
    let body_end = text.trim_end_matches(['\r', '\n']).len();
    let mut fields = Vec::with_capacity(needed + 2);
    let mut previous_len = 0;
    for (k, line) in lines.iter().enumerate().skip(layout.first_data) {
        if line.is_blank() {
            continue;
        }
        let bad = |reason: String, span: (usize, usize)| {
            CaptureError::BadRow(Box::new(BadRow {
                path: path.to_path_buf(),
                line: k + 1,
                reason,
                src: src(),
                span: (line.offset + span.0, span.1 - span.0).into(),
            }))
        };
        let whole = (0, line.text.len());
        text::split_into(line.text, layout.sep, &mut fields);
        if fields.len() < needed {
            return Err(bad(
                format!(
                    "{} fields where {needed} are needed (truncated line?)",
                    fields.len()
                ),
                whole,
            ));
        }
        // A last line without a line end and shorter than its predecessor was cut off.
        if line.offset + line.text.len() >= body_end
            && !text.ends_with('\n')
            && previous_len > 0
            && line.text.len() + 2 < previous_len
        {
            return Err(bad(
                "the last line is shorter than the others and has no line end (truncated file?)"
                    .into(),
                whole,
            ));
        }
        previous_len = line.text.len();
        let number = |index: usize| -> Result<Value, CaptureError> {
            let (a, b) = fields[index];
            let f = &line.text[a..b];
            text::value(f, layout.decimal_comma).ok_or_else(|| {
                let what = text::clean(f);
                bad(
                    if what.is_empty() {
                        format!("no value in column {}", index + 1)
                    } else {
                        format!("`{what}` is not a number")
                    },
                    (a, b),
                )
            })
        };
        let ti = layout.time.index();
        let t = match number(ti)? {
            Value::Number(x) => match layout.time {
                TimeSource::Column { scale, .. } => x * scale * time_factor,
                TimeSource::Index {
                    start, increment, ..
                } => (start + x * increment) * time_factor,
            },
            Value::Infinite(_) => {
                return Err(bad("the time is infinite".into(), fields[ti]));
            }
        };
        if let Some(&previous) = cap.time.last() {
            if t.partial_cmp(&previous) != Some(std::cmp::Ordering::Greater) {
                let (a, b) = fields[ti];
                return Err(CaptureError::TimeNotIncreasing(Box::new(
                    error::NotIncreasing {
                        path: path.to_path_buf(),
                        line: k + 1,
                        time: t,
                        previous,
                        src: src(),
                        span: (line.offset + a, b - a).into(),
                    },
                )));
            }
        }
        if !t.is_finite() {
            return Err(bad("the time is out of range".into(), fields[ti]));
        }
        cap.time.push(t);
        for ((col, ch), scale) in layout.columns.iter().zip(&mut cap.channels).zip(scales) {
            let (v, clipped) = match number(col.index)? {
                Value::Number(x) => {
                    let v = x * col.scale * scale;
                    if !v.is_finite() {
                        return Err(bad("the value is out of range".into(), fields[col.index]));
                    }
                    (v, false)
                }
                Value::Infinite(up) => (if up { f64::INFINITY } else { f64::NEG_INFINITY }, true),
            };
            ch.values.push(v);
            ch.clipped.push(clipped);
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests;
