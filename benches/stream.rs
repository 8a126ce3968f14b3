//! Streaming output (issue 23): peak memory and wall time of `vams run` on an event-heavy
//! run, `benches/models/counter_rc.vhd` (a counter stepping every 1 ns beside an RC low pass,
//! two rows per nanosecond), writing a CSV, at 0.1, 1 and 10 ms of simulated time. The release
//! binary runs as a child process; its peak resident set comes from `/usr/bin/time -f %M`
//! when that exists, else from the highest `VmHWM` of `/proc/<pid>/status` seen while it runs
//! (sampled every 5 ms). Peak memory must not grow with the run: the three figures agree
//! within 10 %.
//!
//! Then the event kernel alone beside GHDL: `benches/models/counter.vhd` (the counter without
//! the RC, plain VHDL) for 1 ms without output, through `vams run` and, when Debian's `ghdl`
//! is installed, `ghdl --elab-run` (its mcode backend; analysis not timed).
//!
//! Run: `cargo bench --bench stream` (`STREAM_STOPS=0.1ms,1ms` for other lengths). Writes
//! CSVs of up to 2.5 GB into a temporary directory, removed after each run.

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const MODEL: &str = "benches/models/counter_rc.vhd";

/// One run: wall time, peak RSS in kB, CSV bytes and rows.
struct Measured {
    wall: f64,
    peak_kb: u64,
    csv_bytes: u64,
    rows: u64,
}

fn vams_run(stop: &str, csv: &Path) -> Vec<String> {
    let args = ["run", MODEL, "--stop", stop, "-o"];
    let mut all: Vec<String> = args.iter().map(|s| s.to_string()).collect();
    all.push(csv.display().to_string());
    all
}

fn measure(stop: &str, dir: &Path) -> Measured {
    let csv = dir.join("counter.csv");
    let vams = env!("CARGO_BIN_EXE_vams");
    let started = Instant::now();
    let peak_kb = if Path::new("/usr/bin/time").exists() {
        let out = Command::new("/usr/bin/time")
            .args(["-f", "peak %M"])
            .arg(vams)
            .args(vams_run(stop, &csv))
            .stderr(Stdio::piped())
            .output()
            .expect("vams runs under /usr/bin/time");
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let stderr = String::from_utf8_lossy(&out.stderr);
        stderr
            .lines()
            .filter_map(|l| l.strip_prefix("peak "))
            .filter_map(|n| n.trim().parse().ok())
            .next_back()
            .expect("/usr/bin/time prints the peak")
    } else {
        let mut child = Command::new(vams)
            .args(vams_run(stop, &csv))
            .stderr(Stdio::null())
            .spawn()
            .expect("vams starts");
        let status = format!("/proc/{}/status", child.id());
        let mut peak = 0;
        loop {
            if let Ok(text) = std::fs::read_to_string(&status) {
                let hwm = text
                    .lines()
                    .filter_map(|l| l.strip_prefix("VmHWM:"))
                    .filter_map(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
                    .next();
                peak = peak.max(hwm.unwrap_or(0));
            }
            if child.try_wait().expect("waits").is_some() {
                break;
            }
            std::thread::sleep(Duration::from_millis(5));
        }
        peak
    };
    let wall = started.elapsed().as_secs_f64();
    let csv_bytes = std::fs::metadata(&csv).map(|m| m.len()).unwrap_or(0);
    let rows = count_lines(&csv).saturating_sub(1);
    let _ = std::fs::remove_file(&csv);
    Measured {
        wall,
        peak_kb,
        csv_bytes,
        rows,
    }
}

fn count_lines(path: &Path) -> u64 {
    use std::io::Read;
    let Ok(mut file) = std::fs::File::open(path) else {
        return 0;
    };
    let mut buffer = vec![0u8; 1 << 20];
    let mut lines = 0;
    while let Ok(n) = file.read(&mut buffer) {
        if n == 0 {
            break;
        }
        lines += buffer[..n].iter().filter(|&&b| b == b'\n').count() as u64;
    }
    lines
}

fn main() {
    // `cargo bench` passes `--bench`; the figures need no arguments.
    let stops = std::env::var("STREAM_STOPS").unwrap_or_else(|_| "0.1ms,1ms,10ms".into());
    let dir = tempfile::tempdir().expect("temporary directory");
    println!("vams run {MODEL} --stop T -o counter.csv");
    println!(
        "{:>8} {:>12} {:>12} {:>10} {:>12}",
        "stop", "rows", "CSV MB", "wall s", "peak RSS MB"
    );
    let mut peaks = Vec::new();
    for stop in stops.split(',').map(str::trim).filter(|s| !s.is_empty()) {
        let m = measure(stop, dir.path());
        println!(
            "{stop:>8} {:>12} {:>12.1} {:>10.2} {:>12.1}",
            m.rows,
            m.csv_bytes as f64 / 1e6,
            m.wall,
            m.peak_kb as f64 / 1024.0
        );
        peaks.push(m.peak_kb);
    }
    if let (Some(lo), Some(hi)) = (peaks.iter().min(), peaks.iter().max()) {
        let spread = (*hi as f64 / (*lo).max(1) as f64 - 1.0) * 100.0;
        let verdict = if spread <= 10.0 {
            "within"
        } else {
            "NOT within"
        };
        println!("peak memory spread {spread:.1} % ({verdict} 10 %)");
    }
    beside_ghdl(dir.path());
}

/// Wall time of one command, or `None` when it does not run or fails.
fn timed(command: &mut Command) -> Option<f64> {
    let started = Instant::now();
    let out = command
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .ok()?;
    out.success().then(|| started.elapsed().as_secs_f64())
}

/// The digital counter for 1 ms in vams and in GHDL (best of three each).
fn beside_ghdl(dir: &Path) {
    const COUNTER: &str = "benches/models/counter.vhd";
    let best = |f: &mut dyn FnMut() -> Option<f64>| (0..3).filter_map(|_| f()).reduce(f64::min);
    let vams = env!("CARGO_BIN_EXE_vams");
    let v = best(&mut || timed(Command::new(vams).args(["run", COUNTER, "--stop", "1 ms"])));
    println!("event kernel, {COUNTER} for 1 ms without output (best of 3):");
    match v {
        Some(t) => println!("  vams run          {t:>8.3} s"),
        None => println!("  vams run          failed"),
    }
    let work = format!("--workdir={}", dir.display());
    let analysed = Command::new("ghdl")
        .args(["-a", "--std=02", &work, COUNTER])
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success());
    if !analysed {
        println!("  ghdl              not installed (.ci/install-ghdl.sh installs it)");
        return;
    }
    let g = best(&mut || {
        timed(Command::new("ghdl").args([
            "--elab-run",
            "--std=02",
            &work,
            "counter",
            "--stop-time=1ms",
        ]))
    });
    match (v, g) {
        (Some(v), Some(g)) => println!(
            "  ghdl --elab-run   {g:>8.3} s  (vams / ghdl = {:.1})",
            v / g
        ),
        _ => println!("  ghdl --elab-run   failed"),
    }
}
