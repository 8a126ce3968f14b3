//! The SPICE frontend of vams: ngspice/SPICE3 decks read into plain, checked data.
//!
//! Takes a deck's text (registered in a [`SourceMap`]) and a [`Loader`] for the files it
//! includes; gives a [`Deck`] (the deck as written: nested subcircuits, values as
//! expressions) with every diagnostic, then, from a deck, a flat [`Circuit`] (interned nodes,
//! elements with hierarchical names and numeric values, resolved models, analyses, options,
//! outputs), and from a circuit the simulator's elaborated [`vams_design::Design`] (`lower`:
//! the device equations, as elaborating the same circuit in VHDL-AMS would give them). No
//! simulation here.
//!
//! ```text
//! text ──lines──▶ logical lines ──reader──▶ Deck ──flatten──▶ Circuit ──lower──▶ Design
//!       (lexer,    (tokens with spans)      (expr, eval)
//!        number)
//! ```
//!
//! Modules: `number` (SPICE numbers and scale factors), `lexer` (logos tokens), `lines`
//! (title, continuations, comments, `.end`, `.control`), `expr` (expression AST and parser),
//! `eval` (evaluation against a scope chain), `deck` (the deck as data), `reader` (lines to a
//! deck, includes and libraries), `loader` (where included files come from), `circuit` (the
//! flat circuit as data), `flatten` (subcircuit expansion and resolution), `lower` (a circuit
//! to a design: terminals, branch quantities, equations; `.tran` and output names), `error`
//! (`SpiceError`, codes `vams::spice::*`), `suggest` ("did you mean").

pub mod circuit;
pub mod deck;
pub mod error;
pub mod eval;
pub mod expr;
mod flatten;
mod lexer;
mod lines;
pub mod loader;
pub mod lower;
pub mod number;
mod reader;
mod suggest;
#[cfg(test)]
mod test_support;

pub use circuit::Circuit;
pub use deck::Deck;
pub use error::SpiceError;
pub use flatten::flatten;
pub use loader::{FsLoader, Loader, MemLoader};
pub use lower::{TranSpec, lower, outputs, transient};
pub use reader::read_deck;

#[doc(no_inline)]
pub use vams_syntax::source::{FileId, SourceMap, Span};
