//! `vams test` end to end: discovery, verdict lines in name order, JUnit output and the exit
//! code. What is decided before elaboration runs now; real runs need the engine.

use assert_cmd::Command;
use predicates::str::contains;

fn vams() -> Command {
    Command::cargo_bin("vams").expect("the vams binary is built for integration tests")
}

#[test]
fn no_testbench_is_an_error() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("e.vhd"), "entity helper is end;").unwrap();
    vams()
        .arg("test")
        .arg(dir.path())
        .assert()
        .code(1)
        .stderr(contains("no testbench found"))
        .stderr(contains("tb_"));
    vams()
        .arg("test")
        .arg(dir.path())
        .args(["--filter", "x"])
        .assert()
        .code(1)
        .stderr(contains("--filter"));
}

#[test]
fn usage_errors() {
    vams().args(["test", "-j", "0"]).assert().code(2);
    vams().args(["test", "--stop", "never"]).assert().code(2);
    vams()
        .args(["test", "no/such/dir"])
        .assert()
        .code(1)
        .stderr(contains("cannot read"));
}

#[test]
fn testbenches_that_cannot_start_fail_with_their_diagnostic_and_junit_records_them() {
    let dir = tempfile::tempdir().unwrap();
    // A testbench with a syntax error, one without a stop time, and a broken non-testbench
    // file that is skipped with a warning.
    std::fs::write(
        dir.path().join("tb_broken.vhd"),
        "-- vams: stop 1 ms\nentity tb_broken is end;\narchitecture a of tb_broken is begin x <= ; end;\n",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("tb_nostop.vhd"),
        "entity tb_nostop is end;\narchitecture a of tb_nostop is begin end;\n",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("lib.vhd"),
        "entity lib is port (a : in bit) end;",
    )
    .unwrap();
    let junit = dir.path().join("results.xml");
    let out = vams()
        .arg("test")
        .arg(dir.path())
        .arg("--junit")
        .arg(&junit)
        .args(["-j", "2"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let stdout = String::from_utf8(out.stdout).unwrap();
    let stderr = String::from_utf8(out.stderr).unwrap();
    let broken = stdout.find("test tb_broken ... FAILED").expect(&stdout);
    let nostop = stdout.find("test tb_nostop ... FAILED").expect(&stdout);
    assert!(broken < nostop, "name order:\n{stdout}");
    assert!(
        stdout.contains("    ") && stdout.contains("vams::parse::"),
        "{stdout}"
    );
    assert!(stdout.contains("pass --stop TIME"), "{stdout}");
    assert!(stdout.contains("0 passed, 2 failed"), "{stdout}");
    assert!(
        stderr.contains("warning: skipping") && stderr.contains("lib.vhd"),
        "{stderr}"
    );
    assert!(stderr.contains("2 of 2 testbench(es) failed"), "{stderr}");
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(
        xml.contains("tests=\"2\" failures=\"0\" errors=\"2\""),
        "{xml}"
    );
    assert!(xml.contains("<testcase name=\"tb_broken\""));
    assert!(xml.contains("<testcase name=\"tb_nostop\""));
    assert!(
        xml.contains("<error message=\"no stop time for `tb_nostop`\">"),
        "{xml}"
    );
}

// ---- With the engine ----

#[test]
fn passing_and_failing_testbenches() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("tb_fails.vhd"),
        r#"-- vams: stop 3 ms
entity tb_fails is end;
architecture a of tb_fails is
begin
  process
  begin
    wait for 1 ms;
    assert false report "first problem" severity error;
    wait for 1 ms;
    report "just a note";
    assert 1 + 1 = 3 report "second problem" severity failure;
    wait;
  end process;
end;
"#,
    )
    .unwrap();
    let junit = dir.path().join("j.xml");
    let out = vams()
        .arg("test")
        .arg(dir.path())
        .arg("tests/run")
        .arg("--junit")
        .arg(&junit)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let stdout = String::from_utf8(out.stdout).unwrap();
    let fails = stdout.find("test tb_fails ... FAILED").expect(&stdout);
    let rc = stdout.find("test tb_rc ... ok").expect(&stdout);
    assert!(fails < rc);
    assert!(
        stdout.contains("    1 ms: error: first problem"),
        "{stdout}"
    );
    assert!(
        stdout.contains("    2 ms: failure: second problem"),
        "{stdout}"
    );
    assert!(!stdout.contains("just a note"), "{stdout}");
    assert!(stdout.contains("1 passed, 1 failed"), "{stdout}");
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(xml.contains("failures=\"1\" errors=\"0\""), "{xml}");
    assert!(
        xml.contains("<failure message=\"1 ms: error: first problem"),
        "{xml}"
    );
}

#[test]
fn the_repository_testbenches_pass_by_default() {
    // Default paths: tests/ (tests/diagnostics is skipped: its files do not parse) and models/.
    vams()
        .arg("test")
        .assert()
        .success()
        .stdout(contains("test tb_overvoltage ... ok"))
        .stdout(contains("test tb_rc ... ok"))
        .stdout(contains("test tb_tracking ... ok"))
        .stdout(contains("test tb_motor_bench ... ok"))
        .stdout(contains("test tb_servo_fit ... ok"))
        .stdout(contains("test tb_rlc_elimination ... ok"))
        .stdout(contains("test tb_configuration_specification ... ok"))
        .stdout(contains("test tb_configuration_declaration ... ok"))
        .stdout(contains("test tb_binding_maps ... ok"))
        .stdout(contains("test tb_scalar_attributes ... ok"))
        .stdout(contains("test tb_bit_operators ... ok"))
        .stdout(contains("test tb_concurrent_statements ... ok"))
        .stdout(contains("test tb_local_nature ... ok"))
        .stdout(contains("test tb_mass_spring_damper ... ok"))
        .stdout(contains("test tb_simultaneous_case ... ok"))
        .stdout(contains("test tb_bouncing_ball ... ok"))
        .stdout(contains("test tb_block_ports ... ok"))
        .stdout(contains("test tb_analog_functions ... ok"))
        .stdout(contains("test tb_pwl_table_generic ... ok"))
        .stdout(contains("test tb_static_calls_and_sources ... ok"))
        .stdout(contains("test tb_procedural ... ok"))
        .stdout(contains("test tb_aggregate_targets ... ok"))
        .stdout(contains("test tb_subprogram_aliases ... ok"))
        .stdout(contains("test tb_signal_elements ... ok"))
        .stdout(contains("test tb_vector_operators ... ok"))
        .stdout(contains("test tb_element_port_actuals ... ok"))
        .stdout(contains("test tb_shift_operators ... ok"))
        .stdout(contains("test tb_groups_and_attribute_signatures ... ok"))
        .stdout(contains("test tb_configuration_instance ... ok"))
        .stdout(contains("test tb_guarded_blocks ... ok"))
        .stdout(contains("test tb_slices ... ok"))
        .stdout(contains("test tb_numeric_std_arith ... ok"))
        .stdout(contains("test tb_std_logic_arith_packages ... ok"))
        .stdout(contains("test tb_numeric_std_operators ... ok"))
        .stdout(contains("test tb_numeric_bit_arith ... ok"))
        .stdout(contains("test tb_numeric_bit_shifts_compare ... ok"))
        .stdout(contains("test tb_numeric_bit_counter ... ok"))
        .stdout(contains("test tb_real_now_and_power ... ok"))
        .stdout(contains("test tb_type_aliases ... ok"))
        .stdout(contains("test tb_free_running_phase ... ok"))
        .stdout(contains("test tb_limiter_in_a_loop ... ok"))
        .stdout(contains("test tb_threshold_restart ... ok"))
        .stdout(contains("test tb_terminal_attributes ... ok"))
        .stdout(contains("test tb_subnature_tolerance ... ok"))
        .stdout(contains("test tb_signal_port_elements ... ok"))
        .stdout(contains("test tb_signal_parameter_elements ... ok"))
        .stdout(contains("test tb_literal_operands ... ok"))
        .stdout(contains("test tb_operator_aliases ... ok"))
        .stdout(contains("test tb_declared_guard ... ok"))
        .stdout(contains("test tb_open_actuals ... ok"))
        .stdout(contains("test tb_terminal_slices ... ok"))
        .stdout(contains("test tb_textio_log ... ok"))
        .stdout(contains("test tb_linked_list ... ok"))
        .stdout(contains("test tb_std_logic_textio ... ok"))
        .stdout(contains("test tb_protected_counter ... ok"))
        .stdout(contains("test tb_exact_time ... ok"))
        .stdout(contains("test tb_driver_attributes ... ok"))
        .stdout(contains("test tb_name_attributes ... ok"))
        .stdout(contains("test tb_file_in_function ... ok"))
        .stdout(contains("test tb_deep_recursion ... ok"))
        .stdout(contains("test tb_inout_of_a_visible_variable ... ok"))
        .stdout(contains("test tb_procedural_array ... ok"))
        .stdout(contains("test tb_user_attributes ... ok"))
        .stdout(contains("test tb_binding_indications ... ok"))
        .stdout(contains("component instance `unused` is unbound"))
        .stdout(contains("test tb_parameter_bounds ... ok"))
        .stdout(contains("test tb_record_natures ... ok"))
        .stdout(contains("test tb_math_complex ... ok"))
        .stdout(contains("test tb_composite_equations ... ok"))
        .stdout(contains("test tb_shared_variables ... ok"))
        .stdout(contains("test tb_protected_parameters ... ok"))
        .stdout(contains("test tb_seams_idioms ... ok"))
        .stdout(contains(
            "the function `sin` has no body: its calls compute the built-in `sin`",
        ))
        .stdout(contains("test tb_simultaneous_if_without_else ... ok"))
        .stdout(contains("test tb_above_tolerance ... ok"))
        .stdout(contains("test tb_operator_calls ... ok"))
        .stdout(contains("test tb_operator_overloads ... ok"))
        .stdout(contains("test tb_math_real_uniform ... ok"))
        .stdout(contains("test tb_quantity_port_expressions ... ok"))
        .stdout(contains("test tb_package_body_context ... ok"))
        .stdout(contains("test tb_array_quantity_attributes ... ok"))
        .stdout(contains("test tb_break_integral ... ok"))
        .stdout(contains("test tb_quantity_array_ports ... ok"))
        .stdout(contains("test tb_terminal_port_slices ... ok"))
        .stdout(contains("test tb_multidimensional_nature ... ok"))
        .stdout(contains("test tb_function_result_bounds ... ok"))
        .stdout(contains("test tb_lone_across_source ... ok"))
        .stdout(contains(
            "warning: `vout` is set by an equation but has no through quantity",
        ))
        .stdout(contains("test tb_stable_and_quiet_signals ... ok"))
        .stdout(contains("test tb_unnamed_reference ... ok"))
        .stdout(contains(
            "the nature `electrical` names no reference terminal",
        ))
        .stdout(contains("test tb_generate_iteration_configuration ... ok"))
        .stdout(contains("test tb_ghdl_element_sensitivity ... ok"))
        .stdout(contains("test tb_named_choice_equations ... ok"))
        .stdout(contains("test tb_runtime_slice_targets ... ok"))
        .stdout(contains("test tb_port_conversions ... ok"))
        .stdout(contains("test tb_nature_subtypes ... ok"))
        .stdout(contains("test tb_procedural_derivatives ... ok"))
        .stdout(contains("test tb_quantity_array_arguments ... ok"))
        .stdout(contains("test tb_package_shared_variable ... ok"))
        .stdout(contains("test tb_process_constants ... ok"))
        .stdout(contains("test tb_element_last_value ... ok"))
        .stdout(contains("test tb_resolved_initial_value ... ok"))
        .stdout(contains("test tb_edge_functions ... ok"))
        .stdout(contains("test tb_shared_idle_conditions ... ok"))
        // tests/ac/: the AC models also run in the time domain (spectral sources are zero).
        .stdout(contains("test tb_rc_lowpass ... ok"))
        .stdout(contains("test tb_attributes ... ok"))
        // tests/noise/: so do the noise models (noise sources are zero there too).
        .stdout(contains("test tb_rc_thermal ... ok"))
        .stdout(contains("test tb_divider ... ok"))
        .stdout(contains("156 passed, 0 failed"));
}

/// A testbench fails with the analysis errors of the units it reaches (here a package it
/// uses), and only with those: another testbench beside it runs and passes.
/// `-- vams: assert` comments check the small-signal response: a testbench without a stop
/// time is an AC test only; one with both runs in time first. A false assertion fails with
/// its value, a bad one is a located diagnostic.
#[test]
fn assertions_on_the_small_signal_response_judge_a_testbench() {
    let dir = tempfile::tempdir().unwrap();
    let rc = |name: &str, comments: &str| {
        format!(
            "{comments}library ieee;\nuse ieee.electrical_systems.all;\n\
             entity {name} is end;\narchitecture a of {name} is\n\
             terminal n_in, n_out : electrical;\n\
             quantity ac_in : real spectrum 1.0, 0.0;\n\
             quantity vin across iin through n_in to electrical_ref;\n\
             quantity vr across ir through n_in to n_out;\n\
             quantity vout across ic through n_out to electrical_ref;\n\
             begin\n  vin == 1.0 + ac_in;\n  vr == 1.0e3 * ir;\n  ic == 1.0e-7 * vout'dot;\n\
             end;\n"
        )
    };
    let write = |file: &str, text: String| std::fs::write(dir.path().join(file), text).unwrap();
    write(
        "tb_ac_only.vhd",
        rc(
            "tb_ac_only",
            "-- vams: assert gain_db(vout, 1591.55Hz) > -3.02\n",
        ),
    );
    write(
        "tb_both.vhd",
        rc(
            "tb_both",
            "-- vams: stop 1 ms\n-- vams: assert phase_deg(vout, 1591.55Hz) < -44.99\n",
        ),
    );
    write(
        "tb_too_flat.vhd",
        rc("tb_too_flat", "-- vams: assert gain_db(vout, 10kHz) > -3\n"),
    );
    write(
        "tb_unreadable.vhd",
        rc("tb_unreadable", "-- vams: assert gain_db(vout) > -3\n"),
    );
    vams()
        .arg("test")
        .arg(dir.path())
        .assert()
        .code(1)
        .stdout(contains("test tb_ac_only ... ok"))
        .stdout(contains("test tb_both ... ok"))
        .stdout(contains("test tb_too_flat ... FAILED"))
        .stdout(contains("assert gain_db(vout, 10kHz) > -3: -16.07"))
        .stdout(contains("test tb_unreadable ... FAILED"))
        .stdout(contains("expected two arguments"))
        .stdout(contains("tb_unreadable.vhd:1"))
        .stdout(contains("2 passed, 2 failed"));
}

#[test]
fn a_testbench_reaching_a_unit_with_an_analysis_error_fails_with_it() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("limits.vhd"),
        "package limits is\n  constant vmax : real := 16.0;\n  constant vmin : real := -vmaxx;\nend package limits;\n",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("tb_uses.vhd"),
        "-- vams: stop 1 ms\nuse work.limits.all;\nentity tb_uses is end;\narchitecture a of tb_uses is begin end;\n",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("tb_alone.vhd"),
        "-- vams: stop 1 ms\nentity tb_alone is end;\narchitecture a of tb_alone is begin end;\n",
    )
    .unwrap();
    vams()
        .arg("test")
        .arg(dir.path())
        .assert()
        .code(1)
        .stdout(contains("test tb_alone ... ok"))
        .stdout(contains("test tb_uses ... FAILED"))
        .stdout(contains("`vmaxx` is not declared"));
}

/// Units of a resource library (`library util;`) come from `--lib util=DIR`; without it the
/// design fails with the missing package named.
#[test]
fn a_resource_library_is_given_with_lib() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("out.csv");
    vams()
        .args([
            "run",
            "tests/libraries/uses_util.vhd",
            "--lib",
            "util=tests/libraries/util",
        ])
        .arg("-o")
        .arg(&csv)
        .assert()
        .success();
    vams()
        .args(["check", "tests/libraries/uses_util.vhd"])
        .assert()
        .code(1)
        .stderr(contains("no package `stimulus` in library `util`"));
    vams()
        .args([
            "check",
            "tests/libraries/uses_util.vhd",
            "--lib",
            "work=tests",
        ])
        .assert()
        .code(2)
        .stderr(contains(
            "library `work` is where the files given without --lib go",
        ));
}
