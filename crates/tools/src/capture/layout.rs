//! Where a capture's samples are: the separator, the first data line, the time column (or
//! Rigol's sample index with its start and increment) and the channel columns with their
//! names and units. Decided from the lines above the data, never from the samples.

use super::error::{CaptureError, MissingChannel};
use super::text::{self, Line, clean, is_number, key, name_and_unit, split, unit};
use super::{Header, ReadOptions};
use miette::NamedSource;
use std::path::Path;

/// How a row gives its time.
#[derive(Debug, Clone, Copy)]
pub(super) enum TimeSource {
    /// A column of times, multiplied by `scale` (its unit's prefix).
    Column { index: usize, scale: f64 },
    /// A column of sample indices: time = start + index * increment (Rigol).
    Index {
        index: usize,
        start: f64,
        increment: f64,
    },
}

impl TimeSource {
    pub fn index(&self) -> usize {
        match *self {
            TimeSource::Column { index, .. } | TimeSource::Index { index, .. } => index,
        }
    }
}

/// A channel's column.
#[derive(Debug, Clone)]
pub(super) struct Column {
    pub name: String,
    pub index: usize,
    pub unit: Option<String>,
    pub scale: f64,
}

/// Where the samples are.
#[derive(Debug)]
pub(super) struct Layout {
    pub sep: u8,
    pub decimal_comma: bool,
    pub first_data: usize,
    pub time: TimeSource,
    /// The time column's name (without its unit).
    pub time_name: String,
    pub columns: Vec<Column>,
    pub header: Header,
}

const SEPARATORS: [(u8, bool); 3] = [(b';', true), (b'\t', true), (b',', false)];

/// Names a time column goes by when `--time-col` is not given.
const TIME_NAMES: [&str; 7] = ["time", "t", "x", "x-axis", "second", "seconds", "sec"];

fn is_data(line: &Line, sep: u8, comma: bool) -> bool {
    let mut nonempty = 0;
    for f in split(line.text, sep) {
        if f.trim().is_empty() {
            continue;
        }
        if !is_number(f, comma) {
            return false;
        }
        nonempty += 1;
    }
    nonempty >= 2
}

/// The first data line (followed by another data line, or the last one), its separator and
/// whether it uses decimal commas.
fn find_data(lines: &[Line]) -> Option<(usize, u8, bool)> {
    let mut single = None;
    for (k, line) in lines.iter().enumerate() {
        if line.is_blank() {
            continue;
        }
        for (sep, comma) in SEPARATORS {
            if !is_data(line, sep, comma) {
                continue;
            }
            let next = lines[k + 1..].iter().find(|l| !l.is_blank());
            match next {
                Some(n) if !is_data(n, sep, comma) => single = single.or(Some((k, sep, comma))),
                _ => return Some((k, sep, comma)),
            }
        }
    }
    single
}

/// Whether a line is a units row: `s,V,mA`, `(ms),(V),(mV)`, `second,Volt,Volt`.
fn is_units_row(fields: &[&str]) -> bool {
    let mut units = 0;
    for f in fields {
        let c = clean(f);
        if c.is_empty() {
            continue;
        }
        let wrapped =
            (c.starts_with('(') && c.ends_with(')')) || (c.starts_with('[') && c.ends_with(']'));
        if unit(c).is_some() || wrapped {
            units += 1;
        } else if !c.eq_ignore_ascii_case("sequence") {
            return false;
        }
    }
    units > 0
}

/// The nearest non-blank line above `k`.
fn above(lines: &[Line], k: usize) -> Option<usize> {
    (0..k).rev().find(|&j| !lines[j].is_blank())
}

fn first_field<'a>(line: &Line<'a>) -> &'a str {
    let end = line.text.find([',', ';', '\t']).unwrap_or(line.text.len());
    clean(&line.text[..end])
}

/// Decides the layout of `text` (split into `lines`).
pub(super) fn layout(
    path: &Path,
    text: &str,
    lines: &[Line],
    opts: &ReadOptions,
) -> Result<Layout, CaptureError> {
    let first = lines.iter().find(|l| !l.is_blank());
    if first.is_some_and(|l| first_field(l).eq_ignore_ascii_case("record length")) {
        return Ok(tektronix_tds(lines));
    }
    let Some((first_data, sep, comma)) = find_data(lines) else {
        return Err(no_data(path, lines, opts));
    };

    // The header and units rows just above the data.
    let l1 = above(lines, first_data);
    let l0 = l1.and_then(|k| above(lines, k));
    let fields = |k: usize| split(lines[k].text, sep);
    let mut rigol = None;
    let (mut header_idx, units_idx) = match (l0, l1) {
        (Some(h), Some(u)) => {
            let hf = fields(h);
            let uf = fields(u);
            let pos = |name: &str| hf.iter().position(|f| clean(f).eq_ignore_ascii_case(name));
            let num = |p: Option<usize>| {
                p.and_then(|p| uf.get(p))
                    .and_then(|f| text::value(f, comma))
                    .and_then(|v| match v {
                        text::Value::Number(x) => Some(x),
                        text::Value::Infinite(_) => None,
                    })
            };
            if let (Some(start), Some(increment)) = (num(pos("start")), num(pos("increment"))) {
                rigol = Some((start, increment));
                (Some(h), Some(u))
            } else if is_units_row(&uf) {
                (Some(h), Some(u))
            } else {
                (Some(u), None)
            }
        }
        (None, Some(u)) if is_units_row(&fields(u)) => (None, Some(u)),
        (None, Some(h)) => (Some(h), None),
        _ => (None, None),
    };
    // A requested time column above the header found (metadata between them).
    if let Some(want) = &opts.time_column {
        let kw = key(want);
        let has = |k: usize| fields(k).iter().any(|f| key(f) == kw);
        if !header_idx.is_some_and(has) {
            if let Some(k) = (0..first_data).rev().find(|&k| has(k)) {
                header_idx = Some(k);
            }
        }
    }

    let header_fields: Vec<&str> = header_idx.map(fields).unwrap_or_default();
    let units_fields: Vec<&str> = units_idx.map(fields).unwrap_or_default();
    let header = Header {
        names: header_fields
            .iter()
            .map(|f| clean(f).to_string())
            .filter(|f| !f.is_empty())
            .collect(),
        span: header_idx.map(|k| (lines[k].offset, lines[k].text.len())),
    };
    let meta = metadata_units(lines, header_idx.unwrap_or(first_data), sep);
    let data_fields = fields(first_data);
    let width = data_fields.len().max(header_fields.len());

    // Name, unit and scale of every column.
    let describe = |k: usize| -> (String, Option<String>, f64) {
        let (name, mut u) = match header_fields.get(k) {
            Some(f) => name_and_unit(f),
            None if header_idx.is_none() => (format!("column {}", k + 1), None),
            None => (String::new(), None),
        };
        if let Some(uu) = units_fields.get(k).and_then(|f| unit(f)) {
            u = Some(uu);
        }
        if u.is_none() {
            u = meta.get(k).copied().flatten();
        }
        let unit_text = match (u, units_fields.get(k)) {
            (Some((sym, _)), _) => Some(sym.to_string()),
            (None, Some(f)) if !clean(f).is_empty() && rigol.is_none() => {
                Some(clean(f).trim_matches(['(', ')', '[', ']']).to_string())
            }
            _ => None,
        };
        (name, unit_text, u.map_or(1.0, |(_, s)| s))
    };

    // The time column.
    let time_index = match &opts.time_column {
        Some(want) => {
            let kw = key(want);
            match (0..width).find(|&k| header_fields.get(k).is_some_and(|f| key(f) == kw)) {
                Some(k) => k,
                None if header_idx.is_none() && kw == "column1" => 0,
                None => {
                    return Err(CaptureError::MissingChannel(Box::new(MissingChannel {
                        path: path.to_path_buf(),
                        channel: want.clone(),
                        suggestion: super::closest(want, header.names.iter().map(String::as_str)),
                        found: header.names.clone(),
                        src: Some(NamedSource::new(
                            path.display().to_string(),
                            text.to_string(),
                        )),
                        span: Some(header.span.unwrap_or((lines[first_data].offset, 0)).into()),
                    })));
                }
            }
        }
        None => (0..width)
            .find(|&k| {
                header_fields
                    .get(k)
                    .is_some_and(|f| TIME_NAMES.contains(&key(f).as_str()))
            })
            .or_else(|| (0..width).find(|&k| describe(k).1.as_deref() == Some("s")))
            .unwrap_or(0),
    };
    let time_name = describe(time_index).0;
    let time_key = key(&time_name);
    let time = match rigol {
        Some((start, increment)) => TimeSource::Index {
            index: time_index,
            start,
            increment,
        },
        None => TimeSource::Column {
            index: time_index,
            scale: describe(time_index).2,
        },
    };

    let mut columns = Vec::new();
    for k in 0..width {
        if k == time_index {
            continue;
        }
        let (name, unit, scale) = describe(k);
        let nk = key(&name);
        let meta_column = rigol.is_some() && (nk == "start" || nk == "increment");
        let numeric = data_fields.get(k).is_some_and(|f| is_number(f, comma));
        if name.is_empty() || nk == time_key || meta_column || !numeric {
            continue;
        }
        columns.push(Column {
            name,
            index: k,
            unit,
            scale,
        });
    }
    Ok(Layout {
        sep,
        decimal_comma: comma,
        first_data,
        time,
        time_name,
        columns,
        header,
    })
}

/// Units from Tektronix metadata rows above the header (`Vertical Units,V,A`, aligned with
/// the columns; `Horizontal Units,s` for the time column).
fn metadata_units(lines: &[Line], end: usize, sep: u8) -> Vec<Option<(&'static str, f64)>> {
    let mut out: Vec<Option<(&'static str, f64)>> = Vec::new();
    for line in &lines[..end] {
        let f = split(line.text, sep);
        let Some(name) = f.first().map(|n| clean(n)) else {
            continue;
        };
        if name.eq_ignore_ascii_case("vertical units") {
            out.resize(out.len().max(f.len()), None);
            for (k, u) in f.iter().enumerate().skip(1) {
                if out[k].is_none() {
                    out[k] = unit(u);
                }
            }
        } else if name.eq_ignore_ascii_case("horizontal units") {
            if out.is_empty() {
                out.push(None);
            }
            out[0] = f.get(1).and_then(|u| unit(u));
        }
    }
    out
}

/// The older Tektronix layout (TDS, DPO2000, TBS): metadata in the first three columns of
/// each row (`Record Length,2500,,-0.0005,0.02`), time and value in columns 4 and 5.
fn tektronix_tds(lines: &[Line]) -> Layout {
    let first = lines.iter().position(|l| !l.is_blank()).unwrap_or(0);
    let sep = SEPARATORS
        .iter()
        .map(|s| s.0)
        .find(|&s| lines[first].text.as_bytes().contains(&s))
        .unwrap_or(b',');
    let comma = sep != b',';
    let mut name = "CH1".to_string();
    let (mut vunit, mut hunit) = (None, None);
    for line in lines {
        let f = split(line.text, sep);
        let (Some(k), Some(v)) = (f.first().map(|x| clean(x)), f.get(1).map(|x| clean(x))) else {
            continue;
        };
        if k.eq_ignore_ascii_case("source") && !v.is_empty() {
            name = v.to_string();
        } else if k.eq_ignore_ascii_case("vertical units") {
            vunit = unit(v);
        } else if k.eq_ignore_ascii_case("horizontal units") {
            hunit = unit(v);
        }
    }
    let header = Header {
        names: vec!["time".into(), name.clone()],
        span: None,
    };
    Layout {
        sep,
        decimal_comma: comma,
        first_data: first,
        time: TimeSource::Column {
            index: 3,
            scale: hunit.map_or(1.0, |u| u.1),
        },
        time_name: "time".into(),
        columns: vec![Column {
            name,
            index: 4,
            unit: Some(vunit.map_or("V", |u| u.0).to_string()),
            scale: vunit.map_or(1.0, |u| u.1),
        }],
        header,
    }
}

/// The error for text without a data line.
fn no_data(path: &Path, lines: &[Line], opts: &ReadOptions) -> CaptureError {
    let wanted: Vec<String> = match &opts.time_column {
        Some(t) => vec![key(t)],
        None => TIME_NAMES.iter().map(|n| n.to_string()).collect(),
    };
    let has_header = lines.iter().any(|l| {
        SEPARATORS
            .iter()
            .any(|&(s, _)| split(l.text, s).iter().any(|f| wanted.contains(&key(f))))
    });
    if lines.iter().all(|l| l.is_blank()) {
        return CaptureError::Empty {
            path: path.to_path_buf(),
        };
    }
    CaptureError::NoData {
        path: path.to_path_buf(),
        what: if has_header {
            "a header but no row of numbers"
        } else {
            "text but no header and no row of numbers"
        },
        has_header,
    }
}
