//! The analysis stage of vams: the design units of parsed files with their names, types and
//! natures resolved ([`analysis`]), and the standard packages the binary carries ([`stdlib`]).
//! Reads the syntax crate's AST; nothing here elaborates or simulates.

pub mod analysis;
pub mod stdlib;
