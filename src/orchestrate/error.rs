//! What the build layer itself finds wrong (not the stages: their errors are their own), as a
//! typed enum turned into diagnostics here.

use crate::diagnostics::Diagnostic;
use crate::source::Span;
use std::path::PathBuf;

/// A build-layer mistake, with what the diagnostic needs.
#[derive(Debug)]
pub enum BuildLayerError {
    /// `kiln check --all-variants` on a pass whose keyword sets multiply past the limit (K0408).
    TooManyVariants {
        /// The pass's index in its SubShader.
        pass: usize,
        /// Its shader's name.
        shader: String,
        /// How many variants it has (a number, or "more than 2^64").
        count: String,
        /// The limit.
        limit: u128,
        /// Its first keyword set (or the shader's name).
        span: Span,
    },
    /// The output folder cannot be written (K0410).
    Write {
        /// The output folder.
        output: PathBuf,
        /// The system's reason.
        error: std::io::Error,
    },
    /// No shard built a pass of this shader (K0412).
    PassMissing {
        /// The shader's name.
        shader: String,
    },
    /// A module's bytes in its shard's pack are missing or not what their hash says (K0412).
    ModuleDamaged {
        /// Its stage.
        stage: crate::manifest::ShaderStage,
        /// The entry point.
        entry: String,
        /// The pack.
        pack: PathBuf,
    },
    /// No shard's record carries the catalogue's part, or its materials are not all there (K0412).
    CatalogueMissing,
    /// A pass's part in a shard's record does not read (K0412).
    PartDamaged {
        /// The shard's output folder.
        folder: PathBuf,
    },
    /// The project is not what the shards read (K0413).
    ProjectChanged,
    /// A pass program without a vertex, fragment or kernel entry point (K0430).
    NoEntryPoint {
        /// The pragma of a stage or form kiln does not build (`#pragma surface`), if there is one.
        pragma: Option<crate::source::Spanned<String>>,
        /// The program's language.
        language: crate::shaderlab::ast::ProgramLanguage,
        /// Its first block.
        span: Span,
    },
    /// A `dynamic_branch` or `ubershader` pragma in an HLSL or Cg program (K0428).
    WgslOnlyPragma {
        /// The pragma's name.
        pragma: &'static str,
        /// The program's language.
        language: crate::shaderlab::ast::ProgramLanguage,
        /// The pragma.
        span: Span,
    },
    /// A pass whose program is in a language kiln lists but does not compile (K0424).
    LanguageNotBuilt {
        /// Its blocks' language.
        language: crate::shaderlab::ast::ProgramLanguage,
        /// Its shader's name.
        shader: String,
        /// Its first block.
        span: Span,
    },
}

impl From<BuildLayerError> for Diagnostic {
    fn from(error: BuildLayerError) -> Diagnostic {
        match error {
            BuildLayerError::TooManyVariants { pass, shader, count, limit, span } => {
                let past_any_build = count.starts_with("more than");
                let diagnostic = Diagnostic::error(
                    "K0408",
                    format!("pass {pass} of `{shader}` has {count} variants, over the limit of {limit}"),
                )
                .at(span, "its keyword sets multiply to that many");
                let diagnostic = match past_any_build {
                    true => diagnostic.note("that is past what any build could make: at a million variants a second, 2^64 takes half a million years"),
                    false => diagnostic,
                };
                diagnostic
                    .help("check the variants materials use with `kiln check` (without `--all-variants`)")
            }
            BuildLayerError::Write { output, error } => {
                Diagnostic::error("K0410", format!("cannot write to `{}`: {error}", output.display()))
            }
            BuildLayerError::PassMissing { shader } => {
                Diagnostic::error("K0412", format!("no shard holds a pass of `{shader}`"))
                    .note("its shard's output is damaged, or was built from another state of the project")
            }
            BuildLayerError::ModuleDamaged { stage, entry, pack } => {
                Diagnostic::error("K0412", format!("no shard holds the {stage} module of `{entry}` intact"))
                    .note(format!("`{}` is damaged or missing", pack.display()))
                    .help("build that shard again")
            }
            BuildLayerError::CatalogueMissing => {
                Diagnostic::error("K0412", "no shard holds the project's catalogue")
                    .note("the first shard's `shard.json` carries it; that shard's output is damaged")
                    .help("build that shard again")
            }
            BuildLayerError::PartDamaged { folder } => {
                Diagnostic::error("K0412", format!("a pass's part in `{}` is damaged", folder.display()))
                    .help("build that shard again")
            }
            BuildLayerError::ProjectChanged => {
                Diagnostic::error("K0413", "the shards were built from another state of the project")
                    .note(
                        "a file the build reads, the project's settings or the build's options changed since",
                    )
                    .help("build the shards again from this state of the project, then merge them")
            }
            BuildLayerError::NoEntryPoint { pragma: Some(pragma), .. } => Diagnostic::error(
                "K0430",
                format!("`#pragma {}` is not built: the program names no vertex or fragment entry point", pragma.value),
            )
            .at(pragma.span, "a stage or form kiln does not compile")
            .note(match pragma.value.as_str() {
                "surface" => "Unity generates a surface shader's vertex and fragment programs; kiln compiles only the programs a pass writes",
                _ => "kiln compiles vertex, fragment and compute programs",
            })
            .help("write the pass's `#pragma vertex` and `#pragma fragment` programs"),
            BuildLayerError::NoEntryPoint { pragma: None, language, span } => {
                Diagnostic::error("K0430", "the program names no entry point: it would build nothing")
                    .at(opening_keyword(language, span), "this program")
                    .help("name them: `#pragma vertex NAME` and `#pragma fragment NAME` (or `#pragma kernel NAME` in a `.compute` file)")
            }
            BuildLayerError::WgslOnlyPragma { pragma, language, span } => Diagnostic::error(
                "K0428",
                format!("`#pragma {pragma}` is for WGSL programs: this is an `{}`", language.open_keyword(false)),
            )
            .at(span, "here")
            .note(match pragma {
                "dynamic_branch" => "kiln declares each `dynamic_branch` keyword as a WGSL `override` constant, which an HLSL or Cg program cannot use",
                _ => "kiln reads the ubershader's keywords from WGSL immediate data, which an HLSL or Cg program cannot declare",
            })
            .help("make the keywords `shader_feature` or `multi_compile` (each value is then a variant), or write the pass in WGSL"),
            BuildLayerError::LanguageNotBuilt { language, shader, span } => {
                let span = opening_keyword(language, span);
                Diagnostic::error(
                "K0424",
                format!("`{}` blocks are listed but not compiled: `{shader}` is not built", language.open_keyword(false)),
            )
            .at(span, "this program")
            .note("kiln compiles `WGSLPROGRAM`, `HLSLPROGRAM` and `CGPROGRAM` blocks; a pass in another language is an error rather than a pass counted as checked")
            .help("write the program in WGSL (docs/first-shader.md) or HLSL (docs/hlsl.md)")
            }
        }
    }
}

/// Where a diagnostic about a whole program block points: its opening keyword (`HLSLPROGRAM`), not
/// the whole block.
fn opening_keyword(language: crate::shaderlab::ast::ProgramLanguage, block: Span) -> Span {
    let keyword = language.open_keyword(false).len().min(block.range().len());
    Span::new(block.file, block.range().start..block.range().start + keyword)
}
