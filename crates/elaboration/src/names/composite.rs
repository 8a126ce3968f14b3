//! The composite analog objects and natures that scope items name: array natures, the scalar
//! elements an array terminal or quantity expands into, record natures, and what a nature
//! indication denotes. Plain data over [`Ty`]; the elaboration of their declarations is in
//! `arrays` and `record_natures`.

use std::rc::Rc;

use crate::names::types::{ArrayTy, Ty};

/// `nature electrical_vector is array (natural range <>) of electrical;` and its constrained
/// subnatures.
#[derive(Debug)]
pub struct ArrayNature {
    pub name: String,
    /// The element nature (index into the elaborator's nature table).
    pub element: usize,
    /// `(left, right, ascending)` when constrained.
    pub bounds: Option<(i64, i64, bool)>,
    /// For a nature of two or more dimensions (`array (1 to 10, 19 downto 0) of thermal`): its
    /// index ranges as an array type of reals, for the attributes of the nature. Terminals
    /// of such a nature are not supported yet.
    pub shape: Option<Ty>,
}

impl ArrayNature {
    /// The array type whose bounds a constrained array (sub)nature has, for `'left`,
    /// `'range`, ... of the nature itself; `None` when unconstrained.
    pub fn bounds_ty(&self) -> Option<Ty> {
        if let Some(shape) = &self.shape {
            return Some(shape.clone());
        }
        let (left, right, ascending) = self.bounds?;
        Some(Ty::Array(Rc::new(ArrayTy {
            name: self.name.clone(),
            element: Ty::Real,
            bounds: Some((left, right, ascending)),
            index_low: left.min(right),
            index: Ty::Integer,
            dimension: 0,
        })))
    }
}

/// The scalar design objects of an expanded array, from left to right.
#[derive(Debug)]
pub struct Elements<T> {
    /// The declared name, for messages.
    pub name: String,
    pub left: i64,
    pub ascending: bool,
    pub ids: Vec<T>,
}

impl<T: Copy> Elements<T> {
    /// The element at `index`, if it is in range.
    pub fn get(&self, index: i64) -> Option<T> {
        let pos = if self.ascending {
            index.checked_sub(self.left)?
        } else {
            self.left.checked_sub(index)?
        };
        usize::try_from(pos)
            .ok()
            .and_then(|p| self.ids.get(p).copied())
    }

    /// An array type with the object's bounds, for `'range`, `'length`, `'left`, ...
    pub fn ty(&self) -> Ty {
        let last = self.ids.len() as i64 - 1;
        let right = match self.ascending {
            true => self.left + last,
            false => self.left - last,
        };
        Ty::Array(Rc::new(ArrayTy {
            name: self.name.clone(),
            element: Ty::Real,
            bounds: Some((self.left, right, self.ascending)),
            index_low: self.left.min(right),
            index: Ty::Integer,
            dimension: 0,
        }))
    }

    /// The index range as written: `0 to 10`, `3 downto 0`.
    pub fn range_text(&self) -> String {
        let n = self.ids.len() as i64 - 1;
        match self.ascending {
            true => format!("{} to {}", self.left, self.left + n),
            false => format!("{} downto {}", self.left, self.left - n),
        }
    }
}

/// What a nature indication denotes.
#[derive(Clone, Debug)]
pub enum NatureMark {
    Scalar(usize),
    Array(Rc<ArrayNature>),
    Record(Rc<RecordNature>),
}

/// The index at position `pos` (from the left) of a range.
pub(crate) fn index_at((left, _, ascending): (i64, i64, bool), pos: usize) -> i64 {
    if ascending {
        left + pos as i64
    } else {
        left - pos as i64
    }
}

/// The indexes of a range, left to right (empty for a null range).
pub(crate) fn indexes((left, right, ascending): (i64, i64, bool)) -> Vec<i64> {
    if ascending {
        (left..=right).collect()
    } else {
        (right..=left).rev().collect()
    }
}

/// A record nature: each field's nature, in declaration order.
#[derive(Debug)]
pub struct RecordNature {
    pub name: String,
    pub fields: Vec<(String, NatureMark)>,
}
