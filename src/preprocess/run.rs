//! One variant's preprocessing: walks the scanned units with that variant's macros, copies the
//! active text (substituting macros) and records the source map.

use super::error::PreprocessError;
use super::expr::{self, ExprError};
use super::include::{Includes, Program};
use super::macros::{
    ExpandError, Expander, HideSets, Lexer, MAX_EXPANSION_DEPTH, MAX_EXPANSION_TOKENS, MacroDef, Macros,
    glues, splice_len, unspliced,
};
use super::pass::{KeywordMacros, UBERSHADER_DATA};
use super::scan::{BranchKind, Condition, END_OF_LINE, Item, Target};
use super::source_map::{ROOT, SourceMap};
use super::{Preprocessed, Stage};
use crate::diagnostics::Diagnostic;
use crate::source::{FileId, SourceStore, Span};
use std::borrow::Cow;
use std::collections::HashSet;

/// Includes nested deeper than this are refused.
pub const MAX_INCLUDE_DEPTH: usize = 64;

/// The most text one stage's preprocessing may make (four times the largest file kiln reads), and
/// the most inclusions it may make: a diamond of 31 headers each including the next twice is 1.5
/// KB of files and 2^30 inclusions, so depth alone bounds nothing.
pub(super) const MAX_STAGE_BYTES: usize = 64 << 20;
/// See [`MAX_STAGE_BYTES`].
pub(super) const MAX_INCLUSIONS: usize = 1 << 16;

pub(super) fn run<'a>(
    includes: &'a Includes,
    store: &'a SourceStore,
    program: &Program,
    keywords: &'a KeywordMacros<'a>,
    stage: Stage,
) -> Preprocessed {
    run_recording(includes, store, program, keywords, stage, None).0
}

/// What a run skipped, when asked for (see [`super::inactive_regions`]).
#[derive(Debug, Default)]
pub struct Skipped {
    /// What each conditional group not taken held: text runs, includes, defines.
    pub spans: Vec<Span>,
    /// Every file the run entered (the program's own and each included), each once.
    pub files: Vec<crate::source::FileId>,
}

/// [`run`], also giving what it skipped (when `skipped` is given), for an editor to grey out.
pub(super) fn run_recording<'a>(
    includes: &'a Includes,
    store: &'a SourceStore,
    program: &Program,
    keywords: &'a KeywordMacros<'a>,
    stage: Stage,
    skipped: Option<Skipped>,
) -> (Preprocessed, Skipped) {
    let mut runner = Runner {
        skipped,
        includes,
        store,
        macros: Macros::default(),
        hides: HideSets::new(),
        out: String::new(),
        map: SourceMap::default(),
        stack: Vec::new(),
        once: HashSet::new(),
        diagnostics: Vec::new(),
        inclusions: 0,
        over_budget: false,
    };
    runner.macros.insert(stage.macro_name(), MacroDef::object("1"));
    for (keyword, value) in &keywords.defines {
        runner.macros.insert(keyword, MacroDef::object(value));
    }
    for &block in &program.blocks {
        runner.stack.push(block);
        runner.unit(block, ROOT);
        runner.stack.pop();
    }
    // Module-scope declarations may come in any order in WGSL: at the end, nothing shifts. Every
    // stage's text has every function, so each declares them all; the pipeline sets a stage's own.
    // An ubershader reads them from its immediate data instead (a macro each).
    let declared = program
        .dynamic_keywords
        .iter()
        .filter(|k| keywords.ubershader.is_none() || !keywords.defines.iter().any(|(d, _)| *d == k.name));
    for keyword in declared {
        runner.out.push('\n');
        runner.map.expanded(runner.out.len(), keyword.span, None, ROOT);
        runner.out.push_str(&keyword.declaration());
    }
    if let Some(pragma) = keywords.ubershader {
        runner.out.push('\n');
        runner.map.expanded(runner.out.len(), pragma, None, ROOT);
        runner.out.push_str(UBERSHADER_DATA);
    }
    runner.map.finish(runner.out.len());
    let skipped = runner.skipped.unwrap_or_default();
    (Preprocessed { text: runner.out, source_map: runner.map, diagnostics: runner.diagnostics }, skipped)
}

/// A run of source text to copy: its range, the names in it a macro may replace, and whether it
/// has line splices.
struct TextRun<'i> {
    start: usize,
    end: usize,
    idents: &'i [(u32, u32)],
    spliced: bool,
}

struct Runner<'a> {
    includes: &'a Includes,
    store: &'a SourceStore,
    macros: Macros<'a>,
    hides: HideSets<'a>,
    out: String,
    map: SourceMap,
    /// Units being included, outermost first (for cycles and the depth limit).
    stack: Vec<usize>,
    /// Units with `#pragma once` already included.
    once: HashSet<usize>,
    diagnostics: Vec<Diagnostic>,
    /// What skipped groups held, when asked for (builds skip a group in one jump).
    skipped: Option<Skipped>,
    /// Files included so far.
    inclusions: usize,
    /// Past [`MAX_STAGE_BYTES`] or [`MAX_INCLUSIONS`]: reported, and nothing more is read.
    over_budget: bool,
}

impl<'a> Runner<'a> {
    fn report(&mut self, error: PreprocessError, inclusion: u32) {
        let mut diagnostic = Diagnostic::from(error);
        diagnostic.notes.extend(self.map.included_from_notes(self.store, inclusion));
        self.diagnostics.push(diagnostic);
    }

    fn unit(&mut self, id: usize, inclusion: u32) {
        let (includes, store): (&'a Includes, &'a SourceStore) = (self.includes, self.store);
        let unit = &includes.units[id];
        let file = unit.file;
        let text = store.text(file);
        if let Some(skipped) = self.skipped.as_mut().filter(|s| !s.files.contains(&file)) {
            skipped.files.push(file);
        }
        // Whether some branch of each open conditional was taken.
        let mut taken: Vec<bool> = Vec::new();
        let mut i = 0;
        while i < unit.items.len() && !self.over_budget {
            match &unit.items[i] {
                Item::Text { start, end, idents, spliced, .. } => {
                    let run =
                        TextRun { start: *start as usize, end: *end as usize, idents, spliced: *spliced };
                    self.text(text, file, &run, inclusion)
                }
                Item::Include { target, span, .. } => self.include(target, *span, inclusion),
                Item::Define { name, span, params, variadic, value, body } => {
                    let definition = MacroDef::new(params.as_deref(), *variadic, value, body, Some(*span));
                    self.define(name, *span, definition, inclusion)
                }
                Item::Undef { name } => {
                    self.macros.remove(name.as_str());
                }
                Item::Branch { kind, next, end } => {
                    let (next, end) = (*next as usize, *end as usize);
                    let already = match kind {
                        BranchKind::If(_) => {
                            taken.push(false);
                            false
                        }
                        _ => taken.last().copied().unwrap_or(true),
                    };
                    let enter = !already
                        && match kind {
                            BranchKind::If(c) | BranchKind::Elif(c) => self.condition(c, file, inclusion),
                            BranchKind::Else => true,
                        };
                    if let Some(top) = taken.last_mut() {
                        *top |= enter;
                    }
                    let target = if enter {
                        i + 1
                    } else if already {
                        end
                    } else {
                        next
                    };
                    if let Some(skipped) = &mut self.skipped {
                        skipped.spans.extend(
                            unit.items[i + 1..target.max(i + 1)].iter().filter_map(|item| item.span(file)),
                        );
                    }
                    i = target;
                    continue;
                }
                Item::Endif => {
                    taken.pop();
                }
                Item::Error { message, span } => self.report(
                    PreprocessError::ErrorDirective { span: *span, message: message.clone() },
                    inclusion,
                ),
                Item::Warning { message, span } => self.report(
                    PreprocessError::WarningDirective { span: *span, message: message.clone() },
                    inclusion,
                ),
                Item::Refused(error) => self.report(error.clone(), inclusion),
            }
            i += 1;
        }
        // A file without a final newline must not run into the text after its `#include`.
        // The added newline maps to the unit's last character.
        if !self.out.is_empty() && !self.out.ends_with('\n') {
            let last = text[unit.range.clone()].char_indices().next_back();
            if let Some((at, c)) = last {
                let start = unit.range.start + at;
                self.map.expanded(
                    self.out.len(),
                    Span::new(file, start..start + c.len_utf8()),
                    None,
                    inclusion,
                );
            }
            self.out.push('\n');
        }
    }

    /// Copies source text to the output, without its line splices (each piece mapped to where
    /// it starts, so a name split by a splice maps to its first character).
    fn copy(
        &mut self,
        text: &str,
        file: FileId,
        range: std::ops::Range<usize>,
        spliced: bool,
        inclusion: u32,
    ) {
        if !spliced {
            if !range.is_empty() {
                self.map.copied(self.out.len(), file, range.start, inclusion);
                self.out.push_str(&text[range]);
            }
            return;
        }
        let mut start = range.start;
        let bytes = text.as_bytes();
        while start < range.end {
            let splice = text[start..range.end]
                .match_indices('\\')
                .map(|(at, _)| (start + at, splice_len(&bytes[start + at..range.end])))
                .find(|&(_, len)| len > 0);
            let piece_end = splice.map_or(range.end, |(at, _)| at);
            if piece_end > start {
                self.map.copied(self.out.len(), file, start, inclusion);
                self.out.push_str(&text[start..piece_end]);
            }
            match splice {
                Some((at, len)) => start = at + len,
                None => break,
            }
        }
    }

    fn text(&mut self, text: &'a str, file: FileId, run: &TextRun, inclusion: u32) {
        let (end, spliced) = (run.end, run.spliced);
        let mut copied = run.start;
        if !self.macros.is_empty() {
            for &(s, e) in run.idents {
                let s = s as usize;
                let name = if spliced {
                    unspliced(&text[s..e as usize])
                } else {
                    Cow::Borrowed(&text[s..e as usize])
                };
                // Names an earlier expansion consumed (as arguments) are gone.
                if s < copied || !self.macros.contains_key(&*name) {
                    continue;
                }
                self.copy(text, file, copied..s, spliced, inclusion);
                copied = self.expand(text, file, s..end, &name, inclusion);
            }
        }
        self.copy(text, file, copied..end, spliced, inclusion);
    }

    /// Expands the invocation at the start of `range` (a macro name, and its arguments for a
    /// function-like macro) into the output; returns where the text after it starts.
    fn expand(
        &mut self,
        text: &'a str,
        file: FileId,
        range: std::ops::Range<usize>,
        name: &str,
        inclusion: u32,
    ) -> usize {
        let (start, end) = (range.start, range.end);
        let mut lexer = Lexer::new(text, range);
        let mut expander = Expander::new(&self.macros, &mut self.hides);
        let tokens = expander.invocation(&mut lexer);
        let errors = std::mem::take(&mut expander.errors);
        let consumed = lexer.position();
        let definition = self.macros.get(name).and_then(|m| m.defined_at);
        let before = self.out.len();
        for (i, token) in tokens.iter().enumerate() {
            if (i > 0 && token.space) || glues(&self.out, &token.text) {
                self.out.push(' ');
            }
            self.out.push_str(&token.text);
        }
        // Nor may the expansion run into the text that follows it.
        if self.out.len() > before && glues(&self.out, &text[consumed..end]) {
            self.out.push(' ');
        }
        if self.out.len() > before {
            self.map.expanded(before, Span::new(file, start..consumed), definition, inclusion);
        }
        self.within_budget(Span::new(file, start..consumed), inclusion);
        for error in errors {
            let error = self.expand_error(error, file, 0, definition);
            self.report(error, inclusion);
        }
        consumed
    }

    /// An expansion error at its place; `base` turns the expander's offsets into file offsets.
    fn expand_error(
        &self,
        error: ExpandError,
        file: FileId,
        base: usize,
        definition: Option<Span>,
    ) -> PreprocessError {
        let span = |at: std::ops::Range<usize>| Span::new(file, base + at.start..base + at.end);
        let defined = |name: &str| self.macros.get(name).and_then(|m| m.defined_at).or(definition);
        match error {
            ExpandError::ArgumentCount { at, name, expected, variadic, found } => {
                PreprocessError::ArgumentCount {
                    span: span(at),
                    definition: defined(&name),
                    name,
                    expected,
                    variadic,
                    found,
                }
            }
            ExpandError::Unterminated { at, name } => {
                PreprocessError::UnterminatedArguments { span: span(at), name }
            }
            ExpandError::Paste { at, name, left, right } => PreprocessError::InvalidPaste {
                span: span(at),
                definition: defined(&name),
                name,
                left,
                right,
            },
            ExpandError::DefinedInExpansion { at, name } => {
                PreprocessError::DefinedInExpansion { span: span(at), definition: defined(&name), name }
            }
            ExpandError::TooDeep { at, name } => {
                PreprocessError::ExpansionTooDeep { span: span(at), name, limit: MAX_EXPANSION_DEPTH }
            }
            ExpandError::TooMany { at, name } => {
                PreprocessError::ExpansionTooLarge { span: span(at), name, limit: MAX_EXPANSION_TOKENS }
            }
        }
    }

    fn define(&mut self, name: &'a str, span: Span, definition: MacroDef<'a>, inclusion: u32) {
        if let Some(old) = self.macros.get(name)
            && let Some(previous) = old.defined_at
            && !old.same_as(&definition)
        {
            self.report(
                PreprocessError::MacroRedefined { span, name: name.to_string(), previous },
                inclusion,
            );
        }
        self.macros.insert(name, definition);
    }

    fn condition(&mut self, condition: &'a Condition, file: FileId, inclusion: u32) -> bool {
        match condition {
            Condition::Defined { name, .. } => self.macros.contains_key(name.as_str()),
            Condition::NotDefined { name, .. } => !self.macros.contains_key(name.as_str()),
            Condition::Missing { directive, span, expected } => {
                let error = PreprocessError::MalformedDirective {
                    span: *span,
                    directive: directive.to_string(),
                    expected,
                };
                self.report(error, inclusion);
                false
            }
            Condition::Trailing { condition, directive, span } => {
                let error = PreprocessError::MalformedDirective {
                    span: *span,
                    directive: directive.to_string(),
                    expected: END_OF_LINE,
                };
                self.report(error, inclusion);
                self.condition(condition, file, inclusion)
            }
            Condition::Expr { text, start } => {
                let mut expander = Expander::for_condition(&self.macros, &mut self.hides);
                let result = expr::evaluate(text, &mut expander);
                let errors = std::mem::take(&mut expander.errors);
                let at = |offset: usize, len: usize| {
                    let s = *start as usize + offset;
                    Span::new(file, s..s + len)
                };
                for error in errors {
                    let error = self.expand_error(error, file, *start as usize, None);
                    self.report(error, inclusion);
                }
                match result {
                    Ok(value) => value,
                    Err(error) => {
                        let error = match error {
                            ExprError::Malformed { offset, expected } => {
                                PreprocessError::MalformedExpression { span: at(offset, 1), expected }
                            }
                            ExprError::NestedTooDeep { offset, limit } => {
                                PreprocessError::MalformedExpression { span: at(offset, 1), expected: limit }
                            }
                            ExprError::DivisionByZero { offset } => {
                                PreprocessError::DivisionByZero { span: at(offset, 1) }
                            }
                            ExprError::InvalidShift { offset, count } => {
                                PreprocessError::InvalidShift { span: at(offset, 2), count }
                            }
                        };
                        self.report(error, inclusion);
                        false
                    }
                }
            }
        }
    }

    /// Whether the stage is still within [`MAX_STAGE_BYTES`] and [`MAX_INCLUSIONS`]; the first
    /// time it is not, that is reported at `span` (with its include chain) and the run stops.
    fn within_budget(&mut self, span: Span, inclusion: u32) -> bool {
        if !self.over_budget && (self.out.len() > MAX_STAGE_BYTES || self.inclusions > MAX_INCLUSIONS) {
            self.over_budget = true;
            let what = if self.out.len() > MAX_STAGE_BYTES {
                format!("made more than {} MiB of text", MAX_STAGE_BYTES >> 20)
            } else {
                format!("included files more than {MAX_INCLUSIONS} times")
            };
            self.report(PreprocessError::ExpandedTooLarge { span, what }, inclusion);
        }
        !self.over_budget
    }

    fn include(&mut self, target: &Target, span: Span, inclusion: u32) {
        self.inclusions += 1;
        if !self.within_budget(span, inclusion) {
            return;
        }
        let id = match target {
            Target::Unit(id) => *id,
            Target::Failed(error) => return self.report(error.clone(), inclusion),
            Target::Pending => return,
        };
        let unit = &self.includes.units[id];
        if unit.pragma_once && self.once.contains(&id) {
            return;
        }
        if unit.guard.as_deref().is_some_and(|guard| self.macros.contains_key(guard)) {
            return;
        }
        if let Some(position) = self.stack.iter().position(|&u| u == id) {
            let chain = self.stack[position..]
                .iter()
                .chain([&id])
                .map(|&u| self.store.name(self.includes.units[u].file).to_string())
                .collect();
            return self.report(PreprocessError::IncludeCycle { span, chain }, inclusion);
        }
        // The stack holds the program block too, so its length is the include depth plus one.
        if self.stack.len() > MAX_INCLUDE_DEPTH {
            return self
                .report(PreprocessError::IncludeTooDeep { span, limit: MAX_INCLUDE_DEPTH }, inclusion);
        }
        if unit.pragma_once {
            self.once.insert(id);
        }
        let inner = self.map.enter(span, inclusion);
        self.stack.push(id);
        self.unit(id, inner);
        self.stack.pop();
    }
}
