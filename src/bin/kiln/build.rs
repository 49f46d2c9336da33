//! `kiln build`, `kiln check`, `kiln merge` and `kiln watch`: the library's build with a progress
//! bar, its diagnostics and a summary line.

use crate::args::{Format, ProjectArgs};
use crate::output::{exit_code, exit_leaving, host_failure, print_out, report};
use kiln::config::VariantSelection;
use kiln::diagnostics;
use kiln::project::{Part, Request};
use kiln::source::SourceStore;
use std::io::IsTerminal;
use std::path::PathBuf;
use std::process::ExitCode;

/// `kiln build`.
pub fn build(project: ProjectArgs, pretty: bool, shard: Option<String>) -> ExitCode {
    let (project, mode) = project.mode();
    let mode = Request { pretty_manifest: pretty, ..mode };
    let part = match shard.as_deref().map(kiln::orchestrate::shard::Shard::parse) {
        None => Part::Whole,
        Some(Ok(shard)) => Part::Shard(shard),
        Some(Err(error)) => return host_failure(&error.to_string()),
    };
    run(project, mode, Format::Text, part)
}

/// `kiln check`.
pub fn check(project: ProjectArgs, format: Format, all_variants: bool) -> ExitCode {
    let unused_shaders = if all_variants {
        VariantSelection::All { limit: ALL_VARIANTS_LIMIT }
    } else {
        VariantSelection::DefaultsAndEachKeyword
    };
    let (project, mode) = project.mode();
    run(project, Request { write: false, unused_shaders, ..mode }, format, Part::Whole)
}

/// `kiln merge`.
pub fn merge(output: PathBuf, shards: Vec<PathBuf>, project: Option<PathBuf>, pretty: bool) -> ExitCode {
    let mode = Request { output: Some(output), pretty_manifest: pretty, ..Request::default() };
    let mut store = SourceStore::new();
    match kiln::project::merge_shards(&mut store, &shards, project, &mode) {
        Ok((result, mut problems)) => {
            problems.extend(result.diagnostics);
            report(&store, &problems);
            print_summary(&result.summary, Some(&result.output), diagnostics::has_errors(&problems));
            if !diagnostics::has_errors(&problems) {
                eprintln!("merged {} shards: every module came from them, naga compiled none", shards.len());
            }
            exit_leaving(exit_code(&problems), (result.manifest, store))
        }
        Err(error) => host_failure(&error.to_string()),
    }
}

/// `kiln watch`.
pub fn watch(project: ProjectArgs) -> ExitCode {
    let (project, mode) = project.mode();
    watch_loop(project, &mode)
}

/// `kiln check --all-variants` refuses passes with more variants than this.
const ALL_VARIANTS_LIMIT: u128 = 4096;

fn run(project: PathBuf, mode: Request, format: Format, part: Part) -> ExitCode {
    let mut store = SourceStore::new();
    let bar = std::io::stderr().is_terminal().then(|| {
        let bar = indicatif::ProgressBar::new(0);
        bar.set_style(
            indicatif::ProgressStyle::with_template("{spinner} {bar:40} {pos}/{len} variants")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        bar
    });
    let progress = |done: usize, total: usize| {
        if let Some(bar) = &bar {
            bar.set_length(total as u64);
            bar.set_position(done as u64);
        }
    };
    let outcome = kiln::project::build_part(&mut store, &[project], &mode, &progress, part);
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    let (result, mut problems) = match outcome {
        Ok(done) => done,
        Err(error) => return host_failure(&error.to_string()),
    };
    problems.extend(result.diagnostics);
    if format == Format::Json {
        let document = serde_json::json!({ "diagnostics": diagnostics::to_json(&store, &problems) });
        print_out(&format!("{document:#}\n"));
        return exit_code(&problems);
    }
    report(&store, &problems);
    print_summary(
        &result.summary,
        mode.write.then_some(result.output.as_path()),
        diagnostics::has_errors(&problems),
    );
    exit_leaving(exit_code(&problems), (result.manifest, store))
}

/// The closing line of a build (and the note about skipped shaders).
fn print_summary(s: &kiln::orchestrate::BuildSummary, written_to: Option<&std::path::Path>, errors: bool) {
    let write = written_to.is_some();
    let verb = if write { "built" } else { "checked" };
    let counted =
        |n: usize, one: &str, many: &str| if n == 1 { format!("1 {one}") } else { format!("{n} {many}") };
    let mut line = format!(
        "{verb} {}, {}, {}: {} ({} compiled, {} reused from cache",
        counted(s.shaders, "shader", "shaders"),
        counted(s.passes, "pass", "passes"),
        counted(s.variants, "variant", "variants"),
        counted(s.modules, "stage module", "stage modules"),
        s.compiled,
        s.reused
    );
    if s.shared > 0 {
        line.push_str(&format!(", {} shared between passes", s.shared));
    }
    // Modules neither made nor found: their errors (or their pass's) are above.
    let failed = s.modules.saturating_sub(s.compiled + s.reused + s.shared);
    if failed > 0 {
        line.push_str(&format!(", {failed} failed"));
    }
    if s.uncut > 0 {
        // A miss of the cut to what entry points reach: a bug to report, never a wrong module.
        line.push_str(&format!(", {} built from the whole text", s.uncut));
    }
    line.push(')');
    if let Some(output) = written_to {
        line.push_str(&format!(", {} bytes written to {}", s.bytes_written, output.display()));
    }
    if let [received, sent] = s.remote_bytes
        && received + sent > 0
    {
        line.push_str(&format!(", {received} bytes fetched from the remote cache and {sent} sent"));
    }
    line.push_str(&format!(" in {:.2} s", s.elapsed.as_secs_f64()));
    if errors {
        line.push_str(", with errors");
    }
    eprintln!("{line}");
    if let Some(note) = s.unused_note(verb) {
        report(&SourceStore::new(), &[note]);
    }
}

/// `kiln watch`: builds, then rebuilds whenever a file changes in the project folder or in a
/// folder the build read from (include paths, shared libraries), except the output folder.
fn watch_loop(project: PathBuf, mode: &Request) -> ExitCode {
    use notify::Watcher as _;
    let (sender, events) = std::sync::mpsc::channel();
    let mut watcher = match notify::recommended_watcher(sender) {
        Ok(watcher) => watcher,
        Err(error) => return host_failure(&format!("cannot watch files: {error}")),
    };
    let mut watched = std::collections::HashSet::new();
    loop {
        let mut store = SourceStore::new();
        let output = match kiln::project::watch_build(&mut store, std::slice::from_ref(&project), mode) {
            Ok((result, mut problems)) => {
                problems.extend(result.diagnostics);
                report(&store, &problems);
                print_summary(&result.summary, Some(&result.output), diagnostics::has_errors(&problems));
                result.output
            }
            // The first build cannot run at all (no such project): nothing to watch.
            Err(error) if watched.is_empty() => return host_failure(&error.to_string()),
            Err(error) => {
                report(&store, &[kiln::diagnostics::Diagnostic::host_failure(error.to_string())]);
                PathBuf::new()
            }
        };
        let canonical = |path: PathBuf| std::fs::canonicalize(&path).unwrap_or(path);
        let (output, root) = (canonical(output), canonical(project.clone()));
        // The project folder whole (a new shader or material anywhere in it counts), and the
        // folders of every file read outside it.
        let folders = store.files_read().filter_map(|f| f.parent().map(PathBuf::from)).map(canonical);
        for folder in [root.clone()].into_iter().chain(folders.filter(|f| !f.starts_with(&root))) {
            if watched.insert(folder.clone()) {
                let mode = if folder == root {
                    notify::RecursiveMode::Recursive
                } else {
                    notify::RecursiveMode::NonRecursive
                };
                if let Err(error) = watcher.watch(&folder, mode) {
                    eprintln!("warning: cannot watch `{}`: {error}", folder.display());
                }
            }
        }
        eprintln!("watching for changes (ctrl-c to stop)");
        // The build's own writes into the output folder are not changes to the project.
        let relevant = |event: &notify::Event| {
            let changes = event.kind.is_modify() || event.kind.is_create() || event.kind.is_remove();
            changes && event.paths.iter().any(|p| !p.starts_with(&output))
        };
        loop {
            match events.recv() {
                Ok(Ok(event)) if relevant(&event) => break,
                Ok(_) => continue,
                Err(_) => return ExitCode::from(2),
            }
        }
        // Editors write in several steps: wait for the burst to end.
        std::thread::sleep(std::time::Duration::from_millis(150));
        while events.try_recv().is_ok() {}
    }
}
