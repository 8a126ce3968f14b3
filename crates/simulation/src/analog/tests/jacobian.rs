//! The symbolic Jacobian against central finite differences on random expressions, and the
//! tape against direct evaluation of the tree.

use proptest::prelude::*;

use crate::analog::deriv::{Var, derivative};
use crate::analog::lower::lower;
use crate::analog::sym::Sym;
use crate::analog::tape::TapeBuilder;
use vams_design::{BinaryOp, Builtin, Expr, QuantityId};

/// Random expressions in `x0`, `x1` and `x0'dot` with + - * / ** exp tanh and if. Division
/// and powers are built so that their operands stay in the domain (`b*b + 0.5`).
fn expr() -> impl Strategy<Value = Expr> {
    let leaf = prop_oneof![
        (-3.0f64..3.0).prop_map(Expr::real),
        Just(Expr::Quantity(QuantityId(0))),
        Just(Expr::Quantity(QuantityId(1))),
        Just(Expr::Dot(QuantityId(0))),
    ];
    leaf.prop_recursive(4, 24, 2, |inner| {
        let b = |op, x: Expr, y: Expr| Expr::Binary(op, Box::new(x), Box::new(y));
        let positive = move |e: Expr| {
            b(
                BinaryOp::Add,
                b(BinaryOp::Mul, e.clone(), e),
                Expr::real(0.5),
            )
        };
        prop_oneof![
            (inner.clone(), inner.clone()).prop_map(move |(x, y)| b(BinaryOp::Add, x, y)),
            (inner.clone(), inner.clone()).prop_map(move |(x, y)| b(BinaryOp::Sub, x, y)),
            (inner.clone(), inner.clone()).prop_map(move |(x, y)| b(BinaryOp::Mul, x, y)),
            (inner.clone(), inner.clone()).prop_map(move |(x, y)| b(BinaryOp::Div, x, positive(y))),
            (inner.clone(), inner.clone()).prop_map(move |(x, y)| b(BinaryOp::Pow, positive(x), y)),
            (inner.clone(), 2.0f64..3.0).prop_map(move |(x, k)| b(
                BinaryOp::Pow,
                x,
                Expr::real(k.round())
            )),
            inner
                .clone()
                .prop_map(|x| Expr::Call(Builtin::Exp, vec![x])),
            inner
                .clone()
                .prop_map(|x| Expr::Call(Builtin::Tanh, vec![x])),
            (inner.clone(), inner.clone(), inner.clone()).prop_map(move |(c, x, y)| Expr::If(
                Box::new(b(BinaryOp::Gt, c, Expr::real(0.0))),
                Box::new(x),
                Box::new(y)
            )),
        ]
    })
}

/// Central difference of `e` in `var` at `(x, xdot)` with step `h`.
fn central(e: &Sym, var: Var, x: [f64; 2], xdot: [f64; 2], h: f64) -> f64 {
    let at = |d: f64| {
        let (mut x, mut xdot, mut t) = (x, xdot, 0.0);
        match var {
            Var::X(i) => x[i] += d,
            Var::Dot(i) => xdot[i] += d,
            Var::Now => t += d,
            // The generated expressions read no signal.
            Var::Signal(_) => {}
        }
        e.eval(t, &x, &xdot, &[])
    };
    (at(h) - at(-h)) / (2.0 * h)
}

proptest! {
    #[test]
    fn symbolic_jacobian_matches_central_differences(
        e in expr(),
        x in prop::array::uniform2(-1.5f64..1.5),
        xdot in prop::array::uniform2(-1.5f64..1.5),
    ) {
        let sym = lower(&e, &|q| q).expect("analog expression");
        let value = sym.eval(0.0, &x, &xdot, &[]);
        // Outside the region where doubles resolve differences the check says nothing.
        if !value.is_finite() || value.abs() > 1e6 {
            return Ok(());
        }
        for var in [Var::X(0), Var::X(1), Var::Dot(0), Var::Now] {
            let d = derivative(&sym, var);
            // The residual as a section of its own, evaluated first (after a full evaluation
            // elsewhere), then the rest at the same point, as Newton does.
            let mut tb = TapeBuilder::default();
            tb.push(&sym);
            let section = tb.end_section();
            tb.push(&d);
            let mut tape = tb.finish();
            tape.eval(0.0, &[x[0] + 0.25, x[1]], &xdot, &[]);
            tape.eval_section(section, 0.0, &x, &xdot, &[]);
            prop_assert!(tape.output(0) == value || (tape.output(0).is_nan() && value.is_nan()));
            tape.eval(0.0, &x, &xdot, &[]);
            let exact = d.eval(0.0, &x, &xdot, &[]);
            prop_assert!(tape.output(0) == value || (tape.output(0).is_nan() && value.is_nan()));
            prop_assert!(tape.output(1).to_bits() == exact.to_bits());
            let coord = match var {
                Var::X(i) => x[i],
                Var::Dot(i) => xdot[i],
                Var::Now | Var::Signal(_) => 0.0,
            };
            let h = 1e-5 * (1.0 + coord.abs());
            let fd = central(&sym, var, x, xdot, h);
            let fd_half = central(&sym, var, x, xdot, h / 2.0);
            // Only where the expression is smooth at this scale (no `if` switching, no
            // steep region): both difference quotients agree.
            let scale = 1.0 + fd.abs();
            if !fd.is_finite() || (fd - fd_half).abs() > 1e-6 * scale {
                continue;
            }
            prop_assert!(
                (exact - fd_half).abs() <= 1e-5 * scale,
                "d/d{var:?} of {sym:?}: symbolic {exact}, differences {fd_half}"
            );
        }
    }
}

#[test]
fn derivatives_are_simplified() {
    // d/dx (3 x + 2 y') = 3, d/dy' = 2, d/dz = 0 (no entry).
    let e = Sym::add(
        Sym::mul(Sym::Const(3.0), Sym::X(0)),
        Sym::mul(Sym::Const(2.0), Sym::Dot(1)),
    );
    assert_eq!(derivative(&e, Var::X(0)), Sym::Const(3.0));
    assert_eq!(derivative(&e, Var::Dot(1)), Sym::Const(2.0));
    assert_eq!(derivative(&e, Var::X(1)), Sym::Const(0.0));
    // Conditions contribute nothing: d/dx (if x > 0 then x else -x) = if x > 0 then 1 else -1.
    let abs_like = Sym::cond(
        Sym::bin(crate::analog::sym::Bin::Gt, Sym::X(0), Sym::Const(0.0)),
        Sym::X(0),
        Sym::neg(Sym::X(0)),
    );
    match derivative(&abs_like, Var::X(0)) {
        Sym::If(_, a, b) => assert_eq!((*a, *b), (Sym::Const(1.0), Sym::Const(-1.0))),
        other => panic!("expected an If, got {other:?}"),
    }
}

#[test]
fn the_tape_shares_common_subexpressions() {
    // exp(x) appears in the residual and in its derivative: compiled once.
    let e = Sym::un(crate::analog::sym::Un::Exp, Sym::X(0));
    let mut tb = TapeBuilder::default();
    tb.push(&e);
    tb.push(&derivative(&e, Var::X(0)));
    let tape = tb.finish();
    assert_eq!(tape.instructions(), 1); // exp (the load of x is an input)
}

#[test]
fn the_tape_rewrites_exactly_and_drops_dead_instructions() {
    use crate::analog::sym::Bin;
    let (x0, x1) = (Sym::X(0), Sym::X(1));
    let raw = |op, a: Sym, b: Sym| Sym::Bin(op, Box::new(a), Box::new(b));
    let neg = |a: Sym| Sym::Un(crate::analog::sym::Un::Neg, Box::new(a));
    let roots = [
        // x0 + -x1: one subtraction (the negation it came with is dead).
        raw(Bin::Add, x0.clone(), neg(x1.clone())),
        // --x0: no instruction at all.
        neg(neg(x0.clone())),
        // x0 * x1 and x1 * x0: one instruction. x0 / 4: a multiplication by 0.25.
        raw(Bin::Mul, x0.clone(), x1.clone()),
        raw(Bin::Mul, x1.clone(), x0.clone()),
        raw(Bin::Div, x0.clone(), Sym::Const(4.0)),
        // x0 / 3 stays a division (1/3 is not exact).
        raw(Bin::Div, x0.clone(), Sym::Const(3.0)),
    ];
    let mut tb = TapeBuilder::default();
    for r in &roots {
        tb.push(r);
    }
    let mut tape = tb.finish();
    // sub, mul (shared), mul by 0.25, div.
    assert_eq!(tape.instructions(), 4);
    let (x, xdot) = ([0.7, -1.3], [0.0; 2]);
    tape.eval(0.0, &x, &xdot, &[]);
    for (i, r) in roots.iter().enumerate() {
        assert_eq!(
            tape.output(i).to_bits(),
            r.eval(0.0, &x, &xdot, &[]).to_bits()
        );
    }
}

#[test]
fn every_differentiable_function_matches_central_differences() {
    use crate::analog::sym::{Bin, Un};
    // Points inside each function's domain and away from kinks.
    let unary = [
        (Un::Neg, 0.3),
        (Un::Abs, -0.7),
        (Un::Exp, 0.4),
        (Un::Log, 1.7),
        (Un::Log10, 2.5),
        (Un::Sqrt, 0.8),
        (Un::Sin, 0.9),
        (Un::Cos, 0.9),
        (Un::Tan, 0.6),
        (Un::Asin, 0.35),
        (Un::Acos, 0.35),
        (Un::Atan, 1.3),
        (Un::Sinh, 0.5),
        (Un::Cosh, 0.5),
        (Un::Tanh, 0.5),
        (Un::Asinh, 0.8),
        (Un::Acosh, 1.9),
        (Un::Atanh, 0.45),
        (Un::Floor, 1.3),
        (Un::Sign, -2.0),
    ];
    for (op, at) in unary {
        // op(2 x) exercises the chain rule too.
        let e = Sym::un(op, Sym::mul(Sym::Const(2.0), Sym::X(0)));
        let exact = derivative(&e, Var::X(0)).eval(0.0, &[at / 2.0], &[0.0], &[]);
        let fd = central(&e, Var::X(0), [at / 2.0, 0.0], [0.0; 2], 1e-6);
        assert!(
            (exact - fd).abs() < 1e-6 * (1.0 + fd.abs()),
            "{op:?}: {exact} vs {fd}"
        );
    }
    let binary = [
        (Bin::Mod, 5.3, 1.7),
        (Bin::Rem, -5.3, 1.7),
        (Bin::Atan2, 0.7, -1.2),
        (Bin::Max, 0.7, 0.2),
        (Bin::Min, 0.7, 0.2),
        (Bin::Pow, 1.3, 2.2),
    ];
    for (op, a, b) in binary {
        let e = Sym::bin(op, Sym::X(0), Sym::X(1));
        for (var, i) in [(Var::X(0), 0), (Var::X(1), 1)] {
            let exact = derivative(&e, var).eval(0.0, &[a, b], &[0.0; 2], &[]);
            let fd = central(&e, var, [a, b], [0.0; 2], 1e-6);
            assert!(
                (exact - fd).abs() < 1e-6 * (1.0 + fd.abs()),
                "{op:?} by x{i}: {exact} vs {fd}"
            );
        }
    }
}

#[test]
fn affine_means_affine_in_the_unknowns_for_every_signal_and_time() {
    use crate::analog::sym::{Bin, Un};
    let (x, y, s) = (Sym::X(0), Sym::Dot(1), Sym::Signal(0));
    let raw = |op, a: &Sym, b: &Sym| Sym::Bin(op, Box::new(a.clone()), Box::new(b.clone()));
    let un = |op, a: &Sym| Sym::Un(op, Box::new(a.clone()));
    let iff =
        |c: Sym, a: &Sym, b: &Sym| Sym::If(Box::new(c), Box::new(a.clone()), Box::new(b.clone()));
    let sin_now = un(Un::Sin, &Sym::Now);
    let affine = [
        raw(Bin::Add, &x, &raw(Bin::Mul, &Sym::Const(2.0), &y)),
        raw(Bin::Mul, &sin_now, &x),
        raw(Bin::Div, &x, &Sym::Now),
        un(Un::Neg, &raw(Bin::Sub, &y, &un(Un::Exp, &s))),
        iff(s.clone(), &x, &raw(Bin::Mul, &x, &Sym::Const(3.0))),
    ];
    for e in &affine {
        assert!(e.is_affine(), "{e:?}");
    }
    let not_affine = [
        raw(Bin::Mul, &x, &y),
        raw(Bin::Div, &Sym::Const(1.0), &x),
        un(Un::Exp, &x),
        // Zero or constant derivative, but not affine: rounding, comparisons, conditions.
        un(Un::Floor, &x),
        raw(Bin::Gt, &x, &Sym::Const(0.0)),
        iff(
            raw(Bin::Gt, &x, &Sym::Const(0.0)),
            &x,
            &raw(Bin::Add, &x, &Sym::Const(1.0)),
        ),
    ];
    for e in &not_affine {
        assert!(!e.is_affine(), "{e:?}");
    }
}

#[test]
fn only_the_taken_branch_runs_and_shared_work_stays_outside() {
    use crate::analog::sym::{Bin, Un};
    // if x0 > 0 then exp(x1) * 3 + x1 / 7 else log(x1 * x1 + 1) - exp(x1), nested in a second
    // `if` on the same condition: exp(x1) is needed by both branches and computed before the
    // jump; each branch's own work runs only when taken.
    let e1 = Sym::un(Un::Exp, Sym::X(1));
    let then_branch = Sym::add(
        Sym::mul(e1.clone(), Sym::Const(3.0)),
        Sym::bin(Bin::Div, Sym::X(1), Sym::Const(7.0)),
    );
    let else_branch = Sym::sub(
        Sym::un(
            Un::Log,
            Sym::add(Sym::mul(Sym::X(1), Sym::X(1)), Sym::Const(1.0)),
        ),
        e1.clone(),
    );
    let cond = Sym::bin(Bin::Gt, Sym::X(0), Sym::Const(0.0));
    let inner = Sym::cond(cond.clone(), then_branch, else_branch);
    let outer = Sym::cond(cond, Sym::mul(inner.clone(), Sym::X(1)), e1);
    let roots = [inner, outer];
    let mut tb = TapeBuilder::default();
    for r in &roots {
        tb.push(r);
    }
    let mut tape = tb.finish();
    // One jump, around the inner branches; the outer then-branch is one multiplication (the
    // inner `if` is an output of its own), not worth a jump.
    assert_eq!(tape.jumps(), 1);
    // Alternate the branch so that stale registers of the untaken one would show.
    for (k, x0) in [1.0, -1.0, -2.0, 0.5, f64::NAN, -0.5]
        .into_iter()
        .enumerate()
    {
        let x = [x0, 0.3 + 0.1 * k as f64];
        tape.eval(0.0, &x, &[0.0; 2], &[]);
        for (i, r) in roots.iter().enumerate() {
            let direct = r.eval(0.0, &x, &[0.0; 2], &[]);
            assert_eq!(
                tape.output(i).to_bits(),
                direct.to_bits(),
                "root {i} at {x:?}"
            );
        }
    }
}
