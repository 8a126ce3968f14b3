//! The tools around the simulator: oscilloscope exports read as captures ([`capture`]), DC
//! motor parameters extracted from them ([`extract`]), least-squares fitting with uncertainty
//! ([`fit`]), and the writers of what a run computed: CSV, VCD and plots ([`output`]).

pub mod capture;
pub mod extract;
pub mod fit;
pub mod output;
