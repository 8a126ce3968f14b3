//! Signal assignments to a slice whose bounds are known only at run time
//! (`s(i + 1 downto i) <= "11";`, `acc(n downto 0) <= v;`). A driver belongs to each scalar
//! element of a signal (LRM 12.6.1), so the assignment is the same waveform given element by
//! element: the values are computed once into temporaries, their lengths checked against
//! the slice's (LRM 8.4), and a run-time loop assigns each element its element of each
//! waveform value.

use std::rc::Rc;

use vams_design::{BinaryOp, Builtin, Expr, Instr, SignalId, Type, Value, VarId};
use vams_syntax::ast::{self, Actual, DelayMechanism as AstDelay, Waveform};

use crate::error::ElabError;
use crate::names::scope::{Item, Scope};
use crate::names::types::{ArrayTy, Ty};
use crate::sequential::process::Proc;
use crate::{Elab, R};

/// The signal and range of a slice target whose bounds are not static.
pub(crate) struct RuntimeSlice<'t> {
    signal: SignalId,
    array: Rc<ArrayTy>,
    range: &'t ast::Range,
}

/// Where the elements of one waveform value come from.
#[derive(Clone, Copy)]
enum Element {
    /// A temporary holding the whole value (the element at the loop's position).
    Array(VarId),
    /// A temporary holding the one value of every element (`(others => x)`).
    Each(VarId),
}

/// `x` of an aggregate `(others => x)`.
fn others_only(e: &ast::Expr) -> Option<&ast::Expr> {
    match &e.kind {
        ast::ExprKind::Aggregate(elems) => match elems.as_slice() {
            [el] if matches!(el.choices.as_slice(), [ast::Choice::Others(_)]) => Some(&el.value),
            _ => None,
        },
        ast::ExprKind::Paren(inner) => others_only(inner),
        _ => None,
    }
}

impl<'a> Elab<'a> {
    /// `target` as a slice of an array signal whose bounds are known only at run time;
    /// `None` for any other target (a static slice is a view of the signal).
    pub(crate) fn runtime_signal_slice<'t>(
        &mut self,
        sc: &Scope<'a>,
        target: &'t ast::Expr,
    ) -> R<Option<RuntimeSlice<'t>>> {
        let ast::ExprKind::Apply(prefix, args) = &target.kind else {
            return Ok(None);
        };
        let [
            ast::Assoc {
                actual: Actual::Range(range),
                formal: None,
                ..
            },
        ] = args.as_slice()
        else {
            return Ok(None);
        };
        if !matches!(
            prefix.kind,
            ast::ExprKind::Name(_) | ast::ExprKind::Selected(..)
        ) {
            return Ok(None);
        }
        let (signal, array) = match self.lookup(sc, prefix)?.first() {
            Some(Item::Signal {
                id,
                ty: Ty::Array(a),
            }) => (*id, a.clone()),
            _ => return Ok(None),
        };
        Ok(match self.where_static(|me| me.range_bounds(sc, range))? {
            Some(_) => None,
            None => Some(RuntimeSlice {
                signal,
                array,
                range,
            }),
        })
    }

    /// Lowers `target <= waveform` for the run-time slice `slice` of `target` into `p`.
    pub(crate) fn assign_runtime_slice(
        &mut self,
        sc: &Scope<'a>,
        p: &mut Proc,
        target: &ast::Expr,
        slice: RuntimeSlice<'_>,
        delay: &AstDelay,
        waveform: &Waveform,
    ) -> R<()> {
        let RuntimeSlice {
            signal,
            array,
            range,
        } = slice;
        let (_, len, slice_ty) = self.slice(sc, &array, range, target.span)?;
        let (left, _, ascending) = self.range_exprs(sc, range)?;
        let mechanism = self.delay_mechanism(sc, delay)?;
        let Waveform::Elements(elems) = waveform else {
            return Ok(());
        };
        let int = |k: i64| Expr::Const(Value::Integer(k));
        let bin = |op, a: Expr, b: Expr| Expr::Binary(op, Box::new(a), Box::new(b));
        let integer = Ty::Integer;
        let n = p.new_var("(slice length)", &integer, Value::Integer(0));
        p.emit(Instr::SetVar { var: n, value: len });
        let first = p.new_var("(slice left)", &integer, Value::Integer(0));
        p.emit(Instr::SetVar {
            var: first,
            value: left.e,
        });
        let what = format!("signal `{}`", self.text(target.span));
        // Each waveform element's value, held in a temporary of the slice's length.
        let mut wave = Vec::with_capacity(elems.len());
        for el in elems {
            let d = match &el.after {
                Some(a) => self.expr_of(sc, a, &Ty::Time)?.e,
                None => Expr::Const(Value::Time(0.0)),
            };
            let Some(v) = &el.value else {
                if !self.is_guarded(signal) {
                    let name = self.design.signals[signal.index()].name.clone();
                    return Err(self.error(ElabError::invalid(
                        el.span,
                        format!("`null` disconnects a driver, and `{name}` is not a guarded signal"),
                        Some("declare the signal `bus` or `register` (of a resolved subtype) to disconnect its drivers".into()),
                    )));
                }
                wave.push((None, d));
                continue;
            };
            // `(others => x)` takes the slice's length: each element is `x`.
            if let Some(x) = others_only(v) {
                let t = self.expr_of(sc, x, &array.element)?;
                let tmp = p.new_var("(slice element value)", &t.ty, t.ty.default_value());
                p.emit(Instr::SetVar {
                    var: tmp,
                    value: t.e,
                });
                wave.push((Some(Element::Each(tmp)), d));
                continue;
            }
            let t = self.expr_of(sc, v, &slice_ty)?;
            let tmp = p.new_var("(slice value)", &t.ty, t.ty.default_value());
            p.emit(Instr::SetVar {
                var: tmp,
                value: Expr::Call(
                    Builtin::CheckLength,
                    vec![t.e, Expr::Var(n), Expr::Const(Value::String(what.clone()))],
                ),
            });
            wave.push((Some(Element::Array(tmp)), d));
        }
        // The element at position `k` of a value, whatever its own bounds.
        let by_position = Type::Array {
            element: Box::new(array.element.to_design()),
            left: 0,
            right: i64::MAX,
            ascending: true,
        };
        let k = p.new_var("(slice element)", &integer, Value::Integer(0));
        p.emit(Instr::SetVar {
            var: k,
            value: int(0),
        });
        let top = p.here();
        let test = p.emit(Instr::JumpIfNot {
            cond: bin(BinaryOp::Lt, Expr::Var(k), Expr::Var(n)),
            target: 0,
        });
        let step = if ascending {
            BinaryOp::Add
        } else {
            BinaryOp::Sub
        };
        let index = bin(step, Expr::Var(first), Expr::Var(k));
        let own = self.design.signals.get(signal.index()).map(|s| &s.ty);
        let index = crate::sequential::process::own_index(index, &array, own);
        p.emit(Instr::Assign {
            target: signal,
            index: Some(index),
            waveform: wave
                .iter()
                .map(|(tmp, d)| {
                    let value = tmp.map(|t| match t {
                        Element::Each(x) => Expr::Var(x),
                        Element::Array(a) => Expr::Index {
                            array: Box::new(Expr::Var(a)),
                            index: Box::new(Expr::Var(k)),
                            ty: by_position.clone(),
                        },
                    });
                    (value, d.clone())
                })
                .collect(),
            mechanism,
        });
        p.emit(Instr::SetVar {
            var: k,
            value: bin(BinaryOp::Add, Expr::Var(k), int(1)),
        });
        p.emit(Instr::Jump(top));
        let end = p.here();
        p.patch(test, end);
        Ok(())
    }
}
