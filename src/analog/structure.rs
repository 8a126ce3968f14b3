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
use crate::design::Design;

/// The incidence of equations (rows) and unknowns (columns).
pub struct Incidence {
    pub rows: Vec<Vec<usize>>,
    pub cols: Vec<Vec<usize>>,
}

impl Incidence {
    pub fn new(n_rows: usize, n_cols: usize, pattern: &[(usize, usize)]) -> Incidence {
        let mut rows = vec![Vec::new(); n_rows];
        let mut cols = vec![Vec::new(); n_cols];
        for &(r, c) in pattern {
            rows[r].push(c);
            cols[c].push(r);
        }
        Incidence { rows, cols }
    }
}

/// A maximum matching: `row_match[r]` is the column matched to row `r`, and vice versa.
pub struct Matching {
    pub row_match: Vec<Option<usize>>,
    pub col_match: Vec<Option<usize>>,
}

/// Maximum bipartite matching by repeated breadth-first augmenting-path search.
pub fn maximum_matching(inc: &Incidence) -> Matching {
    let (nr, nc) = (inc.rows.len(), inc.cols.len());
    let mut row_match = vec![None; nr];
    let mut col_match: Vec<Option<usize>> = vec![None; nc];
    // Cheap greedy start.
    for (r, matched) in row_match.iter_mut().enumerate() {
        if let Some(&c) = inc.rows[r].iter().find(|&&c| col_match[c].is_none()) {
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
            for &c in &inc.rows[r] {
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
    let (nr, nc) = (inc.rows.len(), inc.cols.len());
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
            for &r in &inc.cols[c] {
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
            for &c in &inc.rows[r] {
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
    pub names: &'a [String],
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

    fn unknowns(&self, cols: &[usize]) -> String {
        let list: Vec<&str> = cols.iter().map(|&c| self.names[c].as_str()).collect();
        list.join(", ")
    }
}

/// The count rule, then the matching; every structural defect as a diagnostic.
pub fn check(inc: &Incidence, names: &Names<'_>) -> Result<(), Vec<AnalogError>> {
    let (ne, nu) = (inc.rows.len(), inc.cols.len());
    if ne != nu {
        let unused: Vec<usize> = (0..nu).filter(|&c| inc.cols[c].is_empty()).collect();
        let (span, label) = match (unused.first(), names.origins.first()) {
            (Some(&c), _) => (
                names.unknowns[c].span(names.design),
                "appears in no equation",
            ),
            (None, Some(o)) => (o.span(names.design), "the first equation"),
            (None, None) => (Default::default(), "in this design"),
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
        errors.push(AnalogError::Overdetermined {
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
