//! A one-node Slurm cluster for the tests that submit real job arrays: `LocalSlurm::start`
//! runs `scripts/slurm-local.sh start` (which installs slurm-wlm and munge when missing) in a
//! state directory of its own, on two free ports, and stops the cluster when dropped.
//!
//! The cluster's variables (`SLURM_CONF`) are not set on the test process (that needs
//! `unsafe` `std::env::set_var`, and `unsafe_code` is forbidden): give them to each child,
//! through `LocalSlurm::client` for `vams::app::study::slurm`'s `submit` and `wait`, or
//! `LocalSlurm::env` / `LocalSlurm::command` for a `vams sweep --slurm` or any client command.
//!
//! One cluster at a time in a test binary: `start` holds a lock until the guard is dropped,
//! so tests that use it run one after the other (separate binaries never run at once under
//! `cargo test`; separate state directories and ports keep them apart otherwise).

use std::net::TcpListener;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::{Mutex, MutexGuard};

use vams::app::study::slurm::Slurm;

/// The script's exit code when Slurm is missing and cannot be installed here.
const CANNOT_INSTALL: i32 = 3;

static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

/// A running local cluster; stopped on drop.
pub struct LocalSlurm {
    env: Vec<(String, String)>,
    dir: tempfile::TempDir,
    _turn: MutexGuard<'static, ()>,
}

impl LocalSlurm {
    /// Starts the cluster, or gives the reason it cannot run here, for the test to print as
    /// `skipping: ...` (the rule: the Slurm test runs where the cluster can start,
    /// and says why it is skipped where it cannot). With `VAMS_REQUIRE_SLURM` set, only a
    /// machine where Slurm cannot be installed is a skip: a cluster that was installed and
    /// does not start fails the test, so that a broken start cannot pass as a skip there.
    pub fn start() -> Result<LocalSlurm, String> {
        // A test that panicked while holding the lock left nothing behind: its guard's drop
        // stopped its cluster.
        let turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
        if !cfg!(target_os = "linux") {
            return Err("the local Slurm cluster runs on Linux only".into());
        }
        let dir = tempfile::Builder::new()
            .prefix("vams-slurm-")
            .tempdir()
            .map_err(|e| format!("no state directory: {e}"))?;
        let (ctld, slurmd) = free_ports().map_err(|e| format!("no free port: {e}"))?;
        let out = Command::new("sh")
            .arg(script())
            .arg("start")
            .env("VAMS_SLURM_DIR", dir.path())
            .env("VAMS_SLURM_CTLD_PORT", ctld.to_string())
            .env("VAMS_SLURM_SLURMD_PORT", slurmd.to_string())
            .output()
            .map_err(|e| format!("cannot run {}: {e}", script().display()))?;
        let stderr = String::from_utf8_lossy(&out.stderr).trim().to_owned();
        if !out.status.success() {
            let reason = format!("the local Slurm cluster did not start: {stderr}");
            if std::env::var_os("VAMS_REQUIRE_SLURM").is_some()
                && out.status.code() != Some(CANNOT_INSTALL)
            {
                panic!("{reason}");
            }
            return Err(reason);
        }
        let env = exports(&String::from_utf8_lossy(&out.stdout));
        if !env.iter().any(|(k, _)| k == "SLURM_CONF") {
            stop(dir.path());
            panic!("slurm-local.sh start printed no SLURM_CONF: {stderr}");
        }
        Ok(LocalSlurm {
            env,
            dir,
            _turn: turn,
        })
    }

    /// The variables the client commands need (`SLURM_CONF`, `VAMS_SLURM_DIR`).
    #[allow(dead_code)] // for the tests that run `vams sweep --slurm`
    pub fn env(&self) -> &[(String, String)] {
        &self.env
    }

    /// `sweep::slurm`'s client with those variables.
    pub fn client(&self) -> Slurm {
        Slurm::with_env(self.env.iter().cloned())
    }

    /// `program` with those variables, e.g. `sinfo` or the `vams` binary.
    #[allow(dead_code)] // for the tests that drive a command
    pub fn command(&self, program: impl AsRef<std::ffi::OsStr>) -> Command {
        let mut command = Command::new(program);
        command.envs(self.env.iter().map(|(k, v)| (k, v)));
        command
    }

    /// The cluster's state directory (its logs are in `log/`).
    #[allow(dead_code)] // for diagnosing a failed test
    pub fn dir(&self) -> &Path {
        self.dir.path()
    }
}

impl Drop for LocalSlurm {
    fn drop(&mut self) {
        stop(self.dir.path());
    }
}

fn script() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scripts/slurm-local.sh")
}

/// Stops the cluster of state directory `dir` (its jobs, daemons and job step daemons).
fn stop(dir: &Path) {
    let stopped = Command::new("sh")
        .arg(script())
        .arg("stop")
        .env("VAMS_SLURM_DIR", dir)
        .output();
    match stopped {
        Ok(out) if !out.status.success() => eprintln!(
            "slurm-local.sh stop: {}",
            String::from_utf8_lossy(&out.stderr)
        ),
        Ok(_) => {}
        Err(e) => eprintln!("cannot run slurm-local.sh stop: {e}"),
    }
}

/// Two ports nothing listens on now, for slurmctld and slurmd (the defaults 6817 and 6818
/// may belong to a system Slurm).
fn free_ports() -> std::io::Result<(u16, u16)> {
    let a = TcpListener::bind("0.0.0.0:0")?;
    let b = TcpListener::bind("0.0.0.0:0")?;
    Ok((a.local_addr()?.port(), b.local_addr()?.port()))
}

/// The `export NAME='VALUE'` lines `slurm-local.sh start` prints, each value in single
/// quotes with a quote inside written `'\''`.
fn exports(text: &str) -> Vec<(String, String)> {
    text.lines()
        .filter_map(|line| line.strip_prefix("export "))
        .filter_map(|assignment| assignment.split_once('='))
        .map(|(name, value)| {
            let inner = value.strip_prefix('\'').and_then(|v| v.strip_suffix('\''));
            let value = inner.map_or(value.to_owned(), |v| v.replace("'\\''", "'"));
            (name.to_owned(), value)
        })
        .collect()
}
