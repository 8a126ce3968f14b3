//! Semantic types of the elaborator: richer than [`design::Type`] (they keep names, index
//! bounds, tolerance groups and unit symbols) and lowered to it at the end.

use std::fmt;
use std::rc::Rc;
use std::sync::Arc;

use vams_design::{Type, Value};

/// A type as the type checker sees it. Two types are the same when their base names agree
/// (`same`); subtypes of `integer` and `real` share their base type.
#[derive(Clone, Debug, PartialEq)]
pub enum Ty {
    Integer,
    Real,
    /// Physical type `time`, carried in seconds.
    Time,
    Boolean,
    Enum(Rc<EnumTy>),
    Array(Rc<ArrayTy>),
    Record(Rc<RecordTy>),
    /// A physical type of the user's own (`resistance` with `ohm`, `kohm`): values are
    /// integers counting its primary unit.
    Physical(Rc<PhysicalTy>),
    /// An access type: values designate objects of `designated` on the heap.
    Access(Rc<AccessTy>),
    /// A file type of `element`s (`text`: of `string`).
    File(Rc<FileTy>),
    /// A protected type, by its name and the span of its declaration's identifier (where
    /// `Elab::protected` keeps its methods and body).
    Protected(Rc<ProtectedTy>),
}

#[derive(Debug, PartialEq)]
pub struct ProtectedTy {
    pub name: String,
    pub decl: vams_syntax::source::Span,
}

/// An access type. The designated type is set once it is known: a type declared
/// incomplete (`type node;`) is completed later, and a record may hold access values
/// designating itself, so the cell may form a cycle (printing and comparing go by name).
pub struct AccessTy {
    pub name: String,
    pub designated: std::cell::RefCell<Option<Ty>>,
}

impl AccessTy {
    /// The designated type (`None` while it is incomplete).
    pub fn designated(&self) -> Option<Ty> {
        self.designated.borrow().clone()
    }
}

impl PartialEq for AccessTy {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name
    }
}

impl fmt::Debug for AccessTy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "access {}", self.name)
    }
}

#[derive(Debug, PartialEq)]
pub struct FileTy {
    pub name: String,
    pub element: Ty,
}

/// A physical type other than `time` (LRM 3.1.3): its units and their values in the
/// primary unit, the primary first.
#[derive(Debug, PartialEq)]
pub struct PhysicalTy {
    pub name: String,
    pub units: Vec<(String, i64)>,
}

/// A record type: its fields in declaration order. A record value is a
/// [`Value::Array`] of the field values in that order, and a field is selected by its
/// position, as an array element is (`Expr::Index` on a [`Type::Record`]).
#[derive(Debug, PartialEq)]
pub struct RecordTy {
    pub name: String,
    pub fields: Vec<(String, Ty)>,
    /// Each field's default (its subtype's `'left`: 0 for `integer range 0 to 59`).
    pub defaults: Vec<Value>,
}

impl RecordTy {
    /// The position and type of field `name`.
    pub fn field(&self, name: &str) -> Option<(usize, &Ty)> {
        self.fields
            .iter()
            .enumerate()
            .find(|(_, (n, _))| n == name)
            .map(|(k, (_, t))| (k, t))
    }
}

#[derive(Debug, PartialEq)]
pub struct EnumTy {
    pub name: String,
    /// Literals in position order; characters are written `'c'`.
    pub literals: Vec<String>,
}

#[derive(Debug, PartialEq)]
pub struct ArrayTy {
    /// Name of the array base type (`real_vector`, `string`, `segment_array`).
    pub name: String,
    pub element: Ty,
    /// Index bounds `(left, right, ascending)` for a constrained (sub)type.
    pub bounds: Option<(i64, i64, bool)>,
    /// Lowest value of the index subtype (`natural`: 0, `positive`: 1): where the index of an
    /// unconstrained array's value starts.
    pub index_low: i64,
    /// The index's base type: `integer`, or an enumeration (`array (state) of ...`) or
    /// `boolean`, whose values index by their positions (`bounds` and `index_low` are
    /// positions then).
    pub index: Ty,
    /// 0 for an array type of its own; k for the (k+1)-th dimension of a multi-dimensional
    /// array, which is held as an array of its rows: `array (1 to 3, 1 to 4) of real` is an
    /// array (dimension 0) of arrays (dimension 1), `m(i, j)` indexes both at once.
    pub dimension: u8,
}

/// The position of a discrete value (an integer itself, an enumeration literal or boolean by
/// position): what array bounds and indices are kept as.
pub fn position(v: &Value) -> Option<i64> {
    match v {
        Value::Integer(i) => Some(*i),
        Value::Enum(p) => Some(i64::from(*p)),
        Value::Boolean(b) => Some(i64::from(*b)),
        _ => None,
    }
}

/// The value of index type `index` at position `pos` (the inverse of [`position`]).
pub fn index_value(index: &Ty, pos: i64) -> Value {
    match index {
        Ty::Enum(_) => Value::Enum(pos.clamp(0, i64::from(u32::MAX)) as u32),
        Ty::Boolean => Value::Boolean(pos != 0),
        _ => Value::Integer(pos),
    }
}

impl ArrayTy {
    /// The array type of its next dimension, for a multi-dimensional array.
    pub fn next_dimension(&self) -> Option<&Rc<ArrayTy>> {
        match &self.element {
            Ty::Array(e) if e.dimension == self.dimension + 1 => Some(e),
            _ => None,
        }
    }

    /// The number of dimensions from this one on (1 for a one-dimensional array).
    pub fn dimensions(&self) -> usize {
        1 + self.next_dimension().map_or(0, |e| e.dimensions())
    }

    pub fn len(&self) -> Option<usize> {
        self.bounds.map(|(l, r, asc)| bounds_len(l, r, asc))
    }

    /// This array type with `bounds` instead of its own (`None`: unconstrained).
    pub fn with_bounds(&self, bounds: Option<(i64, i64, bool)>) -> Ty {
        Ty::Array(Rc::new(ArrayTy {
            name: self.name.clone(),
            element: self.element.clone(),
            bounds,
            index_low: self.index_low,
            index: self.index.clone(),
            dimension: self.dimension,
        }))
    }
}

/// Number of positions in `left to/downto right`.
pub fn bounds_len(left: i64, right: i64, ascending: bool) -> usize {
    let n = if ascending {
        right - left + 1
    } else {
        left - right + 1
    };
    n.max(0) as usize
}

impl Ty {
    /// True when values of `self` and `other` may be mixed without conversion.
    pub fn same(&self, other: &Ty) -> bool {
        match (self, other) {
            (Ty::Enum(a), Ty::Enum(b)) => a.name == b.name,
            (Ty::Array(a), Ty::Array(b)) => a.name == b.name && a.dimension == b.dimension,
            (Ty::Record(a), Ty::Record(b)) => a.name == b.name,
            (Ty::Physical(a), Ty::Physical(b)) => a.name == b.name,
            (Ty::Access(a), Ty::Access(b)) => a.name == b.name,
            (Ty::File(a), Ty::File(b)) => a.name == b.name,
            (Ty::Protected(a), Ty::Protected(b)) => a.decl == b.decl,
            (a, b) => std::mem::discriminant(a) == std::mem::discriminant(b),
        }
    }

    pub fn is_numeric(&self) -> bool {
        matches!(self, Ty::Integer | Ty::Real)
    }

    pub fn is_scalar(&self) -> bool {
        !matches!(
            self,
            Ty::Array(_) | Ty::Record(_) | Ty::File(_) | Ty::Protected(_)
        )
    }

    pub fn is_string(&self) -> bool {
        matches!(self, Ty::Array(a) if a.name == "string")
    }

    pub fn is_enum_named(&self, name: &str) -> bool {
        matches!(self, Ty::Enum(e) if e.name == name)
    }

    /// The kernel's view of the type.
    pub fn to_design(&self) -> Type {
        match self {
            Ty::Integer => Type::Integer,
            Ty::Real => Type::Real,
            Ty::Time => Type::Time,
            Ty::Boolean => Type::Boolean,
            Ty::Enum(e) => Type::Enum {
                name: e.name.clone(),
                literals: e.literals.clone(),
            },
            Ty::Array(a) if a.name == "string" => Type::String,
            Ty::Array(a) => {
                let (left, right, ascending) = a.bounds.unwrap_or((0, -1, true));
                Type::Array {
                    element: Box::new(a.element.to_design()),
                    left,
                    right,
                    ascending,
                }
            }
            Ty::Physical(p) => Type::Physical {
                name: p.name.clone(),
                units: p.units.clone(),
            },
            Ty::Record(r) => Type::Record {
                name: r.name.clone(),
                fields: r
                    .fields
                    .iter()
                    .map(|(n, t)| (n.clone(), t.to_design()))
                    .collect(),
            },
            Ty::Access(a) => Type::Access {
                name: a.name.clone(),
            },
            Ty::File(t) => Type::File {
                name: t.name.clone(),
            },
            // A shared variable's value is the access value of its object.
            Ty::Protected(p) => Type::Access {
                name: p.name.clone(),
            },
        }
    }

    /// `T'left`: the default initial value of objects of the type (LRM 12.3.1.5).
    pub fn default_value(&self) -> Value {
        match self {
            Ty::Integer => Value::Integer(i32::MIN as i64),
            Ty::Real => Value::Real(-1.0e308),
            Ty::Time => Value::Time(-(i64::MAX as f64) * 1e-15),
            Ty::Boolean => Value::Boolean(false),
            Ty::Enum(_) => Value::Enum(0),
            Ty::Array(a) if a.name == "string" => Value::String(" ".repeat(a.len().unwrap_or(0))),
            Ty::Array(a) => Value::Array(vec![a.element.default_value(); a.len().unwrap_or(0)]),
            Ty::Record(r) => Value::Array(r.defaults.clone()),
            Ty::Physical(_) => Value::Integer(0),
            Ty::Access(_) => Value::Access(0),
            // A file object's value is its number, given where it is declared.
            Ty::File(_) => Value::File(u32::MAX),
            Ty::Protected(_) => Value::Access(0),
        }
    }

    /// Scalar bounds `(T'left, T'right)` of the base type, for `'high`, `'low` and ranges.
    pub fn scalar_bounds(&self) -> Option<(Value, Value)> {
        match self {
            Ty::Integer => Some((
                Value::Integer(i32::MIN as i64),
                Value::Integer(i32::MAX as i64),
            )),
            Ty::Real => Some((Value::Real(-1.0e308), Value::Real(1.0e308))),
            Ty::Time => {
                let max = i64::MAX as f64 * 1e-15;
                Some((Value::Time(-max), Value::Time(max)))
            }
            Ty::Boolean => Some((Value::Boolean(false), Value::Boolean(true))),
            Ty::Enum(e) => Some((
                Value::Enum(0),
                Value::Enum(e.literals.len().saturating_sub(1) as u32),
            )),
            Ty::Physical(_) => Some((
                Value::Integer(i64::from(i32::MIN)),
                Value::Integer(i64::from(i32::MAX)),
            )),
            Ty::Array(_) | Ty::Record(_) | Ty::Access(_) | Ty::File(_) | Ty::Protected(_) => None,
        }
    }
}

impl fmt::Display for Ty {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Ty::Integer => f.write_str("integer"),
            Ty::Real => f.write_str("real"),
            Ty::Time => f.write_str("time"),
            Ty::Boolean => f.write_str("boolean"),
            Ty::Enum(e) => f.write_str(&e.name),
            Ty::Array(a) => f.write_str(&a.name),
            Ty::Record(r) => f.write_str(&r.name),
            Ty::Physical(p) => f.write_str(&p.name),
            Ty::Access(a) => f.write_str(&a.name),
            Ty::File(t) => f.write_str(&t.name),
            Ty::Protected(p) => f.write_str(&p.name),
        }
    }
}

/// A named subtype: a type plus what the analog side needs from the subtype declaration.
#[derive(Clone, Debug, PartialEq)]
pub struct Sub {
    pub ty: Ty,
    /// The subtype's own name (`voltage`), for `Quantity::subtype` (shared, not copied, by each
    /// quantity).
    pub name: Arc<str>,
    /// `tolerance "DEFAULT_VOLTAGE"` (shared by the subtype's quantities, as `name`).
    pub tolerance: Option<Arc<str>>,
    /// The `symbol` attribute (`"V"`), shared likewise.
    pub unit: Option<Arc<str>>,
    /// A range constraint of an integer or real subtype (`natural`), for `'high`/`'low`.
    pub range: Option<(Value, Value)>,
    /// The user-defined resolution function of a resolved subtype (an index into
    /// `Elab::resolvers`); `std_logic`'s is the kernel's own.
    pub resolution: Option<usize>,
}

impl Sub {
    pub fn of(ty: Ty, name: &str) -> Sub {
        Sub {
            ty,
            name: name.into(),
            tolerance: None,
            unit: None,
            range: None,
            resolution: None,
        }
    }
}
