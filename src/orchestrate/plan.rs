//! What a build does, decided from the catalogue before any text is preprocessed: the passes to
//! build with their variants, what each weighs (for shards), and how a pass is known across
//! builds.

use super::BuildSummary;
use super::error::BuildLayerError;
use crate::catalog::{Catalog, CatalogPass, CatalogProgram, CatalogShader};
use crate::config::{ParseScope, Settings, VariantSelection};
use crate::diagnostics::Diagnostic;
use crate::keywords::Variant;
use crate::preprocess::{Includes, Stage};
use crate::source::SourceStore;
use crate::store::PassKey;
use rayon::prelude::*;
use std::borrow::Cow;
use std::collections::HashSet;

/// A pass to build. Its jobs are made when it is built, and dropped with it.
pub(super) struct PassWork<'a> {
    pub shader: &'a CatalogShader,
    /// The shader's index in the catalogue.
    pub shader_index: usize,
    pub pass: &'a CatalogPass,
    pub program: &'a CatalogProgram,
    pub variants: Cow<'a, [Variant]>,
}

/// The passes to build, with their variants, in catalogue order.
pub(super) fn plan<'a>(
    catalog: &'a Catalog,
    selection: VariantSelection,
    summary: &mut BuildSummary,
    diagnostics: &mut Vec<Diagnostic>,
) -> Vec<PassWork<'a>> {
    let mut work: Vec<PassWork> = Vec::new();
    for (shader_index, shader) in catalog.shaders.iter().enumerate() {
        let (mut built_any, mut has_program) = (false, false);
        for pass in &shader.passes {
            let Some(program) = pass.program.as_ref() else { continue };
            if program.source.is_none() {
                // Listed, and never counted as built or checked: a CI job pointed at a library
                // of such shaders must not pass having checked nothing.
                diagnostics.push(
                    BuildLayerError::LanguageNotBuilt {
                        language: program.language,
                        shader: shader.shader.name.value.clone(),
                        span: program.span,
                    }
                    .into(),
                );
                continue;
            }
            has_program = true;
            if let Some(refused) = without_entry_point(program) {
                diagnostics.push(refused.into());
                continue;
            }
            if let Some(refused) = wgsl_only_pragma(program) {
                diagnostics.push(refused.into());
                continue;
            }
            let variants = select_variants(shader, pass, program, selection, diagnostics);
            if variants.is_empty() {
                continue;
            }
            built_any = true;
            summary.variants += variants.len();
            summary.passes += 1;
            work.push(PassWork { shader, shader_index, pass, program, variants });
        }
        summary.shaders += usize::from(built_any);
        if has_program && !built_any && selection == VariantSelection::Used {
            summary.unused.push(shader.shader.name.value.clone());
        }
    }
    work
}

/// A pass program that names no entry point (no `#pragma vertex`, `fragment` or `kernel`): it
/// would build nothing, so it is refused rather than counted as checked. Unity's surface shaders
/// (`#pragma surface`) are the usual case.
fn without_entry_point(program: &crate::catalog::CatalogProgram) -> Option<BuildLayerError> {
    let pragmas = &program.pragmas;
    if pragmas.vertex.is_some() || pragmas.fragment.is_some() || !pragmas.kernels.is_empty() {
        return None;
    }
    let unbuilt = ["surface", "geometry", "hull", "domain", "raytracing"];
    let stage = pragmas.other.iter().find(|(name, _)| unbuilt.contains(&name.value.as_str()));
    Some(BuildLayerError::NoEntryPoint {
        pragma: stage.map(|(name, _)| name.clone()),
        language: program.language,
        span: program.span,
    })
}

/// A pragma whose code kiln writes in WGSL (`dynamic_branch`'s `override` constants, the
/// ubershader's immediate data), in a program of another language: refused at the pragma, for
/// its code would not compile there.
fn wgsl_only_pragma(program: &crate::catalog::CatalogProgram) -> Option<BuildLayerError> {
    use crate::manifest::KeywordKind;
    if program.language == crate::shaderlab::ast::ProgramLanguage::Wgsl {
        return None;
    }
    let pragmas = &program.pragmas;
    let dynamic = pragmas.keyword_sets.iter().find(|s| s.kind == KeywordKind::DynamicBranch);
    let (pragma, span) = match (dynamic, pragmas.ubershader) {
        (Some(set), _) => ("dynamic_branch", set.span),
        (None, Some(span)) => ("ubershader", span),
        (None, None) => return None,
    };
    Some(BuildLayerError::WgslOnlyPragma { pragma, language: program.language, span })
}

/// What each pass costs to build, known before preprocessing: its distinct stage requests (a
/// variant's vertex and fragment keywords; variants that differ only in the other stage's
/// keywords share a module). Every shard weighs every pass: in parallel.
pub(super) fn weights(work: &[PassWork]) -> Vec<u64> {
    work.par_iter()
        .map(|pass| {
            let mut requests = HashSet::new();
            let entries = super::jobs::entry_points(&pass.program.pragmas);
            for variant in pass.variants.iter() {
                for &(stage, entry) in entries.iter() {
                    if let Some(entry) = entry {
                        requests.insert((
                            stage,
                            entry.value.as_str(),
                            pass.program.keywords_for(variant, stage),
                        ));
                    }
                }
            }
            requests.len() as u64
        })
        .collect()
}

/// Identifies a pass across builds: its shader file (relative to the project) and place.
pub(super) fn pass_key(store: &SourceStore, settings: &Settings, work: &PassWork) -> PassKey {
    let file = super::noop::recorded_name(store, work.shader.file, &settings.root);
    PassKey::of(&format!("{file}#{}.{}", work.pass.subshader, work.pass.index))
}

/// The distinct preprocessed stage texts a build of the catalogue compiles, whole, with their
/// stage and entry point: what naga (or glslang, Cg's samplers rewritten) alone would have to
/// parse, validate and emit for the same output (used by the benchmarks to compare kiln with the
/// tools alone).
pub fn stage_texts(
    store: &SourceStore,
    includes: &Includes,
    catalog: &Catalog,
) -> Vec<(Stage, String, String)> {
    let work = plan(catalog, VariantSelection::Used, &mut BuildSummary::default(), &mut Vec::new());
    work.iter()
        .flat_map(|pass| {
            super::jobs::pass_jobs(store, includes, pass, ParseScope::Whole, &mut Vec::new()).jobs
        })
        .map(|j| (j.stage, j.entry.to_string(), crate::compile::front_text(j.language, j.text)))
        .collect()
}

fn select_variants<'a>(
    shader: &CatalogShader,
    pass: &CatalogPass,
    program: &'a CatalogProgram,
    selection: VariantSelection,
    diagnostics: &mut Vec<Diagnostic>,
) -> Cow<'a, [Variant]> {
    if !program.variants.is_empty() {
        return Cow::Borrowed(&program.variants);
    }
    Cow::Owned(match selection {
        VariantSelection::Used => Vec::new(),
        VariantSelection::DefaultsAndEachKeyword => program.keywords.defaults_and_each_keyword(),
        VariantSelection::All { limit } => match program.keywords.possible() {
            Some(n) if n <= limit => program.keywords.enumerate(&[], true, None).unwrap_or_default(),
            count => {
                let count = crate::keywords::PassKeywords::count_text(count);
                let span =
                    program.pragmas.keyword_sets.first().map(|s| s.span).unwrap_or(shader.shader.name.span);
                let error = BuildLayerError::TooManyVariants {
                    pass: pass.index,
                    shader: shader.shader.name.value.clone(),
                    count,
                    limit,
                    span,
                };
                diagnostics.push(error.into());
                Vec::new()
            }
        },
    })
}
