//! Finding and loading a project's files. This is the only place besides [`SourceStore`] that
//! touches the file system: stages get file ids, never paths.

use crate::diagnostics::Diagnostic;
use crate::source::{FileId, LoadError, SourceStore};
use std::path::{Path, PathBuf};

/// Host failures: what was asked for cannot be read at all.
#[derive(Debug, thiserror::Error)]
pub enum ProjectError {
    #[error("`{0}` does not exist")]
    NotFound(PathBuf),
    #[error("cannot walk `{path}`: {message}")]
    Walk { path: PathBuf, message: String },
}

/// The example project bundled with kiln, used when no path is given; relative to the working
/// directory when it lies below it, so diagnostics show short paths.
pub fn bundled_example() -> PathBuf {
    let absolute = Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/project");
    std::env::current_dir()
        .ok()
        .and_then(|cwd| absolute.strip_prefix(cwd).ok().map(Path::to_path_buf))
        .unwrap_or(absolute)
}

/// Every `.shader` file under the given files and folders, in a stable (sorted) order. A file
/// named directly is taken whatever its extension; symbolic links are not followed.
pub fn find_shader_files(paths: &[PathBuf]) -> Result<Vec<PathBuf>, ProjectError> {
    let mut files = Vec::new();
    for path in paths {
        if !path.exists() {
            return Err(ProjectError::NotFound(path.clone()));
        }
        if path.is_file() {
            files.push(path.clone());
            continue;
        }
        for entry in walkdir::WalkDir::new(path).sort_by_file_name() {
            let entry =
                entry.map_err(|e| ProjectError::Walk { path: path.clone(), message: e.to_string() })?;
            let is_shader = entry.path().extension().is_some_and(|ext| ext.eq_ignore_ascii_case("shader"));
            if entry.file_type().is_file() && is_shader {
                files.push(entry.into_path());
            }
        }
    }
    Ok(files)
}

/// Loads files into the store. Unreadable or non-UTF-8 files become diagnostics, not failures,
/// so the rest of the project is still checked.
pub fn load_files(store: &mut SourceStore, paths: &[PathBuf]) -> (Vec<FileId>, Vec<Diagnostic>) {
    let mut ids = Vec::new();
    let mut diagnostics = Vec::new();
    for path in paths {
        match store.load(path) {
            Ok(id) => ids.push(id),
            Err(error @ LoadError::NotUtf8 { .. }) => {
                diagnostics.push(Diagnostic::error("K0001", error.to_string()).help("save the file as UTF-8"))
            }
            Err(error @ LoadError::Io { .. }) => {
                diagnostics.push(Diagnostic::error("K0002", error.to_string()))
            }
        }
    }
    (ids, diagnostics)
}
