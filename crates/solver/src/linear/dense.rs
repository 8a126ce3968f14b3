//! The small-system path: row-major `n x n` storage, LU with partial pivoting, and a compiled
//! refactorisation that reuses the last pivot sequence.
//!
//! A Newton matrix keeps its sparsity pattern and, from one factorisation to the next, mostly
//! its pivots: only the values move. So after each full factorisation (pivot search in every
//! column) the elimination under the pivots it chose is compiled into a [`Schedule`]: which
//! rows each pivot eliminates and which columns each pivot row updates, fill included, from the
//! pattern alone. Later factorisations assemble straight into the permuted rows (zeroing only
//! the structural positions no entry covers, not all n^2) and run the schedule, touching only
//! structural entries and searching nothing: 18 entries and a handful
//! of multiply-adds for the H-bridge's 7 unknowns, where the full loop does 91. A pivot that
//! falls below [`PIVOT_THRESHOLD`] times the largest entry left in its column (threshold
//! partial pivoting, as SPICE's Sparse and KLU's refactorisation do) sends the factorisation
//! back to the full search, which picks new pivots and compiles a new schedule.

/// A reused pivot is kept while it is at least this fraction of the largest magnitude in its
/// column of the partly eliminated matrix (SPICE's relative threshold is 1e-3; a larger one
/// bounds element growth more tightly at the price of more full searches).
pub(super) const PIVOT_THRESHOLD: f64 = 1e-2;

/// Row-major `n x n` LU in place: `a` holds `L` (unit diagonal, below) and `U`; row `k` of the
/// factors is row `perm[k]` of the assembled matrix. The full loops run on row slices (no index
/// arithmetic inside, so no bounds checks and the row updates vectorise): at n = 7 a
/// factorisation is a few hundred flops, and overhead would dominate.
pub(super) struct Dense {
    n: usize,
    a: Vec<f64>,
    /// Position in `a` of each pattern entry and of each diagonal entry: in natural row order
    /// for the full search, in the schedule's row order for a refactorisation.
    natural: Layout,
    permuted: Layout,
    assembly: Assembly,
    pub(super) perm: Vec<usize>,
    /// `1 / U[k][k]`: back substitution multiplies (a division's latency, about 15 cycles,
    /// would sit on the solve's serial dependency chain once per row).
    inv_diag: Vec<f64>,
    scratch: Vec<f64>,
    schedule: Schedule,
    /// Structural nonzeros of the assembled matrix (pattern + diagonal), row-major.
    structure: Vec<bool>,
    /// Scratch for compiling a schedule: the structure in pivot order, filled in, and the
    /// position in pivot order of each assembled row.
    fill: Vec<bool>,
    position: Vec<usize>,
    /// The pivot order before the current one, compiled (`schedule.valid` false when there
    /// is none): a switching circuit alternates between two matrices whose best pivots differ
    /// (the PWM H-bridge's switch conductances move by 1e7 at every edge), and retrying the
    /// other order before searching turns 1 202 searches into 2.
    other: Compiled,
    /// Full factorisations (pivot searches) and refactorisations with reused pivots.
    pub(super) counts: PivotCounts,
}

/// What a pivot search compiles, kept for the previous order in [`Dense::other`].
struct Compiled {
    permuted: Layout,
    assembly: Assembly,
    perm: Vec<usize>,
    schedule: Schedule,
}

impl Compiled {
    /// No order yet, with the capacities of a full matrix (compiling never allocates).
    fn empty(n: usize, entries: usize) -> Compiled {
        let triangle = n * n.saturating_sub(1) / 2;
        Compiled {
            permuted: Layout {
                at: vec![0; entries],
                diag: vec![0; n],
            },
            assembly: Assembly {
                zero: Vec::with_capacity(n * n),
                assign: Vec::with_capacity(entries),
                accumulate: Vec::with_capacity(entries),
            },
            perm: vec![0; n],
            schedule: Schedule {
                valid: false,
                lower_start: vec![0; n + 1],
                lower: Vec::with_capacity(triangle),
                upper_start: vec![0; n + 1],
                upper: Vec::with_capacity(triangle),
            },
        }
    }
}

/// How a solver's factorisations went (pivots searched for, or reused by a refactorisation),
/// for tests and benchmarks.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct PivotCounts {
    pub searched: usize,
    pub reused: usize,
}

struct Layout {
    at: Vec<usize>,
    diag: Vec<usize>,
}

/// Assembly in the schedule's row order without clearing all of `a` (n^2 entries, where the
/// schedule reads only the structural ones): structural positions no pattern entry covers (fill,
/// a diagonal the pattern lacks) are zeroed, the first pattern entry at each position is
/// stored, later ones (duplicates) added; all as (position, value index).
struct Assembly {
    zero: Vec<usize>,
    assign: Vec<(usize, usize)>,
    accumulate: Vec<(usize, usize)>,
}

/// The compiled elimination for one pivot sequence. Row indices are positions in the factors
/// (pivot order); `lower[lower_start[j]..lower_start[j + 1]]` are the rows below `j` with a
/// structural `L[r][j]`, `upper[upper_start[j]..upper_start[j + 1]]` the columns right of `j`
/// with a structural `U[j][c]`. Capacities are those of a full matrix, so compiling a new
/// schedule never allocates.
struct Schedule {
    valid: bool,
    lower_start: Vec<u32>,
    lower: Vec<u32>,
    upper_start: Vec<u32>,
    upper: Vec<u32>,
}

impl Dense {
    pub(super) fn new(n: usize, pattern: &[(usize, usize)]) -> Self {
        let mut structure = vec![false; n * n];
        for &(r, c) in pattern {
            structure[r * n + c] = true;
        }
        for i in 0..n {
            structure[i * n + i] = true;
        }
        let Compiled {
            permuted,
            assembly,
            perm,
            schedule,
        } = Compiled::empty(n, pattern.len());
        Self {
            n,
            a: vec![0.0; n * n],
            natural: Layout {
                at: pattern.iter().map(|&(r, c)| r * n + c).collect(),
                diag: (0..n).map(|i| i * n + i).collect(),
            },
            assembly,
            permuted,
            perm,
            inv_diag: vec![0.0; n],
            scratch: vec![0.0; n],
            schedule,
            structure,
            fill: vec![false; n * n],
            position: vec![0; n],
            other: Compiled::empty(n, pattern.len()),
            counts: PivotCounts::default(),
        }
    }

    /// Exchanges the current compiled pivot order with the previous one.
    fn swap_orders(&mut self) {
        let o = &mut self.other;
        std::mem::swap(&mut self.permuted, &mut o.permuted);
        std::mem::swap(&mut self.assembly, &mut o.assembly);
        std::mem::swap(&mut self.perm, &mut o.perm);
        std::mem::swap(&mut self.schedule, &mut o.schedule);
    }

    /// Factors the matrix whose entries are `values` (pattern order) plus `diag` (one shift
    /// per row) on the diagonal. Reuses the last pivots when they still hold, else searches; a search records
    /// the largest magnitude of each row and column of the assembled matrix in `maxima`
    /// (zeroed by the caller). `Err(j)`: the pivot
    /// step `j` found no pivot above `pivot_tol * col_max[j]` (the matrix counts as singular;
    /// `perm[j]` is the row). `check` sees the maxima before any elimination.
    pub(super) fn factor<E>(
        &mut self,
        pattern: &[(usize, usize)],
        values: &[f64],
        diag: Option<&[f64]>,
        pivot_tol: f64,
        maxima: (&mut [f64], &mut [f64]),
        check: impl FnOnce(&[f64], &[f64]) -> Result<(), E>,
    ) -> Result<Result<(), usize>, E> {
        let (row_max, col_max) = maxima;
        if self.schedule.valid {
            // Only the column maxima (for the singularity test): an empty row or column
            // leaves a zero pivot, and the full path below then names it.
            self.assemble_permuted(pattern, values, diag, col_max);
            if self.refactor(pivot_tol, col_max) {
                self.counts.reused += 1;
                return Ok(Ok(()));
            }
            // The order before: after this swap the current order is the older of the two,
            // which a search below replaces.
            self.swap_orders();
            if self.schedule.valid {
                col_max.fill(0.0);
                self.assemble_permuted(pattern, values, diag, col_max);
                if self.refactor(pivot_tol, col_max) {
                    self.counts.reused += 1;
                    return Ok(Ok(()));
                }
            }
            col_max.fill(0.0);
        }
        assemble(
            &mut self.a,
            &self.natural,
            pattern,
            values,
            diag,
            row_max,
            col_max,
        );
        check(row_max, col_max)?;
        self.counts.searched += 1;
        let searched = self.search(pivot_tol, col_max);
        if searched.is_ok() {
            self.compile(pattern);
        } else {
            self.schedule.valid = false;
        }
        Ok(searched)
    }

    /// Sums `values` into `a` in the schedule's row order (plus `diag` on the diagonal)
    /// and records the largest magnitude in each column. The values are finite (checked by
    /// the caller), so plain comparisons do.
    fn assemble_permuted(
        &mut self,
        pattern: &[(usize, usize)],
        values: &[f64],
        diag: Option<&[f64]>,
        col_max: &mut [f64],
    ) {
        let (a, layout, s) = (&mut self.a, &self.permuted, &self.assembly);
        for &k in &s.zero {
            a[k] = 0.0;
        }
        for &(k, v) in &s.assign {
            a[k] = values[v];
        }
        for &(k, v) in &s.accumulate {
            a[k] += values[v];
        }
        if let Some(diag) = diag {
            for (&k, &d) in layout.diag.iter().zip(diag) {
                a[k] += d;
            }
        }
        let mut record = |c: usize, k: usize| {
            let v = a[k].abs();
            col_max[c] = if v > col_max[c] { v } else { col_max[c] };
        };
        for (&(_, c), &k) in pattern.iter().zip(&layout.at) {
            record(c, k);
        }
        if diag.is_some() {
            for (c, &k) in layout.diag.iter().enumerate() {
                record(c, k);
            }
        }
    }

    /// Full LU with partial pivoting on the naturally ordered `a`.
    // Rows are sliced by index rather than with `chunks_exact`, whose length division costs
    // more than a 4 x 4 elimination step.
    fn search(&mut self, pivot_tol: f64, col_max: &[f64]) -> Result<(), usize> {
        let n = self.n;
        for (k, p) in self.perm.iter_mut().enumerate() {
            *p = k;
        }
        let a = &mut self.a;
        for j in 0..n {
            // Selects rather than branches (the pivot row is data, and mispredicts); a NaN
            // anywhere in the column makes the matrix singular.
            let (mut p, mut best, mut nan) = (j, -1.0_f64, false);
            for r in j..n {
                let v = a[r * n + j].abs();
                nan |= v.is_nan();
                let better = v > best;
                p = if better { r } else { p };
                best = if better { v } else { best };
            }
            if nan || best <= pivot_tol * col_max[j] {
                return Err(j);
            }
            let (top, bottom) = a.split_at_mut((j + 1) * n);
            let pivot_row = &mut top[j * n..];
            if p != j {
                let q = (p - j - 1) * n;
                pivot_row.swap_with_slice(&mut bottom[q..q + n]);
                self.perm.swap(j, p);
            }
            let inv_pivot = 1.0 / pivot_row[j];
            self.inv_diag[j] = inv_pivot;
            let pivot_rest = &pivot_row[j + 1..];
            for r in 0..n - j - 1 {
                let row = &mut bottom[r * n + j..(r + 1) * n];
                let l = row[0] * inv_pivot;
                row[0] = l;
                if l != 0.0 {
                    for (x, &u) in row[1..].iter_mut().zip(pivot_rest) {
                        *x -= l * u;
                    }
                }
            }
        }
        Ok(())
    }

    /// Compiles the schedule and the permuted layout for the pivots `perm` holds.
    fn compile(&mut self, pattern: &[(usize, usize)]) {
        let n = self.n;
        for (k, &p) in self.perm.iter().enumerate() {
            self.position[p] = k;
        }
        let row_of = |r: usize| self.position[r];
        let fill = &mut self.fill;
        for r in 0..n {
            let k = row_of(r);
            fill[k * n..(k + 1) * n].copy_from_slice(&self.structure[r * n..(r + 1) * n]);
        }
        let s = &mut self.schedule;
        s.lower.clear();
        s.upper.clear();
        for j in 0..n {
            s.lower_start[j] = s.lower.len() as u32;
            s.upper_start[j] = s.upper.len() as u32;
            s.upper
                .extend((j + 1..n).filter(|&c| fill[j * n + c]).map(|c| c as u32));
            for r in j + 1..n {
                if fill[r * n + j] {
                    s.lower.push(r as u32);
                    for &c in &s.upper[s.upper_start[j] as usize..] {
                        fill[r * n + c as usize] = true;
                    }
                }
            }
        }
        s.lower_start[n] = s.lower.len() as u32;
        s.upper_start[n] = s.upper.len() as u32;
        s.valid = true;
        for (at, &(r, c)) in self.permuted.at.iter_mut().zip(pattern) {
            *at = row_of(r) * n + c;
        }
        for (i, d) in self.permuted.diag.iter_mut().enumerate() {
            *d = row_of(i) * n + i;
        }
        // `fill` marks the structure in pivot order: each position's first pattern entry is
        // stored (and unmarks it), later ones add; what stays marked is zeroed.
        let s = &mut self.assembly;
        s.zero.clear();
        s.assign.clear();
        s.accumulate.clear();
        for (v, &k) in self.permuted.at.iter().enumerate() {
            if fill[k] {
                fill[k] = false;
                s.assign.push((k, v));
            } else {
                s.accumulate.push((k, v));
            }
        }
        s.zero.extend((0..n * n).filter(|&k| fill[k]));
    }

    /// Eliminates with the schedule's pivots. False (and `a` spoilt) when a pivot is no
    /// longer acceptable: below the threshold of its column, or not above `pivot_tol *
    /// col_max[j]`, or not a number.
    fn refactor(&mut self, pivot_tol: f64, col_max: &[f64]) -> bool {
        let n = self.n;
        let (a, s) = (&mut self.a, &self.schedule);
        for j in 0..n {
            let lower = &s.lower[s.lower_start[j] as usize..s.lower_start[j + 1] as usize];
            let upper = &s.upper[s.upper_start[j] as usize..s.upper_start[j + 1] as usize];
            let pivot = a[j * n + j];
            let below = lower
                .iter()
                .fold(0.0_f64, |m, &r| m.max(a[r as usize * n + j].abs()));
            // Written so that a NaN pivot fails.
            let acceptable =
                pivot.abs() >= PIVOT_THRESHOLD * below && pivot.abs() > pivot_tol * col_max[j];
            if !acceptable {
                return false;
            }
            let inv_pivot = 1.0 / pivot;
            self.inv_diag[j] = inv_pivot;
            for &r in lower {
                let r = r as usize;
                let l = a[r * n + j] * inv_pivot;
                a[r * n + j] = l;
                for &c in upper {
                    let c = c as usize;
                    a[r * n + c] -= l * a[j * n + c];
                }
            }
        }
        true
    }

    /// Forward substitution by columns over `L`'s structure, back substitution by rows over
    /// `U`'s: only the schedule's entries, which hold every nonzero of the factors.
    pub(super) fn solve(&mut self, rhs: &mut [f64]) {
        let n = self.n;
        let (a, y, s) = (&self.a, &mut self.scratch, &self.schedule);
        for (y, &p) in y.iter_mut().zip(&self.perm) {
            *y = rhs[p];
        }
        for c in 0..n {
            let yc = y[c];
            for &r in &s.lower[s.lower_start[c] as usize..s.lower_start[c + 1] as usize] {
                let r = r as usize;
                y[r] -= a[r * n + c] * yc;
            }
        }
        for r in (0..n).rev() {
            let mut v = y[r];
            for &c in &s.upper[s.upper_start[r] as usize..s.upper_start[r + 1] as usize] {
                let c = c as usize;
                v -= a[r * n + c] * y[c];
            }
            y[r] = v * self.inv_diag[r];
        }
        rhs.copy_from_slice(y);
    }
}

/// Sums `values` into `a` at `layout` (plus `diag` on the diagonal) and records the
/// largest magnitude of each row and column (over the structural entries: the rest are zero).
fn assemble(
    a: &mut [f64],
    layout: &Layout,
    pattern: &[(usize, usize)],
    values: &[f64],
    diag: Option<&[f64]>,
    row_max: &mut [f64],
    col_max: &mut [f64],
) {
    a.fill(0.0);
    for (&k, &v) in layout.at.iter().zip(values) {
        a[k] += v;
    }
    // Branch-free maxima: which entry is largest is data, and mispredicts.
    let mut record = |r: usize, c: usize, v: f64| {
        let v = v.abs();
        row_max[r] = row_max[r].max(v);
        col_max[c] = col_max[c].max(v);
    };
    if let Some(diag) = diag {
        for (i, (&k, &d)) in layout.diag.iter().zip(diag).enumerate() {
            a[k] += d;
            record(i, i, a[k]);
        }
    }
    for (&(r, c), &k) in pattern.iter().zip(&layout.at) {
        record(r, c, a[k]);
    }
}
