//! The `kiln list` report: what each shader's passes declare, as data with its own serde schema,
//! rendered as text here and as JSON by serde.

use crate::catalog::{Catalog, CatalogInput, CatalogPass, catalog};
use crate::diagnostics::Diagnostic;
use crate::material::{Material, MaterialValue, Preset, enum_name};
use crate::preprocess::Includes;
use crate::shaderlab::ast::Shader;
use crate::shaderlab::pragma::{KeywordScope, KeywordSet, ProgramPragmas};
use crate::source::SourceStore;
use serde::Serialize;

pub use crate::catalog::program_blocks;
use std::fmt::Write as _;

/// The listing of every shader that parsed, and of every material that resolved.
#[derive(Debug, Serialize)]
pub struct Listing {
    /// Each shader, in the order found.
    pub shaders: Vec<ShaderListing>,
    /// Each material, resolved.
    pub materials: Vec<MaterialListing>,
}

/// One shader in `kiln list`.
#[derive(Debug, Serialize)]
pub struct ShaderListing {
    /// Its name (`Shader "name"`).
    pub name: String,
    /// Its file, relative.
    pub file: String,
    /// Its passes.
    pub passes: Vec<PassListing>,
}

/// One pass in `kiln list`.
#[derive(Debug, Serialize)]
pub struct PassListing {
    /// Its SubShader's index.
    pub subshader: usize,
    /// Its index in the SubShader.
    pub pass: usize,
    /// `pass`, `use_pass`, `grab_pass`, or `surface_program` (a CGPROGRAM in a SubShader).
    pub kind: &'static str,
    /// Its `Name`, if any.
    pub name: Option<String>,
    /// Its tags, in order.
    pub tags: Vec<(String, String)>,
    /// Its program, if it has one.
    pub program: Option<ProgramListing>,
}

/// A pass's program in `kiln list`.
#[derive(Debug, Serialize)]
pub struct ProgramListing {
    /// `WGSL`, `HLSL`, `CG` or `GLSL`.
    pub language: &'static str,
    /// The vertex entry point.
    pub vertex: Option<String>,
    /// The fragment entry point.
    pub fragment: Option<String>,
    /// A compute shader's kernels.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub kernels: Vec<String>,
    /// `#pragma target`, if given.
    pub target: Option<String>,
    /// Its keyword sets.
    pub keyword_sets: Vec<KeywordSetListing>,
    /// The product of the variant-making sets' sizes; `null` when it exceeds 2^128.
    pub possible_variants: Option<u128>,
    /// The product of the `dynamic_branch` sets' sizes: the keyword combinations each variant's
    /// one module serves (absent without such sets; `null` past 2^128).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dynamic_combinations: Option<Option<u128>>,
    /// The variants materials need (all of them for an always-included shader), in key order.
    pub used_variants: Vec<VariantListing>,
    /// The multi_compile sets `global_keywords` in kiln.toml narrows to one option: each set's
    /// keywords and the one built.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub fixed_by_global_keywords: Vec<FixedSet>,
}

/// A multi_compile set the global keyword state narrows to one option.
#[derive(Debug, Serialize)]
pub struct FixedSet {
    /// The set's keywords (`_` for none).
    pub keywords: Vec<String>,
    /// The one built.
    pub built: String,
}

/// One variant materials use.
#[derive(Debug, Serialize)]
pub struct VariantListing {
    /// The variant key: the pass's keyword bits in hexadecimal.
    pub key: String,
    /// Its keywords.
    pub keywords: Vec<String>,
    /// The keywords each stage is compiled with (stage-specific keywords only in their stage).
    pub vertex_keywords: Vec<String>,
    /// The keywords its fragment stage sees.
    pub fragment_keywords: Vec<String>,
    /// The materials that use it.
    pub materials: Vec<String>,
    /// The other files that name it: usage logs, `kiln.toml` (`[compute.NAME]`). A variant no
    /// material or file names is built because the project always includes its shader.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub listed_in: Vec<String>,
}

/// One material in `kiln list --materials`.
#[derive(Debug, Serialize)]
pub struct MaterialListing {
    /// Its name (the file name without extension).
    pub name: String,
    /// Its file, relative.
    pub file: String,
    /// Its shader's name.
    pub shader: String,
    /// Its preset, if any.
    pub preset: Option<&'static str>,
    /// Its render queue.
    pub render_queue: i64,
    /// Its enabled keywords.
    pub keywords: Vec<String>,
    /// The values of the properties the shader's render state refers to (`[_SrcBlend]`), by name
    /// where a drawer names them.
    pub render_state: Vec<(String, String)>,
}

/// One keyword set in `kiln list`.
#[derive(Debug, Serialize)]
pub struct KeywordSetListing {
    /// `multi_compile`, `shader_feature` or `dynamic_branch`.
    pub kind: &'static str,
    /// `global` or `local`.
    pub scope: &'static str,
    /// `all`, `vertex` or `fragment`.
    pub stage: &'static str,
    /// `_` stands for the all-off choice.
    pub keywords: Vec<String>,
    /// The shorthand pragma it came from, if any.
    pub shorthand: Option<&'static str>,
}

/// Parses the shaders, resolves the materials against them and lists what each pass declares and
/// which variants the materials use (see [`catalog`]).
pub fn list_shaders(
    store: &mut SourceStore,
    includes: &mut Includes,
    input: &CatalogInput,
) -> (Listing, Vec<Diagnostic>) {
    let (catalog, diagnostics) = catalog(store, includes, input);
    let global: Option<Vec<&str>> =
        input.global_keywords.as_ref().map(|g| g.iter().map(|k| k.value.as_str()).collect());
    (listing(store, &catalog, global.as_deref()), diagnostics)
}

/// The listing of a catalogue built under the global keyword state `global` (when the project
/// sets one).
pub fn listing(store: &SourceStore, catalog: &Catalog, global: Option<&[&str]>) -> Listing {
    let shaders = catalog
        .shaders
        .iter()
        .map(|s| ShaderListing {
            name: s.shader.name.value.clone(),
            file: store.name(s.file).to_string(),
            passes: s.passes.iter().map(|p| pass_listing(store, catalog, p, global)).collect(),
        })
        .collect();
    let materials = catalog
        .materials
        .iter()
        .map(|m| material_listing(store, &catalog.shaders[m.shader].shader, m))
        .collect();
    Listing { shaders, materials }
}

fn pass_listing(
    store: &SourceStore,
    catalog: &Catalog,
    pass: &CatalogPass,
    global: Option<&[&str]>,
) -> PassListing {
    PassListing {
        subshader: pass.subshader,
        pass: pass.index,
        kind: pass.kind.name(),
        name: pass.name.clone(),
        tags: pass.tags.clone(),
        program: pass.program.as_ref().map(|program| {
            let keywords = &program.keywords;
            let names = |bits| keywords.keywords(bits).map(str::to_string).collect();
            let mut listing = program_from_pragmas(program.language.name(), &program.pragmas);
            listing.used_variants = program
                .variants
                .iter()
                .map(|v| VariantListing {
                    key: v.bits.key(),
                    keywords: names(&v.bits),
                    vertex_keywords: names(&v.vertex),
                    fragment_keywords: names(&v.fragment),
                    materials: v.materials.iter().map(|&m| catalog.materials[m].name.clone()).collect(),
                    listed_in: v.listed_in.iter().map(|&f| store.name(f).to_string()).collect(),
                })
                .collect();
            let fixed = global.map(|global| keywords.fixed_by_global(global)).unwrap_or_default();
            listing.fixed_by_global_keywords =
                fixed.into_iter().map(|(keywords, built)| FixedSet { keywords, built }).collect();
            listing
        }),
    }
}

fn material_listing(store: &SourceStore, shader: &Shader, material: &Material) -> MaterialListing {
    let mut referenced: Vec<String> = Vec::new();
    for (_, _, _, pass) in shader.passes() {
        for command in
            shader.subshaders.iter().flat_map(|s| &s.state.render_state).chain(&pass.state.render_state)
        {
            for name in crate::catalog::property_references(store.slice(command.span)) {
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
                MaterialValue::Number(n) => enum_name(shader, &name, *n).unwrap_or_else(|| n.to_string()),
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

fn program_from_pragmas(language: &'static str, pragmas: &ProgramPragmas) -> ProgramListing {
    ProgramListing {
        language,
        vertex: pragmas.vertex.as_ref().map(|v| v.value.clone()),
        fragment: pragmas.fragment.as_ref().map(|v| v.value.clone()),
        kernels: pragmas.kernels.iter().map(|k| k.value.clone()).collect(),
        target: pragmas.target().map(str::to_string),
        keyword_sets: pragmas.keyword_sets.iter().map(set_listing).collect(),
        possible_variants: pragmas.possible_variants(),
        dynamic_combinations: pragmas.dynamic_combinations(),
        used_variants: Vec::new(),
        fixed_by_global_keywords: Vec::new(),
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
            if !program.kernels.is_empty() {
                facts.push(format!("kernels {}", program.kernels.join(", ")));
            }
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
            let count = crate::keywords::PassKeywords::count_text(program.possible_variants);
            if let Some(combinations) = program.dynamic_combinations {
                let as_variants =
                    combinations.zip(program.possible_variants).and_then(|(c, p)| c.checked_mul(p));
                let text = crate::keywords::PassKeywords::count_text;
                let (combinations, as_variants, saved) = match (combinations, as_variants) {
                    (Some(c), Some(v)) => (text(Some(c)), text(Some(v)), text(Some(v - v / c))),
                    _ => (text(combinations), text(None), text(None)),
                };
                let _ = writeln!(
                    out,
                    "    dynamic_branch: {combinations} keyword combinations share each variant's modules \
                     (as variant keywords: {as_variants} possible, {saved} saved)"
                );
            }
            let _ = writeln!(out, "    variants: used {} of {count} possible", program.used_variants.len());
            for set in &program.fixed_by_global_keywords {
                let _ = writeln!(
                    out,
                    "      multi_compile {} built as `{}` only: kiln.toml's global_keywords",
                    set.keywords.join(" "),
                    set.built
                );
            }
            for variant in &program.used_variants {
                let keywords = if variant.keywords.is_empty() {
                    "(no keywords)".to_string()
                } else {
                    variant.keywords.join(" ")
                };
                let listed = variant.listed_in.iter().map(|file| format!("(listed in {file})"));
                let users: Vec<String> = variant.materials.iter().cloned().chain(listed).collect();
                let users = if users.is_empty() { "(always included)".to_string() } else { users.join(", ") };
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
    if !listing.materials.is_empty() {
        let _ = writeln!(out, "draw one on a sphere: kiln preview MATERIAL (docs/preview.md)");
    }
    out
}
