//! Index reduction: Pantelides' algorithm finds the equations a high-index system hides
//! derivatives of (a position constraint in a mechanism, a rigid gear, an inductor cut-set
//! driven by a current source), differentiates them symbolically, and the dummy-derivative
//! method of Mattsson and Söderlind chooses which derivatives become algebraic unknowns, so
//! that the integrator sees an index-1 system that still satisfies every original equation
//! (no drift off the constraints, unlike integrating the differentiated ones alone).
//!
//! Works on the assembled system, before elimination, so `vams dae` can show the model's own
//! equations differentiated. Variables are `(unknown, order)` pairs; an equation is a residual
//! over them (`Sym::X` of a variable index, never `Sym::Dot`) until [`Reduction::assemble`]
//! writes the chosen first-order form: a derivative kept as a state is `'dot` of the order
//! below it, a dummy derivative is an unknown of its own.

use super::build::{Assembled, Origin, Unknown};
use super::deriv::{Var, derivative};
use super::structure::{Incidence, maximum_matching};
use super::sym::{Sym, Un};

/// Differentiations allowed per equation before the system counts as structurally singular
/// (a mechanism's position constraint needs two; Pantelides terminates on any structurally
/// regular system, so this only guards against one that is not).
const MAX_ORDER: usize = 6;

/// An `order`-th time derivative of assembled unknown `unknown`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Variable {
    unknown: usize,
    order: usize,
}

/// An equation or one of its derivatives.
#[derive(Clone, Debug)]
struct Equation {
    /// Index of the assembled equation this is a derivative of.
    base: usize,
    order: usize,
    /// Residual over variable indices (`Sym::X(v)`).
    residual: Sym,
    /// The variables the residual reads (structurally).
    incidence: Vec<usize>,
}

/// Why the system could not be reduced.
#[derive(Debug, PartialEq)]
pub enum IndexError {
    /// Equation `equation` still had no unknown of its own after [`MAX_ORDER`]
    /// differentiations.
    Singular { equation: usize },
    /// Equation `equation` reads a `'delayed` history, whose derivative is not known.
    Delayed { equation: usize },
}

/// What Pantelides found: every variable and equation of the differentiated system.
pub struct Reduction {
    variables: Vec<Variable>,
    /// The next higher derivative of each variable, once created.
    derivative: Vec<Option<usize>>,
    /// The variable each one is the derivative of.
    antiderivative: Vec<Option<usize>>,
    equations: Vec<Equation>,
    /// The next derivative of each equation, once created.
    differentiated: Vec<Option<usize>>,
    /// The equation each one is the derivative of.
    integrated: Vec<Option<usize>>,
    /// Variables from this index on were made by differentiation.
    first_created: usize,
    /// Assembled unknowns and equations.
    unknowns: usize,
    base_equations: usize,
}

/// The derivative variables chosen as dummies (algebraic unknowns), by variable index.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Selection(Vec<bool>);

/// A residual over assembled slots rewritten over variables: `x` is order 0, `x'` order 1.
fn over_variables(e: &Sym, first_derivative: &[Option<usize>]) -> Sym {
    match e {
        Sym::X(j) => Sym::X(*j),
        // Every `Dot(j)` got its variable when the variables were made.
        Sym::Dot(j) => Sym::X(first_derivative[*j].unwrap_or(usize::MAX)),
        Sym::Const(_) | Sym::Signal(_) | Sym::Now => e.clone(),
        Sym::Un(op, a) => Sym::Un(*op, Box::new(over_variables(a, first_derivative))),
        Sym::Table(f, a) => Sym::Table(f.clone(), Box::new(over_variables(a, first_derivative))),
        Sym::Bin(op, a, b) => Sym::Bin(
            *op,
            Box::new(over_variables(a, first_derivative)),
            Box::new(over_variables(b, first_derivative)),
        ),
        Sym::If(c, a, b) => Sym::If(
            Box::new(over_variables(c, first_derivative)),
            Box::new(over_variables(a, first_derivative)),
            Box::new(over_variables(b, first_derivative)),
        ),
    }
}

fn incidence_of(e: &Sym) -> Vec<usize> {
    let mut v = Vec::new();
    e.structural_unknowns(&mut v);
    v.sort_unstable();
    v.dedup();
    v
}

/// True when every equation matches an unknown it reads at that unknown's highest
/// derivative (`x'` where the model writes one, else `x`): index 0 or 1, Pantelides' first
/// pass, by one maximum matching and without copying a residual (a 100 000-section ladder).
fn matched_at_highest_derivatives(residuals: &[Sym], first_derivative: &[Option<usize>]) -> bool {
    fn highest(e: &Sym, has_dot: &[Option<usize>], out: &mut Vec<usize>) {
        match e {
            Sym::X(j) if has_dot[*j].is_none() => out.push(*j),
            Sym::Dot(j) => out.push(*j),
            Sym::X(_) | Sym::Const(_) | Sym::Signal(_) | Sym::Now => {}
            Sym::Un(Un::Not | Un::Floor | Un::Ceil | Un::Round | Un::Trunc | Un::Sign, _) => {}
            Sym::Un(_, a) => highest(a, has_dot, out),
            Sym::Table(f, _) if f.slope => {}
            Sym::Table(_, a) => highest(a, has_dot, out),
            Sym::Bin(op, _, _) if op.is_logical() => {}
            Sym::Bin(_, a, b) | Sym::If(_, a, b) => {
                highest(a, has_dot, out);
                highest(b, has_dot, out);
            }
        }
    }
    let mut pattern = Vec::new();
    let mut cols = Vec::new();
    for (row, r) in residuals.iter().enumerate() {
        cols.clear();
        highest(r, first_derivative, &mut cols);
        cols.sort_unstable();
        cols.dedup();
        pattern.extend(cols.iter().map(|&c| (row, c)));
    }
    let inc = Incidence::new(residuals.len(), first_derivative.len(), &pattern);
    maximum_matching(&inc).row_match.iter().all(Option::is_some)
}

/// Replaces `Sym::X(v)` by `rep(v)`.
fn substitute(e: &Sym, rep: &dyn Fn(usize) -> Sym) -> Sym {
    match e {
        Sym::X(v) => rep(*v),
        Sym::Const(_) | Sym::Signal(_) | Sym::Now | Sym::Dot(_) => e.clone(),
        Sym::Un(op, a) => Sym::un(*op, substitute(a, rep)),
        Sym::Table(f, a) => Sym::table(f.clone(), substitute(a, rep)),
        Sym::Bin(op, a, b) => Sym::bin(*op, substitute(a, rep), substitute(b, rep)),
        Sym::If(c, a, b) => Sym::cond(substitute(c, rep), substitute(a, rep), substitute(b, rep)),
    }
}

impl Reduction {
    /// Pantelides' algorithm on `residuals` over `unknowns` assembled unknowns. `Ok(None)`: the
    /// system has index 0 or 1 as written (every equation matched to an unknown it reads at
    /// its highest derivative), which is almost every model and costs one matching.
    /// `history_from`: the first signal slot that is a `'delayed` history; `time_slot`: the
    /// flag that is 1 while time runs (0 at the quiescent point, where time stands still, so
    /// a source's derivative in time is zero there like every other derivative).
    pub fn find(
        residuals: &[Sym],
        unknowns: usize,
        history_from: usize,
        time_slot: usize,
    ) -> Result<Option<Reduction>, IndexError> {
        let mut first_derivative = vec![None; unknowns];
        let mut variables: Vec<Variable> = (0..unknowns)
            .map(|unknown| Variable { unknown, order: 0 })
            .collect();
        for r in residuals {
            r.visit(&mut |e| {
                if let Sym::Dot(j) = e
                    && first_derivative[*j].is_none()
                {
                    first_derivative[*j] = Some(variables.len());
                    variables.push(Variable {
                        unknown: *j,
                        order: 1,
                    });
                }
            });
        }
        if matched_at_highest_derivatives(residuals, &first_derivative) {
            return Ok(None);
        }
        let mut derivative = vec![None; variables.len()];
        derivative[..unknowns].copy_from_slice(&first_derivative);
        let mut antiderivative = vec![None; variables.len()];
        for (j, d) in first_derivative.iter().enumerate() {
            if let Some(d) = *d {
                antiderivative[d] = Some(j);
            }
        }
        let equations = residuals
            .iter()
            .enumerate()
            .map(|(base, r)| {
                let residual = over_variables(r, &first_derivative);
                Equation {
                    base,
                    order: 0,
                    incidence: incidence_of(&residual),
                    residual,
                }
            })
            .collect::<Vec<_>>();
        let mut this = Reduction {
            differentiated: vec![None; equations.len()],
            integrated: vec![None; equations.len()],
            first_created: variables.len(),
            variables,
            derivative,
            antiderivative,
            equations,
            unknowns,
            base_equations: residuals.len(),
        };
        let mut assign: Vec<Option<usize>> = vec![None; this.variables.len()];
        let mut reduced = false;
        let mut colored_eq = vec![false; this.equations.len()];
        let mut colored_var = vec![false; this.variables.len()];
        let mut touched = Touched::default();
        for k in 0..this.base_equations {
            let mut i = k;
            loop {
                touched.clear(&mut colored_eq, &mut colored_var);
                colored_eq.resize(this.equations.len(), false);
                colored_var.resize(this.variables.len(), false);
                if this.augment(
                    i,
                    &mut assign,
                    &mut colored_eq,
                    &mut colored_var,
                    &mut touched,
                ) {
                    break;
                }
                reduced = true;
                if this.equations[i].order >= MAX_ORDER {
                    return Err(IndexError::Singular {
                        equation: this.equations[i].base,
                    });
                }
                // Every highest variable of a colored equation is colored: give each its
                // next derivative, then differentiate the colored equations.
                for &v in &touched.vars {
                    this.new_derivative(v);
                }
                for &e in &touched.eqs {
                    this.differentiate(e, history_from, time_slot)?;
                }
                // Differentiation may have made derivatives of lower variables too.
                assign.resize(this.variables.len(), None);
                for &v in &touched.vars {
                    let (Some(dv), Some(e)) = (this.derivative[v], assign[v]) else {
                        continue;
                    };
                    assign[dv] = this.differentiated[e];
                }
                // The equation being matched was colored, so it has its derivative.
                i = this.differentiated[i].unwrap_or(i);
            }
        }
        Ok(reduced.then_some(this))
    }

    /// True when the model itself writes `'dot` of assembled unknown `j`.
    fn first_derivative_written(&self, j: usize) -> bool {
        self.derivative[j].is_some_and(|d| d < self.first_created)
    }

    fn is_highest(&self, v: usize) -> bool {
        self.derivative[v].is_none()
    }

    /// An augmenting path from equation `root` over highest derivatives (iterative, so a
    /// long chain cannot exhaust the stack).
    fn augment(
        &self,
        root: usize,
        assign: &mut [Option<usize>],
        colored_eq: &mut [bool],
        colored_var: &mut [bool],
        touched: &mut Touched,
    ) -> bool {
        // (equation, next incidence position, variable that led here)
        let mut stack: Vec<(usize, usize, usize)> = vec![(root, 0, usize::MAX)];
        colored_eq[root] = true;
        touched.eqs.push(root);
        while let Some(&mut (e, ref mut pos, _)) = stack.last_mut() {
            if *pos == 0
                && let Some(&free) = self.equations[e]
                    .incidence
                    .iter()
                    .find(|&&v| self.is_highest(v) && assign[v].is_none())
            {
                assign[free] = Some(e);
                for f in (1..stack.len()).rev() {
                    assign[stack[f].2] = Some(stack[f - 1].0);
                }
                return true;
            }
            let inc = &self.equations[e].incidence;
            let next = (*pos..inc.len()).find(|&k| {
                let v = inc[k];
                self.is_highest(v) && !colored_var[v]
            });
            match next {
                Some(k) => {
                    *pos = k + 1;
                    let v = inc[k];
                    colored_var[v] = true;
                    touched.vars.push(v);
                    // Not free (checked on arrival), so matched.
                    if let Some(owner) = assign[v]
                        && !colored_eq[owner]
                    {
                        colored_eq[owner] = true;
                        touched.eqs.push(owner);
                        stack.push((owner, 0, v));
                    }
                }
                None => {
                    stack.pop();
                }
            }
        }
        false
    }

    fn new_derivative(&mut self, v: usize) -> usize {
        if let Some(d) = self.derivative[v] {
            return d;
        }
        let d = self.variables.len();
        let Variable { unknown, order } = self.variables[v];
        self.variables.push(Variable {
            unknown,
            order: order + 1,
        });
        self.derivative.push(None);
        self.antiderivative.push(Some(v));
        self.derivative[v] = Some(d);
        d
    }

    /// Appends `d/dt` of equation `e`: the chain rule over its variables, plus its explicit
    /// dependence on `now`. Signals are constant between events (a restart follows each).
    fn differentiate(
        &mut self,
        e: usize,
        history_from: usize,
        time_slot: usize,
    ) -> Result<usize, IndexError> {
        if let Some(d) = self.differentiated[e] {
            return Ok(d);
        }
        let eq = self.equations[e].clone();
        if eq
            .residual
            .any(|n| matches!(n, Sym::Signal(s) if *s >= history_from))
        {
            return Err(IndexError::Delayed { equation: eq.base });
        }
        let mut reads = Vec::new();
        eq.residual.visit(&mut |n| {
            if let Sym::X(v) = n {
                reads.push(*v);
            }
        });
        reads.sort_unstable();
        reads.dedup();
        let mut residual = match derivative(&eq.residual, Var::Now) {
            d if d.is_const(0.0) => d,
            // Already under the flag (a second derivative): flag * flag is the flag.
            d if d.any(|n| *n == Sym::Signal(time_slot)) => d,
            d => Sym::mul(Sym::Signal(time_slot), d),
        };
        for v in reads {
            let partial = derivative(&eq.residual, Var::X(v));
            if partial.is_const(0.0) {
                continue;
            }
            let dv = self.new_derivative(v);
            residual = Sym::add(residual, Sym::mul(partial, Sym::X(dv)));
        }
        let d = self.equations.len();
        self.equations.push(Equation {
            base: eq.base,
            order: eq.order + 1,
            incidence: incidence_of(&residual),
            residual,
        });
        self.differentiated.push(None);
        self.integrated.push(Some(e));
        self.differentiated[e] = Some(d);
        Ok(d)
    }

    /// The highest number of differentiations of any equation plus one: the structural index.
    pub fn index(&self) -> usize {
        self.equations.iter().map(|e| e.order).max().unwrap_or(0) + 1
    }

    /// Mattsson and Söderlind's choice of dummy derivatives, by the Jacobians of the
    /// differentiated equations at `point` (a value per variable: the assembled unknowns'
    /// values, derivatives zero): starting from the most differentiated equations and the
    /// highest derivatives, the columns of a regular square block (complete pivoting, so the
    /// block is as well conditioned as the point allows) become dummies; then one order down,
    /// among the antiderivatives of those chosen.
    /// `held`: per assembled unknown, whether a break sets it at the start; such unknowns
    /// stay states where the point allows (the break says where the model starts).
    pub fn select(&self, unknown_values: &[f64], held: &[bool], signals: &[f64]) -> Selection {
        let values = self.variable_values(unknown_values, &[]);
        let mut dummy = vec![false; self.variables.len()];
        self.levels(|rows, cols| {
            let chosen = self.regular_columns(rows, cols, &values, held, signals);
            for &c in &chosen {
                dummy[c] = true;
            }
            chosen
        });
        Selection(dummy)
    }

    /// How firmly `selection` determines its dummies at the point: the smallest over the
    /// levels of `|det M| / prod(row norms of M)` for the chosen block `M` (1 for orthogonal
    /// rows, 0 when singular). A pendulum's choice of `y` as the dummy loses its grip as the
    /// rod nears the horizontal.
    pub fn grip(
        &self,
        selection: &Selection,
        unknown_values: &[f64],
        unknown_derivatives: &[f64],
        signals: &[f64],
    ) -> f64 {
        let values = self.variable_values(unknown_values, unknown_derivatives);
        let mut grip = 1.0_f64;
        self.levels(|rows, cols| {
            let chosen: Vec<usize> = cols.iter().copied().filter(|&c| selection.0[c]).collect();
            grip = grip.min(det_ratio(self.jacobian(rows, &chosen, &values, signals)));
            chosen
        });
        grip
    }

    /// The value of every variable: the unknowns' and their first derivatives' where given,
    /// higher derivatives zero.
    fn variable_values(&self, unknowns: &[f64], derivatives: &[f64]) -> Vec<f64> {
        (self.variables.iter())
            .map(|var| match var.order {
                0 => unknowns.get(var.unknown).copied().unwrap_or(0.0),
                1 => derivatives.get(var.unknown).copied().unwrap_or(0.0),
                _ => 0.0,
            })
            .collect()
    }

    /// Mattsson and Söderlind's levels: `choose(rows, cols)` picks the dummies among `cols`
    /// for the differentiated equations `rows`, from the most differentiated down; the next
    /// level has the equations these are derivatives of and the variables the chosen ones
    /// are derivatives of, both while still differentiated.
    fn levels(&self, mut choose: impl FnMut(&[usize], &[usize]) -> Vec<usize>) {
        let mut rows: Vec<usize> = (0..self.equations.len())
            .filter(|&e| self.equations[e].order > 0 && self.differentiated[e].is_none())
            .collect();
        let mut cols: Vec<usize> = (0..self.variables.len())
            .filter(|&v| self.variables[v].order > 0 && self.is_highest(v))
            .collect();
        while !rows.is_empty() {
            let chosen = choose(&rows, &cols);
            rows = rows
                .iter()
                .filter_map(|&e| self.integrated[e])
                .filter(|&p| self.equations[p].order > 0)
                .collect();
            cols = chosen
                .iter()
                .filter_map(|&c| self.antiderivative[c])
                .filter(|&p| self.variables[p].order > 0)
                .collect();
        }
    }

    /// The Jacobian of equations `rows` by variables `cols` at `values`.
    fn jacobian(
        &self,
        rows: &[usize],
        cols: &[usize],
        values: &[f64],
        signals: &[f64],
    ) -> Vec<Vec<f64>> {
        rows.iter()
            .map(|&e| {
                cols.iter()
                    .map(|&v| {
                        let d = derivative(&self.equations[e].residual, Var::X(v));
                        let value = d.eval(0.0, values, &[], signals);
                        if value.is_finite() { value } else { 0.0 }
                    })
                    .collect()
            })
            .collect()
    }

    /// `rows.len()` columns of `cols` whose block of the Jacobian is regular at `values`.
    /// Falls back to the structure (entries as if generic) where the point makes every
    /// candidate block singular, as at an all-zero initial guess.
    fn regular_columns(
        &self,
        rows: &[usize],
        cols: &[usize],
        values: &[f64],
        held: &[bool],
        signals: &[f64],
    ) -> Vec<usize> {
        let numeric = self.jacobian(rows, cols, values, signals);
        // Dummies are taken first from derivatives of unknowns no break sets, and among those
        // from the derivatives differentiation created before those the model wrote: the
        // model's own states stay states where the point allows it (the pendulum keeps x, u
        // or y, v, rather than making x'dot a state of its own; two inductors in series keep
        // the current the model breaks).
        let preferred: Vec<u8> = cols
            .iter()
            .map(|&v| {
                let var = self.variables[v];
                let created = var.order > usize::from(self.first_derivative_written(var.unknown));
                let free = !held.get(var.unknown).copied().unwrap_or(false);
                u8::from(free) * 2 + u8::from(created)
            })
            .collect();
        if let Some(chosen) = pivot_columns(numeric, &preferred) {
            return chosen.into_iter().map(|k| cols[k]).collect();
        }
        // Generic values on the structure: distinct, so no accidental cancellation.
        let generic: Vec<Vec<f64>> = rows
            .iter()
            .enumerate()
            .map(|(i, &e)| {
                cols.iter()
                    .enumerate()
                    .map(|(k, v)| match self.equations[e].incidence.contains(v) {
                        true => 1.0 + ((i * 7919 + k * 104_729) % 1000) as f64 / 997.0,
                        false => 0.0,
                    })
                    .collect()
            })
            .collect();
        pivot_columns(generic, &preferred)
            .map(|chosen| chosen.into_iter().map(|k| cols[k]).collect())
            // Pantelides left the block structurally regular; keep the first columns if not.
            .unwrap_or_else(|| cols.iter().copied().take(rows.len()).collect())
    }

    /// The assembled system in the chosen first-order form: the original unknowns, then one
    /// unknown per dummy derivative and per intermediate derivative kept as a state (a second
    /// derivative that is a state needs the first as an unknown); the original equations,
    /// then their derivatives, then `x'dot - x1 = 0` for each intermediate state.
    pub fn assemble(&self, asm: &Assembled, selection: &Selection) -> Assembled {
        let dummy = &selection.0;
        // Highest order kept as a state, per unknown.
        let mut state_order = vec![0usize; self.unknowns];
        for (v, var) in self.variables.iter().enumerate() {
            if var.order > 0 && !dummy[v] {
                state_order[var.unknown] = state_order[var.unknown].max(var.order);
            }
        }
        let mut unknowns = asm.unknowns.clone();
        // Slot of each variable that is an unknown of its own (orders 1 and up).
        let mut slot: Vec<Option<usize>> = vec![None; self.variables.len()];
        for (v, var) in self.variables.iter().enumerate() {
            if var.order == 0 {
                slot[v] = Some(var.unknown);
            } else if dummy[v] || var.order < state_order[var.unknown] {
                slot[v] = Some(unknowns.len());
                unknowns.push(Unknown::Derivative {
                    of: var.unknown as u32,
                    order: var.order as u8,
                });
            }
        }
        let below = |v: usize| self.antiderivative[v];
        let rep = |v: usize| -> Sym {
            match slot[v] {
                Some(s) => Sym::X(s),
                // A state derivative: `'dot` of the order below, which has a slot.
                None => match below(v).and_then(|p| slot[p]) {
                    Some(s) => Sym::Dot(s),
                    None => Sym::Const(f64::NAN),
                },
            }
        };
        let mut residuals = Vec::with_capacity(self.equations.len());
        let mut origins = Vec::with_capacity(self.equations.len());
        for eq in &self.equations {
            residuals.push(substitute(&eq.residual, &rep));
            origins.push(match eq.order {
                0 => asm.origins[eq.base],
                order => Origin::Differentiated {
                    of: eq.base as u32,
                    order: order as u8,
                },
            });
        }
        for (v, var) in self.variables.iter().enumerate() {
            if var.order == 0 || dummy[v] || var.order >= state_order[var.unknown] {
                continue;
            }
            // An intermediate state `x1 = x'`: `'dot` of the order below minus itself.
            if let (Some(s), Some(p)) = (slot[v], below(v).and_then(|p| slot[p])) {
                residuals.push(Sym::sub(Sym::Dot(p), Sym::X(s)));
                origins.push(Origin::StateChain {
                    of: var.unknown as u32,
                });
            }
        }
        Assembled {
            unknowns,
            quantity_slot: asm.quantity_slot.clone(),
            residuals,
            origins,
        }
    }

    #[cfg(test)]
    /// The equations this reduction differentiated, with how often, by assembled index.
    pub fn differentiations(&self) -> Vec<(usize, usize)> {
        let mut out = vec![0; self.base_equations];
        for e in &self.equations {
            out[e.base] = out[e.base].max(e.order);
        }
        out.into_iter()
            .enumerate()
            .filter(|&(_, c)| c > 0)
            .collect()
    }
}

/// The equations and variables an augmenting-path search colored, to clear them for the
/// next search without sweeping every flag (a large circuit matches thousands of equations).
#[derive(Default)]
struct Touched {
    eqs: Vec<usize>,
    vars: Vec<usize>,
}

impl Touched {
    fn clear(&mut self, colored_eq: &mut [bool], colored_var: &mut [bool]) {
        for e in self.eqs.drain(..) {
            colored_eq[e] = false;
        }
        for v in self.vars.drain(..) {
            colored_var[v] = false;
        }
    }
}

/// `|det a| / prod(row norms)` of a square matrix (Hadamard's ratio: 1 for orthogonal rows,
/// 0 for singular ones), by elimination with partial pivoting.
fn det_ratio(mut a: Vec<Vec<f64>>) -> f64 {
    let norms: f64 = a
        .iter()
        .map(|row| row.iter().map(|v| v * v).sum::<f64>().sqrt())
        .product();
    if norms == 0.0 || !norms.is_finite() {
        return 0.0;
    }
    let n = a.len();
    let mut det = 1.0;
    for k in 0..n {
        let Some(p) = (k..n).max_by(|&i, &j| a[i][k].abs().total_cmp(&a[j][k].abs())) else {
            return 0.0;
        };
        if a[p][k] == 0.0 {
            return 0.0;
        }
        a.swap(k, p);
        det *= a[k][k];
        let pivot = a[k].clone();
        for row in a.iter_mut().skip(k + 1) {
            let f = row[k] / pivot[k];
            for (x, p) in row.iter_mut().zip(&pivot).skip(k) {
                *x -= f * p;
            }
        }
    }
    (det / norms).abs()
}

/// A pivot in a more preferred column is taken when it is at least this fraction of the best
/// pivot over all columns.
const PREFERENCE: f64 = 0.1;

/// Columns of a regular square block by complete pivoting, `None` if the rows are singular
/// (relative to the matrix's largest entry). A column of a higher `preference` wins a pivot
/// it is within [`PREFERENCE`] of.
fn pivot_columns(mut a: Vec<Vec<f64>>, preference: &[u8]) -> Option<Vec<usize>> {
    let m = a.first().map_or(0, Vec::len);
    let largest = a.iter().flatten().fold(0.0_f64, |s, v| s.max(v.abs()));
    if largest == 0.0 && !a.is_empty() {
        return None;
    }
    let mut row_done = vec![false; a.len()];
    let mut col_done = vec![false; m];
    let mut chosen = Vec::new();
    for _ in 0..a.len() {
        // The best pivot per preference level.
        let mut best = [(0.0, usize::MAX, usize::MAX); 4];
        for (i, row) in a.iter().enumerate().filter(|(i, _)| !row_done[*i]) {
            for (k, &v) in row.iter().enumerate().filter(|(k, _)| !col_done[*k]) {
                let level = usize::from(preference[k].min(3));
                if v.abs() > best[level].0 {
                    best[level] = (v.abs(), i, k);
                }
            }
        }
        let overall = best.iter().fold(0.0_f64, |m, b| m.max(b.0));
        let &(p, i, k) = best
            .iter()
            .rev()
            .find(|b| b.0 > 0.0 && b.0 >= PREFERENCE * overall)?;
        if p <= 1e-10 * largest {
            return None;
        }
        row_done[i] = true;
        col_done[k] = true;
        chosen.push(k);
        let pivot_row = a[i].clone();
        for (r, row) in a.iter_mut().enumerate() {
            if row_done[r] {
                continue;
            }
            let f = row[k] / pivot_row[k];
            for (x, p) in row.iter_mut().zip(&pivot_row) {
                *x -= f * p;
            }
        }
    }
    Some(chosen)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn x(j: usize) -> Sym {
        Sym::X(j)
    }
    fn dot(j: usize) -> Sym {
        Sym::Dot(j)
    }
    fn c(v: f64) -> Sym {
        Sym::Const(v)
    }

    /// The Cartesian pendulum: x, y, u, v, lam.
    fn pendulum() -> Vec<Sym> {
        vec![
            Sym::sub(dot(0), x(2)),
            Sym::sub(dot(1), x(3)),
            Sym::add(dot(2), Sym::mul(x(4), x(0))),
            Sym::add(Sym::add(dot(3), Sym::mul(x(4), x(1))), c(9.81)),
            Sym::sub(Sym::add(Sym::mul(x(0), x(0)), Sym::mul(x(1), x(1))), c(1.0)),
        ]
    }

    /// The unknowns read as `'dot`.
    fn states(asm: &Assembled) -> Vec<usize> {
        let mut states = Vec::new();
        for r in &asm.residuals {
            r.visit(&mut |e| {
                if let Sym::Dot(j) = e {
                    states.push(*j);
                }
            });
        }
        states.sort_unstable();
        states.dedup();
        states
    }

    #[test]
    fn an_index_one_system_needs_no_reduction() {
        // x' = -x + y, 0 = y - 2.
        let r = vec![
            Sym::add(dot(0), Sym::sub(x(0), x(1))),
            Sym::sub(x(1), c(2.0)),
        ];
        assert!(
            Reduction::find(&r, 2, usize::MAX, usize::MAX)
                .unwrap()
                .is_none()
        );
    }

    #[test]
    fn the_pendulum_has_index_three_and_two_states() {
        let red = Reduction::find(&pendulum(), 5, usize::MAX, usize::MAX)
            .unwrap()
            .unwrap();
        assert_eq!(red.index(), 3);
        // The constraint twice, the two velocity definitions once.
        assert_eq!(red.differentiations(), vec![(0, 1), (1, 1), (4, 2)]);
        // Hanging mostly downward: y is the better dummy, x stays a state.
        let sel = red.select(&[0.3, -0.95, 0.0, 0.0, 0.0], &[], &[]);
        let asm = Assembled {
            unknowns: (0..5)
                .map(|q| Unknown::Quantity(vams_design::QuantityId(q)))
                .collect(),
            quantity_slot: (0..5).collect(),
            residuals: pendulum(),
            origins: (0..5).map(Origin::User).collect(),
        };
        let out = red.assemble(&asm, &sel);
        assert_eq!(out.unknowns.len(), out.residuals.len());
        assert_eq!(out.residuals.len(), 9);
        assert_eq!(states(&out), vec![0, 2], "x and u are the states");
        // Lying mostly sideways, the choice turns round.
        let sel = red.select(&[0.95, -0.3, 0.0, 0.0, 0.0], &[], &[]);
        let out = red.assemble(&asm, &sel);
        assert_eq!(states(&out), vec![1, 3], "y and v are the states");
    }

    #[test]
    fn a_rigid_gear_has_index_two() {
        // j1 w1' = 1 - t1, j2 w2' = t2 - d w2, w1 = 3 w2, t2 = 3 t1.
        let r = vec![
            Sym::sub(Sym::mul(c(0.01), dot(0)), Sym::sub(c(1.0), x(2))),
            Sym::sub(
                Sym::mul(c(0.5), dot(1)),
                Sym::sub(x(3), Sym::mul(c(0.2), x(1))),
            ),
            Sym::sub(x(0), Sym::mul(c(3.0), x(1))),
            Sym::sub(x(3), Sym::mul(c(3.0), x(2))),
        ];
        let red = Reduction::find(&r, 4, usize::MAX, usize::MAX)
            .unwrap()
            .unwrap();
        assert_eq!(red.index(), 2);
        assert_eq!(red.differentiations(), vec![(2, 1)]);
    }

    #[test]
    fn a_constraint_on_a_delayed_value_is_refused() {
        let r = vec![Sym::sub(dot(0), x(1)), Sym::sub(x(0), Sym::Signal(7))];
        assert_eq!(
            Reduction::find(&r, 2, 5, 4).err(),
            Some(IndexError::Delayed { equation: 1 })
        );
    }
}
