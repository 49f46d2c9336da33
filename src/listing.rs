//! The `kiln list` report: what each shader's passes declare, as data with its own serde schema,
//! rendered as text here and as JSON by serde.

use crate::diagnostics::{self, Diagnostic};
use crate::preprocess::{Includes, load_pass};
use crate::shaderlab::ast::{PassItem, ProgramBlock, ProgramLanguage, Shader, StateBlock, SubShader};
use crate::shaderlab::parse_shader;
use crate::shaderlab::pragma::{KeywordScope, KeywordSet, PragmaSource, ProgramPragmas, collect_pragmas};
use crate::source::{FileId, SourceStore};
use serde::Serialize;
use std::fmt::Write as _;

/// The listing of every shader that parsed.
#[derive(Debug, Serialize)]
pub struct Listing {
    pub shaders: Vec<ShaderListing>,
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

/// Parses the files and lists what they declare. WGSL programs are loaded with their includes,
/// whose `#include_with_pragmas` pragmas count. Diagnostics come back in file order.
pub fn list_shaders(
    store: &mut SourceStore,
    includes: &mut Includes,
    files: &[FileId],
) -> (Listing, Vec<Diagnostic>) {
    let mut shaders = Vec::new();
    let mut diagnostics = Vec::new();
    for &file in files {
        let parsed = parse_shader(store, file);
        diagnostics.extend(parsed.diagnostics);
        if let Some(shader) = parsed.shader {
            let mut lister =
                Lister { store: &mut *store, includes: &mut *includes, diagnostics: &mut diagnostics };
            shaders.push(lister.shader(file, &shader));
        }
    }
    // Include blocks and files are shared by passes: report each of their problems once.
    diagnostics::dedup(&mut diagnostics);
    (Listing { shaders }, diagnostics)
}

struct Lister<'a> {
    store: &'a mut SourceStore,
    includes: &'a mut Includes,
    diagnostics: &'a mut Vec<Diagnostic>,
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
            let _ = writeln!(out, "    possible variants: {count}");
        }
    }
    out
}
