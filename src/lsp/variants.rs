//! The active variant of each pass (the editor's choice, else the first a material uses) and what
//! it leaves out: the `#if` groups that are off for it, greyed out as clangd greys inactive code.

use super::analysis::{Analysis, PassRef};
use crate::catalog::CatalogProgram;
use crate::keywords::Variant;
use crate::preprocess::{Stage, inactive_regions};
use crate::source::{FileId, Span};
use std::collections::{HashMap, HashSet};

/// A pass as the editor's choices name it, stable across edits: shader name and pass position.
pub(super) type PassName = (String, usize);

/// The variants chosen in the editor, per pass.
#[derive(Default, Clone)]
pub(super) struct Selections {
    chosen: HashMap<PassName, Vec<String>>,
}

impl Selections {
    /// Chooses the variant with `keywords` for `pass`.
    pub(super) fn choose(&mut self, pass: PassName, keywords: Vec<String>) {
        self.chosen.insert(pass, keywords);
    }

    /// The active variant of a pass: the one chosen, if the pass still has it; else the first a
    /// material uses; else the first. With its position among the pass's variants.
    pub(super) fn active<'a>(
        &self,
        name: &PassName,
        program: &'a CatalogProgram,
    ) -> Option<(usize, &'a Variant)> {
        let variants = &program.variants;
        let chosen = self
            .chosen
            .get(name)
            .and_then(|keywords| variants.iter().position(|v| keyword_list(program, v) == *keywords));
        let used = || variants.iter().position(|v| !v.materials.is_empty());
        let index = chosen.or_else(used).or((!variants.is_empty()).then_some(0))?;
        Some((index, &variants[index]))
    }
}

/// A variant's keywords, in bit order.
pub(super) fn keyword_list(program: &CatalogProgram, variant: &Variant) -> Vec<String> {
    program.keywords.keywords(&variant.bits).map(str::to_string).collect()
}

/// How a variant is shown: its keywords, or `(no keywords)` (as diagnostics name variants).
pub(super) fn shown(keywords: &[String]) -> String {
    if keywords.is_empty() { "(no keywords)".into() } else { keywords.join(" ") }
}

/// The name the editor's choices use for a pass.
pub(super) fn pass_name(analysis: &Analysis, at: PassRef) -> Option<PassName> {
    let (shader, pass, _) = analysis.pass(at)?;
    Some((shader.shader.name.value.clone(), pass.index))
}

/// The inactive regions of every file, for the active variants: a span is inactive in a file when
/// every pass that reads the file skips it (in each stage it compiles).
pub(super) fn inactive(analysis: &Analysis, selections: &Selections) -> HashMap<FileId, Vec<Span>> {
    let Some(checked) = &analysis.checked else { return HashMap::new() };
    // Per file: how many pass stages read it, and how many of them skip each span.
    let mut readers: HashMap<FileId, usize> = HashMap::new();
    let mut skips: HashMap<FileId, HashMap<Span, usize>> = HashMap::new();
    for (at, _, _, program) in analysis.passes() {
        let (Some(name), Some(source)) = (pass_name(analysis, at), program.source.as_ref()) else { continue };
        let Some((_, variant)) = selections.active(&name, program) else { continue };
        let stages: &[Stage] = if program.pragmas.kernels.is_empty() {
            &[Stage::Vertex, Stage::Fragment]
        } else {
            &[Stage::Compute]
        };
        for &stage in stages {
            let keywords: Vec<&str> =
                program.keywords.keywords(program.keywords_for(variant, stage)).collect();
            // As a build preprocesses it: the language's macros too (`SHADER_API_D3D11`).
            let macros = crate::preprocess::KeywordMacros::on(&keywords).in_language(program.language);
            let skipped = inactive_regions(&checked.includes, &analysis.store, source, &macros, stage);
            for file in skipped.files {
                *readers.entry(file).or_default() += 1;
            }
            let distinct: HashSet<Span> = skipped.spans.into_iter().collect();
            for span in distinct {
                *skips.entry(span.file).or_default().entry(span).or_default() += 1;
            }
        }
    }
    skips
        .into_iter()
        .map(|(file, spans)| {
            let needed = readers.get(&file).copied().unwrap_or(0);
            let mut all: Vec<Span> =
                spans.into_iter().filter(|&(_, n)| n >= needed).map(|(s, _)| s).collect();
            all.sort_by_key(|s| s.start);
            (file, all)
        })
        .collect()
}

/// What the macro invocation at byte `offset` of `file` expands to in the active variant of the
/// first pass whose text reaches it: the pass and variant, and the expanded text.
pub(super) fn expansion_at(
    analysis: &Analysis,
    selections: &Selections,
    file: FileId,
    offset: usize,
) -> Option<(String, String)> {
    let checked = analysis.checked.as_ref()?;
    analysis.passes().find_map(|(at, shader, pass, program)| {
        let (name, source) = (pass_name(analysis, at)?, program.source.as_ref()?);
        let (_, variant) = selections.active(&name, program)?;
        let stage = if program.pragmas.kernels.is_empty() { Stage::Fragment } else { Stage::Compute };
        let keywords: Vec<&str> = program.keywords.keywords(program.keywords_for(variant, stage)).collect();
        let macros = program.keyword_macros(&keywords);
        let out =
            crate::preprocess::preprocess_with(&checked.includes, &analysis.store, source, &macros, stage);
        let range = out.source_map.expansion_at(file, offset)?;
        let place = format!(
            "`{}` pass {}, variant `{}`",
            shader.shader.name.value,
            pass.index,
            shown(&keyword_list(program, variant))
        );
        Some((place, out.text[range].trim().to_string()))
    })
}
