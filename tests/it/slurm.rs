//! The Slurm path end to end on a real one-node cluster (`support/slurm.rs`): the job-array
//! script `sweep::slurm` writes, submitted with its `submit`, awaited with its `wait`, runs
//! every shard, and a resubmission of some tasks runs only those. A stand-in for `vams`
//! (a small sh script) writes each shard's file, so this checks the Slurm contract alone;
//! awkward paths (spaces, quotes, `%`) check the script's quoting where sbatch and the shell
//! really read it.

use crate::support::slurm as slurm_support;

use std::fs;
use std::path::Path;
use std::time::{Duration, Instant};

use slurm_support::LocalSlurm;
use vams::app::study::slurm::{ArrayJob, write_script};

/// Stands in for `vams sweep SPEC --shard K/N --out OUT EXTRA...`: writes
/// `OUT/shard-K-of-N.csv` naming the spec and the extra arguments, as the real one would
/// write its rows.
const FAKE_VAMS: &str = r#"#!/bin/sh
set -eu
[ "$1" = sweep ] || exit 2
spec="$2"; shard="$4"; out="$6"; shift 6
k="${shard%/*}"; n="${shard#*/}"
echo "shard $k of $n of $spec with $*" > "$out/shard-$k-of-$n.csv"
echo "task $SLURM_ARRAY_TASK_ID done"
"#;

const SHARDS: usize = 4;

#[test]
fn job_array_runs_every_shard_and_resubmits_only_some() {
    let started = Instant::now();
    let cluster = match LocalSlurm::start() {
        Ok(cluster) => cluster,
        Err(reason) => {
            eprintln!("skipping: {reason}");
            return;
        }
    };
    eprintln!("cluster up in {:.1} s", started.elapsed().as_secs_f64());
    let tmp = tempfile::tempdir().unwrap();
    let bin = tmp.path().join("my bin");
    fs::create_dir(&bin).unwrap();
    let vams = bin.join("vams");
    fs::write(&vams, FAKE_VAMS).unwrap();
    make_executable(&vams);
    let spec = tmp.path().join("o'brien's spec.toml");
    fs::write(&spec, "").unwrap();
    let out = tmp.path().join("out \"dir\" 50%");
    let job = ArrayJob {
        vams,
        spec: spec.clone(),
        out: out.clone(),
        shards: SHARDS,
        partition: None,
        time: Some("5".into()),
        job_name: "vams test #1".into(),
        extra_args: vec!["--seed".into(), "7 8".into()],
    };
    let script = write_script(&job).unwrap();
    let slurm = cluster.client();

    let id = slurm.submit(&script, None).unwrap();
    slurm.wait(&id, Duration::from_secs(60)).unwrap();
    for k in 0..SHARDS {
        let shard = out.join(format!("shard-{k}-of-{SHARDS}.csv"));
        let text = fs::read_to_string(&shard)
            .unwrap_or_else(|e| panic!("{}: {e}; {}", shard.display(), log(&job, k)));
        assert_eq!(
            text,
            format!(
                "shard {k} of {SHARDS} of {} with --seed 7 8\n",
                spec.display()
            )
        );
        assert_eq!(log(&job, k), format!("task {k} done\n"));
    }

    // Shards 1 and 3 lost: only they run again.
    for k in [1, 3] {
        fs::remove_file(out.join(format!("shard-{k}-of-{SHARDS}.csv"))).unwrap();
    }
    fs::write(out.join(format!("shard-0-of-{SHARDS}.csv")), "kept\n").unwrap();
    let again = slurm.submit(&script, Some(&[3, 1])).unwrap();
    assert_ne!(again, id);
    slurm.wait(&again, Duration::from_secs(60)).unwrap();
    for k in [1, 3] {
        assert!(
            out.join(format!("shard-{k}-of-{SHARDS}.csv")).exists(),
            "{}",
            log(&job, k)
        );
    }
    assert_eq!(
        fs::read_to_string(out.join(format!("shard-0-of-{SHARDS}.csv"))).unwrap(),
        "kept\n"
    );
    drop(cluster);
    eprintln!(
        "start, two jobs and stop in {:.1} s",
        started.elapsed().as_secs_f64()
    );
}

/// The issue's check: a 40-run Monte Carlo through `vams sweep --slurm --wait` on the real
/// cluster, its shards collected, equals the local run's table byte for byte.
#[test]
fn a_monte_carlo_sweep_through_slurm_equals_the_local_run() {
    let cluster = match LocalSlurm::start() {
        Ok(cluster) => cluster,
        Err(reason) => {
            eprintln!("skipping: {reason}");
            return;
        }
    };
    let tmp = tempfile::tempdir().unwrap();
    let spec = tmp.path().join("mc.toml");
    let model = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/sweep/decay.vhd");
    fs::write(
        &spec,
        format!(
            "[design]\nfiles = [\"{model}\"]\ntop = \"tb_decay\"\n\n[monte_carlo]\nruns = 39\nseed = 5\n[monte_carlo.parameters]\ntau = {{ distribution = \"normal\", nominal = 1e-3, tolerance = \"20%\" }}\n\n[metrics]\nfall = {{ kind = \"cross\", of = \"x\", value = 0.5, edge = \"falling\" }}\nmean = {{ kind = \"mean\", of = \"x\" }}\n"
        ),
    )
    .unwrap();
    let vams = env!("CARGO_BIN_EXE_vams");
    let local = tmp.path().join("local");
    let status = std::process::Command::new(vams)
        .args([
            "sweep",
            spec.to_str().unwrap(),
            "--out",
            local.to_str().unwrap(),
        ])
        .status()
        .unwrap();
    assert!(status.success());
    let remote = tmp.path().join("remote");
    let out = cluster
        .command(vams)
        .args([
            "sweep",
            spec.to_str().unwrap(),
            "--slurm",
            "--array-size",
            "4",
            "--time",
            "5",
            "--wait",
            "--out",
            remote.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains("submitted job"), "{stderr}");
    assert!(stderr.contains("collected 4 shards, 40 runs"), "{stderr}");
    let a = fs::read(local.join("results.csv")).unwrap();
    let b = fs::read(remote.join("results.csv")).unwrap();
    assert!(a == b, "the collected table differs from the local one");
}

/// Task `k`'s log, or what went wrong reading it.
fn log(job: &ArrayJob, k: usize) -> String {
    let path = job.log_path(k);
    fs::read_to_string(&path).unwrap_or_else(|e| format!("no log {}: {e}", path.display()))
}

fn make_executable(path: &Path) {
    use std::os::unix::fs::PermissionsExt;
    fs::set_permissions(path, fs::Permissions::from_mode(0o755)).unwrap();
}
