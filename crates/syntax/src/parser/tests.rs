use super::*;
use crate::ast::*;

fn parse_ok(text: &str) -> DesignFile {
    let (ast, errors) = parse(FileId(0), text);
    assert!(errors.is_empty(), "unexpected errors: {errors:#?}");
    ast
}

const RESISTOR: &str = r#"
library ieee;
use ieee.electrical_systems.all;

entity resistor is
  generic (r : real := 1.0e3);  -- ohms
  port (terminal p, n : electrical);
end entity resistor;

architecture ideal of resistor is
  quantity v across i through p to n;
begin
  v == i * r;
end architecture ideal;
"#;

#[test]
fn parses_a_resistor() {
    let ast = parse_ok(RESISTOR);
    assert_eq!(ast.units.len(), 2);
    let LibraryUnit::Architecture(arch) = &ast.units[1].unit else {
        panic!("expected an architecture")
    };
    assert_eq!(arch.name.name, "ideal");
    assert!(matches!(
        arch.stmts[0].kind,
        ConcKind::Simultaneous(SimKind::Simple { .. })
    ));
}

const MIXED: &str = r#"
library ieee; use ieee.std_logic_1164.all; use ieee.math_real.all;
use ieee.mechanical_systems.all;
entity tb_ball is end;
architecture a of tb_ball is
  quantity x : real := 10.0;
  quantity v : real := 0.0;
  constant g : real := 9.81;
  signal s : std_logic := '0';
  signal hit : boolean;
  type state_t is (idle, run, \Brake Mode\);
  type arr is array (natural range <>) of real;
  subtype small is integer range 0 to 7;
  function sq(a : real) return real is
  begin
    return a * a;
  end function sq;
begin
  x'dot == v;
  v'dot == -g;
  break v => -0.8 * v when not x'above(0.0);
  p : process (s) is
    variable k : integer := 0;
  begin
    if s = '1' and k /= 3 then
      k := k + 1;
    elsif s = 'X' then
      null;
    else
      k := 16#F#;
    end if;
    case k is
      when 0 | 1 => report "low" severity note;
      when 2 to 5 => k := k mod 2;
      when others => null;
    end case;
    for i in 0 to 3 loop
      next when i = 2;
      exit;
    end loop;
    s <= transport '1' after 10 ns, '0' after 20 ns;
    wait on s until s = '1' for 10 ms;
    assert k < 10 report "k=" & integer'image(k) severity error;
    break for x use v => 0.0 when k = 1;
  end process p;
  s2 : hit <= true when x < 0.0 else false;
  with s select hit <= true when '1', false when others;
  u1 : entity work.resistor(ideal) generic map (r => 2.0e3) port map (p => open, n => ground);
  g1 : for i in 1 to 3 generate
    signal t : bit;
  begin
    t <= '1';
  end generate g1;
  if x > 1.0 use
    x == 1.0;
  elsif v > 0.0 use
    null;
  else
    v == 2.0 ** 3 tolerance "default";
  end use;
  procedural is
    variable tmp : real;
  begin
    tmp := abs x;
  end procedural;
  assert v'delayed(1 ms) < 100.0;
end architecture;
"#;

#[test]
fn parses_mixed_signal_constructs() {
    let ast = parse_ok(MIXED);
    let LibraryUnit::Architecture(arch) = &ast.units[1].unit else {
        panic!("expected an architecture")
    };
    assert_eq!(arch.decls.len(), 9);
    assert_eq!(arch.stmts.len(), 11);
    let ConcKind::Instance { unit, .. } = &arch.stmts[6].kind else {
        panic!("expected an instance, got {:?}", arch.stmts[6].kind)
    };
    assert!(
        matches!(unit, InstantiatedUnit::Entity { architecture: Some(a), .. } if a.name == "ideal")
    );
}

#[test]
fn precedence_follows_the_lrm() {
    let ast = parse_ok("package p is constant c : real := -a * b + c ** 2 and d = e; end;");
    let LibraryUnit::Package(p) = &ast.units[0].unit else {
        panic!()
    };
    let DeclKind::Constant { value: Some(v), .. } = &p.decls[0].kind else {
        panic!()
    };
    // (((-(a*b)) + (c**2)) and (d = e))
    let ExprKind::Binary(BinaryOp::And, lhs, rhs) = &v.kind else {
        panic!("{v:?}")
    };
    assert!(matches!(rhs.kind, ExprKind::Binary(BinaryOp::Eq, ..)));
    let ExprKind::Binary(BinaryOp::Add, neg, _) = &lhs.kind else {
        panic!()
    };
    assert!(
        matches!(&neg.kind, ExprKind::Unary(UnaryOp::Minus, inner) if matches!(inner.kind, ExprKind::Binary(BinaryOp::Mul, ..)))
    );
}

#[test]
fn several_errors_are_reported_per_file() {
    let text = "entity e is end;\narchitecture a of e is\n signal x : bit\n signal y : bit;\nbegin\n x <= '1'\n y <= '0';\nend;\n";
    let (ast, errors) = parse(FileId(0), text);
    assert_eq!(errors.len(), 2, "{errors:#?}");
    assert_eq!(ast.units.len(), 2);
}

#[test]
fn end_label_mismatch_is_reported() {
    let (_, errors) = parse(FileId(0), "entity e is end entity f;");
    assert!(matches!(errors[0], SyntaxError::EndLabel { .. }));
}

#[test]
fn truncated_file_is_reported() {
    let (_, errors) = parse(FileId(0), "entity e is port (a : in bit");
    assert!(matches!(
        errors.last(),
        Some(SyntaxError::UnexpectedEof { .. })
    ));
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(200))]
    #[test]
    fn parser_never_panics(s in "\\PC{0,300}") {
        let _ = parse(FileId(0), &s);
    }

    #[test]
    fn parser_never_panics_on_mutated_vhdl(cut in 0usize..1200, junk in "[a-z;:()=<> ']{0,6}") {
        let mut text = MIXED.to_string();
        let at = cut.min(text.len());
        let at = (0..=at).rev().find(|&i| text.is_char_boundary(i)).unwrap_or(0);
        text.insert_str(at, &junk);
        let _ = parse(FileId(0), &text);
    }
}
