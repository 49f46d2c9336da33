//! Positions and names as the protocol has them: line and UTF-16 column, `file:` URIs; words at a
//! place in a text.

use lsp_types::{Position, Range, Uri};
use std::path::{Path, PathBuf};
use std::str::FromStr;

/// The byte offset of `position` in `text` (clamped to its line's end and the text's end).
pub(super) fn offset_of(text: &str, position: Position) -> usize {
    let mut line_start = 0;
    for _ in 0..position.line {
        match text[line_start..].find('\n') {
            Some(at) => line_start += at + 1,
            None => return text.len(),
        }
    }
    let line_end = text[line_start..].find('\n').map_or(text.len(), |at| line_start + at);
    let mut units = 0;
    for (at, c) in text[line_start..line_end].char_indices() {
        if units >= position.character as usize {
            return line_start + at;
        }
        units += c.len_utf16();
    }
    line_end
}

/// The position of byte `offset` of `text` (clamped to the text, moved back to a char boundary).
pub(super) fn position_of(text: &str, offset: usize) -> Position {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let line = before.matches('\n').count();
    let line_start = before.rfind('\n').map_or(0, |at| at + 1);
    let character: usize = before[line_start..].chars().map(char::len_utf16).sum();
    Position::new(line as u32, character as u32)
}

/// The range of bytes `range` of `text`.
pub(super) fn range_of(text: &str, range: std::ops::Range<usize>) -> Range {
    Range::new(position_of(text, range.start), position_of(text, range.end))
}

/// The file a `file:` URI names (`None` for other schemes and malformed ones).
pub(super) fn path_of(uri: &Uri) -> Option<PathBuf> {
    url::Url::parse(uri.as_str()).ok()?.to_file_path().ok()
}

/// The `file:` URI of an absolute path.
pub(super) fn uri_of(path: &Path) -> Option<Uri> {
    let absolute = std::path::absolute(path).ok()?;
    Uri::from_str(url::Url::from_file_path(absolute).ok()?.as_str()).ok()
}

fn is_name_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// The identifier at (or just before) `offset`, with its byte range.
pub(super) fn word_at(text: &str, offset: usize) -> Option<(&str, std::ops::Range<usize>)> {
    let offset = offset.min(text.len());
    if !text.is_char_boundary(offset) {
        return None;
    }
    let before = text[..offset].char_indices().rev().find(|&(_, c)| !is_name_char(c));
    let start = before.map_or(0, |(at, c)| at + c.len_utf8());
    let end = text[offset..].find(|c: char| !is_name_char(c)).map_or(text.len(), |at| offset + at);
    (start < end).then(|| (&text[start..end], start..end))
}

/// The text of the line `offset` is on, up to `offset`.
pub(super) fn line_before(text: &str, offset: usize) -> &str {
    let offset = offset.min(text.len());
    let offset = (0..=offset).rev().find(|&at| text.is_char_boundary(at)).unwrap_or(0);
    let start = text[..offset].rfind('\n').map_or(0, |at| at + 1);
    &text[start..offset]
}

/// Where `name` is declared at module scope in WGSL `text` (`fn`, `struct`, `var`, `const`,
/// `override`, `alias`): the byte range of the name. A plain scan, so it works on unsaved text
/// that does not parse.
pub(super) fn wgsl_declarations(
    text: &str,
) -> impl Iterator<Item = (&'static str, std::ops::Range<usize>)> + '_ {
    const KINDS: [&str; 6] = ["fn", "struct", "var", "const", "override", "alias"];
    let mut at = 0;
    std::iter::from_fn(move || {
        while at < text.len() {
            let start = at + text[at..].find(|c: char| c.is_ascii_alphabetic())?;
            let end = text[start..].find(|c: char| !is_name_char(c)).map_or(text.len(), |e| start + e);
            at = end;
            let preceded = start == 0 || !text[..start].ends_with(is_name_char);
            let Some(kind) = KINDS.iter().find(|k| **k == &text[start..end]).filter(|_| preceded) else {
                continue;
            };
            let mut rest = end;
            // `var<uniform>` and `var<storage, read>`: the name follows the template list.
            let after = text[rest..].trim_start();
            if *kind == "var" && after.starts_with('<') {
                rest = text.len() - after.len();
                rest += text[rest..].find('>').map_or(0, |e| e + 1);
            }
            let skipped = text[rest..].len() - text[rest..].trim_start().len();
            let name_start = rest + skipped;
            let name_end =
                text[name_start..].find(|c: char| !is_name_char(c)).map_or(text.len(), |e| name_start + e);
            if name_end > name_start && !text[name_start..].starts_with(|c: char| c.is_ascii_digit()) {
                at = name_end;
                return Some((*kind, name_start..name_end));
            }
        }
        None
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positions_count_utf16_units() {
        let text = "a\n\u{1F600}b\nc";
        assert_eq!(offset_of(text, Position::new(1, 2)), 6);
        assert_eq!(position_of(text, 6), Position::new(1, 2));
        assert_eq!(offset_of(text, Position::new(1, 99)), 7);
        assert_eq!(offset_of(text, Position::new(9, 0)), text.len());
        assert_eq!(position_of(text, 4), Position::new(1, 0));
    }

    #[test]
    fn words_and_declarations() {
        let text = "var<uniform> _Light: L;\nfn shade(x: f32) {}\nstruct S { a: f32 }";
        assert_eq!(word_at(text, 15).map(|w| w.0), Some("_Light"));
        assert_eq!(word_at("\u{1F600}ab", 5).map(|w| w.0), Some("ab"));
        let found: Vec<(&str, &str)> = wgsl_declarations(text).map(|(k, r)| (k, &text[r])).collect();
        assert_eq!(found, [("var", "_Light"), ("fn", "shade"), ("struct", "S")]);
    }
}
