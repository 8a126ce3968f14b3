//! Structural errors found before any number is computed, as rendered diagnostics.

use super::fixture::*;
use crate::analog::{AnalogError, AnalogSystem};
use vams_design::NatureId;
use vams_syntax::diagnostics::render_plain;
use vams_syntax::source::SourceMap;

fn errors(b: Builder) -> (Vec<AnalogError>, SourceMap) {
    let (d, sources) = b.finish();
    match AnalogSystem::new(&d) {
        Ok(_) => panic!("the design was accepted"),
        Err(e) => (e, sources),
    }
}

fn render(errors: &[AnalogError], sources: &SourceMap) -> String {
    errors
        .iter()
        .map(|e| render_plain(e, sources))
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn too_few_equations_name_the_unused_quantity() {
    let mut b = Builder::new();
    let x = b.free("x");
    b.free("y");
    b.equation("x == 1.0;", q(x), c(1.0));
    let (e, sources) = errors(b);
    assert!(matches!(
        e[..],
        [AnalogError::Count {
            equations: 1,
            unknowns: 2,
            ..
        }]
    ));
    insta::assert_snapshot!(render(&e, &sources));
}

#[test]
fn too_many_equations() {
    let mut b = Builder::new();
    let x = b.free("x");
    b.equation("x == 1.0;", q(x), c(1.0));
    b.equation("x == 2.0;", q(x), c(2.0));
    let (e, sources) = errors(b);
    assert!(matches!(
        e[..],
        [AnalogError::Count {
            equations: 2,
            unknowns: 1,
            ..
        }]
    ));
    insta::assert_snapshot!(render(&e, &sources));
}

#[test]
fn structurally_singular_pair_is_split_into_over_and_under_determined_parts() {
    let mut b = Builder::new();
    let x = b.free("x");
    let y = b.free("y");
    let z = b.free("z");
    b.equation("x == 1.0;", q(x), c(1.0));
    b.equation("2.0 * x == 3.0;", mul(c(2.0), q(x)), c(3.0));
    b.equation("y + z == 0.0;", add(q(y), q(z)), c(0.0));
    let (e, sources) = errors(b);
    match &e[..] {
        [
            AnalogError::Overdetermined {
                count: 2,
                quantities: over,
                ..
            },
            AnalogError::Underdetermined {
                count: 2,
                quantities: under,
                ..
            },
        ] => {
            assert_eq!(over, "x");
            assert_eq!(under, "y, z");
        }
        other => panic!("unexpected {other:?}"),
    }
    insta::assert_snapshot!(render(&e, &sources));
}

#[test]
fn floating_terminals_are_named_with_their_branches() {
    let mut b = Builder::new();
    let el = NatureId(0);
    let gnd = b.ground(el);
    let a = b.terminal("a", el);
    let f1 = b.terminal("f1", el);
    let f2 = b.terminal("f2", el);
    let (vs, _) = b.branch("vs", "is", a, gnd);
    b.equation("vs == 1.0;", q(vs), c(1.0));
    let (vc, ic) = b.branch("vc", "ic", f1, f2);
    b.equation("ic == 1.0e-6 * vc'dot;", q(ic), mul(c(1e-6), dot(vc)));
    let (e, sources) = errors(b);
    assert!(matches!(&e[..], [AnalogError::Floating { terminals, .. }] if terminals == "f1, f2"));
    insta::assert_snapshot!(render(&e, &sources));
}

#[test]
fn a_terminal_with_only_across_branches_needs_no_conservation_law() {
    // A voltage probe: `vp across a to ground` with no through quantity at `a` besides the
    // source's. And a terminal `p` reached only by an across quantity whose value is given.
    let mut b = Builder::new();
    let el = NatureId(0);
    let gnd = b.ground(el);
    let p = b.terminal("p", el);
    let (vp, _) = b.branch("vp", "ip", p, gnd);
    b.equation("vp == 2.0;", q(vp), c(2.0));
    let (d, _) = b.finish();
    let sys = system(&d);
    assert_eq!(sys.unknown_names(), ["v(p)", "vp", "ip"]);
}

#[test]
fn process_only_expressions_and_bad_indices_are_errors_not_panics() {
    use vams_design::{Expr, QuantityId, VarId};
    let mut b = Builder::new();
    let x = b.free("x");
    b.equation("x == v;", q(x), Expr::Var(VarId(0)));
    let (d, _) = b.finish();
    let e = AnalogSystem::new(&d).err().expect("rejected");
    assert!(
        matches!(&e[..], [AnalogError::NotAnalog { what, .. }] if what == "a process variable")
    );

    let mut b = Builder::new();
    let x = b.free("x");
    b.equation("x == y;", q(x), q(QuantityId(7)));
    let (d, _) = b.finish();
    let e = AnalogSystem::new(&d).err().expect("rejected");
    assert!(matches!(&e[..], [AnalogError::Malformed { .. }]));
}

#[test]
fn an_empty_design_is_an_empty_system() {
    let (d, _) = Builder::new().finish();
    let sys = system(&d);
    assert!(sys.unknown_names().is_empty());
}
