//! Many random circuits against ngspice (the differential test of `tests/it/differential.rs` at
//! scale): `cargo run --release --example differential -- [COUNT] [FIRST_SEED] [RELTOL]`.
//! Prints one line per circuit that does not agree, and the counts; writes the VHDL-AMS and
//! SPICE files of each such circuit to `target/differential/` to become a regression test.

#[path = "../tests/it/support/circuit.rs"]
mod circuit;

use circuit::{Circuit, Verdict, compare, ngspice_available};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let count: u64 = args.first().and_then(|a| a.parse().ok()).unwrap_or(1000);
    let first: u64 = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(1);
    let reltol: f64 = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(1e-6);
    if !ngspice_available() {
        eprintln!("ngspice is not installed (benches/ngspice/install.sh installs it)");
        std::process::exit(1);
    }
    let dir = tempfile::tempdir().expect("temporary directory");
    let keep = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target/differential");
    let (mut agree, mut disagree, mut fail, mut gave_up) = (0, 0, 0, 0);
    let mut worst: f64 = 0.0;
    for seed in first..first + count {
        let circuit = Circuit::random(seed);
        let verdict = compare(&circuit, reltol, 1e-3, dir.path());
        match &verdict {
            Verdict::Agrees(e) => {
                agree += 1;
                worst = worst.max(*e);
                continue;
            }
            Verdict::Disagrees(..) => disagree += 1,
            Verdict::Fails(_) => fail += 1,
            Verdict::NgspiceGaveUp(_) => gave_up += 1,
        }
        println!("seed {seed}: {verdict:?}");
        if !matches!(verdict, Verdict::NgspiceGaveUp(Ok(_)))
            || std::env::var_os("DIFFERENTIAL_KEEP_ALL").is_some()
        {
            let _ = std::fs::create_dir_all(&keep);
            let _ = std::fs::write(keep.join(format!("rand_{seed}.vhd")), circuit.vhdl());
            let data = format!("rand_{seed}.txt");
            let _ = std::fs::write(
                keep.join(format!("rand_{seed}.cir")),
                circuit.spice(reltol, 2000, &data),
            );
        }
    }
    println!(
        "{count} circuits: {agree} agree (worst {worst:.2e} of the swing), {disagree} disagree, \
         {fail} fail where ngspice finishes, {gave_up} where ngspice gives up"
    );
}
