//! The syntax stage of vams: the text of a file to its AST and its lexical and syntax errors.
//!
//! [`source`] (files and spans) -> [`lexer`] (tokens) -> [`parser`] (LALRPOP, the grammar in
//! the repository's `grammar/`) -> [`ast`]; [`diagnostics`] holds the error enums every later
//! stage shares and renders them. A crate of its own so that the 3 MB generated parser is
//! compiled only when the grammar or these files change. It depends on nothing else of vams.

pub mod ast;
pub mod diagnostics;
pub mod lexer;
pub mod parser;
pub mod source;
