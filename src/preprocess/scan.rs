//! Splits a file (or a program block of a `.shader` file) into runs of text and directives, once
//! per file. Every variant then walks this list instead of re-reading the text, and structural
//! mistakes (unbalanced conditionals, malformed directives) are reported once, not per variant.
//!
//! Long because it is one scanner: every directive's syntax is read here, in one pass, and the
//! conditional links need them all; split, the pieces would share the scanner's state.

use super::error::PreprocessError;
use super::macros::{
    BodyToken, is_ident_char, is_ident_start, lex_body, pp_number_end, splice_len, starts_pp_number,
};
use crate::source::{FileId, Span};
use std::ops::Range;

/// Conditionals nested deeper than this are refused (C guarantees 63 levels).
pub const MAX_CONDITIONAL_DEPTH: usize = 64;

/// Keyword pragmas, which count only in the pass's own blocks and `#include_with_pragmas` files.
const KEYWORD_PRAGMAS: [&str; 3] = ["multi_compile", "shader_feature", "dynamic_branch"];

/// One scanned file, or one program block of a `.shader` file.
#[derive(Debug)]
pub(crate) struct Unit {
    pub file: FileId,
    pub range: Range<usize>,
    pub items: Vec<Item>,
    /// The macro of a classic include guard (`#ifndef X` / `#define X` ... `#endif` around
    /// everything): once X is defined, including the file again adds nothing, so it is skipped.
    pub guard: Option<String>,
    pub pragma_once: bool,
    /// Keyword pragmas in this file, reported when it is reached through a plain `#include`.
    pub keyword_pragmas: Vec<(Span, String)>,
}

#[derive(Debug)]
pub(crate) enum Item {
    /// Source text copied to the output. `idents` are the identifiers (outside comments and
    /// strings) a macro may replace, as file offsets.
    Text {
        start: u32,
        end: u32,
        idents: Vec<(u32, u32)>,
        code: bool,
        /// The run has line splices (rare: WGSL has no `\\`), which copying must drop.
        spliced: bool,
    },
    Include {
        name: String,
        span: Span,
        with_pragmas: bool,
        target: Target,
    },
    Define {
        name: String,
        span: Span,
        /// A function-like macro's parameters (`None`: object-like).
        params: Option<Vec<String>>,
        /// The last parameter is `...` (`__VA_ARGS__`).
        variadic: bool,
        value: String,
        /// `value`'s tokens, lexed once here rather than by every variant.
        body: Vec<super::macros::BodyToken>,
    },
    Undef {
        name: String,
    },
    /// `#if`, `#ifdef`, `#ifndef`, `#elif` or `#else`. `next` is the item of the following branch
    /// (or the `#endif`), `end` the `#endif`, so skipping a group is one jump.
    Branch {
        kind: BranchKind,
        next: u32,
        end: u32,
    },
    Endif,
    Error {
        message: String,
        span: Span,
    },
    Warning {
        message: String,
        span: Span,
    },
    /// A directive found malformed inside a conditional group: reported only when the run
    /// reaches it, since C does not check directives in a group it skips.
    Refused(PreprocessError),
}

impl Item {
    /// Where the item is in `file`, for the kinds that keep it (text runs, includes, defines,
    /// `#error` and `#warning`).
    pub(crate) fn span(&self, file: FileId) -> Option<Span> {
        match self {
            Item::Text { start, end, .. } => Some(Span::new(file, *start as usize..*end as usize)),
            Item::Include { span, .. }
            | Item::Define { span, .. }
            | Item::Error { span, .. }
            | Item::Warning { span, .. } => Some(*span),
            Item::Undef { .. } | Item::Refused(_) | Item::Branch { .. } | Item::Endif => None,
        }
    }
}

#[derive(Debug)]
pub(crate) enum BranchKind {
    If(Condition),
    Elif(Condition),
    Else,
}

#[derive(Debug)]
pub(crate) enum Condition {
    /// An `#if` / `#elif` expression; `start` is the file offset of its first byte, so evaluator
    /// offsets become spans.
    Expr {
        text: String,
        start: u32,
    },
    Defined {
        name: String,
        span: Span,
    },
    NotDefined {
        name: String,
        span: Span,
    },
    /// `#if` or `#elif` with nothing after it, or `#elifdef` without a name: an error only if
    /// the run evaluates it (C does not evaluate an `#elif` after a taken group, DR 412, nor an
    /// `#elifdef`'s name).
    Missing {
        directive: &'static str,
        span: Span,
        expected: &'static str,
    },
    /// An `#elifdef` or `#elifndef` with more after its name: an error where the run evaluates
    /// it, skipped unread after a taken group, as C skips it.
    Trailing {
        condition: Box<Condition>,
        directive: &'static str,
        span: Span,
    },
}

/// What a directive with more on its line was expected to end with.
pub(crate) const END_OF_LINE: &str = "the end of the line (put remarks in a `//` comment)";

/// Where an `#include` points, filled in by include resolution after scanning.
#[derive(Debug, Clone)]
pub(crate) enum Target {
    Pending,
    Unit(usize),
    Failed(PreprocessError),
}

/// Scans `text[range]` (the whole file, or one program block's body).
pub(crate) fn scan(file: FileId, text: &str, range: Range<usize>) -> (Unit, Vec<PreprocessError>) {
    let mut scanner = Scanner {
        file,
        text,
        unit: Unit {
            file,
            range: range.clone(),
            items: Vec::new(),
            guard: None,
            pragma_once: false,
            keyword_pragmas: Vec::new(),
        },
        errors: Vec::new(),
        open: Vec::new(),
        comment_depth: 0,
        comment_start: 0,
        run: None,
    };
    let mut pos = range.start;
    while pos < range.end {
        let line_end = next_line(text, pos, range.end);
        if scanner.comment_depth == 0 && is_directive(&text[pos..line_end]) {
            scanner.flush_text();
            // A directive goes on after a line splice, and through a block comment's line
            // breaks (C removes comments before reading directives).
            let mut end = line_end;
            while end < range.end && (ends_with_splice(&text[pos..end]) || comment_open(&text[pos..end])) {
                end = next_line(text, end, range.end);
            }
            if !scanner.directive(pos, end) {
                // Too deeply nested: the structure cannot be trusted, so the file adds nothing.
                scanner.unit.items.clear();
                return (scanner.unit, scanner.errors);
            }
            pos = end;
        } else {
            // A line splice joins the next line to this one, in text as in directives.
            let mut end = line_end;
            while end < range.end && ends_with_splice(&text[pos..end]) {
                end = next_line(text, end, range.end);
            }
            scanner.text_line(pos, end);
            pos = end;
        }
    }
    scanner.flush_text();
    scanner.close_unterminated();
    scanner.errors.extend(splices_after_blanks(file, text, range));
    scanner.unit.guard = include_guard(&scanner.unit.items);
    (scanner.unit, scanner.errors)
}

/// The index of the `)` closing the `(` at `open` in a macro body (the last token when unclosed).
fn closing_paren(value: &str, tokens: &[BodyToken], open: usize) -> usize {
    let mut depth = 0;
    for (i, token) in tokens.iter().enumerate().skip(open) {
        match token.text(value) {
            "(" => depth += 1,
            ")" if depth == 1 => return i,
            ")" => depth -= 1,
            _ => {}
        }
    }
    tokens.len().saturating_sub(1)
}

fn next_line(text: &str, pos: usize, end: usize) -> usize {
    text[pos..end].find('\n').map_or(end, |i| pos + i + 1)
}

/// Whether the last line of `lines` ends in a line splice (`\` right before its line break). Only
/// that line's own break is removed before looking: an empty line after a spliced one ends the
/// directive, as in C, rather than letting the `\` reach past it and swallow the code below.
fn ends_with_splice(lines: &str) -> bool {
    let line = lines.strip_suffix('\n').unwrap_or(lines);
    // gcc also splices a `\` with blanks before the line break (K0334 warns of it).
    line.strip_suffix('\r').unwrap_or(line).trim_end_matches([' ', '\t']).ends_with('\\')
}

/// Each `\` with blanks between it and a line break in `text[range]`: a splice with a warning, as
/// gcc has it (the blanks are often invisible, and a `\` elsewhere is no splice).
fn splices_after_blanks(file: FileId, text: &str, range: Range<usize>) -> Vec<PreprocessError> {
    let bytes = text.as_bytes();
    text[range.clone()]
        .match_indices('\\')
        .map(|(at, _)| range.start + at)
        .filter(|&at| {
            splice_len(&bytes[at..range.end]) > 0 && matches!(bytes.get(at + 1), Some(b' ' | b'\t'))
        })
        .map(|at| PreprocessError::SpliceAfterBlanks { span: Span::new(file, at..at + 1) })
        .collect()
}

/// Whether a line is a directive: `#` first, after blanks and block comments that close on the
/// line (C replaces comments by a space before it looks for directives).
fn is_directive(line: &str) -> bool {
    let mut rest = line.trim_start_matches([' ', '\t']);
    while let Some(comment) = rest.strip_prefix("/*") {
        let Some(close) = comment.find("*/") else { return false };
        rest = comment[close + 2..].trim_start_matches([' ', '\t']);
    }
    rest.starts_with('#')
}

/// Whether a block comment is still open at the end of `text` (WGSL's nest; `//` ends a line).
fn comment_open(text: &str) -> bool {
    let bytes = text.as_bytes();
    let (mut depth, mut i) = (0usize, 0);
    while i < bytes.len() {
        let rest = &bytes[i..];
        if depth == 0 && rest.starts_with(b"//") {
            i += rest.iter().position(|&b| b == b'\n').unwrap_or(rest.len());
        } else if rest.starts_with(b"/*") {
            depth += 1;
            i += 2;
        } else if depth > 0 && rest.starts_with(b"*/") {
            depth -= 1;
            i += 2;
        } else {
            i += 1;
        }
    }
    depth > 0
}

/// Identifiers of an expression or macro value with their offsets (numbers are skipped, so the
/// `f` of `1.0f` is not a name).
pub(crate) fn identifiers(text: &str) -> impl Iterator<Item = (usize, &str)> {
    let bytes = text.as_bytes();
    let mut i = 0;
    std::iter::from_fn(move || {
        while i < bytes.len() {
            let b = bytes[i];
            if is_ident_start(b) {
                let start = i;
                while i < bytes.len() && is_ident_char(bytes[i]) {
                    i += 1;
                }
                return Some((start, &text[start..i]));
            }
            if starts_pp_number(bytes, i) {
                i = pp_number_end(bytes, i);
            } else {
                i += 1;
            }
        }
        None
    })
}

struct OpenConditional {
    directive: String,
    span: Span,
    last_branch: usize,
    branches: Vec<usize>,
    else_span: Option<Span>,
}

struct TextRun {
    start: usize,
    end: usize,
    idents: Vec<(u32, u32)>,
    code: bool,
    spliced: bool,
}

struct Scanner<'a> {
    file: FileId,
    text: &'a str,
    unit: Unit,
    errors: Vec<PreprocessError>,
    open: Vec<OpenConditional>,
    /// WGSL block comments nest, so this is a depth, not a flag.
    comment_depth: usize,
    /// Where the outermost open block comment starts.
    comment_start: usize,
    run: Option<TextRun>,
}

impl Scanner<'_> {
    fn span(&self, range: Range<usize>) -> Span {
        Span::new(self.file, range)
    }

    fn flush_text(&mut self) {
        if let Some(run) = self.run.take() {
            self.unit.items.push(Item::Text {
                start: run.start as u32,
                end: run.end as u32,
                idents: run.idents,
                code: run.code,
                spliced: run.spliced,
            });
        }
    }

    /// Records the identifiers of one line of WGSL, skipping comments and strings.
    fn text_line(&mut self, start: usize, end: usize) {
        let run =
            self.run.get_or_insert(TextRun { start, end, idents: Vec::new(), code: false, spliced: false });
        run.end = end;
        run.spliced |= self.text[start..end].contains('\\');
        let bytes = self.text.as_bytes();
        let mut i = start;
        while i < end {
            if self.comment_depth > 0 {
                if bytes[i..end].starts_with(b"*/") {
                    self.comment_depth -= 1;
                    i += 2;
                } else if bytes[i..end].starts_with(b"/*") {
                    self.comment_depth += 1;
                    i += 2;
                } else {
                    i += 1;
                }
                continue;
            }
            let b = bytes[i];
            if bytes[i..end].starts_with(b"//") {
                break;
            } else if bytes[i..end].starts_with(b"/*") {
                (self.comment_depth, self.comment_start) = (1, i);
                i += 2;
            } else if b == b'"' {
                run.code = true;
                i += 1;
                while i < end && bytes[i] != b'"' && bytes[i] != b'\n' {
                    i += if bytes[i] == b'\\' { 2 } else { 1 };
                }
                i += 1;
            } else if is_ident_start(b) {
                let s = i;
                loop {
                    while i < end && is_ident_char(bytes[i]) {
                        i += 1;
                    }
                    // One name across a line splice.
                    let splice = splice_len(&bytes[i..end]);
                    if splice == 0 || !bytes.get(i + splice).is_some_and(|&c| is_ident_char(c)) {
                        break;
                    }
                    i += splice;
                }
                run.idents.push((s as u32, i as u32));
                run.code = true;
            } else if starts_pp_number(&bytes[..end], i) {
                i = pp_number_end(&bytes[..end], i);
                run.code = true;
            } else {
                run.code |= !b.is_ascii_whitespace();
                i += 1;
            }
        }
    }

    /// Handles one directive spanning `start..end` (continuation lines included). Returns false
    /// when scanning must stop.
    fn directive(&mut self, start: usize, end: usize) -> bool {
        let cleaned = self.clean(start, end);
        let content_end = start + cleaned.trim_end().len();
        let hash = start + cleaned.find('#').unwrap_or(0);
        let mut cursor = Cursor { text: &cleaned, at: hash - start + 1, base: start };
        cursor.skip_space();
        let (name_start, name) = cursor.ident();
        let whole = self.span(hash..content_end);
        let name_span = self.span(hash..name_start + name.len());
        // What this directive finds wrong, deferred when it is inside a conditional group.
        let found = self.errors.len();
        match name {
            // `#` alone is C's null directive.
            "" if cursor.rest().trim().is_empty() => {}
            "" => {
                let token = cursor.rest().split_whitespace().next().unwrap_or("");
                self.errors.push(PreprocessError::UnknownDirective { span: whole, name: token.to_string() });
            }
            "include" | "include_with_pragmas" => {
                self.include(name == "include_with_pragmas", &mut cursor, whole)
            }
            "define" => self.define(&mut cursor, whole),
            "undef" => {
                if let Some((name, _)) = self.macro_name(&mut cursor, "undef", whole) {
                    self.expect_end(&mut cursor, "undef");
                    self.unit.items.push(Item::Undef { name });
                }
            }
            "ifdef" | "ifndef" | "elifdef" | "elifndef" => {
                let branch = name.starts_with("el");
                let condition = self.defined_condition(&mut cursor, name, whole);
                self.defer(found);
                if branch {
                    self.branch(name, name_span, BranchKind::Elif(condition));
                    return true;
                }
                return self.open_conditional(name, name_span, condition);
            }
            "if" | "elif" => {
                let rest_start = cursor.base + cursor.at;
                let condition = if cursor.rest().trim().is_empty() {
                    let directive = if name == "if" { "if" } else { "elif" };
                    Condition::Missing { directive, span: whole, expected: "an expression" }
                } else {
                    Condition::Expr { text: cursor.rest().to_string(), start: rest_start as u32 }
                };
                if name == "if" {
                    return self.open_conditional(name, name_span, condition);
                }
                self.branch(name, name_span, BranchKind::Elif(condition));
                return true;
            }
            "else" | "endif" => {
                self.extra_tokens(&mut cursor, name);
                if name == "else" {
                    self.branch("else", name_span, BranchKind::Else);
                } else {
                    self.endif(name_span);
                }
                return true;
            }
            "error" | "warning" => {
                let message = cursor.rest().trim();
                let message = message.strip_prefix('"').and_then(|m| m.strip_suffix('"')).unwrap_or(message);
                let message =
                    if message.is_empty() { format!("`#{name}` directive") } else { message.to_string() };
                self.unit.items.push(if name == "error" {
                    Item::Error { message, span: whole }
                } else {
                    Item::Warning { message, span: whole }
                });
            }
            "pragma" => {
                let rest = cursor.rest();
                let mut words = rest.split_whitespace();
                match words.next() {
                    Some("once") => self.unit.pragma_once = true,
                    Some(word) if KEYWORD_PRAGMAS.iter().any(|k| word.starts_with(k)) => {
                        self.unit.keyword_pragmas.push((whole, word.to_string()))
                    }
                    _ => {}
                }
            }
            other => self
                .errors
                .push(PreprocessError::UnknownDirective { span: name_span, name: other.to_string() }),
        }
        self.defer(found);
        true
    }

    /// The errors found since `from`, made items when inside a conditional group: C reads only
    /// the names of the directives in a group it skips, so they count only where the run goes.
    fn defer(&mut self, from: usize) {
        if !self.open.is_empty() {
            let deferred: Vec<PreprocessError> = self.errors.drain(from..).collect();
            self.unit.items.extend(deferred.into_iter().map(Item::Refused));
        }
    }

    /// Tokens after `#else` or `#endif` (`#endif _GUARD_H`): a warning, as gcc gives.
    fn extra_tokens(&mut self, cursor: &mut Cursor, directive: &str) {
        if let Some(span) = self.rest_span(cursor) {
            self.errors.push(PreprocessError::ExtraTokens { span, directive: directive.to_string() });
        }
    }

    /// Where the rest of a directive's line is, blanks aside, if anything is there.
    fn rest_span(&self, cursor: &Cursor) -> Option<Span> {
        let rest = cursor.rest();
        let trimmed = rest.trim_start();
        let start = cursor.base + cursor.at + (rest.len() - trimmed.len());
        let len = trimmed.trim_end().len();
        (len > 0).then(|| self.span(start..start + len))
    }

    /// The directive's text with comments and line continuations blanked out, byte for byte, so
    /// offsets into it are offsets into the file.
    fn clean(&mut self, start: usize, end: usize) -> String {
        let bytes = &self.text.as_bytes()[start..end];
        let mut out = bytes.to_vec();
        let mut i = 0;
        let mut in_string = false;
        while i < bytes.len() {
            let rest = &bytes[i..];
            if self.comment_depth > 0 {
                let step = if rest.starts_with(b"*/") {
                    self.comment_depth -= 1;
                    2
                } else if rest.starts_with(b"/*") {
                    self.comment_depth += 1;
                    2
                } else {
                    1
                };
                out[i..i + step].fill(b' ');
                i += step;
            } else if in_string {
                in_string = bytes[i] != b'"';
                i += 1;
            } else if rest.starts_with(b"//") {
                out[i..].fill(b' ');
                break;
            } else if rest.starts_with(b"/*") {
                (self.comment_depth, self.comment_start) = (1, start + i);
                out[i..i + 2].fill(b' ');
                i += 2;
            } else if let step @ 1.. = splice_len(rest) {
                out[i..i + step].fill(b' ');
                i += step;
            } else {
                in_string = bytes[i] == b'"';
                if bytes[i] == b'\n' || bytes[i] == b'\r' {
                    out[i] = b' ';
                }
                i += 1;
            }
        }
        // Only whole comments were blanked, and their delimiters are ASCII, so this is UTF-8.
        String::from_utf8(out).unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned())
    }

    fn include(&mut self, with_pragmas: bool, cursor: &mut Cursor, whole: Span) {
        let directive = if with_pragmas { "include_with_pragmas" } else { "include" };
        let malformed = PreprocessError::MalformedDirective {
            span: whole,
            directive: directive.to_string(),
            expected: "a file name in quotes, like `#include \"Common.wgsl\"`",
        };
        cursor.skip_space();
        let rest = cursor.rest();
        let close = match rest.as_bytes().first() {
            Some(b'"') => '"',
            Some(b'<') => '>',
            _ => return self.errors.push(malformed),
        };
        let Some(len) = rest[1..].find(close) else { return self.errors.push(malformed) };
        let name = &rest[1..1 + len];
        let name_start = cursor.base + cursor.at;
        let span = self.span(name_start..name_start + len + 2);
        if name.trim().is_empty() {
            return self.errors.push(malformed);
        }
        let name = name.to_string();
        cursor.at += len + 2;
        self.expect_end(cursor, directive);
        self.unit.items.push(Item::Include { name, span, with_pragmas, target: Target::Pending });
    }

    fn define(&mut self, cursor: &mut Cursor, whole: Span) {
        let Some((name, span)) = self.macro_name(cursor, "define", whole) else { return };
        // `(` right after the name makes a function-like macro; after a space, it is the value.
        let (params, variadic) = if cursor.rest().starts_with('(') {
            match self.parameters(cursor, whole) {
                Some((params, variadic)) => (Some(params), variadic),
                None => return,
            }
        } else {
            (None, false)
        };
        let value_start = cursor.base + cursor.at + (cursor.rest().len() - cursor.rest().trim_start().len());
        let value = cursor.rest().trim().to_string();
        let body = lex_body(&value);
        if !self.check_body(&value, &body, value_start, params.as_deref(), variadic) {
            return;
        }
        self.unit.items.push(Item::Define { name, span, params, variadic, value, body });
    }

    /// `(a, b)`, `(a, ...)`, `(...)` or `()`, with the cursor on `(`; the names and whether the
    /// macro is variadic.
    fn parameters(&mut self, cursor: &mut Cursor, whole: Span) -> Option<(Vec<String>, bool)> {
        let malformed = PreprocessError::MalformedDirective {
            span: whole,
            directive: "define".into(),
            expected: "parameter names in parentheses, like `#define F(a, b) ...` (or `...` last)",
        };
        cursor.at += 1;
        let mut params: Vec<String> = Vec::new();
        let mut variadic = false;
        cursor.skip_space();
        if cursor.rest().starts_with(')') {
            cursor.at += 1;
            return Some((params, false));
        }
        loop {
            cursor.skip_space();
            if cursor.rest().starts_with("...") {
                cursor.at += 3;
                variadic = true;
            } else {
                let (_, param) = cursor.ident();
                if param.is_empty() || param == "__VA_ARGS__" || params.iter().any(|p| p == param) {
                    self.errors.push(malformed);
                    return None;
                }
                params.push(param.to_string());
            }
            cursor.skip_space();
            if cursor.rest().starts_with(')') {
                cursor.at += 1;
                return Some((params, variadic));
            }
            if variadic || !cursor.rest().starts_with(',') {
                self.errors.push(malformed);
                return None;
            }
            cursor.at += 1;
        }
    }

    /// A macro body's operators: `#` stringification is refused (WGSL has no strings), and `##`
    /// needs a token on each side. `start` is the file offset of `value`.
    fn check_body(
        &mut self,
        value: &str,
        tokens: &[BodyToken],
        start: usize,
        params: Option<&[String]>,
        variadic: bool,
    ) -> bool {
        let span = |t: &BodyToken| {
            let range = t.range();
            Span::new(self.file, start + range.start..start + range.end)
        };
        let is_param = |name: &str| {
            params.is_some_and(|p| p.iter().any(|q| q == name) || (variadic && name == "__VA_ARGS__"))
        };
        // The end of the `__VA_OPT__(...)` group being read, to refuse one inside another.
        let mut in_va_opt: Option<usize> = None;
        for (i, token) in tokens.iter().enumerate() {
            let text = token.text(value);
            if in_va_opt.is_some_and(|end| i > end) {
                in_va_opt = None;
            }
            if text == "__VA_ARGS__" || text == "__VA_OPT__" {
                let reason = if !variadic {
                    Some("only a variadic macro's body (`...` last among its parameters) may use it")
                } else if text == "__VA_OPT__" && tokens.get(i + 1).is_none_or(|t| t.text(value) != "(") {
                    Some("`__VA_OPT__` must be followed by `(`")
                } else if text == "__VA_OPT__" && in_va_opt.is_some() {
                    Some("`__VA_OPT__(...)` may not contain another `__VA_OPT__`")
                } else {
                    None
                };
                if let Some(reason) = reason {
                    self.errors.push(PreprocessError::VariadicMisuse {
                        span: span(token),
                        name: text.to_string(),
                        reason,
                    });
                    return false;
                }
                if text == "__VA_OPT__" {
                    in_va_opt = Some(closing_paren(value, tokens, i + 1));
                }
            }
            if token.text(value) == "##" && (i == 0 || i + 1 == tokens.len()) {
                self.errors.push(PreprocessError::PasteAtEdge { span: span(token) });
                return false;
            }
            if token.text(value) == "#" && params.is_some() {
                let next = tokens.get(i + 1).filter(|t| is_param(t.text(value)));
                let name = next.map_or(String::new(), |t| t.text(value).to_string());
                let whole = next.map_or(span(token), |n| span(token).to(span(n)));
                self.errors.push(PreprocessError::Stringification { span: whole, name });
                return false;
            }
        }
        true
    }

    fn macro_name(&mut self, cursor: &mut Cursor, directive: &str, whole: Span) -> Option<(String, Span)> {
        cursor.skip_space();
        let (start, name) = cursor.ident();
        if directive == "define" && (name == "__VA_ARGS__" || name == "__VA_OPT__") {
            let span = self.span(start..start + name.len());
            let reason = "it is reserved for variadic macros' bodies and cannot be defined";
            self.errors.push(PreprocessError::VariadicMisuse { span, name: name.to_string(), reason });
            return None;
        }
        // `defined` cannot be defined, but `#ifdef defined` asks (and is false), as in gcc.
        let asks = matches!(directive, "ifdef" | "ifndef" | "elifdef" | "elifndef");
        if name.is_empty() || (name == "defined" && !asks) || name.as_bytes()[0].is_ascii_digit() {
            self.errors.push(PreprocessError::MalformedDirective {
                span: whole,
                directive: directive.to_string(),
                expected: "a macro name",
            });
            return None;
        }
        Some((name.to_string(), self.span(start..start + name.len())))
    }

    fn expect_end(&mut self, cursor: &mut Cursor, directive: &str) {
        if let Some(span) = self.rest_span(cursor) {
            self.errors.push(PreprocessError::MalformedDirective {
                span,
                directive: directive.to_string(),
                expected: END_OF_LINE,
            });
        }
    }

    /// The condition of `#ifdef NAME` and its kin. `#ifdef` and `#ifndef` are checked here;
    /// an `#elifdef` or `#elifndef` without a name, or with more after it, is an error only
    /// where the run evaluates it ([`Condition::Missing`], [`Condition::Trailing`]).
    fn defined_condition(&mut self, cursor: &mut Cursor, name: &str, whole: Span) -> Condition {
        let elif = match name {
            "elifdef" => Some("elifdef"),
            "elifndef" => Some("elifndef"),
            _ => None,
        };
        cursor.skip_space();
        if let Some(directive) = elif.filter(|_| cursor.rest().trim().is_empty()) {
            return Condition::Missing { directive, span: whole, expected: "a macro name" };
        }
        let Some((macro_name, span)) = self.macro_name(cursor, name, whole) else {
            // Keep the structure balanced so that the matching `#endif` is not reported too.
            return Condition::Expr { text: "0".into(), start: 0 };
        };
        let condition = if name.ends_with("ndef") {
            Condition::NotDefined { name: macro_name, span }
        } else {
            Condition::Defined { name: macro_name, span }
        };
        match (elif, self.rest_span(cursor)) {
            (Some(directive), Some(span)) => {
                Condition::Trailing { condition: Box::new(condition), directive, span }
            }
            _ => {
                self.expect_end(cursor, name);
                condition
            }
        }
    }

    fn open_conditional(&mut self, directive: &str, span: Span, condition: Condition) -> bool {
        if self.open.len() >= MAX_CONDITIONAL_DEPTH {
            self.errors.push(PreprocessError::ConditionalTooDeep { span, limit: MAX_CONDITIONAL_DEPTH });
            return false;
        }
        let index = self.unit.items.len();
        self.unit.items.push(Item::Branch { kind: BranchKind::If(condition), next: 0, end: 0 });
        self.open.push(OpenConditional {
            directive: directive.to_string(),
            span,
            last_branch: index,
            branches: vec![index],
            else_span: None,
        });
        true
    }

    fn branch(&mut self, directive: &str, span: Span, kind: BranchKind) {
        let is_else = matches!(kind, BranchKind::Else);
        let index = self.unit.items.len();
        let Some(open) = self.open.last_mut() else {
            self.errors.push(PreprocessError::StrayConditional { span, directive: directive.to_string() });
            return;
        };
        if let Some(else_span) = open.else_span {
            self.errors.push(PreprocessError::BranchAfterElse {
                span,
                directive: directive.to_string(),
                else_span,
            });
            return;
        }
        let previous = open.last_branch;
        open.last_branch = index;
        open.branches.push(index);
        if is_else {
            open.else_span = Some(span);
        }
        self.unit.items.push(Item::Branch { kind, next: 0, end: 0 });
        self.link(previous, index);
    }

    fn endif(&mut self, span: Span) {
        let Some(open) = self.open.pop() else {
            self.errors.push(PreprocessError::StrayConditional { span, directive: "endif".into() });
            return;
        };
        self.close(open);
    }

    fn close(&mut self, open: OpenConditional) {
        let index = self.unit.items.len();
        self.unit.items.push(Item::Endif);
        self.link(open.last_branch, index);
        for branch in open.branches {
            if let Item::Branch { end, .. } = &mut self.unit.items[branch] {
                *end = index as u32;
            }
        }
    }

    fn link(&mut self, branch: usize, to: usize) {
        if let Item::Branch { next, .. } = &mut self.unit.items[branch] {
            *next = to as u32;
        }
    }

    fn close_unterminated(&mut self) {
        // C refuses a comment the file does not close; everything after its `/*` was lost.
        if self.comment_depth > 0 {
            let span = self.span(self.comment_start..self.comment_start + 2);
            self.errors.push(PreprocessError::UnterminatedComment { span });
        }
        while let Some(open) = self.open.pop() {
            self.errors.push(PreprocessError::UnterminatedConditional {
                open: open.span,
                directive: open.directive.clone(),
            });
            self.close(open);
        }
    }
}

/// A classic guard wraps every line of code: `#ifndef X`, `#define X`, ..., `#endif`, nothing else
/// outside it but comments and blank lines.
fn include_guard(items: &[Item]) -> Option<String> {
    let mut significant =
        items.iter().enumerate().filter(|(_, item)| !matches!(item, Item::Text { code: false, .. }));
    let (first, opening) = significant.next()?;
    let Item::Branch { kind: BranchKind::If(Condition::NotDefined { name, .. }), next, .. } = opening else {
        return None;
    };
    let (_, Item::Define { name: defined, .. }) = significant.next()? else { return None };
    let (last, _) = significant.next_back()?;
    (defined == name && *next as usize == last && first < last).then(|| name.clone())
}

/// Reads a cleaned directive; `at` is relative to `text`, `base` is the file offset of `text`.
struct Cursor<'a> {
    text: &'a str,
    at: usize,
    base: usize,
}

impl<'a> Cursor<'a> {
    fn skip_space(&mut self) {
        let rest = self.rest();
        self.at += rest.len() - rest.trim_start().len();
    }

    /// The identifier at the cursor (possibly empty) and its file offset.
    fn ident(&mut self) -> (usize, &'a str) {
        let bytes = self.text.as_bytes();
        let start = self.at;
        if start < bytes.len() && is_ident_start(bytes[start]) {
            while self.at < bytes.len() && is_ident_char(bytes[self.at]) {
                self.at += 1;
            }
        }
        (self.base + start, &self.text[start..self.at])
    }

    fn rest(&self) -> &'a str {
        &self.text[self.at..]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::source::SourceStore;

    fn scan_text(text: &str) -> (Unit, Vec<PreprocessError>) {
        let mut store = SourceStore::new();
        let file = store.add("t.wgsl", text);
        scan(file, text, 0..text.len())
    }

    #[test]
    fn identifiers_skip_comments_strings_and_numbers() {
        let text = "let a = B; // C\n/* D /* nested */ E */ let f = 1.0f + 0x1Fu; \"G\" h_2\n";
        let (unit, errors) = scan_text(text);
        assert!(errors.is_empty());
        let [Item::Text { idents, .. }] = unit.items.as_slice() else { panic!("{:?}", unit.items) };
        let names: Vec<&str> = idents.iter().map(|&(s, e)| &text[s as usize..e as usize]).collect();
        assert_eq!(names, ["let", "a", "B", "let", "f", "h_2"]);
    }

    #[test]
    fn guards_are_recognised_only_when_they_wrap_everything() {
        let guarded = "// doc\n#ifndef G\n#define G\nfn f() {}\n#endif\n\n";
        assert_eq!(scan_text(guarded).0.guard.as_deref(), Some("G"));
        let code_after = "#ifndef G\n#define G\n#endif\nfn f() {}\n";
        assert_eq!(scan_text(code_after).0.guard, None);
        let with_else = "#ifndef G\n#define G\n#else\n#endif\n";
        assert_eq!(scan_text(with_else).0.guard, None);
    }

    #[test]
    fn continuation_lines_and_comments_keep_offsets() {
        let text = "#if A /* c */ && \\\n  B // tail\nx\n#endif\n";
        let (unit, errors) = scan_text(text);
        assert!(errors.is_empty(), "{errors:?}");
        let Item::Branch { kind: BranchKind::If(Condition::Expr { text: expr, start }), .. } = &unit.items[0]
        else {
            panic!()
        };
        let b = expr.find('B').unwrap() + *start as usize;
        assert_eq!(&text[b..b + 1], "B");
        assert!(!expr.contains('c') && !expr.contains("tail"));
    }

    #[test]
    fn unbalanced_conditionals_are_closed_and_reported_at_the_opening() {
        let (unit, errors) = scan_text("#ifdef A\n#if B\n#endif\n");
        assert!(
            matches!(errors.as_slice(), [PreprocessError::UnterminatedConditional { open, .. }] if open.start == 0)
        );
        assert_eq!(unit.items.iter().filter(|i| matches!(i, Item::Endif)).count(), 2);
    }
}
