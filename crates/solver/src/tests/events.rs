//! Events: roots, breakpoints, restarts, targets.

use super::systems::LinearDae;
use super::transient::opts;
use crate::{Advance, Stats, Transient, TransientOptions};

/// Runs to the first root and returns it.
fn first_root(s: &mut LinearDae, x0: &[f64], o: TransientOptions) -> (Transient, f64, usize, bool) {
    let mut tr = Transient::new(s, 0.0, x0, o).expect("start");
    loop {
        match tr.advance(s, 2.0).expect("step") {
            Advance::Root { t, index, rising } => return (tr, t, index, rising),
            Advance::Reached(_) => panic!("root missed"),
            Advance::StepAccepted(_) => {}
        }
    }
}

/// x' = 2t (x = t^2, which BDF2 and the Hermite interpolant reproduce exactly) crosses 0.25
/// at t = 0.5: the located time is within 1e-9 of it, and the state there within 1e-9.
#[test]
fn root_located_to_1e9() {
    let mut s = LinearDae::rc(1.0, 0.0);
    s.k = vec![vec![0.0]];
    s.ramp = vec![2.0];
    s.roots = vec![(0, 0.25)];
    let (mut tr, t, index, rising) = first_root(&mut s, &[0.0], opts(1e-10, 1e-14));
    assert!((t - 0.5).abs() <= 1e-9, "root at {t}, error {:e}", t - 0.5);
    assert_eq!((index, rising), (0, true));
    assert_eq!(tr.time(), t);
    assert!((tr.state()[0] - 0.25).abs() <= 1e-9);
    // Integration continues past the root to the end without reporting it again.
    loop {
        match tr.advance(&mut s, 2.0).expect("step") {
            Advance::Reached(_) => break,
            Advance::Root { .. } => panic!("root reported twice"),
            Advance::StepAccepted(_) => {}
        }
    }
    assert!((tr.state()[0] - 4.0).abs() < 1e-8);
}

/// x' = -x crosses 0.5 at ln 2: here the located time carries the integration error, so the
/// bound is the global error at reltol 1e-10 (about 1e-7 after ~900 BDF2 steps), not 1e-9.
#[test]
fn root_of_exponential_decay() {
    let mut s = LinearDae::rc(1.0, 0.0);
    s.roots = vec![(0, 0.5)];
    let (tr, t, index, rising) = first_root(&mut s, &[1.0], opts(1e-10, 1e-14));
    assert!(
        (t - 2f64.ln()).abs() <= 2e-7,
        "root at {t}, error {:e}",
        t - 2f64.ln()
    );
    assert_eq!((index, rising), (0, false));
    // The crossing is located on the interpolant far more tightly than that: x(t) = 0.5.
    assert!(
        (tr.state()[0] - 0.5).abs() <= 1e-12,
        "{}",
        tr.state()[0] - 0.5
    );
}

/// Breakpoints and t_out are landed on exactly (bitwise), and dense output at the middle of
/// every step matches the closed form to 2e-5 at reltol 1e-7 (the global error is ~6e-6).
#[test]
fn breakpoints_landed_exactly() {
    let tau = 1e-3;
    let mut s = LinearDae::rc(tau, 1.0);
    let mut tr = Transient::new(&mut s, 0.0, &[0.0], opts(1e-7, 1e-9)).expect("start");
    let bps = [1.234567e-4, 5e-4, 7.000001e-4];
    for b in bps {
        tr.add_breakpoint(b);
    }
    let mut times = Vec::new();
    loop {
        match tr.advance(&mut s, 2e-3).expect("step") {
            Advance::StepAccepted(t) => times.push(t),
            Advance::Reached(t) => {
                times.push(t);
                break;
            }
            Advance::Root { .. } => unreachable!("no roots"),
        }
        let t_prev = times.len().checked_sub(2).map_or(0.0, |k| times[k]);
        let mid = 0.5 * (t_prev + tr.time());
        let mut x = [0.0];
        tr.interpolate(mid, &mut x).expect("inside the last step");
        assert!(
            (x[0] - (1.0 - (-mid / tau).exp())).abs() < 1e-5,
            "dense output at {mid}"
        );
    }
    for b in bps {
        assert!(times.contains(&b), "breakpoint {b} missed: {times:?}");
    }
    assert_eq!(tr.time(), 2e-3);
    assert!(
        tr.interpolate(3e-3, &mut [0.0]).is_err(),
        "outside the last step"
    );
}

/// Restart after a discontinuity: charge to 5 tau, then the source drops to 0 and the
/// capacitor discharges from the restart state; error <= 5e-5 at reltol 1e-6.
#[test]
fn restart_after_discontinuity() {
    let tau = 1e-3;
    let mut s = LinearDae::rc(tau, 1.0);
    let mut tr = Transient::new(&mut s, 0.0, &[0.0], opts(1e-6, 1e-9)).expect("start");
    while tr.advance(&mut s, 5.0 * tau).expect("step") != Advance::Reached(5.0 * tau) {}
    let x1 = tr.state()[0];
    s.b[0] = 0.0;
    tr.restart(&mut s, 5.0 * tau, &[x1]).expect("restart");
    assert_eq!(tr.order(), 1);
    assert!(
        (tr.derivative()[0] + x1 / tau).abs() < 1e-9,
        "x' recomputed after restart"
    );
    loop {
        match tr.advance(&mut s, 10.0 * tau).expect("step") {
            Advance::Reached(_) => break,
            _ => {
                let t = tr.time() - 5.0 * tau;
                assert!((tr.state()[0] - x1 * (-t / tau).exp()).abs() < 5e-5);
            }
        }
    }
}

/// Two root functions crossing at the same instant are both reported there, lowest index
/// first, and the integrator stays put between the two reports.
#[test]
fn simultaneous_roots_are_queued() {
    let mut s = LinearDae::rc(1.0, 0.0);
    s.roots = vec![(0, 0.5), (0, 0.5)];
    let (mut tr, t, index, _) = first_root(&mut s, &[1.0], opts(1e-8, 1e-12));
    assert_eq!(index, 0);
    let second = tr.advance(&mut s, 2.0).expect("queued root");
    assert_eq!(
        second,
        Advance::Root {
            t,
            index: 1,
            rising: false
        }
    );
    assert_eq!(tr.time(), t);
}

/// A t_out or breakpoint within a few ulp of the current time is reached, not an error.
#[test]
fn targets_within_ulps_are_reached() {
    let mut s = LinearDae::rc(1.0, 1.0);
    let mut tr = Transient::new(&mut s, 1.0, &[0.0], TransientOptions::default()).expect("ok");
    let near = 1.0 + 2.0 * f64::EPSILON;
    tr.add_breakpoint(near);
    assert_eq!(
        tr.advance(&mut s, near).expect("reached"),
        Advance::Reached(near)
    );
    tr.add_breakpoint(near * (1.0 + f64::EPSILON));
    assert!(matches!(
        tr.advance(&mut s, 2.0).expect("step"),
        Advance::StepAccepted(_)
    ));
}

/// A switched system: `x0' = (s - x0) / tau` with `s` the mode's source, and an algebraic
/// `x1^3 + x1 = c (1 + 0.01 x0)` whose right side jumps between modes (10 and 0.1), so that a
/// restart from the other mode's `x1` takes Newton several iterations.
struct Switched {
    on: bool,
    /// Whether `mode` says which mode it is in (else the solver sees no modes).
    modes: bool,
    diff: Vec<bool>,
    pattern: Vec<(usize, usize)>,
}

impl Switched {
    fn new(modes: bool) -> Self {
        Self {
            on: true,
            modes,
            diff: vec![true, false],
            pattern: vec![(0, 0), (1, 0), (1, 1)],
        }
    }
    fn source(&self) -> (f64, f64) {
        if self.on { (1.0, 10.0) } else { (0.0, 0.1) }
    }
}

impl crate::DaeSystem for Switched {
    fn len(&self) -> usize {
        2
    }
    fn differential(&self) -> &[bool] {
        &self.diff
    }
    fn pattern(&self) -> &[(usize, usize)] {
        &self.pattern
    }
    fn residual(&mut self, _t: f64, x: &[f64], xdot: &[f64], out: &mut [f64]) {
        let (s, c) = self.source();
        out[0] = 1e-3 * xdot[0] - (s - x[0]);
        out[1] = x[1] * x[1] * x[1] + x[1] - c * (1.0 + 0.01 * x[0]);
    }
    fn jacobian(&mut self, _t: f64, x: &[f64], _xdot: &[f64], alpha: f64, out: &mut [f64]) {
        let (_, c) = self.source();
        out[0] = 1e-3 * alpha + 1.0;
        out[1] = -0.01 * c;
        out[2] = 3.0 * x[1] * x[1] + 1.0;
    }
    fn mode(&self) -> Option<u64> {
        self.modes.then_some(u64::from(self.on))
    }
}

/// Runs 40 half-periods of 0.5 ms, restarting at each switch; returns the final state and
/// the work counters.
fn run_switched(modes: bool) -> (Vec<f64>, Stats) {
    let mut s = Switched::new(modes);
    let x0 = [0.0, 2.0];
    let mut tr = Transient::new(&mut s, 0.0, &x0, opts(1e-6, 1e-9)).expect("start");
    for k in 1..=40 {
        let t = 0.5e-3 * k as f64;
        while tr.advance(&mut s, t).expect("step") != Advance::Reached(t) {}
        s.on = !s.on;
        let x = tr.state().to_vec();
        tr.restart(&mut s, t, &x).expect("restart");
    }
    (tr.state().to_vec(), tr.stats())
}

/// A restart in a mode seen before starts from that mode's last consistent point, and its
/// first step from what the mode's last restart found the first step could be: fewer Newton
/// iterations and fewer points, the same trajectory to the integrator's accuracy (both runs
/// end about 2e-5 of `x0` from the closed form at reltol 1e-6).
#[test]
fn restarts_start_from_the_modes_last_consistent_point() {
    let (with, stats_with) = run_switched(true);
    let (without, stats_without) = run_switched(false);
    // x0 relaxes to 1 in the on mode and to 0 in the off mode, tau = 1 ms, for 0.5 ms each.
    let decay = (-0.5_f64).exp();
    let exact = (0..40).fold(0.0, |x, k| {
        if k % 2 == 0 {
            1.0 + (x - 1.0) * decay
        } else {
            x * decay
        }
    });
    for x in [&with, &without] {
        assert!(
            (x[0] - exact).abs() <= 5e-5 * exact,
            "{x:?} vs x0 = {exact}"
        );
    }
    assert!(
        stats_with.newton_iterations + 40 <= stats_without.newton_iterations,
        "{stats_with:?} with modes, {stats_without:?} without"
    );
    assert!(
        stats_with.accepted_steps < stats_without.accepted_steps && stats_with.rejected_steps == 0,
        "{stats_with:?} with modes, {stats_without:?} without"
    );
    // The last restart (into the on mode) is consistent: x1^3 + x1 = 10 (1 + 0.01 x0).
    let (x0, x1) = (with[0], with[1]);
    assert!((x1 * x1 * x1 + x1 - 10.0 * (1.0 + 0.01 * x0)).abs() < 1e-9);
}
