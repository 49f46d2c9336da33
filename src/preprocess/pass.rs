//! A pass's WGSL program as the rest of the pipeline sees it: its blocks with everything they
//! can include, the pragmas that count for it, and the keyword warnings about it.

use super::Stage;
use super::analysis::{analyze_keywords, pragma_sources};
use super::include::{Includes, Program};
use crate::diagnostics::Diagnostic;
use crate::shaderlab::ast::ProgramBlock;
use crate::shaderlab::pragma::{KeywordKind, KeywordStage, ProgramPragmas, collect_pragmas};
use crate::source::{SourceStore, Span};
use std::borrow::Cow;

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

/// How one stage's text sees its pass's keywords: each keyword macro and what it stands for.
#[derive(Debug, Clone, Default)]
pub struct KeywordMacros<'a> {
    /// Each macro and its replacement.
    pub defines: Vec<(&'a str, Cow<'static, str>)>,
    /// An ubershader's `#pragma ubershader` line: its immediate data ([`UBERSHADER_DATA`]) is
    /// declared at the end of the text, mapped there, and its `dynamic_branch` keywords are
    /// macros rather than `override` constants.
    pub ubershader: Option<Span>,
}

/// What an HLSL or Cg program is preprocessed with besides its keywords: Unity's Direct3D 11, whose
/// conventions are WebGPU's (clip space y up, depth 0 to 1, texture rows from the top) and whose
/// branches of `HLSLSupport.cginc` and the includes written against it are plain HLSL
/// (docs/hlsl.md).
pub(super) const HLSL_MACROS: [(&str, &str); 1] = [("SHADER_API_D3D11", "1")];

impl<'a> KeywordMacros<'a> {
    /// These macros and a program's language's own ([`HLSL_MACROS`] for HLSL and Cg).
    pub fn in_language(mut self, language: crate::shaderlab::ast::ProgramLanguage) -> KeywordMacros<'a> {
        if language != crate::shaderlab::ast::ProgramLanguage::Wgsl {
            self.defines.extend(HLSL_MACROS.iter().map(|&(name, value)| (name, Cow::Borrowed(value))));
        }
        self
    }

    /// The keywords on, each defined as `1` (Unity's way); the others undefined.
    pub fn on(keywords: &[&'a str]) -> KeywordMacros<'a> {
        KeywordMacros {
            defines: keywords.iter().map(|&k| (k, Cow::Borrowed("1"))).collect(),
            ubershader: None,
        }
    }
}

/// The most keywords an ubershader reads: the bits of its immediate data.
pub const MAX_UBERSHADER_KEYWORDS: usize = 64;

/// What an ubershader's text declares: the bits of the keywords on, in
/// [`ProgramPragmas::ubershader_keywords`] order, as immediate data the draw sets. A struct, not
/// a bare `vec2<u32>`: naga's HLSL writer refuses immediate data of any other type
/// (gfx-rs/wgpu#5683), which `kiln check --backends hlsl` found.
pub const UBERSHADER_DATA: &str =
    "struct KilnKeywords { bits: vec2<u32> } var<immediate> kiln_keywords: KilnKeywords;";

/// The macros a variant's `stage` is preprocessed with, `on` being the stage's keywords on. In a
/// pass with `#pragma ubershader`, every variant keyword is a macro, `true` or `false`, so that
/// the program tests it with `if` as its ubershader does (docs/keywords.md).
pub fn keyword_macros<'a>(pragmas: &'a ProgramPragmas, on: &[&'a str]) -> KeywordMacros<'a> {
    if pragmas.ubershader.is_none() {
        return KeywordMacros::on(on);
    }
    let variant = pragmas.ubershader_keywords().into_iter().filter(|k| !pragmas.is_dynamic(k));
    let defines = variant.map(|k| (k, Cow::Borrowed(if on.contains(&k) { "true" } else { "false" })));
    KeywordMacros { defines: defines.collect(), ubershader: None }
}

/// The macros of a pass's ubershader for `stage`: each keyword the stage sees tests its bit of
/// the immediate data; one it does not see is what a variant's stage sees (`false`, or a
/// `dynamic_branch` keyword's default). `None` when the pass has no `#pragma ubershader`.
pub fn ubershader_macros(pragmas: &ProgramPragmas, stage: Stage) -> Option<KeywordMacros<'_>> {
    let pragma = pragmas.ubershader?;
    let shader_stage = stage.shader_stage();
    let dynamic = DynamicKeyword::of(pragmas);
    let defines = pragmas.ubershader_keywords().into_iter().enumerate().map(|(bit, keyword)| {
        let mut sets = pragmas.keyword_sets.iter().filter(|set| set.keywords().any(|k| k == keyword));
        // A kernel sees every keyword, as its variants' kernels do.
        let seen = stage == Stage::Compute || sets.any(|set| set.stage.includes(shader_stage));
        let value = if seen {
            let word = if bit < 32 { 'x' } else { 'y' };
            Cow::Owned(format!("((kiln_keywords.bits.{word} & {:#x}u) != 0u)", 1u32 << (bit % 32)))
        } else {
            let on = dynamic.iter().any(|d| d.name == keyword && d.default_on);
            Cow::Borrowed(if on { "true" } else { "false" })
        };
        (keyword, value)
    });
    Some(KeywordMacros { defines: defines.collect(), ubershader: Some(pragma) })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_identifier_kiln_writes_into_a_text_is_a_name_no_keyword_may_take() {
        // The declaration and a macro's value, as the ubershader's text holds them.
        let macro_value = "((kiln_keywords.bits.x & 0x1u) != 0u) ((kiln_keywords.bits.y & 0x1u) != 0u)";
        let words = |text: &str| -> Vec<String> {
            text.split(|c: char| !c.is_ascii_alphanumeric() && c != '_')
                .filter(|w| w.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_'))
                .map(str::to_string)
                .collect()
        };
        let wgsl = ["struct", "var", "immediate", "vec2", "u32"];
        for word in words(UBERSHADER_DATA).into_iter().chain(words(macro_value)) {
            let written_by_kiln = !wgsl.contains(&word.as_str());
            assert!(
                !written_by_kiln || crate::shaderlab::reserved::KILN_IDENTIFIERS.contains(&word.as_str()),
                "`{word}` is written by kiln and may be a keyword's name"
            );
        }
    }
}
