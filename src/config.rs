//! A build's settings and where they come from: `kiln.toml` ([`ProjectConfig`]: where a
//! project's shaders, materials and includes are, and what a build emits; every field has a
//! default, so a folder of `.shader` and `.mat` files needs no file at all), the caller's
//! [`Request`] (the command line, a build script, the language server), and the [`Environment`].
//! [`Settings::resolve`] makes one [`Settings`] of them by one rule (the request, else the
//! environment, else `kiln.toml`, else kiln's default), and the build is given only that.
//!
//! A new setting is a field of [`Settings`], of [`Request`] and (where a project may set it) of
//! [`ProjectConfig`], its line in [`Settings::resolve`], all in this file; then its flag in the
//! command line and the code that reads it.

use crate::compile::bind::GroupNames;
use crate::compile::glslang::Glslang;
use crate::diagnostics::Diagnostic;
pub use crate::manifest::Backend;
use crate::source::{FileId, SourceStore, Span};
use crate::store::remote::{Credentials, RemoteConfig, RemoteMode, UrlSource, check_url, credentials_for};
use serde::Deserialize;
use std::path::{Path, PathBuf};
use std::time::Duration;

/// The project file's name, looked for in the project folder.
pub const FILE_NAME: &str = "kiln.toml";

/// `kiln.toml`: a project's settings (docs/project.md), every field defaulted.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ProjectConfig {
    /// Folders searched for `.shader` files, relative to the project folder.
    pub shaders: Vec<PathBuf>,
    /// Folders searched for `.mat` files.
    pub materials: Vec<PathBuf>,
    /// Folders `#include` searches after the including file's own folder.
    pub include_paths: Vec<PathBuf>,
    /// Where builds write their output.
    pub output: PathBuf,
    /// The back ends each stage module is written for (default: both).
    pub backends: Vec<Backend>,
    /// Shaders built with every variant, whether or not a material uses them (by shader name).
    pub always_include: Vec<String>,
    /// The renderer's global keyword state, when it is known (a scene's light setup, say): each
    /// `multi_compile` set is then built only with the option these choose (docs/keywords.md).
    /// Unset: every option of every set.
    pub global_keywords: Option<Vec<toml::Spanned<String>>>,
    /// Warnings count as errors.
    pub strict: bool,
    /// Variant usage logs (JSON Lines, as `kiln_runtime::UsageLog` writes them): the variants
    /// they name are built besides those the materials use.
    pub variant_logs: Vec<PathBuf>,
    /// A module cache shared between builds and machines (docs/scaling.md).
    pub cache_dir: Option<PathBuf>,
    /// The team's cache on an HTTP server, `http://host:port/prefix` (docs/scaling.md).
    pub remote_cache: Option<toml::Spanned<String>>,
    /// What builds may do with it: `read`, `write` (read and publish; the default) or `off`.
    pub remote_cache_mode: Option<crate::store::remote::RemoteMode>,
    /// The variants of each compute shader to build (`[compute.NAME]`), which no material
    /// selects (docs/compute.md).
    pub compute: std::collections::BTreeMap<String, ComputeConfig>,
    /// Resource names the project binds per frame or per object, besides kiln's own
    /// (`[bind_groups]`, docs/project.md).
    pub bind_groups: BindGroupsConfig,
}

/// `[bind_groups]`: names added to the per-frame (0) and per-object (2) groups.
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct BindGroupsConfig {
    /// Bound once per frame, in group 0 (kiln's own: `UnityPerFrame`, `_CustomLight`).
    pub per_frame: Vec<toml::Spanned<String>>,
    /// Bound once per object, in group 2 (kiln's own: `UnityPerDraw`).
    pub per_object: Vec<toml::Spanned<String>>,
}

/// `[compute.NAME]`: which variants of a compute shader are built.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ComputeConfig {
    /// `"all"`, or a list of keyword lists (`[[], ["_SQUARE"]]`), each one variant.
    pub variants: ComputeVariants,
}

/// A compute shader's variants: every one, or those listed.
#[derive(Debug, Clone, PartialEq)]
pub enum ComputeVariants {
    /// `"all"`: every variant, as `always_include` builds a shader.
    All,
    /// Keyword lists, each choosing one variant as a usage log line does.
    Listed(Vec<toml::Spanned<Vec<String>>>),
}

// By hand, not `untagged`: the lists keep their places in the file (`toml::Spanned`).
impl<'de> Deserialize<'de> for ComputeVariants {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<ComputeVariants, D::Error> {
        struct Visitor;
        impl<'de> serde::de::Visitor<'de> for Visitor {
            type Value = ComputeVariants;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str(r#""all", or a list of keyword lists such as [[], ["_SQUARE"]]"#)
            }
            fn visit_str<E: serde::de::Error>(self, word: &str) -> Result<ComputeVariants, E> {
                match word {
                    "all" => Ok(ComputeVariants::All),
                    _ => Err(E::invalid_value(serde::de::Unexpected::Str(word), &self)),
                }
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<ComputeVariants, A::Error> {
                let mut lists = Vec::new();
                while let Some(list) = seq.next_element()? {
                    lists.push(list);
                }
                Ok(ComputeVariants::Listed(lists))
            }
        }
        deserializer.deserialize_any(Visitor)
    }
}

impl Default for ProjectConfig {
    fn default() -> ProjectConfig {
        ProjectConfig {
            shaders: vec![PathBuf::from(".")],
            materials: vec![PathBuf::from(".")],
            include_paths: Vec::new(),
            output: PathBuf::from("build/kiln"),
            backends: Backend::DEFAULT.to_vec(),
            always_include: Vec::new(),
            global_keywords: None,
            strict: false,
            variant_logs: Vec::new(),
            cache_dir: None,
            remote_cache: None,
            remote_cache_mode: None,
            compute: Default::default(),
            bind_groups: Default::default(),
        }
    }
}

/// Reads a loaded `kiln.toml`; a malformed one is reported and the defaults are used.
pub fn parse_config(store: &SourceStore, file: FileId) -> (ProjectConfig, Vec<Diagnostic>) {
    match toml::from_str(store.text(file)) {
        Ok(config) => (config, Vec::new()),
        Err(error) => {
            let span = Span::new(file, error.span().unwrap_or(0..0));
            let message = error.message().trim().trim_end_matches('.').to_string();
            // serde lists the fields after an unknown one; said once, in the help, with the closest.
            let (message, unknown) = match message.split_once(", expected one of") {
                Some((head, _)) => {
                    let field = head.strip_prefix("unknown field `").and_then(|f| f.strip_suffix('`'));
                    (head.to_string(), field.map(str::to_string))
                }
                None => (message, None),
            };
            let suggestion = unknown
                .and_then(|field| crate::diagnostics::closest(&field, FIELDS.iter().copied()))
                .map(|near| format!("did you mean `{near}`? "))
                .unwrap_or_default();
            let diagnostic = Diagnostic::error("K0003", "invalid `kiln.toml`")
                .at(span, message)
                .help(format!("{suggestion}fields are {} (docs/project.md)", FIELDS.join(", ")));
            (ProjectConfig::default(), vec![diagnostic])
        }
    }
}

/// The fields of `kiln.toml`, as a message lists them.
const FIELDS: &[&str] = &[
    "shaders",
    "materials",
    "include_paths",
    "output",
    "backends",
    "always_include",
    "global_keywords",
    "strict",
    "variant_logs",
    "cache_dir",
    "remote_cache",
    "remote_cache_mode",
    "compute",
    "bind_groups",
];

/// The first project folder's `kiln.toml` (its defaults where there is none): the project's layer
/// of a build's settings, with what [`Settings::resolve`] needs to place them.
#[derive(Debug, Clone, Default)]
pub struct ProjectSettings {
    /// The project folder (the first folder given, or the folder of the first file): what the
    /// build records about files is relative to it.
    pub root: PathBuf,
    /// The folder whose `kiln.toml` this is: its paths are relative to it.
    pub folder: PathBuf,
    /// The file, where there is one: where a setting kiln cannot use is reported.
    pub file: Option<FileId>,
    /// What it says.
    pub config: ProjectConfig,
    /// The names every project folder's `[bind_groups]` adds.
    pub groups: GroupNames,
}

impl ProjectSettings {
    /// A path the file names, as the build uses it (joined to its folder).
    fn path(&self, relative: &Path) -> PathBuf {
        crate::source::normalize_lexically(&self.folder.join(relative))
    }

    /// The project's output folder (`output`, default `build/kiln`).
    pub fn output(&self) -> PathBuf {
        self.path(&self.config.output)
    }

    /// The shared module cache a command uses: `given`, else `KILN_CACHE_DIR`, else the project's
    /// `cache_dir`.
    pub fn shared_cache_dir(&self, given: Option<PathBuf>, environment: &Environment) -> Option<PathBuf> {
        given
            .or_else(|| environment.cache_dir.clone())
            .or_else(|| self.config.cache_dir.as_deref().map(|c| self.path(c)))
    }
}

/// What a caller asks of a build: the command line, a build script and the language server each
/// fill one. A setting left unset is the environment's, else the project's, else kiln's default
/// ([`Settings::resolve`]).
#[derive(Debug, Clone)]
pub struct Request {
    /// Write the output (`false` for `kiln check`).
    pub write: bool,
    /// Overrides the project's `output` folder.
    pub output: Option<PathBuf>,
    /// What is built of shaders no material uses.
    pub unused_shaders: VariantSelection,
    /// Worker threads; else `RAYON_NUM_THREADS`, else one per core.
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
}

impl Default for Request {
    /// `kiln build` as it runs without options: written, the project's output folder, the
    /// variants the materials use, every core.
    fn default() -> Request {
        Request {
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
        }
    }
}

/// The environment variables kiln's settings read, read once ([`Environment::of_process`]) so
/// that resolving settings depends on nothing else. An empty variable is an unset one.
#[derive(Debug, Clone, Default)]
pub struct Environment {
    /// `KILN_CACHE_DIR`.
    pub cache_dir: Option<PathBuf>,
    /// `KILN_REMOTE_CACHE`.
    pub remote_cache: Option<String>,
    /// `KILN_REMOTE_CACHE_MODE`.
    pub remote_cache_mode: Option<String>,
    /// `KILN_REMOTE_CACHE_TIMEOUT`: seconds a step of a request may take (default 10).
    pub remote_cache_timeout: Option<String>,
    /// `KILN_REMOTE_CACHE_BUDGET`: seconds all of them may take (default 30).
    pub remote_cache_budget: Option<String>,
    /// `KILN_REMOTE_CACHE_HOST`: the one host a project's URL may send credentials to.
    pub remote_cache_host: Option<String>,
    /// `KILN_REMOTE_CACHE_TOKEN`, or `KILN_REMOTE_CACHE_USER` and `_PASSWORD`.
    pub credentials: Option<Credentials>,
    /// `RAYON_NUM_THREADS`.
    pub threads: Option<String>,
    /// The cores this process may use.
    pub cores: usize,
}

impl Environment {
    /// This process's environment.
    pub fn of_process() -> Environment {
        let var = |name: &str| std::env::var(name).ok().filter(|v| !v.is_empty());
        Environment {
            cache_dir: std::env::var_os("KILN_CACHE_DIR").filter(|v| !v.is_empty()).map(PathBuf::from),
            remote_cache: var("KILN_REMOTE_CACHE"),
            remote_cache_mode: var("KILN_REMOTE_CACHE_MODE"),
            remote_cache_timeout: var("KILN_REMOTE_CACHE_TIMEOUT"),
            remote_cache_budget: var("KILN_REMOTE_CACHE_BUDGET"),
            remote_cache_host: var("KILN_REMOTE_CACHE_HOST"),
            credentials: Credentials::from_env(),
            threads: var("RAYON_NUM_THREADS"),
            cores: std::thread::available_parallelism().map_or(1, usize::from),
        }
    }
}

/// The most worker threads a build starts: far more threads than cores only costs memory, and a
/// mistyped count, from either place, must not exhaust it.
pub const MAX_THREADS: usize = 1024;

/// Which variants of a shader no material uses are compiled.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VariantSelection {
    /// None: only what materials (and `always_include`) need. `kiln build`.
    Used,
    /// The default variant and each keyword on its own. `kiln check`.
    DefaultsAndEachKeyword,
    /// The full product, refused above `limit` variants per pass. `kiln check --all-variants`.
    All {
        /// The most variants a pass may have.
        limit: u128,
    },
}

/// What naga parses of a stage text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParseScope {
    /// The declarations its entry point reaches (`compile::reach`), the texts of a pass's
    /// variants parsed together where they share declarations (`compile::together`): `kiln
    /// build`. An error in code no entry point reaches is not seen.
    Together,
    /// The declarations its entry point reaches, each text parsed alone (`kiln build
    /// --parse-alone`).
    Reachable,
    /// All of it, as preprocessed: `kiln check`, which reports errors anywhere in a variant's
    /// text.
    Whole,
}

/// A build's settings, resolved once ([`Settings::resolve`]): the build reads no request,
/// environment variable or `kiln.toml` of its own.
#[derive(Debug, Clone)]
pub struct Settings {
    /// The output folder.
    pub output: PathBuf,
    /// The project folder: the manifest's shader paths and the cache's keys are relative to it,
    /// so that a project builds the same bytes wherever it sits.
    pub root: PathBuf,
    /// What naga parses of each stage text.
    pub parse: ParseScope,
    /// Worker threads.
    pub threads: usize,
    /// The back ends each stage module is written for.
    pub backends: Vec<Backend>,
    /// What is built of shaders no material uses.
    pub unused_shaders: VariantSelection,
    /// Write `manifest.json` indented (default: compact).
    pub pretty_manifest: bool,
    /// A module cache shared with other builds: modules are taken from it before naga runs,
    /// and every module compiled is published to it.
    pub cache_dir: Option<PathBuf>,
    /// The team's cache on an HTTP server: asked after `cache_dir`, and given what the build
    /// compiled when its mode allows (docs/scaling.md).
    pub remote_cache: Option<RemoteConfig>,
    /// The resource names the project adds to the per-frame and per-object bind groups.
    pub groups: GroupNames,
    /// Reads back the GLSL and HLSL each module is written in: a check, where glslang is
    /// installed.
    pub glslang: Option<Glslang>,
}

impl Settings {
    /// The settings of a build `request` asks of the project, by one rule: what the request
    /// sets, else the environment, else the project's `kiln.toml`, else kiln's default. With
    /// what was found wrong in them: a setting kiln cannot use (K0013, where it is written;
    /// the remote cache is then left out), credentials withheld (K0621).
    pub fn resolve(
        request: &Request,
        environment: &Environment,
        project: &ProjectSettings,
    ) -> (Settings, Vec<Diagnostic>) {
        let backends: Vec<Backend> = Backend::ALL
            .iter()
            .copied()
            .filter(|b| project.config.backends.contains(b) || request.backends.contains(b))
            .collect();
        let parse =
            request.parse.unwrap_or(if request.write { ParseScope::Together } else { ParseScope::Whole });
        let (remote_cache, said) = match remote_cache(request, environment, project) {
            Ok((config, said)) => (config, said),
            Err(error) => (None, Some(error)),
        };
        // A check reads the GLSL and HLSL it writes back, where glslang is installed.
        let reread = !request.write && backends.iter().any(|&b| Glslang::reads(b));
        let settings = Settings {
            output: request.output.clone().unwrap_or_else(|| project.output()),
            root: project.root.clone(),
            parse,
            threads: threads_for(request.threads, environment),
            backends,
            unused_shaders: request.unused_shaders,
            pretty_manifest: request.pretty_manifest,
            cache_dir: project
                .shared_cache_dir(request.cache_dir.clone(), environment)
                .or_else(|| request.fallback_cache_dir.clone()),
            remote_cache,
            groups: project.groups.clone(),
            glslang: reread.then(Glslang::find).flatten(),
        };
        (settings, said.into_iter().collect())
    }

    /// A one-off build of what a caller catalogued itself (a shader to reflect, the accuracy
    /// harness): one thread, both back ends, no shared cache.
    pub fn one_off(root: PathBuf, output: PathBuf) -> Settings {
        Settings {
            output,
            root,
            parse: ParseScope::Together,
            threads: 1,
            backends: Backend::DEFAULT.to_vec(),
            unused_shaders: VariantSelection::Used,
            pretty_manifest: false,
            cache_dir: None,
            remote_cache: None,
            groups: GroupNames::default(),
            glslang: None,
        }
    }
}

/// The worker threads for a build: `requested` (`--threads`), else `RAYON_NUM_THREADS`, else one
/// per core; never more than [`MAX_THREADS`], and never none.
pub fn threads_for(requested: Option<usize>, environment: &Environment) -> usize {
    let from_environment =
        environment.threads.as_deref().and_then(|n| n.trim().parse::<usize>().ok()).filter(|&n| n > 0);
    requested.filter(|&n| n > 0).or(from_environment).unwrap_or(environment.cores.max(1)).min(MAX_THREADS)
}

/// The remote cache a build uses (docs/scaling.md): the URL, else none; its mode, else `write`;
/// each step of a request limited to `KILN_REMOTE_CACHE_TIMEOUT` seconds (default 10), all of
/// them to `KILN_REMOTE_CACHE_BUDGET` (default 30); credentials from the environment where
/// [`credentials_for`] allows them, else a warning (K0621) saying why the build runs without.
/// A setting kiln cannot use is an error (K0013) where it is written.
fn remote_cache(
    request: &Request,
    environment: &Environment,
    project: &ProjectSettings,
) -> Result<(Option<RemoteConfig>, Option<Diagnostic>), Diagnostic> {
    let written = |spanned: &toml::Spanned<String>| project.file.map(|file| Span::new(file, spanned.span()));
    let invalid = |what: String, span: Option<Span>| {
        let d = Diagnostic::error("K0013", format!("invalid remote cache setting: {what}"));
        let d = match span {
            Some(span) => d.at(span, "set here"),
            None => d,
        };
        d.help("give `http://host:port/prefix` or `https://...`, and a mode of `read`, `write` or `off` (docs/scaling.md)")
    };
    let (url, span) = match (&request.remote_cache, &environment.remote_cache, &project.config.remote_cache) {
        (Some(url), ..) | (None, Some(url), _) => (url.clone(), None),
        (None, None, Some(url)) => (url.get_ref().clone(), written(url)),
        (None, None, None) => return Ok((None, None)),
    };
    let url = check_url(&url).map_err(|why| invalid(format!("the URL: {why}"), span))?;
    let chosen = match (request.remote_cache_mode, &environment.remote_cache_mode) {
        (Some(chosen), _) => chosen,
        (None, Some(name)) => RemoteMode::parse(name)
            .ok_or_else(|| invalid(format!("KILN_REMOTE_CACHE_MODE is `{}`", name.escape_debug()), None))?,
        (None, None) => project.config.remote_cache_mode.unwrap_or_default(),
    };
    let seconds = |name: &str, value: &Option<String>, default: u64| match value {
        None => Ok(Duration::from_secs(default)),
        Some(seconds) => seconds
            .parse::<f64>()
            .ok()
            .filter(|s| s.is_finite() && *s > 0.0 && *s <= 3600.0)
            .map(Duration::from_secs_f64)
            .ok_or_else(|| invalid(format!("{name} is `{}`, not seconds", seconds.escape_debug()), None)),
    };
    let timeout = seconds("KILN_REMOTE_CACHE_TIMEOUT", &environment.remote_cache_timeout, 10)?;
    let budget = seconds("KILN_REMOTE_CACHE_BUDGET", &environment.remote_cache_budget, 30)?;
    let source = if span.is_some() { UrlSource::Project } else { UrlSource::User };
    let (credentials, withheld) = match &environment.credentials {
        None => (None, None),
        Some(credentials) => match credentials_for(&url, source, environment.remote_cache_host.as_deref()) {
            Ok(()) => (Some(credentials.clone()), None),
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A project whose `kiln.toml` is `text`, in the folder `project`.
    fn project(store: &mut SourceStore, text: &str) -> ProjectSettings {
        let file = store.add("project/kiln.toml", text);
        let (config, problems) = parse_config(store, file);
        assert!(problems.is_empty(), "{problems:?}");
        let folder = PathBuf::from("project");
        ProjectSettings {
            root: folder.clone(),
            folder,
            file: Some(file),
            config,
            groups: GroupNames::default(),
        }
    }

    fn environment(set: &[(&str, &str)]) -> Environment {
        let get = |name: &str| set.iter().find(|(n, _)| *n == name).map(|(_, v)| v.to_string());
        Environment {
            cache_dir: get("KILN_CACHE_DIR").map(PathBuf::from),
            remote_cache: get("KILN_REMOTE_CACHE"),
            remote_cache_mode: get("KILN_REMOTE_CACHE_MODE"),
            remote_cache_timeout: get("KILN_REMOTE_CACHE_TIMEOUT"),
            remote_cache_budget: get("KILN_REMOTE_CACHE_BUDGET"),
            remote_cache_host: get("KILN_REMOTE_CACHE_HOST"),
            credentials: None,
            threads: get("RAYON_NUM_THREADS"),
            cores: 16,
        }
    }

    const PROJECT: &str = r#"
output = "out/project"
backends = ["wgsl", "msl"]
cache_dir = "cache/project"
remote_cache = "http://project.example:8080/kiln"
remote_cache_mode = "read"
"#;

    #[test]
    fn each_setting_is_the_request_s_then_the_environment_s_then_the_project_s_then_the_default() {
        let mut store = SourceStore::new();
        let configured = project(&mut store, PROJECT);
        let bare = project(&mut store, "");
        let everywhere = environment(&[
            ("KILN_CACHE_DIR", "cache/environment"),
            ("KILN_REMOTE_CACHE", "http://environment.example/kiln"),
            ("KILN_REMOTE_CACHE_MODE", "off"),
            ("RAYON_NUM_THREADS", "7"),
        ]);
        let asked = Request {
            output: Some("out/asked".into()),
            threads: Some(3),
            cache_dir: Some("cache/asked".into()),
            remote_cache: Some("http://asked.example/kiln".into()),
            remote_cache_mode: Some(RemoteMode::Write),
            backends: vec![Backend::Glsl],
            ..Request::default()
        };
        let resolve = |request: &Request, environment: &Environment, project: &ProjectSettings| {
            let (settings, said) = Settings::resolve(request, environment, project);
            assert!(said.is_empty(), "{said:?}");
            let remote = settings.remote_cache.as_ref().map(|r| (r.url.clone(), r.mode));
            (settings.output, settings.threads, settings.cache_dir, remote, settings.backends)
        };
        let remote = |url: &str, mode| Some((url.to_string(), mode));
        // The request wins over everything; its back ends add to the project's.
        assert_eq!(
            resolve(&asked, &everywhere, &configured),
            (
                "out/asked".into(),
                3,
                Some("cache/asked".into()),
                remote("http://asked.example/kiln", RemoteMode::Write),
                vec![Backend::Wgsl, Backend::Msl, Backend::Glsl],
            )
        );
        // Then the environment (the output folder has no variable).
        assert_eq!(
            resolve(&Request::default(), &everywhere, &configured),
            (
                "project/out/project".into(),
                7,
                Some("cache/environment".into()),
                remote("http://environment.example/kiln", RemoteMode::Off),
                vec![Backend::Wgsl, Backend::Msl],
            )
        );
        // Then the project, its paths placed in its folder.
        assert_eq!(
            resolve(&Request::default(), &environment(&[]), &configured),
            (
                "project/out/project".into(),
                16,
                Some("project/cache/project".into()),
                remote("http://project.example:8080/kiln", RemoteMode::Read),
                vec![Backend::Wgsl, Backend::Msl],
            )
        );
        // Then kiln's defaults: the cores, no cache but the caller's fallback, WGSL and SPIR-V.
        let fallback = Request { fallback_cache_dir: Some("cache/fallback".into()), ..Request::default() };
        assert_eq!(
            resolve(&fallback, &environment(&[]), &bare),
            ("project/build/kiln".into(), 16, Some("cache/fallback".into()), None, Backend::DEFAULT.to_vec())
        );
        // A check parses whole texts, a build what entry points reach, unless asked otherwise.
        let check = Request { write: false, ..Request::default() };
        let parse = |request: &Request| Settings::resolve(request, &environment(&[]), &bare).0.parse;
        assert_eq!((parse(&Request::default()), parse(&check)), (ParseScope::Together, ParseScope::Whole));
        let alone = Request { parse: Some(ParseScope::Reachable), ..check };
        assert_eq!(parse(&alone), ParseScope::Reachable);
    }

    #[test]
    fn a_remote_cache_setting_kiln_cannot_use_is_an_error_where_it_is_written() {
        let mut store = SourceStore::new();
        let text = "remote_cache = \"ftp://project.example/kiln\"\n";
        let broken = project(&mut store, text);
        let (settings, said) = Settings::resolve(&Request::default(), &environment(&[]), &broken);
        assert!(settings.remote_cache.is_none(), "the cache is left out");
        assert_eq!(said.len(), 1, "{said:?}");
        assert_eq!((said[0].code, said[0].severity), ("K0013", crate::diagnostics::Severity::Error));
        let at = said[0].primary.as_ref().map(|label| label.span.range());
        let written = text.find('"').map(|at| at..text.trim_end().len());
        assert_eq!(at, written, "at the URL as kiln.toml writes it, quotes included");
        // A variable's mistake has no place in a file, and names the variable.
        let slow = environment(&[("KILN_REMOTE_CACHE_TIMEOUT", "soon")]);
        let (_, said) = Settings::resolve(&Request::default(), &slow, &project(&mut store, PROJECT));
        assert!(said[0].message.contains("KILN_REMOTE_CACHE_TIMEOUT is `soon`"), "{said:?}");
        assert!(said[0].primary.is_none());
    }

    #[test]
    fn threads_come_from_the_request_then_the_environment_then_the_cores_and_are_bounded() {
        let cores = |threads: Option<&str>| Environment {
            threads: threads.map(str::to_string),
            cores: 16,
            ..Environment::default()
        };
        assert_eq!(threads_for(Some(3), &cores(Some("7"))), 3);
        assert_eq!(threads_for(None, &cores(Some("7"))), 7);
        assert_eq!(
            threads_for(None, &cores(Some("100000"))),
            MAX_THREADS,
            "RAYON_NUM_THREADS is bounded too"
        );
        assert_eq!(threads_for(Some(100_000), &cores(None)), MAX_THREADS);
        assert_eq!(threads_for(None, &cores(Some("lots"))), 16);
        assert_eq!(threads_for(Some(0), &cores(Some("0"))), 16);
        assert_eq!(threads_for(None, &Environment::default()), 1, "no core known is one thread");
    }
}
