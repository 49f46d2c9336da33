//! Completion (keywords, property names, pragma names, include paths) and document symbols
//! (Shader, Properties, SubShader, Pass; a WGSL or HLSL file's functions and structs).

use super::analysis::Analysis;
use super::text::{Declared, declarations, line_before, range_of};
use crate::source::FileId;
use lsp_types as lsp;
use std::collections::BTreeSet;
use std::path::Path;

/// The pragmas kiln reads, for completion after `#pragma `.
const PRAGMAS: [&str; 14] = [
    "vertex",
    "fragment",
    "kernel",
    "target",
    "require",
    "multi_compile",
    "multi_compile_local",
    "shader_feature",
    "shader_feature_local",
    "dynamic_branch",
    "dynamic_branch_local",
    "skip_variants",
    "instancing_options",
    "once",
];

/// What to offer at byte `offset` of `file` (whose path is `path`).
pub(super) fn complete(
    analysis: &Analysis,
    file: FileId,
    path: &Path,
    offset: usize,
) -> Vec<lsp::CompletionItem> {
    let text = analysis.store.text(file);
    let line = line_before(text, offset);
    let trimmed = line.trim_start();
    let item = |label: &str, kind, detail: &str| lsp::CompletionItem {
        label: label.to_string(),
        kind: Some(kind),
        detail: (!detail.is_empty()).then(|| detail.to_string()),
        ..lsp::CompletionItem::default()
    };
    let keywords = |only_shader: Option<usize>| -> Vec<lsp::CompletionItem> {
        let mut names = BTreeSet::new();
        for (at, _, _, program) in analysis.passes() {
            if only_shader.is_none_or(|s| s == at.shader) {
                for set in &program.pragmas.keyword_sets {
                    names.extend(set.keywords().map(|k| (k.to_string(), set.kind.name())));
                }
            }
        }
        names.iter().map(|(k, kind)| item(k, lsp::CompletionItemKind::CONSTANT, kind)).collect()
    };
    if path.extension().is_some_and(|e| e == "mat") {
        let checked = analysis.checked.as_ref();
        // From the text, not the resolved material: a file being typed rarely parses.
        let named = text.lines().find_map(|l| {
            let value = l.trim().strip_prefix("shader")?.trim_start().strip_prefix('=')?;
            Some(value.trim().trim_matches('"'))
        });
        let shader = checked
            .and_then(|c| c.catalog.shaders.iter().position(|s| Some(s.shader.name.value.as_str()) == named));
        if trimmed.starts_with("keywords") {
            return keywords(shader);
        }
        let Some(shader) = shader.and_then(|s| checked?.catalog.shaders.get(s)) else { return Vec::new() };
        return shader
            .shader
            .properties
            .iter()
            .map(|p| item(&p.name.value, lsp::CompletionItemKind::PROPERTY, &p.display_name.value))
            .collect();
    }
    let directive = trimmed.strip_prefix('#').map(str::trim_start);
    let Some(directive) = directive else { return Vec::new() };
    if let Some(rest) = directive.strip_prefix("pragma") {
        let words: Vec<&str> = rest.split_whitespace().collect();
        let typing_name = words.is_empty() || (words.len() == 1 && !rest.ends_with(char::is_whitespace));
        if typing_name {
            let shorthands = crate::shaderlab::pragma::shorthand_names();
            return PRAGMAS
                .iter()
                .copied()
                .chain(shorthands)
                .map(|p| item(p, lsp::CompletionItemKind::KEYWORD, "pragma"))
                .collect();
        }
        let sets = ["multi_compile", "shader_feature", "dynamic_branch", "skip_variants"];
        return if sets.iter().any(|s| words[0].starts_with(s)) { keywords(None) } else { Vec::new() };
    }
    if let Some(rest) =
        directive.strip_prefix("include_with_pragmas").or_else(|| directive.strip_prefix("include"))
    {
        let typed = rest.trim_start().trim_start_matches(['"', '<']);
        return include_names(analysis, path, typed)
            .into_iter()
            .map(|name| item(&name, lsp::CompletionItemKind::FILE, ""))
            .collect();
    }
    let conditional = ["if", "elif", "ifdef", "ifndef"].iter().any(|d| directive.starts_with(d));
    if conditional {
        let mut items = keywords(None);
        if let Some(checked) = &analysis.checked {
            let macros: BTreeSet<&str> = checked.includes.defines().map(|define| define.name).collect();
            items.extend(macros.into_iter().map(|m| item(m, lsp::CompletionItemKind::CONSTANT, "macro")));
        }
        return items;
    }
    Vec::new()
}

/// File names an `#include` can name from `path`'s folder: those in the folder (and the typed
/// subfolder), the project's include paths and the bundled library.
fn include_names(analysis: &Analysis, path: &Path, typed: &str) -> Vec<String> {
    let sub = typed.rfind('/').map_or("", |at| &typed[..=at]);
    let mut folders: Vec<std::path::PathBuf> = path.parent().into_iter().map(Path::to_path_buf).collect();
    if let Some(include) = analysis.checked.as_ref().and_then(|c| c.workspace.include.as_ref()) {
        folders.extend(include.include_paths.iter().cloned());
    }
    let mut names = BTreeSet::new();
    // Only folders kiln may read includes from: completion must not list `/etc`.
    let may_read = |folder: &Path| analysis.checked.as_ref().is_some_and(|c| c.includes.may_read(folder));
    for folder in folders.into_iter().map(|folder| folder.join(sub)).filter(|folder| may_read(folder)) {
        let Ok(entries) = std::fs::read_dir(&folder) else { continue };
        for entry in entries.flatten() {
            let name = entry.file_name().to_string_lossy().into_owned();
            let is_dir = entry.file_type().is_ok_and(|t| t.is_dir());
            let included =
                [".wgsl", ".hlsl", ".hlsli", ".cginc", ".inc", ".h"].iter().any(|e| name.ends_with(e));
            if is_dir || included {
                names.insert(format!("{sub}{name}{}", if is_dir { "/" } else { "" }));
            }
        }
    }
    names.extend(crate::shaderlib::FILES.iter().map(|(name, _)| name.to_string()));
    names.into_iter().collect()
}

/// The outline of a file: a shader's structure, or a WGSL or HLSL file's functions and structs.
#[allow(deprecated)] // `DocumentSymbol::deprecated` must be written, though the protocol deprecates it.
pub(super) fn symbols(analysis: &Analysis, file: FileId) -> Vec<lsp::DocumentSymbol> {
    let text = analysis.store.text(file);
    let symbol = |name: String, kind, range: std::ops::Range<usize>, children: Vec<lsp::DocumentSymbol>| {
        let range = range_of(text, range);
        lsp::DocumentSymbol {
            name,
            detail: None,
            kind,
            tags: None,
            deprecated: None,
            range,
            selection_range: lsp::Range::new(range.start, range.start),
            children: (!children.is_empty()).then_some(children),
        }
    };
    let shader = analysis.checked.as_ref().and_then(|c| c.catalog.shaders.iter().find(|s| s.file == file));
    let Some(shader) = shader else {
        return declarations(analysis.store.name(file), text)
            .into_iter()
            .filter_map(|(declared, _, range)| {
                let kind = match declared {
                    Declared::Function => lsp::SymbolKind::FUNCTION,
                    Declared::Type => lsp::SymbolKind::STRUCT,
                    Declared::Value => return None,
                };
                Some(symbol(text[range.clone()].to_string(), kind, range, Vec::new()))
            })
            .collect();
    };
    let ast = &shader.shader;
    let properties: Vec<lsp::DocumentSymbol> = ast
        .properties
        .iter()
        .map(|p| symbol(p.name.value.clone(), lsp::SymbolKind::PROPERTY, p.span.range(), Vec::new()))
        .collect();
    let mut children = Vec::new();
    if let (Some(first), Some(last)) = (ast.properties.first(), ast.properties.last()) {
        let range = first.span.start as usize..last.span.end as usize;
        children.push(symbol("Properties".into(), lsp::SymbolKind::NAMESPACE, range, properties));
    }
    for (s, subshader) in ast.subshaders.iter().enumerate() {
        let passes = shader
            .passes
            .iter()
            .filter(|p| p.subshader == s)
            .filter_map(|p| {
                let span = shader.pass_ast(p)?.span;
                let name = p.name.clone().unwrap_or_else(|| format!("Pass {}", p.index));
                Some(symbol(name, lsp::SymbolKind::CLASS, span.range(), Vec::new()))
            })
            .collect();
        children.push(symbol(
            format!("SubShader {s}"),
            lsp::SymbolKind::MODULE,
            subshader.span.range(),
            passes,
        ));
    }
    vec![symbol(format!("Shader \"{}\"", ast.name.value), lsp::SymbolKind::FILE, 0..text.len(), children)]
}
