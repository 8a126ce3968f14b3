//! Random, well-typed digital testbenches for the differential test against GHDL: signals and
//! variables of `integer`, `bit`, `boolean`, `std_logic` and arrays of them, processes with
//! every `wait` form, signal assignments with inertial, transport and reject delays and several
//! waveform elements, `if`, `case`, `for` and `while` loops, a function of integers, and
//! `report`s of values through `'image` (see `tests/it/ghdl_differential.rs`).
//!
//! Every program is deterministic in VHDL's sense, so that two correct simulators print the
//! same reports at the same times (in any order within a time step, which the comparison
//! allows): each signal has one driver (a `std_logic` signal may have two, resolved the same
//! way in either order), there are no shared variables, no file I/O, and no value that the LRM
//! leaves to the implementation. No run-time error can happen: integers stay far inside 32 bits
//! (an expression that could leave +-1e6 is taken `mod 1000`), array indexes are reduced into
//! their range, divisors are non-zero literals, and `while` loops count a variable of their
//! own. Every process that waits has a `wait for` of at least 1 ns in each pass of its body,
//! and processes with a sensitivity list and concurrent assignments assign with a delay, so
//! there is no endless delta cycle; the run lasts `STOP_NS`.

// The test and the example each use part of this module.
#![allow(dead_code)]

use std::fmt::Write;

/// The simulated time of every run, in nanoseconds. Delays are multiples of 100 ps, so no
/// event falls on the stop time itself, which the two tools may treat differently.
pub const STOP_NS: u64 = 400;
/// The stop time as both command lines take it (50 ps past `STOP_NS`).
pub const STOP: &str = "400050 ps";

/// SplitMix64: a fixed, documented generator, so that a seed names the same program on every
/// machine and in every version (a library generator may change its stream).
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        // Seeds 1, 2, 3 would otherwise start from neighbouring states.
        Rng(seed.wrapping_mul(0x2545_f491_4f6c_dd1d))
    }

    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform integer in `lo..=hi`.
    fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo + 1) as u64) as i64
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    /// True with probability `p`.
    fn chance(&mut self, p: f64) -> bool {
        ((self.next() >> 11) as f64 / (1u64 << 53) as f64) < p
    }

    fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }
}

/// The types of the generated objects.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ty {
    Int,
    Bit,
    Bool,
    Logic,
    /// `bit_vector(3 downto 0)`.
    BitVec,
    /// `std_logic_vector(0 to 3)`.
    LogicVec,
    /// `int_arr`, `array (1 to 3) of integer`.
    IntArr,
    /// `bool_arr`, `array (0 to 2) of boolean`.
    BoolArr,
}

const SCALARS: [Ty; 4] = [Ty::Int, Ty::Bit, Ty::Bool, Ty::Logic];
const ALL: [Ty; 8] = [
    Ty::Int,
    Ty::Bit,
    Ty::Bool,
    Ty::Logic,
    Ty::BitVec,
    Ty::LogicVec,
    Ty::IntArr,
    Ty::BoolArr,
];

/// Integer objects hold values in `-MAX..=MAX`.
const MAX: i64 = 1000;
/// An integer expression whose bound passes this is taken `mod 1000`.
const WRAP: i64 = 1_000_000;

impl Ty {
    fn name(self) -> &'static str {
        match self {
            Ty::Int => "integer",
            Ty::Bit => "bit",
            Ty::Bool => "boolean",
            Ty::Logic => "std_logic",
            Ty::BitVec => "bv4",
            Ty::LogicVec => "slv4",
            Ty::IntArr => "int_arr",
            Ty::BoolArr => "bool_arr",
        }
    }

    /// The element type and the index range `(low, length)` of an array type.
    fn element(self) -> Option<(Ty, i64, i64)> {
        match self {
            Ty::BitVec => Some((Ty::Bit, 0, 4)),
            Ty::LogicVec => Some((Ty::Logic, 0, 4)),
            Ty::IntArr => Some((Ty::Int, 1, 3)),
            Ty::BoolArr => Some((Ty::Bool, 0, 3)),
            _ => None,
        }
    }
}

#[derive(Debug, Clone)]
struct Object {
    name: String,
    ty: Ty,
}

/// What a statement list may contain where it is generated.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Context {
    /// A process with `wait` statements: waits and zero-delay assignments allowed.
    Waiting,
    /// A process with a sensitivity list: no waits, assignments only with a delay.
    Sensitive,
    /// A function body: no signals, no waits, no reports.
    Function,
}

/// One generated program.
pub struct Program {
    pub seed: u64,
    rng: Rng,
    signals: Vec<Object>,
    /// The signals the process being generated may assign (the ones it drives).
    driven: Vec<Object>,
    /// Variables, loop parameters and function parameters in scope (loop parameters and
    /// parameters are read-only, `writable` false).
    locals: Vec<(Object, bool)>,
    context: Context,
    fresh: usize,
    reports: usize,
    /// True while a `wait` statement's condition is generated.
    in_wait: bool,
    /// The signals with two drivers.
    multiple: Vec<String>,
    /// Declarations the statements generated so far need (the counters of `while` loops).
    pending: Vec<String>,
    text: String,
}

impl Program {
    /// The VHDL text of the program of `seed`; the top entity is `tb`.
    pub fn random(seed: u64) -> String {
        let mut p = Program {
            seed,
            rng: Rng::new(seed),
            signals: Vec::new(),
            driven: Vec::new(),
            locals: Vec::new(),
            context: Context::Waiting,
            fresh: 0,
            reports: 0,
            pending: Vec::new(),
            multiple: Vec::new(),
            in_wait: false,
            text: String::new(),
        };
        p.program();
        p.text
    }

    fn name(&mut self, prefix: &str) -> String {
        self.fresh += 1;
        format!("{prefix}{}", self.fresh)
    }

    fn program(&mut self) {
        let seed = self.seed;
        let mut out = format!(
            "-- Generated by tests/it/ghdl_differential/program.rs from seed {seed}.\n\
             library ieee;\nuse ieee.std_logic_1164.all;\n\n\
             entity tb is\nend entity tb;\n\n\
             architecture gen of tb is\n\
             \x20 type int_arr is array (1 to 3) of integer;\n\
             \x20 type bool_arr is array (0 to 2) of boolean;\n\
             \x20 subtype bv4 is bit_vector(3 downto 0);\n\
             \x20 subtype slv4 is std_logic_vector(0 to 3);\n"
        );
        out.push_str(HELPERS);
        let signal_count = self.rng.int(3, 8);
        for _ in 0..signal_count {
            let ty = if self.rng.chance(0.6) {
                *self.rng.pick(&SCALARS)
            } else {
                *self.rng.pick(&ALL)
            };
            let name = self.name("s");
            let init = self.literal(ty);
            let _ = writeln!(out, "  signal {name} : {} := {init};", ty.name());
            self.signals.push(Object { name, ty });
        }
        out.push_str(&self.function());
        out.push_str("begin\n");
        // Each signal gets one driver: a process or a concurrent assignment (a std_logic signal
        // sometimes two, which resolution combines).
        let processes = self.rng.int(2, 4) as usize;
        let mut owners: Vec<Vec<Object>> = vec![Vec::new(); processes + 1];
        for s in self.signals.clone() {
            let owner = self.rng.below(processes + 1);
            if s.ty == Ty::Logic && self.rng.chance(0.3) {
                let other = (owner + 1) % processes;
                owners[other].push(s.clone());
                self.multiple.push(s.name.clone());
            }
            owners[owner].push(s);
        }
        for (k, driven) in owners.iter().enumerate().take(processes) {
            self.driven = driven.clone();
            let text = if self.rng.chance(0.25) {
                self.sensitive_process(k)
            } else {
                self.waiting_process(k)
            };
            out.push_str(&text);
        }
        // The last share of signals is driven by concurrent assignments.
        for s in owners[processes].clone() {
            if self.rng.chance(0.5) {
                continue;
            }
            self.context = Context::Sensitive;
            self.locals.clear();
            let value = self.expr(s.ty, 2);
            let delay = self.delay(false);
            if self.rng.chance(0.3) {
                let c = self.bool_expr(2);
                let other = self.expr(s.ty, 1);
                let delay2 = self.delay(false);
                let _ = writeln!(
                    out,
                    "  {} <= {value} after {delay} when {c} else {other} after {delay2};",
                    s.name
                );
            } else {
                let _ = writeln!(out, "  {} <= {value} after {delay};", s.name);
            }
        }
        out.push_str("end architecture gen;\n");
        self.text = out;
    }

    /// `f(a, b)`: integers in, an integer in `0..1000` out, through a loop, an `if` or a
    /// `case`; it also exercises parameters and local variables.
    fn function(&mut self) -> String {
        self.context = Context::Function;
        self.locals = vec![
            (
                Object {
                    name: "a".into(),
                    ty: Ty::Int,
                },
                false,
            ),
            (
                Object {
                    name: "b".into(),
                    ty: Ty::Int,
                },
                false,
            ),
        ];
        let mut decls = String::new();
        for _ in 0..self.rng.int(1, 3) {
            let ty = *self.rng.pick(&ALL);
            let name = self.name("fv");
            let init = self.literal(ty);
            let _ = writeln!(decls, "    variable {name} : {} := {init};", ty.name());
            self.locals.push((Object { name, ty }, true));
        }
        let body = self.statements(2, 2, 5);
        let result = self.int_expr(2).0;
        self.locals.clear();
        decls.extend(self.pending.drain(..));
        format!(
            "  function f(a : integer; b : integer) return integer is\n{decls}  begin\n{body}    \
             return ({result}) mod 1000;\n  end function f;\n"
        )
    }

    fn declare_variables(&mut self) -> String {
        let mut decls = String::new();
        self.locals.clear();
        for _ in 0..self.rng.int(1, 4) {
            let ty = *self.rng.pick(&ALL);
            let name = self.name("v");
            let init = self.literal(ty);
            let _ = writeln!(decls, "    variable {name} : {} := {init};", ty.name());
            self.locals.push((Object { name, ty }, true));
        }
        decls
    }

    fn waiting_process(&mut self, k: usize) -> String {
        self.context = Context::Waiting;
        let decls = self.declare_variables();
        let body = self.statements(2, 3, 7);
        let decls = decls + &self.pending.drain(..).collect::<String>();
        // The pass's own progress in time (a process always reaches it, whatever it waited on).
        let step = self.delay(false);
        format!(
            "  p{k}: process\n{decls}  begin\n{body}    wait for {step};\n  end process p{k};\n"
        )
    }

    fn sensitive_process(&mut self, k: usize) -> String {
        self.context = Context::Sensitive;
        let decls = self.declare_variables();
        let count = self.rng.int(1, 3) as usize;
        let mut list: Vec<String> = Vec::new();
        for _ in 0..count {
            let s = self.rng.pick(&self.signals).name.clone();
            if !list.contains(&s) {
                list.push(s);
            }
        }
        let body = self.statements(2, 2, 5);
        let decls = decls + &self.pending.drain(..).collect::<String>();
        format!(
            "  p{k}: process ({})\n{decls}  begin\n{body}  end process p{k};\n",
            list.join(", ")
        )
    }

    fn indent(depth: usize) -> String {
        "  ".repeat(6 - depth)
    }

    /// `lo..=hi` statements at nesting `depth` (2 at the top of a body, 0 innermost).
    fn statements(&mut self, depth: usize, lo: i64, hi: i64) -> String {
        let mut out = String::new();
        for _ in 0..self.rng.int(lo, hi) {
            out.push_str(&self.statement(depth));
        }
        out
    }

    fn statement(&mut self, depth: usize) -> String {
        let pad = Self::indent(depth);
        loop {
            let choice = self.rng.below(14);
            match choice {
                0 | 1 => {
                    if let Some(s) = self.variable_assignment() {
                        return format!("{pad}{s}\n");
                    }
                }
                2 | 3 => {
                    if let Some(s) = self.signal_assignment() {
                        return format!("{pad}{s}\n");
                    }
                }
                4 | 5 if self.context == Context::Waiting => {
                    return format!("{pad}{}\n", self.wait());
                }
                6 | 7 if self.context != Context::Function => {
                    return format!("{pad}{}\n", self.report());
                }
                8 if depth > 0 => {
                    let c = self.bool_expr(2);
                    let then = self.statements(depth - 1, 1, 3);
                    let mut s = format!("{pad}if {c} then\n{then}");
                    if self.rng.chance(0.3) {
                        let c2 = self.bool_expr(2);
                        let t2 = self.statements(depth - 1, 1, 2);
                        let _ = write!(s, "{pad}elsif {c2} then\n{t2}");
                    }
                    if self.rng.chance(0.5) {
                        let e = self.statements(depth - 1, 1, 2);
                        let _ = write!(s, "{pad}else\n{e}");
                    }
                    let _ = writeln!(s, "{pad}end if;");
                    return s;
                }
                9 if depth > 0 => return self.case(depth),
                12 if self.context != Context::Function => {
                    if let Some(s) = self.call() {
                        return format!("{pad}{s}\n");
                    }
                }
                13 if self.context != Context::Function => {
                    // An assertion reports when its condition is false.
                    let c = self.bool_expr(2);
                    let r = self.report();
                    let message = r.trim_start_matches("report ").trim_end_matches(';');
                    return format!("{pad}assert {c} report {message} severity note;\n");
                }
                10 if depth > 0 => return self.for_loop(depth),
                11 if depth > 0 => return self.while_loop(depth),
                _ => {}
            }
        }
    }

    fn case(&mut self, depth: usize) -> String {
        let pad = Self::indent(depth);
        let kind = self.rng.below(4);
        let (selector, choices): (String, Vec<String>) = match kind {
            0 => {
                let e = self.int_expr(2).0;
                let a = self.rng.int(-2, 5);
                let b = a + self.rng.int(1, 3);
                (
                    format!("integer'(({e}) mod 8)"),
                    vec![
                        format!("{a}"),
                        format!("{} to {}", b, b + self.rng.int(0, 3)),
                        format!("{} | {}", b + 5, b + 7),
                    ],
                )
            }
            1 => (self.bit_expr(1), vec!["'0'".into(), "'1'".into()]),
            2 => (self.bool_expr(1), vec!["true".into(), "false".into()]),
            _ => {
                let objects = self.readable(Ty::Logic);
                if objects.is_empty() {
                    (self.bit_expr(1), vec!["'0'".into(), "'1'".into()])
                } else {
                    let o = self.rng.pick(&objects).clone();
                    (
                        o,
                        vec!["'0' | 'L'".into(), "'1' | 'H'".into(), "'U'".into()],
                    )
                }
            }
        };
        let mut s = format!("{pad}case {selector} is\n");
        let full = matches!(kind, 1 | 2) && self.rng.chance(0.5);
        for c in &choices {
            let body = self.statements(depth - 1, 1, 2);
            let _ = write!(s, "{pad}  when {c} =>\n{body}");
        }
        if !full {
            let body = if self.rng.chance(0.5) {
                format!("{}null;\n", Self::indent(depth - 1))
            } else {
                self.statements(depth - 1, 1, 1)
            };
            let _ = write!(s, "{pad}  when others =>\n{body}");
        }
        let _ = writeln!(s, "{pad}end case;");
        s
    }

    fn for_loop(&mut self, depth: usize) -> String {
        let pad = Self::indent(depth);
        let i = self.name("i");
        let range = match self.rng.below(3) {
            0 => format!("0 to {}", self.rng.int(0, 4)),
            1 => format!("{} downto -1", self.rng.int(-2, 3)),
            _ => {
                let arrays: Vec<String> = self
                    .signals
                    .iter()
                    .filter(|o| o.ty.element().is_some())
                    .map(|o| o.name.clone())
                    .collect();
                match arrays.first() {
                    Some(a) if self.context != Context::Function => format!("{a}'range"),
                    _ => "1 to 3".into(),
                }
            }
        };
        self.locals.push((
            Object {
                name: i.clone(),
                ty: Ty::Int,
            },
            false,
        ));
        let mut body = self.statements(depth - 1, 1, 3);
        if self.rng.chance(0.3) {
            let c = self.bool_expr(1);
            let which = if self.rng.chance(0.5) { "exit" } else { "next" };
            body = format!("{}{which} when {c};\n{body}", Self::indent(depth - 1));
        }
        self.locals.pop();
        format!("{pad}for {i} in {range} loop\n{body}{pad}end loop;\n")
    }

    /// A `while` loop that counts a variable of its own (declared in the enclosing process or
    /// function through `pending`; the body never assigns it, so the loop ends).
    fn while_loop(&mut self, depth: usize) -> String {
        let pad = Self::indent(depth);
        let inner = Self::indent(depth - 1);
        let counter = self.name("k");
        self.pending
            .push(format!("    variable {counter} : integer;\n"));
        let limit = self.rng.int(1, 4);
        let extra = if self.rng.chance(0.4) {
            format!(" and {}", self.bool_expr(1))
        } else {
            String::new()
        };
        let body = self.statements(depth - 1, 1, 3);
        format!(
            "{pad}{counter} := 0;\n{pad}while {counter} < {limit}{extra} loop\n\
             {inner}{counter} := {counter} + 1;\n{body}{pad}end loop;\n"
        )
    }

    /// A call of the procedures every program has: `bump` on an integer variable, `pause` (a
    /// `wait` inside a procedure) where the process may wait.
    fn call(&mut self) -> Option<String> {
        if self.context == Context::Waiting && self.rng.chance(0.3) {
            return Some(format!("pause({});", self.delay(true)));
        }
        let ints: Vec<String> = self
            .locals
            .iter()
            .filter(|(o, w)| *w && o.ty == Ty::Int)
            .map(|(o, _)| o.name.clone())
            .collect();
        if ints.is_empty() {
            return None;
        }
        let v = self.rng.pick(&ints).clone();
        let d = self.expr(Ty::Int, 1);
        Some(format!("bump({v}, {d});"))
    }

    fn variable_assignment(&mut self) -> Option<String> {
        let writable: Vec<Object> = self
            .locals
            .iter()
            .filter(|(_, w)| *w)
            .map(|(o, _)| o.clone())
            .collect();
        if writable.is_empty() {
            return None;
        }
        let target = self.rng.pick(&writable).clone();
        if let Some((el, low, len)) = target.ty.element()
            && self.rng.chance(0.5)
        {
            let index = self.index(low, len);
            let value = self.expr(el, 2);
            return Some(format!("{}({index}) := {value};", target.name));
        }
        let value = self.expr(target.ty, 2);
        Some(format!("{} := {value};", target.name))
    }

    fn signal_assignment(&mut self) -> Option<String> {
        if self.context == Context::Function || self.driven.is_empty() {
            return None;
        }
        let target = self.rng.pick(&self.driven.clone()).clone();
        let (name, ty) = match target.ty.element() {
            Some((el, low, len)) if self.rng.chance(0.4) => {
                (format!("{}({})", target.name, self.index(low, len)), el)
            }
            _ => (target.name.clone(), target.ty),
        };
        let mechanism = match self.rng.below(5) {
            0 => "transport ".to_string(),
            1 => {
                let r = self.rng.int(0, 30);
                format!("reject {}.{} ns inertial ", r / 10, r % 10)
            }
            _ => String::new(),
        };
        // GHDL 2.0 misses a zero-delay transport transaction on a resolved signal with two
        // drivers (tests/conformance/ghdl_agreement.vhd, tb_ghdl_transport_resolved).
        let zero_ok = self.context == Context::Waiting
            && !(mechanism.starts_with("transport") && self.multiple.contains(&target.name));
        let elements = if mechanism.starts_with("reject") {
            1
        } else {
            self.rng.int(1, 3)
        };
        let mut at = 0i64;
        let mut parts = Vec::new();
        for k in 0..elements {
            let step = if k == 0 && zero_ok && self.rng.chance(0.3) {
                0
            } else {
                self.rng.int(1, 60) * 100
            };
            at += step;
            if k > 0 && step == 0 {
                at += 100;
            }
            let value = self.expr(ty, 2);
            if at == 0 {
                parts.push(value);
            } else {
                parts.push(format!("{value} after {} ps", at));
            }
        }
        // A reject limit longer than the delay is an error (LRM 8.4).
        let mechanism = if mechanism.starts_with("reject") && at < 3000 {
            "inertial ".to_string()
        } else {
            mechanism
        };
        Some(format!("{name} <= {mechanism}{};", parts.join(", ")))
    }

    fn wait(&mut self) -> String {
        self.in_wait = true;
        let wait = self.wait_statement();
        self.in_wait = false;
        wait
    }

    fn wait_statement(&mut self) -> String {
        let signal = |p: &mut Program| p.rng.pick(&p.signals).name.clone();
        match self.rng.below(5) {
            0 => format!("wait for {};", self.delay(true)),
            1 => {
                let a = signal(self);
                let b = signal(self);
                if a == b || self.rng.chance(0.5) {
                    format!("wait on {a} for {};", self.delay(false))
                } else {
                    format!("wait on {a}, {b};")
                }
            }
            2 => format!("wait until {};", self.signal_condition()),
            3 => format!(
                "wait until {} for {};",
                self.signal_condition(),
                self.delay(false)
            ),
            _ => format!(
                "wait on {} until {} for {};",
                signal(self),
                self.bool_expr(1),
                self.delay(false)
            ),
        }
    }

    /// A condition that reads at least one signal (a `wait until` on none would never wake).
    fn signal_condition(&mut self) -> String {
        let s = self.rng.pick(&self.signals).clone();
        let own = match s.ty {
            Ty::Int => format!("{} > {}", s.name, self.rng.int(-5, 20)),
            Ty::Bit => format!("{} = '1'", s.name),
            Ty::Bool => s.name.clone(),
            Ty::Logic => format!("{} = '1'", s.name),
            _ => format!("{}'event", s.name),
        };
        if self.rng.chance(0.4) {
            let other = self.bool_expr(1);
            let op = if self.rng.chance(0.5) { "and" } else { "or" };
            format!("({own}) {op} ({other})")
        } else {
            own
        }
    }

    fn report(&mut self) -> String {
        self.reports += 1;
        let mut parts = vec![format!("\"r{}\"", self.reports)];
        for _ in 0..self.rng.int(1, 3) {
            let ty = *self.rng.pick(&ALL);
            let e = self.expr(ty, 1);
            let image = match ty {
                Ty::Int => format!("integer'image({e})"),
                Ty::Bit => format!("bit'image({e})"),
                Ty::Bool => format!("boolean'image({e})"),
                Ty::Logic => format!("std_logic'image({e})"),
                _ => {
                    let objects = self.readable(ty);
                    match objects.first() {
                        Some(_) => format!("img({})", self.rng.pick(&objects)),
                        None => format!("integer'image({})", self.int_expr(1).0),
                    }
                }
            };
            parts.push("\" \"".into());
            parts.push(image);
        }
        format!("report {};", parts.join(" & "))
    }

    /// A delay of 1 ns to 20 ns (multiples of 100 ps); 0 ns too when `zero` is allowed.
    fn delay(&mut self, zero: bool) -> String {
        let ps = if zero && self.rng.chance(0.1) {
            0
        } else {
            self.rng.int(10, 200) * 100
        };
        format!("{ps} ps")
    }

    /// An index expression into `low..low + len`.
    fn index(&mut self, low: i64, len: i64) -> String {
        if self.rng.chance(0.5) {
            return format!("{}", self.rng.int(low, low + len - 1));
        }
        let e = self.int_expr(1).0;
        if low == 0 {
            format!("({e}) mod {len}")
        } else {
            format!("{low} + ({e}) mod {len}")
        }
    }

    /// Names of the objects of type `ty` readable here.
    fn readable(&self, ty: Ty) -> Vec<String> {
        let mut names: Vec<String> = self
            .locals
            .iter()
            .filter(|(o, _)| o.ty == ty)
            .map(|(o, _)| o.name.clone())
            .collect();
        if self.context != Context::Function {
            names.extend(
                self.signals
                    .iter()
                    .filter(|o| o.ty == ty)
                    .map(|o| o.name.clone()),
            );
        }
        names
    }

    /// A readable element of an array of element type `ty`, if there is an array.
    fn element_of(&mut self, ty: Ty) -> Option<String> {
        let arrays: Vec<(String, Ty)> = ALL
            .iter()
            .filter(|a| a.element().is_some_and(|(e, _, _)| e == ty))
            .flat_map(|a| self.readable(*a).into_iter().map(move |n| (n, *a)))
            .collect();
        if arrays.is_empty() {
            return None;
        }
        let (name, array) = self.rng.pick(&arrays).clone();
        let (_, low, len) = array.element().expect("an array type");
        Some(format!("{name}({})", self.index(low, len)))
    }

    fn object_or_element(&mut self, ty: Ty) -> Option<String> {
        if self.rng.chance(0.3)
            && let Some(e) = self.element_of(ty)
        {
            return Some(e);
        }
        let names = self.readable(ty);
        if names.is_empty() {
            None
        } else {
            Some(self.rng.pick(&names).clone())
        }
    }

    fn expr(&mut self, ty: Ty, depth: usize) -> String {
        match ty {
            Ty::Int => {
                let (e, bound) = self.int_expr(depth);
                if bound > MAX {
                    format!("({e}) mod 1000")
                } else {
                    e
                }
            }
            Ty::Bit => self.bit_expr(depth),
            Ty::Bool => self.bool_expr(depth),
            Ty::Logic => self.logic_expr(depth),
            Ty::BitVec => self.bit_vector_expr(depth),
            Ty::LogicVec => self.logic_vector_expr(depth),
            Ty::IntArr => {
                if self.rng.chance(0.5)
                    && let Some(o) = self.object_or_element(ty)
                {
                    return o;
                }
                let a = self.expr(Ty::Int, depth.saturating_sub(1));
                let b = self.expr(Ty::Int, depth.saturating_sub(1));
                let c = self.expr(Ty::Int, depth.saturating_sub(1));
                format!("int_arr'({a}, {b}, {c})")
            }
            Ty::BoolArr => {
                if self.rng.chance(0.5)
                    && let Some(o) = self.object_or_element(ty)
                {
                    return o;
                }
                if self.rng.chance(0.3) {
                    return format!("bool_arr'(others => {})", self.bool_expr(0));
                }
                let a = self.bool_expr(depth.saturating_sub(1));
                let b = self.bool_expr(depth.saturating_sub(1));
                let c = self.bool_expr(depth.saturating_sub(1));
                format!("bool_arr'({a}, {b}, {c})")
            }
        }
    }

    fn literal(&mut self, ty: Ty) -> String {
        match ty {
            Ty::Int => format!("{}", self.rng.int(-20, 60)),
            Ty::Bit => self.rng.pick(&["'0'", "'1'"]).to_string(),
            Ty::Bool => self.rng.pick(&["false", "true"]).to_string(),
            Ty::Logic => self.rng.pick(&LOGIC).to_string(),
            Ty::BitVec => {
                let bits: String = (0..4).map(|_| *self.rng.pick(&['0', '1'])).collect();
                format!("\"{bits}\"")
            }
            Ty::LogicVec => {
                let bits: String = (0..4)
                    .map(|_| {
                        *self
                            .rng
                            .pick(&['U', 'X', '0', '1', 'Z', 'W', 'L', 'H', '-'])
                    })
                    .collect();
                format!("\"{bits}\"")
            }
            Ty::IntArr => format!(
                "({}, {}, {})",
                self.rng.int(-9, 50),
                self.rng.int(-9, 50),
                self.rng.int(-9, 50)
            ),
            Ty::BoolArr => format!(
                "({}, {}, {})",
                self.literal(Ty::Bool),
                self.literal(Ty::Bool),
                self.literal(Ty::Bool)
            ),
        }
    }

    /// A literal of `ty` with its type named, so that it is never ambiguous (`'0'` may be a
    /// `bit`, a `std_logic` or a `character`).
    fn qualified(&mut self, ty: Ty) -> String {
        let text = self.literal(ty);
        match ty {
            Ty::Int | Ty::Bool => text,
            _ => format!(
                "{}'({})",
                ty.name(),
                text.trim_start_matches('(').trim_end_matches(')')
            ),
        }
    }

    /// An integer expression and a bound of its absolute value.
    fn int_expr(&mut self, depth: usize) -> (String, i64) {
        let leaf = depth == 0 || self.rng.chance(0.3);
        if leaf {
            return match self.rng.below(8) {
                0 if self.context != Context::Function
                    && self.signals.iter().any(|s| s.ty == Ty::Int) =>
                {
                    let ints: Vec<String> = self
                        .signals
                        .iter()
                        .filter(|s| s.ty == Ty::Int)
                        .map(|s| s.name.clone())
                        .collect();
                    (format!("{}'last_value", self.rng.pick(&ints)), MAX)
                }
                0..=3 => match self.object_or_element(Ty::Int) {
                    Some(o) => (o, MAX),
                    None => self.int_literal(),
                },
                4 => {
                    let t = *self.rng.pick(&[Ty::Bit, Ty::Bool, Ty::Logic]);
                    let e = self.expr(t, 0);
                    (format!("{}'pos({e})", t.name()), 8)
                }
                5 => {
                    let arrays: Vec<String> = [Ty::BitVec, Ty::LogicVec, Ty::IntArr, Ty::BoolArr]
                        .iter()
                        .flat_map(|t| self.readable(*t))
                        .collect();
                    if arrays.is_empty() {
                        self.int_literal()
                    } else {
                        let a = self.rng.pick(&arrays).clone();
                        let attr = self.rng.pick(&["length", "left", "right", "high", "low"]);
                        (format!("{a}'{attr}"), 4)
                    }
                }
                _ => self.int_literal(),
            };
        }
        let d = depth - 1;
        let (e, bound) = match self.rng.below(10) {
            0 | 1 => {
                let (a, ba) = self.int_expr(d);
                let (b, bb) = self.int_expr(d);
                (format!("{a} + {b}"), ba + bb)
            }
            2 => {
                let (a, ba) = self.int_expr(d);
                let (b, bb) = self.int_expr(d);
                (format!("{a} - ({b})"), ba + bb)
            }
            3 => {
                let (a, ba) = self.int_expr(d);
                let (b, bb) = self.int_expr(d);
                if ba.saturating_mul(bb) < WRAP * 100 {
                    (format!("({a}) * ({b})"), ba * bb)
                } else {
                    (format!("({a}) * 3"), ba * 3)
                }
            }
            4 => {
                let (a, ba) = self.int_expr(d);
                let c = self.rng.int(1, 9) * if self.rng.chance(0.2) { -1 } else { 1 };
                (format!("({a}) / ({c})"), ba)
            }
            5 => {
                let (a, _) = self.int_expr(d);
                let c = self.rng.int(1, 9) * if self.rng.chance(0.2) { -1 } else { 1 };
                let op = if self.rng.chance(0.5) { "mod" } else { "rem" };
                (format!("({a}) {op} ({c})"), 9)
            }
            6 => {
                let (a, ba) = self.int_expr(d);
                if self.rng.chance(0.5) {
                    (format!("abs ({a})"), ba)
                } else {
                    (format!("-({a})"), ba)
                }
            }
            7 => {
                let (a, _) = self.int_expr(d);
                let (b, _) = self.int_expr(d);
                if self.context == Context::Function {
                    // No recursion: `f` calls nothing of its own.
                    (format!("({a}) mod 10 + ({b}) mod 10"), 20)
                } else {
                    (format!("f({}, {})", wrap(&a), wrap(&b)), 1000)
                }
            }
            8 => {
                let c = self.bool_expr(d);
                (format!("boolean'pos({c}) * 7"), 7)
            }
            _ => {
                let (a, ba) = self.int_expr(d);
                let p = self.rng.int(0, 2);
                if ba < 1000 {
                    (format!("({a}) ** {p}"), ba.pow(p as u32).max(1))
                } else {
                    (format!("({a})"), ba)
                }
            }
        };
        if bound > WRAP {
            (format!("(({e}) mod 1000)"), 1000)
        } else {
            (format!("({e})"), bound)
        }
    }

    fn int_literal(&mut self) -> (String, i64) {
        let v = self.rng.int(0, 40);
        (format!("{v}"), v.max(1))
    }

    fn bool_expr(&mut self, depth: usize) -> String {
        if depth == 0 || self.rng.chance(0.25) {
            return match self.rng.below(4) {
                0 => self.qualified(Ty::Bool),
                _ => self
                    .object_or_element(Ty::Bool)
                    .unwrap_or_else(|| self.qualified(Ty::Bool)),
            };
        }
        let d = depth - 1;
        match self.rng.below(9) {
            0 | 1 => {
                let a = self.int_expr(d).0;
                let b = self.int_expr(d).0;
                let op = self.rng.pick(&["=", "/=", "<", "<=", ">", ">="]);
                format!("({a} {op} {b})")
            }
            2 => {
                let a = self.bool_expr(d);
                let b = self.bool_expr(d);
                let op = self.rng.pick(&["and", "or", "xor", "nand", "nor", "xnor"]);
                format!("({a} {op} {b})")
            }
            3 => format!("(not {})", self.bool_expr(d)),
            4 => {
                let a = self.bit_expr(d);
                let b = self.bit_expr(d);
                let op = self.rng.pick(&["=", "/=", "<", ">="]);
                format!("({a} {op} {b})")
            }
            5 => {
                let a = self.logic_expr(d);
                let b = self.logic_expr(d);
                let op = self.rng.pick(&["=", "/="]);
                format!("({a} {op} {b})")
            }
            6 => {
                let t = *self
                    .rng
                    .pick(&[Ty::BitVec, Ty::LogicVec, Ty::IntArr, Ty::BoolArr]);
                let a = self.expr(t, d);
                let b = self.expr(t, d);
                let op = if t == Ty::BitVec {
                    *self.rng.pick(&["=", "/=", "<", ">="])
                } else {
                    *self.rng.pick(&["=", "/="])
                };
                format!("({a} {op} {b})")
            }
            7 if self.context != Context::Function => {
                let signal = self.rng.pick(&self.signals);
                let (s, scalar) = (signal.name.clone(), SCALARS.contains(&signal.ty));
                // `'stable` and `'quiet` are implicit signals: also where a sensitivity list
                // (a concurrent assignment's, a `wait until`'s) waits on them. Of scalar
                // signals only: GHDL 2.0 leaves a composite signal's `'stable` true in a cycle
                // of an event on it (tests/conformance/stable_and_quiet_signals.vhd).
                let attrs: &[&str] = if scalar {
                    &["event", "active", "stable", "quiet"]
                } else {
                    &["event", "active"]
                };
                let attr = self.rng.pick(attrs);
                format!("{s}'{attr}")
            }
            _ => {
                let a = self.bool_expr(d);
                format!("({a} = {})", self.qualified(Ty::Bool))
            }
        }
    }

    fn bit_expr(&mut self, depth: usize) -> String {
        if depth == 0 || self.rng.chance(0.25) {
            return match self.rng.below(4) {
                0 => self.qualified(Ty::Bit),
                _ => self
                    .object_or_element(Ty::Bit)
                    .unwrap_or_else(|| self.qualified(Ty::Bit)),
            };
        }
        let d = depth - 1;
        match self.rng.below(5) {
            0 | 1 => {
                let a = self.bit_expr(d);
                let b = self.bit_expr(d);
                let op = self.rng.pick(&["and", "or", "xor", "nand", "nor", "xnor"]);
                format!("({a} {op} {b})")
            }
            2 => format!("(not {})", self.bit_expr(d)),
            3 => format!("bit'val(boolean'pos({}))", self.bool_expr(d)),
            _ => format!("to_bit({})", self.logic_expr(d)),
        }
    }

    fn logic_expr(&mut self, depth: usize) -> String {
        if depth == 0 || self.rng.chance(0.25) {
            return match self.rng.below(4) {
                0 => self.qualified(Ty::Logic),
                _ => self
                    .object_or_element(Ty::Logic)
                    .unwrap_or_else(|| self.qualified(Ty::Logic)),
            };
        }
        let d = depth - 1;
        match self.rng.below(6) {
            0 | 1 => {
                let a = self.logic_expr(d);
                let b = self.logic_expr(d);
                let op = self.rng.pick(&["and", "or", "xor", "nand", "nor", "xnor"]);
                format!("({a} {op} {b})")
            }
            2 => format!("(not {})", self.logic_expr(d)),
            3 => format!("to_x01({})", self.logic_expr(d)),
            4 => format!("to_stdulogic({})", self.bit_expr(d)),
            _ => {
                let (k, _) = self.int_expr(d);
                format!("std_logic'val(({k}) mod 9)")
            }
        }
    }

    fn bit_vector_expr(&mut self, depth: usize) -> String {
        if depth == 0 || self.rng.chance(0.3) {
            return match self.rng.below(3) {
                0 => self.qualified(Ty::BitVec),
                _ => self
                    .object_or_element(Ty::BitVec)
                    .unwrap_or_else(|| self.qualified(Ty::BitVec)),
            };
        }
        let d = depth - 1;
        match self.rng.below(7) {
            0 | 1 => {
                let a = self.bit_vector_expr(d);
                let b = self.bit_vector_expr(d);
                let op = self.rng.pick(&["and", "or", "xor", "nand", "nor", "xnor"]);
                format!("({a} {op} {b})")
            }
            2 => format!("(not {})", self.bit_vector_expr(d)),
            3 => {
                let a = self.bit_vector_expr(d);
                let op = self.rng.pick(&["sll", "srl", "sla", "sra", "rol", "ror"]);
                // Not by 0: GHDL 2.0 folds `bv4'("1111") ror 0` wrongly (compared with
                // "0110", it says the rotated literal is the smaller).
                format!("({a} {op} {})", self.rng.int(1, 5))
            }
            4 => {
                let a = self.bit_expr(d);
                let b = self.bit_expr(d);
                let v = self.bit_vector_expr(d);
                // Two bits and the low half of a vector: four bits again.
                format!("bv4'({a} & {b} & bv_low({v}))")
            }
            5 => format!("bv4'(others => {})", self.bit_expr(d)),
            _ => format!("to_bitvector({})", self.logic_vector_expr(d)),
        }
    }

    fn logic_vector_expr(&mut self, depth: usize) -> String {
        if depth == 0 || self.rng.chance(0.3) {
            return match self.rng.below(3) {
                0 => self.qualified(Ty::LogicVec),
                _ => self
                    .object_or_element(Ty::LogicVec)
                    .unwrap_or_else(|| self.qualified(Ty::LogicVec)),
            };
        }
        let d = depth - 1;
        match self.rng.below(5) {
            0 | 1 => {
                let a = self.logic_vector_expr(d);
                let b = self.logic_vector_expr(d);
                let op = self.rng.pick(&["and", "or", "xor", "nand", "nor", "xnor"]);
                format!("({a} {op} {b})")
            }
            2 => format!("(not {})", self.logic_vector_expr(d)),
            3 => {
                let a = self.logic_expr(d);
                let b = self.logic_expr(d);
                let c = self.logic_expr(d);
                let e = self.logic_expr(d);
                format!("slv4'({a}, {b}, {c}, {e})")
            }
            _ => format!("to_stdlogicvector({})", self.bit_vector_expr(d)),
        }
    }
}

/// Wraps an integer argument of `f` into the range `f`'s callers guarantee (`-999..999`).
fn wrap(e: &str) -> String {
    format!("({e}) rem 1000")
}

const LOGIC: [&str; 9] = [
    "'U'", "'X'", "'0'", "'1'", "'Z'", "'W'", "'L'", "'H'", "'-'",
];

/// The helpers every program has: images of the array types (VHDL-2002 has no `'image` of an
/// array) and the low half of a `bit_vector(3 downto 0)`.
const HELPERS: &str = "  function img(v : bit_vector) return string is
    variable r : string(1 to v'length);
    variable k : integer := 1;
  begin
    for i in v'range loop
      if v(i) = '1' then
        r(k) := '1';
      else
        r(k) := '0';
      end if;
      k := k + 1;
    end loop;
    return r;
  end function img;
  function img(v : std_logic_vector) return string is
    variable r : string(1 to v'length);
    variable c : string(1 to 3);
    variable k : integer := 1;
  begin
    for i in v'range loop
      c := std_logic'image(v(i));
      r(k) := c(2);
      k := k + 1;
    end loop;
    return r;
  end function img;
  function img_from(v : int_arr; k : integer) return string is
  begin
    if k > v'high then
      return \"\";
    end if;
    return \" \" & integer'image(v(k)) & img_from(v, k + 1);
  end function img_from;
  function img(v : int_arr) return string is
  begin
    return \"(\" & img_from(v, v'low) & \" )\";
  end function img;
  function img(v : bool_arr) return string is
    variable r : string(1 to v'length);
  begin
    for i in v'range loop
      if v(i) then
        r(i + 1) := 'T';
      else
        r(i + 1) := 'F';
      end if;
    end loop;
    return r;
  end function img;
  procedure bump(variable x : inout integer; constant d : in integer) is
  begin
    x := (x + d) mod 1000;
  end procedure bump;
  procedure pause(constant t : in time) is
  begin
    wait for t;
  end procedure pause;
  function bv_low(v : bv4) return bit_vector is
  begin
    return v(1 downto 0);
  end function bv_low;
";
