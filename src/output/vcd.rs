//! Waveforms as a Value Change Dump (IEEE 1364 §18), readable by GTKWave and Surfer.
//!
//! The timescale is 1 ns: times are rounded to the nearest nanosecond (ample for
//! electromechanical runs of seconds; events closer than 1 ns collapse into one time step, the
//! last value winning). Dotted names become nested `$scope module` blocks under the top
//! entity. Quantities and real signals are `real` variables; booleans and bits 1-bit wires;
//! `std_ulogic` 1-bit wires with U X 0 1 Z W L H - mapped to VCD's x x 0 1 z x 0 1 x; integers
//! and other enumerations (by position) `integer` variables. Strings and arrays are left out.
//! After the initial `$dumpvars`, only changes are written.

use std::io::{self, Write};

use super::csv::format_number;
use super::levels::{Presentation, presentation, std_logic_vcd};
use crate::waveform::Waveforms;

/// Seconds per VCD time unit.
pub const TIME_UNIT: f64 = 1e-9;

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

/// Writes `waveforms` as VCD, with `top` as the outermost scope.
/// `comment` (a partial run's "partial: interrupted at t = ...") goes in a `$comment` of the
/// header, where a script or a viewer finds it first.
pub fn write_vcd(
    out: &mut impl Write,
    waveforms: &Waveforms,
    top: &str,
    comment: Option<&str>,
) -> io::Result<()> {
    writeln!(out, "$version vams {} $end", env!("CARGO_PKG_VERSION"))?;
    if let Some(c) = comment {
        writeln!(out, "$comment {c} $end")?;
    }
    writeln!(out, "$timescale 1 ns $end")?;
    let mut root = Scope {
        name: top.to_string(),
        ..Scope::default()
    };
    let mut vars: Vec<(usize, Presentation, String)> = Vec::new();
    for (c, column) in waveforms.columns.iter().enumerate() {
        let kind = presentation(column);
        if declaration(kind).is_some() {
            let path: Vec<&str> = column.name.split('.').collect();
            root.insert(&path, c);
            vars.push((c, kind, id_code(vars.len())));
        }
    }
    write_scope(out, &root, &vars)?;
    writeln!(out, "$enddefinitions $end")?;

    let mut last: Vec<Option<String>> = vec![None; vars.len()];
    let times = &waveforms.times;
    let mut k = 0;
    while k < times.len() {
        let stamp = (times[k].max(0.0) / TIME_UNIT).round() as u64;
        // Rows rounding to the same stamp collapse into their last one.
        let mut end = k;
        while end + 1 < times.len() && (times[end + 1].max(0.0) / TIME_UNIT).round() as u64 == stamp
        {
            end += 1;
        }
        let mut changes = String::new();
        for (slot, (c, kind, id)) in vars.iter().enumerate() {
            let v = waveforms.columns[*c]
                .values
                .get(end)
                .copied()
                .unwrap_or(f64::NAN);
            let (text, spaced) = encode(*kind, v);
            if last[slot].as_deref() != Some(text.as_str()) {
                changes.push_str(&text);
                if spaced {
                    changes.push(' ');
                }
                changes.push_str(id);
                changes.push('\n');
                last[slot] = Some(text);
            }
        }
        if k == 0 {
            write!(out, "#{stamp}\n$dumpvars\n{changes}$end\n")?;
        } else if !changes.is_empty() {
            write!(out, "#{stamp}\n{changes}")?;
        }
        k = end + 1;
    }
    Ok(())
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
