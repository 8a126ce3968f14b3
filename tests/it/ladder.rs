//! The RC ladder of `tests/simulate/rc_ladder.vhd` (n = 50) against an independent reference:
//! the same nodal ODE integrated in this file with classical RK4 at a fixed step far below its
//! stability limit. The output node must follow the reference within 1e-3 V (of the 1 V step)
//! at every recorded sample.

use std::path::PathBuf;

use vams::analog::AnalogSystem;
use vams::app::load::load;
use vams::elaborate::{ElabOptions, elaborate};
use vams::kernel::{Outcome, SimOptions, simulate};
use vams::solver::DaeSystem;

const SECTIONS: usize = 50;
const R_TOTAL: f64 = 1.0e3;
const C_TOTAL: f64 = 1.0e-6;
const STOP: f64 = 5e-3;

/// `c v_k' = (v_{k-1} - v_k) / r - (v_k - v_{k+1}) / r` with `v_0 = 1` and no current out of
/// the last node: the ladder's node voltages, all starting at 0 V.
struct Reference {
    g: f64,
    c: f64,
    v: Vec<f64>,
    t: f64,
}

impl Reference {
    fn new(n: usize) -> Self {
        Reference {
            g: n as f64 / R_TOTAL,
            c: C_TOTAL / n as f64,
            v: vec![0.0; n],
            t: 0.0,
        }
    }

    fn slope(&self, v: &[f64], out: &mut [f64]) {
        let n = v.len();
        for k in 0..n {
            let left = if k == 0 { 1.0 } else { v[k - 1] };
            let mut i = self.g * (left - v[k]);
            if k + 1 < n {
                i -= self.g * (v[k] - v[k + 1]);
            }
            out[k] = i / self.c;
        }
    }

    fn rk4_step(&mut self, h: f64) {
        let n = self.v.len();
        let (mut k1, mut k2, mut k3, mut k4) =
            (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        let shifted = |k: &[f64], a: f64| -> Vec<f64> {
            self.v.iter().zip(k).map(|(v, d)| v + a * d).collect()
        };
        self.slope(&self.v, &mut k1);
        self.slope(&shifted(&k1, h / 2.0), &mut k2);
        self.slope(&shifted(&k2, h / 2.0), &mut k3);
        self.slope(&shifted(&k3, h), &mut k4);
        for i in 0..n {
            self.v[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
        self.t += h;
    }

    /// Advances to `t` in steps of at most `h`; returns the last node's voltage.
    fn output_at(&mut self, t: f64, h: f64) -> f64 {
        while self.t < t {
            let step = h.min(t - self.t);
            self.rk4_step(step);
        }
        self.v[self.v.len() - 1]
    }
}

fn simulate_ladder(keep_unknowns: bool) -> vams::waveform::Waveforms {
    simulate_ladder_with(SECTIONS, None, keep_unknowns)
}

fn ladder_design(sections: usize) -> vams::design::Design {
    let path = format!(
        "{}/tests/simulate/rc_ladder.vhd",
        env!("CARGO_MANIFEST_DIR")
    );
    let loaded = load(&[PathBuf::from(path)]).expect("ladder model exists");
    assert_eq!(loaded.error_count(), 0, "{:?}", loaded.syntax_errors);
    let options = ElabOptions {
        top: "rc_ladder".into(),
        generics: vec![("n".into(), sections.to_string())],
    };
    elaborate(&loaded.sources, &loaded.files, &options).expect("ladder elaborates")
}

/// The ladder's equations are affine, so Newton may stop after one step with a fresh
/// Jacobian (`DaeSystem::is_linear`); a diode makes a circuit not so.
#[test]
fn the_ladder_is_affine() {
    assert!(
        AnalogSystem::new(&ladder_design(5))
            .expect("builds")
            .is_linear()
    );
}

fn simulate_ladder_with(
    sections: usize,
    abstol: Option<f64>,
    keep_unknowns: bool,
) -> vams::waveform::Waveforms {
    let design = ladder_design(sections);
    let sim = SimOptions {
        stop: STOP,
        reltol: 1e-4,
        abstol,
        probes: vec!["v_out".into(), "i_in".into()],
        keep_unknowns,
        ..SimOptions::default()
    };
    let result = simulate(&design, &sim, &mut |_| {}).expect("ladder simulates");
    assert_eq!(result.outcome, Outcome::Finished);
    result.waveforms
}

/// Checks the output node against RK4 within 1 mV, and the source current (an eliminated
/// quantity unless `keep_unknowns`) within 1e-3 of its 50 mA full scale.
fn check_against_rk4(keep_unknowns: bool) {
    let w = simulate_ladder(keep_unknowns);
    let v_out = &w.column("v_out").expect("v_out recorded").values;
    let i_in = &w.column("i_in").expect("i_in recorded").values;
    assert!(w.times.len() > 20, "too few samples: {}", w.times.len());

    // Largest eigenvalue of the ladder about 4 g / c = 1e7 /s: RK4 is stable below 2.8e-7 s
    // and its error at 2e-8 s is far below the tolerance checked here.
    let mut reference = Reference::new(SECTIONS);
    let full_scale = reference.g;
    let mut worst = (0.0_f64, 0.0);
    for ((&t, &v), &i) in w.times.iter().zip(v_out).zip(i_in) {
        let exact = reference.output_at(t, 2e-8);
        let err = (v - exact).abs();
        if err > worst.0 {
            worst = (err, t);
        }
        assert!(err < 1e-3, "t = {t}: v_out = {v}, RK4 {exact}");
        // The source delivers the first resistor's current (i_in flows from the node into
        // the source, hence the sign).
        let i_exact = -reference.g * (1.0 - reference.v[0]);
        if t > 0.0 {
            assert!(
                (i - i_exact).abs() < 1e-3 * full_scale,
                "t = {t}: i_in = {i}, RK4 {i_exact}"
            );
        }
    }
    // The comparison is not vacuous: the output rises through the whole range.
    assert!(w.value_at("v_out", 0.05e-3).expect("sample") < 0.01);
    assert!(v_out[v_out.len() - 1] > 0.99);
    eprintln!(
        "{} samples; largest difference {:.2e} V at t = {:.3e} s",
        w.times.len(),
        worst.0,
        worst.1
    );
}

#[test]
fn fifty_section_ladder_matches_rk4_within_a_millivolt() {
    check_against_rk4(false);
}

/// The same with every unknown kept: elimination must not change the answer.
#[test]
fn fifty_section_ladder_matches_rk4_with_every_unknown_kept() {
    check_against_rk4(true);
}

/// A tight absolute tolerance on a long ladder: the first capacitor starts at 0 V with a slope
/// of 1e9 V/s, and the first step the slope rule proposes (1e-21 s) is below what the time
/// axis resolves; the run must start anyway and reach the same end value.
#[test]
fn a_tight_abstol_on_a_stiff_start_still_runs() {
    let w = simulate_ladder_with(100, Some(1e-12), false);
    let v_out = &w.column("v_out").expect("v_out recorded").values;
    let reference = Reference::new(100).output_at(STOP, 5e-8);
    let last = v_out[v_out.len() - 1];
    assert!(
        (last - reference).abs() < 1e-3,
        "v_out {last}, RK4 {reference}"
    );
}

/// Sections of 2.5 Ohm and 2.5 nF (N = 400): the elimination keeps one capacitor voltage per
/// section and the source's current (solving the first balance for it would magnify the
/// voltages' errors 4e5 times in its tolerance), and each balance reads its neighbours only. A test of how well an elimination is
/// conditioned once refused to solve `v == r * i` for a small resistor's current, and the node
/// potentials became sums over the whole line: N^2 Jacobian entries, 122 s to build at N = 1000.
#[test]
fn a_fine_ladder_reduces_to_one_unknown_per_section_with_sparse_rows() {
    let n = 400;
    let system = AnalogSystem::new(&ladder_design(n)).expect("builds");
    assert_eq!(system.len(), n + 1, "{:?}", &system.unknown_names()[..3]);
    assert!(
        system.pattern().len() <= 3 * n,
        "{} Jacobian entries for {n} unknowns",
        system.pattern().len()
    );
}
