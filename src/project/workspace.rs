//! What the given paths hold: the project folders and their `kiln.toml`, the shader, material
//! and usage-log files found under them, loaded into the store.

use super::ProjectError;
use crate::catalog::CatalogInput;
use crate::config::{ProjectConfig, ProjectSettings};
use crate::diagnostics::Diagnostic;
use crate::preprocess::IncludeConfig;
use crate::source::{FileId, LinksOut, LoadError, SourceStore, Span, Spanned};
use std::path::{Path, PathBuf};

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
    /// The project's layer of a build's settings: the project folder, and the first project
    /// folder's `kiln.toml` (`[`Settings::resolve`](crate::config::Settings::resolve) reads it).
    pub settings: ProjectSettings,
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
    /// The compute shader variants `kiln.toml` lists (`[compute.NAME] variants`).
    pub listed_variants: Vec<crate::catalog::ListedVariant>,
    /// The names `kiln.toml` adds to the bind groups, where it writes them.
    pub group_names: Vec<Spanned<String>>,
    /// Links out of the project the walk did not follow ([`LinksOut`]), for a project that seems
    /// to hold no shader.
    pub links_refused: usize,
}

impl Workspace {
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
pub(super) fn bind_group_names(
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
pub(super) fn unknown_group_names(store: &SourceStore, names: &[Spanned<String>]) -> Vec<Diagnostic> {
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

/// The folders of `folders` (as `kiln.toml` in `project` names them) that are inside the project;
/// each other one is an error at its line of the file. Every path the file names is confined so,
/// as includes are: a project (one cloned from anywhere) must not make `kiln check` read and quote
/// other files.
pub(super) fn inside_the_project(
    store: &SourceStore,
    project: &Path,
    config_file: Option<FileId>,
    folders: &[PathBuf],
    diagnostics: &mut Vec<Diagnostic>,
) -> Vec<PathBuf> {
    let root = std::fs::canonicalize(project).unwrap_or_else(|_| project.to_path_buf());
    let mut inside = Vec::new();
    for folder in folders {
        let joined = crate::source::normalize_lexically(&project.join(folder));
        let resolved = std::fs::canonicalize(&joined)
            .unwrap_or_else(|_| crate::source::normalize_lexically(&root.join(folder)));
        if resolved.starts_with(&root) {
            inside.push(joined);
        } else if let Some(file) = config_file {
            diagnostics.push(outside_the_project(store, file, folder));
        }
    }
    inside
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
    let links_out = LinksOut::from_env();
    let mut include_paths = Vec::new();
    // The first folder's kiln.toml (or its defaults) and where it is.
    let mut first_folder: Option<(PathBuf, Option<FileId>, ProjectConfig)> = None;
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
            diagnostics.extend(bind_group_names(&config.bind_groups, file, &mut workspace.settings.groups));
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
                                from_trace: false,
                            }
                        }))
                    }
                }
            }
            config
        } else {
            ProjectConfig::default()
        };
        let mut under =
            |folders: &[PathBuf]| inside_the_project(store, path, config_file, folders, &mut diagnostics);
        let (shader_folders, material_folders) = (under(&config.shaders), under(&config.materials));
        let (include_folders, variant_logs) = (under(&config.include_paths), under(&config.variant_logs));
        for (found, files) in [
            (find_files(&shader_folders, &SHADER_EXTENSIONS, links_out)?, &mut workspace.shaders),
            (find_files(&material_folders, &["mat"], links_out)?, &mut workspace.materials),
        ] {
            files.extend(found.files);
            workspace.links_refused += found.links_refused;
        }
        for folder in shader_folders.iter().chain(&material_folders).chain(&include_folders) {
            store.record_searched(folder.clone());
        }
        shader_sources += config.shaders.len();
        material_sources += config.materials.len();
        include_paths.extend(include_folders);
        if first_folder.is_none() {
            first_folder = Some((path.clone(), config_file, config.clone()));
        }
        workspace.always_include.extend(config.always_include);
        workspace.variant_logs.extend(variant_logs);
        workspace.strict |= config.strict;
        roots.push(path.clone());
    }
    // A shader under two roots (`.` and `shaders`) is still one shader. One root cannot list a
    // file twice (`find_files` names each once), which spares a large project a canonical path
    // per file.
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
    let root = roots.first().cloned().unwrap_or_default();
    let (folder, file, config) =
        first_folder.unwrap_or_else(|| (root.clone(), None, ProjectConfig::default()));
    let groups = std::mem::take(&mut workspace.settings.groups);
    workspace.settings = ProjectSettings { root, folder, file, config, groups };
    let mut include = include_config(&roots);
    include.include_paths = include_paths;
    include.links_out = links_out;
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

/// The files a project's shader folders are searched for: `.shader` files and compute shaders.
pub const SHADER_EXTENSIONS: [&str; 2] = ["shader", crate::shaderlab::compute::EXTENSION];

/// Every file with one of these extensions under the given files and folders, folder by folder
/// in name order; a file named directly is taken whatever its extension, and symbolic links are
/// not followed. A folder that does not exist contributes nothing (a project without materials
/// is fine).
pub fn find_files(
    paths: &[PathBuf],
    extensions: &[&str],
    links_out: LinksOut,
) -> Result<Found, ProjectError> {
    let mut files = Vec::new();
    let mut linked = LinkedFolders { links_out, ..LinkedFolders::default() };
    for path in paths.iter().filter(|p| p.exists()) {
        if path.is_file() {
            files.push(path.clone());
        } else {
            linked.roots.extend(std::fs::canonicalize(path));
            find_under(path, extensions, &mut files, &mut linked)?;
        }
    }
    if linked.followed {
        // Two links to one file (or a folder reached twice) name it once, where first found.
        let mut seen = std::collections::HashSet::new();
        files.retain(|file| seen.insert(std::fs::canonicalize(file).unwrap_or_else(|_| file.clone())));
    }
    Ok(Found { files, links_refused: linked.refused })
}

/// What a walk found: the files, and how many links out of the project it did not follow.
#[derive(Debug, Default)]
pub struct Found {
    /// The files, folder by folder in name order.
    pub files: Vec<PathBuf>,
    /// Links whose target is outside the folders walked, not followed ([`LinksOut::Refused`]).
    pub links_refused: usize,
}

/// The folders a walk searches and those it entered through links, by canonical path: a link to
/// something inside a searched folder is skipped (it is found under its own name), and a folder
/// elsewhere is walked once however many links lead to it.
#[derive(Default)]
struct LinkedFolders {
    links_out: LinksOut,
    refused: usize,
    roots: Vec<PathBuf>,
    visited: std::collections::HashSet<PathBuf>,
    /// Whether any link was followed (only then may a file be found twice).
    followed: bool,
}

/// The files with one of `extensions` in `folder` and its subfolders, each folder's entries by
/// name. Links inside the folders walked are found under their targets' names; links out of
/// them are followed where `linked.links_out` says so, to files and (once each) to folders: a
/// sandbox such as Bazel's stages every input as a link. By hand rather than with walkdir: every build, shard and merge
/// walks the material folders, and at 50,000 materials walkdir's path per entry took twice as long.
fn find_under(
    folder: &Path,
    extensions: &[&str],
    files: &mut Vec<PathBuf>,
    linked: &mut LinkedFolders,
) -> Result<(), ProjectError> {
    let walk_error =
        |e: std::io::Error| ProjectError::Walk { path: folder.to_path_buf(), message: e.to_string() };
    let mut entries: Vec<(std::ffi::OsString, std::fs::FileType)> = std::fs::read_dir(folder)
        .and_then(|entries| {
            entries.map(|entry| entry.and_then(|e| Ok((e.file_name(), e.file_type()?)))).collect()
        })
        .map_err(walk_error)?;
    entries.sort_unstable_by(|(a, _), (b, _)| a.cmp(b));
    for (name, mut kind) in entries {
        if kind.is_symlink() {
            // A link that leads nowhere is skipped, as a file of another extension is.
            let Ok(canonical) = std::fs::canonicalize(folder.join(&name)) else { continue };
            let Ok(target) = std::fs::metadata(&canonical) else { continue };
            if linked.roots.iter().any(|root| canonical.starts_with(root)) {
                continue;
            }
            if linked.links_out == LinksOut::Refused {
                linked.refused += 1;
                continue;
            }
            kind = target.file_type();
            linked.followed = true;
            if kind.is_dir() && !linked.visited.insert(canonical) {
                continue;
            }
        }
        if kind.is_dir() {
            find_under(&folder.join(&name), extensions, files, linked)?;
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

/// Loads usage logs into the store for the catalogue; one that cannot be read is a diagnostic.
pub(super) fn load_variant_logs<'a>(
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn found_files_come_folder_by_folder_in_name_order_following_links_once() {
        let dir = tempfile::tempdir().expect("temp dir");
        let root = dir.path();
        for file in ["b.shader", "a.SHADER", "d.txt", "sub/z/c.shader", "sub/b.shader", "sub.shader"] {
            let path = root.join(file);
            std::fs::create_dir_all(path.parent().expect("parent")).expect("folder");
            std::fs::write(path, "").expect("write");
        }
        let elsewhere = tempfile::tempdir().expect("temp dir");
        std::fs::create_dir_all(elsewhere.path().join("kept")).expect("folder");
        std::fs::write(elsewhere.path().join("staged.shader"), "").expect("write");
        std::fs::write(elsewhere.path().join("kept/deep.shader"), "").expect("write");
        #[cfg(unix)]
        {
            use std::os::unix::fs::symlink;
            // Links to files and folders elsewhere, as a sandbox stages them, are followed; a
            // second name for a file found already, a link to a folder above and one that leads
            // nowhere add nothing.
            symlink(elsewhere.path().join("staged.shader"), root.join("l.shader")).expect("link");
            symlink(elsewhere.path().join("kept"), root.join("m")).expect("link");
            symlink(root.join("b.shader"), root.join("link.shader")).expect("link");
            symlink(root.join("sub"), root.join("linked")).expect("link");
            symlink(root, root.join("sub/z/up")).expect("link");
            symlink(root.join("nothing.shader"), root.join("dangling.shader")).expect("link");
        }
        let names = |links_out| {
            let found = find_files(&[root.to_path_buf()], &SHADER_EXTENSIONS, links_out).expect("walk");
            let names: Vec<String> =
                found.files.iter().map(|p| crate::source::relative_to(p, root)).collect();
            (names, found.links_refused)
        };
        // Entries by their names' bytes: `sub` before `sub.shader`, a folder's files where it sorts.
        #[cfg(unix)]
        {
            let followed = [
                "a.SHADER",
                "b.shader",
                "l.shader",
                "m/deep.shader",
                "sub/b.shader",
                "sub/z/c.shader",
                "sub.shader",
            ];
            assert_eq!(names(LinksOut::Followed), (followed.map(String::from).to_vec(), 0));
            let refused = ["a.SHADER", "b.shader", "sub/b.shader", "sub/z/c.shader", "sub.shader"];
            assert_eq!(
                names(LinksOut::Refused),
                (refused.map(String::from).to_vec(), 2),
                "links out skipped, counted"
            );
        }
    }
}
