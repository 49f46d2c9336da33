//! Building a project: every used variant of every WGSL pass, preprocessed per stage, identical
//! stage texts compiled once, unchanged ones taken from the cache, the rest compiled in parallel,
//! and the manifest assembled in a fixed order so that output never depends on the thread count.

use super::bind::{self, Declared, PassLayout};
use super::cache::{Cache, CachedStage, ModuleBytes, PassIndex, Recorded, hash};
use super::stage::{self, StageRequest};
use super::target::Allowed;
use super::{Mapper, parse};
use crate::catalog::{Catalog, CatalogPass, CatalogProgram, CatalogShader, property_references};
use crate::config::Backend;
use crate::diagnostics::{self, Diagnostic};
use crate::keywords::Variant;
use crate::preprocess::{Includes, SourceMap, Stage, preprocess};
use crate::reflect::manifest::*;
use crate::reflect::{Resource, StageReflection, UniformBlock};
use crate::shaderlab::ast::{PropertyDefault, PropertyType, Shader};
use crate::shaderlab::pragma::KeywordScope;
use crate::source::{SourceStore, Span};
use rayon::prelude::*;
use std::collections::{BTreeMap, HashMap};
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// Part of every cache key: a new naga may compile differently.
const NAGA_VERSION: &str = "naga 30";

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
    /// `false` for `kiln check`: nothing is written.
    pub write: bool,
    /// Worker threads (default: all cores).
    pub threads: Option<usize>,
    pub backends: Vec<Backend>,
    pub unused_shaders: VariantSelection,
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
    pub bytes_written: u64,
    pub elapsed: Duration,
}

pub struct BuildResult {
    pub manifest: Manifest,
    pub summary: BuildSummary,
    pub diagnostics: Vec<Diagnostic>,
}

/// One distinct stage module of a pass.
struct Job<'a> {
    pass: usize,
    stage: Stage,
    entry: &'a str,
    entry_pragma: Span,
    text: String,
    map: SourceMap,
    text_hash: String,
    allowed: Allowed,
    keywords: Vec<String>,
    /// Which variant asked for it first, for diagnostics.
    context: String,
}

/// A pass being built.
struct PassWork<'a> {
    shader: &'a CatalogShader,
    pass: &'a CatalogPass,
    program: &'a CatalogProgram,
    variants: Vec<Variant>,
    /// For each variant, its vertex and fragment job (`None` when that stage failed or is absent).
    stages: Vec<[Option<usize>; 2]>,
    layout: PassLayout,
    failed: bool,
}

/// Outcome of a job's front end: its declared resources, and the parsed module when it had to be
/// parsed (kept so the stage phase does not parse again).
type Front = Result<(Vec<Declared>, Option<naga::Module>), Diagnostic>;

/// A stage module of a pass, with its cache key: reused from the cache, or compiled now and not
/// yet stored (the pass's compiled modules are packed together once all are done).
enum Built {
    Reused(CachedStage),
    Compiled(Compiled),
}

/// A stage compiled now: its module per backend (`[wgsl, spirv]`), hashed where it was compiled
/// so that packing, which is serial, only concatenates.
struct Compiled {
    modules: [Option<ModuleBytes>; 2],
    reflection: StageReflection,
}

/// `None` when the stage's pass could not be laid out.
type StageOutcome = Option<Result<(Built, String), Diagnostic>>;

/// Builds (or, without `write`, checks) every WGSL pass of the catalogue.
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
    let cache = Cache::new(&options.output, options.write);
    let mut summary = BuildSummary::default();

    // Nothing changed since a clean build: no preprocessing, no naga, nothing written.
    let inputs = inputs_key(store, options);
    if let Some((manifest, counts)) = cache.unchanged(&inputs) {
        let summary = BuildSummary {
            shaders: counts.shaders,
            passes: counts.passes,
            variants: counts.variants,
            modules: counts.modules,
            reused: counts.modules,
            ..BuildSummary::default()
        };
        return BuildResult { summary, manifest, diagnostics };
    }

    // 1. Variants and their preprocessed stage texts, identical ones merged per pass.
    let (mut work, jobs) =
        plan(store, includes, catalog, options.unused_shaders, &mut summary, &mut diagnostics);
    summary.modules = jobs.len();
    let total = jobs.len() * 2;
    let done = AtomicUsize::new(0);
    let tick = || progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);

    // 2-4, a group of passes at a time, as many as there are threads: each pass's resources
    // (cache or parse), one layout, then its stage modules (cache or compile) and its packs. The
    // passes of a group run at once, so one pass's serial steps overlap another's naga work, and
    // only a group's parsed modules are in memory. Results are merged in pass order.
    let mut ranges = Vec::with_capacity(work.len());
    let mut start = 0;
    for p in 0..work.len() {
        let end = start + jobs[start..].iter().take_while(|j| j.pass == p).count();
        ranges.push(start..end);
        start = end;
    }
    let group = rayon::current_num_threads().max(1);
    let mut stages: Vec<Option<CachedStage>> = Vec::with_capacity(jobs.len());
    for (passes, ranges) in work.chunks_mut(group).zip(ranges.chunks(group)) {
        let built: Vec<PassBuilt> = passes
            .par_iter_mut()
            .zip(ranges)
            .map(|(pass, range)| build_pass(pass, &jobs[range.clone()], store, options, &cache, &tick))
            .collect();
        for pass in built {
            summary.compiled += pass.compiled;
            summary.reused += pass.reused;
            summary.bytes_written += pass.bytes_written;
            diagnostics.extend(pass.diagnostics);
            stages.extend(pass.stages);
        }
    }

    // 5. The manifest, in catalogue order.
    let manifest = manifest(store, catalog, &work, &jobs, &stages);
    if options.write && !diagnostics::has_errors(&diagnostics) {
        let mut text = serde_json::to_string_pretty(&manifest).unwrap_or_default();
        text.push('\n');
        let path = options.output.join("manifest.json");
        // An unchanged manifest is not rewritten, so a no-op build touches nothing.
        if std::fs::read(&path).ok().as_deref() != Some(text.as_bytes()) {
            match super::write_atomically(&path, text.as_bytes()) {
                Ok(()) => summary.bytes_written += text.len() as u64,
                Err(error) => diagnostics.push(write_failure(&options.output, &error)),
            }
        }
    }
    diagnostics::dedup(&mut diagnostics);
    if options.write && diagnostics.is_empty() {
        // Only costs a full pass next time if it cannot be written.
        let _ = cache.record_inputs(&Recorded {
            key: inputs,
            shaders: summary.shaders,
            passes: summary.passes,
            variants: summary.variants,
            modules: summary.modules,
        });
    }
    BuildResult { manifest, summary, diagnostics }
}

/// Everything a build's outcome depends on: every file's name and text (shaders, includes,
/// materials, the project file, the bundled library) and the options.
fn inputs_key(store: &SourceStore, options: &BuildOptions) -> String {
    let mut hasher = blake3::Hasher::new();
    for file in store.ids() {
        let (name, text) = (store.name(file), store.text(file));
        hasher.update(&(name.len() as u64).to_le_bytes());
        hasher.update(name.as_bytes());
        hasher.update(&(text.len() as u64).to_le_bytes());
        hasher.update(text.as_bytes());
    }
    let options = format!(
        "{:?}{:?}{}{NAGA_VERSION}",
        options.backends,
        options.unused_shaders,
        env!("CARGO_PKG_VERSION")
    );
    hasher.update(options.as_bytes());
    hasher.finalize().to_hex()[..32].to_string()
}

/// One layout for a pass from the resources of all its modules, or the reasons there is none.
fn lay_out(
    pass: &mut PassWork,
    members: &[Job],
    fronts: &[Front],
    store: &SourceStore,
    diagnostics: &mut Vec<Diagnostic>,
) {
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
                pass.failed = true;
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
        pass.failed = true;
    }
    pass.layout = layout;
}

/// The passes to build and their distinct stage modules, preprocessed.
fn plan<'a>(
    store: &SourceStore,
    includes: &Includes,
    catalog: &'a Catalog,
    selection: VariantSelection,
    summary: &mut BuildSummary,
    diagnostics: &mut Vec<Diagnostic>,
) -> (Vec<PassWork<'a>>, Vec<Job<'a>>) {
    let mut work: Vec<PassWork> = Vec::new();
    let mut jobs: Vec<Job> = Vec::new();
    for shader in &catalog.shaders {
        let mut built_any = false;
        for pass in &shader.passes {
            let Some(program) = pass.program.as_ref().filter(|p| p.wgsl.is_some()) else { continue };
            let variants = select_variants(shader, pass, program, selection, diagnostics);
            if variants.is_empty() {
                continue;
            }
            built_any = true;
            let index = work.len();
            let stages =
                add_jobs(store, includes, shader, pass, program, &variants, index, &mut jobs, diagnostics);
            summary.variants += variants.len();
            summary.passes += 1;
            work.push(PassWork {
                shader,
                pass,
                program,
                variants,
                stages,
                layout: PassLayout::default(),
                failed: false,
            });
        }
        summary.shaders += usize::from(built_any);
    }
    (work, jobs)
}

/// The distinct preprocessed stage texts a build of the catalogue compiles, with their stage and
/// entry point: what naga alone would have to parse, validate and emit for the same output (used
/// by the benchmarks to compare kiln with naga).
pub fn stage_texts(
    store: &SourceStore,
    includes: &Includes,
    catalog: &Catalog,
) -> Vec<(Stage, String, String)> {
    let (_, jobs) =
        plan(store, includes, catalog, VariantSelection::Used, &mut BuildSummary::default(), &mut Vec::new());
    jobs.into_iter().map(|j| (j.stage, j.entry.to_string(), j.text)).collect()
}

fn write_failure(output: &std::path::Path, error: &std::io::Error) -> Diagnostic {
    Diagnostic::error("K0410", format!("cannot write to `{}`: {error}", output.display()))
}

fn select_variants(
    shader: &CatalogShader,
    pass: &CatalogPass,
    program: &CatalogProgram,
    selection: VariantSelection,
    diagnostics: &mut Vec<Diagnostic>,
) -> Vec<Variant> {
    if !program.variants.is_empty() {
        return program.variants.clone();
    }
    match selection {
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
    }
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
/// preprocessed once, in parallel, and identical texts become one job. Returns each variant's
/// vertex and fragment job.
#[allow(clippy::too_many_arguments)]
fn add_jobs<'a>(
    store: &SourceStore,
    includes: &Includes,
    shader: &CatalogShader,
    pass: &CatalogPass,
    program: &'a CatalogProgram,
    variants: &[Variant],
    pass_index: usize,
    jobs: &mut Vec<Job<'a>>,
    diagnostics: &mut Vec<Diagnostic>,
) -> Vec<[Option<usize>; 2]> {
    let Some(wgsl) = program.wgsl.as_ref() else { return vec![[None, None]; variants.len()] };
    let mut requests: Vec<Request> = Vec::new();
    let mut request_of: HashMap<(Stage, crate::keywords::KeywordBits, String), usize> = HashMap::new();
    let mut per_variant: Vec<[Option<usize>; 2]> = Vec::with_capacity(variants.len());
    for variant in variants {
        let all: Vec<&str> = program.keywords.keywords(&variant.bits).collect();
        let allowed = Allowed::for_variant(&program.pragmas, &all);
        let shown = if all.is_empty() { "(no keywords)".to_string() } else { all.join(" ") };
        per_variant.push([Stage::Vertex, Stage::Fragment].map(|stage| {
            let entry = match stage {
                Stage::Vertex => program.pragmas.vertex.as_ref()?,
                Stage::Fragment => program.pragmas.fragment.as_ref()?,
            };
            let bits = program.keywords_for(variant, stage);
            let key = (stage, bits.clone(), allowed.key());
            Some(*request_of.entry(key).or_insert_with(|| {
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
            preprocess(includes, store, wgsl, &keywords, r.stage)
        })
        .collect();
    // Different keywords can still give the same text (a keyword no `#if` of this stage tests).
    let mut job_of_text: HashMap<(Stage, String, String), usize> = HashMap::new();
    let mut job_of_request: Vec<Option<usize>> = Vec::with_capacity(requests.len());
    for (request, out) in requests.into_iter().zip(outputs) {
        let failed = diagnostics::has_errors(&out.diagnostics);
        diagnostics.extend(out.diagnostics.into_iter().map(|d| d.note(request.context.clone())));
        if failed {
            job_of_request.push(None);
            continue;
        }
        let text_hash = hash(out.text.as_bytes());
        let key = (request.stage, text_hash.clone(), request.allowed.key());
        let job = *job_of_text.entry(key).or_insert_with(|| {
            jobs.push(Job {
                pass: pass_index,
                stage: request.stage,
                entry: &request.entry.value,
                entry_pragma: request.entry.span,
                text: out.text,
                map: out.source_map,
                text_hash,
                keywords: request.keywords,
                allowed: request.allowed,
                context: request.context,
            });
            jobs.len() - 1
        });
        job_of_request.push(Some(job));
    }
    per_variant.into_iter().map(|stages| stages.map(|r| r.and_then(|r| job_of_request[r]))).collect()
}

/// Identifies a pass across builds: its shader file and place.
fn pass_key(store: &SourceStore, work: &PassWork) -> String {
    hash(format!("{}#{}.{}", store.name(work.shader.file), work.pass.subshader, work.pass.index).as_bytes())
}

fn front(job: &Job, store: &SourceStore, index: &PassIndex) -> Front {
    if let Some(declared) = index.front.get(&job.text_hash) {
        return Ok((declared.clone(), None));
    }
    let mapper = Mapper { map: &job.map, store };
    let module = parse(&job.text, &mapper).map_err(|d| d.note(job.context.clone()))?;
    Ok((bind::declared(&module), Some(module)))
}

/// What building one pass gives: a stage per job (`None` where it failed), its diagnostics and
/// its share of the summary.
struct PassBuilt {
    stages: Vec<Option<CachedStage>>,
    diagnostics: Vec<Diagnostic>,
    compiled: usize,
    reused: usize,
    bytes_written: u64,
}

/// One pass: the resources each text declares (cache or parse), one layout, then the stage
/// modules (cache or compile), each step in parallel over the pass's jobs; then its packs and
/// its cache index.
fn build_pass(
    pass: &mut PassWork,
    members: &[Job],
    store: &SourceStore,
    options: &BuildOptions,
    cache: &Cache,
    tick: &(dyn Fn() + Sync),
) -> PassBuilt {
    let mut built =
        PassBuilt { stages: Vec::new(), diagnostics: Vec::new(), compiled: 0, reused: 0, bytes_written: 0 };
    let key = pass_key(store, pass);
    let index = cache.pass_index(&key);
    let mut fronts: Vec<Front> = members
        .par_iter()
        .map(|job| {
            let front = front(job, store, &index);
            tick();
            front
        })
        .collect();
    lay_out(pass, members, &fronts, store, &mut built.diagnostics);
    let pass = &*pass;
    let outcomes: Vec<StageOutcome> = members
        .par_iter()
        .zip(fronts.par_iter_mut())
        .map(|(job, front)| {
            let outcome = match front {
                Err(_) => None,
                Ok(_) if pass.failed => None,
                Ok((declared, module)) => {
                    Some(stage_module(job, declared, module.take(), pass, options, store, &index))
                }
            };
            tick();
            outcome
        })
        .collect();
    let compiled: Vec<&Compiled> = outcomes
        .iter()
        .filter_map(|o| match o {
            Some(Ok((Built::Compiled(output), _))) => Some(output),
            _ => None,
        })
        .collect();
    let mut files = match pack_pass(cache, &compiled) {
        Ok((files, written)) => {
            built.bytes_written += written;
            files.into_iter()
        }
        Err(error) => {
            built.diagnostics.push(write_failure(&options.output, &error));
            Vec::new().into_iter()
        }
    };
    let mut fresh = PassIndex::default();
    for ((outcome, front), job) in outcomes.into_iter().zip(&fronts).zip(members) {
        if let Ok((declared, _)) = front {
            fresh.front.insert(job.text_hash.clone(), declared.clone());
        }
        let stage = match outcome {
            Some(Ok((Built::Reused(stage), key))) => {
                built.reused += 1;
                Some((stage, key))
            }
            Some(Ok((Built::Compiled(compiled), key))) => {
                built.compiled += 1;
                // Packing failed: the error is reported, the stage has no files.
                let [wgsl, spirv] = files.next().unwrap_or_default();
                Some((CachedStage { wgsl, spirv, reflection: compiled.reflection }, key))
            }
            Some(Err(mut error)) => {
                error.notes.push(job.context.clone());
                built.diagnostics.push(error);
                None
            }
            None => None,
        };
        built.stages.push(stage.map(|(stage, key)| {
            fresh.stage.insert(key, stage.clone());
            stage
        }));
    }
    if fresh != index {
        // A cache that cannot be written only costs speed next time.
        let _ = cache.put_pass_index(&key, &fresh);
    }
    built
}

fn stage_module(
    job: &Job,
    declared: &[Declared],
    module: Option<naga::Module>,
    pass: &PassWork,
    options: &BuildOptions,
    store: &SourceStore,
    index: &PassIndex,
) -> Result<(Built, String), Diagnostic> {
    let slots: Vec<String> = declared
        .iter()
        .filter_map(|d| pass.layout.slots.get(&d.name).map(|(g, b)| format!("{}@{g}/{b}", d.name)))
        .collect();
    let backends: Vec<&str> =
        options.backends.iter().map(|b| if *b == Backend::Wgsl { "wgsl" } else { "spirv" }).collect();
    let key = hash(
        format!(
            "{}\n{}\n{}\n{}\n{}\n{}\nkiln {}\n{NAGA_VERSION}",
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
    if let Some(cached) = index.stage.get(&key) {
        return Ok((Built::Reused(cached.clone()), key));
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
        layout: &pass.layout,
        backends: &options.backends,
    };
    let output = stage::compile(module, &request, &mapper)?;
    let module = |bytes: Vec<u8>| ModuleBytes { hash: hash(&bytes), bytes };
    let spirv = output.spirv.map(|words| module(words.iter().flat_map(|w| w.to_le_bytes()).collect()));
    let modules = [output.wgsl.map(|text| module(text.into_bytes())), spirv];
    Ok((Built::Compiled(Compiled { modules, reflection: output.reflection }), key))
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

fn manifest(
    store: &SourceStore,
    catalog: &Catalog,
    work: &[PassWork],
    jobs: &[Job],
    stages: &[Option<CachedStage>],
) -> Manifest {
    let mut shaders = Vec::new();
    for shader in &catalog.shaders {
        let passes: Vec<&PassWork> = work.iter().filter(|w| std::ptr::eq(w.shader, shader)).collect();
        if passes.is_empty() {
            continue;
        }
        let passes: Vec<PassManifest> =
            passes.iter().map(|w| pass_manifest(store, catalog, w, jobs, stages)).collect();
        shaders.push(ShaderManifest {
            name: shader.shader.name.value.clone(),
            file: store.name(shader.file).to_string(),
            properties: properties(&shader.shader, &passes),
            passes,
        });
    }
    Manifest { schema_version: SCHEMA_VERSION, kiln_version: env!("CARGO_PKG_VERSION").to_string(), shaders }
}

fn pass_manifest(
    store: &SourceStore,
    catalog: &Catalog,
    work: &PassWork,
    jobs: &[Job],
    stages: &[Option<CachedStage>],
) -> PassManifest {
    let shader = &work.shader.shader;
    let mut entries: BTreeMap<(u32, u32), LayoutEntry> = BTreeMap::new();
    let mut variants = Vec::new();
    // Distinct uniform block layouts of the pass; variants refer to them by index.
    let mut layouts: Vec<UniformBlock> = Vec::new();
    for (variant, stage_jobs) in work.variants.iter().zip(&work.stages) {
        let [vertex, fragment] = stage_jobs.map(|j| j.and_then(|j| Some((j, stages[j].as_ref()?))));
        let mut blocks: Vec<usize> = Vec::new();
        let mut stage_manifest = |found: Option<(usize, &CachedStage)>, name: &str| {
            let (j, stage) = found?;
            let reflection: &StageReflection = &stage.reflection;
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
            for block in &reflection.uniform_blocks {
                let index = layouts.iter().position(|b| b == block).unwrap_or_else(|| {
                    layouts.push(block.clone());
                    layouts.len() - 1
                });
                if !blocks.contains(&index) {
                    blocks.push(index);
                }
            }
            Some(StageManifest {
                module: stage
                    .wgsl
                    .as_ref()
                    .or(stage.spirv.as_ref())
                    .map_or_else(|| format!("job{j}"), |f| f.hash.clone()),
                entry_point: reflection.entry_point.clone(),
                keywords: jobs[j].keywords.clone(),
                wgsl: stage.wgsl.clone(),
                spirv: stage.spirv.clone(),
                inputs: reflection.inputs.clone(),
                outputs: reflection.outputs.clone(),
                bindings: reflection.bindings.iter().map(|b| [b.group, b.binding]).collect(),
            })
        };
        let vertex = stage_manifest(vertex, "vertex");
        let fragment = stage_manifest(fragment, "fragment");
        blocks.sort_by(|&a, &b| layouts[a].name.cmp(&layouts[b].name));
        variants.push(VariantManifest {
            key: variant.bits.key(),
            keywords: work.program.keywords.keywords(&variant.bits).map(str::to_string).collect(),
            materials: variant.materials.iter().map(|&m| catalog.materials[m].name.clone()).collect(),
            vertex,
            fragment,
            uniform_blocks: blocks,
        });
    }
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
            let text = store.slice(command.span).to_string();
            let properties = property_references(&text)
                .into_iter()
                .map(|name| PropertyReference {
                    default: shader
                        .property(name)
                        .map_or(serde_json::Value::Null, |p| default_json(&p.default.value)),
                    name: name.to_string(),
                })
                .collect();
            RenderState { command: text, properties }
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
        layout: groups.into_iter().map(|(group, entries)| BindGroup { group, entries }).collect(),
        uniform_blocks: layouts,
        variants,
    }
}

fn default_json(default: &PropertyDefault) -> serde_json::Value {
    match default {
        PropertyDefault::Number(n) => serde_json::json!(n),
        PropertyDefault::Vector(v) => serde_json::json!(v),
        PropertyDefault::Texture { name, .. } => serde_json::json!(name),
    }
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
            ty: match p.ty.value {
                PropertyType::Range { min, max } => format!("Range({min}, {max})"),
                other => other.name().to_string(),
            },
            default: default_json(&p.default.value),
            offset: material_block
                .and_then(|b| b.members.iter().find(|m| m.name == p.name.value))
                .map(|m| m.offset),
            binding: bindings.get(p.name.value.as_str()).copied(),
        })
        .collect()
}
