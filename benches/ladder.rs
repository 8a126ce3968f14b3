//! RC ladder of N sections (`tests/simulate/rc_ladder.vhd`, N = 10, 100, 1000): vams's
//! elaboration and simulation timed separately with criterion, and, when `ngspice` is on the
//! PATH, the same circuit in `ngspice -b` (reltol 1e-3 in both) with wall times and the largest
//! difference of the output node's waveform at ngspice's time points. Without ngspice the
//! comparison says so and only the vams part runs (`benches/ngspice/install.sh` installs it).
//!
//! Run: `cargo bench --bench ladder` (sizes: `LADDER_SIZES=10,100 cargo bench --bench ladder`).

use std::hint::black_box;
use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use vams::ast::DesignFile;
use vams::design::Design;
use vams::elaborate::{ElabOptions, elaborate};
use vams::kernel::{SimOptions, simulate};
use vams::source::{FileId, SourceMap};
use vams::waveform::Waveforms;
use vams::{parser, stdlib};

const R_TOTAL: f64 = 1.0e3;
const C_TOTAL: f64 = 1.0e-6;
/// Five time constants of the whole line's R C.
const STOP: f64 = 5e-3;
const RELTOL: f64 = 1e-3;

fn sizes() -> Vec<usize> {
    std::env::var("LADDER_SIZES")
        .ok()
        .map(|s| s.split(',').filter_map(|n| n.trim().parse().ok()).collect())
        .filter(|v: &Vec<usize>| !v.is_empty())
        .unwrap_or_else(|| vec![10, 100, 1000])
}

fn load() -> (SourceMap, Vec<(FileId, DesignFile)>) {
    let mut sources = SourceMap::new();
    let mut ids = stdlib::load(&mut sources);
    let path = format!(
        "{}/tests/simulate/rc_ladder.vhd",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).expect("ladder model readable");
    ids.push(sources.add(path, "work", text));
    let files = ids
        .iter()
        .map(|&id| {
            let text = sources.file(id).text.clone();
            (id, parser::parse(id, &text).0)
        })
        .collect();
    (sources, files)
}

fn elab_options(n: usize) -> ElabOptions {
    ElabOptions {
        top: "rc_ladder".into(),
        generics: vec![("n".into(), n.to_string())],
    }
}

fn sim_options() -> SimOptions {
    SimOptions {
        stop: STOP,
        reltol: RELTOL,
        probes: vec!["v_out".into()],
        ..SimOptions::default()
    }
}

fn run_vams(design: &Design) -> Waveforms {
    simulate(design, &sim_options(), &mut |_| {})
        .expect("ladder simulates")
        .waveforms
}

/// The same ladder as a SPICE deck: every capacitor starts at 0 V (`uic`), the source is 1 V.
fn spice_deck(n: usize, data: &Path) -> String {
    let (r, c) = (R_TOTAL / n as f64, C_TOTAL / n as f64);
    let mut deck = format!("* RC ladder, {n} sections\nV1 n0 0 DC 1\n");
    for k in 1..=n {
        deck += &format!("R{k} n{} n{k} {r:e}\nC{k} n{k} 0 {c:e} IC=0\n", k - 1);
    }
    deck += &format!(
        ".options reltol={RELTOL:e}\n.control\nset wr_singlescale\nset numdgt=12\n\
         tran {:e} {STOP:e} uic\nwrdata {} v(n{n})\nquit\n.endc\n.end\n",
        STOP / 1000.0,
        data.display()
    );
    deck
}

/// Runs ngspice on the ladder: wall time and `(t, v_out)` pairs, or why it could not.
fn run_ngspice(n: usize) -> Result<(Duration, Vec<(f64, f64)>), String> {
    let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
    let (cir, data) = (dir.path().join("ladder.cir"), dir.path().join("out.txt"));
    std::fs::write(&cir, spice_deck(n, &data)).map_err(|e| e.to_string())?;
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
    let points = text
        .lines()
        .filter_map(|l| {
            let mut f = l.split_whitespace().map(str::parse::<f64>);
            Some((f.next()?.ok()?, f.next()?.ok()?))
        })
        .collect();
    Ok((wall, points))
}

fn compare_with_ngspice(sources: &SourceMap, files: &[(FileId, DesignFile)]) {
    println!("RC ladder, stop {STOP} s, reltol {RELTOL}: vams vs ngspice -b (wall times, one run)");
    for n in sizes() {
        let start = Instant::now();
        let design = elaborate(sources, files, &elab_options(n)).expect("ladder elaborates");
        let elab = start.elapsed();
        let start = Instant::now();
        let w = run_vams(&design);
        let sim = start.elapsed();
        print!(
            "  N = {n:>5}: vams elaborate {:>9.3} ms, simulate {:>9.3} ms ({} points)",
            elab.as_secs_f64() * 1e3,
            sim.as_secs_f64() * 1e3,
            w.times.len()
        );
        match run_ngspice(n) {
            Ok((wall, points)) => {
                let worst = points
                    .iter()
                    .filter_map(|&(t, v)| Some((w.value_at("v_out", t)? - v).abs()))
                    .fold(0.0_f64, f64::max);
                println!(
                    "; ngspice {:>9.3} ms ({} points); max |v_out difference| {worst:.2e} V",
                    wall.as_secs_f64() * 1e3,
                    points.len()
                );
            }
            Err(why) => println!("; no ngspice comparison: {why}"),
        }
    }
}

fn ladder(c: &mut Criterion) {
    let (sources, files) = load();
    compare_with_ngspice(&sources, &files);
    let mut group = c.benchmark_group("ladder");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(5));
    for n in sizes() {
        let options = elab_options(n);
        group.bench_with_input(BenchmarkId::new("elaborate", n), &n, |b, _| {
            b.iter(|| black_box(elaborate(&sources, &files, &options).expect("elaborates")))
        });
        let design = elaborate(&sources, &files, &options).expect("elaborates");
        group.bench_with_input(BenchmarkId::new("simulate", n), &n, |b, _| {
            b.iter(|| black_box(run_vams(&design)))
        });
    }
    group.finish();
}

criterion_group!(benches, ladder);
criterion_main!(benches);
