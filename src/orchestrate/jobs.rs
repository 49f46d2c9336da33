//! A pass's stage texts: each distinct (stage, stage keywords) of its variants preprocessed once,
//! in parallel, cut for each entry point that asks for it (a compute program's kernels share a
//! text), and identical texts made one job.

use super::plan::PassWork;
use super::tasks::map_tasks;
use crate::compile::reach;
use crate::compile::target::Allowed;
use crate::config::ParseScope;
use crate::diagnostics;
use crate::diagnostics::{Diagnostic, PassId};
use crate::keywords::KeywordBits;
use crate::preprocess::{
    Includes, MAX_UBERSHADER_KEYWORDS, SourceMap, Stage, preprocess_with, ubershader_macros,
};
use crate::shaderlab::ast::ProgramLanguage;
use crate::shaderlab::pragma::ProgramPragmas;
use crate::source::{SourceStore, Span, Spanned};
use crate::store::hash;
use std::collections::HashMap;

/// One distinct stage module of a pass.
pub(super) struct Job<'a> {
    /// Its program's language: WGSL for naga's front end, HLSL and Cg for glslang's.
    pub language: ProgramLanguage,
    pub stage: Stage,
    pub entry: &'a str,
    pub entry_pragma: Span,
    /// What naga parses: the declarations the entry point reaches ([`reach`]), or the whole
    /// text where nothing is left out or the build parses whole texts.
    pub text: String,
    pub map: SourceMap,
    /// The text as preprocessed, when `text` leaves declarations out: parsed only where naga
    /// refuses `text` (a miss of the scan, counted; or an error, reported from the whole text as
    /// before the cut).
    pub whole: Option<Box<WholeText>>,
    /// The hash of `text`: identical cuts of different texts are one job.
    pub text_hash: String,
    /// The scan of `text`, where it is cut: what parsing texts together reads.
    pub scan: Option<reach::CutScan>,
    pub allowed: Allowed,
    /// Which variant asked for it first (its keywords), for diagnostics.
    pub variant: String,
    /// The pass, for diagnostics.
    pub pass: PassId,
    /// How many stage requests of the pass's variants it serves (for progress).
    pub requests: usize,
}

impl Job<'_> {
    /// Frees what only parsing and compiling read (the texts, their map and scan), once the job's
    /// module is made: most of what a pass holds, freed on the jobs' tasks instead of on one
    /// thread when the pass ends.
    pub(super) fn release_texts(&mut self) {
        drop((
            std::mem::take(&mut self.text),
            std::mem::take(&mut self.map),
            self.whole.take(),
            self.scan.take(),
        ));
    }

    /// A diagnostic about this stage module, said to occur in its variant's stage.
    pub(super) fn in_stage(&self, diagnostic: Diagnostic) -> Diagnostic {
        diagnostic.in_variant(&self.variant, &self.pass, stage_within(self.stage, self.entry))
    }

    /// A diagnostic about its whole text (a parse error is the text's, not the stage's that
    /// parsed it first), said to occur in its variant.
    pub(super) fn in_text(&self, diagnostic: Diagnostic) -> Diagnostic {
        diagnostic.in_variant(&self.variant, &self.pass, "")
    }

    /// What the resources a job's module reaches depend on: its text, stage and entry point.
    pub(super) fn front_key(&self) -> String {
        format!("{} {} {}", self.text_hash, self.stage.name(), self.entry)
    }
}

/// A stage text as the preprocessor wrote it.
pub(super) struct WholeText {
    pub text: String,
    pub map: SourceMap,
}

/// A preprocessed stage text cut to what each of `entries` reaches (a compute program's kernels
/// share one text), where `scope` asks it and the cut leaves something out: for each, the text,
/// its map, the whole, and the cut's scan.
fn cuts(
    language: ProgramLanguage,
    text: String,
    map: SourceMap,
    entries: &[&str],
    scope: ParseScope,
) -> Vec<Cut> {
    let cuts: Vec<Option<(String, SourceMap, Option<reach::CutScan>)>> = match (scope, language) {
        (ParseScope::Whole, _) => entries.iter().map(|_| None).collect(),
        (_, ProgramLanguage::Wgsl) => (reach::cuts_scanned(&text, &map, entries).into_iter())
            .map(|cut| cut.map(|(t, m, scan)| (t, m, Some(scan))))
            .collect(),
        // glslang parses one text for each entry point; texts are not parsed together.
        (_, language) => (entries.iter())
            .map(|entry| crate::compile::cut(language, &text, &map, entry).map(|(t, m)| (t, m, None)))
            .collect(),
    };
    let mut whole = (text, map);
    let last = entries.len().saturating_sub(1);
    let given = cuts.into_iter().zip(entries).enumerate().map(|(index, (cut, entry))| {
        // The last to ask takes the text; the others copy it.
        let (text, map) = if index == last { std::mem::take(&mut whole) } else { whole.clone() };
        let Some((mut cut, cut_map, scan)) = cut else { return (text, map, None, None) };
        // For the test of a miss: debug builds spoil the cut of the entry point this names.
        if cfg!(debug_assertions) && std::env::var("KILN_INJECT_CUT_MISS").is_ok_and(|name| name == *entry) {
            cut.push_str(if language == ProgramLanguage::Wgsl { "fn (\n" } else { "float4 (\n" });
        }
        (cut, cut_map, Some(Box::new(WholeText { text, map })), scan)
    });
    given.collect()
}

/// The hash a stage text is known by: of its bytes, and of its language where that is not WGSL
/// (glslang's front end is not naga's: an HLSL text never shares a WGSL text's module).
fn text_hash(language: ProgramLanguage, text: &str) -> String {
    match language {
        ProgramLanguage::Wgsl => hash(text.as_bytes()),
        other => hash(format!("{}\0{text}", other.name()).as_bytes()),
    }
}

/// What [`cuts`] gives for an entry point.
type Cut = (String, SourceMap, Option<Box<WholeText>>, Option<reach::CutScan>);

/// A pass's distinct stage modules, and each variant's job for each of the pass's
/// [`entry_points`] (`None` when that stage failed or is absent).
pub(super) struct PassJobs<'a> {
    pub jobs: Vec<Job<'a>>,
    pub stages: Vec<Vec<Option<usize>>>,
    /// The ubershader's jobs, as a variant's, when the pass has `#pragma ubershader`.
    pub ubershader: Option<Vec<Option<usize>>>,
    /// Texts the preprocessor wrote (`BuildSummary::preprocessed`).
    pub preprocessed: usize,
}

/// The entry points each variant of a pass compiles, in the order the manifest lists its modules:
/// a compute pass's kernels, else its vertex and its fragment entry point (`None` when absent).
pub(super) fn entry_points(pragmas: &ProgramPragmas) -> Vec<(Stage, Option<&Spanned<String>>)> {
    if !pragmas.kernels.is_empty() {
        return pragmas.kernels.iter().map(|kernel| (Stage::Compute, Some(kernel))).collect();
    }
    vec![(Stage::Vertex, pragmas.vertex.as_ref()), (Stage::Fragment, pragmas.fragment.as_ref())]
}

/// One stage of one variant, to preprocess.
struct Request<'a> {
    stage: Stage,
    entry: &'a crate::source::Spanned<String>,
    keywords: Vec<String>,
    allowed: Allowed,
    /// The variant's keywords, for diagnostics.
    variant: String,
    /// The pass's ubershader (`keywords` unused): every keyword read at run time.
    ubershader: bool,
}

/// Where in its pass a stage is: `, fragment stage` (and a kernel's name).
fn stage_within(stage: Stage, entry: &str) -> String {
    let kernel = if stage == Stage::Compute { format!(" (kernel `{entry}`)") } else { String::new() };
    format!(", {} stage{kernel}", stage.name())
}

/// The distinct stage texts of a pass's variants: each (stage, stage keywords) is preprocessed
/// once, in parallel, cut to what each entry point asking for it reaches (as `scope` says), and
/// identical texts become one job (per entry point and target).
pub(super) fn pass_jobs<'a>(
    store: &SourceStore,
    includes: &Includes,
    work: &PassWork<'a>,
    scope: ParseScope,
    diagnostics: &mut Vec<Diagnostic>,
) -> PassJobs<'a> {
    let (shader, pass, program) = (work.shader, work.pass, work.program);
    let mut jobs: Vec<Job<'a>> = Vec::new();
    let Some(source) = program.source.as_ref() else {
        let stages = vec![Vec::new(); work.variants.len()];
        return PassJobs { jobs, stages, ubershader: None, preprocessed: 0 };
    };
    let mut requests: Vec<Request> = Vec::new();
    let mut request_of: HashMap<(Stage, &str, &KeywordBits, String), usize> = HashMap::new();
    let mut per_variant: Vec<Vec<Option<usize>>> = Vec::with_capacity(work.variants.len());
    let entries = entry_points(&program.pragmas);
    let pass_id = PassId { shader: shader.shader.name.value.clone(), index: pass.index };
    for variant in work.variants.iter() {
        let all: Vec<&str> = program.keywords.keywords(&variant.bits).collect();
        let allowed = Allowed::for_variant(&program.pragmas, &all);
        let variant_jobs = entries.iter().map(|&(stage, entry)| {
            let entry = entry?;
            let bits = program.keywords_for(variant, stage);
            // Each kernel is an entry point of its own, compiled from the same text.
            let key = (stage, entry.value.as_str(), bits, allowed.key());
            Some(*request_of.entry(key).or_insert_with(|| {
                let shown = if all.is_empty() { "(no keywords)".to_string() } else { all.join(" ") };
                requests.push(Request {
                    stage,
                    entry,
                    keywords: program.keywords.keywords(bits).map(str::to_string).collect(),
                    allowed: allowed.clone(),
                    variant: shown,
                    ubershader: false,
                });
                requests.len() - 1
            }))
        });
        per_variant.push(variant_jobs.collect());
    }
    let pragmas = &program.pragmas;
    let ubershader_keywords = pragmas.ubershader_keywords();
    // Past the immediate data's bits the pass has its error (K0336) and no ubershader.
    if pragmas.ubershader.is_some() && ubershader_keywords.len() <= MAX_UBERSHADER_KEYWORDS {
        let allowed = Allowed::for_variant(pragmas, &ubershader_keywords).with_immediates();
        let stages = entries.iter().map(|&(stage, entry)| {
            requests.push(Request {
                stage,
                entry: entry?,
                keywords: Vec::new(),
                allowed: allowed.clone(),
                variant: "(ubershader)".to_string(),
                ubershader: true,
            });
            Some(requests.len() - 1)
        });
        per_variant.push(stages.collect());
    }
    // A variant's kernels share its text: each (stage, keywords) is preprocessed once, then cut
    // for each entry point that asks for it.
    let mut texts: Vec<Vec<usize>> = Vec::new();
    let mut text_of: HashMap<(Stage, &[String], bool), usize> = HashMap::new();
    for (index, r) in requests.iter().enumerate() {
        let text = *text_of.entry((r.stage, &r.keywords, r.ubershader)).or_insert_with(|| {
            texts.push(Vec::new());
            texts.len() - 1
        });
        texts[text].push(index);
    }
    let preprocessed: Vec<_> = map_tasks(&texts, |asking| {
        let r = &requests[asking[0]];
        let keywords: Vec<&str> = r.keywords.iter().map(String::as_str).collect();
        let macros = match r.ubershader {
            true => ubershader_macros(&program.pragmas, r.stage).unwrap_or_default(),
            false => program.keyword_macros(&keywords),
        };
        let out = preprocess_with(includes, store, source, &macros, r.stage);
        let scope = if diagnostics::has_errors(&out.diagnostics) { ParseScope::Whole } else { scope };
        let entries: Vec<&str> = asking.iter().map(|&i| requests[i].entry.value.as_str()).collect();
        let cuts = cuts(program.language, out.text, out.source_map, &entries, scope);
        let cuts: Vec<_> = cuts.into_iter().map(|cut| (text_hash(program.language, &cut.0), cut)).collect();
        (out.diagnostics, cuts)
    });
    let mut outputs: Vec<Option<_>> = requests.iter().map(|_| None).collect();
    for (asking, (found, cuts)) in texts.iter().zip(preprocessed) {
        for (&request, (text_hash, cut)) in asking.iter().zip(cuts) {
            outputs[request] = Some((found.clone(), cut, text_hash));
        }
    }
    // Different keywords can still give the same text (a keyword no `#if` of this stage tests).
    let mut job_of_text: HashMap<(Stage, &str, String, String), usize> = HashMap::new();
    let mut job_of_request: Vec<Option<usize>> = Vec::with_capacity(requests.len());
    for (request, (found, (text, map, whole, scan), text_hash)) in
        requests.into_iter().zip(outputs.into_iter().flatten())
    {
        let failed = diagnostics::has_errors(&found);
        let within = stage_within(request.stage, &request.entry.value);
        diagnostics.extend(found.into_iter().map(|d| d.in_variant(&request.variant, &pass_id, &within)));
        if failed {
            job_of_request.push(None);
            continue;
        }
        let key = (request.stage, request.entry.value.as_str(), text_hash.clone(), request.allowed.key());
        let job = *job_of_text.entry(key).or_insert_with(|| {
            jobs.push(Job {
                language: program.language,
                stage: request.stage,
                entry: &request.entry.value,
                entry_pragma: request.entry.span,
                text,
                map,
                whole,
                text_hash,
                scan,
                allowed: request.allowed,
                variant: request.variant,
                pass: pass_id.clone(),
                requests: 0,
            });
            jobs.len() - 1
        });
        jobs[job].requests += 1;
        job_of_request.push(Some(job));
    }
    let mut stages: Vec<Vec<Option<usize>>> = per_variant
        .into_iter()
        .map(|stages| stages.into_iter().map(|r| r.and_then(|r| job_of_request[r])).collect())
        .collect();
    let ubershader = (stages.len() > work.variants.len()).then(|| stages.pop()).flatten();
    PassJobs { jobs, stages, ubershader, preprocessed: texts.len() }
}
