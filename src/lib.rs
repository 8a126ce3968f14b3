//! vams: a compiler and simulator for a practical subset of VHDL-AMS (IEEE 1076.1).
//!
//! The pipeline is a crate per stage (see ARCHITECTURE.md), re-exported here under the paths
//! users and the front ends know: source -> [`lexer`] -> [`parser`] ([`ast`]) -> [`analysis`]
//! -> [`elaborate`] ([`design`]) -> [`analog`] and [`kernel`] over the [`solver`]; beside it,
//! [`capture`] (oscilloscope exports), [`extract`] (motor parameters from scope captures),
//! [`fit`] and [`output`] (waveforms and plots). This crate adds the application layer
//! ([`app`]) and its front ends: the command line ([`cli`]) and the language server ([`lsp`]).

pub use vams_design as design;
pub use vams_design::pwl;
pub use vams_elaboration as elaborate;
pub use vams_semantics::{analysis, stdlib};
pub use vams_simulation::{analog, kernel, waveform};
pub use vams_solver as solver;
pub use vams_syntax::{ast, diagnostics, lexer, parser, source};
pub use vams_tools::{capture, extract, fit, output};

pub mod app;
pub mod cli;
pub mod lsp;
