//! A pass's WGSL program as the rest of the pipeline sees it: its blocks with everything they
//! can include, the pragmas that count for it, and the keyword warnings about it.

use super::analysis::{analyze_keywords, pragma_sources};
use super::include::{Includes, Program};
use crate::diagnostics::Diagnostic;
use crate::shaderlab::ast::ProgramBlock;
use crate::shaderlab::pragma::{KeywordKind, KeywordStage, ProgramPragmas, collect_pragmas};
use crate::source::{SourceStore, Span};

/// A pass's program, ready to be preprocessed once per variant and stage.
#[derive(Debug, Clone)]
pub struct PassProgram {
    /// The pass's blocks as units.
    pub program: Program,
    /// Pragmas of the blocks and of `#include_with_pragmas` files.
    pub pragmas: ProgramPragmas,
}

/// Loads a pass's program blocks (include blocks first, as
/// [`program_blocks`](crate::listing::program_blocks) orders them) and everything they include.
pub fn load_pass(
    includes: &mut Includes,
    store: &mut SourceStore,
    blocks: &[&ProgramBlock],
) -> (PassProgram, Vec<Diagnostic>) {
    load_pass_text(includes, store, &body_spans(blocks))
}

/// The first half of [`load_pass`]: the blocks and everything they include, loaded (which adds
/// units to `includes`); [`finish_pass`] reads the rest.
pub fn load_blocks(
    includes: &mut Includes,
    store: &mut SourceStore,
    blocks: &[&ProgramBlock],
) -> (Program, Vec<Diagnostic>) {
    includes.load_program(store, &body_spans(blocks))
}

fn body_spans(blocks: &[&ProgramBlock]) -> Vec<Span> {
    blocks.iter().map(|b| b.body_span).collect()
}

/// [`load_pass`] for program text that is no ShaderLab block (the accuracy harness).
pub fn load_pass_text(
    includes: &mut Includes,
    store: &mut SourceStore,
    spans: &[Span],
) -> (PassProgram, Vec<Diagnostic>) {
    let (program, mut diagnostics) = includes.load_program(store, spans);
    let (pass, found) = finish_pass(includes, store, program);
    diagnostics.extend(found);
    (pass, diagnostics)
}

/// What [`load_pass`] does once the program's blocks and includes are loaded: the pragmas that
/// count for it and the keyword warnings about it. It only reads, so a catalogue loads its passes'
/// programs one after another (loading adds units to `includes`) and finishes them in parallel.
pub fn finish_pass(
    includes: &Includes,
    store: &SourceStore,
    mut program: Program,
) -> (PassProgram, Vec<Diagnostic>) {
    let (pragmas, mut diagnostics) = collect_pragmas(pragma_sources(includes, store, &program));
    program.dynamic_keywords = DynamicKeyword::of(&pragmas);
    diagnostics.extend(analyze_keywords(includes, &program, &pragmas));
    (PassProgram { program, pragmas }, diagnostics)
}

/// A `dynamic_branch` keyword: declared in each stage it is for as `override NAME: bool`, so one
/// module tests it with `if` and a pipeline sets it (docs/keywords.md).
#[derive(Debug, Clone)]
pub struct DynamicKeyword {
    /// The keyword.
    pub name: String,
    /// Where the pragma lists it: the declaration maps there.
    pub span: Span,
    /// The stages whose pipeline stage sets it (every stage's text declares it).
    pub stage: KeywordStage,
    /// Whether it is on when nothing sets it: the first keyword of a set without `_`.
    pub default_on: bool,
}

impl DynamicKeyword {
    /// The `dynamic_branch` keywords of a pass's pragmas, in declaration order.
    pub fn of(pragmas: &ProgramPragmas) -> Vec<DynamicKeyword> {
        let sets = pragmas.keyword_sets.iter().filter(|set| set.kind == KeywordKind::DynamicBranch);
        sets.flat_map(|set| {
            let first_is_default = !set.has_off_option();
            set.options.iter().filter_map(|o| o.keyword.as_ref().map(|k| (k, o.span))).enumerate().map(
                move |(i, (name, span))| DynamicKeyword {
                    name: name.clone(),
                    span,
                    stage: set.stage,
                    default_on: first_is_default && i == 0,
                },
            )
        })
        .collect()
    }

    /// Its declaration in WGSL.
    pub fn declaration(&self) -> String {
        format!("override {}: bool = {};", self.name, self.default_on)
    }
}
