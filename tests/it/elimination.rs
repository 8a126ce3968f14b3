//! The elimination of explicit unknowns cannot change the answer: on random circuits (R, C,
//! L with series R, diodes, a sine voltage and a DC current source; `tests/differential/`),
//! the default run and `keep_unknowns` (every unknown solved for) agree.
//!
//! * The operating point is one solution of one set of equations, whichever unknowns Newton
//!   carries: every quantity agrees to 1e-6 relative (plus 1e-9 absolute) at reltol 1e-9.
//! * The transient runs take different steps (the error test sees different unknowns), so
//!   they agree to their accuracy, not to rounding: at reltol 1e-7 with steps of at most a
//!   thousandth of the run, every node voltage of each run lies within 1e-4 of the largest
//!   swing, plus ten voltage abstols, of the other's (interpolated by a parabola through its
//!   three nearest points, or within its range where an edge shifts by picoseconds).
//!   Measured on seeds 1 to 300: below 1e-5 of the swing but for one circuit at 6.4e-5.
//!
//! The cases come from a fixed RNG seed, so that CI tests the same circuits on every run;
//! `PROPTEST_RNG_SEED=N` (and `PROPTEST_CASES=N`) explore others. Circuits found that way
//! which ngspice cannot simulate either are kept in `hard_circuits_found_by_exploration`
//! (ignored: `cargo test --test it elimination:: -- --ignored`) until the numerics issue makes
//! them run.

use crate::support::circuit;
use crate::support::fixed_seed;

use circuit::{Circuit, elaborated, run_vams_with};
use proptest::prelude::*;
use vams::kernel::{SimOptions, operating_point};

/// Ten times the default absolute tolerance of a voltage (1e-6 V): a node that a 100 MOhm leak
/// ties to a small swing is known to that, not to a fraction of the largest swing.
const ALLOWANCE: f64 = 1e-5;

proptest! {
    #![proptest_config(fixed_seed::config(24))]

    #[test]
    fn the_operating_point_does_not_depend_on_elimination(seed in 1u64..1_000_000) {
        let circuit = Circuit::random(seed);
        let dir = tempfile::tempdir().expect("temporary directory");
        let design = elaborated(&circuit, dir.path()).expect("elaborates");
        let op = |keep_unknowns| {
            let options = SimOptions { reltol: 1e-9, keep_unknowns, ..SimOptions::default() };
            operating_point(&design, &options).expect("operating point")
        };
        let (reduced, full) = (op(false), op(true));
        prop_assert_eq!(reduced.len(), full.len());
        for ((name, a), (other, b)) in reduced.iter().zip(&full) {
            prop_assert_eq!(name, other);
            prop_assert!(
                (a - b).abs() <= 1e-6 * a.abs().max(b.abs()) + 1e-9,
                "seed {}: {} is {} eliminated and {} solved for", seed, name, a, b
            );
        }
    }

    #[test]
    fn the_waveforms_do_not_depend_on_elimination(seed in 1u64..1_000_000) {
        let circuit = Circuit::random(seed);
        let dir = tempfile::tempdir().expect("temporary directory");
        let run = |keep_unknowns| {
            let options = SimOptions {
                reltol: 1e-7,
                keep_unknowns,
                max_step: Some(circuit.stop() / 1000.0),
                ..SimOptions::default()
            };
            run_vams_with(&circuit, options, dir.path())
                .unwrap_or_else(|e| panic!("seed {seed}, keep_unknowns {keep_unknowns}: {e}"))
        };
        let (reduced, full) = (run(false), run(true));
        for (a, b, which) in [(&reduced, &full, "eliminated"), (&full, &reduced, "solved for")] {
            let (e, node, t) = a.close_difference(b, ALLOWANCE);
            prop_assert!(
                e <= 1e-4,
                "seed {}: v{} at {:e} s with explicit unknowns {} is {:.2e} of the swing off",
                seed, node, t, which, e
            );
        }
    }
}

/// Random circuits that exploration found and that ngspice cannot simulate either ("timestep
/// too small"): the default run stops with a located diagnostic at 18 ns (622543), or the
/// operating point of a node held only by 100 MOhm leaks and diodes in reverse differs by
/// 3.1e-6 V between the two runs, three voltage abstols (351174). Numerics issue.
#[test]
#[ignore = "circuits ngspice cannot simulate either; the numerics issue makes them run"]
fn hard_circuits_found_by_exploration() {
    for seed in [622_543, 351_174] {
        let circuit = Circuit::random(seed);
        let dir = tempfile::tempdir().expect("temporary directory");
        let options = |keep_unknowns| SimOptions {
            reltol: 1e-7,
            keep_unknowns,
            max_step: Some(circuit.stop() / 1000.0),
            ..SimOptions::default()
        };
        let design = elaborated(&circuit, dir.path()).expect("elaborates");
        let op = |keep_unknowns| {
            let options = SimOptions {
                reltol: 1e-9,
                keep_unknowns,
                ..SimOptions::default()
            };
            operating_point(&design, &options).expect("operating point")
        };
        for ((name, a), (_, b)) in op(false).iter().zip(&op(true)) {
            let bound = 1e-6 * a.abs().max(b.abs()) + 1e-9;
            assert!((a - b).abs() <= bound, "seed {seed}: {name} is {a} and {b}");
        }
        let reduced = run_vams_with(&circuit, options(false), dir.path());
        let full = run_vams_with(&circuit, options(true), dir.path());
        match (reduced, full) {
            (Ok(a), Ok(b)) => {
                let (e, node, t) = a.close_difference(&b, ALLOWANCE);
                assert!(e <= 1e-4, "seed {seed}: v{node} at {t:e} s is {e:.2e} off");
            }
            (a, b) => panic!("seed {seed}: {:?} / {:?}", a.err(), b.err()),
        }
    }
}
