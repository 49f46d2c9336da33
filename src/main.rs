//! The `kiln` command: arguments in, library calls, rendered results out, exit code.
//! Exit codes: 0 success, 1 diagnostics with errors, 2 usage or I/O failure.

use clap::{Parser, Subcommand, ValueEnum};
use kiln::build::VariantSelection;
use kiln::diagnostics::{self, Diagnostic};
use kiln::preprocess::{Includes, Stage};
use kiln::project::{BuildMode, Part, VariantRequest, include_config};
use kiln::source::SourceStore;
use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(name = "kiln", version, about = "Shader-variant compiler and keyword system for WGSL")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// List each shader's passes, keyword sets, and the variants its materials use.
    List {
        /// Project folders (with their kiln.toml, if any), `.shader` or `.mat` files
        /// (default: the bundled example project).
        paths: Vec<PathBuf>,
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Also list each material's resolved keywords and render state.
        #[arg(long)]
        materials: bool,
    },
    /// Print the WGSL the compiler sees for one variant of one pass: includes spliced,
    /// conditionals resolved, macros substituted.
    Preprocess {
        /// The `.shader` file.
        shader: PathBuf,
        /// Pass name (case-insensitive) or 0-based index; default: the first pass with a program.
        #[arg(long)]
        pass: Option<String>,
        /// The variant's keywords, comma-separated. Sets without `_` default to their first keyword.
        #[arg(long, value_delimiter = ',')]
        keywords: Vec<String>,
        #[arg(long, value_enum, default_value_t = StageArg::Fragment)]
        stage: StageArg,
    },
    /// Compile every variant the materials use to WGSL and SPIR-V, with a manifest.
    Build {
        /// The project folder (default: the bundled example project).
        project: Option<PathBuf>,
        /// Worker threads (default: all cores).
        #[arg(long)]
        threads: Option<usize>,
        /// Write here instead of the project's `output` folder.
        #[arg(long)]
        output: Option<PathBuf>,
        /// Write `manifest.json` indented, for reading (default: compact).
        #[arg(long)]
        pretty: bool,
        /// Also build the variants a usage log names (JSON Lines, as `kiln::runtime::UsageLog`
        /// writes them). Repeatable.
        #[arg(long = "variants-from", value_name = "FILE")]
        variants_from: Vec<PathBuf>,
        /// Build only shard I of N (1 <= I <= N) of the stage modules, into the output folder,
        /// for `kiln merge` (docs/scaling.md).
        #[arg(long, value_name = "I/N")]
        shard: Option<String>,
        /// A module cache shared by builds, processes and machines (also `KILN_CACHE_DIR`,
        /// `cache_dir` in kiln.toml).
        #[arg(long, value_name = "DIR")]
        cache_dir: Option<PathBuf>,
    },
    /// Join the outputs of `kiln build --shard` into the output one `kiln build` would write,
    /// byte for byte, compiling nothing.
    Merge {
        /// The output folder to write.
        output: PathBuf,
        /// Every shard's output folder, once each.
        #[arg(required = true)]
        shards: Vec<PathBuf>,
        /// The project (default: the folder the shards were built from).
        #[arg(long)]
        project: Option<PathBuf>,
        #[arg(long)]
        pretty: bool,
    },
    /// The shared module cache: its size, or shrink it.
    #[command(subcommand)]
    Cache(CacheCommand),
    /// Build, then rebuild on every change to a file the build read (or a new file where it
    /// looks), printing diagnostics and a summary line per build. A failed build leaves its
    /// diagnostics in the output folder for a running program (`kiln::runtime`) to report.
    Watch {
        /// The project folder (default: the bundled example project).
        project: Option<PathBuf>,
        #[arg(long)]
        output: Option<PathBuf>,
        #[arg(long = "variants-from", value_name = "FILE")]
        variants_from: Vec<PathBuf>,
        #[arg(long, value_name = "DIR")]
        cache_dir: Option<PathBuf>,
    },
    /// Validate without writing anything: used variants, and for shaders no material uses, the
    /// default variant and each keyword on its own. Exit 1 on any error.
    Check {
        project: Option<PathBuf>,
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Check every variant of shaders no material uses (refused above 4096 per pass).
        #[arg(long)]
        all_variants: bool,
    },
    /// Print one variant's reflection as JSON: the pass's bind group layout, the stage modules'
    /// inputs, outputs and bindings, and the uniform block layouts.
    Reflect {
        shader: PathBuf,
        #[arg(long)]
        pass: Option<String>,
        #[arg(long, value_delimiter = ',')]
        keywords: Vec<String>,
    },
    /// Measure the shader library's formulations against the f64 reference on hard cases, on
    /// the GPU (the speed-against-error table of docs/accuracy.md).
    Accuracy,
    /// Create materials and apply presets to them.
    #[command(subcommand)]
    Material(MaterialCommand),
}

#[derive(Subcommand)]
enum CacheCommand {
    /// How many modules the cache holds and their size (and any that no longer verify).
    Stats {
        /// The project whose kiln.toml names the cache (default: the bundled example project).
        project: Option<PathBuf>,
        #[arg(long, value_name = "DIR")]
        cache_dir: Option<PathBuf>,
    },
    /// Removes the least recently used entries until the cache is at most SIZE (`500M`, `2G`).
    /// Safe while builds run: an entry gone is a miss.
    Gc {
        /// The project whose kiln.toml names the cache (default: the bundled example project).
        project: Option<PathBuf>,
        #[arg(long, value_name = "SIZE")]
        max_size: String,
        #[arg(long, value_name = "DIR")]
        cache_dir: Option<PathBuf>,
    },
}

#[derive(Subcommand)]
enum MaterialCommand {
    /// Write a new material with the shader's defaults.
    New {
        /// The `.mat` file to create (never overwritten).
        path: PathBuf,
        /// The shader's name, as in `Shader "name"`.
        #[arg(long)]
        shader: String,
        /// Opaque, Clip, Fade or Transparent.
        #[arg(long)]
        preset: Option<String>,
        /// The project to find the shader in (default: the nearest folder with a kiln.toml).
        #[arg(long)]
        project: Option<PathBuf>,
    },
    /// Apply a preset to a material, keeping its other values and comments.
    Preset {
        path: PathBuf,
        preset: String,
        #[arg(long)]
        project: Option<PathBuf>,
    },
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum StageArg {
    Vertex,
    Fragment,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Format {
    Text,
    Json,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::List { paths, format, materials } => list(paths, format, materials),
        Command::Preprocess { shader, pass, keywords, stage } => {
            let stage = match stage {
                StageArg::Vertex => Stage::Vertex,
                StageArg::Fragment => Stage::Fragment,
            };
            preprocess(&VariantRequest { shader, pass, keywords, stage })
        }
        Command::Build { project, threads, output, pretty, variants_from, shard, cache_dir } => {
            let mode = BuildMode {
                output,
                threads,
                pretty_manifest: pretty,
                variant_logs: variants_from,
                cache_dir,
                ..BuildMode::default()
            };
            let part = match shard.as_deref().map(kiln::build::shard::Shard::parse) {
                None => Part::Whole,
                Some(Ok(shard)) => Part::Shard(shard),
                Some(Err(message)) => return usage_failure(&message),
            };
            build(project, mode, Format::Text, part)
        }
        Command::Cache(command) => cache(command),
        Command::Merge { output, shards, project, pretty } => {
            let mode = BuildMode { output: Some(output), pretty_manifest: pretty, ..BuildMode::default() };
            let mut store = SourceStore::new();
            match kiln::project::merge_shards(&mut store, &shards, project, &mode) {
                Ok((result, mut problems)) => {
                    problems.extend(result.diagnostics);
                    report(&store, &problems);
                    print_summary(&result.summary, true, diagnostics::has_errors(&problems));
                    if !diagnostics::has_errors(&problems) {
                        eprintln!(
                            "merged {} shards: every module came from them, naga compiled none",
                            shards.len()
                        );
                    }
                    exit_code(&problems)
                }
                Err(error) => usage_failure(&error.to_string()),
            }
        }
        Command::Watch { project, output, variants_from, cache_dir } => {
            let mode = BuildMode { output, variant_logs: variants_from, cache_dir, ..BuildMode::default() };
            watch(project.unwrap_or_else(kiln::project::bundled_example), &mode)
        }
        Command::Check { project, format, all_variants } => {
            let unused_shaders = if all_variants {
                VariantSelection::All { limit: ALL_VARIANTS_LIMIT }
            } else {
                VariantSelection::DefaultsAndEachKeyword
            };
            build(
                project,
                BuildMode { write: false, unused_shaders, ..BuildMode::default() },
                format,
                Part::Whole,
            )
        }
        Command::Reflect { shader, pass, keywords } => {
            let mut store = SourceStore::new();
            let request = VariantRequest { shader, pass, keywords, stage: Stage::Fragment };
            match kiln::project::reflect_variant(&mut store, &request) {
                Ok((json, problems)) => {
                    if let Some(json) = json {
                        print_out(&format!("{json:#}\n"));
                    }
                    report(&store, &problems);
                    exit_code(&problems)
                }
                Err(error) => usage_failure(&error.to_string()),
            }
        }
        Command::Accuracy => accuracy(),
        Command::Material(command) => {
            let done = match command {
                MaterialCommand::New { path, shader, preset, project } => {
                    let project = project.unwrap_or_else(|| kiln::project::project_of(&path));
                    kiln::project::new_material(&path, &shader, preset.as_deref(), &project)
                }
                MaterialCommand::Preset { path, preset, project } => {
                    let project = project.unwrap_or_else(|| kiln::project::project_of(&path));
                    kiln::project::apply_preset(&path, &preset, &project)
                }
            };
            match done {
                Ok(()) => ExitCode::SUCCESS,
                Err(error) => usage_failure(&error.to_string()),
            }
        }
    }
}

fn accuracy() -> ExitCode {
    let gpu = match kiln::accuracy::gpu::device() {
        Ok(found) => found,
        Err(reason) => return usage_failure(&reason),
    };
    match kiln::accuracy::gpu::run(&gpu) {
        Ok((rows, timings, method)) => {
            print_out(&kiln::accuracy::render(&gpu.adapter, &rows, &timings, &method));
            ExitCode::SUCCESS
        }
        Err(error) => {
            eprintln!("error: {error}");
            ExitCode::from(1)
        }
    }
}

/// `kiln check --all-variants` refuses passes with more variants than this.
const ALL_VARIANTS_LIMIT: u128 = 4096;

fn build(project: Option<PathBuf>, mode: BuildMode, format: Format, part: Part) -> ExitCode {
    let project = project.unwrap_or_else(kiln::project::bundled_example);
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
        Err(error) => return usage_failure(&error.to_string()),
    };
    problems.extend(result.diagnostics);
    if format == Format::Json {
        let document = serde_json::json!({ "diagnostics": diagnostics::to_json(&store, &problems) });
        print_out(&format!("{document:#}\n"));
        return exit_code(&problems);
    }
    report(&store, &problems);
    print_summary(&result.summary, mode.write, diagnostics::has_errors(&problems));
    exit_code(&problems)
}

/// `kiln cache stats` and `kiln cache gc`.
fn cache(command: CacheCommand) -> ExitCode {
    let (project, given) = match &command {
        CacheCommand::Stats { project, cache_dir } | CacheCommand::Gc { project, cache_dir, .. } => {
            (project.clone().unwrap_or_else(kiln::project::bundled_example), cache_dir.clone())
        }
    };
    let mut store = SourceStore::new();
    let (workspace, problems) =
        match kiln::project::open_workspace(&mut store, std::slice::from_ref(&project)) {
            Ok(opened) => opened,
            Err(error) => return usage_failure(&error.to_string()),
        };
    report(&store, &problems);
    if diagnostics::has_errors(&problems) {
        return ExitCode::from(1);
    }
    let Some(dir) = workspace.shared_cache_dir(given) else {
        return usage_failure(&format!(
            "no cache folder: give --cache-dir, set KILN_CACHE_DIR, or set `cache_dir` in {}",
            project.join(kiln::config::FILE_NAME).display()
        ));
    };
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
        Err(message) => usage_failure(&message),
    }
}

/// The closing line of a build (and the note about skipped shaders).
fn print_summary(s: &kiln::build::BuildSummary, write: bool, errors: bool) {
    let verb = if write { "built" } else { "checked" };
    let mut line = format!(
        "{verb} {} shaders, {} passes, {} variants: {} stage modules ({} compiled, {} reused from cache",
        s.shaders, s.passes, s.variants, s.modules, s.compiled, s.reused
    );
    if s.shared > 0 {
        line.push_str(&format!(", {} shared between passes", s.shared));
    }
    line.push(')');
    if write {
        line.push_str(&format!(", {} bytes written", s.bytes_written));
    }
    line.push_str(&format!(" in {:.2} s", s.elapsed.as_secs_f64()));
    if errors {
        line.push_str(", with errors");
    }
    eprintln!("{line}");
    if !s.unused.is_empty() {
        eprintln!("{}", unused_hint(&s.unused, verb));
    }
}

/// `kiln watch`: builds, then rebuilds whenever a file changes in the project folder or in a
/// folder the build read from (include paths, shared libraries), except the output folder.
fn watch(project: PathBuf, mode: &BuildMode) -> ExitCode {
    use notify::Watcher as _;
    let (sender, events) = std::sync::mpsc::channel();
    let mut watcher = match notify::recommended_watcher(sender) {
        Ok(watcher) => watcher,
        Err(error) => return usage_failure(&format!("cannot watch files: {error}")),
    };
    let mut watched = std::collections::HashSet::new();
    loop {
        let mut store = SourceStore::new();
        let output = match kiln::project::watch_build(&mut store, std::slice::from_ref(&project), mode) {
            Ok((result, mut problems)) => {
                problems.extend(result.diagnostics);
                report(&store, &problems);
                print_summary(&result.summary, true, diagnostics::has_errors(&problems));
                result.output
            }
            Err(error) => {
                eprintln!("error: {error}");
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

/// The note after a build that skipped shaders because no material uses them.
fn unused_hint(unused: &[String], verb: &str) -> String {
    const SHOWN: usize = 5;
    let mut names: Vec<String> = unused.iter().take(SHOWN).map(|n| format!("`{n}`")).collect();
    if unused.len() > SHOWN {
        names.push(format!("and {} more", unused.len() - SHOWN));
    }
    let what = match unused {
        [one] => format!("`{one}`, so it was not {verb}"),
        _ => format!("{} shaders, so they were not {verb}: {}", unused.len(), names.join(", ")),
    };
    format!(
        "note: no material uses {what}\n  = help: add a `.mat` that names it, list it in `always_include` in \
         kiln.toml, or check every variant with `kiln check --all-variants`"
    )
}

fn preprocess(request: &VariantRequest) -> ExitCode {
    let mut store = SourceStore::new();
    match kiln::project::preprocess_variant(&mut store, request) {
        Ok((output, problems)) => {
            if let Some(output) = output {
                print_out(&output.text);
            }
            report(&store, &problems);
            exit_code(&problems)
        }
        Err(error) => usage_failure(&error.to_string()),
    }
}

fn list(paths: Vec<PathBuf>, format: Format, show_materials: bool) -> ExitCode {
    let paths = if paths.is_empty() { vec![kiln::project::bundled_example()] } else { paths };
    let mut store = SourceStore::new();
    let (workspace, mut problems) = match kiln::project::open_workspace(&mut store, &paths) {
        Ok(opened) => opened,
        Err(error) => return usage_failure(&error.to_string()),
    };
    let mut includes = Includes::new(workspace.include.clone().unwrap_or_else(|| include_config(&paths)));
    let (shaders, found) = kiln::project::load_files(&mut store, &workspace.shaders);
    problems.extend(found);
    let (materials, found) = kiln::project::load_files(&mut store, &workspace.materials);
    problems.extend(found);
    let input = workspace.catalog_input(shaders, materials);
    let (listing, diagnostics) = kiln::listing::list_shaders(&mut store, &mut includes, &input);
    problems.extend(diagnostics);
    if workspace.strict {
        diagnostics::promote_warnings(&mut problems);
    }
    match format {
        Format::Text => {
            let mut text = kiln::listing::render_text(&listing);
            if show_materials {
                text.push_str(&kiln::listing::render_materials(&listing));
            }
            print_out(&text);
            report(&store, &problems);
        }
        Format::Json => {
            let mut document = serde_json::json!({
                "shaders": listing.shaders,
                "diagnostics": diagnostics::to_json(&store, &problems),
            });
            if show_materials {
                document["materials"] = serde_json::json!(listing.materials);
            }
            print_out(&format!("{document:#}\n"));
        }
    }
    exit_code(&problems)
}

fn print_out(text: &str) {
    // A closed pipe (`kiln list | head`) is not an error worth a panic.
    let _ = std::io::stdout().lock().write_all(text.as_bytes());
}

fn report(store: &SourceStore, problems: &[Diagnostic]) {
    let stderr = std::io::stderr();
    let color = stderr.is_terminal() && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty());
    let _ = diagnostics::render_to(store, problems, color, &mut stderr.lock());
}

fn usage_failure(message: &str) -> ExitCode {
    eprintln!("error: {message}");
    ExitCode::from(2)
}

fn exit_code(problems: &[Diagnostic]) -> ExitCode {
    if diagnostics::has_errors(problems) { ExitCode::from(1) } else { ExitCode::SUCCESS }
}
