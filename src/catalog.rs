//! What a project declares, gathered once for every job (`list`, `check`, `build`): shaders with
//! their passes and programs (WGSL ones loaded with their includes), materials resolved against
//! them, and each pass's keywords and used variants.
//!
//! Long because it is one walk over the project whose steps share the catalogue's types: shaders
//! parsed, their programs loaded (one after another: loading adds to the store) and finished in
//! parallel, materials resolved, global keywords checked, variants enumerated and listed ones
//! added.

use crate::diagnostics::{self, Diagnostic};
use crate::keywords::{KeywordBits, MAX_VARIANTS_PER_PASS, PassKeywords, Variant};
use crate::material::{Material, ShaderEntries, ShaderEntry, load_material};
use crate::preprocess::{Includes, Program, ScannedBlock, finish_pass};
use crate::shaderlab::ast::{PassItem, ProgramBlock, ProgramLanguage, Shader, StateBlock, SubShader};
use crate::shaderlab::parse_shader;
use crate::shaderlab::pragma::{
    KeywordKind, KeywordScope, KeywordSet, PragmaSource, ProgramPragmas, collect_pragmas,
};
use crate::source::{FileId, SourceStore, Span, Spanned};
use rayon::prelude::*;
use std::collections::{HashMap, HashSet};

/// More keywords than this in one pass is refused (each is a bit of every variant key, and no
/// real pass comes close).
pub const MAX_KEYWORDS_PER_PASS: usize = 256;

/// More distinct global keywords than this in one project is refused. Global keywords share one
/// name space the renderer sets at run time (a bit each in its global keyword state); local
/// (`_local`) keywords are per shader and count only against [`MAX_KEYWORDS_PER_PASS`].
pub const MAX_GLOBAL_KEYWORDS_PER_PROJECT: usize = 4096;

/// The files a job looks at.
#[derive(Debug, Clone, Default)]
pub struct CatalogInput {
    /// The shader files.
    pub shaders: Vec<FileId>,
    /// The material files.
    pub materials: Vec<FileId>,
    /// Shaders built whole, whatever the materials (by name).
    pub always_include: Vec<String>,
    /// The renderer's global keyword state, where the project knows it (`kiln.toml`'s
    /// `global_keywords`): multi_compile sets are built only with the option it chooses.
    pub global_keywords: Option<Vec<Spanned<String>>>,
    /// Variant usage logs (JSON Lines): each variant they name is built too.
    pub variant_logs: Vec<FileId>,
    /// Variants listed by name (`kiln.toml`'s `[compute.NAME] variants`), built too.
    pub listed_variants: Vec<ListedVariant>,
}

/// A variant a project file names: a shader, a pass, its keywords, and where it is written.
#[derive(Debug, Clone, PartialEq)]
pub struct ListedVariant {
    /// The shader's name.
    pub shader: String,
    /// The pass's index.
    pub pass: usize,
    /// The keywords that choose the variant (`dynamic_branch` ones among them choose nothing).
    pub keywords: Vec<String>,
    /// Where it is written, for diagnostics.
    pub span: Span,
    /// A pipeline trace's line (it has a `version`): one the project no longer has is skipped
    /// with a warning (K0534), as a run time's warm-up skips it, not an error.
    pub from_trace: bool,
}

/// The analysis every job shares (see the module's comment).
pub struct Catalog {
    /// Every shader parsed, in the order given.
    pub shaders: Vec<CatalogShader>,
    /// Every material resolved.
    pub materials: Vec<Material>,
}

/// A parsed shader and its passes.
pub struct CatalogShader {
    /// Its file.
    pub file: FileId,
    /// Its AST.
    pub shader: Shader,
    /// Its passes, in order.
    pub passes: Vec<CatalogPass>,
}

/// How a pass entry of a SubShader is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PassKind {
    /// `Pass { }`.
    Pass,
    /// `UsePass "Shader/PASS"`.
    UsePass,
    /// `GrabPass { }`.
    GrabPass,
    /// A program directly in a SubShader (Unity's surface shaders).
    SurfaceProgram,
}

impl PassKind {
    /// The keyword as written.
    pub fn name(self) -> &'static str {
        match self {
            PassKind::Pass => "pass",
            PassKind::UsePass => "use_pass",
            PassKind::GrabPass => "grab_pass",
            PassKind::SurfaceProgram => "surface_program",
        }
    }
}

/// One pass of a shader.
pub struct CatalogPass {
    /// Its SubShader's index.
    pub subshader: usize,
    /// Index among the SubShader's passes, surface programs first.
    pub index: usize,
    /// What kind of pass it is.
    pub kind: PassKind,
    /// Its `Name`, if any.
    pub name: Option<String>,
    /// Its tags, in order.
    pub tags: Vec<(String, String)>,
    /// Where the pass sits in `shader.subshaders[subshader].passes` (`None` for surface programs).
    pub item: Option<usize>,
    /// Its program, if it has one.
    pub program: Option<CatalogProgram>,
}

/// A pass's program, analysed.
pub struct CatalogProgram {
    /// The language of its blocks.
    pub language: ProgramLanguage,
    /// Its first block.
    pub span: Span,
    /// Its pragmas.
    pub pragmas: ProgramPragmas,
    /// Programs in a language kiln compiles ([`ProgramLanguage::is_compiled`]): the blocks and
    /// their includes, ready to preprocess.
    pub source: Option<Program>,
    /// Its keywords and sets.
    pub keywords: PassKeywords,
    /// The variants the materials need (or all, for an always-included shader), in key order.
    pub variants: Vec<Variant>,
}

impl CatalogShader {
    /// The `Pass { }` of a catalogued pass, if it is one.
    pub fn pass_ast(&self, pass: &CatalogPass) -> Option<&crate::shaderlab::ast::Pass> {
        match self.shader.subshaders[pass.subshader].passes.get(pass.item?)? {
            PassItem::Pass(ast) => Some(ast),
            _ => None,
        }
    }
}

/// The variants usage logs name (one JSON object a line: `{"shader": "Custom RP/Lit", "pass": 0,
/// "keywords": ["_CLIPPING"]}`); a line that does not read is an error at that line.
fn logged_variants(
    store: &SourceStore,
    logs: &[FileId],
    diagnostics: &mut Vec<Diagnostic>,
) -> Vec<ListedVariant> {
    #[derive(serde::Deserialize)]
    struct Logged {
        shader: String,
        pass: usize,
        keywords: Vec<String>,
        /// Only a pipeline trace's lines have one (docs/trace.md).
        version: Option<u32>,
    }
    let mut listed = Vec::new();
    let lines = logs.iter().flat_map(|&log| {
        let mut start = 0;
        store.text(log).split_inclusive('\n').map(move |line| {
            let span = Span::new(log, start..start + line.trim_end().len());
            start += line.len();
            (line, span)
        })
    });
    for (line, span) in lines {
        if line.trim().is_empty() {
            continue;
        }
        match serde_json::from_str::<Logged>(line) {
            Ok(Logged { shader, pass, keywords, version }) => {
                listed.push(ListedVariant { shader, pass, keywords, span, from_trace: version.is_some() })
            }
            Err(e) => {
                // serde counts lines and columns within the line; the label has the real place.
                let message = e.to_string();
                let message = message.split(" at line ").next().unwrap_or_default();
                diagnostics.push(
                    Diagnostic::error("K0530", format!("malformed variant log line: {message}"))
                        .at(span, "not a variant")
                        .help(r#"each line is {"shader": NAME, "pass": INDEX, "keywords": [...]}"#),
                );
            }
        }
    }
    listed
}

/// Adds the variants usage logs and project files name to the passes' variants, each exactly as
/// named; one naming a shader, pass or keyword that does not exist is an error where it is
/// written (a warning for a trace's line, which is skipped).
fn add_listed_variants(listed: &[ListedVariant], shaders: &mut [CatalogShader]) -> Vec<Diagnostic> {
    let mut diagnostics = Vec::new();
    // Found once, not per line: the shaders by name, the added variants by program.
    let by_name: HashMap<String, usize> =
        shaders.iter().enumerate().rev().map(|(i, s)| (s.shader.name.value.clone(), i)).collect();
    let mut added: HashMap<(usize, usize), Vec<Variant>> = HashMap::new();
    for logged in listed {
        let error = |code, message: String, label: &str| {
            match logged.from_trace {
            false => Diagnostic::error(code, message).at(logged.span, label.to_string()),
            true => Diagnostic::warning("K0534", format!("{message}: this trace entry is skipped"))
                .at(logged.span, label.to_string())
                .note("a pipeline trace names what a run created; the project has changed since (docs/trace.md)"),
        }
        };
        let Some(&index) = by_name.get(&logged.shader) else {
            diagnostics.push(error(
                "K0531",
                format!("no shader named `{}` in the project", logged.shader),
                "named here",
            ));
            continue;
        };
        let position = shaders[index].passes.iter().position(|p| {
            p.index == logged.pass && p.program.as_ref().is_some_and(|program| program.source.is_some())
        });
        let Some((position, Some(program))) =
            position.map(|p| (p, shaders[index].passes[p].program.as_ref()))
        else {
            let message = format!("`{}` has no WGSL pass {}", logged.shader, logged.pass);
            diagnostics.push(error("K0532", message, "named here"));
            continue;
        };
        match crate::keywords::select_variant(
            program.keywords.sets(),
            &program.pragmas.variant_keywords(&logged.keywords),
        ) {
            Ok(keywords) => {
                let keywords: Vec<&str> = keywords.iter().map(String::as_str).collect();
                let mut variant = program.keywords.variant_of(&keywords);
                variant.listed_in.push(logged.span.file);
                added.entry((index, position)).or_default().push(variant);
            }
            Err(e) => diagnostics.push(error("K0533", e.to_string(), "named here")),
        }
    }
    for ((shader, pass), variants) in added {
        let Some(program) = shaders[shader].passes[pass].program.as_mut() else { continue };
        let mut known: HashMap<KeywordBits, usize> =
            program.variants.iter().enumerate().map(|(i, v)| (v.bits.clone(), i)).collect();
        for variant in variants {
            match known.get(&variant.bits) {
                Some(&i) => {
                    let listed_in = &mut program.variants[i].listed_in;
                    for file in variant.listed_in {
                        if !listed_in.contains(&file) {
                            listed_in.push(file);
                        }
                    }
                }
                None => {
                    known.insert(variant.bits.clone(), program.variants.len());
                    program.variants.push(variant);
                }
            }
        }
        program.variants.sort_by(|a, b| a.choices.cmp(&b.choices));
    }
    diagnostics
}

/// Parses the shaders, loads their programs, resolves the materials and enumerates each pass's
/// variants. Diagnostics come back in file order, each reported once.
pub fn catalog(
    store: &mut SourceStore,
    includes: &mut Includes,
    input: &CatalogInput,
) -> (Catalog, Vec<Diagnostic>) {
    let mut diagnostics = Vec::new();
    let mut shaders = Vec::new();
    // Parsing reads only its own file, and so does scanning its WGSL blocks: in parallel. Programs
    // load includes into the store: serial; what they say (pragmas, keywords) is only read: in
    // parallel again (`finish_programs`).
    let store_view: &SourceStore = store;
    let (parsed, scanned): (Vec<_>, Vec<Vec<ScannedBlock>>) = input
        .shaders
        .par_iter()
        .map(|&file| {
            let parsed = parse_shader(store_view, file);
            let blocks = parsed.shader.iter().flat_map(compiled_blocks);
            let scanned = blocks.map(|block| ScannedBlock::scan(store_view, block.body_span)).collect();
            ((file, parsed), scanned)
        })
        .unzip();
    includes.add_scanned(scanned.into_iter().flatten());
    let mut failed = Vec::new();
    let mut unfinished = Vec::new();
    let mut cg_prelude = CgPrelude::default();
    for (file, parsed) in parsed {
        diagnostics.extend(parsed.diagnostics);
        match parsed.shader {
            Some(shader) => {
                let loading = Loading {
                    shader: shaders.len(),
                    unfinished: &mut unfinished,
                    cg_prelude: &mut cg_prelude,
                };
                let passes = passes(store, includes, &shader, loading, &mut diagnostics);
                shaders.push(CatalogShader { file, shader, passes });
            }
            None => failed.extend(crate::shaderlab::declared_name(store.text(file))),
        }
    }
    finish_programs(store, includes, &mut shaders, unfinished, &mut diagnostics);

    diagnostics.extend(too_many_global_keywords(&shaders));

    let entries = ShaderEntries::new(
        shaders
            .iter()
            .map(|s| {
                let sets: Vec<_> = s
                    .passes
                    .iter()
                    .filter_map(|p| p.program.as_ref())
                    .flat_map(|p| {
                        let dynamic =
                            p.pragmas.keyword_sets.iter().filter(|s| s.kind == KeywordKind::DynamicBranch);
                        p.keywords.sets().iter().chain(dynamic).cloned()
                    })
                    .collect();
                ShaderEntry::from_shader(&s.shader, &sets)
            })
            .collect(),
    )
    .with_failed(failed);
    // Materials are many and independent: resolved in parallel, kept in their order.
    let store_view: &SourceStore = store;
    let resolved: Vec<(Option<Material>, Vec<Diagnostic>)> =
        input.materials.par_iter().map(|&file| load_material(store_view, file, &entries)).collect();
    let mut materials = Vec::new();
    for (material, found) in resolved {
        diagnostics.extend(found);
        materials.extend(material);
    }

    let global: Option<Vec<&str>> =
        input.global_keywords.as_ref().map(|g| g.iter().map(|k| k.value.as_str()).collect());
    if let Some(global) = &input.global_keywords {
        diagnostics.extend(unknown_global_keywords(&shaders, global));
    }
    // Each shader's materials, found in one pass over them (not one per shader).
    let mut users: Vec<Vec<usize>> = vec![Vec::new(); shaders.len()];
    for (m, material) in materials.iter().enumerate() {
        if let Some(list) = users.get_mut(material.shader) {
            list.push(m);
        }
    }
    // Shaders enumerate independently: in parallel, diagnostics kept in shader order.
    let enumerated: Vec<Vec<Diagnostic>> = shaders
        .par_iter_mut()
        .zip(&users)
        .map(|(shader, users)| {
            let mut diagnostics = Vec::new();
            let everything = input.always_include.contains(&shader.shader.name.value);
            let keywords: Vec<Vec<&str>> = users
                .iter()
                .map(|&m| materials[m].keywords.iter().map(|(k, _)| k.as_str()).collect())
                .collect();
            for program in shader.passes.iter_mut().filter_map(|p| p.program.as_mut()) {
                match program.keywords.enumerate(&keywords, everything, global.as_deref()) {
                    Ok(variants) => program.variants = variants,
                    Err(count) => {
                        let span =
                            program.pragmas.keyword_sets.first().map_or(shader.shader.name.span, |s| s.span);
                        let why = if everything {
                            "it is always included"
                        } else {
                            "its materials and multi_compile sets"
                        };
                        diagnostics.push(
                            Diagnostic::error(
                                "K0411",
                                format!(
                                    "`{}` would build {count} variants of one pass",
                                    shader.shader.name.value
                                ),
                            )
                            .at(span, format!("{why} multiply to that many"))
                            .note(format!("a pass may have at most {MAX_VARIANTS_PER_PASS} variants built"))
                            .help(
                                "make run-time choices `dynamic_branch` keywords, or use fewer multi_compile sets",
                            ),
                        );
                    }
                }
                // Point at materials of the catalog, not of this shader's list.
                for variant in &mut program.variants {
                    for m in &mut variant.materials {
                        *m = users[*m];
                    }
                }
            }
            diagnostics
        })
        .collect();
    diagnostics.extend(enumerated.into_iter().flatten());
    let mut listed = logged_variants(store, &input.variant_logs, &mut diagnostics);
    listed.extend(input.listed_variants.iter().cloned());
    diagnostics.extend(add_listed_variants(&listed, &mut shaders));
    // Include blocks and files are shared by passes: report each of their problems once.
    diagnostics::dedup(&mut diagnostics);
    (Catalog { shaders, materials }, diagnostics)
}

/// Every keyword pragma of every pass.
fn keyword_sets(shaders: &[CatalogShader]) -> impl Iterator<Item = &KeywordSet> {
    shaders
        .iter()
        .flat_map(|s| &s.passes)
        .filter_map(|p| p.program.as_ref())
        .flat_map(|p| &p.pragmas.keyword_sets)
}

/// Points at the first global keyword over [`MAX_GLOBAL_KEYWORDS_PER_PROJECT`], if any.
fn too_many_global_keywords(shaders: &[CatalogShader]) -> Option<Diagnostic> {
    let declared = keyword_sets(shaders)
        .filter(|set| set.scope == KeywordScope::Global)
        .flat_map(|set| set.options.iter().filter_map(|o| Some((o.keyword.as_deref()?, o.span))));
    let mut seen = HashSet::new();
    let distinct: Vec<(&str, Span)> = declared.filter(|(k, _)| seen.insert(*k)).collect();
    let (keyword, span) = *distinct.get(MAX_GLOBAL_KEYWORDS_PER_PROJECT)?;
    let total = distinct.len();
    Some(
        Diagnostic::error("K0214", format!("the project declares {total} global keywords"))
            .at(span, format!("`{keyword}` is global keyword {}", MAX_GLOBAL_KEYWORDS_PER_PROJECT + 1))
            .note(format!(
                "a project may have at most {MAX_GLOBAL_KEYWORDS_PER_PROJECT} distinct global keywords"
            ))
            .help("make per-shader keywords `_local` (`shader_feature_local`, `multi_compile_local`)"),
    )
}

/// A global keyword no pass has in a multi_compile set chooses nothing: most likely a typo.
fn unknown_global_keywords(shaders: &[CatalogShader], global: &[Spanned<String>]) -> Vec<Diagnostic> {
    let declared: HashSet<&str> = keyword_sets(shaders)
        .filter(|set| set.kind == KeywordKind::MultiCompile)
        .flat_map(|set| set.options.iter().filter_map(|o| o.keyword.as_deref()))
        .collect();
    global
        .iter()
        .filter(|k| !declared.contains(k.value.as_str()))
        .map(|k| {
            let message = format!("global keyword `{}` is in no multi_compile set", k.value);
            let d = Diagnostic::warning("K0213", message).at(k.span, "no pass declares it");
            match crate::diagnostics::closest(&k.value, declared.iter().copied()) {
                Some(s) => d.help(format!("did you mean `{s}`?")),
                None => d.help(
                    "global keywords choose options of `#pragma multi_compile` sets; check the spelling",
                ),
            }
        })
        .collect()
}

fn passes(
    store: &mut SourceStore,
    includes: &mut Includes,
    shader: &Shader,
    mut loading: Loading,
    diagnostics: &mut Vec<Diagnostic>,
) -> Vec<CatalogPass> {
    let mut passes = Vec::new();
    for (si, sub) in shader.subshaders.iter().enumerate() {
        // Surface programs come first, as Unity generates their passes ahead of explicit ones.
        let surface_programs = sub.programs.iter().filter(|p| !p.is_include);
        for (index, program) in surface_programs.clone().enumerate() {
            passes.push(CatalogPass {
                subshader: si,
                index,
                kind: PassKind::SurfaceProgram,
                name: None,
                tags: tags(&sub.state),
                item: None,
                program: loading.load(
                    store,
                    includes,
                    (shader, sub, std::slice::from_ref(program)),
                    passes.len(),
                    diagnostics,
                ),
            });
        }
        let first_pass = surface_programs.count();
        for (pi, item) in sub.passes.iter().enumerate() {
            let (kind, name, tags, program) = match item {
                PassItem::Pass(pass) => {
                    let program = if pass.programs.is_empty() {
                        None
                    } else {
                        let programs = (shader, sub, &pass.programs[..]);
                        loading.load(store, includes, programs, passes.len(), diagnostics)
                    };
                    (
                        PassKind::Pass,
                        pass.state.name.as_ref().map(|n| n.value.clone()),
                        tags(&pass.state),
                        program,
                    )
                }
                PassItem::UsePass(name) => (PassKind::UsePass, Some(name.value.clone()), Vec::new(), None),
                PassItem::GrabPass(grab) => (
                    PassKind::GrabPass,
                    grab.name.as_ref().or(grab.texture.as_ref()).map(|n| n.value.clone()),
                    grab.tags.iter().map(|t| (t.key.value.clone(), t.value.value.clone())).collect(),
                    None,
                ),
            };
            passes.push(CatalogPass {
                subshader: si,
                index: first_pass + pi,
                kind,
                name,
                tags,
                item: Some(pi),
                program,
            });
        }
    }
    passes
}

/// Where a shader's pass programs go while the catalogue loads them: compiled programs wait in
/// `unfinished` for [`finish_programs`].
struct Loading<'a> {
    shader: usize,
    unfinished: &'a mut Vec<Unfinished>,
    cg_prelude: &'a mut CgPrelude,
}

/// The name of the in-memory file that holds Unity's `CGPROGRAM` prelude ([`CgPrelude`]).
pub(crate) const CG_PRELUDE_NAME: &str = "<Unity's CGPROGRAM prelude>";

/// What Unity includes in every `CGPROGRAM` block before its own text (`HLSLSupport.cginc`, then
/// `UnityShaderVariables.cginc`), where a project's include paths hold Unity's `CGIncludes`: made
/// once per catalogue, as a file of its own, when a Cg program first asks.
#[derive(Default)]
struct CgPrelude(Option<Option<Span>>);

impl CgPrelude {
    /// The prelude's text, where the include paths have Unity's files.
    fn span(&mut self, store: &mut SourceStore, includes: &Includes) -> Option<Span> {
        *self.0.get_or_insert_with(|| {
            if !includes.on_include_path("HLSLSupport.cginc") {
                return None;
            }
            let text = "#include \"HLSLSupport.cginc\"\n#include \"UnityShaderVariables.cginc\"\n";
            let file = store.add(CG_PRELUDE_NAME, text);
            Some(Span::new(file, 0..text.len()))
        })
    }
}

/// A pass program kiln compiles, with its blocks and includes loaded, its pragmas and keywords not
/// yet read.
struct Unfinished {
    shader: usize,
    pass: usize,
    language: ProgramLanguage,
    program: Program,
    /// Where a diagnostic about the whole program points (its first block).
    span: Span,
    /// How many diagnostics the catalogue had when it was loaded: its own go there.
    at: usize,
}

impl Loading<'_> {
    /// Loads the program of pass `pass` from its blocks: uncompiled languages' whole, the blocks and
    /// includes (which adds units to `includes`, so one pass after another), the rest left for
    /// [`finish_programs`] (`None` until then).
    fn load(
        &mut self,
        store: &mut SourceStore,
        includes: &mut Includes,
        (shader, sub, programs): (&Shader, &SubShader, &[ProgramBlock]),
        pass: usize,
        diagnostics: &mut Vec<Diagnostic>,
    ) -> Option<CatalogProgram> {
        let blocks = program_blocks(shader, sub, programs);
        let language = programs.first().map_or(ProgramLanguage::Wgsl, |p| p.language);
        if !language.is_compiled() {
            let (pragmas, errors) = collect_pragmas(blocks.into_iter().map(PragmaSource::from));
            diagnostics.extend(errors);
            return Some(finished_program(language, pragmas, None, programs[0].span, diagnostics));
        }
        // A Cg program reads Unity's prelude first, as a block before its own.
        let prelude =
            (language == ProgramLanguage::Cg).then(|| self.cg_prelude.span(store, includes)).flatten();
        let spans: Vec<Span> = prelude.into_iter().chain(blocks.iter().map(|b| b.body_span)).collect();
        let (program, found) = includes.load_program(store, &spans);
        diagnostics.extend(found);
        let at = diagnostics.len();
        let unfinished =
            Unfinished { shader: self.shader, pass, language, program, span: programs[0].span, at };
        self.unfinished.push(unfinished);
        None
    }
}

/// Reads the loaded programs' pragmas and keywords, in parallel (nothing is loaded any
/// more), and places each one's diagnostics where loading it left off: the order is a serial
/// catalogue's.
fn finish_programs(
    store: &SourceStore,
    includes: &Includes,
    shaders: &mut [CatalogShader],
    unfinished: Vec<Unfinished>,
    diagnostics: &mut Vec<Diagnostic>,
) {
    let finished: Vec<_> = unfinished
        .into_par_iter()
        .map(|Unfinished { shader, pass, language, program, span, at }| {
            let (loaded, mut found) = finish_pass(includes, store, program);
            let source = Some(loaded.program);
            let program = finished_program(language, loaded.pragmas, source, span, &mut found);
            (shader, pass, at, program, found)
        })
        .collect();
    let mut placed = Vec::with_capacity(diagnostics.len());
    let mut before = std::mem::take(diagnostics).into_iter();
    let mut taken = 0;
    for (shader, pass, at, program, found) in finished {
        shaders[shader].passes[pass].program = Some(program);
        placed.extend(before.by_ref().take(at - taken));
        taken = at;
        placed.extend(found);
    }
    placed.extend(before);
    *diagnostics = placed;
}

/// A pass's program once its pragmas are read, with its keywords; more than a pass may have is an
/// error (K0212) at the first keyword over the limit (or at `span`).
fn finished_program(
    language: ProgramLanguage,
    pragmas: ProgramPragmas,
    source: Option<Program>,
    span: Span,
    diagnostics: &mut Vec<Diagnostic>,
) -> CatalogProgram {
    let keywords = PassKeywords::new(pragmas.variant_sets());
    if keywords.names().len() > MAX_KEYWORDS_PER_PASS {
        // Point at the first keyword over the limit.
        let span = pragmas
            .keyword_sets
            .iter()
            .flat_map(|s| s.options.iter().filter(|o| o.keyword.is_some()))
            .nth(MAX_KEYWORDS_PER_PASS)
            .map_or(span, |o| o.span);
        diagnostics.push(
            Diagnostic::error("K0212", format!("the pass declares {} keywords", keywords.names().len()))
                .at(
                    span,
                    format!(
                        "keyword {} of a pass that may have {MAX_KEYWORDS_PER_PASS}",
                        MAX_KEYWORDS_PER_PASS + 1
                    ),
                )
                .help("split the pass, or make run-time choices `dynamic_branch` keywords"),
        );
    }
    CatalogProgram { language, span, pragmas, source, keywords, variants: Vec::new() }
}

fn tags(state: &StateBlock) -> Vec<(String, String)> {
    state.tags.iter().map(|t| (t.key.value.clone(), t.value.value.clone())).collect()
}

/// Every program block of a shader in a language kiln compiles, its include blocks among them:
/// what loading its programs scans.
fn compiled_blocks(shader: &Shader) -> impl Iterator<Item = &ProgramBlock> {
    let passes = shader.subshaders.iter().flat_map(|sub| &sub.passes).filter_map(|item| match item {
        PassItem::Pass(pass) => Some(&pass.programs),
        _ => None,
    });
    let subshaders = shader.subshaders.iter().map(|sub| &sub.programs);
    (std::iter::once(&shader.includes).chain(subshaders).chain(passes))
        .flatten()
        .filter(|block| block.language.is_compiled())
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

/// The `[_Name]` property references in a render command's text, in order.
pub fn property_references(text: &str) -> Vec<&str> {
    text.match_indices('[')
        .filter_map(|(i, _)| {
            let rest = &text[i + 1..];
            let name = rest[..rest.find(']')?].trim();
            (!name.is_empty() && name.chars().all(|c| c.is_alphanumeric() || c == '_')).then_some(name)
        })
        .collect()
}

impl CatalogProgram {
    /// The macros a variant's text is preprocessed with: its keywords (`on`) and its language's
    /// own (`SHADER_API_D3D11` for HLSL and Cg), as a build, `kiln preprocess` and the language
    /// server all read it.
    pub fn keyword_macros<'a>(&'a self, on: &[&'a str]) -> crate::preprocess::KeywordMacros<'a> {
        crate::preprocess::keyword_macros(&self.pragmas, on).in_language(self.language)
    }

    /// The keywords a variant's `stage` is preprocessed with.
    pub fn keywords_for<'a>(
        &self,
        variant: &'a Variant,
        stage: crate::preprocess::Stage,
    ) -> &'a crate::keywords::KeywordBits {
        self.keywords.stage_bits(variant, stage)
    }
}
