//! The command line's shape: every command, argument and flag, as clap reads them.

use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;

/// The command line.
#[derive(Parser)]
#[command(name = "kiln", version, about = "Shader-variant compiler and keyword system for WGSL and HLSL")]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// What `build`, `watch` and `check` share: the project and what overrides its `kiln.toml`.
#[derive(clap::Args)]
pub struct ProjectArgs {
    /// The project folder (default: the nearest folder up with a kiln.toml, else this one).
    pub project: Option<PathBuf>,
    /// Worker threads, 1 to 1024 (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=1024))]
    pub threads: Option<u16>,
    /// Write here instead of the project's `output` folder (`check` reads its cache only).
    #[arg(long)]
    pub output: Option<PathBuf>,
    /// Also build the variants a usage log names (JSON Lines, as `kiln_runtime::UsageLog`
    /// writes them). Repeatable.
    #[arg(long = "variants-from", value_name = "FILE")]
    pub variants_from: Vec<PathBuf>,
    /// A module cache shared by builds, processes and machines (also `KILN_CACHE_DIR`,
    /// `cache_dir` in kiln.toml).
    #[arg(long, value_name = "DIR")]
    pub cache_dir: Option<PathBuf>,
    /// The team's cache on an HTTP server, `http://host:port/prefix` (also `KILN_REMOTE_CACHE`,
    /// `remote_cache` in kiln.toml; docs/scaling.md).
    #[arg(long, value_name = "URL")]
    pub remote_cache: Option<String>,
    /// What the build may do with the remote cache: fetch only, fetch and publish, or nothing
    /// (also `KILN_REMOTE_CACHE_MODE`, `remote_cache_mode` in kiln.toml; default: write).
    #[arg(long, value_enum, value_name = "MODE")]
    pub remote_cache_mode: Option<RemoteCacheMode>,
    /// Also write these back ends (`check`: also check them), besides kiln.toml's `backends`:
    /// comma-separated, of wgsl, spirv, msl, hlsl, glsl (docs/backends.md).
    #[arg(long, value_delimiter = ',', value_parser = backend, value_name = "LIST")]
    pub backends: Vec<kiln::manifest::Backend>,
    /// Hand naga every stage text whole, as `check` does, rather than the declarations its entry
    /// point reaches (the default for `build`; docs/performance.md).
    #[arg(long, conflicts_with = "parse_alone")]
    pub parse_whole: bool,
    /// Hand naga each stage text's reachable declarations by themselves, rather than parsing the
    /// texts of a pass's variants together where they share declarations (docs/performance.md).
    #[arg(long)]
    pub parse_alone: bool,
}

/// A back end by its name in `kiln.toml`.
fn backend(name: &str) -> Result<kiln::manifest::Backend, String> {
    let all = kiln::manifest::Backend::ALL;
    all.iter().copied().find(|b| b.name() == name).ok_or_else(|| {
        let names: Vec<&str> = all.iter().map(|b| b.name()).collect();
        let meant = kiln::manifest::Backend::meant(name).map(|b| format!(" (did you mean `{}`?)", b.name()));
        format!("no back end `{name}`{}; kiln writes {}", meant.unwrap_or_default(), names.join(", "))
    })
}

/// `--remote-cache-mode`.
#[derive(Clone, Copy, ValueEnum)]
pub enum RemoteCacheMode {
    /// Fetch only.
    Read,
    /// Fetch, and publish what the build compiled.
    Write,
    /// Neither.
    Off,
}

impl ProjectArgs {
    /// The project folder and the request these arguments give, the rest `Request`'s
    /// defaults: made here only.
    pub fn mode(self) -> (PathBuf, kiln::config::Request) {
        let mode = kiln::config::Request {
            output: self.output,
            threads: self.threads.map(usize::from),
            variant_logs: self.variants_from,
            cache_dir: self.cache_dir,
            remote_cache: self.remote_cache,
            backends: self.backends,
            parse: match (self.parse_whole, self.parse_alone) {
                (true, _) => Some(kiln::config::ParseScope::Whole),
                (false, true) => Some(kiln::config::ParseScope::Reachable),
                (false, false) => None,
            },
            remote_cache_mode: self.remote_cache_mode.map(|mode| match mode {
                RemoteCacheMode::Read => kiln::store::remote::RemoteMode::Read,
                RemoteCacheMode::Write => kiln::store::remote::RemoteMode::Write,
                RemoteCacheMode::Off => kiln::store::remote::RemoteMode::Off,
            }),
            ..kiln::config::Request::default()
        };
        (self.project.unwrap_or_else(kiln::project::default_project), mode)
    }
}

#[derive(Subcommand)]
pub enum Command {
    /// List each shader's passes, keyword sets, and the variants its materials use.
    List {
        /// Project folders (with their kiln.toml, if any), `.shader` or `.mat` files
        /// (default: the nearest folder up with a kiln.toml, else this one).
        paths: Vec<PathBuf>,
        /// `text` for people, `json` for tools (diagnostics included).
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Also list each material's resolved keywords and render state.
        #[arg(long)]
        materials: bool,
    },
    /// Print the text (WGSL or HLSL) the compiler sees for one variant of one pass: includes
    /// spliced, conditionals resolved, macros substituted.
    Preprocess {
        /// The `.shader` file.
        shader: PathBuf,
        /// Pass name (case-insensitive) or 0-based index; default: the first pass with a program.
        #[arg(long)]
        pass: Option<String>,
        /// The variant's keywords, comma-separated. Sets without `_` default to their first keyword.
        #[arg(long, value_delimiter = ',')]
        keywords: Vec<String>,
        /// The stage whose text to print (default: compute for a .compute file, else fragment).
        #[arg(long, value_enum)]
        stage: Option<StageArg>,
        /// Print only the declarations the stage's entry point reaches (a compute file's first
        /// kernel's): what `kiln build` hands naga.
        #[arg(long)]
        reachable: bool,
    },
    /// Compile every variant the materials use to WGSL and SPIR-V, with a manifest.
    Build {
        #[command(flatten)]
        project: ProjectArgs,
        /// Write `manifest.json` indented, for reading (default: compact).
        #[arg(long)]
        pretty: bool,
        /// Build only shard I of N (1 <= I <= N) of the stage modules, into the output folder,
        /// for `kiln merge` (docs/scaling.md).
        #[arg(long, value_name = "I/N")]
        shard: Option<String>,
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
        /// Write `manifest.json` indented (the shards must have been built with `--pretty` too).
        #[arg(long)]
        pretty: bool,
    },
    /// The shared module cache: its size, or shrink it.
    #[command(subcommand)]
    Cache(CacheCommand),
    /// Build, then rebuild on every change to a file the build read (or a new file where it
    /// looks), printing diagnostics and a summary line per build. A failed build leaves its
    /// diagnostics in the output folder for a running program (`kiln_runtime`) to report.
    Watch {
        #[command(flatten)]
        project: ProjectArgs,
    },
    /// Validate without writing anything: used variants, and for shaders no material uses, the
    /// default variant and each keyword on its own. Exit 1 on any error.
    Check {
        #[command(flatten)]
        project: ProjectArgs,
        /// `text` for people, `json` for tools.
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Check every variant of shaders no material uses (refused above 4096 per pass).
        #[arg(long)]
        all_variants: bool,
    },
    /// Print one variant's reflection as JSON: the pass's bind group layout, the stage modules'
    /// inputs, outputs and bindings, and the uniform block layouts.
    Reflect {
        /// The `.shader` file.
        shader: PathBuf,
        /// Pass name (case-insensitive) or 0-based index; default: the first pass with a program.
        #[arg(long)]
        pass: Option<String>,
        /// The variant's keywords, comma-separated. Sets without `_` default to their first keyword.
        #[arg(long, value_delimiter = ',')]
        keywords: Vec<String>,
        /// The project whose kiln.toml settings apply (`[bind_groups]`), as `kiln build` uses them
        /// (default: the nearest folder above the shader with a kiln.toml).
        #[arg(long)]
        project: Option<PathBuf>,
    },
    /// Measure the shader library's formulations against the f64 reference on hard cases, on
    /// the GPU (the speed-against-error table of docs/accuracy.md; needs `--features gpu`).
    Accuracy {
        /// Also draw GPU time against worst error, one point per formulation with the Pareto
        /// front: an SVG file, or a PNG one when FILE ends in `.png` (repeat for both).
        #[arg(long, value_name = "FILE.svg|FILE.png")]
        plot: Vec<PathBuf>,
        /// Cases per hard-case set.
        #[arg(long, default_value_t = kiln::accuracy::REPORT_SAMPLES, value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(2..=16_000_000))]
        samples: usize,
    },
    /// Serve editors: a language server (LSP over stdin and stdout) with diagnostics, hover,
    /// go-to-definition and completion for the project of each file opened (docs/editor.md).
    Lsp {
        /// The module cache checks share (default: KILN_CACHE_DIR, else the project's `cache_dir`).
        #[arg(long)]
        cache_dir: Option<PathBuf>,
        /// Accepted for clients that pass it (stdio is the only transport).
        #[arg(long)]
        stdio: bool,
    },
    /// Create materials and apply presets to them.
    #[command(subcommand)]
    Material(MaterialCommand),
    /// Draw a material: its variant on a sphere standing on a plane of it, under four
    /// directional lights, through the run time on the first GPU (or lavapipe), into a PNG
    /// (docs/preview.md; needs `--features preview`).
    Preview {
        /// The material's name (its file name without `.mat`).
        material: String,
        /// The project folder (default: the nearest folder up with a kiln.toml, else this one).
        project: Option<PathBuf>,
        /// The PNG to write (default: MATERIAL.png here).
        #[arg(long, value_name = "FILE.png")]
        out: Option<PathBuf>,
        /// The picture's side in pixels.
        #[arg(long, default_value_t = 256, value_parser = clap::value_parser!(u32).range(16..=4096))]
        size: u32,
    },
}

#[derive(Subcommand)]
pub enum CacheCommand {
    /// How many modules the cache holds and their size (and any that no longer verify).
    Stats {
        /// The project whose kiln.toml names the cache (default: the nearest folder up with a kiln.toml, else this one).
        project: Option<PathBuf>,
        /// The cache folder (default: `KILN_CACHE_DIR`, then the project's `cache_dir`).
        #[arg(long, value_name = "DIR")]
        cache_dir: Option<PathBuf>,
    },
    /// Removes the least recently used entries until the cache is at most SIZE (`500M`, `2G`).
    /// Safe while builds run: an entry gone is a miss.
    Gc {
        /// The project whose kiln.toml names the cache (default: the nearest folder up with a kiln.toml, else this one).
        project: Option<PathBuf>,
        /// The most the cache may hold: bytes, or a number and K, M, G or T.
        #[arg(long, value_name = "SIZE")]
        max_size: String,
        /// The cache folder (default: `KILN_CACHE_DIR`, then the project's `cache_dir`).
        #[arg(long, value_name = "DIR")]
        cache_dir: Option<PathBuf>,
    },
}

#[derive(Subcommand)]
pub enum MaterialCommand {
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
        /// The `.mat` file to change.
        path: PathBuf,
        /// Opaque, Clip, Fade or Transparent.
        preset: String,
        /// The project to find the shader in (default: the nearest folder with a kiln.toml).
        #[arg(long)]
        project: Option<PathBuf>,
    },
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum StageArg {
    Vertex,
    Fragment,
    Compute,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    Text,
    Json,
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    /// Every command and every argument says what it is in `--help`.
    #[test]
    fn every_command_and_argument_has_help() {
        fn visit(command: &clap::Command, path: &str, missing: &mut Vec<String>) {
            for argument in command.get_arguments() {
                let builtin = ["help", "version"].contains(&argument.get_id().as_str());
                if !builtin && argument.get_help().is_none() {
                    missing.push(format!("{path} {}", argument.get_id()));
                }
            }
            for sub in command.get_subcommands() {
                if sub.get_name() != "help" && sub.get_about().is_none() {
                    missing.push(format!("{path} {}", sub.get_name()));
                }
                visit(sub, &format!("{path} {}", sub.get_name()), missing);
            }
        }
        let mut missing = Vec::new();
        visit(&Cli::command(), "kiln", &mut missing);
        assert!(missing.is_empty(), "no help for: {missing:?}");
    }
}
