//! The differential test of the event kernel against GHDL: 100 random digital testbenches
//! (`tests/it/ghdl_differential/program.rs`: integer, bit, boolean and std_logic signals and
//! arrays of them, every `wait` form, inertial, transport and reject delays with several
//! waveform elements, `case`, loops, a function, reports of values through `'image`), each
//! run by the `vams` binary and by `ghdl -r`; the reports of every time step must be the same
//! multiset in both (`tests/it/ghdl_differential/compare.rs`; the LRM leaves the order of
//! processes within a delta cycle open, so the order within a time step may differ).
//!
//! Needs `ghdl` (`.ci/run` installs it; `.ci/install-ghdl.sh` by hand): without it the test
//! prints why and passes. `cargo run --release --example ghdl_differential -- COUNT SEED` runs
//! thousands. A program that GHDL itself cannot run because of an internal error of GHDL 2.0
//! (it folds `xnor` of two `bit_vector` literals into a crash) is counted and left out; any
//! other refusal by GHDL is a bug of the generator and fails the test.

mod compare;
mod program;

use compare::{Verdict, compare, ghdl_available};
use std::path::Path;

const COUNT: u64 = 100;

#[test]
fn random_testbenches_agree_with_ghdl() {
    if !ghdl_available() {
        println!("skipped: ghdl is not installed (.ci/install-ghdl.sh installs it)");
        return;
    }
    let vams = Path::new(env!("CARGO_BIN_EXE_vams"));
    // Two workers (the CI machine's cores), each on every other seed.
    let results: Vec<(u64, Verdict)> = std::thread::scope(|scope| {
        let workers: Vec<_> = (0..2)
            .map(|worker| {
                scope.spawn(move || {
                    let dir = tempfile::tempdir().expect("temporary directory");
                    (1..=COUNT)
                        .filter(|s| s % 2 == worker)
                        .map(|seed| {
                            let text = program::Program::random(seed);
                            let stop_fs = program::STOP_NS * 1_000_000;
                            (
                                seed,
                                compare(&text, vams, program::STOP, stop_fs, dir.path()),
                            )
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|w| w.join().expect("worker finished"))
            .collect()
    });
    let mut problems = Vec::new();
    let (mut agree, mut reports, mut ghdl_bugs) = (0, 0, 0);
    for (seed, verdict) in results {
        match verdict {
            Verdict::Agrees(n) => {
                agree += 1;
                reports += n;
            }
            Verdict::GhdlFails(message) if message.contains("GHDL Bug occurred") => ghdl_bugs += 1,
            other => problems.push(format!("seed {seed}: {other:?}")),
        }
    }
    println!(
        "{COUNT} programs: {agree} agree ({reports} reports), {ghdl_bugs} stopped by an internal \
         error of GHDL, {} do not agree",
        problems.len()
    );
    assert!(
        problems.is_empty(),
        "{} of {COUNT} programs (write one with `Program::random(seed)` to reproduce):\n{}",
        problems.len(),
        problems.join("\n")
    );
}
