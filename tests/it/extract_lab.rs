//! `vams extract` on captures taken as a lab takes them (`support/lab_motor.rs`, a generator
//! independent of vams): every capture on its own bench, the blocked rotor at 2-4 V and the
//! others at 10-14 V, each with its own source resistance, timebase, ranges and trigger.
//! The goals: R, L and Ke within 1 %, J, D and Tcst within 5 % of the truth. The extraction
//! of 44d4e4f (one supply and one source resistance for all four captures) missed them on
//! every such lab, by tens of per cent, and met them on one shared bench (the ignored
//! control); with a supply per experiment it meets them on 19 of 20 labs (the bench,
//! `cargo bench --bench extract_lab`). Each test prints every parameter's error, the paper's method's and the intervals'.

use crate::support::lab_motor;

use assert_cmd::Command;
use lab_motor::{Bench, Lab, LabMotor};

/// The goals, in the order of [`LabMotor::NAMES`].
const GOALS: [f64; 7] = [0.01, 0.01, 0.01, 0.01, 0.05, 0.05, 0.05];

/// What `vams extract --json` gave for one lab.
struct Extracted {
    fitted: [f64; 7],
    paper: [f64; 7],
    /// `ci95` and `ci95_bootstrap`: whether each holds the truth (`None`: no interval).
    holds: [[Option<bool>; 2]; 7],
}

/// Extracts lab `seed`'s motor, on its own four benches or on one `shared` bench; it must
/// succeed and converge.
fn extract(seed: u64, shared: Option<Bench>) -> (Lab, Extracted) {
    match try_extract(seed, shared) {
        (lab, Ok(e)) => (lab, e),
        (_, Err(why)) => panic!("lab {seed}: {why}"),
    }
}

/// [`extract`], or why the extraction gave no converged result (its diagnostic, or the
/// fit's reasons).
fn try_extract(seed: u64, shared: Option<Bench>) -> (Lab, Result<Extracted, String>) {
    let lab = Lab::random_on(seed, shared);
    let dir = tempfile::tempdir().unwrap();
    let paths = lab.write(dir.path()).unwrap();
    let out = Command::cargo_bin("vams")
        .expect("the vams binary is built for tests")
        .env("NO_COLOR", "1")
        .args(&Lab::extract_args(&paths)[..])
        .output()
        .expect("vams runs");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    let Ok(v) = serde_json::from_slice::<serde_json::Value>(&out.stdout) else {
        return (lab, Err(format!("no result: {stderr}")));
    };
    if v["converged"] != true || !out.status.success() {
        return (lab, Err(format!("not converged: {}", v["reasons"])));
    }
    let truth = lab.motor.values();
    let get =
        |obj: &serde_json::Value, k: usize| obj[LabMotor::NAMES[k]].as_f64().unwrap_or(f64::NAN);
    let holds = |key: &str, k: usize| {
        let ci = &v[key][LabMotor::NAMES[k]];
        let (lo, hi) = (ci[0].as_f64()?, ci[1].as_f64()?);
        Some(lo <= truth[k] && truth[k] <= hi)
    };
    let e = Extracted {
        fitted: std::array::from_fn(|k| get(&v, k)),
        paper: std::array::from_fn(|k| get(&v["paper"], k)),
        holds: std::array::from_fn(|k| [holds("ci95", k), holds("ci95_bootstrap", k)]),
    };
    eprintln!("lab {seed}: {:?}\n{}", lab.motor, lab.describe());
    for (k, &t) in truth.iter().enumerate() {
        let (got, paper) = (e.fitted[k], e.paper[k]);
        let mark = |h: Option<bool>| match h {
            Some(true) => "y",
            Some(false) => "n",
            None => "-",
        };
        eprintln!(
            "  {:10} true {t:.4e} fitted {got:.4e} ({:+7.2} %) paper {paper:.4e} ({:+7.2} %) \
             ci95 {} bootstrap {}",
            LabMotor::NAMES[k],
            100.0 * (got / t - 1.0),
            100.0 * (paper / t - 1.0),
            mark(e.holds[k][0]),
            mark(e.holds[k][1]),
        );
    }
    (lab, Ok(e))
}

/// Whether a relative error `err` meets `goal` (NaN, a key missing, does not).
fn meets(err: f64, goal: f64) -> bool {
    err.abs() < goal
}

/// The parameters that miss their goal, with their errors.
fn misses(lab: &Lab, e: &Extracted) -> Vec<String> {
    let truth = lab.motor.values();
    (0..7)
        .filter_map(|k| {
            let err = e.fitted[k] / truth[k] - 1.0;
            (!meets(err, GOALS[k])).then(|| {
                format!(
                    "{} {:+.2} % (goal {} %)",
                    LabMotor::NAMES[k],
                    100.0 * err,
                    100.0 * GOALS[k]
                )
            })
        })
        .collect()
}

fn meets_the_goals(seed: u64, shared: Option<Bench>) {
    let (lab, e) = extract(seed, shared);
    let missed = misses(&lab, &e);
    assert!(missed.is_empty(), "lab {seed}: {}", missed.join(", "));
}

// Two labs: each `vams extract` of the unoptimised test build takes tens of seconds.

#[test]
fn meets_the_goals_on_lab_1() {
    meets_the_goals(1, None);
}

#[test]
fn meets_the_goals_on_lab_2() {
    meets_the_goals(2, None);
}

/// The control: the same motors with all four captures on one 12 V bench, the set-up the
/// extraction's model first assumed. When the two tests above fail and this passes, what
/// fails is the benches, not the generator's motor, ripple or scope.
#[test]
#[ignore = "a control for diagnosis: two more extractions; run with --ignored"]
fn meets_the_goals_on_labs_1_and_2_with_one_shared_bench() {
    for seed in [1, 2] {
        meets_the_goals(seed, Some(Bench { vs: 12.0, rs: 0.2 }));
    }
}

#[test]
#[ignore = "slow: 24 extractions; run with --ignored (a release build: --release)"]
fn the_intervals_hold_the_truth_in_most_labs() {
    let labs = 24;
    let mut held = [[0usize; 2]; 7];
    let mut missed = Vec::new();
    for seed in 100..100 + labs {
        // A lab without a converged result counts as missed by every interval (two of these
        // 24 end so, with a diagnostic or exit status 3: benches/README.md).
        let (lab, e) = match try_extract(seed, None) {
            (lab, Ok(e)) => (lab, e),
            (_, Err(why)) => {
                missed.push(format!("lab {seed}: {why}"));
                continue;
            }
        };
        for (h, got) in held.iter_mut().zip(&e.holds) {
            for (count, g) in h.iter_mut().zip(got) {
                *count += usize::from(*g == Some(true));
            }
        }
        let m = misses(&lab, &e);
        if !m.is_empty() {
            missed.push(format!("lab {seed}: {}", m.join(", ")));
        }
    }
    eprintln!("labs missing a goal: {}", missed.len());
    for m in &missed {
        eprintln!("  {m}");
    }
    // The 95 % interval with model error should hold the truth in at least 80 % of the labs
    // (a margin for the small number of labs). The covariance's assumes the model exact:
    // against this generator's stick and varying ripple it held Ke, J, D and Tcst in about
    // half the labs (benches/README.md), and is only printed. Measured 2026-12-07: the second
    // interval of Ke held the truth in 17 of these 24 labs (the others in 19-22), so this test
    // fails on Ke: the goal, not yet the state.
    let least = (labs as usize * 4).div_ceil(5);
    let mut short = Vec::new();
    for (name, counts) in LabMotor::NAMES.iter().zip(held) {
        eprintln!(
            "{name}: ci95 holds the truth in {} of {labs}, ci95_bootstrap in {}",
            counts[0], counts[1]
        );
        if counts[1] < least {
            short.push(format!("{name} ci95_bootstrap {} of {labs}", counts[1]));
        }
    }
    assert!(
        short.is_empty(),
        "intervals holding the truth in fewer than {least} labs: {}",
        short.join(", ")
    );
}
