//! Runs one VHDL program through vams (`vams run`) and GHDL (`ghdl -c ... -r`), reads the
//! reports each prints, and compares them time step by time step as multisets: the LRM leaves
//! the order of processes within a delta cycle open, so two correct simulators may print one
//! time step's reports in different orders, but never different reports or times.

// The test and the example each use part of this module.
#![allow(dead_code)]

use std::collections::BTreeMap;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// How long one tool may run on one program before it counts as hanging.
const DEADLINE: Duration = Duration::from_secs(60);

/// The reports of one run: message texts per time in femtoseconds, each time's sorted.
pub type Reports = BTreeMap<u64, Vec<String>>;

#[derive(Debug)]
pub enum Verdict {
    Agrees(usize),
    /// The first time step where the reports differ, with each tool's reports there.
    Disagrees {
        time_fs: u64,
        vams: Vec<String>,
        ghdl: Vec<String>,
    },
    /// vams failed (its message) where GHDL ran.
    VamsFails(String),
    /// GHDL refused or failed the program (a generator bug, or a GHDL limit).
    GhdlFails(String),
}

/// True when `ghdl` runs here.
pub fn ghdl_available() -> bool {
    Command::new("ghdl")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

/// The output of one command: success, and its standard error (where both tools report).
struct Run {
    ok: bool,
    stderr: String,
}

/// Runs `command` in `dir` to completion or `DEADLINE`, its output going to files (a pipe
/// nobody reads would block a talkative child).
fn run(mut command: Command, dir: &Path, name: &str) -> Run {
    let out = dir.join(format!("{name}.out"));
    let err = dir.join(format!("{name}.err"));
    let (Ok(out_file), Ok(err_file)) = (std::fs::File::create(&out), std::fs::File::create(&err))
    else {
        return Run {
            ok: false,
            stderr: "cannot create output files".into(),
        };
    };
    let child = command
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(out_file)
        .stderr(err_file)
        .spawn();
    let mut child = match child {
        Ok(c) => c,
        Err(e) => {
            return Run {
                ok: false,
                stderr: format!("cannot start: {e}"),
            };
        }
    };
    let deadline = Instant::now() + DEADLINE;
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break Some(status),
            Ok(None) if Instant::now() > deadline => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(5)),
            Err(_) => break None,
        }
    };
    let mut stderr = std::fs::read_to_string(&err).unwrap_or_default();
    stderr.push_str(&std::fs::read_to_string(&out).unwrap_or_default());
    match status {
        Some(s) => Run {
            ok: s.success(),
            stderr,
        },
        None => Run {
            ok: false,
            stderr: format!("did not finish within {DEADLINE:?}\n{stderr}"),
        },
    }
}

/// Femtoseconds in `number unit` (`2.5 ns`, `2500ps`, `0ms`).
fn femtoseconds(text: &str) -> Option<u64> {
    let text = text.trim();
    let split = text.find(|c: char| c.is_ascii_alphabetic())?;
    let (number, unit) = text.split_at(split);
    let value: f64 = number.trim().parse().ok()?;
    let scale = match unit.trim() {
        "fs" => 1.0,
        "ps" => 1e3,
        "ns" => 1e6,
        "us" => 1e9,
        "ms" => 1e12,
        "s" | "sec" => 1e15,
        _ => return None,
    };
    Some((value * scale).round() as u64)
}

/// vams's report lines: `2.5 ns: note: MESSAGE (process p1, f.vhd:8:5)`.
pub fn vams_reports(stderr: &str) -> Reports {
    let mut reports = Reports::new();
    for line in stderr.lines() {
        let Some((time, rest)) = line.split_once(": ") else {
            continue;
        };
        let Some(fs) = femtoseconds(time) else {
            continue;
        };
        let Some((severity, message)) = rest.split_once(": ") else {
            continue;
        };
        if !matches!(severity, "note" | "warning" | "error" | "failure") {
            continue;
        }
        let message = message
            .rsplit_once(" (process ")
            .map_or(message, |(m, _)| m);
        reports.entry(fs).or_default().push(message.to_string());
    }
    reports.values_mut().for_each(|v| v.sort());
    reports
}

/// GHDL's report lines: `f.vhd:8:5:@2500ps:(report note): MESSAGE`.
pub fn ghdl_reports(stderr: &str) -> Reports {
    let mut reports = Reports::new();
    for line in stderr.lines() {
        let Some((_, rest)) = line.split_once(":@") else {
            continue;
        };
        let Some((time, rest)) = rest.split_once(":(") else {
            continue;
        };
        let Some((kind, message)) = rest.split_once("): ") else {
            continue;
        };
        if !(kind.starts_with("report") || kind.starts_with("assertion")) {
            continue;
        }
        let Some(fs) = femtoseconds(time) else {
            continue;
        };
        reports.entry(fs).or_default().push(message.to_string());
    }
    reports.values_mut().for_each(|v| v.sort());
    reports
}

/// Runs `text` (top entity `tb`) through both tools in `dir` up to `stop` (a time both
/// command lines accept, `400050 ps`) and compares the reports before `stop_fs`.
pub fn compare(text: &str, vams: &Path, stop: &str, stop_fs: u64, dir: &Path) -> Verdict {
    let file = dir.join("tb.vhd");
    if let Err(e) = std::fs::write(&file, text) {
        return Verdict::GhdlFails(format!("cannot write {}: {e}", file.display()));
    }
    let mut ghdl = Command::new("ghdl");
    // VHDL-2002, vams's baseline; mcode's work library goes to the program's directory.
    ghdl.args(["-c", "--std=02", "tb.vhd", "-r", "tb"])
        .arg(format!("--stop-time={}", stop.replace(' ', "")));
    let ghdl_run = run(ghdl, dir, "ghdl");
    if !ghdl_run.ok {
        return Verdict::GhdlFails(ghdl_run.stderr);
    }
    let mut command = Command::new(vams);
    command.args(["run", "tb.vhd", "--top", "tb", "--stop", stop]);
    let vams_run = run(command, dir, "vams");
    if !vams_run.ok {
        return Verdict::VamsFails(vams_run.stderr);
    }
    let before = |mut r: Reports| {
        r.retain(|t, _| *t < stop_fs);
        r
    };
    let theirs = before(ghdl_reports(&ghdl_run.stderr));
    let ours = before(vams_reports(&vams_run.stderr));
    let times: std::collections::BTreeSet<u64> =
        theirs.keys().chain(ours.keys()).copied().collect();
    for time in times {
        let (a, b) = (ours.get(&time), theirs.get(&time));
        if a != b {
            return Verdict::Disagrees {
                time_fs: time,
                vams: a.cloned().unwrap_or_default(),
                ghdl: b.cloned().unwrap_or_default(),
            };
        }
    }
    Verdict::Agrees(theirs.values().map(Vec::len).sum())
}
