//! An independent generator of the four bench captures of `vams extract`, taken the way a lab
//! takes them: every capture on its own bench (its own Thevenin supply and source resistance,
//! the blocked rotor at a reduced voltage), its own scope settings (a 1-2-5 timebase and
//! vertical range, a record length, a pre-trigger), a switch that acts between two samples.
//!
//! Deliberately shares no code with `vams` (not `vams::extract::synth`, not its motor law):
//! it depends on `std` only, with its own random numbers, integrator and scope, so that a
//! mistake shared by the extraction and its own synthetic captures cannot hide here.
//!
//! The physics (SI units; `i` the smooth armature current, `w` the speed, `th` the angle):
//!
//! ```text
//! L di/dt = v_term - R i - ke w          v_term = vs - rs i f(th) while the switch is closed
//! J dw/dt = ke i - d w - tcst            while the rotor turns (it only turns forward here)
//! ```
//!
//! Constant friction is Coulomb friction with a true stick: a rotor at rest stays at rest while
//! `|ke i| <= tcst`, and a coasting rotor that reaches `w = 0` stops there (the instants found
//! by bisection inside the RK4 substep). The extraction's model smooths it with
//! `tanh(w / 0.5 rad/s)`, so the two differ slightly near rest, as a real motor differs from
//! any model.
//!
//! The commutation ripple: the current that flows (through the source, the motor and the
//! probe) is `i f(th)`, `f(th) = 1 + a(th) (sin(N th) + 0.2 sin(2 N th + phi2))`, with a depth
//! `a` of 3-8 % that varies around the revolution (an eccentricity, `1 + e cos(th + phi_e)`, e
//! up to 0.2) and by a few per cent from one revolution to the next (brush contact; smoothly
//! interpolated, so the current has no jumps). It stands for what the brushes do as they pass
//! the segment gaps; it is the terminals' view of the commutation, not its mechanism. The torque
//! follows the smooth current: its ripple averages out within a commutation period, and the
//! inertia filters what is left to a speed ripple far below what the captures resolve. The
//! source's drop sees the current that flows, so the terminal voltage carries a small ripple
//! too. The blocked rotor is held where its current reads the average of the positions (what
//! an operator does, reading R), so its capture carries no ripple. While coasting (switch
//! open, current 0) the terminals show the back-EMF `ke w (1 + 0.01 (sin(N th) + 0.2 sin(2 N
//! th + phi2)))`.
//!
//! The scope: 10 horizontal divisions of a 1-2-5 timebase (the nearest to the wanted span:
//! inrush 4-6 mechanical time constants, blocked rotor 10-20 electrical ones, speed 50-200
//! ripple periods, coast 1.3-2 times the stop), a record of 2 000 to 20 000 samples (a longer
//! one where the inrush's current rise would get fewer than 10 samples per electrical time
//! constant, or the ripple fewer than 10 per period), a pre-trigger of 5-30 %; the trigger (time
//! 0) is the first sample after the switch, which acts at a random instant inside the sample
//! interval before it. Each channel: 8 divisions of the finest 1-2-5 range in which the signal
//! and its ground level fill at most 90 % of the screen (so 36-90 %), positioned with a random
//! margin, 8-bit quantisation (256 codes over the screen), Gaussian noise of 0.3-1 LSB and a
//! probe offset (voltage up to +-20 mV, current up to +-2 mA), codes clipped to the screen.

#![allow(dead_code)] // the integration test and the benchmark each use part of it

use std::f64::consts::PI;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Commutations per revolution of the generated motors (the extraction's default).
pub const COMMUTATIONS: u32 = 4;

/// SplitMix64 with uniform, log-uniform and Gaussian draws (Box-Muller).
#[derive(Debug, Clone)]
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed ^ 0x5DEE_CE66_D1CE_4E5B)
    }
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in (0, 1), never 0 (the logarithm of Box-Muller).
    pub fn uniform(&mut self) -> f64 {
        ((self.next_u64() >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.uniform()
    }
    pub fn log_range(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + (hi.ln() - lo.ln()) * self.uniform()).exp()
    }
    pub fn gauss(&mut self) -> f64 {
        let (u1, u2) = (self.uniform(), self.uniform());
        (-2.0 * u1.ln()).sqrt() * (2.0 * PI * u2).cos()
    }
    pub fn sign(&mut self) -> f64 {
        if self.next_u64() & 1 == 0 { 1.0 } else { -1.0 }
    }
    pub fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[(self.next_u64() % items.len() as u64) as usize]
    }
}

/// The lowest and highest supply of the driven captures and the largest source resistance:
/// a motor is drawn so that every bench [`Bench::random`] can give makes sense.
const RUN_SUPPLY: (f64, f64) = (10.0, 14.0);
const BLOCKED_SUPPLY: (f64, f64) = (2.0, 4.0);
const SOURCE_R: (f64, f64) = (0.05, 0.5);

/// The motor's true parameters (SI), `kt = ke`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LabMotor {
    /// Armature resistance, ohm.
    pub r: f64,
    /// Armature inductance, H.
    pub l: f64,
    /// Back-EMF (= torque) constant, V s/rad.
    pub ke: f64,
    /// Rotor inertia, kg m^2.
    pub j: f64,
    /// Viscous friction, N m s/rad.
    pub d: f64,
    /// Constant (Coulomb) friction, N m.
    pub tcst: f64,
}

impl LabMotor {
    /// The names of `vams extract --json` in the order of [`LabMotor::values`].
    pub const NAMES: [&'static str; 7] = ["r", "l", "ke", "kt", "j", "d", "tcst_motor"];

    pub fn values(&self) -> [f64; 7] {
        [self.r, self.l, self.ke, self.ke, self.j, self.d, self.tcst]
    }

    /// A small actuator motor, each parameter log-uniform in its range, drawn again until the
    /// four experiments make sense on every bench the lab may use.
    pub fn random(rng: &mut Rng) -> LabMotor {
        loop {
            let m = LabMotor {
                r: rng.log_range(3.0, 20.0),
                l: rng.log_range(1e-3, 8e-3),
                ke: rng.log_range(0.008, 0.03),
                j: rng.log_range(0.4e-6, 3e-6),
                d: rng.log_range(0.5e-6, 4e-6),
                tcst: rng.log_range(0.1e-3, 0.6e-3),
            };
            if m.sensible() {
                return m;
            }
        }
    }

    /// Whether the experiments make sense on the worst bench: the motor starts with a torque
    /// well above its friction at the lowest running supply; its electrical time constant is
    /// clearly shorter than the mechanical one (else the inrush cannot separate them), but not
    /// so short that a record of 20 000 samples over the run-up misses the current's rise; the
    /// coast from the highest supply's speed stops within 3 s; the run-up takes under a
    /// second; and neither friction term is negligible at speed (else the coast cannot tell
    /// them apart: the extraction's goals could not be met by any method).
    pub fn sensible(&self) -> bool {
        let (v_lo, v_hi) = RUN_SUPPLY;
        let rs = SOURCE_R.1;
        let start_torque = self.ke * v_lo / (self.r + rs);
        let w_lo = self.steady(v_lo, rs).0;
        let w_hi = self.steady(v_hi, SOURCE_R.0).0;
        let viscous_share = self.d * w_lo / (self.d * w_lo + self.tcst);
        start_torque > 5.0 * self.tcst
            && self.tau_m(SOURCE_R.0) > 10.0 * self.tau_e(SOURCE_R.0)
            && self.tau_m(rs) < 100.0 * self.tau_e(rs)
            && self.stop_time(w_hi) < 3.0
            && 5.0 * self.tau_m(rs) < 1.0
            && (0.1..0.9).contains(&viscous_share)
    }

    /// Electrical time constant behind a source resistance `rs`, s.
    pub fn tau_e(&self, rs: f64) -> f64 {
        self.l / (self.r + rs)
    }

    /// Mechanical time constant of the run-up behind `rs` (linearised: viscous friction and
    /// the back-EMF's damping), s.
    pub fn tau_m(&self, rs: f64) -> f64 {
        self.j / (self.d + self.ke * self.ke / (self.r + rs))
    }

    /// The no-load steady speed and current behind a supply `vs` with `rs`: `ke i = d w +
    /// tcst` and `vs = (r + rs) i + ke w`.
    pub fn steady(&self, vs: f64, rs: f64) -> (f64, f64) {
        let rt = self.r + rs;
        let w = (vs - rt * self.tcst / self.ke) / (self.ke + rt * self.d / self.ke);
        (w, (self.d * w + self.tcst) / self.ke)
    }

    /// How long a rotor at `w0` coasts (no current) before it sticks: `w(t) = (w0 + c)
    /// exp(-t d/J) - c` with `c = tcst/d`.
    pub fn stop_time(&self, w0: f64) -> f64 {
        self.j / self.d * (1.0 + w0 * self.d / self.tcst).ln()
    }
}

/// One capture's bench: a Thevenin supply.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bench {
    /// Open-circuit supply voltage, V.
    pub vs: f64,
    /// Source (supply, wiring, switch) resistance, ohm.
    pub rs: f64,
}

impl Bench {
    /// A bench of its own: the blocked rotor at 2-4 V, the others at 10-14 V, each with a
    /// source resistance of 0.05-0.5 ohm.
    pub fn random(rng: &mut Rng, role: Role) -> Bench {
        let (lo, hi) = if role == Role::Blocked {
            BLOCKED_SUPPLY
        } else {
            RUN_SUPPLY
        };
        Bench {
            vs: rng.range(lo, hi),
            rs: rng.log_range(SOURCE_R.0, SOURCE_R.1),
        }
    }
}

/// The four experiments.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    Inrush,
    Blocked,
    Speed,
    Coast,
}

impl Role {
    pub const ALL: [Role; 4] = [Role::Inrush, Role::Blocked, Role::Speed, Role::Coast];

    /// The file stem and the `vams extract` option.
    pub fn name(self) -> &'static str {
        match self {
            Role::Inrush => "inrush",
            Role::Blocked => "blocked",
            Role::Speed => "speed",
            Role::Coast => "coast",
        }
    }
}

/// The commutation ripple of one motor (see the module's documentation).
#[derive(Debug, Clone)]
pub struct Ripple {
    /// Mean relative depth of the current ripple.
    pub depth: f64,
    /// Depth modulation around the revolution and its phase.
    pub eccentricity: f64,
    pub ecc_phase: f64,
    /// Phase of the second commutation harmonic.
    pub phase2: f64,
    /// Relative spread of the depth from one revolution to the next.
    pub jitter: f64,
    /// Seed of the per-revolution spread.
    pub seed: u64,
    /// Relative depth of the coasting back-EMF's ripple.
    pub emf_depth: f64,
}

impl Ripple {
    pub fn random(rng: &mut Rng) -> Ripple {
        Ripple {
            depth: rng.range(0.03, 0.08),
            eccentricity: rng.range(0.0, 0.2),
            ecc_phase: rng.range(0.0, 2.0 * PI),
            phase2: rng.range(0.0, 2.0 * PI),
            jitter: 0.03,
            seed: rng.next_u64(),
            emf_depth: 0.01,
        }
    }

    /// No ripple at all (the physics tests' closed forms).
    pub fn none() -> Ripple {
        Ripple {
            depth: 0.0,
            eccentricity: 0.0,
            ecc_phase: 0.0,
            phase2: 0.0,
            jitter: 0.0,
            seed: 0,
            emf_depth: 0.0,
        }
    }

    fn shape(&self, th: f64) -> f64 {
        let n = f64::from(COMMUTATIONS);
        (n * th).sin() + 0.2 * (2.0 * n * th + self.phase2).sin()
    }

    /// A standard Gaussian for revolution `k`, the same each time it is asked for.
    fn revolution_spread(&self, k: i64) -> f64 {
        let mut rng = Rng::new(self.seed ^ (k as u64).wrapping_mul(0xD1B5_4A32_D192_ED03));
        rng.gauss()
    }

    /// The current's factor `f(th)`.
    pub fn current(&self, th: f64) -> f64 {
        if self.depth == 0.0 {
            return 1.0;
        }
        let rev = th / (2.0 * PI);
        let k = rev.floor();
        let frac = rev - k;
        // Interpolated between revolutions (smoothstep), so the depth changes without a jump.
        let s = frac * frac * (3.0 - 2.0 * frac);
        let spread =
            (1.0 - s) * self.revolution_spread(k as i64) + s * self.revolution_spread(k as i64 + 1);
        let a = self.depth
            * (1.0 + self.eccentricity * (th + self.ecc_phase).cos())
            * (1.0 + self.jitter * spread);
        1.0 + a * self.shape(th)
    }

    /// The coasting back-EMF's factor.
    pub fn emf(&self, th: f64) -> f64 {
        1.0 + self.emf_depth * self.shape(th)
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
struct State {
    i: f64,
    w: f64,
    th: f64,
}

/// Whether the rotor sticks (held, or at rest with friction holding it) or turns forward.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Mode {
    Stuck,
    Turning,
}

/// The motor on one bench, integrated with RK4.
struct Sim<'a> {
    m: &'a LabMotor,
    ripple: &'a Ripple,
    bench: Bench,
    /// The rotor held (blocked-rotor capture): it never turns.
    held: bool,
    x: State,
    mode: Mode,
    closed: bool,
}

impl Sim<'_> {
    fn deriv(&self, x: State, mode: Mode) -> State {
        let m = self.m;
        let di = if self.closed {
            let flowing = x.i * self.ripple_factor(x.th);
            (self.bench.vs - self.bench.rs * flowing - m.r * x.i - m.ke * x.w) / m.l
        } else {
            0.0
        };
        let (dw, dth) = match mode {
            Mode::Stuck => (0.0, 0.0),
            Mode::Turning => ((m.ke * x.i - m.d * x.w - m.tcst) / m.j, x.w),
        };
        State {
            i: di,
            w: dw,
            th: dth,
        }
    }

    fn rk4(&self, x: State, mode: Mode, h: f64) -> State {
        let add = |a: State, b: State, s: f64| State {
            i: a.i + s * b.i,
            w: a.w + s * b.w,
            th: a.th + s * b.th,
        };
        let k1 = self.deriv(x, mode);
        let k2 = self.deriv(add(x, k1, 0.5 * h), mode);
        let k3 = self.deriv(add(x, k2, 0.5 * h), mode);
        let k4 = self.deriv(add(x, k3, h), mode);
        State {
            i: x.i + h / 6.0 * (k1.i + 2.0 * k2.i + 2.0 * k3.i + k4.i),
            w: x.w + h / 6.0 * (k1.w + 2.0 * k2.w + 2.0 * k3.w + k4.w),
            th: x.th + h / 6.0 * (k1.th + 2.0 * k2.th + 2.0 * k3.th + k4.th),
        }
    }

    /// The fraction `s` of a step of `h` from `x` at which `g` of the stepped state turns
    /// positive (`g` is negative at 0 and positive at 1), by bisection.
    fn crossing(&self, x: State, mode: Mode, h: f64, g: impl Fn(State) -> f64) -> f64 {
        let (mut lo, mut hi) = (0.0, 1.0);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if g(self.rk4(x, mode, mid * h)) > 0.0 {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        hi
    }

    /// The longest substep: a hundredth of the electrical time constant while current flows,
    /// a fiftieth of a commutation period while the rotor turns.
    fn max_substep(&self) -> f64 {
        let mut h = f64::INFINITY;
        if self.closed {
            h = h.min(self.m.tau_e(self.bench.rs) / 100.0);
        }
        if self.mode == Mode::Turning && self.x.w > 0.0 {
            h = h.min(2.0 * PI / (f64::from(COMMUTATIONS) * self.x.w) / 50.0);
        }
        h
    }

    /// One substep of `h`, switching between sticking and turning at the exact instant.
    fn substep(&mut self, h: f64) {
        let m = self.m;
        let x = self.x;
        let y = self.rk4(x, self.mode, h);
        match self.mode {
            Mode::Stuck if !self.held && m.ke * y.i > m.tcst => {
                // Breakaway: the torque exceeds the friction part-way through the substep.
                let s = self.crossing(x, Mode::Stuck, h, |z| m.ke * z.i - m.tcst);
                let at = self.rk4(x, Mode::Stuck, s * h);
                self.x = self.rk4(at, Mode::Turning, (1.0 - s) * h);
                self.mode = Mode::Turning;
            }
            Mode::Turning if y.w < 0.0 => {
                // The rotor comes to rest part-way through: it sticks if friction can hold it
                // (always, in these experiments: it only stops with the current off).
                let s = self.crossing(x, Mode::Turning, h, |z| -z.w);
                let mut at = self.rk4(x, Mode::Turning, s * h);
                at.w = 0.0;
                assert!(
                    (m.ke * at.i).abs() <= m.tcst,
                    "the rotor stops against a driving torque"
                );
                self.mode = Mode::Stuck;
                self.x = self.rk4(at, Mode::Stuck, (1.0 - s) * h);
            }
            _ => self.x = y,
        }
    }

    /// Integrates over `span` seconds.
    fn advance(&mut self, span: f64) {
        if span <= 0.0 {
            return;
        }
        let n = (span / self.max_substep()).ceil().max(1.0);
        // Bounded: a span is at most a sample interval or a pre-roll, the substep at least
        // nanoseconds, so `n` stays far below usize's range.
        let h = span / n;
        for _ in 0..n as usize {
            self.substep(h);
        }
    }

    /// The current's ripple factor: none on the held rotor (see the module's documentation).
    fn ripple_factor(&self, th: f64) -> f64 {
        if self.held {
            1.0
        } else {
            self.ripple.current(th)
        }
    }

    /// The terminal voltage and the current through the motor.
    fn terminals(&self) -> (f64, f64) {
        if self.closed {
            let flowing = self.x.i * self.ripple_factor(self.x.th);
            (self.bench.vs - self.bench.rs * flowing, flowing)
        } else {
            (self.m.ke * self.x.w * self.ripple.emf(self.x.th), 0.0)
        }
    }
}

/// The true signals of one capture at its sample instants (before the scope).
#[derive(Debug, Clone, Default)]
pub struct Truth {
    pub v: Vec<f64>,
    pub i: Vec<f64>,
    /// The speed and the smooth current, for the physics tests.
    pub w: Vec<f64>,
    pub i_smooth: Vec<f64>,
}

/// How one experiment starts and what its switch does.
#[derive(Debug, Clone, Copy)]
pub struct Experiment {
    pub role: Role,
    pub bench: Bench,
    /// The rotor's angle at the start, rad.
    pub angle: f64,
}

/// Simulates `e` at the instants `t` (ascending), the switch acting at `t_switch` (closing
/// for the inrush and the blocked rotor, opening for the coast; ignored for the speed).
pub fn simulate(m: &LabMotor, ripple: &Ripple, e: &Experiment, t: &[f64], t_switch: f64) -> Truth {
    let mut sim = Sim {
        m,
        ripple,
        bench: e.bench,
        held: e.role == Role::Blocked,
        x: State {
            i: 0.0,
            w: 0.0,
            th: e.angle,
        },
        mode: Mode::Stuck,
        closed: false,
    };
    let t0 = t.first().copied().unwrap_or(0.0);
    let mut switch = match e.role {
        Role::Inrush | Role::Blocked => Some(t_switch),
        Role::Speed | Role::Coast => {
            // Already running: from the closed-form steady state, then long enough that what
            // the ripple in the source's drop changes has settled.
            let (w, i) = m.steady(e.bench.vs, e.bench.rs);
            sim.x.w = w;
            sim.x.i = i;
            sim.mode = Mode::Turning;
            sim.closed = true;
            let angle = sim.x.th;
            sim.advance(3.0 * m.tau_m(e.bench.rs));
            sim.x.th = angle;
            (e.role == Role::Coast).then_some(t_switch)
        }
    };
    let mut out = Truth::default();
    let mut now = t0;
    for &tk in t {
        if let Some(ts) = switch.filter(|&ts| ts <= tk) {
            sim.advance(ts - now);
            now = ts;
            sim.closed = !sim.closed;
            if !sim.closed {
                sim.x.i = 0.0;
            }
            switch = None;
        }
        sim.advance(tk - now);
        now = tk;
        let (v, i) = sim.terminals();
        out.v.push(v);
        out.i.push(i);
        out.w.push(sim.x.w);
        out.i_smooth.push(if sim.closed { sim.x.i } else { 0.0 });
    }
    out
}

/// The 1-2-5 sequence from 1e-6 to 50.
fn one_two_five() -> impl Iterator<Item = f64> {
    (-6..=1).flat_map(|e| [1.0, 2.0, 5.0].map(|m| m * 10f64.powi(e)))
}

/// One scope channel's settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Channel {
    /// Units per division (8 divisions on the screen).
    pub per_div: f64,
    /// The value at the bottom of the screen.
    pub bottom: f64,
    /// Noise, RMS, in LSB.
    pub noise_lsb: f64,
    /// The probe's offset.
    pub offset: f64,
}

impl Channel {
    pub fn lsb(&self) -> f64 {
        8.0 * self.per_div / 256.0
    }

    /// The operator's setting for a signal `x` seen through a probe with `offset`: the
    /// finest 1-2-5 range in which the signal and its ground level fill at most 90 % of the
    /// screen, the trace placed with a random share of the free room below it.
    fn choose(rng: &mut Rng, x: &[f64], offset: f64) -> Channel {
        let lo = x.iter().copied().fold(0.0, f64::min) + offset;
        let hi = x.iter().copied().fold(0.0, f64::max) + offset;
        let span = hi - lo;
        let per_div = one_two_five()
            .find(|d| span <= 0.9 * 8.0 * d)
            .unwrap_or(50.0);
        let room = 8.0 * per_div - span;
        Channel {
            per_div,
            bottom: lo - rng.range(0.3, 0.7) * room,
            noise_lsb: rng.range(0.3, 1.0),
            offset,
        }
    }

    /// The samples as the scope records them, and how many were clipped.
    fn record(&self, rng: &mut Rng, x: &[f64]) -> (Vec<f64>, usize) {
        let lsb = self.lsb();
        let mut clipped = 0;
        let v = x
            .iter()
            .map(|v| {
                let seen = v + self.offset + self.noise_lsb * lsb * rng.gauss();
                let code = ((seen - self.bottom) / lsb).round();
                if !(0.0..=255.0).contains(&code) {
                    clipped += 1;
                }
                self.bottom + code.clamp(0.0, 255.0) * lsb
            })
            .collect();
        (v, clipped)
    }
}

/// One capture as the scope gives it, with its settings and the truth behind it.
#[derive(Debug, Clone)]
pub struct Capture {
    pub experiment: Experiment,
    /// Times relative to the trigger, s.
    pub t: Vec<f64>,
    pub v: Vec<f64>,
    pub i: Vec<f64>,
    /// The switching instant (`None` for the speed capture), s.
    pub t_switch: Option<f64>,
    /// Seconds per division (10 divisions).
    pub time_per_div: f64,
    /// Samples before the trigger.
    pub pre: usize,
    pub voltage: Channel,
    pub current: Channel,
    /// Samples outside the screen (0 when the operator's range holds the signal).
    pub clipped: usize,
    pub truth: Truth,
}

impl Capture {
    pub fn dt(&self) -> f64 {
        self.t[1] - self.t[0]
    }

    /// The CSV text: `time,voltage,current`.
    pub fn csv(&self) -> String {
        let mut s = String::with_capacity(40 * self.t.len() + 32);
        s.push_str("time,voltage,current\n");
        for k in 0..self.t.len() {
            let _ = writeln!(s, "{:.9e},{:.7e},{:.7e}", self.t[k], self.v[k], self.i[k]);
        }
        s
    }
}

/// The record lengths the operator chooses from.
const RECORD_LENGTHS: [usize; 5] = [2_000, 2_500, 5_000, 10_000, 20_000];

/// How the operator frames one experiment: the span after the trigger that should fill the
/// record, the least that must be on it, and the least sample rate (what must be resolved:
/// the speed capture's ripple, the inrush's current rise, which gives L).
struct Framing {
    wanted: f64,
    least: f64,
    least_rate: f64,
}

fn framing(rng: &mut Rng, m: &LabMotor, e: &Experiment) -> Framing {
    let (w_run, _) = m.steady(e.bench.vs, e.bench.rs);
    let ripple_period = 2.0 * PI / (f64::from(COMMUTATIONS) * w_run);
    match e.role {
        Role::Inrush => {
            let tau = m.tau_m(e.bench.rs);
            Framing {
                wanted: rng.range(4.0, 6.0) * tau,
                least: 3.5 * tau,
                least_rate: 10.0 / m.tau_e(e.bench.rs),
            }
        }
        Role::Blocked => {
            let tau = m.tau_e(e.bench.rs);
            Framing {
                wanted: rng.range(10.0, 20.0) * tau,
                least: 8.0 * tau,
                least_rate: 0.0,
            }
        }
        Role::Speed => Framing {
            wanted: rng.range(50.0, 200.0) * ripple_period,
            least: 40.0 * ripple_period,
            least_rate: 10.0 / ripple_period,
        },
        Role::Coast => {
            let stop = m.stop_time(w_run);
            Framing {
                wanted: rng.range(1.3, 2.0) * stop,
                least: 1.2 * stop,
                least_rate: 0.0,
            }
        }
    }
}

/// Takes one capture of experiment `e`.
pub fn take(rng: &mut Rng, m: &LabMotor, ripple: &Ripple, e: &Experiment) -> Capture {
    let f = framing(rng, m, e);
    let pre_share = rng.range(0.05, 0.30);
    let record = rng.pick(&RECORD_LENGTHS);
    // The timebase nearest (by ratio) to the wanted window, or the next one up that holds
    // what must be on the record after the trigger.
    let window = f.wanted / (1.0 - pre_share);
    let mut time_per_div = one_two_five()
        .min_by(|a, b| {
            let da = (10.0 * a / window).ln().abs();
            let db = (10.0 * b / window).ln().abs();
            da.total_cmp(&db)
        })
        .unwrap_or(1.0);
    while 10.0 * time_per_div * (1.0 - pre_share) < f.least {
        time_per_div = one_two_five()
            .find(|&d| d > time_per_div * 1.01)
            .unwrap_or(10.0 * time_per_div);
    }
    // A longer record where what must be resolved would be sampled too coarsely (motors are
    // drawn so that the longest record suffices).
    let window = 10.0 * time_per_div;
    let least_samples = (f.least_rate * window).ceil() as usize;
    let n = RECORD_LENGTHS
        .iter()
        .copied()
        .filter(|&n| n >= record.max(least_samples))
        .min()
        .unwrap_or(RECORD_LENGTHS[RECORD_LENGTHS.len() - 1]);
    let dt = window / n as f64;
    let pre = (pre_share * n as f64).round() as usize;
    let t: Vec<f64> = (0..n).map(|k| (k as f64 - pre as f64) * dt).collect();
    // The switch acts inside the interval before the trigger sample, never on a sample.
    let t_switch = -rng.range(0.05, 0.95) * dt;
    let truth = simulate(m, ripple, e, &t, t_switch);
    let v_offset = rng.range(-0.02, 0.02);
    let i_offset = rng.range(-2e-3, 2e-3);
    let voltage = Channel::choose(rng, &truth.v, v_offset);
    let current = Channel::choose(rng, &truth.i, i_offset);
    let (v, clipped_v) = voltage.record(rng, &truth.v);
    let (i, clipped_i) = current.record(rng, &truth.i);
    Capture {
        experiment: *e,
        t,
        v,
        i,
        t_switch: (e.role != Role::Speed).then_some(t_switch),
        time_per_div,
        pre,
        voltage,
        current,
        clipped: clipped_v + clipped_i,
        truth,
    }
}

/// A lab session: one motor, its ripple, four benches and the captures taken on them.
#[derive(Debug, Clone)]
pub struct Lab {
    pub motor: LabMotor,
    pub ripple: Ripple,
    /// Inrush, blocked, speed, coast.
    pub captures: [Capture; 4],
}

impl Lab {
    /// A random motor on four random benches, from `seed`.
    pub fn random(seed: u64) -> Lab {
        Lab::random_on(seed, None)
    }

    /// The motor of [`Lab::random`]`(seed)` with all four captures on one `shared` bench when
    /// given (the case the extraction was first written for: a control).
    pub fn random_on(seed: u64, shared: Option<Bench>) -> Lab {
        let mut rng = Rng::new(seed);
        let motor = LabMotor::random(&mut rng);
        // Drawn either way, so that the rest of the lab (ripple, angles, scope) is the same.
        let benches = Role::ALL.map(|r| Bench::random(&mut rng, r));
        Lab::on_benches(&mut rng, motor, shared.map_or(benches, |b| [b; 4]))
    }

    /// `motor` on the given benches (inrush, blocked, speed, coast).
    pub fn on_benches(rng: &mut Rng, motor: LabMotor, benches: [Bench; 4]) -> Lab {
        let ripple = Ripple::random(rng);
        let captures = std::array::from_fn(|k| {
            let e = Experiment {
                role: Role::ALL[k],
                bench: benches[k],
                angle: rng.range(0.0, 2.0 * PI),
            };
            take(rng, &motor, &ripple, &e)
        });
        Lab {
            motor,
            ripple,
            captures,
        }
    }

    /// Writes `inrush.csv`, `blocked.csv`, `speed.csv`, `coast.csv` into `dir`.
    pub fn write(&self, dir: &Path) -> std::io::Result<[PathBuf; 4]> {
        std::fs::create_dir_all(dir)?;
        let mut paths: [PathBuf; 4] = Default::default();
        for (cap, path) in self.captures.iter().zip(&mut paths) {
            *path = dir.join(format!("{}.csv", cap.experiment.role.name()));
            std::fs::write(&*path, cap.csv())?;
        }
        Ok(paths)
    }

    /// The arguments of `vams extract` for the files `paths` (from [`Lab::write`]).
    pub fn extract_args(paths: &[PathBuf; 4]) -> Vec<String> {
        let mut args = vec!["extract".to_string(), "--json".to_string()];
        for (role, p) in Role::ALL.iter().zip(paths) {
            args.push(format!("--{}", role.name()));
            args.push(p.display().to_string());
        }
        args
    }

    /// One line per capture: its bench and scope settings.
    pub fn describe(&self) -> String {
        let mut s = String::new();
        for c in &self.captures {
            let e = &c.experiment;
            let _ = writeln!(
                s,
                "  {:7} vs {:6.3} V rs {:.3} ohm | {} samples, {:.0e} s/div, pre {}, switch {} | \
                 {:.0e} V/div, {:.0e} A/div, clipped {}",
                e.role.name(),
                e.bench.vs,
                e.bench.rs,
                c.t.len(),
                c.time_per_div,
                c.pre,
                c.t_switch.map_or("-".to_string(), |t| format!("{t:.3e} s")),
                c.voltage.per_div,
                c.current.per_div,
                c.clipped,
            );
        }
        s
    }
}

#[cfg(test)]
mod physics {
    use super::*;

    fn motor() -> LabMotor {
        LabMotor {
            r: 7.0,
            l: 3e-3,
            ke: 0.014,
            j: 1.2e-6,
            d: 1.5e-6,
            tcst: 0.3e-3,
        }
    }

    fn run(role: Role, bench: Bench, ripple: &Ripple, t: &[f64], ts: f64) -> Truth {
        let e = Experiment {
            role,
            bench,
            angle: 0.7,
        };
        simulate(&motor(), ripple, &e, t, ts)
    }

    fn grid(n: usize, dt: f64) -> Vec<f64> {
        (0..n).map(|k| (k as f64 - 10.0) * dt).collect()
    }

    #[test]
    fn the_blocked_current_settles_at_the_supply_over_the_resistances() {
        let m = motor();
        let bench = Bench { vs: 3.1, rs: 0.27 };
        let t = grid(1000, 30.0 * m.tau_e(bench.rs) / 1000.0);
        let out = run(
            Role::Blocked,
            bench,
            &Ripple::random(&mut Rng::new(1)),
            &t,
            -1e-7,
        );
        let i_end = *out.i.last().unwrap();
        let want = bench.vs / (m.r + bench.rs);
        assert!((i_end / want - 1.0).abs() < 1e-6, "{i_end} vs {want}");
        let v_end = *out.v.last().unwrap();
        assert!((v_end - bench.vs * m.r / (m.r + bench.rs)).abs() < 1e-6);
        assert!(out.w.iter().all(|&w| w == 0.0), "a held rotor turned");
        // Before the switch: nothing; the current rises with the electrical time constant.
        assert_eq!((out.v[5], out.i[5]), (0.0, 0.0));
        let k = 10 + 1000 / 30; // one time constant after the trigger
        let ts = -1e-7;
        let want = bench.vs / (m.r + bench.rs) * (1.0 - (-(t[k] - ts) / m.tau_e(bench.rs)).exp());
        assert!(
            (out.i[k] / want - 1.0).abs() < 1e-8,
            "{} vs {want}",
            out.i[k]
        );
    }

    #[test]
    fn the_run_up_ends_at_the_closed_form_speed() {
        let m = motor();
        let bench = Bench { vs: 12.0, rs: 0.2 };
        let t = grid(2000, 15.0 * m.tau_m(bench.rs) / 2000.0);
        let out = run(Role::Inrush, bench, &Ripple::none(), &t, -3e-6);
        let (w, i) = m.steady(bench.vs, bench.rs);
        let w_end = *out.w.last().unwrap();
        let i_end = *out.i.last().unwrap();
        assert!((w_end / w - 1.0).abs() < 1e-6, "{w_end} vs {w}");
        assert!((i_end / i - 1.0).abs() < 1e-5, "{i_end} vs {i}");
    }

    #[test]
    fn the_rotor_sticks_until_the_torque_exceeds_the_friction() {
        let m = motor();
        let bench = Bench { vs: 12.0, rs: 0.2 };
        // Stuck, i = i_inf (1 - exp(-t/tau_e)); the breakaway where ke i = tcst.
        let i_inf = bench.vs / (m.r + bench.rs);
        let t_break = -m.tau_e(bench.rs) * (1.0 - m.tcst / (m.ke * i_inf)).ln();
        let dt = t_break / 50.0;
        let t = grid(200, dt);
        let ts = -0.4 * dt;
        let out = run(Role::Inrush, bench, &Ripple::none(), &t, ts);
        for (tk, w) in t.iter().zip(&out.w) {
            if tk - ts < t_break * 0.999 {
                assert_eq!(*w, 0.0, "turning at {tk} before the breakaway {t_break}");
            } else if tk - ts > t_break * 1.001 {
                assert!(*w > 0.0, "still at {tk} after the breakaway {t_break}");
            }
        }
    }

    #[test]
    fn the_coast_stops_at_the_closed_form_time_and_stays() {
        let m = motor();
        let bench = Bench { vs: 11.0, rs: 0.1 };
        let (w0, _) = m.steady(bench.vs, bench.rs);
        let stop = m.stop_time(w0);
        let dt = 1.5 * stop / 3000.0;
        let t = grid(3000, dt);
        let ts = -0.3 * dt;
        let out = run(Role::Coast, bench, &Ripple::none(), &t, ts);
        // Before: running at the steady state; after: no current, the back-EMF decays.
        assert!((out.w[0] / w0 - 1.0).abs() < 1e-6);
        assert!((out.v[0] - (bench.vs - bench.rs * out.i[0])).abs() < 1e-12);
        for (k, tk) in t.iter().enumerate().skip(10) {
            assert_eq!(out.i[k], 0.0);
            let c = m.tcst / m.d;
            let want = ((w0 + c) * (-(tk - ts) * m.d / m.j).exp() - c).max(0.0);
            assert!(
                (out.w[k] - want).abs() < 1e-6 * w0,
                "at {tk}: {} vs {want}",
                out.w[k]
            );
            assert_eq!(out.v[k], m.ke * out.w[k]);
        }
        assert_eq!(*out.w.last().unwrap(), 0.0);
    }

    #[test]
    fn the_ripple_is_periodic_in_the_commutations_with_its_depth() {
        let ripple = Ripple::random(&mut Rng::new(5));
        let n = 100_000;
        let f: Vec<f64> = (0..n)
            .map(|k| ripple.current(2.0 * PI * k as f64 / n as f64))
            .collect();
        let mean = f.iter().sum::<f64>() / n as f64;
        assert!((mean - 1.0).abs() < 1e-3, "{mean}");
        let peak = f.iter().fold(0.0f64, |a, v| a.max((v - 1.0).abs()));
        assert!(
            peak > 0.8 * ripple.depth && peak < 1.6 * ripple.depth,
            "{peak}"
        );
        // Continuous across a revolution's boundary (the spread is interpolated).
        let th = 2.0 * PI * 3.0;
        assert!((ripple.current(th - 1e-9) - ripple.current(th + 1e-9)).abs() < 1e-6);
    }

    #[test]
    fn labs_frame_their_captures_like_an_operator() {
        for seed in 0..12 {
            let lab = Lab::random(seed);
            for c in &lab.captures {
                let name = c.experiment.role.name();
                let n = c.t.len();
                assert!((2_000..=20_000).contains(&n), "{name}: {n} samples");
                assert_eq!(c.clipped, 0, "{name}: clipped\n{}", lab.describe());
                let share = c.pre as f64 / n as f64;
                assert!(
                    (0.049..=0.301).contains(&share),
                    "{name}: pre-trigger {share}"
                );
                assert!(c.t[0] < 0.0 && c.t[c.pre] == 0.0);
                if let Some(ts) = c.t_switch {
                    let k = c.t.iter().position(|&t| t > ts).unwrap();
                    assert!(ts > c.t[k - 1] && ts < c.t[k], "{name}: switch on a sample");
                }
                for (ch, x) in [(c.voltage, &c.truth.v), (c.current, &c.truth.i)] {
                    let hi = x.iter().fold(0.0f64, |a, &v| a.max(v)) + ch.offset;
                    let lo = x.iter().fold(0.0f64, |a, &v| a.min(v)) + ch.offset;
                    let fill = (hi - lo) / (8.0 * ch.per_div);
                    assert!((0.3..=0.9).contains(&fill), "{name}: fill {fill}");
                }
            }
            // The inrush resolves the current's rise, the speed capture its ripple.
            let m = &lab.motor;
            let inrush = &lab.captures[0];
            assert!(inrush.dt() <= m.tau_e(inrush.experiment.bench.rs) / 10.0);
            let speed = &lab.captures[2];
            let b = speed.experiment.bench;
            let period = 2.0 * PI / (f64::from(COMMUTATIONS) * m.steady(b.vs, b.rs).0);
            assert!(speed.dt() <= period / 10.0);
            assert!(
                (40.0 * period..=500.0 * period).contains(&(speed.dt() * speed.t.len() as f64))
            );
            let e: Vec<Bench> = lab.captures.iter().map(|c| c.experiment.bench).collect();
            assert!(e[1].vs < 4.0 && e.iter().all(|b| (0.05..=0.5).contains(&b.rs)));
            // The coast stops inside its record, the speed capture turns at its steady speed.
            let coast = &lab.captures[3];
            assert_eq!(*coast.truth.w.last().unwrap(), 0.0, "seed {seed}");
            let speed = &lab.captures[2];
            let (w, _) = lab
                .motor
                .steady(speed.experiment.bench.vs, speed.experiment.bench.rs);
            assert!(speed.truth.w.iter().all(|v| (v / w - 1.0).abs() < 1e-3));
        }
    }

    #[test]
    fn a_capture_writes_as_a_scope_csv() {
        let lab = Lab::random(3);
        let text = lab.captures[0].csv();
        let mut lines = text.lines();
        assert_eq!(lines.next(), Some("time,voltage,current"));
        let first: Vec<f64> = lines
            .next()
            .unwrap()
            .split(',')
            .map(|f| f.parse().unwrap())
            .collect();
        assert!(first[0] < 0.0);
        assert_eq!(text.lines().count(), lab.captures[0].t.len() + 1);
    }
}
