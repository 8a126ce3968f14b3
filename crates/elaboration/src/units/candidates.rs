//! The top-level candidates of a compilation with what stands in the way of elaborating each
//! one alone: generics without a default (nothing can give them a value) and terminal or
//! quantity ports (open at the top, so the analog system would float or lack equations).
//! `vams check` elaborates every candidate it can and says why it skips the others.

use vams_syntax::ast::{ExprKind, InterfaceDecl, ObjectClass};
use vams_syntax::source::Span;

use crate::units::library::Library;

/// An entity of library `work` that no architecture instantiates.
#[derive(Clone, Debug, PartialEq)]
pub struct TopCandidate {
    /// The entity's name (lower case).
    pub name: String,
    /// Where the entity's name is declared.
    pub span: Span,
    /// Generics without a default value, in declaration order.
    pub generics_without_default: Vec<String>,
    /// Terminal and quantity ports, in declaration order.
    pub analog_ports: Vec<String>,
    /// The configuration declarations of library `work` that configure it, sorted: the
    /// designer's ways of elaborating it.
    pub configurations: Vec<String>,
    /// Whether any architecture of it was given: an entity declaration alone (an interface
    /// a book shows before its bodies) is legal, but there is nothing to elaborate.
    pub has_architecture: bool,
}

impl TopCandidate {
    /// True when default generics elaborate it (signal ports become open objects).
    pub fn can_elaborate(&self) -> bool {
        self.generics_without_default.is_empty()
    }

    /// True when its analog system stands alone: no analog port left open.
    pub fn is_closed(&self) -> bool {
        self.analog_ports.is_empty()
    }
}

/// Names declared by the interface declarations that satisfy `keep`.
fn names_where(decls: &[InterfaceDecl], keep: impl Fn(&InterfaceDecl) -> bool) -> Vec<String> {
    decls
        .iter()
        .filter(|d| keep(d))
        .flat_map(|d| d.names.iter().map(|n| n.name.clone()))
        .collect()
}

/// Every candidate of `lib`, sorted by name.
pub fn candidates(lib: &Library) -> Vec<TopCandidate> {
    lib.tops()
        .into_iter()
        .filter_map(|name| {
            let unit = lib.entity(&("work".to_string(), name.clone()), usize::MAX)?;
            let has_architecture = lib
                .architectures
                .get(&unit.index)
                .is_some_and(|a| !a.is_empty());
            let entity = unit.unit;
            let mut configurations: Vec<String> = lib
                .configurations
                .iter()
                .filter(|((library, _), c)| {
                    library == "work"
                        && matches!(&c.unit.entity.kind,
                            ExprKind::Name(e) | ExprKind::Selected(_, e) if e.name == name)
                })
                .map(|((_, cfg), _)| cfg.clone())
                .collect();
            configurations.sort();
            Some(TopCandidate {
                configurations,
                has_architecture,
                span: entity.name.span,
                generics_without_default: names_where(&entity.generics, |d| d.default.is_none()),
                analog_ports: names_where(&entity.ports, |d| {
                    matches!(d.class, Some(ObjectClass::Terminal | ObjectClass::Quantity))
                }),
                name,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use crate::tests::parse_all;
    use crate::top_candidates;

    #[test]
    fn candidates_name_missing_defaults_and_open_analog_ports() {
        let text = "
library ieee; use ieee.electrical_systems.all;
entity r is
  generic (res : real; scale : real := 1.0);
  port (terminal p, n : electrical; quantity q : in real; signal s : in bit);
end entity;
architecture a of r is begin end architecture;
entity tb is port (signal done : out bit); end entity;
architecture a of tb is begin end architecture;
entity user is end entity;
architecture a of user is
  terminal t : electrical;
begin
  u : entity work.sub generic map (g => 1) port map (t, electrical_ref);
end architecture;
entity sub is generic (g : integer); port (terminal a, b : electrical); end entity;
architecture a of sub is begin end architecture;
";
        let (sources, files) = parse_all(&[("c.vhd", text)]);
        let cands = top_candidates(&vams_semantics::analysis::analyse(&sources, &files), &files);
        let names: Vec<&str> = cands.iter().map(|c| c.name.as_str()).collect();
        assert_eq!(names, ["r", "tb", "user"]);
        assert_eq!(cands[0].generics_without_default, ["res"]);
        assert_eq!(cands[0].analog_ports, ["p", "n", "q"]);
        assert!(!cands[0].can_elaborate() && !cands[0].is_closed());
        assert!(cands[1].can_elaborate() && cands[1].is_closed());
        assert_eq!(sources.snippet(cands[2].span), "user");
    }
}
