//! `vams ac` end to end on the models in `tests/ac/`: closed forms (RC low-pass, series RLC
//! resonance and Q, a mass-spring-damper in the translational nature, a biased diode,
//! `'delayed`, `'ltf`, `'integ`, a spectrum that reads `frequency`, equations switched on
//! `domain`) to 1e-9 relative, `'zoh`, `'ztf` and a loop through
//! `'zoh`, the refusals (no spectral source, `'slew`), the outputs, and
//! ngspice's `.ac` on the RC, the RLC and the diode stage when ngspice is installed.

use std::f64::consts::{PI, TAU};
use std::path::Path;

use assert_cmd::Command;

use crate::support::ngspice;
use predicates::str::contains;

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/ac");

fn vams() -> Command {
    Command::cargo_bin("vams").expect("the vams binary is built for integration tests")
}

/// A complex number as `(re, im)`.
#[derive(Clone, Copy, Debug)]
struct Z(f64, f64);

impl Z {
    fn norm(self) -> f64 {
        self.0.hypot(self.1)
    }
    fn div(self, d: Z) -> Z {
        let den = d.0 * d.0 + d.1 * d.1;
        Z(
            (self.0 * d.0 + self.1 * d.1) / den,
            (self.1 * d.0 - self.0 * d.1) / den,
        )
    }
    fn relative_error(self, exact: Z) -> f64 {
        Z(self.0 - exact.0, self.1 - exact.1).norm() / exact.norm()
    }
}

/// The CSV of a run: the header's names and the rows.
struct Table {
    names: Vec<String>,
    rows: Vec<Vec<f64>>,
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

    /// `(frequency, value)` of a probe from `--complex` columns.
    fn complex(&self, probe: &str) -> Vec<(f64, Z)> {
        let f = self.column("frequency");
        let re = self.column(&format!("{probe}_re"));
        let im = self.column(&format!("{probe}_im"));
        (0..f.len()).map(|k| (f[k], Z(re[k], im[k]))).collect()
    }
}

/// Runs `vams ac` on `tests/ac/<model>.vhd` with `args`; the CSV on standard output.
/// `vams ac tests/ac/MODEL.vhd --from FROM --to TO`, for the diagnostics' tests.
fn ac_command(model: &str, from: &str, to: &str) -> Command {
    let mut command = vams();
    command.args([
        "ac",
        &format!("{DIR}/{model}.vhd"),
        "--from",
        from,
        "--to",
        to,
    ]);
    command
}

fn ac(model: &str, args: &[&str]) -> Table {
    let out = vams()
        .arg("ac")
        .arg(format!("{DIR}/{model}.vhd"))
        .args(args)
        .output()
        .expect("vams runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    Table::parse(&String::from_utf8(out.stdout).expect("utf-8"))
}

/// The largest relative error of a probe against `exact(w)`.
fn worst(points: &[(f64, Z)], exact: impl Fn(f64) -> Z) -> f64 {
    points
        .iter()
        .map(|&(f, z)| z.relative_error(exact(TAU * f)))
        .fold(0.0, f64::max)
}

#[test]
fn rc_low_pass_matches_its_closed_form() {
    let (r, c) = (1.0e3, 100.0e-9);
    let t = ac(
        "rc_lowpass",
        &[
            "--from",
            "1Hz",
            "--to",
            "1MHz",
            "--probe",
            "vout",
            "--complex",
        ],
    );
    let points = t.complex("vout");
    assert_eq!(points.len(), 121);
    let err = worst(&points, |w| Z(1.0, 0.0).div(Z(1.0, w * r * c)));
    println!("RC low-pass, vout: largest relative error {err:.2e}");
    assert!(err < 1e-9, "{err:e}");
    // The capacitor's current, eliminated as `c * v'dot`: jwC times vout.
    let t = ac(
        "rc_lowpass",
        &[
            "--from",
            "1Hz",
            "--to",
            "1MHz",
            "--probe",
            "ic",
            "--complex",
        ],
    );
    let err = worst(&t.complex("ic"), |w| Z(0.0, w * c).div(Z(1.0, w * r * c)));
    println!("RC low-pass, ic: largest relative error {err:.2e}");
    assert!(err < 1e-9, "{err:e}");

    // Magnitude (dB) and phase (degrees): -3.0103 dB and -45 degrees at the corner.
    let corner = 1.0 / (TAU * r * c);
    let t = ac(
        "rc_lowpass",
        &[
            "--from",
            &corner.to_string(),
            "--to",
            "1MHz",
            "--points-per-decade",
            "1",
            "--probe",
            "vout",
        ],
    );
    let (db, deg) = (t.column("vout_db"), t.column("vout_deg"));
    assert!((db[0] + 10.0 * 2f64.log10()).abs() < 1e-9, "{}", db[0]);
    assert!((deg[0] + 45.0).abs() < 1e-9, "{}", deg[0]);
    for (k, f) in t.column("frequency").iter().enumerate() {
        let wrc = TAU * f * r * c;
        let exact_db = -10.0 * (1.0 + wrc * wrc).log10();
        assert!((db[k] - exact_db).abs() < 1e-9 * exact_db.abs().max(1.0));
        assert!((deg[k] + wrc.atan().to_degrees()).abs() < 1e-9 * 90.0);
    }
}

#[test]
fn series_rlc_resonates_at_its_closed_form_frequency_with_its_q() {
    let (r, l, c): (f64, f64, f64) = (10.0, 1.0e-3, 1.0e-6);
    let f0 = 1.0 / (TAU * (l * c).sqrt());
    let q = (l / c).sqrt() / r;
    let impedance = |w: f64| Z(r, w * l - 1.0 / (w * c));
    let t = ac(
        "rlc_series",
        &[
            "--from",
            "100Hz",
            "--to",
            "100kHz",
            "--points-per-decade",
            "50",
            "--probe",
            "vc",
            "--probe",
            "il",
            "--complex",
        ],
    );
    let err_i = worst(&t.complex("il"), |w| Z(1.0, 0.0).div(impedance(w)));
    let err_v = worst(&t.complex("vc"), |w| {
        Z(1.0, 0.0).div(Z(1.0 - w * w * l * c, w * r * c))
    });
    println!("series RLC: largest relative error il {err_i:.2e}, vc {err_v:.2e}");
    assert!(err_i < 1e-9 && err_v < 1e-9, "{err_i:e} {err_v:e}");

    // At f0 the current is 1/R in phase; at the half-power frequencies
    // f0 (sqrt(1 + 1/(4 Q^2)) -+ 1/(2 Q)) it is 1/(R sqrt 2) at +-45 degrees: Q = f0 / (f2 - f1).
    let s = (1.0 + 1.0 / (4.0 * q * q)).sqrt();
    let (f1, f2) = (f0 * (s - 1.0 / (2.0 * q)), f0 * (s + 1.0 / (2.0 * q)));
    let t = ac(
        "rlc_series",
        &[
            "--from",
            &f1.to_string(),
            "--to",
            &f2.to_string(),
            "--linear",
            "2",
            "--probe",
            "il",
        ],
    );
    let (db, deg) = (t.column("il_db"), t.column("il_deg"));
    let half_power = 20.0 * (1.0 / (r * 2f64.sqrt())).log10();
    for (k, sign) in [(0, 1.0), (1, -1.0)] {
        assert!(
            (db[k] - half_power).abs() < 1e-9 * half_power.abs(),
            "{}",
            db[k]
        );
        assert!((deg[k] - sign * 45.0).abs() < 1e-9 * 45.0, "{}", deg[k]);
    }
    let t = ac(
        "rlc_series",
        &[
            "--from",
            &(f0 * 0.999).to_string(),
            "--to",
            &(f0 * 1.001).to_string(),
            "--linear",
            "201",
            "--probe",
            "il",
        ],
    );
    let db = t.column("il_db");
    let peak = (0..db.len())
        .max_by(|&a, &b| db[a].total_cmp(&db[b]))
        .expect("points");
    let f_peak = t.column("frequency")[peak];
    println!("series RLC: peak at {f_peak} Hz (closed form {f0} Hz), Q = {q}");
    assert_eq!(peak, 100, "peak at {f_peak} Hz, f0 = {f0} Hz");
    assert!((db[peak] - 20.0 * (1.0 / r).log10()).abs() < 1e-9);
}

#[test]
fn mass_spring_damper_in_the_translational_nature() {
    let (m, k, d) = (2.0, 2000.0, 4.0);
    let t = ac(
        "msd",
        &[
            "--from",
            "0.1Hz",
            "--to",
            "100Hz",
            "--points-per-decade",
            "40",
            "--probe",
            "x",
            "--probe",
            "f_spring",
            "--complex",
        ],
    );
    let receptance = |w: f64| Z(1.0, 0.0).div(Z(k - m * w * w, w * d));
    let err_x = worst(&t.complex("x"), receptance);
    let err_f = worst(&t.complex("f_spring"), |w| {
        let z = receptance(w);
        Z(k * z.0, k * z.1)
    });
    println!("mass-spring-damper: largest relative error x {err_x:.2e}, f_spring {err_f:.2e}");
    assert!(err_x < 1e-9 && err_f < 1e-9, "{err_x:e} {err_f:e}");
}

#[test]
fn delayed_ltf_integ_and_a_frequency_dependent_spectrum() {
    let t = ac(
        "attributes",
        &[
            "--from",
            "1Hz",
            "--to",
            "10kHz",
            "--points-per-decade",
            "10",
            "--complex",
        ],
    );
    // u: a spectrum of magnitude frequency / 1 kHz at phase pi/4.
    let u = |w: f64| {
        let f = w / TAU;
        let a = f / 1e3;
        Z(a * (PI / 4.0).cos(), a * (PI / 4.0).sin())
    };
    let mul = |a: Z, b: Z| Z(a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0);
    assert!(worst(&t.complex("u"), u) < 1e-12);
    // y_delayed = u'delayed(0.1 ms): e^{-jw 1e-4}.
    let err = worst(&t.complex("y_delayed"), |w| {
        mul(u(w), Z((w * 1e-4).cos(), -(w * 1e-4).sin()))
    });
    println!("'delayed: {err:.2e}");
    assert!(err < 1e-9, "{err:e}");
    // y_ltf = u'ltf((1.0), (1.0, 2 zeta / w0, 1 / w0^2)) with w0 = 2 pi 1 kHz, zeta = 0.3.
    let (w0, zeta) = (TAU * 1e3, 0.3);
    let err = worst(&t.complex("y_ltf"), |w| {
        mul(
            u(w),
            Z(1.0, 0.0).div(Z(1.0 - w * w / (w0 * w0), 2.0 * zeta * w / w0)),
        )
    });
    println!("'ltf: {err:.2e}");
    assert!(err < 1e-9, "{err:e}");
    // y_integ = 1e3 * u'integ: 1e3 u / (jw).
    let err = worst(&t.complex("y_integ"), |w| {
        mul(u(w), Z(1.0e3, 0.0).div(Z(0.0, w)))
    });
    println!("'integ: {err:.2e}");
    assert!(err < 1e-9, "{err:e}");
}

#[test]
fn a_model_switches_its_equations_on_the_frequency_domain() {
    // y == u outside the frequency domain; in it, y / 2 has a pole at 1 kHz.
    let t = ac(
        "domain_switch",
        &[
            "--from",
            "10Hz",
            "--to",
            "100kHz",
            "--probe",
            "y",
            "--complex",
        ],
    );
    let err = worst(&t.complex("y"), |w| {
        Z(2.0, 0.0).div(Z(1.0, w / (TAU * 1e3)))
    });
    println!("domain switch: largest relative error {err:.2e}");
    assert!(err < 1e-9, "{err:e}");
}

/// The diode stage's quiescent diode voltage and small-signal conductance, by Newton.
fn diode_point(r: f64, is_sat: f64, vt: f64) -> (f64, f64) {
    let mut v = 0.6;
    for _ in 0..100 {
        let f = (5.0 - v) / r - is_sat * ((v / vt).exp() - 1.0) - 1e-12 * v;
        let df = -1.0 / r - is_sat / vt * (v / vt).exp() - 1e-12;
        v -= f / df;
    }
    (v, is_sat / vt * (v / vt).exp() + 1e-12)
}

#[test]
fn a_diode_is_linearised_at_its_quiescent_point() {
    let (r, c, is_sat, vt) = (1.0e3, 10.0e-9, 1.0e-14, 0.025852);
    let (_, g) = diode_point(r, is_sat, vt);
    let t = ac(
        "diode_stage",
        &[
            "--from",
            "1Hz",
            "--to",
            "1MHz",
            "--probe",
            "vd",
            "--complex",
        ],
    );
    let err = worst(&t.complex("vd"), |w| {
        Z(1.0 / r, 0.0).div(Z(1.0 / r + g, w * c))
    });
    println!("diode stage: largest relative error {err:.2e}");
    assert!(err < 1e-9, "{err:e}");
}

#[test]
fn writes_csv_and_bode_plot_files() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let csv = dir.path().join("rc.csv");
    let svg = dir.path().join("rc.svg");
    vams()
        .arg("ac")
        .arg(format!("{DIR}/rc_lowpass.vhd"))
        .args([
            "--from", "10Hz", "--to", "100kHz", "--probe", "vout", "--probe", "ir",
        ])
        .arg("-o")
        .arg(&csv)
        .arg("--plot")
        .arg(&svg)
        .assert()
        .success()
        .stdout("")
        .stderr(contains("analysed tb_rc_lowpass at 81 frequencies"));
    let text = std::fs::read_to_string(&csv).expect("CSV written");
    assert!(text.starts_with("frequency,vout_db,vout_deg,ir_db,ir_deg\n10,"));
    assert_eq!(text.lines().count(), 82);
    let plot = std::fs::read_to_string(&svg).expect("plot written");
    assert!(plot.contains("magnitude (dB)") && plot.contains("phase (degrees)"));
    assert!(plot.contains("vout") && plot.contains("frequency (Hz)"));
}

#[test]
fn sampled_data_attributes_follow_their_z_domain_closed_forms() {
    let t = ac(
        "sampled",
        &[
            "--from",
            "1Hz",
            "--to",
            "10kHz",
            "--points-per-decade",
            "25",
            "--probe",
            "held",
            "--probe",
            "filtered",
            "--probe",
            "loop_out",
            "--probe",
            "fir",
            "--complex",
        ],
    );
    let period = 1e-3;
    let hold = |w: f64| {
        // (1 - e^{-jwT}) / (jwT)
        let x = w * period;
        Z(1.0 - x.cos(), x.sin()).div(Z(0.0, x))
    };
    let z_inv = |w: f64| Z((w * period).cos(), -(w * period).sin());
    let filter = |w: f64| Z(0.2, 0.0).div(Z(1.0 - 0.8 * z_inv(w).0, -0.8 * z_inv(w).1));
    let k = 0.5;
    let closed_loop = |w: f64| {
        let h = hold(w);
        Z(k, 0.0).div(Z(1.0 + k * h.0, k * h.1))
    };
    // The hold's zeros (every multiple of 1 kHz) make a relative error meaningless there:
    // compare against the largest response.
    let absolute = |points: &[(f64, Z)], exact: &dyn Fn(f64) -> Z| {
        (points.iter())
            .map(|&(f, z)| {
                let e = exact(TAU * f);
                Z(z.0 - e.0, z.1 - e.1).norm()
            })
            .fold(0.0, f64::max)
    };
    let fir = |w: f64| {
        let (z1, z2) = (z_inv(w), z_inv(2.0 * w));
        Z(0.25 + 0.5 * z1.0 + 0.25 * z2.0, 0.5 * z1.1 + 0.25 * z2.1)
    };
    let errors = [
        absolute(&t.complex("held"), &hold),
        absolute(&t.complex("filtered"), &filter),
        absolute(&t.complex("loop_out"), &closed_loop),
        absolute(&t.complex("fir"), &fir),
    ];
    println!("'zoh, IIR and FIR 'ztf, loop through 'zoh: largest errors {errors:?}");
    for e in errors {
        assert!(e < 1e-12, "{errors:?}");
    }
    // At the sampling frequency the hold passes nothing and the filter is back at its DC gain.
    let held = t.complex("held");
    let at_1k = held
        .iter()
        .find(|(f, _)| (*f - 1e3).abs() < 1e-6)
        .expect("1 kHz");
    assert!(at_1k.1.norm() < 1e-12, "{:?}", at_1k.1);
}

#[test]
fn assertions_check_the_response_at_their_own_frequencies() {
    // The corner, 1591.549 Hz, is between the points of the 1-per-decade grid: each
    // assertion is solved at its frequency.
    ac_command("rc_lowpass", "1Hz", "1MHz")
        .args(["--points-per-decade", "1", "--probe", "vout"])
        .args(["--assert", "gain_db(vout, 1591.5494309189535Hz) > -3.0104"])
        .args(["--assert", "gain_db(vout, 1591.5494309189535Hz) < -3.0102"])
        .args([
            "--assert",
            "phase_deg(vout, 1591.5494309189535Hz) >= -45.000001",
        ])
        .assert()
        .success()
        .stderr(contains(
            "assert gain_db(vout, 1591.5494309189535Hz) > -3.0104: -3.0102999566",
        ))
        .stderr(contains("... ok"));
    ac_command("rc_lowpass", "1Hz", "1MHz")
        .args([
            "--assert",
            "gain(vout, 10kHz) > 0.5",
            "--assert",
            "gain(vout, 1Hz) > 0.99",
        ])
        .assert()
        .code(1)
        .stderr(contains("assert gain(vout, 10kHz) > 0.5: 0.157"))
        .stderr(contains("FAILED"))
        .stderr(contains("1 of 2 assertion(s) on the response failed"));
    ac_command("rc_lowpass", "1Hz", "1MHz")
        .args(["--assert", "gain(vot, 10kHz) > 0.5"])
        .assert()
        .code(1)
        .stderr(contains("did you mean `vout`?"));
}

#[test]
fn an_inverting_amplifier_runs_out_of_gain_at_its_gain_bandwidth() {
    let t = ac(
        "opamp_inverting",
        &[
            "--from",
            "1Hz",
            "--to",
            "10MHz",
            "--points-per-decade",
            "10",
            "--probe",
            "vout",
            "--complex",
        ],
    );
    let (r1, r2, a0, fa) = (1e3, 10e3, 1e5, 10.0);
    let err = worst(&t.complex("vout"), |w| {
        // a(jw) = a0 / (1 + jw / wa); H = -(r2 / r1) / (1 + (1 + r2 / r1) / a).
        let a = Z(a0, 0.0).div(Z(1.0, w / (TAU * fa)));
        let inverse_a = Z(1.0, 0.0).div(a);
        let den = Z(
            1.0 + (1.0 + r2 / r1) * inverse_a.0,
            (1.0 + r2 / r1) * inverse_a.1,
        );
        Z(-r2 / r1, 0.0).div(den)
    });
    println!("inverting amplifier: {err:.2e}");
    assert!(err < 1e-9, "{err:e}");
}

#[test]
fn a_twenty_section_rlc_ladder_agrees_with_ngspice() {
    if !ngspice::available() {
        println!("skipped: ngspice is not on the PATH");
        return;
    }
    let dir = tempfile::tempdir().expect("temporary directory");
    let mut deck = String::from("rlc ladder\nV1 n0 0 DC 0 AC 1\n");
    for k in 1..=20 {
        deck.push_str(&format!(
            "R{k} n{} m{k} 1\nL{k} m{k} n{k} 1m\nC{k} n{k} 0 1u\n",
            k - 1
        ));
    }
    let reference = ngspice_ac(&deck, "n20", dir.path(), "ac dec 20 1 10k")
        .expect("ngspice is installed but did not run the ladder");
    let t = ac(
        "rlc_ladder",
        &[
            "--from",
            "1Hz",
            "--to",
            "10kHz",
            "--probe",
            "vout",
            "--complex",
        ],
    );
    let ours = t.complex("vout");
    assert_eq!(ours.len(), reference.len());
    let mut worst_error = 0.0_f64;
    for (&(f, z), &(fs, zs)) in ours.iter().zip(&reference) {
        assert!((f / fs - 1.0).abs() < 1e-6, "{f} vs {fs}");
        let magnitude = (z.norm() / zs.norm() - 1.0).abs();
        let ratio = z.div(zs);
        worst_error = worst_error.max(magnitude).max(ratio.1.atan2(ratio.0).abs());
    }
    println!("20-section RLC ladder: largest difference from ngspice {worst_error:.2e}");
    assert!(worst_error < 1e-6, "{worst_error:e}");
}

#[test]
fn a_design_without_a_spectral_source_is_refused() {
    ac_command("no_source", "1Hz", "1kHz")
        .assert()
        .code(1)
        .stderr(contains("no spectral source quantity"))
        .stderr(contains("spectrum"));
}

#[test]
fn unsupported_constructs_and_bad_arguments_are_diagnosed() {
    ac_command("slew", "1Hz", "1kHz")
        .assert()
        .code(1)
        .stderr(contains("does not support `vin'slew"))
        .stderr(contains("slew.vhd:"));
    ac_command("rc_lowpass", "1kHz", "1Hz")
        .assert()
        .code(1)
        .stderr(contains("frequency range is empty"));
    ac_command("rc_lowpass", "0Hz", "1Hz")
        .assert()
        .code(2)
        .stderr(contains("not a positive frequency"));
    ac_command("rc_lowpass", "1Hz", "1kHz")
        .args(["--probe", "vot"])
        .assert()
        .code(1)
        .stderr(contains("did you mean `vout`?"));
    vams()
        .args(["check", &format!("{DIR}/frequency_outside.vhd")])
        .assert()
        .code(1)
        .stderr(contains("`frequency` is readable only"));
}

/// ngspice's `.ac` of a deck (`analysis`, e.g. `ac dec 20 1 1meg`): frequency, real and
/// imaginary parts of `v(node)`.
fn ngspice_ac(deck: &str, node: &str, dir: &Path, analysis: &str) -> Option<Vec<(f64, Z)>> {
    let control = format!("{analysis}\nwrdata {{out}} vr({node}) vi({node})");
    let rows = ngspice::run(deck, &control, 3, dir)?;
    Some(rows.iter().map(|v| (v[0], Z(v[1], v[2]))).collect())
}

#[test]
fn agrees_with_ngspice_ac_on_the_rc_and_the_rlc() {
    if !ngspice::available() {
        println!("skipped: ngspice is not on the PATH");
        return;
    }
    let dir = tempfile::tempdir().expect("temporary directory");
    let cases = [
        (
            "rc_lowpass",
            "vout",
            "rc\nV1 in 0 DC 2 AC 1\nR1 in out 1k\nC1 out 0 100n",
            "out",
        ),
        (
            "rlc_series",
            "vc",
            "rlc\nV1 in 0 DC 1 AC 1\nR1 in rl 10\nL1 rl c 1m\nC1 c 0 1u",
            "c",
        ),
    ];
    // ngspice's quiescent point stops at its own tolerances even at reltol 1e-9 (the
    // diode's voltage 2e-7 V from the solution), which moves its small-signal conductance
    // by about 1e-5: the diode stage agrees to that, the linear circuits to ngspice's digits.
    let diode = ".options reltol=1e-9 abstol=1e-15 vntol=1e-12 temp=26.85 tnom=26.85\n\
                 V1 in 0 DC 5 AC 1\nR1 in d 1k\nD1 d 0 dmod\nC1 d 0 10n\n\
                 .model dmod D(IS=1e-14 N=1 RS=0 CJO=0)";
    let diode = format!("diode stage\n{diode}");
    let cases = [
        cases[0],
        cases[1],
        ("diode_stage", "vd", diode.as_str(), "d"),
    ];
    for (model, probe, deck, node) in cases {
        let tolerance = if model == "diode_stage" { 1e-5 } else { 1e-6 };
        let Some(reference) = ngspice_ac(deck, node, dir.path(), "ac dec 20 1 1meg") else {
            panic!("ngspice is installed but did not run the {model} deck");
        };
        let t = ac(
            model,
            &[
                "--from",
                "1Hz",
                "--to",
                "1MHz",
                "--probe",
                probe,
                "--complex",
            ],
        );
        let ours = t.complex(probe);
        assert_eq!(ours.len(), reference.len(), "{model}");
        let mut worst_error = 0.0_f64;
        for (&(f, z), &(fs, zs)) in ours.iter().zip(&reference) {
            assert!((f / fs - 1.0).abs() < 1e-6, "{f} vs {fs}");
            // ngspice prints 9 significant digits: compare magnitudes and phases.
            let magnitude = (z.norm() / zs.norm() - 1.0).abs();
            let ratio = z.div(zs);
            let phase = ratio.1.atan2(ratio.0).abs();
            worst_error = worst_error.max(magnitude).max(phase);
        }
        println!("{model}: largest difference from ngspice {worst_error:.2e}");
        assert!(worst_error < tolerance, "{model}: {worst_error:e}");
    }
}
