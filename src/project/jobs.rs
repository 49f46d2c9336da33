//! The jobs over a whole project: build (whole, a shard, or a check for an editor), merge,
//! watch and list, each from settings resolved once ([`Settings::resolve`]: the caller's
//! [`Request`], the environment, `kiln.toml`) and the run's own decisions ([`Run`]).

use super::ProjectError;
use super::workspace::{
    Workspace, include_config, load_files, load_variant_logs, open_workspace, unknown_group_names,
};
use crate::catalog::{Catalog, CatalogInput, catalog};
use crate::config::{Environment, Request, Settings};
use crate::diagnostics::{self, Diagnostic};
use crate::orchestrate::{BuildResult, Cancel, Part, Run, Writes, build};
use crate::preprocess::Includes;
use crate::source::{SourceStore, Span, Spanned};
use std::path::PathBuf;

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

/// Builds (or checks) the projects and files at `paths`. `Err` only when a path does not exist.
pub fn build_project(
    store: &mut SourceStore,
    paths: &[PathBuf],
    request: &Request,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<(BuildResult, Vec<Diagnostic>), ProjectError> {
    build_part(store, paths, request, progress, Part::Whole)
}

/// [`build_project`] for a part of the work.
pub fn build_part(
    store: &mut SourceStore,
    paths: &[PathBuf],
    request: &Request,
    progress: &(dyn Fn(usize, usize) + Sync),
    part: Part,
) -> Result<(BuildResult, Vec<Diagnostic>), ProjectError> {
    let Given { workspace, mut includes, input, mut diagnostics, settings, given_files } =
        load_given(store, paths, request)?;
    let run = Run { writes: writes(request), part, given_files, cancel: Cancel::default() };
    // Held until the build is done: another build into the folder waits.
    let _lock = request.write.then(|| crate::store::OutputLock::acquire(&settings.output));
    if diagnostics.is_empty()
        && !matches!(run.part, Part::Shard(_))
        && let Some(mut result) = crate::orchestrate::unchanged(store, &settings, run.writes)
    {
        strict_errors(&workspace, &mut result, &mut diagnostics);
        return Ok((result, diagnostics));
    }
    let (catalog, found) = catalog(store, &mut includes, &input);
    diagnostics.extend(found);
    diagnostics.extend(unknown_group_names(store, &workspace.group_names));
    let mut result = build(store, &includes, &catalog, &settings, &run, &diagnostics, progress);
    // At 100,000 variants, freeing the catalogue takes a twentieth of a second nobody waits for.
    std::thread::spawn(move || drop((catalog, includes)));
    strict_errors(&workspace, &mut result, &mut diagnostics);
    Ok((result, diagnostics))
}

/// Under `strict`, every warning a build says is an error: the project's and the catalogue's
/// (`diagnostics`), and the build's own or those a no-op says again (`result`).
fn strict_errors(workspace: &Workspace, result: &mut BuildResult, diagnostics: &mut [Diagnostic]) {
    if workspace.strict {
        diagnostics::promote_warnings(diagnostics);
        diagnostics::promote_warnings(&mut result.diagnostics);
    }
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
    pub summary: crate::orchestrate::BuildSummary,
    /// Everything `kiln check` reports.
    pub diagnostics: Vec<Diagnostic>,
}

/// `kiln check` of the project at `paths`, keeping what it found: never the no-op path (the store
/// may hold texts that are not on disk: [`SourceStore::with_overlay`]), never written. `narrow`
/// may drop variants from the catalogue before anything is compiled (an editor checking the
/// variants it shows first); `cancel` stops it before its next pass (the result is then
/// partial, for the caller to drop).
pub fn check_project(
    store: &mut SourceStore,
    paths: &[PathBuf],
    request: &Request,
    cancel: &Cancel,
    narrow: impl FnOnce(&mut Catalog),
) -> Result<Checked, ProjectError> {
    let request = Request { write: false, ..request.clone() };
    let Given { workspace, mut includes, input, mut diagnostics, settings, given_files } =
        load_given(store, paths, &request)?;
    let (mut catalog, found) = catalog(store, &mut includes, &input);
    diagnostics.extend(found);
    narrow(&mut catalog);
    let run = Run { writes: Writes::Nothing, part: Part::Whole, given_files, cancel: cancel.clone() };
    let result = build(store, &includes, &catalog, &settings, &run, &diagnostics, &|_, _| {});
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

/// What a project is given before anything is parsed: its files, the shaders, materials and
/// variant logs it names (loaded), the settings of a build of it, and how many files that was
/// ([`Run::given_files`]).
struct Given {
    workspace: Workspace,
    includes: Includes,
    input: CatalogInput,
    diagnostics: Vec<Diagnostic>,
    settings: Settings,
    given_files: usize,
}

/// What a build `request` asks for writes: the output, and the record of a clean build.
fn writes(request: &Request) -> Writes {
    if request.write { Writes::OutputAndRecord } else { Writes::Nothing }
}

/// The project at `paths` loaded, and the settings of a build of it, resolved once from
/// `request`, the environment and the project's `kiln.toml`.
fn load_given(store: &mut SourceStore, paths: &[PathBuf], request: &Request) -> Result<Given, ProjectError> {
    let (workspace, mut diagnostics) = open_workspace(store, paths)?;
    // Not after a broken kiln.toml: its error says why nothing was found.
    if workspace.shaders.is_empty() && !diagnostics::has_errors(&diagnostics) {
        diagnostics.push(no_shaders(paths, request.write, workspace.links_refused));
    }
    let includes = Includes::new(workspace.include.clone().unwrap_or_else(|| include_config(paths)));
    let (shaders, found) = load_files(store, &workspace.shaders);
    diagnostics.extend(found);
    let (materials, found) = load_files(store, &workspace.materials);
    diagnostics.extend(found);
    let mut input = workspace.catalog_input(shaders, materials);
    // A usage log named on the command line and not there is a mistake in the command.
    if let Some(missing) = request.variant_logs.iter().find(|path| !path.exists()) {
        return Err(ProjectError::NotFound(missing.clone()));
    }
    load_variant_logs(
        store,
        workspace.variant_logs.iter().chain(&request.variant_logs),
        &mut input,
        &mut diagnostics,
    );
    if let Some(global) = &request.global_keywords {
        input.global_keywords = Some(given_global_keywords(store, global));
    }
    let (settings, said) = Settings::resolve(request, &Environment::of_process(), &workspace.settings);
    diagnostics.extend(said);
    let given_files = store.files_read().count();
    Ok(Given { workspace, includes, input, diagnostics, settings, given_files })
}

/// A project without shaders: a warning for a build, an error for a check, so that CI pointed at
/// the wrong folder fails.
fn no_shaders(paths: &[PathBuf], build: bool, links_refused: usize) -> Diagnostic {
    let shown: Vec<String> = paths.iter().map(|p| format!("`{}`", p.display())).collect();
    let message = format!("no shaders in {}", shown.join(", "));
    // A folder of no shader is a project not started (a warning for a build); one whose shaders
    // are links kiln did not follow is a build that would ship nothing (a sandbox's staging).
    let diagnostic = match (build, links_refused) {
        (true, 0) => Diagnostic::warning("K0009", message),
        (_, 0) => Diagnostic::error("K0009", message),
        (_, n) => Diagnostic::error("K0009", message).note(format!(
            "{n} links lead out of the project and were not followed; a sandbox that stages its inputs as links (Bazel's) sets `KILN_FOLLOW_LINKS=1` to follow them"
        )),
    };
    diagnostic.help(
        "give the project folder (kiln looks for `.shader` files in it, or in the folders its kiln.toml's \
         `shaders` names) or `.shader` files",
    )
}

/// `kiln merge`: checks the shard outputs against each other, then writes into `request.output` the
/// bytes one build of the project gives, from their parts (no catalogue, no naga). The project is
/// `project`, or the one the shards were built from.
pub fn merge_shards(
    store: &mut SourceStore,
    shards: &[PathBuf],
    project: Option<PathBuf>,
    request: &Request,
) -> Result<(BuildResult, Vec<Diagnostic>), ProjectError> {
    let records = || {
        let (records, inputs) = crate::orchestrate::shard::check_shards(shards)?;
        Ok::<_, ProjectError>(crate::orchestrate::Merge {
            shards: shards.iter().cloned().zip(records).collect(),
            inputs,
        })
    };
    // The shards and the project are read at once (each takes about a tenth of a second at
    // 100,000 variants); without a project given, the first record names it.
    let ((merge, read), given) = match project {
        Some(project) => {
            let read_shards = || records().map(|merge| (merge.read_shards(), merge));
            let (shards, given) = rayon::join(read_shards, || load_given(store, &[project], request));
            let (read, merge) = shards?;
            ((merge, read), given?)
        }
        None => {
            let merge = records()?;
            let project = PathBuf::from(&merge.shards[0].1.project);
            let (read, given) =
                rayon::join(|| merge.read_shards(), || load_given(store, &[project], request));
            ((merge, read), given?)
        }
    };
    let Given { workspace, mut diagnostics, settings, .. } = given;
    // As a build holds its output folder: another build or merge into it waits.
    let _lock = crate::store::OutputLock::acquire(&settings.output);
    let mut result = crate::orchestrate::merge(store, &settings, writes(request), &diagnostics, &merge, read);
    // The shards' parts are many small strings: freeing them would hold up the answer for a
    // tenth of a second at 100,000 variants, which a process about to exit need not wait for.
    std::thread::spawn(move || drop(merge));
    strict_errors(&workspace, &mut result, &mut diagnostics);
    Ok((result, diagnostics))
}

/// One build of `kiln watch`: [`build_project`], and then, in the output folder, the rendered
/// diagnostics of a build with errors ([`ERRORS_FILE`](crate::manifest::ERRORS_FILE)),
/// removed again by a build without. A failed build writes nothing else, so a program running
/// on the folder keeps the last good build and can say why the new one is not there.
pub fn watch_build(
    store: &mut SourceStore,
    paths: &[PathBuf],
    request: &Request,
) -> Result<(BuildResult, Vec<Diagnostic>), ProjectError> {
    // The output folder keeps each pass's last build only; where no shared cache is set, one of
    // the user's keeps every module built, so that an edit undone compiles nothing.
    let request = Request {
        fallback_cache_dir: request
            .fallback_cache_dir
            .clone()
            .or_else(|| Some(user_cache_dir().join("watch-modules"))),
        ..request.clone()
    };
    let (result, diagnostics) = build_project(store, paths, &request, &|_, _| {})?;
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

/// `kiln preview`'s build of a project: [`build_project`] as `kiln build` runs it, into a folder
/// of the user's cache kept per project (`preview/` and a hash of the project's path), so that
/// the project's own output is left as it was and a second preview rebuilds only what changed.
/// Modules go to the cache `kiln watch` keeps, where the project names none.
pub fn preview_build(
    store: &mut SourceStore,
    project: &std::path::Path,
) -> Result<(BuildResult, Vec<Diagnostic>), ProjectError> {
    let root = std::fs::canonicalize(project).unwrap_or_else(|_| project.to_path_buf());
    let key = blake3::hash(root.as_os_str().as_encoded_bytes()).to_hex();
    let request = Request {
        output: Some(user_cache_dir().join("preview").join(&key[..16])),
        fallback_cache_dir: Some(user_cache_dir().join("watch-modules")),
        ..Request::default()
    };
    build_project(store, &[project.to_path_buf()], &request, &|_, _| {})
}

/// kiln's folder in the user's cache (`$XDG_CACHE_HOME/kiln`, else `~/.cache/kiln`), for the
/// caches of the long-running jobs (`kiln watch`, `kiln lsp`) where the project names none.
pub fn user_cache_dir() -> PathBuf {
    std::env::var_os("XDG_CACHE_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|home| PathBuf::from(home).join(".cache")))
        .unwrap_or_else(std::env::temp_dir)
        .join("kiln")
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
