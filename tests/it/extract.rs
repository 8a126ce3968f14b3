//! End-to-end tests of `vams extract`: captures generated from known parameters (noise,
//! 8-bit quantisation, offsets, commutation ripple, scope-export quirks) are written to a
//! temporary directory and the binary is driven with assert_cmd.

use assert_cmd::Command;
use std::path::{Path, PathBuf};
use vams::extract::MotorParams;
use vams::extract::synth::{self, ScopeStyle, SynthOptions};

const ROLES: [&str; 4] = ["inrush", "blocked", "speed", "coast"];

fn vams() -> Command {
    let mut cmd = Command::cargo_bin("vams").expect("the vams binary is built for tests");
    cmd.env("NO_COLOR", "1");
    cmd
}

/// Writes the captures of `p` with `o` in `style` (None: the demo's mixed styles).
fn write(dir: &Path, p: &MotorParams, o: &SynthOptions, style: Option<ScopeStyle>) -> [PathBuf; 4] {
    let caps = synth::generate(p, o);
    match style {
        None => synth::write_captures(dir, &caps).unwrap(),
        Some(s) => std::array::from_fn(|k| {
            let path = dir.join(format!("{}.csv", ROLES[k]));
            std::fs::write(&path, synth::to_csv(&caps[k], s)).unwrap();
            path
        }),
    }
}

fn args(paths: &[PathBuf; 4]) -> Vec<String> {
    ROLES
        .iter()
        .zip(paths)
        .flat_map(|(r, p)| [format!("--{r}"), p.display().to_string()])
        .collect()
}

/// A parameter's 95 % interval of `key` in `--json`: `ci95` (the covariance's) or
/// `ci95_bootstrap` (the second, which accounts for model error).
fn interval(v: &serde_json::Value, key: &str, name: &str) -> (f64, f64) {
    let ci = &v[key][name];
    (ci[0].as_f64().unwrap(), ci[1].as_f64().unwrap())
}

fn check_json(stdout: &[u8], truth: &MotorParams) {
    let v: serde_json::Value = serde_json::from_slice(stdout).expect("--json prints JSON");
    assert_eq!(v["converged"], true, "{}", v["reasons"]);
    // The goals: R, L and Ke within 1 %, J, D and Tcst within 5 %.
    let tol = [0.01, 0.01, 0.01, 0.01, 0.05, 0.05, 0.05];
    for ((name, t), tol) in MotorParams::NAMES.iter().zip(truth.values()).zip(tol) {
        let got = v[*name].as_f64().unwrap_or(f64::NAN);
        let err = (got - t) / t;
        eprintln!("{name}: true {t:.4e} got {got:.4e} ({:+.2} %)", 100.0 * err);
        assert!(
            err.abs() < tol,
            "{name}: {got} vs {t} ({:+.2} %)",
            100.0 * err
        );
        // The second interval, which accounts for model error, holds the truth here; the
        // covariance interval misses it in about one draw of twenty for each parameter, as
        // a 95 % interval does (the coverage tests below count both).
        let (lo, hi) = interval(&v, "ci95_bootstrap", name);
        assert!(lo <= t && t <= hi, "{name}: {t} outside {lo} .. {hi}");
    }
    for r in ROLES {
        assert!(
            v["rms_residual"]["refined"][r]
                .as_f64()
                .is_some_and(f64::is_finite)
        );
    }
}

#[test]
fn recovers_the_demo_motor_and_writes_params_and_plots() {
    let dir = tempfile::tempdir().unwrap();
    let truth = MotorParams::example();
    let paths = write(dir.path(), &truth, &SynthOptions::default(), None);
    let params = dir.path().join("motor.params");
    let plots = dir.path().join("plots");
    let out = vams()
        .arg("extract")
        .args(args(&paths))
        .arg("--json")
        .arg("--params")
        .arg(&params)
        .arg("--plot")
        .arg(&plots)
        .assert()
        .success();
    check_json(&out.get_output().stdout, &truth);
    let text = std::fs::read_to_string(&params).unwrap();
    let names: Vec<&str> = text
        .lines()
        .filter_map(|l| l.split_once('='))
        .map(|(n, _)| n)
        .collect();
    assert_eq!(names, MotorParams::NAMES);
    for r in ROLES {
        let svg = std::fs::read_to_string(plots.join(format!("{r}.svg"))).unwrap();
        assert!(
            svg.len() > 10_000 && svg.contains("fitted") && svg.contains("residual"),
            "{r}.svg"
        );
    }
}

#[test]
fn recovers_another_motor_with_deep_ripple_and_semicolon_exports() {
    let dir = tempfile::tempdir().unwrap();
    let truth = MotorParams {
        r: 5.0,
        l: 2.5e-3,
        ke: 0.011,
        kt: 0.011,
        j: 1.6e-6,
        d: 3.0e-7,
        tcst_motor: 4.0e-4,
    };
    let o = SynthOptions {
        ripple_depth: 0.18,
        noise_lsb: 1.0,
        seed: 7,
        current_offset: -2e-3,
        ..SynthOptions::default()
    };
    let paths = write(dir.path(), &truth, &o, Some(ScopeStyle::European));
    let out = vams()
        .arg("extract")
        .args(args(&paths))
        .arg("--json")
        .assert()
        .success();
    check_json(&out.get_output().stdout, &truth);
}

#[test]
fn shallow_ripple_six_commutations_and_renamed_columns() {
    let dir = tempfile::tempdir().unwrap();
    let truth = MotorParams {
        r: 12.0,
        l: 6.0e-3,
        ke: 0.02,
        kt: 0.02,
        j: 0.8e-6,
        d: 8.0e-7,
        tcst_motor: 2.0e-4,
    };
    let o = SynthOptions {
        ripple_depth: 0.04,
        commutations: 6,
        seed: 3,
        ..SynthOptions::default()
    };
    let paths = write(dir.path(), &truth, &o, Some(ScopeStyle::Preamble));
    for p in &paths {
        let text = std::fs::read_to_string(p)
            .unwrap()
            .replace("Time,Voltage,Current", "TIME,CH1,CH2");
        std::fs::write(p, text).unwrap();
    }
    let out = vams()
        .arg("extract")
        .args(args(&paths))
        .args([
            "--time-col",
            "time",
            "--voltage-col",
            "ch1",
            "--current-col",
            "CH2",
            "--commutations",
            "6",
            "--json",
        ])
        .assert()
        .success();
    check_json(&out.get_output().stdout, &truth);
}

#[test]
fn prints_a_table_for_people_and_writes_demo_captures() {
    let dir = tempfile::tempdir().unwrap();
    vams()
        .arg("extract")
        .arg("--demo")
        .arg(dir.path())
        .assert()
        .success();
    let paths: [PathBuf; 4] = std::array::from_fn(|k| dir.path().join(format!("{}.csv", ROLES[k])));
    let out = vams().arg("extract").args(args(&paths)).assert().success();
    let table = String::from_utf8_lossy(&out.get_output().stdout).to_string();
    for needle in [
        "paper's method",
        "joint fit (dc_motor)",
        "95 % (with model error)",
        "tcst_motor",
        "RMS residual",
        "coast",
    ] {
        assert!(table.contains(needle), "{needle} missing in\n{table}");
    }
}

/// Fits the demo motor's captures from `draws` seeded noise draws (the scope's usual sizes,
/// ripple, offsets) and counts, per parameter, the draws whose covariance interval and whose
/// second interval hold the truth.
fn motor_coverage(draws: u64) -> Vec<(&'static str, [usize; 2])> {
    let truth = MotorParams::example();
    let mut held = [[0usize; 2]; MotorParams::NAMES.len()];
    for seed in 0..draws {
        let dir = tempfile::tempdir().unwrap();
        let o = SynthOptions {
            seed: 1000 + seed,
            ..SynthOptions::default()
        };
        let paths = write(dir.path(), &truth, &o, Some(ScopeStyle::Plain));
        let out = vams()
            .arg("extract")
            .arg("--json")
            .args(args(&paths))
            .assert()
            .success();
        let v: serde_json::Value = serde_json::from_slice(&out.get_output().stdout).unwrap();
        for ((name, t), held) in MotorParams::NAMES.iter().zip(truth.values()).zip(&mut held) {
            for (key, held) in ["ci95", "ci95_bootstrap"].into_iter().zip(held) {
                let (lo, hi) = interval(&v, key, name);
                if lo <= t && t <= hi {
                    *held += 1;
                } else {
                    eprintln!("draw {seed}: {name} {t:e} outside {key} {lo:e} .. {hi:e}");
                }
            }
        }
    }
    MotorParams::NAMES.into_iter().zip(held).collect()
}

#[test]
fn motor_intervals_hold_the_truth_in_most_draws() {
    // A reduced form of the 100-draw test below: 4 draws, at most one miss per parameter and
    // interval. Four, because `cargo test` builds vams unoptimised and each fit then takes
    // most of a minute.
    for (name, [covariance, second]) in motor_coverage(4) {
        assert!(
            covariance >= 3 && second >= 3,
            "{name}: the truth inside the covariance interval in {covariance} of 4 draws, \
             the second in {second}"
        );
    }
}

#[test]
#[ignore = "slow: 100 fits; run with --ignored"]
fn motor_intervals_hold_the_truth_in_90_of_100_draws() {
    for (name, [covariance, second]) in motor_coverage(100) {
        eprintln!("{name}: covariance {covariance} of 100, second {second} of 100");
        assert!(
            covariance >= 90 && second >= 90,
            "{name}: the truth inside the covariance interval in {covariance} of 100 draws, \
             the second in {second}"
        );
    }
}

/// Runs with one capture replaced by `text` and checks exit 1 and the diagnostic.
fn diagnosed(role: &str, text: impl FnOnce(&str) -> String, code: &str, expect: &str) {
    let dir = tempfile::tempdir().unwrap();
    let paths = write(
        dir.path(),
        &MotorParams::example(),
        &SynthOptions::default(),
        Some(ScopeStyle::Plain),
    );
    let k = ROLES.iter().position(|r| *r == role).unwrap();
    let original = std::fs::read_to_string(&paths[k]).unwrap();
    std::fs::write(&paths[k], text(&original)).unwrap();
    let out = vams().arg("extract").args(args(&paths)).assert().code(1);
    // Flatten miette's wrapping: drop the frame characters and collapse whitespace.
    let err = String::from_utf8_lossy(&out.get_output().stderr).replace(['│', '×'], " ");
    let err = err.split_whitespace().collect::<Vec<_>>().join(" ");
    let file = paths[k].file_name().unwrap().to_string_lossy().to_string();
    assert!(err.contains(code), "no code {code} in\n{err}");
    assert!(err.contains(&file), "no file name {file} in\n{err}");
    assert!(err.contains(expect), "no `{expect}` in\n{err}");
}

#[test]
fn diagnoses_a_missing_column() {
    diagnosed(
        "blocked",
        |t| t.replacen("voltage", "volts", 1),
        "vams::extract::missing_column",
        "--voltage-col",
    );
}

#[test]
fn diagnoses_an_empty_file() {
    diagnosed(
        "speed",
        |_| String::new(),
        "vams::extract::empty_file",
        "expected a header",
    );
}

#[test]
fn diagnoses_a_file_cut_mid_line() {
    // Cut inside the current field of a line in the middle: no line end, a short last line.
    diagnosed(
        "inrush",
        |t| {
            let mid = t[t.len() / 2..]
                .find('\n')
                .map_or(t.len(), |p| p + t.len() / 2);
            t[..mid - 3].to_string()
        },
        "vams::extract::bad_row",
        "truncated",
    );
    // Cut after a separator: a field missing.
    diagnosed(
        "blocked",
        |t| {
            let mid = t[t.len() / 2..]
                .find(',')
                .map_or(t.len(), |p| p + t.len() / 2);
            t[..=mid].to_string()
        },
        "vams::extract::bad_row",
        "2 fields where 3 are needed",
    );
}

#[test]
fn diagnoses_a_header_without_samples() {
    diagnosed(
        "coast",
        |t| t.lines().take(3).collect::<Vec<_>>().join("\n"),
        "vams::extract::truncated",
        "at least",
    );
}

#[test]
fn diagnoses_a_capture_without_ripple() {
    let dir = tempfile::tempdir().unwrap();
    let o = SynthOptions {
        ripple_depth: 0.0,
        ..SynthOptions::default()
    };
    let flat = synth::generate(&MotorParams::example(), &o);
    let text = synth::to_csv(&flat[2], ScopeStyle::Plain);
    drop(dir);
    diagnosed("speed", |_| text, "vams::extract::no_ripple", "commutation");
}

#[test]
fn diagnoses_a_coast_that_never_stops() {
    diagnosed(
        "coast",
        |t| {
            t.lines()
                .take(t.lines().count() * 2 / 5)
                .collect::<Vec<_>>()
                .join("\n")
        },
        "vams::extract::coast_never_stops",
        "expected it to fall to about 0 V",
    );
}

#[test]
fn usage_errors_exit_with_2() {
    vams()
        .args(["extract", "--inrush", "a.csv"])
        .assert()
        .code(2);
}
