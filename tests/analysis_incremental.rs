//! Incremental analysis equals analysis from scratch: random sequences of edits (a file
//! replaced by an earlier version or a mutated one, removed, added back) over the shipped
//! models and test sources; after each, the host's analysis is exactly what analysing every
//! file again gives (diagnostics, resolved names and types: the whole `Analysis`).

use std::path::Path;

#[path = "support/fixed_seed.rs"]
mod fixed_seed;

use proptest::prelude::*;
use vams::analysis::{AnalysisHost, analyse};

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
            let mut incremental = host.analysis().clone();
            incremental.reused = 0;
            prop_assert_eq!(format!("{incremental:?}"), format!("{scratch:?}"), "after {:?}", e);
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
