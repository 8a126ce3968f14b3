//! Piecewise-linear tables: `vams.tables.pwl(table, x)`, the function a testbench uses to
//! drive a quantity from measured or tabulated data (`vams fit --drive` fills such a table
//! from a capture's column).
//!
//! A table is a flat list of `x0, y0, x1, y1, ...` pairs, as SPICE's PWL source writes them,
//! with `x` increasing: the value is linear between neighbouring points and constant beyond
//! the ends, so it is continuous (a jump is a steep segment: an integrator cannot step
//! across a jump in an equation without a `break`, and the corners of a table of `now` are
//! its breakpoints). One definition of the rules for elaboration (checks and folding), the
//! analog tape and the event kernel.

/// Why a table cannot be one.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TableError {
    #[error("a table needs x, y pairs, but it has {0} element(s), an odd number")]
    Odd(usize),
    #[error("a table needs at least one x, y pair, but it is empty")]
    Empty,
    #[error("element {0} of the table is not a finite number")]
    NotFinite(usize),
    #[error("the table's x values must increase, but x = {next} follows x = {prev} (pair {pair})")]
    NotIncreasing { pair: usize, prev: f64, next: f64 },
}

impl TableError {
    /// How to fix a table.
    pub const HELP: &'static str = "write the table as (x0, y0, x1, y1, ...) with x0 < x1 < ...: `pwl((0.0, 0.0, 1.0e-3, 5.0), now)`; a jump is a steep segment (1.0e-3, 0.0, 1.001e-3, 5.0)";
}

/// A checked table.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    xs: Vec<f64>,
    ys: Vec<f64>,
}

impl Table {
    /// The table of the flat pairs `flat`, checked.
    pub fn new(flat: &[f64]) -> Result<Table, TableError> {
        check(flat.len(), |k| flat[k])?;
        Ok(Table {
            xs: flat.iter().step_by(2).copied().collect(),
            ys: flat.iter().skip(1).step_by(2).copied().collect(),
        })
    }

    /// The x values, increasing.
    pub fn xs(&self) -> &[f64] {
        &self.xs
    }

    /// The number of points.
    pub fn len(&self) -> usize {
        self.xs.len()
    }

    /// Whether the table has no point (never, for a checked table).
    pub fn is_empty(&self) -> bool {
        self.xs.is_empty()
    }

    /// The value at `x`.
    pub fn value(&self, x: f64) -> f64 {
        lookup(self.xs.len(), |k| (self.xs[k], self.ys[k]), x).0
    }

    /// The slope at `x` (zero beyond the ends; the right segment's at a point).
    pub fn slope(&self, x: f64) -> f64 {
        lookup(self.xs.len(), |k| (self.xs[k], self.ys[k]), x).1
    }
}

/// Checks a table of `len` flat elements, element `k` given by `at`.
pub fn check(len: usize, at: impl Fn(usize) -> f64) -> Result<(), TableError> {
    if len == 0 {
        return Err(TableError::Empty);
    }
    if len % 2 == 1 {
        return Err(TableError::Odd(len));
    }
    if let Some(k) = (0..len).find(|&k| !at(k).is_finite()) {
        return Err(TableError::NotFinite(k));
    }
    for pair in 1..len / 2 {
        let (prev, next) = (at(2 * pair - 2), at(2 * pair));
        if next <= prev {
            return Err(TableError::NotIncreasing { pair, prev, next });
        }
    }
    Ok(())
}

/// The value and slope at `x` of the checked table of `n` points, point `k` given by `point`.
/// A NaN `x` gives NaN (Newton rejects the step).
pub fn lookup(n: usize, point: impl Fn(usize) -> (f64, f64), x: f64) -> (f64, f64) {
    if x.is_nan() || n == 0 {
        return (f64::NAN, f64::NAN);
    }
    // The first point beyond x: x lies in [point(k - 1), point(k)).
    let (mut lo, mut hi) = (0, n);
    while lo < hi {
        let mid = (lo + hi) / 2;
        if point(mid).0 <= x {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    if lo == 0 {
        return (point(0).1, 0.0);
    }
    if lo == n {
        return (point(n - 1).1, 0.0);
    }
    let ((x0, y0), (x1, y1)) = (point(lo - 1), point(lo));
    // x0 <= x < x1.
    let slope = (y1 - y0) / (x1 - x0);
    (y0 + slope * (x - x0), slope)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn linear_between_points_constant_beyond() {
        let t = Table::new(&[0.0, 1.0, 2.0, 3.0, 4.0, -1.0]).unwrap();
        assert_eq!(t.value(-5.0), 1.0);
        assert_eq!(t.value(0.0), 1.0);
        assert_eq!(t.value(1.0), 2.0);
        assert_eq!(t.value(3.0), 1.0);
        assert_eq!(t.value(9.0), -1.0);
        assert_eq!(t.slope(1.0), 1.0);
        assert_eq!(t.slope(3.5), -2.0);
        assert_eq!(t.slope(-1.0), 0.0);
        assert_eq!(t.slope(5.0), 0.0);
        assert!(t.value(f64::NAN).is_nan());
    }

    #[test]
    fn bad_tables_are_refused() {
        assert_eq!(Table::new(&[]), Err(TableError::Empty));
        assert_eq!(Table::new(&[0.0, 1.0, 2.0]), Err(TableError::Odd(3)));
        assert_eq!(
            Table::new(&[0.0, 1.0, f64::INFINITY, 2.0]),
            Err(TableError::NotFinite(2))
        );
        assert!(matches!(
            Table::new(&[0.0, 1.0, 2.0, 2.0, 1.0, 0.0]),
            Err(TableError::NotIncreasing { pair: 2, .. })
        ));
        assert!(matches!(
            Table::new(&[0.0, 1.0, 0.0, 2.0]),
            Err(TableError::NotIncreasing { pair: 1, .. })
        ));
    }

    proptest! {
        /// The slope is the value's derivative away from the points, and the value is
        /// continuous.
        #[test]
        fn slope_is_the_derivative(ys in proptest::collection::vec(-10.0f64..10.0, 2..12), x in -1.0f64..12.0) {
            let flat: Vec<f64> = ys.iter().enumerate().flat_map(|(k, y)| [k as f64, *y]).collect();
            let t = Table::new(&flat).unwrap();
            let h = 1e-7;
            let near_point = (x - x.round()).abs() < 1e-5;
            if !near_point {
                let fd = (t.value(x + h) - t.value(x - h)) / (2.0 * h);
                prop_assert!((fd - t.slope(x)).abs() < 1e-5 * (1.0 + fd.abs()));
            }
            let jump = (t.value(x + 1e-9) - t.value(x - 1e-9)).abs();
            prop_assert!(jump < 1e-6 * 40.0);
        }
    }
}
