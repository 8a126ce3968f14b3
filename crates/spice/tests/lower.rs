//! Decks lowered to designs and run by the simulator, against closed forms (each with its
//! tolerance), against ngspice where it is installed (skipped with a printed reason where
//! not), and the diagnostics of what the lowering refuses (snapshots).

use vams_spice::{MemLoader, SourceMap, flatten, lower, outputs, read_deck};

mod support;
use support::{at, circuit, design, ngspice, op, render, run, value};

#[test]
fn rc_step_follows_one_minus_exp() {
    // A 1 V step (1 ns edge) into 1 kOhm and 1 uF: tau = 1 ms.
    let w = run("rc\n\
         v1 in 0 pwl(0 0 1n 1)\n\
         r1 in out 1k\n\
         c1 out 0 1u\n\
         .tran 10u 5m\n\
         .print tran v(out)\n\
         .end\n");
    let tau: f64 = 1e-3;
    let mut worst: f64 = 0.0;
    for t in [0.2e-3, 0.5e-3, 1e-3, 2e-3, 3e-3, 5e-3] {
        // The 1 ns ramp delays the exponential by half its length.
        let exact = 1.0 - (-(t - 0.5e-9) / tau).exp();
        let rel = (at(&w, "v(out)", t) - exact).abs() / exact;
        worst = worst.max(rel);
    }
    println!("rc: worst relative error {worst:e}");
    assert!(worst < 1e-3, "relative error {worst:e}");
}

#[test]
fn rlc_rings_at_its_damped_frequency() {
    // Series 1 Ohm, 1 mH, 1 uF stepped to 1 V: omega_d = sqrt(1/LC - (R/2L)^2).
    let (r, l, cap): (f64, f64, f64) = (1.0, 1e-3, 1e-6);
    let w = run("rlc\n\
         v1 in 0 pwl(0 0 1n 1)\n\
         r1 in a 1\n\
         l1 a out 1m\n\
         c1 out 0 1u\n\
         .tran 1u 2m\n\
         .print tran v(out)\n\
         .end\n");
    let col = match w.column("v(out)") {
        Some(c) => c,
        None => panic!("no v(out)"),
    };
    // Upward and downward crossings of the final value, 1 V, interpolated.
    let mut crossings = Vec::new();
    for k in 1..w.times.len() {
        let (a, b) = (col.values[k - 1] - 1.0, col.values[k] - 1.0);
        if a != 0.0 && a.signum() != b.signum() {
            let (t0, t1) = (w.times[k - 1], w.times[k]);
            crossings.push(t0 + (t1 - t0) * a / (a - b));
        }
    }
    assert!(crossings.len() >= 10, "{} crossings", crossings.len());
    let n = crossings.len() - 1;
    let half_period = (crossings[n] - crossings[0]) / n as f64;
    let measured = std::f64::consts::PI / half_period;
    let exact = (1.0 / (l * cap) - (r / (2.0 * l)).powi(2)).sqrt();
    let rel = (measured - exact).abs() / exact;
    println!("rlc: omega {measured} vs {exact} (rel {rel:e})");
    assert!(rel < 1e-3, "omega {measured} vs {exact} (rel {rel:e})");
}

#[test]
fn controlled_sources_at_dc_are_exact() {
    // Signs as ngspice 39 gives them (`.op` on this deck): v(4) 1, v(8) 2, v(9) 0.5,
    // i(v1) -1 mA, i(vs) +1 mA.
    let p = op(
        "controlled\n\
         v1 1 0 dc 2\n\
         r1 1 2 1k\n\
         r2 2 0 1k\n\
         e1 3 0 2 0 3\n\
         r3 3 0 1k\n\
         g1 0 4 2 0 1m\n\
         r4 4 0 1k\n\
         v2 6 0 dc 1\n\
         r5 6 7 1k\n\
         vs 7 0 dc 0\n\
         f1 0 8 vs 2\n\
         r6 8 0 1k\n\
         h1 9 0 vs 500\n\
         r7 9 0 1k\n\
         .op\n\
         .end\n",
        None,
    );
    for (name, exact) in [
        ("v(2)", 1.0),
        ("v(3)", 3.0),
        ("v(4)", 1.0),
        ("v(8)", 2.0),
        ("v(9)", 0.5),
        ("i(v1)", -1e-3),
        ("i(vs)", 1e-3),
    ] {
        let v = value(&p, name);
        assert!(
            (v - exact).abs() <= 1e-9 * exact.abs().max(1e-3),
            "{name} = {v} vs {exact}"
        );
    }
}

/// `v` with `i == is*(exp(v/nvt) - 1) + gmin*v` for the given `i`, by Newton.
fn shockley(i: f64, is: f64, nvt: f64, gmin: f64) -> f64 {
    let mut v = nvt * (i / is + 1.0).ln();
    for _ in 0..50 {
        let f = is * ((v / nvt).exp() - 1.0) + gmin * v - i;
        let df = is / nvt * (v / nvt).exp() + gmin;
        v -= f / df;
    }
    v
}

#[test]
fn diode_forward_voltage_at_one_milliamp() {
    let p = op(
        "diode\n\
         i1 0 1 1m\n\
         d1 1 0 dmod\n\
         i2 0 2 1m\n\
         d2 2 0 dmod2\n\
         .model dmod d(is=1e-14 n=1)\n\
         .model dmod2 d(is=1e-14 n=1.5 rs=10)\n\
         .op\n\
         .end\n",
        None,
    );
    let vt = 1.380_648_52e-23 * 300.15 / 1.602_176_620_8e-19;
    let plain = shockley(1e-3, 1e-14, vt, 1e-12);
    let series = shockley(1e-3, 1e-14, 1.5 * vt, 1e-12) + 10.0 * 1e-3;
    let (v1, v2) = (value(&p, "v(1)"), value(&p, "v(2)"));
    println!("diode: {v1} vs {plain}, with rs {v2} vs {series}");
    assert!((v1 - plain).abs() < 1e-6, "{v1} vs {plain}");
    assert!((v2 - series).abs() < 1e-6, "{v2} vs {series}");
    // What ngspice 39 prints for this deck (`.op`, 7 digits): its Newton stops within its
    // vntol (1 uV) and reltol of the root, which the series case shows (5 uV off).
    assert!((v1 - 0.655_118_0).abs() < 1e-6, "{v1} vs ngspice");
    assert!((v2 - 0.992_682_0).abs() < 1e-5, "{v2} vs ngspice");
}

#[test]
fn pulse_levels_and_edges() {
    let w = run("pulse\n\
         v1 1 0 pulse(0 5 1m 0.1m 0.2m 1m 3m)\n\
         r1 1 0 1k\n\
         v2 2 0 pulse(0 1 1m)\n\
         r2 2 0 1k\n\
         .tran 10u 8m\n\
         .print tran v(1) v(2)\n\
         .end\n");
    // v1: rises 1m..1.1m, high until 2.1m, falls until 2.3m; again 3 ms later.
    for (t, exact) in [
        (0.5e-3, 0.0),
        (1.05e-3, 2.5),
        (1.5e-3, 5.0),
        (2.2e-3, 2.5),
        (3.0e-3, 0.0),
        (4.05e-3, 2.5),
        (4.5e-3, 5.0),
        (7.05e-3, 2.5),
        (7.2e-3, 5.0),
    ] {
        let v = at(&w, "v(1)", t);
        assert!((v - exact).abs() < 1e-9, "v(1) at {t} = {v}, not {exact}");
    }
    // The corners are time points of the run.
    for corner in [1e-3, 1.1e-3, 2.1e-3, 2.3e-3, 4e-3, 4.1e-3, 5.1e-3, 5.3e-3] {
        assert!(
            w.times.iter().any(|&t| (t - corner).abs() < 1e-12),
            "no time point at the corner {corner}"
        );
    }
    // v2 with ngspice's defaults: tr = TSTEP (10 us), pw = per = TSTOP.
    assert!((at(&w, "v(2)", 1.005e-3) - 0.5).abs() < 1e-9);
    assert!((at(&w, "v(2)", 7.9e-3) - 1.0).abs() < 1e-9);
}

#[test]
fn sin_amplitude_delay_and_phase() {
    let w = run("sine\n\
         v1 1 0 sin(1 2 1k)\n\
         r1 1 0 1k\n\
         v2 2 0 sin(0 1 1k 1m 0 90)\n\
         r2 2 0 1k\n\
         v3 3 0 exp(0 1 1m 0.2m 2m 0.5m)\n\
         r3 3 0 1k\n\
         .tran 1u 3m\n\
         .print tran v(1) v(2) v(3)\n\
         .end\n");
    let col = match w.column("v(1)") {
        Some(c) => c,
        None => panic!("no v(1)"),
    };
    let max = col.values.iter().copied().fold(f64::MIN, f64::max);
    let min = col.values.iter().copied().fold(f64::MAX, f64::min);
    println!("sin: max {max}, min {min}");
    assert!((max - 3.0).abs() < 1e-3 && (min + 1.0).abs() < 1e-3);
    // Before its delay a SIN holds vo + va*sin(phase); after, it runs from there.
    assert!((at(&w, "v(2)", 0.5e-3) - 1.0).abs() < 1e-9);
    let t = 1.3e-3;
    let exact = (2.0 * std::f64::consts::PI * 1e3 * (t - 1e-3) + std::f64::consts::FRAC_PI_2).sin();
    assert!((at(&w, "v(2)", t) - exact).abs() < 1e-3);
    // EXP: rises from 1 ms with tau 0.2 ms, falls from 2 ms with tau 0.5 ms.
    let e = |t: f64| {
        let r = |td: f64, tau: f64| 1.0 - (-((t - td).max(0.0)) / tau).exp();
        r(1e-3, 0.2e-3) - r(2e-3, 0.5e-3)
    };
    for t in [0.5e-3, 1.5e-3, 2.5e-3, 3e-3] {
        let v = at(&w, "v(3)", t);
        assert!((v - e(t)).abs() < 1e-3, "v(3) at {t} = {v}, not {}", e(t));
    }
}

#[test]
fn output_names_are_ngspice_vectors() {
    let c = circuit(
        "names\n\
         v1 1 0 1\n\
         r1 1 2 1k\n\
         r2 2 0 1k\n\
         .tran 1u 1m\n\
         .print tran v(2) v(1,2) i(v1)\n\
         .end\n",
    );
    assert_eq!(outputs(&c), ["v(2)", "v(1,2)", "i(v1)"]);
    let d = design(&c);
    for name in ["v(1)", "v(2)", "v(1,2)", "i(v1)", "r1.v", "r1.i"] {
        assert!(
            d.quantities.iter().any(|q| q.name == name),
            "no quantity {name}"
        );
    }
    // As elaborating the circuit in VHDL-AMS would give it.
    assert_eq!(d.natures.len(), 1);
    assert_eq!(d.natures[0].name, "electrical");
    assert_eq!(
        d.natures[0].across_tolerance.as_deref(),
        Some("DEFAULT_VOLTAGE")
    );
    assert_eq!(
        d.natures[0].through_tolerance.as_deref(),
        Some("DEFAULT_CURRENT")
    );
    let names: Vec<_> = d.terminals.iter().map(|t| t.name.as_str()).collect();
    assert_eq!(names, ["0", "1", "2"]);
    assert!(d.terminals[d.natures[0].reference.index()].is_reference);
    assert!(d.domain_signal().is_some());
    assert_eq!(d.equations.len(), 3);
    let none = circuit("defaults\nv1 1 0 1\nr1 1 2 1k\nr2 2 0 1k\n.end\n");
    assert_eq!(outputs(&none), ["v(1)", "v(2)"]);
}

/// The largest difference of `v(out)` from ngspice's at `times` (linear between ngspice's
/// printed points); `None` when ngspice is absent.
fn versus_ngspice(deck: &str, times: &[f64]) -> Option<f64> {
    let rows = ngspice(deck)?;
    assert!(rows.len() > 100, "ngspice gave {} rows", rows.len());
    let w = run(deck);
    let theirs = |t: f64| {
        let k = rows.partition_point(|r| r[0] <= t).max(1);
        let (a, b) = (&rows[k - 1], &rows[k.min(rows.len() - 1)]);
        if b[0] <= a[0] {
            a[1]
        } else {
            a[1] + (b[1] - a[1]) * (t - a[0]) / (b[0] - a[0])
        }
    };
    let mut worst: f64 = 0.0;
    for &t in times {
        let (ours, ng) = (at(&w, "v(out)", t), theirs(t));
        assert!(
            (ours - ng).abs() < 1e-3,
            "v(out) at {t}: {ours} vs ngspice {ng}"
        );
        worst = worst.max((ours - ng).abs());
    }
    Some(worst)
}

#[test]
fn agrees_with_ngspice_on_a_pulsed_rc_with_a_diode() {
    let deck = "rc with a diode clamp\n\
         v1 in 0 pulse(0 2 0.1m 10u 10u 1m 2m)\n\
         r1 in out 1k\n\
         c1 out 0 0.5u\n\
         d1 out 0 dmod\n\
         r2 out 0 10k\n\
         .model dmod d(is=1e-14 n=1.2)\n\
         .tran 1u 4m\n\
         .print tran v(out)\n\
         .end\n";
    let times = [
        0.05e-3, 0.3e-3, 0.6e-3, 1.0e-3, 1.5e-3, 2.5e-3, 3.3e-3, 3.9e-3,
    ];
    if let Some(worst) = versus_ngspice(deck, &times) {
        println!("ngspice, pulse: worst difference {worst:e} V");
    }
}

#[test]
fn agrees_with_ngspice_on_sin_and_exp_sources() {
    let deck = "sources into an rl and a follower\n\
         v1 in 0 sin(0.5 1 2k 0.2m 100 30)\n\
         r1 in a 100\n\
         l1 a m 10m\n\
         v2 m 0 exp(0 0.3 0.5m 0.1m 1.5m 0.3m)\n\
         e1 out 0 a 0 0.5\n\
         .tran 1u 3m\n\
         .print tran v(out)\n\
         .end\n";
    let times = [0.1e-3, 0.25e-3, 0.7e-3, 1.2e-3, 1.7e-3, 2.2e-3, 2.9e-3];
    if let Some(worst) = versus_ngspice(deck, &times) {
        println!("ngspice, sin and exp: worst difference {worst:e} V");
    }
}

#[test]
fn unsupported_model_level() {
    insta::assert_snapshot!(render(
        "amplifier\n\
         v1 d 0 5\n\
         m1 d g 0 0 nch\n\
         r1 g 0 1k\n\
         .model nch nmos(level=3 vto=0.7)\n\
         .end\n"
    ));
}

#[test]
fn unsupported_model_parameter() {
    insta::assert_snapshot!(render(
        "zener\n\
         v1 a 0 5\n\
         r1 a k 1k\n\
         d1 k 0 dz\n\
         .model dz d(is=1e-14 bv=3.3 cjo=2p)\n\
         .end\n"
    ));
}

mod no_panic {
    use proptest::prelude::*;

    use super::*;

    /// One element line of a random kind on nodes 0 to 3, with a random value.
    fn line(k: usize, kind: usize, n: [u8; 4], v: f64) -> String {
        let [a, b, c, d] = n;
        match kind {
            0 => format!("r{k} {a} {b} {v}"),
            1 => format!("c{k} {a} {b} {v} ic=1"),
            2 => format!("l{k} {a} {b} {v}"),
            3 => format!("v{k} {a} {b} pulse(0 {v} 0 0 0 0 0)"),
            4 => format!("i{k} {a} {b} sin(0 {v} 0 {v})"),
            5 => format!("e{k} {a} {b} {c} {d} {v}"),
            6 => format!("g{k} {a} {b} {c} {d} {v}"),
            7 => format!("f{k} {a} {b} vs {v}"),
            8 => format!("h{k} {a} {b} vs {v}"),
            9 => format!("d{k} {a} {b} dm {v}"),
            10 => format!("v{k} {a} {b} exp(0 {v}) ac 1"),
            11 => format!("v{k} {a} {b} pwl(0 0 {v} 1 {v} 2)"),
            _ => format!("q{k} {a} {b} {c} qm"),
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]

        #[test]
        fn lowering_never_panics(
            elements in prop::collection::vec(
                (0usize..13, prop::array::uniform4(0u8..4), prop_oneof![Just(0.0), 1e-9f64..1e3]),
                0..8,
            ),
            tran in any::<bool>(),
        ) {
            let mut deck = String::from("random\nvs 3 0 0\n.model dm d(is=1e-14 rs=1)\n.model qm npn\n");
            for (k, (kind, n, v)) in elements.into_iter().enumerate() {
                deck.push_str(&line(k, kind, n, v));
                deck.push('\n');
            }
            if tran {
                deck.push_str(".tran 1u 1m\n.print tran v(1) i(vs)\n");
            }
            deck.push_str(".end\n");
            let mut sources = SourceMap::new();
            let id = sources.add("random.cir", "work", deck);
            let (d, errors) = read_deck(&mut sources, id, &mut MemLoader::new());
            if errors.is_empty() && let Ok(c) = flatten(&d) {
                let _ = lower(&c);
                let _ = outputs(&c);
            }
        }
    }
}
