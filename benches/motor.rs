//! DC motor step at equal accuracy (issue 3): `models/dc_motor.vhd` on a 12 V step from rest
//! (`tests/analog/motor_step.vhd`) in vams and, when `ngspice` is on the PATH, the motor's
//! electrical analogue in `ngspice -b` (back-EMF a B source, inertia a capacitor, friction a
//! resistor). Both against the exact solution of the linear second-order system, at each
//! simulator's own time points, at reltol 1e-3 and 1e-6; then the loosest ngspice reltol whose
//! error is no larger than vams's at 1e-3. Then, at equal accuracy, the loosest reltol (and
//! its time and points) at which vams with BDF up to order 2 (what it had before issue 15),
//! vams up to order 5 (the default) and ngspice reach an error of 1e-6 and 1e-8 against the
//! closed form. Then criterion times the vams runs alone.
//!
//! Run: `cargo bench --bench motor`.

mod common;

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use vams::design::Design;
use vams::kernel::{SimOptions, SimResult, simulate};

use common::{mean_of, run_ngspice};

/// models/dc_motor.vhd's defaults and the step of tests/analog/motor_step.vhd.
const R: f64 = 4.0;
const L: f64 = 3.0e-3;
const KT: f64 = 0.015;
const KE: f64 = 0.015;
const D: f64 = 1.5e-6;
const J: f64 = 1.0e-6;
const V: f64 = 12.0;
/// About six mechanical time constants (the slow eigenvalue is about -60 /s).
const STOP: f64 = 0.1;
/// Runs per timing (mean): ngspice's timer has 1 ms resolution and one run takes less.
const RUNS: usize = 200;
/// ngspice reltols tried, loosest first, for the one matching vams's error at 1e-3.
const SWEEP: [f64; 9] = [1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6, 3e-7, 1e-7];

/// `(i, w)` at `t` for `L i' = V - R i - ke w`, `J w' = kt i - d w` from rest: the steady
/// state plus `exp(A t)` applied to the initial offset, with the 2 x 2 exponential
/// `exp(A t) = exp(m t) (c(t) I + s(t) (A - m I))`, `m` half the trace, `q = m^2 - det`,
/// `c = cosh(sqrt(q) t)`, `s = sinh(sqrt(q) t) / sqrt(q)` (cos and sin when `q < 0`).
fn exact(t: f64) -> (f64, f64) {
    let a = [[-R / L, -KE / L], [KT / J, -D / J]];
    let det = R * D + KE * KT;
    let (i_ss, w_ss) = (V * D / det, V * KT / det);
    let m = (a[0][0] + a[1][1]) / 2.0;
    let q = m * m - (a[0][0] * a[1][1] - a[0][1] * a[1][0]);
    let (c, s) = if q > 0.0 {
        let r = q.sqrt();
        ((r * t).cosh(), (r * t).sinh() / r)
    } else if q < 0.0 {
        let r = (-q).sqrt();
        ((r * t).cos(), (r * t).sin() / r)
    } else {
        (1.0, t)
    };
    let (x0, y0) = (-i_ss, -w_ss);
    let e = (m * t).exp();
    let i = i_ss + e * (c * x0 + s * ((a[0][0] - m) * x0 + a[0][1] * y0));
    let w = w_ss + e * (c * y0 + s * (a[1][0] * x0 + (a[1][1] - m) * y0));
    (i, w)
}

/// Largest error of current and speed over `(t, i, w)` samples, each relative to its peak.
fn errors(samples: impl Iterator<Item = (f64, f64, f64)>) -> (f64, f64) {
    let (i_peak, w_peak) = (V / R, exact(STOP).1);
    samples.fold((0.0_f64, 0.0_f64), |(ei, ew), (t, i, w)| {
        let (xi, xw) = exact(t);
        (
            ei.max((i - xi).abs() / i_peak),
            ew.max((w - xw).abs() / w_peak),
        )
    })
}

fn motor() -> Design {
    common::design(
        &["models/dc_motor.vhd", "tests/analog/motor_step.vhd"],
        "motor_step",
        &[],
    )
}

fn run_vams(design: &Design, reltol: f64) -> SimResult {
    run_vams_with(design, reltol, SimOptions::default())
}

/// A run for the equal-accuracy table: BDF up to `max_order`, and an absolute tolerance far
/// below the errors asked for (1e-8 of 3 A and of 8 000 rad/s), so that `reltol` alone sets
/// the accuracy.
fn run_vams_at_order(design: &Design, reltol: f64, max_order: usize) -> SimResult {
    let options = SimOptions {
        max_order,
        abstol: Some(1e-13),
        ..SimOptions::default()
    };
    run_vams_with(design, reltol, options)
}

fn run_vams_with(design: &Design, reltol: f64, options: SimOptions) -> SimResult {
    let options = SimOptions {
        stop: STOP,
        reltol,
        probes: vec!["motor.i".into(), "motor.w".into()],
        ..options
    };
    simulate(design, &options, &mut |_| {}).expect("the motor simulates")
}

fn vams_errors(result: &SimResult) -> (f64, f64) {
    let w = &result.waveforms;
    let (i, s) = (
        &w.column("motor.i").expect("motor.i recorded").values,
        &w.column("motor.w").expect("motor.w recorded").values,
    );
    errors((0..w.times.len()).map(|k| (w.times[k], i[k], s[k])))
}

fn netlist(reltol: f64) -> String {
    format!(
        "V1 p 0 DC {V}\nRa p m1 {R}\nLa m1 m2 {L} IC=0\nVsense m2 m3 DC 0\n\
         Bemf m3 0 V = {KE} * V(w)\nCj w 0 {J} IC=0\nRd w 0 {}\nBt 0 w I = {KT} * I(Vsense)\n\
         .options reltol={reltol:e}",
        1.0 / D
    )
}

/// Step ceiling STOP / 50 (ngspice's own default for a small print step), so that the error
/// control sets the steps.
const TRAN: &str = "tran 10u 0.1 0 2m uic";

/// `(analysis or wall seconds, accepted points, error)` of ngspice at `reltol`.
fn ngspice(reltol: f64) -> Result<(f64, usize, (f64, f64)), String> {
    let run = run_ngspice(&netlist(reltol), TRAN, &["i(vsense)", "v(w)"], RUNS)?;
    let secs = run.analysis.unwrap_or(run.wall.as_secs_f64() / RUNS as f64);
    let points = run.accepted.unwrap_or(run.rows.len());
    let err = errors(run.rows.iter().map(|r| (r[0], r[1], r[2])));
    Ok((secs, points, err))
}

fn line(name: &str, reltol: f64, secs: f64, points: usize, (ei, ew): (f64, f64)) {
    println!(
        "  {name:<8} {reltol:>8.0e} {:>10.3} {points:>8} {ei:>12.2e} {ew:>12.2e}",
        secs * 1e3
    );
}

fn table(design: &Design) {
    println!(
        "DC motor 12 V step, 0.1 s, against the closed form (errors relative to V/R and the \
         final speed), mean of {RUNS} runs\n  {:<8} {:>8} {:>10} {:>8} {:>12} {:>12}",
        "", "reltol", "time [ms]", "points", "current err", "speed err"
    );
    let mut vams_at_1e3 = None;
    for reltol in [1e-3, 1e-6] {
        let (time, result) = mean_of(RUNS, || run_vams(design, reltol));
        let err = vams_errors(&result);
        vams_at_1e3.get_or_insert(err);
        line(
            "vams",
            reltol,
            time.as_secs_f64(),
            result.stats.accepted_steps,
            err,
        );
    }
    for reltol in [1e-3, 1e-6] {
        match ngspice(reltol) {
            Ok((secs, points, err)) => line("ngspice", reltol, secs, points, err),
            Err(why) => {
                println!("  no ngspice comparison: {why}");
                return;
            }
        }
    }
    let Some((ti, tw)) = vams_at_1e3 else { return };
    let target = ti.max(tw);
    let matched = SWEEP.iter().find_map(|&reltol| {
        let (secs, points, err) = ngspice(reltol).ok()?;
        (err.0.max(err.1) <= target).then_some((reltol, secs, points, err))
    });
    match matched {
        Some((reltol, secs, points, err)) => {
            println!("  ngspice at vams's reltol 1e-3 accuracy ({target:.2e}):");
            line("ngspice", reltol, secs, points, err);
        }
        None => println!(
            "  no ngspice reltol down to {:.0e} reaches vams's error at 1e-3 ({target:.2e})",
            SWEEP[SWEEP.len() - 1]
        ),
    }
}

/// Reltols tried for the equal-accuracy table, loosest first (half decades).
const FINE_SWEEP: [f64; 17] = [
    1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6, 3e-7, 1e-7, 3e-8, 1e-8, 3e-9, 1e-9, 3e-10, 1e-10,
    3e-11, 1e-11,
];

/// Runs per timing in the equal-accuracy table (the tight runs are longer).
const FINE_RUNS: usize = 20;

/// For each error target, the loosest reltol of [`FINE_SWEEP`] at which each simulator's
/// larger error (current or speed) is within it, with its time and points.
fn equal_accuracy(design: &Design) {
    println!(
        "At equal accuracy: the loosest reltol whose larger error is within the target, mean of          {FINE_RUNS} runs\n  {:<10} {:>8} {:>8} {:>10} {:>8} {:>12}",
        "", "target", "reltol", "time [ms]", "points", "error"
    );
    let vams = |order: usize, reltol: f64| {
        let result = run_vams_at_order(design, reltol, order);
        let (ei, ew) = vams_errors(&result);
        (ei.max(ew), result.stats.accepted_steps)
    };
    for target in [1e-6, 1e-8] {
        for (name, order) in [("vams BDF2", 2), ("vams BDF5", vams::solver::MAX_ORDER)] {
            let found = FINE_SWEEP
                .iter()
                .find(|&&reltol| vams(order, reltol).0 <= target);
            match found {
                Some(&reltol) => {
                    let (time, (err, points)) = mean_of(FINE_RUNS, || vams(order, reltol));
                    fine_line(name, target, reltol, time.as_secs_f64(), points, err);
                }
                None => println!("  {name:<10} {target:>8.0e}  not reached down to reltol 1e-11"),
            }
        }
        let found = FINE_SWEEP.iter().find_map(|&reltol| {
            let (secs, points, (ei, ew)) = ngspice(reltol).ok()?;
            (ei.max(ew) <= target).then_some((reltol, secs, points, ei.max(ew)))
        });
        match found {
            Some((reltol, secs, points, err)) => {
                fine_line("ngspice", target, reltol, secs, points, err)
            }
            None => println!(
                "  {:<10} {target:>8.0e}  not reached down to reltol 1e-11 (or not installed)",
                "ngspice"
            ),
        }
    }
}

fn fine_line(name: &str, target: f64, reltol: f64, secs: f64, points: usize, err: f64) {
    println!(
        "  {name:<10} {target:>8.0e} {reltol:>8.0e} {:>10.3} {points:>8} {err:>12.2e}",
        secs * 1e3
    );
}

fn bench(c: &mut Criterion) {
    let design = motor();
    table(&design);
    equal_accuracy(&design);
    let mut group = c.benchmark_group("motor");
    group
        .sample_size(20)
        .measurement_time(Duration::from_secs(3));
    for reltol in [1e-3, 1e-6] {
        group.bench_with_input(
            BenchmarkId::new("simulate", format!("{reltol:e}")),
            &reltol,
            |b, &r| b.iter(|| black_box(run_vams(&design, r))),
        );
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
