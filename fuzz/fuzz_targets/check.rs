//! What `vams check` does, on arbitrary bytes taken as one source file: parse, analyse,
//! elaborate every top candidate and build its analog system. Any input must end in
//! diagnostics or a design, never a panic, an abort or a hang (no simulation here: the
//! bounded mutation test, `tests/it/mutation.rs`, runs short simulations of mutated models).
//! Seed corpus: `fuzz/seed.sh` copies the repository's models and tests into
//! `fuzz/corpus/check/`.

#![no_main]

use libfuzzer_sys::fuzz_target;
use vams::analog::AnalogSystem;
use vams::analysis::analyse;
use vams::app::load::load_text;
use vams::elaborate::{ElabOptions, elaborate_analysed, top_candidates};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let loaded = load_text("fuzz.vhd", text.to_string());
    let analysis = analyse(&loaded.sources, &loaded.files);
    if loaded.error_count() > 0 {
        return;
    }
    for top in top_candidates(&analysis, &loaded.files) {
        if !top.can_elaborate() || !top.has_architecture {
            continue;
        }
        let options = ElabOptions {
            top: top.name.clone(),
            generics: Vec::new(),
        };
        if let Ok(design) = elaborate_analysed(&analysis, &loaded.sources, &loaded.files, &options)
            && top.is_closed()
            && !design.quantities.is_empty()
        {
            let _ = AnalogSystem::new(&design);
        }
    }
});
