//! The hierarchy: the top entity and each instance with its generic and port maps, blocks and
//! generate statements, and the conversions in port maps.
//!
//! Reads the library and the configuration; writes where the walk is (`Elab::here`), port
//! defaults and converted actuals (`Elab::signals`), and calls every other sub-stage on the
//! declarations and statements of each instance.

pub(crate) mod hier;
pub(crate) mod port_conversions;
pub(crate) mod ports;
