//! The bundled standard packages (`stdlib/`): `std.standard`, `std.textio`, `std.env`,
//! `ieee.std_logic_1164`, `ieee.math_real` and the IEEE 1076.1.1 discipline packages, compiled
//! into the binary by `build.rs` so that `vams` needs no installation directory.

include!(concat!(env!("OUT_DIR"), "/stdlib_files.rs"));

use crate::source::{FileId, SourceMap};

/// Registers every bundled file in `sources` under its library; returns their ids.
pub fn load(sources: &mut SourceMap) -> Vec<FileId> {
    FILES
        .iter()
        .map(|(lib, path, text)| sources.add(*path, lib, (*text).to_string()))
        .collect()
}
