//! `vams check` end to end: the bundled stdlib and the models are clean; each kind of mistake
//! in `tests/diagnostics/` renders the diagnostic recorded in its snapshot; bad input of every
//! kind exits 1 without a panic.

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
