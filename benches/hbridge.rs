//! Small-system speed (issue 3): a behavioural H-bridge driving a DC motor with 20 kHz PWM at
//! 60 % duty for 20 ms (`benches/models/hbridge_pwm.vhd`, 22 unknowns), in vams and, when
//! `ngspice` is on the PATH, the same circuit in `ngspice -b` (reltol 1e-3 in both; the motor
//! as its electrical analogue: back-EMF a B source, inertia a capacitor, friction a
//! resistor). Prints a table: unknowns, time, accepted time points, points per second, Newton
//! iterations per point, and the largest difference of motor current and speed at ngspice's
//! time points. Then criterion times the vams run alone.
//!
//! Run: `cargo bench --bench hbridge`.

mod common;

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use vams::analog::AnalogSystem;
use vams::design::Design;
use vams::kernel::{SimOptions, SimResult, simulate};

use common::{NgspiceRun, median_of, run_ngspice};

/// 400 PWM periods. The vams run stops 10 ns later, past the switching event at 20 ms, so
/// that both simulators take the same number of breaks.
const STOP: f64 = 20e-3;
const VAMS_STOP: f64 = STOP + 10e-9;
const RELTOL: f64 = 1e-3;
/// Runs timed for the table: vams's median of `RUNS` runs, ngspice's mean of `NGSPICE_RUNS`.
const RUNS: usize = 21;
const NGSPICE_RUNS: usize = 5;
/// ngspice takes about 15 600 points in 20 ms; a step ceiling of 1.25 us gives vams about as
/// many, for the per-point cost at equal point density.
const DENSE_MAX_STEP: f64 = 1.25e-6;

fn hbridge() -> Design {
    common::design(
        &["models/dc_motor.vhd", "benches/models/hbridge_pwm.vhd"],
        "hbridge_pwm",
        &[],
    )
}

fn run_vams(design: &Design, max_step: Option<f64>) -> SimResult {
    let options = SimOptions {
        stop: VAMS_STOP,
        reltol: RELTOL,
        max_step,
        probes: vec!["motor.i".into(), "motor.w".into()],
        ..SimOptions::default()
    };
    simulate(design, &options, &mut |_| {}).expect("the H-bridge simulates")
}

/// The model's circuit with its default generics. The PWM control is a pulse with 10 ns
/// edges centred on vams's switching instants; hs1 is a B source whose conductance follows
/// it; hs2 (always off), ls1 (off: the diode freewheels) and ls2 (always on) are resistors.
const NETLIST: &str = "\
.param ron=0.1 roff=1e6 r=4 l=3e-3 kt=0.015 ke=0.015 d=1.5e-6 j=1e-6
Vsup vs 0 DC 12
Vctl ctl 0 PULSE(1 0 29.995u 10n 10n 19.99u 50u)
Bhs1 vs out1 I = V(vs,out1) * (1/roff + (1/ron - 1/roff) * V(ctl))
Rls1 out1 0 {roff}
Rhs2 vs out2 {roff}
Rls2 out2 0 {ron}
Ddh out1 vs dfw
Ddl 0 out1 dfw
.model dfw D(IS=1e-8 N=1 RS=0)
Ra out1 m1 {r}
La m1 m2 {l} IC=0
Vsense m2 m3 DC 0
Bemf m3 out2 V = ke * V(w)
Cj w 0 {j} IC=0
Rd w 0 {1/d}
Bt 0 w I = kt * I(Vsense)
.options reltol=1e-3";

/// Step ceiling one PWM period, so that only accuracy and the breakpoints limit ngspice.
const TRAN: &str = "tran 1u 20m 0 50u uic";

fn row(name: &str, unknowns: Option<usize>, secs: f64, points: usize, iterations: Option<usize>) {
    let cell = |x: Option<usize>| x.map_or("-".to_string(), |x| x.to_string());
    let per_point = iterations.map_or("-".to_string(), |n| {
        format!("{:.2}", n as f64 / points as f64)
    });
    println!(
        "  {name:<18} {:>8} {:>10.2} {:>10} {:>12.0} {:>10}",
        cell(unknowns),
        secs * 1e3,
        points,
        points as f64 / secs,
        per_point
    );
}

fn compare(vams: &SimResult, ngspice: &NgspiceRun) {
    let w = &vams.waveforms;
    let (mut di, mut dw, mut peak_i, mut peak_w) = (0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64);
    for r in &ngspice.rows {
        let (Some(i), Some(s)) = (w.value_at("motor.i", r[0]), w.value_at("motor.w", r[0])) else {
            continue;
        };
        di = di.max((i - r[1]).abs());
        dw = dw.max((s - r[2]).abs());
        peak_i = peak_i.max(r[1].abs());
        peak_w = peak_w.max(r[2].abs());
    }
    println!(
        "  largest difference at ngspice's {} time points: motor current {di:.2e} A \
         (peak {peak_i:.3} A), speed {dw:.2e} rad/s (peak {peak_w:.1} rad/s)",
        ngspice.rows.len()
    );
}

fn table(design: &Design) {
    let unknowns = AnalogSystem::new(design).ok().map(|s| s.unknowns().len());
    let (time, result) = median_of(RUNS, || run_vams(design, None));
    let stats = result.stats;
    println!(
        "H-bridge PWM (20 kHz, 60 % duty, 20 ms), reltol {RELTOL}; vams: median of {RUNS} runs, \
         ngspice: mean of {NGSPICE_RUNS}\n  {:<18} {:>8} {:>10} {:>10} {:>12} {:>10}",
        "", "unknowns", "time [ms]", "points", "points/s", "Newton/pt"
    );
    row(
        "vams simulate",
        unknowns,
        time.as_secs_f64(),
        stats.accepted_steps,
        Some(stats.newton_iterations),
    );
    let (dense_time, dense) = median_of(RUNS, || run_vams(design, Some(DENSE_MAX_STEP)));
    row(
        "  max-step 1.25 us",
        unknowns,
        dense_time.as_secs_f64(),
        dense.stats.accepted_steps,
        Some(dense.stats.newton_iterations),
    );
    match run_ngspice(NETLIST, TRAN, &["i(vsense)", "v(w)"], NGSPICE_RUNS) {
        Ok(ng) => {
            let points = ng.accepted.unwrap_or(ng.rows.len());
            let secs = ng
                .analysis
                .unwrap_or(ng.wall.as_secs_f64() / NGSPICE_RUNS as f64);
            row(
                "ngspice transient",
                ng.equations,
                secs,
                points,
                ng.iterations,
            );
            println!(
                "  (ngspice -b process with start-up and {NGSPICE_RUNS} runs: {:.1} ms)",
                ng.wall.as_secs_f64() * 1e3
            );
            compare(&result, &ng);
        }
        Err(why) => println!("  no ngspice comparison: {why}"),
    }
}

fn bench(c: &mut Criterion) {
    let design = hbridge();
    table(&design);
    let mut group = c.benchmark_group("hbridge");
    group
        .sample_size(20)
        .measurement_time(Duration::from_secs(5));
    group.bench_function("simulate/20ms", |b| {
        b.iter(|| black_box(run_vams(&design, None)))
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
