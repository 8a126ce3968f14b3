//! Phase timing of the RC ladder (`tests/simulate/rc_ladder.vhd`) at a given N: runs the
//! pipeline up to a given phase and prints each phase's wall time, so that the peak memory of a
//! prefix of the pipeline can be read from `/usr/bin/time` around one run (issue 3).
//!
//! Run: `cargo run --release --example ladder_phases -- N [parse|elaborate|analog|listing]`
//! e.g. `/usr/bin/time -f "%e s %M KB" target/release/examples/ladder_phases 100000 elaborate`.

use std::time::Instant;

use vams::analog::AnalogSystem;
use vams::elaborate::{ElabOptions, elaborate};
use vams::source::SourceMap;
use vams::{parser, stdlib};

const PHASES: [&str; 4] = ["parse", "elaborate", "analog", "listing"];

fn main() {
    let mut args = std::env::args().skip(1);
    let n: usize = match args.next().and_then(|a| a.parse().ok()) {
        Some(n) => n,
        None => return eprintln!("usage: ladder_phases N [parse|elaborate|analog|listing]"),
    };
    let last = args.next().unwrap_or_else(|| "listing".into());
    let Some(stop) = PHASES.iter().position(|&p| p == last) else {
        return eprintln!("unknown phase {last}; one of {PHASES:?}");
    };
    let lap = |phase: &str, start: Instant| {
        println!("{phase:>10}: {:8.3} s", start.elapsed().as_secs_f64());
    };

    let start = Instant::now();
    let mut sources = SourceMap::new();
    let mut ids = stdlib::load(&mut sources);
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/simulate/rc_ladder.vhd");
    let text = std::fs::read_to_string(path).expect("ladder model readable");
    ids.push(sources.add(path.to_string(), "work", text));
    let files: Vec<_> = ids
        .iter()
        .map(|&id| (id, parser::parse(id, &sources.file(id).text).0))
        .collect();
    lap("parse", start);
    if stop == 0 {
        return;
    }

    let start = Instant::now();
    let options = ElabOptions {
        top: "rc_ladder".into(),
        generics: vec![("n".into(), n.to_string())],
    };
    let design = elaborate(&sources, &files, &options).expect("ladder elaborates");
    lap("elaborate", start);
    if stop == 1 {
        return;
    }

    let start = Instant::now();
    let system = AnalogSystem::new(&design).expect("ladder builds");
    lap("analog", start);
    if stop == 2 {
        return;
    }

    let start = Instant::now();
    let listing = system.listing(&design, &sources);
    lap("listing", start);
    println!("{:>10}: {} bytes", "text", listing.len());
}
