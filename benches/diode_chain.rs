//! The nonlinear benchmark of the analog-correctness issue: a chain of N stages (100 Ohm, a
//! diode, 10 nF in parallel with 10 kOhm; `benches/models/diode_chain.vhd`) driven by a 5 V,
//! 10 kHz sine for 1 ms, N = 100, 1 000, 10 000, in vams and in `ngspice -b` on the same
//! netlist (default tolerances in both: reltol 1e-3; ngspice's `tran 1u 1m`, whose step
//! ceiling is 1 us). For each N: the time of each (vams: parsing, elaboration and simulation,
//! and the simulation alone, medians of a few runs; ngspice: its whole process, netlist
//! parsing included, and its own analysis time), time points and Newton iterations, and the accuracy of both: the
//! largest distance of the first three stages' voltages (the wave dies out after about seven
//! diodes) from ngspice at reltol 1e-7 with a 0.1 us step ceiling, as a fraction of each
//! stage's swing (the reference is the chain's first 20 stages: the later ones, all diodes
//! off, load the third by less than its junction's leakage). A second vams row compares at
//! equal accuracy, as the motor bench does: the loosest reltol (2e-3, 5e-3, 1e-2) at which
//! vams is still no further from the reference than ngspice at its default.
//!
//! Run: `cargo bench --bench diode_chain` (sizes: `DIODE_CHAIN_SIZES=100,1000`). Without
//! ngspice on the PATH only the vams part runs.

mod common;

use std::time::{Duration, Instant};

use vams::kernel::{SimOptions, SimResult, simulate};

use common::{NgspiceRun, median_of, run_ngspice};

const STOP: f64 = 1e-3;
const MODEL: &str = "benches/models/diode_chain.vhd";
const PROBES: [&str; 3] = ["v_1", "v_2", "v_3"];
const NODES: [&str; 3] = ["v(n1)", "v(n2)", "v(n3)"];

fn sizes() -> Vec<usize> {
    std::env::var("DIODE_CHAIN_SIZES")
        .ok()
        .map(|s| s.split(',').filter_map(|n| n.trim().parse().ok()).collect())
        .filter(|v: &Vec<usize>| !v.is_empty())
        .unwrap_or_else(|| vec![100, 1000, 10000])
}

/// Parsing, elaboration and simulation at `reltol`, as `vams run` does them; the time of the
/// simulation alone beside the result (ngspice's analysis time is the counterpart).
fn run_vams(n: usize, reltol: f64) -> (Duration, SimResult) {
    let design = common::design(&[MODEL], "diode_chain", &[("n", n.to_string())]);
    let options = SimOptions {
        stop: STOP,
        reltol,
        probes: PROBES.iter().map(|p| p.to_string()).collect(),
        ..SimOptions::default()
    };
    let start = Instant::now();
    let result = simulate(&design, &options, &mut |_| {}).expect("the diode chain simulates");
    (start.elapsed(), result)
}

/// Medians of `runs` runs of [`run_vams`]: whole, simulation alone, and the last result.
fn time_vams(n: usize, reltol: f64, runs: usize) -> (Duration, Duration, SimResult) {
    let mut simulation = Vec::new();
    let (time, result) = median_of(runs, || {
        let (sim, result) = run_vams(n, reltol);
        simulation.push(sim);
        result
    });
    simulation.sort();
    (time, simulation[simulation.len() / 2], result)
}

/// The probes' columns of a vams result, in `PROBES` order.
fn columns(result: &SimResult) -> Vec<Vec<f64>> {
    PROBES
        .iter()
        .map(|p| {
            let column = result.waveforms.column(p).expect("probe recorded");
            column.values.clone()
        })
        .collect()
}

/// The same circuit for ngspice: the default diode (IS 1e-14, no series resistance or
/// capacitance) with ngspice's GMIN across it, as the model's `chain_diode`, at 300 K (where
/// ngspice's thermal voltage is the model's `vt`).
fn netlist(n: usize, reltol: f64) -> String {
    let mut s = format!(
        ".options reltol={reltol:e} temp=26.85 tnom=26.85\n.model dchain D(IS=1e-14)\n\
         V1 n0 0 SIN(0 5 10k)\n"
    );
    for k in 1..=n {
        s += &format!(
            "R{k} n{} m{k} 100\nD{k} m{k} n{k} dchain\nC{k} n{k} 0 10n\nRL{k} n{k} 0 10k\n",
            k - 1
        );
    }
    s
}

/// Linear interpolation of `(times, values)` at `t`.
fn at(times: &[f64], values: &[f64], t: f64) -> f64 {
    let i = times.partition_point(|&x| x < t);
    if i == 0 {
        return values[0];
    }
    if i >= times.len() {
        return values[values.len() - 1];
    }
    let a = (t - times[i - 1]) / (times[i] - times[i - 1]);
    values[i - 1] + a * (values[i] - values[i - 1])
}

/// The largest distance from the reference over the three stages, at the reference's points,
/// as a fraction of each stage's swing in the reference.
fn error(reference: &NgspiceRun, times: &[f64], columns: &[Vec<f64>]) -> f64 {
    let ref_times: Vec<f64> = reference.rows.iter().map(|r| r[0]).collect();
    let mut worst = 0.0_f64;
    for (k, values) in columns.iter().enumerate() {
        let reference_values: Vec<f64> = reference.rows.iter().map(|r| r[k + 1]).collect();
        let (lo, hi) = reference_values
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &v| {
                (l.min(v), h.max(v))
            });
        for (&t, &r) in ref_times.iter().zip(&reference_values) {
            worst = worst.max((at(times, values, t) - r).abs() / (hi - lo));
        }
    }
    worst
}

fn main() {
    println!(
        "diode chain, 5 V 10 kHz sine, {} ms, reltol 1e-3; error: largest distance of stages 1-3 \
         from ngspice at reltol 1e-7, of their swing",
        STOP * 1e3
    );
    for n in sizes() {
        let runs = if n >= 10000 { 1 } else { 5 };
        let (time, simulation, result) = time_vams(n, 1e-3, runs);
        let stats = result.stats;
        print!(
            "  N = {n:>5}: vams {:>8.1} ms (simulation {:.1} ms), {} points, {} Newton iterations",
            ms(time),
            ms(simulation),
            stats.accepted_steps,
            stats.newton_iterations
        );
        let tight = run_ngspice(&netlist(n.min(20), 1e-7), "tran 0.1u 1m 0 0.1u", &NODES, 1);
        let start = Instant::now();
        let spice = run_ngspice(&netlist(n, 1e-3), "tran 1u 1m", &NODES, 1);
        let spice_wall = start.elapsed();
        let (spice, tight) = match (spice, tight) {
            (Ok(spice), Ok(tight)) => (spice, tight),
            (Err(why), _) | (_, Err(why)) => {
                println!("; no ngspice comparison: {why}");
                continue;
            }
        };
        let spice_times: Vec<f64> = spice.rows.iter().map(|r| r[0]).collect();
        let spice_columns: Vec<Vec<f64>> = (1..=3)
            .map(|k| spice.rows.iter().map(|r| r[k]).collect())
            .collect();
        let spice_error = error(&tight, &spice_times, &spice_columns);
        println!(
            ", error {:.1e}; ngspice {:>8.1} ms (analysis {:.1} ms), {} points, {} iterations, \
             error {:.1e}",
            error(&tight, &result.waveforms.times, &columns(&result)),
            ms(spice_wall),
            spice.analysis.unwrap_or(f64::NAN) * 1e3,
            spice.accepted.unwrap_or(0),
            spice.iterations.unwrap_or(0),
            spice_error,
        );
        // At equal accuracy (as the motor bench compares): the loosest reltol of 1e-3, 2e-3,
        // 5e-3, 1e-2 at which vams is no further from the reference than ngspice at 1e-3.
        let mut equal = None;
        for reltol in [2e-3, 5e-3, 1e-2] {
            let (time, simulation, result) = time_vams(n, reltol, runs);
            let e = error(&tight, &result.waveforms.times, &columns(&result));
            if e > spice_error {
                break;
            }
            equal = Some((reltol, time, simulation, result.stats, e));
        }
        if let Some((reltol, time, simulation, stats, e)) = equal {
            println!(
                "           vams at ngspice's accuracy (reltol {reltol:.0e}): {:>8.1} ms \
                 (simulation {:.1} ms), {} points, {} Newton iterations, error {e:.1e}",
                ms(time),
                ms(simulation),
                stats.accepted_steps,
                stats.newton_iterations,
            );
        }
    }
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}
