//! The client commands, `sbatch` and `squeue`, run with the process's environment plus
//! variables of the caller's (`Slurm::with_env`: the tests' local cluster), their failures
//! turned into `SlurmError`s that keep Slurm's own message.

use std::ffi::OsString;
use std::path::Path;
use std::process::{Command, Output};
use std::time::{Duration, Instant};

use super::{JobId, SlurmError, array_list, shell_quote};

/// The client commands with variables added to the process's environment (`SLURM_CONF` of
/// a local cluster, in the tests): setting them on the process itself would need `unsafe`
/// `std::env::set_var`. `Slurm::default()` adds none.
#[derive(Clone, Debug, Default)]
pub struct Slurm {
    env: Vec<(OsString, OsString)>,
}

impl Slurm {
    /// A client whose commands also see `env`.
    pub fn with_env<K: Into<OsString>, V: Into<OsString>>(
        env: impl IntoIterator<Item = (K, V)>,
    ) -> Slurm {
        Slurm {
            env: env.into_iter().map(|(k, v)| (k.into(), v.into())).collect(),
        }
    }

    /// See [`super::submit`].
    pub fn submit(&self, script: &Path, only: Option<&[usize]>) -> Result<JobId, SlurmError> {
        let mut args: Vec<OsString> = vec!["--parsable".into()];
        if let Some(only) = only {
            if only.is_empty() {
                return Err(SlurmError::NoTask);
            }
            args.push(format!("--array={}", array_list(only)).into());
        }
        args.push(script.into());
        let output = self.run("sbatch", &args)?;
        if !output.status.success() {
            return Err(failed("sbatch", &args, &output));
        }
        JobId::parse(&String::from_utf8_lossy(&output.stdout))
    }

    /// See [`super::wait`]. Accounting (`sacct`) is not needed nor used: a job has left the
    /// queue when `squeue -j` lists none of its tasks in a state before the end, or no longer
    /// knows the id (after `MinJobAge`).
    pub fn wait(&self, job: &JobId, timeout: Duration) -> Result<(), SlurmError> {
        let start = Instant::now();
        let mut args: Vec<OsString> = vec![];
        if let Some(cluster) = &job.cluster {
            args.push(format!("--clusters={cluster}").into());
        }
        args.extend(["-h", "-o", "%T", "-j"].map(OsString::from));
        args.push(job.id.to_string().into());
        // Short polls first (a small array is done within seconds), then every 2 s.
        let mut pause = Duration::from_millis(200);
        // A controller that is busy or restarting fails a query now and then: a `--wait` of
        // hours should not end on one, but a query that keeps failing is an error.
        let mut failures = 0;
        loop {
            let output = self.run("squeue", &args)?;
            let text = String::from_utf8_lossy(&output.stdout);
            let unknown = String::from_utf8_lossy(&output.stderr).contains("Invalid job id");
            if output.status.success() || unknown {
                failures = 0;
                if unknown || text.lines().all(|state| finished(state.trim())) {
                    return Ok(());
                }
            } else {
                failures += 1;
                if failures == 3 {
                    return Err(failed("squeue", &args, &output));
                }
            }
            let waited = start.elapsed();
            if waited >= timeout {
                return Err(SlurmError::Timeout {
                    job: job.clone(),
                    waited,
                });
            }
            std::thread::sleep(pause.min(timeout - waited));
            pause = (pause * 2).min(Duration::from_secs(2));
        }
    }

    fn run(&self, program: &'static str, args: &[OsString]) -> Result<Output, SlurmError> {
        let mut tries = 0;
        loop {
            let output = Command::new(program)
                .args(args)
                .envs(self.env.iter().map(|(k, v)| (k, v)))
                .output();
            match output {
                Ok(output) => return Ok(output),
                Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                    return Err(SlurmError::Missing { program });
                }
                // A wrapper script just written (the unit tests' fakes) is "busy" while
                // another thread's fork still holds it open, for an instant: try again.
                Err(e) if e.kind() == std::io::ErrorKind::ExecutableFileBusy && tries < 10 => {
                    tries += 1;
                    std::thread::sleep(Duration::from_millis(20));
                }
                Err(source) => return Err(SlurmError::Spawn { program, source }),
            }
        }
    }
}

/// A state `squeue -o %T` prints once a job or task is over (a clusters header line, on a
/// multi-cluster query, counts as one too: it is no task).
fn finished(state: &str) -> bool {
    const ACTIVE: [&str; 13] = [
        "PENDING",
        "RUNNING",
        "SUSPENDED",
        "COMPLETING",
        "CONFIGURING",
        "REQUEUED",
        "REQUEUE_FED",
        "REQUEUE_HOLD",
        "RESIZING",
        "SIGNALING",
        "STAGE_OUT",
        "STOPPED",
        "RESV_DEL_HOLD",
    ];
    !ACTIVE.contains(&state)
}

/// The error of a client command that ran and failed, with its standard error.
fn failed(program: &str, args: &[OsString], output: &Output) -> SlurmError {
    let words: Vec<String> = args
        .iter()
        .map(|a| shell_quote(&a.to_string_lossy()).into_owned())
        .collect();
    SlurmError::Failed {
        command: format!("{program} {}", words.join(" ")),
        status: output.status.to_string(),
        stderr: String::from_utf8_lossy(&output.stderr).trim().to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn states_before_and_after_the_end() {
        assert!(!finished("PENDING"));
        assert!(!finished("COMPLETING"));
        assert!(finished("COMPLETED"));
        assert!(finished("FAILED"));
        assert!(finished("CANCELLED"));
    }

    #[test]
    fn an_empty_task_list_is_refused_before_sbatch_runs() {
        let err = Slurm::default()
            .submit(Path::new("/nonexistent/sweep.sbatch"), Some(&[]))
            .unwrap_err();
        assert!(matches!(err, SlurmError::NoTask));
    }

    #[test]
    fn a_missing_client_says_how_to_get_one() {
        // An empty PATH: no sbatch can be found whatever is installed.
        let err = Slurm::with_env([("PATH", "")])
            .submit(Path::new("/nonexistent/sweep.sbatch"), None)
            .unwrap_err();
        assert!(
            matches!(err, SlurmError::Missing { program: "sbatch" }),
            "{err:?}"
        );
    }

    /// A client whose only commands are the sh scripts `commands` (name, body), in `dir`.
    #[cfg(unix)]
    fn fake(dir: &Path, commands: &[(&str, &str)]) -> Slurm {
        use std::os::unix::fs::PermissionsExt;
        for (name, body) in commands {
            let path = dir.join(name);
            std::fs::write(&path, format!("#!/bin/sh\n{body}\n")).unwrap();
            std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o755)).unwrap();
        }
        Slurm::with_env([("PATH", dir)])
    }

    #[cfg(unix)]
    #[test]
    fn submit_passes_the_array_list_and_reads_the_id() {
        let dir = tempfile::tempdir().unwrap();
        let slurm = fake(
            dir.path(),
            &[("sbatch", r#"echo "$@" > "${0%/*}/args"; echo '42;hpc'"#)],
        );
        let script = Path::new("/o/sweep.sbatch");
        let id = slurm.submit(script, Some(&[7, 3, 4])).unwrap();
        assert_eq!(id.id, 42);
        assert_eq!(id.cluster.as_deref(), Some("hpc"));
        let args = std::fs::read_to_string(dir.path().join("args")).unwrap();
        assert_eq!(args, "--parsable --array=3-4,7 /o/sweep.sbatch\n");
        slurm.submit(script, None).unwrap();
        let args = std::fs::read_to_string(dir.path().join("args")).unwrap();
        assert_eq!(args, "--parsable /o/sweep.sbatch\n");
    }

    #[cfg(unix)]
    #[test]
    fn sbatch_refusing_keeps_its_message() {
        let dir = tempfile::tempdir().unwrap();
        let slurm = fake(
            dir.path(),
            &[(
                "sbatch",
                "echo 'sbatch: error: invalid partition specified: gpu' >&2; exit 1",
            )],
        );
        let err = slurm.submit(Path::new("/o/s.sbatch"), None).unwrap_err();
        let SlurmError::Failed {
            command, stderr, ..
        } = err
        else {
            panic!("{err:?}");
        };
        assert_eq!(command, "sbatch --parsable /o/s.sbatch");
        assert_eq!(stderr, "sbatch: error: invalid partition specified: gpu");
    }

    /// A fake squeue that prints, at its Nth call, line N of `answers` (`fail` for a failed
    /// query, `gone` for an id the controller has forgotten, `,` between task states).
    #[cfg(unix)]
    fn squeue(answers: &[&str]) -> String {
        let mut body = String::from(
            "d=${0%/*}; n=0; [ -f \"$d/n\" ] && read n < \"$d/n\"; echo $((n + 1)) > \"$d/n\"\n\
             case $n in\n",
        );
        for (i, answer) in answers.iter().enumerate() {
            let action = match *answer {
                "fail" => "echo 'squeue: error: Socket timed out' >&2; exit 1".to_owned(),
                "gone" => {
                    "echo 'slurm_load_jobs error: Invalid job id specified' >&2; exit 1".to_owned()
                }
                states => states
                    .split(',')
                    .filter(|s| !s.is_empty())
                    .map(|s| format!("echo {s}; "))
                    .collect(),
            };
            body.push_str(&format!("{i}) {action} ;;\n"));
        }
        body.push_str("*) exit 9 ;;\nesac");
        body
    }

    #[cfg(unix)]
    #[test]
    fn wait_polls_until_no_task_is_before_its_end() {
        let job = JobId {
            id: 5,
            cluster: None,
        };
        let long = Duration::from_secs(30);
        for answers in [
            &["PENDING,PENDING", "RUNNING,COMPLETED", "COMPLETED,FAILED"][..],
            &["RUNNING", "fail", "fail", "RUNNING", ""],
            &["COMPLETING", "gone"],
        ] {
            let dir = tempfile::tempdir().unwrap();
            let slurm = fake(dir.path(), &[("squeue", &squeue(answers))]);
            slurm.wait(&job, long).unwrap();
            let calls = std::fs::read_to_string(dir.path().join("n")).unwrap();
            assert_eq!(calls.trim(), answers.len().to_string(), "{answers:?}");
        }
        let dir = tempfile::tempdir().unwrap();
        let slurm = fake(
            dir.path(),
            &[("squeue", &squeue(&["fail", "fail", "fail"]))],
        );
        let err = slurm.wait(&job, long).unwrap_err();
        assert!(
            matches!(&err, SlurmError::Failed { stderr, .. } if stderr.contains("timed out")),
            "{err:?}"
        );
        let dir = tempfile::tempdir().unwrap();
        let slurm = fake(dir.path(), &[("squeue", "echo RUNNING")]);
        let err = slurm.wait(&job, Duration::from_millis(300)).unwrap_err();
        assert!(matches!(err, SlurmError::Timeout { .. }), "{err:?}");
    }
}
