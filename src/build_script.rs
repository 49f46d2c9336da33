//! The API for renderer crates' `build.rs`: build a project into `OUT_DIR`, generate the Rust
//! module, and speak cargo's protocol: `cargo:rerun-if-changed` for every file read and nothing
//! else, `cargo:warning` for warnings, readable errors.
//!
//! [`Build::run`] is the one place in the library that prints: to stdout, for cargo.

use crate::diagnostics::{self, Diagnostic, Severity, render_plain};
use crate::manifest::{FILE_NAME, Manifest};
use crate::orchestrate::BuildSummary;
use crate::project::{ProjectError, Request, build_project};
use crate::source::SourceStore;
use crate::source::relative_to;
use std::path::{Path, PathBuf};

/// A kiln build from a build script.
///
/// ```no_run
/// // build.rs
/// fn main() -> Result<(), kiln::BuildError> {
///     kiln::Build::new("shaders").run()?;
///     Ok(())
/// }
/// // src/shaders.rs
/// // include!(concat!(env!("OUT_DIR"), "/kiln_shaders.rs"));
/// ```
#[derive(Debug, Clone)]
pub struct Build {
    paths: Vec<PathBuf>,
    out_dir: Option<PathBuf>,
    prebuilt: Option<PathBuf>,
    /// What the methods set, as the command line's flags set it (the output folder is
    /// `OUT_DIR`'s).
    request: Request,
}

/// What a build script gets back.
#[derive(Debug)]
pub struct BuildOutput {
    /// The generated module: `include!` it.
    pub module: PathBuf,
    /// The manifest of the build.
    pub manifest: Manifest,
    /// What was built.
    pub summary: BuildSummary,
    /// `cargo:...` lines: what [`Build::run`] printed (or would print).
    pub cargo_lines: Vec<String>,
}

/// Why a build script fails. Its `Debug` is the rendered diagnostics, because that is what
/// `fn main() -> Result<..>` shows.
#[derive(thiserror::Error)]
// Each variant's fields are named in its message.
#[allow(missing_docs)]
#[non_exhaustive]
pub enum BuildError {
    #[error("kiln found errors in the shaders:\n{rendered}")]
    Diagnostics { rendered: String, cargo_lines: Vec<String> },
    #[error(transparent)]
    Project(#[from] ProjectError),
    #[error("OUT_DIR is not set: kiln::Build runs from a build script, or give it `out_dir`")]
    NoOutDir,
    #[error("cannot write `{path}`: {source}")]
    Write { path: PathBuf, source: std::io::Error },
    #[error("cannot read `{path}`: {source}")]
    Read { path: PathBuf, source: std::io::Error },
}

impl std::fmt::Debug for BuildError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Display::fmt(self, f)
    }
}

impl Build {
    /// A build of the project folder (its `kiln.toml`, or the defaults).
    pub fn new(project: impl Into<PathBuf>) -> Build {
        Build { paths: vec![project.into()], out_dir: None, prebuilt: None, request: Request::default() }
    }

    /// Also use the `.mat` files under this folder (a scene's materials, say).
    pub fn materials(mut self, folder: impl Into<PathBuf>) -> Build {
        self.paths.push(folder.into());
        self
    }

    /// Where to write (default: `OUT_DIR`).
    pub fn out_dir(mut self, dir: impl Into<PathBuf>) -> Build {
        self.out_dir = Some(dir.into());
        self
    }

    /// Worker threads (default: all cores).
    pub fn threads(mut self, threads: usize) -> Build {
        self.request.threads = Some(threads);
        self
    }

    /// The renderer's global keyword state, known from the scene: each `multi_compile` set is
    /// built only with the option these choose (its keyword, else `_`). Replaces the project's
    /// `global_keywords`. A scene with one directional light, say, gives
    /// `["_SINGLE_DIRECTIONAL_LIGHT"]` and gets no variant with the general light loop.
    pub fn global_keywords<S: Into<String>>(mut self, keywords: impl IntoIterator<Item = S>) -> Build {
        self.request.global_keywords = Some(keywords.into_iter().map(Into::into).collect());
        self
    }

    /// Also build the variants a usage log names (as `kiln_runtime::UsageLog` writes them, one
    /// JSON object a line): what a scene asked for at run time that no material uses.
    pub fn variant_log(mut self, file: impl Into<PathBuf>) -> Build {
        self.request.variant_logs.push(file.into());
        self
    }

    /// Starts from a build made elsewhere (`kiln merge`'s output of a build farm, or any `kiln
    /// build` output of this project): it is copied into `OUT_DIR` and, when the project has not
    /// changed since, nothing is compiled here. A cargo warning says which it was.
    pub fn prebuilt(mut self, folder: impl Into<PathBuf>) -> Build {
        self.prebuilt = Some(folder.into());
        self
    }

    /// A module cache shared with other builds (CI runners, other crates, developers' machines
    /// on a shared folder): modules found there are not compiled (see docs/scaling.md).
    pub fn cache_dir(mut self, folder: impl Into<PathBuf>) -> Build {
        self.request.cache_dir = Some(folder.into());
        self
    }

    /// Builds, prints the cargo lines, and returns what was built.
    pub fn run(self) -> Result<BuildOutput, BuildError> {
        let result = self.execute();
        let lines = match &result {
            Ok(output) => &output.cargo_lines,
            Err(BuildError::Diagnostics { cargo_lines, .. }) => cargo_lines,
            Err(_) => return result,
        };
        // A build script's protocol with cargo is its stdout: the one place the library prints.
        #[allow(clippy::print_stdout)]
        for line in lines {
            println!("{line}");
        }
        result
    }

    /// Builds without printing anything.
    pub fn execute(self) -> Result<BuildOutput, BuildError> {
        let out_dir = match self.out_dir.clone().or_else(|| std::env::var_os("OUT_DIR").map(PathBuf::from)) {
            Some(dir) => dir,
            None => return Err(BuildError::NoOutDir),
        };
        let output = out_dir.join("kiln");
        if let Some(prebuilt) = &self.prebuilt {
            copy_newer(prebuilt, &output)
                .map_err(|source| BuildError::Read { path: prebuilt.clone(), source })?;
        }
        let mut store = SourceStore::new();
        let request = Request { output: Some(output.clone()), ..self.request };
        let (result, mut problems) = build_project(&mut store, &self.paths, &request, &|_, _| {})?;
        problems.extend(result.diagnostics);
        let crate_root = std::env::var_os("CARGO_MANIFEST_DIR").map(PathBuf::from);
        let mut cargo_lines: Vec<String> = match (self.paths.first(), crate_root) {
            (Some(project), Some(crate_root)) => unread_config(project, &crate_root).into_iter().collect(),
            _ => Vec::new(),
        };
        for path in watched(store.files_read(), store.searched(), &out_dir) {
            match rerun_if_changed(&path) {
                Ok(line) => cargo_lines.push(line),
                Err(refused) => problems.push(refused),
            }
        }
        for warning in problems.iter().filter(|d| d.severity == Severity::Warning) {
            // cargo shows one line per warning; the rendered form spans several.
            for line in
                render_plain(&store, std::slice::from_ref(warning)).lines().filter(|l| !l.trim().is_empty())
            {
                cargo_lines.push(format!("cargo:warning={line}"));
            }
        }
        if diagnostics::has_errors(&problems) {
            return Err(BuildError::Diagnostics { rendered: render_plain(&store, &problems), cargo_lines });
        }
        cargo_lines.extend(unoptimised_warning(result.summary.compiled, env!("KILN_OPT_LEVEL")));
        if let Some(prebuilt) = &self.prebuilt {
            let from = prebuilt.display().to_string().escape_debug().to_string();
            cargo_lines.push(match result.summary.compiled {
                0 => format!("cargo:warning=kiln: shaders from the prebuilt build in `{from}`: nothing compiled"),
                n => format!(
                    "cargo:warning=kiln: the prebuilt build in `{from}` is out of date: {n} stage modules compiled here"
                ),
            });
        }
        // A no-op build did not read its manifest; the module needs it.
        let manifest = match result.manifest {
            Some(manifest) => manifest,
            None => Manifest::read(&output)
                .map_err(|source| BuildError::Read { path: output.join(FILE_NAME), source })?,
        };
        let module = out_dir.join("kiln_shaders.rs");
        let text =
            crate::codegen::generate(&manifest, &relative_to(&output, &out_dir)).map_err(|clashes| {
                let clashes: Vec<_> = clashes.iter().map(|c| c.to_diagnostic()).collect();
                BuildError::Diagnostics {
                    rendered: render_plain(&store, &clashes),
                    cargo_lines: cargo_lines.clone(),
                }
            })?;
        // Unchanged, it is not rewritten, so cargo has nothing to recompile.
        if std::fs::read(&module).ok().as_deref() != Some(text.as_bytes()) {
            crate::store::write_atomically(&module, text.as_bytes())
                .map_err(|source| BuildError::Write { path: module.clone(), source })?;
        }
        Ok(BuildOutput { module, manifest, summary: result.summary, cargo_lines })
    }
}

/// A `cargo:warning` when the project folder has no `kiln.toml` but a folder above it, up to the
/// crate's root, has one: the build reads only the project folder's (as `kiln build FOLDER`
/// does), and a file at the crate root, where `kiln build` run there finds it, would otherwise be
/// ignored without a word.
fn unread_config(project: &Path, crate_root: &Path) -> Option<String> {
    if !project.is_dir() || project.join(crate::config::FILE_NAME).is_file() {
        return None;
    }
    // Resolved: `../../shaders` from a crate lies outside it, though it starts with its path.
    let crate_root = std::fs::canonicalize(crate_root).ok()?;
    let folder = std::fs::canonicalize(project).ok()?;
    let above = folder
        .ancestors()
        .skip(1)
        .take_while(|a| a.starts_with(&crate_root))
        .find(|a| a.join(crate::config::FILE_NAME).is_file())?;
    let (project, above) = (project.display().to_string(), above.display().to_string());
    Some(format!(
        "cargo:warning=kiln: `{}` has no kiln.toml, so `{}/kiln.toml` is not read: move it into `{}`, or \
         give kiln::Build::new its folder with `shaders` and `materials` listed in it (docs/renderer.md)",
        project.escape_debug(),
        above.escape_debug(),
        project.escape_debug(),
    ))
}

/// The line that has cargo watch `path`. Cargo's build-script protocol is one directive a line
/// with no escapes, so a path with a line break (or any other control character) cannot be
/// watched, and printing it would let the rest of its name speak to cargo: it is refused.
fn rerun_if_changed(path: &Path) -> Result<String, Diagnostic> {
    match path.to_str().filter(|text| !text.contains(char::is_control)) {
        Some(text) => Ok(format!("cargo:rerun-if-changed={text}")),
        None => Err(Diagnostic::error(
            "K0420",
            format!(
                "cargo cannot watch `{}`: its name holds a control character or is not UTF-8",
                path.to_string_lossy().escape_debug()
            ),
        )
        .note("a build script's lines to cargo have no escapes: a line break in a path would end its `cargo:rerun-if-changed` line and start another directive")
        .help("rename the file or folder, or build it with the `kiln` command, which has no such limit")),
    }
}

/// What cargo should watch: every file the build read and every folder it searched (so that a
/// new shader, material or include reruns the build script), sorted, each once. Nothing under
/// `out_dir` is watched: a build script that writes there (materials made from a scene) would
/// otherwise rerun on every build. A searched folder that holds `out_dir` is watched through its
/// other entries; a path that does not exist is left out (cargo would rerun every time).
fn watched<'a>(
    read: impl Iterator<Item = &'a Path>,
    searched: &'a [PathBuf],
    out_dir: &Path,
) -> Vec<PathBuf> {
    let out_dir = std::fs::canonicalize(out_dir).unwrap_or_else(|_| out_dir.to_path_buf());
    let mut paths = Vec::new();
    for path in read.chain(searched.iter().map(PathBuf::as_path)) {
        watch(path, &out_dir, &mut paths);
    }
    paths.sort();
    paths.dedup();
    paths
}

fn watch(path: &Path, out_dir: &Path, paths: &mut Vec<PathBuf>) {
    let Ok(canonical) = std::fs::canonicalize(path) else { return };
    if canonical.starts_with(out_dir) {
        return;
    }
    if !out_dir.starts_with(&canonical) {
        paths.push(path.to_path_buf());
        return;
    }
    let Ok(entries) = std::fs::read_dir(path) else { return };
    for entry in entries.flatten() {
        watch(&entry.path(), out_dir, paths);
    }
}

/// Copies every file under `from` to the same place under `to`: packs (named by their content)
/// only where missing or of another size, every other file (manifest, materials, cache) always.
fn copy_newer(from: &Path, to: &Path) -> std::io::Result<()> {
    for entry in walkdir::WalkDir::new(from) {
        let entry = entry.map_err(std::io::Error::other)?;
        if !entry.file_type().is_file() {
            continue;
        }
        let relative = entry.path().strip_prefix(from).map_err(std::io::Error::other)?;
        let target = to.join(relative);
        let same =
            std::fs::metadata(&target).is_ok_and(|m| Some(m.len()) == entry.metadata().ok().map(|e| e.len()));
        if !same || !relative.starts_with("modules") {
            if let Some(parent) = target.parent() {
                std::fs::create_dir_all(parent)?;
            }
            std::fs::copy(entry.path(), &target)?;
        }
    }
    Ok(())
}

/// Above this many modules compiled, an unoptimised kiln costs a renderer's build noticeably.
const UNOPTIMISED_WARNING_MODULES: usize = 300;

/// The `cargo:warning` lines for a build that compiled `compiled` modules with kiln built at
/// `opt_level` (cargo's `OPT_LEVEL`): as a plain build-dependency in a debug profile, kiln and naga
/// run unoptimised, several times slower (docs/performance.md).
fn unoptimised_warning(compiled: usize, opt_level: &str) -> Vec<String> {
    if opt_level != "0" || compiled <= UNOPTIMISED_WARNING_MODULES {
        return Vec::new();
    }
    [
        format!(
            "kiln compiled {compiled} shader modules unoptimised (a build-dependency in a debug profile)."
        ),
        "To build shaders several times faster, add to the workspace's Cargo.toml:".to_string(),
        "[profile.dev.build-override]".to_string(),
        "opt-level = 3".to_string(),
    ]
    .map(|line| format!("cargo:warning={line}"))
    .into()
}

#[cfg(test)]
mod tests {
    use super::{unoptimised_warning, unread_config, watched};
    use std::path::{Path, PathBuf};

    #[test]
    fn nothing_under_out_dir_is_watched_and_a_folder_holding_it_is_watched_through_its_other_entries() {
        let dir = tempfile::tempdir().expect("temp dir");
        let root = dir.path();
        for path in ["shaders/Lit.shader", "shaders/Lit.wgsl", "target/out/scene/A.mat", "target/keep.txt"] {
            std::fs::create_dir_all(root.join(path).parent().expect("folder")).expect("mkdir");
            std::fs::write(root.join(path), "x").expect("write");
        }
        let out_dir = root.join("target/out");
        let read: Vec<PathBuf> =
            ["shaders/Lit.shader", "target/out/scene/A.mat"].map(|p| root.join(p)).into();
        // The project folder holds OUT_DIR (a crate pointing kiln at itself).
        let searched = [root.join("shaders"), root.to_path_buf(), root.join("target/out/scene")];
        let paths = watched(read.iter().map(PathBuf::as_path), &searched, &out_dir);
        let relative: Vec<String> = paths
            .iter()
            .map(|p| p.strip_prefix(root).unwrap_or(Path::new("?")).to_string_lossy().replace('\\', "/"))
            .collect();
        assert_eq!(relative, ["shaders", "shaders/Lit.shader", "target/keep.txt"]);
    }

    /// A `kiln.toml` at the crate root, above the folder the build script names, is named in a
    /// warning; one in the folder, or none anywhere, or one above the crate, is not.
    #[test]
    fn a_kiln_toml_above_the_project_folder_inside_the_crate_is_named_in_a_warning() {
        let dir = tempfile::tempdir().expect("temp dir");
        let crate_root = dir.path().join("renderer");
        let shaders = crate_root.join("shaders");
        std::fs::create_dir_all(&shaders).expect("mkdir");
        assert_eq!(unread_config(&shaders, &crate_root), None, "no kiln.toml anywhere");
        std::fs::write(dir.path().join("kiln.toml"), "").expect("write");
        assert_eq!(unread_config(&shaders, &crate_root), None, "above the crate: not the crate's");
        std::fs::write(crate_root.join("kiln.toml"), "").expect("write");
        let warning = unread_config(&shaders, &crate_root).expect("a warning");
        assert!(warning.starts_with("cargo:warning=kiln: `"), "{warning}");
        assert!(warning.contains("renderer/kiln.toml` is not read"), "{warning}");
        // A folder outside the crate, named through it, is not the crate's.
        let outside = dir.path().join("elsewhere");
        std::fs::create_dir_all(&outside).expect("mkdir");
        assert_eq!(unread_config(&crate_root.join("../elsewhere"), &crate_root), None);
        std::fs::write(shaders.join("kiln.toml"), "").expect("write");
        assert_eq!(unread_config(&shaders, &crate_root), None, "the folder's own is read");
    }

    #[test]
    fn only_many_modules_compiled_unoptimised_are_worth_a_warning() {
        assert!(unoptimised_warning(300, "0").is_empty());
        assert!(unoptimised_warning(5000, "3").is_empty());
        assert!(unoptimised_warning(5000, "1").is_empty());
        let lines = unoptimised_warning(301, "0");
        assert!(lines.iter().all(|l| l.starts_with("cargo:warning=")));
        assert!(lines[0].contains("301 shader modules unoptimised"), "{lines:?}");
        assert_eq!(lines[2..], ["cargo:warning=[profile.dev.build-override]", "cargo:warning=opt-level = 3"]);
    }
}
