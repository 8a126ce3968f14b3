//! Shared by the unit tests: property tests on a fixed seed (overridable from the
//! environment, `PROPTEST_RNG_SEED` / `PROPTEST_CASES`), and reading a deck from a string.

use proptest::test_runner::{Config, RngSeed};

use crate::deck::Deck;
use crate::error::SpiceError;
use crate::loader::MemLoader;
use crate::reader::read_deck;
use vams_syntax::source::SourceMap;

/// `cases` cases from a fixed seed.
pub fn config(cases: u32) -> Config {
    let mut config = Config::default();
    if std::env::var_os("PROPTEST_CASES").is_none() {
        config.cases = cases;
    }
    if config.rng_seed == RngSeed::Random {
        config.rng_seed = RngSeed::Fixed(10_761);
    }
    config
}

/// Reads `text` as `deck.cir`, with `files` loadable.
pub fn read_with(text: &str, files: &[(&str, &str)]) -> (Deck, Vec<SpiceError>, SourceMap) {
    let mut sources = SourceMap::new();
    let id = sources.add("deck.cir", "work", text.to_string());
    let mut loader = MemLoader::new();
    for (path, text) in files {
        loader.insert(*path, *text);
    }
    let (deck, errors) = read_deck(&mut sources, id, &mut loader);
    (deck, errors, sources)
}

/// Reads `text`, asserting it has no error.
pub fn read_ok(text: &str) -> Deck {
    let (deck, errors, _) = read_with(text, &[]);
    assert!(errors.is_empty(), "{errors:#?}");
    deck
}
