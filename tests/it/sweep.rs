//! `vams sweep` end to end on `tests/sweep/decay.vhd` (x' = -x / tau, whose metrics have
//! closed forms): metrics against them over a grid, failed runs recorded, shards collected
//! into the local run's table byte for byte, a sweep interrupted by SIGINT and resumed, and
//! the spec's diagnostics.

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use predicates::str::contains;

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/sweep");

fn vams() -> Command {
    Command::cargo_bin("vams").expect("the vams binary is built for integration tests")
}

/// Writes `spec.toml` (a `[design]` on decay.vhd, then `body`) into a fresh folder.
fn spec(body: &str) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("spec.toml");
    let text = format!("[design]\nfiles = [\"{DIR}/decay.vhd\"]\ntop = \"tb_decay\"\n\n{body}");
    std::fs::write(&path, text).unwrap();
    (dir, path)
}

/// The rows of a result table as maps from column to cell.
fn rows(path: &Path) -> Vec<std::collections::HashMap<String, String>> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut reader = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .from_reader(text.as_bytes());
    let header: Vec<String> = reader.headers().unwrap().iter().map(String::from).collect();
    reader
        .records()
        .map(|r| {
            let r = r.unwrap();
            header
                .iter()
                .cloned()
                .zip(r.iter().map(String::from))
                .collect()
        })
        .collect()
}

/// `vams sweep SPEC --out OUT`.
fn sweep_into(spec: &Path, out: &Path) -> Command {
    let mut command = vams();
    command.args([
        "sweep",
        spec.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    command
}

fn number(cell: &str) -> f64 {
    cell.parse()
        .unwrap_or_else(|_| panic!("`{cell}` is not a number"))
}

const METRICS: &str = "[metrics]
fall  = { kind = \"cross\", of = \"x\", value = 0.36787944117144233, edge = \"falling\" }
mean  = { kind = \"mean\", of = \"x\" }
calm  = { kind = \"settling_time\", of = \"x\", from = 0.0, target = 0.0, band = 0.01, max = \"5 ms\" }
final = { kind = \"final\", of = \"x\" }
";

#[test]
fn grid_metrics_agree_with_the_closed_forms() {
    let (dir, path) = spec(&format!(
        "[grid.parameters]\ntau = [0.5e-3, 1.0e-3, 2.0e-3]\n\n{METRICS}"
    ));
    let out = dir.path().join("out");
    sweep_into(&path, &out)
        .assert()
        .success()
        .stderr(contains("3 runs: 3 ok, 0 failed"))
        .stderr(contains("yield: 2 of 3 runs meet every limit"));
    let table = rows(&out.join("results.csv"));
    assert_eq!(table.len(), 3);
    let stop = 5e-3;
    for row in &table {
        let tau = number(&row["tau"]);
        // At the default reltol 1e-3 the solution is within a few 1e-3 of exp(-t / tau).
        let fall = number(&row["fall"]);
        assert!((fall - tau).abs() < 5e-3 * tau, "tau {tau}: fell at {fall}");
        let mean = number(&row["mean"]);
        let want = tau * (1.0 - (-stop / tau).exp()) / stop;
        assert!(
            (mean - want).abs() < 5e-3 * want,
            "tau {tau}: mean {mean}, want {want}"
        );
        let want = tau * 100f64.ln();
        if want < stop {
            let calm = number(&row["calm"]);
            assert!(
                (calm - want).abs() < 1e-2 * want,
                "tau {tau}: calm {calm}, want {want}"
            );
            assert_eq!(row["pass"], "pass");
        } else {
            // Still outside the band at the stop time: no value, and the run's limits fail
            // (the run itself is ok).
            assert_eq!(row["calm"], "");
            assert!(row["message"].contains("calm"), "{row:?}");
            assert_eq!(row["pass"], "fail");
        }
        assert_eq!(row["status"], "ok");
    }
    assert!(out.join("histograms.svg").exists());
}

#[test]
fn failed_runs_are_recorded_with_their_message_and_the_sweep_goes_on() {
    let (dir, path) = spec(&format!(
        "[grid.parameters]\nsteps = [1, 0]\ntau_max = [1.0, 1e-4]\n\n{METRICS}"
    ));
    let out = dir.path().join("out");
    sweep_into(&path, &out)
        .assert()
        .success()
        .stderr(contains("4 runs: 1 ok, 3 failed"));
    let table = rows(&out.join("results.csv"));
    let by = |steps: &str, tau_max: &str| {
        table
            .iter()
            .find(|r| r["steps"] == steps && r["tau_max"] == tau_max)
            .unwrap()
    };
    assert_eq!(by("1", "1").get("status").unwrap(), "ok");
    let assertion = by("1", "0.0001");
    assert_eq!(assertion["status"], "failed");
    assert!(
        assertion["message"].contains("tau beyond tau_max"),
        "{assertion:?}"
    );
    assert_eq!(assertion["pass"], "fail");
    assert_eq!(assertion["fall"], "");
    let elaboration = by("0", "1");
    assert_eq!(elaboration["status"], "failed");
    assert!(
        elaboration["message"].contains("outside its subtype's range"),
        "{elaboration:?}"
    );
}

const MONTE_CARLO: &str = "[monte_carlo]
runs = 40
seed = 11
sampling = \"latin_hypercube\"
[monte_carlo.parameters]
tau = { distribution = \"lognormal\", nominal = 1e-3, tolerance = \"30%\" }
tau_max = { distribution = \"uniform\", min = 1.0, max = 2.0 }
";

#[test]
fn shards_collect_into_the_local_table_byte_for_byte() {
    let (dir, path) = spec(&format!("{MONTE_CARLO}\n{METRICS}"));
    let local = dir.path().join("local");
    sweep_into(&path, &local).assert().success();
    let sharded = dir.path().join("sharded");
    // In reverse order and with one job each: neither changes a row.
    for k in (0..3).rev() {
        vams()
            .args([
                "sweep",
                path.to_str().unwrap(),
                "--shard",
                &format!("{k}/3"),
                "--jobs",
                "1",
                "--out",
                sharded.to_str().unwrap(),
            ])
            .assert()
            .success();
    }
    std::fs::remove_file(sharded.join("shard-1-of-3.csv")).unwrap();
    vams()
        .args(["sweep", "collect", sharded.to_str().unwrap()])
        .assert()
        .failure()
        .stderr(contains("1 of 3 shards are missing or partial"))
        .stderr(contains("--shard K/3"));
    vams()
        .args([
            "sweep",
            path.to_str().unwrap(),
            "--shard",
            "1/3",
            "--out",
            sharded.to_str().unwrap(),
        ])
        .assert()
        .success();
    vams()
        .args(["sweep", "collect", sharded.to_str().unwrap()])
        .assert()
        .success()
        .stderr(contains("collected 3 shards, 41 runs"));
    let a = std::fs::read(local.join("results.csv")).unwrap();
    let b = std::fs::read(sharded.join("results.csv")).unwrap();
    assert!(a == b, "the collected table differs from the local one");
    // The samples are the seed's: a second local run gives the same table.
    let again = dir.path().join("again");
    sweep_into(&path, &again).assert().success();
    assert!(std::fs::read(again.join("results.csv")).unwrap() == a);
}

/// Starts `vams ARGS`, sends SIGINT once `table` holds a few rows, and returns the exit
/// status and standard error.
fn interrupt_when_started(args: &[&str], table: &Path) -> (std::process::ExitStatus, String) {
    use std::time::{Duration, Instant};
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_vams"))
        .args(args)
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let started = Instant::now();
    loop {
        let lines = std::fs::read_to_string(table).map_or(0, |t| t.lines().count());
        if lines >= 5 {
            break;
        }
        assert!(
            child.try_wait().unwrap().is_none(),
            "the sweep ended before the signal"
        );
        assert!(
            started.elapsed() < Duration::from_secs(120),
            "no rows written"
        );
        std::thread::sleep(Duration::from_millis(2));
    }
    let killed = std::process::Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(killed.success());
    let status = child.wait().unwrap();
    let mut stderr = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut stderr).unwrap();
    (status, stderr)
}

#[test]
fn an_interrupted_sweep_keeps_its_runs_and_resumes() {
    // 2 000 runs of 500 steps each: about a second in a release build, ten in a debug one.
    let (dir, path) = spec(
        "[monte_carlo]\nruns = 2000\nseed = 3\n[monte_carlo.parameters]\ntau = { distribution = \"uniform\", min = 0.5e-3, max = 2e-3 }\n[metrics]\nfinal = { kind = \"final\", of = \"x\" }\n",
    );
    let text = std::fs::read_to_string(&path).unwrap();
    std::fs::write(
        &path,
        text.replace(
            "top = \"tb_decay\"\n",
            "top = \"tb_decay\"\nmax_step = \"10 us\"\n",
        ),
    )
    .unwrap();
    let out = dir.path().join("out");
    let table = out.join("results.csv");
    let (status, stderr) = interrupt_when_started(
        &[
            "sweep",
            path.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ],
        &table,
    );
    assert_eq!(status.code(), Some(130), "{stderr}");
    assert!(stderr.contains("--resume"), "{stderr}");
    let text = std::fs::read_to_string(&table).unwrap();
    let last = text.lines().last().unwrap();
    assert!(last.starts_with("# partial: interrupted after "), "{last}");
    let kept = rows(&table);
    assert!(!kept.is_empty() && kept.len() < 2001, "{} rows", kept.len());
    // Every kept row is complete and in order.
    for (k, row) in kept.iter().enumerate() {
        assert_eq!(number(&row["run"]), k as f64);
        assert_eq!(row["status"], "ok");
    }
    // Without --resume the table is not overwritten.
    sweep_into(&path, &out)
        .assert()
        .failure()
        .stderr(contains("already holds the table of a sweep"));
    // A changed spec is not resumed into it.
    let changed = dir.path().join("changed.toml");
    std::fs::write(
        &changed,
        std::fs::read_to_string(&path)
            .unwrap()
            .replace("seed = 3", "seed = 4"),
    )
    .unwrap();
    vams()
        .args([
            "sweep",
            changed.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--resume",
        ])
        .assert()
        .failure()
        .stderr(contains("is the table of another spec"));
    vams()
        .args([
            "sweep",
            path.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--resume",
        ])
        .assert()
        .success()
        .stderr(contains(format!("{} to do", 2001 - kept.len())));
    let all = rows(&table);
    assert_eq!(all.len(), 2001);
    assert_eq!(&all[..kept.len()], &kept[..]);
    assert!(
        !std::fs::read_to_string(&table)
            .unwrap()
            .contains("# partial")
    );
}

#[test]
fn spec_errors_name_the_line_and_exit_1() {
    for (body, line, message) in [
        (
            "[grid.parameters]\ntau = [1e-3]\ntua = [1, 2]\n",
            7,
            "the design has no generic `tua`",
        ),
        (
            "[monte_carlo]\nruns = 10\n[monte_carlo.parameters]\ntau = { nominal = 1e-3, sigma = -1e-4 }\n",
            8,
            "the spread must not be negative",
        ),
        (
            "[grid.parameters]\ntau = { from = 1e-3, to = 2e-3, steps = 0 }\n",
            6,
            "a range of 0 steps has no values",
        ),
        (
            "[grid.parameters]\ntau = { from = 1e-3, to = 2e-3, steps = 1000 }\ntau_max = { from = 1.0, to = 2.0, steps = 1000 }\nsteps = { from = 1, to = 1000, steps = 1000 }\n",
            5,
            "this plan has 1000000000 runs",
        ),
        (
            "[grid.parameters]\ntau = [1e-3]\n[metrics]\nm = { kind = \"max\", of = \"xx\" }\n",
            8,
            "the design has no quantity or signal `xx`",
        ),
        (
            "[grid.parameters]\ntau = [1e-3]\n[plots]\nenvelope = [\"x\", \"y\"]\n",
            8,
            "the design has no quantity or signal `y`",
        ),
        (
            "[grid.parameters]\ntau = [1e-3]\n[metrics]\nm = { kind = \"max\", of = \"x\", from = \"2 ms\", to = \"1 ms\" }\n",
            8,
            "metric `m`",
        ),
    ] {
        let (_dir, path) = spec(body);
        vams()
            .args(["sweep", path.to_str().unwrap()])
            .current_dir(path.parent().unwrap())
            .assert()
            .code(1)
            .stderr(contains(format!("spec.toml:{line}: {message}")));
    }
    vams()
        .args(["sweep", "/no/such/spec.toml"])
        .assert()
        .code(1)
        .stderr(contains("cannot read the sweep spec"));
}

#[test]
fn a_sweep_of_reports_alone_records_no_waveform() {
    // Only assertion_failures: no column is read, so no row is built (no probe would
    // otherwise mean recording every quantity); the count is still there.
    let (dir, path) = spec(
        "[grid.parameters]\ntau_max = [1.0, 1e-4]\n[metrics]\nf = { kind = \"assertion_failures\", max = 0 }\n",
    );
    let out = dir.path().join("out");
    sweep_into(&path, &out)
        .assert()
        .success()
        .stderr(contains("yield: 1 of 2 runs meet every limit"));
    let table = rows(&out.join("results.csv"));
    assert_eq!(
        (table[0]["f"].as_str(), table[0]["status"].as_str()),
        ("0", "ok")
    );
    assert_eq!(table[1]["status"], "failed");
}

#[test]
fn the_designs_own_generics_are_checked_too() {
    let (_dir, path) = spec("[grid.parameters]\ntau = [1e-3]\n");
    let text = std::fs::read_to_string(&path).unwrap();
    std::fs::write(
        &path,
        text.replace(
            "top = \"tb_decay\"\n",
            "top = \"tb_decay\"\ngenerics = { taux = 1 }\n",
        ),
    )
    .unwrap();
    vams()
        .args(["sweep", path.to_str().unwrap()])
        .current_dir(path.parent().unwrap())
        .assert()
        .code(1)
        .stderr(contains("has no generic `taux`"))
        .stderr(contains("its generics are `tau`, `tau_max` and `steps`"));
}

#[test]
fn instance_generics_are_set_by_their_path() {
    // `-g` reaches an instance's generic by its hierarchical name, and a wrong path is an
    // error that suggests the right one.
    let models = concat!(env!("CARGO_MANIFEST_DIR"), "/models");
    vams()
        .args([
            "run",
            models,
            "--top",
            "tb_tracking",
            "-g",
            "dut.u_motr.r=5",
        ])
        .assert()
        .code(1)
        .stderr(contains(
            "no instance of the design has a generic `dut.u_motr.r`",
        ))
        .stderr(contains("did you mean `dut.u_motor.r`?"));
}
