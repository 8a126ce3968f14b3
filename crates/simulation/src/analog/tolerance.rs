//! Absolute tolerances per unknown from the tolerance groups of IEEE 1076.1.1.
//!
//! | group                      | abstol |
//! |----------------------------|--------|
//! | `DEFAULT_VOLTAGE`          | 1e-6   |
//! | `DEFAULT_CURRENT`          | 1e-9   |
//! | `DEFAULT_DISPLACEMENT`     | 1e-9   |
//! | `DEFAULT_VELOCITY`         | 1e-6   |
//! | `DEFAULT_ANGULAR_VELOCITY` | 1e-4   |
//! | `DEFAULT_ANGLE`            | 1e-6   |
//! | `DEFAULT_FORCE`            | 1e-9   |
//! | `DEFAULT_TORQUE`           | 1e-9   |
//!
//! A quantity without a group of its own takes its branch's group (across quantities the
//! nature's across group, through quantities its through group); potentials take their
//! nature's across group; anything else gets the caller's default.

use super::build::Unknown;
use vams_design::{Design, Nature, QuantityKind, TerminalId};

/// The known tolerance groups and their absolute tolerances.
pub const TOLERANCE_GROUPS: &[(&str, f64)] = &[
    ("DEFAULT_VOLTAGE", 1e-6),
    ("DEFAULT_CURRENT", 1e-9),
    ("DEFAULT_DISPLACEMENT", 1e-9),
    ("DEFAULT_VELOCITY", 1e-6),
    ("DEFAULT_ANGULAR_VELOCITY", 1e-4),
    ("DEFAULT_ANGLE", 1e-6),
    ("DEFAULT_FORCE", 1e-9),
    ("DEFAULT_TORQUE", 1e-9),
];

/// The absolute tolerance of a group (names compare case-insensitively).
pub fn group_abstol(group: &str) -> Option<f64> {
    TOLERANCE_GROUPS
        .iter()
        .find(|(name, _)| name.eq_ignore_ascii_case(group))
        .map(|&(_, v)| v)
}

fn nature_of(design: &Design, t: TerminalId) -> &Nature {
    &design.natures[design.terminals[t.index()].nature.index()]
}

/// The tolerance of terminal `t`'s through quantities (its nature's through group): what a
/// conservation law at `t` balances.
pub fn through_abstol(design: &Design, t: TerminalId) -> Option<f64> {
    nature_of(design, t)
        .through_tolerance
        .as_deref()
        .and_then(group_abstol)
}

/// The group tolerance of each unknown, `None` where no known group applies.
pub fn per_unknown(design: &Design, unknowns: &[Unknown]) -> Vec<Option<f64>> {
    let nature_of = |t: TerminalId| nature_of(design, t);
    // Nearly every unknown names the same group as the one before (each quantity holds its
    // own copy of the name): the last lookup is remembered, so a large circuit compares one
    // name exactly per unknown instead of searching the table case-insensitively.
    let mut last: Option<(&str, Option<f64>)> = None;
    unknowns
        .iter()
        .map(|u| {
            let group = match *u {
                Unknown::Potential(t) => nature_of(t).across_tolerance.as_deref(),
                Unknown::Flow(q) => match design.quantities[q.index()].kind {
                    QuantityKind::Across { plus, .. } => {
                        nature_of(plus).through_tolerance.as_deref()
                    }
                    _ => None,
                },
                Unknown::Quantity(q) => {
                    let q = &design.quantities[q.index()];
                    q.tolerance.as_deref().or(match q.kind {
                        QuantityKind::Across { plus, .. } => {
                            nature_of(plus).across_tolerance.as_deref()
                        }
                        QuantityKind::Through { plus, .. } => {
                            nature_of(plus).through_tolerance.as_deref()
                        }
                        QuantityKind::Free => None,
                    })
                }
                // A derivative's scale is not its unknown's: judged on the default.
                Unknown::Derivative { .. } => None,
            };
            let group = group?;
            match last {
                Some((name, abstol)) if name == group => abstol,
                _ => {
                    let abstol = group_abstol(group);
                    last = Some((group, abstol));
                    abstol
                }
            }
        })
        .collect()
}
