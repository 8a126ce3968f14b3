//! The simulation stage of vams: the analog system an elaborated design's equations make
//! ([`analog`]), the VHDL event kernel that runs its processes and drives the solver through
//! time ([`kernel`]), and the waveforms a run records ([`waveform`]). Reads only the design
//! crate's plain data (and the solver); never the AST or the elaborator.

pub mod analog;
pub mod kernel;
pub mod waveform;
