//! vams: a compiler and simulator for a practical subset of VHDL-AMS (IEEE 1076.1).

pub mod cli;
pub mod extract;
pub mod output;
