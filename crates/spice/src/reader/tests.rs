//! The reader's unit tests: element shapes, cards, structure, includes, recovery, and that
//! no input makes it (or `flatten` after it) panic.

use proptest::prelude::*;

use crate::deck::{
    AcScale, Analysis, ElementKind, InitialState, ModelKind, OptionValue, OutputCard, Part,
    PrintAnalysis, Vector, Waveform,
};
use crate::error::SpiceError;
use crate::expr::Expr;
use crate::flatten::flatten;
use crate::test_support::{config, read_ok, read_with};

fn num(e: &Expr) -> f64 {
    match e.as_num() {
        Some(v) => v,
        None => panic!("not a number: {e:?}"),
    }
}

fn nums(es: &[Expr]) -> Vec<f64> {
    es.iter().map(num).collect()
}

fn keys(names: &[crate::deck::Name]) -> Vec<&str> {
    names.iter().map(|n| n.key.as_str()).collect()
}

fn errors(text: &str) -> Vec<SpiceError> {
    read_with(text, &[]).1
}

#[test]
fn element_shapes() {
    let deck = read_ok(
        "title\n\
         R1 A B 10Kohm tc1=0.001\n\
         c2 a 0 2pf ic=1\n\
         l3 a b 5uH\n\
         k1 l3 l4 0.99\n\
         e1 o 0 a b 2\n\
         f1 o 0 vsense 3\n\
         g1 o 0 a b 1m\n\
         h1 o 0 vsense 1k\n\
         s1 10 0 1 0 switch1 OFF\n\
         w1 40 0 vm3 wswitch1 on\n\
         d1 a k dmod 2 off\n\
         q1 2 1 3 qnl\n\
         q2 c b e s qnl 1.5\n\
         mp1 2 7 1 1 penh l=1.0u w=10.0u\n\
         x1 in out amp params: gain=3\n\
         r5 a b r=5k\n\
         r6 a b rval\n\
         .end\n",
    );
    let els = &deck.body.elements;
    assert_eq!(els.len(), 17);
    let r1 = &els[0];
    assert_eq!(
        (r1.kind, r1.name.key.as_str(), r1.name.text.as_str()),
        (ElementKind::R, "r1", "R1")
    );
    assert_eq!(keys(&r1.nodes), ["a", "b"]);
    assert_eq!(nums(&r1.values), [1e4]);
    assert_eq!(r1.params[0].name.key, "tc1");
    assert_eq!(nums(&els[1].values), [2e-12]);
    assert_eq!(els[1].params[0].name.key, "ic");
    assert_eq!(nums(&els[2].values), [5e-6]);
    assert_eq!(keys(&els[3].controls), ["l3", "l4"]);
    assert_eq!(nums(&els[3].values), [0.99]);
    assert_eq!(keys(&els[4].nodes), ["o", "0", "a", "b"]);
    assert_eq!(keys(&els[5].controls), ["vsense"]);
    assert_eq!(nums(&els[7].values), [1e3]);
    let s1 = &els[8];
    assert_eq!(keys(&s1.nodes), ["10", "0", "1", "0"]);
    assert_eq!(s1.model.as_ref().map(|m| m.key.as_str()), Some("switch1"));
    assert_eq!(s1.state, Some(InitialState::Off));
    let w1 = &els[9];
    assert_eq!(
        (keys(&w1.nodes), keys(&w1.controls)),
        (vec!["40", "0"], vec!["vm3"])
    );
    assert_eq!(w1.state, Some(InitialState::On));
    let d1 = &els[10];
    assert_eq!(
        (nums(&d1.values), d1.state),
        (vec![2.0], Some(InitialState::Off))
    );
    assert_eq!(keys(&els[11].nodes), ["2", "1", "3"]);
    assert_eq!(keys(&els[12].nodes), ["c", "b", "e", "s"]);
    assert_eq!(nums(&els[12].values), [1.5]);
    let mp1 = &els[13];
    assert_eq!(keys(&mp1.nodes), ["2", "7", "1", "1"]);
    assert_eq!(mp1.params.len(), 2);
    assert_eq!(num(&mp1.params[1].value), 10e-6);
    let x1 = &els[14];
    assert_eq!(
        (keys(&x1.nodes), x1.model.as_ref().map(|m| m.key.as_str())),
        (vec!["in", "out"], Some("amp"))
    );
    assert_eq!(x1.params[0].name.key, "gain");
    assert_eq!(nums(&els[15].values), [5e3]);
    assert!(els[15].params.is_empty());
    assert_eq!(els[16].model.as_ref().map(|m| m.key.as_str()), Some("rval"));
}

#[test]
fn independent_sources() {
    let deck = read_ok(
        "t\n\
         vee 6 0 dc -10 pwl 0 0 1e-9 -10\n\
         v1 1 0 DC 0.0 PWL (0 0 2e-3 2 4e-3 0)\n\
         v2 1 0 pulse(0 5 1n 1n 1n 5u 10u)\n\
         v3 1 0 sin 0 1 1k ac 1\n\
         v4 1 0 5\n\
         i1 1 0 dc 1m ac 1 90\n\
         v5 1 0 exp(0, 1, 1u, 1u)\n\
         v6 1 0 ac\n\
         v7 1 0 pwl(0 0 1 1) r=0 td=1m\n\
         v8 1 0 {vdd*2}\n\
         .end\n",
    );
    let src = |i: usize| deck.body.elements[i].source.clone().unwrap_or_default();
    let vee = src(0);
    assert_eq!(vee.dc.as_ref().map(num), Some(-10.0));
    match vee.tran {
        Some(Waveform::Pwl { points, .. }) => {
            let p: Vec<(f64, f64)> = points.iter().map(|(t, v)| (num(t), num(v))).collect();
            assert_eq!(p, [(0.0, 0.0), (1e-9, -10.0)]);
        }
        other => panic!("{other:?}"),
    }
    match src(1).tran {
        Some(Waveform::Pwl { points, .. }) => assert_eq!(points.len(), 3),
        other => panic!("{other:?}"),
    }
    match src(2).tran {
        Some(Waveform::Pulse { v2, per, np, .. }) => {
            assert_eq!(
                (num(&v2), per.as_ref().map(num), np),
                (5.0, Some(10e-6), None)
            );
        }
        other => panic!("{other:?}"),
    }
    let v3 = src(3);
    assert!(
        matches!(v3.tran, Some(Waveform::Sin { freq: Some(ref f), td: None, .. }) if num(f) == 1e3)
    );
    assert_eq!(v3.ac.and_then(|a| a.mag).as_ref().map(num), Some(1.0));
    assert_eq!(src(4).dc.as_ref().map(num), Some(5.0));
    let i1 = src(5).ac.unwrap_or(crate::deck::Ac {
        mag: None,
        phase: None,
    });
    assert_eq!(
        (i1.mag.as_ref().map(num), i1.phase.as_ref().map(num)),
        (Some(1.0), Some(90.0))
    );
    assert!(matches!(
        src(6).tran,
        Some(Waveform::Exp {
            tau1: Some(_),
            td2: None,
            ..
        })
    ));
    assert!(matches!(
        src(7).ac,
        Some(crate::deck::Ac {
            mag: None,
            phase: None
        })
    ));
    assert!(matches!(
        src(8).tran,
        Some(Waveform::Pwl {
            repeat: Some(_),
            delay: Some(_),
            ..
        })
    ));
    assert!(matches!(
        src(9).dc,
        Some(Expr {
            kind: crate::expr::ExprKind::Binary(..),
            ..
        })
    ));
}

#[test]
fn source_errors() {
    let errs = errors(
        "t\nv1 1 0 pwl(0 0 1)\nv2 1 0 sffm(0 1 1k)\nv3 1 0 pulse(0)\nv4 1 0 sin(0 1\n.end\n",
    );
    let msgs: Vec<String> = errs.iter().map(|e| e.to_string()).collect();
    assert_eq!(msgs.len(), 4, "{msgs:?}");
    assert!(msgs[0].contains("`PWL` with an odd number of values (3)"));
    assert!(msgs[1].contains("`sffm` is not read yet"));
    assert!(msgs[2].contains("`PULSE` with 1 argument"));
    assert!(msgs[3].contains("`sin(` is not closed"));
}

#[test]
fn behavioural_controlled_sources_are_refused_clearly() {
    let errs = errors("t\ne1 o 0 value={v(a)*2}\ng1 o 0 poly(1) a 0 1 2\n.end\n");
    let msgs: Vec<String> = errs.iter().map(|e| e.to_string()).collect();
    assert_eq!(
        msgs,
        [
            "the `value` form of a controlled source is not read yet",
            "the `poly` form of a controlled source is not read yet"
        ]
    );
}

#[test]
fn models_in_both_forms() {
    let deck = read_ok(
        "t\n\
         .model qnl npn(level=1 bf=80 rb=100 ccs=2pf tf=0.3ns)\n\
         .model switch1 sw vt=1 vh=0.2 ron=1 roff=10k\n\
         .model nenh NMOS\n\
         +    Level=2            Ld=-0.168u\n\
         +    Mjsw=.195\trd = 50\trs=100\n\
         .model d1 d (is=1e-14, n=1.5)\n\
         .end\n",
    );
    let m = &deck.body.models;
    assert_eq!(m.len(), 4);
    assert_eq!(
        (m[0].kind, m[0].level.as_ref().map(num)),
        (ModelKind::Npn, Some(1.0))
    );
    let p: Vec<(&str, f64)> = m[0]
        .params
        .iter()
        .map(|p| (p.name.key.as_str(), num(&p.value)))
        .collect();
    assert_eq!(
        p,
        [("bf", 80.0), ("rb", 100.0), ("ccs", 2e-12), ("tf", 0.3e-9)]
    );
    assert_eq!((m[1].kind, m[1].params.len()), (ModelKind::Sw, 4));
    assert_eq!(
        (m[2].kind, m[2].level.as_ref().map(num)),
        (ModelKind::Nmos, Some(2.0))
    );
    let p: Vec<(&str, f64)> = m[2]
        .params
        .iter()
        .map(|p| (p.name.key.as_str(), num(&p.value)))
        .collect();
    assert_eq!(
        p,
        [
            ("ld", -0.168e-6),
            ("mjsw", 0.195),
            ("rd", 50.0),
            ("rs", 100.0)
        ]
    );
    assert_eq!(m[3].params.len(), 2);
}

#[test]
fn subcircuits_nest_and_take_params() {
    let deck = read_ok(
        "t\n\
         .param vdd=5 gain = 2*vdd+1\n\
         .subckt amp in out params: g=2 r={1k*g}\n\
         .subckt stage a b\n\
         r1 a b 1k\n\
         .ends stage\n\
         x1 in mid stage\n\
         .model dm d is=1e-14\n\
         .ends amp\n\
         x1 1 2 amp g=3\n\
         .end\n",
    );
    let top = &deck.body;
    assert_eq!(
        (top.params.len(), top.subckts.len(), top.elements.len()),
        (2, 1, 1)
    );
    let amp = &top.subckts[0];
    assert_eq!(keys(&amp.ports), ["in", "out"]);
    assert_eq!(
        amp.params
            .iter()
            .map(|p| p.name.key.as_str())
            .collect::<Vec<_>>(),
        ["g", "r"]
    );
    assert_eq!(
        (
            amp.body.subckts.len(),
            amp.body.elements.len(),
            amp.body.models.len()
        ),
        (1, 1, 1)
    );
    assert_eq!(amp.body.subckts[0].body.elements.len(), 1);
}

#[test]
fn structure_errors() {
    let errs =
        errors("t\n.subckt a n1\nr1 n1 0 1\n.ends b\n.ends\n.subckt open x\nr2 x 0 1\n.end\n");
    let msgs: Vec<String> = errs.iter().map(|e| e.to_string()).collect();
    assert_eq!(
        msgs,
        [
            "`.ends b` closes subcircuit `a`",
            "`.ends` closes nothing",
            "subcircuit `open` is not closed"
        ]
    );
    let errs = errors("t\n.subckt a n\n.ends\n.subckt A n\n.ends\n.model m d\n.model M d\n.end\n");
    assert_eq!(errs.len(), 2);
    assert!(errs.iter().all(|e| matches!(e, SpiceError::DuplicateDefinition { first_line, .. } if *first_line == 2 || *first_line == 6)));
}

#[test]
fn cards() {
    let deck = read_ok(
        "t\n\
         .options reltol=1e-4 method=gear noinit\n\
         .temp 50\n\
         .ic v(1)=0 v(out)=2.5\n\
         .nodeset v(2)=1\n\
         .tran 10n 20u 0 1n uic\n\
         .op\n\
         .dc vin 0 5 0.1 vdd 1 3 1\n\
         .ac dec 10 1 1meg\n\
         .print tran v(7) v(a, b) i(vm3)\n\
         .print ac vdb(2) vp(2)\n\
         .save all v(x1.n3) out\n\
         .probe v(1)\n\
         .global vdd vss\n\
         .title a better title\n\
         .end\n",
    );
    assert_eq!(deck.title, "a better title");
    assert_eq!(deck.options.len(), 3);
    assert!(matches!(deck.options[1].value, Some(OptionValue::Word(ref w)) if w.key == "gear"));
    assert!(deck.options[2].value.is_none());
    assert_eq!(nums(&deck.temps), [50.0]);
    assert_eq!(deck.initial.len(), 2);
    assert_eq!(deck.initial[1].node.key, "out");
    assert_eq!(deck.nodesets.len(), 1);
    match &deck.analyses[0].analysis {
        Analysis::Tran {
            tstep,
            tstop,
            tstart,
            tmax,
            uic,
        } => {
            assert_eq!((num(tstep), num(tstop)), (10e-9, 20e-6));
            assert_eq!(
                (tstart.as_ref().map(num), tmax.as_ref().map(num), *uic),
                (Some(0.0), Some(1e-9), true)
            );
        }
        other => panic!("{other:?}"),
    }
    assert!(matches!(deck.analyses[1].analysis, Analysis::Op));
    assert!(
        matches!(&deck.analyses[2].analysis, Analysis::Dc { sweeps } if sweeps.len() == 2 && sweeps[1].target.key == "vdd")
    );
    assert!(
        matches!(&deck.analyses[3].analysis, Analysis::Ac { scale: AcScale::Dec, points, .. } if num(points) == 10.0)
    );
    let p = &deck.outputs[0];
    assert_eq!(
        (p.card, p.analysis, p.vectors.len()),
        (OutputCard::Print, Some(PrintAnalysis::Tran), 3)
    );
    assert!(
        matches!(&p.vectors[1], Vector::Voltage { pos, neg: Some(n), .. } if pos.key == "a" && n.key == "b")
    );
    assert!(matches!(&p.vectors[2], Vector::Current { element, .. } if element.key == "vm3"));
    assert!(matches!(
        &deck.outputs[1].vectors[0],
        Vector::Voltage { part: Part::Db, .. }
    ));
    let save = &deck.outputs[2];
    assert_eq!((save.card, save.analysis), (OutputCard::Save, None));
    assert!(matches!(&save.vectors[0], Vector::All { .. }));
    assert!(matches!(&save.vectors[1], Vector::Voltage { pos, .. } if pos.key == "x1.n3"));
    assert!(matches!(&save.vectors[2], Vector::Voltage { pos, .. } if pos.key == "out"));
    assert_eq!(keys(&deck.globals), ["vdd", "vss"]);
}

#[test]
fn params_take_bare_expressions() {
    let deck = read_ok(
        "t\n.param a=1 b = 2 * a + 1, c={a+b} d='max(a, b)' e=max(a, b) f = -a\n+ g=1k\n.end\n",
    );
    let names: Vec<&str> = deck
        .body
        .params
        .iter()
        .map(|p| p.name.key.as_str())
        .collect();
    assert_eq!(names, ["a", "b", "c", "d", "e", "f", "g"]);
    assert_eq!(num(&deck.body.params[6].value), 1e3);
    let errs = errors("t\n.param f(x)=x*2\n.param\n.param a=\n.end\n");
    assert_eq!(errs.len(), 3, "{errs:?}");
    assert!(matches!(&errs[0], SpiceError::Syntax { help: Some(h), .. } if h.contains(".func")));
}

#[test]
fn warnings_and_unknown_cards() {
    let (deck, errs, _) = read_with(
        "t\n.control\nrun\n.endc\n.width out=80\n.fourier v(1)\n.noise v(1) v1 dec 10 1 1k\n.end\n",
        &[],
    );
    assert_eq!(deck.warnings.len(), 2);
    assert!(deck.warnings.iter().all(SpiceError::is_warning));
    assert_eq!(errs.len(), 2);
    assert!(
        matches!(&errs[0], SpiceError::UnknownCard { card, help, .. } if card == ".fourier" && help.contains("ngspice card"))
    );
    assert!(matches!(&errs[1], SpiceError::UnknownCard { card, .. } if card == ".noise"));
    let errs = errors("t\n.tram 1n 1u\n.end\n");
    assert!(
        matches!(&errs[0], SpiceError::UnknownCard { help, .. } if help == "did you mean `.tran`?")
    );
    let (deck, _, _) = read_with("t\nr1 a b 1\n", &[]);
    assert!(matches!(deck.warnings[..], [SpiceError::NoEnd { .. }]));
}

#[test]
fn every_bad_line_is_reported_and_the_rest_read() {
    let (deck, errs, _) = read_with(
        "t\n\
         r1 a b 1k5\n\
         y1 a b 1\n\
         r2 a b 1k\n\
         c1 a\n\
         .tran 1n\n\
         q1 1 2 3\n\
         r3 a b {1k*}\n\
         .model m bjt(bf=1)\n\
         v1 a 0 1\n\
         .end\n",
        &[],
    );
    let codes: Vec<String> = errs
        .iter()
        .map(|e| {
            miette::Diagnostic::code(e)
                .map(|c| c.to_string())
                .unwrap_or_default()
        })
        .collect();
    assert_eq!(
        codes,
        [
            "vams::spice::bad_number",
            "vams::spice::unknown_element",
            "vams::spice::syntax",
            "vams::spice::syntax",
            "vams::spice::syntax",
            "vams::spice::syntax",
            "vams::spice::unknown_model_type"
        ]
    );
    let names: Vec<&str> = deck
        .body
        .elements
        .iter()
        .map(|e| e.name.key.as_str())
        .collect();
    assert_eq!(names, ["r2", "v1"]);
}

#[test]
fn includes_are_spliced_and_located() {
    let (deck, errs, sources) = read_with(
        "t\n\
         .include \"lib/models.inc\"\n\
         .inc lib/sub.inc\n\
         x1 a b buf\n\
         .end\n",
        &[
            ("lib/models.inc", ".model dm d is=1e-14\n"),
            (
                "lib/sub.inc",
                "* a subcircuit\n.subckt buf a b\n.include ./deeper/r.inc\n.ends\n",
            ),
            ("lib/deeper/r.inc", "r1 a b {oops\nr2 a b 1\n"),
        ],
    );
    assert_eq!(deck.files.len(), 4);
    assert_eq!(deck.body.models.len(), 1);
    assert_eq!(deck.body.subckts[0].body.elements.len(), 1);
    // The error in the innermost file points into it.
    assert_eq!(errs.len(), 1);
    let span = errs[0].span();
    assert_eq!(sources.file(span.file).name, "lib/deeper/r.inc");
    assert_eq!(sources.snippet(span), "{");
    let model = &deck.body.models[0];
    assert_eq!(sources.snippet(model.name.span), "dm");
}

#[test]
fn include_errors() {
    let (_, errs, sources) = read_with(
        "t\n.include missing.inc\n.include a.inc\n.end\n",
        &[("a.inc", ".include b.inc\n"), ("b.inc", ".include a.inc\n")],
    );
    assert_eq!(errs.len(), 2, "{errs:?}");
    assert!(matches!(&errs[0], SpiceError::IncludeNotFound { path, .. } if path == "missing.inc"));
    match &errs[1] {
        SpiceError::IncludeCycle { chain, span, .. } => {
            assert_eq!(chain, "a.inc -> b.inc -> a.inc");
            assert_eq!(sources.file(span.file).name, "b.inc");
        }
        other => panic!("{other:?}"),
    }
    let (_, errs, _) = read_with(
        "t\n.include deck.cir\n.end\n",
        &[("deck.cir", "r1 a b 1\n")],
    );
    assert!(matches!(&errs[..], [SpiceError::IncludeCycle { .. }]));
}

#[test]
fn library_sections() {
    let lib = "* corner library\n\
               .lib tt\n\
               .model nch nmos level=1 vto=0.7\n\
               .endl tt\n\
               .lib ff\n\
               .model nch nmos level=1 vto=0.6\n\
               .lib models.lib common\n\
               .endl\n\
               .lib common\n\
               .param lmin=0.18u\n\
               .endl\n";
    let (deck, errs, _) = read_with("t\n.lib models.lib ff\n.end\n", &[("models.lib", lib)]);
    assert!(errs.is_empty(), "{errs:?}");
    assert_eq!(deck.body.models.len(), 1);
    assert_eq!(num(&deck.body.models[0].params[0].value), 0.6);
    assert_eq!(deck.body.params[0].name.key, "lmin");
    let (_, errs, _) = read_with("t\n.lib models.lib fs\n.end\n", &[("models.lib", lib)]);
    match &errs[..] {
        [
            SpiceError::LibSection {
                available,
                suggestion,
                ..
            },
        ] => {
            assert_eq!(available, "tt, ff, common");
            assert_eq!(suggestion.as_deref(), Some("ff"));
        }
        other => panic!("{other:?}"),
    }
    let (_, errs, _) = read_with(
        "t\n.lib self.lib a\n.end\n",
        &[("self.lib", ".lib a\n.lib self.lib a\n.endl\n")],
    );
    assert!(
        matches!(&errs[..], [SpiceError::IncludeCycle { chain, .. }] if chain.contains("(section a)"))
    );
    // A section definition in a file read whole is skipped.
    let deck = read_ok("t\n.lib unused\nr9 a b 1\n.endl\nr1 a b 1\n.end\n");
    assert_eq!(deck.body.elements.len(), 1);
}

/// SPICE-ish fragments, to reach deeper than random characters do.
fn fragment() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("r1 a b 1k\n".to_string()),
        Just(".subckt s a b params: p=1\n".to_string()),
        Just(".ends\n".to_string()),
        Just("x1 a b s p={p*2}\n".to_string()),
        Just("x2 a s\n".to_string()),
        Just(".param p={q} q={p}\n".to_string()),
        Just("v1 a 0 dc 1 pwl(0 0 1 1)\n".to_string()),
        Just(".model m d(is=1e-14)\n".to_string()),
        Just("d1 a 0 m\n".to_string()),
        Just(".tran 1n 1u\n".to_string()),
        Just(".print tran v(a) i(v1) v(x1.a)\n".to_string()),
        Just("+ 2 ( ) = { } ' \" ;$*\n".to_string()),
        Just(".include x.inc\n".to_string()),
        Just(".lib x.inc s\n".to_string()),
        Just(".control\n".to_string()),
        Just("f1 a 0 v1 2\n".to_string()),
        "[ -~]{0,30}\n",
    ]
}

proptest! {
    #![proptest_config(config(300))]

    #[test]
    fn no_text_makes_the_reader_or_flatten_panic(text in "\\PC{0,200}") {
        let (deck, _, _) = read_with(&text, &[("x.inc", ".lib s\nr5 a b 1\n.endl\n")]);
        let _ = flatten(&deck);
    }

    #[test]
    fn no_bytes_make_it_panic(bytes in proptest::collection::vec(any::<u8>(), 0..300)) {
        let text = String::from_utf8_lossy(&bytes);
        let (deck, _, _) = read_with(&text, &[]);
        let _ = flatten(&deck);
    }

    #[test]
    fn no_deck_of_fragments_makes_it_panic(parts in proptest::collection::vec(fragment(), 0..25)) {
        let text = format!("title\n{}", parts.concat());
        let (deck, _, _) = read_with(&text, &[("x.inc", ".lib s\nx9 a b s\n.endl\n.subckt s a b\n")]);
        let _ = flatten(&deck);
    }
}
