//! RC ladder of N sections (`tests/simulate/rc_ladder.vhd`, N = 10, 100, 1000): vams's
//! elaboration and simulation timed separately with criterion, and, when `ngspice` is on the
//! PATH, the same circuit in `ngspice -b` (reltol 1e-3 in both) with wall times and the largest
//! difference of the output node's waveform at ngspice's time points. Without ngspice the
//! comparison says so and only the vams part runs (`benches/ngspice/install.sh` installs it).
//!
//! Run: `cargo bench --bench ladder` (sizes: `LADDER_SIZES=10,100 cargo bench --bench ladder`).

mod common;

use std::hint::black_box;
use std::path::PathBuf;
use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use vams::app::load::{Loaded, load};
use vams::design::Design;
use vams::elaborate::{ElabOptions, elaborate};
use vams::kernel::{SimOptions, simulate};
use vams::waveform::Waveforms;

use common::run_ngspice;

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

/// The ladder model with the stdlib, parsed once (each size elaborates it again).
fn load_ladder() -> Loaded {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/simulate/rc_ladder.vhd");
    let loaded = load(&[path]).expect("ladder model readable");
    assert_eq!(loaded.error_count(), 0, "{:?}", loaded.syntax_errors);
    loaded
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

/// The same ladder as SPICE elements: every capacitor starts at 0 V (`uic`), the source is 1 V.
fn spice_netlist(n: usize) -> String {
    let (r, c) = (R_TOTAL / n as f64, C_TOTAL / n as f64);
    let mut netlist = format!("V1 n0 0 DC 1\n.options reltol={RELTOL:e}\n");
    for k in 1..=n {
        netlist += &format!("R{k} n{} n{k} {r:e}\nC{k} n{k} 0 {c:e} IC=0\n", k - 1);
    }
    netlist
}

fn compare_with_ngspice(loaded: &Loaded) {
    println!("RC ladder, stop {STOP} s, reltol {RELTOL}: vams vs ngspice -b (wall times, one run)");
    for n in sizes() {
        let start = Instant::now();
        let design =
            elaborate(&loaded.sources, &loaded.files, &elab_options(n)).expect("ladder elaborates");
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
        let tran = format!("tran {:e} {STOP:e} uic", STOP / 1000.0);
        match run_ngspice(&spice_netlist(n), &tran, &[&format!("v(n{n})")], 1) {
            Ok(run) => {
                let worst = run
                    .rows
                    .iter()
                    .filter_map(|row| Some((w.value_at("v_out", row[0])? - row[1]).abs()))
                    .fold(0.0_f64, f64::max);
                println!(
                    "; ngspice {:>9.3} ms ({} points); max |v_out difference| {worst:.2e} V",
                    run.wall.as_secs_f64() * 1e3,
                    run.rows.len()
                );
            }
            Err(why) => println!("; no ngspice comparison: {why}"),
        }
    }
}

fn ladder(c: &mut Criterion) {
    let loaded = load_ladder();
    compare_with_ngspice(&loaded);
    let (sources, files) = (&loaded.sources, &loaded.files);
    let mut group = c.benchmark_group("ladder");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(5));
    for n in sizes() {
        let options = elab_options(n);
        group.bench_with_input(BenchmarkId::new("elaborate", n), &n, |b, _| {
            b.iter(|| black_box(elaborate(sources, files, &options).expect("elaborates")))
        });
        let design = elaborate(sources, files, &options).expect("elaborates");
        group.bench_with_input(BenchmarkId::new("simulate", n), &n, |b, _| {
            b.iter(|| black_box(run_vams(&design)))
        });
    }
    group.finish();
}

criterion_group!(benches, ladder);
criterion_main!(benches);
