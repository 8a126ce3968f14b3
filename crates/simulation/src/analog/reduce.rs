//! Elimination of unknowns that an equation gives explicitly: before compiling, every
//! equation that is linear in some unknown with a constant coefficient (`v - r * i = 0`, an
//! across definition `v - (v(p) - v(m)) = 0`, a conservation law) may be solved for it, and
//! the unknown substituted everywhere else. A circuit's branch voltages and currents then
//! disappear and the solver integrates about one unknown per node, as modified nodal analysis
//! does, while the model keeps all its quantities (their values are evaluated from the
//! survivors after each accepted step).
//!
//! The reduced system is exactly equivalent, also after BDF discretisation: each step is a
//! block elimination with a constant nonzero pivot. Rules that keep it so:
//! * the unknown occurs exactly once in the equation, only under `+`, `-`, negation and
//!   multiplication or division by a constant, and its `'dot` does not occur there;
//! * an unknown whose `'dot` occurs anywhere is eliminated only as a constant multiple of one
//!   other unknown (plus a constant), so its `'dot` becomes that multiple of the other's;
//! * unknowns that occur nonlinearly (a diode's junction voltage inside `exp`) stay, so that
//!   Newton's convergence test measures them: a value derived from the survivors can move
//!   far more than they do (an inductor's voltage is `L / h` times its current's update);
//! * protected unknowns (break targets, `'delayed` inputs, quantities whose `'dot` processes or
//!   thresholds read) stay;
//! * an unknown is never replaced by an expression of `now` (the error control must see it);
//! * replacements stay small (`MAX_REPLACEMENT` nodes), so substitution cannot blow up;
//! * a balance (a conservation law, which holds only to its tolerance) is solved for an unknown
//!   only where that cannot magnify the others' errors (see [`MAX_AMPLIFICATION`]), and never
//!   where it reads a derivative (a capacitor's `C v'` is `C / h` times `v` in a step: a node
//!   potential solved from it, behind 154 Ohm, once carried 140 of its tolerances).
//!
//! After the choices, a linear subtree in which an unknown cancels out (`a - (b - (-a))`, from
//! a chain of substitutions round a capacitor loop) is rebuilt with its terms merged, so the
//! cancellation is exact rather than rounding at the scale of the cancelled terms
//! ([`merge_terms`]).
//!
//! A property test (`tests/it/elimination.rs`) runs random circuits both ways.
//!
//! Preference: quantities before terminal potentials (so node potentials, not branch
//! quantities, remain), algebraic before differential.

use super::sym::{Bin, Sym, Un};

/// Largest replacement expression (nodes) worth substituting.
const MAX_REPLACEMENT: usize = 48;

/// The result of [`eliminate`], over the original unknown indices.
pub struct Elimination {
    /// For each original unknown, its replacement when eliminated (fully resolved: it reads
    /// only surviving unknowns).
    pub replacement: Vec<Option<Sym>>,
    /// The equation (assembly row) each eliminated unknown was solved from.
    pub solved_from: Vec<Option<usize>>,
    /// Assembly rows that remain equations, in assembly order, with their resolved residuals.
    pub kept: Vec<(usize, Sym)>,
}

/// What may be eliminated, per original unknown.
pub struct Candidates<'a> {
    /// Never eliminate these.
    pub protected: &'a [bool],
    /// True for terminal potentials (eliminated only after quantities).
    pub potential: &'a [bool],
    /// The absolute tolerance of each unknown: the scale on which its error is judged, so
    /// that coefficients of unknowns in different units compare (see [`MAX_AMPLIFICATION`]).
    pub abstol: &'a [f64],
    /// Per assembly row, the tolerance its residual is known to when it has one of its own (a
    /// conservation law balances through quantities: their group's tolerance).
    pub row_abstol: &'a [Option<f64>],
}

/// Largest factor by which solving an equation for an unknown may magnify the survivors'
/// errors, measured in tolerances: solving `a_u x_u + sum a_k x_k = 0` for `x_u` moves it by
/// `|a_k / a_u|` per unit of `x_k`, so `|a_k| abstol_k / (|a_u| abstol_u)` is how many of its
/// own tolerances `x_u` moves when `x_k` is off by its tolerance. The full system controls
/// `x_u`'s error directly; the reduced one only through the survivors, so a small pivot
/// (a node's voltage from a current balance across a 100 MOhm leak: 1e5) turns errors that
/// are within tolerance into wrong values. This is threshold pivoting with the rows and
/// columns scaled by the tolerances. A row with a tolerance of its own (a current balance)
/// counts it as one more term: the row holds only to that, so solving it for `x_u` leaves
/// `x_u` uncertain by `row_abstol / |a_u|` whatever the other terms (a diode's current,
/// a capacitor's `C v'`) contribute. Only such rows are refused: an equation without a
/// tolerance of its own (`v == r * i`) holds to rounding in the full system as in the reduced
/// one, so solving it for any unknown leaves the answer as it was (refusing `i = v / r` for
/// small resistors once turned an RC ladder's node potentials into sums over the whole line).
pub const MAX_AMPLIFICATION: f64 = 100.0;

/// Solves equations for unknowns where the rules above allow it, in assembly order.
pub fn eliminate(residuals: Vec<Sym>, candidates: &Candidates<'_>) -> Elimination {
    let n = candidates.protected.len();
    let mut differentiated = vec![false; n];
    for r in &residuals {
        r.visit(&mut |e| {
            if let Sym::Dot(j) = e {
                differentiated[*j] = true;
            }
        });
    }
    let mut state = Resolver {
        replacement: vec![None; n],
    };
    let mut solved_from = vec![None; n];
    let mut kept = Vec::new();
    for (row, r) in residuals.into_iter().enumerate() {
        let r = state.resolve(r);
        let row_abstol = candidates.row_abstol.get(row).copied().flatten();
        match choose(&r, candidates, row_abstol, &differentiated) {
            Some((j, replacement)) => {
                if differentiated[j] {
                    replacement.visit(&mut |e| {
                        if let Sym::X(k) = e {
                            differentiated[*k] = true;
                        }
                    });
                }
                state.replacement[j] = Some(replacement);
                solved_from[j] = Some(row);
            }
            None => kept.push((row, r)),
        }
    }
    // Equations kept early may read unknowns eliminated later.
    for (_, r) in &mut kept {
        *r = state.resolve(std::mem::replace(r, Sym::Const(0.0)));
    }
    for j in 0..n {
        if let Some(r) = state.replacement[j].take() {
            state.replacement[j] = Some(state.resolve(r));
        }
    }
    // Only now, so that the choices above are those of the equations as written.
    for (_, r) in &mut kept {
        *r = merge_terms(std::mem::replace(r, Sym::Const(0.0)));
    }
    for r in state.replacement.iter_mut().flatten() {
        *r = merge_terms(std::mem::replace(r, Sym::Const(0.0)));
    }
    Elimination {
        replacement: state.replacement,
        solved_from,
        kept,
    }
}

impl Elimination {
    /// `e` with every eliminated unknown replaced (stored replacements are resolved, so one
    /// pass suffices).
    pub fn apply(&self, e: &Sym) -> Sym {
        substitute(e, &mut |j| self.replacement[j].clone())
    }
}

/// `e` with `X(j)` replaced by `lookup(j)` where it gives one, and `Dot(j)` by that
/// replacement's time derivative (only affine replacements are stored for differentiated
/// unknowns, so it exists).
fn substitute(e: &Sym, lookup: &mut dyn FnMut(usize) -> Option<Sym>) -> Sym {
    match e {
        Sym::X(j) => lookup(*j).unwrap_or_else(|| e.clone()),
        Sym::Dot(j) => match lookup(*j) {
            Some(r) => time_derivative(&r).unwrap_or(Sym::Const(f64::NAN)),
            None => e.clone(),
        },
        Sym::Const(_) | Sym::Signal(_) | Sym::Now => e.clone(),
        Sym::Un(op, a) => Sym::un(*op, substitute(a, lookup)),
        Sym::Table(f, a) => Sym::table(f.clone(), substitute(a, lookup)),
        Sym::Bin(op, a, b) => {
            let a = substitute(a, lookup);
            Sym::bin(*op, a, substitute(b, lookup))
        }
        Sym::If(c, a, b) => {
            let (c, a) = (substitute(c, lookup), substitute(a, lookup));
            Sym::cond(c, a, substitute(b, lookup))
        }
    }
}

struct Resolver {
    replacement: Vec<Option<Sym>>,
}

impl Resolver {
    /// `e` with every eliminated unknown replaced (recursively); stores resolved replacements
    /// back so that chains are walked once. Takes `e` by value: a tree that reads nothing
    /// eliminated (most, early in assembly order) is returned as it is, not copied.
    fn resolve(&mut self, e: Sym) -> Sym {
        if !self.reads_eliminated(&e) {
            return e;
        }
        substitute(&e, &mut |j| self.resolved(j))
    }

    fn resolved(&mut self, j: usize) -> Option<Sym> {
        let stored = self.replacement[j].as_ref()?;
        if !self.reads_eliminated(stored) {
            return Some(stored.clone());
        }
        let r = self.replacement[j].take()?;
        let r = self.resolve(r);
        self.replacement[j] = Some(r.clone());
        Some(r)
    }

    /// True when `e` reads an eliminated unknown (most trees do not: checking is cheaper
    /// than rebuilding them).
    fn reads_eliminated(&self, e: &Sym) -> bool {
        let mut found = false;
        e.visit(&mut |n| {
            if let Sym::X(j) | Sym::Dot(j) = n {
                found |= self.replacement[*j].is_some();
            }
        });
        found
    }
}

/// The unknown to solve `e = 0` for and its replacement, if any qualifies.
fn choose(
    e: &Sym,
    candidates: &Candidates<'_>,
    row_abstol: Option<f64>,
    differentiated: &[bool],
) -> Option<(usize, Sym)> {
    // Occurrences of each unknown as x and as x' (equations are small: a linear scan).
    let mut seen: Vec<(usize, u32, u32)> = Vec::new();
    e.visit(&mut |node| {
        let (j, is_dot) = match node {
            Sym::X(j) => (*j, false),
            Sym::Dot(j) => (*j, true),
            _ => return,
        };
        let entry = match seen.iter().position(|s| s.0 == j) {
            Some(k) => &mut seen[k],
            None => {
                seen.push((j, 0, 0));
                seen.last_mut().expect("just pushed")
            }
        };
        if is_dot {
            entry.2 += 1;
        } else {
            entry.1 += 1;
        }
    });
    let rank = |j: usize| usize::from(candidates.potential[j]) * 2 + usize::from(differentiated[j]);
    // The constant coefficient of each unknown that occurs once, and the error scale of its
    // term `a_k x_k`; the largest scale in the row, its own tolerance included.
    let coefficients: Vec<Option<f64>> = seen
        .iter()
        .map(|&(k, xs, _)| if xs == 1 { coefficient(e, k) } else { None })
        .collect();
    let scale = |k: usize, a: Option<f64>| a.map_or(0.0, |a| a.abs() * candidates.abstol[k]);
    // A derivative's term `c x_k'` is `c alpha x_k` in a step, with `alpha` up to 1/h: at the
    // steps a run takes, its error scale has no bound this pass could compare with, so a
    // balance that reads one is solved for nothing (see [`MAX_AMPLIFICATION`]).
    let reads_derivative = seen.iter().any(|&(_, _, dots)| dots > 0);
    let largest = if row_abstol.is_some() && reads_derivative {
        f64::INFINITY
    } else {
        seen.iter()
            .zip(&coefficients)
            .fold(row_abstol.unwrap_or(0.0), |m, (&(k, _, _), &a)| {
                m.max(scale(k, a))
            })
    };
    let mut best: Option<(usize, f64, usize, Sym)> = None;
    for (&(j, xs, dots), &a) in seen.iter().zip(&coefficients) {
        if xs != 1 || dots != 0 || candidates.protected[j] {
            continue;
        }
        if best.as_ref().is_some_and(|b| b.0 < rank(j)) {
            continue;
        }
        let Some(a) = a else {
            continue;
        };
        if !(a.is_finite() && a != 0.0) {
            continue;
        }
        let amplification = largest / scale(j, Some(a));
        // Only a balance is held to a tolerance of its own; other equations hold to rounding in
        // the full system as in the reduced one. (A NaN amplification, from a zero tolerance,
        // never qualifies.)
        let acceptable = row_abstol.is_none() || amplification <= MAX_AMPLIFICATION;
        if !acceptable
            || best
                .as_ref()
                .is_some_and(|b| b.0 == rank(j) && b.1 <= amplification)
        {
            continue;
        }
        let rest = substitute_zero(e, j);
        let replacement = if a == 1.0 {
            Sym::neg(rest)
        } else if a == -1.0 {
            rest
        } else {
            Sym::div(Sym::neg(rest), Sym::Const(a))
        };
        // A quantity given as a function of time stays an unknown: the step-size control
        // must see how fast it moves (a source driving nothing else would otherwise allow
        // arbitrarily long steps, and its threshold crossings would be missed).
        if size(&replacement) > MAX_REPLACEMENT || replacement.any(|n| matches!(n, Sym::Now)) {
            continue;
        }
        // A differentiated unknown goes only as a scaled copy of one other (`v = 2e-6 * w`
        // behind a gear): its `'dot` then moves to that unknown alone. Spreading it over
        // several would make algebraic survivors differential, which a restart then holds
        // (a capacitor's voltage as a diode's junction voltage that must be free to jump).
        if differentiated[j] && affine(&replacement).is_none_or(|t| t.len() > 1) {
            continue;
        }
        // From a balance, its state would then live in the other unknown, whose tolerance must
        // not judge it far more finely than its own: an inductor's current as 1e-8 times the
        // potential of a node that only a 100 MOhm leak holds would be integrated to 1e-14 A,
        // and the step matrix, scaled in tolerances, turns singular. (A model's own relation,
        // `w1 == 3.0 * w2` behind a gear, is eliminated whatever the scales: keeping both
        // would leave a constraint between two states, of index 2.)
        if row_abstol.is_some()
            && differentiated[j]
            && affine(&replacement).is_some_and(|t| {
                t.iter().any(|&(k, c)| {
                    c.abs() * candidates.abstol[k] * MAX_AMPLIFICATION < candidates.abstol[j]
                })
            })
        {
            continue;
        }
        best = Some((rank(j), amplification, j, replacement));
    }
    best.map(|(_, _, j, r)| (j, r))
}

/// The constant coefficient of `X(j)` in `e`, when its single occurrence is in a linear
/// position (under `+`, `-`, negation, and products or quotients by constants).
fn coefficient(e: &Sym, j: usize) -> Option<f64> {
    match e {
        Sym::X(k) if *k == j => Some(1.0),
        Sym::Un(Un::Neg, a) => coefficient(a, j).map(|c| -c),
        Sym::Bin(Bin::Add, a, b) => coefficient(a, j).or_else(|| coefficient(b, j)),
        Sym::Bin(Bin::Sub, a, b) => coefficient(a, j).or_else(|| coefficient(b, j).map(|c| -c)),
        Sym::Bin(Bin::Mul, a, b) => match (a.as_const(), b.as_const()) {
            (Some(k), _) => coefficient(b, j).map(|c| k * c),
            (_, Some(k)) => coefficient(a, j).map(|c| k * c),
            _ => None,
        },
        Sym::Bin(Bin::Div, a, b) => b.as_const().and_then(|k| coefficient(a, j).map(|c| c / k)),
        _ => None,
    }
}

/// `e` with `X(j)` set to zero.
fn substitute_zero(e: &Sym, j: usize) -> Sym {
    match e {
        Sym::X(k) if *k == j => Sym::Const(0.0),
        Sym::Const(_) | Sym::X(_) | Sym::Dot(_) | Sym::Signal(_) | Sym::Now => e.clone(),
        Sym::Un(op, a) => Sym::un(*op, substitute_zero(a, j)),
        Sym::Table(f, a) => Sym::table(f.clone(), substitute_zero(a, j)),
        Sym::Bin(op, a, b) => Sym::bin(*op, substitute_zero(a, j), substitute_zero(b, j)),
        Sym::If(c, a, b) => Sym::cond(
            substitute_zero(c, j),
            substitute_zero(a, j),
            substitute_zero(b, j),
        ),
    }
}

/// Marks the unknowns that occur in `e` in a nonlinear position: anywhere but under sums,
/// negation, products and quotients by factors that read no unknown, and branches of a
/// condition that reads no unknown.
pub fn mark_nonlinear(e: &Sym, out: &mut [bool]) {
    fn all(e: &Sym, out: &mut [bool]) {
        e.visit(&mut |n| {
            if let Sym::X(j) | Sym::Dot(j) = n {
                out[*j] = true;
            }
        });
    }
    let free = |e: &Sym| !e.reads_unknown();
    match e {
        Sym::X(_) | Sym::Dot(_) | Sym::Const(_) | Sym::Signal(_) | Sym::Now => {}
        Sym::Un(Un::Neg, a) => mark_nonlinear(a, out),
        Sym::Bin(Bin::Add | Bin::Sub, a, b) => {
            mark_nonlinear(a, out);
            mark_nonlinear(b, out);
        }
        Sym::Bin(Bin::Mul, a, b) if free(a) => mark_nonlinear(b, out),
        Sym::Bin(Bin::Mul, a, b) if free(b) => mark_nonlinear(a, out),
        Sym::Bin(Bin::Div, a, b) if free(b) => mark_nonlinear(a, out),
        Sym::If(c, a, b) if free(c) => {
            mark_nonlinear(a, out);
            mark_nonlinear(b, out);
        }
        _ => all(e, out),
    }
}

/// Number of nodes of `e`.
pub fn size(e: &Sym) -> usize {
    let mut n = 0;
    e.visit(&mut |_| n += 1);
    n
}

/// `e` as `c0 + sum c_k x_k` with constant coefficients, if it has that form (the terms,
/// an unknown possibly more than once; no derivative may occur).
pub fn affine(e: &Sym) -> Option<Vec<(usize, f64)>> {
    let (mut c0, mut terms) = (0.0, Vec::new());
    if !linear_form(e, 1.0, &mut c0, &mut terms) {
        return None;
    }
    terms
        .into_iter()
        .map(|(v, c)| match v {
            Var::X(k) => Some((k, c)),
            Var::Dot(_) => None,
        })
        .collect()
}

/// A variable of a linear form: an unknown or its derivative.
#[derive(Clone, Copy, PartialEq)]
enum Var {
    X(usize),
    Dot(usize),
}

/// `e` as `c0 + sum c_k v_k` over unknowns and derivatives, accumulated into `c0` and
/// `terms` (an unknown may appear more than once), if it has that form.
fn linear_form(e: &Sym, scale: f64, c0: &mut f64, terms: &mut Vec<(Var, f64)>) -> bool {
    match e {
        Sym::Const(v) => {
            *c0 += scale * v;
            true
        }
        Sym::X(k) => {
            terms.push((Var::X(*k), scale));
            true
        }
        Sym::Dot(k) => {
            terms.push((Var::Dot(*k), scale));
            true
        }
        Sym::Un(Un::Neg, a) => linear_form(a, -scale, c0, terms),
        Sym::Bin(Bin::Add, a, b) => {
            linear_form(a, scale, c0, terms) && linear_form(b, scale, c0, terms)
        }
        Sym::Bin(Bin::Sub, a, b) => {
            linear_form(a, scale, c0, terms) && linear_form(b, -scale, c0, terms)
        }
        Sym::Bin(Bin::Mul, a, b) => match (a.as_const(), b.as_const()) {
            (Some(k), _) => linear_form(b, scale * k, c0, terms),
            (_, Some(k)) => linear_form(a, scale * k, c0, terms),
            _ => false,
        },
        Sym::Bin(Bin::Div, a, b) => match b.as_const() {
            Some(k) => linear_form(a, scale / k, c0, terms),
            None => false,
        },
        _ => false,
    }
}

/// `e` with every largest linear subtree in which an unknown cancels out rebuilt with its
/// terms merged. Substitution chains produce such trees (`v(n1) = e2.v - (e4.v - (-e2.v))` around a
/// capacitor loop): evaluated as written, the two `e2.v` cancel only to rounding, and with a
/// capacitor charged to 46 kV that rounding (5e-12 V) is more than a source's tolerance, so
/// Newton never converged. Merged, `e2.v` drops out exactly.
pub fn merge_terms(e: Sym) -> Sym {
    let (mut c0, mut terms) = (0.0, Vec::new());
    if linear_form(&e, 1.0, &mut c0, &mut terms) {
        let mut merged: Vec<(Var, f64)> = Vec::with_capacity(terms.len());
        for &(v, c) in &terms {
            match merged.iter_mut().find(|(w, _)| *w == v) {
                Some((_, sum)) => *sum += c,
                None => merged.push((v, c)),
            }
        }
        if !merged.iter().any(|&(_, c)| c == 0.0) {
            // Nothing cancels: the tree stays as written (rebuilding it would only move
            // rounding around).
            return e;
        }
        let mut sum: Option<Sym> = None;
        for (v, c) in merged.into_iter().filter(|&(_, c)| c != 0.0) {
            let x = match v {
                Var::X(k) => Sym::X(k),
                Var::Dot(k) => Sym::Dot(k),
            };
            sum = Some(match sum {
                None => Sym::mul(Sym::Const(c), x),
                Some(s) if c < 0.0 => Sym::sub(s, Sym::mul(Sym::Const(-c), x)),
                Some(s) => Sym::add(s, Sym::mul(Sym::Const(c), x)),
            });
        }
        return Sym::add(sum.unwrap_or(Sym::Const(0.0)), Sym::Const(c0));
    }
    match e {
        Sym::Un(op, a) => Sym::un(op, merge_terms(*a)),
        Sym::Table(f, a) => Sym::table(f, merge_terms(*a)),
        Sym::Bin(op, a, b) => Sym::bin(op, merge_terms(*a), merge_terms(*b)),
        Sym::If(c, a, b) => Sym::cond(merge_terms(*c), merge_terms(*a), merge_terms(*b)),
        other => other,
    }
}

/// `d e / dt` for an affine `e` (a combination of `'dot`s), else `None`.
pub fn time_derivative(e: &Sym) -> Option<Sym> {
    let terms = affine(e)?;
    Some(
        terms
            .into_iter()
            .map(|(k, c)| Sym::mul(Sym::Const(c), Sym::Dot(k)))
            .fold(Sym::Const(0.0), Sym::add),
    )
}

/// Renames unknown `k` to `map(k)` (for `X` and `Dot`) in place.
pub fn renumber_in_place(e: &mut Sym, map: &dyn Fn(usize) -> usize) {
    match e {
        Sym::X(k) | Sym::Dot(k) => *k = map(*k),
        Sym::Const(_) | Sym::Signal(_) | Sym::Now => {}
        Sym::Un(_, a) | Sym::Table(_, a) => renumber_in_place(a, map),
        Sym::Bin(_, a, b) => {
            renumber_in_place(a, map);
            renumber_in_place(b, map);
        }
        Sym::If(c, a, b) => {
            renumber_in_place(c, map);
            renumber_in_place(a, map);
            renumber_in_place(b, map);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn x(j: usize) -> Sym {
        Sym::X(j)
    }

    fn c(v: f64) -> Sym {
        Sym::Const(v)
    }

    fn free(n: usize) -> (Vec<bool>, Vec<bool>) {
        (vec![false; n], vec![false; n])
    }

    #[test]
    fn coefficient_follows_linear_positions_only() {
        // 2 * (x0 - 3 * x1) / 4
        let e = Sym::div(
            Sym::mul(c(2.0), Sym::sub(x(0), Sym::mul(c(3.0), x(1)))),
            c(4.0),
        );
        assert_eq!(coefficient(&e, 0), Some(0.5));
        assert_eq!(coefficient(&e, 1), Some(-1.5));
        let nonlinear = Sym::mul(x(0), x(1));
        assert_eq!(coefficient(&nonlinear, 0), None);
        let switched = Sym::cond(Sym::bin(Bin::Gt, x(0), c(0.0)), x(1), c(1.0));
        assert_eq!(coefficient(&switched, 0), None);
    }

    #[test]
    fn resistor_and_across_definition_leave_the_node_potentials() {
        // unknowns: 0 v(a), 1 v(b), 2 r.v, 3 r.i; equations: r.v - 2 r.i, r.v - (v(a) - v(b)),
        // v(a) - 1, r.i + v(b) (a made-up closure so the system is square).
        let residuals = vec![
            Sym::sub(x(2), Sym::mul(c(2.0), x(3))),
            Sym::sub(x(2), Sym::sub(x(0), x(1))),
            Sym::sub(x(0), c(1.0)),
            Sym::add(x(3), x(1)),
        ];
        let (protected, mut potential) = free(4);
        potential[0] = true;
        potential[1] = true;
        let out = eliminate(
            residuals,
            &Candidates {
                protected: &protected,
                potential: &potential,
                abstol: &[1.0; 4][..potential.len()],
                row_abstol: &[],
            },
        );
        let eliminated: Vec<bool> = out.replacement.iter().map(Option::is_some).collect();
        assert_eq!(eliminated, [true, false, true, true]);
        assert_eq!(out.kept.len(), 1);
        // The kept equation is r.i + v(b) with r.i = (1 - v(b)) / 2: (1 - v(b)) / 2 + v(b).
        let (row, r) = &out.kept[0];
        assert_eq!(*row, 3);
        let value = |vb: f64| r.eval(0.0, &[f64::NAN, vb, f64::NAN, f64::NAN], &[0.0; 4], &[]);
        assert!((value(-1.0) - 0.0).abs() < 1e-15);
        assert!((value(0.0) - 0.5).abs() < 1e-15);
    }

    #[test]
    fn repeated_terms_cancel_exactly() {
        // a - (b - (-a)) with a = 46 kV: as written it keeps 5e-12 of rounding; merged, -b.
        let e = Sym::sub(x(0), Sym::sub(x(1), Sym::neg(x(0))));
        let merged = merge_terms(e.clone());
        let at = |s: &Sym| s.eval(0.0, &[-46_444.685_993_452_16, 1.0e-6], &[0.0; 2], &[]);
        assert_eq!(at(&merged), -1.0e-6);
        assert_ne!(at(&e), -1.0e-6, "the unmerged form rounds");
        // Where nothing cancels the tree is left as it is.
        let once = Sym::sub(x(0), Sym::mul(c(2.0), x(1)));
        assert_eq!(merge_terms(once.clone()), once);
        let twice = Sym::add(x(0), Sym::sub(x(1), Sym::mul(c(0.5), x(0))));
        assert_eq!(merge_terms(twice.clone()), twice);
    }

    #[test]
    fn differentiated_unknowns_need_affine_replacements() {
        // x0' + x0 = 0 keeps x0; x1 - x0 * x0 = 0 with x1' read elsewhere keeps x1.
        let residuals = vec![
            Sym::add(Sym::Dot(0), x(0)),
            Sym::sub(x(1), Sym::mul(x(0), x(0))),
            Sym::sub(Sym::Dot(1), c(1.0)),
        ];
        let (protected, potential) = free(2);
        let out = eliminate(
            residuals,
            &Candidates {
                protected: &protected,
                potential: &potential,
                abstol: &[1.0; 4][..potential.len()],
                row_abstol: &[],
            },
        );
        assert!(out.replacement.iter().all(Option::is_none));
        assert_eq!(out.kept.len(), 3);
    }

    #[test]
    fn scaled_copy_carries_the_derivative() {
        // x0 - 2 x1 = 0 with x0' used and x1 a potential: x0' becomes 2 x1'.
        let residuals = vec![Sym::sub(x(0), Sym::mul(c(2.0), x(1))), Sym::Dot(0)];
        let protected = [false; 2];
        let potential = [false, true];
        let out = eliminate(
            residuals,
            &Candidates {
                protected: &protected,
                potential: &potential,
                abstol: &[1.0; 4][..potential.len()],
                row_abstol: &[],
            },
        );
        assert!(out.replacement[0].is_some());
        let r = &out.kept[0].1;
        assert_eq!(r.eval(0.0, &[0.0; 2], &[0.0, 5.0], &[]), 10.0);
    }

    #[test]
    fn differentiated_unknowns_are_not_spread_over_several() {
        // x0 - (x1 - x2) = 0 with x0' used: x1 goes (x1 = x0 + x2), x0 stays differential.
        let residuals = vec![Sym::sub(x(0), Sym::sub(x(1), x(2))), Sym::Dot(0)];
        let protected = [false; 3];
        let potential = [false, true, true];
        let out = eliminate(
            residuals,
            &Candidates {
                protected: &protected,
                potential: &potential,
                abstol: &[1.0; 4][..potential.len()],
                row_abstol: &[],
            },
        );
        let eliminated: Vec<bool> = out.replacement.iter().map(Option::is_some).collect();
        assert_eq!(eliminated, [false, true, false]);
    }

    #[test]
    fn small_pivots_measured_in_tolerances_are_refused() {
        // g * v(a) - i = 0 as a current balance (tolerance 1e-9 A) with i an inductor's
        // current (kept): v(a) = i / g is a node voltage from the balance. Across a 100 Ohm
        // conductance a current error of its tolerance moves v(a) by 1e-7 V, a tenth of its
        // own; across a 100 MOhm leak by 0.1 V, 1e5 of its tolerances: that unknown must stay.
        // The same relation as a branch equation (no tolerance of its own) holds exactly in
        // the full system too, so solving it changes nothing, whatever the pivot.
        for (g, balance, eliminated) in
            [(1e-2, true, true), (1e-8, true, false), (1e-8, false, true)]
        {
            let residuals = vec![Sym::sub(Sym::mul(c(g), x(0)), x(1))];
            let out = eliminate(
                residuals,
                &Candidates {
                    protected: &[false, true],
                    potential: &[true, false],
                    abstol: &[1e-6, 1e-9],
                    row_abstol: &[balance.then_some(1e-9)],
                },
            );
            assert_eq!(
                out.replacement[0].is_some(),
                eliminated,
                "g = {g}, balance: {balance}"
            );
        }
    }

    #[test]
    fn among_equal_ranks_the_best_conditioned_pivot_wins() {
        // v - r i = 0 with r = 0.01: i = v / r would carry v's error 1e5 times in tolerances;
        // v = r i carries none, so v goes.
        let residuals = vec![Sym::sub(x(0), Sym::mul(c(0.01), x(1)))];
        let out = eliminate(
            residuals,
            &Candidates {
                protected: &[false, false],
                potential: &[false, false],
                abstol: &[1e-6, 1e-9],
                row_abstol: &[],
            },
        );
        assert!(out.replacement[0].is_some());
        assert!(out.replacement[1].is_none());
    }

    #[test]
    fn protected_unknowns_stay() {
        let residuals = vec![Sym::sub(x(0), c(1.0))];
        let out = eliminate(
            residuals,
            &Candidates {
                protected: &[true],
                potential: &[false],
                abstol: &[1.0],
                row_abstol: &[],
            },
        );
        assert!(out.replacement[0].is_none());
        assert_eq!(out.kept.len(), 1);
    }
}
