//! `kiln check`'s diagnostics as the protocol has them: one list per file, errors in an include
//! shown in the include with the including places as related information, and the variants a
//! problem occurs in said as "in 3 of 8 variants of `S` pass 0: those with `_CLIPPING`".

use super::analysis::Analysis;
use super::text::{range_of, uri_of};
use super::variants::{keyword_list, shown};
use crate::diagnostics::{Diagnostic, Occurrence, Severity};
use crate::source::{FileId, Span};
use lsp_types as lsp;
use std::collections::{BTreeMap, HashMap};
use std::path::PathBuf;

/// The diagnostics of one analysis (and the inactive regions of its active variants), per file.
pub(super) fn by_file(
    analysis: &Analysis,
    inactive: &HashMap<FileId, Vec<Span>>,
) -> BTreeMap<PathBuf, Vec<lsp::Diagnostic>> {
    let mut files: BTreeMap<PathBuf, Vec<lsp::Diagnostic>> = BTreeMap::new();
    for diagnostic in analysis.diagnostics() {
        let (path, converted) = match &diagnostic.primary {
            Some(label) => match analysis.path(label.span.file) {
                Some(path) => (path, convert(analysis, diagnostic, Some(label.span))),
                None => continue,
            },
            // Not about a place (a project without shaders): shown at the top of `kiln.toml`.
            None => (analysis.root.join(crate::config::FILE_NAME), convert(analysis, diagnostic, None)),
        };
        files.entry(path).or_default().push(converted);
    }
    if let Some(error) = &analysis.error {
        let diagnostic = lsp::Diagnostic {
            severity: Some(lsp::DiagnosticSeverity::ERROR),
            source: Some("kiln".into()),
            message: error.clone(),
            ..lsp::Diagnostic::default()
        };
        files.entry(analysis.root.join(crate::config::FILE_NAME)).or_default().push(diagnostic);
    }
    for (&file, spans) in inactive {
        let Some(path) = analysis.path(file) else { continue };
        let text = analysis.store.text(file);
        let hints = spans.iter().map(|span| lsp::Diagnostic {
            range: range_of(text, span.range()),
            severity: Some(lsp::DiagnosticSeverity::HINT),
            source: Some("kiln".into()),
            message: "inactive in the selected variant".into(),
            tags: Some(vec![lsp::DiagnosticTag::UNNECESSARY]),
            ..lsp::Diagnostic::default()
        });
        files.entry(path).or_default().extend(hints);
    }
    files
}

fn convert(analysis: &Analysis, diagnostic: &Diagnostic, at: Option<Span>) -> lsp::Diagnostic {
    let store = &analysis.store;
    let range = at.map(|span| range_of(store.text(span.file), span.range())).unwrap_or_default();
    let severity = match diagnostic.severity {
        Severity::Error => lsp::DiagnosticSeverity::ERROR,
        Severity::Warning => lsp::DiagnosticSeverity::WARNING,
        Severity::Note => lsp::DiagnosticSeverity::INFORMATION,
    };
    let mut message = diagnostic.message.clone();
    if let Some(label) = diagnostic.primary.as_ref().filter(|l| !l.message.is_empty()) {
        message.push_str(&format!(" ({})", label.message));
    }
    if let Some(occurrence) = &diagnostic.occurrence {
        message.push('\n');
        message.push_str(&occurrence_line(analysis, occurrence));
    }
    let notes = diagnostic.notes.iter().filter(|n| !n.starts_with("included from "));
    for note in notes {
        message.push_str(&format!("\nnote: {note}"));
    }
    if let Some(help) = &diagnostic.help {
        message.push_str(&format!("\nhelp: {help}"));
    }
    let mut related: Vec<lsp::DiagnosticRelatedInformation> = diagnostic
        .secondary
        .iter()
        .filter_map(|label| location(analysis, label.span).map(|location| (location, label.message.clone())))
        .map(|(location, message)| lsp::DiagnosticRelatedInformation { location, message })
        .collect();
    related.extend(included_from(analysis, diagnostic));
    lsp::Diagnostic {
        range,
        severity: Some(severity),
        code: Some(lsp::NumberOrString::String(diagnostic.code.into())),
        source: Some("kiln".into()),
        message,
        related_information: (!related.is_empty()).then_some(related),
        ..lsp::Diagnostic::default()
    }
}

/// A place as the protocol has it.
pub(super) fn location(analysis: &Analysis, span: Span) -> Option<lsp::Location> {
    let uri = uri_of(&analysis.path(span.file)?)?;
    Some(lsp::Location::new(uri, range_of(analysis.store.text(span.file), span.range())))
}

/// The `included from FILE:LINE:COL` notes as related places: the shaders that include the file.
fn included_from(analysis: &Analysis, diagnostic: &Diagnostic) -> Vec<lsp::DiagnosticRelatedInformation> {
    let store = &analysis.store;
    diagnostic
        .notes
        .iter()
        .filter_map(|note| {
            let place = note.strip_prefix("included from ")?;
            let mut parts = place.rsplitn(3, ':');
            let column: u32 = parts.next()?.parse().ok()?;
            let line: u32 = parts.next()?.parse().ok()?;
            let name = parts.next()?;
            let file = store.ids().find(|&id| store.name(id) == name)?;
            let uri = uri_of(&analysis.path(file)?)?;
            // The note counts columns in characters; near enough for a line with an `#include`.
            let position = lsp::Position::new(line.saturating_sub(1), column.saturating_sub(1));
            Some(lsp::DiagnosticRelatedInformation {
                location: lsp::Location::new(uri, lsp::Range::new(position, position)),
                message: "included from here".into(),
            })
        })
        .collect()
}

/// `in 3 of 8 variants of `S` pass 0, fragment stage: those with `_CLIPPING``: the variants of
/// an occurrence against all the pass's variants, with the keywords they share when exactly the
/// variants with those keywords have the problem.
fn occurrence_line(analysis: &Analysis, occurrence: &Occurrence) -> String {
    let pass = analysis.passes().find(|(_, shader, pass, _)| {
        shader.shader.name.value == occurrence.pass.shader && pass.index == occurrence.pass.index
    });
    // A first check of the active variants alone cannot say how many others have it.
    let Some((_, _, _, program)) = pass.filter(|_| !analysis.partial) else { return occurrence.note() };
    let all: Vec<Vec<String>> = program.variants.iter().map(|v| keyword_list(program, v)).collect();
    let listed: Vec<Vec<String>> = occurrence
        .variants
        .iter()
        .map(|v| if v == "(no keywords)" { Vec::new() } else { v.split(' ').map(str::to_string).collect() })
        .collect();
    if listed.len() >= all.len() {
        let all = if all.len() == 1 {
            "its one variant".to_string()
        } else {
            format!("all {} variants", all.len())
        };
        return format!("in {all}{}", occurrence.place());
    }
    let common: Vec<String> =
        listed[0].iter().filter(|k| listed.iter().all(|l| l.contains(k))).cloned().collect();
    let with_common = all.iter().filter(|v| common.iter().all(|k| v.contains(k))).count();
    let which = if !common.is_empty() && with_common == listed.len() {
        format!("those with `{}`", common.join(" "))
    } else {
        let names: Vec<String> = listed.iter().map(|l| format!("`{}`", shown(l))).collect();
        names.join(", ")
    };
    let variants = if all.len() == 1 { "variant" } else { "variants" };
    format!("in {} of {} {variants}{}: {which}", listed.len(), all.len(), occurrence.place())
}
