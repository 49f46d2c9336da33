//! `kiln cache stats` and `kiln cache gc`: the shared module cache a project's builds use.

use crate::args::CacheCommand;
use crate::output::{host_failure, report};
use kiln::diagnostics;
use kiln::source::SourceStore;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// `kiln cache stats` and `kiln cache gc`.
pub fn run(command: CacheCommand) -> ExitCode {
    let (project, given) = match &command {
        CacheCommand::Stats { project, cache_dir } | CacheCommand::Gc { project, cache_dir, .. } => {
            (project.clone().unwrap_or_else(kiln::project::default_project), cache_dir.clone())
        }
    };
    // A cache named by the flag or the environment needs no project: none is opened (opening
    // one finds its files, and without a kiln.toml that is every file under this folder).
    let dir = match given.or(kiln::config::Environment::of_process().cache_dir) {
        Some(dir) => dir,
        None => match project_cache_dir(&project) {
            Ok(dir) => dir,
            Err(code) => return code,
        },
    };
    if !dir.is_dir() {
        return host_failure(&format!("no cache at `{}`: the folder does not exist", dir.display()));
    }
    let outcome = match command {
        CacheCommand::Stats { .. } => kiln::store::shared::cache_stats(&dir)
            .map_err(|e| format!("cannot read `{}`: {e}", dir.display()))
            .map(|stats| {
                let damaged = if stats.damaged > 0 {
                    format!(", {} damaged (misses; gc removes them)", stats.damaged)
                } else {
                    String::new()
                };
                println!(
                    "{}: {} modules, {} pass layouts, {} bytes{damaged}",
                    dir.display(),
                    stats.modules,
                    stats.layouts,
                    stats.bytes
                );
            }),
        CacheCommand::Gc { max_size, .. } => kiln::store::shared::parse_size(&max_size).and_then(|limit| {
            let (removed, left) = kiln::store::shared::cache_gc(&dir, limit)
                .map_err(|e| format!("cannot clean `{}`: {e}", dir.display()))?;
            println!("{}: removed {removed} entries, {left} bytes left (limit {limit})", dir.display());
            Ok(())
        }),
    };
    match outcome {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => host_failure(&message),
    }
}

/// The cache the project's `kiln.toml` names, or the exit code after saying why there is none.
fn project_cache_dir(project: &Path) -> Result<PathBuf, ExitCode> {
    let mut store = SourceStore::new();
    let (workspace, problems) = kiln::project::open_workspace(&mut store, &[project.to_path_buf()])
        .map_err(|error| host_failure(&error.to_string()))?;
    report(&store, &problems);
    if diagnostics::has_errors(&problems) {
        return Err(ExitCode::from(1));
    }
    workspace.settings.shared_cache_dir(None, &kiln::config::Environment::of_process()).ok_or_else(|| {
        host_failure(&format!(
            "no cache folder: give --cache-dir, set KILN_CACHE_DIR, or set `cache_dir` in {}",
            project.join(kiln::config::FILE_NAME).display()
        ))
    })
}
