//! A quick structural scan run before the grammar: it finds unterminated strings and comments,
//! unclosed program blocks and unbalanced braces, all in one pass, and points at where they
//! start. The grammar alone would stop at the first and blame the end of the file.
//!
//! Returns the lexical problems (always reported) and the brace problems (reported when they
//! explain the grammar's error) separately.

use crate::shaderlab::ast::ProgramLanguage;
use crate::shaderlab::error::ShaderLabError;
use crate::source::{FileId, Span};

/// Deeper nesting than any real shader needs; the limit keeps the recursive grammar off the end
/// of the stack.
pub(super) const MAX_NESTING: usize = 64;

pub(crate) fn scan(file: FileId, text: &str) -> (Vec<ShaderLabError>, Vec<ShaderLabError>) {
    let bytes = text.as_bytes();
    let line_starts: Vec<usize> = std::iter::once(0)
        .chain(bytes.iter().enumerate().filter(|(_, b)| **b == b'\n').map(|(i, _)| i + 1))
        .collect();
    let indentation = |at: usize| {
        let start = line_starts[line_starts.partition_point(|&s| s <= at) - 1];
        let indent = bytes[start..at].iter().take_while(|&&b| b == b' ' || b == b'\t').count();
        // The indentation, and whether the brace is the first thing on its line.
        (indent, start + indent == at)
    };
    let mut errors = Vec::new();
    let mut braces = Vec::new();
    // Open braces: their offset and the indentation of their line.
    let mut open: Vec<(usize, usize)> = Vec::new();
    // The first brace whose closing `}` sits at another indentation: the likely culprit.
    let mut misindented: Option<usize> = None;
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'/' if bytes.get(i + 1) == Some(&b'/') => i = line_end(bytes, i),
            b'/' if bytes.get(i + 1) == Some(&b'*') => match text[i + 2..].find("*/") {
                Some(end) => i += end + 4,
                None => {
                    errors.push(ShaderLabError::UnterminatedComment { span: Span::new(file, i..i + 2) });
                    return (errors, braces);
                }
            },
            b'"' => {
                let mut j = i + 1;
                while j < bytes.len() && bytes[j] != b'"' && bytes[j] != b'\n' {
                    j += if bytes[j] == b'\\' && bytes.get(j + 1).is_some_and(|&b| b != b'\n') {
                        2
                    } else {
                        1
                    };
                }
                if bytes.get(j) == Some(&b'\n')
                    && let Some(close) = display_name_end(bytes, i)
                {
                    j = close;
                }
                if j >= bytes.len() || bytes[j] != b'"' {
                    let end = j.min(bytes.len());
                    let end = if end > i + 1 && bytes[end - 1] == b'\r' { end - 1 } else { end };
                    errors.push(ShaderLabError::UnterminatedString { span: Span::new(file, i..end) });
                }
                i = j + 1;
            }
            b'{' => {
                if open.len() == MAX_NESTING {
                    errors.push(ShaderLabError::NestedTooDeep {
                        span: Span::new(file, i..i + 1),
                        limit: MAX_NESTING,
                    });
                    return (errors, braces);
                }
                open.push((i, indentation(i).0));
                i += 1;
            }
            b'}' => {
                match open.pop() {
                    Some((at, indent)) => {
                        let (close_indent, first_on_line) = indentation(i);
                        if misindented.is_none() && first_on_line && close_indent != indent {
                            misindented = Some(at);
                        }
                    }
                    None => {
                        braces.push(ShaderLabError::UnmatchedCloseBrace { span: Span::new(file, i..i + 1) })
                    }
                }
                i += 1;
            }
            b if b.is_ascii_alphabetic() || b == b'_' => {
                let start = i;
                while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                    i += 1;
                }
                if let Some((language, include)) = program_opening(&text[start..i]) {
                    let close = language.close_keyword();
                    match find_ignore_case(&text[i..], close) {
                        Some(end) => i += end + close.len(),
                        None => {
                            errors.push(ShaderLabError::UnclosedProgram {
                                open: Span::new(file, start..i),
                                language,
                                include,
                            });
                            return (errors, braces);
                        }
                    }
                }
            }
            _ => i += 1,
        }
    }
    if let Some(&(outer, _)) = open.first() {
        let likely = misindented.filter(|&at| at != outer).map(|at| Span::new(file, at..at + 1));
        braces.push(ShaderLabError::UnclosedBrace { open: Span::new(file, outer..outer + 1), likely });
    }
    (errors, braces)
}

/// Where a property's display name that runs over lines closes: a string right after `NAME (`
/// whose closing quote is followed by `,` (Unity reads `_Mode ("Preset--{...\n...}", Int)`).
/// Any other string ends on its line.
fn display_name_end(bytes: &[u8], open: usize) -> Option<usize> {
    let before = bytes[..open].iter().rposition(|b| !b.is_ascii_whitespace())?;
    let name_end = bytes[..before].iter().rposition(|b| !b.is_ascii_whitespace())?;
    if bytes[before] != b'(' || !(bytes[name_end].is_ascii_alphanumeric() || bytes[name_end] == b'_') {
        return None;
    }
    let mut j = open + 1;
    while j < bytes.len() && bytes[j] != b'"' {
        j += if bytes[j] == b'\\' { 2 } else { 1 };
    }
    let after = bytes.get(j + 1..)?.iter().find(|b| !b.is_ascii_whitespace());
    (after == Some(&b',')).then_some(j)
}

fn program_opening(word: &str) -> Option<(ProgramLanguage, bool)> {
    ProgramLanguage::ALL.into_iter().find_map(|language| {
        [false, true]
            .into_iter()
            .find(|&include| word.eq_ignore_ascii_case(language.open_keyword(include)))
            .map(|include| (language, include))
    })
}

fn find_ignore_case(haystack: &str, needle: &str) -> Option<usize> {
    let (h, n) = (haystack.as_bytes(), needle.as_bytes());
    (0..h.len().saturating_sub(n.len() - 1)).find(|&i| h[i..i + n.len()].eq_ignore_ascii_case(n))
}

fn line_end(bytes: &[u8], from: usize) -> usize {
    bytes[from..].iter().position(|&b| b == b'\n').map_or(bytes.len(), |p| from + p)
}
