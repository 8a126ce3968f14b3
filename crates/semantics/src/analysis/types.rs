//! The types of analysis: one entry per base type (a subtype denotes its base type here;
//! constraints are elaboration's business), with the pseudo-types of literals whose type the
//! context decides.

/// Index of a base type in the [`TypeTable`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct TypeId(pub u32);

/// A type analysis could not determine (an unsupported construct, a name that failed): it
/// matches everything, so one gap never produces a cascade of diagnostics.
pub const UNKNOWN: TypeId = TypeId(0);
pub const UNIVERSAL_INTEGER: TypeId = TypeId(1);
pub const UNIVERSAL_REAL: TypeId = TypeId(2);
/// A string or bit-string literal: any one-dimensional array of a character type.
pub const STRING_LITERAL: TypeId = TypeId(3);
/// An aggregate: any array or record type.
pub const AGGREGATE: TypeId = TypeId(4);
/// `null`: any access type.
pub const NULL: TypeId = TypeId(5);

#[derive(Clone, Debug, PartialEq)]
pub enum TypeKind {
    Unknown,
    UniversalInteger,
    UniversalReal,
    StringLiteral,
    Aggregate,
    Null,
    /// `type t;` not completed yet.
    Incomplete,
    Integer,
    Real,
    Physical,
    /// `chars`: some literal is a character literal (`'0'`), so string literals can be
    /// arrays of it.
    Enum {
        chars: bool,
    },
    Array {
        indexes: Vec<TypeId>,
        element: TypeId,
    },
    Record {
        fields: Vec<(String, TypeId)>,
    },
    Access(TypeId),
    File(TypeId),
    /// A protected type: its methods are declared in the region.
    Protected(super::ids::RegionId),
}

#[derive(Clone, Debug, PartialEq)]
pub struct TypeInfo {
    /// The declared name (`real`, `std_ulogic_vector`), or the pseudo-type's description.
    pub name: String,
    pub kind: TypeKind,
}

/// Every type of an analysis.
#[derive(Clone, Debug)]
pub struct TypeTable {
    types: Vec<TypeInfo>,
}

impl Default for TypeTable {
    fn default() -> Self {
        let pseudo = |name: &str, kind| TypeInfo {
            name: name.to_string(),
            kind,
        };
        TypeTable {
            types: vec![
                pseudo("an unknown type", TypeKind::Unknown),
                pseudo("universal_integer", TypeKind::UniversalInteger),
                pseudo("universal_real", TypeKind::UniversalReal),
                pseudo("a string literal", TypeKind::StringLiteral),
                pseudo("an aggregate", TypeKind::Aggregate),
                pseudo("null", TypeKind::Null),
            ],
        }
    }
}

impl TypeTable {
    pub fn add(&mut self, name: &str, kind: TypeKind) -> TypeId {
        self.types.push(TypeInfo {
            name: name.to_string(),
            kind,
        });
        TypeId(self.types.len() as u32 - 1)
    }

    /// Completes an incomplete type.
    pub fn complete(&mut self, id: TypeId, kind: TypeKind) {
        self.types[id.0 as usize].kind = kind;
    }

    pub fn get(&self, id: TypeId) -> &TypeInfo {
        &self.types[id.0 as usize]
    }

    pub fn kind(&self, id: TypeId) -> &TypeKind {
        &self.get(id).kind
    }

    pub fn name(&self, id: TypeId) -> &str {
        &self.get(id).name
    }

    pub fn len(&self) -> usize {
        self.types.len()
    }

    /// Drops the types added after the first `n`.
    pub fn truncate(&mut self, n: usize) {
        self.types.truncate(n);
    }

    pub fn is_empty(&self) -> bool {
        self.types.is_empty()
    }

    /// True when a value of type `actual` may stand where `formal` is expected: the same
    /// type, a universal literal of the formal's class (the only implicit conversion VHDL
    /// has), a literal whose type the context gives, or an unknown type on either side.
    pub fn fits(&self, actual: TypeId, formal: TypeId) -> bool {
        if actual == formal || actual == UNKNOWN || formal == UNKNOWN {
            return true;
        }
        match (self.kind(actual), self.kind(formal)) {
            (TypeKind::Incomplete, _) | (_, TypeKind::Incomplete) => true,
            (TypeKind::UniversalInteger, TypeKind::Integer)
            | (TypeKind::UniversalReal, TypeKind::Real) => true,
            (TypeKind::StringLiteral, TypeKind::Array { indexes, element }) => {
                indexes.len() == 1 && self.is_character_like(*element)
            }
            (TypeKind::Aggregate, TypeKind::Array { .. } | TypeKind::Record { .. }) => true,
            (TypeKind::Null, TypeKind::Access(_)) => true,
            _ => false,
        }
    }

    /// An enumeration with character literals (or a type analysis does not know).
    pub fn is_character_like(&self, id: TypeId) -> bool {
        matches!(
            self.kind(id),
            TypeKind::Enum { chars: true } | TypeKind::Unknown | TypeKind::Incomplete
        )
    }

    /// False for the unknown type and a type not completed yet: nothing can be said of them.
    pub fn is_known(&self, id: TypeId) -> bool {
        !matches!(self.kind(id), TypeKind::Unknown | TypeKind::Incomplete)
    }

    /// The one type of `set` when it is a declared type (not unknown, not a universal
    /// literal's, whose type the context decides).
    pub fn single_definite(&self, set: &[TypeId]) -> Option<TypeId> {
        match set {
            [t] if self.is_known(*t)
                && !matches!(
                    self.kind(*t),
                    TypeKind::UniversalInteger | TypeKind::UniversalReal
                ) =>
            {
                Some(*t)
            }
            _ => None,
        }
    }

    pub fn is_discrete(&self, id: TypeId) -> bool {
        matches!(self.kind(id), TypeKind::Integer | TypeKind::Enum { .. })
    }

    /// The element type of an array type (`UNKNOWN` for anything else).
    pub fn element(&self, id: TypeId) -> TypeId {
        match self.kind(id) {
            TypeKind::Array { element, .. } => *element,
            _ => UNKNOWN,
        }
    }

    /// What to call a type in a diagnostic.
    pub fn describe(&self, id: TypeId) -> String {
        match self.kind(id) {
            TypeKind::UniversalInteger => "an integer literal (universal_integer)".to_string(),
            TypeKind::UniversalReal => "a real literal (universal_real)".to_string(),
            TypeKind::StringLiteral | TypeKind::Aggregate | TypeKind::Null | TypeKind::Unknown => {
                self.name(id).to_string()
            }
            _ => format!("`{}`", self.name(id)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn universal_literals_convert_only_within_their_class() {
        let mut t = TypeTable::default();
        let int = t.add("integer", TypeKind::Integer);
        let real = t.add("real", TypeKind::Real);
        assert!(t.fits(UNIVERSAL_INTEGER, int));
        assert!(!t.fits(UNIVERSAL_INTEGER, real));
        assert!(t.fits(UNIVERSAL_REAL, real));
        assert!(!t.fits(UNIVERSAL_REAL, int));
        assert!(!t.fits(int, real));
        assert!(
            !t.fits(real, UNIVERSAL_REAL),
            "a real object is not a literal"
        );
        assert!(t.fits(UNKNOWN, int) && t.fits(real, UNKNOWN));
    }

    #[test]
    fn string_literals_fit_arrays_of_characters_only() {
        let mut t = TypeTable::default();
        let ch = t.add("character", TypeKind::Enum { chars: true });
        let boolean = t.add("boolean", TypeKind::Enum { chars: false });
        let int = t.add("integer", TypeKind::Integer);
        let string = t.add(
            "string",
            TypeKind::Array {
                indexes: vec![int],
                element: ch,
            },
        );
        let bools = t.add(
            "boolean_vector",
            TypeKind::Array {
                indexes: vec![int],
                element: boolean,
            },
        );
        assert!(t.fits(STRING_LITERAL, string));
        assert!(!t.fits(STRING_LITERAL, bools));
        assert!(t.fits(AGGREGATE, bools));
    }
}
