//! `vams poles` end to end: the natural frequencies of a DC motor (`models/dc_motor.vhd` on
//! `tests/analog/motor_step.vhd`) and of a series RLC (`tests/ac/rlc_series.vhd`) against their
//! closed forms, to 1e-6 relative (the table prints 7 significant digits), the zeros of a lead
//! network and of a series RLC, and the refusal of a design with `'delayed`.

use assert_cmd::Command;
use predicates::str::contains;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

fn vams() -> Command {
    Command::cargo_bin("vams").expect("the vams binary is built for integration tests")
}

/// `(real, imag)` of each line of the table (imag 0 for a real pole, the positive part of a
/// pair).
fn poles(args: &[&str]) -> Vec<(f64, f64)> {
    let out = vams().arg("poles").args(args).output().expect("runs");
    let text = String::from_utf8(out.stdout).expect("utf-8");
    assert!(out.status.success(), "{text}");
    text.lines()
        .skip(2)
        .map(|line| {
            let mut cols = line.split_whitespace();
            let re: f64 = cols.next().expect("real").parse().expect("number");
            let im = cols.next().expect("imag");
            let im: f64 = im.trim_start_matches("+-").parse().expect("number");
            (re, im)
        })
        .collect()
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-6 * b.abs().max(1e-300)
}

/// `L i' = V - R i - ke w`, `J w' = kt i - d w`: the eigenvalues of the 2 x 2 matrix, the
/// electrical (about 0.78 ms) and mechanical (about 16.6 ms) time constants.
#[test]
fn a_dc_motor_shows_its_two_time_constants() {
    let (r, l, kt, ke, d, j): (f64, f64, f64, f64, f64, f64) =
        (4.0, 3.0e-3, 0.015, 0.015, 1.5e-6, 1.0e-6);
    let trace = -r / l - d / j;
    let det = (r * d + ke * kt) / (l * j);
    let root = (trace * trace / 4.0 - det).sqrt();
    let (slow, fast) = (trace / 2.0 + root, trace / 2.0 - root);
    let found = poles(&[
        &format!("{ROOT}/models/dc_motor.vhd"),
        &format!("{ROOT}/tests/analog/motor_step.vhd"),
        "--top",
        "motor_step",
    ]);
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(
        close(found[0].0, slow) && found[0].1 == 0.0,
        "{found:?} vs {slow}"
    );
    assert!(
        close(found[1].0, fast) && found[1].1 == 0.0,
        "{found:?} vs {fast}"
    );
}

/// `s = -R / 2L +- j sqrt(1/LC - (R/2L)^2)`.
#[test]
fn a_series_rlc_rings_at_its_damped_frequency() {
    let (r, l, c): (f64, f64, f64) = (10.0, 1.0e-3, 1.0e-6);
    let sigma = -r / (2.0 * l);
    let wd = (1.0 / (l * c) - sigma * sigma).sqrt();
    let found = poles(&[&format!("{ROOT}/tests/ac/rlc_series.vhd")]);
    assert_eq!(found.len(), 1, "one conjugate pair: {found:?}");
    assert!(close(found[0].0, sigma), "{found:?}");
    assert!(close(found[0].1, wd), "{found:?}");
}

#[test]
fn a_design_with_delayed_is_refused() {
    vams()
        .args(["poles", &format!("{ROOT}/tests/ac/attributes.vhd")])
        .assert()
        .code(1)
        .stderr(contains("not polynomial"));
}

/// The rows of the zeros' table after the poles'.
fn zeros(args: &[&str]) -> Vec<(f64, f64)> {
    let out = vams().arg("poles").args(args).output().expect("runs");
    let text = String::from_utf8(out.stdout).expect("utf-8");
    assert!(out.status.success(), "{text}");
    let start = text.find("zeros from").expect("a zeros table");
    text[start..]
        .lines()
        .skip(2)
        .map(|line| {
            let mut cols = line.split_whitespace();
            let re: f64 = cols.next().expect("real").parse().expect("number");
            let im = cols.next().expect("imag");
            (re, im.trim_start_matches("+-").parse().expect("number"))
        })
        .collect()
}

/// A lead network's zero, `-1 / (r1 c1)`, and the series RLC's double zero at the origin
/// from the source to the inductor's voltage (`s^2 L C / (1 + s R C + s^2 L C)`).
#[test]
fn zeros_from_an_input_to_an_output() {
    let lead = format!("{ROOT}/tests/ac/lead.vhd");
    let found = zeros(&[&lead, "--input", "ac_in", "--output", "vout"]);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(close(found[0].0, -100.0) && found[0].1 == 0.0, "{found:?}");
    // Its pole, -(r1 + r2) / (r1 r2 c1), is listed above the zeros.
    assert!(close(poles(&[&lead])[0].0, -1100.0));
    let rlc = format!("{ROOT}/tests/ac/rlc_series.vhd");
    let found = zeros(&[&rlc, "--input", "ac_in", "--output", "vl"]);
    assert_eq!(found, [(0.0, 0.0), (0.0, 0.0)]);
    vams()
        .args(["poles", &lead, "--input", "vin", "--output", "vout"])
        .assert()
        .code(1)
        .stderr(contains("not a spectral source quantity"))
        .stderr(contains("ac_in"));
    vams()
        .args(["poles", &lead, "--input", "ac_in"])
        .assert()
        .code(2);
}
