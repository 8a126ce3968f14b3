//! Switches (S, W), coupled inductors (K) and the diode's junction charge, lowered and run
//! against ngspice's reference figures and closed forms (each with its tolerance).

use std::path::Path;

use vams_simulation::kernel::{SimOptions, simulate};
use vams_spice::{MemLoader, SourceMap, flatten, lower, read_deck};

mod support;
use support::{at, circuit, column_crossings, design, ngspice, op, run, value};

#[test]
fn switches_follow_the_shared_hysteresis_case() {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/cases/spice/switch_hyst.cir");
    let Ok(text) = std::fs::read_to_string(&path) else {
        println!("skipped: {} is absent", path.display());
        return;
    };
    let w = run(&text);
    // ngspice 39 (reltol 1e-4, tmax 0.2 us) switches at these times (the case's README).
    let step = 2e-6;
    let cases: [(&str, f64, &[f64]); 4] = [
        ("v(10)", 0.5, &[1.2e-3, 3.2e-3]),
        ("v(20)", 0.5, &[0.5454e-3, 3.5e-3]),
        ("v(30)", 0.5, &[3.5e-3]),
        ("v(40)", 0.59, &[1.2e-3, 3.2e-3]),
    ];
    for (name, level, expected) in cases {
        let got = column_crossings(&w, name, level);
        println!("{name}: switches at {got:?} (ngspice {expected:?})");
        assert_eq!(got.len(), expected.len(), "{name}: {got:?} vs {expected:?}");
        for (g, e) in got.iter().zip(expected) {
            assert!((g - e).abs() < 3.0 * step, "{name}: {g} vs {e}");
        }
    }
    // Off: 2 V over 10k + 10k; S3 on from the start: 2 V over 10k + 1.
    assert!((at(&w, "v(20)", 0.1e-3) - 1.0).abs() < 1e-6);
    assert!((at(&w, "v(30)", 0.1e-3) - 2.0 / 10001.0).abs() < 1e-6);
}

#[test]
fn switch_state_at_the_operating_point_follows_a_control_outside_the_window() {
    // s1 is `off` but its control (2 V) is above vt + vh: on. s2 is `on` but its control (0 V)
    // is below vt - vh: off. s3 is `on` with its control (1 V) inside the window: on.
    let w = run("op states\n\
         vc1 c1 0 dc 2\n\
         vc2 c2 0 dc 0\n\
         vc3 c3 0 dc 1\n\
         v4 4 0 dc 2\n\
         r1 4 1 10k\n\
         r2 4 2 10k\n\
         r3 4 3 10k\n\
         s1 1 0 c1 0 sw1 off\n\
         s2 2 0 c2 0 sw1 on\n\
         s3 3 0 c3 0 sw1 on\n\
         .model sw1 sw vt=1 vh=0.2 ron=1 roff=10k\n\
         .tran 1u 10u\n\
         .print tran v(1) v(2) v(3)\n\
         .end\n");
    let on = 2.0 / 10001.0;
    for (name, exact) in [("v(1)", on), ("v(2)", 1.0), ("v(3)", on)] {
        let v = at(&w, name, 5e-6);
        println!("{name} = {v} (expected {exact})");
        assert!((v - exact).abs() < 1e-6, "{name} = {v} vs {exact}");
    }
}

#[test]
fn coupled_inductors_transform_by_m_over_l1() {
    // A 1 kHz, 1 V sine into l1 = 10 mH (through 1 Ohm), l2 = 1 mH loaded by 1 kOhm, k = 0.999:
    // from the two inductor equations, v2 + l2*(1 - k^2)/r2 * v2'dot == (m/l1) * v1 at every
    // instant, and the lag term is ~1e-9 of v2 here; so v2 == k*sqrt(l2/l1) * v1.
    let (l1, l2, k): (f64, f64, f64) = (10e-3, 1e-3, 0.999);
    let w = run("transformer\n\
         vin in 0 sin(0 1 1k)\n\
         rin in 1 1\n\
         l1 1 0 10m\n\
         l2 2 0 1m\n\
         r2 2 0 1k\n\
         k1 l1 l2 0.999\n\
         .tran 2u 3m\n\
         .print tran v(1) v(2)\n\
         .end\n");
    let ratio = k * (l2 / l1).sqrt();
    let (v1, v2) = match (w.column("v(1)"), w.column("v(2)")) {
        (Some(a), Some(b)) => (a, b),
        _ => panic!("no v(1) or v(2)"),
    };
    let peak = v1.values.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let worst = v1
        .values
        .iter()
        .zip(&v2.values)
        .fold(0.0_f64, |m, (a, b)| m.max((b - ratio * a).abs()));
    println!(
        "transformer: worst |v2 - {ratio} v1| = {worst:e} of a {peak} V primary ({:e} relative)",
        worst / (ratio * peak)
    );
    assert!(peak > 0.9, "primary peak {peak}");
    assert!(worst < 1e-4 * ratio * peak, "worst deviation {worst:e}");
}

#[test]
fn reverse_biased_diode_discharges_through_its_depletion_charge() {
    // 5 V to 0 in 1 ns through 1 kOhm into the cathode of a reverse-biased diode, cjo = 1 nF,
    // vj = 1, m = 0.5: C(u) = cjo/sqrt(1 + u/vj) at reverse voltage u, and R*C(u)*u' = -u
    // gives t(u) = R*cjo*(L(u0) - L(u)), L(u) = ln((s - 1)/(s + 1)), s = sqrt(1 + u/vj)
    // (the leakage, ~1e-14 A + gmin*u, is below 1e-8 of the current).
    let (r, cjo, vj): (f64, f64, f64) = (1e3, 1e-9, 1.0);
    let w = run("depletion\n\
         vin in 0 pwl(0 5 1n 0)\n\
         r1 in a 1k\n\
         d1 0 a dcap\n\
         .model dcap d(is=1e-14 cjo=1n vj=1 m=0.5)\n\
         .tran 5n 8u\n\
         .print tran v(a)\n\
         .end\n");
    let big_l = |u: f64| {
        let s = (1.0 + u / vj).sqrt();
        ((s - 1.0) / (s + 1.0)).ln()
    };
    let mut worst: f64 = 0.0;
    for u in [4.0, 3.0, 2.0, 1.0, 0.5, 0.1] {
        // The 1 ns fall delays the discharge by about half its length.
        let exact = r * cjo * (big_l(5.0) - big_l(u)) + 0.5e-9;
        let got = column_crossings(&w, "v(a)", u);
        let Some(t) = got.first() else {
            panic!("v(a) never falls to {u}")
        };
        let rel = (t - exact).abs() / exact;
        println!("depletion: v(a) = {u} at {t:e} s vs {exact:e} (rel {rel:e})");
        worst = worst.max(rel);
    }
    assert!(worst < 2e-3, "worst relative error {worst:e}");
}

#[test]
fn diode_without_charge_has_no_charge_quantity() {
    let p = op(
        "plain\n\
         i1 0 1 1m\n\
         d1 1 0 dmod\n\
         .model dmod d(is=1e-14 vj=0.7 m=0.3 fc=0.6)\n\
         .op\n\
         .end\n",
        None,
    );
    assert!(p.iter().all(|(n, _)| !n.ends_with(".qv")), "{p:?}");
    assert!(value(&p, "v(1)") > 0.5);
}

#[test]
fn diode_charge_agrees_with_ngspice_through_reverse_recovery() {
    // +-5 V pulses through 1 kOhm: the diode conducts ~4.3 mA, then its stored charge
    // (tt = 20 ns) holds it forward for ~tt*ln(1 + if/ir) before the depletion charge
    // (cjo = 2 pF, vj = 0.7, m = 0.4; above fc*vj the linear extension) takes over.
    let body = "v1 in 0 pulse(-5 5 10n 1n 1n 100n 200n)\n\
         r1 in out 1k\n\
         d1 out 0 dmod\n\
         .model dmod d(is=1e-14 tt=20n cjo=2p vj=0.7 m=0.4 fc=0.5)\n";
    let deck = format!("reverse recovery\n{body}.tran 0.1n 400n\n.print tran v(out)\n.end\n");
    let tight = format!(
        "reverse recovery\n{body}.options reltol=1e-5\n.tran 0.1n 400n 0 0.01n\n.print tran v(out)\n.end\n"
    );
    let w = run(&deck);
    let Some(rows) = ngspice(&tight) else { return };
    assert!(rows.len() > 100, "ngspice gave {} rows", rows.len());
    let theirs = |t: f64| {
        let k = rows.partition_point(|r| r[0] <= t).clamp(1, rows.len() - 1);
        let (a, b) = (&rows[k - 1], &rows[k]);
        if b[0] <= a[0] {
            a[1]
        } else {
            a[1] + (b[1] - a[1]) * (t - a[0]) / (b[0] - a[0])
        }
    };
    let mut worst: f64 = 0.0;
    for k in 1..400 {
        let t = k as f64 * 1e-9;
        let d = (at(&w, "v(out)", t) - theirs(t)).abs();
        if d > worst {
            println!(
                "t {t:e}: ours {} ngspice {}",
                at(&w, "v(out)", t),
                theirs(t)
            );
        }
        worst = worst.max(d);
    }
    // Recovery ends where the diode's voltage falls through 0 on the first falling edge.
    let ours = column_crossings(&w, "v(out)", 0.0);
    println!("diode charge vs ngspice: worst difference {worst:e} V; our zero crossings {ours:?}");
    assert!(worst < 5e-3, "worst difference {worst:e} V");
}

/// The errors of lowering a deck that reads and flattens, as `code: message` lines.
fn refused(text: &str) -> Vec<String> {
    match lower(&circuit(text)) {
        Ok(_) => Vec::new(),
        Err(e) => e.iter().map(|d| format!("{d}")).collect(),
    }
}

#[test]
fn what_switches_and_couplings_refuse() {
    let errors = refused(
        "bad\n\
         v1 1 0 dc 1\n\
         r1 1 2 1k\n\
         s1 2 0 1 0 neg\n\
         s2 2 0 1 0 extra\n\
         .model neg sw(vt=1 vh=-0.1)\n\
         .model extra sw(vt=1 von=2)\n\
         l1 3 0 1m\n\
         l2 3 0 1m\n\
         k1 l1 l2 1.5\n\
         .end\n",
    );
    println!("{errors:#?}");
    assert_eq!(errors.len(), 3, "{errors:#?}");
    assert!(errors.iter().any(|e| e.contains("negative hysteresis")));
    assert!(errors.iter().any(|e| e.contains("`von`")));
    assert!(
        errors
            .iter()
            .any(|e| e.contains("coupling coefficient 1.5"))
    );
}

#[test]
fn a_coupling_may_precede_its_inductors() {
    let d = design(&circuit(
        "order\n\
         k1 l1 l2 0.5\n\
         v1 1 0 dc 0\n\
         l1 1 0 4m\n\
         l2 2 0 1m\n\
         r2 2 0 1k\n\
         .end\n",
    ));
    let texts: Vec<&str> = d.equations.iter().map(|e| e.text.as_str()).collect();
    println!("{texts:#?}");
    // m = 0.5 * sqrt(4m * 1m) = 1 mH, on each inductor's equation.
    assert!(texts.contains(&"l1.v == 0.004 * l1.i'dot + 0.001 * l2.i'dot"));
    assert!(texts.contains(&"l2.v == 0.001 * l2.i'dot + 0.001 * l1.i'dot"));
}

mod no_panic {
    use proptest::prelude::*;

    use super::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(100))]

        #[test]
        fn switches_couplings_and_charges_never_panic(
            n in prop::array::uniform4(0u8..4),
            x in prop::array::uniform4(prop_oneof![Just(0.0), -2.0f64..2.0, 1e-12f64..1e6]),
            which in 0usize..4,
            tran in any::<bool>(),
        ) {
            let [a, b, c, d] = n;
            let [p, q, r, s] = x;
            let mut deck = format!(
                "random\nvs 3 0 0\nr0 3 1 1k\nl1 {a} {b} 1m\nl2 {c} {d} 2m\n\
                 .model sm sw(vt={p} vh={q} ron={r} roff={s})\n\
                 .model wm csw(it={p} ih={q} ron={r})\n\
                 .model dm d(cjo={r} vj={p} m={q} fc={s} tt={r})\n"
            );
            deck.push_str(&match which {
                0 => format!("s1 {a} {b} {c} {d} sm on\n"),
                1 => format!("w1 {a} {b} vs wm\n"),
                2 => format!("k1 l1 l2 {p}\nk2 l2 l1 {q}\n"),
                _ => format!("d1 {a} {b} dm\n"),
            });
            if tran {
                deck.push_str(".tran 1u 10u\n");
            }
            deck.push_str(".end\n");
            let mut sources = SourceMap::new();
            let id = sources.add("random.cir", "work", deck);
            let (d, errors) = read_deck(&mut sources, id, &mut MemLoader::new());
            if errors.is_empty() && let Ok(c) = flatten(&d) && let Ok(design) = lower(&c) {
                let options = SimOptions { stop: 1e-5, max_step: Some(1e-6), ..SimOptions::default() };
                let _ = simulate(&design, &options, &mut |_| {});
            }
        }
    }
}
