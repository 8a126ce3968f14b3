//! `flatten`'s unit tests: ngspice's names and scoping (the expected values are what
//! ngspice 39 prints for the same decks), resolution, and each error.

use crate::circuit::{Analysis, Circuit, Method, NodeId, OptionValue, Probe, SweepTarget};
use crate::deck::{ElementKind, ModelKind, Waveform};
use crate::error::SpiceError;
use crate::flatten::flatten;
use crate::test_support::read_ok;

fn flat(text: &str) -> Circuit {
    match flatten(&read_ok(text)) {
        Ok(c) => c,
        Err(e) => panic!("{e:#?}"),
    }
}

fn flat_errors(text: &str) -> Vec<SpiceError> {
    match flatten(&read_ok(text)) {
        Ok(c) => panic!("no error: {c:#?}"),
        Err(e) => e,
    }
}

fn messages(text: &str) -> Vec<String> {
    flat_errors(text).iter().map(|e| e.to_string()).collect()
}

fn value(c: &Circuit, element: &str) -> f64 {
    match c.element(element) {
        Some(e) => e.values[0],
        None => panic!(
            "no element {element}: {:?}",
            c.elements.iter().map(|e| &e.name).collect::<Vec<_>>()
        ),
    }
}

#[test]
fn names_and_values_match_ngspice() {
    // ngspice 39 `listing expand`: r.x9.x1.r1 1 x9.x1.n1 14; r.x9.x1.r2 x9.x1.n1 x9.m 28;
    // r.x9.r3 x9.m 0 1.
    let c = flat(
        "test naming\n\
         .param g=2\n\
         .subckt inner a b params: r=1k\n\
         r1 a n1 {r}\n\
         r2 n1 b {r*g}\n\
         .ends\n\
         .subckt outer a b params: rr=5\n\
         x1 a m inner r={rr*2}\n\
         r3 m b 1\n\
         .ends\n\
         x9 1 0 outer rr=7\n\
         v1 1 0 1\n\
         .end\n",
    );
    let names: Vec<&str> = c.elements.iter().map(|e| e.name.as_str()).collect();
    assert_eq!(names, ["r.x9.x1.r1", "r.x9.x1.r2", "r.x9.r3", "v1"]);
    assert_eq!(c.nodes, ["0", "1", "x9.m", "x9.x1.n1"]);
    assert_eq!(
        (
            value(&c, "r.x9.x1.r1"),
            value(&c, "r.x9.x1.r2"),
            value(&c, "r.x9.r3")
        ),
        (14.0, 28.0, 1.0)
    );
    let r1 = c.element("R.X9.X1.R1").map(|e| e.nodes.clone());
    assert_eq!(r1, Some(vec![NodeId(1), NodeId(3)]));
    assert_eq!(c.node("x9.x1.n1"), Some(NodeId(3)));
    assert_eq!(c.params, [("g".to_string(), 2.0)]);
}

#[test]
fn parameter_scoping_matches_ngspice() {
    // ngspice 39: r.x2.r1 = 14, r.x1.r1 = 70 (the last global `y` wins; defaults follow the
    // overrides they depend on); forward references are fine.
    let c = flat(
        "params\n\
         .param x={y*2}\n\
         .param y=3\n\
         .param y=5\n\
         .subckt s a b params: w=2 z={w*y}\n\
         r1 a b {z}\n\
         .ends\n\
         x1 1 0 s w=10\n\
         x2 1 0 s\n\
         .param y=7\n\
         r9 1 0 {x}\n\
         .end\n",
    );
    assert_eq!(
        (value(&c, "r.x1.r1"), value(&c, "r.x2.r1"), value(&c, "r9")),
        (70.0, 14.0, 14.0)
    );
    // Dynamic scoping: `inner` instantiated in `outer` sees outer's `q` (ngspice: 50 and 10);
    // a model in a subcircuit is per instance, `x1:dm`.
    let c = flat(
        "scoping\n\
         .param q=1\n\
         .subckt inner a b\n\
         r1 a b {q*10}\n\
         .ends\n\
         .subckt outer a b params: q=5\n\
         x1 a b inner\n\
         .model dm d is=1e-14\n\
         d1 a b dm\n\
         .ends\n\
         x1 1 0 outer\n\
         x2 1 0 inner\n\
         .end\n",
    );
    assert_eq!(
        (value(&c, "r.x1.x1.r1"), value(&c, "r.x2.r1")),
        (50.0, 10.0)
    );
    let d1 = c
        .element("d.x1.d1")
        .and_then(|d| d.model)
        .map(|m| c.models[m.0 as usize].name.clone());
    assert_eq!(d1.as_deref(), Some("x1:dm"));
}

#[test]
fn models_resolve_lexically_with_local_shadowing() {
    let c = flat(
        "t\n\
         .model dm d is=1e-14\n\
         .subckt s a\n\
         .model dm d is={isat}\n\
         .param isat=2e-14\n\
         d1 a 0 dm\n\
         .subckt t a\n\
         d2 a 0 dm\n\
         .ends\n\
         x1 a t\n\
         .ends\n\
         d0 1 0 dm\n\
         xa 1 s\n\
         .end\n",
    );
    let model = |e: &str| {
        let m = c
            .element(e)
            .and_then(|e| e.model)
            .map(|m| &c.models[m.0 as usize]);
        m.map(|m| (m.name.clone(), m.param("is")))
    };
    assert_eq!(model("d0"), Some(("dm".into(), Some(1e-14))));
    assert_eq!(model("d.xa.d1"), Some(("xa:dm".into(), Some(2e-14))));
    // `t` is defined in `s`: it sees `s`'s model, from the enclosing instance.
    assert_eq!(model("d.xa.x1.d2"), Some(("xa:dm".into(), Some(2e-14))));
}

#[test]
fn ground_globals_controls_and_bare_parameter_values() {
    let c = flat(
        "t\n\
         .global vdd\n\
         .param rval=2k\n\
         .subckt cell in out\n\
         vs in mid 0\n\
         f1 out gnd vs 2\n\
         r1 mid vdd rval\n\
         .ends\n\
         x1 a b cell\n\
         vdd vdd 0 5\n\
         k1 l1 l2 0.5\n\
         l1 a 0 1u\n\
         l2 b 0 1u\n\
         .end\n",
    );
    assert_eq!(c.nodes, ["0", "a", "b", "x1.mid", "vdd"]);
    let f1 = c.element("f.x1.f1");
    assert_eq!(
        f1.map(|f| f.nodes.clone()),
        Some(vec![NodeId(2), NodeId::GROUND])
    );
    let vs = c.elements.iter().position(|e| e.name == "v.x1.vs");
    assert_eq!(f1.map(|f| f.controls[0].0 as usize), vs);
    assert_eq!(value(&c, "r.x1.r1"), 2000.0);
    let k1 = c.element("k1").map(|k| k.controls.len());
    assert_eq!(k1, Some(2));
}

#[test]
fn sources_analyses_options_and_outputs() {
    let c = flat(
        "t\n\
         .param per=10u\n\
         v1 1 0 dc 0 pulse(0 5 0 1n 1n {per/2} {per})\n\
         vin 2 0 dc 1 ac 1\n\
         r1 1 2 1k\n\
         .tran 10n 20u\n\
         .dc vin 0 5 0.1 temp 0 100 50\n\
         .ac dec 10 1 1meg\n\
         .op\n\
         .options reltol=1e-4 method=gear itl4=50 nopage\n\
         .temp 85\n\
         .ic v(1)=0\n\
         .print tran v(1) v(1,2) i(vin)\n\
         .end\n",
    );
    match c
        .element("v1")
        .and_then(|v| v.source.clone())
        .and_then(|s| s.tran)
    {
        Some(Waveform::Pulse { pw, per, .. }) => assert_eq!((pw, per), (Some(5e-6), Some(10e-6))),
        other => panic!("{other:?}"),
    }
    assert!(
        matches!(c.analyses[0].analysis, Analysis::Tran { tstep, tstop, tstart: None, tmax: None, uic: false } if tstep == 10e-9 && tstop == 20e-6)
    );
    match &c.analyses[1].analysis {
        Analysis::Dc { sweeps } => {
            assert!(
                matches!(sweeps[0].target, SweepTarget::Element(id) if c.elements[id.0 as usize].name == "vin")
            );
            assert_eq!(sweeps[1].target, SweepTarget::Temperature);
        }
        other => panic!("{other:?}"),
    }
    assert!(
        matches!(c.analyses[2].analysis, Analysis::Ac { points: 10, fstop, .. } if fstop == 1e6)
    );
    let o = &c.options;
    assert_eq!(
        (o.reltol, o.method, o.temp),
        (Some(1e-4), Some(Method::Gear), Some(85.0))
    );
    assert_eq!(o.other.len(), 2);
    assert_eq!(
        (o.other[0].0.as_str(), &o.other[0].1),
        ("itl4", &OptionValue::Number(50.0))
    );
    assert_eq!(o.other[1].1, OptionValue::Flag);
    assert_eq!(c.initial.len(), 1);
    let probes = &c.outputs[0].probes;
    assert!(matches!(
        probes[1],
        Probe::Voltage {
            pos: NodeId(1),
            neg: Some(NodeId(2)),
            ..
        }
    ));
    assert!(
        matches!(probes[2], Probe::Current { element, .. } if c.elements[element.0 as usize].name == "vin")
    );
}

#[test]
fn subcircuit_errors() {
    let m = messages(
        "t\n\
         .subckt amp in out params: gain=1\n\
         r1 in out 1k\n\
         .ends\n\
         .subckt a n\n\
         xb n b\n\
         .ends\n\
         .subckt b n\n\
         xa n a\n\
         .ends\n\
         x1 1 2 ampp\n\
         x2 1 amp\n\
         x3 1 2 amp gian=2\n\
         x4 1 a\n\
         .end\n",
    );
    assert_eq!(
        m,
        [
            "unknown subcircuit `ampp`",
            "`x2` connects 1 node, but subcircuit `amp` has 2 ports",
            "subcircuit `amp` has no parameter `gian`",
            "subcircuit `a` instantiates itself",
        ]
    );
    let e =
        flat_errors("t\n.subckt a n\nxb n b\n.ends\n.subckt b n\nxa n a\n.ends\nx4 1 a\n.end\n");
    assert!(
        matches!(&e[..], [SpiceError::RecursiveSubckt { chain, .. }] if chain == "a (in x4) -> b (in xb) -> a (in xa)")
    );
    // A subcircuit defined inside another is not visible outside it.
    let m = messages("t\n.subckt outer a\n.subckt inner a\n.ends\n.ends\nx1 1 inner\n.end\n");
    assert_eq!(m, ["unknown subcircuit `inner`"]);
}

#[test]
fn element_errors() {
    let e = flat_errors(
        "t\n\
         .model qm npn bf=100\n\
         .model sw1 sw vt=1\n\
         d1 1 0 dmod\n\
         d2 1 0 qm\n\
         r1 1 0 1k\n\
         r1 2 0 1k\n\
         f1 1 0 vx 2\n\
         h1 1 0 r1 2\n\
         w1 1 0 r1 sw1\n\
         r2 1 0 {1/0}\n\
         r3 1 0 {undefined_p}\n\
         .end\n",
    );
    let m: Vec<String> = e.iter().map(|e| e.to_string()).collect();
    assert_eq!(
        m,
        [
            "unknown model `dmod`",
            "`d2` needs a `d` model, but `qm` is `npn`",
            "element `r1` is defined twice",
            "`w1` needs a `csw` model, but `sw1` is `sw`",
            "division by zero",
            "unknown parameter `undefined_p`",
            "unknown voltage source `vx`",
            "`r1` is not a voltage source",
            "`r1` is not a voltage source",
        ]
    );
}

#[test]
fn card_errors() {
    let m = messages(
        "t\n\
         v1 1 0 1\n\
         r1 1 0 1k\n\
         .tran 0 1m\n\
         .tran 1n 1m 2m\n\
         .ac dec 2.5 1 1k\n\
         .dc vx 0 1 0.1\n\
         .dc v1 0 1 -0.1\n\
         .print tran v(2) i(r9) v(n1)\n\
         .ic v(3)=1\n\
         .options method=euler\n\
         .end\n",
    );
    assert_eq!(
        m,
        [
            "the time step must be positive",
            "the start time must be before the stop time",
            "the number of points must be a whole number from 1",
            "unknown source `vx`",
            "the sweep step must be non-zero, with the sign of stop - start",
            "`method` is `trap` or `gear`",
            "unknown node `3`",
            "unknown node `2`",
            "unknown element `r9`",
            "unknown node `n1`",
        ]
    );
}

#[test]
fn errors_in_a_body_are_reported_once_for_all_instances() {
    let e = flat_errors("t\n.subckt s a\nr1 a 0 {nope}\n.ends\nx1 1 s\nx2 1 s\nx3 1 s\n.end\n");
    assert_eq!(e.len(), 1, "{e:?}");
}

#[test]
fn model_types_and_levels() {
    let c = flat("t\n.model n1 nmos level=2 vto=0.7\nm1 d g 0 0 n1 w=1u l=1u\n.end\n");
    assert_eq!(c.models[0].kind, ModelKind::Nmos);
    assert_eq!(c.models[0].level, Some(2));
    assert_eq!(c.elements[0].kind, ElementKind::M);
    assert_eq!(c.elements[0].param("w"), Some(1e-6));
    let m = messages("t\n.model n1 nmos level=2.5\n.end\n");
    assert_eq!(m, ["the level of model `n1` must be a whole number from 1"]);
}
