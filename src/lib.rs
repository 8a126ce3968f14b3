//! vams: a compiler and simulator for a practical subset of VHDL-AMS (IEEE 1076.1).
//!
//! The pipeline, one module per stage (see ARCHITECTURE.md):
//! source -> [`lexer`] -> [`parser`] ([`ast`]) -> analysis -> elaboration -> [`solver`];
//! beside it, [`capture`] (oscilloscope exports), [`extract`] (motor parameters from scope
//! captures) and [`output`] (plots).

// The syntax stage is its own crate (`crates/syntax`): re-exported under its old paths.
pub use vams_syntax::{ast, diagnostics, lexer, parser, source};
// So is the numerical core (`crates/solver`).
pub use vams_solver as solver;

pub mod analog;
pub mod analysis;
pub mod app;
pub mod capture;
pub mod cli;
pub mod design;
pub mod elaborate;
pub mod extract;
pub mod fit;
pub mod kernel;
pub mod lsp;
pub mod output;
pub mod pwl;
pub mod stdlib;
pub mod waveform;
