//! Synthetic oscilloscope captures of the four bench experiments, from known parameters.
//!
//! Takes motor parameters and the bench set-up (supply, source resistance, ripple depth,
//! noise, probe offsets); gives the four captures as a scope would record them: commutation
//! ripple, noise, 8-bit quantisation over an auto-ranged window, offsets, a pre-trigger, and
//! the text of a CSV export (metadata preamble, `;` or `,`, units row, trailing empty columns).
//!
//! The ripple is a multiplicative modulation of the current, `i*(1 + a(theta)*m(N*theta))`
//! with `m(p) = sin p + 0.3 sin 2p` and a depth `a` that varies by 25 % around the
//! revolution; the coasting back-EMF carries a smaller modulation of the same shape. The rotor
//! starts (and is blocked) at an angle where `m = 0`, where an operator reads R.
//! Used by the tests, `vams extract --demo` and the README; never used by the extraction.

use super::capture::Capture;
use super::model::MotorParams;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The bench set-up and the scope's imperfections.
#[derive(Debug, Clone)]
pub struct SynthOptions {
    /// Supply voltage, V.
    pub supply: f64,
    /// Source (supply + wiring) resistance, ohm: the terminal voltage sags with current.
    pub source_r: f64,
    /// The blocked rotor's own supply, V (labs take it at a few volts, so that the stalled
    /// current stays within the probe's range); `None`: `supply`.
    pub blocked_supply: Option<f64>,
    /// Current commutations per revolution.
    pub commutations: u32,
    /// Relative depth of the current ripple.
    pub ripple_depth: f64,
    /// Relative depth of the back-EMF ripple in the coast.
    pub emf_ripple: f64,
    /// Noise, RMS, in least significant bits of the 8-bit scope.
    pub noise_lsb: f64,
    /// Offset of the current probe, A.
    pub current_offset: f64,
    /// Offset of the voltage probe, V.
    pub voltage_offset: f64,
    /// Seed of the noise.
    pub seed: u64,
    /// Samples per capture (`None`: a scope's usual 12 000, 1 500, 6 000 and 12 000); the
    /// same records, sampled finer (benchmarks use 100 000).
    pub samples: Option<usize>,
}

impl Default for SynthOptions {
    fn default() -> Self {
        SynthOptions {
            supply: 10.5,
            source_r: 0.3,
            blocked_supply: None,
            commutations: 4,
            ripple_depth: 0.08,
            emf_ripple: 0.01,
            noise_lsb: 0.6,
            current_offset: 1.0e-3,
            voltage_offset: 0.02,
            seed: 1,
            samples: None,
        }
    }
}

impl SynthOptions {
    /// The bench as labs set it up (`vams extract --demo`): the blocked rotor at 3 V beside
    /// the other three at the full supply.
    pub fn lab() -> SynthOptions {
        SynthOptions {
            blocked_supply: Some(3.0),
            ..SynthOptions::default()
        }
    }
}

/// The four captures, in the order inrush, blocked, speed, coast.
pub type Captures = [Capture; 4];

/// A small deterministic generator (SplitMix64) with Gaussian samples.
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn uniform(&mut self) -> f64 {
        ((self.next_u64() >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
    fn gauss(&mut self) -> f64 {
        let (u1, u2) = (self.uniform(), self.uniform());
        (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
    }
}

fn modulation(p: f64) -> f64 {
    p.sin() + 0.3 * (2.0 * p).sin()
}

/// The state of the bench: current, speed, angle.
type State = [f64; 3];

/// Integrates one sample interval `dt` of the driven motor (source `vs` behind `rs`).
fn step_driven(p: &MotorParams, x: State, vs: f64, rs: f64, dt: f64, blocked: bool) -> State {
    let sub = ((dt / (0.05 * p.l / (p.r + rs))).ceil() as usize).max(1);
    let h = dt / sub as f64;
    let f = |x: State| -> State {
        let [i, w, _] = x;
        let di = (vs - (p.r + rs) * i - p.ke * w) / p.l;
        let dw = if blocked {
            0.0
        } else {
            (p.kt * i - p.friction(w)) / p.j
        };
        [di, dw, w]
    };
    let mut x = x;
    for _ in 0..sub {
        let add = |a: State, b: State, s: f64| [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]];
        let k1 = f(x);
        let k2 = f(add(x, k1, 0.5 * h));
        let k3 = f(add(x, k2, 0.5 * h));
        let k4 = f(add(x, k3, h));
        for c in 0..3 {
            x[c] += h / 6.0 * (k1[c] + 2.0 * k2[c] + 2.0 * k3[c] + k4[c]);
        }
    }
    x
}

/// Integrates one interval of the coasting rotor (i = 0).
fn step_coast(p: &MotorParams, x: State, dt: f64) -> State {
    let sub = 20;
    let h = dt / sub as f64;
    let (mut w, mut th) = (x[1], x[2]);
    for _ in 0..sub {
        let f = |w: f64| -p.friction(w) / p.j;
        let k1 = f(w);
        let k2 = f(w + 0.5 * h * k1);
        let k3 = f(w + 0.5 * h * k2);
        let k4 = f(w + h * k3);
        th += h * w;
        w += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    [0.0, w, th]
}

/// Adds noise and offset and quantises to 8 bits over a range that holds the signal and 0.
fn scope_channel(x: &[f64], offset: f64, noise_lsb: f64, rng: &mut Rng) -> Vec<f64> {
    let lo = x.iter().copied().fold(0.0, f64::min);
    let hi = x.iter().copied().fold(0.0, f64::max);
    let span = (hi - lo).max(1e-3) * 1.25;
    let lo = lo - 0.1 * span;
    let lsb = span / 255.0;
    x.iter()
        .map(|v| {
            let noisy = v + offset + noise_lsb * lsb * rng.gauss();
            let code = ((noisy - lo) / lsb).round().clamp(0.0, 255.0);
            lo + code * lsb
        })
        .collect()
}

fn capture(
    role: &'static str,
    t: Vec<f64>,
    v: Vec<f64>,
    i: Vec<f64>,
    o: &SynthOptions,
    rng: &mut Rng,
) -> Capture {
    Capture {
        role,
        path: PathBuf::from(format!("{role}.csv")),
        v: scope_channel(&v, o.voltage_offset, o.noise_lsb, rng),
        i: scope_channel(&i, o.current_offset, o.noise_lsb, rng),
        t,
    }
}

fn ripple(o: &SynthOptions, th: f64) -> f64 {
    let a = o.ripple_depth * (1.0 + 0.25 * th.cos());
    1.0 + a * modulation(o.commutations as f64 * th)
}

/// Generates the four captures of a motor with parameters `p`.
pub fn generate(p: &MotorParams, o: &SynthOptions) -> Captures {
    let mut rng = Rng(o.seed);
    let (rs, vs) = (o.source_r, o.supply);
    // Steady state behind the source resistance: solve with the terminal voltage iterated.
    let mut v_term = vs;
    let mut ss = p.steady_state(v_term);
    for _ in 0..50 {
        v_term = vs - rs * ss.1;
        ss = p.steady_state(v_term);
    }
    let (w_ss, i_ss) = ss;
    let tau_m = p.j * p.r / (p.ke * p.kt);

    // a. Inrush: 6 % pre-trigger, then the supply switched on; about 4 mechanical time constants.
    let span = (4.0 * tau_m).clamp(0.02, 1.0);
    let n = o.samples.unwrap_or(12_000);
    let dt = span / n as f64;
    let pre = n / 16;
    let (mut t, mut v, mut i) = (Vec::new(), Vec::new(), Vec::new());
    let mut x: State = [0.0, 0.0, 0.0];
    for k in 0..n {
        let on = k >= pre;
        if k > pre {
            x = step_driven(p, x, vs, rs, dt, false);
        }
        t.push((k as f64 - pre as f64) * dt);
        v.push(if on { vs - rs * x[0] } else { 0.0 });
        i.push(x[0] * ripple(o, x[2]));
    }
    let inrush = capture("inrush", t, v, i, o, &mut rng);

    // b. Blocked rotor: 10 % pre-trigger, 12 electrical time constants.
    let tau_e = p.l / (p.r + rs);
    let n = o.samples.unwrap_or(1500);
    let dt = 12.0 * tau_e / n as f64;
    let pre = n / 10;
    let (mut t, mut v, mut i) = (Vec::new(), Vec::new(), Vec::new());
    let mut x: State = [0.0, 0.0, 0.0];
    let vs_blocked = o.blocked_supply.unwrap_or(vs);
    for k in 0..n {
        if k > pre {
            x = step_driven(p, x, vs_blocked, rs, dt, true);
        }
        t.push((k as f64 - pre as f64) * dt);
        v.push(if k >= pre {
            vs_blocked - rs * x[0]
        } else {
            0.0
        });
        i.push(x[0]);
    }
    let blocked = capture("blocked", t, v, i, o, &mut rng);

    // c. Constant speed: about 60 commutation periods.
    let f_c = o.commutations as f64 * w_ss / (2.0 * std::f64::consts::PI);
    let n = o.samples.unwrap_or(6000);
    let dt = (60.0 / f_c.max(1.0)) / n as f64;
    let (mut t, mut v, mut i) = (Vec::new(), Vec::new(), Vec::new());
    let mut x: State = [i_ss, w_ss, 0.3];
    for k in 0..n {
        if k > 0 {
            x = step_driven(p, x, vs, rs, dt, false);
        }
        t.push(k as f64 * dt);
        v.push(vs - rs * x[0]);
        i.push(x[0] * ripple(o, x[2]));
    }
    let speed = capture("speed", t, v, i, o, &mut rng);

    // d. Coast: 4 % pre-trigger at speed, then the supply disconnected (an inductive kick of
    // two samples), the back-EMF decaying to rest; the record is 1.6 times the stop time.
    let w_end = p.tcst_motor / p.d;
    let t_stop = if p.d > 0.0 {
        p.j / p.d * ((w_ss + w_end) / w_end).ln()
    } else {
        p.j * w_ss / p.tcst_motor
    };
    let n = o.samples.unwrap_or(12_000);
    let dt = 1.6 * t_stop / n as f64;
    let pre = n / 25;
    let (mut t, mut v, mut i) = (Vec::new(), Vec::new(), Vec::new());
    let mut x: State = [i_ss, w_ss, 1.0];
    for k in 0..n {
        if k < pre {
            x[2] += w_ss * dt;
            v.push(v_term);
            i.push(i_ss * ripple(o, x[2]));
        } else {
            x = step_coast(p, x, dt);
            let emf = p.ke * x[1] * (1.0 + o.emf_ripple * modulation(o.commutations as f64 * x[2]));
            v.push(if k < pre + 2 { -0.15 * vs } else { emf });
            i.push(0.0);
        }
        t.push((k as f64 - pre as f64) * dt);
    }
    let coast = capture("coast", t, v, i, o, &mut rng);
    [inrush, blocked, speed, coast]
}

/// How a capture is written as text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ScopeStyle {
    /// `time,voltage,current` and samples, nothing else.
    Plain,
    /// A metadata preamble, a header `Time,Voltage,Current`, a units row `s,V,A`.
    Preamble,
    /// Like `Preamble` with `;` separators, decimal commas, current in mA and trailing
    /// empty columns.
    European,
}

/// The text of a scope export of `cap`.
pub fn to_csv(cap: &Capture, style: ScopeStyle) -> String {
    let mut s = String::new();
    let (sep, comma, iscale, unit_i) = match style {
        ScopeStyle::European => (';', true, 1e3, "mA"),
        _ => (',', false, 1.0, "A"),
    };
    if style != ScopeStyle::Plain {
        let _ = writeln!(s, "Model{sep}VAMS-SYNTH 8-bit{sep}{sep}");
        let _ = writeln!(s, "Capture{sep}{}{sep}{sep}", cap.role);
        let _ = writeln!(s, "Record length{sep}{}{sep}{sep}", cap.len());
        let _ = writeln!(s, "Sample interval (s){sep}{:e}{sep}{sep}", cap.dt());
        let _ = writeln!(
            s,
            "Time{sep}Voltage{sep}Current{}",
            if comma { ";;" } else { "" }
        );
        let _ = writeln!(s, "s{sep}V{sep}{unit_i}{}", if comma { ";;" } else { "" });
    } else {
        s.push_str("time,voltage,current\n");
    }
    for k in 0..cap.len() {
        let line = format!(
            "{:.7e}{sep}{:.5}{sep}{:.6}{}",
            cap.t[k],
            cap.v[k],
            cap.i[k] * iscale,
            if comma { ";;" } else { "" }
        );
        if comma {
            s.push_str(&line.replace('.', ","));
        } else {
            s.push_str(&line);
        }
        s.push('\n');
    }
    s
}

/// Writes the four captures into `dir` as `inrush.csv`, `blocked.csv`, `speed.csv`,
/// `coast.csv`, in the styles Preamble, European, Plain, Preamble.
pub fn write_captures(dir: &Path, caps: &Captures) -> std::io::Result<[PathBuf; 4]> {
    std::fs::create_dir_all(dir)?;
    let styles = [
        ScopeStyle::Preamble,
        ScopeStyle::European,
        ScopeStyle::Plain,
        ScopeStyle::Preamble,
    ];
    let mut out: [PathBuf; 4] = Default::default();
    for (k, cap) in caps.iter().enumerate() {
        let path = dir.join(format!("{}.csv", cap.role));
        std::fs::write(&path, to_csv(cap, styles[k]))?;
        out[k] = path;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::super::capture::{Columns, parse_capture};
    use super::*;

    #[test]
    fn captures_round_trip_through_every_style() {
        let caps = generate(&MotorParams::example(), &SynthOptions::default());
        for style in [
            ScopeStyle::Plain,
            ScopeStyle::Preamble,
            ScopeStyle::European,
        ] {
            let text = to_csv(&caps[1], style);
            let back =
                parse_capture("blocked", Path::new("b.csv"), &text, &Columns::default()).unwrap();
            assert_eq!(back.len(), caps[1].len());
            assert!((back.i[1000] - caps[1].i[1000]).abs() < 1e-5);
        }
    }

    #[test]
    fn the_coast_stops_inside_the_record() {
        let caps = generate(&MotorParams::example(), &SynthOptions::default());
        let coast = &caps[3];
        let tail = &coast.v[coast.len() - 100..];
        assert!(tail.iter().all(|v| v.abs() < 0.2), "{tail:?}");
    }
}
