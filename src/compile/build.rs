//! Building a project: every used variant of every WGSL pass, each pass a parallel task. A pass's
//! variants are preprocessed per stage, identical stage texts compiled once, unchanged ones taken
//! from the cache, the rest compiled in parallel and packed, and the pass's part of the manifest
//! made there, so that memory follows the passes in flight, not the project. The manifest keeps
//! catalogue order, so output never depends on the thread count. Before any of it, [`unchanged`]
//! tells from the last clean build's record that nothing needs doing.

use super::bind::{self, Declared, PassLayout};
use super::cache::{Cache, CachedStage, Digest, Hashed, ModuleBytes, PassIndex, Recorded, hash};
use super::objects::{
    Recent, TextCounts, fetch_object, publish_layouts, publish_object, read_layouts, read_object,
    write_object,
};
use super::shard::{SHARD_FILE, Shard, ShardRecord};
use super::stage::{self, StageRequest};
use super::target::Allowed;
use super::{Mapper, parse};
use crate::catalog::{Catalog, CatalogPass, CatalogProgram, CatalogShader, property_references};
use crate::config::Backend;
use crate::diagnostics::{self, Diagnostic};
use crate::keywords::{KeywordBits, Variant};
use crate::material::MaterialValue;
use crate::preprocess::{Includes, LIBRARY_PREFIX, SourceMap, Stage, preprocess};
use crate::reflect::manifest::*;
use crate::reflect::{Resource, StageReflection, UniformBlock};
use crate::shaderlab::ast::Shader;
use crate::shaderlab::pragma::KeywordScope;
use crate::source::{FileId, SourceStore, Span, relative_to};
use rayon::prelude::*;
use std::borrow::Cow;
use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// Part of every cache key: a new naga may compile differently.
const NAGA_VERSION: &str = "naga 30";

/// Part of every cache key, raised when kiln compiles the same text differently (revision 2:
/// layouts by the WGSL spec, a wider capability baseline), so that a cache an earlier kiln of the
/// same version filled is not taken for current.
const COMPILER_REVISION: u32 = 2;

/// Which variants of a shader no material uses are compiled.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VariantSelection {
    /// None: only what materials (and `always_include`) need. `kiln build`.
    Used,
    /// The default variant and each keyword on its own. `kiln check`.
    DefaultsAndEachKeyword,
    /// The full product, refused above `limit` variants per pass. `kiln check --all-variants`.
    All { limit: u128 },
}

#[derive(Debug, Clone)]
pub struct BuildOptions {
    pub output: PathBuf,
    /// The project folder: the manifest's shader paths and the cache's keys are relative to it,
    /// so that a project builds the same bytes wherever it sits.
    pub root: PathBuf,
    /// `false` for `kiln check`: nothing is written.
    pub write: bool,
    /// Worker threads (default: all cores).
    pub threads: Option<usize>,
    pub backends: Vec<Backend>,
    pub unused_shaders: VariantSelection,
    /// Write `manifest.json` indented (default: compact).
    pub pretty_manifest: bool,
    /// Record the inputs for the next build's no-op check ([`unchanged`]). Only when the
    /// catalogue reported nothing: a no-op build reports nothing either.
    pub record: bool,
    /// The whole build, one shard of it, or a merge of shards.
    pub part: Part,
    /// A module cache shared with other builds: modules are taken from it before naga runs,
    /// and every module compiled is published to it.
    pub cache_dir: Option<PathBuf>,
    /// How many files the store held from disk before the catalogue was built (the project
    /// file, shaders, materials, variant logs): the rest were read through includes. A no-op
    /// needs the same files given, not merely the same files read.
    pub given_files: usize,
}

/// How much of a build one process does.
#[derive(Debug, Clone, Default)]
pub enum Part {
    #[default]
    Whole,
    /// `kiln build --shard I/N`: only this shard's stage modules, as objects in the output folder
    /// (`shard.json`).
    Shard(Shard),
    /// `kiln merge`: the whole build, with the stage modules of shard outputs instead of naga's.
    Merge(Merge),
}

impl BuildOptions {
    fn shard(&self) -> Option<Shard> {
        match self.part {
            Part::Shard(shard) => Some(shard),
            _ => None,
        }
    }

    fn merge(&self) -> Option<&Merge> {
        match &self.part {
            Part::Merge(merge) => Some(merge),
            _ => None,
        }
    }
}

/// Shard outputs a build takes its stage modules from ([`super::shard::check_shards`] checked
/// them against each other).
#[derive(Debug, Clone)]
pub struct Merge {
    pub folders: Vec<PathBuf>,
    /// The inputs hash the shards share, which the project must still have.
    pub inputs: String,
}

#[derive(Debug, Clone, Default, PartialEq)]
pub struct BuildSummary {
    pub shaders: usize,
    pub passes: usize,
    pub variants: usize,
    /// Distinct stage modules.
    pub modules: usize,
    pub compiled: usize,
    pub reused: usize,
    /// Modules another pass of the build compiled (identical stage texts, laid out alike).
    pub shared: usize,
    pub bytes_written: u64,
    pub elapsed: Duration,
    /// Shaders with WGSL programs that no material uses, so nothing of them was built.
    pub unused: Vec<String>,
}

pub struct BuildResult {
    /// `None` when nothing changed since the last clean build ([`unchanged`], which does not
    /// read the manifest): it is in the output folder, as that build wrote it.
    pub manifest: Option<Manifest>,
    pub summary: BuildSummary,
    pub diagnostics: Vec<Diagnostic>,
    /// The output folder (written or not).
    pub output: std::path::PathBuf,
}

/// One distinct stage module of a pass.
struct Job<'a> {
    stage: Stage,
    entry: &'a str,
    entry_pragma: Span,
    text: String,
    map: SourceMap,
    text_hash: String,
    allowed: Allowed,
    /// Which variant asked for it first, for diagnostics.
    context: String,
    /// How many stage requests of the pass's variants it serves (for progress).
    requests: usize,
}

impl Job<'_> {
    /// What the resources a job's module reaches depend on: its text, stage and entry point.
    fn front_key(&self) -> String {
        format!("{} {} {}", self.text_hash, self.stage.name(), self.entry)
    }
}

/// A pass to build. Its jobs are made when it is built, and dropped with it.
struct PassWork<'a> {
    shader: &'a CatalogShader,
    pass: &'a CatalogPass,
    program: &'a CatalogProgram,
    variants: Cow<'a, [Variant]>,
}

/// A pass's distinct stage modules, and each variant's vertex and fragment job (`None` when that
/// stage failed or is absent).
struct PassJobs<'a> {
    jobs: Vec<Job<'a>>,
    stages: Vec<[Option<usize>; 2]>,
}

/// Outcome of a job's front end: its declared resources, and the parsed module when it had to be
/// parsed (kept so the stage phase does not parse again).
type Front = Result<(Vec<Declared>, Option<naga::Module>), Diagnostic>;

/// A stage module of a pass, with its cache key: reused from the cache, or compiled now and not
/// yet stored (the pass's compiled modules are packed together once all are done).
enum Built {
    Reused(Box<CachedStage>),
    Compiled(Arc<Compiled>),
    /// Another shard's to compile.
    Skipped,
    /// Already in this shard's objects.
    Kept,
    /// From the shared cache: packed as if compiled now, but not compiled.
    Fetched(Arc<Compiled>),
    /// Compiled by another pass of this build: packed as if compiled now.
    Shared(Arc<Compiled>),
}

impl Built {
    /// The modules this build packs (compiled now, fetched from the shared cache, or another
    /// pass's); `None` for modules already packed or not this build's.
    fn output(&self) -> Option<&Arc<Compiled>> {
        match self {
            Built::Compiled(output) | Built::Fetched(output) | Built::Shared(output) => Some(output),
            Built::Reused(_) | Built::Skipped | Built::Kept => None,
        }
    }
}

/// A stage compiled now: its module per backend (`[wgsl, spirv]`), hashed where it was compiled
/// so that packing, which is serial, only concatenates.
struct Compiled {
    modules: [Option<ModuleBytes>; 2],
    reflection: StageReflection,
}

/// `None` when the stage's pass could not be laid out.
type StageOutcome = Option<Result<(Built, String), Diagnostic>>;

/// What the passes of one build share: the output's cache, progress, and what other passes
/// compiled and parsed lately (a whole build only: a shard's modules are objects already, a
/// merge compiles nothing).
struct Session<'a> {
    cache: Cache,
    progress: Progress<'a>,
    /// Only texts more than one pass has are kept for sharing.
    texts: TextCounts,
    compiled: Recent<Compiled>,
    parsed: Recent<Vec<Declared>>,
}

/// Bytes of compiled modules, and of parsed resources, a build keeps for its other passes.
const SHARED_MODULE_BYTES: usize = 48 << 20;
const SHARED_FRONT_BYTES: usize = 8 << 20;
const RECENT_SHARDS: usize = 64;

impl Compiled {
    /// About what it holds in memory.
    fn size(&self) -> usize {
        self.modules.iter().flatten().map(|m| m.bytes.len() + m.hash.len()).sum::<usize>() + 1024
    }
}

/// Progress in variants: a pass's variants are counted off as its jobs finish.
struct Progress<'a> {
    report: &'a (dyn Fn(usize, usize) + Sync),
    done: AtomicUsize,
    total: usize,
}

impl Progress<'_> {
    /// `served` of the pass's `requests` stage requests are done: its `variants` advance in
    /// proportion, adding up to exactly `variants` when all are.
    fn advance(&self, variants: usize, requests: usize, before: usize, served: usize) {
        let share = |n: usize| (n * variants).checked_div(requests).unwrap_or(variants);
        let step = share(before + served) - share(before);
        if step > 0 {
            let done = self.done.fetch_add(step, Ordering::Relaxed) + step;
            (self.report)(done, self.total);
        }
    }
}

/// Builds (or, without `write`, checks) every WGSL pass of the catalogue. `progress` is told
/// (variants done, variants in all).
pub fn build(
    store: &SourceStore,
    includes: &Includes,
    catalog: &Catalog,
    options: &BuildOptions,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> BuildResult {
    let started = Instant::now();
    let pool = rayon::ThreadPoolBuilder::new().num_threads(options.threads.unwrap_or(0)).build();
    let run = || build_in_pool(store, includes, catalog, options, progress);
    let mut result = match pool {
        Ok(pool) => pool.install(run),
        Err(_) => run(),
    };
    result.summary.elapsed = started.elapsed();
    result
}

fn build_in_pool(
    store: &SourceStore,
    includes: &Includes,
    catalog: &Catalog,
    options: &BuildOptions,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> BuildResult {
    let mut diagnostics = Vec::new();
    let mut summary = BuildSummary::default();
    if let Some(merge) = options.merge()
        && inputs_key(store, options) != merge.inputs
    {
        let error = Diagnostic::error("K0413", "the shards were built from another state of the project")
            .note("a file the build reads, the project's settings or the build's options changed since")
            .help("build the shards again from this state of the project, then merge them");
        return BuildResult {
            manifest: None,
            summary,
            diagnostics: vec![error],
            output: options.output.clone(),
        };
    }

    let work = plan(catalog, options.unused_shaders, &mut summary, &mut diagnostics);
    let whole = matches!(options.part, Part::Whole);
    let (module_bytes, front_bytes) = if whole { (SHARED_MODULE_BYTES, SHARED_FRONT_BYTES) } else { (0, 0) };
    let session = Session {
        cache: Cache::new(&options.output, options.write),
        progress: Progress { report: progress, done: AtomicUsize::new(0), total: summary.variants },
        texts: TextCounts::new(if whole { RECENT_SHARDS } else { 0 }),
        compiled: Recent::new(module_bytes, RECENT_SHARDS),
        parsed: Recent::new(front_bytes, RECENT_SHARDS),
    };
    let cache = &session.cache;

    // Every pass is a task: its stage texts, their resources (cache or parse), one layout, its
    // stage modules (cache or compile), its packs and its part of the manifest. Threads take
    // passes as they free up (no barrier between passes), so one pass's serial steps overlap
    // other passes' naga work, and only the passes in flight hold texts and modules.
    let built: Vec<PassBuilt> = work
        .par_iter()
        .with_max_len(1)
        .map(|pass| build_pass(pass, store, includes, catalog, options, &session))
        .collect();
    let mut passes: Vec<PassManifest> = Vec::with_capacity(work.len());
    for pass in built {
        summary.modules += pass.modules;
        summary.compiled += pass.compiled;
        summary.reused += pass.reused;
        summary.shared += pass.shared;
        summary.bytes_written += pass.bytes_written;
        diagnostics.extend(pass.diagnostics);
        passes.push(pass.manifest);
    }

    let manifest = manifest(store, options, &work, passes);
    if let Some(shard) = options.shard() {
        // A shard leaves its objects and what `kiln merge` checks; the merge writes the rest.
        diagnostics::dedup(&mut diagnostics);
        if options.write && !diagnostics::has_errors(&diagnostics) {
            let record = ShardRecord {
                kiln_version: env!("CARGO_PKG_VERSION").to_string(),
                inputs: inputs_key(store, options),
                shard: shard.index + 1,
                count: shard.count,
                project: options.root.to_string_lossy().replace('\\', "/"),
                modules: summary.compiled + summary.reused,
            };
            if let Err(error) = write_json(&options.output.join(SHARD_FILE), &record, true) {
                diagnostics.push(write_failure(&options.output, &error));
            }
        }
        return BuildResult { manifest: None, summary, diagnostics, output: options.output.clone() };
    }
    let mut packs = Vec::new();
    if options.write && !diagnostics::has_errors(&diagnostics) {
        packs = manifest.packs().into_iter().collect();
        let written = [
            (
                MATERIALS_FILE,
                write_json(
                    &options.output.join(MATERIALS_FILE),
                    &materials(catalog),
                    options.pretty_manifest,
                ),
            ),
            (FILE_NAME, write_json(&options.output.join(FILE_NAME), &manifest, options.pretty_manifest)),
        ];
        for (name, result) in written {
            match result {
                Ok((len, written)) => {
                    summary.bytes_written += if written { len } else { 0 };
                    packs.push((name.to_string(), len));
                }
                Err(error) => diagnostics.push(write_failure(&options.output, &error)),
            }
        }
    }
    diagnostics::dedup(&mut diagnostics);
    if options.write && options.record && diagnostics.is_empty() {
        let read = disk_files(store).map(|f| recorded_name(store, f, options)).collect();
        // Each path once, however many includes looked there.
        let absent: BTreeSet<String> = store.absent().iter().map(|p| relative_to(p, &options.root)).collect();
        // Only costs a full build next time if it cannot be written.
        let _ = cache.record_inputs(&Recorded {
            key: inputs_key(store, options),
            given: options.given_files,
            shaders: summary.shaders,
            passes: summary.passes,
            variants: summary.variants,
            modules: summary.modules,
            files: packs,
            read,
            absent: absent.into_iter().collect(),
        });
    }
    BuildResult { manifest: Some(manifest), summary, diagnostics, output: options.output.clone() }
}

/// A file's name as the build records it: relative to the project folder for files read from
/// disk, so that nothing recorded depends on where the project sits.
fn recorded_name(store: &SourceStore, file: FileId, options: &BuildOptions) -> String {
    match store.path(file) {
        Some(path) => relative_to(path, &options.root),
        None => store.name(file).to_string(),
    }
}

/// Writes JSON (the manifest, the materials) streamed, so that a million variants' manifest is
/// never a string in memory, and hashed as it goes; a file that already holds exactly these bytes
/// is left as it is, so that a rebuild that compiles nothing touches nothing. Returns its length
/// and whether it was written.
fn write_json(
    path: &std::path::Path,
    value: &impl serde::Serialize,
    pretty: bool,
) -> std::io::Result<(u64, bool)> {
    use std::io::Write as _;
    // What was written, for the comparison with the old file once it is all written.
    let digest = std::cell::RefCell::new(Digest::default());
    let serialize = |out: &mut dyn std::io::Write| {
        let mut out = Hashed { out, digest: Digest::default() };
        if pretty {
            serde_json::to_writer_pretty(&mut out, value)
        } else {
            serde_json::to_writer(&mut out, value)
        }
        .map_err(std::io::Error::other)?;
        out.write_all(b"\n")?;
        digest.replace(out.digest);
        Ok(())
    };
    let changed = |old: &std::path::Path| {
        let new = digest.borrow();
        let same = std::fs::metadata(old).is_ok_and(|m| m.len() == new.len)
            && Digest::of_file(old).is_ok_and(|old| old.finish() == new.finish());
        !same
    };
    let written = super::cache::write_atomically_with(path, serialize, changed)?;
    let len = digest.borrow().len;
    Ok((len, written))
}

/// The files of the store read from disk, in the order read.
fn disk_files(store: &SourceStore) -> impl Iterator<Item = FileId> + '_ {
    store.ids().filter(|&f| store.path(f).is_some())
}

/// Raised when what a build writes changes shape (files added), so that an earlier build's
/// record no longer passes for a no-op. (A new manifest schema does the same.)
const OUTPUT_FORMAT: u32 = 2;

/// Everything a build's outcome depends on: the options, the texts given in memory (global
/// keywords from a build script; the bundled library is part of kiln's version), and every file
/// read from disk (shaders, includes, materials, variant logs, the project file) by its name
/// relative to the project, in the order read.
fn inputs_key(store: &SourceStore, options: &BuildOptions) -> String {
    let mut hasher = blake3::Hasher::new();
    let mut file = |name: &str, bytes: &[u8]| {
        hasher.update(&(name.len() as u64).to_le_bytes());
        hasher.update(name.as_bytes());
        hasher.update(&(bytes.len() as u64).to_le_bytes());
        hasher.update(bytes);
    };
    for f in store.ids().filter(|&f| store.path(f).is_none() && !store.name(f).starts_with(LIBRARY_PREFIX)) {
        file(store.name(f), store.text(f).as_bytes());
    }
    file("<read from disk>", &[]);
    for f in disk_files(store) {
        file(&recorded_name(store, f, options), store.text(f).as_bytes());
    }
    let options = format!(
        "{:?}{:?}{}{} revision {COMPILER_REVISION} {NAGA_VERSION} output {OUTPUT_FORMAT} manifest {SCHEMA_VERSION}",
        options.backends,
        options.unused_shaders,
        options.pretty_manifest,
        env!("CARGO_PKG_VERSION")
    );
    hasher.update(options.as_bytes());
    hasher.finalize().to_hex()[..32].to_string()
}

/// The no-op check, made before the catalogue is built: `store` holds the files found so far
/// (the project file, shaders, materials, variant logs). When they are exactly the files the last
/// clean build was given, the rest it read (includes, read again here into `store`) are
/// unchanged, nothing appeared where it looked in vain,
/// and every file it wrote is in place, nothing needs doing: no parsing, no preprocessing, no
/// naga, and the manifest is not read.
pub fn unchanged(store: &mut SourceStore, options: &BuildOptions) -> Option<BuildResult> {
    let started = Instant::now();
    let cache = Cache::new(&options.output, false);
    let recorded = cache.recorded()?;
    let found: Vec<String> = disk_files(store).map(|f| recorded_name(store, f, options)).collect();
    if found.len() != recorded.given || recorded.read.get(..found.len()) != Some(&found[..]) {
        return None;
    }
    if recorded.absent.par_iter().any(|path| std::fs::symlink_metadata(options.root.join(path)).is_ok()) {
        return None;
    }
    // The includes are read through the store, as a build reads them, so that what it reports
    // as read (a build script's `rerun-if-changed`) is the same whether it compiled or not.
    for name in &recorded.read[found.len()..] {
        let path = options.root.join(name);
        let canonical = store.canonical_file(&path)?;
        store.load_once(&path, canonical).ok()?;
    }
    if !cache.unchanged(&recorded, &inputs_key(store, options)) {
        return None;
    }
    let summary = BuildSummary {
        shaders: recorded.shaders,
        passes: recorded.passes,
        variants: recorded.variants,
        modules: recorded.modules,
        reused: recorded.modules,
        elapsed: started.elapsed(),
        ..BuildSummary::default()
    };
    Some(BuildResult { summary, manifest: None, diagnostics: Vec::new(), output: options.output.clone() })
}

/// One layout for a pass from the resources of all its modules, or the reasons there is none
/// (reported).
fn lay_out(
    members: &[Job],
    fronts: &[Front],
    store: &SourceStore,
    diagnostics: &mut Vec<Diagnostic>,
) -> Option<PassLayout> {
    let mut failed = false;
    let mut declared: Vec<&[Declared]> = Vec::new();
    let mut owners = Vec::new();
    for (j, front) in fronts.iter().enumerate() {
        match front {
            Ok((d, _)) => {
                declared.push(d);
                owners.push(j);
            }
            Err(error) => {
                diagnostics.push(error.clone());
                failed = true;
            }
        }
    }
    let (layout, clashes) = bind::layout(&declared);
    for (m, d, message) in clashes {
        let job = &members[owners[m]];
        let range = declared[m][d].range;
        let mapper = Mapper { map: &job.map, store };
        let diagnostic = Diagnostic::error("K0406", message).help(
            "give each resource its own slot, or leave out `@group`/`@binding` and let kiln assign them",
        );
        let mut diagnostic = mapper
            .diagnostic_at(diagnostic, vec![(range.0 as usize..range.1 as usize, "declared here".into())]);
        diagnostic.notes.push(job.context.clone());
        diagnostics.push(diagnostic);
        failed = true;
    }
    (!failed).then_some(layout)
}

/// The passes to build, with their variants.
fn plan<'a>(
    catalog: &'a Catalog,
    selection: VariantSelection,
    summary: &mut BuildSummary,
    diagnostics: &mut Vec<Diagnostic>,
) -> Vec<PassWork<'a>> {
    let mut work: Vec<PassWork> = Vec::new();
    for shader in &catalog.shaders {
        let (mut built_any, mut has_wgsl) = (false, false);
        for pass in &shader.passes {
            let Some(program) = pass.program.as_ref().filter(|p| p.wgsl.is_some()) else { continue };
            has_wgsl = true;
            let variants = select_variants(shader, pass, program, selection, diagnostics);
            if variants.is_empty() {
                continue;
            }
            built_any = true;
            summary.variants += variants.len();
            summary.passes += 1;
            work.push(PassWork { shader, pass, program, variants });
        }
        summary.shaders += usize::from(built_any);
        if has_wgsl && !built_any && selection == VariantSelection::Used {
            summary.unused.push(shader.shader.name.value.clone());
        }
    }
    work
}

/// The distinct preprocessed stage texts a build of the catalogue compiles, with their stage and
/// entry point: what naga alone would have to parse, validate and emit for the same output (used
/// by the benchmarks to compare kiln with naga).
pub fn stage_texts(
    store: &SourceStore,
    includes: &Includes,
    catalog: &Catalog,
) -> Vec<(Stage, String, String)> {
    let work = plan(catalog, VariantSelection::Used, &mut BuildSummary::default(), &mut Vec::new());
    work.iter()
        .flat_map(|pass| pass_jobs(store, includes, pass, &mut Vec::new()).jobs)
        .map(|j| (j.stage, j.entry.to_string(), j.text))
        .collect()
}

fn write_failure(output: &std::path::Path, error: &std::io::Error) -> Diagnostic {
    Diagnostic::error("K0410", format!("cannot write to `{}`: {error}", output.display()))
}

fn select_variants<'a>(
    shader: &CatalogShader,
    pass: &CatalogPass,
    program: &'a CatalogProgram,
    selection: VariantSelection,
    diagnostics: &mut Vec<Diagnostic>,
) -> Cow<'a, [Variant]> {
    if !program.variants.is_empty() {
        return Cow::Borrowed(&program.variants);
    }
    Cow::Owned(match selection {
        VariantSelection::Used => Vec::new(),
        VariantSelection::DefaultsAndEachKeyword => program.keywords.defaults_and_each_keyword(),
        VariantSelection::All { limit } => match program.keywords.possible() {
            Some(n) if n <= limit => program.keywords.enumerate(&[], true, None).unwrap_or_default(),
            count => {
                let count = count.map_or("more than 2^128".to_string(), |n| n.to_string());
                let span =
                    program.pragmas.keyword_sets.first().map(|s| s.span).unwrap_or(shader.shader.name.span);
                diagnostics.push(
                    Diagnostic::error(
                        "K0408",
                        format!(
                            "pass {} of `{}` has {count} variants, over the limit of {limit}",
                            pass.index, shader.shader.name.value
                        ),
                    )
                    .at(span, "its keyword sets multiply to that many")
                    .help("check the variants materials use with `kiln check` (without `--all-variants`)"),
                );
                Vec::new()
            }
        },
    })
}

/// One stage of one variant, to preprocess.
struct Request<'a> {
    stage: Stage,
    entry: &'a crate::source::Spanned<String>,
    keywords: Vec<String>,
    allowed: Allowed,
    context: String,
}

/// The distinct stage texts of a pass's variants: each (stage, stage keywords, target) is
/// preprocessed once, in parallel, and identical texts become one job.
fn pass_jobs<'a>(
    store: &SourceStore,
    includes: &Includes,
    work: &PassWork<'a>,
    diagnostics: &mut Vec<Diagnostic>,
) -> PassJobs<'a> {
    let (shader, pass, program) = (work.shader, work.pass, work.program);
    let mut jobs: Vec<Job<'a>> = Vec::new();
    let Some(wgsl) = program.wgsl.as_ref() else {
        return PassJobs { jobs, stages: vec![[None, None]; work.variants.len()] };
    };
    let mut requests: Vec<Request> = Vec::new();
    let mut request_of: HashMap<(Stage, &KeywordBits, String), usize> = HashMap::new();
    let mut per_variant: Vec<[Option<usize>; 2]> = Vec::with_capacity(work.variants.len());
    for variant in work.variants.iter() {
        let all: Vec<&str> = program.keywords.keywords(&variant.bits).collect();
        let allowed = Allowed::for_variant(&program.pragmas, &all);
        per_variant.push([Stage::Vertex, Stage::Fragment].map(|stage| {
            let entry = match stage {
                Stage::Vertex => program.pragmas.vertex.as_ref()?,
                Stage::Fragment => program.pragmas.fragment.as_ref()?,
            };
            let bits = program.keywords_for(variant, stage);
            Some(*request_of.entry((stage, bits, allowed.key())).or_insert_with(|| {
                let shown = if all.is_empty() { "(no keywords)".to_string() } else { all.join(" ") };
                requests.push(Request {
                    stage,
                    entry,
                    keywords: program.keywords.keywords(bits).map(str::to_string).collect(),
                    allowed: allowed.clone(),
                    context: format!(
                        "in variant `{shown}` of `{}` pass {}, {} stage",
                        shader.shader.name.value,
                        pass.index,
                        stage.name()
                    ),
                });
                requests.len() - 1
            }))
        }));
    }
    let outputs: Vec<_> = requests
        .par_iter()
        .map(|r| {
            let keywords: Vec<&str> = r.keywords.iter().map(String::as_str).collect();
            let out = preprocess(includes, store, wgsl, &keywords, r.stage);
            let text_hash = hash(out.text.as_bytes());
            (out, text_hash)
        })
        .collect();
    // Different keywords can still give the same text (a keyword no `#if` of this stage tests).
    let mut job_of_text: HashMap<(Stage, String, String), usize> = HashMap::new();
    let mut job_of_request: Vec<Option<usize>> = Vec::with_capacity(requests.len());
    for (request, (out, text_hash)) in requests.into_iter().zip(outputs) {
        let failed = diagnostics::has_errors(&out.diagnostics);
        diagnostics.extend(out.diagnostics.into_iter().map(|d| d.note(request.context.clone())));
        if failed {
            job_of_request.push(None);
            continue;
        }
        let key = (request.stage, text_hash.clone(), request.allowed.key());
        let job = *job_of_text.entry(key).or_insert_with(|| {
            jobs.push(Job {
                stage: request.stage,
                entry: &request.entry.value,
                entry_pragma: request.entry.span,
                text: out.text,
                map: out.source_map,
                text_hash,
                allowed: request.allowed,
                context: request.context,
                requests: 0,
            });
            jobs.len() - 1
        });
        jobs[job].requests += 1;
        job_of_request.push(Some(job));
    }
    let stages =
        per_variant.into_iter().map(|stages| stages.map(|r| r.and_then(|r| job_of_request[r]))).collect();
    PassJobs { jobs, stages }
}

/// Identifies a pass across builds: its shader file (relative to the project) and place.
fn pass_key(store: &SourceStore, options: &BuildOptions, work: &PassWork) -> String {
    let file = recorded_name(store, work.shader.file, options);
    hash(format!("{file}#{}.{}", work.pass.subshader, work.pass.index).as_bytes())
}

/// A stage text's declared resources: from the cache (`known`), another pass of the build, or
/// parsed now.
fn front(
    job: &Job,
    store: &SourceStore,
    known: &BTreeMap<String, Vec<Declared>>,
    session: &Session,
) -> Front {
    let key = job.front_key();
    if let Some(declared) = known.get(&key) {
        return Ok((declared.clone(), None));
    }
    let shared = session.texts.shared(&job.text_hash);
    if shared && let Some(declared) = session.parsed.get(&key) {
        return Ok(((*declared).clone(), None));
    }
    let mapper = Mapper { map: &job.map, store };
    let module = parse(&job.text, &mapper).map_err(|d| d.note(job.context.clone()))?;
    let declared = bind::declared(&module, job.entry, stage::naga_stage(job.stage));
    if shared {
        let size = declared.iter().map(|d| d.name.len() + 64).sum();
        session.parsed.insert(&key, Arc::new(declared.clone()), size);
    }
    Ok((declared, Some(module)))
}

/// The resources each stage text of a pass declares, by text hash (texts that did not parse
/// left out).
fn declared_by_text(jobs: &[Job], fronts: &[Front]) -> BTreeMap<String, Vec<Declared>> {
    jobs.iter()
        .zip(fronts)
        .filter_map(|(job, front)| Some((job.front_key(), front.as_ref().ok()?.0.clone())))
        .collect()
}

/// What building one pass gives: its part of the manifest, its diagnostics and its share of the
/// summary.
struct PassBuilt {
    manifest: PassManifest,
    diagnostics: Vec<Diagnostic>,
    modules: usize,
    compiled: usize,
    reused: usize,
    shared: usize,
    bytes_written: u64,
}

/// One pass: its stage texts, the resources each declares (cache or parse), one layout, then the
/// stage modules (cache or compile), each step in parallel over the pass's jobs; then its packs,
/// its cache index and its manifest. Its texts and modules are dropped when it returns.
fn build_pass(
    work: &PassWork,
    store: &SourceStore,
    includes: &Includes,
    catalog: &Catalog,
    options: &BuildOptions,
    session: &Session,
) -> PassBuilt {
    let (cache, progress) = (&session.cache, &session.progress);
    let mut diagnostics = Vec::new();
    let PassJobs { jobs, stages } = pass_jobs(store, includes, work, &mut diagnostics);
    for job in &jobs {
        session.texts.add(&job.text_hash);
    }
    let (mut compiled_count, mut reused, mut shared, mut bytes_written) = (0, 0, 0, 0);
    let key = pass_key(store, options, work);
    let index = cache.pass_index(&key);
    // Every shard keeps every stage text's resources, so a merge lays passes out from the first
    // shard's without parsing anything.
    let mut known = match options.merge() {
        Some(merge) if index.front.is_empty() => Cache::new(&merge.folders[0], false).pass_index(&key).front,
        _ => index.front.clone(),
    };
    if let Some(dir) = &options.cache_dir
        && jobs.iter().any(|j| !known.contains_key(&j.front_key()))
    {
        for (text, declared) in read_layouts(dir, &key) {
            known.entry(text).or_insert(declared);
        }
    }
    let mut fronts: Vec<Front> = jobs.par_iter().map(|job| front(job, store, &known, session)).collect();
    // What was parsed now is published for every other build of the pass.
    if let Some(dir) = &options.cache_dir
        && fronts.iter().any(|f| matches!(f, Ok((_, Some(_)))))
    {
        publish_layouts(dir, &key, &declared_by_text(&jobs, &fronts));
    }
    let layout = lay_out(&jobs, &fronts, store, &mut diagnostics);
    let requests: usize = jobs.iter().map(|j| j.requests).sum();
    let served = AtomicUsize::new(0);
    let outcomes: Vec<StageOutcome> = jobs
        .par_iter()
        .zip(fronts.par_iter_mut())
        .map(|(job, front)| {
            let outcome = match front {
                Ok((declared, module)) => layout.as_ref().map(|layout| {
                    stage_module(job, declared, module.take(), layout, options, store, &index, session)
                }),
                Err(_) => None,
            };
            let before = served.fetch_add(job.requests, Ordering::Relaxed);
            progress.advance(work.variants.len(), requests, before, job.requests);
            outcome
        })
        .collect();
    if options.shard().is_some() {
        // The resources of every stage text, own or not: the next round and the merge parse none.
        let fresh = PassIndex { front: declared_by_text(&jobs, &fronts), stage: BTreeMap::new() };
        if fresh != index {
            let _ = cache.put_pass_index(&key, &fresh);
        }
        return shard_pass(work, store, catalog, options, &jobs, &stages, outcomes, diagnostics);
    }
    let compiled: Vec<&Compiled> =
        outcomes.iter().filter_map(|o| Some(&**o.as_ref()?.as_ref().ok()?.0.output()?)).collect();
    let mut files = match pack_pass(cache, &compiled) {
        Ok((files, written)) => {
            bytes_written += written;
            files.into_iter()
        }
        Err(error) => {
            diagnostics.push(write_failure(&options.output, &error));
            Vec::new().into_iter()
        }
    };
    let mut fresh = PassIndex { front: declared_by_text(&jobs, &fronts), stage: BTreeMap::new() };
    let mut modules: Vec<Option<CachedStage>> = Vec::with_capacity(jobs.len());
    for (outcome, job) in outcomes.into_iter().zip(&jobs) {
        let stage = match outcome {
            Some(Ok((Built::Reused(stage), key))) => {
                reused += 1;
                Some((*stage, key))
            }
            Some(Ok((built, key))) => built.output().map(|module| {
                match built {
                    Built::Compiled(_) => {
                        compiled_count += 1;
                        if let Some(dir) = &options.cache_dir {
                            publish_object(dir, &key, &module.modules, &module.reflection);
                        }
                    }
                    Built::Shared(_) => shared += 1,
                    _ => reused += 1,
                }
                // Packing failed: the error is reported, the stage has no files.
                let [wgsl, spirv] = files.next().unwrap_or_default();
                (CachedStage { wgsl, spirv, reflection: module.reflection.clone() }, key)
            }),
            Some(Err(mut error)) => {
                error.notes.push(job.context.clone());
                diagnostics.push(error);
                None
            }
            None => None,
        };
        modules.push(stage.map(|(stage, key)| {
            fresh.stage.insert(key, stage.clone());
            stage
        }));
    }
    if fresh != index {
        // A cache that cannot be written only costs speed next time.
        let _ = cache.put_pass_index(&key, &fresh);
    }
    PassBuilt {
        manifest: pass_manifest(store, catalog, work, &jobs, &stages, &modules),
        diagnostics,
        modules: jobs.len(),
        compiled: compiled_count,
        reused,
        shared,
        bytes_written,
    }
}

/// A shard's pass: its own modules stored as objects (nothing packed, no manifest part).
#[allow(clippy::too_many_arguments)]
fn shard_pass(
    work: &PassWork,
    store: &SourceStore,
    catalog: &Catalog,
    options: &BuildOptions,
    jobs: &[Job],
    stages: &[[Option<usize>; 2]],
    outcomes: Vec<StageOutcome>,
    mut diagnostics: Vec<Diagnostic>,
) -> PassBuilt {
    let (mut compiled, mut reused, mut bytes_written) = (0, 0, 0);
    for (outcome, job) in outcomes.into_iter().zip(jobs) {
        match outcome {
            Some(Ok((Built::Kept, _))) => reused += 1,
            Some(Ok((built, key))) => {
                // Only a whole build shares between passes: a shard compiles or fetches.
                let Some(module) = built.output() else { continue };
                if let Built::Compiled(_) = built {
                    compiled += 1;
                    if let Some(dir) = &options.cache_dir {
                        publish_object(dir, &key, &module.modules, &module.reflection);
                    }
                } else {
                    reused += 1;
                }
                if options.write {
                    match write_object(&options.output, &key, &module.modules, &module.reflection) {
                        Ok(written) => bytes_written += written,
                        Err(error) => diagnostics.push(write_failure(&options.output, &error)),
                    }
                }
            }
            Some(Err(mut error)) => {
                error.notes.push(job.context.clone());
                diagnostics.push(error);
            }
            None => {}
        }
    }
    let nothing = vec![None; jobs.len()];
    PassBuilt {
        manifest: pass_manifest(store, catalog, work, jobs, stages, &nothing),
        diagnostics,
        modules: compiled + reused,
        compiled,
        reused,
        shared: 0,
        bytes_written,
    }
}

#[allow(clippy::too_many_arguments)]
fn stage_module(
    job: &Job,
    declared: &[Declared],
    module: Option<naga::Module>,
    layout: &PassLayout,
    options: &BuildOptions,
    store: &SourceStore,
    index: &PassIndex,
    session: &Session,
) -> Result<(Built, String), Diagnostic> {
    let slots: Vec<String> = declared
        .iter()
        .filter_map(|d| layout.slots.get(&d.name).map(|(g, b)| format!("{}@{g}/{b}", d.name)))
        .collect();
    let backends: Vec<&str> =
        options.backends.iter().map(|b| if *b == Backend::Wgsl { "wgsl" } else { "spirv" }).collect();
    let key = hash(
        format!(
            "{}\n{}\n{}\n{}\n{}\n{}\nkiln {} revision {COMPILER_REVISION}\n{NAGA_VERSION}",
            job.text_hash,
            job.stage.name(),
            job.entry,
            job.allowed.key(),
            slots.join(","),
            backends.join(","),
            env!("CARGO_PKG_VERSION")
        )
        .as_bytes(),
    );
    if let Some(shard) = options.shard() {
        if !shard.owns(&key) {
            return Ok((Built::Skipped, key));
        }
        if read_object(&options.output, &key).is_some() {
            return Ok((Built::Kept, key));
        }
    }
    // A shard's modules are objects: a whole build's packs in the same folder are not its own.
    if options.shard().is_none()
        && let Some(cached) = index.stage.get(&key)
    {
        return Ok((Built::Reused(Box::new(cached.clone())), key));
    }
    if let Some(merge) = options.merge() {
        // Every module comes from the shard that owns it; naga is not run.
        let found = merge.folders.iter().find_map(|folder| read_object(folder, &key));
        return match found {
            Some((modules, reflection)) => {
                Ok((Built::Compiled(Arc::new(Compiled { modules, reflection })), key))
            }
            None => Err(Diagnostic::error(
                "K0412",
                format!("no shard holds the {} module of `{}`", job.stage.name(), job.entry),
            )
            .note("its shard's output is damaged, or was built from another state of the project")),
        };
    }
    if let Some(dir) = &options.cache_dir
        && let Some((modules, reflection)) = fetch_object(dir, &key)
    {
        return Ok((Built::Fetched(Arc::new(Compiled { modules, reflection })), key));
    }
    if session.texts.shared(&job.text_hash)
        && let Some(compiled) = session.compiled.get(&key)
    {
        return Ok((Built::Shared(compiled), key));
    }
    let mapper = Mapper { map: &job.map, store };
    let module = match module {
        Some(module) => module,
        None => parse(&job.text, &mapper)?,
    };
    let request = StageRequest {
        text: &job.text,
        stage: job.stage,
        entry: job.entry,
        entry_pragma: job.entry_pragma,
        allowed: &job.allowed,
        layout,
        backends: &options.backends,
    };
    let output = stage::compile(module, &request, &mapper)?;
    let module = |bytes: Vec<u8>| ModuleBytes { hash: hash(&bytes), bytes };
    let spirv = output.spirv.map(|words| module(words.iter().flat_map(|w| w.to_le_bytes()).collect()));
    let modules = [output.wgsl.map(|text| module(text.into_bytes())), spirv];
    let compiled = Arc::new(Compiled { modules, reflection: output.reflection });
    // Asked again now: another pass may have found the text meanwhile.
    if session.texts.shared(&job.text_hash) {
        session.compiled.insert(&key, compiled.clone(), compiled.size());
    }
    Ok((Built::Compiled(compiled), key))
}

/// Packs a pass's newly compiled modules, one pack per backend; returns each module's
/// `[wgsl, spirv]` files, in order, and the bytes written.
fn pack_pass(cache: &Cache, compiled: &[&Compiled]) -> std::io::Result<(Vec<[Option<FileRef>; 2]>, u64)> {
    let mut files: Vec<[Option<FileRef>; 2]> = vec![[None, None]; compiled.len()];
    let mut written = 0;
    for (slot, extension) in [(0, "wgsl.pack"), (1, "spv.pack")] {
        let present: Vec<(usize, &ModuleBytes)> =
            compiled.iter().enumerate().filter_map(|(i, c)| Some((i, c.modules[slot].as_ref()?))).collect();
        if present.is_empty() {
            continue;
        }
        let modules: Vec<&ModuleBytes> = present.iter().map(|(_, m)| *m).collect();
        let (refs, count) = cache.pack(&modules, extension)?;
        written += count;
        for ((i, _), file) in present.iter().zip(refs) {
            files[*i][slot] = Some(file);
        }
    }
    Ok((files, written))
}

/// The manifest: the built passes grouped by shader, in catalogue order.
fn manifest(
    store: &SourceStore,
    options: &BuildOptions,
    work: &[PassWork],
    passes: Vec<PassManifest>,
) -> Manifest {
    let mut grouped: Vec<(&CatalogShader, Vec<PassManifest>)> = Vec::new();
    for (w, pass) in work.iter().zip(passes) {
        match grouped.last_mut() {
            Some((shader, passes)) if std::ptr::eq(*shader, w.shader) => passes.push(pass),
            _ => grouped.push((w.shader, vec![pass])),
        }
    }
    let shaders = grouped
        .into_iter()
        .map(|(shader, passes)| ShaderManifest {
            name: shader.shader.name.value.clone(),
            file: recorded_name(store, shader.file, options),
            render_queue: crate::material::shader_queue(&shader.shader),
            properties: properties(&shader.shader, &passes),
            passes,
        })
        .collect();
    Manifest { schema_version: SCHEMA_VERSION, kiln_version: env!("CARGO_PKG_VERSION").to_string(), shaders }
}

/// A pass's part of the manifest: each module once, each distinct interface, uniform block and
/// pack once, and its variants as module indices.
fn pass_manifest(
    store: &SourceStore,
    catalog: &Catalog,
    work: &PassWork,
    jobs: &[Job],
    stages: &[[Option<usize>; 2]],
    built: &[Option<CachedStage>],
) -> PassManifest {
    let shader = &work.shader.shader;
    let mut entries: BTreeMap<(u32, u32), LayoutEntry> = BTreeMap::new();
    let mut uniform_blocks: Vec<UniformBlock> = Vec::new();
    let mut packs: Vec<String> = Vec::new();
    let mut pack_of: HashMap<String, usize> = HashMap::new();
    let mut interfaces: Vec<StageInterface> = Vec::new();
    let mut interface_of: HashMap<StageInterface, usize> = HashMap::new();
    let mut modules: Vec<ModuleManifest> = Vec::new();
    // A module is its interface, its files' hashes and the features it was validated with.
    type ModuleIdentity = (usize, [Option<String>; 2], Vec<String>);
    let mut module_of: HashMap<ModuleIdentity, usize> = HashMap::new();
    // For each job, its module (`None` when it failed).
    let mut module_of_job: Vec<Option<usize>> = Vec::with_capacity(jobs.len());
    for (job, stage) in jobs.iter().zip(built) {
        let Some(stage) = stage else {
            module_of_job.push(None);
            continue;
        };
        let reflection = &stage.reflection;
        let name = job.stage.name();
        for b in &reflection.bindings {
            let entry = entries.entry((b.group, b.binding)).or_insert_with(|| LayoutEntry {
                binding: b.binding,
                name: b.name.clone(),
                visibility: Vec::new(),
                resource: b.resource.clone(),
            });
            if !entry.visibility.iter().any(|v| v == name) {
                entry.visibility.push(name.to_string());
            }
        }
        let mut blocks: Vec<usize> = reflection
            .uniform_blocks
            .iter()
            .map(|block| {
                uniform_blocks.iter().position(|b| b == block).unwrap_or_else(|| {
                    uniform_blocks.push(block.clone());
                    uniform_blocks.len() - 1
                })
            })
            .collect();
        blocks.sort_by(|&a, &b| uniform_blocks[a].name.cmp(&uniform_blocks[b].name));
        let interface = StageInterface {
            stage: name.to_string(),
            entry_point: reflection.entry_point.clone(),
            inputs: reflection.inputs.clone(),
            outputs: reflection.outputs.clone(),
            bindings: reflection.bindings.iter().map(|b| [b.group, b.binding]).collect(),
            uniform_blocks: blocks,
        };
        let interface = *interface_of.entry(interface).or_insert_with_key(|interface| {
            interfaces.push(interface.clone());
            interfaces.len() - 1
        });
        let mut file = |file: &Option<FileRef>| {
            file.as_ref().map(|f| {
                let pack = *pack_of.entry(f.path.clone()).or_insert_with(|| {
                    packs.push(f.path.clone());
                    packs.len() - 1
                });
                ModuleFile { pack, offset: f.offset, size: f.size, hash: f.hash.clone() }
            })
        };
        // Texts that differ only where compaction removes code give the same module.
        let hashes = [&stage.wgsl, &stage.spirv].map(|f| f.as_ref().map(|f| f.hash.clone()));
        let module =
            *module_of.entry((interface, hashes, job.allowed.features())).or_insert_with_key(|key| {
                let (wgsl, spirv) = (file(&stage.wgsl), file(&stage.spirv));
                modules.push(ModuleManifest { interface, features: key.2.clone(), wgsl, spirv });
                modules.len() - 1
            });
        module_of_job.push(Some(module));
    }
    let variants = work
        .variants
        .iter()
        .zip(stages)
        .map(|(variant, [vertex, fragment])| VariantManifest {
            key: variant.bits.key(),
            keywords: work.program.keywords.keywords(&variant.bits).map(str::to_string).collect(),
            materials: variant.materials.iter().map(|&m| catalog.materials[m].name.clone()).collect(),
            vertex: vertex.and_then(|j| module_of_job[j]),
            fragment: fragment.and_then(|j| module_of_job[j]),
        })
        .collect();
    let mut groups: BTreeMap<u32, Vec<LayoutEntry>> = BTreeMap::new();
    for ((group, _), mut entry) in entries {
        entry.visibility.sort();
        groups.entry(group).or_default().push(entry);
    }
    let render_state = work
        .shader
        .shader
        .subshaders
        .get(work.pass.subshader)
        .map(|sub| &sub.state.render_state)
        .into_iter()
        .flatten()
        .chain(work.shader.pass_ast(work.pass).map(|p| &p.state.render_state).into_iter().flatten())
        .map(|command| {
            let text = store.slice(command.span).trim().to_string();
            let properties = property_references(&text)
                .into_iter()
                .map(|name| PropertyReference {
                    default: shader
                        .property(name)
                        .map_or(serde_json::Value::Null, |p| MaterialValue::from(&p.default.value).to_json()),
                    name: name.to_string(),
                })
                .collect();
            RenderState { command: text, state: StateCommand::from_ast(&command.kind), properties }
        })
        .collect();
    PassManifest {
        subshader: work.pass.subshader,
        index: work.pass.index,
        name: work.pass.name.clone(),
        tags: work.pass.tags.clone(),
        render_state,
        keyword_sets: work
            .program
            .keywords
            .sets()
            .iter()
            .map(|set| KeywordSetManifest {
                kind: set.kind.name().to_string(),
                scope: if set.scope == KeywordScope::Local { "local" } else { "global" }.to_string(),
                stage: set.stage.name().to_string(),
                keywords: set
                    .options
                    .iter()
                    .map(|o| o.keyword.clone().unwrap_or_else(|| "_".into()))
                    .collect(),
            })
            .collect(),
        keywords: work.program.keywords.names().to_vec(),
        layout: groups.into_iter().map(|(group, entries)| BindGroup { group, entries }).collect(),
        uniform_blocks,
        packs,
        interfaces,
        modules,
        variants,
    }
}

/// Every resolved material, for the run time (`materials.json`).
fn materials(catalog: &Catalog) -> Vec<MaterialManifest> {
    catalog
        .materials
        .iter()
        .filter_map(|m| Some(MaterialManifest::new(m, &catalog.shaders.get(m.shader)?.shader.name.value)))
        .collect()
}

/// The shader's properties, with their place in the material block (from the first variant that
/// has one) and their texture bindings.
fn properties(shader: &Shader, passes: &[PassManifest]) -> Vec<PropertyManifest> {
    let material_block = passes.iter().flat_map(|p| &p.uniform_blocks).find(|b| b.name == "UnityPerMaterial");
    let mut bindings: HashMap<&str, [u32; 2]> = HashMap::new();
    for pass in passes {
        for group in &pass.layout {
            for entry in &group.entries {
                if matches!(entry.resource, Resource::Texture { .. } | Resource::StorageTexture { .. }) {
                    bindings.entry(entry.name.as_str()).or_insert([group.group, entry.binding]);
                }
            }
        }
    }
    shader
        .properties
        .iter()
        .map(|p| PropertyManifest {
            name: p.name.value.clone(),
            display_name: p.display_name.value.clone(),
            ty: p.ty.value.manifest_text(),
            default: MaterialValue::from(&p.default.value).to_json(),
            offset: material_block
                .and_then(|b| b.members.iter().find(|m| m.name == p.name.value))
                .map(|m| m.offset),
            binding: bindings.get(p.name.value.as_str()).copied(),
            drawer: crate::material::KeywordDrawer::of(p),
            enum_names: crate::material::enum_names(p),
        })
        .collect()
}
