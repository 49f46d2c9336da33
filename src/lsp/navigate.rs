//! What is at a place in a file (an include, a keyword, a macro, a property, a uniform member, a
//! WGSL or HLSL declaration), and from it hover text and go-to-definition.

use super::analysis::Analysis;
use super::text::{Language, declarations, word_at};
use super::variants::{Selections, expansion_at};
use crate::manifest::{Member, UniformBlock};
use crate::preprocess::MacroDefinition;
use crate::shaderlab::pragma::KeywordSet;
use crate::source::{FileId, Span};
use std::fmt::Write as _;

/// What the word at a place names.
pub(super) enum Found<'a> {
    /// An `#include`, with the file it resolves to.
    Include { name: &'a str, target: Option<FileId> },
    /// A keyword some pass declares (its first declaration).
    Keyword { name: &'a str, set: &'a KeywordSet },
    /// A macro, by its `#define`.
    Macro(MacroDefinition<'a>),
    /// A property of a shader (`shader`, `property`: catalogue positions).
    Property { shader: usize, property: usize },
    /// A member of a uniform block a built pass reflects.
    Member { block: &'a UniformBlock, member: &'a Member },
    /// Any other name: a WGSL or HLSL declaration, looked up by name.
    Name(&'a str),
}

/// What is at byte `offset` of `file`.
pub(super) fn find(analysis: &Analysis, file: FileId, offset: usize) -> Option<Found<'_>> {
    let checked = analysis.checked.as_ref()?;
    if let Some((_, name, target)) = checked.includes.include_at(file, offset) {
        return Some(Found::Include { name, target });
    }
    let text = analysis.store.text(file);
    let (word, _) = word_at(text, offset)?;
    let is_material = analysis.store.name(file).ends_with(".mat");
    let material_shader = checked.catalog.materials.iter().find(|m| m.file == file).map(|m| m.shader);
    // In a `.mat` file, a name is first its own shader's.
    if let Some(shader) = material_shader {
        if let Some(property) = property_of(analysis, shader, word) {
            return Some(Found::Property { shader, property });
        }
    }
    if let Some(set) = declaring_set(analysis, word) {
        return Some(Found::Keyword { name: set.keywords().find(|k| *k == word)?, set });
    }
    if is_material {
        return None;
    }
    let defines: Vec<_> = checked.includes.defines().filter(|define| define.name == word).collect();
    if let Some(&define) = defines.iter().find(|define| define.span.file == file).or(defines.first()) {
        return Some(Found::Macro(define));
    }
    if analysis.store.name(file).ends_with(".shader") {
        let shader = checked.catalog.shaders.iter().position(|s| s.file == file);
        if let Some((shader, property)) = shader.and_then(|s| Some((s, property_of(analysis, s, word)?))) {
            return Some(Found::Property { shader, property });
        }
    }
    if let Some((block, member)) = uniform_member(analysis, word) {
        return Some(Found::Member { block, member });
    }
    Some(Found::Name(word))
}

fn property_of(analysis: &Analysis, shader: usize, name: &str) -> Option<usize> {
    let shader = analysis.checked.as_ref()?.catalog.shaders.get(shader)?;
    shader.shader.properties.iter().position(|p| p.name.value == name)
}

/// The first keyword set (of any pass, in catalogue order) that declares `name`.
fn declaring_set<'a>(analysis: &'a Analysis, name: &str) -> Option<&'a KeywordSet> {
    analysis.passes().find_map(|(_, _, _, program)| {
        program.pragmas.keyword_sets.iter().find(|set| set.keywords().any(|k| k == name))
    })
}

fn uniform_member<'a>(analysis: &'a Analysis, name: &str) -> Option<(&'a UniformBlock, &'a Member)> {
    let manifest = analysis.checked.as_ref()?.manifest.as_ref()?;
    manifest
        .passes()
        .flat_map(|pass| &pass.uniform_blocks)
        .find_map(|block| Some((block, block.members.iter().find(|m| m.name == name)?)))
}

/// Markdown for a hover on `found` at `at` (file and byte offset): a macro's expansion there is
/// the active variant's (`selections`).
pub(super) fn hover(
    analysis: &Analysis,
    selections: &Selections,
    found: &Found,
    at: Option<(FileId, usize)>,
) -> Option<String> {
    let store = &analysis.store;
    let checked = analysis.checked.as_ref()?;
    let place = |span: Span| {
        let at = store.line_col(span.file, span.start as usize);
        let name = store.name(span.file).rsplit('/').next().unwrap_or_default().to_string();
        format!("{name}:{}:{}", at.line, at.column)
    };
    let mut out = String::new();
    match found {
        Found::Include { name, target } => {
            let _ = match target.map(|file| (file, analysis.path(file))) {
                Some((file, _)) if store.path(file).is_none() => {
                    write!(out, "`#include \"{name}\"`: the bundled shader library's `{name}`")
                }
                Some((_, Some(path))) => write!(out, "`#include \"{name}\"`: `{}`", path.display()),
                _ => write!(out, "`#include \"{name}\"`: not found"),
            };
        }
        Found::Keyword { name, set } => {
            let _ = writeln!(
                out,
                "**`{name}`**: `{}` keyword ({:?}, {:?} stages)\n\n`{}` at {}",
                set.kind.name(),
                set.scope,
                set.stage,
                store.slice(set.span).trim(),
                place(set.span)
            );
            let materials: Vec<&str> = checked
                .catalog
                .materials
                .iter()
                .filter(|m| m.keywords.iter().any(|(k, _)| k == name))
                .map(|m| m.name.as_str())
                .collect();
            let _ = writeln!(
                out,
                "\nenabled by {}",
                if materials.is_empty() { "no material".to_string() } else { materials.join(", ") }
            );
            let (mut with, mut all) = (0, 0);
            for (_, _, _, program) in analysis.passes() {
                all += program.variants.len();
                if let Some(bit) = program.keywords.names().iter().position(|n| n == name) {
                    with += program.variants.iter().filter(|v| v.bits.contains(bit)).count();
                }
            }
            let _ = write!(out, "\nin {with} of the project's {all} variants");
        }
        Found::Macro(define) => {
            let _ = write!(out, "```c\n{}\n```\ndefined at {}", define.directive(), place(define.span));
            if let Some((pass, text)) =
                at.and_then(|(file, offset)| expansion_at(analysis, selections, file, offset))
            {
                let (file, offset) = at.unwrap_or((define.span.file, define.span.start as usize));
                let language = Language::at(store.name(file), store.text(file), offset).fence();
                let _ = write!(out, "\n\nexpands here, in {pass}, to:\n```{language}\n{text}\n```");
            }
        }
        Found::Property { shader, property } => {
            let shader = checked.catalog.shaders.get(*shader)?;
            let property = shader.shader.properties.get(*property)?;
            let _ = write!(out, "```\n{}\n```", store.slice(property.span).trim());
            let manifest = checked.manifest.as_ref().and_then(|m| {
                let built = m.shaders.iter().find(|s| s.name == shader.shader.name.value)?;
                built.properties.iter().find(|p| p.name == property.name.value)
            });
            if let Some(offset) = manifest.and_then(|p| p.offset) {
                let _ = write!(out, "\nmaterial uniform block: offset {offset}");
            }
            if let Some([group, binding]) = manifest.and_then(|p| p.binding) {
                let _ = write!(out, "\nbound at `@group({group}) @binding({binding})`");
            }
        }
        Found::Member { block, member } => {
            let _ = write!(
                out,
                "`{}: {}` in `{}` (`{}`): offset {}, size {}, alignment {}",
                member.name,
                member.ty,
                block.name,
                block.type_name,
                member.offset,
                member.size,
                member.alignment
            );
            if let Some(stride) = member.array_stride {
                let _ = write!(out, ", array stride {stride}");
            }
        }
        Found::Name(name) => {
            let (file, language, range) = declaration(analysis, name, None)?;
            let text = store.text(file);
            let line_start = text[..range.start].rfind('\n').map_or(0, |at| at + 1);
            let line_end = text[range.start..].find('\n').map_or(text.len(), |at| range.start + at);
            let _ = write!(
                out,
                "```{}\n{}\n```\n{}",
                language.fence(),
                text[line_start..line_end].trim(),
                place(Span::new(file, range))
            );
        }
    }
    Some(out)
}

/// Where `found` is defined.
pub(super) fn definition(analysis: &Analysis, found: &Found, from: FileId) -> Option<Span> {
    let checked = analysis.checked.as_ref()?;
    match found {
        Found::Include { target, .. } => target.map(|file| Span::new(file, 0..0)),
        Found::Keyword { name, set } => {
            let text = analysis.store.slice(set.span);
            let at = text.find(name).map_or(0, |at| at);
            Some(Span::new(
                set.span.file,
                set.span.start as usize + at..set.span.start as usize + at + name.len(),
            ))
        }
        Found::Macro(define) => Some(define.span),
        Found::Property { shader, property } => {
            Some(checked.catalog.shaders.get(*shader)?.shader.properties.get(*property)?.name.span)
        }
        // HLSL's constant-buffer members are declared as globals are.
        Found::Member { member, .. } => declaration_in_structs(analysis, &member.name).or_else(|| {
            declaration(analysis, &member.name, None).map(|(file, _, range)| Span::new(file, range))
        }),
        Found::Name(name) => {
            declaration(analysis, name, Some(from)).map(|(file, _, range)| Span::new(file, range))
        }
    }
}

/// The module-scope declaration of `name`: in `first` if it has one, else in the project's other
/// files and includes; with the language it is written in.
fn declaration(
    analysis: &Analysis,
    name: &str,
    first: Option<FileId>,
) -> Option<(FileId, Language, std::ops::Range<usize>)> {
    let checked = analysis.checked.as_ref()?;
    let mut files = checked.includes.files();
    if let Some(first) = first {
        files.retain(|&f| f != first);
        files.insert(0, first);
    }
    files.into_iter().find_map(|file| {
        let text = analysis.store.text(file);
        declarations(analysis.store.name(file), text)
            .into_iter()
            .find(|(_, _, range)| &text[range.clone()] == name)
            .map(|(_, language, range)| (file, language, range))
    })
}

/// A struct member's declaration (`name:` inside a `struct`), in the files the programs read.
fn declaration_in_structs(analysis: &Analysis, name: &str) -> Option<Span> {
    let checked = analysis.checked.as_ref()?;
    checked.includes.files().into_iter().find_map(|file| {
        let text = analysis.store.text(file);
        let mut from = 0;
        while let Some(at) = text[from..].find(name).map(|at| from + at) {
            from = at + name.len();
            let before_ok = !text[..at].ends_with(|c: char| c.is_ascii_alphanumeric() || c == '_');
            if before_ok && text[from..].trim_start().starts_with(':') {
                return Some(Span::new(file, at..from));
            }
        }
        None
    })
}
