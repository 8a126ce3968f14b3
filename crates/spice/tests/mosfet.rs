//! The level 1 MOSFET lowered and run at DC: bias points in every region (both modes, body
//! effect, pmos) and an inverter's transfer curve, against closed forms and against
//! `ngspice -b` where it is installed (skipped with a printed reason where not); and the
//! diagnostics of what the MOSFET lowering refuses (snapshots).

use vams_simulation::kernel::{SimOptions, operating_point, simulate};
use vams_spice::{MemLoader, SourceMap, flatten, lower, outputs, read_deck};

mod support;
use support::{crossings, ngspice, op, rel, render, value};

/// Shichman-Hodges as a textbook writes it (nmos sense, `vds >= 0`), with the body effect.
/// `[vto, beta, gamma, phi, lambda]` in `model`.
fn shichman_hodges(vgs: f64, vds: f64, vbs: f64, model: [f64; 5]) -> f64 {
    let [vto, beta, gamma, phi, lambda] = model;
    let vth = vto + gamma * ((phi - vbs).sqrt() - phi.sqrt());
    let vov = vgs - vth;
    if vov <= 0.0 {
        0.0
    } else if vds >= vov {
        beta / 2.0 * vov * vov * (1.0 + lambda * vds)
    } else {
        beta * vds * (vov - vds / 2.0) * (1.0 + lambda * vds)
    }
}

/// A four-source bias deck around one MOSFET, the drain at `vd` (or swept by `.dc`).
fn bias_deck(kind: &str, vd: f64, sign: f64, extra: &str) -> String {
    format!(
        "bias\n\
         vd d 0 {vd}\n\
         vg g 0 {}\n\
         vs s 0 0\n\
         vb b 0 {}\n\
         m1 d g s b mod l=2u w=10u{extra}\n\
         .model mod {kind} (level=1 vto={} kp=50u gamma=0.5 phi=0.7 lambda=0.02)\n\
         .dc vd {} {} {}\n\
         .print dc i(vd)\n\
         .end\n",
        2.0 * sign,
        -3.0 * sign,
        0.7 * sign,
        -2.0 * sign,
        3.0 * sign,
        0.25 * sign,
    )
}

#[test]
fn bias_points_in_every_region_match_the_closed_form_and_ngspice() {
    // vgs 2, vbs -3 (vth 1.156), vds from -2 (reverse mode) to 3 (saturation).
    let beta = 50e-6 * 10.0 / 2.0;
    let sweep: Vec<f64> = (0..=20).map(|k| -2.0 + 0.25 * f64::from(k)).collect();
    let theirs = ngspice(&bias_deck("nmos", 0.0, 1.0, ""));
    let theirs_p = ngspice(&bias_deck("pmos", 0.0, -1.0, ""));
    let mut worst_exact: f64 = 0.0;
    let mut worst_ng: f64 = 0.0;
    for (k, &vd) in sweep.iter().enumerate() {
        let ours = value(&op(&bias_deck("nmos", vd, 1.0, ""), None), "i(vd)");
        // The channel current into the drain; in reverse mode drain and source swap.
        let ids = if vd >= 0.0 {
            shichman_hodges(2.0, vd, -3.0, [0.7, beta, 0.5, 0.7, 0.02])
        } else {
            -shichman_hodges(2.0 - vd, -vd, -3.0 - vd, [0.7, beta, 0.5, 0.7, 0.02])
        };
        // The reverse-biased drain junction adds -is - gmin*vbd (into the drain).
        let vbd = -3.0 - vd;
        let junction = -(1e-14 * ((vbd / 0.025_864).exp() - 1.0) + 1e-12 * vbd);
        let exact = -(ids + junction);
        worst_exact = worst_exact.max(rel(ours, exact, 1e-9));
        assert!(rel(ours, exact, 1e-9) < 1e-6, "vd {vd}: {ours} vs {exact}");
        // pmos: every voltage and current negated.
        let ours_p = value(&op(&bias_deck("pmos", -vd, -1.0, ""), None), "i(vd)");
        assert!(
            rel(-ours_p, ours, 1e-9) < 1e-9,
            "pmos at {vd}: {ours_p} vs {ours}"
        );
        for (rows, mine) in [(&theirs, ours), (&theirs_p, ours_p)] {
            if let Some(rows) = rows {
                let ng = rows[k][1];
                worst_ng = worst_ng.max(rel(mine, ng, 1e-9));
                assert!(
                    rel(mine, ng, 1e-9) < 1e-3,
                    "vd {vd}: {mine} vs ngspice {ng}"
                );
            }
        }
    }
    println!(
        "mosfet bias: worst relative error {worst_exact:e} (closed form), {worst_ng:e} (ngspice)"
    );
}

#[test]
fn series_resistances_multiplier_and_kp_from_tox_agree_with_ngspice() {
    // rd, rs (given), and rsh*nrd/nrs on the second; m=2; ld; kp from uo and tox.
    let deck = |vd: f64| {
        format!(
            "bias with resistances\n\
             vd d 0 {vd}\n\
             vg g 0 2.5\n\
             vb b 0 -1\n\
             m1 d g 0 b mod1 l=3u w=20u m=2\n\
             vd2 d d2 0\n\
             m2 d2 g 0 b mod2 l=3u w=20u nrd=2 nrs=3\n\
             .model mod1 nmos (vto=0.8 tox=20n uo=500 ld=0.2u gamma=0.4 lambda=0.05 rd=200 rs=100)\n\
             .model mod2 nmos (vto=0.8 kp=40u rsh=50 is=1e-15 js=1e-4)\n\
             .options reltol=1e-7\n\
             .dc vd -1.5 3 0.25\n\
             .print dc i(vd) i(vd2)\n\
             .end\n"
        )
    };
    let Some(rows) = ngspice(&deck(0.0)) else {
        return;
    };
    assert_eq!(rows.len(), 19, "{rows:?}");
    let mut worst: f64 = 0.0;
    for row in &rows {
        let p = op(&deck(row[0]), None);
        for (name, ng) in [("i(vd)", row[1]), ("i(vd2)", row[2])] {
            let ours = value(&p, name);
            worst = worst.max(rel(ours, ng, 1e-9));
            assert!(
                rel(ours, ng, 1e-9) < 1e-3,
                "{name} at {}: {ours} vs ngspice {ng}",
                row[0]
            );
        }
    }
    println!("mosfet resistances: worst relative difference from ngspice {worst:e}");
}

fn inverter(vin: f64) -> String {
    format!(
        "nmos inverter\n\
         vdd dd 0 5\n\
         vin in 0 {vin}\n\
         rl dd out 10k\n\
         m1 out in 0 0 nch l=2u w=10u\n\
         .model nch nmos (level=1 vto=1 kp=40u lambda=0.01)\n\
         .options reltol=1e-7\n\
         .dc vin 0 5 0.25\n\
         .print dc v(out)\n\
         .end\n"
    )
}

#[test]
fn inverter_transfer_curve_matches_the_closed_form_and_ngspice() {
    let beta = 40e-6 * 10.0 / 2.0;
    let theirs = ngspice(&inverter(0.0));
    let mut worst: f64 = 0.0;
    for k in 0..=20 {
        let vin = 0.25 * f64::from(k);
        let ours = value(&op(&inverter(vin), None), "v(out)");
        // (5 - vout)/10k == ids(vin, vout) + the drain junction, by bisection.
        let f = |v: f64| {
            (5.0 - v) / 10e3
                - shichman_hodges(vin, v, 0.0, [1.0, beta, 0.0, 0.6, 0.01])
                - (1e-14 * ((-v / 0.025_864).exp() - 1.0) - 1e-12 * v)
        };
        let (mut lo, mut hi) = (0.0, 5.0);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if f(mid) > 0.0 { lo = mid } else { hi = mid }
        }
        let exact = 0.5 * (lo + hi);
        assert!(
            rel(ours, exact, 1e-3) < 1e-6,
            "vin {vin}: {ours} vs {exact}"
        );
        if let Some(rows) = &theirs {
            let ng = rows[k as usize][1];
            worst = worst.max(rel(ours, ng, 1e-3));
            assert!(
                rel(ours, ng, 1e-3) < 1e-3,
                "vin {vin}: {ours} vs ngspice {ng}"
            );
        }
    }
    println!("inverter: worst relative difference from ngspice {worst:e}");
}

const CMOS: &str = "cmos inverter
vdd dd 0 5
vin in 0 pulse(0 5 2n 1n 1n 10n 24n)
m1 out in dd dd pch l=2u w=20u ad=40p as=40p pd=24u ps=24u
m2 out in 0 0 nch l=2u w=10u ad=20p as=20p pd=14u ps=14u
cl out 0 50f
.model nch nmos (level=1 vto=0.8 kp=50u gamma=0.5 phi=0.7 lambda=0.02 tox=20n cj=2e-4 cjsw=5e-10
+ mj=0.5 mjsw=0.33 pb=0.8 cgso=3e-10 cgdo=3e-10 cgbo=2e-10)
.model pch pmos (level=1 vto=-0.9 kp=20u gamma=0.6 phi=0.7 lambda=0.03 tox=20n cj=3e-4 cjsw=4e-10
+ mj=0.45 mjsw=0.3 pb=0.9 cgso=3e-10 cgdo=3e-10 cgbo=2e-10)
.tran 0.01n 30n
.print tran v(out)
.end
";

#[test]
fn cmos_inverter_transient_agrees_with_ngspice() {
    // Junction depletion charge and Meyer gate capacitances with overlaps on both devices.
    let mut sources = SourceMap::new();
    let id = sources.add("deck.cir", "work", CMOS.to_string());
    let (deck, errors) = read_deck(&mut sources, id, &mut MemLoader::new());
    assert!(errors.is_empty(), "{errors:#?}");
    let c = match flatten(&deck) {
        Ok(c) => c,
        Err(e) => panic!("{e:#?}"),
    };
    let d = match lower(&c) {
        Ok(d) => d,
        Err(e) => panic!("{e:#?}"),
    };
    let options = SimOptions {
        stop: 30e-9,
        reltol: 1e-4,
        max_step: Some(0.01e-9),
        probes: outputs(&c),
        ..SimOptions::default()
    };
    let w = match simulate(&d, &options, &mut |_| {}) {
        Ok(r) => r.waveforms,
        Err(e) => panic!("{e:?}"),
    };
    let Some(col) = w.column("v(out)") else {
        panic!("no v(out)")
    };
    let ours = crossings(&w.times, &col.values, 2.5);
    let at = |t: f64| w.value_at("v(out)", t).unwrap_or(f64::NAN);
    // The output falls after the input's rises (2-3 ns, 26-27 ns) and rises after its fall
    // (13-14 ns).
    assert_eq!(ours.len(), 3, "crossings {ours:?}");
    assert!(
        (2e-9..5e-9).contains(&ours[0]) && (13e-9..16e-9).contains(&ours[1]),
        "{ours:?}"
    );
    let (low, high) = (at(10e-9), at(22e-9));
    assert!(
        low.abs() < 0.05 && (high - 5.0).abs() < 0.05,
        "levels {low} {high}"
    );
    let Some(rows) = ngspice(CMOS) else { return };
    let times: Vec<f64> = rows.iter().map(|r| r[0]).collect();
    let values: Vec<f64> = rows.iter().map(|r| r[1]).collect();
    let theirs = crossings(&times, &values, 2.5);
    assert_eq!(theirs.len(), 3, "ngspice crossings {theirs:?}");
    let step = 0.01e-9;
    let mut worst_t: f64 = 0.0;
    for (a, b) in ours.iter().zip(&theirs) {
        worst_t = worst_t.max((a - b).abs());
        assert!(
            (a - b).abs() < 3.0 * step,
            "50 % crossing at {a:e} vs ngspice {b:e}"
        );
    }
    let mut worst_v: f64 = 0.0;
    for t in [1e-9, 8e-9, 12e-9, 20e-9, 29e-9] {
        let k = times.partition_point(|&x| x < t).min(values.len() - 1);
        let (mine, ng) = (at(times[k]), values[k]);
        worst_v = worst_v.max((mine - ng).abs());
        assert!(
            (mine - ng).abs() < 0.05,
            "v(out) at {t:e}: {mine} vs ngspice {ng}"
        );
    }
    println!(
        "cmos inverter: crossings {ours:?} vs ngspice {theirs:?} (worst {worst_t:e} s), \
         levels within {worst_v:e} V"
    );
}

#[test]
fn unsupported_mosfet_parameters() {
    insta::assert_snapshot!(render(
        "cmos\n\
         vdd dd 0 5\n\
         m1 out in dd dd pch l=2u w=10u off\n\
         m2 out in 0 0 nch l=2u w=5u icvds=1\n\
         m3 out in 0 0 nch\n\
         .model pch pmos (level=1 vto=-1 tox=20n cgso=1p nsub=1e15 fc=1)\n\
         .model nch nmos (level=3 vto=1 cbd=0)\n\
         .tran 1n 10n\n\
         .end\n"
    ));
}

mod no_panic {
    use proptest::prelude::*;

    use super::*;

    /// A parameter value: often 0 or negative, else from 1e-15 to 1e3.
    fn number() -> impl Strategy<Value = f64> {
        prop_oneof![Just(0.0), Just(-1.0), Just(1.0), 1e-15f64..1e3]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        #[test]
        fn lowering_and_solving_never_panic_nor_give_nan(
            model in prop::collection::vec((0usize..16, number()), 0..8),
            inst in prop::collection::vec((0usize..9, number()), 0..4),
            pmos in any::<bool>(),
            bias in prop::array::uniform3(-5.0f64..5.0),
        ) {
            const MODEL: [&str; 16] = [
                "vto", "kp", "gamma", "phi", "lambda", "rd", "rs", "rsh", "is", "js", "tox",
                "uo", "ld", "cj", "pb", "fc",
            ];
            const INST: [&str; 9] = ["l", "w", "ad", "as", "pd", "ps", "nrd", "nrs", "m"];
            let params: String = model.iter().map(|(k, v)| format!(" {}={v:e}", MODEL[*k])).collect();
            let sizes: String = inst.iter().map(|(k, v)| format!(" {}={v:e}", INST[*k])).collect();
            let kind = if pmos { "pmos" } else { "nmos" };
            let [vd, vg, vb] = bias;
            let deck = format!(
                "random\nvd d 0 {vd}\nvg g 0 {vg}\nvb b 0 {vb}\nm1 d g 0 b mm{sizes}\n\
                 .model mm {kind} ({params})\n.op\n.end\n"
            );
            let mut sources = SourceMap::new();
            let id = sources.add("random.cir", "work", deck);
            let (d, errors) = read_deck(&mut sources, id, &mut MemLoader::new());
            if errors.is_empty()
                && let Ok(c) = flatten(&d)
                && let Ok(design) = lower(&c)
                && let Ok(point) = operating_point(&design, &SimOptions::default())
            {
                for (name, v) in point {
                    prop_assert!(v.is_finite(), "{name} = {v}");
                }
            }
        }
    }
}
