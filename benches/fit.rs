//! `vams fit`'s wall time (issue 18): the motor's joint fit through `vams extract` on four
//! synthetic captures of 100 000 samples each (the goal: under 2 s on 2 cores), then the
//! same captures at a scope's usual 1 500 to 12 000 samples, then a generic `vams fit` of
//! `tests/fit/rc.vhd` to two captures of 10 000 samples. Each: the binary as a user runs it
//! (reading, the paper's method, the fit, the table), best of three wall times.
//!
//! Run: `cargo bench --bench fit`.

use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

use vams::extract::MotorParams;
use vams::extract::synth::{SynthOptions, generate, write_captures};

const VAMS: &str = env!("CARGO_BIN_EXE_vams");

/// Best of three wall times of `vams ARGS` (which must succeed), and its stdout.
fn best_of_three(args: &[String]) -> (Duration, String) {
    let mut best = Duration::MAX;
    let mut out = String::new();
    for _ in 0..3 {
        let start = Instant::now();
        let o = Command::new(VAMS).args(args).output().expect("vams runs");
        let took = start.elapsed();
        assert!(
            o.status.success(),
            "vams {args:?} failed: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        best = best.min(took);
        out = String::from_utf8_lossy(&o.stdout).into_owned();
    }
    (best, out)
}

fn motor(dir: &Path, samples: Option<usize>) {
    let o = SynthOptions {
        samples,
        ..SynthOptions::default()
    };
    let caps = generate(&MotorParams::example(), &o);
    write_captures(dir, &caps).expect("the temporary folder is writable");
    let bytes: u64 = ["inrush", "blocked", "speed", "coast"]
        .iter()
        .map(|r| std::fs::metadata(dir.join(format!("{r}.csv"))).map_or(0, |m| m.len()))
        .sum();
    let mut args = vec!["extract".to_string(), "--json".to_string()];
    for r in ["inrush", "blocked", "speed", "coast"] {
        args.push(format!("--{r}"));
        args.push(dir.join(format!("{r}.csv")).display().to_string());
    }
    let (took, out) = best_of_three(&args);
    let json: serde_json::Value = serde_json::from_str(&out).expect("--json prints JSON");
    let truth = MotorParams::example();
    let errors: Vec<String> = MotorParams::NAMES
        .iter()
        .zip(truth.values())
        .map(|(n, t)| {
            let got = json[*n].as_f64().unwrap_or(f64::NAN);
            format!("{n} {:+.2} %", 100.0 * (got - t) / t)
        })
        .collect();
    println!(
        "motor fit, {} samples per capture ({:.1} MB of CSV): {:.3} s wall, {} simulations; {}",
        samples.map_or("12 000/1 500/6 000/12 000".to_string(), |n| n.to_string()),
        bytes as f64 / 1e6,
        took.as_secs_f64(),
        json["simulations"],
        errors.join(", ")
    );
}

fn main() {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    println!("{cores} core(s)");
    let dir = tempfile::tempdir().expect("a temporary folder");
    motor(dir.path(), Some(100_000));
    motor(dir.path(), None);

    // The generic fit: tests/fit/rc.vhd's charge, 10 000 samples, c and the step free.
    let rc = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/fit/rc.vhd");
    let path = dir.path().join("charge.csv");
    let mut text = String::from("time,v\n");
    for k in 0..10_000 {
        let t = -0.5e-3 + k as f64 * 0.6e-6;
        let v = if t < 0.0 {
            0.0
        } else {
            5.0 * (1.0 - (-t / (2.2e3 * 0.47e-6)).exp())
        };
        // A deterministic wobble of 20 mV stands in for noise: the timing is the point here.
        let wobble = 0.02 * ((k * 7919 % 101) as f64 / 50.0 - 1.0);
        text.push_str(&format!("{t:.7e},{:.5}\n", v + wobble));
    }
    std::fs::write(&path, text).expect("the temporary folder is writable");
    let args: Vec<String> = [
        "fit",
        rc,
        "--top",
        "tb_rc",
        "-g",
        "r=2.2e3",
        "--measured",
        &format!("{}:mode=0,shift=1ms", path.display()),
        "--match",
        "vc=v",
        "--free",
        "c=1e-6",
        "--free",
        "v_step=4",
        "--json",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    let (took, out) = best_of_three(&args);
    let json: serde_json::Value = serde_json::from_str(&out).expect("--json prints JSON");
    println!(
        "rc fit, 10 000 samples: {:.3} s wall, {} simulations, c = {}",
        took.as_secs_f64(),
        json["simulations"],
        json["parameters"]["c"]["value"]
    );
}
