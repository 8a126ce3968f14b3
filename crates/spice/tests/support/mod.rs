//! Helpers shared by the spice crate's integration tests (`lower`, `mosfet`, `mosfet2`,
//! `switches`, `bjt`): reading a deck into a [`Circuit`] and lowering it, its operating
//! point and `.tran` run, lookups in their results, the rendered diagnostics of a refused
//! deck, running `ngspice -b` and parsing its `.print` tables (skipped with a printed reason
//! where ngspice is absent), and the small numeric helpers the comparisons use.

// Each test binary compiles this module on its own and uses only a subset of it.
#![allow(dead_code)]

use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

use vams_design::Design;
use vams_simulation::kernel::{SimOptions, operating_point, simulate};
use vams_simulation::waveform::Waveforms;
use vams_spice::circuit::Circuit;
use vams_spice::{MemLoader, SourceMap, SpiceError, flatten, lower, outputs, read_deck, transient};
use vams_syntax::diagnostics::render_plain;

/// Reads and flattens a deck, asserting no error.
pub fn circuit(text: &str) -> Circuit {
    let mut sources = SourceMap::new();
    let id = sources.add("deck.cir", "work", text.to_string());
    let (deck, errors) = read_deck(&mut sources, id, &mut MemLoader::new());
    assert!(errors.is_empty(), "{errors:#?}");
    match flatten(&deck) {
        Ok(c) => c,
        Err(e) => panic!("{e:#?}"),
    }
}

/// Lowers a circuit to a design, asserting no error.
pub fn design(c: &Circuit) -> Design {
    match lower(c) {
        Ok(d) => d,
        Err(e) => panic!("{e:#?}"),
    }
}

/// The operating point of a deck, by quantity name, solved with `reltol` (`None`: the
/// simulator's default options).
pub fn op(text: &str, reltol: Option<f64>) -> Vec<(String, f64)> {
    let d = design(&circuit(text));
    let mut options = SimOptions::default();
    if let Some(reltol) = reltol {
        options.reltol = reltol;
    }
    match operating_point(&d, &options) {
        Ok(p) => p,
        Err(e) => panic!("{e:?}"),
    }
}

/// The value of quantity `name` in an operating point; panics when it is missing.
pub fn value(point: &[(String, f64)], name: &str) -> f64 {
    match point.iter().find(|(n, _)| n == name) {
        Some((_, v)) => *v,
        None => panic!("no quantity {name} in {point:?}"),
    }
}

/// The deck's `.tran`, run with the largest step TSTEP (or TMAX) and a tight reltol (1e-5).
pub fn run(text: &str) -> Waveforms {
    let c = circuit(text);
    let d = design(&c);
    let Some(t) = transient(&c) else {
        panic!("the deck has no .tran")
    };
    let options = SimOptions {
        stop: t.tstop,
        reltol: 1e-5,
        max_step: Some(t.tmax.unwrap_or(t.tstep)),
        probes: outputs(&c),
        ..SimOptions::default()
    };
    match simulate(&d, &options, &mut |_| {}) {
        Ok(r) => r.waveforms,
        Err(e) => panic!("{e:?}"),
    }
}

/// Column `name` of a waveform at time `t` (interpolated); panics when there is no such
/// column.
pub fn at(w: &Waveforms, name: &str, t: f64) -> f64 {
    match w.value_at(name, t) {
        Some(v) => v,
        None => panic!("no column {name}"),
    }
}

/// The times `v` (sampled at `times`) crosses `level`, either way, linear between samples.
pub fn crossings(times: &[f64], v: &[f64], level: f64) -> Vec<f64> {
    let mut out = Vec::new();
    for k in 1..times.len().min(v.len()) {
        let (a, b) = (v[k - 1] - level, v[k] - level);
        if a != 0.0 && a.signum() != b.signum() {
            out.push(times[k - 1] + (times[k] - times[k - 1]) * a / (a - b));
        }
    }
    out
}

/// The times where waveform column `name` crosses `level`, either way, interpolated;
/// panics when there is no such column.
pub fn column_crossings(w: &Waveforms, name: &str, level: f64) -> Vec<f64> {
    let Some(col) = w.column(name) else {
        panic!("no column {name}")
    };
    crossings(&w.times, &col.values, level)
}

/// Relative difference of `a` from `b`, with a floor on `|b|` for values near zero.
pub fn rel(a: f64, b: f64, floor: f64) -> f64 {
    (a - b).abs() / b.abs().max(floor)
}

/// Every diagnostic of reading, flattening and lowering a deck, rendered (for snapshots;
/// the snapshot assertion stays in the test so its name and path do not change).
pub fn render(text: &str) -> String {
    let mut sources = SourceMap::new();
    let id = sources.add("bad.cir", "work", text.to_string());
    let (deck, errors) = read_deck(&mut sources, id, &mut MemLoader::new());
    let mut all: Vec<SpiceError> = errors;
    if all.is_empty() {
        match flatten(&deck) {
            Ok(c) => {
                if let Err(e) = lower(&c) {
                    all.extend(e);
                }
            }
            Err(e) => all.extend(e),
        }
    }
    all.iter()
        .map(|d| render_plain(d, &sources))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Runs `ngspice -b` on a deck and returns its stdout; `None` (with the reason printed)
/// when ngspice is absent or does not run. Each deck gets its own file in a directory per
/// test binary and process, as tests run in parallel.
fn ngspice_stdout(deck: &str) -> Option<String> {
    if Command::new("ngspice").arg("--version").output().is_err() {
        println!("skipped: ngspice is not installed");
        return None;
    }
    let dir = std::env::temp_dir().join(format!(
        "vams-spice-{}-{}",
        env!("CARGO_CRATE_NAME"),
        std::process::id()
    ));
    if let Err(e) = std::fs::create_dir_all(&dir) {
        println!("skipped: cannot make {}: {e}", dir.display());
        return None;
    }
    static NEXT: AtomicUsize = AtomicUsize::new(0);
    let path = dir.join(format!("deck{}.cir", NEXT.fetch_add(1, Ordering::Relaxed)));
    if let Err(e) = std::fs::write(&path, deck) {
        println!("skipped: cannot write {}: {e}", path.display());
        return None;
    }
    let out = Command::new("ngspice").arg("-b").arg(&path).output();
    let _ = std::fs::remove_file(&path);
    match out {
        Ok(o) => Some(String::from_utf8_lossy(&o.stdout).into_owned()),
        Err(e) => {
            println!("skipped: ngspice did not run: {e}");
            None
        }
    }
}

/// The numbered rows of ngspice's `.print` tables (index dropped): the sweep value or time,
/// then the columns, with at least one column.
fn print_rows(text: &str) -> Vec<Vec<f64>> {
    text.lines()
        .filter_map(|l| {
            let mut f = l.split_whitespace();
            f.next()?.parse::<u64>().ok()?;
            f.map(|x| x.parse::<f64>().ok()).collect::<Option<Vec<_>>>()
        })
        .filter(|r| r.len() >= 2)
        .collect()
}

/// ngspice's `.print dc` or `.print tran` rows of a deck, as printed (sweep value or time,
/// then the columns; a wide `.print`'s several tables follow one another); `None` when
/// ngspice is absent.
pub fn ngspice(deck: &str) -> Option<Vec<Vec<f64>>> {
    Some(print_rows(&ngspice_stdout(deck)?))
}

/// ngspice's `.print dc` rows of a deck with a wide `.print`'s several tables of the same
/// sweep joined row by row (sweep value, then all the columns); `None` when ngspice is
/// absent.
pub fn ngspice_joined(deck: &str) -> Option<Vec<Vec<f64>>> {
    let rows = print_rows(&ngspice_stdout(deck)?);
    let mut joined: Vec<Vec<f64>> = Vec::new();
    let mut k = 0;
    for r in rows {
        if k < joined.len() && joined[k][0] == r[0] {
            joined[k].extend_from_slice(&r[1..]);
            k += 1;
        } else if joined.is_empty() || k == 0 {
            joined.push(r);
        } else {
            k = 0;
            joined[k].extend_from_slice(&r[1..]);
            k += 1;
        }
    }
    Some(joined)
}
