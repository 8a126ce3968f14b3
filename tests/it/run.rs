//! `vams run`, `op` and `dae` end to end: usage errors, runs and their outputs, and what a
//! failed or interrupted run keeps.

use std::path::Path;

use assert_cmd::Command;
use predicates::str::contains;

#[cfg(unix)]
use crate::support::interrupt;

fn vams() -> Command {
    Command::cargo_bin("vams").expect("the vams binary is built for integration tests")
}

/// Writes `text` as the file `name` in a fresh temporary directory (kept alive by the
/// returned handle, which also holds any outputs a test writes beside it).
fn model_file(name: &str, text: &str) -> (tempfile::TempDir, std::path::PathBuf) {
    let dir = tempfile::tempdir().expect("temporary directory");
    let path = dir.path().join(name);
    std::fs::write(&path, text).expect("written");
    (dir, path)
}

#[test]
fn a_bad_time_is_a_usage_error_naming_the_accepted_forms() {
    for bad in ["6 parsecs", "-1s", "0", "soon"] {
        vams()
            .args(["run", "tests/run/rc.vhd", &format!("--stop={bad}")])
            .assert()
            .code(2)
            .stderr(contains("--stop"));
    }
    vams()
        .args(["run", "tests/run/rc.vhd", "--stop", "6 weeks"])
        .assert()
        .code(2)
        .stderr(contains("fs, ps, ns, us, ms, s or sec, min, hr"));
    vams()
        .args(["run", "tests/run/rc.vhd", "--max-step", "1 parsec"])
        .assert()
        .code(2);
}

#[test]
fn unknown_output_extensions_are_usage_errors() {
    vams()
        .args(["run", "tests/run/rc.vhd", "-o", "waves.txt"])
        .assert()
        .code(2)
        .stderr(contains(".csv or .vcd"));
    vams()
        .args(["run", "tests/run/rc.vhd", "--plot", "waves.pdf"])
        .assert()
        .code(2)
        .stderr(contains(".svg or .png"));
}

#[test]
fn malformed_generics_and_tolerances_are_usage_errors() {
    for args in [
        ["-g", "r"],
        ["-g", "=4"],
        ["--reltol", "0"],
        ["--abstol", "x"],
    ] {
        vams()
            .args(["run", "tests/run/rc.vhd"])
            .args(args)
            .assert()
            .code(2);
    }
}

#[test]
fn a_missing_source_file_is_diagnosed() {
    vams()
        .args(["run", "no/such/file.vhd", "--stop", "1ms"])
        .assert()
        .code(1)
        .stderr(contains("cannot read `no/such/file.vhd`"))
        .stderr(contains("vams::input::unreadable"));
    vams().arg("run").assert().code(2);
}

#[test]
fn a_bad_parameter_file_line_is_diagnosed_with_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let params = dir.path().join("motor.params");
    std::fs::write(&params, "# motor\nr=4.0\nl 3e-3\n").unwrap();
    vams()
        .args(["run", "tests/run/rc.vhd", "--params"])
        .arg(&params)
        .assert()
        .code(1)
        .stderr(contains("motor.params:3: expected `name=value`"))
        .stderr(contains("vams::params::bad_line"));
}

#[test]
fn syntax_errors_stop_before_elaboration() {
    vams()
        .args([
            "run",
            "tests/diagnostics/missing_semicolon.vhd",
            "--stop",
            "1 ms",
        ])
        .assert()
        .code(1)
        .stderr(contains("nothing was elaborated"));
    vams()
        .args(["op", "tests/diagnostics/end_label.vhd"])
        .assert()
        .code(1);
    vams()
        .args(["dae", "tests/diagnostics/end_label.vhd"])
        .assert()
        .code(1);
}

#[test]
fn help_documents_every_option() {
    let out = vams().args(["run", "--help"]).output().unwrap();
    let help = String::from_utf8(out.stdout).unwrap();
    for option in [
        "--top",
        "--stop",
        "--out",
        "--plot",
        "--reltol",
        "--abstol",
        "--max-step",
        "--generic",
        "--params",
        "--probe",
        "--panel",
        "--stats",
        "vams: stop",
    ] {
        assert!(help.contains(option), "`vams run --help` lacks {option}");
    }
    for command in ["op", "dae", "test"] {
        vams().args([command, "--help"]).assert().success();
    }
}

// ---- With the engine ----

fn csv_column(text: &str, name: &str) -> Vec<(f64, f64)> {
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(header[0], "time");
    let col = header.iter().position(|h| *h == name).unwrap();
    // A partial run's last line is a `# partial: ...` comment.
    lines
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            let cells: Vec<f64> = l.split(',').map(|c| c.parse().unwrap()).collect();
            (cells[0], cells[col])
        })
        .collect()
}

/// Every quantity is a default probe, whatever its name: a quantity array named `v` (whose
/// elements are named `v(1)`, as SPICE names a node voltage) is recorded like any other.
#[test]
fn quantities_named_like_node_voltages_are_default_probes() {
    let (dir, path) = model_file(
        "named.vhd",
        "entity named is end;\narchitecture a of named is\n  quantity v : real_vector(1 to 2);\n  quantity potential : real;\nbegin\n  v == (1.0, 2.0);\n  potential == 3.0;\nend;\n",
    );
    let csv = dir.path().join("named.csv");
    vams()
        .args(["run", "--stop", "1ms", "-o"])
        .arg(&csv)
        .arg(&path)
        .assert()
        .success();
    let text = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(text.lines().next(), Some("time,v(1),v(2),potential"));
    assert_eq!(csv_column(&text, "v(2)").last().map(|p| p.1), Some(2.0));
}

#[test]
fn rc_step_matches_its_closed_form_in_every_output() {
    let dir = tempfile::tempdir().unwrap();
    let (csv, vcd, svg) = (
        dir.path().join("rc.csv"),
        dir.path().join("rc.vcd"),
        dir.path().join("rc.svg"),
    );
    vams()
        .args(["run", "tests/run/rc.vhd", "--stats", "-o"])
        .arg(&csv)
        .arg("-o")
        .arg(&vcd)
        .arg("--plot")
        .arg(&svg)
        .assert()
        .success()
        .stderr(contains("simulated rc to 5 ms"))
        .stderr(contains("accepted steps"))
        .stderr(contains("delta cycles"));
    let text = std::fs::read_to_string(&csv).unwrap();
    let vout = csv_column(&text, "vout");
    assert!(vout.last().unwrap().0 >= 5e-3 * (1.0 - 1e-9));
    // Tolerance: 1e-2 V absolute, the default reltol 1e-3 leaves a good margin.
    for (t, v) in vout {
        let exact = if t <= 1e-3 {
            0.0
        } else {
            1.0 - (-(t - 1e-3) / 1e-3).exp()
        };
        assert!((v - exact).abs() < 1e-2, "vout({t}) = {v}, exact {exact}");
    }
    let dump = std::fs::read_to_string(&vcd).unwrap();
    assert!(dump.contains("$timescale 1 fs $end") && dump.contains("$scope module rc $end"));
    assert!(dump.contains(" vout $end") && dump.contains("wire 1"));
    assert!(std::fs::read_to_string(&svg).unwrap().contains("vout"));
}

#[test]
fn generics_from_params_and_command_line_change_the_time_constant() {
    let dir = tempfile::tempdir().unwrap();
    let (params, csv) = (dir.path().join("rc.params"), dir.path().join("rc.csv"));
    // c = 2 uF from the file; -g r=500 wins over the file's r=2e3: RC stays 1 ms.
    std::fs::write(&params, "r=2.0e3\nc=2.0e-6 -- F\n").unwrap();
    vams()
        .args([
            "run",
            "tests/run/rc.vhd",
            "--probe",
            "vout",
            "-g",
            "r=500.0",
            "--params",
        ])
        .arg(&params)
        .arg("-o")
        .arg(&csv)
        .assert()
        .success();
    let text = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(text.lines().next().unwrap(), "time,vout");
    let at_2ms = csv_column(&text, "vout")
        .into_iter()
        .min_by(|a, b| (a.0 - 2e-3).abs().total_cmp(&(b.0 - 2e-3).abs()))
        .unwrap();
    let exact = 1.0 - (-(at_2ms.0 - 1e-3) / 1e-3).exp();
    assert!((at_2ms.1 - exact).abs() < 1e-2, "{at_2ms:?} vs {exact}");
}

#[test]
fn reports_print_as_they_happen_and_a_failure_fails_the_run() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("f.csv");
    std::fs::write(&csv, "previous\n").unwrap();
    vams()
        .args(["run", "tests/run/failure.vhd", "-o"])
        .arg(&csv)
        .assert()
        .code(1)
        .stderr(contains("1 ms: note: starting"))
        .stderr(contains("2 ms: error: something is off"))
        .stderr(contains("failure.vhd:16:"))
        .stderr(contains("3 ms: failure: giving up"))
        .stderr(contains("vams::cli::run_failed"));
    // The waveforms up to the failure are still written, and say that they end there.
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.starts_with("time"), "{text}");
    assert_eq!(
        text.lines().last(),
        Some("# partial: stopped by an assertion of severity failure at t = 3 ms")
    );
    // Errors alone do not fail `run`.
    vams()
        .args(["run", "tests/run/failure.vhd", "--stop", "2.5 ms"])
        .assert()
        .success()
        .stderr(contains("error: something is off"));
}

#[test]
fn headlight_tracking_runs_with_the_motor_parameters() {
    let dir = tempfile::tempdir().unwrap();
    let (csv, png) = (dir.path().join("t.csv"), dir.path().join("t.png"));
    vams()
        .args([
            "run",
            "models",
            "--top",
            "tb_tracking",
            "--params",
            "models/headlight.params",
        ])
        .args(["--panel", "vref,vfb", "--panel", "v_motor", "--panel", "ov"])
        .arg("-o")
        .arg(&csv)
        .arg("--plot")
        .arg(&png)
        .assert()
        .success()
        .stderr(contains("simulated tb_tracking to 6 s"));
    let text = std::fs::read_to_string(&csv).unwrap();
    let vref = csv_column(&text, "vref");
    let at = |t: f64| {
        vref.iter()
            .min_by(|a, b| (a.0 - t).abs().total_cmp(&(b.0 - t).abs()))
            .unwrap()
            .1
    };
    assert!((at(1.0) - 1.0).abs() < 1e-6 && (at(5.0) - 2.0).abs() < 1e-6);
    assert!(Path::new(&png).exists());
}

#[test]
fn several_tops_need_top_and_a_missing_stop_is_diagnosed() {
    vams()
        .args(["run", "models"])
        .assert()
        .code(1)
        .stderr(contains("vams::cli::ambiguous_top"))
        .stderr(contains("tb_overvoltage"));
    vams()
        .args(["run", "models", "--top", "dc_motor"])
        .assert()
        .code(1)
        .stderr(contains("vams::cli::no_stop"));
}

#[test]
fn op_prints_the_quiescent_point_and_dae_the_equations() {
    vams()
        .args(["op", "tests/run/rc.vhd"])
        .assert()
        .success()
        .stdout(predicates::str::is_match(r"(?m)^vout +\S+ V$").unwrap())
        .stdout(predicates::str::is_match(r"(?m)^high +false$").unwrap());
    vams()
        .args(["op", "tests/run/rc.vhd", "-g", "r=2.0e3"])
        .assert()
        .success();
    vams()
        .args(["dae", "tests/run/rc.vhd"])
        .assert()
        .success()
        .stdout(contains("rc.vhd:"));
}

/// `--accuracy fine` is `--reltol 1e-6` by name (the same waveforms); with `--reltol` it is a
/// usage error.
#[test]
fn accuracy_names_a_relative_tolerance() {
    let dir = tempfile::tempdir().unwrap();
    let (named, given) = (dir.path().join("named.csv"), dir.path().join("given.csv"));
    for (args, out) in [
        (["--accuracy", "fine"], &named),
        (["--reltol", "1e-6"], &given),
    ] {
        vams()
            .args(["run", "tests/analog/msd_integ.vhd", "--stop", "0.5 s"])
            .args(args)
            .arg("-o")
            .arg(out)
            .assert()
            .success();
    }
    let text = |p: &std::path::Path| std::fs::read_to_string(p).unwrap();
    assert_eq!(text(&named), text(&given));
    vams()
        .args(["run", "tests/analog/msd_integ.vhd", "--stop", "0.5 s"])
        .args(["--accuracy", "draft", "--reltol", "1e-3"])
        .assert()
        .code(2)
        .stderr(contains("cannot be used with"));
}

/// `vams dae` on a model of index 3 shows the equations index reduction added (the
/// constraint's first and second derivatives, those of the velocities' definitions), the
/// derivatives made algebraic unknowns and the states, for teaching.
#[test]
fn dae_shows_what_index_reduction_differentiated() {
    let out = vams()
        .args(["dae", "tests/analog/pendulum.vhd"])
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    insta::assert_snapshot!(String::from_utf8_lossy(&out));
}

/// Every unit of every file given is analysed before the top is elaborated, as a VHDL tool
/// analyses each file first: an error in a package the top never uses fails the run, with
/// its location, and nothing is simulated.
#[test]
fn an_analysis_error_in_a_unit_the_top_does_not_reach_fails_the_run() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let out = dir.path().join("waves.csv");
    vams()
        .args([
            "run",
            "tests/run/rc.vhd",
            "tests/analysis/unused_package.vhd",
        ])
        .args(["--top", "rc", "-o"])
        .arg(&out)
        .assert()
        .code(1)
        .stderr(contains("`vmaxx` is not declared"))
        .stderr(contains("unused_package.vhd:4:28"))
        .stderr(contains("1 analysis error(s)"));
    assert!(!out.exists(), "nothing was simulated");
}

/// `--top` names a configuration declaration: its entity is elaborated with the bindings it
/// gives (r1 ideal, the others doubled: the divider's midpoint at 2/3 V instead of the 1/2 V
/// of the default binding); an incremental binding keeps the default entity and adds its map.
#[test]
fn a_configuration_declaration_is_a_top() {
    vams()
        .args(["op", "tests/conformance/configuration_declaration.vhd"])
        .args(["--top", "cfg_mixed"])
        .assert()
        .success()
        .stdout(contains("vmid    0.6666666666666"));
    vams()
        .args(["op", "tests/conformance/configuration_declaration.vhd"])
        .args(["--top", "cfg_incremental"])
        .assert()
        .success()
        .stdout(contains("vmid    0.75 V"));
    vams()
        .args(["op", "tests/conformance/configuration_declaration.vhd"])
        .args(["--top", "tb_configuration_declaration"])
        .assert()
        .success()
        .stdout(contains("vmid    0.5 V"));
}

/// A threshold crossing that flips back at every analog restart (equations switched by the
/// `'above` that decides them, without hysteresis) stops the run with a diagnostic naming the
/// signal, instead of looping at one time point and growing without bound.
#[test]
fn a_crossing_that_never_settles_is_an_error_not_a_hang() {
    let (_dir, model) = model_file(
        "chatter.vhd",
        "entity tb_chatter is end;\narchitecture a of tb_chatter is\n  quantity x : real;\n\
         begin\n  if x'above(0.5) use\n    x == 0.0;\n  else\n    x == 1.0;\n  end use;\n\
         break on x'above(0.5);\nend;\n",
    );
    vams()
        .arg("run")
        .arg(&model)
        .args(["--stop", "1 ms"])
        .timeout(std::time::Duration::from_secs(60))
        .assert()
        .code(1)
        .stderr(contains("did not settle at t = 0 s"))
        .stderr(contains("`x'above(0.5)`"));
}

/// `T'val` outside the type is a run-time error, not a value past the last literal.
#[test]
fn val_outside_an_enumeration_is_a_run_time_error() {
    let (_dir, model) = model_file(
        "val.vhd",
        "entity tb_val is end;\narchitecture t of tb_val is\n  type state is (idle, run, stop);\nbegin\n  \
         p : process\n    variable k : integer := 7;\n    variable st : state;\n  begin\n    \
         st := state'val(k);\n    wait;\n  end process;\nend;\n",
    );
    vams()
        .arg("run")
        .arg(&model)
        .args(["--stop", "1 ms"])
        .assert()
        .code(1)
        .stderr(contains("'val(7) is outside the type's positions 0 to 2"));
}

/// The first step and the step floor come from the model and the current time, not from the
/// stop time: with `--stop 1e30s`, `x' = -1/x` from 1 still fails where its solution ends
/// (t = 0.5), as with `--stop 1s`, instead of jumping to t = 3.6e15 s.
#[test]
fn a_far_stop_time_does_not_scale_the_first_step() {
    let (dir, model) = model_file(
        "sing.vhd",
        "entity sing is end;\narchitecture a of sing is\n  quantity x : real;\nbegin\n  \
         break x => 1.0;\n  x'dot == -1.0 / x;\nend;\n",
    );
    let out = dir.path().join("x.csv");
    let run = vams()
        .arg("run")
        .arg(&model)
        .args(["--stop", "1e30s", "-o"])
        .arg(&out)
        .output()
        .expect("runs");
    assert_eq!(run.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(stderr.contains("failed at t = 0.49"), "{stderr}");
}

/// An array value whose length is known only at run time and differs from its target's
/// stops the run at the statement, naming the target and both lengths (LRM 8.4, 8.5); with
/// every length right (`which=0`) the run completes.
#[test]
fn array_lengths_that_differ_stop_the_run() {
    vams()
        .args(["run", "tests/run/length_check.vhd"])
        .assert()
        .success();
    let cases = [
        (
            "1",
            "a value of 6 element(s) assigned to variable `v` of 8 element(s)",
            "length_check.vhd:42:21",
        ),
        // A signal assignment after a delay is checked when it is executed.
        (
            "2",
            "a value of 3 element(s) assigned to signal `s` of 4 element(s)",
            "length_check.vhd:43:17",
        ),
        (
            "3",
            "a value of 3 element(s) assigned to variable `v(7 downto 4)` of 4 element(s)",
            "length_check.vhd:44:17",
        ),
        // A subprogram's variable initialised from its parameter, at its declaration.
        (
            "4",
            "a value of 3 element(s) assigned to variable `r` of 4 element(s)",
            "length_check.vhd:27:5",
        ),
        // A function result of a constrained subtype (at the statement calling it).
        (
            "5",
            "a value of 3 element(s) assigned to the function's result of 4 element(s)",
            "length_check.vhd:46:17",
        ),
        // A slice of a signal whose bounds are known only at run time.
        (
            "6",
            "a value of 4 element(s) assigned to signal `s(n downto 0)` of 3 element(s)",
            "length_check.vhd:47:17",
        ),
    ];
    for (which, message, at) in cases {
        vams()
            .args([
                "run",
                "tests/run/length_check.vhd",
                "-g",
                &format!("which={which}"),
            ])
            .assert()
            .code(1)
            .stderr(contains(message))
            .stderr(contains("in process `p`"))
            .stderr(contains("5e-9 s"))
            .stderr(contains(at));
    }
}

#[test]
fn integers_outside_their_range_stop_the_run() {
    vams()
        .args(["run", "tests/run/range_check.vhd"])
        .assert()
        .code(1)
        .stderr(contains("signal `k` assigned 8, outside its range 0 to 7"))
        .stderr(contains("at t = 8e-9 s"))
        // The statement that assigns it, not just its process.
        .stderr(contains("range_check.vhd:21:7"));
    vams()
        .args(["run", "tests/run/range_check.vhd", "-g", "wrap=true"])
        .assert()
        .success();
    // 2147483000 + 7 * 100 passes 2**31 - 1 at 7 ns, before `n` (10 at the start) passes 0 at 11 ns.
    vams()
        .args(["run", "tests/run/overflow.vhd"])
        .assert()
        .code(1)
        .stderr(contains(
            "variable `big` assigned 2147483700, outside its range -2147483648 to 2147483647",
        ));
    vams()
        .args(["run", "tests/run/overflow.vhd", "-g", "step=0"])
        .assert()
        .code(1)
        .stderr(contains(
            "variable `n` assigned -1, outside its range 0 to 2147483647",
        ));
    // An initial value outside the range is found before the run.
    let (_dir, file) = model_file(
        "init.vhd",
        "entity t is end;\narchitecture a of t is\n  signal s : integer range 0 to 3 := 5;\nbegin\nend;\n",
    );
    vams()
        .arg("check")
        .arg(&file)
        .assert()
        .code(1)
        .stderr(contains(
            "the initial value 5 is outside the subtype's range 0 to 3",
        ))
        .stderr(contains("init.vhd:3:38"));
}

#[test]
fn a_quantity_that_is_not_a_number_stops_the_run() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("partial.csv");
    vams()
        .args(["run", "tests/run/not_finite.vhd", "-o"])
        .arg(&csv)
        .assert()
        .code(1)
        .stderr(contains("quantity `r` is not a number at t ="))
        .stderr(contains("not_finite.vhd:12:15"))
        .stderr(contains("sqrt(y);`"))
        .stderr(contains("wrote the waveforms up to t ="));
    // What the run computed before the error is written, and none of it is NaN.
    let text = std::fs::read_to_string(&csv).unwrap();
    let r = csv_column(&text, "r");
    assert!(r.len() > 2, "{text}");
    assert!(r.iter().all(|(t, v)| *t < 1.0 && v.is_finite()), "{text}");
    assert!(
        r.iter().all(|(t, v)| (v - (1.0 - t).sqrt()).abs() < 1e-9),
        "{text}"
    );
    // Before y turns negative the run is fine.
    vams()
        .args(["run", "tests/run/not_finite.vhd", "--stop", "0.9 s"])
        .assert()
        .success();
}

#[test]
fn a_simultaneous_if_without_else_that_no_condition_covers_stops_the_run() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("partial.csv");
    vams()
        .args(["run", "tests/run/no_branch.vhd", "--stop", "2 s", "-o"])
        .arg(&csv)
        .assert()
        .code(1)
        .stderr(contains(
            "no condition of this simultaneous if holds at t =",
        ))
        // Located inside the step on the dense output: x = 1 - t reaches 0 at t = 1 s.
        .stderr(predicates::str::is_match(r"holds at t = (1\.00000|0\.99999)").unwrap())
        .stderr(contains("no_branch.vhd:10:3"))
        .stderr(contains("add an `else` branch"));
    // Up to the error both branches ran: y is continuous, 2x then x + 1/2 (rows after the
    // switch at t = 0.5 s).
    let text = std::fs::read_to_string(&csv).unwrap();
    let y = csv_column(&text, "y");
    assert!(y.iter().filter(|(t, _)| *t > 0.5).count() >= 2, "{text}");
    for (t, v) in y {
        let x = 1.0 - t;
        let expected = if x > 0.5 { 2.0 * x } else { x + 0.5 };
        assert!(t < 1.0 && (v - expected).abs() < 1e-9, "{t}: {v}");
    }
    // While x stays positive the run is fine.
    vams()
        .args(["run", "tests/run/no_branch.vhd", "--stop", "0.9 s"])
        .assert()
        .success();
}

#[test]
fn math_real_outside_its_domain_and_real_division_by_zero_are_errors() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("domain.vhd");
    let model = |body: &str| {
        format!(
            "-- vams: stop 5 ns\nlibrary ieee;\nuse ieee.math_real.all;\n\
             entity domain is end;\narchitecture a of domain is\nbegin\n\
             p : process is\n  variable x : real := 1.0;\nbegin\n  wait for 1 ns;\n  \
             x := x - 1.5;\n  {body}\nend process;\nend;\n"
        )
    };
    std::fs::write(&file, model("x := sqrt(x);")).unwrap();
    vams()
        .arg("run")
        .arg(&file)
        .assert()
        .code(1)
        .stderr(contains("X < 0.0 in SQRT(X), with X = -0.5"))
        .stderr(contains("domain.vhd:12:3"));
    std::fs::write(&file, model("x := 1.0 / (x + 0.5);")).unwrap();
    vams()
        .arg("run")
        .arg(&file)
        .assert()
        .code(1)
        .stderr(contains("real division by zero"));
}

#[test]
fn an_array_too_large_to_hold_is_a_diagnostic_not_an_abort() {
    let (_dir, file) = model_file(
        "huge.vhd",
        "entity huge is end;\narchitecture a of huge is\n  \
         signal s : bit_vector(0 to 2000000000);\nbegin\nend;\n",
    );
    vams()
        .arg("check")
        .arg(&file)
        .assert()
        .code(1)
        .stderr(contains(
            "not supported yet: an array of 2000000001 elements",
        ))
        .stderr(contains("huge.vhd:3:14"));
}

/// A generate statement's bound typed a few digits too long (found by tests/it/mutation.rs: it
/// tried to allocate 16 GiB) is a diagnostic at the statement.
#[test]
fn a_generate_of_billions_of_iterations_is_a_diagnostic() {
    let (_dir, file) = model_file(
        "many.vhd",
        "entity many is end;\narchitecture a of many is\n  signal s : bit;\nbegin\n  \
         g : for i in 0 to 2147483647 generate\n    s <= '1';\n  end generate;\nend;\n",
    );
    vams()
        .arg("check")
        .arg(&file)
        .assert()
        .code(1)
        .stderr(contains(
            "not supported yet: a generate statement of 2147483648 iterations",
        ))
        .stderr(contains("many.vhd:5:3"));
}

/// Ctrl-C stops a run at its next step: the waveforms computed so far are written, and the
/// exit code is the shell's for SIGINT.
#[cfg(unix)]
#[test]
fn ctrl_c_stops_the_run_and_keeps_its_waveforms() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("endless.csv");
    let (status, stderr) = interrupt::run_interrupted(
        [
            "run",
            "tests/run/endless.vhd",
            "--stop",
            "1e9 sec",
            "--max-step",
            "0.05 sec",
            "-o",
        ]
        .map(std::ffi::OsString::from)
        .into_iter()
        .chain([csv.clone().into_os_string()]),
    );
    assert_eq!(status.code(), Some(130), "{stderr}");
    assert!(stderr.contains("interrupted at t ="), "{stderr}");
    assert!(stderr.contains("wrote the waveforms up to"), "{stderr}");
    let text = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(text.lines().next(), Some("time,x"));
    assert!(text.lines().count() > 10, "{} lines", text.lines().count());
    let last = text.lines().last().unwrap();
    assert!(last.starts_with("# partial: interrupted at t = "), "{last}");
}

/// An output that cannot be written is reported before the run, not after it.
#[test]
fn an_unwritable_output_fails_before_the_run() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("missing/dir/out.csv");
    vams()
        .args(["run", "tests/run/endless.vhd", "--stop", "1e9 sec"])
        .arg("-o")
        .arg(&csv)
        .timeout(std::time::Duration::from_secs(30))
        .assert()
        .code(1)
        .stderr(contains("cannot write"));
}

/// Two processes may drive different elements of an unresolved array, not the same one: the
/// error names the element and the processes.
#[test]
fn two_drivers_of_one_unresolved_element_are_an_error_naming_it() {
    let (_dir, file) = model_file(
        "md.vhd",
        "entity md is end entity md;\narchitecture a of md is\n  signal v : bit_vector(3 downto 0);\n\
         begin\n  p1 : process begin v(1) <= '1'; v(3) <= '1'; wait; end process;\n\
         p2 : process begin v(1) <= '0'; v(2) <= '1'; wait; end process;\nend architecture a;\n",
    );
    vams()
        .args(["run"])
        .arg(&file)
        .args(["--stop", "1 ns"])
        .assert()
        .code(1)
        .stderr(contains("signal `v(1)` has 2 drivers (p1, p2)"));
}

/// A file object whose file cannot be opened is an error at the start of the run pointing at
/// its declaration; one that can is written in the directory vams runs in, and a failed read
/// of a file names the file.
#[test]
fn files_open_where_vams_runs_and_a_missing_one_is_located() {
    let (dir, path) = model_file(
        "files.vhd",
        "use std.textio.all;\n\
         entity files is end entity;\n\
         architecture a of files is\n\
           file missing : text open read_mode is \"no_such_dir/data.txt\";\n\
         begin\n\
         end architecture;\n",
    );
    vams()
        .current_dir(dir.path())
        .args(["run", "files.vhd", "--stop", "1 ns"])
        .assert()
        .code(1)
        .stderr(contains("vams::sim::file_open"))
        .stderr(contains("cannot open \"no_such_dir/data.txt\" for reading"))
        .stderr(contains("files.vhd:4:"));
    std::fs::write(
        &path,
        "use std.textio.all;\n\
         entity files is end entity;\n\
         architecture a of files is\n\
           file log : text open write_mode is \"log.txt\";\n\
         begin\n\
           process\n\
             variable l : line;\n\
             variable n : integer;\n\
           begin\n\
             write(l, string'(\"answer \"));\n\
             write(l, 42);\n\
             writeline(log, l);\n\
             file_close(log);\n\
             file_open(log, \"log.txt\", read_mode);\n\
             readline(log, l);\n\
             readline(log, l);\n\
             wait;\n\
           end process;\n\
         end architecture;\n",
    )
    .unwrap();
    vams()
        .current_dir(dir.path())
        .args(["run", "files.vhd", "--stop", "1 ns"])
        .assert()
        .code(1)
        .stderr(contains("read past the end of file `log`"))
        .stderr(contains("files.vhd:16:"));
    let log = std::fs::read_to_string(dir.path().join("log.txt")).unwrap();
    assert_eq!(log, "answer 42\n");
}

#[test]
fn a_function_reports_in_order_and_the_run_goes_on() {
    let out = vams()
        .args(["run", "tests/run/function_report.vhd", "--stop", "2ms"])
        .assert()
        .success()
        .get_output()
        .stderr
        .clone();
    let text = String::from_utf8(out).unwrap();
    let at = |s: &str| {
        text.find(s)
            .unwrap_or_else(|| panic!("{s} missing from {text}"))
    };
    assert!(at("0 s: note: halving 7") < at("0 s: warning: odd value"));
    assert!(at("0 s: warning: odd value") < at("0 s: note: half of 7 is 3"));
    assert!(at("function_report.vhd:10:") < at("function_report.vhd:11:"));
    assert!(at("1 ms: note: done") > at("half of 7 is 3"));
}

/// Ctrl-C in the middle of a long computation inside a function (minutes of interpreted
/// loops) stops the run within moments, with the waveforms up to that time.
#[cfg(unix)]
#[test]
fn ctrl_c_stops_a_long_function_call() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("long.csv");
    let (status, stderr) = interrupt::run_interrupted(
        ["run", "tests/run/long_function.vhd", "--stop", "2 ns", "-o"]
            .map(std::ffi::OsString::from)
            .into_iter()
            .chain([csv.clone().into_os_string()]),
    );
    assert_eq!(status.code(), Some(130), "{stderr}");
    assert!(stderr.contains("interrupted at t = 1e-9 s"), "{stderr}");
    let text = std::fs::read_to_string(&csv).unwrap();
    let last = text.lines().last().unwrap();
    assert_eq!(last, "# partial: interrupted at t = 1 ns");
}
