//! Declarations: types and subtypes, objects, aliases and attribute specifications; array and
//! record natures and their objects; protected types; resolution functions.
//!
//! Reads the scope and the analysis's resolutions; writes scope items, the design's objects
//! (signals, quantities, terminals) and the pending declarations
//! (`Elab::pending`).

pub(crate) mod arrays;
pub(crate) mod decls;
pub(crate) mod protected;
pub(crate) mod record_natures;
pub(crate) mod resolution;
