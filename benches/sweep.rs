//! Design-space runs (issue 17): 1 000 Monte Carlo runs of the tracking testbench
//! (`benches/models/tracking_mc.toml`) through `vams sweep` on one and on two threads, beside
//! the same testbench run alone by `vams run` (parse, analyse, elaborate, simulate, no output
//! file). Prints runs per second and the cost of a run inside the sweep against a lone run:
//! the sweep parses and analyses once, so a run in it should cost no more than a lone
//! `vams run` (goal: within 5 %), and two threads should nearly halve the time.
//!
//! Run: `cargo bench --bench sweep` (`SWEEP_RUNS=200` for a shorter plan).

use std::process::Command;
use std::time::Instant;

const SPEC: &str = "benches/models/tracking_mc.toml";

fn vams() -> Command {
    Command::new(env!("CARGO_BIN_EXE_vams"))
}

/// Wall seconds of one `vams run` of the tracking testbench (best of `n`).
fn lone_run(n: usize) -> f64 {
    (0..n)
        .map(|_| {
            let started = Instant::now();
            let out = vams()
                .args(["run", "models", "--top", "tb_tracking"])
                .output()
                .expect("vams runs");
            assert!(
                out.status.success(),
                "{}",
                String::from_utf8_lossy(&out.stderr)
            );
            started.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}

/// Wall seconds of the sweep on `jobs` threads (best of `n`).
fn sweep(spec: &std::path::Path, jobs: usize, n: usize) -> f64 {
    (0..n)
        .map(|_| {
            let out = tempfile::tempdir().expect("a temporary folder");
            let started = Instant::now();
            let status = vams()
                .args(["sweep"])
                .arg(spec)
                .args(["--jobs", &jobs.to_string(), "--overwrite", "--out"])
                .arg(out.path())
                .output()
                .expect("vams sweep runs");
            assert!(
                status.status.success(),
                "{}",
                String::from_utf8_lossy(&status.stderr)
            );
            started.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}

fn main() {
    let runs: usize = std::env::var("SWEEP_RUNS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1000);
    let dir = tempfile::tempdir().expect("a temporary folder");
    let spec = dir.path().join("tracking_mc.toml");
    let text = std::fs::read_to_string(SPEC).expect("the benchmark's spec");
    let models = std::fs::canonicalize("models").expect("the models folder");
    let text = text
        .replace("runs = 1000", &format!("runs = {runs}"))
        .replace(
            "\"../../models\"",
            &format!("{:?}", models.display().to_string()),
        );
    std::fs::write(&spec, text).expect("the spec is written");
    let total = runs + 1; // and the nominal run
    let lone = lone_run(10);
    let one = sweep(&spec, 1, 2);
    let two = sweep(&spec, 2, 2);
    let per_run = one / total as f64;
    println!(
        "tb_tracking alone (vams run, best of 10): {:.1} ms",
        lone * 1e3
    );
    println!(
        "vams sweep, {total} runs, 1 thread:  {one:.2} s, {:.0} runs/s, {:.1} ms a run ({:+.1} % against a lone run)",
        total as f64 / one,
        per_run * 1e3,
        100.0 * (per_run / lone - 1.0)
    );
    println!(
        "vams sweep, {total} runs, 2 threads: {two:.2} s, {:.0} runs/s, speed-up {:.2} on 2 cores",
        total as f64 / two,
        one / two
    );
}
