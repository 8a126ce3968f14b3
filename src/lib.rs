//! vams: a compiler and simulator for a practical subset of VHDL-AMS (IEEE 1076.1).
//!
//! The pipeline, one module per stage (see ARCHITECTURE.md):
//! source -> [`lexer`] -> [`parser`] ([`ast`]) -> analysis -> elaboration -> [`solver`];
//! beside it, [`capture`] (oscilloscope exports), [`extract`] (motor parameters from scope
//! captures) and [`output`] (plots).

pub mod analog;
pub mod analysis;
pub mod ast;
pub mod capture;
pub mod cli;
pub mod design;
pub mod diagnostics;
pub mod elaborate;
pub mod extract;
pub mod fit;
pub mod kernel;
pub mod lexer;
pub mod lsp;
pub mod output;
pub mod parser;
pub mod pwl;
pub mod solver;
pub mod source;
pub mod stdlib;
pub mod waveform;
