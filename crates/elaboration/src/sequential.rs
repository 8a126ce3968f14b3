//! Sequential code: processes lowered to the kernel's instructions, user functions and
//! procedures (declarations and bodies, calls and their specialisation), access and file
//! types with their operations, implicit sensitivity, and assignments to slices with run-time
//! bounds.
//!
//! Reads the scope, the declarations' helpers and the signals' tables; writes the design's
//! processes and subprograms, the implicit signals they read (`Elab::signals`) and the
//! subprogram bodies to release (`Elab::pending`).

pub(crate) mod io;
pub(crate) mod process;
pub(crate) mod sensitivity;
pub(crate) mod signal_slices;
pub(crate) mod subprogram;
