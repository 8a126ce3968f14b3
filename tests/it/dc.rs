//! `vams dc` end to end on the models in `tests/dc/`: a diode's I-V curve against its implicit
//! closed form and against ngspice's `.dc` (when installed), a Schmitt trigger's hysteresis
//! against its fold thresholds, an integer generic that changes the design's structure, a
//! sweep cut short by a point without solution (the points before it written), and the
//! diagnostics.

use std::path::Path;

use assert_cmd::Command;

use crate::support::ngspice;
use predicates::prelude::*;
use predicates::str::contains;

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/dc");

fn vams() -> Command {
    Command::cargo_bin("vams").expect("the vams binary is built for integration tests")
}

/// The CSV of a sweep: the header's names, the rows (empty cells as NaN), the last `#` line.
struct Table {
    names: Vec<String>,
    rows: Vec<Vec<f64>>,
    ending: Option<String>,
}

impl Table {
    fn parse(text: &str) -> Table {
        let mut lines = text.lines();
        let names = lines
            .next()
            .expect("header")
            .split(',')
            .map(String::from)
            .collect();
        let (mut rows, mut ending) = (Vec::new(), None);
        for line in lines {
            if let Some(comment) = line.strip_prefix("# ") {
                ending = Some(comment.to_string());
                continue;
            }
            let cells = line.split(',');
            rows.push(
                cells
                    .map(|v| {
                        if v.is_empty() {
                            f64::NAN
                        } else {
                            v.parse().expect("a number")
                        }
                    })
                    .collect(),
            );
        }
        Table {
            names,
            rows,
            ending,
        }
    }

    fn column(&self, name: &str) -> Vec<f64> {
        let k = self.names.iter().position(|n| n == name).expect(name);
        self.rows.iter().map(|r| r[k]).collect()
    }
}

/// `vams dc MODEL ARGS`, expected to succeed; its CSV (standard output).
fn dc(model: &str, args: &[&str]) -> Table {
    let out = vams()
        .arg("dc")
        .arg(format!("{DIR}/{model}.vhd"))
        .args(args)
        .output()
        .expect("vams runs");
    assert!(
        out.status.success(),
        "{model}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    Table::parse(&String::from_utf8_lossy(&out.stdout))
}

/// The diode's voltage for a source level: the root of vs = vd + r id(vd), by bisection (the
/// right side is increasing in vd).
fn diode_voltage(vs: f64) -> f64 {
    let (r, is, vt) = (1.0e3, 1.0e-14, 0.025852);
    let f = |vd: f64| vd + r * (is * ((vd / vt).exp() - 1.0) + 1.0e-12 * vd) - vs;
    let (mut lo, mut hi) = (-10.0, 10.0_f64.min(vs.max(0.0) + 1.0));
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn a_diode_iv_curve_follows_its_implicit_closed_form() {
    let t = dc("diode_iv", &["--sweep", "vs_level", "-1", "0.8", "0.01"]);
    let (levels, vd, id) = (t.column("vs_level"), t.column("vd"), t.column("id"));
    assert_eq!(levels.len(), 181);
    assert_eq!((levels[0], levels[100], levels[180]), (-1.0, 0.0, 0.8));
    let (mut worst, mut worst_v) = (0.0_f64, 0.0_f64);
    for ((&vs, &vd), &id) in levels.iter().zip(&vd).zip(&id) {
        let exact = diode_voltage(vs);
        worst_v = worst_v.max((vd - exact).abs());
        // The current through 1 kOhm carries the voltage's error a thousandfold: compare it
        // to the largest current of the sweep, the voltage to a microvolt.
        assert!((vd - exact).abs() < 1e-6, "vs = {vs}: vd {vd} vs {exact}");
        worst = worst.max((vs - exact - 1e3 * id).abs() / 1.9e-4 / 1e3);
    }
    println!("diode I-V: largest error {worst_v:.2e} V, {worst:.2e} of the full-scale current");
    assert!(
        worst < 1e-6,
        "largest current error {worst:e} of full scale"
    );
}

#[test]
fn a_schmitt_trigger_switches_at_its_folds_and_shows_hysteresis_both_ways() {
    let t = dc(
        "schmitt",
        &[
            "--sweep",
            "vin_level",
            "-1",
            "1",
            "0.01",
            "--both-ways",
            "--probe",
            "vout",
        ],
    );
    assert_eq!(t.names, ["vin_level", "direction", "vout"]);
    assert_eq!(t.rows.len(), 401, "201 up, 200 down");
    // The fold: cosh(k u0)^2 = a b k, threshold a b tanh(k u0) - u0 (a 5, b 0.1, k 10).
    let (a, b, k) = (5.0_f64, 0.1, 10.0);
    let u0 = (a * b * k).sqrt().acosh() / k;
    let threshold = a * b * (k * u0).tanh() - u0;
    assert!((threshold - 0.30277).abs() < 1e-4, "{threshold}");
    for (direction, edge) in [(1.0, threshold), (-1.0, -threshold)] {
        let rows: Vec<&Vec<f64>> = t.rows.iter().filter(|r| r[1] == direction).collect();
        let switch = rows
            .windows(2)
            .find(|w| (w[0][2] > 0.0) != (w[1][2] > 0.0))
            .expect("the output switches");
        // The jump happens at the first point past the fold, not before it.
        let (before, after) = (switch[0][0], switch[1][0]);
        assert!(
            (before - edge) * (after - edge) <= 0.0,
            "direction {direction}: switched between {before} and {after}, fold at {edge}"
        );
        assert!((after - before).abs() < 0.011);
    }
    // Between the thresholds the two directions disagree: the state is kept.
    let at_zero: Vec<f64> = (t.rows.iter())
        .filter(|r| r[0] == 0.0)
        .map(|r| r[2])
        .collect();
    assert_eq!(at_zero.len(), 2);
    assert!(at_zero[0] < -4.9 && at_zero[1] > 4.9, "{at_zero:?}");
}

#[test]
fn an_integer_generic_changes_the_structure_from_point_to_point() {
    let t = dc("divider", &["--sweep", "n", "1", "4", "1"]);
    let (n, vout) = (t.column("n"), t.column("vout"));
    assert_eq!(n, [1.0, 2.0, 3.0, 4.0]);
    for (n, v) in n.iter().zip(&vout) {
        assert!((v - 1.0 / (n + 1.0)).abs() < 1e-12, "n = {n}: {v}");
    }
    // The second section exists from n = 2 on: its cell is empty at n = 1.
    let second = t.column("chain(1).v");
    assert!(second[0].is_nan() && (second[1] - 1.0 / 3.0).abs() < 1e-12);
}

#[test]
fn a_point_without_solution_ends_the_sweep_and_keeps_the_points_before_it() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let csv = dir.path().join("roots.csv");
    let svg = dir.path().join("roots.svg");
    vams()
        .arg("dc")
        .arg(format!("{DIR}/no_root.vhd"))
        .args(["--sweep", "p", "1", "-1", "-0.25", "-o"])
        .arg(&csv)
        .arg("--plot")
        .arg(&svg)
        .assert()
        .code(1)
        .stderr(contains("stopped at p = -0.25: no quiescent point there"))
        .stderr(contains("x * x == p"))
        .stderr(contains("swept p over 5 of 9 point(s)"));
    let t = Table::parse(&std::fs::read_to_string(&csv).expect("the CSV is written"));
    assert_eq!(t.column("p"), [1.0, 0.75, 0.5, 0.25, 0.0]);
    for (p, x) in t.column("p").iter().zip(t.column("x")) {
        assert!((x - p.sqrt()).abs() < 1e-6, "p = {p}: x = {x}");
    }
    assert_eq!(
        t.ending.as_deref(),
        Some("stopped at p = -0.25: no quiescent point")
    );
    let picture = std::fs::read_to_string(&svg).expect("the plot is drawn");
    assert!(picture.contains("stopped at p = -0.25"));
    let left: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert_eq!(left.len(), 2, "no temporary file is left behind");
}

#[test]
fn bad_sweeps_and_probes_are_diagnostics() {
    let model = format!("{DIR}/divider.vhd");
    let cases: [(&[&str], &str); 5] = [
        (&["--sweep", "nn", "1", "3", "1"], "has no generic `nn`"),
        (&["--sweep", "n", "1", "3", "0"], "STEP is zero"),
        (
            &["--sweep", "n", "1", "3", "-1"],
            "give STEP the sign of TO - FROM",
        ),
        (
            &["--sweep", "n", "0", "3", "1"],
            "generic `n` = 0 is outside its subtype's range 1 to",
        ),
        (
            &["--sweep", "n", "1", "3", "1", "--probe", "vot"],
            "did you mean `vout`?",
        ),
    ];
    for (args, message) in cases {
        vams()
            .arg("dc")
            .arg(&model)
            .args(args)
            .assert()
            .code(1)
            .stderr(contains(message));
    }
    // An output that cannot be written fails before any point is solved.
    vams()
        .arg("dc")
        .arg(&model)
        .args([
            "--sweep",
            "n",
            "1",
            "3",
            "1",
            "-o",
            "/nonexistent/dir/out.csv",
        ])
        .assert()
        .code(1)
        .stderr(contains("cannot write `/nonexistent/dir/out.csv`"))
        .stderr(contains("swept").not());
}

/// ngspice's `.dc` of a deck: the swept value and the current into the source, negated.
fn ngspice_dc(deck: &str, dir: &Path) -> Option<Vec<(f64, f64)>> {
    let rows = ngspice::run(deck, "dc V1 -1 0.8 0.01\nwrdata {out} -i(V1)", 2, dir)?;
    Some(rows.iter().map(|v| (v[0], v[1])).collect())
}

#[test]
fn agrees_with_ngspice_dc_on_the_diode_curve() {
    if !ngspice::available() {
        println!("skipped: ngspice is not on the PATH");
        return;
    }
    let dir = tempfile::tempdir().expect("temporary directory");
    let deck = "diode iv\n.options reltol=1e-9 abstol=1e-15 vntol=1e-12 temp=26.85 tnom=26.85\n\
                V1 in 0 DC 0\nR1 in d 1k\nD1 d 0 dmod\n\
                .model dmod D(IS=1e-14 N=1 RS=0 CJO=0)";
    let reference = ngspice_dc(deck, dir.path()).expect("ngspice is installed but did not run");
    let t = dc("diode_iv", &["--sweep", "vs_level", "-1", "0.8", "0.01"]);
    let (levels, id) = (t.column("vs_level"), t.column("id"));
    assert_eq!(levels.len(), reference.len());
    let mut worst = 0.0_f64;
    for ((&vs, &i), &(vs_ref, i_ref)) in levels.iter().zip(&id).zip(&reference) {
        assert!((vs - vs_ref).abs() < 1e-9, "{vs} vs {vs_ref}");
        // Relative to the largest current of the sweep (0.19 mA).
        worst = worst.max((i - i_ref).abs() / 1.9e-4);
    }
    println!("diode I-V: largest difference from ngspice {worst:.2e} of full scale");
    // ngspice's Newton stops at its own tolerances even at reltol 1e-9 (the closed-form test
    // above holds vams to 1e-6 V): about 1e-6 of full scale apart on ngspice 39.
    assert!(worst < 1e-5, "{worst:e}");
}
