//! vams: a compiler and simulator for a practical subset of VHDL-AMS (IEEE 1076.1).
//!
//! The pipeline, one module per stage (see ARCHITECTURE.md):
//! source -> [`lexer`] -> [`parser`] ([`ast`]) -> analysis -> elaboration -> [`solver`].

pub mod ast;
pub mod diagnostics;
pub mod lexer;
pub mod parser;
pub mod solver;
pub mod source;
