//! A small builder of [`Design`]s with a matching source text, so that spans point at
//! something readable in diagnostic snapshots, plus expression shorthands and an integrator
//! loop.

use crate::analog::{AnalogOptions, AnalogSystem};
use vams_design::*;
use vams_solver::{Advance, DaeSystem, OpOptions, Transient, TransientOptions};
use vams_syntax::source::{FileId, SourceMap, Span};

pub struct Builder {
    pub design: Design,
    text: String,
}

impl Builder {
    /// A design with the `electrical` nature (reference `electrical_ref`).
    pub fn new() -> Builder {
        let mut b = Builder {
            design: Design {
                top: "tb".into(),
                ..Design::default()
            },
            text: String::new(),
        };
        b.nature("electrical", "DEFAULT_VOLTAGE", "DEFAULT_CURRENT");
        b
    }

    /// Appends a source line; returns its span (the line without the newline).
    fn line(&mut self, text: &str) -> Span {
        let start = self.text.len();
        self.text.push_str(text);
        let span = Span::new(FileId(0), start, self.text.len());
        self.text.push('\n');
        span
    }

    /// Adds a nature and its reference terminal.
    pub fn nature(&mut self, name: &str, across: &str, through: &str) -> NatureId {
        let id = NatureId(self.design.natures.len() as u32);
        let r = TerminalId(self.design.terminals.len() as u32);
        let span = self.line(&format!(
            "nature {name} is {across} across {through} through;"
        ));
        self.design.terminals.push(Terminal {
            name: format!("{name}_ref"),
            nature: id,
            is_reference: true,
            span,
        });
        self.design.natures.push(Nature {
            name: name.into(),
            across_tolerance: Some(across.into()),
            through_tolerance: Some(through.into()),
            reference: r,
        });
        id
    }

    pub fn ground(&self, nature: NatureId) -> TerminalId {
        self.design.natures[nature.index()].reference
    }

    pub fn terminal(&mut self, name: &str, nature: NatureId) -> TerminalId {
        let span = self.line(&format!(
            "terminal {name} : {};",
            self.design.natures[nature.index()].name
        ));
        self.design.terminals.push(Terminal {
            name: name.into(),
            nature,
            is_reference: false,
            span,
        });
        TerminalId(self.design.terminals.len() as u32 - 1)
    }

    fn quantity(
        &mut self,
        name: &str,
        kind: QuantityKind,
        tolerance: Option<&str>,
        decl: &str,
    ) -> QuantityId {
        let span = self.line(decl);
        self.design.quantities.push(Quantity {
            name: name.into(),
            kind,
            tolerance: tolerance.map(std::sync::Arc::from),
            subtype: "real".into(),
            unit: None,
            initial_guess: None,
            span,
        });
        QuantityId(self.design.quantities.len() as u32 - 1)
    }

    fn term_name(&self, t: TerminalId) -> String {
        self.design.terminals[t.index()].name.clone()
    }

    /// `quantity v across i through plus to minus;`
    pub fn branch(
        &mut self,
        v: &str,
        i: &str,
        plus: TerminalId,
        minus: TerminalId,
    ) -> (QuantityId, QuantityId) {
        let decl = format!(
            "quantity {v} across {i} through {} to {};",
            self.term_name(plus),
            self.term_name(minus)
        );
        let qv = self.quantity(v, QuantityKind::Across { plus, minus }, None, &decl);
        let qi = self.quantity(
            i,
            QuantityKind::Through { plus, minus },
            None,
            &format!("-- {i} of {v}"),
        );
        (qv, qi)
    }

    /// `quantity i through plus to minus;`
    pub fn through(&mut self, i: &str, plus: TerminalId, minus: TerminalId) -> QuantityId {
        let decl = format!(
            "quantity {i} through {} to {};",
            self.term_name(plus),
            self.term_name(minus)
        );
        self.quantity(i, QuantityKind::Through { plus, minus }, None, &decl)
    }

    pub fn free(&mut self, name: &str) -> QuantityId {
        self.quantity(
            name,
            QuantityKind::Free,
            None,
            &format!("quantity {name} : real;"),
        )
    }

    pub fn signal(&mut self, name: &str, init: f64) -> SignalId {
        let span = self.line(&format!("signal {name} : real := {init:?};"));
        self.design.signals.push(Signal {
            range: None,
            resolution: None,
            guarded: None,
            name: name.into(),
            ty: Type::Real,
            init: Value::Real(init),
            kind: SignalKind::Explicit,
            span,
        });
        SignalId(self.design.signals.len() as u32 - 1)
    }

    /// `text` is the statement as written; the residual is `lhs - rhs`.
    pub fn equation(&mut self, text: &str, lhs: Expr, rhs: Expr) {
        let span = self.line(text);
        self.design.equations.push(Equation {
            residual: sub(lhs, rhs),
            span,
            instance: String::new(),
            text: text.trim_end_matches(';').into(),
        });
    }

    pub fn finish(self) -> (Design, SourceMap) {
        let mut sources = SourceMap::new();
        sources.add("test.vhd", "work", self.text);
        (self.design, sources)
    }
}

pub fn q(id: QuantityId) -> Expr {
    Expr::Quantity(id)
}

pub fn dot(id: QuantityId) -> Expr {
    Expr::Dot(id)
}

pub fn c(v: f64) -> Expr {
    Expr::real(v)
}

pub use vams_design::build::{add, bin, mul, sub};

pub fn call(f: Builtin, a: Expr) -> Expr {
    Expr::Call(f, vec![a])
}

/// Builds the system or fails the test with the diagnostics.
pub fn system(design: &Design) -> AnalogSystem {
    match AnalogSystem::with_options(
        design,
        &AnalogOptions {
            eliminate: false,
            ..AnalogOptions::default()
        },
    ) {
        Ok(s) => s,
        Err(e) => panic!("analog system rejected: {e:?}"),
    }
}

/// Quiescent point with the given break values, then BDF to each time in `times`; returns
/// the state at each.
pub fn simulate(
    sys: &mut AnalogSystem,
    fixed: &[(usize, f64)],
    reltol: f64,
    times: &[f64],
) -> Vec<Vec<f64>> {
    let n = sys.len();
    let abstol = sys.abstol(1e-9);
    let (x0, _) = sys
        .quiescent_point(
            0.0,
            &vec![0.0; n],
            fixed,
            reltol,
            &abstol,
            &OpOptions::default(),
        )
        .expect("quiescent point");
    let opts = TransientOptions {
        reltol,
        abstol_per_unknown: abstol,
        ..TransientOptions::default()
    };
    let mut tr = Transient::new(sys, 0.0, &x0, opts).expect("initial conditions");
    let mut out = Vec::new();
    for &t in times {
        loop {
            match tr.advance(sys, t).expect("step") {
                Advance::Reached(_) => break,
                Advance::StepAccepted(_) | Advance::Root { .. } => {}
            }
        }
        out.push(tr.state().to_vec());
    }
    out
}
