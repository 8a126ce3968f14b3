//! Design-space runs.

pub mod slurm;
