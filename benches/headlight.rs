//! The project's main job as a benchmark: the headlight servo's two verification runs
//! (`tb_tracking`, 6 s; `tb_overvoltage`, 8 s) at default tolerance, from parsed sources to the
//! recorded waveforms (elaboration included, parsing excluded), and the front end alone
//! (parse + elaborate). Goal: well under 0.2 s per run on the 2-core CI machine.
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

fn load() -> (SourceMap, Vec<(FileId, DesignFile)>) {
    let mut sources = SourceMap::new();
    let mut ids = stdlib::load(&mut sources);
    let dir = format!("{}/models", env!("CARGO_MANIFEST_DIR"));
    let mut paths: Vec<_> = std::fs::read_dir(&dir)
        .expect("models/ exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "vhd"))
        .collect();
    paths.sort();
    for p in paths {
        let text = std::fs::read_to_string(&p).expect("model readable");
        ids.push(sources.add(p.display().to_string(), "work", text));
    }
    let files = ids
        .iter()
        .map(|&id| {
            let text = sources.file(id).text.clone();
            (id, parser::parse(id, &text).0)
        })
        .collect();
    (sources, files)
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
    parse.finish();
}

criterion_group!(benches, headlight);
criterion_main!(benches);
