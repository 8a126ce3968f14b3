//! `vams op`: the quiescent operating point of a design (after initialisation: processes run to
//! their first wait, breaks applied), one line per quantity and signal with its unit.

use rustc_hash::FxHashMap;

use crate::design::{Design, Type};

use super::time::format_time;
use crate::output::csv::format_number as csv_number;

/// What decides how a name's value is printed: a quantity's unit or a signal's type.
enum Kind<'d> {
    Quantity(Option<&'d str>),
    Signal(&'d Type),
}

/// The quantities and signals of a design by name, looked up once per printed value (a
/// search through the design per value made the listing quadratic in its size).
pub struct ValueFormats<'d> {
    by_name: FxHashMap<&'d str, Kind<'d>>,
}

impl<'d> ValueFormats<'d> {
    pub fn new(design: &'d Design) -> ValueFormats<'d> {
        let mut by_name = FxHashMap::default();
        by_name.reserve(design.quantities.len() + design.signals.len());
        // Quantities first: they win over a signal of the same name.
        for q in &design.quantities {
            by_name
                .entry(q.name.as_str())
                .or_insert(Kind::Quantity(q.unit.as_deref()));
        }
        for s in &design.signals {
            by_name
                .entry(s.name.as_str())
                .or_insert(Kind::Signal(&s.ty));
        }
        ValueFormats { by_name }
    }

    /// A value as text: quantities with their unit symbol; signals by their type (booleans
    /// and enumeration literals by name).
    pub fn format(&self, name: &str, value: f64) -> String {
        // A listing is read, not parsed back: a current of -0 A reads as 0 A.
        let value = value + 0.0;
        let ty = match self.by_name.get(name) {
            Some(Kind::Quantity(Some(unit))) => return format!("{} {unit}", csv_number(value)),
            Some(Kind::Quantity(None)) => return csv_number(value),
            Some(Kind::Signal(ty)) => Some(*ty),
            None => None,
        };
        match ty {
            Some(Type::Boolean) => (if value > 0.5 { "true" } else { "false" }).into(),
            Some(Type::Enum { literals, .. }) => literals
                .get(value.round().max(0.0) as usize)
                .cloned()
                .unwrap_or_else(|| csv_number(value)),
            Some(Type::Integer) => format!("{}", value.round() as i64),
            Some(Type::Time) => format_time(value),
            _ => csv_number(value),
        }
    }
}

/// The listing: names padded to one column.
pub fn format_point(design: &Design, point: &[(String, f64)]) -> String {
    let formats = ValueFormats::new(design);
    let width = point.iter().map(|(n, _)| n.len()).max().unwrap_or(0);
    point
        .iter()
        .map(|(name, v)| format!("{name:<width$}  {}\n", formats.format(name, *v)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::{Quantity, QuantityKind, Signal, SignalKind, Value};
    use crate::source::Span;

    fn design() -> Design {
        let quantity = |name: &str, unit: Option<&str>| Quantity {
            name: name.into(),
            kind: QuantityKind::Free,
            tolerance: None,
            subtype: "voltage".into(),
            unit: unit.map(Into::into),
            initial_guess: None,
            span: Span::default(),
        };
        let signal = |name: &str, ty: Type| Signal {
            range: None,
            resolution: None,
            guarded: None,
            name: name.into(),
            ty,
            init: Value::Integer(0),
            kind: SignalKind::Explicit,
            span: Span::default(),
        };
        Design {
            top: "tb".into(),
            quantities: vec![quantity("vfb", Some("V")), quantity("x", None)],
            signals: vec![
                signal("ov", Type::Boolean),
                signal(
                    "en",
                    Type::Enum {
                        name: "std_ulogic".into(),
                        literals: ["'U'", "'X'", "'0'", "'1'"].map(String::from).to_vec(),
                    },
                ),
                signal("n", Type::Integer),
                signal("t", Type::Time),
            ],
            ..Design::default()
        }
    }

    #[test]
    fn values_carry_units_and_literal_names() {
        let d = design();
        let point: Vec<(String, f64)> = [
            ("vfb", 0.9),
            ("x", -2.5),
            ("ov", 0.0),
            ("en", 3.0),
            ("n", 7.0),
            ("t", 0.01),
        ]
        .iter()
        .map(|(n, v)| (n.to_string(), *v))
        .collect();
        assert_eq!(
            format_point(&d, &point),
            "vfb  0.9 V\nx    -2.5\nov   false\nen   '1'\nn    7\nt    10 ms\n"
        );
    }
}
