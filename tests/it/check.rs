//! `vams check` end to end: the bundled stdlib and the models are clean; each kind of mistake
//! in `tests/diagnostics/` (syntax) and `tests/check/` (elaboration, analog structure) renders
//! the diagnostics recorded in its snapshot; bad input of every kind exits 1 without a panic.

use std::path::Path;

use assert_cmd::Command;
use vams::diagnostics::render_plain;
use vams::parser::parse;
use vams::source::SourceMap;

fn vams() -> Command {
    Command::cargo_bin("vams").expect("the vams binary is built for integration tests")
}

#[test]
fn stdlib_and_models_parse_cleanly() {
    vams()
        .args(["check", "models", "stdlib"])
        .assert()
        .success();
    let mut sources = SourceMap::new();
    for id in vams::stdlib::load(&mut sources) {
        let text = sources.file(id).text.clone();
        let (ast, errors) = parse(id, &text);
        assert!(errors.is_empty(), "{}: {errors:?}", sources.file(id).name);
        assert!(!ast.units.is_empty());
    }
}

#[test]
fn diagnostics_match_their_snapshots() {
    let dir = Path::new("tests/diagnostics");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "vhd"))
        .collect();
    files.sort();
    assert!(files.len() >= 6);
    for path in files {
        let text = std::fs::read_to_string(&path).unwrap();
        let name = path.file_stem().unwrap().to_str().unwrap().to_string();
        let mut sources = SourceMap::new();
        let id = sources.add(format!("{name}.vhd"), "work", text.clone());
        let (_, errors) = parse(id, &text);
        assert!(!errors.is_empty(), "{name} should have errors");
        let rendered: String = errors.iter().map(|e| render_plain(e, &sources)).collect();
        insta::assert_snapshot!(name, rendered);
        vams().arg("check").arg(&path).assert().code(1);
    }
}

/// Each file of `tests/check/` fails `vams check` with the whole stderr in its snapshot.
#[test]
fn semantic_and_structural_errors_match_their_snapshots() {
    let mut files: Vec<_> = std::fs::read_dir("tests/check")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "vhd"))
        .collect();
    files.sort();
    assert_eq!(files.len(), 8);
    for path in files {
        let name = path.file_stem().unwrap().to_str().unwrap().to_string();
        let output = vams().arg("check").arg(&path).output().unwrap();
        assert_eq!(output.status.code(), Some(1), "{name}");
        let stderr = String::from_utf8(output.stderr).unwrap();
        insta::assert_snapshot!(format!("check_{name}"), stderr);
    }
}

/// Entities that cannot stand alone are noted, not failed; an error in an entity that two tops
/// instantiate is printed once.
#[test]
fn lone_components_are_noted_and_shared_errors_printed_once() {
    let dir = tempfile::tempdir().unwrap();
    let component = dir.path().join("component.vhd");
    std::fs::write(
        &component,
        "library ieee; use ieee.electrical_systems.all;
entity res is
  generic (r : real := 1.0);
  port (terminal p, n : electrical);
end entity;
architecture a of res is
  quantity v across i through p to n;
begin
  v == r * i;
end architecture;
entity scaled is generic (k : real); end entity;
architecture a of scaled is begin end architecture;
",
    )
    .unwrap();
    vams()
        .arg("check")
        .arg(&component)
        .assert()
        .success()
        .stderr(predicates::str::contains(
            "note: the analog system of `res` is not checked alone: port(s) `p`, `n` would be open",
        ))
        .stderr(predicates::str::contains(
            "note: `scaled` is not elaborated: no default for generic(s) `k`",
        ))
        .stderr(predicates::str::contains(
            "1 top(s) elaborated, 0 analog system(s) built: no errors",
        ));
    let shared = dir.path().join("shared.vhd");
    std::fs::write(
        &shared,
        "entity leaf is generic (k : real); end entity;
architecture a of leaf is
begin
end architecture;
entity top_a is end entity;
architecture a of top_a is begin u : entity work.leaf; end architecture;
entity top_b is end entity;
architecture a of top_b is begin u : entity work.leaf; end architecture;
",
    )
    .unwrap();
    let output = vams().arg("check").arg(&shared).output().unwrap();
    assert_eq!(output.status.code(), Some(1));
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert_eq!(
        stderr.matches("generic `k` of `leaf` has no value").count(),
        1,
        "{stderr}"
    );
    assert!(stderr.contains("2 top(s) elaborated"), "{stderr}");
    assert!(
        stderr.contains("0 syntax, 0 analysis, 1 elaboration and 0 analog error(s)"),
        "{stderr}"
    );
}

/// A folder of testbenches where each file carries its own copy of a package or entity (the
/// book's case studies): each unit sees the namesake declared last before it in file order,
/// in analysis and in elaboration alike, and an instance naming an architecture that only
/// another namesake has gets that one.
#[test]
fn namesake_units_of_several_files_are_the_ones_each_unit_sees() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("a.vhd"),
        "-- vams: stop 1 ns
package pwl is function step(x : real) return real; end package;
package body pwl is
  function step(x : real) return real is begin return x + 1.0; end function;
end package body;
entity reg is end entity;
architecture test of reg is begin end architecture;
use work.pwl.all;
entity tb_a is end entity;
architecture t of tb_a is
begin
  process begin
    assert step(1.0) = 2.0 report \"wrong step\" severity error;
    wait;
  end process;
  u : entity work.reg(behavioral);
end architecture;
",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("b.vhd"),
        "package pwl is function other(x : real) return real; end package;
package body pwl is
  function other(x : real) return real is begin return x; end function;
end package body;
entity reg is end entity;
architecture behavioral of reg is begin end architecture;
",
    )
    .unwrap();
    vams().arg("check").arg(dir.path()).assert().success();
    vams()
        .arg("test")
        .arg(dir.path())
        .assert()
        .success()
        .stdout(predicates::str::contains("1 passed, 0 failed"));
}

/// A file with syntax errors among others is left out, with a note naming it; the other
/// files are still analysed and elaborated, so their errors are reported in the same run.
#[test]
fn a_file_with_syntax_errors_does_not_hide_the_others_errors() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("broken.vhd"),
        "entity broken is end;\narchitecture a of broken is\n  type t is . . .;\nbegin end;\n",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("undriven.vhd"),
        "entity free is end;\narchitecture a of free is\n  quantity x, y : real;\nbegin\n  x == 1.0;\nend;\n",
    )
    .unwrap();
    vams()
        .arg("check")
        .arg(dir.path())
        .assert()
        .code(1)
        .stderr(predicates::str::contains("syntax error"))
        .stderr(predicates::str::contains(
            "1 file(s) with syntax errors left out of the analysis",
        ))
        .stderr(predicates::str::contains("broken.vhd"))
        .stderr(predicates::str::contains("1 equations for 2 unknowns"));
}

#[test]
fn bad_input_of_every_kind_exits_1() {
    let dir = tempfile::tempdir().unwrap();
    let garbage = dir.path().join("garbage.vhd");
    std::fs::write(
        &garbage,
        (0..4096u32)
            .map(|i| (i * 7919 % 256) as u8)
            .collect::<Vec<_>>(),
    )
    .unwrap();
    let deep = dir.path().join("deep.vhd");
    std::fs::write(
        &deep,
        format!(
            "package p is constant c : integer := {}1{}; end;",
            "(".repeat(5000),
            ")".repeat(5000)
        ),
    )
    .unwrap();
    let truncated = dir.path().join("truncated.vhd");
    std::fs::write(&truncated, "entity e is port (a : in bit").unwrap();
    for path in [&garbage, &deep, &truncated] {
        vams().arg("check").arg(path).assert().code(1);
    }
    vams()
        .args(["check", "no/such/file.vhd"])
        .assert()
        .code(1)
        .stderr(predicates::str::contains("cannot read"));
    vams().arg("check").assert().code(2);
}

/// A component instance that no entity binds is legal (LRM 5.2.2): `vams check` warns at the
/// instance and succeeds.
#[test]
fn an_unbound_component_instance_is_a_warning() {
    let out = vams()
        .args(["check", "tests/conformance/binding_indications.vhd"])
        .output()
        .expect("vams runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.contains("component instance `unused` is unbound")
            && stderr.contains("binding_indications.vhd:48:22"),
        "{stderr}"
    );
    assert!(stderr.contains(": no errors"), "{stderr}");
}

/// An entity declaration alone is legal VHDL (books show interfaces before their bodies):
/// `check` notes that it has nothing to elaborate instead of failing.
#[test]
fn an_entity_without_architecture_is_a_note() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let path = dir.path().join("interface.vhd");
    std::fs::write(
        &path,
        "entity small_adder is\n  port ( a, b : in integer; s : out integer );\nend entity small_adder;\n",
    )
    .expect("writable");
    let out = vams().arg("check").arg(&path).output().expect("vams runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.contains("note: `small_adder` is not elaborated: it has no architecture"),
        "{stderr}"
    );
    // Run, which must elaborate it, still says what is missing.
    let out = vams()
        .args(["run", "--stop", "1 ns"])
        .arg(&path)
        .output()
        .expect("vams runs");
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("has no architecture"));
}
