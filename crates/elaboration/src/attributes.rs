//! Attributes: predefined and AMS attributes, and what elaboration synthesises behind the
//! AMS ones (`'delayed`, `'ramp`/`'slew` on signals, `'ltf`, `'zoh`, `'slew` on quantities):
//! auxiliary quantities, equations and processes.
//!
//! Reads the scope and where the walk is (`Elab::here`); writes auxiliary quantities
//! (`Elab::analog`), implicit signals (`Elab::signals`) and the design objects they need.

pub(crate) mod attr;
pub(crate) mod delay;
pub(crate) mod follow;
pub(crate) mod ltf;
pub(crate) mod sampled;
pub(crate) mod slew;
pub(crate) mod synth;
