//! One variant's preprocessing: walks the scanned units with that variant's macros, copies the
//! active text (substituting macros) and records the source map.

use super::error::PreprocessError;
use super::expr::{self, ExprError, MAX_EXPANSION_DEPTH};
use super::include::{Includes, Program};
use super::scan::{BranchKind, Condition, Item, Target, identifiers};
use super::source_map::{ROOT, SourceMap};
use super::{Preprocessed, Stage};
use crate::diagnostics::Diagnostic;
use crate::source::{FileId, SourceStore, Span};
use std::collections::{HashMap, HashSet};

/// Includes nested deeper than this are refused.
pub const MAX_INCLUDE_DEPTH: usize = 64;

#[derive(Clone, Copy)]
struct Macro<'a> {
    value: &'a str,
    /// Where a `#define` defined it; `None` for keywords and built-in macros.
    defined_at: Option<Span>,
}

pub(super) fn run<'a>(
    includes: &'a Includes,
    store: &'a SourceStore,
    program: &Program,
    keywords: &[&'a str],
    stage: Stage,
) -> Preprocessed {
    let mut runner = Runner {
        includes,
        store,
        macros: HashMap::new(),
        out: String::new(),
        map: SourceMap::default(),
        stack: Vec::new(),
        once: HashSet::new(),
        diagnostics: Vec::new(),
    };
    runner.macros.insert(stage.macro_name(), Macro { value: "1", defined_at: None });
    for keyword in keywords {
        runner.macros.insert(keyword, Macro { value: "1", defined_at: None });
    }
    for &block in &program.blocks {
        runner.stack.push(block);
        runner.unit(block, ROOT);
        runner.stack.pop();
    }
    runner.map.finish(runner.out.len());
    Preprocessed { text: runner.out, source_map: runner.map, diagnostics: runner.diagnostics }
}

struct Runner<'a> {
    includes: &'a Includes,
    store: &'a SourceStore,
    macros: HashMap<&'a str, Macro<'a>>,
    out: String,
    map: SourceMap,
    /// Units being included, outermost first (for cycles and the depth limit).
    stack: Vec<usize>,
    /// Units with `#pragma once` already included.
    once: HashSet<usize>,
    diagnostics: Vec<Diagnostic>,
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
        // Whether some branch of each open conditional was taken.
        let mut taken: Vec<bool> = Vec::new();
        let mut i = 0;
        while i < unit.items.len() {
            match &unit.items[i] {
                Item::Text { start, end, idents, .. } => {
                    self.text(text, file, *start as usize, *end as usize, idents, inclusion)
                }
                Item::Include { target, span, .. } => self.include(target, *span, inclusion),
                Item::Define { name, span, value } => self.define(name, *span, value, inclusion),
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
                    i = if enter {
                        i + 1
                    } else if already {
                        end
                    } else {
                        next
                    };
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
            }
            i += 1;
        }
        // A file without a final newline must not run into the text after its `#include`.
        // The added newline maps to the unit's last character.
        if !self.out.is_empty() && !self.out.ends_with('\n') {
            let last = text[unit.range.clone()].char_indices().next_back();
            if let Some((at, c)) = last {
                let start = unit.range.start + at;
                self.map.expanded(self.out.len(), Span::new(file, start..start + c.len_utf8()), inclusion);
            }
            self.out.push('\n');
        }
    }

    fn copy(&mut self, text: &str, file: FileId, range: std::ops::Range<usize>, inclusion: u32) {
        if range.is_empty() {
            return;
        }
        self.map.copied(self.out.len(), file, range.start, inclusion);
        self.out.push_str(&text[range]);
    }

    fn text(
        &mut self,
        text: &'a str,
        file: FileId,
        start: usize,
        end: usize,
        idents: &[(u32, u32)],
        inclusion: u32,
    ) {
        let mut copied = start;
        if !self.macros.is_empty() {
            for &(s, e) in idents {
                let (s, e) = (s as usize, e as usize);
                let name = &text[s..e];
                let Some(&value) = self.macros.get(name) else { continue };
                self.copy(text, file, copied..s, inclusion);
                let before = self.out.len();
                let mut active = vec![name];
                self.expand(value.value, &mut active, Span::new(file, s..e), inclusion);
                if self.out.len() > before {
                    self.map.expanded(before, Span::new(file, s..e), inclusion);
                }
                copied = e;
            }
        }
        self.copy(text, file, copied..end, inclusion);
    }

    /// Writes a macro's value, expanding the macros it names (but not those being expanded, as
    /// in C, so `#define X X` stops).
    fn expand(&mut self, value: &'a str, active: &mut Vec<&'a str>, at: Span, inclusion: u32) {
        if active.len() > MAX_EXPANSION_DEPTH {
            let name = active.first().copied().unwrap_or_default().to_string();
            self.report(
                PreprocessError::ExpansionTooDeep { span: at, name, limit: MAX_EXPANSION_DEPTH },
                inclusion,
            );
            return;
        }
        let mut copied = 0;
        for (offset, name) in identifiers(value) {
            if active.contains(&name) {
                continue;
            }
            let Some(&inner) = self.macros.get(name) else { continue };
            self.out.push_str(&value[copied..offset]);
            active.push(name);
            self.expand(inner.value, active, at, inclusion);
            active.pop();
            copied = offset + name.len();
        }
        self.out.push_str(&value[copied..]);
    }

    fn define(&mut self, name: &'a str, span: Span, value: &'a str, inclusion: u32) {
        let new = Macro { value, defined_at: Some(span) };
        if let Some(old) = self.macros.insert(name, new)
            && let Some(previous) = old.defined_at
            && old.value.split_whitespace().ne(value.split_whitespace())
        {
            self.report(
                PreprocessError::MacroRedefined { span, name: name.to_string(), previous },
                inclusion,
            );
        }
    }

    fn condition(&mut self, condition: &Condition, file: FileId, inclusion: u32) -> bool {
        match condition {
            Condition::Defined { name, .. } => self.macros.contains_key(name.as_str()),
            Condition::NotDefined { name, .. } => !self.macros.contains_key(name.as_str()),
            Condition::Expr { text, start } => {
                let macros = &self.macros;
                let result = expr::evaluate(text, &|name| macros.get(name).map(|m| m.value.to_string()));
                match result {
                    Ok(value) => value != 0,
                    Err(error) => {
                        let at = |offset: usize, len: usize| {
                            let s = *start as usize + offset;
                            Span::new(file, s..s + len)
                        };
                        let error = match error {
                            ExprError::Malformed { offset, expected } => {
                                PreprocessError::MalformedExpression { span: at(offset, 1), expected }
                            }
                            ExprError::NestedTooDeep { offset } => PreprocessError::MalformedExpression {
                                span: at(offset, 1),
                                expected: "fewer than 64 nested parentheses or unary operators",
                            },
                            ExprError::DivisionByZero { offset } => {
                                PreprocessError::DivisionByZero { span: at(offset, 1) }
                            }
                            // The evaluator names the innermost macro; the user wrote the outermost.
                            ExprError::ExpansionTooDeep { offset, .. } => {
                                let name = identifiers(&text[offset..]).next().map_or("", |(_, n)| n);
                                PreprocessError::ExpansionTooDeep {
                                    span: at(offset, name.len()),
                                    name: name.to_string(),
                                    limit: MAX_EXPANSION_DEPTH,
                                }
                            }
                        };
                        self.report(error, inclusion);
                        false
                    }
                }
            }
        }
    }

    fn include(&mut self, target: &Target, span: Span, inclusion: u32) {
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
