//! Ctrl-C (KeyboardInterrupt) during a run: the run holds no GIL, so a progress hook asks
//! Python for pending signals every 50 ms of wall time and cancels the run when there is one.

use pyo3::prelude::*;
use vams::kernel::{Cancel, ProgressHook};

/// The cancel flag of a run and the hook that sets it on a pending KeyboardInterrupt.
pub fn on_keyboard_interrupt() -> (Cancel, ProgressHook) {
    let cancel = Cancel::new();
    let flag = cancel.clone();
    let hook = ProgressHook::new(move |_time| {
        // The signal's exception is dropped here; the caller raises KeyboardInterrupt when
        // the run ends interrupted.
        if Python::attach(|py| py.check_signals()).is_err() {
            flag.cancel();
        }
    });
    (cancel, hook)
}
