//! SPICE decks end to end: `vams run deck.cir` writes the deck's `.print` vectors under
//! ngspice's names, checked against the closed form of an RC step; a bad deck is a located
//! diagnostic and exit code 1.

use assert_cmd::Command;
use predicates::str::contains;

fn vams() -> Command {
    Command::cargo_bin("vams").expect("the vams binary is built for integration tests")
}

/// The columns of a CSV file: the header's names and the rows of numbers.
fn read_csv(path: &std::path::Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).expect("the CSV was written");
    let mut lines = text.lines();
    let header = (lines.next().expect("a header").split(','))
        .map(|s| s.trim().to_string())
        .collect();
    let rows = lines
        .map(|l| {
            l.split(',')
                .map(|x| x.trim().parse().expect("a number"))
                .collect()
        })
        .collect();
    (header, rows)
}

#[test]
fn an_rc_deck_runs_to_its_tran_stop_with_ngspice_names() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let csv = dir.path().join("rc.csv");
    vams()
        .args(["run", "tests/spice/rc_step.cir", "-o"])
        .arg(&csv)
        .assert()
        .success()
        .stderr(contains("simulated rc_step to 5 ms"));
    let (header, rows) = read_csv(&csv);
    assert_eq!(header, ["time", "v(1)", "v(2)", "i(v1)"]);
    let last = rows.last().expect("rows");
    assert!((last[0] - 5e-3).abs() < 1e-12, "stops at the .tran TSTOP");
    // The closed form after the edge at 0.1 ms, within 2e-3 of the step (the default
    // tolerance; the step's 1 ns rise is far below tau).
    let mut checked = 0;
    for row in rows.iter().filter(|r| r[0] > 0.2e-3) {
        let t = row[0] - 0.1e-3;
        let want = 1.0 - (-t / 1e-3).exp();
        assert!(
            (row[2] - want).abs() < 2e-3,
            "v(2) at {}: {} against {want}",
            row[0],
            row[2]
        );
        // ngspice's sign: the source's current flows from + to - inside it, so it is
        // negative while the source charges the capacitor.
        let i = -(1.0 - row[2]) / 1e3;
        assert!((row[3] - i).abs() < 2e-6, "i(v1) at {}: {}", row[0], row[3]);
        checked += 1;
    }
    assert!(checked > 10, "{checked} rows after the edge");
}

#[test]
fn a_deck_with_a_missing_model_is_a_located_error() {
    vams()
        .args(["run", "tests/spice/bad_deck.cir"])
        .assert()
        .code(1)
        .stderr(contains("nomodel"))
        .stderr(contains("bad_deck.cir:3"));
}

#[test]
fn a_deck_among_vhdl_sources_is_refused_with_a_help() {
    vams()
        .args(["run", "tests/spice/rc_step.cir", "tests/run/rc.vhd"])
        .assert()
        .code(1)
        .stderr(contains("comes with other sources"));
}

#[test]
fn a_cmos_inverter_switches_where_ngspice_does() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let csv = dir.path().join("inverter.csv");
    vams()
        .args(["run", "tests/spice/cmos_inverter.cir", "-o"])
        .arg(&csv)
        .assert()
        .success();
    let (header, rows) = read_csv(&csv);
    assert_eq!(header, ["time", "v(in)", "v(out)", "i(vdd)"]);
    let mut crossings = Vec::new();
    for pair in rows.windows(2) {
        let (a, b) = (pair[0][2] - 2.5, pair[1][2] - 2.5);
        if a != 0.0 && a.signum() != b.signum() {
            crossings.push(pair[0][0] + (pair[1][0] - pair[0][0]) * a / (a - b));
        }
    }
    // ngspice 39 at `.options reltol=1e-7` (the deck's header): within 5 ps, a twentieth of
    // the output's edge.
    let reference = [2.8243e-9, 13.8586e-9, 26.8243e-9];
    assert_eq!(crossings.len(), reference.len(), "{crossings:?}");
    for (ours, theirs) in crossings.iter().zip(reference) {
        assert!((ours - theirs).abs() < 5e-12, "{ours:e} against {theirs:e}");
    }
}

/// The time-weighted mean of `(t, v)` samples, their rising crossings of it, and their
/// peak-to-peak span.
fn oscillation(points: &[(f64, f64)]) -> (f64, Vec<f64>, f64) {
    let span = points[points.len() - 1].0 - points[0].0;
    let area: f64 = (points.windows(2))
        .map(|w| (w[1].0 - w[0].0) * (w[0].1 + w[1].1) / 2.0)
        .sum();
    let mean = area / span;
    let rising = (points.windows(2))
        .filter(|w| w[0].1 < mean && w[1].1 >= mean)
        .map(|w| w[0].0 + (w[1].0 - w[0].0) * (mean - w[0].1) / (w[1].1 - w[0].1))
        .collect();
    let (lo, hi) = (points.iter()).fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
        (a.min(p.1), b.max(p.1))
    });
    (mean, rising, hi - lo)
}

#[test]
fn the_shared_colpitts_oscillates_at_the_reference_frequency() {
    let deck = std::path::Path::new("../shared/cases/spice/colpitts.cir");
    if !deck.exists() {
        eprintln!("skipped: {} is not here", deck.display());
        return;
    }
    let dir = tempfile::tempdir().expect("temporary directory");
    let csv = dir.path().join("colpitts.csv");
    vams()
        .args(["run", "-o"])
        .arg(&csv)
        .arg(deck)
        .assert()
        .success();
    let (header, rows) = read_csv(&csv);
    let col = header
        .iter()
        .position(|h| h == "v(2)")
        .expect("v(2) printed");
    let between = |t0: f64, t1: f64| -> Vec<(f64, f64)> {
        (rows.iter())
            .filter(|r| (t0..=t1).contains(&r[0]))
            .map(|r| (r[0], r[col]))
            .collect()
    };
    // The reference (../shared/cases/spice/README.md, ngspice at reltol 1e-4 and TMAX =
    // TSTEP/10): 3.3425 MHz over 6-12 us, 5.08 V peak to peak over 10-12 us, mean 5.00 V;
    // here at vams's defaults.
    let (mean, rising, _) = oscillation(&between(6e-6, 12e-6));
    let frequency = (rising.len() - 1) as f64 / (rising[rising.len() - 1] - rising[0]);
    assert!(
        (frequency / 3.3425e6 - 1.0).abs() < 5e-3,
        "{frequency} Hz against 3.3425 MHz"
    );
    assert!((mean - 5.0).abs() < 0.05, "mean {mean} V");
    let (_, _, swing) = oscillation(&between(10e-6, 12e-6));
    assert!((swing / 5.08 - 1.0).abs() < 0.01, "peak to peak {swing} V");
}
