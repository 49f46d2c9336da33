//! What a pass's spliced source says about its keywords, whatever the variant: where its pragmas
//! come from, which keywords no `#if` tests, and which tested names nothing declares.

use super::BUILTIN_MACROS;
use super::error::PreprocessError;
use super::include::{Includes, Program};
use super::pass::MAX_UBERSHADER_KEYWORDS;
use super::scan::{BranchKind, Condition, Item, Target, identifiers};
use crate::diagnostics::Diagnostic;
use crate::shaderlab::pragma::{KeywordKind, PragmaSource, ProgramPragmas};
use crate::source::{SourceStore, Span};
use std::collections::HashSet;

/// The texts whose `#pragma`s count for the pass: its blocks, then every file reached through
/// `#include_with_pragmas` (as Unity counts them).
pub(super) fn pragma_sources<'a>(
    includes: &Includes,
    store: &'a SourceStore,
    program: &Program,
) -> Vec<PragmaSource<'a>> {
    includes
        .reachable(program, true)
        .into_iter()
        .map(|unit| {
            let unit = &includes.units[unit];
            PragmaSource {
                span: Span::new(unit.file, unit.range.clone()),
                text: &store.text(unit.file)[unit.range.clone()],
            }
        })
        .collect()
}

/// Warnings about the pass's keywords, from every file it can include:
/// - a declared keyword that no `#if`, `#ifdef` or `#ifndef` tests only multiplies variants;
/// - a name tested in the project's own files that no pragma declares and no `#define` defines
///   is always off (often a misspelt keyword);
/// - keyword pragmas in a file reached only through a plain `#include` do not count;
/// - a `dynamic_branch` keyword tested by a conditional is an error (it is never a macro).
pub(super) fn analyze_keywords(
    includes: &Includes,
    program: &Program,
    pragmas: &ProgramPragmas,
) -> Vec<Diagnostic> {
    let reachable = includes.reachable(program, false);
    // An include that was not found (its own error) may test any keyword.
    let all_loaded = reachable.iter().all(|&id| {
        includes.units[id]
            .items
            .iter()
            .all(|item| !matches!(item, Item::Include { target: Target::Failed(_), .. }))
    });
    let counted: HashSet<usize> = includes.reachable(program, true).into_iter().collect();
    let mut tested: HashSet<&str> = HashSet::new();
    let mut defined: HashSet<&str> = BUILTIN_MACROS.into_iter().collect();
    // Tests in the project's own files, in source order, for the "never declared" warning.
    let mut project_tests: Vec<(&str, Span)> = Vec::new();
    // Every name a conditional tests, in any file, for `dynamic_branch` keywords tested there.
    let mut conditions: Vec<(&str, Span)> = Vec::new();
    let mut warnings = Vec::new();
    for &id in &reachable {
        let unit = &includes.units[id];
        let in_project = !includes.is_library(id);
        for item in &unit.items {
            match item {
                Item::Define { name, value, .. } => {
                    defined.insert(name);
                    // `#define USE_X defined(_X)` tests `_X` as surely as an `#if` does.
                    tested.extend(identifiers(value).map(|(_, name)| name));
                }
                Item::Branch { kind: BranchKind::If(condition) | BranchKind::Elif(condition), .. } => {
                    for (name, span) in condition_names(condition, unit.file) {
                        tested.insert(name);
                        conditions.push((name, span));
                        if in_project {
                            project_tests.push((name, span));
                        }
                    }
                }
                _ => {}
            }
        }
        if !counted.contains(&id) {
            for (span, pragma) in &unit.keyword_pragmas {
                warnings.push(PreprocessError::PragmaInPlainInclude { span: *span, pragma: pragma.clone() });
            }
        }
    }

    let ubershader_keywords = pragmas.ubershader.map(|_| pragmas.ubershader_keywords()).unwrap_or_default();
    if let Some(pragma) = pragmas.ubershader
        && ubershader_keywords.len() > MAX_UBERSHADER_KEYWORDS
    {
        warnings
            .push(PreprocessError::UbershaderTooManyKeywords { pragma, count: ubershader_keywords.len() });
    }
    for (name, span) in conditions {
        if let Some(pragma) = pragmas.ubershader
            && ubershader_keywords.contains(&name)
            && !pragmas.is_dynamic(name)
        {
            let mut declared = pragmas.keyword_sets.iter().flat_map(|set| &set.options);
            let declared = declared.find(|o| o.keyword.as_deref() == Some(name)).map_or(pragma, |o| o.span);
            warnings.push(PreprocessError::UbershaderKeywordInCondition {
                span,
                keyword: name.to_string(),
                declared,
                pragma,
            });
        }
        let dynamic = pragmas.keyword_sets.iter().filter(|set| set.kind == KeywordKind::DynamicBranch);
        let declaration = dynamic.flat_map(|set| &set.options).find(|o| o.keyword.as_deref() == Some(name));
        if let Some(declaration) = declaration {
            warnings.push(PreprocessError::DynamicKeywordInCondition {
                span,
                keyword: name.to_string(),
                declared: declaration.span,
            });
        }
    }

    let mut declared: HashSet<&str> = HashSet::new();
    for set in &pragmas.keyword_sets {
        for option in &set.options {
            let Some(keyword) = option.keyword.as_deref() else { continue };
            // Dynamic-branch keywords are tested by `if` at run time, not by the preprocessor.
            let first_declaration = declared.insert(keyword);
            // With an include missing, what it tests is unknown: not reported as untested.
            let untested = all_loaded && !tested.contains(keyword);
            // An ubershader's keywords are tested by `if`, as `dynamic_branch` ones are.
            let by_if = set.kind == KeywordKind::DynamicBranch || pragmas.ubershader.is_some();
            if first_declaration && !by_if && untested {
                warnings.push(PreprocessError::KeywordNeverTested {
                    span: option.span,
                    keyword: keyword.to_string(),
                });
            }
        }
    }
    let mut reported: HashSet<&str> = HashSet::new();
    for (name, span) in project_tests {
        let platform = super::PLATFORM_MACRO_PREFIXES.iter().any(|prefix| name.starts_with(prefix));
        if declared.contains(name) || defined.contains(name) || platform || !reported.insert(name) {
            continue;
        }
        let suggestion = declared
            .iter()
            .map(|k| (strsim::damerau_levenshtein(k, name), *k))
            .filter(|&(distance, _)| distance <= 2)
            .min()
            .map(|(_, k)| k.to_string());
        warnings.push(PreprocessError::KeywordNeverDeclared { span, name: name.to_string(), suggestion });
    }
    warnings.into_iter().map(Diagnostic::from).collect()
}

/// The macro names a condition tests, with their spans.
fn condition_names(condition: &Condition, file: crate::source::FileId) -> Vec<(&str, Span)> {
    match condition {
        Condition::Defined { name, span } | Condition::NotDefined { name, span } => {
            vec![(name.as_str(), *span)]
        }
        Condition::Expr { text, start } => identifiers(text)
            .filter(|&(_, name)| name != "defined")
            .map(|(offset, name)| {
                let at = *start as usize + offset;
                (name, Span::new(file, at..at + name.len()))
            })
            .collect(),
        Condition::Missing { .. } => Vec::new(),
        Condition::Trailing { condition, .. } => condition_names(condition, file),
    }
}
