//! Output of results: plots of waveforms (and, later, CSV and VCD writers).
//!
//! Reads results handed to it as plain data; never reaches into the solver or the extractor.

pub mod plot;
