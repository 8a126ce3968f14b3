//! `vams sweep --slurm`: a sweep's shards as one Slurm job array.
//!
//! Takes an `ArrayJob` (the binary, the spec, the output directory, the number of shards);
//! gives the sbatch script (`script`), writes it (`write_script`), submits it or some of its
//! tasks (`submit`: `sbatch --parsable`) and waits for the job to leave the queue (`wait`:
//! `squeue`). Slurm places, runs and retries the tasks: nothing here schedules, and nothing
//! parses the command line (`cli::sweep` does). The client commands are found on `PATH` and
//! read the cluster's configuration from the environment (`SLURM_CONF`), which `Slurm`
//! can extend for one call (the tests' local cluster) without touching the process's own.

mod client;
mod script;
mod time;

pub use client::Slurm;
pub use script::{ArrayJob, array_list, resubmit_command, shell_quote};
pub use time::validate_time;

use std::fmt;
use std::path::{Path, PathBuf};
use std::time::Duration;

use miette::Diagnostic;
use thiserror::Error;

use crate::output::atomic::write_atomically;

/// A failure to talk to Slurm (codes `vams::slurm::*`).
#[derive(Debug, Error, Diagnostic)]
pub enum SlurmError {
    /// A client command is not on `PATH`: this is not a Slurm machine.
    #[error("`{program}` not found: Slurm's client commands are not installed here")]
    #[diagnostic(
        code(vams::slurm::missing),
        help(
            "run this on a Slurm login node, or start a one-node cluster on this machine with \
             `eval \"$(scripts/slurm-local.sh start)\"` (Debian: apt-get install slurm-wlm munge); \
             `--dry-run` prints the script without submitting it"
        )
    )]
    Missing { program: &'static str },

    /// A client command could not be run for another reason (permissions, resources).
    #[error("could not run `{program}`")]
    #[diagnostic(code(vams::slurm::spawn))]
    Spawn {
        program: &'static str,
        #[source]
        source: std::io::Error,
    },

    /// The command ran and failed; Slurm's own message says why.
    #[error("`{command}` failed ({status}): {stderr}")]
    #[diagnostic(
        code(vams::slurm::failed),
        help("Slurm's message above says why; `sinfo` shows the partitions and their state")
    )]
    Failed {
        command: String,
        status: String,
        stderr: String,
    },

    /// `sbatch --parsable` printed something other than `ID` or `ID;CLUSTER`.
    #[error("`sbatch --parsable` printed `{output}`, not a job id")]
    #[diagnostic(code(vams::slurm::unparsable))]
    Unparsable { output: String },

    /// `submit` was asked for no task at all.
    #[error("no array task to submit")]
    #[diagnostic(code(vams::slurm::no_task))]
    NoTask,

    /// The job was still queued or running when `wait` gave up.
    #[error("job {job} still in the queue after {} s", waited.as_secs())]
    #[diagnostic(
        code(vams::slurm::timeout),
        help("`squeue -j {job}` shows its tasks; `scancel {job}` cancels them")
    )]
    Timeout { job: JobId, waited: Duration },

    /// The script or its log directory could not be written.
    #[error("cannot write `{}`", path.display())]
    #[diagnostic(code(vams::slurm::write))]
    Write {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
}

/// A submitted job: its id and, on a multi-cluster setup, its cluster (`123;cluster`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct JobId {
    pub id: u64,
    pub cluster: Option<String>,
}

impl JobId {
    /// Reads `sbatch --parsable`'s output: `ID` or `ID;CLUSTER`, then a newline.
    pub fn parse(output: &str) -> Result<JobId, SlurmError> {
        let line = output.trim();
        let unparsable = || SlurmError::Unparsable {
            output: line.to_owned(),
        };
        let (id, cluster) = match line.split_once(';') {
            Some((id, cluster)) => (id, Some(cluster.trim())),
            None => (line, None),
        };
        let id = id.trim().parse().map_err(|_| unparsable())?;
        match cluster {
            Some("") => Err(unparsable()),
            Some(c) if c.contains(char::is_whitespace) => Err(unparsable()),
            c => Ok(JobId {
                id,
                cluster: c.map(str::to_owned),
            }),
        }
    }
}

impl fmt::Display for JobId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.id)
    }
}

/// Writes `job`'s script to `OUT/sweep.sbatch` (atomically) and creates `OUT/logs/`, where
/// the tasks' output goes: Slurm does not create it, and a task whose output file cannot be
/// opened fails without a word. Gives the script's path.
pub fn write_script(job: &ArrayJob) -> Result<PathBuf, SlurmError> {
    let logs = job.out.join("logs");
    std::fs::create_dir_all(&logs).map_err(|source| SlurmError::Write { path: logs, source })?;
    let path = job.out.join("sweep.sbatch");
    let text = job.script();
    write_atomically(&path, |w| std::io::Write::write_all(w, text.as_bytes())).map_err(
        |source| SlurmError::Write {
            path: path.clone(),
            source,
        },
    )?;
    Ok(path)
}

/// Submits `script` with `sbatch --parsable`, all its array tasks or (`only`) just those,
/// with the process's environment.
pub fn submit(script: &Path, only: Option<&[usize]>) -> Result<JobId, SlurmError> {
    Slurm::default().submit(script, only)
}

/// Waits until `job` has left the queue, polling `squeue`, for at most `timeout`.
pub fn wait(job: &JobId, timeout: Duration) -> Result<(), SlurmError> {
    Slurm::default().wait(job, timeout)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parsable_output() {
        assert_eq!(
            JobId::parse("123\n").unwrap(),
            JobId {
                id: 123,
                cluster: None
            }
        );
        let multi = JobId::parse("4567;gpu-cluster\n").unwrap();
        assert_eq!(multi.id, 4567);
        assert_eq!(multi.cluster.as_deref(), Some("gpu-cluster"));
        assert_eq!(multi.to_string(), "4567");
        for bad in ["", "Submitted batch job 12", "12;", "x;c", "12;a b", "-3"] {
            assert!(
                matches!(JobId::parse(bad), Err(SlurmError::Unparsable { .. })),
                "{bad}"
            );
        }
    }

    #[test]
    fn the_script_and_its_log_directory_are_written() {
        let dir = tempfile::tempdir().unwrap();
        let job = ArrayJob {
            vams: "/bin/vams".into(),
            spec: "/s.toml".into(),
            out: dir.path().join("out"),
            shards: 2,
            partition: None,
            time: None,
            job_name: "t".into(),
            extra_args: vec![],
        };
        let path = write_script(&job).unwrap();
        assert_eq!(path, dir.path().join("out/sweep.sbatch"));
        assert_eq!(std::fs::read_to_string(&path).unwrap(), job.script());
        assert!(dir.path().join("out/logs").is_dir());
    }
}
