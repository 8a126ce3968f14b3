//! One small design per construct.

use vams_design::{BinaryOp, Expr, Instr, QuantityKind, Value};

use super::{errors, ok, run};

const HEADER: &str = "library ieee;\nuse ieee.electrical_systems.all;\nuse ieee.math_real.all;\n";

fn src(body: &str) -> String {
    format!("{HEADER}{body}")
}

#[test]
fn higher_derivatives_and_integrals_get_auxiliary_quantities() {
    let d = ok(
        &src(
            "entity t is end;\narchitecture a of t is\n  quantity x, y : real;\nbegin\n  x'dot'dot == -x;\n  y == x'integ;\nend;\n",
        ),
        "t",
    );
    let names: Vec<&str> = d.quantities.iter().map(|q| q.name.as_str()).collect();
    assert_eq!(names, ["x", "y", "x'dot", "x'integ"]);
    // x'dot - d(x)/dt, then d(x'integ)/dt - x, then the two statements.
    assert_eq!(d.equations.len(), 4);
    assert_eq!(
        d.equations[0].residual,
        Expr::Binary(
            BinaryOp::Sub,
            Box::new(Expr::Quantity(vams_design::QuantityId(2))),
            Box::new(Expr::Dot(vams_design::QuantityId(0)))
        )
    );
    let init = d
        .processes
        .iter()
        .find(|p| p.name == "x'integ_init")
        .expect("integ init process");
    assert!(
        matches!(&init.code[0], Instr::Break { reinit, .. } if reinit[0].quantity.index() == 3 && reinit[0].value == Expr::real(0.0))
    );
    assert!(matches!(init.code[1], Instr::Halt));
}

#[test]
fn branch_quantities_default_to_the_reference_and_share_terminals() {
    let d = ok(
        &src(
            "entity t is end;\narchitecture a of t is\n  terminal p, n : electrical;\n  quantity v1, v2 across i1, i2 through p to n;\n  quantity vp across p;\nbegin\n  i1 == v1; i2 == v2;\nend;\n",
        ),
        "t",
    );
    assert_eq!(d.terminals[0].name, "electrical_ref");
    assert!(d.terminals[0].is_reference);
    let kinds: Vec<QuantityKind> = d.quantities.iter().map(|q| q.kind).collect();
    let (p, n, r) = (
        vams_design::TerminalId(1),
        vams_design::TerminalId(2),
        vams_design::TerminalId(0),
    );
    assert_eq!(kinds[0], QuantityKind::Across { plus: p, minus: n });
    assert_eq!(kinds[1], QuantityKind::Across { plus: p, minus: n });
    assert_eq!(kinds[2], QuantityKind::Through { plus: p, minus: n });
    assert_eq!(kinds[4], QuantityKind::Across { plus: p, minus: r });
    assert_eq!(d.natures.len(), 1);
    assert_eq!(
        d.natures[0].across_tolerance.as_deref(),
        Some("DEFAULT_VOLTAGE")
    );
}

#[test]
fn simultaneous_case_becomes_if_chains() {
    let d = ok(
        &src(
            "entity t is end;\narchitecture a of t is\n  signal mode : integer := 0;\n  quantity x : real;\nbegin\n  case mode use\n    when 0 => x == 1.0;\n    when 1 | 2 => x == 2.0;\n    when others => x == 3.0;\n  end case;\nend;\n",
        ),
        "t",
    );
    assert_eq!(d.equations.len(), 1);
    let Expr::If(c, _, rest) = &d.equations[0].residual else {
        panic!("{:?}", d.equations[0].residual)
    };
    assert!(matches!(&**c, Expr::Binary(BinaryOp::Eq, _, _)));
    assert!(matches!(&**rest, Expr::If(..)));
}

#[test]
fn static_if_conditions_select_their_branch() {
    let d = ok(
        &src(
            "entity t is generic (lin : boolean := true); end;\narchitecture a of t is\n  quantity x : real;\nbegin\n  if lin use x == 1.0; else x == exp(1.0); end use;\nend;\n",
        ),
        "t",
    );
    assert_eq!(
        d.equations[0].residual,
        Expr::Binary(
            BinaryOp::Sub,
            Box::new(Expr::Quantity(vams_design::QuantityId(0))),
            Box::new(Expr::real(1.0))
        )
    );
}

#[test]
fn loops_case_and_exit_lower_to_jumps() {
    let text = "entity t is end;\narchitecture a of t is\n  signal s : integer := 0;\nbegin\n  p : process\n    variable acc : integer := 0;\n  begin\n    outer : for i in 1 to 10 loop\n      next when i = 2;\n      exit outer when i > 5;\n      case i is\n        when 1 | 3 => acc := acc + i;\n        when 4 to 5 => acc := acc * 2;\n        when others => null;\n      end case;\n    end loop;\n    while acc > 0 loop acc := acc - 1; end loop;\n    s <= acc after 1 ns, 0 after 2 ns;\n    wait;\n  end process;\nend;\n";
    let d = ok(&src(text), "t");
    let p = &d.processes[0];
    assert_eq!(p.name, "p");
    assert_eq!(p.vars.len(), 2);
    assert!(p.code.iter().any(|i| matches!(i, Instr::Assign { waveform, .. } if waveform.len() == 2 && waveform[1].1 == Expr::Const(Value::Time(2e-9)))));
    assert!(matches!(p.code[p.code.len() - 2], Instr::Halt));
    for i in &p.code {
        if let Instr::Jump(t) | Instr::JumpIfNot { target: t, .. } = i {
            assert!(*t < p.code.len());
        }
    }
}

#[test]
fn generate_unrolls_with_indexed_names() {
    let text = "entity t is end;\narchitecture a of t is\nbegin\n  g : for k in 1 to 3 generate\n    quantity q : real;\n  begin\n    q == real(k);\n  end generate;\n  h : if false generate\n    quantity z : real;\n  begin\n    z == 0.0;\n  end generate;\nend;\n";
    let d = ok(&src(text), "t");
    let names: Vec<&str> = d.quantities.iter().map(|q| q.name.as_str()).collect();
    assert_eq!(names, ["g(1).q", "g(2).q", "g(3).q"]);
    assert_eq!(
        d.equations[2].residual,
        Expr::Binary(
            BinaryOp::Sub,
            Box::new(Expr::Quantity(vams_design::QuantityId(2))),
            Box::new(Expr::real(3.0))
        )
    );
}

#[test]
fn open_ports_get_fresh_objects() {
    let text = "entity leaf is\n  generic (g : real := 2.0);\n  port (terminal p : electrical; quantity qi : in real; signal s : in boolean := true);\nend;\narchitecture a of leaf is\n  quantity v across i through p;\nbegin\n  i == g * v + qi;\nend;\nentity t is end;\narchitecture a of t is\nbegin\n  u : entity work.leaf port map (p => open);\nend;\n";
    let d = ok(&src(text), "t");
    assert!(d.terminals.iter().any(|t| t.name == "u.p"));
    assert!(d.quantities.iter().any(|q| q.name == "u.qi"));
    let s = d.signals.iter().find(|s| s.name == "u.s").expect("u.s");
    assert_eq!(s.init, Value::Boolean(true));
}

#[test]
fn concurrent_statements_become_processes() {
    let text = "entity t is end;\narchitecture a of t is\n  signal a, b : boolean;\n  signal n : integer;\n  quantity x : real;\nbegin\n  a <= true when b else false;\n  with n select b <= true when 1, false when others;\n  assert a report \"a\" severity warning;\n  break x => 1.0 when a;\nend;\n";
    let d = ok(&src(text), "t");
    let names: Vec<&str> = d.processes.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names, ["_p0", "_p1", "_p2", "_p3"]);
    // The break waits on the signals of its condition.
    assert!(
        matches!(&d.processes[3].code[1], Instr::Wait { on, .. } if on.len() == 1 && on[0].index() == 1)
    );
}

#[test]
fn unlabelled_processes_count_per_region_around_nested_ones() {
    let text = "entity leaf is end;\narchitecture a of leaf is\n  signal s : boolean;\nbegin\n  s <= true;\nend;\nentity t is end;\narchitecture a of t is\n  signal a : boolean;\nbegin\n  a <= true;\n  b : block begin\n    a <= false;\n  end block b;\n  u : entity work.leaf;\n  a <= a;\n  g : for i in 1 to 2 generate\n    a <= a;\n  end generate g;\n  a <= not a;\nend;\n";
    let d = ok(&src(text), "t");
    let names: Vec<&str> = d.processes.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "_p0", "b._p0", "u._p0", "_p1", "g(1)._p0", "g(2)._p0", "_p2"
        ]
    );
}

#[test]
fn integer_and_real_do_not_mix() {
    let e = errors(
        &src(
            "entity t is end;\narchitecture a of t is\n  quantity x : real;\nbegin\n  x == 2 * x;\nend;\n",
        ),
        "t",
    );
    assert_eq!(e.len(), 1);
    assert!(e[0].contains("vams::elab::bad_operands"), "{}", e[0]);
    assert!(e[0].contains("write a real literal"), "{}", e[0]);
}

#[test]
fn several_errors_are_collected() {
    let e = errors(
        &src(
            "entity t is end;\narchitecture a of t is\n  quantity x : real;\n  signal s : real;\nbegin\n  x == y;\n  x <= 1.0;\n  s == 1.0;\nend;\n",
        ),
        "t",
    );
    assert!(e.len() >= 2, "{e:#?}");
    assert!(
        e[0].contains("did you mean `x`?") || e[0].contains("`y` is not declared"),
        "{}",
        e[0]
    );
}

#[test]
fn generic_overrides_are_checked() {
    let text = src(
        "entity t is generic (r : real := 1.0; n : integer); end;\narchitecture a of t is\n  quantity x : real;\nbegin\n  x == r;\nend;\n",
    );
    let (_, r) = run(&text, "t", &[("n", "3"), ("rr", "2.0")]);
    let e = r.expect_err("unknown generic");
    assert!(
        e.iter()
            .any(|e| matches!(e, crate::ElabError::UnknownGeneric { .. }))
    );
    let (_, r) = run(&text, "t", &[]);
    assert!(
        r.expect_err("missing")
            .iter()
            .any(|e| matches!(e, crate::ElabError::MissingGeneric { .. }))
    );
    let (_, r) = run(&text, "t", &[("n", "x")]);
    assert!(
        r.expect_err("bad")
            .iter()
            .any(|e| matches!(e, crate::ElabError::BadGenericValue { .. }))
    );
    let (_, r) = run(&text, "t", &[("n", "3"), ("R", "2.5")]);
    let d = r.expect("overrides");
    assert_eq!(
        d.equations[0].residual,
        Expr::Binary(
            BinaryOp::Sub,
            Box::new(Expr::Quantity(vams_design::QuantityId(0))),
            Box::new(Expr::real(2.5))
        )
    );
}

/// Use regions are shared between units with the same context clause, but a clause that fails
/// is reported for every unit that has it, and a shared region written by a nested `use`
/// stays unchanged for the others.
#[test]
fn shared_use_regions_keep_errors_and_visibility_per_unit() {
    let text = "
use ieee.no_such_package.all;
entity a is end entity;
architecture x of a is begin end architecture;
use ieee.no_such_package.all;
entity b is end entity;
architecture x of b is begin end architecture;
entity top is end entity;
architecture x of top is begin
  ua : entity work.a;
  ub : entity work.b;
end architecture;
";
    let (_, r) = run(text, "top", &[]);
    let errors = r.expect_err("the package does not exist");
    assert_eq!(errors.len(), 2, "{errors:?}");
    let text = "
library ieee;
entity c is end entity;
architecture x of c is
  use ieee.math_real.all;
  constant k : real := math_pi;
begin end architecture;
library ieee;
entity d is end entity;
architecture x of d is
  constant k : real := math_pi;
begin end architecture;
entity top is end entity;
architecture x of top is begin
  uc : entity work.c;
  ud : entity work.d;
end architecture;
";
    let (_, r) = run(text, "top", &[]);
    let errors = r.expect_err("math_pi is not visible in d");
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert!(format!("{:?}", errors[0]).contains("math_pi"));
}
