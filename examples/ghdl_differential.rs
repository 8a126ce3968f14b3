//! Many random digital testbenches against GHDL (the differential test of
//! `tests/it/ghdl_differential.rs` at scale):
//! `cargo build --release && cargo run --release --example ghdl_differential -- [COUNT] [FIRST_SEED]`.
//! Runs the `vams` binary beside the example's directory (`target/release/vams`; `VAMS=PATH`
//! chooses another) on two threads, prints one line per program that does not agree and the
//! counts, and writes each such program to `target/ghdl_differential/seed_N.vhd` to be reduced
//! into a regression test.

#[path = "../tests/it/ghdl_differential/compare.rs"]
mod compare;
#[path = "../tests/it/ghdl_differential/program.rs"]
mod program;

use compare::{Verdict, compare, ghdl_available};
use std::path::PathBuf;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let count: u64 = args.first().and_then(|a| a.parse().ok()).unwrap_or(1000);
    let first: u64 = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(1);
    if !ghdl_available() {
        eprintln!("ghdl is not installed (.ci/install-ghdl.sh installs it)");
        std::process::exit(1);
    }
    // target/release/examples/ghdl_differential -> target/release/vams
    let vams: PathBuf = std::env::var_os("VAMS")
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            let exe = std::env::current_exe().expect("the example's path");
            exe.parent()
                .and_then(|examples| examples.parent())
                .map(|profile| profile.join("vams"))
                .expect("the example runs from target/PROFILE/examples")
        });
    if !vams.exists() {
        eprintln!(
            "{} does not exist: run `cargo build --release` first",
            vams.display()
        );
        std::process::exit(1);
    }
    let keep = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target/ghdl_differential");
    let workers = 2;
    let results: Vec<(u64, Verdict)> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..workers)
            .map(|worker| {
                let vams = &vams;
                let keep = &keep;
                scope.spawn(move || {
                    let dir = tempfile::tempdir().expect("temporary directory");
                    let mut results = Vec::new();
                    for seed in (first..first + count).filter(|s| s % workers == worker) {
                        let text = program::Program::random(seed);
                        let verdict = compare(
                            &text,
                            vams,
                            program::STOP,
                            program::STOP_NS * 1_000_000,
                            dir.path(),
                        );
                        if !matches!(verdict, Verdict::Agrees(_)) {
                            println!("seed {seed}: {verdict:?}");
                            let _ = std::fs::create_dir_all(keep);
                            let _ = std::fs::write(keep.join(format!("seed_{seed}.vhd")), &text);
                        }
                        results.push((seed, verdict));
                    }
                    results
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().expect("worker finished"))
            .collect()
    });
    let (mut agree, mut disagree, mut vams_fails, mut ghdl_fails, mut reports) = (0, 0, 0, 0, 0);
    for (_, verdict) in &results {
        match verdict {
            Verdict::Agrees(n) => {
                agree += 1;
                reports += n;
            }
            Verdict::Disagrees { .. } => disagree += 1,
            Verdict::VamsFails(_) => vams_fails += 1,
            Verdict::GhdlFails(_) => ghdl_fails += 1,
        }
    }
    println!(
        "{count} programs from seed {first}: {agree} agree ({reports} reports), {disagree} \
         disagree, {vams_fails} fail in vams where GHDL runs, {ghdl_fails} that GHDL refuses"
    );
}
