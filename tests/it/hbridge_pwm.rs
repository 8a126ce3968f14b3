//! The PWM H-bridge of the `hbridge` benchmark (`benches/models/hbridge_pwm.vhd`) for 40 PWM
//! periods from rest, so that the model file cannot rot:
//! * synchronous freewheeling (piecewise linear): the motor follows the state-space averaged
//!   model `L i' = D V - (R + 2 r_on) i - ke w`, `J w' = kt i - d w` (closed form). Both start
//!   from rest at the start of an on part, so the PWM current runs ahead of the averaged one
//!   by up to the ripple's peak-to-peak `dI = V D (1 - D) T / L` (at the end of each on part);
//!   checked within 1.1 dI. Its mean lead, about dI / 2, decays with the electrical time
//!   constant `L / R`, so the speed runs ahead by about `kt / J dI / 2 L / R` (0.26 rad/s);
//!   checked within 1.5 times that;
//! * diode freewheeling (the benchmark's default): in the off part of the last period the
//!   diode gnd -> out1 carries the motor current (within 0.1 %) at a forward drop between
//!   0.3 V and 0.6 V (`vt ln(i / is)` = 0.46 V at 0.5 A).

use std::path::PathBuf;

use vams::analog::AnalogSystem;
use vams::app::load::load;
use vams::design::SignalId;
use vams::elaborate::{ElabOptions, elaborate};
use vams::kernel::{Outcome, SimOptions, SimResult, simulate};
use vams::solver::DaeSystem;

/// The model's defaults (and models/dc_motor.vhd's).
const V: f64 = 12.0;
const DUTY: f64 = 0.6;
const PERIOD: f64 = 50e-6;
const R_ON: f64 = 0.1;
const R: f64 = 4.0;
const L: f64 = 3.0e-3;
const KT: f64 = 0.015;
const KE: f64 = 0.015;
const D: f64 = 1.5e-6;
const J: f64 = 1.0e-6;
/// 40 periods, ending in the middle of the last off part (an event-free instant).
const STOP: f64 = 39.8 * PERIOD;

fn run(synchronous: bool) -> SimResult {
    let root = env!("CARGO_MANIFEST_DIR");
    let paths = [
        PathBuf::from(root).join("models/dc_motor.vhd"),
        PathBuf::from(root).join("benches/models/hbridge_pwm.vhd"),
    ];
    let loaded = load(&paths).expect("models exist");
    assert_eq!(loaded.error_count(), 0, "{:?}", loaded.syntax_errors);
    let options = ElabOptions {
        top: "hbridge_pwm".into(),
        generics: vec![("synchronous".into(), synchronous.to_string())],
    };
    let design = elaborate(&loaded.sources, &loaded.files, &options).expect("elaborates");
    // The diodes' exponentials: Newton must confirm every step (`DaeSystem::is_linear`).
    let mut system = AnalogSystem::new(&design).expect("builds");
    assert!(!system.is_linear());
    // The switches' signals are what the equations read: their values name the mode that a
    // restart at a switching edge starts from (`DaeSystem::mode`).
    let hs1_on = design
        .signals
        .iter()
        .position(|s| s.name == "hs1_on")
        .map(|i| SignalId(i as u32))
        .expect("hs1_on is a signal");
    let off = system.mode();
    system.set_signal(hs1_on, 1.0);
    let on = system.mode();
    assert!(off.is_some() && on.is_some() && on != off, "{off:?} {on:?}");
    system.set_signal(hs1_on, 0.0);
    assert_eq!(system.mode(), off);
    let sim = SimOptions {
        stop: STOP,
        probes: ["motor.i", "motor.w", "i_dl", "v_dl"]
            .map(String::from)
            .to_vec(),
        ..SimOptions::default()
    };
    let result = simulate(&design, &sim, &mut |_| {}).expect("the H-bridge simulates");
    assert_eq!(result.outcome, Outcome::Finished);
    result
}

/// `(i, w)` of the averaged model from rest: steady state plus `exp(A t)` of the offset, with
/// `exp(A t) = exp(m t) (cosh(r t) I + sinh(r t) / r (A - m I))`, `m` half the trace,
/// `r^2 = m^2 - det > 0` (real eigenvalues for these figures).
fn averaged(t: f64) -> (f64, f64) {
    let r_loop = R + 2.0 * R_ON;
    let a = [[-r_loop / L, -KE / L], [KT / J, -D / J]];
    let det = (r_loop * D + KE * KT) / (L * J);
    let (i_ss, w_ss) = (
        DUTY * V * D / (r_loop * D + KE * KT),
        DUTY * V * KT / (r_loop * D + KE * KT),
    );
    let m = (a[0][0] + a[1][1]) / 2.0;
    let r = (m * m - det).sqrt();
    let (c, s) = ((r * t).cosh(), (r * t).sinh() / r);
    let (x0, y0) = (-i_ss, -w_ss);
    let e = (m * t).exp();
    (
        i_ss + e * (c * x0 + s * ((a[0][0] - m) * x0 + a[0][1] * y0)),
        w_ss + e * (c * y0 + s * (a[1][0] * x0 + (a[1][1] - m) * y0)),
    )
}

#[test]
fn synchronous_bridge_follows_the_averaged_model() {
    let result = run(true);
    let w = &result.waveforms;
    let ripple = V * DUTY * (1.0 - DUTY) * PERIOD / L;
    let w_end = averaged(STOP).1;
    let (mut worst_i, mut worst_w) = (0.0_f64, 0.0_f64);
    for &t in &w.times {
        let (i_avg, w_avg) = averaged(t);
        let i = w.value_at("motor.i", t).expect("motor.i recorded");
        let s = w.value_at("motor.w", t).expect("motor.w recorded");
        worst_i = worst_i.max((i - i_avg).abs());
        worst_w = worst_w.max((s - w_avg).abs());
    }
    eprintln!(
        "{} samples; current within {worst_i:.3e} A of the averaged model (ripple {ripple:.3e} A \
         p-p), speed within {worst_w:.3e} rad/s (final {w_end:.2} rad/s)",
        w.times.len()
    );
    let speed_lead = KT / J * ripple / 2.0 * L / (R + 2.0 * R_ON);
    assert!(worst_i < 1.1 * ripple, "current off by {worst_i} A");
    assert!(worst_w < 1.5 * speed_lead, "speed off by {worst_w} rad/s");
    // Not vacuous: the motor has accelerated and the current has risen past the ripple.
    assert!(w_end > 20.0 && averaged(STOP).0 > 5.0 * ripple);
}

#[test]
fn freewheel_diode_carries_the_motor_current_when_hs1_is_off() {
    let result = run(false);
    let w = &result.waveforms;
    let at = |name: &str| w.value_at(name, STOP).expect("recorded");
    let (i_motor, i_diode, v_diode) = (at("motor.i"), at("i_dl"), at("v_dl"));
    eprintln!("at {STOP} s: motor {i_motor} A, diode {i_diode} A at {v_diode} V");
    assert!(i_motor > 0.1, "motor current {i_motor} A");
    assert!((i_diode - i_motor).abs() < 1e-3 * i_motor);
    assert!((0.3..0.6).contains(&v_diode), "diode drop {v_diode} V");
}
