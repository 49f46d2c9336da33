//! The `kiln list` report: what each shader's passes declare, as data with its own serde schema,
//! rendered as text here and as JSON by serde.

use crate::diagnostics::{self, Diagnostic};
use crate::keywords::PassKeywords;
use crate::material::{Material, MaterialValue, Preset, ShaderEntry, enum_names, load_material};
use crate::preprocess::{Includes, load_pass};
use crate::shaderlab::ast::{PassItem, ProgramBlock, ProgramLanguage, Shader, StateBlock, SubShader};
use crate::shaderlab::parse_shader;
use crate::shaderlab::pragma::{KeywordScope, KeywordSet, PragmaSource, ProgramPragmas, collect_pragmas};
use crate::source::{FileId, SourceStore};
use serde::Serialize;
use std::fmt::Write as _;

/// The listing of every shader that parsed, and of every material that resolved.
#[derive(Debug, Serialize)]
pub struct Listing {
    pub shaders: Vec<ShaderListing>,
    pub materials: Vec<MaterialListing>,
}

/// What `kiln list` looks at.
#[derive(Debug, Clone, Default)]
pub struct ListInput {
    pub shaders: Vec<FileId>,
    pub materials: Vec<FileId>,
    /// Shaders built whole, whatever the materials (by name).
    pub always_include: Vec<String>,
}

#[derive(Debug, Serialize)]
pub struct ShaderListing {
    pub name: String,
    pub file: String,
    pub passes: Vec<PassListing>,
}

#[derive(Debug, Serialize)]
pub struct PassListing {
    pub subshader: usize,
    pub pass: usize,
    /// `pass`, `use_pass`, `grab_pass`, or `surface_program` (a CGPROGRAM in a SubShader).
    pub kind: &'static str,
    pub name: Option<String>,
    pub tags: Vec<(String, String)>,
    pub program: Option<ProgramListing>,
}

#[derive(Debug, Serialize)]
pub struct ProgramListing {
    pub language: &'static str,
    pub vertex: Option<String>,
    pub fragment: Option<String>,
    pub target: Option<String>,
    pub keyword_sets: Vec<KeywordSetListing>,
    /// The product of the variant-making sets' sizes; `null` when it exceeds 2^128.
    pub possible_variants: Option<u128>,
    /// The variants materials need (all of them for an always-included shader), in key order.
    pub used_variants: Vec<VariantListing>,
}

#[derive(Debug, Serialize)]
pub struct VariantListing {
    /// The variant key: the pass's keyword bits in hexadecimal.
    pub key: String,
    pub keywords: Vec<String>,
    /// The keywords each stage is compiled with (stage-specific keywords only in their stage).
    pub vertex_keywords: Vec<String>,
    pub fragment_keywords: Vec<String>,
    pub materials: Vec<String>,
}

#[derive(Debug, Serialize)]
pub struct MaterialListing {
    pub name: String,
    pub file: String,
    pub shader: String,
    pub preset: Option<&'static str>,
    pub render_queue: i64,
    pub keywords: Vec<String>,
    /// The values of the properties the shader's render state refers to (`[_SrcBlend]`), by name
    /// where a drawer names them.
    pub render_state: Vec<(String, String)>,
}

#[derive(Debug, Serialize)]
pub struct KeywordSetListing {
    pub kind: &'static str,
    pub scope: &'static str,
    pub stage: &'static str,
    /// `_` stands for the all-off choice.
    pub keywords: Vec<String>,
    pub shorthand: Option<&'static str>,
}

/// Parses the shaders, resolves the materials against them and lists what each pass declares and
/// which variants the materials use. WGSL programs are loaded with their includes, whose
/// `#include_with_pragmas` pragmas count. Diagnostics come back in file order.
pub fn list_shaders(
    store: &mut SourceStore,
    includes: &mut Includes,
    input: &ListInput,
) -> (Listing, Vec<Diagnostic>) {
    let mut diagnostics = Vec::new();
    let mut parsed_shaders: Vec<(FileId, Shader)> = Vec::new();
    let mut listings = Vec::new();
    let mut pass_sets: Vec<Vec<Vec<KeywordSet>>> = Vec::new();
    for &file in &input.shaders {
        let parsed = parse_shader(store, file);
        diagnostics.extend(parsed.diagnostics);
        if let Some(shader) = parsed.shader {
            let mut lister = Lister {
                store: &mut *store,
                includes: &mut *includes,
                diagnostics: &mut diagnostics,
                sets: Vec::new(),
            };
            listings.push(lister.shader(file, &shader));
            pass_sets.push(lister.sets);
            parsed_shaders.push((file, shader));
        }
    }

    let entries: Vec<ShaderEntry> = parsed_shaders
        .iter()
        .zip(&pass_sets)
        .map(|((_, shader), sets)| ShaderEntry {
            shader,
            keyword_sets: sets.iter().flatten().cloned().collect(),
        })
        .collect();
    let mut materials = Vec::new();
    for &file in &input.materials {
        let (material, found) = load_material(store, file, &entries);
        diagnostics.extend(found);
        materials.extend(material);
    }

    for (s, listing) in listings.iter_mut().enumerate() {
        let everything = input.always_include.contains(&listing.name);
        let users: Vec<&Material> = materials.iter().filter(|m| m.shader == s).collect();
        let keywords: Vec<Vec<&str>> =
            users.iter().map(|m| m.keywords.iter().map(|(k, _)| k.as_str()).collect()).collect();
        let programs = listing.passes.iter_mut().filter_map(|p| p.program.as_mut());
        for (program, sets) in programs.zip(&pass_sets[s]) {
            let pass = PassKeywords::new(sets.clone());
            let names = |bits| pass.keywords(bits).map(str::to_string).collect();
            program.used_variants = pass
                .enumerate(&keywords, everything)
                .iter()
                .map(|v| VariantListing {
                    key: v.bits.key(),
                    keywords: names(&v.bits),
                    vertex_keywords: names(&v.vertex),
                    fragment_keywords: names(&v.fragment),
                    materials: v.materials.iter().map(|&m| users[m].name.clone()).collect(),
                })
                .collect();
        }
    }
    let materials = materials.iter().map(|m| material_listing(store, &entries[m.shader], m)).collect();
    // Include blocks and files are shared by passes: report each of their problems once.
    diagnostics::dedup(&mut diagnostics);
    (Listing { shaders: listings, materials }, diagnostics)
}

fn material_listing(store: &SourceStore, entry: &ShaderEntry, material: &Material) -> MaterialListing {
    let shader = entry.shader;
    let mut referenced: Vec<String> = Vec::new();
    for (_, _, _, pass) in shader.passes() {
        for command in
            shader.subshaders.iter().flat_map(|s| &s.state.render_state).chain(&pass.state.render_state)
        {
            for (_, name) in bracketed(store.slice(command.span)) {
                if !referenced.iter().any(|r| r == name) {
                    referenced.push(name.to_string());
                }
            }
        }
    }
    let render_state = referenced
        .into_iter()
        .filter_map(|name| {
            let shown = match material.values.get(&name)? {
                MaterialValue::Number(n) => {
                    let named = shader
                        .property(&name)
                        .and_then(enum_names)
                        .and_then(|names| names.into_iter().find(|(_, v)| v == n).map(|(label, _)| label));
                    named.unwrap_or_else(|| n.to_string())
                }
                other => format!("{other:?}"),
            };
            Some((name, shown))
        })
        .collect();
    MaterialListing {
        name: material.name.clone(),
        file: store.name(material.file).to_string(),
        shader: shader.name.value.clone(),
        preset: material.preset.map(Preset::name),
        render_queue: material.render_queue,
        keywords: material.keywords.iter().map(|(k, _)| k.clone()).collect(),
        render_state,
    }
}

/// `[_Name]` references in a render command's text.
fn bracketed(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.match_indices('[').filter_map(move |(i, _)| {
        let rest = &text[i + 1..];
        let end = rest.find(']')?;
        let name = rest[..end].trim();
        (!name.is_empty() && name.chars().all(|c| c.is_alphanumeric() || c == '_')).then_some((i, name))
    })
}

struct Lister<'a> {
    store: &'a mut SourceStore,
    includes: &'a mut Includes,
    diagnostics: &'a mut Vec<Diagnostic>,
    /// The variant sets of each program listed, in listing order.
    sets: Vec<Vec<KeywordSet>>,
}

impl Lister<'_> {
    fn shader(&mut self, file: FileId, shader: &Shader) -> ShaderListing {
        let mut passes = Vec::new();
        for (si, sub) in shader.subshaders.iter().enumerate() {
            // Surface programs come first, as Unity generates their passes ahead of explicit ones.
            let surface_programs = sub.programs.iter().filter(|p| !p.is_include);
            for (index, program) in surface_programs.clone().enumerate() {
                let listing = self.program(shader, sub, std::slice::from_ref(program));
                passes.push(PassListing {
                    subshader: si,
                    pass: index,
                    kind: "surface_program",
                    name: None,
                    tags: tags(&sub.state),
                    program: Some(listing),
                });
            }
            let first_pass = surface_programs.count();
            for (pi, item) in sub.passes.iter().enumerate() {
                let (kind, name, tags, program) = match item {
                    PassItem::Pass(pass) => {
                        let program =
                            (!pass.programs.is_empty()).then(|| self.program(shader, sub, &pass.programs));
                        (
                            "pass",
                            pass.state.name.as_ref().map(|n| n.value.clone()),
                            tags(&pass.state),
                            program,
                        )
                    }
                    PassItem::UsePass(name) => ("use_pass", Some(name.value.clone()), Vec::new(), None),
                    PassItem::GrabPass(grab) => (
                        "grab_pass",
                        grab.name.as_ref().or(grab.texture.as_ref()).map(|n| n.value.clone()),
                        grab.tags.iter().map(|t| (t.key.value.clone(), t.value.value.clone())).collect(),
                        None,
                    ),
                };
                passes.push(PassListing { subshader: si, pass: first_pass + pi, kind, name, tags, program });
            }
        }
        ShaderListing { name: shader.name.value.clone(), file: self.store.name(file).to_string(), passes }
    }

    fn program(&mut self, shader: &Shader, sub: &SubShader, programs: &[ProgramBlock]) -> ProgramListing {
        let blocks = program_blocks(shader, sub, programs);
        let language = programs.first().map_or(ProgramLanguage::Wgsl, |p| p.language);
        let pragmas = if language == ProgramLanguage::Wgsl {
            let (pass, diagnostics) = load_pass(self.includes, self.store, &blocks);
            self.diagnostics.extend(diagnostics);
            pass.pragmas
        } else {
            let (pragmas, errors) = collect_pragmas(blocks.into_iter().map(PragmaSource::from));
            self.diagnostics.extend(errors);
            pragmas
        };
        self.sets.push(pragmas.variant_sets());
        program_from_pragmas(language.name(), &pragmas)
    }
}

fn tags(state: &StateBlock) -> Vec<(String, String)> {
    state.tags.iter().map(|t| (t.key.value.clone(), t.value.value.clone())).collect()
}

/// The include blocks a program sees (shader-level, then SubShader-level, of its language),
/// followed by the program itself.
pub fn program_blocks<'a>(
    shader: &'a Shader,
    sub: &'a SubShader,
    programs: &'a [ProgramBlock],
) -> Vec<&'a ProgramBlock> {
    let language = programs.first().map_or(ProgramLanguage::Wgsl, |p| p.language);
    shader
        .includes
        .iter()
        .chain(sub.programs.iter().filter(|p| p.is_include))
        .filter(|p| p.language == language)
        .chain(programs)
        .collect()
}

fn program_from_pragmas(language: &'static str, pragmas: &ProgramPragmas) -> ProgramListing {
    ProgramListing {
        language,
        vertex: pragmas.vertex.as_ref().map(|v| v.value.clone()),
        fragment: pragmas.fragment.as_ref().map(|v| v.value.clone()),
        target: pragmas.target().map(str::to_string),
        keyword_sets: pragmas.keyword_sets.iter().map(set_listing).collect(),
        possible_variants: pragmas.possible_variants(),
        used_variants: Vec::new(),
    }
}

fn set_listing(set: &KeywordSet) -> KeywordSetListing {
    KeywordSetListing {
        kind: set.kind.name(),
        scope: match set.scope {
            KeywordScope::Global => "global",
            KeywordScope::Local => "local",
        },
        stage: set.stage.name(),
        keywords: set.options.iter().map(|o| o.keyword.clone().unwrap_or_else(|| "_".into())).collect(),
        shorthand: set.shorthand,
    }
}

/// Renders the listing for people.
pub fn render_text(listing: &Listing) -> String {
    let mut out = String::new();
    for shader in &listing.shaders {
        let _ = writeln!(out, "{} ({})", shader.name, shader.file);
        for pass in &shader.passes {
            let name = pass.name.as_deref().map(|n| format!(" \"{n}\"")).unwrap_or_default();
            let label = match pass.kind {
                "pass" => "pass",
                "use_pass" => "use pass",
                "grab_pass" => "grab pass",
                _ => "surface program",
            };
            let tags: Vec<String> = pass.tags.iter().map(|(k, v)| format!("{k}={v}")).collect();
            let tags = if tags.is_empty() { String::new() } else { format!("  [{}]", tags.join(" ")) };
            let _ = writeln!(out, "  {label} {}.{}{name}{tags}", pass.subshader, pass.pass);
            let Some(program) = &pass.program else { continue };
            let mut facts = vec![program.language.to_uppercase()];
            facts.extend(program.vertex.as_ref().map(|v| format!("vertex {v}")));
            facts.extend(program.fragment.as_ref().map(|f| format!("fragment {f}")));
            facts.extend(program.target.as_ref().map(|t| format!("target {t}")));
            let _ = writeln!(out, "    program: {}", facts.join(", "));
            for set in &program.keyword_sets {
                let via = set.shorthand.map(|s| format!("  (from {s})")).unwrap_or_default();
                let _ = writeln!(
                    out,
                    "    {:<14} {:<6} {:<8} {}{via}",
                    set.kind,
                    set.scope,
                    set.stage,
                    set.keywords.join(" ")
                );
            }
            let count = program.possible_variants.map_or("more than 2^128".to_string(), |n| n.to_string());
            let _ = writeln!(out, "    variants: used {} of {count} possible", program.used_variants.len());
            for variant in &program.used_variants {
                let keywords = if variant.keywords.is_empty() {
                    "(no keywords)".to_string()
                } else {
                    variant.keywords.join(" ")
                };
                let users = if variant.materials.is_empty() {
                    "(always included)".to_string()
                } else {
                    variant.materials.join(", ")
                };
                let _ = writeln!(out, "      {keywords:<40} {users}");
            }
        }
    }
    out
}

/// Renders each material's shader, preset, queue, keywords and render-state values.
pub fn render_materials(listing: &Listing) -> String {
    let mut out = String::new();
    for m in &listing.materials {
        let preset = m.preset.map(|p| format!(", preset {p}")).unwrap_or_default();
        let _ = writeln!(out, "{} ({}): {}{preset}, queue {}", m.name, m.file, m.shader, m.render_queue);
        let keywords = if m.keywords.is_empty() { "(none)".to_string() } else { m.keywords.join(" ") };
        let _ = writeln!(out, "  keywords: {keywords}");
        if !m.render_state.is_empty() {
            let state: Vec<String> = m.render_state.iter().map(|(k, v)| format!("{k} = {v}")).collect();
            let _ = writeln!(out, "  render state: {}", state.join(", "));
        }
    }
    out
}
