//! Macro expansion as the C preprocessor does it: object-like and function-like macros,
//! arguments macro-expanded before substitution (unless next to `##`), `##` pasting, `__VA_ARGS__`
//! and `__VA_OPT__`, rescanning with the text that follows, and hide sets (Prosser's algorithm) so
//! that a macro never expands inside its own expansion ("painted blue").
//!
//! Expansion works on C preprocessing tokens lexed from the text only where a macro name
//! occurs; the rest of the text is copied as it is by the caller.
//!
//! Long because C's expansion algorithm is one piece: lexing, argument collection, `##`,
//! `__VA_OPT__` and rescanning share the hide-set state and the token type.

use std::borrow::Cow;
use std::collections::{HashMap, VecDeque};
use std::ops::Range;

/// A macro nested in its own expansion chain deeper than this is a runaway: an error.
pub(super) const MAX_EXPANSION_DEPTH: usize = 64;

/// More tokens than this from one invocation is a runaway (exponential growth): an error.
pub(super) const MAX_EXPANSION_TOKENS: usize = 1 << 20;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Kind {
    Ident,
    Number,
    /// A string or character literal: never looked into.
    Literal,
    Punct,
    Other,
}

#[derive(Debug, Clone)]
pub(crate) struct Token<'a> {
    pub kind: Kind,
    pub text: Cow<'a, str>,
    /// Whitespace, a comment or a line break came before it.
    pub space: bool,
    /// Macros this token may no longer expand: its hide set, interned in the [`Expander`].
    hide: u32,
    /// Offset, in the lexed text, of where it came from: for expanded tokens, the invocation.
    pub at: usize,
    /// A `##` of a macro body (an argument's `##` does not paste).
    paste: bool,
}

impl Token<'_> {
    fn is(&self, punct: &str) -> bool {
        self.kind == Kind::Punct && self.text == punct
    }
}

/// C's two-character punctuators (the three-character ones are `...`, `<<=` and `>>=`); any other
/// ASCII punctuation character is a punctuator of its own.
const PUNCTUATOR_PAIRS: [&[u8; 2]; 21] = [
    b"->", b"++", b"--", b"<<", b">>", b"<=", b">=", b"==", b"!=", b"&&", b"||", b"*=", b"/=", b"%=", b"+=",
    b"-=", b"&=", b"^=", b"|=", b"##", b"::",
];

/// The length of the punctuator at the start of `rest` (whose first byte is ASCII punctuation).
fn punctuator_len(rest: &[u8]) -> usize {
    if rest.starts_with(b"...") || rest.starts_with(b"<<=") || rest.starts_with(b">>=") {
        3
    } else if rest.len() >= 2 && PUNCTUATOR_PAIRS.contains(&&[rest[0], rest[1]]) {
        2
    } else {
        1
    }
}

/// The length of the comment `rest` starts with: a `//` comment up to its line's end, or a
/// `/* */` comment, which nest in WGSL (an unclosed one runs to the end).
fn comment_len(rest: &[u8]) -> Option<usize> {
    if rest.starts_with(b"//") {
        return Some(rest.iter().position(|&b| b == b'\n').unwrap_or(rest.len()));
    }
    if !rest.starts_with(b"/*") {
        return None;
    }
    let mut depth = 0;
    let mut i = 0;
    while i < rest.len() {
        if rest[i..].starts_with(b"/*") {
            depth += 1;
            i += 2;
        } else if rest[i..].starts_with(b"*/") {
            depth -= 1;
            i += 2;
            if depth == 0 {
                break;
            }
        } else {
            i += 1;
        }
    }
    Some(i)
}

/// The length of a line splice (`\\` and a line break) at the start of `bytes`, or 0.
pub(crate) fn splice_len(bytes: &[u8]) -> usize {
    if bytes.first() != Some(&b'\\') {
        return 0;
    }
    // gcc takes blanks between the `\` and the line break as a splice too, with a warning
    // (K0334, from the scanner).
    let blanks = bytes[1..].iter().take_while(|&&b| b == b' ' || b == b'\t').count();
    match &bytes[1 + blanks..] {
        [b'\n', ..] => 2 + blanks,
        [b'\r', b'\n', ..] => 3 + blanks,
        _ => 0,
    }
}

/// `text` without its line splices (C's translation phase 2).
pub(crate) fn unspliced(text: &str) -> Cow<'_, str> {
    if !text.contains('\\') {
        return Cow::Borrowed(text);
    }
    let bytes = text.as_bytes();
    let (mut out, mut copied, mut at) = (String::with_capacity(text.len()), 0, 0);
    while let Some(found) = text[at..].find('\\') {
        let splice = at + found;
        let len = splice_len(&bytes[splice..]);
        if len > 0 {
            out.push_str(&text[copied..splice]);
            copied = splice + len;
        }
        at = splice + len.max(1);
    }
    out.push_str(&text[copied..]);
    Cow::Owned(out)
}

/// Whether a preprocessing number starts at `at`: a digit, or `.` and a digit.
pub(crate) fn starts_pp_number(bytes: &[u8], at: usize) -> bool {
    bytes[at].is_ascii_digit() || (bytes[at] == b'.' && bytes.get(at + 1).is_some_and(u8::is_ascii_digit))
}

/// Where the preprocessing number starting at `at` ends: C's pp-number is digits, letters, `_`,
/// `.`, and a sign after `e`, `E`, `p` or `P`, so `12E+EXP` is one token and no macro is
/// expanded inside it.
pub(crate) fn pp_number_end(bytes: &[u8], at: usize) -> usize {
    let mut i = at + 1;
    while i < bytes.len() {
        let c = bytes[i];
        let signed_exponent = matches!(c, b'+' | b'-') && matches!(bytes[i - 1], b'e' | b'E' | b'p' | b'P');
        if !(signed_exponent || is_ident_char(c) || c == b'.') {
            break;
        }
        i += 1;
    }
    i
}

pub(crate) fn is_ident_start(b: u8) -> bool {
    b.is_ascii_alphabetic() || b == b'_' || b >= 0x80
}

pub(crate) fn is_ident_char(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_' || b >= 0x80
}

/// Preprocessing tokens of `text[range]`, on demand; comments (nested, as in WGSL) and line
/// breaks are whitespace.
#[derive(Clone)]
pub(crate) struct Lexer<'a> {
    text: &'a str,
    pos: usize,
    end: usize,
}

impl<'a> Lexer<'a> {
    pub(super) fn new(text: &'a str, range: Range<usize>) -> Lexer<'a> {
        Lexer { text, pos: range.start, end: range.end }
    }

    pub(super) fn position(&self) -> usize {
        self.pos
    }

    /// Skips whitespace, comments and line splices; whether there was whitespace or a comment
    /// (a splice joins what it separates: it is no space).
    fn skip_space(&mut self) -> bool {
        let bytes = self.text.as_bytes();
        let mut space = false;
        while self.pos < self.end {
            let rest = &bytes[self.pos..self.end];
            if rest[0].is_ascii_whitespace() {
                self.pos += 1;
                space = true;
            } else if let Some(len) = comment_len(rest) {
                self.pos += len;
                space = true;
            } else if splice_len(rest) > 0 {
                self.pos += splice_len(rest);
            } else {
                break;
            }
        }
        space
    }

    pub(super) fn next_token(&mut self) -> Option<Token<'a>> {
        let space = self.skip_space();
        if self.pos >= self.end {
            return None;
        }
        let bytes = &self.text.as_bytes()[..self.end];
        let start = self.pos;
        let b = bytes[start];
        let mut i = start + 1;
        // An identifier split by line splices is one name; its text is then spliced.
        let mut spliced: Option<String> = None;
        let kind = if is_ident_start(b) {
            let mut piece = start;
            loop {
                while i < bytes.len() && is_ident_char(bytes[i]) {
                    i += 1;
                }
                let splice = splice_len(&bytes[i..]);
                if splice == 0 || !bytes.get(i + splice).is_some_and(|&c| is_ident_char(c)) {
                    break;
                }
                spliced.get_or_insert_with(String::new).push_str(&self.text[piece..i]);
                i += splice;
                piece = i;
            }
            if let Some(name) = spliced.as_mut() {
                name.push_str(&self.text[piece..i]);
            }
            Kind::Ident
        } else if starts_pp_number(bytes, start) {
            i = pp_number_end(bytes, start);
            Kind::Number
        } else if b == b'"' || b == b'\'' {
            while i < bytes.len() && bytes[i] != b && bytes[i] != b'\n' {
                i += if bytes[i] == b'\\' { 2 } else { 1 };
            }
            i = (i + 1).min(bytes.len());
            Kind::Literal
        } else if b.is_ascii_punctuation() {
            i = start + punctuator_len(&bytes[start..]);
            Kind::Punct
        } else {
            // One character, whole.
            i = start + self.text[start..].chars().next().map_or(1, char::len_utf8);
            Kind::Other
        };
        self.pos = i;
        Some(Token {
            kind,
            text: spliced.map_or(Cow::Borrowed(&self.text[start..i]), Cow::Owned),
            space,
            hide: 0,
            at: start,
            paste: false,
        })
    }
}

/// Every token of a text.
pub(crate) fn lex(text: &str) -> Vec<Token<'_>> {
    let mut lexer = Lexer::new(text, 0..text.len());
    std::iter::from_fn(|| lexer.next_token()).collect()
}

/// A token of a macro body, lexed once when its file is scanned: a range of the body's text.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct BodyToken {
    kind: Kind,
    range: Range<u32>,
    space: bool,
    /// A `##` operator.
    paste: bool,
}

impl BodyToken {
    /// Its byte range in the body's text.
    pub(crate) fn range(&self) -> Range<usize> {
        self.range.start as usize..self.range.end as usize
    }

    pub(crate) fn text<'v>(&self, value: &'v str) -> &'v str {
        &value[self.range()]
    }
}

/// The tokens of a macro's body.
pub(crate) fn lex_body(value: &str) -> Vec<BodyToken> {
    lex(value)
        .into_iter()
        .map(|t| BodyToken {
            kind: t.kind,
            range: t.at as u32..(t.at + t.text.len()) as u32,
            space: t.space,
            paste: t.is("##"),
        })
        .collect()
}

/// A `#define`, ready to expand: it borrows what the scan made of the directive.
#[derive(Debug, Clone)]
pub(crate) struct MacroDef<'a> {
    /// `None` for an object-like macro.
    pub params: Option<&'a [String]>,
    pub variadic: bool,
    value: &'a str,
    body: Cow<'a, [BodyToken]>,
    /// The name in the `#define` (`None` for keywords and built-in macros).
    pub defined_at: Option<crate::source::Span>,
}

impl<'a> MacroDef<'a> {
    pub(super) fn new(
        params: Option<&'a [String]>,
        variadic: bool,
        value: &'a str,
        body: &'a [BodyToken],
        defined_at: Option<crate::source::Span>,
    ) -> MacroDef<'a> {
        MacroDef { params, variadic, value, body: Cow::Borrowed(body), defined_at }
    }

    /// An object-like macro not from a `#define` (a keyword: `1`).
    pub(super) fn object(value: &'a str) -> MacroDef<'a> {
        MacroDef { params: None, variadic: false, value, body: Cow::Owned(lex_body(value)), defined_at: None }
    }

    fn text(&self, token: &BodyToken) -> &'a str {
        token.text(self.value)
    }

    fn token(&self, token: &BodyToken) -> Token<'a> {
        Token {
            kind: token.kind,
            text: Cow::Borrowed(self.text(token)),
            space: token.space,
            hide: 0,
            at: 0,
            paste: token.paste,
        }
    }

    /// The same definition, as C compares them: parameters and tokens (spacing aside).
    pub(super) fn same_as(&self, other: &MacroDef<'_>) -> bool {
        self.params == other.params
            && self.variadic == other.variadic
            && self.body.len() == other.body.len()
            && self.body.iter().zip(other.body.iter()).enumerate().all(|(i, (a, b))| {
                // C compares whitespace too: its presence between tokens, not its amount.
                self.text(a) == other.text(b) && (i == 0 || a.space == b.space)
            })
    }

    fn param(&self, name: &str) -> Option<usize> {
        let params = self.params?;
        if let Some(i) = params.iter().position(|p| p == name) {
            return Some(i);
        }
        (self.variadic && name == "__VA_ARGS__").then_some(params.len())
    }
}

/// What went wrong in an expansion; `at` is an offset in the lexed text.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum ExpandError {
    /// `defined` written by expanding the macro `name` in an `#if` (a warning).
    DefinedInExpansion {
        at: Range<usize>,
        name: String,
    },
    ArgumentCount {
        at: Range<usize>,
        name: String,
        expected: usize,
        variadic: bool,
        found: usize,
    },
    Unterminated {
        at: Range<usize>,
        name: String,
    },
    Paste {
        at: Range<usize>,
        name: String,
        left: String,
        right: String,
    },
    TooDeep {
        at: Range<usize>,
        name: String,
    },
    /// Past [`MAX_EXPANSION_TOKENS`] however shallow the chain.
    TooMany {
        at: Range<usize>,
        name: String,
    },
}

/// Where macro tokens come from during one expansion: tokens to rescan first, then the text.
struct Input<'l, 'a> {
    pending: VecDeque<Token<'a>>,
    source: Option<&'l mut Lexer<'a>>,
}

impl<'a> Input<'_, 'a> {
    fn next(&mut self) -> Option<Token<'a>> {
        self.pending.pop_front().or_else(|| self.source.as_mut()?.next_token())
    }

    /// Takes the next token if it is `(`.
    fn open_paren(&mut self) -> Option<Token<'a>> {
        if let Some(front) = self.pending.front() {
            return if front.is("(") { self.pending.pop_front() } else { None };
        }
        let source = self.source.as_mut()?;
        let saved = source.pos;
        match source.next_token() {
            Some(t) if t.is("(") => Some(t),
            _ => {
                source.pos = saved;
                None
            }
        }
    }
}

/// The macros of one variant by name. Every identifier of the text is looked up in it, so it
/// uses a fast, non-cryptographic hash (macro names are not chosen by an adversary).
pub(crate) type Macros<'a> = HashMap<&'a str, MacroDef<'a>, foldhash::fast::FixedState>;

/// Hide sets, interned so that a token carries a number (set 0 is empty): expansion makes a set
/// for every token it writes, from a handful of distinct ones.
#[derive(Debug)]
pub(crate) struct HideSets<'a> {
    /// Each set's names, sorted.
    sets: Vec<Vec<&'a str>>,
    ids: HashMap<Vec<&'a str>, u32, foldhash::fast::FixedState>,
    added: HashMap<(u32, &'a str), u32, foldhash::fast::FixedState>,
}

impl Default for HideSets<'_> {
    fn default() -> Self {
        Self::new()
    }
}

impl<'a> HideSets<'a> {
    pub(super) fn new() -> HideSets<'a> {
        let mut ids = HashMap::default();
        ids.insert(Vec::new(), 0);
        HideSets { sets: vec![Vec::new()], ids, added: HashMap::default() }
    }

    fn contains(&self, set: u32, name: &str) -> bool {
        self.sets[set as usize].binary_search(&name).is_ok()
    }

    fn len(&self, set: u32) -> usize {
        self.sets[set as usize].len()
    }

    fn intern(&mut self, names: Vec<&'a str>) -> u32 {
        if let Some(&id) = self.ids.get(&names) {
            return id;
        }
        let id = self.sets.len() as u32;
        self.sets.push(names.clone());
        self.ids.insert(names, id);
        id
    }

    fn add(&mut self, set: u32, name: &'a str) -> u32 {
        if let Some(&id) = self.added.get(&(set, name)) {
            return id;
        }
        let mut names = self.sets[set as usize].clone();
        if let Err(at) = names.binary_search(&name) {
            names.insert(at, name);
        }
        let id = self.intern(names);
        self.added.insert((set, name), id);
        id
    }

    fn union(&mut self, a: u32, b: u32) -> u32 {
        if a == b || b == 0 {
            return a;
        }
        if a == 0 {
            return b;
        }
        let names = self.sets[b as usize].clone();
        names.into_iter().fold(a, |set, name| self.add(set, name))
    }

    fn intersection(&mut self, a: u32, b: u32) -> u32 {
        if a == b {
            return a;
        }
        let names = self.sets[a as usize].iter().copied().filter(|n| self.contains(b, n)).collect();
        self.intern(names)
    }
}

/// Expands macros from a table of definitions.
pub(crate) struct Expander<'m, 'a> {
    pub macros: &'m Macros<'a>,
    pub errors: Vec<ExpandError>,
    /// Kept by the caller across expansions, so sets are made once per variant.
    hides: &'m mut HideSets<'a>,
    produced: usize,
    /// The invocation the user wrote that the current expansion came from (name's place, name).
    outer: (Range<usize>, String),
    /// Expanding an `#if` expression: the name after `defined` is an operand, never expanded.
    in_condition: bool,
}

impl<'m, 'a> Expander<'m, 'a> {
    pub(super) fn new(macros: &'m Macros<'a>, hides: &'m mut HideSets<'a>) -> Expander<'m, 'a> {
        Expander {
            macros,
            errors: Vec::new(),
            hides,
            produced: 0,
            outer: (0..0, String::new()),
            in_condition: false,
        }
    }

    /// An expander for an `#if` expression: `defined NAME` and `defined(NAME)` that a macro's
    /// expansion writes keep their operand unexpanded, as gcc evaluates them (with a warning).
    pub(super) fn for_condition(macros: &'m Macros<'a>, hides: &'m mut HideSets<'a>) -> Expander<'m, 'a> {
        Expander { in_condition: true, ..Expander::new(macros, hides) }
    }

    /// Expands the invocation that starts at the lexer's position (a macro name), reading as
    /// much of the text after it as the expansion needs (arguments, and the arguments of a
    /// function-like macro its expansion ends with). The lexer is left after what was used.
    pub(super) fn invocation(&mut self, lexer: &mut Lexer<'a>) -> Vec<Token<'a>> {
        self.produced = 0;
        let Some(first) = lexer.next_token() else { return Vec::new() };
        let mut input = Input { pending: VecDeque::from([first]), source: Some(lexer) };
        let mut out = Vec::new();
        self.run(&mut input, &mut out, true);
        out
    }

    /// Expands every macro of a token list (an argument, an `#if` expression).
    pub(super) fn all(&mut self, tokens: Vec<Token<'a>>) -> Vec<Token<'a>> {
        // Most arguments name no macro at all.
        if !tokens.iter().any(|t| t.kind == Kind::Ident && self.macros.contains_key(&*t.text)) {
            return tokens;
        }
        let mut input = Input { pending: tokens.into(), source: None };
        let mut out = Vec::new();
        self.run(&mut input, &mut out, false);
        out
    }

    /// Rescans `input`; with `stop_when_pending_empty`, ends once everything that came from the
    /// invocation is out, rather than reading the whole source.
    fn run(&mut self, input: &mut Input<'_, 'a>, out: &mut Vec<Token<'a>>, stop_when_pending_empty: bool) {
        loop {
            let token = if stop_when_pending_empty {
                match input.pending.pop_front() {
                    Some(t) => t,
                    None => return,
                }
            } else {
                match input.next() {
                    Some(t) => t,
                    None => return,
                }
            };
            if self.in_condition && token.kind == Kind::Ident && token.text == "defined" {
                let reported =
                    self.errors.iter().any(|e| matches!(e, ExpandError::DefinedInExpansion { .. }));
                if token.hide != 0 && !reported {
                    let (at, name) = self.outer.clone();
                    self.errors.push(ExpandError::DefinedInExpansion { at, name });
                }
                out.push(token);
                // Its operand, `NAME` or `( NAME`, passes through as written.
                let Some(next) = input.next() else { return };
                let parenthesised = next.is("(");
                out.push(next);
                if parenthesised && let Some(name) = input.next() {
                    out.push(name);
                }
                continue;
            }
            if token.kind != Kind::Ident || self.hides.contains(token.hide, &token.text) {
                out.push(token);
                continue;
            }
            let Some(def) = self.macros.get(&*token.text) else {
                out.push(token);
                continue;
            };
            let name: &'a str = self.macros.get_key_value(&*token.text).map_or("", |(k, _)| *k);
            if token.hide == 0 {
                self.outer = (token.at..token.at + token.text.len(), name.to_string());
            }
            if self.hides.len(token.hide) >= MAX_EXPANSION_DEPTH {
                let (at, name) = self.outer.clone();
                self.errors.push(ExpandError::TooDeep { at, name });
                out.push(token);
                continue;
            }
            let expansion = match &def.params {
                None => {
                    let hide = self.hides.add(token.hide, name);
                    self.substitute(def, name, &[], hide, &token)
                }
                Some(params) => {
                    let Some(_) = input.open_paren() else {
                        // A function-like macro's name without `(` is just a name.
                        out.push(token);
                        continue;
                    };
                    let Some((args, close)) = self.arguments(input, &token, name) else { return };
                    let (expected, found) = (params.len(), args.len());
                    // `F()` gives one empty argument, which is none for a macro without parameters.
                    let args =
                        if expected == 0 && found == 1 && args[0].is_empty() { Vec::new() } else { args };
                    let found = if expected == 0 { args.len() } else { found };
                    let count_ok = if def.variadic { found >= expected } else { found == expected };
                    if !count_ok {
                        self.errors.push(ExpandError::ArgumentCount {
                            at: token.at..close.at + 1,
                            name: name.to_string(),
                            expected,
                            variadic: def.variadic,
                            found,
                        });
                        continue;
                    }
                    let common = self.hides.intersection(token.hide, close.hide);
                    let hide = self.hides.add(common, name);
                    self.substitute(def, name, &args, hide, &token)
                }
            };
            self.produced += expansion.len();
            if self.produced > MAX_EXPANSION_TOKENS {
                let (at, name) = self.outer.clone();
                self.errors.push(ExpandError::TooMany { at, name });
                return;
            }
            for t in expansion.into_iter().rev() {
                input.pending.push_front(t);
            }
        }
    }

    /// The arguments after a macro's `(`, split at top-level commas, and the closing `)`.
    fn arguments(
        &mut self,
        input: &mut Input<'_, 'a>,
        name_token: &Token<'a>,
        name: &str,
    ) -> Option<(Vec<Vec<Token<'a>>>, Token<'a>)> {
        let mut args = vec![Vec::new()];
        let mut depth = 0;
        loop {
            let Some(token) = input.next() else {
                let end = name_token.at + name_token.text.len();
                self.errors
                    .push(ExpandError::Unterminated { at: name_token.at..end, name: name.to_string() });
                return None;
            };
            if token.is("(") {
                depth += 1;
            } else if token.is(")") {
                if depth == 0 {
                    return Some((args, token));
                }
                depth -= 1;
            } else if token.is(",") && depth == 0 {
                args.push(Vec::new());
                continue;
            }
            if let Some(last) = args.last_mut() {
                last.push(token);
            }
        }
    }

    /// An argument macro-expanded on its own, as C expands it before substitution. The macros
    /// expanded inside it are hidden from its tokens only while that expansion runs (gcc's
    /// contexts, which end with it): afterwards a token keeps the hide set it came in with, unless
    /// it was painted (its own name hidden when it was read), which lasts.
    fn pre_expand(&mut self, tokens: Vec<Token<'a>>) -> Vec<Token<'a>> {
        let came_in = tokens.iter().fold(0, |set, t| self.hides.union(set, t.hide));
        let mut expanded = self.all(tokens);
        for t in &mut expanded {
            let painted = t.kind == Kind::Ident && self.hides.contains(t.hide, &t.text);
            if !painted {
                t.hide = self.hides.intersection(t.hide, came_in);
            }
        }
        expanded
    }

    /// A macro's body with its parameters replaced and `##` applied, every token hidden from the
    /// macros in `hide` and placed at the invocation.
    fn substitute(
        &mut self,
        def: &MacroDef<'a>,
        name: &'a str,
        args: &[Vec<Token<'a>>],
        hide: u32,
        invocation: &Token<'a>,
    ) -> Vec<Token<'a>> {
        let named = def.params.map_or(0, <[String]>::len);
        // `__VA_ARGS__`: the arguments after the named ones, with their commas.
        let variadic: Vec<Token<'a>> = if def.variadic {
            let mut joined = Vec::new();
            for (i, arg) in args.iter().enumerate().skip(named) {
                if i > named {
                    joined.push(comma(invocation.at));
                }
                joined.extend(arg.iter().cloned());
            }
            joined
        } else {
            Vec::new()
        };
        let arg = |index: usize| if index == named { &variadic } else { &args[index] };
        // Each argument is macro-expanded once, however often its parameter appears.
        let mut expanded: Vec<Option<Vec<Token<'a>>>> = vec![None; named + 1];
        let body = &def.body;
        let mut out: Vec<Option<Token<'a>>> = Vec::with_capacity(body.len());
        let mut i = 0;
        while i < body.len() {
            let token = def.token(&body[i]);
            if def.variadic && token.kind == Kind::Ident && token.text == "__VA_OPT__" {
                // `__VA_OPT__(x)`: x when the variadic arguments expand to tokens, nothing
                // otherwise (as C23 and gcc: an argument that expands to nothing is none).
                let (group, after) = parenthesised(def, i + 1);
                if expanded[named].is_none() {
                    expanded[named] = Some(self.pre_expand(variadic.clone()));
                }
                if expanded[named].as_ref().is_some_and(|tokens| !tokens.is_empty()) {
                    let inner = MacroDef { body: Cow::Owned(group), defined_at: None, ..def.clone() };
                    out.extend(self.substitute(&inner, name, args, 0, invocation).into_iter().map(Some));
                }
                i = after;
                continue;
            }
            match (token.kind, def.param(&token.text)) {
                (Kind::Ident, Some(index)) => {
                    let beside_paste =
                        body.get(i + 1).is_some_and(|t| t.paste) || (i > 0 && body[i - 1].paste);
                    let tokens = if beside_paste {
                        arg(index).clone()
                    } else {
                        match &expanded[index] {
                            Some(tokens) => tokens.clone(),
                            None => {
                                let tokens = self.pre_expand(arg(index).clone());
                                expanded[index] = Some(tokens.clone());
                                tokens
                            }
                        }
                    };
                    if tokens.is_empty() {
                        // A placemarker: `##` next to an empty argument pastes nothing.
                        out.push(None);
                    }
                    for (k, mut t) in tokens.into_iter().enumerate() {
                        if k == 0 {
                            t.space = token.space;
                        }
                        out.push(Some(t));
                    }
                }
                _ => out.push(Some(token)),
            }
            i += 1;
        }
        let mut pasted = self.paste(out, name, invocation);
        for (k, t) in pasted.iter_mut().enumerate() {
            t.hide = self.hides.union(t.hide, hide);
            t.at = invocation.at;
            if k == 0 {
                t.space = invocation.space;
            }
        }
        pasted
    }

    /// Applies the body's `##` operators (placemarkers are `None`).
    fn paste(
        &mut self,
        tokens: Vec<Option<Token<'a>>>,
        name: &str,
        invocation: &Token<'a>,
    ) -> Vec<Token<'a>> {
        let mut out: Vec<Option<Token<'a>>> = Vec::with_capacity(tokens.len());
        let mut iter = tokens.into_iter().peekable();
        while let Some(token) = iter.next() {
            if !token.as_ref().is_some_and(|t| t.paste) {
                out.push(token);
                continue;
            }
            let left = out.pop().flatten();
            let right = iter.next().flatten();
            let joined = match (left, right) {
                (None, None) => None,
                (Some(t), None) | (None, Some(t)) => Some(t),
                (Some(l), Some(r)) => {
                    let text = format!("{}{}", l.text, r.text);
                    let tokens = lex(&text);
                    if tokens.len() != 1 || tokens[0].text.len() != text.len() {
                        self.errors.push(ExpandError::Paste {
                            at: invocation.at..invocation.at + invocation.text.len(),
                            name: name.to_string(),
                            left: l.text.to_string(),
                            right: r.text.to_string(),
                        });
                        Some(l)
                    } else {
                        let kind = tokens[0].kind;
                        let hide = self.hides.intersection(l.hide, r.hide);
                        Some(Token {
                            kind,
                            text: Cow::Owned(text),
                            space: l.space,
                            hide,
                            at: l.at,
                            paste: false,
                        })
                    }
                }
            };
            out.push(joined);
        }
        out.into_iter().flatten().collect()
    }
}

fn comma<'a>(at: usize) -> Token<'a> {
    Token { kind: Kind::Punct, text: Cow::Borrowed(","), space: false, hide: 0, at, paste: false }
}

/// The body tokens inside the parentheses that start at `open`, and the index after the `)`.
fn parenthesised(def: &MacroDef<'_>, open: usize) -> (Vec<BodyToken>, usize) {
    let body = &def.body;
    let is = |i: usize, p: &str| body.get(i).is_some_and(|t| t.kind == Kind::Punct && def.text(t) == p);
    if !is(open, "(") {
        return (Vec::new(), open);
    }
    let mut depth = 0;
    for i in open..body.len() {
        if is(i, "(") {
            depth += 1;
        } else if is(i, ")") {
            depth -= 1;
            if depth == 0 {
                return (body[open + 1..i].to_vec(), i + 1);
            }
        }
    }
    (body[open + 1..].to_vec(), body.len())
}

/// Whether writing `right` straight after `left` would lex differently (`-` `-` is `--`, `1`
/// `.5` is `1.5`, `>` `=` is `>=`): then a space goes between them, as cpp does.
pub(crate) fn glues(left: &str, right: &str) -> bool {
    let (Some(a), Some(b)) = (left.as_bytes().last().copied(), right.as_bytes().first().copied()) else {
        return false;
    };
    // The pp-number `left` ends with, if it does: digits, letters, `_`, `.`, and a sign after
    // `e`, `E`, `p` or `P` (a paste can end one with its sign: `1.0e` `##` `-` is `1.0e-`).
    let bytes = left.as_bytes();
    let mut word_start = bytes.len();
    while word_start > 0 {
        let c = bytes[word_start - 1];
        let signed = matches!(c, b'+' | b'-')
            && word_start >= 2
            && matches!(bytes[word_start - 2], b'e' | b'E' | b'p' | b'P');
        if !(is_ident_char(c) || c == b'.' || signed) {
            break;
        }
        word_start -= 1;
    }
    let number = bytes.get(word_start).is_some_and(|c| c.is_ascii_digit() || *c == b'.');
    if is_ident_char(a) && is_ident_char(b) {
        return true;
    }
    // A number goes on through letters, digits and `.`: `1` `.5` is `1.5`, `1e-` `1` is `1e-1`;
    // but `uv` `.x` is still `uv.x`.
    if (number && (is_ident_char(b) || b == b'.')) || (a == b'.' && (b.is_ascii_digit() || b == b'.')) {
        return true;
    }
    if number && matches!(a, b'e' | b'E' | b'p' | b'P') && matches!(b, b'+' | b'-') {
        return true;
    }
    const PAIRS: [&[u8; 2]; 24] = [
        b"++", b"--", b"->", b"<<", b">>", b"<=", b">=", b"==", b"!=", b"&&", b"||", b"+=", b"-=", b"*=",
        b"/=", b"%=", b"&=", b"|=", b"^=", b"##", b"//", b"/*", b"::", b"*/",
    ];
    PAIRS.contains(&&[a, b])
}
