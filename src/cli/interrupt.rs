//! Ctrl-C, and SIGTERM or SIGHUP (what Slurm's `scancel` and time limits send): the first
//! asks the run to stop (it ends at its next step and keeps its waveforms, which the command
//! writes); a second ends the process at once, for a run that does not reach a step.

use std::sync::OnceLock;

use crate::kernel::Cancel;

/// The flag that Ctrl-C (or SIGTERM, SIGHUP) sets, installed once per process.
pub fn cancel_on_ctrl_c() -> Cancel {
    static FLAG: OnceLock<Cancel> = OnceLock::new();
    FLAG.get_or_init(|| {
        let flag = Cancel::new();
        let handler = flag.clone();
        let installed = ctrlc::set_handler(move || {
            if handler.is_cancelled() {
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
