//! How a recorded column is shown: as a real number, a 1-bit logic level, a nine-valued
//! `std_ulogic`, or an integer (other enumerations, by position). Shared by the VCD writer and
//! the plots so that both agree on what is "logic".

use vams_design::Type;
use vams_simulation::waveform::{Column, ColumnKind};

/// The presentation of a column.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Presentation {
    /// Quantities and real or time signals.
    Real,
    /// `boolean` and `bit`: position 0 is low, 1 is high.
    Bit,
    /// `std_ulogic`/`std_logic`: positions of `U X 0 1 Z W L H -`.
    StdLogic,
    /// Integers and other enumerations (by position).
    Integer,
    /// Strings and arrays: not representable as one number.
    Other,
}

/// The `std_ulogic` literals in position order.
const STD_ULOGIC: [&str; 9] = ["u", "x", "0", "1", "z", "w", "l", "h", "-"];

/// A literal without quotes, lower case (elaboration may keep `'1'` or `1`).
fn bare(literal: &str) -> String {
    literal.trim_matches('\'').to_ascii_lowercase()
}

/// Classifies a column.
pub fn presentation(column: &Column) -> Presentation {
    match &column.kind {
        ColumnKind::Quantity { .. } => Presentation::Real,
        ColumnKind::Signal { ty } => match ty {
            Type::Real | Type::Time => Presentation::Real,
            Type::Boolean => Presentation::Bit,
            Type::Integer | Type::Physical { .. } => Presentation::Integer,
            Type::Enum { literals, .. } => {
                let bare: Vec<String> = literals.iter().map(|l| bare(l)).collect();
                if bare == ["0", "1"] || bare == ["false", "true"] {
                    Presentation::Bit
                } else if bare == STD_ULOGIC {
                    Presentation::StdLogic
                } else {
                    Presentation::Integer
                }
            }
            Type::String
            | Type::Array { .. }
            | Type::Record { .. }
            | Type::Access { .. }
            | Type::File { .. } => Presentation::Other,
        },
    }
}

/// A `std_ulogic` position as a VCD scalar value: `0`, `1`, `z`, or `x` for the unknowns
/// (U, X, W, -); the weak L and H map to their strong levels.
pub fn std_logic_vcd(position: f64) -> char {
    match position.round() as i64 {
        2 | 6 => '0',
        3 | 7 => '1',
        4 => 'z',
        _ => 'x',
    }
}

/// A logic value as a plot level: 0 or 1, and 0.5 for std_ulogic's unknown and
/// high-impedance values (drawn between the rails).
pub fn plot_level(presentation: Presentation, value: f64) -> f64 {
    match presentation {
        Presentation::StdLogic => match std_logic_vcd(value) {
            '0' => 0.0,
            '1' => 1.0,
            _ => 0.5,
        },
        _ if value > 0.5 => 1.0,
        _ => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn signal(ty: Type) -> Column {
        Column {
            name: "s".into(),
            kind: ColumnKind::Signal { ty },
            values: vec![],
        }
    }

    fn enumeration(literals: &[&str]) -> Type {
        Type::Enum {
            name: "t".into(),
            literals: literals.iter().map(|s| s.to_string()).collect(),
        }
    }

    #[test]
    fn classifies_by_type_and_literals() {
        assert_eq!(presentation(&signal(Type::Boolean)), Presentation::Bit);
        assert_eq!(
            presentation(&signal(enumeration(&["'0'", "'1'"]))),
            Presentation::Bit
        );
        let std = [
            "'U'", "'X'", "'0'", "'1'", "'Z'", "'W'", "'L'", "'H'", "'-'",
        ];
        assert_eq!(
            presentation(&signal(enumeration(&std))),
            Presentation::StdLogic
        );
        assert_eq!(
            presentation(&signal(enumeration(&["idle", "up", "down"]))),
            Presentation::Integer
        );
        assert_eq!(presentation(&signal(Type::Time)), Presentation::Real);
        assert_eq!(presentation(&signal(Type::String)), Presentation::Other);
        let q = Column {
            name: "v".into(),
            kind: ColumnKind::Quantity { unit: None },
            values: vec![],
        };
        assert_eq!(presentation(&q), Presentation::Real);
    }

    #[test]
    fn std_logic_maps_to_four_vcd_states_and_three_plot_levels() {
        let vcd: String = (0..9).map(|p| std_logic_vcd(p as f64)).collect();
        assert_eq!(vcd, "xx01zx01x");
        let levels: Vec<f64> = (0..9)
            .map(|p| plot_level(Presentation::StdLogic, p as f64))
            .collect();
        assert_eq!(levels, [0.5, 0.5, 0.0, 1.0, 0.5, 0.5, 0.0, 1.0, 0.5]);
        assert_eq!(plot_level(Presentation::Bit, 1.0), 1.0);
        assert_eq!(plot_level(Presentation::Bit, 0.0), 0.0);
    }
}
