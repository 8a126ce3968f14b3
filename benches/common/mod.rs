//! What the ngspice comparisons (`hbridge`, `motor`, `ladder`) share: loading vams models, running a
//! deck in `ngspice -b` with its own counters (`rusage all`), and mean timing over n runs.
//!
//! Without ngspice on the PATH, [`run_ngspice`] says so and the benchmarks run the vams part
//! only (`benches/ngspice/install.sh` installs it).

// Each benchmark compiles its own copy of this module and uses only part of it.
#![allow(dead_code)]

use std::path::PathBuf;
use std::process::Command;
use std::time::{Duration, Instant};

use vams::app::load::{Loaded, load};
use vams::design::Design;
use vams::elaborate::{ElabOptions, elaborate};

/// Parses `paths` (relative to the crate root) with the stdlib and elaborates `top`.
pub fn design(paths: &[&str], top: &str, generics: &[(&str, String)]) -> Design {
    let root = env!("CARGO_MANIFEST_DIR");
    let paths: Vec<PathBuf> = paths.iter().map(|p| PathBuf::from(root).join(p)).collect();
    let loaded: Loaded = load(&paths).expect("benchmark models exist");
    assert_eq!(loaded.error_count(), 0, "{:?}", loaded.syntax_errors);
    let options = ElabOptions {
        top: top.into(),
        generics: generics
            .iter()
            .map(|(n, v)| (n.to_string(), v.clone()))
            .collect(),
    };
    elaborate(&loaded.sources, &loaded.files, &options).expect("benchmark model elaborates")
}

/// The mean time of `n` runs of `f`, and the last result.
pub fn mean_of<T>(n: usize, mut f: impl FnMut() -> T) -> (Duration, T) {
    let n = n.max(1);
    let start = Instant::now();
    let mut last = f();
    for _ in 1..n {
        last = f();
    }
    (start.elapsed() / n as u32, last)
}

/// The median time of `n` runs of `f`, and the last result. On a shared machine the median
/// resists the runs a neighbour slowed down, which pull a mean up.
pub fn median_of<T>(n: usize, mut f: impl FnMut() -> T) -> (Duration, T) {
    let mut times = Vec::with_capacity(n.max(1));
    let mut last = None;
    for _ in 0..n.max(1) {
        let start = Instant::now();
        last = Some(f());
        times.push(start.elapsed());
    }
    times.sort();
    // At least one run happened (n.max(1)).
    (times[times.len() / 2], last.expect("one run at least"))
}

/// `n` runs of one deck in one `ngspice -b` process: wall time of the process, ngspice's own
/// figures per run, and the data rows of the last run.
pub struct NgspiceRun {
    /// The whole `ngspice -b` process, start-up, deck parsing and all `n` runs included.
    pub wall: Duration,
    /// "Transient analysis time" of `rusage all` over `n` (it has 1 ms resolution, hence the
    /// repeats), in seconds.
    pub analysis: Option<f64>,
    /// "Accepted timepoints" of one run.
    pub accepted: Option<usize>,
    /// "Transient iterations" (Newton iterations) of one run.
    pub iterations: Option<usize>,
    /// "Circuit Equations": the size of ngspice's matrix.
    pub equations: Option<usize>,
    /// One row per output time: time, then each vector asked for.
    pub rows: Vec<Vec<f64>>,
}

/// Runs `netlist` (elements and `.model`/`.options` lines) `n` times with `tran` (e.g. `tran
/// 1u 20m uic`) and writes `vectors` (e.g. `i(vsense)`) at every accepted time point of the
/// last run. ngspice's counters add up over the runs; they are divided by `n`.
pub fn run_ngspice(
    netlist: &str,
    tran: &str,
    vectors: &[&str],
    n: usize,
) -> Result<NgspiceRun, String> {
    let n = n.max(1);
    let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
    let (cir, data) = (dir.path().join("deck.cir"), dir.path().join("out.txt"));
    let warm = if n > 1 {
        format!("repeat {}\n{tran}\ndestroy\nend\n", n - 1)
    } else {
        String::new()
    };
    let deck = format!(
        "* vams benchmark\n{netlist}\n.control\nset wr_singlescale\nset numdgt=12\n{warm}{tran}\n\
         wrdata {} {}\nrusage all\nquit\n.endc\n.end\n",
        data.display(),
        vectors.join(" ")
    );
    std::fs::write(&cir, deck).map_err(|e| e.to_string())?;
    let start = Instant::now();
    let out = Command::new("ngspice")
        .arg("-b")
        .arg(&cir)
        .output()
        .map_err(|e| format!("ngspice not runnable ({e})"))?;
    let wall = start.elapsed();
    let text = std::fs::read_to_string(&data).map_err(|_| {
        format!(
            "ngspice wrote no data: {}",
            String::from_utf8_lossy(&out.stderr)
        )
    })?;
    let rows = text
        .lines()
        .filter_map(|l| {
            let row: Vec<f64> = l
                .split_whitespace()
                .map(str::parse::<f64>)
                .collect::<Result<_, _>>()
                .ok()?;
            (row.len() == vectors.len() + 1).then_some(row)
        })
        .collect();
    let log = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let per_run = |name: &str| figure(&log, name).map(|x| x / n as f64);
    Ok(NgspiceRun {
        wall,
        analysis: per_run("Transient analysis time"),
        accepted: per_run("Accepted timepoints").map(|x| x.round() as usize),
        iterations: per_run("Transient iterations").map(|x| x.round() as usize),
        equations: figure(&log, "Circuit Equations").map(|x| x as usize),
        rows,
    })
}

/// The number after `name =` in ngspice's `rusage` listing.
fn figure(log: &str, name: &str) -> Option<f64> {
    log.lines()
        .filter_map(|l| l.trim().strip_prefix(name))
        .filter_map(|rest| rest.trim().strip_prefix('='))
        .find_map(|v| v.split_whitespace().next()?.parse().ok())
}
