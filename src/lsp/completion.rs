//! Completion: after a tick (`q'd|`), the predefined attributes; elsewhere, the names visible
//! at the cursor (`Analysis::names_at`: the innermost declarative part and every region around
//! it, what use clauses import included).

use lsp_types::{CompletionItem, CompletionItemKind};

use crate::analysis::PREDEFINED_ATTRIBUTES;
use crate::source::FileId;

use super::workspace::Workspace;

pub fn completion(ws: &Workspace, file: FileId, offset: usize) -> Vec<CompletionItem> {
    let text = ws.text(file);
    if after_tick(text, offset) {
        return PREDEFINED_ATTRIBUTES
            .iter()
            .map(|a| CompletionItem {
                label: a.to_string(),
                kind: Some(CompletionItemKind::PROPERTY),
                detail: Some("predefined attribute".to_string()),
                ..CompletionItem::default()
            })
            .collect();
    }
    ws.host()
        .analysis()
        .names_at(file, offset as u32)
        .into_iter()
        .map(|name| CompletionItem {
            label: name,
            ..CompletionItem::default()
        })
        .collect()
}

/// True when the word being typed at `offset` follows a tick that follows a name or a
/// closing parenthesis (an attribute name, not a character literal).
fn after_tick(text: &str, offset: usize) -> bool {
    let mut at = offset.min(text.len());
    while !text.is_char_boundary(at) {
        at -= 1;
    }
    let before = &text[..at];
    let word = before
        .trim_end_matches(|c: char| c.is_ascii_alphanumeric() || c == '_')
        .len();
    let Some(head) = before[..word].strip_suffix('\'') else {
        return false;
    };
    head.ends_with(|c: char| c.is_ascii_alphanumeric() || c == '_' || c == ')')
}

#[cfg(test)]
mod tests {
    use super::after_tick;

    #[test]
    fn a_tick_after_a_name_starts_an_attribute() {
        assert!(after_tick("v'", 2));
        assert!(after_tick("x <= v'do", 9));
        assert!(after_tick("a(1)'ra", 7));
        assert!(!after_tick("c <= '", 6));
        assert!(!after_tick("v", 1));
        assert!(!after_tick("", 0));
        // An offset past the end, or inside a character, does not panic.
        assert!(!after_tick("é", 1));
        assert!(after_tick("q'", 99));
    }
}
