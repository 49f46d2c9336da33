//! A project: finding and loading its files, and running the stages over them for the CLI and
//! build scripts. Files are read here and through [`SourceStore`] only (stages get file ids,
//! never paths); the build's outputs are written by `crate::store` and `crate::build`.
//!
//! Long because it holds every job the CLI and build scripts run (build, merge, list, preprocess,
//! reflect, material files), each a short sequence of library calls over the workspace.

pub use crate::build::Part;
use crate::build::{BuildOptions, BuildResult, VariantSelection, build};
use crate::catalog::{Catalog, CatalogInput, CatalogProgram, catalog};
use crate::config::ProjectConfig;
use crate::diagnostics::{self, Diagnostic};
use crate::keywords::{Variant, VariantError, select_variant};
use crate::manifest::StageView;
use crate::material::Preset;
use crate::preprocess::{IncludeConfig, Includes, Preprocessed, Stage, preprocess};
use crate::reflect::UniformBlock;
use crate::shaderlab::ast::ProgramLanguage;
use crate::shaderlab::parse_shader;
use crate::source::{FileId, LoadError, SourceStore, Span, Spanned};
use std::path::{Path, PathBuf};

/// Host failures: what was asked for cannot be read at all.
#[derive(Debug, thiserror::Error)]
// Each variant's fields are named in its message.
#[allow(missing_docs)]
pub enum ProjectError {
    #[error("`{0}` does not exist")]
    NotFound(PathBuf),
    #[error("cannot walk `{path}`: {message}")]
    Walk { path: PathBuf, message: String },
    #[error("{0}")]
    Load(#[from] LoadError),
    #[error("`{shader}` has no pass {}", selector.as_ref().map_or("with a program".to_string(), |s| format!("`{s}`")))]
    PassNotFound { shader: String, selector: Option<String> },
    #[error("the pass's program is {language}: only WGSL programs are preprocessed and compiled")]
    NotWgsl { language: &'static str },
    #[error(transparent)]
    Variant(#[from] VariantError),
    #[error("no shader named `{name}` in the project at `{}`{}", project.display(), suggestion.as_ref().map(|s| format!(" (did you mean `{s}`?)")).unwrap_or_else(|| " (pass `--project` to look elsewhere)".into()))]
    ShaderNotFound { name: String, suggestion: Option<String>, project: PathBuf },
    #[error("unknown preset `{0}`: presets are Opaque, Clip, Fade and Transparent")]
    UnknownPreset(String),
    #[error("preset `{preset}` is not offered for `{shader}`: it has no `_PremulAlpha` property")]
    PresetNotOffered { preset: &'static str, shader: String },
    #[error("`{0}` already exists; use `kiln material preset` to change it")]
    Exists(PathBuf),
    #[error("`{path}` is not a valid material: {message}")]
    NotAMaterial { path: PathBuf, message: String },
    #[error("cannot write `{path}`: {source}")]
    Write { path: PathBuf, source: std::io::Error },
    #[error("`{}` is not a .shader or .compute file: give the shader that holds the pass", .0.display())]
    NotAShader(PathBuf),
    #[error("cannot merge: {0}")]
    Shards(#[from] crate::build::shard::ShardError),
}

/// The project a material file belongs to: the nearest folder above it with a `kiln.toml`; without
/// one (the file is optional), the current folder when the material lies under it, as for `kiln
/// build` run there, else the material's own folder.
pub fn project_of(material: &Path) -> PathBuf {
    let folder = material.parent().map(Path::to_path_buf).unwrap_or_default();
    let absolute = std::path::absolute(&folder).unwrap_or_else(|_| folder.clone());
    let current = std::env::current_dir().ok().filter(|cwd| absolute.starts_with(cwd));
    config_folder_above(material).or(current).unwrap_or(folder)
}

/// The nearest folder above `file` (absolute) that holds a `kiln.toml`.
pub fn config_folder_above(file: &Path) -> Option<PathBuf> {
    let absolute = std::path::absolute(file).ok()?;
    absolute.ancestors().skip(1).find(|a| a.join(crate::config::FILE_NAME).is_file()).map(Path::to_path_buf)
}

/// Parses the project's shaders and returns the one named `name`.
fn find_shader(
    store: &mut SourceStore,
    project: &Path,
    name: &str,
) -> Result<crate::shaderlab::ast::Shader, ProjectError> {
    let (workspace, _) = open_workspace(store, &[project.to_path_buf()])?;
    let (files, _) = load_files(store, &workspace.shaders);
    let shaders: Vec<_> = files.into_iter().filter_map(|f| parse_shader(store, f).shader).collect();
    let names = shaders.iter().map(|s| s.name.value.as_str());
    let suggestion = crate::diagnostics::closest(name, names);
    shaders.into_iter().find(|s| s.name.value == name).ok_or_else(|| ProjectError::ShaderNotFound {
        name: name.to_string(),
        suggestion,
        project: project.to_path_buf(),
    })
}

fn parse_preset(name: &str, shader: &crate::shaderlab::ast::Shader) -> Result<Preset, ProjectError> {
    let preset = Preset::parse(name).ok_or_else(|| ProjectError::UnknownPreset(name.to_string()))?;
    if !preset.offered_for(|p| shader.property(p).is_some()) {
        return Err(ProjectError::PresetNotOffered {
            preset: preset.name(),
            shader: shader.name.value.clone(),
        });
    }
    Ok(preset)
}

/// `kiln material new`: writes a material for the named shader with its defaults (and a preset).
/// Never overwrites a file.
pub fn new_material(
    path: &Path,
    shader: &str,
    preset: Option<&str>,
    project: &Path,
) -> Result<(), ProjectError> {
    if path.exists() {
        return Err(ProjectError::Exists(path.to_path_buf()));
    }
    let shader = find_shader(&mut SourceStore::new(), project, shader)?;
    let preset = preset.map(|p| parse_preset(p, &shader)).transpose()?;
    write_atomically(path, &crate::material::preset::new_material(&shader, preset))
}

/// `kiln material preset`: applies a preset to an existing material, keeping its other values
/// and comments.
pub fn apply_preset(path: &Path, preset: &str, project: &Path) -> Result<(), ProjectError> {
    let text =
        std::fs::read_to_string(path).map_err(|source| LoadError::Io { path: path.to_path_buf(), source })?;
    let not_a_material = |message: String| ProjectError::NotAMaterial { path: path.to_path_buf(), message };
    let mut document: toml_edit::DocumentMut =
        text.parse().map_err(|e: toml_edit::TomlError| not_a_material(e.message().to_string()))?;
    let name = document
        .get("shader")
        .and_then(|s| s.as_str())
        .ok_or_else(|| not_a_material("it names no `shader`".into()))?;
    let shader = find_shader(&mut SourceStore::new(), project, name)?;
    let preset = parse_preset(preset, &shader)?;
    crate::material::preset::apply(&mut document, &shader, preset);
    write_atomically(path, &document.to_string())
}

fn write_atomically(path: &Path, text: &str) -> Result<(), ProjectError> {
    crate::store::write_atomically(path, text.as_bytes())
        .map_err(|source| ProjectError::Write { path: path.to_path_buf(), source })
}

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
    /// The project whose `kiln.toml` settings apply (`[bind_groups]`, as `kiln build` uses them);
    /// default: the nearest folder above the shader with a `kiln.toml`, if any.
    pub project: Option<PathBuf>,
}

/// A requested variant of a pass of one shader file, with the catalogue it was found in.
struct Requested {
    catalog: Catalog,
    includes: Includes,
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
    let mut includes = Includes::new(include_config(std::slice::from_ref(&request.shader)));
    let input = CatalogInput { shaders: vec![file], ..CatalogInput::default() };
    let mut diagnostics = crate::diagnostics::text_warnings(store, file);
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
    if program.language != ProgramLanguage::Wgsl {
        return Err(ProjectError::NotWgsl { language: program.language.name() });
    }
    let keywords =
        select_variant(program.keywords.sets(), &program.pragmas.variant_keywords(&request.keywords))?;
    let keywords: Vec<&str> = keywords.iter().map(String::as_str).collect();
    let variant = program.keywords.variant_of(&keywords);
    if diagnostics::has_errors(&diagnostics) {
        return Ok((None, diagnostics));
    }
    Ok((Some(Requested { catalog, includes, pass, variant }), diagnostics))
}

/// Preprocesses one variant of one pass for one stage (a `_fragment` keyword is not defined in
/// the vertex stage). The text is `None` when any diagnostic is an error.
pub fn preprocess_variant(
    store: &mut SourceStore,
    request: &VariantRequest,
) -> Result<(Option<Preprocessed>, Vec<Diagnostic>), ProjectError> {
    let (requested, mut diagnostics) = requested_variant(store, request)?;
    let Some(requested) = requested else { return Ok((None, diagnostics)) };
    let program = requested.program();
    let Some(wgsl) = program.wgsl.as_ref() else { return Ok((None, diagnostics)) };
    let keywords: Vec<&str> =
        program.keywords.keywords(program.keywords_for(&requested.variant, request.stage)).collect();
    let output = preprocess(&requested.includes, store, wgsl, &keywords, request.stage);
    diagnostics.extend(output.diagnostics.iter().cloned());
    let ok = !diagnostics::has_errors(&output.diagnostics);
    Ok((ok.then_some(output), diagnostics))
}

/// The project a command without a path works on, as cargo finds its package: the nearest folder
/// from the current one up with a `kiln.toml` (written relative, `.`, `..`, ..., so diagnostics
/// show short paths), else the current folder (a project of defaults).
pub fn default_project() -> PathBuf {
    let Ok(current) = std::env::current_dir() else { return PathBuf::from(".") };
    let found = current.ancestors().position(|a| a.join(crate::config::FILE_NAME).is_file());
    match found {
        None | Some(0) => PathBuf::from("."),
        Some(levels) => (0..levels).map(|_| "..").collect(),
    }
}

/// What the given paths hold: folders are projects (with their `kiln.toml`, or the defaults), files
/// are shaders (or materials, by their `.mat` extension).
#[derive(Debug, Default)]
pub struct Workspace {
    /// The project folder (the first folder given, or the folder of the first file): what the
    /// build records about files is relative to it.
    pub root: PathBuf,
    /// Where builds write: the first project folder's `output` (default `build/kiln` in it).
    pub output: PathBuf,
    /// The back ends stage modules are written for.
    pub backends: Vec<crate::config::Backend>,
    /// The shader files found.
    pub shaders: Vec<PathBuf>,
    /// The material files found.
    pub materials: Vec<PathBuf>,
    /// Include folders and roots, when `kiln.toml` sets them.
    pub include: Option<IncludeConfig>,
    /// Shaders built in full though no material uses them.
    pub always_include: Vec<String>,
    /// `kiln.toml`'s `global_keywords`, gathered from every project folder that sets it.
    pub global_keywords: Option<Vec<Spanned<String>>>,
    /// Warnings are errors.
    pub strict: bool,
    /// `kiln.toml`'s `variant_logs`, relative to the working folder.
    pub variant_logs: Vec<PathBuf>,
    /// The first project folder's `cache_dir`.
    pub cache_dir: Option<PathBuf>,
    /// The compute shader variants `kiln.toml` lists (`[compute.NAME] variants`).
    pub listed_variants: Vec<crate::catalog::ListedVariant>,
    /// The names `kiln.toml` adds to the per-frame and per-object bind groups.
    pub groups: crate::compile::bind::GroupNames,
    /// The same names, where `kiln.toml` writes them.
    pub group_names: Vec<Spanned<String>>,
}

impl Workspace {
    /// The shared module cache a command uses: the folder given, else `KILN_CACHE_DIR`, else
    /// the project's `cache_dir`.
    pub fn shared_cache_dir(&self, given: Option<PathBuf>) -> Option<PathBuf> {
        named_cache_dir(given).or_else(|| self.cache_dir.clone())
    }

    /// What the catalogue is built from: the loaded shader and material files, with this
    /// workspace's settings.
    pub fn catalog_input(&self, shaders: Vec<FileId>, materials: Vec<FileId>) -> CatalogInput {
        CatalogInput {
            shaders,
            materials,
            always_include: self.always_include.clone(),
            global_keywords: self.global_keywords.clone(),
            variant_logs: Vec::new(),
            listed_variants: self.listed_variants.clone(),
        }
    }
}

/// Adds `[bind_groups]`'s names to `groups`; a name in both groups is an error at its second
/// place (a resource has one update frequency).
fn bind_group_names(
    config: &crate::config::BindGroupsConfig,
    file: FileId,
    groups: &mut crate::compile::bind::GroupNames,
) -> Vec<Diagnostic> {
    let mut diagnostics = Vec::new();
    for name in &config.per_object {
        if let Some(first) = config.per_frame.iter().find(|f| f.get_ref() == name.get_ref()) {
            diagnostics.push(
                Diagnostic::error("K0010", format!("`{}` is named in two bind groups", name.get_ref()))
                    .at(Span::new(file, name.span()), "bound per object here")
                    .label(Span::new(file, first.span()), "bound per frame here")
                    .help("a resource is updated at one frequency: keep it in one list"),
            );
        }
    }
    groups.per_frame.extend(config.per_frame.iter().map(|n| n.get_ref().clone()));
    groups.per_object.extend(config.per_object.iter().map(|n| n.get_ref().clone()));
    diagnostics
}

/// `[bind_groups]` names that no shader or include of the project mentions: a misspelt resource
/// (`ObjectDta`) would silently stay in the material's group, and the run time would bind it
/// wrongly. A warning at the name, with the closest resource a file declares (`var` names).
fn unknown_group_names(store: &SourceStore, names: &[Spanned<String>]) -> Vec<Diagnostic> {
    // The shader texts: not `kiln.toml` (which names them) nor the materials (which cannot).
    let is_text = |file: &FileId| {
        store.path(*file).is_some_and(|p| {
            !p.ends_with(crate::config::FILE_NAME)
                && !p.extension().is_some_and(|e| e.eq_ignore_ascii_case("mat"))
        })
    };
    let words_of = |file: FileId| {
        store.text(file).split(|c: char| !(c.is_alphanumeric() || c == '_')).filter(|w| !w.is_empty())
    };
    let mut missing: Vec<&Spanned<String>> = names.iter().collect();
    for file in store.ids().filter(is_text) {
        if missing.is_empty() {
            return Vec::new();
        }
        let words: std::collections::HashSet<&str> = words_of(file).collect();
        missing.retain(|name| !words.contains(name.value.as_str()));
    }
    if missing.is_empty() {
        return Vec::new();
    }
    // What the files declare, for the suggestion: after `var`, the first word that is not an
    // address space or access mode.
    const SPACES: [&str; 7] =
        ["uniform", "storage", "read", "read_write", "private", "workgroup", "function"];
    let mut declared = std::collections::BTreeSet::new();
    for file in store.ids().filter(is_text) {
        let mut after_var = false;
        for word in words_of(file) {
            if word == "var" {
                after_var = true;
            } else if after_var && !SPACES.contains(&word) {
                declared.insert(word);
                after_var = false;
            }
        }
    }
    missing
        .into_iter()
        .map(|name| {
            let d = Diagnostic::warning(
                "K0012",
                format!("`[bind_groups]` names `{}`, which no shader or include declares", name.value),
            )
            .at(name.span, "not a resource of this project");
            match crate::diagnostics::closest(&name.value, declared.iter().copied()) {
                Some(suggestion) => d.help(format!("did you mean `{suggestion}`?")),
                None => d.help("name a resource's variable, as `var<uniform> Name` declares it"),
            }
        })
        .collect()
}

/// A `kiln.toml` path that leads out of the project folder, at the place the file names it.
fn outside_the_project(store: &SourceStore, file: FileId, folder: &Path) -> Diagnostic {
    let written = folder.to_string_lossy();
    let text = store.text(file);
    let at = ['"', '\'']
        .iter()
        .find_map(|quote| text.find(&format!("{quote}{written}{quote}")))
        .map_or(0..0, |at| at..at + written.len() + 2);
    Diagnostic::error("K0011", format!("`{}` is outside the project", written.escape_debug()))
        .at(Span::new(file, at), "this path leads out of the project folder")
        .note(
            "kiln reads a project's shaders, materials, includes and usage logs only from inside its folder",
        )
        .help("move or link the files into the project, or give the folder to kiln as a path of its own")
}

/// Gathers the shaders, materials and include settings of `paths` (see [`Workspace`]); a
/// malformed `kiln.toml` is a diagnostic, its defaults used instead.
pub fn open_workspace(
    store: &mut SourceStore,
    paths: &[PathBuf],
) -> Result<(Workspace, Vec<Diagnostic>), ProjectError> {
    let mut workspace = Workspace::default();
    let mut diagnostics = Vec::new();
    let mut roots = Vec::new();
    let mut include_paths = Vec::new();
    // How many files and folders the shaders and the materials were gathered from.
    let (mut shader_sources, mut material_sources) = (0, 0);
    for path in paths {
        if !path.exists() {
            return Err(ProjectError::NotFound(path.clone()));
        }
        if path.is_file() {
            let is_material = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("mat"));
            if is_material { &mut workspace.materials } else { &mut workspace.shaders }.push(path.clone());
            *if is_material { &mut material_sources } else { &mut shader_sources } += 1;
            roots.push(path.parent().map(Path::to_path_buf).unwrap_or_default());
            continue;
        }
        let config_path = path.join(crate::config::FILE_NAME);
        let mut config_file = None;
        let config = if config_path.is_file() {
            let file = store.load(&config_path)?;
            config_file = Some(file);
            diagnostics.extend(crate::diagnostics::text_warnings(store, file));
            let (config, problems) = crate::config::parse_config(store, file);
            diagnostics.extend(problems);
            if let Some(global) = &config.global_keywords {
                let spanned =
                    global.iter().map(|k| Spanned::new(k.get_ref().clone(), Span::new(file, k.span())));
                workspace.global_keywords.get_or_insert_with(Vec::new).extend(spanned);
            }
            diagnostics.extend(bind_group_names(&config.bind_groups, file, &mut workspace.groups));
            let spanned = config.bind_groups.per_frame.iter().chain(&config.bind_groups.per_object);
            workspace
                .group_names
                .extend(spanned.map(|n| Spanned::new(n.get_ref().clone(), Span::new(file, n.span()))));
            for (name, compute) in &config.compute {
                match &compute.variants {
                    crate::config::ComputeVariants::All => workspace.always_include.push(name.clone()),
                    crate::config::ComputeVariants::Listed(lists) => {
                        workspace.listed_variants.extend(lists.iter().map(|keywords| {
                            crate::catalog::ListedVariant {
                                shader: name.clone(),
                                pass: 0,
                                keywords: keywords.get_ref().clone(),
                                span: Span::new(file, keywords.span()),
                            }
                        }))
                    }
                }
            }
            config
        } else {
            ProjectConfig::default()
        };
        // Every path the file names is confined to the project folder, as includes are: a
        // project (one cloned from anywhere) must not make `kiln check` read and quote other files.
        let root = std::fs::canonicalize(path).unwrap_or_else(|_| path.clone());
        let mut under = |folders: &[PathBuf]| -> Vec<PathBuf> {
            let mut inside = Vec::new();
            for folder in folders {
                let joined = crate::source::normalize_lexically(&path.join(folder));
                let resolved = std::fs::canonicalize(&joined)
                    .unwrap_or_else(|_| crate::source::normalize_lexically(&root.join(folder)));
                if resolved.starts_with(&root) {
                    inside.push(joined);
                } else if let Some(file) = config_file {
                    diagnostics.push(outside_the_project(store, file, folder));
                }
            }
            inside
        };
        let (shader_folders, material_folders) = (under(&config.shaders), under(&config.materials));
        let (include_folders, variant_logs) = (under(&config.include_paths), under(&config.variant_logs));
        workspace.shaders.extend(find_files(&shader_folders, &SHADER_EXTENSIONS)?);
        workspace.materials.extend(find_files(&material_folders, &["mat"])?);
        for folder in shader_folders.iter().chain(&material_folders).chain(&include_folders) {
            store.record_searched(folder.clone());
        }
        shader_sources += config.shaders.len();
        material_sources += config.materials.len();
        include_paths.extend(include_folders);
        if workspace.output.as_os_str().is_empty() {
            workspace.output = crate::source::normalize_lexically(&path.join(&config.output));
            workspace.backends = config.backends.clone();
        }
        workspace.always_include.extend(config.always_include);
        workspace.variant_logs.extend(variant_logs);
        if workspace.cache_dir.is_none() {
            workspace.cache_dir =
                config.cache_dir.as_ref().map(|c| crate::source::normalize_lexically(&path.join(c)));
        }
        workspace.strict |= config.strict;
        roots.push(path.clone());
    }
    // A shader under two roots (`.` and `shaders`) is still one shader. One root cannot list a
    // file twice (links are not followed), which spares a large project a canonical path per file.
    for (files, sources) in
        [(&mut workspace.shaders, shader_sources), (&mut workspace.materials, material_sources)]
    {
        if sources > 1 {
            use rayon::prelude::*;
            let canonical: Vec<PathBuf> =
                files.par_iter().map(|f| std::fs::canonicalize(f).unwrap_or_else(|_| f.clone())).collect();
            let mut seen = std::collections::HashSet::new();
            let mut keep = canonical.into_iter().map(|c| seen.insert(c));
            files.retain(|_| keep.next().unwrap_or(true));
        }
    }
    workspace.root = roots.first().cloned().unwrap_or_default();
    if workspace.output.as_os_str().is_empty() {
        let defaults = ProjectConfig::default();
        let folder = workspace.root.clone();
        workspace.output = crate::source::normalize_lexically(&folder.join(defaults.output));
        workspace.backends = defaults.backends;
    }
    let mut include = include_config(&roots);
    include.include_paths = include_paths;
    workspace.include = Some(include);
    Ok((workspace, diagnostics))
}

/// Where includes may come from for shaders found under `paths`: each folder given (or the folder
/// of each file given) is a root, searched after the including file's own folder.
pub fn include_config(paths: &[PathBuf]) -> IncludeConfig {
    let roots = paths
        .iter()
        .map(|p| if p.is_dir() { p.clone() } else { p.parent().map(Path::to_path_buf).unwrap_or_default() })
        .map(|p| if p.as_os_str().is_empty() { PathBuf::from(".") } else { p })
        .collect();
    IncludeConfig::new(roots)
}

/// Every `.shader` and `.compute` file under the given files and folders, in a stable (sorted) order. A file
/// named directly is taken whatever its extension; symbolic links are not followed.
pub fn find_shader_files(paths: &[PathBuf]) -> Result<Vec<PathBuf>, ProjectError> {
    if let Some(missing) = paths.iter().find(|p| !p.exists()) {
        return Err(ProjectError::NotFound(missing.clone()));
    }
    find_files(paths, &SHADER_EXTENSIONS)
}

/// The shared module cache named without a project: the folder given, else `KILN_CACHE_DIR`
/// (a project's `cache_dir` comes after both: [`Workspace::shared_cache_dir`]).
pub fn named_cache_dir(given: Option<PathBuf>) -> Option<PathBuf> {
    given.or_else(|| std::env::var_os("KILN_CACHE_DIR").map(PathBuf::from))
}

/// The files a project's shader folders are searched for: `.shader` files and compute shaders.
pub const SHADER_EXTENSIONS: [&str; 2] = ["shader", crate::shaderlab::compute::EXTENSION];

/// Every file with this extension under the given files and folders (see [`find_shader_files`]).
/// A folder that does not exist contributes nothing (a project without materials is fine).
pub fn find_files(paths: &[PathBuf], extensions: &[&str]) -> Result<Vec<PathBuf>, ProjectError> {
    let mut files = Vec::new();
    for path in paths.iter().filter(|p| p.exists()) {
        if path.is_file() {
            files.push(path.clone());
        } else {
            find_under(path, extensions, &mut files)?;
        }
    }
    Ok(files)
}

/// The files with one of `extensions` in `folder` and its subfolders, each folder's entries by
/// name, links not followed. By hand rather than with walkdir: every build, shard and merge walks
/// the material folders, and at 50,000 materials walkdir's path per entry took twice as long.
fn find_under(folder: &Path, extensions: &[&str], files: &mut Vec<PathBuf>) -> Result<(), ProjectError> {
    let walk_error =
        |e: std::io::Error| ProjectError::Walk { path: folder.to_path_buf(), message: e.to_string() };
    let mut entries: Vec<(std::ffi::OsString, std::fs::FileType)> = std::fs::read_dir(folder)
        .and_then(|entries| {
            entries.map(|entry| entry.and_then(|e| Ok((e.file_name(), e.file_type()?)))).collect()
        })
        .map_err(walk_error)?;
    entries.sort_unstable_by(|(a, _), (b, _)| a.cmp(b));
    for (name, kind) in entries {
        if kind.is_dir() {
            find_under(&folder.join(&name), extensions, files)?;
        } else if kind.is_file()
            && Path::new(&name)
                .extension()
                .is_some_and(|ext| extensions.iter().any(|wanted| ext.eq_ignore_ascii_case(wanted)))
        {
            files.push(folder.join(name));
        }
    }
    Ok(())
}

/// `kiln list`: the listing of the projects and files at `paths` (strict projects' warnings
/// promoted), with what was found wrong.
pub fn list_project(
    store: &mut SourceStore,
    paths: &[PathBuf],
) -> Result<(crate::listing::Listing, Vec<Diagnostic>), ProjectError> {
    let (workspace, mut problems) = open_workspace(store, paths)?;
    let mut includes = Includes::new(workspace.include.clone().unwrap_or_else(|| include_config(paths)));
    let (shaders, found) = load_files(store, &workspace.shaders);
    problems.extend(found);
    let (materials, found) = load_files(store, &workspace.materials);
    problems.extend(found);
    let mut input = workspace.catalog_input(shaders, materials);
    // The listing shows what a build builds: the logged variants too.
    load_variant_logs(store, workspace.variant_logs.iter(), &mut input, &mut problems);
    let (listing, found) = crate::listing::list_shaders(store, &mut includes, &input);
    problems.extend(found);
    if workspace.strict {
        diagnostics::promote_warnings(&mut problems);
    }
    Ok((listing, problems))
}

/// Loads usage logs into the store for the catalogue; one that cannot be read is a diagnostic.
fn load_variant_logs<'a>(
    store: &mut SourceStore,
    paths: impl Iterator<Item = &'a PathBuf>,
    input: &mut CatalogInput,
    diagnostics: &mut Vec<Diagnostic>,
) {
    for path in paths {
        match store.load(path) {
            Ok(file) => input.variant_logs.push(file),
            Err(error) => diagnostics.push(load_error(&error)),
        }
    }
}

/// Loads files into the store. Unreadable files and files that are not text become diagnostics,
/// not failures, so the rest of the project is still checked; a file read with problems (bytes
/// that are not UTF-8, NULs) comes with its warnings.
pub fn load_files(store: &mut SourceStore, paths: &[PathBuf]) -> (Vec<FileId>, Vec<Diagnostic>) {
    let mut ids = Vec::new();
    let mut diagnostics = Vec::new();
    for loaded in store.load_all(paths) {
        match loaded {
            Ok(id) => {
                diagnostics.extend(crate::diagnostics::text_warnings(store, id));
                ids.push(id);
            }
            Err(error) => diagnostics.push(load_error(&error)),
        }
    }
    (ids, diagnostics)
}

/// The diagnostic for a file that could not be loaded.
pub fn load_error(error: &LoadError) -> Diagnostic {
    let code = match error {
        LoadError::NotText { .. } => "K0005",
        LoadError::Io { .. } => "K0002",
        LoadError::TooLarge { .. } => "K0004",
    };
    let diagnostic = Diagnostic::error(code, error.to_string());
    match error {
        LoadError::NotText { .. } => diagnostic
            .note("it is not UTF-8 and has NUL bytes near its start, as binary data does")
            .help("only text files belong where kiln looks for shaders and materials"),
        _ => diagnostic,
    }
}

/// How `kiln build` and `kiln check` run.
#[derive(Debug, Clone)]
pub struct BuildMode {
    /// Write the output (`false` for `kiln check`).
    pub write: bool,
    /// Overrides the project's `output` folder.
    pub output: Option<PathBuf>,
    /// What is built of shaders no material uses.
    pub unused_shaders: VariantSelection,
    /// Worker threads (default: all cores).
    pub threads: Option<usize>,
    /// Overrides the projects' `global_keywords` (a build script that knows the scene).
    pub global_keywords: Option<Vec<String>>,
    /// Write `manifest.json` indented rather than compact.
    pub pretty_manifest: bool,
    /// Variant usage logs whose variants are built too (`--variants-from`), besides the
    /// project's `variant_logs`.
    pub variant_logs: Vec<PathBuf>,
    /// The shared module cache; else `KILN_CACHE_DIR`, else the project's `cache_dir`.
    pub cache_dir: Option<PathBuf>,
    /// The shared module cache when none of those names one (the language server's own).
    pub fallback_cache_dir: Option<PathBuf>,
}

impl Default for BuildMode {
    /// `kiln build` as it runs without options: written, the project's output folder, the
    /// variants the materials use, every core.
    fn default() -> BuildMode {
        BuildMode {
            write: true,
            output: None,
            unused_shaders: VariantSelection::Used,
            threads: None,
            global_keywords: None,
            pretty_manifest: false,
            variant_logs: Vec::new(),
            cache_dir: None,
            fallback_cache_dir: None,
        }
    }
}

/// Builds (or checks) the projects and files at `paths`. `Err` only when a path does not exist.
pub fn build_project(
    store: &mut SourceStore,
    paths: &[PathBuf],
    mode: &BuildMode,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<(BuildResult, Vec<Diagnostic>), ProjectError> {
    build_part(store, paths, mode, progress, Part::Whole)
}

/// [`build_project`] for a part of the work.
pub fn build_part(
    store: &mut SourceStore,
    paths: &[PathBuf],
    mode: &BuildMode,
    progress: &(dyn Fn(usize, usize) + Sync),
    part: Part,
) -> Result<(BuildResult, Vec<Diagnostic>), ProjectError> {
    let Given { workspace, mut includes, input, mut diagnostics, options } =
        load_given(store, paths, mode, part)?;
    // Held until the build is done: another build into the folder waits.
    let _lock = mode.write.then(|| crate::store::OutputLock::acquire(&options.output));
    if diagnostics.is_empty()
        && !matches!(options.part, Part::Shard(_))
        && let Some(result) = crate::build::unchanged(store, &options)
    {
        return Ok((result, diagnostics));
    }
    let (catalog, found) = catalog(store, &mut includes, &input);
    diagnostics.extend(found);
    diagnostics.extend(unknown_group_names(store, &workspace.group_names));
    let result = build(store, &includes, &catalog, &options, &diagnostics, progress);
    // At 100,000 variants, freeing the catalogue takes a twentieth of a second nobody waits for.
    std::thread::spawn(move || drop((catalog, includes)));
    if workspace.strict {
        diagnostics::promote_warnings(&mut diagnostics);
    }
    Ok((result, diagnostics))
}

/// A project checked for an editor: besides the diagnostics, what its files were found to hold
/// (the catalogue, the includes, the manifest a build would write) for hover and go-to.
pub struct Checked {
    /// The project's settings and files.
    pub workspace: Workspace,
    /// Every unit the programs can include.
    pub includes: Includes,
    /// Shaders, programs, materials, variants.
    pub catalog: Catalog,
    /// The manifest a build would write (`None` when a stage failed).
    pub manifest: Option<crate::manifest::Manifest>,
    /// What the check compiled and what it took from caches.
    pub summary: crate::build::BuildSummary,
    /// Everything `kiln check` reports.
    pub diagnostics: Vec<Diagnostic>,
}

/// `kiln check` of the project at `paths`, keeping what it found: never the no-op path (the store
/// may hold texts that are not on disk: [`SourceStore::with_overlay`]), never written. `narrow`
/// may drop variants from the catalogue before anything is compiled (an editor checking the
/// variants it shows first).
pub fn check_project(
    store: &mut SourceStore,
    paths: &[PathBuf],
    mode: &BuildMode,
    narrow: impl FnOnce(&mut Catalog),
) -> Result<Checked, ProjectError> {
    let mode = BuildMode { write: false, ..mode.clone() };
    let Given { workspace, mut includes, input, mut diagnostics, options } =
        load_given(store, paths, &mode, Part::Whole)?;
    let (mut catalog, found) = catalog(store, &mut includes, &input);
    diagnostics.extend(found);
    narrow(&mut catalog);
    let result = build(store, &includes, &catalog, &options, &diagnostics, &|_, _| {});
    diagnostics.extend(result.diagnostics);
    if workspace.strict {
        diagnostics::promote_warnings(&mut diagnostics);
    }
    Ok(Checked {
        workspace,
        includes,
        catalog,
        manifest: result.manifest,
        summary: result.summary,
        diagnostics,
    })
}

/// What a project is given before anything is parsed: its settings, the shaders, materials and
/// variant logs it names (loaded), and the options of a build of it.
struct Given {
    workspace: Workspace,
    includes: Includes,
    input: CatalogInput,
    diagnostics: Vec<Diagnostic>,
    options: BuildOptions,
}

/// The project at `paths` loaded, and the options of a build of `part` of it, made once from
/// `mode` and the project's `kiln.toml`.
fn load_given(
    store: &mut SourceStore,
    paths: &[PathBuf],
    mode: &BuildMode,
    part: Part,
) -> Result<Given, ProjectError> {
    let (workspace, mut diagnostics) = open_workspace(store, paths)?;
    // Not after a broken kiln.toml: its error says why nothing was found.
    if workspace.shaders.is_empty() && !diagnostics::has_errors(&diagnostics) {
        diagnostics.push(no_shaders(paths, mode.write));
    }
    let includes = Includes::new(workspace.include.clone().unwrap_or_else(|| include_config(paths)));
    let (shaders, found) = load_files(store, &workspace.shaders);
    diagnostics.extend(found);
    let (materials, found) = load_files(store, &workspace.materials);
    diagnostics.extend(found);
    let mut input = workspace.catalog_input(shaders, materials);
    // A usage log named on the command line and not there is a mistake in the command.
    if let Some(missing) = mode.variant_logs.iter().find(|path| !path.exists()) {
        return Err(ProjectError::NotFound(missing.clone()));
    }
    load_variant_logs(
        store,
        workspace.variant_logs.iter().chain(&mode.variant_logs),
        &mut input,
        &mut diagnostics,
    );
    if let Some(global) = &mode.global_keywords {
        input.global_keywords = Some(given_global_keywords(store, global));
    }
    let options = BuildOptions {
        output: mode.output.clone().unwrap_or_else(|| workspace.output.clone()),
        root: workspace.root.clone(),
        write: mode.write,
        threads: mode.threads,
        backends: workspace.backends.clone(),
        unused_shaders: mode.unused_shaders,
        pretty_manifest: mode.pretty_manifest,
        record: true,
        part,
        cache_dir: workspace
            .shared_cache_dir(mode.cache_dir.clone())
            .or_else(|| mode.fallback_cache_dir.clone()),
        given_files: store.files_read().count(),
        groups: workspace.groups.clone(),
    };
    Ok(Given { workspace, includes, input, diagnostics, options })
}

/// A project without shaders: a warning for a build, an error for a check, so that CI pointed at
/// the wrong folder fails.
fn no_shaders(paths: &[PathBuf], build: bool) -> Diagnostic {
    let shown: Vec<String> = paths.iter().map(|p| format!("`{}`", p.display())).collect();
    let message = format!("no shaders in {}", shown.join(", "));
    let diagnostic =
        if build { Diagnostic::warning("K0009", message) } else { Diagnostic::error("K0009", message) };
    diagnostic.help(
        "give the project folder (kiln looks for `.shader` files in it, or in the folders its kiln.toml's \
         `shaders` names) or `.shader` files",
    )
}

/// `kiln merge`: checks the shard outputs against each other, then writes into `mode.output` the
/// bytes one build of the project gives, from their parts (no catalogue, no naga). The project is
/// `project`, or the one the shards were built from.
pub fn merge_shards(
    store: &mut SourceStore,
    shards: &[PathBuf],
    project: Option<PathBuf>,
    mode: &BuildMode,
) -> Result<(BuildResult, Vec<Diagnostic>), ProjectError> {
    let records = || {
        let (records, inputs) = crate::build::shard::check_shards(shards)?;
        Ok::<_, ProjectError>(crate::build::Merge {
            shards: shards.iter().cloned().zip(records).collect(),
            inputs,
        })
    };
    // The shards and the project are read at once (each takes about a tenth of a second at
    // 100,000 variants); without a project given, the first record names it.
    let ((merge, read), given) = match project {
        Some(project) => {
            let read_shards = || records().map(|merge| (merge.read_shards(), merge));
            let (shards, given) =
                rayon::join(read_shards, || load_given(store, &[project], mode, Part::Whole));
            let (read, merge) = shards?;
            ((merge, read), given?)
        }
        None => {
            let merge = records()?;
            let project = PathBuf::from(&merge.shards[0].1.project);
            let (read, given) =
                rayon::join(|| merge.read_shards(), || load_given(store, &[project], mode, Part::Whole));
            ((merge, read), given?)
        }
    };
    let Given { workspace, mut diagnostics, options, .. } = given;
    // As a build holds its output folder: another build or merge into it waits.
    let _lock = crate::store::OutputLock::acquire(&options.output);
    let result = crate::build::merge(store, &options, &diagnostics, &merge, read);
    // The shards' parts are many small strings: freeing them would hold up the answer for a
    // tenth of a second at 100,000 variants, which a process about to exit need not wait for.
    std::thread::spawn(move || drop(merge));
    if workspace.strict {
        diagnostics::promote_warnings(&mut diagnostics);
    }
    Ok((result, diagnostics))
}

/// One build of `kiln watch`: [`build_project`], and then, in the output folder, the rendered
/// diagnostics of a build with errors ([`ERRORS_FILE`](crate::manifest::ERRORS_FILE)),
/// removed again by a build without. A failed build writes nothing else, so a program running
/// on the folder keeps the last good build and can say why the new one is not there.
pub fn watch_build(
    store: &mut SourceStore,
    paths: &[PathBuf],
    mode: &BuildMode,
) -> Result<(BuildResult, Vec<Diagnostic>), ProjectError> {
    let (result, diagnostics) = build_project(store, paths, mode, &|_, _| {})?;
    let errors_file = result.output.join(crate::manifest::ERRORS_FILE);
    let all: Vec<Diagnostic> = diagnostics.iter().chain(&result.diagnostics).cloned().collect();
    let written = if diagnostics::has_errors(&all) {
        std::fs::create_dir_all(&result.output).and_then(|()| {
            crate::store::write_atomically(&errors_file, diagnostics::render_plain(store, &all).as_bytes())
        })
    } else {
        match std::fs::remove_file(&errors_file) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(e),
            _ => Ok(()),
        }
    };
    written.map_err(|source| ProjectError::Write { path: errors_file, source })?;
    Ok((result, diagnostics))
}

/// Global keywords given by a caller become a source of their own, a keyword a line, so that
/// diagnostics can point at them and the no-op check sees them change.
fn given_global_keywords(store: &mut SourceStore, keywords: &[String]) -> Vec<Spanned<String>> {
    let text: String = keywords.iter().map(|k| format!("{k}\n")).collect();
    let file = store.add("<global keywords given to the build>", text);
    let mut start = 0;
    keywords
        .iter()
        .map(|k| {
            let span = Span::new(file, start..start + k.len());
            start += k.len() + 1;
            Spanned::new(k.clone(), span)
        })
        .collect()
}

/// `kiln reflect`: compiles one variant of one pass (writing nothing) and returns its bind group
/// layout and its variant entry of the manifest, as JSON.
pub fn reflect_variant(
    store: &mut SourceStore,
    request: &VariantRequest,
) -> Result<(Option<serde_json::Value>, Vec<Diagnostic>), ProjectError> {
    let (requested, mut diagnostics) = requested_variant(store, request)?;
    let Some(Requested { mut catalog, includes, pass: index, variant }) = requested else {
        return Ok((None, diagnostics));
    };
    // Only the requested variant is built.
    for (i, pass) in catalog.shaders[0].passes.iter_mut().enumerate() {
        if let Some(program) = pass.program.as_mut() {
            program.variants = if i == index { vec![variant.clone()] } else { Vec::new() };
        }
    }
    let folder = request.shader.parent().map(Path::to_path_buf).unwrap_or_default();
    // Bindings as the project's build gives them: its `[bind_groups]` move resources between
    // groups. Only its `kiln.toml` is read: the project's files are not walked for one shader.
    let mut groups = Default::default();
    let project = request.project.clone().or_else(|| config_folder_above(&request.shader));
    let config = project.map(|p| p.join(crate::config::FILE_NAME)).filter(|c| c.is_file());
    if let Some(config) = config {
        let file = store.load(&config)?;
        let (config, problems) = crate::config::parse_config(store, file);
        diagnostics.extend(problems);
        diagnostics.extend(bind_group_names(&config.bind_groups, file, &mut groups));
    }
    let options = BuildOptions {
        groups,
        ..BuildOptions::one_off(folder.clone(), folder.join(".kiln-reflect-unused"), false)
    };
    let result = build(store, &includes, &catalog, &options, &diagnostics, &|_, _| {});
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn found_files_come_folder_by_folder_in_name_order_without_following_links() {
        let dir = tempfile::tempdir().expect("temp dir");
        let root = dir.path();
        for file in ["b.shader", "a.SHADER", "d.txt", "sub/z/c.shader", "sub/b.shader", "sub.shader"] {
            let path = root.join(file);
            std::fs::create_dir_all(path.parent().expect("parent")).expect("folder");
            std::fs::write(path, "").expect("write");
        }
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink(root.join("b.shader"), root.join("link.shader")).expect("link");
            std::os::unix::fs::symlink(root.join("sub"), root.join("linked")).expect("link");
        }
        let found = find_shader_files(&[root.to_path_buf()]).expect("walk");
        let names: Vec<String> = found.iter().map(|p| crate::source::relative_to(p, root)).collect();
        // Entries by their names' bytes: `sub` before `sub.shader`, a folder's files where it sorts.
        assert_eq!(names, ["a.SHADER", "b.shader", "sub/b.shader", "sub/z/c.shader", "sub.shader"]);
    }
}
