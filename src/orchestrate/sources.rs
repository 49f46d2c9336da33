//! Where a pass's fronts (the resources a stage text declares) and stage modules come from. Each
//! is asked of an ordered list of sources until one has it; when none has, naga makes it. Whole
//! builds and shards compile alike (a shard is a whole build of the passes it owns), so there is
//! one list of each; a merge compiles nothing and has none.
//!
//! A new source is a type implementing [`FrontSource`] or [`ModuleSource`] (with `publish`
//! where it keeps what naga made), holding its own configuration, and its place in
//! [`Sources::new`], made once per build from its settings.

use super::jobs::{Job, WholeText};
use super::pass::{Built, Compiled};
use super::session::Session;
use super::tasks::map_tasks;
use crate::compile::bind::{self, Declared, PassLayout};
use crate::compile::stage::{self, StageRequest};
use crate::compile::{Mapper, hlsl, parse, together};
use crate::config::{ParseScope, Settings};
use crate::diagnostics::Diagnostic;
use crate::shaderlab::ast::ProgramLanguage;
use crate::source::SourceStore;
use crate::store::remote::{RemoteCache, RemoteMode};
use crate::store::{ModuleBytes, PassIndex, hash, shared};
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::atomic::Ordering;
use std::sync::{Arc, OnceLock};

/// Outcome of a job's front end: its declared resources, and the parsed module when it had to be
/// parsed (kept so that naga does not parse it again for the module).
pub(super) type Front = Result<(Vec<Declared>, Option<Parsed>), Diagnostic>;

/// A module naga parsed for a job.
pub(super) struct Parsed {
    module: naga::Module,
    from: ParsedFrom,
}

/// What naga parsed to make a job's module.
#[derive(Clone, Copy, PartialEq, Eq)]
enum ParsedFrom {
    /// The job's text (cut, where the build cuts).
    Text,
    /// Its whole text, where naga refused the cut one.
    Whole,
    /// Its pass's texts together (`compile::together`): where its module fails to compile, its
    /// own text decides.
    Together,
}

/// What the sources of one pass read: the build's session, the pass's entry in the output's
/// cache, and (read once, when first asked) its entry in the shared cache.
pub(super) struct PassSources<'a> {
    pub store: &'a SourceStore,
    pub settings: &'a Settings,
    pub session: &'a Session<'a>,
    pub pass_key: &'a str,
    pub index: &'a PassIndex,
    pub shared_fronts: OnceLock<BTreeMap<String, Vec<Declared>>>,
    /// The same, from the remote cache.
    pub remote_fronts: OnceLock<BTreeMap<String, Vec<Declared>>>,
}

/// A source of fronts.
pub(super) trait FrontSource: Send + Sync {
    /// The resources `job`'s text declares, if this source knows them.
    fn front(&self, pass: &PassSources, job: &Job) -> Option<Front>;

    /// Keeps what naga parsed for a pass (`declared`, by text), for later builds.
    fn publish(&self, _pass_key: &str, _declared: &BTreeMap<String, Vec<Declared>>) {}
}

/// A stage module wanted: its job, its content key, its pass's layout, and the module its front
/// parsed, if it did.
pub(super) struct ModuleAsk<'a> {
    pub job: &'a Job<'a>,
    pub key: &'a str,
    pub layout: &'a PassLayout,
    pub parsed: Option<Parsed>,
}

/// A source of stage modules.
pub(super) trait ModuleSource: Send + Sync {
    /// The module asked for, if this source has it (or an error when making it failed).
    fn module(&self, pass: &PassSources, ask: &mut ModuleAsk) -> Option<Result<Built, Diagnostic>>;

    /// Keeps a module naga compiled under its content key, for later builds.
    fn publish(&self, _key: &str, _compiled: &Compiled) {}
}

/// The sources a build asks, in order, before naga parses or compiles: made once from its
/// settings, each holding its own configuration (the shared cache its folder).
pub(super) struct Sources {
    fronts: Vec<Arc<dyn FrontSource>>,
    modules: Vec<Arc<dyn ModuleSource>>,
    /// The remote cache, also in both lists: for its warning and its byte counts.
    remote: Option<Arc<Remote>>,
}

impl Sources {
    /// The output folder's cache, the shared cache where the build has one, then what the
    /// build's other passes made.
    pub(super) fn new(settings: &Settings) -> Sources {
        let shared = settings.cache_dir.clone().map(|dir| Arc::new(SharedCache { dir }));
        let remote = settings.remote_cache.clone().filter(|r| r.mode != RemoteMode::Off);
        let remote =
            remote.map(|config| Arc::new(Remote { cache: RemoteCache::new(config), keep: shared.clone() }));
        let mut fronts: Vec<Arc<dyn FrontSource>> = vec![Arc::new(OutputCache)];
        let mut modules: Vec<Arc<dyn ModuleSource>> = vec![Arc::new(OutputCache)];
        if let Some(shared) = shared {
            fronts.push(shared.clone());
            modules.push(shared);
        }
        if let Some(remote) = &remote {
            fronts.push(remote.clone());
            modules.push(remote.clone());
        }
        fronts.push(Arc::new(OtherPasses));
        modules.push(Arc::new(OtherPasses));
        Sources { fronts, modules, remote }
    }

    /// Waits for the remote cache's uploads; then its one warning, when it could not be used as
    /// configured, and the bytes it received and sent.
    pub(super) fn finish(&self) -> (Option<Diagnostic>, [u64; 2]) {
        let Some(remote) = &self.remote else { return (None, [0, 0]) };
        remote.cache.finish();
        (remote.cache.warning(), remote.cache.bytes())
    }

    /// The first front a source has: `None` where naga must parse the job's text.
    pub(super) fn known_front(&self, pass: &PassSources, job: &Job) -> Option<Front> {
        self.fronts.iter().find_map(|source| source.front(pass, job))
    }

    /// The front of a job no source has: from its module cut out of a parse together where
    /// there is one ([`parse_together`]), else naga's parse of its text.
    pub(super) fn parse_front(&self, pass: &PassSources, job: &Job, together: Option<naga::Module>) -> Front {
        Naga.parse(pass, job, together)
    }

    /// The first module a source has, or naga's compile.
    pub(super) fn module(&self, pass: &PassSources, ask: &mut ModuleAsk) -> Result<Built, Diagnostic> {
        self.modules
            .iter()
            .find_map(|source| source.module(pass, ask))
            .unwrap_or_else(|| Naga.compile(pass, ask))
    }

    /// Offers what naga parsed for a pass to every source that keeps fronts.
    pub(super) fn publish_fronts(&self, pass_key: &str, declared: &BTreeMap<String, Vec<Declared>>) {
        for source in &self.fronts {
            source.publish(pass_key, declared);
        }
    }

    /// Offers a module naga compiled to every source that keeps modules.
    pub(super) fn publish_module(&self, key: &str, compiled: &Compiled) {
        for source in &self.modules {
            source.publish(key, compiled);
        }
    }
}

/// What the last build into the output folder left for the pass (`.cache/pass`).
struct OutputCache;

impl FrontSource for OutputCache {
    fn front(&self, pass: &PassSources, job: &Job) -> Option<Front> {
        pass.index.front.get(&job.front_key()).map(|declared| Ok((declared.clone(), None)))
    }
}

impl ModuleSource for OutputCache {
    fn module(&self, pass: &PassSources, ask: &mut ModuleAsk) -> Option<Result<Built, Diagnostic>> {
        let cached = pass.index.stage.get(ask.key)?;
        Some(Ok(Built::Reused(Box::new(cached.clone()))))
    }
}

/// The module cache builds share: a folder (`cache_dir`).
struct SharedCache {
    dir: PathBuf,
}

impl FrontSource for SharedCache {
    fn front(&self, pass: &PassSources, job: &Job) -> Option<Front> {
        let fronts = pass.shared_fronts.get_or_init(|| shared::read_layouts(&self.dir, pass.pass_key));
        fronts.get(&job.front_key()).map(|declared| Ok((declared.clone(), None)))
    }

    fn publish(&self, pass_key: &str, declared: &BTreeMap<String, Vec<Declared>>) {
        shared::publish_layouts(&self.dir, pass_key, declared);
    }
}

impl ModuleSource for SharedCache {
    fn module(&self, _pass: &PassSources, ask: &mut ModuleAsk) -> Option<Result<Built, Diagnostic>> {
        let (modules, reflection) = shared::fetch_object(&self.dir, ask.key, super::compiler_id())?;
        Some(Ok(Built::Fetched(Arc::new(Compiled { modules, reflection }))))
    }

    fn publish(&self, key: &str, compiled: &Compiled) {
        shared::publish_object(&self.dir, key, super::compiler_id(), &compiled.modules, &compiled.reflection);
    }
}

/// The team's cache on an HTTP server (`remote_cache`), and the shared cache on this machine,
/// where the build has one, which keeps what the server gave: a clean build after it fetches
/// nothing again.
struct Remote {
    cache: RemoteCache,
    keep: Option<Arc<SharedCache>>,
}

impl FrontSource for Remote {
    fn front(&self, pass: &PassSources, job: &Job) -> Option<Front> {
        let fronts = pass.remote_fronts.get_or_init(|| {
            let fetched = self.cache.read_layouts(pass.pass_key);
            if let Some(keep) = self.keep.as_ref().filter(|_| !fetched.is_empty()) {
                FrontSource::publish(&**keep, pass.pass_key, &fetched);
            }
            fetched
        });
        fronts.get(&job.front_key()).map(|declared| Ok((declared.clone(), None)))
    }

    fn publish(&self, pass_key: &str, declared: &BTreeMap<String, Vec<Declared>>) {
        self.cache.publish_layouts(pass_key, declared);
    }
}

impl ModuleSource for Remote {
    fn module(&self, _pass: &PassSources, ask: &mut ModuleAsk) -> Option<Result<Built, Diagnostic>> {
        let (modules, reflection) = self.cache.fetch_object(ask.key, super::compiler_id())?;
        let compiled = Compiled { modules, reflection };
        if let Some(keep) = &self.keep {
            ModuleSource::publish(&**keep, ask.key, &compiled);
        }
        Some(Ok(Built::Fetched(Arc::new(compiled))))
    }

    fn publish(&self, key: &str, compiled: &Compiled) {
        self.cache.publish_object(key, super::compiler_id(), &compiled.modules, &compiled.reflection);
    }
}

/// What another pass of this build parsed or compiled lately (texts more than one pass has).
struct OtherPasses;

impl FrontSource for OtherPasses {
    fn front(&self, pass: &PassSources, job: &Job) -> Option<Front> {
        if !pass.session.texts.shared(&job.text_hash) {
            return None;
        }
        let declared = pass.session.parsed.get(&job.front_key())?;
        Some(Ok(((*declared).clone(), None)))
    }
}

impl ModuleSource for OtherPasses {
    fn module(&self, pass: &PassSources, ask: &mut ModuleAsk) -> Option<Result<Built, Diagnostic>> {
        if !pass.session.texts.shared(&ask.job.text_hash) {
            return None;
        }
        pass.session.compiled.get(ask.key).map(|compiled| Ok(Built::Shared(compiled)))
    }
}

impl WholeText {
    /// The parse of the whole text (naga's, or glslang's and naga's), its errors placed through
    /// its own map.
    fn parse(&self, job: &Job, store: &SourceStore) -> Result<Parsed, Diagnostic> {
        Ok(Parsed { module: parse_text(job, &self.text, &self.map, store)?, from: ParsedFrom::Whole })
    }
}

/// A text of `job`'s parsed in its language: by naga's WGSL front end, or by glslang's HLSL one
/// and naga's SPIR-V reader.
fn parse_text(
    job: &Job,
    text: &str,
    map: &crate::preprocess::SourceMap,
    store: &SourceStore,
) -> Result<naga::Module, Diagnostic> {
    let mapper = Mapper { map, store };
    match job.language {
        ProgramLanguage::Wgsl => parse(text, &mapper),
        language => hlsl::parse(text, language, job.stage, (job.entry, job.entry_pragma), &mapper),
    }
}

/// naga, when no source has it: parses and compiles; what it made is offered to the build's
/// other passes.
struct Naga;

impl Naga {
    fn parse(&self, pass: &PassSources, job: &Job, together: Option<naga::Module>) -> Front {
        let parsed = match together {
            Some(module) => Parsed { module, from: ParsedFrom::Together },
            None => self.parse_job(pass, job).map_err(|d| job.in_text(d))?,
        };
        let declared = bind::declared(&parsed.module, job.entry, stage::naga_stage(job.stage));
        if pass.session.texts.shared(&job.text_hash) {
            let size = declared.iter().map(|d| d.name.len() + 64).sum();
            pass.session.parsed.insert(&job.front_key(), Arc::new(declared.clone()), size);
        }
        Ok((declared, Some(parsed)))
    }

    /// naga's parse of a job's text; where it refuses a cut text, of the whole text, whose error
    /// is the one reported (as before the cut), and whose module, where it parses, is a miss of
    /// the cut.
    fn parse_job(&self, pass: &PassSources, job: &Job) -> Result<Parsed, Diagnostic> {
        pass.session.parses.fetch_add(1, Ordering::Relaxed);
        match parse_text(job, &job.text, &job.map, pass.store) {
            Ok(module) => Ok(Parsed { module, from: ParsedFrom::Text }),
            Err(error) => match &job.whole {
                None => Err(error),
                Some(whole) => {
                    pass.session.parses.fetch_add(1, Ordering::Relaxed);
                    let parsed = whole.parse(job, pass.store)?;
                    pass.session.uncut.fetch_add(1, Ordering::Relaxed);
                    Ok(parsed)
                }
            },
        }
    }

    fn compile(&self, pass: &PassSources, ask: &mut ModuleAsk) -> Result<Built, Diagnostic> {
        let job = ask.job;
        let parsed = match ask.parsed.take() {
            Some(parsed) => parsed,
            None => self.parse_job(pass, job)?,
        };
        let output = match parsed.from {
            ParsedFrom::Together => match self.compile_parsed(pass, ask, parsed) {
                Ok(output) => {
                    pass.session.parsed_together.fetch_add(1, Ordering::Relaxed);
                    output
                }
                // Refused as cut out of the parse together: its own text decides.
                Err(_) => self.compile_own(pass, ask, self.parse_job(pass, job)?)?,
            },
            _ => self.compile_own(pass, ask, parsed)?,
        };
        let module = |bytes: Vec<u8>| ModuleBytes { hash: hash(&bytes), bytes };
        let modules = output.modules.map(|bytes| bytes.map(module));
        let compiled = Arc::new(Compiled { modules, reflection: output.reflection });
        // Asked again now: another pass may have found the text meanwhile.
        if pass.session.texts.shared(&job.text_hash) {
            pass.session.compiled.insert(ask.key, compiled.clone(), compiled.size());
        }
        Ok(Built::Compiled(compiled))
    }

    /// One stage module from its own text's parse; where naga refuses it from the cut text, from
    /// the whole text, which decides as it did before the cut.
    fn compile_own(
        &self,
        pass: &PassSources,
        ask: &ModuleAsk,
        parsed: Parsed,
    ) -> Result<stage::StageOutput, Diagnostic> {
        let from_cut = parsed.from == ParsedFrom::Text;
        match (self.compile_parsed(pass, ask, parsed), &ask.job.whole) {
            (Err(_), Some(whole)) if from_cut => {
                pass.session.parses.fetch_add(1, Ordering::Relaxed);
                let output = self.compile_parsed(pass, ask, whole.parse(ask.job, pass.store)?)?;
                pass.session.uncut.fetch_add(1, Ordering::Relaxed);
                Ok(output)
            }
            (output, _) => output,
        }
    }

    /// One stage module from a parsed text (the job's, its whole one, or its pass's together).
    fn compile_parsed(
        &self,
        pass: &PassSources,
        ask: &ModuleAsk,
        parsed: Parsed,
    ) -> Result<stage::StageOutput, Diagnostic> {
        let job = ask.job;
        let (text, map) = match (&job.whole, parsed.from) {
            (Some(whole), ParsedFrom::Whole) => (&whole.text, &whole.map),
            _ => (&job.text, &job.map),
        };
        let request = StageRequest {
            language: job.language,
            text,
            stage: job.stage,
            entry: job.entry,
            entry_pragma: job.entry_pragma,
            allowed: &job.allowed,
            layout: ask.layout,
            backends: &pass.settings.backends,
            glslang: pass.settings.glslang.as_ref(),
            compacted: parsed.from == ParsedFrom::Together || job.language != ProgramLanguage::Wgsl,
        };
        stage::compile(parsed.module, &request, &Mapper { map, store: pass.store })
    }
}

/// The modules of the jobs naga must parse (`asked`), cut out of parses of their pass's texts
/// together (`compile::together`): jobs of one stage and entry point, a few at a time. `None` for
/// a job left to its own parse. A group whose first parse together gave fewer than half its
/// members' modules parses the rest alone: those would be parsed twice.
pub(super) fn parse_together(pass: &PassSources, jobs: &[Job], asked: &[bool]) -> Vec<Option<naga::Module>> {
    let mut modules: Vec<Option<naga::Module>> = (0..jobs.len()).map(|_| None).collect();
    if pass.settings.parse != ParseScope::Together {
        return modules;
    }
    // By stage: a compute pass's kernels are entry points of one text, and a variant's kernels
    // share all but their own entry point.
    let mut groups: BTreeMap<&str, Vec<usize>> = BTreeMap::new();
    // glslang compiles one entry point of one text at a time: only WGSL texts parse together.
    let wgsl = |job: &Job| job.language == ProgramLanguage::Wgsl;
    for (index, job) in jobs.iter().enumerate().filter(|&(i, job)| asked[i] && wgsl(job)) {
        groups.entry(job.stage.name()).or_default().push(index);
    }
    // Each group's first few jobs (`first`), or the rest.
    fn batches<'g>(groups: &'g BTreeMap<&str, Vec<usize>>, first: bool) -> Vec<&'g [usize]> {
        let chunks = groups.values().map(|members| members.chunks(together::MOST_TEXTS));
        let chunks: Vec<&[usize]> = match first {
            true => chunks.filter_map(|mut c| c.next()).collect(),
            false => chunks.flat_map(|c| c.skip(1)).collect(),
        };
        chunks.into_iter().filter(|b| b.len() > 1).collect()
    }
    let cut = |batches: Vec<&[usize]>| -> Vec<Vec<(usize, naga::Module)>> {
        map_tasks(batches, |batch| {
            let texts: Vec<together::Text> = (batch.iter())
                .map(|&j| together::Text {
                    text: &jobs[j].text,
                    entry: jobs[j].entry,
                    scan: jobs[j].scan.as_ref(),
                })
                .collect();
            let Some(together) = together::assemble(&texts).filter(together::Together::saves_enough) else {
                return Vec::new();
            };
            pass.session.parses.fetch_add(1, Ordering::Relaxed);
            let Some(parsed) = together.parse() else { return Vec::new() };
            let cuts = map_tasks(batch.iter().enumerate(), |(member, &j)| {
                Some((j, together.cut(&parsed, member, stage::naga_stage(jobs[j].stage))?))
            });
            cuts.into_iter().flatten().collect()
        })
    };
    let first = cut(batches(&groups, true));
    for (job, module) in first.into_iter().flatten() {
        modules[job] = Some(module);
    }
    // Groups whose first batch mostly failed to share a parse are left to their own parses.
    groups.retain(|_, members| {
        let first = &members[..members.len().min(together::MOST_TEXTS)];
        2 * first.iter().filter(|&&j| modules[j].is_some()).count() >= first.len()
    });
    for (job, module) in cut(batches(&groups, false)).into_iter().flatten() {
        modules[job] = Some(module);
    }
    modules
}
