//! The project's main job as a benchmark: the headlight servo's two verification runs
//! (`tb_tracking`, 6 s; `tb_overvoltage`, 8 s) at default tolerance, from parsed sources to the
//! recorded waveforms (elaboration included, parsing excluded), and the front end alone
//! (parse + elaborate). Goal: well under 0.2 s per run on the 2-core CI machine.
//!
//! The front end's throughput is measured on the models as they are and on a large generated
//! design (about 2 MB: [`COPIES`] renamed copies of the models, a top instantiating every copy
//! of `tb_tracking`); goal: parse + elaborate at 20 MB/s or more in release.
//!
//! Run: `cargo bench --bench headlight`.

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use vams::ast::DesignFile;
use vams::elaborate::{ElabOptions, elaborate};
use vams::kernel::{SimOptions, simulate};
use vams::source::{FileId, SourceMap};
use vams::{parser, stdlib};

/// Copies of the models in the generated design.
const COPIES: usize = 48;

/// The models as (path, text), sorted by path.
fn models() -> Vec<(String, String)> {
    let dir = format!("{}/models", env!("CARGO_MANIFEST_DIR"));
    let mut paths: Vec<_> = std::fs::read_dir(&dir)
        .expect("models/ exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "vhd"))
        .collect();
    paths.sort();
    paths
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).expect("model readable");
            (p.display().to_string(), text)
        })
        .collect()
}

/// `user` files and the bundled packages they need (as `vams run` loads them), parsed.
fn parse_with_stdlib(user: Vec<(String, String)>) -> (SourceMap, Vec<(FileId, DesignFile)>) {
    let mut sources = SourceMap::new();
    let ids: Vec<FileId> = user
        .into_iter()
        .map(|(name, text)| sources.add(name, "work", text))
        .collect();
    let parsed: Vec<(FileId, DesignFile)> = ids
        .iter()
        .map(|&id| {
            let text = sources.file(id).text.clone();
            (id, parser::parse(id, &text).0)
        })
        .collect();
    let (mut files, _) = stdlib::load_needed(&mut sources, &parsed);
    files.extend(parsed);
    (sources, files)
}

fn load() -> (SourceMap, Vec<(FileId, DesignFile)>) {
    parse_with_stdlib(models())
}

/// `text` with every identifier in `names` (lower case) followed by `suffix`.
fn rename(text: &str, names: &[String], suffix: &str) -> String {
    let mut out = String::with_capacity(text.len() + text.len() / 16);
    let mut rest = text;
    while let Some(start) = rest.find(|c: char| c.is_ascii_alphabetic()) {
        out.push_str(&rest[..start]);
        rest = &rest[start..];
        let end = rest
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .unwrap_or(rest.len());
        let word = &rest[..end];
        out.push_str(word);
        if names.contains(&word.to_ascii_lowercase()) {
            out.push_str(suffix);
        }
        rest = &rest[end..];
    }
    out.push_str(rest);
    out
}

/// [`COPIES`] copies of the models (all but `tb_overvoltage`) with every entity renamed
/// `<name>_c<k>`, and `bench_top` instantiating each copy of `tb_tracking`, as one file.
fn generated() -> String {
    let models: Vec<(String, String)> = models()
        .into_iter()
        .filter(|(path, _)| !path.ends_with("tb_overvoltage.vhd"))
        .collect();
    let mut names: Vec<String> = Vec::new();
    for (_, text) in &models {
        let mut words = text.split_whitespace().map(str::to_ascii_lowercase);
        while let Some(w) = words.next() {
            if w == "entity"
                && let Some(name) = words.next()
                && words.next().as_deref() == Some("is")
            {
                names.push(name);
            }
        }
    }
    let mut out = String::new();
    for k in 0..COPIES {
        for (_, text) in &models {
            out.push_str(&rename(text, &names, &format!("_c{k}")));
            out.push('\n');
        }
    }
    out.push_str("entity bench_top is end entity;\narchitecture a of bench_top is\nbegin\n");
    for k in 0..COPIES {
        out.push_str(&format!("  u{k} : entity work.tb_tracking_c{k};\n"));
    }
    out.push_str("end architecture;\n");
    out
}

fn headlight(c: &mut Criterion) {
    let (sources, files) = load();
    let mut group = c.benchmark_group("headlight");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(8));
    for (top, stop) in [("tb_tracking", 6.0), ("tb_overvoltage", 8.0)] {
        let options = ElabOptions {
            top: top.to_string(),
            generics: Vec::new(),
        };
        group.bench_function(format!("elaborate/{top}"), |b| {
            b.iter(|| black_box(elaborate(&sources, &files, &options).expect("elaborates")))
        });
        group.bench_function(format!("run/{top}"), |b| {
            b.iter(|| {
                let design = elaborate(&sources, &files, &options).expect("elaborates");
                let sim = SimOptions {
                    stop,
                    ..SimOptions::default()
                };
                black_box(simulate(&design, &sim, &mut |_| {}).expect("runs"))
            })
        });
    }
    group.finish();
    let mut parse = c.benchmark_group("frontend");
    parse.sample_size(20);
    let bytes: usize = files
        .iter()
        .map(|(id, _)| sources.file(*id).text.len())
        .sum();
    parse.throughput(Throughput::Bytes(bytes as u64));
    parse.bench_function("parse/models+stdlib", |b| {
        b.iter(|| {
            for (id, _) in &files {
                let text = sources.file(*id).text.clone();
                black_box(parser::parse(*id, &text));
            }
        })
    });
    // Analysis of every unit (the stdlib and the models), from parsed files; goal 20 ms.
    parse.bench_function("analyse/models+stdlib", |b| {
        b.iter(|| black_box(vams::analysis::analyse(&sources, &files)))
    });
    // Re-analysis after a one-line edit of one model file (an editor's keystroke): the
    // host re-parses the file and re-analyses from the first unit the edit affects; goal 5 ms.
    let mut host = vams::analysis::AnalysisHost::new();
    for (name, text) in models() {
        host.set_file(&name, text);
    }
    let motor = models()
        .into_iter()
        .find(|(n, _)| n.ends_with("dc_motor.vhd"))
        .expect("the motor model");
    let edited = motor.1.replacen("begin", "begin\n  -- edited", 1);
    let mut flip = false;
    parse.bench_function("reanalyse/one-line-edit", |b| {
        b.iter(|| {
            flip = !flip;
            let text = if flip { &edited } else { &motor.1 };
            host.set_file(&motor.0, text.clone());
            black_box(host.analysis().units.len())
        })
    });
    parse.finish();
    generated_frontend(c);
}

/// Parse + elaborate of the generated design, and each stage alone.
fn generated_frontend(c: &mut Criterion) {
    let text = generated();
    let user = vec![("generated.vhd".to_string(), text.clone())];
    let (sources, files) = parse_with_stdlib(user);
    let options = ElabOptions {
        top: "bench_top".into(),
        generics: Vec::new(),
    };
    let design = elaborate(&sources, &files, &options).expect("the generated design elaborates");
    assert!(design.quantities.len() > COPIES * 50);
    let id = files.last().expect("the generated file").0;
    let mut group = c.benchmark_group("frontend");
    group.sample_size(10);
    group.throughput(Throughput::Bytes(text.len() as u64));
    group.bench_function("parse/generated", |b| {
        b.iter(|| black_box(parser::parse(id, &text)))
    });
    group.bench_function("elaborate/generated", |b| {
        b.iter(|| black_box(elaborate(&sources, &files, &options)))
    });
    let mut fresh = files.clone();
    group.bench_function("parse+elaborate/generated", |b| {
        b.iter(|| {
            if let Some(last) = fresh.last_mut() {
                last.1 = parser::parse(id, &text).0;
            }
            black_box(elaborate(&sources, &fresh, &options))
        })
    });
    group.finish();
}

criterion_group!(benches, headlight);
criterion_main!(benches);
