//! The application layer: what each command does, as functions over plain option structs.
//!
//! Loads sources, analyses and elaborates them, and runs the analyses, studies and fits the
//! commands name; returns values and their findings (diagnostics as values) and takes
//! progress and cancellation as parameters. It never parses a command line: the CLI (`cli`),
//! the Python package and the language server call it. May use every stage below it
//! (syntax, analysis, elaborate, analog, kernel, output, capture, fit, extract); nothing
//! below it uses it.

pub mod ac;
pub mod ac_assert;
pub mod check;
pub mod compile;
pub mod dc;
pub mod error;
pub mod extract;
pub mod fit;
pub mod load;
pub mod netlist;
pub mod noise;
pub mod notes;
pub mod op;
pub mod parallel;
pub mod params;
pub mod poles;
pub mod render;
pub mod run;
pub mod stop;
pub mod study;
pub mod testbench;
pub mod time;
