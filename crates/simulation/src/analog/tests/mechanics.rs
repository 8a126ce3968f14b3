//! The headlight servo's structures: two inductors in series (motor armature and wiring
//! harness: KCL ties two differentiated currents) and inertias rigidly coupled by a gear (both
//! speeds differentiated, `v = ratio * w`). Both have index 2, integrated as written (index
//! reduction starts at 3). With every differential unknown held, the integrator's
//! initialisation is singular on both; these check that it recovers and that BDF stays
//! accurate.

use super::fixture::*;
use vams_design::NatureId;
use vams_solver::DaeSystem;

#[test]
fn series_inductors_follow_the_combined_time_constant() {
    let (r1, l1, r2, l2, v) = (4.0, 3e-3, 0.1, 3.75e-6, 11.0);
    let mut b = Builder::new();
    let el = NatureId(0);
    let gnd = b.ground(el);
    let [a, m, n] = ["a", "m", "n"].map(|name| b.terminal(name, el));
    let (vs, _) = b.branch("vs", "is", a, gnd);
    b.equation("vs == 11.0;", q(vs), c(v));
    // The motor's armature: `v1 == r1 * i1 + l1 * i1'dot`.
    let (v1, i1) = b.branch("v1", "i1", a, m);
    b.equation(
        "v1 == 4.0 * i1 + 3.0e-3 * i1'dot;",
        q(v1),
        add(mul(c(r1), q(i1)), mul(c(l1), dot(i1))),
    );
    // The harness: `v2 == r2 * i2 + l2 * i2'dot`, then a short to ground through `n`.
    let (v2, i2) = b.branch("v2", "i2", m, n);
    b.equation(
        "v2 == 0.1 * i2 + 3.75e-6 * i2'dot;",
        q(v2),
        add(mul(c(r2), q(i2)), mul(c(l2), dot(i2))),
    );
    let (vw, _) = b.branch("vw", "iw", n, gnd);
    b.equation("vw == 0.0;", q(vw), c(0.0));
    let (d, _) = b.finish();
    let mut sys = system(&d);
    let (s1, s2) = (
        sys.quantity_slot(i1).expect("kept"),
        sys.quantity_slot(i2).expect("kept"),
    );
    assert!(sys.differential()[s1] && sys.differential()[s2]);
    let tau = (l1 + l2) / (r1 + r2);
    let times = [0.1 * tau, 0.5 * tau, tau, 3.0 * tau, 6.0 * tau];
    // `break i1 => 0` as the motor has it; the harness current follows from KCL.
    let states = simulate(&mut sys, &[(s1, 0.0)], 1e-4, &times);
    for (t, x) in times.iter().zip(&states) {
        let exact = v / (r1 + r2) * (1.0 - (-t / tau).exp());
        for s in [s1, s2] {
            let rel = (x[s] - exact).abs() / exact;
            assert!(
                rel < 1e-3,
                "t = {t:e}: {} = {} vs {exact} (rel {rel:e})",
                sys.unknown_names()[s],
                x[s]
            );
        }
    }
}

#[test]
fn gear_coupled_inertia_and_spring_mass_oscillate_at_the_closed_form_frequency() {
    let (j, ratio, mass, k, x0) = (1e-3, 0.1, 0.5, 100.0, 0.01);
    let mut b = Builder::new();
    let rot = b.nature("rotational_v", "DEFAULT_ANGULAR_VELOCITY", "DEFAULT_TORQUE");
    let tr = b.nature("translational_v", "DEFAULT_VELOCITY", "DEFAULT_FORCE");
    let (rot_ref, tr_ref) = (b.ground(rot), b.ground(tr));
    let shaft = b.terminal("shaft", rot);
    let rack = b.terminal("rack", tr);
    // Motor inertia: torque = j * w'dot.
    let (w, t_m) = b.branch("w", "t_m", shaft, rot_ref);
    b.equation("t_m == 1.0e-3 * w'dot;", q(t_m), mul(c(j), dot(w)));
    // The gear: `v_g == ratio * w_g; tau == -ratio * f`.
    let (w_g, tau) = b.branch("w_g", "tau", shaft, rot_ref);
    let (v_g, f) = b.branch("v_g", "f", rack, tr_ref);
    b.equation("v_g == 0.1 * w_g;", q(v_g), mul(c(ratio), q(w_g)));
    b.equation("tau == -0.1 * f;", q(tau), mul(c(-ratio), q(f)));
    // The reflector mass: f_m == mass * v_m'dot.
    let (v_m, f_m) = b.branch("v_m", "f_m", rack, tr_ref);
    b.equation("f_m == 0.5 * v_m'dot;", q(f_m), mul(c(mass), dot(v_m)));
    // The spring: f_s == k * x, x'dot == v_s.
    let (v_s, f_s) = b.branch("v_s", "f_s", rack, tr_ref);
    let x = b.free("x");
    b.equation("x'dot == v_s;", dot(x), q(v_s));
    b.equation("f_s == 100.0 * x;", q(f_s), mul(c(k), q(x)));
    let (d, _) = b.finish();
    let mut sys = system(&d);
    let (sw, sv, sx) = (
        sys.quantity_slot(w).expect("kept"),
        sys.quantity_slot(v_m).expect("kept"),
        sys.quantity_slot(x).expect("kept"),
    );
    assert!(sys.differential()[sx] && sys.differential()[sw] && sys.differential()[sv]);

    // x'' = -k x / (mass + j / ratio^2).
    let omega = (k / (mass + j / (ratio * ratio))).sqrt();
    let period = 2.0 * std::f64::consts::PI / omega;
    let dt = period / 400.0;
    let times: Vec<f64> = (1..=1200).map(|i| i as f64 * dt).collect();
    let states = simulate(&mut sys, &[(sw, 0.0), (sx, x0)], 1e-4, &times);
    let xs: Vec<f64> = states.iter().map(|s| s[sx]).collect();
    // The trajectory over three periods (BDF2's phase and damping errors accumulate: 1% of
    // the amplitude at reltol 1e-4).
    for (t, xv) in times.iter().zip(&xs) {
        let exact = x0 * (omega * t).cos();
        assert!(
            (xv - exact).abs() < 1e-2 * x0,
            "t = {t}: x = {xv} vs {exact}"
        );
    }
    // Downward zero crossings, linearly interpolated: the period from the first to the last.
    let crossings: Vec<f64> = (1..xs.len())
        .filter(|&i| xs[i - 1] > 0.0 && xs[i] <= 0.0)
        .map(|i| times[i - 1] + dt * xs[i - 1] / (xs[i - 1] - xs[i]))
        .collect();
    assert_eq!(crossings.len(), 3);
    let measured = (crossings[2] - crossings[0]) / 2.0;
    let rel = (measured - period).abs() / period;
    assert!(rel < 1e-3, "period {measured} vs {period} (rel {rel:e})");
}

/// The headlight drive as the models wire it: battery, wiring harness, DC motor
/// (`models/dc_motor.vhd`), rack-and-pinion gear, reflector mass; both structures above at
/// once. The steady speed has a closed form: `V = (r + r_line) i + ke w`, `kt i = d w`.
#[test]
fn headlight_drive_reaches_the_closed_form_steady_speed() {
    let (v_bat, r_line, l_line) = (11.0, 0.1, 3.75e-6);
    let (r, l, kt, ke, d, j) = (4.0, 3e-3, 0.015, 0.015, 1.5e-6, 1e-6);
    let (ratio, mass) = (2e-3, 0.5);
    let mut b = Builder::new();
    let el = NatureId(0);
    let rot = b.nature("rotational_v", "DEFAULT_ANGULAR_VELOCITY", "DEFAULT_TORQUE");
    let tr = b.nature("translational_v", "DEFAULT_VELOCITY", "DEFAULT_FORCE");
    let (gnd, rot_ref, tr_ref) = (b.ground(el), b.ground(rot), b.ground(tr));
    let [bat, m] = ["bat", "m"].map(|n| b.terminal(n, el));
    let shaft = b.terminal("shaft", rot);
    let rack = b.terminal("rack", tr);
    let (vb, _) = b.branch("vb", "ib", bat, gnd);
    b.equation("vb == 11.0;", q(vb), c(v_bat));
    let (vh, ih) = b.branch("vh", "ih", bat, m);
    b.equation(
        "vh == r_line * ih + l_line * ih'dot;",
        q(vh),
        add(mul(c(r_line), q(ih)), mul(c(l_line), dot(ih))),
    );
    let (vm, im) = b.branch("vm", "im", m, gnd);
    let (w, t) = b.branch("w", "t", shaft, rot_ref);
    b.equation(
        "v == ke * w + r * i + l * i'dot;",
        q(vm),
        add(add(mul(c(ke), q(w)), mul(c(r), q(im))), mul(c(l), dot(im))),
    );
    b.equation(
        "t == j * w'dot + d * w - kt * i;",
        q(t),
        sub(add(mul(c(j), dot(w)), mul(c(d), q(w))), mul(c(kt), q(im))),
    );
    let (wg, tau) = b.branch("wg", "tau", shaft, rot_ref);
    let (vg, f) = b.branch("vg", "f", rack, tr_ref);
    b.equation("v == ratio * w;", q(vg), mul(c(ratio), q(wg)));
    b.equation("tau == -ratio * f;", q(tau), mul(c(-ratio), q(f)));
    let (vr, fr) = b.branch("vr", "fr", rack, tr_ref);
    b.equation("f == m * v'dot;", q(fr), mul(c(mass), dot(vr)));
    let (design, _) = b.finish();
    let mut sys = system(&design);
    let (si, sw, sv) = (
        sys.quantity_slot(im).expect("kept"),
        sys.quantity_slot(w).expect("kept"),
        sys.quantity_slot(vr).expect("kept"),
    );
    // `break i => 0, w => 0` as the motor model does.
    let states = simulate(&mut sys, &[(si, 0.0), (sw, 0.0)], 1e-4, &[1.0]);
    let x = &states[0];
    let w_ss = kt * v_bat / (ke * kt + d * (r + r_line));
    let i_ss = d * w_ss / kt;
    let close = |got: f64, want: f64| (got - want).abs() <= 1e-3 * want.abs();
    assert!(close(x[sw], w_ss), "w = {} vs {w_ss}", x[sw]);
    assert!(
        close(x[sv], ratio * w_ss),
        "v = {} vs {}",
        x[sv],
        ratio * w_ss
    );
    assert!(close(x[si], i_ss), "i = {} vs {i_ss}", x[si]);
    assert!(close(x[sys.quantity_slot(ih).expect("kept")], i_ss));
}
