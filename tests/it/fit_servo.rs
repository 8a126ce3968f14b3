//! `vams fit` on the headlight servo (issue 18, the example `models/fit/README.md`): the
//! H-bridge IC's deadband and hysteresis and the feedback pot's factor estimated from one
//! captured run of `models/fit/tb_servo_fit.vhd` (a slow reference ramp that makes the motor
//! brake and restart). The captures are synthetic: a vams run at known values, sampled as a
//! scope would (1 ms per sample, 8 bits over the screen, Gaussian noise), written in the
//! Keysight layout. Also: the step run of `tb_tracking` leaves the hysteresis undetermined,
//! and the fit says so; and the committed capture gives the README's numbers.
//!
//! `VAMS_WRITE_SERVO_CAPTURE=1 cargo test --release --test it fit_servo::` rewrites the committed
//! capture `models/fit/tracking_capture.csv` from the first test's draw.

use std::path::Path;

use assert_cmd::Command;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

const MODELS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/models");
const CAPTURE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/models/fit/tracking_capture.csv"
);

/// The truth of the synthetic captures (the defaults are 0.1 V, 0.05 V and 625 V/m).
const DEADBAND: f64 = 0.12;
const HYSTERESIS: f64 = 0.04;
const K_POT: f64 = 610.0;

/// The scope: one sample per millisecond from the trigger at t = 0; channel 1 (the feedback
/// voltage) at 375 mV/div from -0.5 V, channel 2 (the motor voltage) at 3.75 V/div from
/// -15 V, 8 divisions, 8 bits, with 5 mV and 50 mV of Gaussian noise.
const SAMPLE: f64 = 1e-3;
const CH1: (f64, f64, f64) = (-0.5, 3.0 / 256.0, 5e-3);
const CH2: (f64, f64, f64) = (-15.0, 30.0 / 256.0, 50e-3);

fn vams() -> Command {
    Command::cargo_bin("vams").expect("the vams binary is built for integration tests")
}

/// A seeded Gaussian stream (ChaCha8 and Box-Muller), as in `tests/it/fit.rs`.
struct Noise(ChaCha8Rng);

impl Noise {
    fn gauss(&mut self) -> f64 {
        let u1: f64 = self.0.random_range(f64::EPSILON..1.0);
        let u2: f64 = self.0.random_range(0.0..1.0);
        (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
    }
}

/// `vams run` of `top` with `generics`: rows of time, vfb and v_motor at the solver's steps.
fn simulate(dir: &Path, top: &str, generics: &[String]) -> Vec<[f64; 3]> {
    let csv = dir.join(format!("{top}.csv"));
    let mut cmd = vams();
    cmd.arg("run").arg(MODELS).args(["--top", top]);
    for g in generics {
        cmd.args(["-g", g]);
    }
    cmd.args([
        "--accuracy",
        "fine",
        "--probe",
        "vfb",
        "--probe",
        "v_motor",
        "-o",
    ])
    .arg(&csv)
    .assert()
    .success();
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (vfb, v_motor) = (col("vfb"), col("v_motor"));
    lines
        .map(|line| {
            let f: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
            [f[0], f[vfb], f[v_motor]]
        })
        .collect()
}

/// The run's vfb and v_motor at time `t`, linear between steps (at a step's discontinuity,
/// where two rows share a time, the later row).
fn at(run: &[[f64; 3]], t: f64) -> [f64; 2] {
    let k = run.partition_point(|r| r[0] <= t).clamp(1, run.len() - 1);
    let (a, b) = (run[k - 1], run[k]);
    let w = if b[0] > a[0] {
        ((t - a[0]) / (b[0] - a[0])).clamp(0.0, 1.0)
    } else {
        1.0
    };
    [a[1] + w * (b[1] - a[1]), a[2] + w * (b[2] - a[2])]
}

/// One 8-bit sample of a channel `(bottom, lsb, noise)`, clipped to the screen.
fn digitise(v: f64, (bottom, lsb, sd): (f64, f64, f64), noise: &mut Noise) -> f64 {
    let level = ((v + sd * noise.gauss() - bottom) / lsb)
        .round()
        .clamp(0.0, 255.0);
    bottom + level * lsb
}

/// The Keysight export (`x-axis,1,2`, `second,Volt,Volt`) of `samples` samples of `run`,
/// under a comment line that says what it is.
fn capture(run: &[[f64; 3]], samples: usize, seed: u64, what: &str) -> String {
    let mut noise = Noise(ChaCha8Rng::seed_from_u64(seed));
    let mut text = format!(
        "# SYNTHETIC capture, not measured: {what}; 1 ms/sample, 8 bits, noise 5 mV (ch 1) and \
         50 mV (ch 2), ChaCha8 seed {seed} (tests/it/fit_servo.rs)\nx-axis,1,2\nsecond,Volt,Volt\n"
    );
    for k in 0..samples {
        let t = k as f64 * SAMPLE;
        let [vfb, v_motor] = at(run, t);
        let v1 = digitise(vfb, CH1, &mut noise);
        let v2 = digitise(v_motor, CH2, &mut noise);
        text.push_str(&format!("{t:.6e},{v1:.5e},{v2:.5e}\n"));
    }
    text
}

/// `vams fit --json` of `capture` against `top`: the JSON and stderr.
fn fit(capture: &Path, top: &str, free: &[&str]) -> (serde_json::Value, String) {
    let mut cmd = vams();
    cmd.arg("fit").arg(MODELS).args(["--top", top, "--json"]);
    cmd.arg("--measured")
        .arg(capture)
        .args(["--match", "vfb=1"]);
    for f in free {
        cmd.args(["--free", f]);
    }
    let out = cmd.output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("--json prints JSON");
    // Exit status 3: the fit ran but did not converge (a parameter at a bound), and says so.
    let expected = if json["converged"] == true { 0 } else { 3 };
    assert_eq!(out.status.code(), Some(expected), "vams fit: {stderr}");
    (json, stderr)
}

/// The free generics of the example, from the models' defaults (`models/fit/README.md`).
const FREE: [&str; 3] = [
    "deadband=0.1:0.02:0.3",
    "hysteresis=0.05:0.005:0.2",
    "k_pot=625:400:900",
];

/// The fitted value of `name` is within `tol` (relative) of `truth`, inside its interval,
/// and the truth within twice the interval's half-width of it.
fn near(j: &serde_json::Value, name: &str, truth: f64, tol: f64) {
    let p = &j["parameters"][name];
    let v = p["value"].as_f64().unwrap();
    let (lo, hi) = (
        p["ci95"][0].as_f64().unwrap(),
        p["ci95"][1].as_f64().unwrap(),
    );
    eprintln!("{name}: {v} ({lo} .. {hi}), truth {truth}");
    assert!(
        (v - truth).abs() / truth < tol,
        "{name} = {v}, truth {truth}"
    );
    assert!(lo < v && v < hi, "{name}: {lo} {v} {hi}");
    assert!((v - truth).abs() < hi - lo, "{name} = {v}: {lo} .. {hi}");
}

/// Tolerances: about five times the 95 % half-widths measured (deadband ±0.2 %, hysteresis
/// ±0.25 %, k_pot ±0.07 %), so that another noise draw or solver change does not trip them
/// while a fit stuck in a wrong minimum (hysteresis 0.053 with a ramp of 10 restarts) does.
const TOL_DEADBAND: f64 = 0.01;
const TOL_HYSTERESIS: f64 = 0.015;
const TOL_K_POT: f64 = 0.004;

#[test]
fn recovers_the_ic_thresholds_and_the_pot_factor_from_a_ramp() {
    let dir = tempfile::tempdir().unwrap();
    let truth = [
        format!("deadband={DEADBAND}"),
        format!("hysteresis={HYSTERESIS}"),
        format!("k_pot={K_POT}"),
    ];
    let run = simulate(dir.path(), "tb_servo_fit", &truth);
    let what = format!(
        "vams run models --top tb_servo_fit -g {} --accuracy fine",
        truth.join(" -g ")
    );
    let text = capture(&run, 3500, 18, &what);
    if std::env::var_os("VAMS_WRITE_SERVO_CAPTURE").is_some() {
        std::fs::write(CAPTURE, &text).unwrap();
    }
    let path = dir.path().join("tracking_capture.csv");
    std::fs::write(&path, text).unwrap();
    let (j, stderr) = fit(&path, "tb_servo_fit", &FREE);
    assert_eq!(j["converged"], true, "{}", j["reasons"]);
    near(&j, "deadband", DEADBAND, TOL_DEADBAND);
    near(&j, "hysteresis", HYSTERESIS, TOL_HYSTERESIS);
    near(&j, "k_pot", K_POT, TOL_K_POT);
    // The residual is the noise and the quantisation (5 mV and 11.7 mV / sqrt(12)), no misfit.
    let rms = j["series"][0]["rms"].as_f64().unwrap();
    assert!(rms < 7e-3, "rms {rms}");
    assert!(!stderr.contains("warning"), "{stderr}");
    assert_eq!(j["warnings"].as_array().unwrap().len(), 0, "{j}");
}

#[test]
fn the_committed_capture_gives_the_readme_example() {
    let text = std::fs::read_to_string(CAPTURE).unwrap();
    assert!(
        text.starts_with("# SYNTHETIC"),
        "the capture says what it is"
    );
    let (j, stderr) = fit(Path::new(CAPTURE), "tb_servo_fit", &FREE);
    assert_eq!(j["converged"], true, "{}", j["reasons"]);
    near(&j, "deadband", DEADBAND, TOL_DEADBAND);
    near(&j, "hysteresis", HYSTERESIS, TOL_HYSTERESIS);
    near(&j, "k_pot", K_POT, TOL_K_POT);
    assert!(!stderr.contains("warning"), "{stderr}");
}

/// The paper's tracking run (a 1 V step at 3 s) restarts the motor far beyond the hysteresis:
/// nothing in it depends on the hysteresis, and the fit says so, while it still finds the
/// deadband and the pot factor. Generics set by instance path: `tb_tracking` does not pass
/// them through. With nothing to hold it, the hysteresis wanders on the simulations'
/// round-off: as measured, to 0.119 in one noise draw (flagged "not identifiable") and to its
/// lower bound in another (flagged "ended at its bound"); either way it gets a warning and no
/// interval.
#[test]
fn a_step_tracking_run_leaves_the_hysteresis_undetermined() {
    let dir = tempfile::tempdir().unwrap();
    let truth = [
        format!("dut.u_ic.deadband={DEADBAND}"),
        format!("dut.u_ic.hysteresis={HYSTERESIS}"),
        format!("dut.u_feedback_pot.k={K_POT}"),
    ];
    let run = simulate(dir.path(), "tb_tracking", &truth);
    let path = dir.path().join("step.csv");
    std::fs::write(&path, capture(&run, 6000, 19, "tb_tracking")).unwrap();
    let (j, stderr) = fit(
        &path,
        "tb_tracking",
        &[
            "dut.u_ic.deadband=0.1:0.02:0.3",
            "dut.u_ic.hysteresis=0.05:0.005:0.2",
            "dut.u_feedback_pot.k=625:400:900",
        ],
    );
    assert!(
        stderr.contains("`dut.u_ic.hysteresis` is not identifiable")
            || stderr.contains("`dut.u_ic.hysteresis` ended at its bound"),
        "{stderr}"
    );
    let warnings = j["warnings"].as_array().unwrap();
    assert_eq!(warnings.len(), 1, "{j}");
    assert!(
        j["parameters"]["dut.u_ic.hysteresis"]["ci95"].is_null(),
        "{j}"
    );
    near(&j, "dut.u_ic.deadband", DEADBAND, TOL_DEADBAND);
    near(&j, "dut.u_feedback_pot.k", K_POT, TOL_K_POT);
}
