//! Real decks end to end: the three reference decks of `shared/cases/spice` (read-only, skipped
//! with a printed reason when the folder is absent), and decks of our own for subcircuits
//! with parameters, nesting, `.include` and `.lib` through the in-memory loader.

use std::path::{Path, PathBuf};

use vams_spice::circuit::{Analysis, Circuit, NodeId, Probe};
use vams_spice::deck::{ElementKind, InitialState, ModelKind, Part, PrintAnalysis, Waveform};
use vams_spice::{FsLoader, MemLoader, SourceMap, flatten, read_deck};

fn cases() -> Option<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/cases/spice");
    if dir.is_dir() {
        Some(dir)
    } else {
        println!("skipped: {} is absent", dir.display());
        None
    }
}

/// Reads and flattens a case deck from the file system, asserting no error and no warning.
fn case(name: &str) -> Option<Circuit> {
    let path = cases()?.join(name);
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) => panic!("{}: {e}", path.display()),
    };
    let mut sources = SourceMap::new();
    let id = sources.add(path.display().to_string(), "work", text);
    let (deck, errors) = read_deck(&mut sources, id, &mut FsLoader);
    assert!(errors.is_empty(), "{errors:#?}");
    assert!(deck.warnings.is_empty(), "{:#?}", deck.warnings);
    match flatten(&deck) {
        Ok(c) => Some(c),
        Err(e) => panic!("{e:#?}"),
    }
}

/// Reads `main` (as `top/main.cir`) with the given in-memory files, and flattens it.
fn mem(main: &str, files: &[(&str, &str)]) -> Circuit {
    let mut sources = SourceMap::new();
    let id = sources.add("top/main.cir", "work", main.to_string());
    let mut loader = MemLoader::new();
    for (p, t) in files {
        loader.insert(*p, *t);
    }
    let (deck, errors) = read_deck(&mut sources, id, &mut loader);
    assert!(errors.is_empty(), "{errors:#?}");
    match flatten(&deck) {
        Ok(c) => c,
        Err(e) => panic!("{e:#?}"),
    }
}

fn count(c: &Circuit, kind: ElementKind) -> usize {
    c.elements.iter().filter(|e| e.kind == kind).count()
}

fn voltages(c: &Circuit, probes: &[Probe]) -> Vec<String> {
    probes
        .iter()
        .map(|p| match p {
            Probe::Voltage { pos, neg: None, .. } => format!("v({})", c.node_name(*pos)),
            Probe::Voltage {
                pos, neg: Some(n), ..
            } => {
                format!("v({},{})", c.node_name(*pos), c.node_name(*n))
            }
            Probe::Current { element, .. } => {
                format!("i({})", c.elements[element.0 as usize].name)
            }
            Probe::All { .. } => "all".into(),
        })
        .collect()
}

#[test]
fn colpitts() {
    let Some(c) = case("colpitts.cir") else {
        return;
    };
    assert!(c.title.starts_with("Colpitts LC oscillator"));
    assert_eq!(c.elements.len(), 9);
    assert_eq!(
        (
            count(&c, ElementKind::R),
            count(&c, ElementKind::C),
            count(&c, ElementKind::L)
        ),
        (3, 2, 1)
    );
    assert_eq!(
        (count(&c, ElementKind::Q), count(&c, ElementKind::V)),
        (1, 2)
    );
    let qnl = c.model("qnl").map(|m| {
        (
            m.kind,
            m.level,
            m.param("bf"),
            m.param("cje"),
            m.param("va"),
        )
    });
    assert_eq!(
        qnl,
        Some((ModelKind::Npn, Some(1), Some(80.0), Some(3e-12), Some(50.0)))
    );
    let m = c.model("qnl");
    assert_eq!(m.and_then(|m| m.param("tf")), Some(0.3e-9));
    assert_eq!(m.and_then(|m| m.param("ccs")), Some(2e-12));
    let q1 = c
        .element("q1")
        .map(|q| (q.nodes.clone(), q.model.is_some()));
    let n = |name: &str| c.node(name).unwrap_or(NodeId(u32::MAX));
    assert_eq!(q1, Some((vec![n("2"), n("1"), n("3")], true)));
    assert_eq!(c.element("l1").map(|l| l.values.clone()), Some(vec![5e-6]));
    assert_eq!(
        c.element("re").map(|r| r.values.clone()),
        Some(vec![4650.0])
    );
    assert_eq!(
        c.element("c2").map(|r| r.values.clone()),
        Some(vec![4500e-12])
    );
    let vee = c.element("vee").and_then(|v| v.source.clone());
    let vee = vee.unwrap_or_default();
    assert_eq!(vee.dc, Some(-10.0));
    match vee.tran {
        Some(Waveform::Pwl {
            points,
            repeat: None,
            delay: None,
        }) => {
            assert_eq!(points, [(0.0, 0.0), (1e-9, -10.0)]);
        }
        other => panic!("{other:?}"),
    }
    assert!(
        matches!(c.analyses[..], [vams_spice::circuit::AnalysisSpec {
        analysis: Analysis::Tran { tstep, tstop, tstart: None, tmax: None, uic: false }, ..
    }] if tstep == 30e-9 && tstop == 12e-6)
    );
    assert_eq!(c.outputs.len(), 1);
    assert_eq!(c.outputs[0].analysis, Some(PrintAnalysis::Tran));
    assert_eq!(voltages(&c, &c.outputs[0].probes), ["v(2)", "v(3)", "v(1)"]);
}

#[test]
fn cmos_schmitt() {
    let Some(c) = case("cmos_schmitt.cir") else {
        return;
    };
    assert_eq!(
        (
            count(&c, ElementKind::M),
            count(&c, ElementKind::V),
            c.elements.len()
        ),
        (6, 2, 8)
    );
    let nenh = c.model("nenh");
    assert_eq!(
        nenh.map(|m| (m.kind, m.level)),
        Some((ModelKind::Nmos, Some(2)))
    );
    let p = |model: &str, name: &str| c.model(model).and_then(|m| m.param(name));
    assert_eq!(p("nenh", "ld"), Some(-0.168e-6));
    assert_eq!(p("nenh", "tox"), Some(241e-10));
    assert_eq!(p("nenh", "nfs"), Some(4.55168e12));
    assert_eq!(
        (p("nenh", "rd"), p("nenh", "rs")),
        (Some(50.0), Some(100.0))
    );
    assert_eq!(p("penh", "vto"), Some(-0.79));
    assert_eq!(p("penh", "xj"), Some(0.112799e-6));
    assert_eq!(c.model("penh").map(|m| m.params.len()), Some(27));
    let mp2 = c.element("mp2");
    assert_eq!(
        mp2.map(|m| (m.param("l"), m.param("w"))),
        Some((Some(1e-6), Some(10e-6)))
    );
    let names: Vec<&str> = mp2
        .map(|m| m.nodes.iter().map(|n| c.node_name(*n)).collect())
        .unwrap_or_default();
    assert_eq!(names, ["2", "7", "6", "1"]);
    // The commented-out mp4 / mn4 are not read.
    assert!(c.element("mp4").is_none());
    match c
        .element("vsrc")
        .and_then(|v| v.source.clone())
        .and_then(|s| s.tran)
    {
        Some(Waveform::Pwl { points, .. }) => {
            assert_eq!(points, [(0.0, 0.0), (10e-6, 5.0), (20e-6, 0.0)])
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(
        c.element("vdd")
            .and_then(|v| v.source.clone())
            .and_then(|s| s.dc),
        Some(5.0)
    );
    assert!(
        matches!(c.analyses[0].analysis, Analysis::Tran { tstep, tstop, .. } if tstep == 10e-9 && tstop == 20e-6)
    );
    assert_eq!(
        voltages(&c, &c.outputs[0].probes),
        ["v(7)", "v(6)", "v(2)", "v(4)"]
    );
}

#[test]
fn switch_hyst() {
    let Some(c) = case("switch_hyst.cir") else {
        return;
    };
    assert_eq!(
        (count(&c, ElementKind::S), count(&c, ElementKind::W)),
        (3, 1)
    );
    assert_eq!(
        (
            count(&c, ElementKind::V),
            count(&c, ElementKind::I),
            count(&c, ElementKind::R)
        ),
        (4, 1, 5)
    );
    let sw = c.model("switch1");
    assert_eq!(
        sw.map(|m| (m.kind, m.param("vt"), m.param("vh"), m.param("roff"))),
        Some((ModelKind::Sw, Some(1.0), Some(0.2), Some(1e4)))
    );
    let csw = c.model("wswitch1");
    assert_eq!(
        csw.map(|m| (m.kind, m.param("it"), m.param("ih"))),
        Some((ModelKind::Csw, Some(1e-3), Some(0.2e-3)))
    );
    let state = |e: &str| c.element(e).and_then(|e| e.state);
    assert_eq!(
        (state("s1"), state("s2"), state("s3"), state("w1")),
        (
            Some(InitialState::Off),
            Some(InitialState::Off),
            Some(InitialState::On),
            Some(InitialState::Off)
        )
    );
    let w1 = c.element("w1");
    let vm3 = c.elements.iter().position(|e| e.name == "vm3");
    assert_eq!(w1.map(|w| w.controls[0].0 as usize), vm3);
    match c
        .element("i3")
        .and_then(|v| v.source.clone())
        .and_then(|s| s.tran)
    {
        Some(Waveform::Pwl { points, .. }) => assert_eq!(points[1], (2e-3, 2e-3)),
        other => panic!("{other:?}"),
    }
    match c.element("v2").and_then(|v| v.source.clone()) {
        Some(s) => {
            assert_eq!(s.dc, Some(0.0));
            assert!(
                matches!(s.tran, Some(Waveform::Pwl { ref points, .. }) if points[0] == (0.0, 0.9))
            );
        }
        None => panic!("no v2"),
    }
    assert!(
        matches!(c.analyses[0].analysis, Analysis::Tran { tstep, tstop, .. } if tstep == 2e-6 && tstop == 5e-3)
    );
    assert_eq!(
        voltages(&c, &c.outputs[0].probes),
        [
            "v(1)", "v(10)", "v(2)", "v(20)", "v(30)", "v(3)", "v(40)", "i(vm3)"
        ]
    );
}

#[test]
fn a_parameterised_hierarchy() {
    let c = mem(
        "parameterised RC ladder\n\
         .param rbase=1k cbase=1n\n\
         .subckt rc in out gnd params: r=1k c=1n\n\
         r1 in out {r}\n\
         c1 out gnd {c}\n\
         .ends rc\n\
         .subckt ladder in out params: scale=1\n\
         x1 in m1 0 rc r={rbase*scale} c={cbase}\n\
         x2 m1 out 0 rc r={rbase*scale*2}\n\
         .ends ladder\n\
         vin in 0 dc 0 ac 1 sin(0 1 1k)\n\
         xl in out ladder scale=3\n\
         rl out 0 1meg\n\
         .ac dec 20 10 100k\n\
         .print ac vdb(out) vp(xl.m1)\n\
         .end\n",
        &[],
    );
    assert_eq!(c.nodes, ["0", "in", "out", "xl.m1"]);
    let v = |e: &str| c.element(e).map(|e| e.values[0]);
    assert_eq!((v("r.xl.x1.r1"), v("r.xl.x2.r1")), (Some(3e3), Some(6e3)));
    assert_eq!((v("c.xl.x1.c1"), v("c.xl.x2.c1")), (Some(1e-9), Some(1e-9)));
    // The `gnd` port is tied to node 0 by the instances.
    assert_eq!(
        c.element("c.xl.x2.c1").map(|e| e.nodes[1]),
        Some(NodeId::GROUND)
    );
    assert!(
        matches!(&c.outputs[0].probes[1], Probe::Voltage { part: Part::Phase, pos, .. } if c.node_name(*pos) == "xl.m1")
    );
}

#[test]
fn includes_and_library_sections() {
    let c = mem(
        "includes\n\
         .include ../lib/opamp.inc\n\
         .lib '../lib/corners.lib' slow\n\
         x1 inp inn out vcc vee opamp gain=1e5\n\
         vcc vcc 0 15\n\
         vee vee 0 -15\n\
         vp inp 0 dc 0.1\n\
         rf out inn 10k\n\
         rg inn 0 1k\n\
         d1 out 0 dclamp\n\
         .op\n\
         .end\n",
        &[
            (
                "lib/opamp.inc",
                "* a behavioural op-amp\n\
                 .subckt opamp in+ in- out vcc vee params: gain=1e4\n\
                 rin in+ in- 1meg\n\
                 e1 mid 0 in+ in- {gain}\n\
                 rout mid out 75\n\
                 .ends opamp\n",
            ),
            (
                "lib/corners.lib",
                ".lib fast\n.model dclamp d is=1e-12\n.endl fast\n\
                 .lib slow\n.model dclamp d is=1e-15 n={nslow}\n.include params.inc\n.endl slow\n",
            ),
            ("lib/params.inc", ".param nslow=1.2\n"),
        ],
    );
    assert_eq!(c.element("e.x1.e1").map(|e| e.values[0]), Some(1e5));
    let nodes: Vec<&str> = c
        .element("r.x1.rin")
        .map(|e| e.nodes.iter().map(|n| c.node_name(*n)).collect())
        .unwrap_or_default();
    assert_eq!(nodes, ["inp", "inn"]);
    let d = c.model("dclamp");
    assert_eq!(
        d.map(|m| (m.param("is"), m.param("n"))),
        Some((Some(1e-15), Some(1.2)))
    );
    assert_eq!(c.params, [("nslow".to_string(), 1.2)]);
}
