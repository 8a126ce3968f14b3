//! The VCD writer, checked by reading its output back with a small parser of the format.

use super::*;
use crate::output::csv::tests::synthetic;
use std::collections::HashMap;

#[derive(Debug)]
struct Var {
    scope: String,
    ty: String,
    width: u32,
    name: String,
}

#[derive(Debug, Default)]
struct Dump {
    timescale: String,
    vars: HashMap<String, Var>,
    /// (time, id, value) in file order.
    changes: Vec<(u64, String, String)>,
}

fn parse(text: &str) -> Dump {
    let mut dump = Dump::default();
    let mut scopes: Vec<String> = Vec::new();
    let mut tokens = text.split_whitespace().peekable();
    let mut time = None;
    while let Some(tok) = tokens.next() {
        match tok {
            "$timescale" => {
                let mut parts = Vec::new();
                for t in tokens.by_ref() {
                    if t == "$end" {
                        break;
                    }
                    parts.push(t);
                }
                dump.timescale = parts.join(" ");
            }
            "$scope" => {
                assert_eq!(tokens.next(), Some("module"));
                scopes.push(tokens.next().unwrap().to_string());
                assert_eq!(tokens.next(), Some("$end"));
            }
            "$upscope" => {
                scopes.pop().expect("balanced scopes");
                assert_eq!(tokens.next(), Some("$end"));
            }
            "$var" => {
                let ty = tokens.next().unwrap().to_string();
                let width = tokens.next().unwrap().parse().unwrap();
                let id = tokens.next().unwrap().to_string();
                let name = tokens.next().unwrap().to_string();
                assert_eq!(tokens.next(), Some("$end"));
                let var = Var {
                    scope: scopes.join("."),
                    ty,
                    width,
                    name,
                };
                assert!(dump.vars.insert(id, var).is_none(), "duplicate id");
            }
            "$version" | "$enddefinitions" => {
                for _ in tokens.by_ref().take_while(|t| *t != "$end") {}
            }
            "$dumpvars" | "$end" => {}
            t if t.starts_with('#') => {
                assert!(scopes.is_empty(), "changes after an unclosed scope");
                let now: u64 = t[1..].parse().unwrap();
                assert!(
                    time.is_none_or(|before| now > before),
                    "times must increase"
                );
                time = Some(now);
            }
            t if t.starts_with('r') || t.starts_with('b') => {
                let id = tokens.next().unwrap().to_string();
                dump.changes.push((time.unwrap(), id, t.to_string()));
            }
            t => {
                let (value, id) = t.split_at(1);
                assert!("01xz".contains(value), "bad scalar change {t}");
                dump.changes
                    .push((time.unwrap(), id.to_string(), value.to_string()));
            }
        }
    }
    assert!(scopes.is_empty());
    dump
}

fn written() -> (Waveforms, Dump) {
    let wf = synthetic();
    let mut out = Vec::new();
    write_vcd(&mut out, &wf, "tb_servo", None).unwrap();
    let text = String::from_utf8(out).unwrap();
    (wf, parse(&text))
}

fn id_of<'a>(dump: &'a Dump, scope: &str, name: &str) -> &'a str {
    dump.vars
        .iter()
        .find(|(_, v)| v.scope == scope && v.name == name)
        .map(|(id, _)| id.as_str())
        .unwrap_or_else(|| panic!("no {scope}.{name} in {:?}", dump.vars))
}

fn history<'a>(dump: &'a Dump, id: &str) -> Vec<(u64, &'a str)> {
    dump.changes
        .iter()
        .filter(|(_, i, _)| i == id)
        .map(|(t, _, v)| (*t, v.as_str()))
        .collect()
}

#[test]
fn header_declares_every_probe_in_its_scope_with_its_kind() {
    let (_, dump) = written();
    assert_eq!(dump.timescale, "1 fs");
    assert_eq!(dump.vars.len(), 5);
    let types: Vec<(&str, u32)> = [
        ("tb_servo", "vout"),
        ("tb_servo.dut.u_ic", "ov"),
        ("tb_servo.dut.u_ic", "en"),
        ("tb_servo.dut", "state"),
        ("tb_servo.dut.u_motor", "i"),
    ]
    .iter()
    .map(|(s, n)| {
        let v = &dump.vars[id_of(&dump, s, n)];
        (v.ty.as_str(), v.width)
    })
    .collect();
    assert_eq!(
        types,
        [
            ("real", 64),
            ("wire", 1),
            ("wire", 1),
            ("integer", 64),
            ("real", 64)
        ]
    );
}

#[test]
fn changes_only_with_collapsed_discontinuities() {
    let (wf, dump) = written();
    // Times 0, 1 ms, 2 ms (twice: the before/after pair collapses), 100 ms, 1/3 s.
    let stamps = [0u64, MS, 2 * MS, 100 * MS, 333_333_333_333_333];
    let ov = history(&dump, id_of(&dump, "tb_servo.dut.u_ic", "ov"));
    assert_eq!(ov, [(0, "0"), (2 * MS, "1"), (333_333_333_333_333, "0")]);
    let en = history(&dump, id_of(&dump, "tb_servo.dut.u_ic", "en"));
    // U, 0, (1 then) Z, H -> x 0 z 1; the final H repeats and is not written again.
    assert_eq!(en, [(0, "x"), (MS, "0"), (2 * MS, "z"), (100 * MS, "1")]);
    let state = history(&dump, id_of(&dump, "tb_servo.dut", "state"));
    assert_eq!(
        state,
        [(0, "b0"), (MS, "b1"), (2 * MS, "b10"), (100 * MS, "b0")]
    );
    // Reals read back exactly, at every distinct stamp (all values differ).
    let vout = history(&dump, id_of(&dump, "tb_servo", "vout"));
    let rows = [0usize, 1, 3, 4, 5];
    assert_eq!(vout.len(), rows.len());
    for ((t, v), (&stamp, &row)) in vout.iter().zip(stamps.iter().zip(rows.iter())) {
        assert_eq!(*t, stamp);
        assert_eq!(v[1..].parse::<f64>().unwrap(), wf.columns[0].values[row]);
    }
    let i = history(&dump, id_of(&dump, "tb_servo.dut.u_motor", "i"));
    assert_eq!(i[0].1, "r-2e-9");
}

/// A millisecond in femtoseconds, the VCD's unit.
const MS: u64 = 1_000_000_000_000;

/// Events 1 fs apart stay apart and in order; long runs take a coarser unit.
#[test]
fn femtosecond_stamps_and_units_for_long_runs() {
    let mut wf = synthetic();
    wf.times = vec![0.0, 1e-15, 2e-15, 2e-15, 0.009, 6.0];
    let mut out = Vec::new();
    write_vcd(&mut out, &wf, "tb", None).unwrap();
    let dump = parse(&String::from_utf8(out).unwrap());
    let ov = history(&dump, id_of(&dump, "tb.dut.u_ic", "ov"));
    assert_eq!(ov, [(0, "0"), (2, "1"), (6000 * MS, "0")]);
    let state = history(&dump, id_of(&dump, "tb.dut", "state"));
    assert_eq!(state, [(0, "b0"), (1, "b1"), (2, "b10"), (9 * MS, "b0")]);
    assert_eq!(time_unit(6.0), (1e-15, "fs"));
    assert_eq!(time_unit(1e5), (1e-12, "ps"));
    assert_eq!(time_unit(1e9), (1e-9, "ns"));
    assert_eq!(time_unit(1e30), (1.0, "s"));
}

#[test]
fn identifier_codes_are_distinct_and_printable() {
    let codes: Vec<String> = (0..20_000).map(id_code).collect();
    let unique: std::collections::HashSet<&String> = codes.iter().collect();
    assert_eq!(unique.len(), codes.len());
    assert!(
        codes
            .iter()
            .all(|c| c.bytes().all(|b| (33..=126).contains(&b)))
    );
    assert_eq!(codes[0], "!");
    assert_eq!(codes[93], "~");
    assert_eq!(codes[94].len(), 2);
}

#[test]
fn negative_integers_are_twos_complement() {
    assert_eq!(
        encode(Presentation::Integer, -1.0).0,
        format!("b{}", "1".repeat(64))
    );
    assert_eq!(encode(Presentation::Integer, 5.0).0, "b101");
    assert_eq!(encode(Presentation::Bit, f64::NAN).0, "x");
}
