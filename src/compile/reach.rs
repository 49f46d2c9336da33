//! What an entry point can reach: a token-level scan of a WGSL text's top-level declarations
//! (functions, structs, aliases, constants, overrides, globals, directives), each with the
//! identifiers it names, and the closure from the entry point over those names. naga then parses
//! only the declarations kept (the rest of a stage text, the lighting library under a vertex
//! stage, is the bulk of its parse).
//!
//! The scan is conservative: whatever it cannot prove unused stays. Every directive,
//! `const_assert`, `const` and `override` stays (naga's compaction keeps named constants, so the
//! module after compaction keeps them too), as does every declaration of a form the scan does not
//! know; a name a local variable shadows counts as a use of the global (members, attribute names
//! and names being declared are not uses). A text the scan cannot split (an unclosed body, a name
//! declared twice, a byte that was not UTF-8) is not cut at all: naga reports it whole.
//!
//! Long because a scanner is: the token loop, the declaration forms and the name closure share
//! one token stream and its tables, and `together` reads the scan's declarations as they are.

use crate::preprocess::SourceMap;
use std::collections::HashMap;
use std::ops::Range;

/// `text` cut to the declarations `entry` reaches ([`reachable`], [`joined`]), with its source map
/// cut alike, or `None` when nothing would be left out (or the scan cannot tell).
pub fn cut(text: &str, map: &SourceMap, entry: &str) -> Option<(String, SourceMap)> {
    cut_scanned(text, map, entry).map(|(text, map, _)| (text, map))
}

/// [`cut`], with the scan of the text cut (its declarations, uses and locals moved to where
/// [`joined`] puts them): what parsing texts together reads again, not scanned twice.
pub(crate) fn cut_scanned(text: &str, map: &SourceMap, entry: &str) -> Option<(String, SourceMap, CutScan)> {
    let (scan, kept) = reached(text, entry)?;
    Some(cut_kept(text, map, &scan, &kept))
}

/// [`cut_scanned`] for each of `entries` (a compute program's kernels share their text), the text
/// scanned once.
pub(crate) fn cuts_scanned(
    text: &str,
    map: &SourceMap,
    entries: &[&str],
) -> Vec<Option<(String, SourceMap, CutScan)>> {
    let scan = scanned(text);
    let cut = |entry: &str| {
        let scan = scan.as_ref()?;
        Some(cut_kept(text, map, scan, &kept_in_order(scan, entry)?))
    };
    entries.iter().map(|entry| cut(entry)).collect()
}

/// The text cut to the declarations `kept` of its scan, with its map and the cut's scan.
fn cut_kept(text: &str, map: &SourceMap, scan: &Scan, kept: &[usize]) -> (String, SourceMap, CutScan) {
    let ranges: Vec<Range<usize>> = kept.iter().map(|&d| scan.declarations[d].range.clone()).collect();
    let cut_text = joined(text, &ranges);
    let mut moved = CutScan::default();
    let mut at = 0;
    for &d in kept {
        let declaration = &scan.declarations[d];
        let start = declaration.range.start;
        let place = |word: &str| {
            let from = word.as_ptr() as usize - text.as_ptr() as usize - start + at;
            from..from + word.len()
        };
        let (uses, locals) = (moved.uses.len(), moved.locals.len());
        moved.uses.extend(scan.uses[declaration.uses.clone()].iter().map(|w| place(w)));
        moved.locals.extend(scan.locals[declaration.locals.clone()].iter().map(|w| place(w)));
        moved.declarations.push(CutDeclaration {
            range: at..at + declaration.range.len(),
            kind: declaration.kind,
            name: declaration.name.map(place),
            uses: uses..moved.uses.len(),
            locals: locals..moved.locals.len(),
        });
        at += declaration.range.len() + 1;
    }
    (cut_text, map.cut(&ranges), moved)
}

/// A cut text's scan by positions ([`cut_scanned`]), made a [`Scan`] of the text again by
/// [`CutScan::of`].
#[derive(Debug, Default)]
pub(crate) struct CutScan {
    declarations: Vec<CutDeclaration>,
    uses: Vec<Range<usize>>,
    locals: Vec<Range<usize>>,
}

#[derive(Debug)]
struct CutDeclaration {
    range: Range<usize>,
    kind: Kind,
    name: Option<Range<usize>>,
    uses: Range<usize>,
    locals: Range<usize>,
}

impl CutScan {
    /// The scan of `text`, the cut text it was made with.
    pub(super) fn of<'t>(&self, text: &'t str) -> Option<Scan<'t>> {
        let word = |r: &Range<usize>| text.get(r.clone());
        let declarations = (self.declarations.iter())
            .map(|d| {
                Some(Declaration {
                    range: d.range.clone(),
                    kind: d.kind,
                    name: match &d.name {
                        Some(r) => Some(word(r)?),
                        None => None,
                    },
                    uses: d.uses.clone(),
                    locals: d.locals.clone(),
                })
            })
            .collect::<Option<Vec<_>>>()?;
        let uses = self.uses.iter().map(word).collect::<Option<Vec<_>>>()?;
        let locals = self.locals.iter().map(word).collect::<Option<Vec<_>>>()?;
        Some(Scan { declarations, uses, locals })
    }
}

/// The byte ranges of `text`'s top-level declarations that the entry point `entry` can reach, in
/// the order naga lowers them ([`dependency_order`]), or `None` when nothing would be left out
/// (or the scan cannot tell).
pub fn reachable(text: &str, entry: &str) -> Option<Vec<Range<usize>>> {
    let (scan, kept) = reached(text, entry)?;
    Some(kept.into_iter().map(|d| scan.declarations[d].range.clone()).collect())
}

/// `text`'s scan and the declarations `entry` reaches in it ([`kept_in_order`]).
fn reached<'t>(text: &'t str, entry: &str) -> Option<(Scan<'t>, Vec<usize>)> {
    let scan = scanned(text)?;
    let kept = kept_in_order(&scan, entry)?;
    Some((scan, kept))
}

/// A text's declarations, where it may be cut at all.
fn scanned(text: &str) -> Option<Scan<'_>> {
    // A byte that was not UTF-8 (read as U+FFFD) is an error wherever code holds it (K0001): naga
    // reports it from the whole text.
    if text.contains(char::REPLACEMENT_CHARACTER) {
        return None;
    }
    declarations(text)
}

/// The declarations of a text's scan that `entry` reaches, in the order naga lowers them; `None`
/// where that is all of them or the scan cannot tell.
fn kept_in_order(scan: &Scan, entry: &str) -> Option<Vec<usize>> {
    let (declarations, uses) = (&scan.declarations, &scan.uses);
    let mut by_name: Names = HashMap::with_capacity_and_hasher(declarations.len(), Default::default());
    for (index, declaration) in declarations.iter().enumerate() {
        if let Some(name) = declaration.name
            && by_name.insert(name, index).is_some()
        {
            // Declared twice: naga's error, from the whole text.
            return None;
        }
    }
    let root = *by_name.get(entry)?;
    if declarations[root].kind != Kind::Function {
        return None;
    }
    let mut kept = vec![false; declarations.len()];
    let mut work: Vec<usize> = Vec::new();
    for (index, declaration) in declarations.iter().enumerate() {
        if index == root || !declaration.kind.removable() {
            kept[index] = true;
            work.push(index);
        }
    }
    while let Some(index) = work.pop() {
        for name in &uses[declarations[index].uses.clone()] {
            if let Some(&used) = by_name.get(name)
                && !kept[used]
            {
                kept[used] = true;
                work.push(used);
            }
        }
    }
    if kept.iter().all(|k| *k) {
        return None;
    }
    let order = dependency_order(declarations, uses, &by_name);
    Some(order.into_iter().filter(|&d| kept[d]).collect())
}

/// The declarations in the order naga's WGSL front end lowers them: in text order, each after
/// what it names (depth first). The cut keeps this order, so that naga lowers what it keeps in the
/// order it would have in the whole text, and writes its declarations in that order.
pub(super) fn dependency_order(declarations: &[Declaration], uses: &[&str], by_name: &Names) -> Vec<usize> {
    #[derive(Clone, Copy, PartialEq)]
    enum Visit {
        New,
        Open,
        Done,
    }
    let mut visits = vec![Visit::New; declarations.len()];
    let mut order = Vec::with_capacity(declarations.len());
    for start in 0..declarations.len() {
        if visits[start] != Visit::New {
            continue;
        }
        visits[start] = Visit::Open;
        // Each open declaration with the next of its names to follow.
        let mut path = vec![(start, 0)];
        while let Some((at, next)) = path.last_mut() {
            if let Some(name) = uses[declarations[*at].uses.clone()].get(*next) {
                *next += 1;
                if let Some(&used) = by_name.get(name)
                    && visits[used] == Visit::New
                {
                    visits[used] = Visit::Open;
                    path.push((used, 0));
                }
            } else {
                visits[*at] = Visit::Done;
                order.push(*at);
                path.pop();
            }
        }
    }
    order
}

/// The text of `ranges` of `text`, one line break after each (what naga parses; the source
/// map is cut alike by [`crate::preprocess::SourceMap::cut`]).
pub fn joined(text: &str, ranges: &[Range<usize>]) -> String {
    let mut out = String::with_capacity(ranges.iter().map(|r| r.len() + 1).sum());
    for range in ranges {
        out.push_str(&text[range.clone()]);
        out.push('\n');
    }
    out
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    Function,
    Struct,
    Alias,
    Variable,
    /// `const` and `override`: named, and always kept.
    Constant,
    /// Directives, `const_assert`, and any form the scan does not know: kept, naming nothing.
    Other,
}

impl Kind {
    fn of(keyword: &str) -> Kind {
        match keyword {
            "fn" => Kind::Function,
            "struct" => Kind::Struct,
            "alias" => Kind::Alias,
            "var" => Kind::Variable,
            "const" | "override" => Kind::Constant,
            _ => Kind::Other,
        }
    }

    pub(super) fn removable(self) -> bool {
        matches!(self, Kind::Function | Kind::Struct | Kind::Alias | Kind::Variable)
    }
}

/// How far a declaration's head has been read.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Head {
    /// Before its keyword (attributes may come first).
    Keyword,
    /// After a keyword that declares a name.
    Name,
    /// Named, or a form that names nothing.
    Done,
}

/// The declarations of a text by name (a fast hash: every stage text a build compiles is
/// scanned).
pub(super) type Names<'t> = HashMap<&'t str, usize, foldhash::fast::FixedState>;

/// One top-level declaration: where it is, what it declares, and where its uses and locals are
/// in the text's lists of them.
pub(super) struct Declaration<'t> {
    pub range: Range<usize>,
    pub kind: Kind,
    pub name: Option<&'t str>,
    /// The identifiers in it that may name a global.
    pub uses: Range<usize>,
    /// The names it declares inside itself (parameters, members, `let`s, `case` labels): the
    /// identifiers in declaring places other than its own name.
    pub locals: Range<usize>,
}

/// A text's top-level declarations, with the lists their uses and locals index. Each identifier
/// is a slice of the text, so where it is can be told.
pub(super) struct Scan<'t> {
    pub declarations: Vec<Declaration<'t>>,
    pub uses: Vec<&'t str>,
    pub locals: Vec<&'t str>,
}

/// A token of the scan: an identifier, or one byte of punctuation.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Token<'t> {
    Identifier(&'t str),
    Punctuation(u8),
    /// A number: it names nothing.
    Number,
}

/// `text`'s top-level declarations, their uses and locals, or `None` where its shape is not one
/// the scan knows (an unclosed body or comment, a removable declaration without a name).
pub(super) fn declarations(text: &str) -> Option<Scan<'_>> {
    let mut tokens = Tokens { text, at: 0 };
    let (mut out, mut uses, mut locals) = (Vec::new(), Vec::new(), Vec::new());
    let mut current: Option<(Declaration, Head)> = None;
    let (mut depth, mut previous) = (0usize, Token::Number);
    // A `var`'s `<address space>`, skipped before its name.
    let mut in_template = false;
    // One token of lookahead: a name followed by `:` is being declared.
    let mut following = tokens.next()?;
    while let Some((token, range)) = following {
        following = tokens.next()?;
        let (declaration, head) = current.get_or_insert_with(|| {
            let (start, at, local) = (range.start, uses.len(), locals.len());
            let declaration = Declaration {
                range: start..start,
                kind: Kind::Other,
                name: None,
                uses: at..at,
                locals: local..local,
            };
            (declaration, Head::Keyword)
        });
        let mut ends = false;
        match token {
            Token::Identifier(word) => {
                // What names a global: not a member (`.x`), an attribute (`@location`), nor a
                // name being declared (`x: T`, `let x`, `fn f`); the rest may.
                let declared = matches!(previous, Token::Punctuation(b'.' | b'@'))
                    || matches!(previous, Token::Identifier(k) if DECLARING.contains(&k))
                    || matches!(following, Some((Token::Punctuation(b':'), _)));
                let top = depth == 0 && !in_template && previous != Token::Punctuation(b'@');
                if !declared {
                    uses.push(word);
                } else if !(matches!(previous, Token::Punctuation(b'.' | b'@'))
                    || (top && *head == Head::Name))
                {
                    locals.push(word);
                }
                if top {
                    match head {
                        Head::Keyword => {
                            declaration.kind = Kind::of(word);
                            *head = if declaration.kind == Kind::Other { Head::Done } else { Head::Name };
                        }
                        Head::Name => {
                            declaration.name = Some(word);
                            *head = Head::Done;
                        }
                        Head::Done => {}
                    }
                }
            }
            Token::Punctuation(b'<')
                if depth == 0 && *head == Head::Name && declaration.kind == Kind::Variable =>
            {
                in_template = true
            }
            Token::Punctuation(b'>') if in_template => in_template = false,
            Token::Punctuation(b'(' | b'[' | b'{') => depth += 1,
            Token::Punctuation(b')' | b']') => depth = depth.checked_sub(1)?,
            Token::Punctuation(b'}') => {
                depth = depth.checked_sub(1)?;
                ends = depth == 0 && matches!(declaration.kind, Kind::Function | Kind::Struct);
            }
            Token::Punctuation(b';') => ends = depth == 0,
            _ => {}
        }
        previous = token;
        if ends {
            let (mut declaration, head) = current.take()?;
            declaration.range.end = range.end;
            declaration.uses.end = uses.len();
            declaration.locals.end = locals.len();
            match head {
                // A bare `;` declares nothing.
                Head::Keyword if declaration.range.start == range.start => {}
                Head::Done => out.push(declaration),
                _ => return None,
            }
        }
    }
    // A declaration left open at the end: naga says where.
    if current.is_some() || depth != 0 {
        return None;
    }
    Some(Scan { declarations: out, uses, locals })
}

/// The keywords whose next identifier is a name being declared.
const DECLARING: &[&str] = &["fn", "struct", "alias", "var", "let", "const", "override"];

/// The tokens of a WGSL text with their byte ranges, comments (nested, as WGSL's are) and blanks
/// skipped.
struct Tokens<'t> {
    text: &'t str,
    at: usize,
}

impl<'t> Tokens<'t> {
    /// The next token; `Some(None)` at the end, `None` in a comment that never closes.
    fn next(&mut self) -> Option<Option<(Token<'t>, Range<usize>)>> {
        let bytes = self.text.as_bytes();
        loop {
            let Some(&b) = bytes.get(self.at) else { return Some(None) };
            match b {
                b'/' if bytes.get(self.at + 1) == Some(&b'/') => {
                    self.at = self.text[self.at..].find('\n').map_or(bytes.len(), |n| self.at + n);
                }
                b'/' if bytes.get(self.at + 1) == Some(&b'*') => {
                    let mut open = 1;
                    self.at += 2;
                    while open > 0 {
                        match (bytes.get(self.at)?, bytes.get(self.at + 1)) {
                            (b'/', Some(b'*')) => (open, self.at) = (open + 1, self.at + 2),
                            (b'*', Some(b'/')) => (open, self.at) = (open - 1, self.at + 2),
                            _ => self.at += 1,
                        }
                    }
                }
                b if b.is_ascii_whitespace() => self.at += 1,
                _ => break,
            }
        }
        let (start, b) = (self.at, bytes[self.at]);
        let word = |c: u8| c.is_ascii_alphanumeric() || c == b'_' || c >= 0x80;
        let token = if word(b) {
            // Numbers run on through `.` and exponents' letters: `1.5e3f`, `0x1p-3` (its `-` is a
            // token of its own, which names nothing either).
            let number = b.is_ascii_digit();
            self.at += 1;
            while let Some(&c) = bytes.get(self.at) {
                if !(word(c) || (number && c == b'.')) {
                    break;
                }
                self.at += 1;
            }
            if number { Token::Number } else { Token::Identifier(&self.text[start..self.at]) }
        } else {
            self.at += 1;
            if b == b'.' && bytes.get(self.at).is_some_and(u8::is_ascii_digit) {
                while bytes.get(self.at).is_some_and(|&c| word(c) || c == b'.') {
                    self.at += 1;
                }
                Token::Number
            } else {
                Token::Punctuation(b)
            }
        };
        Some(Some((token, start..self.at)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cut(text: &str, entry: &str) -> Option<String> {
        reachable(text, entry).map(|ranges| joined(text, &ranges))
    }

    #[test]
    fn an_entry_point_keeps_what_it_names_transitively_and_every_constant() {
        let text = "enable f16;\n\
            const PI: f32 = 3.14; // kept: naga keeps named constants\n\
            struct Light { colour: vec3<f32> }\n\
            struct Unused { a: f32 };\n\
            alias Colour = vec3<f32>;\n\
            @group(0) @binding(0) var<uniform> light: Light;\n\
            var<private> scratch: array<f32, 4>;\n\
            fn shade() -> Colour { return light.colour * PI; }\n\
            /* fn vs() */ fn unused() -> f32 { return scratch[0]; }\n\
            @fragment fn fs() -> @location(0) vec4<f32> { return vec4(shade(), 1.0); }\n";
        assert_eq!(
            cut(text, "fs").as_deref(),
            Some(
                "enable f16;\nconst PI: f32 = 3.14;\nstruct Light { colour: vec3<f32> }\nalias Colour = vec3<f32>;\n\
                 @group(0) @binding(0) var<uniform> light: Light;\nfn shade() -> Colour { return light.colour * PI; }\n\
                 @fragment fn fs() -> @location(0) vec4<f32> { return vec4(shade(), 1.0); }\n"
            )
        );
    }

    #[test]
    fn what_is_kept_comes_in_the_order_naga_lowers_the_whole_text() {
        // naga lowers `removed` first, and `B` before it; then `A`.
        let text = "fn removed() -> f32 { return B; }\nconst A: f32 = 1.0;\nconst B: f32 = 2.0;\n\
            @vertex fn vs() -> @builtin(position) vec4<f32> { return vec4(A, B, 0.0, 1.0); }\n";
        assert_eq!(
            cut(text, "vs").as_deref(),
            Some(
                "const B: f32 = 2.0;\nconst A: f32 = 1.0;\n\
                 @vertex fn vs() -> @builtin(position) vec4<f32> { return vec4(A, B, 0.0, 1.0); }\n"
            )
        );
    }

    #[test]
    fn members_attributes_and_declared_names_are_not_uses() {
        // `colour` is a member and `location` an attribute: the global `colour` goes. A local's
        // later use (`location`, `x`) is read as the global's, which stays.
        let text = "var<private> colour: vec4<f32>;\nfn location() {}\nfn x() {}\n\
            struct Out { @location(0) colour: vec4<f32> }\n\
            @fragment fn fs(x: f32) -> Out { let location = x; var o: Out; o.colour = vec4(location); return o; }\n";
        assert_eq!(
            cut(text, "fs").as_deref(),
            Some(
                "fn location() {}\nfn x() {}\nstruct Out { @location(0) colour: vec4<f32> }\n\
                 @fragment fn fs(x: f32) -> Out { let location = x; var o: Out; o.colour = vec4(location); return o; }\n"
            )
        );
    }

    #[test]
    fn nothing_is_cut_where_the_scan_cannot_tell() {
        // Everything reached.
        assert_eq!(cut("fn f() {}\n@vertex fn vs() { f(); }", "vs"), None);
        // An entry point the text does not declare, a name declared twice, a body left open, a
        // comment left open, an unknown entry point: naga reports each from the whole text.
        assert_eq!(cut("fn g() {}\n@vertex fn vs() {}", "fs"), None);
        assert_eq!(cut("fn g() {}\nfn g() {}\n@vertex fn vs() {}", "vs"), None);
        assert_eq!(cut("fn g() {\n@vertex fn vs() {}", "vs"), None);
        assert_eq!(cut("fn g() {}\n@vertex fn vs() {} /* /* */", "vs"), None);
        assert_eq!(cut("fn () {}\n@vertex fn vs() {}", "vs"), None);
        assert_eq!(cut("fn caf\u{FFFD}() {}\n@vertex fn vs() {}", "vs"), None);
    }

    #[test]
    fn attributes_templates_and_numbers_name_nothing_and_nested_comments_are_skipped() {
        let text = "override block: u32 = 8u;\nvar<workgroup> tile: array<f32, block>;\n\
            fn private() {}\n/* fn a() { /* nested */ } */\n\
            @compute @workgroup_size(block, 1e3f, 0x1p-3) fn main() { tile[0] = 1.5e-3; }\n";
        assert_eq!(
            cut(text, "main").as_deref(),
            Some(
                "override block: u32 = 8u;\nvar<workgroup> tile: array<f32, block>;\n\
                 @compute @workgroup_size(block, 1e3f, 0x1p-3) fn main() { tile[0] = 1.5e-3; }\n"
            )
        );
    }
}

#[cfg(test)]
mod against_naga {
    use super::{Kind, declarations, dependency_order};

    /// Each of Tint's WGSL tests (`tests/corpus/tint`): its path and text.
    fn tint_texts() -> impl Iterator<Item = (std::path::PathBuf, String)> {
        walkdir::WalkDir::new("tests/corpus/tint").into_iter().flatten().filter_map(|entry| {
            let path = entry.into_path();
            let text = path
                .extension()
                .filter(|e| *e == "wgsl")
                .and_then(|_| std::fs::read_to_string(&path).ok())?;
            Some((path, text))
        })
    }

    /// Every function of each Tint test as the entry point: the cut's scan moved ([`cut_scanned`])
    /// is a fresh scan of the cut text.
    #[test]
    fn a_cut_s_scan_moved_is_the_scan_of_the_cut_text() {
        use crate::compile::reach::{Scan, cut_scanned};
        use crate::preprocess::SourceMap;
        let (mut compared, mut differing) = (0, Vec::new());
        for (path, text) in tint_texts() {
            let functions: Vec<String> = declarations(&text)
                .map(|s| {
                    s.declarations
                        .iter()
                        .filter(|d| d.kind == Kind::Function)
                        .filter_map(|d| d.name)
                        .map(str::to_string)
                        .collect()
                })
                .unwrap_or_default();
            for entry in &functions {
                let Some((cut, _, moved)) = cut_scanned(&text, &SourceMap::default(), entry) else {
                    continue;
                };
                let shape = |scan: Scan| {
                    let words = |list: &[&str]| -> Vec<(usize, String)> {
                        list.iter()
                            .map(|w| (w.as_ptr() as usize - cut.as_ptr() as usize, w.to_string()))
                            .collect()
                    };
                    let heads: Vec<_> = (scan.declarations.iter())
                        .map(|d| {
                            (
                                d.range.clone(),
                                d.kind,
                                d.name.map(str::to_string),
                                d.uses.clone(),
                                d.locals.clone(),
                            )
                        })
                        .collect();
                    (heads, words(&scan.uses), words(&scan.locals))
                };
                compared += 1;
                if moved.of(&cut).map(shape) != declarations(&cut).map(shape) {
                    differing.push(format!("{} ({entry})", path.display()));
                }
            }
        }
        assert!(compared > 1000, "{compared} texts cut");
        assert!(differing.is_empty(), "{differing:#?}");
    }

    /// Every function of each Tint test as an entry point of one text (a compute program's
    /// kernels): the cuts of one scan ([`cuts_scanned`]) are each entry point's own cut.
    #[test]
    fn cuts_of_one_scan_are_each_entry_point_s_own_cut() {
        use crate::compile::reach::{cut_scanned, cuts_scanned};
        use crate::preprocess::SourceMap;
        let (mut compared, mut differing) = (0, Vec::new());
        let shown = |cut: Option<(String, SourceMap, super::CutScan)>| format!("{cut:?}");
        for (path, text) in tint_texts() {
            let Some(scan) = declarations(&text) else { continue };
            let functions: Vec<&str> = (scan.declarations.iter())
                .filter(|d| d.kind == Kind::Function)
                .filter_map(|d| d.name)
                .collect();
            let map = SourceMap::default();
            for (entry, cut) in functions.iter().zip(cuts_scanned(&text, &map, &functions)) {
                compared += 1;
                if shown(cut) != shown(cut_scanned(&text, &map, entry)) {
                    differing.push(format!("{} ({entry})", path.display()));
                }
            }
        }
        assert!(compared > 1000, "{compared} entry points cut");
        assert!(differing.is_empty(), "{differing:#?}");
    }

    /// naga's own order of every kind of declaration it lowers in each of Tint's WGSL tests
    /// that it parses, against [`dependency_order`]'s.
    #[test]
    fn the_dependency_order_is_naga_s_on_tint_s_corpus() {
        let (mut compared, mut differing) = (0, Vec::new());
        for (path, text) in tint_texts() {
            let (Ok(module), Some(super::Scan { declarations, uses, .. })) =
                (naga::front::wgsl::parse_str(&text), declarations(&text))
            else {
                continue;
            };
            let by_name: super::Names =
                declarations.iter().enumerate().filter_map(|(i, d)| Some((d.name?, i))).collect();
            let order = dependency_order(&declarations, &uses, &by_name);
            let ours = |kind: Kind| -> Vec<&str> {
                order
                    .iter()
                    .filter(|&&d| declarations[d].kind == kind)
                    .filter_map(|&d| declarations[d].name)
                    .collect()
            };
            let named = |name: &Option<String>| name.clone();
            let structs =
                module.types.iter().filter(|(_, t)| matches!(t.inner, naga::TypeInner::Struct { .. }));
            let naga_s: [(Kind, Vec<String>); 4] = [
                (Kind::Function, module.functions.iter().filter_map(|(_, f)| named(&f.name)).collect()),
                (
                    Kind::Constant,
                    (module.constants.iter().filter_map(|(_, c)| named(&c.name)))
                        .chain(module.overrides.iter().filter_map(|(_, o)| named(&o.name)))
                        .collect(),
                ),
                (
                    Kind::Variable,
                    module.global_variables.iter().filter_map(|(_, v)| named(&v.name)).collect(),
                ),
                (Kind::Struct, structs.filter_map(|(_, t)| named(&t.name)).collect()),
            ];
            compared += 1;
            for (kind, theirs) in naga_s {
                // Each kind as far as both name it (naga keeps `const` and `override` apart).
                let ours: Vec<&str> =
                    ours(kind).into_iter().filter(|n| theirs.iter().any(|t| t == n)).collect();
                let theirs: Vec<&str> =
                    theirs.iter().map(String::as_str).filter(|n| ours.contains(n)).collect();
                if ours != theirs {
                    differing.push(format!("{}: {kind:?}: ours {ours:?}, naga's {theirs:?}", path.display()));
                }
            }
        }
        assert!(compared > 2_500, "only {compared} files compared");
        assert!(differing.is_empty(), "{}", differing.join("\n"));
    }
}
