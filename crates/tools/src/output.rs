//! Output of results: waveform files (CSV, VCD), plots of waveforms, and the atomic file
//! writes they share; `stream` writes them as a run goes (a [`vams_simulation::waveform::WaveformSink`]),
//! `decimate` keeps a long run's plot in bounded memory.
//!
//! Reads results handed to it as plain data ([`vams_simulation::waveform::Waveforms`], rows, plot
//! panels); never reaches into the solver, the kernel or the extractor.

pub mod atomic;
pub mod bode;
pub mod csv;
pub mod decimate;
pub mod levels;
pub mod noise_plot;
pub mod plot;
pub mod stream;
pub mod sweep_plot;
pub mod vcd;
pub mod waveplot;
