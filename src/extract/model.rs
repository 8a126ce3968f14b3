//! The brushed DC motor's equations, and the four bench experiments simulated with them.
//!
//! Takes motor parameters and a measured terminal voltage; gives the simulated current and
//! speed at the capture's sample times. It is the same law as the `dc_motor` model:
//!
//! ```text
//! V = Ke*w + R*i + L*di/dt
//! J*dw/dt = Kt*i - D*w - Tcst_motor*tanh(w/OMEGA_EPS)
//! ```
//!
//! Constant friction is smoothed by `tanh(w/OMEGA_EPS)` with `OMEGA_EPS` = 0.5 rad/s (about
//! 5 rpm, far below any speed the captures resolve). It never reads files and never fits.

/// The velocity scale of the smoothed constant friction, rad/s.
pub const OMEGA_EPS: f64 = 0.5;

/// Parameters of the motor, SI units; names as the `dc_motor` generics.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotorParams {
    /// Armature resistance, ohm.
    pub r: f64,
    /// Armature inductance, H.
    pub l: f64,
    /// Back-EMF constant, V s/rad.
    pub ke: f64,
    /// Torque constant, N m/A.
    pub kt: f64,
    /// Rotor moment of inertia, kg m^2.
    pub j: f64,
    /// Viscous damping, N m s/rad.
    pub d: f64,
    /// Constant (Coulomb) friction torque of the motor, N m.
    pub tcst_motor: f64,
}

impl MotorParams {
    /// The generic names in the order of [`MotorParams::values`].
    pub const NAMES: [&'static str; 7] = ["r", "l", "ke", "kt", "j", "d", "tcst_motor"];

    /// The values in the order of [`MotorParams::NAMES`].
    pub fn values(&self) -> [f64; 7] {
        [
            self.r,
            self.l,
            self.ke,
            self.kt,
            self.j,
            self.d,
            self.tcst_motor,
        ]
    }

    /// A plausible 12 V leveling-actuator motor (used by the demo captures and the tests).
    pub fn example() -> Self {
        MotorParams {
            r: 8.0,
            l: 4.0e-3,
            ke: 0.015,
            kt: 0.015,
            j: 1.0e-6,
            d: 5.0e-7,
            tcst_motor: 3.0e-4,
        }
    }

    /// Friction torque at speed `w`.
    pub fn friction(&self, w: f64) -> f64 {
        self.d * w + self.tcst_motor * (w / OMEGA_EPS).tanh()
    }

    /// Steady speed and current under a constant voltage `v` (no load).
    pub fn steady_state(&self, v: f64) -> (f64, f64) {
        // Kt*i = D*w + Tcst and v = Ke*w + R*i, for w > 0.
        let w = (v - self.r * self.tcst_motor / self.kt) / (self.ke + self.r * self.d / self.kt);
        let w = w.max(0.0);
        (w, self.friction(w) / self.kt)
    }
}

/// Substeps per sample interval at most: bounds the work for absurd trial parameters (the
/// fit then sees a poor or non-finite residual and rejects the step).
const MAX_SUBSTEPS: usize = 256;

/// The largest integration step for these parameters: a quarter of the fastest time constant.
fn max_step(p: &MotorParams) -> f64 {
    let electrical = p.l / p.r;
    let friction = p.j * OMEGA_EPS / p.tcst_motor.max(1e-30);
    let viscous = p.j / p.d.max(1e-30);
    0.25 * electrical.min(friction).min(viscous)
}

fn rk4(x: [f64; 2], h: f64, f: impl Fn(f64, [f64; 2]) -> [f64; 2]) -> [f64; 2] {
    let add = |a: [f64; 2], b: [f64; 2], s: f64| [a[0] + s * b[0], a[1] + s * b[1]];
    let k1 = f(0.0, x);
    let k2 = f(0.5, add(x, k1, 0.5 * h));
    let k3 = f(0.5, add(x, k2, 0.5 * h));
    let k4 = f(1.0, add(x, k3, h));
    [
        x[0] + h / 6.0 * (k1[0] + 2.0 * k2[0] + 2.0 * k3[0] + k4[0]),
        x[1] + h / 6.0 * (k1[1] + 2.0 * k2[1] + 2.0 * k3[1] + k4[1]),
    ]
}

/// Simulates the motor driven by the terminal voltage `v` sampled at `t` (linear between
/// samples), from current `i0` and speed `w0`. With `blocked` the rotor is held (w = 0).
/// Returns current and speed at each sample time.
pub fn simulate_driven(
    p: &MotorParams,
    t: &[f64],
    v: &[f64],
    i0: f64,
    w0: f64,
    blocked: bool,
) -> (Vec<f64>, Vec<f64>) {
    let n = t.len().min(v.len());
    let mut cur = Vec::with_capacity(n);
    let mut spd = Vec::with_capacity(n);
    let mut x = [i0, if blocked { 0.0 } else { w0 }];
    let hmax = max_step(p);
    for k in 0..n {
        if k > 0 {
            let dt = t[k] - t[k - 1];
            let steps = ((dt / hmax).ceil() as usize).clamp(1, MAX_SUBSTEPS);
            let h = dt / steps as f64;
            for s in 0..steps {
                let (va, vb) = (v[k - 1], v[k]);
                let f0 = s as f64 / steps as f64;
                x = rk4(x, h, |frac, [i, w]| {
                    let a = f0 + frac / steps as f64;
                    let vin = va + (vb - va) * a;
                    let di = (vin - p.ke * w - p.r * i) / p.l;
                    let dw = if blocked {
                        0.0
                    } else {
                        (p.kt * i - p.friction(w)) / p.j
                    };
                    [di, dw]
                });
            }
        }
        cur.push(x[0]);
        spd.push(x[1]);
    }
    (cur, spd)
}

/// Simulates the coasting rotor (i = 0) from speed `w0` at `t[0]`; returns the speed at `t`.
pub fn simulate_coast(p: &MotorParams, t: &[f64], w0: f64) -> Vec<f64> {
    let mut out = Vec::with_capacity(t.len());
    let mut x = [0.0, w0];
    let friction = p.j * OMEGA_EPS / p.tcst_motor.max(1e-30);
    let hmax = 0.25 * friction.min(p.j / p.d.max(1e-30));
    for k in 0..t.len() {
        if k > 0 {
            let dt = t[k] - t[k - 1];
            let steps = ((dt / hmax).ceil() as usize).clamp(1, MAX_SUBSTEPS);
            let h = dt / steps as f64;
            for _ in 0..steps {
                x = rk4(x, h, |_, [_, w]| [0.0, -p.friction(w) / p.j]);
            }
        }
        out.push(x[1]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocked_rotor_reaches_ohms_law() {
        let p = MotorParams::example();
        let t: Vec<f64> = (0..2000).map(|k| k as f64 * 1e-5).collect();
        let v = vec![10.0; t.len()];
        let (i, _) = simulate_driven(&p, &t, &v, 0.0, 0.0, true);
        let tau = p.l / p.r;
        // i(t) = V/R (1 - exp(-t/tau)) in closed form.
        for k in [10, 100, 1999] {
            let exact = 10.0 / p.r * (1.0 - (-t[k] / tau).exp());
            assert!((i[k] - exact).abs() < 1e-6, "{} vs {exact}", i[k]);
        }
    }

    #[test]
    fn run_up_settles_at_the_steady_state() {
        let p = MotorParams::example();
        let t: Vec<f64> = (0..4000).map(|k| k as f64 * 1e-4).collect();
        let v = vec![10.5; t.len()];
        let (i, w) = simulate_driven(&p, &t, &v, 0.0, 0.0, false);
        let (ws, is) = p.steady_state(10.5);
        assert!((w[3999] - ws).abs() / ws < 1e-3);
        assert!((i[3999] - is).abs() / is < 1e-2);
    }

    #[test]
    fn coast_without_viscous_damping_is_a_straight_line() {
        let p = MotorParams {
            d: 0.0,
            ..MotorParams::example()
        };
        let t: Vec<f64> = (0..1000).map(|k| k as f64 * 1e-3).collect();
        let w = simulate_coast(&p, &t, 200.0);
        let decel = p.tcst_motor / p.j;
        // Until the rotor nears standstill, w = w0 - (Tcst/J) t.
        assert!((w[300] - (200.0 - decel * 0.3)).abs() < 1e-6);
        assert!(w[999].abs() < 1e-3);
    }
}
