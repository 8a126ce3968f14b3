//! What several topics of the integration tests share: references (ngspice, a Slurm cluster,
//! an LSP client), generators (random circuits, lab motor captures) and the fixed seeds of the
//! property tests. `examples/` and `benches/` include some of these files by `#[path]`.

pub mod circuit;
pub mod fixed_seed;
#[cfg(unix)]
pub mod interrupt;
pub mod lab_motor;
pub mod lsp_client;
pub mod ngspice;
#[cfg(unix)]
pub mod slurm;
