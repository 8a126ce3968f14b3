//! The history behind `Q'delayed(T)`: the input's accepted values and derivatives, and the
//! value `T` seconds ago by cubic Hermite interpolation between accepted points (the same
//! dense output the integrator's own steps are accurate to).
//!
//! The kernel records every accepted point; the step is limited to the shortest delay, so
//! `t - T` never passes the last accepted point while Newton iterates (no extrapolation
//! except within one step of a restart). Before the first point the history is the
//! quiescent value. Points older than the delay window are dropped.

use std::collections::VecDeque;

/// One delayed quantity's history.
#[derive(Clone, Debug)]
pub struct DelayLine {
    /// Unknown slot of the input quantity.
    pub input: usize,
    /// Seconds.
    pub delay: f64,
    /// Accepted `(t, x, x')`, times non-decreasing (two points may share a time at a
    /// discontinuity: the later is the value after it).
    points: VecDeque<(f64, f64, f64)>,
}

impl DelayLine {
    pub fn new(input: usize, delay: f64) -> DelayLine {
        DelayLine {
            input,
            delay,
            points: VecDeque::new(),
        }
    }

    /// Records an accepted point; a point earlier than the last (a restart from an earlier
    /// time) replaces the history after it.
    pub fn record(&mut self, t: f64, x: f64, xdot: f64) {
        while self.points.back().is_some_and(|&(tb, _, _)| tb > t) {
            self.points.pop_back();
        }
        self.points.push_back((t, x, xdot));
        // Keep one point at or before the oldest time still needed.
        let horizon = t - self.delay;
        while self.points.len() > 2 && self.points[1].0 <= horizon {
            self.points.pop_front();
        }
    }

    /// Copies `other`'s recorded points (the same quantity and delay, its input in another
    /// slot of a rebuilt system).
    pub fn copy_history(&mut self, other: &DelayLine) {
        debug_assert_eq!(self.delay, other.delay);
        self.points.clone_from(&other.points);
    }

    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// The input's value at time `tau` (NaN without history).
    pub fn value_at(&self, tau: f64) -> f64 {
        let Some(&(t0, x0, _)) = self.points.front() else {
            return f64::NAN;
        };
        if tau <= t0 {
            return x0;
        }
        // Last point at or before tau (after a discontinuity: the value after it).
        let k = self.points.partition_point(|&(t, _, _)| t <= tau) - 1;
        let (ta, xa, da) = self.points[k];
        match self.points.get(k + 1) {
            Some(&(tb, xb, db)) if tb > ta => hermite(ta, xa, da, tb, xb, db, tau),
            // Past the last point: its tangent.
            _ => xa + da * (tau - ta),
        }
    }
}

/// Cubic Hermite interpolation on `[ta, tb]` from values and slopes at both ends.
fn hermite(ta: f64, xa: f64, da: f64, tb: f64, xb: f64, db: f64, tau: f64) -> f64 {
    let h = tb - ta;
    let s = (tau - ta) / h;
    let (s2, s3) = (s * s, s * s * s);
    let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
    let h10 = s3 - 2.0 * s2 + s;
    let h01 = -2.0 * s3 + 3.0 * s2;
    let h11 = s3 - s2;
    h00 * xa + h10 * h * da + h01 * xb + h11 * h * db
}

/// Signal-slot layout after the design's signals: the source scale, then the "history
/// ready" flag (0 at the quiescent point, where `Q'delayed(T) = Q`), then the "time runs"
/// flag (0 while the quiescent point is solved, where time stands still: the explicit time
/// derivative of a differentiated equation vanishes there), then one slot per line holding
/// its delayed value at the time being evaluated.
pub fn ready_slot(design_signals: usize) -> usize {
    design_signals + 1
}

pub fn time_slot(design_signals: usize) -> usize {
    design_signals + 2
}

pub fn history_slot(design_signals: usize, line: usize) -> usize {
    design_signals + 3 + line
}

#[cfg(test)]
mod tests {
    use super::DelayLine;

    #[test]
    fn hermite_is_exact_on_cubics() {
        let f = |t: f64| 2.0 * t * t * t - t * t + 3.0 * t - 1.0;
        let df = |t: f64| 6.0 * t * t - 2.0 * t + 3.0;
        let mut line = DelayLine::new(0, 10.0);
        for t in [0.0, 0.3, 1.0] {
            line.record(t, f(t), df(t));
        }
        for tau in [0.1, 0.25, 0.5, 0.9] {
            assert!((line.value_at(tau) - f(tau)).abs() < 1e-12, "tau = {tau}");
        }
    }

    #[test]
    fn before_the_first_point_is_the_first_value() {
        let mut line = DelayLine::new(0, 1.0);
        assert!(line.value_at(0.0).is_nan());
        line.record(0.0, 4.0, 1.0);
        assert_eq!(line.value_at(-0.5), 4.0);
    }

    #[test]
    fn discontinuities_keep_the_value_after() {
        let mut line = DelayLine::new(0, 5.0);
        line.record(0.0, 0.0, 0.0);
        line.record(1.0, 0.0, 0.0);
        line.record(1.0, 5.0, 0.0);
        line.record(2.0, 5.0, 0.0);
        assert_eq!(line.value_at(0.5), 0.0);
        assert_eq!(line.value_at(1.5), 5.0);
    }

    #[test]
    fn old_points_are_dropped_and_restarts_replace_the_future() {
        let mut line = DelayLine::new(0, 1.0);
        for k in 0..100 {
            let t = k as f64 * 0.1;
            line.record(t, t, 1.0);
        }
        assert!(line.points.len() <= 13, "kept {}", line.points.len());
        assert!((line.value_at(9.0) - 9.0).abs() < 1e-12);
        line.record(9.5, 0.0, 0.0);
        assert_eq!(line.points.back().map(|p| p.0), Some(9.5));
        assert!(line.points.iter().all(|p| p.0 <= 9.5));
    }
}
