//! The experiments of a fit: each `--measured FILE[:KEY=VALUE,...]` is one capture with its
//! testbench, its generics and its alignment; its matched columns become [`Series`].

use std::path::{Path, PathBuf};

use crate::app::time::parse_time;
use crate::capture::{Capture, ReadOptions};
use crate::fit::Series;

use super::error::FitCliError;

/// One `--measured` argument.
#[derive(Debug, Clone, PartialEq)]
pub struct Measured {
    pub path: PathBuf,
    /// The testbench of this experiment (else `--top`).
    pub top: Option<String>,
    /// Added to the capture's times to give the simulation's; `None`: the capture's first
    /// sample is the simulation's time 0.
    pub shift: Option<f64>,
    /// The part of the capture compared (capture time).
    pub from: Option<f64>,
    pub to: Option<f64>,
    /// Align by a trigger instead: the first crossing of `level` by the channel (rising
    /// unless `edge=falling`) is placed at simulation time `at` (default 0).
    pub trigger: Option<(String, f64)>,
    pub rising: bool,
    pub at: Option<f64>,
    /// Generics of this experiment.
    pub generics: Vec<(String, String)>,
}

/// Whether `tail` reads as `KEY=VALUE[,KEY=VALUE...]`.
fn is_settings(tail: &str) -> bool {
    !tail.is_empty()
        && tail.split(',').all(|kv| {
            kv.split_once('=').is_some_and(|(k, _)| {
                let k = k.trim();
                !k.is_empty()
                    && k.chars()
                        .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '.')
            })
        })
}

impl Measured {
    /// Parses `FILE` or `FILE:KEY=VALUE,...` (the settings start after the last `:` that is
    /// followed by settings, so a path with colons still reads).
    pub fn parse(arg: &str) -> Result<Measured, FitCliError> {
        let bad = |why: String| FitCliError::Measured {
            arg: arg.to_string(),
            why,
        };
        let (file, settings) = match arg.rfind(':') {
            Some(k) if is_settings(&arg[k + 1..]) => (&arg[..k], &arg[k + 1..]),
            _ => (arg, ""),
        };
        if file.trim().is_empty() {
            return Err(bad("the capture file is missing".into()));
        }
        let mut m = Measured {
            path: PathBuf::from(file),
            top: None,
            shift: None,
            from: None,
            to: None,
            trigger: None,
            rising: true,
            at: None,
            generics: Vec::new(),
        };
        for kv in settings.split(',').filter(|s| !s.trim().is_empty()) {
            let (k, v) = kv.split_once('=').unwrap_or((kv, ""));
            let (k, v) = (k.trim().to_ascii_lowercase(), v.trim());
            // Times here may be negative (a shift back, a window in the pre-trigger).
            let time = |v: &str| {
                let (sign, magnitude) = match v.strip_prefix('-') {
                    Some(rest) => (-1.0, rest),
                    None => (1.0, v),
                };
                parse_time(magnitude.trim())
                    .map(|t| sign * t)
                    .map_err(|e| bad(format!("`{k}={v}`: {e}")))
            };
            match k.as_str() {
                "top" => m.top = Some(v.to_ascii_lowercase()),
                "shift" => m.shift = Some(time(v)?),
                "from" => m.from = Some(time(v)?),
                "to" => m.to = Some(time(v)?),
                "at" => m.at = Some(time(v)?),
                "trigger" => {
                    let parsed = v.rsplit_once('@').and_then(|(ch, level)| {
                        let level: f64 = level.trim().parse().ok()?;
                        (!ch.trim().is_empty() && level.is_finite())
                            .then(|| (ch.trim().to_string(), level))
                    });
                    m.trigger = Some(parsed.ok_or_else(|| {
                        bad(format!(
                            "`trigger={v}`: expected CHANNEL@LEVEL, e.g. `trigger=CH1@2.5`"
                        ))
                    })?);
                }
                "edge" => {
                    m.rising = match v.to_ascii_lowercase().as_str() {
                        "rising" => true,
                        "falling" => false,
                        _ => return Err(bad(format!("`edge={v}`: expected rising or falling"))),
                    }
                }
                _ => m.generics.push((k, v.to_string())),
            }
        }
        if m.trigger.is_some() && m.shift.is_some() {
            return Err(bad("give `shift=` or `trigger=`, not both".into()));
        }
        if m.trigger.is_none() && (m.at.is_some() || !m.rising) {
            return Err(bad(
                "`at=` and `edge=` go with `trigger=CHANNEL@LEVEL`".into()
            ));
        }
        if let (Some(a), Some(b)) = (m.from, m.to)
            && a >= b
        {
            return Err(bad(format!("`from` ({a} s) is not before `to` ({b} s)")));
        }
        Ok(m)
    }

    /// The file's name as people see it.
    pub fn name(&self) -> String {
        self.path.display().to_string()
    }
}

/// A `QUANTITY=COLUMN` pair of `--match`.
#[derive(Debug, Clone, PartialEq)]
pub struct Match {
    pub quantity: String,
    pub column: String,
}

pub fn parse_match(arg: &str) -> Result<Match, FitCliError> {
    match arg.split_once('=') {
        Some((q, c)) if !q.trim().is_empty() && !c.trim().is_empty() => Ok(Match {
            quantity: q.trim().to_ascii_lowercase(),
            column: c.trim().to_string(),
        }),
        _ => Err(FitCliError::Argument {
            flag: "match",
            arg: arg.into(),
            expected: "QUANTITY=COLUMN, e.g. `dut.i=current` (a quantity or signal of the testbench, and a column of the captures)",
        }),
    }
}

/// `--drive GENERIC=COLUMN`: the generic and the column, which must be a table generic of
/// the testbench (a `real_vector` that an equation reads with `vams.tables.pwl`).
pub fn parse_drive(arg: &str) -> Result<(String, String), FitCliError> {
    match arg.split_once('=') {
        Some((g, c)) if !g.trim().is_empty() && !c.trim().is_empty() => {
            Ok((g.trim().to_ascii_lowercase(), c.trim().to_string()))
        }
        _ => Err(FitCliError::Argument {
            flag: "drive",
            arg: arg.into(),
            expected: "GENERIC=COLUMN, e.g. `drive=voltage` (a real_vector generic the testbench reads with `pwl(drive, now)`, and a column of the captures)",
        }),
    }
}

/// The table text of generic `generic` from column `column` of a loaded capture: every
/// sample at simulation time, reduced by [`crate::fit::drive::table`].
pub fn drive_generic(
    loaded: &Loaded,
    (generic, column): &(String, String),
) -> Result<(String, String), crate::capture::CaptureError> {
    let cap = &loaded.aligned;
    let ch = cap.channel_or_error(column)?;
    // Blocks of at most 2 % of the record where the column is a line within its noise.
    let table = crate::fit::drive::table(&cap.time, &ch.values, 50);
    Ok((generic.clone(), crate::fit::drive::literal(&table)))
}

pub fn parse_scale(arg: &str) -> Result<(String, f64), FitCliError> {
    let bad = || FitCliError::Argument {
        flag: "scale",
        arg: arg.into(),
        expected: "COLUMN=FACTOR, e.g. `current=0.1` for a 100 mV/A current probe read in volts",
    };
    let (c, f) = arg.split_once('=').ok_or_else(bad)?;
    let f: f64 = f.trim().parse().map_err(|_| bad())?;
    if c.trim().is_empty() || !f.is_finite() || f == 0.0 {
        return Err(bad());
    }
    Ok((c.trim().to_string(), f))
}

/// A capture read, aligned and reduced for its experiment.
pub struct Loaded {
    pub capture: Capture,
    /// Every sample, aligned (simulation time), not reduced: what a `--drive` table is made
    /// of.
    pub aligned: Capture,
    /// The duration of each reduced sample's block (empty: the samples as read).
    pub widths: Vec<f64>,
    /// The interval of the samples as read.
    pub sample_interval: f64,
    /// Capture time + shift = simulation time.
    pub shift: f64,
}

/// Reads a capture, keeps `from..to`, aligns it, and reduces it to at most `points` samples
/// (block means: the noise averages, the shape stays).
pub fn load(m: &Measured, read: &ReadOptions, points: usize) -> Result<Loaded, miette::Report> {
    let mut capture = crate::capture::read(&m.path, read)?;
    if m.from.is_some() || m.to.is_some() {
        capture = capture.window(
            m.from.unwrap_or(f64::NEG_INFINITY),
            m.to.unwrap_or(f64::INFINITY),
        );
    }
    let Some(&first) = capture.time.first() else {
        return Err(FitCliError::TooShort {
            path: m.path.clone(),
            why: "no sample lies between `from` and `to`".into(),
        }
        .into());
    };
    let shift = match &m.trigger {
        Some((channel, level)) => {
            capture.channel_or_error(channel)?;
            let Some(t) = capture.trigger_time(channel, *level, m.rising) else {
                return Err(FitCliError::TooShort {
                    path: m.path.clone(),
                    why: format!(
                        "`{channel}` never crosses {level} {}: no trigger to align by",
                        if m.rising { "upwards" } else { "downwards" }
                    ),
                }
                .into());
            };
            m.at.unwrap_or(0.0) - t
        }
        None => m.shift.unwrap_or(-first),
    };
    let widths = crate::fit::series::block_widths(&capture.time, points);
    let sample_interval = crate::fit::series::sample_interval(&capture.time);
    let aligned = capture.shifted(shift);
    let capture = aligned.clone().decimated(points);
    Ok(Loaded {
        capture,
        aligned,
        widths,
        sample_interval,
        shift,
    })
}

/// The series of one experiment: each matched column the capture has, its clipped samples and
/// those before the simulation's time 0 left out.
pub fn series(
    experiment: usize,
    m: &Measured,
    loaded: &Loaded,
    matches: &[Match],
) -> Result<Vec<Series>, FitCliError> {
    let cap = &loaded.capture;
    let mut out = Vec::new();
    for mt in matches {
        let Some(ch) = cap.channel(&mt.column) else {
            continue;
        };
        let mut time = Vec::new();
        let mut measured = Vec::new();
        let mut width = Vec::new();
        for (k, &t) in cap.time.iter().enumerate() {
            if t >= 0.0 && !ch.clipped.get(k).copied().unwrap_or(false) {
                time.push(t);
                measured.push(ch.values[k]);
                if let Some(w) = loaded.widths.get(k) {
                    width.push(*w);
                }
            }
        }
        if measured.len() < 8 {
            return Err(FitCliError::TooShort {
                path: m.path.clone(),
                why: format!(
                    "only {} usable samples of `{}` at simulation times >= 0 (shift {} s)",
                    measured.len(),
                    mt.column,
                    crate::output::csv::format_number(loaded.shift)
                ),
            });
        }
        out.push(Series {
            experiment,
            simulated: mt.quantity.clone(),
            label: format!("{}: {}", file_name(&m.path), ch.name),
            time,
            measured,
            width,
            sample_interval: loaded.sample_interval,
            sigma: None,
            offset: None,
        });
    }
    if out.is_empty() {
        return Err(FitCliError::UnmatchedCapture {
            path: m.path.clone(),
            columns: matches.iter().map(|mt| mt.column.clone()).collect(),
            available: cap
                .channels
                .iter()
                .map(|c| format!("`{}`", c.name))
                .collect::<Vec<_>>()
                .join(", "),
        });
    }
    Ok(out)
}

/// The file name without its folder.
pub fn file_name(path: &Path) -> String {
    path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn measured_arguments() {
        let m = Measured::parse("caps/coast.csv:experiment=3,shift=2 ms,top=tb_bench").unwrap();
        assert_eq!(m.path, PathBuf::from("caps/coast.csv"));
        assert_eq!(m.top.as_deref(), Some("tb_bench"));
        assert!((m.shift.unwrap() - 2e-3).abs() < 1e-15);
        assert_eq!(
            m.generics,
            vec![("experiment".to_string(), "3".to_string())]
        );
        // A colon that is not followed by settings belongs to the path.
        let m = Measured::parse("c:/data/x.csv").unwrap();
        assert_eq!(m.path, PathBuf::from("c:/data/x.csv"));
        assert!(m.generics.is_empty());
        assert!(Measured::parse(":a=1").is_err());
        assert!(Measured::parse("x.csv:shift=abc").is_err());
        assert!(Measured::parse("x.csv:from=2ms,to=1ms").is_err());
        let m = Measured::parse("x.csv:trigger=Channel A@2.5,edge=falling,at=1ms").unwrap();
        assert_eq!(m.trigger, Some(("Channel A".to_string(), 2.5)));
        assert!(!m.rising && (m.at.unwrap() - 1e-3).abs() < 1e-15);
        for bad in [
            "x.csv:trigger=CH1",
            "x.csv:trigger=CH1@2.5,shift=1ms",
            "x.csv:at=1ms",
            "x.csv:trigger=CH1@1,edge=up",
        ] {
            assert!(Measured::parse(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn match_and_scale_arguments() {
        assert_eq!(
            parse_match("Dut.I=current").unwrap(),
            Match {
                quantity: "dut.i".into(),
                column: "current".into()
            }
        );
        assert!(parse_match("i=").is_err() && parse_match("i").is_err());
        assert_eq!(parse_scale("current=0.1").unwrap(), ("current".into(), 0.1));
        assert!(parse_scale("current=0").is_err() && parse_scale("=2").is_err());
    }
}
