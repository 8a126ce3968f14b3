//! Output of results: waveform files (CSV, VCD), plots of waveforms, and the atomic file
//! writes they share.
//!
//! Reads results handed to it as plain data ([`crate::waveform::Waveforms`], plot panels);
//! never reaches into the solver, the kernel or the extractor.

pub mod atomic;
pub mod csv;
pub mod levels;
pub mod plot;
pub mod vcd;
pub mod waveplot;
