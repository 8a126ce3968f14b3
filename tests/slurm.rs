//! The Slurm path end to end on a real one-node cluster (`support/slurm.rs`): the job-array
//! script `sweep::slurm` writes, submitted with its `submit`, awaited with its `wait`, runs
//! every shard, and a resubmission of some tasks runs only those. A stand-in for `vams`
//! (a small sh script) writes each shard's file, so this checks the Slurm contract alone;
//! awkward paths (spaces, quotes, `%`) check the script's quoting where sbatch and the shell
//! really read it.

#![cfg(unix)]

#[path = "support/slurm.rs"]
mod slurm_support;

use std::fs;
use std::path::Path;
use std::time::{Duration, Instant};

use slurm_support::LocalSlurm;
use vams::cli::sweep::slurm::{ArrayJob, write_script};

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

/// Task `k`'s log, or what went wrong reading it.
fn log(job: &ArrayJob, k: usize) -> String {
    let path = job.log_path(k);
    fs::read_to_string(&path).unwrap_or_else(|e| format!("no log {}: {e}", path.display()))
}

fn make_executable(path: &Path) {
    use std::os::unix::fs::PermissionsExt;
    fs::set_permissions(path, fs::Permissions::from_mode(0o755)).unwrap();
}
