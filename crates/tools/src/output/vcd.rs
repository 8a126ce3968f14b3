//! Waveforms as a Value Change Dump (IEEE 1364 §18), readable by GTKWave and Surfer.
//!
//! The timescale is 1 fs, the resolution of VHDL's time and the grid of the kernel's event
//! times (coarser only for runs longer than about three hours, [`time_unit`]): analog points
//! are rounded to it, and rows at one stamp (a discontinuity's before/after pair) collapse
//! into the last. Dotted names become nested `$scope module` blocks under the top
//! entity. Quantities and real signals are `real` variables; booleans and bits 1-bit wires;
//! `std_ulogic` 1-bit wires with U X 0 1 Z W L H - mapped to VCD's x x 0 1 z x 0 1 x; integers
//! and other enumerations (by position) `integer` variables. Strings and arrays are left out.
//! After the initial `$dumpvars`, only changes are written.

use std::io::{self, Write};

use super::csv::format_number;
use super::levels::{Presentation, presentation, std_logic_vcd};
use vams_simulation::waveform::{Column, Waveforms};

/// A hierarchy level: its variables (column indices) and sub-scopes, in first-seen order.
#[derive(Default)]
struct Scope {
    name: String,
    vars: Vec<(usize, String)>,
    children: Vec<Scope>,
}

impl Scope {
    fn insert(&mut self, path: &[&str], column: usize) {
        match path {
            [] => {}
            [leaf] => self.vars.push((column, leaf.to_string())),
            [head, rest @ ..] => {
                let pos = match self.children.iter().position(|c| c.name == *head) {
                    Some(p) => p,
                    None => {
                        self.children.push(Scope {
                            name: head.to_string(),
                            ..Scope::default()
                        });
                        self.children.len() - 1
                    }
                };
                self.children[pos].insert(rest, column);
            }
        }
    }
}

/// The short identifier code of variable `n`: base 94 over the printable ASCII characters.
fn id_code(mut n: usize) -> String {
    let mut code = String::new();
    loop {
        code.push((b'!' + (n % 94) as u8) as char);
        n /= 94;
        if n == 0 {
            return code;
        }
        n -= 1;
    }
}

/// VCD references cannot hold white space.
fn reference(name: &str) -> String {
    name.chars()
        .map(|c| if c.is_whitespace() { '_' } else { c })
        .collect()
}

fn declaration(kind: Presentation) -> Option<(&'static str, u32)> {
    match kind {
        Presentation::Real => Some(("real", 64)),
        Presentation::Bit | Presentation::StdLogic => Some(("wire", 1)),
        Presentation::Integer => Some(("integer", 64)),
        Presentation::Other => None,
    }
}

/// One value in VCD syntax, without the identifier.
fn encode(kind: Presentation, v: f64) -> (String, bool) {
    // The bool says whether the identifier follows after a space (vectors and reals).
    match kind {
        Presentation::Real => (format!("r{}", format_number(v)), true),
        Presentation::Bit if v.is_nan() => ("x".into(), false),
        Presentation::Bit => ((if v > 0.5 { "1" } else { "0" }).into(), false),
        Presentation::StdLogic => (std_logic_vcd(v).to_string(), false),
        Presentation::Integer if v.is_finite() => {
            // Two's complement in 64 bits for negative integers.
            (format!("b{:b}", v.round() as i64 as u64), true)
        }
        Presentation::Integer | Presentation::Other => ("bx".into(), true),
    }
}

/// The VCD time unit for a run that ends at `stop` seconds: the femtosecond, VHDL's resolution
/// limit and the grid the kernel's times live on (so events 1 fs apart stay apart and every
/// kernel time is an exact stamp), unless the run is too long for 64-bit stamps of it (about
/// three hours); then the finest of ps, ns, us, ms, s that fits. `(seconds, name)`.
pub fn time_unit(stop: f64) -> (f64, &'static str) {
    const UNITS: [(f64, &str); 6] = [
        (1e-15, "fs"),
        (1e-12, "ps"),
        (1e-9, "ns"),
        (1e-6, "us"),
        (1e-3, "ms"),
        (1.0, "s"),
    ];
    UNITS
        .into_iter()
        .find(|(unit, _)| stop / unit < 1e19)
        .unwrap_or(UNITS[5])
}

/// A VCD written row by row as a run accepts its points ([`write_vcd`] for a whole record):
/// the header on creation, value changes as rows come (rows that round to one stamp collapse
/// into their last one, so the last row is held until a later stamp or [`finish`](Self::finish)).
pub struct VcdWriter<W: Write> {
    out: W,
    /// Seconds per time unit.
    unit: f64,
    /// Per variable: its column, presentation and identifier code.
    vars: Vec<(usize, Presentation, String)>,
    /// The last value written per variable.
    last: Vec<Option<String>>,
    /// The row waiting for a later stamp: its stamp and values.
    pending: Option<u64>,
    values: Vec<f64>,
    first: bool,
}

impl<W: Write> VcdWriter<W> {
    /// Writes the header: `top` as the outermost scope, `comment` (a partial run's "partial:
    /// interrupted at t = ...") in a `$comment` where a script or a viewer finds it first, the
    /// time unit for a run that ends at `stop` ([`time_unit`]).
    pub fn new(
        mut out: W,
        columns: &[Column],
        top: &str,
        comment: Option<&str>,
        stop: f64,
    ) -> io::Result<Self> {
        writeln!(out, "$version vams {} $end", env!("CARGO_PKG_VERSION"))?;
        if let Some(c) = comment {
            write_comment(&mut out, c)?;
        }
        let (unit, name) = time_unit(stop);
        writeln!(out, "$timescale 1 {name} $end")?;
        let mut root = Scope {
            name: top.to_string(),
            ..Scope::default()
        };
        let mut vars: Vec<(usize, Presentation, String)> = Vec::new();
        for (c, column) in columns.iter().enumerate() {
            let kind = presentation(column);
            if declaration(kind).is_some() {
                let path: Vec<&str> = column.name.split('.').collect();
                root.insert(&path, c);
                vars.push((c, kind, id_code(vars.len())));
            }
        }
        write_scope(&mut out, &root, &vars)?;
        writeln!(out, "$enddefinitions $end")?;
        Ok(VcdWriter {
            out,
            unit,
            last: vec![None; vars.len()],
            vars,
            pending: None,
            values: vec![f64::NAN; columns.len()],
            first: true,
        })
    }

    /// One row: `values` in column order.
    pub fn row(&mut self, time: f64, values: impl IntoIterator<Item = f64>) -> io::Result<()> {
        let stamp = (time.max(0.0) / self.unit).round() as u64;
        if self.pending.is_some_and(|p| p != stamp) {
            self.flush_pending()?;
        }
        self.pending = Some(stamp);
        for (slot, v) in self.values.iter_mut().zip(values) {
            *slot = v;
        }
        Ok(())
    }

    /// The held row's changes.
    fn flush_pending(&mut self) -> io::Result<()> {
        let Some(stamp) = self.pending.take() else {
            return Ok(());
        };
        let mut changes = String::new();
        for (slot, (c, kind, id)) in self.vars.iter().enumerate() {
            let v = self.values.get(*c).copied().unwrap_or(f64::NAN);
            let (text, spaced) = encode(*kind, v);
            if self.last[slot].as_deref() != Some(text.as_str()) {
                changes.push_str(&text);
                if spaced {
                    changes.push(' ');
                }
                changes.push_str(id);
                changes.push('\n');
                self.last[slot] = Some(text);
            }
        }
        if self.first {
            self.first = false;
            write!(self.out, "#{stamp}\n$dumpvars\n{changes}$end\n")
        } else if !changes.is_empty() {
            write!(self.out, "#{stamp}\n{changes}")
        } else {
            Ok(())
        }
    }

    /// Writes the held row and gives the output back.
    pub fn finish(mut self) -> io::Result<W> {
        self.flush_pending()?;
        Ok(self.out)
    }
}

fn write_comment(out: &mut impl Write, comment: &str) -> io::Result<()> {
    writeln!(out, "$comment {comment} $end")
}

/// Copies a VCD that [`VcdWriter`] wrote without a comment from `from` to `to`, adding the
/// `$comment` it would have written in its header: how a streamed dump learns at its end that
/// the run was partial.
pub fn copy_with_comment(
    mut from: impl io::BufRead,
    to: &mut impl Write,
    comment: &str,
) -> io::Result<()> {
    let mut version = Vec::new();
    from.read_until(b'\n', &mut version)?;
    to.write_all(&version)?;
    write_comment(to, comment)?;
    io::copy(&mut from, to).map(|_| ())
}

/// Writes `waveforms` as VCD, with `top` as the outermost scope; `comment` as in
/// [`VcdWriter::new`], the time unit for the last recorded time.
pub fn write_vcd(
    out: &mut impl Write,
    waveforms: &Waveforms,
    top: &str,
    comment: Option<&str>,
) -> io::Result<()> {
    let end = waveforms.times.last().copied().unwrap_or(0.0);
    let mut writer = VcdWriter::new(out, &waveforms.columns, top, comment, end)?;
    for (k, &t) in waveforms.times.iter().enumerate() {
        let values = waveforms.columns.iter().map(|c| c.values.get(k).copied());
        writer.row(t, values.map(|v| v.unwrap_or(f64::NAN)))?;
    }
    writer.finish().map(|_| ())
}

fn write_scope(
    out: &mut impl Write,
    scope: &Scope,
    vars: &[(usize, Presentation, String)],
) -> io::Result<()> {
    writeln!(out, "$scope module {} $end", reference(&scope.name))?;
    for (column, leaf) in &scope.vars {
        // Every column in the tree was given a variable with a declarable kind.
        let declared = vars
            .iter()
            .find(|(c, _, _)| c == column)
            .and_then(|(_, kind, id)| declaration(*kind).map(|d| (d, id)));
        if let Some(((ty, width), id)) = declared {
            writeln!(out, "$var {ty} {width} {id} {} $end", reference(leaf))?;
        }
    }
    for child in &scope.children {
        write_scope(out, child, vars)?;
    }
    writeln!(out, "$upscope $end")
}

#[cfg(test)]
mod tests;
