//! A recorded column as a function of time: points joined by straight lines, where two points
//! at the same time are a jump (the value before, then after).
//!
//! Quantities are piecewise linear between samples as recorded; a signal holds its value until
//! the next sample, so each of its changes becomes such a before/after pair. The metrics then
//! need one kind of curve only.

/// Points `(time, value)`, times non-decreasing, at least one.
#[derive(Debug)]
pub(super) struct Curve {
    points: Vec<(f64, f64)>,
}

impl Curve {
    /// The curve of `values` sampled at `times` (same length, not empty, non-decreasing):
    /// linear between samples, or held until the next one when `piecewise_constant`.
    pub(super) fn new(times: &[f64], values: &[f64], piecewise_constant: bool) -> Curve {
        let mut points = Vec::with_capacity(times.len());
        for (k, (&t, &v)) in times.iter().zip(values).enumerate() {
            if piecewise_constant && k > 0 {
                let held = values[k - 1];
                if held != v && t > times[k - 1] {
                    points.push((t, held));
                }
            }
            points.push((t, v));
        }
        Curve { points }
    }

    /// The time of the first point.
    pub(super) fn start(&self) -> f64 {
        self.points[0].0
    }

    /// The time of the last point.
    pub(super) fn end(&self) -> f64 {
        self.points[self.points.len() - 1].0
    }

    /// The last point's value.
    pub(super) fn last(&self) -> f64 {
        self.points[self.points.len() - 1].1
    }

    /// The value at `t` within the curve's span: after the jump when `t` is the time of one.
    pub(super) fn value_at(&self, t: f64) -> f64 {
        let k = self.points.partition_point(|p| p.0 <= t);
        if k == 0 {
            return self.points[0].1;
        }
        let (t0, v0) = self.points[k - 1];
        if k == self.points.len() || t0 == t {
            return v0;
        }
        let (t1, v1) = self.points[k];
        v0 + (v1 - v0) * (t - t0) / (t1 - t0)
    }

    /// The points within `[a, b]` (inside the curve's span, `a <= b`), with interpolated
    /// points at `a` and `b` where they fall between samples.
    pub(super) fn window(&self, a: f64, b: f64) -> Vec<(f64, f64)> {
        let pts = &self.points;
        let i = pts.partition_point(|p| p.0 < a);
        let j = pts.partition_point(|p| p.0 <= b);
        let mut out = Vec::with_capacity(j.saturating_sub(i) + 2);
        if i == pts.len() || pts[i].0 > a {
            out.push((a, self.value_at(a)));
        }
        out.extend_from_slice(&pts[i..j]);
        if out.last().is_some_and(|p| p.0 < b) {
            // Between samples j - 1 and j: `b` is inside the span, so sample j exists.
            let (t0, v0) = pts[j - 1];
            let (t1, v1) = pts[j.min(pts.len() - 1)];
            let v = if t1 > t0 {
                v0 + (v1 - v0) * (b - t0) / (t1 - t0)
            } else {
                v0
            };
            out.push((b, v));
        }
        out
    }
}

/// The integral of the piecewise-linear `points` (trapezoids; jumps have no width).
pub(super) fn integral(points: &[(f64, f64)]) -> f64 {
    points
        .windows(2)
        .map(|w| 0.5 * (w[1].0 - w[0].0) * (w[0].1 + w[1].1))
        .sum()
}

/// The integral of the square of the piecewise-linear `points`, exact on each segment.
pub(super) fn integral_of_square(points: &[(f64, f64)]) -> f64 {
    points
        .windows(2)
        .map(|w| {
            let (a, b) = (w[0].1, w[1].1);
            (w[1].0 - w[0].0) * (a * a + a * b + b * b) / 3.0
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn signals_hold_and_jumps_take_the_value_after() {
        let c = Curve::new(&[0.0, 1.0, 2.0], &[0.0, 1.0, 1.0], true);
        assert_eq!(c.value_at(0.5), 0.0);
        assert_eq!(c.value_at(1.0), 1.0);
        assert_eq!(
            c.window(0.5, 1.5),
            vec![(0.5, 0.0), (1.0, 0.0), (1.0, 1.0), (1.5, 1.0)]
        );
        let q = Curve::new(&[0.0, 1.0, 1.0, 2.0], &[0.0, 1.0, 3.0, 3.0], false);
        assert_eq!(q.value_at(0.5), 0.5);
        assert_eq!(q.value_at(1.0), 3.0);
        assert_eq!(q.window(0.0, 1.0), vec![(0.0, 0.0), (1.0, 1.0), (1.0, 3.0)]);
        assert_eq!(integral(&q.window(0.0, 2.0)), 0.5 + 3.0);
        assert_eq!(integral_of_square(&[(0.0, 0.0), (3.0, 3.0)]), 9.0);
    }
}
