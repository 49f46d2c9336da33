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
mod part;
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
use crate::config::Settings;
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
/// module-scope array value let through; 9: HLSL and Cg texts cut to what the entry point reaches,
/// an HLSL pass's bindings numbered over the resources its stages use), so that a cache an earlier kiln of the
/// same version filled is not taken for current.
const COMPILER_REVISION: u32 = 9;

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

/// What one build writes: decided by its caller (a check writes nothing) and by what was reported
/// before it ([`Writes::after`]).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum Writes {
    /// Nothing: a check, or a build after an error.
    Nothing,
    /// The output, and no record of its inputs for the next build's no-op check ([`unchanged`]):
    /// a build after a warning (a no-op build reports nothing), or a one-off build.
    Output,
    /// The output and that record.
    #[default]
    OutputAndRecord,
}

impl Writes {
    /// Whether the output is written.
    pub fn output(self) -> bool {
        self != Writes::Nothing
    }

    /// Whether the record of the build's inputs is written.
    fn record(self) -> bool {
        self == Writes::OutputAndRecord
    }

    /// What a build asked to write `self` writes after `earlier` findings: nothing after an
    /// error. (Warnings are recorded with the no-op, to be said again: [`noop::recordable`].)
    fn after(self, earlier: &[Diagnostic]) -> Writes {
        if crate::diagnostics::has_errors(earlier) { Writes::Nothing } else { self }
    }
}

/// What one run of a build does, beside its [`Settings`]: what its caller decided.
#[derive(Debug, Clone, Default)]
pub struct Run {
    /// What is written.
    pub writes: Writes,
    /// The whole build, one shard of it, or a merge of shards.
    pub part: Part,
    /// How many files the store held from disk before the catalogue was built (the project
    /// file, shaders, materials, variant logs): the rest were read through includes. A no-op
    /// needs the same files given, not merely the same files read.
    pub given_files: usize,
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
    fn failed(settings: &Settings, summary: BuildSummary, diagnostics: Vec<Diagnostic>) -> BuildResult {
        BuildResult { manifest: None, summary, diagnostics, output: settings.output.clone() }
    }
}

/// Builds (or, writing nothing, checks) every pass of the catalogue, or the part of it `run.part`
/// names. `earlier` is what was reported before it (the project's and the catalogue's
/// findings): after an error nothing is written ([`Writes::after`]); the record of a no-op keeps
/// them with the build's own. `progress` is told (variants done, variants in all).
pub fn build(
    store: &SourceStore,
    includes: &Includes,
    catalog: &Catalog,
    settings: &Settings,
    run: &Run,
    earlier: &[Diagnostic],
    progress: &(dyn Fn(usize, usize) + Sync),
) -> BuildResult {
    let run = &Run { writes: run.writes.after(earlier), ..run.clone() };
    timed_in_pool(settings, || build_passes(store, includes, catalog, settings, run, earlier, progress))
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
    settings: &Settings,
    writes: Writes,
    earlier: &[Diagnostic],
    shards: &Merge,
    read: ShardsRead,
) -> BuildResult {
    let writes = writes.after(earlier);
    timed_in_pool(settings, || merge::merge(store, settings, writes, earlier, shards, read))
}

/// Whether rayon's global pool is one [`init_global_pool`] made: with kiln's stacks, and bounded.
static GLOBAL_POOL_IS_KILNS: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Makes rayon's global pool as a build's would be (`threads` workers, as
/// [`config::threads_for`](crate::config::threads_for) counts them, with [`WORKER_STACK`]
/// stacks), for a program whose main work is kiln's (the CLI): a build of that many threads then
/// runs in it rather than in a second pool beside it, so the process never runs more than
/// [`MAX_THREADS`](crate::config::MAX_THREADS) workers, whatever `RAYON_NUM_THREADS` says. Does
/// nothing where the global pool exists already.
pub fn init_global_pool(threads: usize) {
    let built = rayon::ThreadPoolBuilder::new().num_threads(threads).stack_size(WORKER_STACK).build_global();
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

/// Runs `job` on a pool of `settings.threads` (the global pool if one cannot be made), its summary
/// timed.
fn timed_in_pool(settings: &Settings, job: impl FnOnce() -> BuildResult + Send) -> BuildResult {
    let started = Instant::now();
    let mut result = match pool(settings.threads) {
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
    settings: &Settings,
    run: &Run,
    earlier: &[Diagnostic],
    progress: &(dyn Fn(usize, usize) + Sync),
) -> BuildResult {
    let mut diagnostics = Vec::new();
    let mut summary = BuildSummary::default();
    let work = plan::plan(catalog, settings.unused_shaders, &mut summary, &mut diagnostics);
    // A shard decides what it owns before preprocessing anything.
    let owned: Vec<bool> = match &run.part {
        Part::Shard(shard) => shard.owned(&plan::weights(&work)),
        _ => vec![true; work.len()],
    };
    let mine: Vec<&plan::PassWork> = work.iter().zip(&owned).filter(|(_, o)| **o).map(|(w, _)| w).collect();
    let total = mine.iter().map(|w| w.variants.len()).sum();
    let session = session::Session::new(settings, run, progress, total);
    // Only a whole build and the first shard list the shaders (the manifest, the catalogue's part).
    let heads = match &run.part {
        Part::Shard(shard) if shard.index != 0 => Vec::new(),
        _ => emit::shader_heads(store, settings, &work),
    };
    // A whole build's compact manifest is written as its passes finish.
    let manifest_path = settings.output.join(crate::manifest::FILE_NAME);
    let streamed = run.writes.output() && !settings.pretty_manifest && matches!(run.part, Part::Whole);
    let passes = emit::PassParts::new(mine.len(), streamed.then_some((&heads[..], manifest_path.as_path())));
    // Only a check stops early: a build that writes finishes what it began.
    let stopped = || !run.writes.output() && run.cancel.is_cancelled();
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
                    let (part, built) = pass::build_pass(work, store, includes, catalog, &session);
                    passes.add(index, part, built);
                }
            });
        },
        || {
            if !run.writes.output() {
                return Default::default();
            }
            let read = noop::disk_names(store, settings);
            let inputs = noop::inputs_key(store, settings, &read);
            let materials = match &run.part {
                Part::Shard(shard) => shard.materials(catalog, &work, &owned),
                Part::Whole => emit::material_texts(catalog, |_| true),
            };
            (read, inputs, materials)
        },
    );
    if stopped() {
        // Whoever stopped it drops what it would say: what it found so far is not the project's.
        return BuildResult::failed(settings, summary, diagnostics);
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
    let catalogue =
        |read| emit::catalogue_part(store, catalog, settings, run.given_files, heads, &summary, read);
    match &run.part {
        Part::Shard(shard) => {
            let passes = (mine.par_iter().zip(modules).zip(parts))
                .map(|((work, modules), part)| {
                    shard::ShardPass::new(
                        plan::pass_key(store, settings, work),
                        modules,
                        part,
                        settings,
                        run.writes,
                    )
                })
                .collect::<std::io::Result<Vec<_>>>()
                .unwrap_or_else(|error| {
                    diagnostics.push(emit::write_failure(&settings.output, error));
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
            shard::finish(settings, run.writes, *shard, inputs, parts, summary, diagnostics)
        }
        Part::Whole => {
            let materials: Vec<&serde_json::value::RawValue> = materials.iter().map(|(_, m)| &**m).collect();
            let mut catalogue = catalogue(read);
            let mut manifest = emit::manifest(std::mem::take(&mut catalogue.shaders), parts);
            let outputs = emit::Outputs {
                store,
                earlier,
                manifest: &mut manifest,
                materials: &materials,
                catalogue: &catalogue,
                inputs: &inputs,
                streamed,
            };
            let mut result = emit::finish(settings, run.writes, outputs, summary, diagnostics, || Ok(0));
            result.manifest = Some(emit::parsed(manifest));
            result
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Writes;
    use crate::diagnostics::Diagnostic;

    #[test]
    fn a_build_writes_nothing_after_an_error_and_records_its_no_op_after_a_warning() {
        let (warning, error) = (Diagnostic::warning("K0008", "w"), Diagnostic::error("K0003", "e"));
        assert_eq!(Writes::OutputAndRecord.after(&[]), Writes::OutputAndRecord);
        // The record keeps a warning, to be said again (`noop::recordable`).
        assert_eq!(Writes::OutputAndRecord.after(std::slice::from_ref(&warning)), Writes::OutputAndRecord);
        assert_eq!(Writes::OutputAndRecord.after(&[warning.clone(), error.clone()]), Writes::Nothing);
        assert_eq!(Writes::Output.after(&[]), Writes::Output);
        assert_eq!(Writes::Nothing.after(&[warning]), Writes::Nothing);
        assert!(!Writes::Output.record() && Writes::OutputAndRecord.record() && !Writes::Nothing.output());
    }
}
