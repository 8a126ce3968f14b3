//! The indices into the analysis's arenas: declarations, declarative regions and natures
//! (types have theirs, [`TypeId`](super::types::TypeId), beside the type table). Plain data, so
//! that the type table can name a protected type's region without depending on `scope`.

/// Index of a declaration in [`Analysis::decls`](super::super::Analysis).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct DeclId(pub u32);

/// Index of a declarative region.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct RegionId(pub u32);

/// Index of a nature.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct NatureId(pub u32);
