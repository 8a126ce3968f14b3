//! Cancellation: a flag the caller sets (on Ctrl-C) and the run reads between time points and
//! integration steps, so that a run stopped by the user ends as an error at a consistent
//! point and keeps the waveforms computed so far.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// Shared between the caller, which cancels, and the run, which checks.
#[derive(Clone, Debug, Default)]
pub struct Cancel(Arc<AtomicBool>);

impl Cancel {
    pub fn new() -> Cancel {
        Cancel::default()
    }

    /// Asks the run to stop at its next time point or step.
    pub fn cancel(&self) {
        self.0.store(true, Ordering::Relaxed);
    }

    pub fn is_cancelled(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }
}
