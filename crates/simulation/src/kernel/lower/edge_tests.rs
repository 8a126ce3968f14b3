//! `rising_edge` and `falling_edge` of the bundled packages, lowered to [`Edge`]: the same
//! result as running the function's body, for every value, previous value and event; a
//! user's own function of that name is called.

use super::*;
use crate::kernel::eval::{Env, eval};
use crate::kernel::io::Io;
use vams_elaboration::{ElabOptions, elaborate};
use vams_semantics::stdlib;
use vams_syntax::parser;
use vams_syntax::source::SourceMap;

/// `text`'s design `top`, elaborated with the bundled packages.
fn design(text: &str, top: &str) -> Design {
    let mut sources = SourceMap::new();
    let mut ids = stdlib::load(&mut sources);
    ids.push(sources.add("test.vhd", "work", text.to_string()));
    let files: Vec<_> = ids
        .into_iter()
        .map(|id| (id, parser::parse(id, &sources.file(id).text.clone()).0))
        .collect();
    let options = ElabOptions {
        top: top.into(),
        ..ElabOptions::default()
    };
    match elaborate(&sources, &files, &options) {
        Ok(d) => d,
        Err(errors) => panic!("elaboration failed: {errors:?}"),
    }
}

/// The right-hand sides of the variable assignments of the design's first process.
fn assigned(d: &Design) -> Vec<&Expr> {
    (d.processes[0].code.iter())
        .filter_map(|i| match i {
            Instr::SetVar { value, .. } => Some(value),
            _ => None,
        })
        .collect()
}

const EDGES: &str = "
library ieee;
use ieee.std_logic_1164.all;
use ieee.numeric_bit.all;
entity edges is
end entity edges;
architecture a of edges is
  signal s : std_ulogic := '0';
  signal b : bit := '0';
begin
  p : process (s, b)
    variable r : boolean;
  begin
    r := rising_edge(s);
    r := falling_edge(s);
    r := rising_edge(b);
    r := falling_edge(b);
  end process p;
end architecture a;
";

#[test]
fn bundled_edges_agree_with_their_bodies() {
    let d = design(EDGES, "edges");
    let signals = Signals::new(&d).expect("signals");
    let process = &d.processes[0];
    let cx = Lowering {
        design: &d,
        process,
    };
    let io = Io::default();
    let vars = vec![Value::Boolean(false)];
    let calls = assigned(&d);
    assert_eq!(calls.len(), 4);
    let mut checked = 0;
    for e in calls {
        let Expr::FnCall { sub, .. } = e else {
            panic!("not a call: {e:?}");
        };
        // std_ulogic's nine literals, or bit's two.
        let (signal, levels) = match d.subprograms[sub.index()].intrinsic {
            Some(Intrinsic::StdLogicEdge { signal, .. }) => (signal, 9),
            Some(Intrinsic::BitEdge { signal, .. }) => (signal, 2),
            None => panic!("not recognised: {}", d.subprograms[sub.index()].name),
        };
        let node = Node::lower(e, &cx).expect("lowered");
        for now in 0..levels {
            for last in 0..levels {
                for event in [false, true] {
                    let mut states = signals.states.clone();
                    let st = &mut states[signal.index()];
                    (st.value, st.last_value, st.event) =
                        (Value::Enum(now), Value::Enum(last), event);
                    let env = Env {
                        signals: &states,
                        vars: &vars,
                        quantities: &[],
                        derivatives: &[],
                        now: 0.0,
                        subprograms: &d.subprograms,
                        depth: 0,
                        io: &io,
                        drivers: None,
                    };
                    let lowered = node.eval(&states, &vars).map(|v| node.kind.value(v));
                    assert_eq!(
                        lowered.as_ref(),
                        eval(e, &env).as_ref().ok(),
                        "{now} {last} {event}"
                    );
                    checked += 1;
                }
            }
        }
    }
    assert_eq!(checked, 2 * (2 * 81 + 2 * 4));
}

#[test]
fn a_users_own_rising_edge_is_called() {
    let d = design(
        "
library ieee;
use ieee.std_logic_1164.all;
entity own is
end entity own;
architecture a of own is
  function rising_edge (signal s : std_ulogic) return boolean is
  begin
    return s = '1';
  end function rising_edge;
  signal s : std_ulogic := '0';
begin
  p : process (s)
    variable r : boolean;
  begin
    r := rising_edge(s);
  end process p;
end architecture a;
",
        "own",
    );
    let cx = Lowering {
        design: &d,
        process: &d.processes[0],
    };
    let calls = assigned(&d);
    assert_eq!(calls.len(), 1);
    let Expr::FnCall { sub, .. } = calls[0] else {
        panic!("not a call: {:?}", calls[0]);
    };
    assert_eq!(d.subprograms[sub.index()].intrinsic, None);
    assert!(Node::lower(calls[0], &cx).is_none());
}
