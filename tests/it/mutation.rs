//! Bounded mutation test (reliability): the models of `tests/` and `models/`, mutated
//! deterministically (a token dropped, replaced or inserted, a line dropped, repeated or moved,
//! a number changed to an extreme, the file cut short), go through what `vams check` does
//! (parse, analyse, elaborate every candidate top, build its analog system) and, for those that
//! elaborate, a short simulation. Whatever the mutant, vams must answer with diagnostics or
//! results: no panic, no hang (each run is cancelled after a few seconds of wall time, and a
//! run that ignores the cancel fails the test). `VAMS_MUTANTS=N` sets the number of mutants
//! (default 1000, seconds in a debug build); `VAMS_MUTATION_SEED` the first seed.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use vams::analysis::analyse;
use vams::app::load::load;
use vams::elaborate::{ElabOptions, elaborate_analysed, top_candidates};
use vams::kernel::{Cancel, SimOptions, simulate};

/// A small deterministic generator (xorshift64*): the same seed gives the same mutants on
/// every machine.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

/// Byte ranges of the tokens of `text`: runs of identifier characters, or single other
/// non-space characters.
fn tokens(text: &str) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let bytes = text.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        if c.is_ascii_whitespace() {
            i += 1;
            continue;
        }
        let start = i;
        if c.is_ascii_alphanumeric() || c == b'_' || c == b'.' {
            while i < bytes.len()
                && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_' || bytes[i] == b'.')
            {
                i += 1;
            }
        } else {
            // One character (a multi-byte one whole).
            i += text[i..].chars().next().map_or(1, char::len_utf8);
        }
        out.push((start, i));
    }
    out
}

const INSERTS: &[&str] = &[
    ";",
    "(",
    ")",
    ",",
    "end",
    "begin",
    "is",
    "'dot",
    "==",
    "<=",
    ":=",
    "=>",
    "process",
    "if",
    "loop",
    "others",
    "'",
    "\"",
    "0",
    "1.0e308",
    "-",
    "**",
    "(others => '1')",
    "wait;",
];

const NUMBERS: &[&str] = &[
    "0",
    "0.0",
    "-1",
    "2147483647",
    "-2147483648",
    "9223372036854775807",
    "1.0e308",
    "1.0e-320",
    "1.0e400",
    "16#FFFF_FFFF#",
    "0 ns",
    "1 fs",
    "1.0e9 sec",
];

/// One mutant of `text`.
fn mutate(text: &str, rng: &mut Rng) -> String {
    let toks = tokens(text);
    let lines: Vec<&str> = text.lines().collect();
    if toks.is_empty() || lines.is_empty() {
        return text.to_string();
    }
    let (s, e) = toks[rng.below(toks.len())];
    match rng.below(8) {
        0 => format!("{}{}", &text[..s], &text[e..]),
        1 => {
            let (s2, e2) = toks[rng.below(toks.len())];
            format!("{}{}{}", &text[..s], &text[s2..e2], &text[e..])
        }
        2 => {
            let insert = INSERTS[rng.below(INSERTS.len())];
            format!("{} {insert} {}", &text[..s], &text[s..])
        }
        3 => {
            let numbers: Vec<&(usize, usize)> = toks
                .iter()
                .filter(|(a, _)| text.as_bytes()[*a].is_ascii_digit())
                .collect();
            match numbers.get(rng.below(numbers.len())) {
                Some(&&(a, b)) => {
                    let n = NUMBERS[rng.below(NUMBERS.len())];
                    format!("{}{n}{}", &text[..a], &text[b..])
                }
                None => text.to_string(),
            }
        }
        4 => {
            let k = rng.below(lines.len());
            let mut out: Vec<&str> = lines.clone();
            out.remove(k);
            out.join("\n")
        }
        5 => {
            let k = rng.below(lines.len());
            let mut out: Vec<&str> = lines.clone();
            out.insert(k, lines[k]);
            out.join("\n")
        }
        6 => {
            let (a, b) = (rng.below(lines.len()), rng.below(lines.len()));
            let mut out: Vec<&str> = lines.clone();
            out.swap(a, b);
            out.join("\n")
        }
        _ => text[..s].to_string(),
    }
}

/// The `.vhd` files under `dir`, sorted.
fn vhd_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut paths: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
    paths.sort();
    for p in paths {
        if p.is_dir() {
            vhd_files(&p, out);
        } else if p.extension().is_some_and(|e| e == "vhd") {
            out.push(p);
        }
    }
}

/// What `vams check` does, then a short run of each top that elaborates; `Err` names a run
/// that did not stop when cancelled.
fn check_and_run(paths: &[PathBuf]) -> Result<(), String> {
    let Ok(loaded) = load(paths) else {
        return Ok(());
    };
    if loaded.error_count() > 0 {
        return Ok(());
    }
    let analysis = analyse(&loaded.sources, &loaded.files);
    for top in top_candidates(&analysis, &loaded.files) {
        if !top.can_elaborate() || !top.has_architecture {
            continue;
        }
        let options = ElabOptions {
            top: top.name.clone(),
            generics: Vec::new(),
        };
        let Ok(design) = elaborate_analysed(&analysis, &loaded.sources, &loaded.files, &options)
        else {
            continue;
        };
        if !top.is_closed() {
            continue;
        }
        let cancel = Cancel::new();
        let watchdog = cancel.clone();
        let sim = SimOptions {
            stop: 1e-6,
            cancel: Some(cancel),
            ..SimOptions::default()
        };
        let (done_tx, done_rx) = std::sync::mpsc::channel::<()>();
        let timer = std::thread::spawn(move || {
            if done_rx.recv_timeout(Duration::from_secs(3)).is_err() {
                watchdog.cancel();
            }
        });
        let started = Instant::now();
        let _ = simulate(&design, &sim, &mut |_| {});
        let _ = done_tx.send(());
        let _ = timer.join();
        if started.elapsed() > Duration::from_secs(20) {
            return Err(format!(
                "`{}` ran {:?} after being cancelled at 3 s",
                top.name,
                started.elapsed()
            ));
        }
    }
    Ok(())
}

#[test]
fn mutated_models_give_diagnostics_never_a_panic_or_a_hang() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    vhd_files(&root.join("tests"), &mut files);
    let models: Vec<PathBuf> = {
        let mut m = Vec::new();
        vhd_files(&root.join("models"), &mut m);
        m.retain(|p| p.parent() == Some(&root.join("models")));
        m
    };
    files.extend(models.iter().cloned());
    assert!(files.len() > 50, "found {} model files", files.len());
    let count: usize = std::env::var("VAMS_MUTANTS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1000);
    let seed: u64 = std::env::var("VAMS_MUTATION_SEED")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1);
    let dir = tempfile::tempdir().unwrap();
    let mut failures = Vec::new();
    for k in 0..count {
        let seed = seed + k as u64;
        let mut rng = Rng(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1);
        let original = &files[rng.below(files.len())];
        let text = std::fs::read_to_string(original).unwrap();
        let mut mutant = text.clone();
        for _ in 0..1 + rng.below(3) {
            mutant = mutate(&mutant, &mut rng);
        }
        // A model of `models/` is checked with its siblings (a testbench needs the parts).
        let case = dir.path().join(format!("m{k}"));
        std::fs::create_dir_all(&case).unwrap();
        let name = original.file_name().unwrap();
        if models.contains(original) {
            for m in &models {
                if m != original {
                    std::fs::copy(m, case.join(m.file_name().unwrap())).unwrap();
                }
            }
        }
        std::fs::write(case.join(name), &mutant).unwrap();
        let mut paths: Vec<PathBuf> = Vec::new();
        vhd_files(&case, &mut paths);
        if std::env::var_os("VAMS_MUTATION_TRACE").is_some() {
            eprintln!("seed {seed}: {}", original.display());
        }
        // On a thread with the command line's stack (`main` runs everything on one).
        let outcome = std::thread::scope(|scope| {
            std::thread::Builder::new()
                .stack_size(vams::kernel::DEEP_STACK)
                .spawn_scoped(scope, || {
                    catch_unwind(AssertUnwindSafe(|| check_and_run(&paths)))
                })
                .expect("a thread starts")
                .join()
                .unwrap_or_else(Err)
        });
        let problem = match outcome {
            Ok(Ok(())) => None,
            Ok(Err(hang)) => Some(hang),
            Err(panic) => Some(
                panic
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_else(|| "a panic".into()),
            ),
        };
        if let Some(problem) = problem {
            // Keep the mutant where a developer finds it.
            let keep = root.join("target").join("mutants");
            std::fs::create_dir_all(&keep).unwrap();
            let kept = keep.join(format!("seed{seed}_{}", name.to_string_lossy()));
            std::fs::write(&kept, &mutant).unwrap();
            failures.push(format!(
                "seed {seed} ({}): {problem}; mutant kept in {}",
                original.display(),
                kept.display()
            ));
        }
        std::fs::remove_dir_all(&case).unwrap();
    }
    assert!(
        failures.is_empty(),
        "{} of {count} mutants failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
