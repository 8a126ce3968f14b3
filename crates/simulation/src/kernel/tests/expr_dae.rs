//! A deliberately plain analog model for the kernel's tests: the unknowns are the design's
//! (free) quantities, residuals are the equations' expression trees evaluated directly, and
//! Jacobians come from central differences on a dense pattern. It lets the mixed-signal cycle
//! be tested independently of the real `analog` module.

use crate::kernel::analog_model::AnalogModel;
use crate::kernel::ops::real_builtin;
use vams_design::{BinaryOp, Design, Expr, QuantityId, SignalId, SignalKind, UnaryOp};
use vams_solver::{
    DaeSystem, Newton, NewtonOptions, NonlinearProblem, OpOptions, SolveError, Tolerances,
};

pub struct ExprDae {
    names: Vec<String>,
    equations: Vec<Expr>,
    differential: Vec<bool>,
    pattern: Vec<(usize, usize)>,
    signals: Vec<f64>,
    reads: Vec<bool>,
    above: Vec<SignalId>,
    roots: Vec<(Expr, Expr)>,
    r0: Vec<f64>,
    r1: Vec<f64>,
}

impl ExprDae {
    pub fn new(design: &Design) -> ExprDae {
        let n = design.quantities.len();
        let mut differential = vec![false; n];
        let mut reads = vec![false; design.signals.len()];
        for eq in &design.equations {
            eq.residual.visit(&mut |e| match e {
                Expr::Dot(q) => differential[q.index()] = true,
                Expr::Signal(s) => reads[s.index()] = true,
                _ => {}
            });
        }
        let mut above = Vec::new();
        let mut roots = Vec::new();
        for (i, s) in design.signals.iter().enumerate() {
            if let SignalKind::Above { quantity, level } = &s.kind {
                above.push(SignalId(i as u32));
                roots.push((quantity.clone(), level.clone()));
            }
        }
        ExprDae {
            names: design.quantities.iter().map(|q| q.name.clone()).collect(),
            equations: design
                .equations
                .iter()
                .map(|e| e.residual.clone())
                .collect(),
            differential,
            pattern: (0..n).flat_map(|r| (0..n).map(move |c| (r, c))).collect(),
            signals: design
                .signals
                .iter()
                .map(|s| s.init.as_f64().unwrap_or(0.0))
                .collect(),
            reads,
            above,
            roots,
            r0: vec![0.0; n],
            r1: vec![0.0; n],
        }
    }

    fn eval(&self, e: &Expr, t: f64, x: &[f64], xd: &[f64]) -> f64 {
        let ev = |e: &Expr| self.eval(e, t, x, xd);
        match e {
            Expr::Const(v) => v.as_f64().unwrap_or(f64::NAN),
            Expr::Quantity(q) => x[q.index()],
            Expr::Dot(q) => xd[q.index()],
            Expr::Signal(s) => self.signals[s.index()],
            Expr::Now => t,
            Expr::Unary(UnaryOp::Neg, a) => -ev(a),
            Expr::Unary(UnaryOp::Plus, a) => ev(a),
            Expr::Unary(UnaryOp::Abs, a) => ev(a).abs(),
            Expr::Unary(UnaryOp::Not, a) => f64::from(ev(a) == 0.0),
            Expr::Binary(op, a, b) => {
                let (a, b) = (ev(a), ev(b));
                let truth = |c: bool| f64::from(c);
                match op {
                    BinaryOp::Add => a + b,
                    BinaryOp::Sub => a - b,
                    BinaryOp::Mul => a * b,
                    BinaryOp::Div => a / b,
                    BinaryOp::Pow => a.powf(b),
                    BinaryOp::Lt => truth(a < b),
                    BinaryOp::Le => truth(a <= b),
                    BinaryOp::Gt => truth(a > b),
                    BinaryOp::Ge => truth(a >= b),
                    BinaryOp::Eq => truth(a == b),
                    BinaryOp::Ne => truth(a != b),
                    BinaryOp::And => truth(a != 0.0 && b != 0.0),
                    BinaryOp::Or => truth(a != 0.0 || b != 0.0),
                    _ => f64::NAN,
                }
            }
            Expr::Call(f, args) => {
                let a = args.first().map_or(0.0, ev);
                let b = args.get(1).map_or(0.0, ev);
                real_builtin(*f, a, b)
            }
            Expr::If(c, a, b) => {
                if ev(c) != 0.0 {
                    ev(a)
                } else {
                    ev(b)
                }
            }
            _ => f64::NAN,
        }
    }

    fn residual_into(&self, t: f64, x: &[f64], xd: &[f64], out: &mut [f64]) {
        for (o, e) in out.iter_mut().zip(&self.equations) {
            *o = self.eval(e, t, x, xd);
        }
    }
}

impl DaeSystem for ExprDae {
    fn len(&self) -> usize {
        self.names.len()
    }
    fn differential(&self) -> &[bool] {
        &self.differential
    }
    fn pattern(&self) -> &[(usize, usize)] {
        &self.pattern
    }
    fn residual(&mut self, t: f64, x: &[f64], xdot: &[f64], out: &mut [f64]) {
        self.residual_into(t, x, xdot, out);
    }
    fn jacobian(&mut self, t: f64, x: &[f64], xdot: &[f64], alpha: f64, out: &mut [f64]) {
        let n = self.len();
        let (mut x, mut xd) = (x.to_vec(), xdot.to_vec());
        let (mut r0, mut r1) = (std::mem::take(&mut self.r0), std::mem::take(&mut self.r1));
        out.fill(0.0);
        for c in 0..n {
            // Central differences in x, then in x'.
            let hx = 1e-7 * x[c].abs().max(1.0);
            let keep = x[c];
            x[c] = keep + hx;
            self.residual_into(t, &x, &xd, &mut r1);
            x[c] = keep - hx;
            self.residual_into(t, &x, &xd, &mut r0);
            x[c] = keep;
            for r in 0..n {
                out[r * n + c] += (r1[r] - r0[r]) / (2.0 * hx);
            }
            if alpha != 0.0 {
                let hd = 1e-7 * xd[c].abs().max(1.0);
                let keep = xd[c];
                xd[c] = keep + hd;
                self.residual_into(t, &x, &xd, &mut r1);
                xd[c] = keep - hd;
                self.residual_into(t, &x, &xd, &mut r0);
                xd[c] = keep;
                for r in 0..n {
                    out[r * n + c] += alpha * (r1[r] - r0[r]) / (2.0 * hd);
                }
            }
        }
        self.r0 = r0;
        self.r1 = r1;
    }
    fn root_count(&self) -> usize {
        self.roots.len()
    }
    fn roots(&mut self, t: f64, x: &[f64], xdot: &[f64], out: &mut [f64]) {
        for (o, (q, level)) in out.iter_mut().zip(&self.roots) {
            *o = self.eval(q, t, x, xdot) - self.eval(level, t, x, xdot);
        }
    }
}

/// The quiescent problem: unknown `z_i` is `x'_i` for held unknowns, else `x_i` (with
/// `x'_i = 0`).
struct Quiescent<'a> {
    dae: &'a mut ExprDae,
    t: f64,
    held: Vec<Option<f64>>,
}

impl Quiescent<'_> {
    fn split(&self, z: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let mut x = z.to_vec();
        let mut xd = vec![0.0; z.len()];
        for (i, h) in self.held.iter().enumerate() {
            if let Some(v) = h {
                x[i] = *v;
                xd[i] = z[i];
            }
        }
        (x, xd)
    }
}

impl NonlinearProblem for Quiescent<'_> {
    fn residual(&mut self, z: &[f64], out: &mut [f64]) {
        let (x, xd) = self.split(z);
        self.dae.residual_into(self.t, &x, &xd, out);
    }
    fn jacobian(&mut self, z: &[f64], out: &mut [f64]) {
        let n = z.len();
        let (mut r0, mut r1) = (vec![0.0; n], vec![0.0; n]);
        let mut z = z.to_vec();
        for c in 0..n {
            let h = 1e-7 * z[c].abs().max(1.0);
            let keep = z[c];
            z[c] = keep + h;
            self.residual(&z.clone(), &mut r1);
            z[c] = keep - h;
            self.residual(&z.clone(), &mut r0);
            z[c] = keep;
            for r in 0..n {
                out[r * n + c] = (r1[r] - r0[r]) / (2.0 * h);
            }
        }
    }
}

impl AnalogModel for ExprDae {
    fn unknown_names(&self) -> &[String] {
        &self.names
    }
    fn quantity_slot(&self, q: QuantityId) -> Option<usize> {
        Some(q.index())
    }
    fn set_signal(&mut self, s: SignalId, value: f64) {
        self.signals[s.index()] = value;
    }
    fn reads_signal(&self, s: SignalId) -> bool {
        self.reads[s.index()]
    }
    fn above_signals(&self) -> &[SignalId] {
        &self.above
    }
    fn abstol(&self, default: f64) -> Vec<f64> {
        vec![default; self.len()]
    }
    fn quiescent_point(
        &mut self,
        t: f64,
        guess: &[f64],
        fixed: &[(usize, f64)],
        reltol: f64,
        abstol: &[f64],
        _options: &OpOptions,
    ) -> Result<(Vec<f64>, Vec<f64>), SolveError> {
        let n = self.len();
        let mut held = vec![None; n];
        for &(i, v) in fixed {
            held[i] = Some(v);
        }
        let mut z = guess.to_vec();
        for (zi, h) in z.iter_mut().zip(&held) {
            if h.is_some() {
                *zi = 0.0;
            }
        }
        let mut newton = Newton::new(n, &self.pattern, Default::default())?;
        let tol = Tolerances {
            reltol,
            abstol: abstol.to_vec(),
            norm: Default::default(),
        };
        let mut p = Quiescent { dae: self, t, held };
        newton.solve(&mut p, &mut z, &tol, &NewtonOptions::default(), t)?;
        Ok(p.split(&z))
    }
}
