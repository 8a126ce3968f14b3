//! The Gummel-Poon BJT lowered and run: a common-emitter bias point and output curves (npn
//! and pnp) against `ngspice -b` where it is installed (skipped with a printed reason where
//! not), the shared Colpitts oscillator against its reference figures, and the diagnostics
//! of what the BJT lowering refuses (snapshots).

use std::path::Path;

use vams_simulation::kernel::{SimOptions, simulate};
use vams_spice::{outputs, transient};

mod support;
use support::{circuit, design, ngspice_joined, op, rel, render, value};

/// Every DC parameter: Early voltages, roll-off, leakage, series and base resistances.
const NPN: &str = ".model qn npn (is=2e-15 bf=150 br=3 nf=1.01 nr=1.02 vaf=60 var=8 ikf=20m ikr=5m
+ ise=5e-14 ne=1.6 isc=2e-13 nc=1.8 rb=200 rbm=20 irb=50u re=2 rc=15)
";

fn pnp_model() -> String {
    NPN.replace("npn", "pnp").replace(".model qn", ".model qp")
}

/// A common-emitter stage: collector resistor, base divider, emitter resistor, area 2.
fn bias_deck(sign: f64) -> String {
    let (model, name) = if sign > 0.0 {
        (NPN.to_string(), "qn")
    } else {
        (pnp_model(), "qp")
    };
    format!(
        "common emitter\n\
         vcc vcc 0 {}\n\
         rc vcc c 2k\n\
         r1 vcc b 47k\n\
         r2 b 0 10k\n\
         re e 0 330\n\
         q1 c b e {name} 2\n\
         {model}\
         .options reltol=1e-7\n\
         .dc vcc {} {} 1\n\
         .print dc v(c) v(b) v(e) i(vcc)\n\
         .end\n",
        12.0 * sign,
        12.0 * sign,
        12.0 * sign,
    )
}

#[test]
fn common_emitter_bias_point_matches_ngspice() {
    for sign in [1.0, -1.0] {
        let deck = bias_deck(sign);
        let ours = op(&deck, Some(1e-7));
        let names = ["v(c)", "v(b)", "v(e)", "i(vcc)"];
        let mine: Vec<f64> = names.iter().map(|n| value(&ours, n)).collect();
        println!("bjt bias (sign {sign}): {names:?} = {mine:?}");
        // Sanity without ngspice: the transistor conducts, in the active region.
        assert!(
            sign * mine[2] > 0.5 && sign * mine[0] > sign * mine[1],
            "{mine:?}"
        );
        let Some(rows) = ngspice_joined(&deck) else {
            continue;
        };
        assert_eq!(rows.len(), 1, "{rows:?}");
        for (k, name) in names.iter().enumerate() {
            let ng = rows[0][k + 1];
            println!("  {name}: vams {} ngspice {ng}", mine[k]);
            assert!(
                rel(mine[k], ng, 1e-9) < 1e-4,
                "{name}: {} vs ngspice {ng}",
                mine[k]
            );
        }
    }
}

/// The output curve at base current `ib`, collector swept by `.dc vce`.
fn output_deck(ib: f64, vce: f64, sign: f64) -> String {
    let (model, name) = if sign > 0.0 {
        (NPN.to_string(), "qn")
    } else {
        (pnp_model(), "qp")
    };
    format!(
        "output curve\n\
         ib 0 b {}\n\
         vce c 0 {}\n\
         q1 c b 0 {name}\n\
         {model}\
         .options reltol=1e-7\n\
         .dc vce {} {} {}\n\
         .print dc i(vce) v(b)\n\
         .end\n",
        ib * sign,
        vce * sign,
        0.0,
        5.0 * sign,
        0.25 * sign,
    )
}

#[test]
fn output_curves_at_two_base_currents_match_ngspice() {
    let mut worst: f64 = 0.0;
    for sign in [1.0, -1.0] {
        for ib in [10e-6, 40e-6] {
            let Some(rows) = ngspice_joined(&output_deck(ib, 0.0, sign)) else {
                return;
            };
            assert_eq!(rows.len(), 21, "{rows:?}");
            for row in &rows {
                let p = op(&output_deck(ib, row[0] * sign, sign), Some(1e-7));
                for (name, ng, floor) in [("i(vce)", row[1], 1e-9), ("v(b)", row[2], 1e-6)] {
                    let ours = value(&p, name);
                    worst = worst.max(rel(ours, ng, floor));
                    assert!(
                        rel(ours, ng, floor) < 1e-4,
                        "{name} at vce {} ib {ib} sign {sign}: {ours} vs ngspice {ng}",
                        row[0]
                    );
                }
            }
        }
    }
    println!("bjt output curves: worst relative difference {worst:e} against ngspice");
}

/// The times where `col` crosses `level` upwards, interpolated.
fn rising(t: &[f64], col: &[f64], level: f64) -> Vec<f64> {
    let mut out = Vec::new();
    for k in 1..col.len() {
        let (a, b) = (col[k - 1] - level, col[k] - level);
        if a < 0.0 && b >= 0.0 {
            out.push(t[k - 1] + (t[k] - t[k - 1]) * (-a) / (b - a));
        }
    }
    out
}

#[test]
fn colpitts_oscillates_at_the_reference_frequency_and_amplitude() {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/cases/spice/colpitts.cir");
    let Ok(text) = std::fs::read_to_string(&path) else {
        println!("skipped: {} is absent", path.display());
        return;
    };
    let c = circuit(&text);
    let d = design(&c);
    let Some(t) = transient(&c) else {
        panic!("the deck has no .tran")
    };
    let options = SimOptions {
        stop: t.tstop,
        reltol: 1e-4,
        max_step: Some(t.tstep / 10.0),
        probes: outputs(&c),
        ..SimOptions::default()
    };
    let w = match simulate(&d, &options, &mut |_| {}) {
        Ok(r) => r.waveforms,
        Err(e) => panic!("{e:?}"),
    };
    let time = &w.times;
    let Some(v2) = w.column("v(2)").map(|c| &c.values) else {
        panic!("no v(2) column")
    };
    let window = |from: f64, to: f64| -> (Vec<f64>, Vec<f64>) {
        time.iter()
            .zip(v2.iter())
            .filter(|(t, _)| **t >= from && **t <= to)
            .map(|(t, v)| (*t, *v))
            .unzip()
    };
    let (t1, y1) = window(6e-6, 12e-6);
    // The time average (the steps are not uniform).
    let area: f64 = (1..t1.len())
        .map(|k| (t1[k] - t1[k - 1]) * (y1[k] + y1[k - 1]) / 2.0)
        .sum();
    let mean = area / (t1[t1.len() - 1] - t1[0]);
    let ups = rising(&t1, &y1, mean);
    assert!(ups.len() > 10, "no oscillation: {} crossings", ups.len());
    let (first, last) = (ups[0], ups[ups.len() - 1]);
    let f = (ups.len() - 1) as f64 / (last - first);
    let (_, y2) = window(10e-6, 12e-6);
    let hi = y2.iter().copied().fold(f64::MIN, f64::max);
    let lo = y2.iter().copied().fold(f64::MAX, f64::min);
    println!(
        "colpitts: {f:.6e} Hz (reference 3.3425e6), peak-to-peak {:.4} V (5.08), mean {mean:.4} V (5.00)",
        hi - lo
    );
    assert!(rel(f, 3.3425e6, 1.0) < 5e-3, "frequency {f}");
    assert!((hi - lo - 5.08).abs() < 0.1, "peak-to-peak {}", hi - lo);
    assert!((mean - 5.0).abs() < 0.05, "mean {mean}");
}

#[test]
fn what_the_bjt_lowering_refuses_is_named() {
    insta::assert_snapshot!(render(
        "refused\n\
         vcc c 0 5\n\
         q1 c b 0 quasi\n\
         q2 c b 0 lev4 off\n\
         q3 c b 0 good m=2\n\
         q4 c b 0 bad\n\
         .model quasi npn (rco=10 vo=2 gamma=1e-11 qco=1p ptf=20 kf=1e-16 af=1)\n\
         .model lev4 npn (level=4 bf=100)\n\
         .model good npn (bf=100 xtb=1.5 eg=1.2 xti=3)\n\
         .model bad npn (nf=0 fc=1.2 mjc=1)\n\
         .end\n"
    ));
    insta::assert_snapshot!(
        "temperature",
        render(
            "hot\n\
             vcc c 0 5\n\
             q1 c b 0 good\n\
             .model good npn (bf=100 xtb=1.5)\n\
             .temp 85\n\
             .end\n"
        )
    );
}
