//! "Did you mean": the closest known name to a misspelt one.
//!
//! Takes a name and the candidates in scope; gives the nearest candidate when it is near
//! enough to be a likely typo (strsim's Damerau-Levenshtein and Jaro-Winkler), else nothing.

/// The candidate nearest `name`, if it is a plausible misspelling of it.
pub fn suggest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<String> {
    let mut best: Option<(f64, &str)> = None;
    for c in candidates {
        if c == name {
            continue;
        }
        let edits = strsim::damerau_levenshtein(name, c);
        let similarity = strsim::jaro_winkler(name, c);
        let close = edits <= 1 || (edits <= 2 && name.len() > 3) || similarity >= 0.88;
        if close && best.is_none_or(|(s, _)| similarity > s) {
            best = Some((similarity, c));
        }
    }
    best.map(|(_, c)| c.to_string())
}

#[cfg(test)]
mod tests {
    use super::suggest;

    #[test]
    fn near_names_are_suggested() {
        assert_eq!(suggest("rlaod", ["rload", "vin"]), Some("rload".into()));
        assert_eq!(suggest("gain", ["gain2", "offset"]), Some("gain2".into()));
        assert_eq!(suggest("x", ["offset", "vdd"]), None);
        assert_eq!(suggest("abc", []), None);
    }
}
