//! Ctrl-C, and SIGTERM or SIGHUP (what Slurm's `scancel` and time limits send): the first
//! asks the run to stop (it ends at its next step and keeps its waveforms, which the command
//! writes); a second ends the process at once, for a run that does not reach a step,
//! removing the temporary files the run was writing its outputs into.

use std::path::PathBuf;
use std::sync::{Mutex, OnceLock};

use crate::kernel::Cancel;

/// The flag that Ctrl-C (or SIGTERM, SIGHUP) sets, installed once per process.
pub fn cancel_on_ctrl_c() -> Cancel {
    static FLAG: OnceLock<Cancel> = OnceLock::new();
    FLAG.get_or_init(|| {
        let flag = Cancel::new();
        let handler = flag.clone();
        let installed = ctrlc::set_handler(move || {
            if handler.is_cancelled() {
                if let Ok(paths) = TEMPORARIES.lock() {
                    for path in paths.iter() {
                        let _ = std::fs::remove_file(path);
                    }
                }
                std::process::exit(130);
            }
            handler.cancel();
        });
        if let Err(e) = installed {
            // Without the handler Ctrl-C ends the process as usual; nothing else changes.
            eprintln!("note: Ctrl-C will not keep the waveforms of this run ({e})");
        }
        flag
    })
    .clone()
}

/// Temporary files to remove when a second signal ends the process.
static TEMPORARIES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Sets the temporary files a second Ctrl-C removes before exiting (empty once they are
/// renamed or removed).
pub fn remove_on_exit(paths: Vec<PathBuf>) {
    if let Ok(mut held) = TEMPORARIES.lock() {
        *held = paths;
    }
}
