//! The build layer: everything that orchestrates the stages for a whole project. A build plans
//! its passes from the catalogue ([`plan`]), builds each as a parallel task ([`pass`]: its stage
//! texts from [`jobs`], each front and stage module from the first of an ordered list of
//! [`sources`] that has it, one pack per backend), and emits the manifest or, for a shard, its
//! passes' parts ([`emit`], [`shard`]); a merge joins shards' parts without compiling
//! (`merge`). Before any of it, [`unchanged`] tells from the last clean build's record that
//! nothing needs doing ([`noop`]). The manifest keeps catalogue order, so output never depends on
//! the thread count or on how the work was split.

mod emit;
mod error;
mod jobs;
mod merge;
mod noop;
mod pass;
mod plan;
mod session;
pub mod shard;
mod sources;
mod tasks;

pub use emit::{CataloguePart, ShaderHead};
pub use error::BuildLayerError;
pub use merge::ShardsRead;
pub use noop::unchanged;
pub use plan::stage_texts;

use crate::catalog::Catalog;
use crate::config::Backend;
use crate::diagnostics::Diagnostic;
use crate::manifest::Manifest;
use crate::preprocess::Includes;
use crate::source::SourceStore;
use rayon::prelude::*;
use shard::Shard;
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// Part of every cache key: a new naga may compile differently.
const NAGA_VERSION: &str = "naga 30";

/// Part of every cache key: HLSL and Cg modules are glslang's SPIR-V first.
const GLSLANG_VERSION: &str = "glslang 0.9";

/// Part of every cache key, raised when kiln compiles the same text differently (revision 2:
/// layouts by the WGSL spec, a wider capability baseline; 3: `override` constants reflected, their
/// modules WGSL only, compute kernels; 4: WGSL repaired where naga misspells it, modules naga's
/// SPIR-V writer cannot write shipped WGSL only; 5: storage texture access reflected as WGSL's
/// modes; 6: MSL, HLSL and GLSL back ends; 7: HLSL and Cg programs; 8: glslang's "recursion" on a
/// module-scope array value let through), so that a cache an earlier kiln of the
/// same version filled is not taken for current.
const COMPILER_REVISION: u32 = 8;

/// What compiled a module, as the shared cache records it beside each object: kiln's version and
/// revision, naga's and glslang's. Made once: every object fetched or published names it.
pub(crate) fn compiler_id() -> &'static str {
    static ID: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    ID.get_or_init(|| {
        let version = env!("CARGO_PKG_VERSION");
        format!("kiln {version} revision {COMPILER_REVISION} {NAGA_VERSION} {GLSLANG_VERSION}")
    })
}

/// Each worker thread's stack. naga's front end, validator and back ends recurse once per level
/// of an expression (a sum of 5,000 terms is 5,000 levels), past what rayon's default 2 MiB holds,
/// and a stack overflow aborts the process where a panic would have been a diagnostic (K0416). The
/// memory is reserved, not used: a thread touches only what it recurses into.
pub const WORKER_STACK: usize = 256 << 20;

/// The most worker threads a build starts.
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

/// How a build runs and where it writes.
#[derive(Debug, Clone)]
pub struct BuildOptions {
    /// The output folder.
    pub output: PathBuf,
    /// The project folder: the manifest's shader paths and the cache's keys are relative to it,
    /// so that a project builds the same bytes wherever it sits.
    pub root: PathBuf,
    /// `false` for `kiln check`: nothing is written.
    pub write: bool,
    /// What naga parses of each stage text.
    pub parse: ParseScope,
    /// Worker threads (default: all cores).
    pub threads: Option<usize>,
    /// The back ends each stage module is written for.
    pub backends: Vec<Backend>,
    /// What is built of shaders no material uses.
    pub unused_shaders: VariantSelection,
    /// Write `manifest.json` indented (default: compact).
    pub pretty_manifest: bool,
    /// Record the inputs for the next build's no-op check ([`unchanged`]) when nothing is
    /// reported ([`build`]'s `earlier`, and the build's own).
    pub record: bool,
    /// The whole build, one shard of it, or a merge of shards.
    pub part: Part,
    /// A module cache shared with other builds: modules are taken from it before naga runs,
    /// and every module compiled is published to it.
    pub cache_dir: Option<PathBuf>,
    /// The team's cache on an HTTP server: asked after `cache_dir`, and given what the build
    /// compiled when its mode allows (docs/scaling.md).
    pub remote_cache: Option<crate::store::remote::RemoteConfig>,
    /// How many files the store held from disk before the catalogue was built (the project
    /// file, shaders, materials, variant logs): the rest were read through includes. A no-op
    /// needs the same files given, not merely the same files read.
    pub given_files: usize,
    /// The resource names the project adds to the per-frame and per-object bind groups.
    pub groups: crate::compile::bind::GroupNames,
    /// Reads back the GLSL and HLSL each module is written in (`kiln check`, where installed).
    pub glslang: Option<crate::compile::glslang::Glslang>,
    /// Stops a check (a build that writes nothing) before its next pass when set.
    pub cancel: Cancel,
}

/// A caller's way to stop a check early: cloned into the build, set from another thread.
/// A check told to stop starts no further pass and returns what it found so far, for the
/// caller to drop. A build that writes is not stopped (its output is old or new, never cut).
#[derive(Clone, Debug, Default)]
pub struct Cancel(Option<std::sync::Arc<std::sync::atomic::AtomicBool>>);

impl Cancel {
    /// A token that [`Cancel::cancel`] can set (the default one never is).
    pub fn new() -> Cancel {
        Cancel(Some(Default::default()))
    }

    /// Tells every build holding a clone of this token to stop.
    pub fn cancel(&self) {
        if let Some(flag) = &self.0 {
            flag.store(true, std::sync::atomic::Ordering::Relaxed);
        }
    }

    /// Whether the build was told to stop.
    pub fn is_cancelled(&self) -> bool {
        self.0.as_ref().is_some_and(|flag| flag.load(std::sync::atomic::Ordering::Relaxed))
    }
}

impl BuildOptions {
    /// What a build with these options may do after `earlier` findings: write nothing after an
    /// error, record no no-op after any finding.
    fn after(&self, earlier: &[Diagnostic]) -> BuildOptions {
        BuildOptions {
            write: self.write && !crate::diagnostics::has_errors(earlier),
            record: self.record && earlier.is_empty(),
            ..self.clone()
        }
    }

    /// A one-off build of what a caller catalogued itself (a shader to reflect, the accuracy
    /// harness): one thread, both back ends, nothing recorded for a no-op, no shared cache.
    pub fn one_off(root: PathBuf, output: PathBuf, write: bool) -> BuildOptions {
        BuildOptions {
            output,
            root,
            write,
            parse: ParseScope::Together,
            threads: Some(1),
            backends: Backend::DEFAULT.to_vec(),
            unused_shaders: VariantSelection::Used,
            pretty_manifest: false,
            record: false,
            part: Part::Whole,
            cache_dir: None,
            remote_cache: None,
            given_files: 0,
            groups: Default::default(),
            glslang: None,
            cancel: Cancel::default(),
        }
    }
}

/// How much of a build one process does.
#[derive(Debug, Clone, Default)]
pub enum Part {
    /// Every pass, and the manifest.
    #[default]
    Whole,
    /// `kiln build --shard I/N`: the passes that fall to this shard, built as a whole build
    /// builds them, and their parts of the manifest (`shard.json`) for `kiln merge` (`merge`).
    Shard(Shard),
}

/// Shard outputs a merge joins ([`shard::check_shards`] checked them against each other).
#[derive(Debug, Clone)]
pub struct Merge {
    /// Each shard's output folder and its record.
    pub shards: Vec<(PathBuf, shard::ShardRecord)>,
    /// The inputs hash the shards share, which the project must still have.
    pub inputs: String,
}

/// What a build did, in numbers.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct BuildSummary {
    /// Shaders with at least one pass built.
    pub shaders: usize,
    /// Passes built (in a shard: in the whole project).
    pub passes: usize,
    /// Variants built (in a shard: in the whole project).
    pub variants: usize,
    /// Distinct stage modules.
    pub modules: usize,
    /// Modules naga compiled.
    pub compiled: usize,
    /// Modules taken from the output's cache, the shared cache or shards.
    pub reused: usize,
    /// Modules another pass of the build compiled (identical stage texts, laid out alike).
    pub shared: usize,
    /// Modules built from their whole text because naga refused the text cut to what the entry
    /// point reaches (a miss of `compile::reach`'s scan; 0 on every input the suite builds).
    pub uncut: usize,
    /// Stage texts the preprocessor wrote: one for each stage and keywords of a pass, whatever
    /// its entry points (a compute pass's kernels share one).
    pub preprocessed: usize,
    /// Texts naga parsed: a stage text, or texts of one pass parsed together (each once).
    pub parses: usize,
    /// Modules cut out of a parse of several texts together (`compile::together`).
    pub parsed_together: usize,
    /// Bytes of files written.
    pub bytes_written: u64,
    /// Bytes received from and sent to the remote cache.
    pub remote_bytes: [u64; 2],
    /// Wall-clock time of the build.
    pub elapsed: Duration,
    /// Shaders with programs kiln compiles that no material uses, so nothing of them was built.
    pub unused: Vec<String>,
}

impl BuildSummary {
    /// The note after a build that left shaders out because no material uses them (`verb`:
    /// "built" or "checked").
    pub fn unused_note(&self, verb: &str) -> Option<Diagnostic> {
        const SHOWN: usize = 5;
        let unused = &self.unused;
        let mut names: Vec<String> = unused.iter().take(SHOWN).map(|n| format!("`{n}`")).collect();
        if unused.len() > SHOWN {
            names.push(format!("and {} more", unused.len() - SHOWN));
        }
        let what = match &unused[..] {
            [] => return None,
            [one] => format!("`{one}`, so it was not {verb}"),
            _ => format!("{} shaders, so they were not {verb}: {}", unused.len(), names.join(", ")),
        };
        Some(
            Diagnostic::remark("K0008", format!("no material uses {what}"))
                .help(
                    "add a `.mat` that names it, list it in `always_include` in kiln.toml, or check every \
                     variant with `kiln check --all-variants`",
                )
                .note("a compute shader's variants are listed in kiln.toml: `[compute.NAME] variants = [[], [\"_KEYWORD\"]]` or `\"all\"`"),
        )
    }
}

/// A build's outcome.
pub struct BuildResult {
    /// `None` when nothing changed since the last clean build ([`unchanged`], which does not
    /// read the manifest: it is in the output folder, as that build wrote it), and for a shard.
    pub manifest: Option<Manifest>,
    /// The counts.
    pub summary: BuildSummary,
    /// What the build found wrong (the catalogue's are the caller's).
    pub diagnostics: Vec<Diagnostic>,
    /// The output folder (written or not).
    pub output: PathBuf,
}

impl BuildResult {
    fn failed(options: &BuildOptions, summary: BuildSummary, diagnostics: Vec<Diagnostic>) -> BuildResult {
        BuildResult { manifest: None, summary, diagnostics, output: options.output.clone() }
    }
}

/// Builds (or, without `write`, checks) every WGSL pass of the catalogue, or the part of it
/// `options.part` names. `earlier` is what was reported before it (the project's and the
/// catalogue's findings): after an error nothing is written, after any finding no no-op is
/// recorded (a no-op build reports nothing). `progress` is told (variants done, variants in all).
pub fn build(
    store: &SourceStore,
    includes: &Includes,
    catalog: &Catalog,
    options: &BuildOptions,
    earlier: &[Diagnostic],
    progress: &(dyn Fn(usize, usize) + Sync),
) -> BuildResult {
    let options = &options.after(earlier);
    timed_in_pool(options, || build_passes(store, includes, catalog, options, progress))
}

impl Merge {
    /// What the merge needs of the shards alone, their packs checked against the hashes they recorded:
    /// needs no project, so a caller can read the project at the same time.
    pub fn read_shards(&self) -> ShardsRead {
        merge::read_shards(self)
    }
}

/// `kiln merge`: the output of one build of the project from the shards' outputs (`read`:
/// [`Merge::read_shards`]), compiling nothing and reading no catalogue. `store` holds the files
/// the project was given (its `kiln.toml`, shaders, materials, variant logs); the rest the
/// shards read is read here, and all of it must still be what the shards read (K0413).
pub fn merge(
    store: &mut SourceStore,
    options: &BuildOptions,
    earlier: &[Diagnostic],
    shards: &Merge,
    read: ShardsRead,
) -> BuildResult {
    let options = &options.after(earlier);
    timed_in_pool(options, || merge::merge(store, options, shards, read))
}

/// The worker threads for a build asked for `requested` (`--threads`), else `RAYON_NUM_THREADS`,
/// else one per core; never more than [`MAX_THREADS`]: far more threads than cores only costs
/// memory, and a mistyped count, from either place, must not exhaust it.
pub fn thread_count(requested: Option<usize>) -> usize {
    let cores = std::thread::available_parallelism().map_or(1, usize::from);
    threads_for(requested, std::env::var("RAYON_NUM_THREADS").ok().as_deref(), cores)
}

/// [`thread_count`] from what it reads: the request, `RAYON_NUM_THREADS`'s text, the cores.
fn threads_for(requested: Option<usize>, environment: Option<&str>, cores: usize) -> usize {
    let from_environment = environment.and_then(|n| n.trim().parse::<usize>().ok()).filter(|&n| n > 0);
    requested.filter(|&n| n > 0).or(from_environment).unwrap_or(cores).min(MAX_THREADS)
}

/// Whether rayon's global pool is one [`init_global_pool`] made: with kiln's stacks, and bounded.
static GLOBAL_POOL_IS_KILNS: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Makes rayon's global pool as a build's would be ([`thread_count`] workers with
/// [`WORKER_STACK`] stacks), for a program whose main work is kiln's (the CLI): a build of that
/// many threads then runs in it rather than in a second pool beside it, so the process never runs
/// more than [`MAX_THREADS`] workers, whatever `RAYON_NUM_THREADS` says. Does nothing where the
/// global pool exists already.
pub fn init_global_pool() {
    let built = rayon::ThreadPoolBuilder::new()
        .num_threads(thread_count(None))
        .stack_size(WORKER_STACK)
        .build_global();
    if built.is_ok() {
        GLOBAL_POOL_IS_KILNS.store(true, std::sync::atomic::Ordering::Relaxed);
    }
}

/// A pool of `threads` workers, made once in a process and kept: a build script, the language
/// server and a benchmark build again in the same process, and a new pool's threads start with
/// cold stacks and allocator heaps. `None` where one cannot be made, or where the global pool is
/// kiln's own of that size (the build runs there).
fn pool(threads: usize) -> Option<std::sync::Arc<rayon::ThreadPool>> {
    if GLOBAL_POOL_IS_KILNS.load(std::sync::atomic::Ordering::Relaxed)
        && rayon::current_num_threads() == threads
    {
        return None;
    }
    static POOLS: std::sync::Mutex<Vec<(usize, std::sync::Arc<rayon::ThreadPool>)>> =
        std::sync::Mutex::new(Vec::new());
    let mut pools = POOLS.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    if let Some((_, pool)) = pools.iter().find(|(n, _)| *n == threads) {
        return Some(pool.clone());
    }
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).stack_size(WORKER_STACK).build().ok()?;
    let pool = std::sync::Arc::new(pool);
    pools.push((threads, pool.clone()));
    Some(pool)
}

/// Runs `job` on a pool of `options.threads` (all cores by default; the global pool if one cannot
/// be made), its summary timed.
fn timed_in_pool(options: &BuildOptions, job: impl FnOnce() -> BuildResult + Send) -> BuildResult {
    let started = Instant::now();
    let mut result = match pool(thread_count(options.threads)) {
        Some(pool) => pool.install(job),
        // On one of the global pool's workers (and their stacks), as `install` would run it.
        None => rayon::scope(|_| job()),
    };
    result.summary.elapsed = started.elapsed();
    result
}

/// A whole build, or a shard: every pass it owns is a task (its stage texts, their resources,
/// one layout, its stage modules, its packs and its part of the manifest). Each worker thread
/// takes the next pass in plan order as it frees up (no barrier between passes), so one pass's
/// serial steps overlap other passes' naga work, only the passes in flight (one a thread) hold
/// texts and modules, and a compact manifest is written as they finish.
fn build_passes(
    store: &SourceStore,
    includes: &Includes,
    catalog: &Catalog,
    options: &BuildOptions,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> BuildResult {
    let mut diagnostics = Vec::new();
    let mut summary = BuildSummary::default();
    let work = plan::plan(catalog, options.unused_shaders, &mut summary, &mut diagnostics);
    // A shard decides what it owns before preprocessing anything.
    let owned: Vec<bool> = match &options.part {
        Part::Shard(shard) => shard.owned(&plan::weights(&work)),
        _ => vec![true; work.len()],
    };
    let mine: Vec<&plan::PassWork> = work.iter().zip(&owned).filter(|(_, o)| **o).map(|(w, _)| w).collect();
    let total = mine.iter().map(|w| w.variants.len()).sum();
    let session = session::Session::new(options, progress, total);
    // Only a whole build and the first shard list the shaders (the manifest, the catalogue's part).
    let heads = match &options.part {
        Part::Shard(shard) if shard.index != 0 => Vec::new(),
        _ => emit::shader_heads(store, options, &work),
    };
    // A whole build's compact manifest is written as its passes finish.
    let manifest_path = options.output.join(crate::manifest::FILE_NAME);
    let streamed = options.write && !options.pretty_manifest && matches!(options.part, Part::Whole);
    let passes = emit::PassParts::new(mine.len(), streamed.then_some((&heads[..], manifest_path.as_path())));
    // Only a check stops early: a build that writes finishes what it began.
    let stopped = || !options.write && options.cancel.is_cancelled();
    // What needs no compiled pass is made while the passes compile: the files read, named once
    // (the inputs key hashes them and the catalogue's part lists them; nothing is read while
    // passes compile, the store is only shared), the inputs key, the materials' texts. Only what
    // is written needs them: a check (the language server's, on every edit) makes none.
    let ((), (read, inputs, materials)) = rayon::join(
        || {
            // Every worker takes the next pass in plan order until none is left. No pass waits
            // in a queue where a thread that waits inside its own pass would take it up (rayon
            // lets a waiting thread run queued work): passes start in plan order, and at most
            // one a thread is in flight (a pass's own steps are tasks an item: `tasks`).
            let next = std::sync::atomic::AtomicUsize::new(0);
            rayon::broadcast(|_| {
                while !stopped() {
                    let index = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    let Some(work) = mine.get(index) else { return };
                    let (part, built) = pass::build_pass(work, store, includes, catalog, options, &session);
                    passes.add(index, part, built);
                }
            });
        },
        || {
            if !options.write {
                return Default::default();
            }
            let read = noop::disk_names(store, options);
            let inputs = noop::inputs_key(store, options, &read);
            let materials = match &options.part {
                Part::Shard(shard) => shard.materials(catalog, &work, &owned),
                Part::Whole => emit::material_texts(catalog, |_| true),
            };
            (read, inputs, materials)
        },
    );
    if stopped() {
        // Whoever stopped it drops what it would say: what it found so far is not the project's.
        return BuildResult::failed(options, summary, diagnostics);
    }
    let (parts, built, streamed) = passes.into_parts();
    let mut modules = Vec::with_capacity(built.len());
    for pass in built {
        modules.push(pass.modules);
        summary.modules += pass.modules;
        summary.compiled += pass.compiled;
        summary.reused += pass.reused;
        summary.shared += pass.shared;
        summary.bytes_written += pass.bytes_written;
        diagnostics.extend(pass.diagnostics);
    }
    summary.uncut = session.uncut.load(std::sync::atomic::Ordering::Relaxed);
    summary.preprocessed = session.preprocessed.load(std::sync::atomic::Ordering::Relaxed);
    summary.parses = session.parses.load(std::sync::atomic::Ordering::Relaxed);
    summary.parsed_together = session.parsed_together.load(std::sync::atomic::Ordering::Relaxed);
    let (remote_warning, remote_bytes) = session.sources.finish();
    summary.remote_bytes = remote_bytes;
    diagnostics.extend(remote_warning);
    let catalogue = |read| emit::catalogue_part(store, catalog, options, heads, &summary, read);
    match &options.part {
        Part::Shard(shard) => {
            let passes = (mine.par_iter().zip(modules).zip(parts))
                .map(|((work, modules), part)| {
                    shard::ShardPass::new(plan::pass_key(store, options, work), modules, part, options)
                })
                .collect::<std::io::Result<Vec<_>>>()
                .unwrap_or_else(|error| {
                    diagnostics.push(emit::write_failure(&options.output, error));
                    Vec::new()
                });
            // Every shard has the catalogue; the first writes its part for the merge.
            let catalogue = (shard.index == 0).then(|| catalogue(read));
            let parts = shard::ShardParts { catalogue, materials, passes };
            // The catalogue's part keeps the project's counts, for the merge to say; a shard's
            // own summary counts what it built.
            let mut summary = summary;
            summary.shaders =
                mine.iter().map(|w| w.shader_index).collect::<std::collections::BTreeSet<_>>().len();
            summary.passes = mine.len();
            summary.variants = total;
            shard::finish(options, *shard, inputs, parts, summary, diagnostics)
        }
        Part::Whole => {
            let materials: Vec<&serde_json::value::RawValue> = materials.iter().map(|(_, m)| &**m).collect();
            let mut catalogue = catalogue(read);
            let mut manifest = emit::manifest(std::mem::take(&mut catalogue.shaders), parts);
            let mut result = emit::finish(
                options,
                &inputs,
                &catalogue,
                &materials,
                &mut manifest,
                summary,
                diagnostics,
                streamed,
                || Ok(0),
            );
            result.manifest = Some(emit::parsed(manifest));
            result
        }
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn threads_come_from_the_request_then_the_environment_then_the_cores_and_are_bounded() {
        use super::{MAX_THREADS, threads_for};
        assert_eq!(threads_for(Some(3), Some("7"), 16), 3);
        assert_eq!(threads_for(None, Some("7"), 16), 7);
        assert_eq!(threads_for(None, Some("100000"), 16), MAX_THREADS, "RAYON_NUM_THREADS is bounded too");
        assert_eq!(threads_for(Some(100_000), None, 16), MAX_THREADS);
        assert_eq!(threads_for(None, Some("lots"), 16), 16);
        assert_eq!(threads_for(Some(0), Some("0"), 16), 16);
    }
}
