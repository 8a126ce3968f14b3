//! Analysis of small sources with the bundled stdlib.

use crate::stdlib;
use vams_syntax::ast::DesignFile;
use vams_syntax::parser::parse;
use vams_syntax::source::{FileId, SourceMap};

use super::{AnalysisError, DeclKind, analyse};

/// The stdlib plus `texts` as files of `work`, parsed (syntax errors fail the test).
fn load(texts: &[&str]) -> (SourceMap, Vec<(FileId, DesignFile)>) {
    let mut sources = SourceMap::new();
    let mut ids = stdlib::load(&mut sources);
    for (i, t) in texts.iter().enumerate() {
        ids.push(sources.add(format!("f{i}.vhd"), "work", t.to_string()));
    }
    let files = ids
        .into_iter()
        .map(|id| {
            let text = sources.file(id).text.clone();
            let (ast, errors) = parse(id, &text);
            assert!(errors.is_empty(), "{errors:?}");
            (id, ast)
        })
        .collect();
    (sources, files)
}

fn errors(texts: &[&str]) -> Vec<AnalysisError> {
    let (sources, files) = load(texts);
    analyse(&sources, &files).errors().cloned().collect()
}

fn messages(texts: &[&str]) -> Vec<String> {
    errors(texts).iter().map(|e| e.to_string()).collect()
}

const WRAP: &str = "entity e is end entity e;\narchitecture a of e is\n";

fn arch(decls: &str, body: &str) -> String {
    format!("{WRAP}{decls}\nbegin\n{body}\nend architecture a;\n")
}

#[test]
fn the_stdlib_analyses_without_errors() {
    assert_eq!(messages(&[]), Vec::<String>::new());
}

#[test]
fn an_integer_literal_is_not_a_real() {
    let m = messages(&[&arch(
        "signal s : integer := 1.5;\nconstant r : real := 2;",
        "",
    )]);
    assert_eq!(m.len(), 2, "{m:?}");
    assert!(
        m[0].contains("expected `integer`, found a real literal"),
        "{m:?}"
    );
    assert!(
        m[1].contains("expected `real`, found an integer literal"),
        "{m:?}"
    );
}

#[test]
fn operators_need_operands_of_one_type() {
    let m = messages(&[&arch(
        "constant x : real := 1.0;\nconstant y : real := x * 2;\nconstant z : real := x * 2.0 + 1.0e-3;",
        "",
    )]);
    assert_eq!(
        m,
        ["no `*` takes `real` and an integer literal (universal_integer)"]
    );
}

#[test]
fn physical_arithmetic_follows_the_predefined_operators() {
    let ok = arch(
        "constant t1 : time := 2 * 10 ns;\nconstant t2 : time := 1.5 * t1;\n\
         constant n : integer := t2 / t1;\nconstant r : real := real(n) * 2.0;",
        "",
    );
    assert_eq!(messages(&[&ok]), Vec::<String>::new());
    let bad = arch("constant t : time := 10 ns + 1.0;", "");
    assert_eq!(messages(&[&bad]).len(), 1);
}

#[test]
fn overloads_are_chosen_by_the_expected_type() {
    // `now` is both a time and a real; the context decides.
    let ok = arch(
        "quantity q : real;",
        "q == now * 2.0;\nprocess begin\n  wait for now;\n  assert now < 1 ms;\n  wait;\nend process;",
    );
    assert_eq!(messages(&[&ok]), Vec::<String>::new());
}

#[test]
fn undeclared_names_are_reported_with_a_suggestion() {
    let e = errors(&[&arch("signal speed : real;", "speed <= sped after 1 ns;")]);
    match e.as_slice() {
        [AnalysisError::Undeclared { name, help, .. }] => {
            assert_eq!(name, "sped");
            assert_eq!(help.as_deref(), Some("did you mean `speed`?"));
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn std_logic_and_math_real_resolve() {
    let ok = format!(
        "library ieee;\nuse ieee.std_logic_1164.all;\nuse ieee.math_real.all;\n{}",
        arch(
            "signal a, b : std_logic := '0';\nsignal v : std_logic_vector(3 downto 0);\n\
             constant c : real := sin(math_pi / 2.0) + sqrt(2.0);",
            "a <= b and '1';\nv <= \"10\" & a & b;\nb <= v(2) xor a;",
        )
    );
    assert_eq!(messages(&[&ok]), Vec::<String>::new());
}

#[test]
fn analog_declarations_get_their_nature_types() {
    let ok = format!(
        "library ieee;\nuse ieee.electrical_systems.all;\n{}",
        arch(
            "terminal p, n : electrical;\nquantity v across i through p to n;\nconstant r : resistance := 1.0e3;",
            "v == r * i;\nbreak v => 0.0 when v'above(1.0);",
        )
    );
    assert_eq!(messages(&[&ok]), Vec::<String>::new());
    let bad = format!(
        "library ieee;\nuse ieee.electrical_systems.all;\n{}",
        arch("terminal p : electrical;\nquantity v across p;", "v == 5;",)
    );
    assert_eq!(messages(&[&bad]).len(), 1, "{:?}", messages(&[&bad]));
}

#[test]
fn file_order_does_not_change_the_result() {
    let pkg = "package p is\n  constant k : real := 2.0;\n  function f(x : real) return real;\nend package p;";
    let body = "package body p is\n  function f(x : real) return real is\n  begin\n    return x * k;\n  end function f;\nend package body p;";
    let user = "use work.p.all;\nentity u is end entity u;\narchitecture a of u is\n  signal s : real := f(k) + 1;\nbegin\nend architecture a;";
    let forward = messages(&[pkg, body, user]);
    let backward = messages(&[user, body, pkg]);
    assert_eq!(forward.len(), 1, "{forward:?}");
    assert_eq!(forward, backward);
}

/// A package named only by a selected name (`work.p.k`, no `use` clause) is analysed before
/// the unit that names it, whatever the file order (LRM 11.4).
#[test]
fn a_unit_named_by_a_selected_name_is_analysed_first() {
    let pkg =
        "package p is\n  type small is range 0 to 3;\n  constant k : real := 2.0;\nend package p;";
    let user = "entity u is end entity u;\narchitecture a of u is\n  signal s : work.p.small := 1;\n  constant c : real := work.p.k * 2.0;\nbegin\nend architecture a;";
    for order in [[user, pkg], [pkg, user]] {
        assert_eq!(messages(&order), Vec::<String>::new());
        let (sources, files) = load(&order);
        let a = analyse(&sources, &files);
        let user_file = files[files.len() - 2 + usize::from(order[0] == pkg)].0;
        for name in ["small", ".k "] {
            let at = user.find(name).expect("the use") as u32 + u32::from(name == ".k ");
            let d = a.declaration_at(user_file, at).expect("resolves");
            assert_eq!(a.decl(d).name, name.trim_matches(['.', ' ']));
        }
    }
}

/// An entity's own name does not hide what its context imports: `severity failure` in an
/// entity named `failure` is std.standard's literal.
#[test]
fn a_units_own_name_yields_to_imported_names() {
    let unit = "entity failure is end entity failure;\narchitecture a of failure is\nbegin\n  process begin\n    assert false report \"x\" severity failure;\n    wait;\n  end process;\nend architecture a;";
    assert_eq!(messages(&[unit]), Vec::<String>::new());
    let (sources, files) = load(&[unit]);
    let a = analyse(&sources, &files);
    let at = unit.rfind("failure").expect("the severity") as u32;
    let d = a
        .declaration_at(files.last().expect("the file").0, at)
        .expect("resolves");
    assert!(matches!(a.decl(d).kind, DeclKind::EnumLiteral(_)));
}

/// An alias with a signature denotes the overload of that profile; a signature no overload
/// has is reported at the signature.
#[test]
fn an_alias_signature_chooses_one_overload() {
    let pkg = "package p is\n  function f(x : integer) return integer;\n  function f(x : real) return real;\nend package p;";
    let ok = "entity u is end entity u;\narchitecture a of u is\n  alias g is work.p.f [real return real];\n  constant c : real := g(1.0);\nbegin\nend architecture a;";
    assert_eq!(messages(&[pkg, ok]), Vec::<String>::new());
    let (sources, files) = load(&[pkg, ok]);
    let a = analyse(&sources, &files);
    let at = ok.find(".f ").expect("the target") as u32 + 1;
    let d = a
        .declaration_at(files.last().expect("the file").0, at)
        .expect("resolves");
    assert!(
        matches!(&a.decl(d).kind, DeclKind::Subprogram(s) if s.result.is_some_and(|r| a.types.name(r) == "real")),
        "{:?}",
        a.decl(d)
    );
    let bad = ok.replace("[real return real]", "[boolean return real]");
    let m = messages(&[pkg, &bad]);
    assert!(
        m.len() == 1 && m[0].contains("no `f` takes [`boolean` return `real`]"),
        "{m:?}"
    );
}

#[test]
fn a_cycle_of_uses_is_one_diagnostic() {
    let e = errors(&[
        "use work.b.all;\npackage a is\n  constant x : integer := 1;\nend package a;",
        "use work.a.all;\npackage b is\n  constant y : integer := x + 1;\nend package b;",
    ]);
    assert!(
        matches!(e.as_slice(), [AnalysisError::CircularDependency { .. }]),
        "{e:?}"
    );
}

#[test]
fn instances_are_checked_against_the_interface() {
    let leaf = "entity leaf is\n  generic (gain : real);\n  port (x : in real);\nend entity leaf;\n\
                architecture a of leaf is begin end architecture a;";
    let top = arch(
        "signal s : real;",
        "u1 : entity work.leaf generic map (gain => 2) port map (x => s);\n\
         u2 : entity work.leaf generic map (gian => 2.0) port map (x => s);",
    );
    let m = messages(&[leaf, &top]);
    assert_eq!(m.len(), 2, "{m:?}");
    assert!(m[0].contains("expected `real`"), "{m:?}");
    assert!(m[1].contains("`gian` is not a generic of `leaf`"), "{m:?}");
}

#[test]
fn queries_answer_the_declaration_and_the_type_at_a_position() {
    let text = arch(
        "constant gain : real := 2.0;\nsignal s : real;",
        "s <= gain * s after 1 ns;",
    );
    let (sources, files) = load(&[&text]);
    let a = analyse(&sources, &files);
    let file = files.last().expect("the user file").0;
    let use_at = text.rfind("gain").expect("a use of gain") as u32;
    let d = a.declaration_at(file, use_at).expect("gain resolves");
    assert_eq!(a.decl(d).name, "gain");
    assert!(matches!(a.decl(d).kind, DeclKind::Object { .. }));
    let t = a.type_at(file, use_at).expect("a type");
    assert_eq!(a.types.name(t), "real");
}

#[test]
fn labels_are_visible_inside_their_own_statement() {
    let ok = arch(
        "signal d : bit;",
        "check : process (d) is\nbegin\n  report \"in \" & check'path_name;\nend process check;",
    );
    assert_eq!(messages(&[&ok]), Vec::<String>::new());
}

#[test]
fn file_types_bring_their_operations() {
    let ok = arch(
        "type int_file is file of integer;",
        "process is\n  file f : int_file open read_mode is \"data.txt\";\n  variable x : integer;\n\
         begin\n  while not endfile(f) loop\n    read(f, x);\n  end loop;\n  file_close(f);\n  wait;\nend process;",
    );
    assert_eq!(messages(&[&ok]), Vec::<String>::new());
}

#[test]
fn a_missing_primary_unit_is_one_diagnostic() {
    let e = errors(&[
        "architecture a of nowhere is\nbegin\n  p : process (clk) is begin end process;\nend architecture a;",
    ]);
    assert!(
        matches!(e.as_slice(), [AnalysisError::MissingUnit { .. }]),
        "{e:?}"
    );
    let e = errors(&[
        "use work.absent.all;\nentity u is end entity u;\narchitecture a of u is\n  constant k : real := from_absent;\nbegin\nend architecture a;",
    ]);
    assert!(
        matches!(e.as_slice(), [AnalysisError::MissingUnit { .. }]),
        "{e:?}"
    );
}

#[test]
fn an_architecture_belongs_to_the_entity_declared_before_it() {
    // Two variants of one entity in two files: each file's architecture sees its own.
    let v1 = "entity e is\n  port (x : in integer);\nend entity e;\narchitecture a of e is\n  signal s : integer;\nbegin\n  s <= x;\nend architecture a;";
    let v2 = "entity e is\n  port (x : in real);\nend entity e;\narchitecture b of e is\n  signal s : real;\nbegin\n  s <= x;\nend architecture b;";
    assert_eq!(messages(&[v1, v2]), Vec::<String>::new());
}

#[test]
fn queries_answer_references_and_the_names_visible_at_a_position() {
    let text = format!(
        "library ieee;\nuse ieee.math_real.all;\n{}",
        arch(
            "constant gain : real := 2.0;\nsignal s : real;",
            "p : process is\n  variable local_v : real;\nbegin\n  local_v := gain * s;\n  s <= gain after 1 ns;\n  wait;\nend process p;",
        )
    );
    let (sources, files) = load(&[&text]);
    let a = analyse(&sources, &files);
    let file = files.last().expect("the user file").0;
    let decl_at = text.find("gain").expect("the declaration") as u32;
    let d = a
        .declaration_at(file, decl_at)
        .expect("gain is a declaration");
    assert_eq!(a.references_to(d).len(), 3, "declared once, used twice");
    let in_process = text.find("local_v :=").expect("the assignment") as u32;
    let names = a.names_at(file, in_process);
    for n in ["local_v", "gain", "s", "math_pi", "integer", "now"] {
        assert!(names.contains(&n.to_string()), "{n} in {names:?}");
    }
    let in_architecture = text.find("signal s").expect("the signal") as u32;
    assert!(
        !a.names_at(file, in_architecture)
            .contains(&"local_v".to_string())
    );
}

/// Every analysed expression is marked with its staticness (LRM 7.4): literals and constants
/// initialised with them locally static, generics and what they compute globally static,
/// signals, variables and impure calls not static.
#[test]
fn expressions_are_marked_with_their_staticness() {
    use super::Staticness::{Global, Local, None};
    let text = "entity e is generic (g : real := 1.0); end entity e;\n\
                architecture a of e is\n\
                  constant c : real := 2.0 * 3.0;\n\
                  constant d : real := c + g;\n\
                  signal s : real := 0.0;\n\
                begin\n\
                  p : process\n\
                    variable v : real;\n\
                  begin\n\
                    v := c * 2.0;\n\
                    v := d * 2.0;\n\
                    v := s * 2.0;\n\
                    v := real'high;\n\
                    wait;\n\
                  end process p;\n\
                end architecture a;\n";
    let (sources, files) = load(&[text]);
    let analysis = analyse(&sources, &files);
    assert_eq!(analysis.errors().count(), 0);
    let file = files.last().expect("the test file").0;
    // At the operator (or the tick): the innermost expression there is the whole one.
    let at = |needle: &str| {
        let start = text.find(needle).expect("in the text");
        let op = needle.find(['*', '+', '\'']).expect("an operator");
        analysis.staticness_at(file, (start + op) as u32)
    };
    assert_eq!(at("2.0 * 3.0"), Local);
    assert_eq!(at("c + g"), Global);
    assert_eq!(at("c * 2.0"), Local);
    assert_eq!(at("d * 2.0"), Global);
    assert_eq!(at("s * 2.0"), None);
    assert_eq!(at("real'high"), Global);
}

/// A configuration specification names a visible component and an entity of the library.
#[test]
fn configuration_specifications_name_a_component_and_an_entity() {
    let leaf =
        "entity leaf is end entity leaf;\narchitecture a of leaf is begin end architecture a;\n";
    let good = "entity top is end entity top;\narchitecture a of top is\n\
                component leaf is end component;\n\
                for all : leaf use entity work.leaf(a);\n\
                begin\n  u : leaf;\nend architecture a;\n";
    assert!(
        messages(&[good, leaf]).is_empty(),
        "{:?}",
        messages(&[good, leaf])
    );
    let bad = "entity top is end entity top;\narchitecture a of top is\n\
               for all : leef use entity work.leaf(a);\n\
               begin\nend architecture a;\n";
    let m = messages(&[leaf, bad]);
    assert!(
        m.iter().any(|m| m.contains("`leef` is not declared")),
        "{m:?}"
    );
}

/// A configuration declaration is analysed after its entity and the architecture it names,
/// whatever the file order, and names an entity of the library.
#[test]
fn configuration_declarations_follow_their_entity() {
    let cfg = "configuration c of top is\n  for a\n    for u : leaf use entity work.leaf(a); end for;\n  end for;\nend configuration c;\n";
    let top = "entity top is end entity top;\narchitecture a of top is\n\
               component leaf is end component;\nbegin\n  u : leaf;\nend architecture a;\n";
    let leaf =
        "entity leaf is end entity leaf;\narchitecture a of leaf is begin end architecture a;\n";
    assert!(
        messages(&[cfg, top, leaf]).is_empty(),
        "{:?}",
        messages(&[cfg, top, leaf])
    );
    let missing = "configuration c of nothing is\n  for a\n  end for;\nend configuration c;\n";
    let m = messages(&[missing]);
    assert!(m.iter().any(|m| m.contains("nothing")), "{m:?}");
}

/// The de-facto packages std_logic_arith and std_logic_unsigned resolve: their types, their
/// arithmetic by operand types, and their conversions.
#[test]
fn std_logic_arith_and_unsigned_resolve() {
    let text = "library ieee;\nuse ieee.std_logic_1164.all;\nuse ieee.std_logic_arith.all;\n\
                use ieee.std_logic_unsigned.all;\n\
                entity e is end entity e;\narchitecture a of e is\n\
                signal u : unsigned(3 downto 0);\nsignal v : std_logic_vector(3 downto 0);\n\
                begin\n  p : process\n    variable n : integer;\n  begin\n\
                u <= u + 1;\n    v <= v + 1;\n    n := conv_integer(u) + conv_integer(v);\n\
                v <= conv_std_logic_vector(n, 4);\n    wait;\n  end process p;\nend architecture a;\n";
    assert_eq!(messages(&[text]), Vec::<String>::new());
}

/// numeric_bit resolves: its explicit operators on `unsigned` (an array of bit) hide the
/// predefined ones of the same profile (`and`, `sll`, `=`, `<`), and its `rising_edge` on bit
/// sits beside std_logic_1164's on std_ulogic.
#[test]
fn numeric_bit_resolves_beside_std_logic_1164() {
    let text = "library ieee;\nuse ieee.std_logic_1164.all;\nuse ieee.numeric_bit.all;\n\
                entity e is end entity e;\narchitecture a of e is\n\
                signal clk : bit;\nsignal sclk : std_logic;\n\
                signal u : unsigned(3 downto 0);\nsignal s : signed(3 downto 0);\n\
                begin\n  p : process (clk, sclk)\n    variable n : integer;\n  begin\n\
                if rising_edge(clk) and falling_edge(sclk) then\n\
                u <= (u and \"0110\") sll 1;\n      s <= -s + to_signed(n, 4);\n\
                n := to_integer(u) + to_integer(s);\n    end if;\n\
                if u = \"0110\" or u < 3 or s >= -2 then\n      u <= resize(u, 4);\n    end if;\n\
                end process p;\nend architecture a;\n";
    assert_eq!(messages(&[text]), Vec::<String>::new());
}

#[test]
fn an_element_of_a_terminal_array_resolves_to_the_array() {
    let cell = "library ieee;\nuse ieee.electrical_systems.all;\n\
                entity cell is\n  port (terminal p : electrical);\nend entity cell;\n\
                architecture a of cell is begin end architecture a;";
    let top = "library ieee;\nuse ieee.electrical_systems.all;\n\
               entity top is\nend entity top;\narchitecture a of top is\n\
               \x20 terminal node : electrical_vector(0 to 3);\nbegin\n\
               \x20 g : for k in 1 to 3 generate\n\
               \x20   u : entity work.cell port map (p => node(k - 1));\n\
               \x20 end generate g;\nend architecture a;";
    let (sources, files) = load(&[cell, top]);
    let a = analyse(&sources, &files);
    let file = files.last().expect("the user file").0;
    let use_at = top.rfind("node(k").expect("a use of node") as u32;
    let d = a.declaration_at(file, use_at).expect("node resolves");
    // The terminal array's declaration (an array nature is not modelled yet: `Opaque`).
    assert_eq!(a.decl(d).name, "node");
    let declared_at = top.find("node :").expect("the declaration") as u32;
    assert_eq!(a.decl(d).span.start, declared_at);
}

#[test]
fn the_predefined_attributes_are_sorted_and_include_the_analog_ones() {
    use crate::analysis::PREDEFINED_ATTRIBUTES as ATTRS;
    assert!(ATTRS.windows(2).all(|w| w[0] < w[1]), "sorted, each once");
    for a in [
        "dot", "integ", "above", "delayed", "ltf", "zoh", "slew", "ramp",
    ] {
        assert!(ATTRS.contains(&a), "{a}");
    }
    for a in [
        "reference",
        "contribution",
        "across",
        "through",
        "tolerance",
    ] {
        assert!(ATTRS.contains(&a), "{a}");
    }
}

#[test]
fn a_declarations_own_name_is_found_under_the_cursor() {
    let text = "entity e is\nend entity e;\narchitecture a of e is\n\
                \x20 signal s : bit;\nbegin\n  s <= '1';\nend architecture a;";
    let (sources, files) = load(&[text]);
    let a = analyse(&sources, &files);
    let file = files.last().expect("the user file").0;
    let declared = text.find("s :").expect("the declaration") as u32;
    let d = a.declared_at(file, declared).expect("found");
    assert_eq!(a.decl(d).name, "s");
    // The use resolves to the same declaration; `signal` itself names nothing.
    let used = text.find("s <=").expect("the use") as u32;
    assert_eq!(a.declaration_at(file, used), Some(d));
    assert_eq!(a.declared_at(file, declared - 3), None);
}
