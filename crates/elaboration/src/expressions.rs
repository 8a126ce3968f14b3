//! Expressions: AST expressions to typed design expressions, constant folding, inlining of
//! user functions into equations, the intrinsic functions, views of elements and slices,
//! and array lengths where values meet constrained objects.
//!
//! Reads the scope, the analysis's resolutions and the package cache; writes signal views
//! (`Elab::signals`) and nothing else of the design but what it lowers.

pub(crate) mod expr;
pub(crate) mod fold;
pub(crate) mod inline;
pub(crate) mod intrinsic;
pub(crate) mod lengths;
pub(crate) mod views;
