//! Analysis and elaboration: parsed design files -> one flat [`Design`].
//!
//! **Takes** the parsed files of a compilation (user files in library `work`, the bundled
//! stdlib in `std` and `ieee`, as recorded in the [`SourceMap`]) and the name of the top
//! entity with generic overrides. **Gives** a [`Design`] or every error found, each an
//! [`ElabError`] with the span it is about and a help line.
//!
//! May use `ast`, `source`, `design`, `diagnostics`. Never touches the solver or the kernel.

use crate::ast::DesignFile;
use crate::design::Design;
use crate::source::{FileId, SourceMap};

mod error;

pub use error::ElabError;

/// What to elaborate.
#[derive(Clone, Debug, Default)]
pub struct ElabOptions {
    /// The top entity (lower case); its architecture is the last one analysed for it.
    pub top: String,
    /// Top-level generic overrides `(name, value text)`, from `-g NAME=VALUE` and `--params`;
    /// the text is a VHDL literal (`4.0`, `1e-3`, `12`, `true`, `10 ms`).
    pub generics: Vec<(String, String)>,
}

/// Elaborates `options.top` from `files`.
pub fn elaborate(
    sources: &SourceMap,
    files: &[(FileId, DesignFile)],
    options: &ElabOptions,
) -> Result<Design, Vec<ElabError>> {
    let _ = (sources, files, options);
    todo!("elaboration")
}

/// Entities of library `work` that no architecture instantiates: the candidates for `--top`.
pub fn find_tops(sources: &SourceMap, files: &[(FileId, DesignFile)]) -> Vec<String> {
    let _ = (sources, files);
    todo!("find_tops")
}
