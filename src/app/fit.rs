//! `vams fit`: estimate generics of the user's own testbench from measured waveforms.
//!
//! Each `--measured FILE[:KEY=VALUE,...]` is one experiment: a capture, the testbench that
//! reproduces it (`top=`, else `--top`) and the generics that select the experiment. The
//! free generics (`--free NAME=GUESS[:MIN:MAX]`) are fitted jointly to every matched column
//! (`--match QUANTITY=COLUMN`) of every capture by [`crate::fit`]. Everything the fit needs
//! is checked before the first simulation: the captures, the columns, the generics' names and
//! the quantities, each with its own diagnostic.

pub mod error;
pub mod experiment;
pub mod motor;
pub mod plot;
pub mod problem;
pub mod report;
pub mod simulate;

pub use error::FitCliError;
