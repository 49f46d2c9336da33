//! The WGSL preprocessor: `#include`, `#define`, conditionals and macro substitution, with a
//! source map from every output byte back to its original file.
//!
//! Work is split in two so that variants cost little: [`Includes::load_program`] finds and scans
//! every file a pass can include, once, whatever the keywords (this is the only part that reads
//! files, through the [`SourceStore`]); [`preprocess`] then walks those scans for one variant and
//! stage, without I/O, so variants can run in parallel.

mod analysis;
mod error;
mod expr;
mod include;
mod macros;
mod pass;
mod run;
mod scan;
mod source_map;

pub use error::PreprocessError;
pub use include::{IncludeConfig, Includes, LIBRARY_PREFIX, MacroDefinition, Program, ScannedBlock};
pub(crate) use macros::{Kind, Token, lex};
pub use pass::{
    DynamicKeyword, KeywordMacros, MAX_UBERSHADER_KEYWORDS, PassProgram, UBERSHADER_DATA, finish_pass,
    keyword_macros, load_pass, load_pass_text, ubershader_macros,
};
pub use run::MAX_INCLUDE_DEPTH;
pub use run::Skipped;
pub use scan::MAX_CONDITIONAL_DEPTH;
pub use source_map::{Origin, SourceMap};

use crate::diagnostics::Diagnostic;
use crate::source::SourceStore;

/// The stage a text is preprocessed for. Its macro (`SHADER_STAGE_VERTEX`,
/// `SHADER_STAGE_FRAGMENT` or `SHADER_STAGE_COMPUTE`) is defined, as Unity does.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Stage {
    /// The vertex stage.
    Vertex,
    /// The fragment stage.
    Fragment,
    /// A compute kernel (`#pragma kernel`).
    Compute,
}

impl Stage {
    /// The macro defined while preprocessing it (`SHADER_STAGE_VERTEX`, ...).
    pub fn macro_name(self) -> &'static str {
        match self {
            Stage::Vertex => "SHADER_STAGE_VERTEX",
            Stage::Fragment => "SHADER_STAGE_FRAGMENT",
            Stage::Compute => "SHADER_STAGE_COMPUTE",
        }
    }

    /// The manifest's name for it.
    pub fn shader_stage(self) -> crate::manifest::ShaderStage {
        match self {
            Stage::Vertex => crate::manifest::ShaderStage::Vertex,
            Stage::Fragment => crate::manifest::ShaderStage::Fragment,
            Stage::Compute => crate::manifest::ShaderStage::Compute,
        }
    }

    /// Its name: `vertex` or `fragment`.
    pub fn name(self) -> &'static str {
        match self {
            Stage::Vertex => "vertex",
            Stage::Fragment => "fragment",
            Stage::Compute => "compute",
        }
    }
}

/// The macros Unity's compiler defines for a platform, target and stage (`SHADER_API_D3D11`,
/// `SHADER_TARGET`, ...), which HLSL and Cg includes test: never keywords, so keyword analysis
/// does not call them undeclared.
pub const PLATFORM_MACRO_PREFIXES: [&str; 4] =
    ["SHADER_API_", "SHADER_TARGET", "UNITY_COMPILER_", "SHADER_STAGE_"];

/// Macros kiln defines itself, which keyword analysis must not call undeclared.
pub const BUILTIN_MACROS: [&str; 3] =
    ["SHADER_STAGE_VERTEX", "SHADER_STAGE_FRAGMENT", "SHADER_STAGE_COMPUTE"];

/// One variant's spliced WGSL.
#[derive(Debug, Clone)]
pub struct Preprocessed {
    /// The WGSL text.
    pub text: String,
    /// Where each byte came from.
    pub source_map: SourceMap,
    /// `#error`, `#warning`, failed includes and expression errors met on this variant's path,
    /// each with its "included from" chain.
    pub diagnostics: Vec<Diagnostic>,
}

/// Preprocesses `program` for one variant: `keywords` are defined (as `1`), as is the stage's
/// macro. `includes` must be the set the program was loaded into.
pub fn preprocess(
    includes: &Includes,
    store: &SourceStore,
    program: &Program,
    keywords: &[&str],
    stage: Stage,
) -> Preprocessed {
    run::run(includes, store, program, &KeywordMacros::on(keywords), stage)
}

/// [`preprocess`] with the keywords given as macros ([`keyword_macros`], [`ubershader_macros`]).
pub fn preprocess_with(
    includes: &Includes,
    store: &SourceStore,
    program: &Program,
    keywords: &KeywordMacros,
    stage: Stage,
) -> Preprocessed {
    run::run(includes, store, program, keywords, stage)
}

/// What [`preprocess_with`] skips for this variant (its keywords and language as macros): each
/// text run, include and define of a conditional group not taken (an editor's inactive regions),
/// and the files it reads.
pub fn inactive_regions(
    includes: &Includes,
    store: &SourceStore,
    program: &Program,
    keywords: &KeywordMacros,
    stage: Stage,
) -> Skipped {
    run::run_recording(includes, store, program, keywords, stage, Some(Skipped::default())).1
}
