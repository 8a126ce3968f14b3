//! Functions and procedures: lowering, overloads, signal parameters, inlining in equations and
//! the diagnostics of what subprograms cannot do.

use vams_design::{Expr, Instr, ParamMode, SubprogramKind};

use super::{errors, ok};

#[test]
fn overloads_by_argument_type_lower_to_separate_subprograms() {
    let d = ok(
        "entity t is end;
architecture a of t is
  function f (x : real) return real is begin return x; end function;
  function f (n : integer) return integer is begin return n + 1; end function;
begin
  process
    variable r : real;
    variable i : integer;
  begin
    r := f(1.0);
    i := f(1);
    wait;
  end process;
end;
",
        "t",
    );
    assert_eq!(d.subprograms.len(), 2);
    let called: Vec<u32> = d.processes[0]
        .code
        .iter()
        .filter_map(|i| match i {
            Instr::SetVar {
                value: Expr::FnCall { sub, .. },
                ..
            } => Some(sub.0),
            _ => None,
        })
        .collect();
    assert_eq!(called, [0, 1]);
    assert_eq!(d.subprograms[0].vars[0].ty, vams_design::Type::Real);
    assert_eq!(d.subprograms[1].vars[0].ty, vams_design::Type::Integer);
}

#[test]
fn procedures_get_one_instance_per_actual_signal_and_copy_back_out_parameters() {
    let d = ok(
        "entity t is end;
architecture a of t is
  signal s1, s2 : bit;
  procedure set (signal s : out bit; v : in bit; done : out boolean) is
  begin
    s <= v;
    done := true;
  end procedure;
begin
  process
    variable ok1 : boolean;
  begin
    set(s1, '1', ok1);
    set(s2, '1', ok1);
    set(s1, '0', ok1);
    wait;
  end process;
end;
",
        "t",
    );
    assert_eq!(d.subprograms.len(), 2, "one instance per actual signal");
    assert!(d.subprograms.iter().all(
        |s| s.kind == SubprogramKind::Procedure && s.params == [ParamMode::In, ParamMode::Out]
    ));
    let calls: Vec<_> = d.processes[0]
        .code
        .iter()
        .filter_map(|i| match i {
            Instr::Call {
                sub,
                copy_back,
                signals,
                ..
            } => Some((sub.0, copy_back.len(), signals.clone())),
            _ => None,
        })
        .collect();
    assert_eq!(calls.len(), 3);
    assert_eq!(calls[0].0, calls[2].0);
    assert_ne!(calls[0].0, calls[1].0);
    assert!(calls.iter().all(|c| c.1 == 1));
    let assigned: Vec<_> = d
        .subprograms
        .iter()
        .map(|s| {
            s.code.iter().find_map(|i| match i {
                Instr::Assign { target, .. } => Some(d.signals[target.index()].name.clone()),
                _ => None,
            })
        })
        .collect();
    assert_eq!(assigned, [Some("s1".to_string()), Some("s2".to_string())]);
}

#[test]
fn a_straight_line_function_is_inlined_into_an_equation() {
    let d = ok(
        "entity t is end;
architecture a of t is
  constant k : real := 3.0;
  function g (x : real) return real is
    constant two : real := 2.0;
    variable y : real := two * x;
  begin
    y := y + k;
    return y;
  end function;
  quantity q : real;
begin
  q == g(1.5);
end;
",
        "t",
    );
    // q - (2 * 1.5 + 3), folded after inlining.
    let e = &d.equations[0].residual;
    assert!(e.is_analog(), "{e:?}");
    let mut calls = 0;
    e.visit(&mut |x| calls += usize::from(matches!(x, Expr::FnCall { .. })));
    assert_eq!(calls, 0);
    let mut consts = Vec::new();
    e.visit(&mut |x| {
        if let Expr::Const(v) = x {
            consts.push(v.as_f64());
        }
    });
    assert_eq!(consts, [Some(6.0)]);
}

#[test]
fn functions_cannot_wait_or_assign_signals() {
    let errs = errors(
        "entity t is end;
architecture a of t is
  signal s : bit;
  function f (x : integer) return integer is
  begin
    wait for 1 ns;
    s <= '1';
    return x;
  end function;
begin
  process
    variable v : integer;
  begin
    v := f(1);
    wait;
  end process;
end;
",
        "t",
    );
    let text = errs.join("\n");
    assert!(text.contains("a function cannot wait"), "{text}");
    assert!(text.contains("a function cannot assign signals"), "{text}");
}

/// A function declared in a process reads the process's variables (passed to each call);
/// one that assigns them is refused, as a call has nothing to copy back.
#[test]
fn a_local_function_reads_but_does_not_assign_process_variables() {
    let reads = "entity t is end;
architecture a of t is
begin
  process
    variable count : integer := 0;
    impure function next_count return integer is
    begin
      return count + 1;
    end function;
  begin
    count := next_count;
    wait;
  end process;
end;
";
    ok(reads, "t");
    let assigns = reads.replace("return count + 1;", "count := 5;\n      return count;");
    let errs = errors(&assigns, "t");
    assert!(
        errs.join("\n")
            .contains("assigns a variable of its process"),
        "{}",
        errs.join("\n")
    );
}

/// Overloads that only the context resolves: `f(g(1.0), true)` calls the `f` of `(real,
/// boolean)` with the `g` that returns real, since no `g` gives the other `f` a boolean's
/// place. Elaboration takes the overload analysis chose; on its own it lowered `g(1.0)`
/// without an expected type, took the first `g` (integer) and found no `f` for it.
#[test]
fn the_overload_analysis_chose_is_the_one_called() {
    let d = ok(
        "entity t is end;
architecture a of t is
  function g (x : real) return integer is begin return 1; end function;
  function g (x : real) return real is begin return 2.5; end function;
  function f (x : real; b : boolean) return real is begin return x; end function;
  function f (x : integer; b : integer) return real is begin return 0.0; end function;
begin
  process
    variable r : real;
  begin
    r := f(g(1.0), true);
    wait;
  end process;
end;
",
        "t",
    );
    assert_eq!(d.subprograms.len(), 2, "f and g, once each");
    for sub in &d.subprograms {
        assert_eq!(sub.vars[0].ty, vams_design::Type::Real, "{}", sub.name);
    }
}
