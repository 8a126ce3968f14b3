//! The analog side: natures, terminals, free and branch quantities, and the simultaneous
//! statements lowered to equations.
//!
//! Reads the scope; writes the design's natures, terminals, quantities and equations and the
//! analog tables (`Elab::analog`).

pub(crate) mod analog;
pub(crate) mod simultaneous;
