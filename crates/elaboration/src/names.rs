//! What names denote: the scope of regions and items, the elaborator's semantic types, and the
//! composite analog objects (array and record natures, expanded arrays) that items name.
//!
//! Plain data shared by every sub-stage; reads and writes nothing of `Elab` itself.

pub(crate) mod composite;
pub(crate) mod scope;
pub(crate) mod types;
