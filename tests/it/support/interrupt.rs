//! Runs `vams` as a child process and stops it with SIGINT (Ctrl-C) after two seconds,
//! long enough to be simulating in a debug build: the tests of what an interrupted run
//! leaves behind.

use std::ffi::OsStr;
use std::process::ExitStatus;
use std::time::{Duration, Instant};

/// The exit status and the standard error of `vams ARGS` interrupted mid-run; fails the
/// test when it does not stop within a minute of the signal.
pub fn run_interrupted<I, S>(args: I) -> (ExitStatus, String)
where
    I: IntoIterator<Item = S>,
    S: AsRef<OsStr>,
{
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_vams"))
        .args(args)
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    std::thread::sleep(Duration::from_secs(2));
    let killed = std::process::Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(killed.success());
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        assert!(
            started.elapsed() < Duration::from_secs(60),
            "the run did not stop"
        );
        std::thread::sleep(Duration::from_millis(20));
    };
    let mut stderr = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut stderr).unwrap();
    (status, stderr)
}
