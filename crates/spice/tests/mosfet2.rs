//! The level 2 MOSFET (ngspice's mos2) lowered and run: Id-Vds curves at several gate and
//! bulk biases (subthreshold with `nfs`, mobility degradation, the
//! short-channel threshold, `lambda` computed from `nsub`; nmos and pmos; both modes)
//! against `ngspice -b` where it is installed (skipped with a printed reason where not), and
//! the shared CMOS Schmitt trigger: refused for its `vmax`, and without `vmax` against
//! ngspice's run of the same deck.

use std::path::Path;

use vams_simulation::kernel::{SimOptions, simulate};
use vams_spice::{lower, outputs, transient};

mod support;
use support::{circuit, crossings, design, ngspice, op, rel, value};

/// The Schmitt deck's models (no rd/rs, no vmax), and one without `vmax`/`nfs`/`lambda` (the
/// channel-length modulation from `nsub`), with `delta` and `tox`-derived kp.
const MODELS: &str = "\
.model nenh nmos (Level=2 Ld=-0.168u Tox=241.000e-10 Nsub=1.066e+16 Vto=0.7610 Kp=3.843E-05
+ Gamma=.639243 Phi=.31 Uo=790. Uexp=4.612355e-2 Ucrit=174667 Delta=0.0 Xj=.9u
+ Lambda=0.0 Nfs=4.55168e+12 Neff=4.68830 Nss=3.000000E+10 Tpg=1)
.model penh pmos (Level=2 Ld=-.138000u Tox=241.000e-10 Nsub=6.575441e+16 Vto=-0.79000
+ Kp=1.601e-05 Gamma=0.618101 Phi=.541111 Uo=235.0 Uexp=8.886957e-02 Ucrit=637449 Delta=0.0
+ Xj=0.112799u Lambda=0. Nfs=1.668437e+11 Neff=0.64354 Nss=3.000000E+10 Tpg=-1)
.model nplain nmos (level=2 tox=30n nsub=2e16 uo=600 xj=0.5u delta=0.5 ucrit=2e4 uexp=0.1 nss=1e10)
";

fn curve_deck(model: &str, sign: f64, vg: f64, vb: f64, vd: f64) -> String {
    format!(
        "level 2 curve\n\
         vd d 0 {}\n\
         vg g 0 {}\n\
         vb b 0 {}\n\
         m1 d g 0 b {model} l=2u w=10u\n\
         {MODELS}\
         .options reltol=1e-7\n\
         .dc vd {} {} {}\n\
         .print dc i(vd)\n\
         .end\n",
        sign * vd,
        sign * vg,
        sign * vb,
        -sign,
        4.0 * sign,
        0.25 * sign,
    )
}

#[test]
fn level2_curves_agree_with_ngspice() {
    let mut worst: f64 = 0.0;
    let mut points = 0;
    let mut bad = Vec::new();
    for (model, sign) in [("nenh", 1.0), ("penh", -1.0), ("nplain", 1.0)] {
        for (vg, vb) in [(0.3, 0.0), (0.7, 0.0), (1.5, 0.0), (3.0, -1.0), (5.0, 0.0)] {
            let Some(rows) = ngspice(&curve_deck(model, sign, vg, vb, 0.0)) else {
                return;
            };
            assert_eq!(rows.len(), 21, "{model} {vg} {vb}: {rows:?}");
            for row in &rows {
                let vd = row[0];
                let ours = value(
                    &op(&curve_deck(model, sign, vg, vb, vd * sign), Some(1e-7)),
                    "i(vd)",
                );
                let ng = row[1];
                let e = rel(ours, ng, 1e-12);
                worst = worst.max(e);
                points += 1;
                if e >= 1e-3 {
                    bad.push(format!(
                        "{model} vg {vg} vb {vb} vd {vd}: {ours} vs ngspice {ng}"
                    ));
                }
            }
        }
    }
    assert!(
        bad.is_empty(),
        "{} of {points} points differ:\n{}",
        bad.len(),
        bad.join("\n")
    );
    println!("mosfet level 2: {points} bias points, worst relative error {worst:e} (ngspice)");
}

/// The deck's v(6) crossings of 2.5 V and the input there (v(7), a 0 -> 5 -> 0 V triangle
/// over 20 us).
fn thresholds(edges: &[f64]) -> (f64, f64) {
    let input = |t: f64| {
        if t <= 10e-6 {
            t / 2e-6
        } else {
            (20e-6 - t) / 2e-6
        }
    };
    (input(edges[0]), input(edges[1]))
}

#[test]
fn cmos_schmitt_is_refused_for_vmax_and_agrees_with_ngspice_without_it() {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/cases/spice/cmos_schmitt.cir");
    let Ok(text) = std::fs::read_to_string(&path) else {
        println!("skipped: {} is absent", path.display());
        return;
    };
    match lower(&circuit(&text)) {
        Ok(_) => panic!("the deck's vmax is not refused"),
        Err(errors) => {
            let all = format!("{errors:?}");
            assert!(all.contains("vmax"), "{all}");
        }
    }
    // The same deck without velocity saturation.
    let text = text.replace("Vmax=177269", "").replace("Vmax=637449", "");
    let c = circuit(&text);
    let d = design(&c);
    let Some(t) = transient(&c) else {
        panic!("the deck has no .tran")
    };
    let options = SimOptions {
        stop: t.tstop,
        reltol: 1e-4,
        max_step: Some(t.tstep * 10.0),
        probes: outputs(&c),
        ..SimOptions::default()
    };
    let w = match simulate(&d, &options, &mut |_| {}) {
        Ok(r) => r.waveforms,
        Err(e) => panic!("{e:?}"),
    };
    let Some(out) = w.column("v(6)").map(|c| &c.values) else {
        panic!("no v(6) column")
    };
    let edges = crossings(&w.times, out, 2.5);
    assert_eq!(edges.len(), 2, "v(6) crosses 2.5 V at {edges:?}");
    let (high, low) = thresholds(&edges);
    println!(
        "cmos_schmitt without vmax: falls at {:e} s (v(7) = {high} V), rises at {:e} s \
         (v(7) = {low} V); {} steps",
        edges[0],
        edges[1],
        w.times.len()
    );
    let reference = text
        .replace(".tran 10n 20u", ".options reltol=1e-4\n.tran 10n 20u 0 10n")
        .replace(".print tran v(7) v(6) v(2) v(4)", ".print tran v(6)");
    let Some(rows) = ngspice(&reference) else {
        return;
    };
    let times: Vec<f64> = rows.iter().map(|r| r[0]).collect();
    let values: Vec<f64> = rows.iter().map(|r| r[1]).collect();
    let theirs = crossings(&times, &values, 2.5);
    assert_eq!(
        theirs.len(),
        2,
        "ngspice's v(6) crosses 2.5 V at {theirs:?}"
    );
    let (ng_high, ng_low) = thresholds(&theirs);
    println!("ngspice without vmax: v(7) = {ng_high} V and {ng_low} V");
    assert!(
        rel(high, ng_high, 0.0) < 0.01,
        "upper threshold {high} V, ngspice {ng_high}"
    );
    assert!(
        rel(low, ng_low, 0.0) < 0.01,
        "lower threshold {low} V, ngspice {ng_low}"
    );
    for (ours, ng) in edges.iter().zip(&theirs) {
        assert!(
            (ours - ng).abs() < 0.05e-6,
            "edge at {ours:e}, ngspice {ng:e}"
        );
    }
}
