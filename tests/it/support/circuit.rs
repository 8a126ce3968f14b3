//! Random small circuits written twice, as VHDL-AMS and as a SPICE netlist, simulated by vams
//! (in process) and by ngspice, and compared node by node: the differential test of the
//! analog engine (`tests/it/differential.rs` runs a bounded number, `examples/differential.rs`
//! thousands).
//!
//! A circuit has 3 to 10 nodes joined by a random spanning tree plus a few more elements:
//! resistors, capacitors, inductors with a series resistance (through an inner node) and
//! Shockley diodes; a sine voltage source drives node 1, a DC current source feeds another
//! node, and a 100 MOhm leak joins every node to ground (so that no node floats at DC). The
//! run lasts three periods of the source. The VHDL-AMS diode has SPICE's `GMIN` (1e-12 S)
//! across its junction, as ngspice's does: behind a reverse diode it decides a node's voltage.

// The test and the example each use part of this module.
#![allow(dead_code)]

use std::fmt::Write;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// How long one ngspice run may take before it counts as having given up.
const NGSPICE_DEADLINE: Duration = Duration::from_secs(20);

use vams::app::load::load;
use vams::design::Design;
use vams::elaborate::{ElabOptions, elaborate};
use vams::kernel::{Outcome, SimOptions, simulate};

/// SplitMix64: a fixed, documented generator, so that a seed names the same circuit on every
/// machine and in every version (a library generator may change its stream).
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Rng(seed)
    }

    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform integer in `lo..=hi`.
    fn int(&mut self, lo: usize, hi: usize) -> usize {
        lo + (self.next() % (hi - lo + 1) as u64) as usize
    }

    /// Log-uniform in [lo, hi).
    fn log(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + self.unit() * (hi.ln() - lo.ln())).exp()
    }
}

/// A two-terminal element between nodes `a` and `b` (0 is ground).
#[derive(Debug, Clone)]
pub enum Element {
    Resistor {
        r: f64,
    },
    Capacitor {
        c: f64,
    },
    /// An inductor in series with its winding's resistance.
    Inductor {
        l: f64,
        r: f64,
    },
    Diode,
}

#[derive(Debug, Clone)]
pub struct Circuit {
    pub seed: u64,
    pub nodes: usize,
    pub elements: Vec<(usize, usize, Element)>,
    pub amplitude: f64,
    pub frequency: f64,
    /// The DC current source feeds `current_node` with `current` (A).
    pub current: f64,
    pub current_node: usize,
}

impl Circuit {
    pub fn random(seed: u64) -> Self {
        let mut rng = Rng::new(seed);
        let nodes = rng.int(3, 10);
        let mut elements = Vec::new();
        let element = |rng: &mut Rng| match rng.int(0, 9) {
            0..=3 => Element::Resistor {
                r: rng.log(10.0, 10e3),
            },
            4..=6 => Element::Capacitor {
                c: rng.log(1e-9, 1e-6),
            },
            7..=8 => Element::Inductor {
                l: rng.log(10e-6, 1e-3),
                r: rng.log(10.0, 100.0),
            },
            _ => Element::Diode,
        };
        // A spanning tree over ground and the nodes keeps the circuit connected.
        for n in 1..=nodes {
            let other = rng.int(0, n - 1);
            let e = element(&mut rng);
            if rng.unit() < 0.5 {
                elements.push((other, n, e));
            } else {
                elements.push((n, other, e));
            }
        }
        for _ in 0..rng.int(1, nodes) {
            let a = rng.int(0, nodes);
            let mut b = rng.int(0, nodes);
            if b == a {
                b = (a + 1) % (nodes + 1);
            }
            let e = element(&mut rng);
            elements.push((a, b, e));
        }
        Circuit {
            seed,
            nodes,
            elements,
            amplitude: rng.log(0.5, 5.0),
            frequency: rng.log(1e3, 1e5),
            current: (rng.unit() * 2.0 - 1.0) * 2e-3,
            current_node: rng.int(1, nodes),
        }
    }

    pub fn stop(&self) -> f64 {
        3.0 / self.frequency
    }

    fn node(n: usize) -> String {
        if n == 0 {
            "electrical_ref".into()
        } else {
            format!("n{n}")
        }
    }

    /// The circuit as VHDL-AMS: one file with the element entities and `tb_rand`, whose
    /// quantities `v1 .. vN` are the node voltages.
    pub fn vhdl(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "-- Random circuit, seed {} (tests/it/support/circuit.rs).",
            self.seed
        );
        let _ = writeln!(s, "-- vams: stop {:e} sec", self.stop());
        s.push_str(ENTITIES);
        let inner: Vec<usize> = (0..self.elements.len())
            .filter(|&k| matches!(self.elements[k].2, Element::Inductor { .. }))
            .collect();
        s.push_str("library ieee;\nuse ieee.electrical_systems.all;\nuse ieee.math_real.all;\n");
        s.push_str("entity tb_rand is end entity;\narchitecture bench of tb_rand is\n");
        let names: Vec<String> = (1..=self.nodes).map(|n| format!("n{n}")).collect();
        let _ = writeln!(s, "  terminal {} : electrical;", names.join(", "));
        if !inner.is_empty() {
            let xs: Vec<String> = inner.iter().map(|k| format!("x{k}")).collect();
            let _ = writeln!(s, "  terminal {} : electrical;", xs.join(", "));
        }
        s.push_str("  quantity vs across is_src through n1 to electrical_ref;\n");
        let _ = writeln!(
            s,
            "  quantity idc_q through electrical_ref to n{};",
            self.current_node
        );
        for n in 1..=self.nodes {
            let _ = writeln!(s, "  quantity v{n} across n{n} to electrical_ref;");
        }
        s.push_str("begin\n");
        let _ = writeln!(
            s,
            "  vs == {:?} * sin(math_2_pi * {:?} * now);",
            self.amplitude, self.frequency
        );
        let _ = writeln!(s, "  idc_q == {:?};", self.current);
        for n in 1..=self.nodes {
            let _ = writeln!(
                s,
                "  leak{n} : entity work.d_res(a) generic map (r => 1.0e8) port map (n{n}, electrical_ref);"
            );
        }
        for (k, (a, b, e)) in self.elements.iter().enumerate() {
            let (a, b) = (Self::node(*a), Self::node(*b));
            let _ = match e {
                Element::Resistor { r } => writeln!(
                    s,
                    "  e{k} : entity work.d_res(a) generic map (r => {r:?}) port map ({a}, {b});"
                ),
                Element::Capacitor { c } => writeln!(
                    s,
                    "  e{k} : entity work.d_cap(a) generic map (c => {c:?}) port map ({a}, {b});"
                ),
                Element::Inductor { l, r } => writeln!(
                    s,
                    "  r{k} : entity work.d_res(a) generic map (r => {r:?}) port map ({a}, x{k});\n  \
                     e{k} : entity work.d_ind(a) generic map (l => {l:?}) port map (x{k}, {b});"
                ),
                Element::Diode => {
                    writeln!(s, "  e{k} : entity work.d_dio(a) port map ({a}, {b});")
                }
            };
        }
        s.push_str("end architecture;\n");
        s
    }

    /// The circuit as a SPICE netlist (`ngspice -b` writes `data_file`, one pair of columns
    /// per node voltage), at `reltol`, with the largest step `stop / points`.
    pub fn spice(&self, reltol: f64, points: usize, data_file: &str) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "* random circuit, seed {}", self.seed);
        s.push_str(".model dd D(IS=1e-14 N=1 RS=0 CJO=0)\n");
        let _ = writeln!(s, "VS 1 0 SIN(0 {:?} {:?})", self.amplitude, self.frequency);
        let _ = writeln!(s, "IS1 0 {} DC {:?}", self.current_node, self.current);
        for n in 1..=self.nodes {
            let _ = writeln!(s, "RLEAK{n} {n} 0 1e8");
        }
        for (k, (a, b, e)) in self.elements.iter().enumerate() {
            let _ = match e {
                Element::Resistor { r } => writeln!(s, "R{k} {a} {b} {r:?}"),
                Element::Capacitor { c } => writeln!(s, "C{k} {a} {b} {c:?}"),
                Element::Inductor { l, r } => {
                    writeln!(s, "RL{k} {a} x{k} {r:?}\nL{k} x{k} {b} {l:?}")
                }
                Element::Diode => writeln!(s, "D{k} {a} {b} dd"),
            };
        }
        // 300 K: ngspice's thermal voltage is then the VHDL diode's `vt` (0.025852 V); at 27 C
        // its 0.0258652 V shifts a junction at 0.7 V by 0.4 mV and an edge with it.
        let _ = writeln!(
            s,
            ".options reltol={reltol:e} abstol=1e-12 vntol=1e-9 temp=26.85 tnom=26.85"
        );
        let h = self.stop() / points as f64;
        let _ = writeln!(s, ".tran {h:e} {:e} 0 {h:e}", self.stop());
        let vectors: Vec<String> = (1..=self.nodes).map(|n| format!("v({n})")).collect();
        let _ = writeln!(
            s,
            ".control\nrun\nwrdata {data_file} {}\n.endc\n.end",
            vectors.join(" ")
        );
        s
    }
}

const ENTITIES: &str = "library ieee;
use ieee.electrical_systems.all;
entity d_res is generic (r : real); port (terminal p, n : electrical); end entity;
architecture a of d_res is quantity v across i through p to n; begin v == i * r; end architecture;
library ieee;
use ieee.electrical_systems.all;
entity d_cap is generic (c : real); port (terminal p, n : electrical); end entity;
architecture a of d_cap is quantity v across i through p to n; begin i == c * v'dot; end architecture;
library ieee;
use ieee.electrical_systems.all;
entity d_ind is generic (l : real); port (terminal p, n : electrical); end entity;
architecture a of d_ind is quantity v across i through p to n; begin v == l * i'dot; end architecture;
library ieee;
use ieee.electrical_systems.all;
use ieee.math_real.all;
entity d_dio is generic (is_sat : real := 1.0e-14; vt : real := 0.025852); port (terminal p, n : electrical); end entity;
architecture a of d_dio is quantity v across i through p to n; begin i == is_sat * (exp(v / vt) - 1.0) + 1.0e-12 * v; end architecture;

";

/// Node voltages over time: `times` and one column per node (`v1 .. vN`).
#[derive(Debug, Clone)]
pub struct Waves {
    pub times: Vec<f64>,
    pub columns: Vec<Vec<f64>>,
}

impl Waves {
    /// Column `c` at `t`, linearly interpolated.
    pub fn at(&self, c: usize, t: f64) -> f64 {
        let i = self
            .times
            .partition_point(|&x| x <= t)
            .clamp(1, self.times.len() - 1)
            - 1;
        let (t0, t1) = (self.times[i], self.times[i + 1]);
        let w = if t1 > t0 {
            ((t - t0) / (t1 - t0)).clamp(0.0, 1.0)
        } else {
            1.0
        };
        self.columns[c][i] + w * (self.columns[c][i + 1] - self.columns[c][i])
    }

    /// Column `c` at `t`, by the parabola through the three recorded points nearest `t`
    /// (interpolation error of third order in the step: two runs of one circuit with steps
    /// of a thousandth of a period compare to 1e-8 of the swing where linear interpolation
    /// leaves 1e-6).
    pub fn at_quadratic(&self, c: usize, t: f64) -> f64 {
        let n = self.times.len();
        if n < 3 {
            return self.at(c, t);
        }
        let i = self.times.partition_point(|&x| x <= t).clamp(1, n - 1);
        // Points i - 1 and i bracket t; the third is the nearer of their neighbours.
        let first = if i >= 2 && (i + 1 >= n || t - self.times[i - 2] < self.times[i + 1] - t) {
            i - 2
        } else {
            i - 1
        };
        let (ts, vs) = (
            &self.times[first..first + 3],
            &self.columns[c][first..first + 3],
        );
        if ts[0] == ts[1] || ts[1] == ts[2] {
            return self.at(c, t);
        }
        (0..3)
            .map(|j| {
                let mut w = vs[j];
                for k in (0..3).filter(|&k| k != j) {
                    w *= (t - ts[k]) / (ts[j] - ts[k]);
                }
                w
            })
            .sum()
    }

    /// The worst distance of `self`'s recorded points (after 0) from `other`, as a fraction of
    /// `other`'s largest node swing plus 1e-3 of its largest magnitude (see
    /// [`Waves::disagreement`]), with the node (1-based) and time: the smaller of the distance
    /// from `other` interpolated by [`Waves::at_quadratic`] (smooth stretches) and from its
    /// tube (edges, where a time shift of a few picoseconds is a large pointwise difference),
    /// less `allowance` (volts: what absolute tolerances leave).
    pub fn close_difference(&self, other: &Waves, allowance: f64) -> (f64, usize, f64) {
        let (swing, peak) = other.scale();
        let scale = (swing + 1e-3 * peak).max(1e-9);
        let span = other.times.last().copied().unwrap_or(0.0) - other.times[0];
        let dt = 1e-4 * span;
        let mut worst = (0.0, 0, 0.0);
        for (c, column) in self.columns.iter().enumerate() {
            for (&t, &v) in self.times.iter().zip(column).filter(|(t, _)| **t > 0.0) {
                let (lo, hi) = other.range(c, t, dt);
                let tube = (lo - v).max(v - hi).max(0.0);
                let d = (v - other.at_quadratic(c, t)).abs().min(tube);
                let e = (d - allowance).max(0.0) / scale;
                if e.is_nan() || e > worst.0 {
                    worst = (e, c + 1, t);
                }
            }
        }
        worst
    }

    /// The range of column `c` over `[t - dt, t + dt]`.
    fn range(&self, c: usize, t: f64, dt: f64) -> (f64, f64) {
        let (a, b) = (self.at(c, t - dt), self.at(c, t + dt));
        let (mut lo, mut hi) = (a.min(b), a.max(b));
        let first = self.times.partition_point(|&x| x < t - dt);
        let last = self.times.partition_point(|&x| x <= t + dt);
        for &v in &self.columns[c][first..last] {
            lo = lo.min(v);
            hi = hi.max(v);
        }
        (lo, hi)
    }

    /// The largest node swing and the largest magnitude of any node voltage.
    pub fn scale(&self) -> (f64, f64) {
        let mut swing: f64 = 0.0;
        let mut peak: f64 = 0.0;
        for c in &self.columns {
            let (lo, hi) = c
                .iter()
                .fold((f64::MAX, f64::MIN), |(lo, hi), &v| (lo.min(v), hi.max(v)));
            swing = swing.max(hi - lo);
            peak = peak.max(lo.abs()).max(hi.abs());
        }
        (swing, peak)
    }

    /// How far `self`, at its own points, lies from `reference`: for each point, its distance
    /// from the reference's range over a window of 1e-4 of the run around it (a tube: an edge
    /// a nanosecond early is not a wrong value), as a fraction of the reference's largest node
    /// swing plus 1e-3 of its largest magnitude (nodes kilovolts away from ground on a 100
    /// MOhm leak agree to reltol, not to a fraction of a one-volt swing). The worst fraction,
    /// its node (1-based) and time.
    pub fn disagreement(&self, reference: &Waves) -> (f64, usize, f64) {
        let (swing, peak) = reference.scale();
        let scale = (swing + 1e-3 * peak).max(1e-9);
        let span = reference.times.last().copied().unwrap_or(0.0) - reference.times[0];
        let dt = 1e-4 * span;
        let mut worst = (0.0, 0, 0.0);
        for (c, column) in self.columns.iter().enumerate() {
            // From the first step on: at 0, ngspice writes its DC point and vams the state at
            // `0+`, whose algebraic nodes may already follow a source's slope through a
            // capacitor (`v = R C v_src'`); any error of the DC point carries into the steps.
            for (&t, &v) in self.times.iter().zip(column).filter(|(t, _)| **t > 0.0) {
                let (lo, hi) = reference.range(c, t, dt);
                let e = (lo - v).max(v - hi).max(0.0) / scale;
                if e.is_nan() || e > worst.0 {
                    worst = (e, c + 1, t);
                }
            }
        }
        worst
    }
}

/// vams on `circuit` at `reltol` (in process; `dir` holds the source file). `Err` carries
/// the failure's message.
pub fn run_vams(
    circuit: &Circuit,
    reltol: f64,
    keep_unknowns: bool,
    dir: &Path,
) -> Result<Waves, String> {
    run_vams_with(
        circuit,
        SimOptions {
            reltol,
            keep_unknowns,
            ..SimOptions::default()
        },
        dir,
    )
}

/// [`run_vams`] with other options (`stop` and `probes` are the circuit's).
pub fn run_vams_with(circuit: &Circuit, options: SimOptions, dir: &Path) -> Result<Waves, String> {
    let design = elaborated(circuit, dir)?;
    let options = SimOptions {
        stop: circuit.stop(),
        probes: (1..=circuit.nodes).map(|n| format!("v{n}")).collect(),
        ..options
    };
    let result = simulate(&design, &options, &mut |_| {}).map_err(|e| e.to_string())?;
    if result.outcome != Outcome::Finished {
        return Err(format!("{:?}", result.outcome));
    }
    let w = &result.waveforms;
    let columns = (1..=circuit.nodes)
        .map(|n| {
            w.column(&format!("v{n}"))
                .expect("probed node recorded")
                .values
                .clone()
        })
        .collect();
    Ok(Waves {
        times: w.times.clone(),
        columns,
    })
}

/// `circuit` written to `dir`, loaded and elaborated.
pub fn elaborated(circuit: &Circuit, dir: &Path) -> Result<Design, String> {
    let path = dir.join(format!("rand_{}.vhd", circuit.seed));
    std::fs::write(&path, circuit.vhdl()).map_err(|e| e.to_string())?;
    let loaded = load(&[path]).map_err(|e| format!("{e:?}"))?;
    if loaded.error_count() != 0 {
        return Err(format!("{:?}", loaded.syntax_errors));
    }
    let options = ElabOptions {
        top: "tb_rand".into(),
        generics: Vec::new(),
    };
    elaborate(&loaded.sources, &loaded.files, &options).map_err(|e| format!("{e:?}"))
}

/// True when `ngspice` runs here.
pub fn ngspice_available() -> bool {
    Command::new("ngspice")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

/// ngspice on `circuit` at `reltol` with the largest step `stop / points`; `None` when it
/// gives up ("timestep too small") or writes nothing.
pub fn run_ngspice(circuit: &Circuit, reltol: f64, points: usize, dir: &Path) -> Option<Waves> {
    let data = format!("rand_{}.txt", circuit.seed);
    let deck = dir.join(format!("rand_{}.cir", circuit.seed));
    std::fs::write(&deck, circuit.spice(reltol, points, &data)).ok()?;
    let _ = std::fs::remove_file(dir.join(&data));
    // `ngspice -b` exits 1 after a `.control` block even when it ran: the data file tells.
    // Some circuits make it crawl with its memory growing; past the deadline it has given up.
    let mut child = Command::new("ngspice")
        .arg("-b")
        .arg(&deck)
        .current_dir(dir)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .ok()?;
    let deadline = Instant::now() + NGSPICE_DEADLINE;
    loop {
        if child.try_wait().ok()?.is_some() {
            break;
        }
        if Instant::now() > deadline {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        std::thread::sleep(Duration::from_millis(5));
    }
    let text = std::fs::read_to_string(dir.join(&data)).ok()?;
    let mut waves = Waves {
        times: Vec::new(),
        columns: vec![Vec::new(); circuit.nodes],
    };
    for line in text.lines() {
        let fields: Vec<f64> = line
            .split_whitespace()
            .filter_map(|f| f.parse().ok())
            .collect();
        if fields.len() != 2 * circuit.nodes {
            return None;
        }
        waves.times.push(fields[0]);
        for (c, column) in waves.columns.iter_mut().enumerate() {
            column.push(fields[2 * c + 1]);
        }
    }
    // A run that stopped early did not simulate the circuit.
    let last = *waves.times.last()?;
    // (`wrdata` prints 9 significant digits.)
    (last >= circuit.stop() * (1.0 - 1e-6)).then_some(waves)
}

/// One circuit's verdict.
#[derive(Debug)]
pub enum Verdict {
    /// Within the bound of ngspice (the worst fraction of the swing).
    Agrees(f64),
    /// Beyond it: fraction, node, time.
    Disagrees(f64, usize, f64),
    /// vams failed where ngspice finished.
    Fails(String),
    /// ngspice gave up; vams agrees with its own run at a 100 times tighter tolerance.
    NgspiceGaveUp(Result<f64, String>),
}

/// Compares vams at `reltol` (default elimination) with ngspice on the same circuit.
pub fn compare(circuit: &Circuit, reltol: f64, bound: f64, dir: &Path) -> Verdict {
    let vams = run_vams(circuit, reltol, false, dir);
    match run_ngspice(circuit, (reltol * 0.1).max(1e-9), 20_000, dir) {
        Some(reference) => match vams {
            Ok(w) => {
                let (e, node, t) = w.disagreement(&reference);
                if e <= bound {
                    Verdict::Agrees(e)
                } else {
                    Verdict::Disagrees(e, node, t)
                }
            }
            Err(message) => Verdict::Fails(message),
        },
        None => Verdict::NgspiceGaveUp(vams.and_then(|w| {
            let tight = run_vams(circuit, reltol / 100.0, false, dir)?;
            Ok(w.disagreement(&tight).0)
        })),
    }
}
