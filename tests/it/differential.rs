//! The differential test of the analog engine against ngspice: 50 random circuits (R, C,
//! L with series R, diodes, a sine voltage and a DC current source; see
//! `tests/it/support/circuit.rs`), each simulated by vams at reltol 1e-6 and by ngspice at
//! 1e-7 with a dense grid; every recorded node voltage of vams must lie within 1e-3 of the
//! circuit's largest node swing of ngspice's waveform. Where ngspice gives up, vams must agree
//! with its own run at a 100 times tighter tolerance, or fail with a diagnostic.
//!
//! Needs `ngspice` (`.ci/run` installs it; `benches/ngspice/install.sh` by hand): without it
//! the test prints why and passes. `cargo run --release --example differential -- COUNT SEED`
//! runs thousands.

use crate::support::circuit;

use circuit::{Circuit, Verdict, compare, ngspice_available};

const COUNT: u64 = 50;
const BOUND: f64 = 1e-3;

#[test]
fn random_circuits_agree_with_ngspice() {
    if !ngspice_available() {
        println!("skipped: ngspice is not installed (benches/ngspice/install.sh installs it)");
        return;
    }
    let dir = tempfile::tempdir().expect("temporary directory");
    // Two workers (the CI machine's cores), each on every other seed.
    let problems: Vec<String> = std::thread::scope(|scope| {
        let workers: Vec<_> = (0..2)
            .map(|worker| {
                let dir = dir.path();
                scope.spawn(move || {
                    let mut problems = Vec::new();
                    for seed in (1..=COUNT).filter(|s| s % 2 == worker) {
                        match compare(&Circuit::random(seed), 1e-6, BOUND, dir) {
                            Verdict::Agrees(_) | Verdict::NgspiceGaveUp(Ok(_)) => {}
                            // Where ngspice gives up, a located diagnostic is acceptable.
                            Verdict::NgspiceGaveUp(Err(message)) if !message.is_empty() => {}
                            other => problems.push(format!("seed {seed}: {other:?}")),
                        }
                    }
                    problems
                })
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|w| w.join().expect("worker finished"))
            .collect()
    });
    assert!(
        problems.is_empty(),
        "{} of {COUNT} circuits:\n{}",
        problems.len(),
        problems.join("\n")
    );
}
