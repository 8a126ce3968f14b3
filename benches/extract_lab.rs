//! `vams extract` on captures taken as a lab takes them: random motors, each capture on its
//! own bench (the blocked rotor at 2-4 V, the others at 10-14 V, each with its own source
//! resistance), timebase, ranges, trigger, from `tests/it/support/lab_motor.rs`, a generator that
//! shares no code with vams. Per lab: the truth, the fitted value, its error, the paper's
//! method's error, and whether `ci95` and `ci95_bootstrap` hold the truth; then the largest
//! errors, the intervals' coverage and the wall time per extraction.
//!
//! A plain program, not criterion: `cargo bench --bench extract_lab` (`LAB_SETS=N` labs,
//! default 20; `LAB_SEED=S` the first seed, default 1; `LAB_KEEP=DIR` keeps the captures;
//! `LAB_SHARED=1` puts all four captures
//! of each lab on one 12 V bench, the control). Exits with 1 when a lab misses a goal (R, L
//! and Ke within 1 %, J, D and Tcst within 5 %) or the extraction fails.

#[path = "../tests/it/support/lab_motor.rs"]
mod lab_motor;

use std::process::Command;
use std::time::{Duration, Instant};

use lab_motor::{Bench, Lab, LabMotor};

const VAMS: &str = env!("CARGO_BIN_EXE_vams");

/// The goals, in the order of [`LabMotor::NAMES`].
const GOALS: [f64; 7] = [0.01, 0.01, 0.01, 0.01, 0.05, 0.05, 0.05];

/// Whether a relative error `err` meets `goal` (NaN, a value missing, does not).
fn meets(err: f64, goal: f64) -> bool {
    err.abs() < goal
}

fn env_u64(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// One lab's outcome: per parameter the fitted and the paper's relative errors and whether
/// the two intervals hold the truth; `None` when the extraction failed.
struct Outcome {
    errors: [f64; 7],
    paper: [f64; 7],
    holds: [[Option<bool>; 2]; 7],
}

fn yes_no(h: Option<bool>) -> &'static str {
    match h {
        Some(true) => "y",
        Some(false) => "n",
        None => "-",
    }
}

fn run(seed: u64, shared: Option<Bench>) -> (Duration, Option<Outcome>) {
    let lab = Lab::random_on(seed, shared);
    let dir = tempfile::tempdir().expect("a temporary folder");
    // `LAB_KEEP=DIR` keeps each lab's captures in DIR/lab<seed>, to look into one.
    let folder = match std::env::var_os("LAB_KEEP") {
        Some(keep) => std::path::PathBuf::from(keep).join(format!("lab{seed}")),
        None => dir.path().to_path_buf(),
    };
    let paths = lab.write(&folder).expect("the folder is writable");
    let start = Instant::now();
    let out = Command::new(VAMS)
        .args(Lab::extract_args(&paths))
        .env("NO_COLOR", "1")
        .output()
        .expect("vams runs");
    let took = start.elapsed();
    println!("lab {seed} ({:.2} s): {:?}", took.as_secs_f64(), lab.motor);
    print!("{}", lab.describe());
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        println!("  extraction failed:");
        for line in err.lines().filter(|l| !l.trim().is_empty()).take(6) {
            println!("    {line}");
        }
        return (took, None);
    }
    let v: serde_json::Value = match serde_json::from_slice(&out.stdout) {
        Ok(v) => v,
        Err(e) => {
            println!("  --json printed no JSON: {e}");
            return (took, None);
        }
    };
    let truth = lab.motor.values();
    let rel = |obj: &serde_json::Value, k: usize| {
        obj[LabMotor::NAMES[k]].as_f64().unwrap_or(f64::NAN) / truth[k] - 1.0
    };
    let holds = |key: &str, k: usize| {
        let ci = &v[key][LabMotor::NAMES[k]];
        let (lo, hi) = (ci[0].as_f64()?, ci[1].as_f64()?);
        Some(lo <= truth[k] && truth[k] <= hi)
    };
    let o = Outcome {
        errors: std::array::from_fn(|k| rel(&v, k)),
        paper: std::array::from_fn(|k| rel(&v["paper"], k)),
        holds: std::array::from_fn(|k| [holds("ci95", k), holds("ci95_bootstrap", k)]),
    };
    println!(
        "  | {:10} | {:>11} | {:>11} | {:>8} | {:>8} | ci95 | bootstrap | goal |",
        "parameter", "true", "fitted", "error", "paper"
    );
    for k in 0..7 {
        let fitted = truth[k] * (1.0 + o.errors[k]);
        println!(
            "  | {:10} | {:11.4e} | {:11.4e} | {:+7.2}% | {:+7.2}% | {:>4} | {:>9} | {:>4} |",
            LabMotor::NAMES[k],
            truth[k],
            fitted,
            100.0 * o.errors[k],
            100.0 * o.paper[k],
            yes_no(o.holds[k][0]),
            yes_no(o.holds[k][1]),
            if meets(o.errors[k], GOALS[k]) {
                "ok"
            } else {
                "MISS"
            },
        );
    }
    (took, Some(o))
}

fn main() {
    // Cargo passes `--bench` (and a filter, if given) to every bench; none is used here.
    let sets = env_u64("LAB_SETS", 20);
    let first = env_u64("LAB_SEED", 1);
    let shared = (std::env::var_os("LAB_SHARED").is_some_and(|v| v != "0"))
        .then_some(Bench { vs: 12.0, rs: 0.2 });
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    println!(
        "{sets} labs from seed {first}, {}; {cores} core(s)",
        if shared.is_some() {
            "all captures on one 12 V, 0.2 ohm bench (control)"
        } else {
            "each capture on its own bench"
        }
    );
    let mut times = Vec::new();
    let mut outcomes = Vec::new();
    let mut failed = Vec::new();
    for seed in first..first + sets {
        let (took, o) = run(seed, shared);
        times.push(took.as_secs_f64());
        match o {
            Some(o) => outcomes.push((seed, o)),
            None => failed.push(seed),
        }
    }

    println!(
        "\nsummary over {} extracted labs ({} failed)",
        outcomes.len(),
        failed.len()
    );
    println!(
        "| parameter | goal | max fitted error | max paper error | labs within goal | ci95 holds | bootstrap holds |"
    );
    println!("|---|---|---|---|---|---|---|");
    let n = outcomes.len();
    for (k, &goal) in GOALS.iter().enumerate() {
        let max_abs = |f: &dyn Fn(&Outcome) -> f64| {
            outcomes
                .iter()
                .map(|(_, o)| f(o).abs())
                .fold(
                    0.0f64,
                    |a, e| if e.is_nan() { f64::INFINITY } else { a.max(e) },
                )
        };
        let within = outcomes
            .iter()
            .filter(|(_, o)| meets(o.errors[k], goal))
            .count();
        let held = |i: usize| {
            outcomes
                .iter()
                .filter(|(_, o)| o.holds[k][i] == Some(true))
                .count()
        };
        println!(
            "| {} | {} % | {:.2} % | {:.2} % | {within} of {n} | {} of {n} | {} of {n} |",
            LabMotor::NAMES[k],
            100.0 * goal,
            100.0 * max_abs(&|o| o.errors[k]),
            100.0 * max_abs(&|o| o.paper[k]),
            held(0),
            held(1),
        );
    }
    let mut sorted = times.clone();
    sorted.sort_by(f64::total_cmp);
    if let (Some(lo), Some(hi)) = (sorted.first(), sorted.last()) {
        println!(
            "wall time per extraction: median {:.2} s, min {lo:.2} s, max {hi:.2} s, total {:.1} s",
            sorted[sorted.len() / 2],
            sorted.iter().sum::<f64>()
        );
    }
    let missed: Vec<u64> = outcomes
        .iter()
        .filter(|(_, o)| o.errors.iter().zip(GOALS).any(|(&e, g)| !meets(e, g)))
        .map(|(s, _)| *s)
        .collect();
    println!("labs missing a goal: {missed:?}; extractions failed: {failed:?}");
    if !missed.is_empty() || !failed.is_empty() {
        std::process::exit(1);
    }
}
