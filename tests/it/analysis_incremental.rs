//! Incremental analysis equals analysis from scratch: random sequences of edits (a file
//! replaced by an earlier version or a mutated one, removed, added back) over the shipped
//! models and test sources; after each, the host's analysis says exactly what analysing every
//! file again says (diagnostics, resolved names, types, static marks and scopes; only the
//! numbering of its tables may differ, since edited units are analysed last).

use std::path::Path;

use crate::support::fixed_seed;

use proptest::prelude::*;
use vams::analysis::{Analysis, AnalysisHost, DeclKind, analyse};

/// The texts edits choose from: the headlight models and a few test sources with errors.
fn pool() -> Vec<(String, String)> {
    let mut out = Vec::new();
    for dir in ["models", "tests/analysis", "tests/check"] {
        let mut paths: Vec<_> = std::fs::read_dir(dir)
            .expect("source directory")
            .map(|e| e.expect("entry").path())
            .filter(|p| p.extension().is_some_and(|e| e == "vhd"))
            .collect();
        paths.sort();
        for p in paths {
            let name = Path::new(&p).to_string_lossy().into_owned();
            out.push((name, std::fs::read_to_string(&p).expect("readable")));
        }
    }
    out
}

/// What an analysis says, whatever the order its units were analysed in (declaration, type and
/// region ids are positions in tables that the order fills, and a re-analysis puts the edited
/// units last): per unit in file order its identity and dependencies, its diagnostics, every
/// resolved name as its declaration's name, span and kind, every expression's type by name,
/// the static marks, and the names visible in each declarative part.
fn normalized(a: &Analysis) -> String {
    use std::fmt::Write;
    let kind = |k: &DeclKind| match k {
        DeclKind::Object { class, ty, value } => {
            format!("object {class:?} {} {value:?}", a.types.name(*ty))
        }
        DeclKind::Type(t) => format!("type {}", a.types.name(*t)),
        DeclKind::EnumLiteral(t) => format!("literal {}", a.types.name(*t)),
        DeclKind::Subprogram(sig) => format!(
            "subprogram ({}) {:?}",
            sig.params
                .iter()
                .map(|p| a.types.name(p.ty).to_string())
                .collect::<Vec<_>>()
                .join(", "),
            sig.result.map(|r| a.types.name(r).to_string())
        ),
        other => format!("{:?}", std::mem::discriminant(other)),
    };
    let mut out = String::new();
    for u in &a.units {
        let _ = writeln!(
            out,
            "unit {} {} {:?} {:?} {:?} primary {:?} deps {:?} incomplete {}",
            u.library, u.name, u.kind, u.file, u.span, u.primary, u.depends_on, u.incomplete
        );
        let _ = writeln!(out, "  errors {:?}", u.errors);
        if let Some(d) = u.decl {
            let _ = writeln!(out, "  decl {} {:?}", a.decl(d).name, a.decl(d).span);
        }
        for (span, d) in &u.references {
            let decl = a.decl(*d);
            let _ = writeln!(
                out,
                "  ref {span:?} {} {:?} {}",
                decl.name,
                decl.span,
                kind(&decl.kind)
            );
        }
        for (span, t) in &u.types {
            let _ = writeln!(out, "  type {span:?} {}", a.types.name(*t));
        }
        let _ = writeln!(out, "  statics {:?}", u.statics);
        if u.library == "work" {
            for (span, regions) in &u.scopes {
                let mut names: Vec<String> = regions
                    .iter()
                    .flat_map(|r| {
                        a.regions[r.0 as usize]
                            .names
                            .iter()
                            .map(|(n, ds)| format!("{n}/{}", ds.len()))
                    })
                    .collect();
                names.sort();
                let _ = writeln!(out, "  scope {span:?} {}", names.join(" "));
            }
        }
    }
    out
}

/// One edit: which file, and what to do with it.
#[derive(Clone, Debug)]
enum Edit {
    /// The file's original text (adds it back if removed).
    Original(usize),
    /// The original without line `n` (modulo its length): often a syntax or a name error.
    DropLine(usize, usize),
    /// The original with line `n` doubled (a redeclaration, a duplicate statement).
    DoubleLine(usize, usize),
    Remove(usize),
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        (0..64usize).prop_map(Edit::Original),
        (0..64usize, 0..400usize).prop_map(|(f, n)| Edit::DropLine(f, n)),
        (0..64usize, 0..400usize).prop_map(|(f, n)| Edit::DoubleLine(f, n)),
        (0..64usize).prop_map(Edit::Remove),
    ]
}

fn with_line(text: &str, n: usize, double: bool) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let n = n % lines.len().max(1);
    let mut out = String::new();
    for (i, l) in lines.iter().enumerate() {
        if i != n || double {
            out.push_str(l);
            out.push('\n');
        }
        if i == n && double {
            out.push_str(l);
            out.push('\n');
        }
    }
    out
}

proptest! {
    #![proptest_config(fixed_seed::config(12))]

    #[test]
    fn incremental_analysis_equals_analysis_from_scratch(edits in prop::collection::vec(edit(), 1..8)) {
        let pool = pool();
        let mut host = AnalysisHost::new();
        // Start from the models, as an editor opening the project would.
        for (name, text) in pool.iter().filter(|(n, _)| n.starts_with("models")) {
            host.set_file(name, text.clone());
        }
        for e in &edits {
            match *e {
                Edit::Original(f) => {
                    let (name, text) = &pool[f % pool.len()];
                    host.set_file(name, text.clone());
                }
                Edit::DropLine(f, n) | Edit::DoubleLine(f, n) => {
                    let (name, text) = &pool[f % pool.len()];
                    let double = matches!(e, Edit::DoubleLine(..));
                    host.set_file(name, with_line(text, n, double));
                }
                Edit::Remove(f) => {
                    host.remove_file(&pool[f % pool.len()].0);
                }
            }
            let scratch = analyse(host.sources(), host.files());
            prop_assert_eq!(normalized(host.analysis()), normalized(&scratch), "after {:?}", e);
        }
    }
}

/// An edit of the last model file takes over everything analysed before it.
#[test]
fn an_edit_reanalyses_only_from_the_first_unit_it_affects() {
    let mut host = AnalysisHost::new();
    let stdlib_units = host.analysis().units.len();
    let motor = std::fs::read_to_string("models/dc_motor.vhd").expect("model");
    host.set_file("models/dc_motor.vhd", motor.clone());
    assert_eq!(
        host.reused(),
        stdlib_units,
        "adding a file keeps the stdlib"
    );
    host.set_file(
        "models/dc_motor.vhd",
        motor.replace("behavioral", "behavioural"),
    );
    assert!(host.reused() >= stdlib_units);
    assert!(host.analysis().errors().next().is_none());
    host.set_file(
        "models/dc_motor.vhd",
        motor.replacen("architecture", "-- an edit\narchitecture", 1),
    );
    assert!(host.reused() >= stdlib_units);
    // Setting the same text again changes nothing.
    let before = format!("{:?}", host.analysis());
    host.set_file(
        "models/dc_motor.vhd",
        motor.replacen("architecture", "-- an edit\narchitecture", 1),
    );
    assert_eq!(host.reused(), host.analysis().units.len());
    assert_eq!(format!("{:?}", host.analysis()), before);
}

/// A file edited again is re-analysed with its dependents only: the first edit puts its units
/// and those that depend on them last in analysis order, so the next edit keeps every other
/// unit, whatever the file order.
#[test]
fn repeated_edits_reanalyse_only_the_file_and_its_dependents() {
    let mut host = AnalysisHost::new();
    let mut names = Vec::new();
    for (name, text) in pool().into_iter().filter(|(n, _)| n.starts_with("models")) {
        host.set_file(&name, text);
        names.push(name);
    }
    // The motor model: early in file order, used by the servo and the testbenches.
    let motor = "models/dc_motor.vhd";
    let text = std::fs::read_to_string(motor).expect("model");
    host.set_file(
        motor,
        text.replacen("architecture", "-- one\narchitecture", 1),
    );
    host.set_file(
        motor,
        text.replacen("architecture", "-- two\narchitecture", 1),
    );
    let a = host.analysis();
    let file = a
        .units
        .iter()
        .find(|u| host.sources().file(u.file).name == motor)
        .expect("the motor's units")
        .file;
    // Its units and everything that depends on them, directly or not.
    let mut affected: Vec<bool> = a.units.iter().map(|u| u.file == file).collect();
    loop {
        let before = affected.iter().filter(|&&x| x).count();
        for (u, unit) in a.units.iter().enumerate() {
            if unit.depends_on.iter().any(|&d| affected[d]) {
                affected[u] = true;
            }
        }
        if affected.iter().filter(|&&x| x).count() == before {
            break;
        }
    }
    let affected = affected.iter().filter(|&&x| x).count();
    assert!(
        affected < a.units.len() / 2,
        "{affected} of {}",
        a.units.len()
    );
    assert_eq!(host.reused(), a.units.len() - affected);
    let scratch = analyse(host.sources(), host.files());
    assert_eq!(normalized(host.analysis()), normalized(&scratch));
}
