//! Structural analysis of the equation/unknown incidence before any number is computed.
//!
//! First the VHDL-AMS count rule (as many equations as unknowns); then a maximum bipartite
//! matching (augmenting paths found by breadth-first search); if it is not perfect, the
//! Dulmage-Mendelsohn coarse decomposition: equations reachable from an unmatched equation by
//! alternating paths form the over-determined part, unknowns reachable from an unmatched
//! unknown the under-determined part.

use std::collections::VecDeque;

use super::build::{Origin, Unknown};
use super::error::AnalogError;
use vams_design::{BinaryOp, Design, Expr, QuantityId};

/// The incidence of equations (rows) and unknowns (columns), both ways in compressed form
/// (offsets into one index array each: two allocations, not one per equation and unknown).
pub struct Incidence {
    row_start: Vec<usize>,
    row_cols: Vec<usize>,
    col_start: Vec<usize>,
    col_rows: Vec<usize>,
}

/// `(start, indices)` of a compressed adjacency: the entries of `key(p)` for each pattern entry
/// `p`, grouped by `key`, in pattern order within each group.
fn compress(
    n: usize,
    pattern: &[(usize, usize)],
    key: impl Fn(&(usize, usize)) -> (usize, usize),
) -> (Vec<usize>, Vec<usize>) {
    let mut start = vec![0; n + 1];
    for p in pattern {
        start[key(p).0 + 1] += 1;
    }
    for k in 0..n {
        start[k + 1] += start[k];
    }
    let mut next = start.clone();
    let mut indices = vec![0; pattern.len()];
    for p in pattern {
        let (k, v) = key(p);
        indices[next[k]] = v;
        next[k] += 1;
    }
    (start, indices)
}

impl Incidence {
    pub fn new(n_rows: usize, n_cols: usize, pattern: &[(usize, usize)]) -> Incidence {
        let (row_start, row_cols) = compress(n_rows, pattern, |&(r, c)| (r, c));
        let (col_start, col_rows) = compress(n_cols, pattern, |&(r, c)| (c, r));
        Incidence {
            row_start,
            row_cols,
            col_start,
            col_rows,
        }
    }

    pub fn n_rows(&self) -> usize {
        self.row_start.len() - 1
    }

    pub fn n_cols(&self) -> usize {
        self.col_start.len() - 1
    }

    /// The columns of row `r`, in pattern order.
    pub fn row(&self, r: usize) -> &[usize] {
        &self.row_cols[self.row_start[r]..self.row_start[r + 1]]
    }

    /// The rows of column `c`, in pattern order.
    pub fn col(&self, c: usize) -> &[usize] {
        &self.col_rows[self.col_start[c]..self.col_start[c + 1]]
    }
}

/// A maximum matching: `row_match[r]` is the column matched to row `r`, and vice versa.
pub struct Matching {
    pub row_match: Vec<Option<usize>>,
    pub col_match: Vec<Option<usize>>,
}

/// Maximum bipartite matching by repeated breadth-first augmenting-path search.
pub fn maximum_matching(inc: &Incidence) -> Matching {
    let (nr, nc) = (inc.n_rows(), inc.n_cols());
    let mut row_match = vec![None; nr];
    let mut col_match: Vec<Option<usize>> = vec![None; nc];
    // Cheap greedy start.
    for (r, matched) in row_match.iter_mut().enumerate() {
        if let Some(&c) = inc.row(r).iter().find(|&&c| col_match[c].is_none()) {
            *matched = Some(c);
            col_match[c] = Some(r);
        }
    }
    // parent_col[c] = the row from which column c was reached in this search.
    let mut parent = vec![usize::MAX; nc];
    let mut reached: Vec<usize> = Vec::new();
    let mut queue = VecDeque::new();
    for start in 0..nr {
        if row_match[start].is_some() {
            continue;
        }
        // Reset only the columns the last search reached: a full fill per search would make
        // the matching quadratic in the system size.
        for &c in &reached {
            parent[c] = usize::MAX;
        }
        reached.clear();
        queue.clear();
        queue.push_back(start);
        let mut free_col = None;
        'search: while let Some(r) = queue.pop_front() {
            for &c in inc.row(r) {
                if parent[c] != usize::MAX {
                    continue;
                }
                parent[c] = r;
                reached.push(c);
                match col_match[c] {
                    None => {
                        free_col = Some(c);
                        break 'search;
                    }
                    Some(next) => queue.push_back(next),
                }
            }
        }
        // Flip the path back to `start`.
        let mut c = free_col;
        while let Some(col) = c {
            let r = parent[col];
            let prev = row_match[r];
            row_match[r] = Some(col);
            col_match[col] = Some(r);
            c = if r == start { None } else { prev };
        }
    }
    Matching {
        row_match,
        col_match,
    }
}

/// Rows and columns of the over-determined part (from unmatched rows) or, with `from_cols`,
/// the under-determined part (from unmatched columns).
fn alternating_reach(inc: &Incidence, m: &Matching, from_cols: bool) -> (Vec<usize>, Vec<usize>) {
    let (nr, nc) = (inc.n_rows(), inc.n_cols());
    let mut seen_r = vec![false; nr];
    let mut seen_c = vec![false; nc];
    let mut queue = VecDeque::new();
    if from_cols {
        for (c, seen) in seen_c.iter_mut().enumerate() {
            if m.col_match[c].is_none() {
                *seen = true;
                queue.push_back(c);
            }
        }
        while let Some(c) = queue.pop_front() {
            for &r in inc.col(c) {
                if !seen_r[r] {
                    seen_r[r] = true;
                    if let Some(next) = m.row_match[r]
                        && !seen_c[next]
                    {
                        seen_c[next] = true;
                        queue.push_back(next);
                    }
                }
            }
        }
    } else {
        for (r, seen) in seen_r.iter_mut().enumerate() {
            if m.row_match[r].is_none() {
                *seen = true;
                queue.push_back(r);
            }
        }
        while let Some(r) = queue.pop_front() {
            for &c in inc.row(r) {
                if !seen_c[c] {
                    seen_c[c] = true;
                    if let Some(next) = m.col_match[c]
                        && !seen_r[next]
                    {
                        seen_r[next] = true;
                        queue.push_back(next);
                    }
                }
            }
        }
    }
    let pick = |v: &[bool]| v.iter().enumerate().filter(|e| *e.1).map(|e| e.0).collect();
    (pick(&seen_r), pick(&seen_c))
}

/// What the structural checks need to name things.
pub struct Names<'a> {
    pub design: &'a Design,
    pub unknowns: &'a [Unknown],
    pub origins: &'a [Origin],
}

impl Names<'_> {
    fn equations(&self, rows: &[usize]) -> String {
        let list: Vec<String> = rows
            .iter()
            .map(|&r| self.origins[r].describe(self.design))
            .collect();
        list.join(", ")
    }

    /// [`Names::equations`] of at most `max` rows, then how many more.
    fn some_equations(&self, rows: &[usize], max: usize) -> String {
        let shown = self.equations(&rows[..rows.len().min(max)]);
        match rows.len().saturating_sub(max) {
            0 => shown,
            more => format!("{shown} and {more} more"),
        }
    }

    fn unknowns(&self, cols: &[usize]) -> String {
        let list: Vec<String> = cols
            .iter()
            .map(|&c| self.unknowns[c].name(self.design))
            .collect();
        list.join(", ")
    }
}

/// The lone across quantity to give an implicit through quantity ([`Unknown::Flow`]), if the
/// system has an over-determined part (equations a maximum matching leaves out) and one of the
/// model's equations sets such a quantity there: `quantity vs across p to m; vs == 5.0;` is a
/// voltage source whose current the model forgot. LRM 1076.1 12.6.6 counts only through and
/// free quantities, so the equation is one too many; the University of Cincinnati's test
/// suite and the simulator it was written for read it as a source, and so does vams, with a
/// warning. Of several candidates, one that an equation has on its left (`vout == 2.0 * vm`
/// sets `vout`: the voltmeter `vm` it reads keeps no current), then the one whose setting
/// equation names the fewest unknowns (`vs == f(t)` before `vs == k * vin`).
pub fn implicit_flow(inc: &Incidence, names: &Names<'_>) -> Option<QuantityId> {
    if names.design.lone_across.is_empty() {
        return None;
    }
    let m = maximum_matching(inc);
    if m.row_match.iter().all(Option::is_some) {
        return None;
    }
    let (rows, cols) = alternating_reach(inc, &m, false);
    let lone = |c: usize| match names.unknowns[c] {
        Unknown::Quantity(q) if names.design.lone_across.contains(&q) => Some(q),
        _ => None,
    };
    // Already given one: its column is a Flow now, so it is no candidate (the lookup above).
    let given = |q: QuantityId| names.unknowns.contains(&Unknown::Flow(q));
    // The user's equation of origin `r` written `q == ...` (`Sub(q, ...)` once elaborated).
    let on_left = |r: usize, q: QuantityId| match names.origins[r] {
        Origin::User(i) => matches!(
            &names.design.equations[i].residual,
            Expr::Binary(BinaryOp::Sub, l, _) if **l == Expr::Quantity(q)
        ),
        _ => false,
    };
    (cols.iter().copied())
        .filter_map(|c| {
            let q = lone(c).filter(|&q| !given(q))?;
            let rank = (rows.iter().copied())
                .filter(|&r| is_user(names, r) && inc.row(r).contains(&c))
                .map(|r| (!on_left(r, q), inc.row(r).len()))
                .min()?;
            Some((rank, q))
        })
        .min_by_key(|&(rank, q)| (rank, q.index()))
        .map(|(_, q)| q)
}

/// The count rule, then the matching; every structural defect as a diagnostic.
pub fn check(inc: &Incidence, names: &Names<'_>) -> Result<(), Vec<AnalogError>> {
    let (ne, nu) = (inc.n_rows(), inc.n_cols());
    if ne != nu {
        let unused: Vec<usize> = (0..nu).filter(|&c| inc.col(c).is_empty()).collect();
        // Too many equations: the over-determined part of a maximum matching says which
        // equations compete for too few quantities.
        let over = if ne > nu {
            let m = maximum_matching(inc);
            alternating_reach(inc, &m, false)
        } else {
            (Vec::new(), Vec::new())
        };
        let source = across_only(names, &over.1);
        // The equation to show: one that sets an across-only quantity, else the first of the
        // user's among the over-determined ones.
        let first_over = (source.and_then(|(_, c)| setting_row(inc, names, &over.0, c)))
            .or_else(|| (over.0.iter().copied()).find(|&r| is_user(names, r)))
            .or(over.0.first().copied());
        let (span, label) = match (unused.first(), first_over, names.origins.first()) {
            (Some(&c), _, _) => (
                names.unknowns[c].span(names.design),
                "appears in no equation",
            ),
            (None, Some(r), _) => (
                names.origins[r].span(names.design),
                if source.is_some() {
                    "this sets an across quantity that has no through quantity"
                } else {
                    "one equation too many is among these"
                },
            ),
            (None, None, Some(o)) => (o.span(names.design), "the first equation"),
            (None, None, None) => (Default::default(), "in this design"),
        };
        let help = if ne < nu && !unused.is_empty() {
            format!(
                "too few equations; {} {} in no equation: add an equation for each \
                 (LRM 1076.1 12.6.6: one simultaneous statement per free quantity)",
                names.unknowns(&unused),
                if unused.len() == 1 {
                    "appears"
                } else {
                    "appear"
                }
            )
        } else if ne < nu {
            "too few equations: add a simultaneous statement for each quantity that is only \
             read (LRM 1076.1 12.6.6)"
                .to_string()
        } else if let Some((q, _)) = source {
            lone_across_help(names.design, q)
        } else if !over.0.is_empty() {
            let determined = match over.1.len() {
                0 => "nothing".to_string(),
                1..=8 => names.unknowns(&over.1),
                n => format!("{n} quantities"),
            };
            format!(
                "too many equations: {} equations ({}) determine only {determined}; remove \
                 one (a conservation law the terminals already give, written out?), or \
                 declare the quantity it determines (LRM 1076.1 12.6.6)",
                over.0.len(),
                names.some_equations(&over.0, 4),
            )
        } else {
            "too many equations: remove redundant simultaneous statements, or declare the \
             quantity they determine (LRM 1076.1 12.6.6)"
                .to_string()
        };
        return Err(vec![AnalogError::Count {
            span,
            label,
            equations: ne,
            unknowns: nu,
            help: Some(help),
        }]);
    }
    let m = maximum_matching(inc);
    if m.row_match.iter().all(Option::is_some) {
        return Ok(());
    }
    let mut errors = Vec::new();
    let (rows, cols) = alternating_reach(inc, &m, false);
    if let Some(&first) = rows.first() {
        let source = across_only(names, &cols);
        // Shown: the user's equation that sets a lone across quantity, if one does.
        let first = (source.and_then(|(_, c)| setting_row(inc, names, &rows, c))).unwrap_or(first);
        let help = match source {
            Some((q, _)) => lone_across_help(names.design, q),
            None => "these equations leave no room for each other: remove or rewrite one so \
                     that it determines another quantity (LRM 1076.1 12.6.6: one equation per \
                     quantity)"
                .to_string(),
        };
        errors.push(AnalogError::Overdetermined {
            help,
            span: names.origins[first].span(names.design),
            count: rows.len(),
            equations: names.equations(&rows),
            quantities: if cols.is_empty() {
                "(none)".to_string()
            } else {
                names.unknowns(&cols)
            },
        });
    }
    let (rows, cols) = alternating_reach(inc, &m, true);
    if let Some(&first) = cols.first() {
        errors.push(AnalogError::Underdetermined {
            span: names.unknowns[first].span(names.design),
            count: cols.len(),
            quantities: names.unknowns(&cols),
            equations: if rows.is_empty() {
                "no equation".to_string()
            } else {
                names.equations(&rows)
            },
        });
    }
    Err(errors)
}

/// Whether row `r` is one of the model's own equations (not a conservation law or an
/// across quantity's definition).
fn is_user(names: &Names<'_>, r: usize) -> bool {
    matches!(names.origins[r], Origin::User(_))
}

/// The first of the user's equations among `rows` that names column `c`: the one to show
/// for a lone across quantity it sets.
fn setting_row(inc: &Incidence, names: &Names<'_>, rows: &[usize], c: usize) -> Option<usize> {
    (rows.iter().copied()).find(|&r| is_user(names, r) && inc.row(r).contains(&c))
}

/// Why an equation that sets the lone across quantity `q` cannot hold, and the fix.
fn lone_across_help(design: &Design, q: QuantityId) -> String {
    let name = &design.quantities[q.index()].name;
    format!(
        "`{name}` is an across quantity declared without a through quantity: no flow can make \
         an equation that sets it hold (LRM 1076.1 12.6.6 asks one equation per through and \
         free quantity). For a source, give its declaration one: `quantity {name} across \
         i_{name} through ...;`"
    )
}

/// An across quantity among `cols` declared without a through quantity (`quantity vs
/// across t1; vs == 5.0;`, written as a voltage source), and its column.
fn across_only(names: &Names<'_>, cols: &[usize]) -> Option<(QuantityId, usize)> {
    cols.iter().find_map(|&c| match names.unknowns[c] {
        Unknown::Quantity(q)
            if names.design.lone_across.contains(&q)
                && !names.unknowns.contains(&Unknown::Flow(q)) =>
        {
            Some((q, c))
        }
        _ => None,
    })
}

/// The algebraic unknowns of higher index: those that the equations determine only through
/// the derivative of a constrained differential unknown (the current of a voltage source with
/// a capacitor across it is `C` times the derivative of the source's waveform).
///
/// `index1` is the incidence of the matrix that an index-1 system keeps regular,
/// `[dF/dx'_d  dF/dx_a]` (x' of the differential unknowns, x of the algebraic ones). Where its
/// matching is not perfect, an equation ties differential unknowns together without any x'
/// (the source's `v == f(t)`): the unknowns it leaves under-determined are those whose values
/// come from a differentiated constraint, so BDF computes them to first order only, whatever
/// its order, and a local error test on them drives the step size to nothing (IDA and DASSL
/// leave such components out of the test; SPICE tests only charges and fluxes).
pub fn higher_index_algebraic(index1: &Incidence, differential: &[bool]) -> Vec<bool> {
    let m = maximum_matching(index1);
    let mut higher = vec![false; index1.n_cols()];
    if m.row_match.iter().all(Option::is_some) {
        return higher;
    }
    let (_, cols) = alternating_reach(index1, &m, true);
    for c in cols {
        higher[c] = !differential[c];
    }
    higher
}

#[cfg(test)]
mod tests {
    use super::{Incidence, higher_index_algebraic};

    /// A source `v = f(t)` with a capacitor across it (`i_c = C v'`) and its current `i_s`
    /// in the balance `i_s + i_c = 0`: unknowns v (differential), i_c and i_s (algebraic).
    /// In `[dF/dv', dF/di_c, dF/di_s]` the source row is empty, so `i_c` or `i_s` (whichever
    /// the matching leaves) and everything alternating paths reach from it are of higher
    /// index: both currents, not `v`.
    #[test]
    fn the_current_of_a_source_with_a_capacitor_across_it_is_of_higher_index() {
        // Rows: source (no entry: v' does not occur, v is differential), capacitor
        // `i_c - C v' = 0`, balance `i_s + i_c = 0`.
        let pattern = [(1, 0), (1, 1), (2, 1), (2, 2)];
        let inc = Incidence::new(3, 3, &pattern);
        let higher = higher_index_algebraic(&inc, &[true, false, false]);
        assert_eq!(higher, [false, true, true]);
    }

    /// The same capacitor charged through a resistor (`v' = (u - v) / (R C)`, one row with
    /// v'): index 1, nothing is left out.
    #[test]
    fn an_index_one_system_has_no_higher_index_unknowns() {
        // Rows: capacitor `i - C v' = 0`, resistor `u - v - R i = 0` (u a known input).
        let pattern = [(0, 0), (0, 1), (1, 1)];
        let inc = Incidence::new(2, 2, &pattern);
        assert_eq!(higher_index_algebraic(&inc, &[true, false]), [false, false]);
    }
}
