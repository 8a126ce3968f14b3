//! What the ngspice comparisons (`hbridge`, `motor`) share: loading vams models, running a
//! deck in `ngspice -b` with its own counters (`rusage all`), and best-of-n timing.
//!
//! Without ngspice on the PATH, [`run_ngspice`] says so and the benchmarks run the vams part
//! only (`benches/ngspice/install.sh` installs it).

use std::path::PathBuf;
use std::process::Command;
use std::time::{Duration, Instant};

use vams::cli::load::{Loaded, load};
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

/// The shortest of `n` runs of `f`, and the last result.
pub fn best_of<T>(n: usize, mut f: impl FnMut() -> T) -> (Duration, T) {
    let mut best = Duration::MAX;
    let mut last = None;
    for _ in 0..n.max(1) {
        let start = Instant::now();
        let out = f();
        best = best.min(start.elapsed());
        last = Some(out);
    }
    (best, last.expect("at least one run"))
}

/// One ngspice run: wall time of the process, ngspice's own figures, and the data rows.
pub struct NgspiceRun {
    /// The whole `ngspice -b` process, start-up and deck parsing included.
    pub wall: Duration,
    /// "Transient analysis time" of `rusage all`, in seconds (1 ms resolution).
    pub analysis: Option<f64>,
    /// "Accepted timepoints".
    pub accepted: Option<usize>,
    /// "Transient iterations" (Newton iterations of the transient analysis).
    pub iterations: Option<usize>,
    /// "Circuit Equations": the size of ngspice's matrix.
    pub equations: Option<usize>,
    /// One row per output time: time, then each vector asked for.
    pub rows: Vec<Vec<f64>>,
}

/// Runs `netlist` (elements and `.model`/`.options` lines) with `tran` (e.g. `tran 1u 20m
/// uic`) and writes `vectors` (e.g. `i(vsense)`) at every accepted time point.
pub fn run_ngspice(netlist: &str, tran: &str, vectors: &[&str]) -> Result<NgspiceRun, String> {
    let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
    let (cir, data) = (dir.path().join("deck.cir"), dir.path().join("out.txt"));
    let deck = format!(
        "* vams benchmark\n{netlist}\n.control\nset wr_singlescale\nset numdgt=12\n{tran}\n\
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
    Ok(NgspiceRun {
        wall,
        analysis: figure(&log, "Transient analysis time"),
        accepted: figure(&log, "Accepted timepoints").map(|x| x as usize),
        iterations: figure(&log, "Transient iterations").map(|x| x as usize),
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

/// The best of `n` ngspice runs by analysis time (by wall time when it prints none).
pub fn best_ngspice(
    n: usize,
    netlist: &str,
    tran: &str,
    vectors: &[&str],
) -> Result<NgspiceRun, String> {
    let mut best: Option<NgspiceRun> = None;
    for _ in 0..n.max(1) {
        let run = run_ngspice(netlist, tran, vectors)?;
        let key = |r: &NgspiceRun| r.analysis.unwrap_or(r.wall.as_secs_f64());
        if best.as_ref().is_none_or(|b| key(&run) < key(b)) {
            best = Some(run);
        }
    }
    best.ok_or_else(|| "no run".into())
}
