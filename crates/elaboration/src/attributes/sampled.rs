//! The time-sampled attributes `Q'zoh(T [, initial_delay])` and
//! `Q'ztf(num, den, T [, initial_delay])`: a generated process samples `Q` at
//! `initial_delay + k T` (its `wait for` makes each sample a kernel time point, so the
//! integrator lands on it) and drives an implicit real signal with the held value or the
//! z-domain filter's output. Equations read the signal: piecewise constant between samples,
//! with a discontinuity (an integrator restart) at each sample.
//!
//! Each is also recorded in `Design::sampled`, for the frequency domain (`vams ac`), where it
//! is a transfer from its input rather than a process.
//!
//! `'ztf` is the direct form `y_k = (n0 u_k + n1 u_(k-1) + ... - d1 y_(k-1) - ...) / d0` over
//! coefficients in ascending powers of `z^-1`; its state (past inputs and outputs, zero at
//! the start) lives in the process's variables.

use vams_design::{DelayMechanism, Expr, Instr, Process, QuantityId, SignalId, Type, Value};
use vams_design::{Sampled, VarId, Variable};
use vams_syntax::ast;
use vams_syntax::source::Span;

use crate::attributes::synth::{arg, div, linear, real, sub};
use crate::error::ElabError;
use crate::names::scope::Scope;
use crate::{Elab, R};

/// Sampling period and first sample time, seconds.
#[derive(Clone, Copy, Debug)]
struct Sampling {
    period: f64,
    initial_delay: f64,
}

impl<'a> Elab<'a> {
    /// `q'zoh(T [, initial_delay])`.
    pub(crate) fn zoh_attribute(
        &mut self,
        sc: &Scope<'a>,
        q: QuantityId,
        args: &[ast::Assoc],
        span: Span,
    ) -> R<Expr> {
        if arg(args, 0).is_none() || arg(args, 2).is_some() {
            return Err(self.error(ElabError::invalid(
                span,
                "`'zoh` takes a sampling period and an optional initial delay",
                Some("`q'zoh(1.0e-3)` or `q'zoh(1.0e-3, 0.5e-3)` (seconds, as reals)".into()),
            )));
        }
        let sampling = self.sampling(sc, args, 0, span)?;
        let name = format!("{}'zoh", self.qname(q));
        let out = self.implicit_signal(name.clone(), 0.0, span);
        let code = vec![Instr::Assign {
            index: None,
            target: out,
            waveform: vec![(Some(Expr::Quantity(q)), Expr::Const(Value::Time(0.0)))],
            mechanism: DelayMechanism::Transport,
        }];
        self.sampling_process(name, Vec::new(), code, sampling, span);
        self.design.sampled.push(Sampled {
            signal: out,
            input: q,
            period: sampling.period,
            filter: None,
            span,
        });
        Ok(Expr::Signal(out))
    }

    /// `q'ztf(num, den, T [, initial_delay])`.
    pub(crate) fn ztf_attribute(
        &mut self,
        sc: &Scope<'a>,
        q: QuantityId,
        args: &[ast::Assoc],
        span: Span,
    ) -> R<Expr> {
        let (Some(num), Some(den), Some(_), None) =
            (arg(args, 0), arg(args, 1), arg(args, 2), arg(args, 4))
        else {
            return Err(self.error(ElabError::invalid(
                span,
                "`'ztf` takes numerator, denominator, sampling period and an optional initial delay",
                Some("`q'ztf(num, den, 1.0e-3)` with real_vector constants in powers of z**-1".into()),
            )));
        };
        let num = self.coefficients(sc, num, "the numerator of `'ztf`")?;
        let den = self.coefficients(sc, den, "the denominator of `'ztf`")?;
        if den[0] == 0.0 || den.iter().chain(&num).any(|c| !c.is_finite()) {
            return Err(self.error(ElabError::invalid(
                span,
                "the first denominator coefficient of `'ztf` must be finite and nonzero",
                Some("it multiplies the current output: `(1.0, -1.0)` is `1 - z**-1`".into()),
            )));
        }
        let sampling = self.sampling(sc, args, 2, span)?;
        let name = format!("{}'ztf", self.qname(q));
        let out = self.implicit_signal(name.clone(), 0.0, span);
        let (vars, code) = ztf_code(q, out, &num, &den, &name);
        self.sampling_process(name, vars, code, sampling, span);
        self.design.sampled.push(Sampled {
            signal: out,
            input: q,
            period: sampling.period,
            filter: Some((num, den)),
            span,
        });
        Ok(Expr::Signal(out))
    }

    /// The period (argument `first`) and optional initial delay (`first + 1`).
    fn sampling(
        &mut self,
        sc: &Scope<'a>,
        args: &[ast::Assoc],
        first: usize,
        span: Span,
    ) -> R<Sampling> {
        let period = match arg(args, first) {
            Some(e) => self.static_real(sc, e, "the sampling period")?,
            None => 0.0,
        };
        let initial_delay = match arg(args, first + 1) {
            Some(e) => self.static_real(sc, e, "the initial delay")?,
            None => 0.0,
        };
        let valid =
            period > 0.0 && period.is_finite() && initial_delay >= 0.0 && initial_delay.is_finite();
        if !valid {
            return Err(self.error(ElabError::invalid(
                span,
                "the sampling period must be positive and the initial delay non-negative",
                Some("both are reals in seconds: `q'zoh(1.0e-3)`".into()),
            )));
        }
        Ok(Sampling {
            period,
            initial_delay,
        })
    }

    /// Wraps `sample` (the work at each sample) in the sampling loop:
    /// `wait for initial_delay; loop sample; wait for T; end loop`.
    fn sampling_process(
        &mut self,
        name: String,
        vars: Vec<Variable>,
        sample: Vec<Instr>,
        s: Sampling,
        span: Span,
    ) {
        let wait = |t: f64| Instr::Wait {
            on: Vec::new(),
            until: None,
            timeout: Some(Expr::Const(Value::Time(t))),
        };
        let mut code = vec![wait(s.initial_delay)];
        code.extend(sample);
        code.push(wait(s.period));
        code.push(Instr::Jump(1));
        self.design.processes.push(Process {
            spans: Vec::new(),
            name: format!("{name}_sampler"),
            vars,
            code,
            span,
            driver_inits: Vec::new(),
        });
    }
}

/// The variables and per-sample instructions of the direct-form filter `num / den`.
fn ztf_code(
    q: QuantityId,
    out: SignalId,
    num: &[f64],
    den: &[f64],
    name: &str,
) -> (Vec<Variable>, Vec<Instr>) {
    let mut vars = Vec::new();
    let mut var = |n: String| {
        vars.push(Variable {
            range: None,
            name: n,
            ty: Type::Real,
            init: Value::Real(0.0),
        });
        VarId(vars.len() as u32 - 1)
    };
    let u = var(format!("{name}.u"));
    let y = var(format!("{name}.y"));
    // Past inputs u(k-1)..u(k-m) and outputs y(k-1)..y(k-n).
    let past_u: Vec<VarId> = (1..num.len())
        .map(|i| var(format!("{name}.u{i}")))
        .collect();
    let past_y: Vec<VarId> = (1..den.len())
        .map(|i| var(format!("{name}.y{i}")))
        .collect();
    let v = |id: VarId| Expr::Var(id);
    let feed = linear(
        std::iter::once((num[0], v(u)))
            .chain(past_u.iter().zip(&num[1..]).map(|(&p, &c)| (c, v(p)))),
    );
    let back = linear(past_y.iter().zip(&den[1..]).map(|(&p, &c)| (c, v(p))));
    let mut code = vec![
        Instr::SetVar {
            var: u,
            value: Expr::Quantity(q),
        },
        Instr::SetVar {
            var: y,
            value: div(sub(feed, back), real(den[0])),
        },
    ];
    // Shift the delay lines, oldest first.
    for past in [(&past_u, u), (&past_y, y)] {
        let (line, newest) = past;
        for i in (0..line.len()).rev() {
            let from = if i == 0 { newest } else { line[i - 1] };
            code.push(Instr::SetVar {
                var: line[i],
                value: v(from),
            });
        }
    }
    code.push(Instr::Assign {
        index: None,
        target: out,
        waveform: vec![(Some(v(y)), Expr::Const(Value::Time(0.0)))],
        mechanism: DelayMechanism::Transport,
    });
    (vars, code)
}
