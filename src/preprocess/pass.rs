//! A pass's WGSL program as the rest of the pipeline sees it: its blocks with everything they
//! can include, the pragmas that count for it, and the keyword warnings about it.

use super::analysis::{analyze_keywords, pragma_sources};
use super::include::{Includes, Program};
use crate::diagnostics::Diagnostic;
use crate::shaderlab::ast::ProgramBlock;
use crate::shaderlab::pragma::{ProgramPragmas, collect_pragmas};
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
    let spans: Vec<Span> = blocks.iter().map(|b| b.body_span).collect();
    load_pass_text(includes, store, &spans)
}

/// [`load_pass`] for program text that is no ShaderLab block (the accuracy harness).
pub fn load_pass_text(
    includes: &mut Includes,
    store: &mut SourceStore,
    spans: &[Span],
) -> (PassProgram, Vec<Diagnostic>) {
    let (program, mut diagnostics) = includes.load_program(store, spans);
    let (pragmas, errors) = collect_pragmas(pragma_sources(includes, store, &program));
    diagnostics.extend(errors);
    diagnostics.extend(analyze_keywords(includes, &program, &pragmas));
    (PassProgram { program, pragmas }, diagnostics)
}
