//! Elaboration diagnostics, golden: each `tests/elaborate/*.vhd` (top entity `t` unless the
//! first line says `-- top: NAME`) fails to elaborate with the diagnostics of its snapshot,
//! rendered as the CLI prints them. The files of `tests/elaborate/ok/` elaborate, and their
//! designs are checked object by object.

use std::path::Path;

use vams::design::{Design, QuantityKind};
use vams::diagnostics::render_plain;
use vams::elaborate::{ElabOptions, elaborate};
use vams::parser::parse;
use vams::source::SourceMap;

/// Elaborates `tests/elaborate/ok/<name>.vhd` with top entity `top`; panics with the rendered
/// diagnostics when it fails.
fn elaborate_ok(name: &str, top: &str) -> Design {
    let path = format!("tests/elaborate/ok/{name}.vhd");
    let text = std::fs::read_to_string(&path).expect("readable test file");
    let mut sources = SourceMap::new();
    let mut ids = vams::stdlib::load(&mut sources);
    ids.push(sources.add(path, "work", text));
    let mut files = Vec::new();
    for id in ids {
        let file_text = sources.file(id).text.clone();
        let (ast, errors) = parse(id, &file_text);
        assert!(errors.is_empty(), "{name}: syntax errors {errors:?}");
        files.push((id, ast));
    }
    let options = ElabOptions {
        top: top.into(),
        generics: Vec::new(),
    };
    match elaborate(&sources, &files, &options) {
        Ok(d) => d,
        Err(errors) => {
            let text: Vec<String> = errors.iter().map(|e| render_plain(e, &sources)).collect();
            panic!("{name} should elaborate:\n{}", text.join("\n"));
        }
    }
}

/// The names of the terminals at the ends of quantity `name`'s branch.
fn branch_ends(d: &Design, name: &str) -> (String, String) {
    let q = d
        .quantities
        .iter()
        .find(|q| q.name == name)
        .unwrap_or_else(|| panic!("no quantity {name}"));
    let (QuantityKind::Across { plus, minus } | QuantityKind::Through { plus, minus }) = q.kind
    else {
        panic!("{name} is not a branch quantity");
    };
    let t = |id: vams::design::TerminalId| d.terminals[id.index()].name.clone();
    (t(plus), t(minus))
}

#[test]
fn terminal_and_quantity_arrays_expand_into_scalar_objects() {
    let d = elaborate_ok("terminal_arrays", "t");
    let terminals: Vec<&str> = d
        .terminals
        .iter()
        .filter(|t| !t.is_reference)
        .map(|t| t.name.as_str())
        .collect();
    // Declaration order, left to right; ports are their actuals and add no terminal.
    assert_eq!(
        terminals,
        [
            "node(0)", "node(1)", "node(2)", "node(3)", "down(2)", "down(1)", "down(0)", "ends(0)",
            "ends(1)"
        ]
    );
    // The for-generate chains node(k - 1) to node(k).
    for k in 1..=3 {
        let (p, m) = branch_ends(&d, &format!("chain({k}).r.v"));
        assert_eq!(
            (p.as_str(), m.as_str()),
            (&*format!("node({})", k - 1), &*format!("node({k})"))
        );
    }
    assert_eq!(branch_ends(&d, "i_s").0, "node(0)");
    // The unconstrained port takes node's range 0 to 3: one resistor per element.
    for k in 0..=3 {
        let (p, m) = branch_ends(&d, &format!("gnd.g({k}).r.v"));
        assert_eq!(
            (p.as_str(), m.as_str()),
            (&*format!("node({k})"), "electrical_ref")
        );
    }
    // b : bus3 (1 to 3) on down (2 downto 0): b(1) is down(2), b(2) down(1), b(3) down(0).
    assert_eq!(
        branch_ends(&d, "both.v12"),
        ("down(2)".to_string(), "down(1)".to_string())
    );
    assert_eq!(
        branch_ends(&d, "both.v23"),
        ("down(0)".to_string(), "down(1)".to_string())
    );
    // Element by element: b(1) => ends(1), b(2) => node(3), b(3) => electrical_ref.
    assert_eq!(
        branch_ends(&d, "pick.v12"),
        ("ends(1)".to_string(), "node(3)".to_string())
    );
    assert_eq!(
        branch_ends(&d, "pick.v23"),
        ("electrical_ref".to_string(), "node(3)".to_string())
    );
    assert_eq!(
        branch_ends(&d, "e.v"),
        ("ends(0)".to_string(), "ends(1)".to_string())
    );
    // Quantity arrays: free scalar quantities with their element of the initial value, and
    // the unit and tolerance of voltage_vector (electrical_vector'across) on u.
    let q = |name: &str| {
        d.quantities
            .iter()
            .find(|q| q.name == name)
            .unwrap_or_else(|| panic!("no quantity {name}"))
    };
    assert_eq!(q("q(1)").initial_guess, Some(0.5));
    assert_eq!(q("q(2)").initial_guess, Some(0.25));
    assert_eq!(q("q(1)").kind, QuantityKind::Free);
    assert_eq!(q("u(2)").tolerance.as_deref(), Some("DEFAULT_VOLTAGE"));
    assert_eq!(q("u(2)").unit.as_deref(), Some("V"));
    let texts: Vec<&str> = d.equations.iter().map(|e| e.text.as_str()).collect();
    assert!(texts.contains(&"q(1) == 2.0 * q(2);"), "{texts:?}");
}

#[test]
fn pre_standard_vector_subnatures_and_across_vector_subtypes_elaborate() {
    let d = elaborate_ok("terminal_arrays", "shafts");
    assert_eq!(
        branch_ends(&d, "w"),
        ("s(1)".to_string(), "s(2)".to_string())
    );
    let speed = d
        .quantities
        .iter()
        .find(|q| q.name == "speeds(2)")
        .expect("speeds(2) declared");
    assert_eq!(speed.kind, QuantityKind::Free);
    assert_eq!(speed.tolerance.as_deref(), Some("DEFAULT_ANGULAR_VELOCITY"));
}

#[test]
fn diagnostics_match_their_snapshots() {
    let dir = Path::new("tests/elaborate");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .expect("tests/elaborate exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "vhd"))
        .collect();
    files.sort();
    assert!(files.len() >= 10);
    for path in files {
        let text = std::fs::read_to_string(&path).expect("readable test file");
        let name = path
            .file_stem()
            .and_then(|s| s.to_str())
            .unwrap_or_default()
            .to_string();
        let top = text
            .lines()
            .next()
            .and_then(|l| l.strip_prefix("-- top: "))
            .unwrap_or("t")
            .trim()
            .to_string();
        let mut sources = SourceMap::new();
        let mut ids = vams::stdlib::load(&mut sources);
        ids.push(sources.add(format!("{name}.vhd"), "work", text.clone()));
        let mut files = Vec::new();
        for id in ids {
            let file_text = sources.file(id).text.clone();
            let (ast, errors) = parse(id, &file_text);
            assert!(errors.is_empty(), "{name}: syntax errors {errors:?}");
            files.push((id, ast));
        }
        let options = ElabOptions {
            top,
            generics: Vec::new(),
        };
        let errors = match elaborate(&sources, &files, &options) {
            Ok(_) => panic!("{name} should not elaborate"),
            Err(e) => e,
        };
        let rendered: String = errors
            .iter()
            .map(|e| render_plain(e, &sources))
            .collect::<Vec<_>>()
            .join("\n");
        insta::assert_snapshot!(name, rendered);
    }
}
