//! `vams noise` end to end on the models in `tests/noise/`: a resistor's thermal noise into
//! an RC (density against sqrt(4kTR) / |1 + jwRC|, the band's power against kT/C), a divider
//! of two instances of a noisy resistor, two uncorrelated sources adding in power, a 1/f
//! source, the input-referred noise of an inverting amplifier, the diagnostics, the plot, and
//! ngspice's `.noise` on the RC and the divider when ngspice is installed.

use std::f64::consts::TAU;
use std::path::Path;

use assert_cmd::Command;

use crate::support::ngspice;
use predicates::str::contains;

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/noise");
const BOLTZMANN: f64 = 1.380649e-23;

fn vams() -> Command {
    Command::cargo_bin("vams").expect("the vams binary is built for integration tests")
}

/// The CSV of a run: the header's names and the rows.
struct Table {
    names: Vec<String>,
    rows: Vec<Vec<f64>>,
}

impl Table {
    fn parse(text: &str) -> Table {
        let mut lines = text.lines();
        let names = (lines.next().expect("header").split(','))
            .map(String::from)
            .collect();
        let rows = lines
            .map(|l| l.split(',').map(|v| v.parse().expect("a number")).collect())
            .collect();
        Table { names, rows }
    }

    fn column(&self, name: &str) -> Vec<f64> {
        let k = (self.names.iter().position(|n| n == name))
            .unwrap_or_else(|| panic!("no column {name} in {:?}", self.names));
        self.rows.iter().map(|r| r[k]).collect()
    }
}

/// `vams noise tests/noise/<model>.vhd ARGS`: the CSV (standard output) and the summary
/// (standard error, beside a CSV on standard output).
fn noise(model: &str, args: &[&str]) -> (Table, String) {
    let out = vams()
        .arg("noise")
        .arg(format!("{DIR}/{model}.vhd"))
        .args(args)
        .output()
        .expect("vams runs");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "{stderr}");
    let table = Table::parse(&String::from_utf8(out.stdout).expect("utf-8"));
    (table, stderr)
}

/// The number after `label` and before ` ` in the summary.
fn summary_value(summary: &str, label: &str) -> f64 {
    let start = summary
        .find(label)
        .unwrap_or_else(|| panic!("no `{label}` in {summary}"))
        + label.len();
    let rest = summary[start..].trim_start();
    rest.split_whitespace()
        .next()
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("no number after `{label}` in {summary}"))
}

/// The largest relative difference of `values` from `exact(f)`.
fn worst(frequencies: &[f64], values: &[f64], exact: impl Fn(f64) -> f64) -> f64 {
    (frequencies.iter().zip(values))
        .map(|(&f, &v)| (v / exact(f) - 1.0).abs())
        .fold(0.0, f64::max)
}

/// `|1 + jwRC|^2`.
fn rc_pole(f: f64, r: f64, c: f64) -> f64 {
    1.0 + (TAU * f * r * c).powi(2)
}

#[test]
fn resistor_thermal_noise_through_an_rc_matches_its_closed_form() {
    let (r, c, t) = (1e3, 1e-9, 300.0);
    let (table, summary) = noise(
        "rc_thermal",
        &["--probe", "vout", "--from", "1Hz", "--to", "1GHz"],
    );
    let f = table.column("frequency");
    assert_eq!(f.len(), 181);
    let density = |f: f64| (4.0 * BOLTZMANN * t * r / rc_pole(f, r, c)).sqrt();
    let err = worst(&f, &table.column("vout_noise_V_per_rtHz"), density);
    println!("RC thermal noise: largest relative error of the density {err:.2e}");
    assert!(err < 1e-9, "{err:e}");
    // One source: its contribution is the total.
    assert_eq!(
        table.column("vout_from_vn_r_V_per_rtHz"),
        table.column("vout_noise_V_per_rtHz")
    );
    assert!(summary.contains("trapezoid rule"), "{summary}");
}

#[test]
fn the_band_integral_of_rc_thermal_noise_tends_to_kt_over_c() {
    let (r, c, t) = (1e3, 1e-9, 300.0);
    let kt_c = BOLTZMANN * t / c;
    // The exact integral over [f1, f2] is kT/C (2/pi) (atan(2 pi f2 RC) - atan(2 pi f1 RC)).
    let band = |f1: f64, f2: f64| {
        kt_c * 2.0 / std::f64::consts::PI * ((TAU * f2 * r * c).atan() - (TAU * f1 * r * c).atan())
    };
    let dir = tempfile::tempdir().expect("temporary directory");
    let csv = dir.path().join("rc.csv");
    let csv = csv.to_str().expect("utf-8 path");
    // 20 points per decade over 1 Hz..1 GHz: the trapezoid's error near the corner is
    // about 0.2 % of the power (measured 2.2e-3); 1000 per decade over 1 mHz..10 THz, where
    // the band misses 1e-8 of kT/C: measured 6e-7.
    for (from, to, per_decade, tolerance) in
        [("1Hz", "1GHz", "20", 1e-2), ("1mHz", "10THz", "1000", 1e-6)]
    {
        let out = vams()
            .args(["noise", &format!("{DIR}/rc_thermal.vhd"), "--probe", "vout"])
            .args([
                "--from",
                from,
                "--to",
                to,
                "--points-per-decade",
                per_decade,
            ])
            .args(["-o", csv])
            .output()
            .expect("vams runs");
        assert!(out.status.success());
        // With -o the summary is on standard output.
        let summary = String::from_utf8(out.stdout).expect("utf-8");
        let rms = summary_value(&summary, "integrated output noise at vout:");
        let table = Table::parse(&std::fs::read_to_string(csv).expect("the CSV"));
        let f = table.column("frequency");
        let (f1, f2) = (f[0], f[f.len() - 1]);
        let power = rms * rms;
        let against_band = (power / band(f1, f2) - 1.0).abs();
        let against_kt_c = (power / kt_c - 1.0).abs();
        println!(
            "RC kT/C, {from}..{to} at {per_decade}/decade: {rms:.6e} V rms; power against \
             the band's exact integral {against_band:.2e}, against kT/C {against_kt_c:.2e}"
        );
        assert!(against_band < tolerance, "{against_band:e}");
        assert!(against_kt_c < tolerance, "{against_kt_c:e}");
    }
}

#[test]
fn two_uncorrelated_sources_add_in_power() {
    let (r, c, t, i_psd) = (10e3, 1e-9, 300.0, 4e-24);
    let (table, summary) = noise(
        "two_sources",
        &["--probe", "vc", "--from", "10Hz", "--to", "10MHz"],
    );
    let f = table.column("frequency");
    let thermal = |f: f64| 4.0 * BOLTZMANN * t * r / rc_pole(f, r, c);
    let current = |f: f64| i_psd * r * r / rc_pole(f, r, c);
    let from_r = table.column("vc_from_vn_r_V_per_rtHz");
    let from_i = table.column("vc_from_in_x_V_per_rtHz");
    let total = table.column("vc_noise_V_per_rtHz");
    let errors = [
        worst(&f, &from_r, |f| thermal(f).sqrt()),
        worst(&f, &from_i, |f| current(f).sqrt()),
        worst(&f, &total, |f| (thermal(f) + current(f)).sqrt()),
    ];
    println!("two sources: largest relative errors (r, i, total) {errors:?}");
    assert!(errors.iter().all(|&e| e < 1e-9), "{errors:?}");
    for k in 0..f.len() {
        let sum = from_r[k].powi(2) + from_i[k].powi(2);
        assert!((total[k].powi(2) / sum - 1.0).abs() < 1e-12);
    }
    // The shares of the power: 4kTR against i_psd r^2, the same transfer.
    let share = 4.0 * BOLTZMANN * t * r / (4.0 * BOLTZMANN * t * r + i_psd * r * r) * 100.0;
    assert!(
        summary.contains("from vn_r: ") && summary.contains(&format!("({share:.2} %")),
        "{share} {summary}"
    );
}

#[test]
fn a_divider_of_two_noisy_resistor_instances_adds_them_and_integrates_to_kt_over_c() {
    let (r1, r2, c, t) = (3e3, 1e3, 1e-9, 300.0);
    let rp = r1 * r2 / (r1 + r2);
    let dir = tempfile::tempdir().expect("temporary directory");
    let csv = dir.path().join("divider.csv");
    let out = vams()
        .args(["noise", &format!("{DIR}/divider.vhd"), "--probe", "vout"])
        .args([
            "--from",
            "1mHz",
            "--to",
            "10THz",
            "--points-per-decade",
            "1000",
            "-o",
        ])
        .arg(&csv)
        .output()
        .expect("vams runs");
    assert!(out.status.success());
    let table = Table::parse(&std::fs::read_to_string(&csv).expect("the CSV"));
    let f = table.column("frequency");
    let pole = |f: f64| rc_pole(f, rp, c);
    // Each instance's source by its hierarchical name; r1's reaches the output through
    // r2 / (r1 + r2), r2's through r1 / (r1 + r2).
    let errors = [
        worst(&f, &table.column("vout_noise_V_per_rtHz"), |f| {
            (4.0 * BOLTZMANN * t * rp / pole(f)).sqrt()
        }),
        worst(&f, &table.column("vout_from_top.vn_V_per_rtHz"), |f| {
            (4.0 * BOLTZMANN * t * r1 / pole(f)).sqrt() * r2 / (r1 + r2)
        }),
        worst(&f, &table.column("vout_from_bottom.vn_V_per_rtHz"), |f| {
            (4.0 * BOLTZMANN * t * r2 / pole(f)).sqrt() * r1 / (r1 + r2)
        }),
    ];
    println!("divider: largest relative errors (total, r1, r2) {errors:?}");
    assert!(errors.iter().all(|&e| e < 1e-9), "{errors:?}");
    let summary = String::from_utf8(out.stdout).expect("utf-8");
    let rms = summary_value(&summary, "integrated output noise at vout:");
    let err = (rms * rms / (BOLTZMANN * t / c) - 1.0).abs();
    println!("divider: band power against kT/C {err:.2e}");
    assert!(err < 1e-6, "{err:e}");
}

#[test]
fn a_flicker_source_follows_one_over_f() {
    let (r, c, kf) = (1e3, 1e-9, 1e-12);
    let (table, _) = noise(
        "flicker",
        &["--probe", "vout", "--from", "1Hz", "--to", "100MHz"],
    );
    let f = table.column("frequency");
    let err = worst(&f, &table.column("vout_noise_V_per_rtHz"), |f| {
        (kf / f / rc_pole(f, r, c)).sqrt()
    });
    println!("1/f through an RC: largest relative error of the density {err:.2e}");
    assert!(err < 1e-9, "{err:e}");
    // With the corner far above the band the power over 1 Hz..1 MHz is kf ln(1e6); the
    // trapezoid on a log grid of ratio q overestimates a 1/f integral by exactly
    // (q - 1)(1 + 1/q) / (2 ln q).
    let (table, summary) = noise(
        "flicker",
        &[
            "--probe",
            "vout",
            "--from",
            "1Hz",
            "--to",
            "1MHz",
            "-g",
            "c=1.0e-21",
        ],
    );
    assert_eq!(table.rows.len(), 121);
    let rms = summary_value(&summary, "integrated output noise at vout:");
    let q = 10f64.powf(1.0 / 20.0);
    let trapezoid = (q - 1.0) * (1.0 + 1.0 / q) / (2.0 * q.ln());
    let exact = kf * 1e6f64.ln();
    let err = (rms * rms / (exact * trapezoid) - 1.0).abs();
    println!(
        "1/f band power: {:.6e} V^2 against kf ln(f2/f1) {exact:.6e} (the rule's factor \
         {trapezoid:.6}); after the factor {err:.2e}",
        rms * rms
    );
    assert!(err < 1e-6, "{err:e}");
}

/// `a(jw) = a0 / (1 + j f / fp)` as `(re, im)`.
fn opamp_gain(f: f64, a0: f64, fp: f64) -> (f64, f64) {
    let d = 1.0 + (f / fp).powi(2);
    (a0 / d, -a0 * (f / fp) / d)
}

#[test]
fn input_referred_noise_of_an_inverting_amplifier_is_output_over_gain() {
    let (r1, r2, a0, fp, t, en) = (1e3, 10e3, 1e5, 10.0, 300.0, 1e-16);
    let (s1, s2) = (4.0 * BOLTZMANN * t * r1, 4.0 * BOLTZMANN * t * r2);
    let (table, summary) = noise(
        "inverting_amp",
        &[
            "--probe", "vout", "--input", "ac_in", "--from", "1Hz", "--to", "10MHz",
        ],
    );
    let f = table.column("frequency");
    // |H_in|^2 = |a r2 / ((r1 + r2) D)|^2, D = 1 + a r1 / (r1 + r2).
    let transfer = |f: f64| {
        let (are, aim) = opamp_gain(f, a0, fp);
        let beta = r1 / (r1 + r2);
        let d2 = (1.0 + are * beta).powi(2) + (aim * beta).powi(2);
        (are * are + aim * aim) / d2
    };
    let h_in = |f: f64| transfer(f) * (r2 / (r1 + r2)).powi(2);
    let output = |f: f64| {
        let a2d = transfer(f);
        let k = (r1 + r2).powi(2);
        a2d * (s1 * r2 * r2 / k + s2 * r1 * r1 / k + en)
    };
    let referred = (s1 + s2 * (r1 / r2).powi(2) + en * ((r1 + r2) / r2).powi(2)).sqrt();
    let out = table.column("vout_noise_per_rtHz");
    let input = table.column("ac_in_referred_per_rtHz");
    let errors = [
        worst(&f, &out, |f| output(f).sqrt()),
        worst(&f, &input, |_| referred),
    ];
    println!("inverting amplifier: largest relative errors (output, input-referred) {errors:?}");
    assert!(errors.iter().all(|&e| e < 1e-9), "{errors:?}");
    // The input-referred density is the output's over the gain `vams ac` reports.
    let out_ac = vams()
        .args(["ac", &format!("{DIR}/inverting_amp.vhd"), "--probe", "vout"])
        .args(["--from", "1Hz", "--to", "10MHz", "--complex"])
        .output()
        .expect("vams runs");
    assert!(out_ac.status.success());
    let ac = Table::parse(&String::from_utf8(out_ac.stdout).expect("utf-8"));
    let (re, im) = (ac.column("vout_re"), ac.column("vout_im"));
    for k in 0..f.len() {
        let gain = re[k].hypot(im[k]);
        assert!((gain * gain / h_in(f[k]) - 1.0).abs() < 1e-9);
        assert!((input[k] * gain / out[k] - 1.0).abs() < 1e-12, "{k}");
    }
    // Flat, so its band integral is the density times the root of the bandwidth (up to the
    // sum's rounding).
    let rms = summary_value(&summary, "integrated input-referred noise at ac_in:");
    let exact = referred * (10e6f64 - 1.0).sqrt();
    assert!((rms / exact - 1.0).abs() < 1e-6, "{rms} {exact}");
}

#[test]
fn noise_sources_are_zero_in_an_ac_analysis() {
    let (r, c) = (1e3, 1e-9);
    let out = vams()
        .args(["ac", &format!("{DIR}/rc_thermal.vhd"), "--probe", "vout"])
        .args(["--from", "1Hz", "--to", "1MHz", "--complex"])
        .output()
        .expect("vams runs");
    assert!(out.status.success());
    let t = Table::parse(&String::from_utf8(out.stdout).expect("utf-8"));
    let f = t.column("frequency");
    let (re, im) = (t.column("vout_re"), t.column("vout_im"));
    for k in 0..f.len() {
        let wrc = TAU * f[k] * r * c;
        let d = 1.0 + wrc * wrc;
        assert!((re[k] - 1.0 / d).abs() < 1e-12 && (im[k] + wrc / d).abs() < 1e-12);
    }
}

#[test]
fn draws_the_densities() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let plot = dir.path().join("noise.svg");
    vams()
        .args(["noise", &format!("{DIR}/two_sources.vhd"), "--probe", "vc"])
        .args(["--from", "10Hz", "--to", "10MHz", "--plot"])
        .arg(&plot)
        .assert()
        .success()
        .stderr(contains("wrote"));
    let svg = std::fs::read_to_string(&plot).expect("the plot");
    for text in ["vc (total)", "vn_r", "in_x", "frequency (Hz)", "V/√Hz"] {
        assert!(svg.contains(text), "no `{text}` in the plot");
    }
}

/// `vams noise tests/noise/MODEL.vhd --from 1Hz --to 1MHz ARGS`, for the diagnostics.
fn noise_command(model: &str, args: &[&str]) -> Command {
    let mut command = vams();
    command
        .args([
            "noise",
            &format!("{DIR}/{model}.vhd"),
            "--from",
            "1Hz",
            "--to",
            "1MHz",
        ])
        .args(args);
    command
}

#[test]
fn bad_input_is_diagnosed_with_exit_code_1() {
    noise_command("no_noise", &["--probe", "vout"])
        .assert()
        .code(1)
        .stderr(contains("`tb_no_noise` has no noise source quantity"));
    noise_command("rc_thermal", &["--probe", "vot"])
        .assert()
        .code(1)
        .stderr(contains("--probe `vot`: no quantity of that name"))
        .stderr(contains("did you mean `vout`?"));
    noise_command("rc_thermal", &["--probe", "vout", "--input", "vin"])
        .assert()
        .code(1)
        .stderr(contains(
            "--input `vin`: a quantity, but not a spectral source quantity",
        ))
        .stderr(contains("the spectral source quantities: ac_in"));
    noise_command("rc_thermal", &["--probe", "vout", "--input", "nothing"])
        .assert()
        .code(1)
        .stderr(contains("no quantity of that name"));
    // The density turns negative above 1 kHz: the first grid point past it is named, with
    // the source's declaration.
    noise_command("negative_density", &["--probe", "vc"])
        .assert()
        .code(1)
        .stderr(contains("the noise density of `vn_bad` is -1.22"))
        .stderr(contains("at 1122.01"))
        .stderr(contains("negative_density.vhd:10:12"));
    // Not a number above 1 kHz.
    noise_command("nan_density", &["--probe", "vc"])
        .assert()
        .code(1)
        .stderr(contains("the noise density of `vn_bad` is NaN at 1122.01"));
    // A density of 0 is a silent source, not an error.
    noise_command("flicker", &["--probe", "vout", "-g", "kf=0.0"])
        .assert()
        .success();
    noise_command("two_sources", &["--probe", "vc", "-g", "i_psd=-1.0"])
        .assert()
        .code(1)
        .stderr(contains("the noise density of `in_x` is -1e0 at 1 Hz"));
    // `vams ac` on a design with noise sources and no spectral source still refuses.
    vams()
        .args([
            "ac",
            &format!("{DIR}/two_sources.vhd"),
            "--from",
            "1Hz",
            "--to",
            "1MHz",
        ])
        .assert()
        .code(1)
        .stderr(contains("no spectral source quantity"));
    noise_command("rc_thermal", &["--probe", "vout", "--from", "1MHz"])
        .assert()
        .code(2);
}

/// ngspice's `.noise` of a deck: frequency and the output noise density.
fn ngspice_noise(deck: &str, output: &str, source: &str, dir: &Path) -> Option<Vec<(f64, f64)>> {
    let control = format!(
        "noise {output} {source} dec 20 1 1g\nsetplot noise1\nwrdata {{out}} onoise_spectrum"
    );
    let rows = ngspice::run(deck, &control, 2, dir)?;
    Some(rows.iter().map(|v| (v[0], v[1])).collect())
}

#[test]
fn agrees_with_ngspice_noise_on_the_rc_and_the_divider() {
    if !ngspice::available() {
        println!("skipped: ngspice is not on the PATH");
        return;
    }
    let dir = tempfile::tempdir().expect("temporary directory");
    // T = 300 K exactly (ngspice's default is 300.15 K).
    let options = ".options temp=26.85 tnom=26.85";
    let cases = [
        (
            "rc_thermal",
            format!("rc noise\n{options}\nV1 in 0 DC 1 AC 1\nR1 in out 1k\nC1 out 0 1n"),
        ),
        (
            "divider",
            format!(
                "divider noise\n{options}\nV1 supply 0 DC 5 AC 1\nR1 supply out 3k\n\
                 R2 out 0 1k\nC1 out 0 1n"
            ),
        ),
    ];
    for (model, deck) in cases {
        let Some(reference) = ngspice_noise(&deck, "v(out)", "V1", dir.path()) else {
            panic!("ngspice is installed but did not run the {model} deck");
        };
        let (table, _) = noise(model, &["--probe", "vout", "--from", "1Hz", "--to", "1GHz"]);
        let f = table.column("frequency");
        let ours = table.column("vout_noise_V_per_rtHz");
        assert_eq!(f.len(), reference.len());
        let mut worst_error = 0.0_f64;
        for (k, &(fs, density)) in reference.iter().enumerate() {
            assert!((f[k] / fs - 1.0).abs() < 1e-6, "{} vs {fs}", f[k]);
            worst_error = worst_error.max((ours[k] / density - 1.0).abs());
        }
        // ngspice prints 9 digits and may use an older Boltzmann constant (1.38064852e-23,
        // 1.4e-7 relative in the density's square).
        println!(
            "{model}: largest difference of the output density from ngspice {worst_error:.2e}"
        );
        assert!(worst_error < 1e-4, "{model}: {worst_error:e}");
    }
}

#[test]
fn vams_ac_leaves_noise_sources_out_of_its_default_probes() {
    let out = vams()
        .args([
            "ac",
            &format!("{DIR}/rc_thermal.vhd"),
            "--from",
            "1Hz",
            "--to",
            "10Hz",
        ])
        .output()
        .expect("vams runs");
    assert!(out.status.success());
    let header = String::from_utf8(out.stdout).expect("utf-8");
    let header = header.lines().next().expect("a header");
    assert!(
        header.contains("vout_db") && !header.contains("vn_r"),
        "{header}"
    );
}
