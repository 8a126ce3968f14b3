//! Consistent initialisation where holding every differential unknown is singular: the
//! implicit-Euler fallback.

use super::systems::LinearDae;
use super::transient::opts;
use crate::Transient;

/// Two inductors in series: unknowns `[i1, i2, vm]`; `L1 i1' + R1 i1 + vm = V`,
/// `L2 i2' + R2 i2 - vm = 0`, `i1 - i2 = 0` (a KCL row of held unknowns only).
fn series_inductors(l1: f64, l2: f64, r1: f64, r2: f64, v: f64) -> LinearDae {
    LinearDae::new(
        vec![vec![l1, 0.0, 0.0], vec![0.0, l2, 0.0], vec![0.0; 3]],
        vec![
            vec![r1, 0.0, 1.0],
            vec![0.0, r2, -1.0],
            vec![1.0, -1.0, 0.0],
        ],
        vec![v, 0.0, 0.0],
    )
}

#[test]
fn series_inductors_start_with_the_combined_slope() {
    let (l1, l2, v) = (3e-3, 1e-3, 2.0);
    let mut sys = series_inductors(l1, l2, 4.0, 1.0, v);
    let tr = Transient::new(&mut sys, 0.0, &[0.0; 3], opts(1e-6, 1e-12)).expect("init");
    let slope = v / (l1 + l2);
    // The fallback's Euler step (1e-8 s here) moves the state by O(h x') and leaves x' with a
    // relative error of O(h R / L).
    for i in 0..2 {
        assert!((tr.derivative()[i] - slope).abs() < 1e-4 * slope);
        assert!(tr.state()[i].abs() < 2e-8 * slope);
    }
    // vm divides the voltage across the inductances: L2 / (L1 + L2) of V.
    assert!((tr.state()[2] - v * l2 / (l1 + l2)).abs() < 1e-6 * v);
}

#[test]
fn inconsistent_held_currents_are_projected_conserving_flux() {
    // i1 = 1, i2 = 0 cannot both hold: the impulse in vm conserves L1 i1 + L2 i2.
    let (l1, l2) = (3e-3, 1e-3);
    let mut sys = series_inductors(l1, l2, 0.0, 0.0, 0.0);
    let tr = Transient::new(&mut sys, 0.0, &[1.0, 0.0, 0.0], opts(1e-6, 1e-12)).expect("init");
    let shared = l1 / (l1 + l2);
    assert!(
        (tr.state()[0] - shared).abs() < 1e-6,
        "i1 = {}",
        tr.state()[0]
    );
    assert!(
        (tr.state()[1] - shared).abs() < 1e-6,
        "i2 = {}",
        tr.state()[1]
    );
    // Without sources or losses the currents stay put after the jump.
    assert!(tr.derivative()[0].abs() < 1e-3 && tr.derivative()[1].abs() < 1e-3);
}

/// Restarts at a consistent state leave it where it is: the fallback's Euler step starts
/// from the held state taken back along its derivative, so a thousand restarts at one
/// instant (a limiter chattering on its threshold, a clock the equations read) do not run
/// the currents ahead. Starting from the held state itself moved them by `h x'` (1e-8 s of
/// the 500 A/s slope) at every restart, 5e-3 A after a thousand.
#[test]
fn restarts_at_a_consistent_state_do_not_move_it() {
    let (l1, l2, v) = (3e-3, 1e-3, 2.0);
    let mut sys = series_inductors(l1, l2, 0.0, 0.0, v);
    let mut tr = Transient::new(&mut sys, 0.0, &[0.0; 3], opts(1e-6, 1e-12)).expect("init");
    tr.advance(&mut sys, 1e-4).expect("step");
    let t = tr.time();
    let before = tr.state().to_vec();
    for _ in 0..1000 {
        let x = tr.state().to_vec();
        tr.restart(&mut sys, t, &x).expect("restart");
    }
    let slope = v / (l1 + l2);
    for (i, (&now, &then)) in tr.state().iter().zip(&before).take(2).enumerate() {
        assert!(
            (now - then).abs() < 1e-9,
            "i{} moved from {then} to {now}",
            i + 1
        );
        assert!((tr.derivative()[i] - slope).abs() < 1e-4 * slope);
    }
}
