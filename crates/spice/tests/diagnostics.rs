//! Golden snapshots of rendered SPICE diagnostics (`render_plain`, as `vams check` prints them
//! when stderr is not a terminal): a wording or span regression is a reviewable diff.

use vams_spice::{MemLoader, SourceMap, SpiceError, flatten, read_deck};
use vams_syntax::diagnostics::render_plain;

/// Every diagnostic of a deck: the reader's warnings and errors, then `flatten`'s.
fn render(deck_text: &str, files: &[(&str, &str)]) -> String {
    let mut sources = SourceMap::new();
    let id = sources.add("bad.cir", "work", deck_text.to_string());
    let mut loader = MemLoader::new();
    for (p, t) in files {
        loader.insert(*p, *t);
    }
    let (deck, errors) = read_deck(&mut sources, id, &mut loader);
    let mut all: Vec<SpiceError> = deck.warnings.clone();
    all.extend(errors.iter().cloned());
    if errors.is_empty() {
        if let Err(e) = flatten(&deck) {
            all.extend(e);
        }
    }
    all.iter()
        .map(|d| render_plain(d, &sources))
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn unknown_parameter_in_a_subcircuit() {
    insta::assert_snapshot!(render(
        "divider\n\
         .param rtop=10k\n\
         .subckt div in out params: ratio=0.5\n\
         r1 in out {rtpo*(1-ratio)}\n\
         r2 out 0 {rtop*ratio}\n\
         .ends\n\
         x1 a b div\n\
         v1 a 0 1\n\
         .end\n",
        &[],
    ));
}

#[test]
fn parameter_cycle_and_division_by_zero() {
    insta::assert_snapshot!(render(
        "params\n\
         .param a={b*2} b={c+1} c={a}\n\
         .param w=0\n\
         r1 1 0 {1k/w}\n\
         v1 1 0 1\n\
         .end\n",
        &[],
    ));
}

#[test]
fn subcircuit_mistakes() {
    insta::assert_snapshot!(render(
        "instances\n\
         .subckt buffer in out\n\
         e1 out 0 in 0 1\n\
         .ends\n\
         .subckt ping a\n\
         x1 a pong\n\
         .ends\n\
         .subckt pong a\n\
         x1 a ping\n\
         .ends\n\
         x1 1 2 bufer\n\
         x2 1 buffer\n\
         x3 1 ping\n\
         .end\n",
        &[],
    ));
}

#[test]
fn reader_errors_are_all_reported() {
    insta::assert_snapshot!(render(
        "several bad lines\n\
         r1 a b 1k5\n\
         y1 a b 1\n\
         .fourier v(a)\n\
         .tarn 1n 1u\n\
         c1 a b {1p*\n\
         .model qx bjt(bf=100)\n\
         .control\n\
         run\n\
         .endc\n\
         .end\n",
        &[],
    ));
}

#[test]
fn include_problems() {
    insta::assert_snapshot!(render(
        "includes\n\
         .include \"models/missing.lib\"\n\
         .include models/bad.inc\n\
         .lib models/corners.lib typ\n\
         .end\n",
        &[
            (
                "models/bad.inc",
                "* a file with a mistake\nr1 a b 1meg\nr2 a b 10Kohm\nr3 a b 2..5\n"
            ),
            ("models/corners.lib", ".lib tt\n.endl\n.lib ff\n.endl\n"),
        ],
    ));
}

#[test]
fn models_and_references() {
    insta::assert_snapshot!(render(
        "references\n\
         .model qn npn bf=100\n\
         q1 c b 0 qp\n\
         d1 a 0 qn\n\
         r1 a 0 1k\n\
         r1 a b 2k\n\
         f1 a 0 vsense 2\n\
         .print tran v(c) v(x1.n2)\n\
         .tran 1n 1u\n\
         .end\n",
        &[],
    ));
}
