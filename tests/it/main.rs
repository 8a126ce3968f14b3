//! The integration tests: one binary, a module per topic (rust-analyzer's layout), so that
//! `cargo test` links the crate once instead of once per topic. Each module runs real `.vhd`
//! files (its data in `tests/<topic>/`) through the library or the `vams` binary
//! (`CARGO_BIN_EXE_vams`); `support` holds what several of them share.
//!
//! One topic: `cargo test --test it fit::` (a module path is a name filter).

mod ac;
mod analog_closed_form;
mod analysis;
mod analysis_incremental;
mod check;
mod dc;
mod differential;
mod elaborate;
mod elimination;
mod extract;
mod extract_lab;
mod fit;
mod fit_servo;
mod ghdl_differential;
mod hbridge_pwm;
mod headlight;
mod ladder;
mod lsp;
mod lsp_edits;
mod mutation;
mod ngspice_agreement;
mod noise;
mod poles;
mod run;
mod simulate;
#[cfg(unix)]
mod slurm;
mod spice;
mod stream;
mod support;
mod sweep;
mod test_cmd;
