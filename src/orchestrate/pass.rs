//! One pass: its stage texts, the resources each declares, one layout, then its stage modules,
//! each step in parallel over the pass's jobs; then its packs, its entry in the output's cache
//! and its part of the manifest. Its texts and modules are dropped when it returns.

use super::emit::{BuiltPass, write_failure};
use super::jobs::{Job, PassJobs, pass_jobs};
use super::part::{CompiledPass, pass_manifest};
use super::plan::{PassWork, pass_key};
use super::session::Session;
use super::sources::{Front, ModuleAsk, PassSources, parse_together};
use super::tasks::map_tasks;
use super::{COMPILER_REVISION, NAGA_VERSION};
use crate::catalog::Catalog;
use crate::compile::Mapper;
use crate::compile::bind::{self, Declared, PassLayout};
use crate::config::Settings;
use crate::diagnostics::Diagnostic;
use crate::manifest::{Backend, FileRef, PackPath, PerBackend};
use crate::preprocess::Includes;
use crate::reflect::{SpirvGap, StageReflection};
use crate::source::SourceStore;
use crate::store::{Cache, CachedStage, ModuleBytes, PassIndexView, PlannedPack, hash};
use rayon::prelude::*;
use std::collections::{BTreeMap, HashMap};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, OnceLock};

/// A stage module of a pass: reused from the output's cache, or made now and not yet stored (the
/// pass's new modules are packed together once all are done).
pub(super) enum Built {
    /// In the output's packs already.
    Reused(Box<CachedStage>),
    /// Compiled by naga now.
    Compiled(Arc<Compiled>),
    /// From the shared cache: packed as if compiled now, but not compiled.
    Fetched(Arc<Compiled>),
    /// Compiled by another pass of this build: packed as if compiled now.
    Shared(Arc<Compiled>),
}

impl Built {
    /// The module's bytes to pack: `None` for modules packed already.
    fn output(&self) -> Option<&Arc<Compiled>> {
        match self {
            Built::Compiled(output) | Built::Fetched(output) | Built::Shared(output) => Some(output),
            Built::Reused(_) => None,
        }
    }
}

/// A stage module made in this build: its bytes per backend, hashed where it was made so that
/// packing, which is serial, only concatenates.
pub(super) struct Compiled {
    pub modules: PerBackend<Option<ModuleBytes>>,
    pub reflection: StageReflection,
}

impl Compiled {
    /// About what it holds in memory.
    pub(super) fn size(&self) -> usize {
        self.modules.values().flatten().map(|m| m.bytes.len() + m.hash.len()).sum::<usize>() + 1024
    }
}

/// `None` when the stage's pass could not be laid out.
type StageOutcome = Option<Result<Made, Diagnostic>>;

/// A job's stage module, its content key, and a copy of its reflection for the pass's record,
/// made on the job's own task so that the pass's serial end only places files (`None` where the
/// module was reused from the output: its record is whole already).
struct Made {
    built: Built,
    key: String,
    reflection: Option<StageReflection>,
}

/// What building one pass gives besides its part of the manifest: its diagnostics and its share
/// of the summary.
pub(super) struct PassBuilt {
    pub diagnostics: Vec<Diagnostic>,
    pub modules: usize,
    pub compiled: usize,
    pub reused: usize,
    pub shared: usize,
    pub bytes_written: u64,
}

/// Builds one pass (see the module's comment): its part of the manifest, and the rest.
pub(super) fn build_pass(
    work: &PassWork,
    store: &SourceStore,
    includes: &Includes,
    catalog: &Catalog,
    session: &Session,
) -> (BuiltPass, PassBuilt) {
    let (cache, progress, settings) = (&session.cache, &session.progress, session.settings);
    let mut diagnostics = Vec::new();
    let PassJobs { mut jobs, stages, ubershader, preprocessed } =
        pass_jobs(store, includes, work, settings.parse, &mut diagnostics);
    session.preprocessed.fetch_add(preprocessed, Ordering::Relaxed);
    for job in &jobs {
        session.texts.add(&job.text_hash);
    }
    let key = pass_key(store, settings, work);
    let index = cache.pass_index(&key);
    let sources = PassSources {
        store,
        settings,
        session,
        pass_key: &key,
        index: &index,
        shared_fronts: OnceLock::new(),
        remote_fronts: OnceLock::new(),
    };
    let known: Vec<Option<Front>> = map_tasks(&jobs, |job| session.sources.known_front(&sources, job));
    let asked: Vec<bool> = known.iter().map(Option::is_none).collect();
    let together = parse_together(&sources, &jobs, &asked);
    let mut fronts: Vec<Front> =
        map_tasks(jobs.iter().zip(known).zip(together), |((job, known), together)| {
            known.unwrap_or_else(|| session.sources.parse_front(&sources, job, together))
        });
    // What each text declares: published now where it was parsed now (for every other build of
    // the pass), and kept in the pass's cache entry.
    let front = declared_by_text(&jobs, &fronts);
    if fronts.iter().any(|f| matches!(f, Ok((_, Some(_))))) {
        session.sources.publish_fronts(&key, &front);
    }
    let layout = lay_out(&jobs, &fronts, store, &settings.groups, &mut diagnostics);
    let requests: usize = jobs.iter().map(|j| j.requests).sum();
    let served = AtomicUsize::new(0);
    let mut outcomes: Vec<StageOutcome> =
        map_tasks(jobs.iter_mut().zip(fronts.iter_mut()), |(job, front)| {
            let outcome = match front {
                Ok((declared, parsed)) => layout.as_ref().map(|layout| {
                    let key = stage_key(job, declared, layout, settings);
                    let mut ask = ModuleAsk { job, key: &key, layout, parsed: parsed.take() };
                    let built = session.sources.module(&sources, &mut ask)?;
                    if let Built::Compiled(module) = &built {
                        session.sources.publish_module(&key, module);
                    }
                    let reflection = built.output().map(|module| module.reflection.clone());
                    Ok(Made { built, key, reflection })
                }),
                Err(_) => None,
            };
            // What naga read is not needed again: freed here, in parallel, not when the pass ends.
            job.release_texts();
            let before = served.fetch_add(job.requests, Ordering::Relaxed);
            progress.advance(work.variants.len(), requests, before, job.requests);
            outcome
        });
    repack_reused(&mut outcomes, &settings.output);
    // Packs are named by their modules' hashes, so each module's place is known before a byte
    // is written: the packs are written while the manifest part and the cache entry are made.
    let compiled: Vec<Arc<Compiled>> = outcomes
        .iter()
        .filter_map(|o| Some(Arc::clone(o.as_ref()?.as_ref().ok()?.built.output()?)))
        .collect();
    let (packs, files) = plan_packs(&compiled);
    // The pass's own thread takes the longer branch (the packs take about half as long at
    // compute 1,000): waiting for a branch another thread took costs a wake-up when it ends
    // late, and at the build's end nothing else is left to do meanwhile.
    let ((counts, part, entry), written) = rayon::join(
        || {
            let Gathered { modules, keys, counts } =
                gather(outcomes, &jobs, files, &settings.backends, &mut diagnostics);
            let (part, entry) = rayon::join(
                || {
                    let compiled = CompiledPass {
                        jobs: &jobs,
                        built: &modules,
                        variants: &stages,
                        ubershader: ubershader.as_deref(),
                    };
                    let manifest = pass_manifest(store, catalog, work, &compiled);
                    BuiltPass::new(manifest, session.pass_texts)
                },
                || {
                    let stage = (keys.iter().zip(&modules))
                        .filter_map(|(key, stage)| Some((key.as_deref()?, stage.as_ref()?)))
                        .collect();
                    let fresh = PassIndexView { front: &front, stage };
                    // A cache that cannot be written only costs speed next time.
                    (!fresh.matches(&index)).then(|| Cache::seal_pass_index(&key, &fresh).ok()).flatten()
                },
            );
            (counts, part, entry)
        },
        || packs.par_iter().map(|pack| cache.write_pack(pack)).sum::<std::io::Result<u64>>(),
    );
    let bytes_written = match written {
        Ok(bytes) => {
            // The cache entry names the packs: written once they are in place.
            if let Some(entry) = entry {
                let _ = cache.put_entry(&entry);
            }
            bytes
        }
        Err(error) => {
            diagnostics.push(write_failure(&settings.output, error));
            0
        }
    };
    let built = PassBuilt {
        diagnostics,
        modules: jobs.len(),
        compiled: counts.compiled,
        reused: counts.reused,
        shared: counts.shared,
        bytes_written,
    };
    (part, built)
}

/// A pass with new modules is packed whole: the modules it reuses from the output are read back
/// (their hashes checked) and packed with the new ones, so that an output built in steps is byte
/// for byte a clean build's, whose packs hold each pass's modules in order. A module that cannot be
/// read back stays in its old pack.
fn repack_reused(outcomes: &mut [StageOutcome], output: &std::path::Path) {
    let new = |o: &StageOutcome| matches!(o, Some(Ok(made)) if made.built.output().is_some());
    if !outcomes.iter().any(new) {
        return;
    }
    // Each old pack read once, however many of its modules the pass reuses, and no further than
    // the last of them.
    let mut ends: HashMap<PackPath, u64> = HashMap::new();
    for outcome in outcomes.iter() {
        let Some(Ok(Made { built: Built::Reused(stage), .. })) = outcome else { continue };
        for file in stage.files.values().flatten() {
            let end = ends.entry(file.path.clone()).or_default();
            *end = (*end).max(file.end());
        }
    }
    let mut packs: HashMap<PackPath, Option<Vec<u8>>> = HashMap::new();
    for outcome in outcomes.iter_mut() {
        let Some(Ok(Made { built: Built::Reused(stage), .. })) = outcome else { continue };
        let mut read = |file: &FileRef| {
            let end = ends.get(&file.path).copied().unwrap_or(0);
            let pack = packs.entry(file.path.clone()).or_insert_with(|| file.path.read(output, end).ok());
            let bytes = file.slice(pack.as_deref()?)?;
            (hash(bytes) == file.hash).then(|| ModuleBytes { hash: file.hash.clone(), bytes: bytes.to_vec() })
        };
        let modules = stage.files.clone().map(|file| file.map(|f| read(&f).ok_or(())).transpose());
        if modules.values().any(Result::is_err) {
            continue;
        }
        let modules = modules.map(|m| m.ok().flatten());
        let compiled = Compiled { modules, reflection: stage.reflection.clone() };
        if let Some(Ok(made)) = outcome {
            made.built = Built::Fetched(Arc::new(compiled));
        }
    }
}

/// The warning for a module shipped as WGSL only (K0415). It is said from the module's
/// reflection, so a module a cache gives warns as one naga compiled does.
fn spirv_gap_warning(gap: &SpirvGap, job: &Job) -> Diagnostic {
    let d =
        Diagnostic::warning("K0415", format!("no SPIR-V for `{}`: {gap}; it ships as WGSL only", job.entry))
            .at(job.entry_pragma, "this entry point");
    let d = d.note(
        "wgpu's Vulkan back end translates WGSL with the same naga writer, so on Vulkan this pipeline \
         meets the same problem (docs/diagnostics.md)",
    );
    match gap {
        SpirvGap::UniformMatrix { .. } => d.help(
            "move the block to a `var<storage, read>` buffer, or store the matrix's columns as vector members",
        ),
        SpirvGap::AliasedArray { alias, ty } => {
            d.help(format!("use `{alias}` (or `{ty}`) in every place, not both, to get SPIR-V"))
        }
        SpirvGap::Writer { .. } => d.help(
            "this is a gap in naga's SPIR-V back end; please report it with this variant's `kiln preprocess` \
             output (https://github.com/gfx-rs/wgpu/issues)",
        ),
    }
}

/// A stage module's content key: everything its bytes depend on (text, stage, entry point,
/// target, the slots of the resources it declares, backends, kiln and naga).
fn stage_key(job: &Job, declared: &[Declared], layout: &PassLayout, settings: &Settings) -> String {
    let slots: Vec<String> = declared
        .iter()
        .filter_map(|d| layout.slots.get(&d.name).map(|(g, b)| format!("{}@{g}/{b}", d.name)))
        .collect();
    let mut backends: Vec<&str> = settings.backends.iter().map(|b| b.name()).collect();
    // A module glslang read back is not one it did not: a check with it compiles anew.
    backends.extend(settings.glslang.as_ref().map(|g| g.version()));
    hash(
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
    )
}

/// The resources each stage text of a pass declares, by text hash (texts that did not parse
/// left out).
fn declared_by_text(jobs: &[Job], fronts: &[Front]) -> BTreeMap<String, Vec<Declared>> {
    jobs.iter()
        .zip(fronts)
        .filter_map(|(job, front)| Some((job.front_key(), front.as_ref().ok()?.0.clone())))
        .collect()
}

/// One layout for a pass from the resources of the modules naga parsed (a variant it could not
/// parse is reported and left out), or the clashes that leave it none (reported).
fn lay_out(
    members: &[Job],
    fronts: &[Front],
    store: &SourceStore,
    groups: &bind::GroupNames,
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
            // A variant naga cannot parse is reported and left out: the pass's other variants
            // still lay out and compile, so a check (the language server's) says what they hold.
            Err(error) => diagnostics.push(error.clone()),
        }
    }
    let (layout, clashes) = bind::layout(&declared, groups);
    for (m, d, message) in clashes {
        let job = &members[owners[m]];
        let range = declared[m][d].range;
        let mapper = Mapper { map: &job.map, store };
        let diagnostic = Diagnostic::error("K0406", message).help(
            "give each resource its own slot, or leave out `@group`/`@binding` and let kiln assign them",
        );
        let diagnostic = mapper
            .diagnostic_at(diagnostic, vec![(range.0 as usize..range.1 as usize, "declared here".into())]);
        diagnostics.push(job.in_stage(diagnostic));
        failed = true;
    }
    (!failed).then_some(layout)
}

/// A pass's new modules placed in packs, one pack per backend: the packs to write, and each
/// module's files, in order.
fn plan_packs<'a>(compiled: &'a [Arc<Compiled>]) -> (Vec<PlannedPack<'a>>, Vec<PerBackend<Option<FileRef>>>) {
    let mut files: Vec<PerBackend<Option<FileRef>>> = vec![PerBackend::default(); compiled.len()];
    let mut packs = Vec::new();
    for &backend in Backend::ALL {
        let (present, modules): (Vec<usize>, Vec<&ModuleBytes>) =
            compiled.iter().enumerate().filter_map(|(i, c)| Some((i, c.modules[backend].as_ref()?))).unzip();
        if present.is_empty() {
            continue;
        }
        let (pack, refs) = Cache::plan_pack(&modules, backend);
        for (i, file) in present.into_iter().zip(refs) {
            files[i][backend] = Some(file);
        }
        packs.push(pack);
    }
    (packs, files)
}

/// What a pass's stage outcomes come to, in the jobs' order: each stage's record (with its
/// modules' places in the packs) and content key, and the counts for the summary. Failed stages
/// become diagnostics.
struct Gathered {
    modules: Vec<Option<CachedStage>>,
    keys: Vec<Option<String>>,
    counts: StageCounts,
}

/// How a pass's stage modules were come by.
#[derive(Default)]
struct StageCounts {
    compiled: usize,
    reused: usize,
    shared: usize,
}

/// Gathers a pass's stage outcomes (see [`Gathered`]); `files` are the new modules' places, in
/// order.
fn gather(
    outcomes: Vec<StageOutcome>,
    jobs: &[Job],
    files: Vec<PerBackend<Option<FileRef>>>,
    backends: &[Backend],
    diagnostics: &mut Vec<Diagnostic>,
) -> Gathered {
    let mut files = files.into_iter();
    let mut gathered = Gathered {
        modules: Vec::with_capacity(jobs.len()),
        keys: Vec::with_capacity(jobs.len()),
        counts: StageCounts::default(),
    };
    for (outcome, job) in outcomes.into_iter().zip(jobs) {
        let stage = match outcome {
            Some(Ok(Made { built: Built::Reused(stage), key, .. })) => {
                gathered.counts.reused += 1;
                Some((*stage, key))
            }
            Some(Ok(Made { built, key, reflection })) => built.output().map(|module| {
                match built {
                    Built::Compiled(_) => gathered.counts.compiled += 1,
                    Built::Shared(_) => gathered.counts.shared += 1,
                    _ => gathered.counts.reused += 1,
                }
                let files = files.next().unwrap_or_default();
                let reflection = reflection.unwrap_or_else(|| module.reflection.clone());
                (CachedStage { files, reflection }, key)
            }),
            Some(Err(error)) => {
                diagnostics.push(job.in_stage(error));
                None
            }
            None => None,
        };
        if let Some((stage, _)) = &stage
            && let Some(gap) = &stage.reflection.spirv_gap
            && backends.contains(&Backend::Spirv)
        {
            diagnostics.push(job.in_stage(spirv_gap_warning(gap, job)));
        }
        let (stage, key) = stage.unzip();
        gathered.modules.push(stage);
        gathered.keys.push(key);
    }
    gathered
}
