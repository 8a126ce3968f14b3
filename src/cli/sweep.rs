//! Design-space runs.

pub mod metric;
