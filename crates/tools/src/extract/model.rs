//! The parameters of a brushed DC motor, and the two closed forms the paper's method and the
//! synthetic captures need (the friction torque, the no-load steady state). The motor's
//! dynamics are simulated by the `dc_motor` model itself (`vams extract` fits it); the law:
//!
//! ```text
//! V = Ke*w + R*i + L*di/dt
//! J*dw/dt = Kt*i - D*w - Tcst_motor*tanh(w/OMEGA_EPS)
//! ```
//!
//! Constant friction is smoothed by `tanh(w/OMEGA_EPS)` with `OMEGA_EPS` = 0.5 rad/s (about
//! 5 rpm, far below any speed the captures resolve), as `constant_friction`'s `w_s` on the
//! extraction's bench. It never reads files and never fits.

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
