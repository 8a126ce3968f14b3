//! `vams check` analyses every design unit of every file, whether or not a top reaches it:
//! each file of `tests/analysis/` with errors renders the diagnostics recorded in its
//! snapshot; units in any file order analyse cleanly.

use assert_cmd::Command;

fn vams() -> Command {
    Command::cargo_bin("vams").expect("the vams binary is built for integration tests")
}

#[test]
fn errors_in_units_no_top_reaches_match_their_snapshots() {
    for name in [
        "unreached",
        "unused_package",
        "circular",
        "not_static",
        "ambiguous_now",
    ] {
        let path = format!("tests/analysis/{name}.vhd");
        let output = vams().arg("check").arg(&path).output().unwrap();
        assert_eq!(output.status.code(), Some(1), "{name}");
        let stderr = String::from_utf8(output.stderr).unwrap();
        insta::assert_snapshot!(format!("analysis_{name}"), stderr);
    }
}

#[test]
fn units_are_analysed_in_dependency_order_whatever_the_file_order() {
    vams()
        .args(["check", "tests/analysis/any_order.vhd"])
        .assert()
        .success()
        .stderr(predicates::str::contains("1 top(s) elaborated"));
}

#[test]
fn shipped_models_and_stdlib_analyse_cleanly() {
    vams()
        .args(["check", "models", "stdlib", "benches/models"])
        .assert()
        .success();
}
