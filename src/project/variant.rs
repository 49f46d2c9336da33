//! One variant of one pass, as `kiln preprocess` and `kiln reflect` ask for it: found in its
//! shader file alone and preprocessed or compiled without the rest of the project.

use super::ProjectError;
use super::materials::config_folder_above;
use super::workspace::{SHADER_EXTENSIONS, bind_group_names, include_config, inside_the_project};
use crate::catalog::{Catalog, CatalogInput, CatalogProgram, catalog};
use crate::config::{ParseScope, Settings};
use crate::diagnostics::{self, Diagnostic};
use crate::keywords::{Variant, select_variant};
use crate::manifest::StageView;
use crate::orchestrate::{Run, Writes, build};
use crate::preprocess::{Includes, Preprocessed, Stage, preprocess_with};
use crate::reflect::UniformBlock;
use crate::source::SourceStore;
use std::path::{Path, PathBuf};

/// One variant of one pass, as `kiln preprocess` asks for it.
#[derive(Debug, Clone)]
pub struct VariantRequest {
    /// The `.shader` file.
    pub shader: PathBuf,
    /// Pass name or index (see [`Shader::find_pass`](crate::shaderlab::ast::Shader::find_pass)).
    pub pass: Option<String>,
    /// The variant's keywords (sets without `_` default to their first keyword).
    pub keywords: Vec<String>,
    /// Which stage to preprocess.
    pub stage: Stage,
    /// The project whose `kiln.toml` settings apply (`include_paths` and `[bind_groups]`, as
    /// `kiln build` uses them); default: the nearest folder above the shader with a `kiln.toml`,
    /// if any.
    pub project: Option<PathBuf>,
}

/// A requested variant of a pass of one shader file, with the catalogue it was found in.
struct Requested {
    catalog: Catalog,
    includes: Includes,
    /// The project's bind-group names (`[bind_groups]`).
    groups: crate::compile::bind::GroupNames,
    /// Index of the pass in `catalog.shaders[0].passes`.
    pass: usize,
    variant: Variant,
}

impl Requested {
    fn program(&self) -> &CatalogProgram {
        // `requested_variant` only returns passes with a WGSL program.
        self.catalog.shaders[0].passes[self.pass].program.as_ref().expect("a program")
    }
}

/// Loads the shader and finds the variant a request names. `Err` is a request that names nothing
/// (exit code 2); mistakes in the files are diagnostics, and there is no `Requested` when any of
/// them is an error.
fn requested_variant(
    store: &mut SourceStore,
    request: &VariantRequest,
) -> Result<(Option<Requested>, Vec<Diagnostic>), ProjectError> {
    if !request.shader.extension().is_some_and(|e| SHADER_EXTENSIONS.iter().any(|s| e == *s)) {
        return Err(ProjectError::NotAShader(request.shader.clone()));
    }
    let file = store.load(&request.shader)?;
    let mut diagnostics = crate::diagnostics::text_warnings(store, file);
    // Includes and bindings as the project's build has them. Only its `kiln.toml` is read: the
    // project's files are not walked for one shader.
    let mut roots = vec![request.shader.clone()];
    let mut include_paths = Vec::new();
    let mut groups = Default::default();
    let project = request.project.clone().or_else(|| config_folder_above(&request.shader));
    if let Some(project) = project.filter(|p| p.join(crate::config::FILE_NAME).is_file()) {
        let config_file = store.load(&project.join(crate::config::FILE_NAME))?;
        let (config, problems) = crate::config::parse_config(store, config_file);
        diagnostics.extend(problems);
        diagnostics.extend(bind_group_names(&config.bind_groups, config_file, &mut groups));
        include_paths =
            inside_the_project(store, &project, Some(config_file), &config.include_paths, &mut diagnostics);
        roots.push(project);
    }
    let mut include = include_config(&roots);
    include.include_paths = include_paths;
    let mut includes = Includes::new(include);
    let input = CatalogInput { shaders: vec![file], ..CatalogInput::default() };
    let (catalog, found) = catalog(store, &mut includes, &input);
    diagnostics.extend(found);
    let Some(shader) = catalog.shaders.first() else { return Ok((None, diagnostics)) };
    let not_found = || ProjectError::PassNotFound {
        shader: shader.shader.name.value.clone(),
        selector: request.pass.clone(),
    };
    let chosen =
        shader.shader.find_pass(request.pass.as_deref()).map(|(_, pass)| pass).ok_or_else(not_found)?;
    let pass = (0..shader.passes.len())
        .find(|&i| shader.pass_ast(&shader.passes[i]).is_some_and(|p| std::ptr::eq(p, chosen)))
        .ok_or_else(not_found)?;
    let program = shader.passes[pass].program.as_ref().ok_or_else(not_found)?;
    if !program.language.is_compiled() {
        return Err(ProjectError::NotCompiled { language: program.language.name() });
    }
    let keywords =
        select_variant(program.keywords.sets(), &program.pragmas.variant_keywords(&request.keywords))?;
    let keywords: Vec<&str> = keywords.iter().map(String::as_str).collect();
    let variant = program.keywords.variant_of(&keywords);
    if diagnostics::has_errors(&diagnostics) {
        return Ok((None, diagnostics));
    }
    Ok((Some(Requested { catalog, includes, groups, pass, variant }), diagnostics))
}

/// Preprocesses one variant of one pass for one stage (a `_fragment` keyword is not defined in
/// the vertex stage), whole or (`scope`) cut as a build cuts it. The text is `None` when any
/// diagnostic is an error.
pub fn preprocess_variant(
    store: &mut SourceStore,
    request: &VariantRequest,
    scope: ParseScope,
) -> Result<(Option<Preprocessed>, Vec<Diagnostic>), ProjectError> {
    let (requested, mut diagnostics) = requested_variant(store, request)?;
    let Some(requested) = requested else { return Ok((None, diagnostics)) };
    let program = requested.program();
    let Some(source) = program.source.as_ref() else { return Ok((None, diagnostics)) };
    let keywords: Vec<&str> =
        program.keywords.keywords(program.keywords_for(&requested.variant, request.stage)).collect();
    let macros = program.keyword_macros(&keywords);
    let mut output = preprocess_with(&requested.includes, store, source, &macros, request.stage);
    diagnostics.extend(output.diagnostics.iter().cloned());
    let ok = !diagnostics::has_errors(&output.diagnostics);
    // What a build hands naga: the declarations the stage's entry point reaches (a compute file's
    // first kernel's).
    let pragmas = &program.pragmas;
    let entry = match request.stage {
        Stage::Vertex => pragmas.vertex.as_ref(),
        Stage::Fragment => pragmas.fragment.as_ref(),
        Stage::Compute => pragmas.kernels.first(),
    };
    if let (true, ParseScope::Reachable, Some(entry)) = (ok, scope, entry)
        && let Some((text, map)) =
            crate::compile::cut(program.language, &output.text, &output.source_map, &entry.value)
    {
        (output.text, output.source_map) = (text, map);
    }
    Ok((ok.then_some(output), diagnostics))
}

/// `kiln reflect`: compiles one variant of one pass (writing nothing) and returns its bind group
/// layout and its variant entry of the manifest, as JSON.
pub fn reflect_variant(
    store: &mut SourceStore,
    request: &VariantRequest,
) -> Result<(Option<serde_json::Value>, Vec<Diagnostic>), ProjectError> {
    let (requested, mut diagnostics) = requested_variant(store, request)?;
    let Some(Requested { mut catalog, includes, groups, pass: index, variant }) = requested else {
        return Ok((None, diagnostics));
    };
    // Only the requested variant is built.
    for (i, pass) in catalog.shaders[0].passes.iter_mut().enumerate() {
        if let Some(program) = pass.program.as_mut() {
            program.variants = if i == index { vec![variant.clone()] } else { Vec::new() };
        }
    }
    let folder = request.shader.parent().map(Path::to_path_buf).unwrap_or_default();
    let settings =
        Settings { groups, ..Settings::one_off(folder.clone(), folder.join(".kiln-reflect-unused")) };
    let run = Run { writes: Writes::Nothing, ..Run::default() };
    let result = build(store, &includes, &catalog, &settings, &run, &diagnostics, &|_, _| {});
    diagnostics.extend(result.diagnostics);
    let pass = result.manifest.as_ref().and_then(|m| m.passes().next());
    let json = pass.filter(|_| !diagnostics::has_errors(&diagnostics)).and_then(|p| {
        let variant = p.variants.first()?;
        // A stage's interface, its uniform blocks named (they are printed in full beside it).
        let stage = |stage: Option<StageView>| {
            stage.map(|s| {
                let mut json = serde_json::json!(s.interface);
                let names: Vec<&str> =
                    s.interface.uniform_blocks.iter().map(|&b| p.uniform_blocks[b].name.as_str()).collect();
                json["uniform_blocks"] = serde_json::json!(names);
                json
            })
        };
        let [vertex, fragment] = p.variant_stages(variant);
        let blocks: Vec<&UniformBlock> =
            p.variant_uniform_blocks(variant).into_iter().map(|b| &p.uniform_blocks[b]).collect();
        let mut reflected = serde_json::json!({
            "layout": p.layout,
            "uniform_blocks": blocks,
            "variant": { "key": variant.key, "keywords": variant.keywords,
                         "vertex": stage(vertex), "fragment": stage(fragment) },
        });
        // A compute shader's kernels, by name.
        if !p.kernels.is_empty() {
            let kernels = p
                .kernels
                .iter()
                .zip(&variant.kernels)
                .map(|(name, m)| (name.clone(), serde_json::json!(stage(m.map(|m| p.stage(m))))));
            reflected["variant"]["kernels"] = serde_json::Value::Object(kernels.collect());
        }
        Some(reflected)
    });
    Ok((json, diagnostics))
}
