//! Design units and their contexts: the library index (which unit is which, by library and
//! name), the packages elaborated on first `use` with the use regions of context clauses, the
//! candidates for `--top`, and the top's generic overrides read as literals.
//!
//! Reads the parsed files and the analysis's unit table; writes the package cache
//! (`Elab::packages`) and the scopes every other sub-stage starts from.

pub(crate) mod candidates;
pub(crate) mod generics;
pub(crate) mod library;
pub(crate) mod packages;
