//! One project as the editor sees it: `kiln check` over the open buffers, and the lookups every
//! request needs (a file's id, a path for each file, the passes that read a file).

use super::variants::Selections;
use crate::catalog::{Catalog, CatalogPass, CatalogProgram, CatalogShader};
use crate::diagnostics::Diagnostic;
use crate::preprocess::LIBRARY_PREFIX;
use crate::project::{Checked, Request, check_project};
use crate::source::{FileId, Overlay, SourceStore};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The project a file belongs to: the nearest folder up with a `kiln.toml`, or a `.shader` or
/// `.compute` file on its own; `None` for other files outside any project.
pub(super) fn project_of(file: &Path) -> Option<PathBuf> {
    if let Some(folder) = crate::project::config_folder_above(file) {
        return Some(folder);
    }
    let extension = file.extension().and_then(|e| e.to_str()).unwrap_or_default();
    crate::project::SHADER_EXTENSIONS.contains(&extension).then(|| file.to_path_buf())
}

/// A project checked once: what `kiln check` found, with the store its spans point into.
pub(super) struct Analysis {
    /// The project folder (or lone shader file).
    pub root: PathBuf,
    pub store: SourceStore,
    /// `None` when the project could not be read at all (`error` says why).
    pub checked: Option<Checked>,
    pub error: Option<String>,
    /// Canonical path of each file read from disk (or an open buffer).
    by_path: HashMap<PathBuf, FileId>,
    /// Where the bundled library's files are written for the editor to open.
    library: PathBuf,
    /// Only each pass's active variant was checked.
    pub partial: bool,
}

/// Where checks keep what outlives them.
#[derive(Clone)]
pub(super) struct Caches {
    /// The shared module cache given to the server (`--cache-dir`), which wins over the
    /// project's.
    pub modules: Option<PathBuf>,
    /// The shared module cache when neither the server, `KILN_CACHE_DIR` nor the project names
    /// one: without one, every check would compile every pass again.
    pub fallback_modules: PathBuf,
    /// Where the bundled library's files are written for the editor to open.
    pub library: PathBuf,
}

/// A pass of the catalogue, by shader and position.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub(super) struct PassRef {
    pub shader: usize,
    pub pass: usize,
}

impl Analysis {
    /// Checks the project at `root` reading `overlay`'s texts instead of those files: every
    /// variant, or (`active_only`) each pass's active variant alone.
    pub(super) fn run(
        root: &Path,
        overlay: Arc<Overlay>,
        caches: &Caches,
        active_only: Option<&Selections>,
        cancel: crate::project::Cancel,
    ) -> Analysis {
        let mut store = SourceStore::with_overlay(overlay);
        let request = Request {
            write: false,
            cache_dir: caches.modules.clone(),
            fallback_cache_dir: Some(caches.fallback_modules.clone()),
            // A check runs on every edit: a slow server must not hold the editor's diagnostics
            // (each check is a new build, with a breaker of its own). The shared folder serves.
            remote_cache_mode: Some(crate::store::remote::RemoteMode::Off),
            ..Request::default()
        };
        let narrow = |catalog: &mut Catalog| {
            let Some(selections) = active_only else { return };
            for shader in &mut catalog.shaders {
                let name = shader.shader.name.value.clone();
                for pass in &mut shader.passes {
                    let index = pass.index;
                    let Some(program) = pass.program.as_mut() else { continue };
                    let active = selections.active(&(name.clone(), index), program).map(|(i, _)| i);
                    let mut position = 0;
                    program.variants.retain(|_| {
                        position += 1;
                        Some(position - 1) == active
                    });
                }
            }
        };
        let (checked, error) =
            match check_project(&mut store, &[root.to_path_buf()], &request, &cancel, narrow) {
                Ok(checked) => (Some(checked), None),
                Err(error) => (None, Some(error.to_string())),
            };
        let by_path =
            store.ids().filter_map(|id| Some((std::fs::canonicalize(store.path(id)?).ok()?, id))).collect();
        let library = caches.library.clone();
        Analysis {
            root: root.to_path_buf(),
            store,
            checked,
            error,
            by_path,
            library,
            partial: active_only.is_some(),
        }
    }

    /// A check that could not run: `why` is shown at the project's `kiln.toml`.
    pub(super) fn failed(root: &Path, library: &Path, why: &str) -> Analysis {
        Analysis {
            root: root.to_path_buf(),
            store: SourceStore::new(),
            checked: None,
            error: Some(why.to_string()),
            by_path: HashMap::new(),
            library: library.to_path_buf(),
            partial: false,
        }
    }

    /// How many variants the check compiled.
    pub(super) fn variants(&self) -> usize {
        self.passes().map(|(.., program)| program.variants.len()).sum()
    }

    /// The diagnostics of the check (a project that could not be read: none, see `error`).
    pub(super) fn diagnostics(&self) -> &[Diagnostic] {
        self.checked.as_ref().map_or(&[], |c| &c.diagnostics)
    }

    /// The id of the file at canonical `path`, if the check read it (a bundled library file: by
    /// its place under the library folder).
    pub(super) fn file(&self, path: &Path) -> Option<FileId> {
        if let Some(&id) = self.by_path.get(path) {
            return Some(id);
        }
        let name = path.strip_prefix(&self.library).ok()?.to_string_lossy().replace('\\', "/");
        let wanted = format!("{LIBRARY_PREFIX}{name}");
        self.store.ids().find(|&id| self.store.path(id).is_none() && self.store.name(id) == wanted)
    }

    /// Where the editor finds a file: its path, or a bundled library file's copy.
    pub(super) fn path(&self, file: FileId) -> Option<PathBuf> {
        if let Some(path) = self.store.path(file) {
            return Some(std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf()));
        }
        let name = self.store.name(file).strip_prefix(LIBRARY_PREFIX)?;
        Some(self.library.join(name))
    }

    /// Every catalogued pass with a WGSL program.
    pub(super) fn passes(
        &self,
    ) -> impl Iterator<Item = (PassRef, &CatalogShader, &CatalogPass, &CatalogProgram)> {
        let shaders = self.checked.iter().flat_map(|c| c.catalog.shaders.iter().enumerate());
        shaders.flat_map(|(s, shader)| {
            shader.passes.iter().enumerate().filter_map(move |(p, pass)| {
                let program = pass.program.as_ref().filter(|program| program.source.is_some())?;
                Some((PassRef { shader: s, pass: p }, shader, pass, program))
            })
        })
    }

    /// The pass `at` names.
    pub(super) fn pass(&self, at: PassRef) -> Option<(&CatalogShader, &CatalogPass, &CatalogProgram)> {
        let shader = self.checked.as_ref()?.catalog.shaders.get(at.shader)?;
        let pass = shader.passes.get(at.pass)?;
        Some((shader, pass, pass.program.as_ref()?))
    }
}

/// Writes the bundled library's files under `folder` (once per kiln version), so that go-to-
/// definition on `#include "Common.wgsl"` has a file to open.
pub(super) fn write_library(folder: &Path) -> std::io::Result<()> {
    for (name, text) in crate::shaderlib::FILES {
        let path = folder.join(name);
        if std::fs::read_to_string(&path).ok().as_deref() != Some(*text) {
            if let Some(parent) = path.parent() {
                std::fs::create_dir_all(parent)?;
            }
            crate::store::write_atomically(&path, text.as_bytes())?;
        }
    }
    Ok(())
}
