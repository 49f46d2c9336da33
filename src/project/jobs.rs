//! The jobs over a whole project: build (whole, a shard, or a check for an editor), merge,
//! watch and list, each from options made once ([`BuildMode`] resolved against `kiln.toml`).

use super::ProjectError;
use super::workspace::{
    Workspace, include_config, load_files, load_variant_logs, open_workspace, unknown_group_names,
};
use crate::catalog::{Catalog, CatalogInput, catalog};
use crate::compile::glslang::Glslang;
use crate::diagnostics::{self, Diagnostic};
use crate::manifest::Backend;
use crate::orchestrate::{BuildOptions, BuildResult, Cancel, ParseScope, Part, VariantSelection, build};
use crate::preprocess::Includes;
use crate::source::{SourceStore, Span, Spanned};
use crate::store::remote::{Credentials, RemoteConfig, RemoteMode, UrlSource, check_url, credentials_for};
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
    /// The remote cache's URL; else `KILN_REMOTE_CACHE`, else the project's `remote_cache`.
    pub remote_cache: Option<String>,
    /// What the build may do with it; else `KILN_REMOTE_CACHE_MODE`, else the project's
    /// `remote_cache_mode`, else `write`.
    pub remote_cache_mode: Option<RemoteMode>,
    /// Back ends written (or checked) besides the project's `backends` (`--backends`).
    pub backends: Vec<Backend>,
    /// What naga parses of each stage text; else the declarations each entry point reaches for
    /// a build, the whole text for a check (`--parse-whole`).
    pub parse: Option<ParseScope>,
    /// Set by the caller to stop a check early (the language server, when a newer edit makes
    /// it moot): no pass starts after it is set, and the result is partial. A build that
    /// writes is never stopped.
    pub cancel: Cancel,
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
            remote_cache: None,
            remote_cache_mode: None,
            backends: Vec::new(),
            parse: None,
            cancel: Cancel::default(),
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
        && let Some(result) = crate::orchestrate::unchanged(store, &options)
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
    pub summary: crate::orchestrate::BuildSummary,
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
        diagnostics.push(no_shaders(paths, mode.write, workspace.links_refused));
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
    let (remote_cache, said) = remote_cache(&workspace, mode).unwrap_or_else(|error| (None, Some(error)));
    diagnostics.extend(said);
    let options = BuildOptions {
        output: mode.output.clone().unwrap_or_else(|| workspace.output.clone()),
        root: workspace.root.clone(),
        write: mode.write,
        parse: mode.parse.unwrap_or(if mode.write { ParseScope::Together } else { ParseScope::Whole }),
        threads: mode.threads,
        backends: Backend::ALL
            .iter()
            .copied()
            .filter(|b| workspace.backends.contains(b) || mode.backends.contains(b))
            .collect(),
        unused_shaders: mode.unused_shaders,
        pretty_manifest: mode.pretty_manifest,
        record: true,
        part,
        cache_dir: workspace
            .shared_cache_dir(mode.cache_dir.clone())
            .or_else(|| mode.fallback_cache_dir.clone()),
        remote_cache,
        given_files: store.files_read().count(),
        groups: workspace.groups.clone(),
        glslang: None,
        cancel: mode.cancel.clone(),
    };
    // A check reads the GLSL and HLSL it writes back with glslang, where it is installed.
    let reread = !options.write && options.backends.iter().any(|&b| Glslang::reads(b));
    let options = BuildOptions { glslang: reread.then(Glslang::find).flatten(), ..options };
    Ok(Given { workspace, includes, input, diagnostics, options })
}

/// The remote cache a build uses (docs/scaling.md): the URL given (`--remote-cache`), else
/// `KILN_REMOTE_CACHE`, else the project's `remote_cache`; its mode given, else
/// `KILN_REMOTE_CACHE_MODE`, else the project's `remote_cache_mode`, else `write`; each step of
/// a request limited to `KILN_REMOTE_CACHE_TIMEOUT` seconds (default 10), all of them to
/// `KILN_REMOTE_CACHE_BUDGET` (default 30); credentials from the environment where
/// [`credentials_for`] allows them, else a warning (K0621) saying why the build runs without.
/// A setting kiln cannot use is an error (K0013) where it is written.
fn remote_cache(
    workspace: &Workspace,
    mode: &BuildMode,
) -> Result<(Option<RemoteConfig>, Option<Diagnostic>), Diagnostic> {
    let invalid = |what: String, span: Option<crate::source::Span>| {
        let d = Diagnostic::error("K0013", format!("invalid remote cache setting: {what}"));
        let d = match span {
            Some(span) => d.at(span, "set here"),
            None => d,
        };
        d.help("give `http://host:port/prefix` or `https://...`, and a mode of `read`, `write` or `off` (docs/scaling.md)")
    };
    let env = |name: &str| std::env::var(name).ok().filter(|v| !v.is_empty());
    let (url, span) = match (mode.remote_cache.clone(), env("KILN_REMOTE_CACHE"), &workspace.remote_cache) {
        (Some(url), ..) | (None, Some(url), _) => (url, None),
        (None, None, Some(url)) => (url.value.clone(), Some(url.span)),
        (None, None, None) => return Ok((None, None)),
    };
    let url = check_url(&url).map_err(|why| invalid(format!("the URL: {why}"), span))?;
    let chosen = match (mode.remote_cache_mode, env("KILN_REMOTE_CACHE_MODE")) {
        (Some(chosen), _) => chosen,
        (None, Some(name)) => RemoteMode::parse(&name)
            .ok_or_else(|| invalid(format!("KILN_REMOTE_CACHE_MODE is `{}`", name.escape_debug()), None))?,
        (None, None) => workspace.remote_cache_mode.unwrap_or_default(),
    };
    let seconds = |name: &str, default: u64| match env(name) {
        None => Ok(std::time::Duration::from_secs(default)),
        Some(seconds) => seconds
            .parse::<f64>()
            .ok()
            .filter(|s| s.is_finite() && *s > 0.0 && *s <= 3600.0)
            .map(std::time::Duration::from_secs_f64)
            .ok_or_else(|| invalid(format!("{name} is `{}`, not seconds", seconds.escape_debug()), None)),
    };
    let (timeout, budget) =
        (seconds("KILN_REMOTE_CACHE_TIMEOUT", 10)?, seconds("KILN_REMOTE_CACHE_BUDGET", 30)?);
    let source = if span.is_some() { UrlSource::Project } else { UrlSource::User };
    let (credentials, withheld) = match Credentials::from_env() {
        None => (None, None),
        Some(credentials) => match credentials_for(&url, source, env("KILN_REMOTE_CACHE_HOST").as_deref()) {
            Ok(()) => (Some(credentials), None),
            Err(why) => {
                let warning = Diagnostic::warning(
                    "K0621",
                    "the remote cache gets no credentials: the build uses it without them".to_string(),
                )
                .note(format!("the environment holds credentials, and they are not sent: {why}"));
                let warning = match span {
                    Some(span) => warning.at(span, "this URL gets no credentials"),
                    None => warning,
                };
                let help = "name the server with `--remote-cache` or `KILN_REMOTE_CACHE` (over `https://`), or pin its host with `KILN_REMOTE_CACHE_HOST`";
                (None, Some(warning.help(help)))
            }
        },
    };
    Ok((Some(RemoteConfig { url, mode: chosen, timeout, budget, credentials }), withheld))
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
    let result = crate::orchestrate::merge(store, &options, &diagnostics, &merge, read);
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
    // The output folder keeps each pass's last build only; where no shared cache is set, one of
    // the user's keeps every module built, so that an edit undone compiles nothing.
    let mode = BuildMode {
        fallback_cache_dir: mode
            .fallback_cache_dir
            .clone()
            .or_else(|| Some(user_cache_dir().join("watch-modules"))),
        ..mode.clone()
    };
    let (result, diagnostics) = build_project(store, paths, &mode, &|_, _| {})?;
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
    let mode = BuildMode {
        output: Some(user_cache_dir().join("preview").join(&key[..16])),
        fallback_cache_dir: Some(user_cache_dir().join("watch-modules")),
        ..BuildMode::default()
    };
    build_project(store, &[project.to_path_buf()], &mode, &|_, _| {})
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
