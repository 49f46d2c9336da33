//! The `kiln` command: arguments in, library calls, rendered results out, exit code.
//! Exit codes: 0 success, 1 diagnostics with errors, 2 the run could not be made (K0007).
//!
//! One file per command group: `build.rs` (build, check, merge, watch), `inspect.rs` (list,
//! preprocess, reflect, accuracy, lsp, preview), `cache.rs`, `material.rs`; `output.rs` renders.

mod args;
mod build;
mod cache;
mod inspect;
mod material;
mod output;

use args::{Cli, Command};
use clap::Parser;
use std::process::ExitCode;

#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> ExitCode {
    // Rayon's global pool would take `RAYON_NUM_THREADS` as it is, and 2 MiB stacks: it gets a
    // build pool's bound and stacks, and builds run in it.
    kiln::orchestrate::init_global_pool(kiln::config::threads_for(
        None,
        &kiln::config::Environment::of_process(),
    ));
    match Cli::parse().command {
        Command::List { paths, format, materials } => inspect::list(paths, format, materials),
        Command::Preprocess { shader, pass, keywords, stage, reachable } => {
            inspect::preprocess(shader, pass, keywords, stage, reachable)
        }
        Command::Reflect { shader, pass, keywords, project } => {
            inspect::reflect(shader, pass, keywords, project)
        }
        Command::Accuracy { plot, samples } => inspect::accuracy(plot, samples),
        Command::Lsp { cache_dir, stdio: _ } => inspect::lsp(cache_dir),
        Command::Build { project, pretty, shard } => build::build(project, pretty, shard),
        Command::Check { project, format, all_variants } => build::check(project, format, all_variants),
        Command::Merge { output, shards, project, pretty } => build::merge(output, shards, project, pretty),
        Command::Watch { project } => build::watch(project),
        Command::Cache(command) => cache::run(command),
        Command::Material(command) => material::run(command),
        Command::Preview { material, project, out, size } => inspect::preview(material, project, out, size),
    }
}
