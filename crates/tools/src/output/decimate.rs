//! The plot's copy of a run, kept as the rows come in memory that does not grow with the run.
//!
//! A short run is kept whole (up to [`RAW_ROWS`] rows), so that its plot is drawn from every
//! point, as from the in-memory [`vams_simulation::waveform::Waveforms`]. Past that, the rows go into at
//! most [`BINS`] time bins of equal width from time 0, and each bin keeps, per column, its
//! first and last value and its lowest and highest with their times (the M4 reduction of
//! waveform viewers: a line through those four points per pixel column draws what a line
//! through every point draws, so a spike of a single sample stays). When a row falls beyond
//! the last bin, neighbouring bins merge pairwise and the width doubles, so the bins cover
//! the run so far with between half and all of [`BINS`], more than the plot's pixel columns.
//!
//! Takes rows of `f64`; gives a list of points per kept column. Knows nothing of files.

/// Rows kept whole before the copy switches to bins.
pub const RAW_ROWS: usize = 1 << 14;

/// The most bins the copy holds.
pub const BINS: usize = 2048;

/// Per column and bin: first, last, lowest and highest value, with the times of the last two.
#[derive(Clone, Copy, Debug)]
struct Cell {
    first: f64,
    last: f64,
    min: (f64, f64),
    max: (f64, f64),
}

impl Cell {
    fn new(t: f64, v: f64) -> Cell {
        Cell {
            first: v,
            last: v,
            min: (t, v),
            max: (t, v),
        }
    }

    fn add(&mut self, t: f64, v: f64) {
        self.last = v;
        // NaN never wins a comparison; a first NaN gives way to the first number.
        if v < self.min.1 || (self.min.1.is_nan() && !v.is_nan()) {
            self.min = (t, v);
        }
        if v > self.max.1 || (self.max.1.is_nan() && !v.is_nan()) {
            self.max = (t, v);
        }
    }

    /// `self` followed in time by `later`.
    fn merge(&mut self, later: &Cell) {
        self.last = later.last;
        if later.min.1 < self.min.1 || (self.min.1.is_nan() && !later.min.1.is_nan()) {
            self.min = later.min;
        }
        if later.max.1 > self.max.1 || (self.max.1.is_nan() && !later.max.1.is_nan()) {
            self.max = later.max;
        }
    }
}

/// The bins: their width, and per bin its first and last time (`None`: no row in it) and a
/// cell per column (`cells[bin * columns + c]`).
struct Bins {
    width: f64,
    columns: usize,
    times: Vec<Option<(f64, f64)>>,
    cells: Vec<Cell>,
}

/// A bounded copy of the rows of some columns, for a plot.
pub struct Decimator {
    /// The columns kept, as indices into the rows pushed.
    keep: Vec<usize>,
    raw_times: Vec<f64>,
    /// Per kept column, its raw values.
    raw: Vec<Vec<f64>>,
    bins: Option<Bins>,
}

impl Decimator {
    /// Keeps the columns `keep` (indices into each row).
    pub fn new(keep: Vec<usize>) -> Decimator {
        Decimator {
            raw: vec![Vec::new(); keep.len()],
            keep,
            raw_times: Vec::new(),
            bins: None,
        }
    }

    /// Adds a row (times non-decreasing, from 0).
    pub fn push(&mut self, t: f64, row: &[f64]) {
        let value = |c: usize| row.get(c).copied().unwrap_or(f64::NAN);
        match &mut self.bins {
            None => {
                self.raw_times.push(t);
                for (raw, &c) in self.raw.iter_mut().zip(&self.keep) {
                    raw.push(value(c));
                }
                if self.raw_times.len() > RAW_ROWS {
                    self.start_binning();
                }
            }
            Some(bins) => bins.push(t, self.keep.iter().map(|&c| value(c))),
        }
    }

    /// Moves the raw rows into bins: the run so far fills about half of them.
    fn start_binning(&mut self) {
        let span = self.raw_times.last().copied().unwrap_or(0.0);
        let width = if span > 0.0 {
            span / (BINS / 2) as f64
        } else {
            // Every row at time 0 (a run of delta cycles): any width; it doubles as needed.
            1e-15
        };
        let mut bins = Bins {
            width,
            columns: self.keep.len(),
            times: Vec::new(),
            cells: Vec::new(),
        };
        let times = std::mem::take(&mut self.raw_times);
        let raw = std::mem::take(&mut self.raw);
        for (k, &t) in times.iter().enumerate() {
            bins.push(t, raw.iter().map(|values| values[k]));
        }
        self.raw = vec![Vec::new(); self.keep.len()];
        self.bins = Some(bins);
    }

    /// The points of kept column `k` (its position in `keep`): every row of a short run;
    /// of a long one, per bin the first point, the lowest and highest in time order, and the
    /// last, without repeating a point.
    pub fn points(&self, k: usize) -> Vec<(f64, f64)> {
        let Some(bins) = &self.bins else {
            let values = self.raw.get(k).map(Vec::as_slice).unwrap_or(&[]);
            return self
                .raw_times
                .iter()
                .copied()
                .zip(values.iter().copied())
                .collect();
        };
        let columns = self.keep.len();
        let mut out: Vec<(f64, f64)> = Vec::with_capacity(4 * bins.times.len());
        let mut add = |p: (f64, f64)| {
            if out
                .last()
                .is_none_or(|q| q.0 != p.0 || q.1.to_bits() != p.1.to_bits())
            {
                out.push(p);
            }
        };
        for (b, times) in bins.times.iter().enumerate() {
            let Some((first, last)) = *times else {
                continue;
            };
            let Some(cell) = bins.cells.get(b * columns + k) else {
                continue;
            };
            add((first, cell.first));
            let (a, z) = if cell.min.0 <= cell.max.0 {
                (cell.min, cell.max)
            } else {
                (cell.max, cell.min)
            };
            add(a);
            add(z);
            add((last, cell.last));
        }
        out
    }
}

impl Bins {
    fn push(&mut self, t: f64, values: impl Iterator<Item = f64>) {
        let mut b = self.index(t);
        while b >= BINS {
            self.halve();
            b = self.index(t);
        }
        let columns = self.columns;
        if b >= self.times.len() {
            self.times.resize(b + 1, None);
            // An empty bin's cells are placeholders, never read: `Decimator::points` skips it.
            self.cells
                .resize((b + 1) * columns, Cell::new(0.0, f64::NAN));
        }
        let cells = &mut self.cells[b * columns..(b + 1) * columns];
        match &mut self.times[b] {
            Some((_, last)) => {
                *last = t;
                for (cell, v) in cells.iter_mut().zip(values) {
                    cell.add(t, v);
                }
            }
            slot @ None => {
                *slot = Some((t, t));
                for (cell, v) in cells.iter_mut().zip(values) {
                    *cell = Cell::new(t, v);
                }
            }
        }
    }

    fn index(&self, t: f64) -> usize {
        let b = (t.max(0.0) / self.width).floor();
        if b.is_finite() && b < BINS as f64 {
            b as usize
        } else {
            BINS
        }
    }

    /// Merges bins pairwise; the width doubles.
    fn halve(&mut self) {
        let columns = self.columns;
        let n = self.times.len().div_ceil(2);
        for j in 0..n {
            let (a, b) = (2 * j, 2 * j + 1);
            let right = self.times.get(b).copied().flatten();
            let left = self.times[a];
            let merged = match (left, right) {
                (Some((first, _)), Some((_, last))) => {
                    for c in 0..columns {
                        let later = self.cells[b * columns + c];
                        self.cells[a * columns + c].merge(&later);
                    }
                    Some((first, last))
                }
                (Some(l), None) => Some(l),
                (None, Some(r)) => {
                    for c in 0..columns {
                        self.cells[a * columns + c] = self.cells[b * columns + c];
                    }
                    Some(r)
                }
                (None, None) => None,
            };
            self.times[j] = merged;
            for c in 0..columns {
                self.cells[j * columns + c] = self.cells[a * columns + c];
            }
        }
        self.times.truncate(n);
        self.cells.truncate(n * columns);
        self.width *= 2.0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_short_run_is_kept_whole() {
        let mut d = Decimator::new(vec![1]);
        for k in 0..100 {
            d.push(k as f64, &[0.0, k as f64 * 2.0]);
        }
        let points = d.points(0);
        assert_eq!(points.len(), 100);
        assert_eq!(points[7], (7.0, 14.0));
    }

    /// A million rows of a slow sine with one sample far above it and one far below: both
    /// stay, at their times, in a bounded number of points in time order.
    #[test]
    fn a_long_run_keeps_every_spike_in_bounded_points() {
        let mut d = Decimator::new(vec![0, 2]);
        let n = 1_000_000;
        for k in 0..n {
            let t = k as f64 * 1e-9;
            let mut v = (t * 1e3).sin();
            if k == 123_457 {
                v = 50.0;
            }
            if k == 876_543 {
                v = -50.0;
            }
            d.push(t, &[v, 7.0, (k % 2) as f64]);
        }
        let points = d.points(0);
        assert!(points.len() <= 4 * BINS, "{}", points.len());
        assert!(points.len() >= BINS / 2, "{}", points.len());
        assert!(points.windows(2).all(|w| w[0].0 <= w[1].0));
        assert!(points.contains(&(123_457.0 * 1e-9, 50.0)));
        assert!(points.contains(&(876_543.0 * 1e-9, -50.0)));
        assert_eq!(points[0], (0.0, 0.0));
        assert_eq!(points.last().unwrap().0, (n - 1) as f64 * 1e-9);
        // A toggling column keeps both levels in every bin.
        let toggles = d.points(1);
        assert!(toggles.iter().any(|p| p.1 == 0.0) && toggles.iter().any(|p| p.1 == 1.0));
        let highest = points.iter().map(|p| p.1).fold(f64::MIN, f64::max);
        assert_eq!(highest, 50.0);
    }

    #[test]
    fn gaps_and_times_at_zero_are_binned() {
        let mut d = Decimator::new(vec![0]);
        for k in 0..=RAW_ROWS {
            d.push(0.0, &[k as f64]);
        }
        d.push(1.0, &[-1.0]);
        d.push(1e6, &[2.0]);
        let points = d.points(0);
        assert_eq!(points.first(), Some(&(0.0, 0.0)));
        assert!(points.contains(&(0.0, RAW_ROWS as f64)));
        assert!(points.contains(&(1.0, -1.0)));
        assert_eq!(points.last(), Some(&(1e6, 2.0)));
    }
}
