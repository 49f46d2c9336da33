//! The pipeline trace: every pipeline the run time creates, by what decides it and by stable
//! names (shader, pass, keywords, the render-state properties' values, override values, targets,
//! vertex layout; never module hashes, which change with every edit), appended a line at a time;
//! and warm-up from a trace before the first frame: all at once, a few per frame, or on worker
//! threads.

use super::layout::VertexLayout;
use super::pipelines::{PipelineRequest, Runtime, Targets};
use super::{KernelRequest, RuntimeError};
use kiln_manifest::MaterialManifest;
use serde::{Deserialize, Serialize};
use std::collections::{BTreeMap, HashSet};
use std::io::Write as _;
use std::path::Path;

/// The trace format's version, in every line: a reader refuses lines of another.
pub const TRACE_VERSION: u32 = 1;

/// One pipeline as a trace records it (a line of JSON; docs/trace.md).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TraceEntry {
    /// [`TRACE_VERSION`].
    pub version: u32,
    /// The shader's name.
    pub shader: String,
    /// The pass's index (0 for a compute shader).
    pub pass: usize,
    /// The variant's keywords and the `dynamic_branch` keywords on, sorted: a usage log's line
    /// too (`kiln build --variants-from` reads a trace).
    pub keywords: Vec<String>,
    /// The modules' own `override` values, as the request gave them.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub overrides: Vec<(String, f64)>,
    /// What kind of pipeline, with what decides it besides the above.
    #[serde(flatten)]
    pub pipeline: TracedPipeline,
}

/// A traced pipeline's own part.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum TracedPipeline {
    /// A render pipeline.
    Render {
        /// The values of the properties the pass's render state reads (`_SrcBlend`, ...), from
        /// the material the request named: any material with these values makes this pipeline.
        state: BTreeMap<String, f64>,
        /// Its render targets.
        targets: Targets,
        /// Its vertex layout (`None`: the default packing).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        vertex_layout: Option<VertexLayout>,
    },
    /// A compute pipeline.
    Compute {
        /// The kernel.
        kernel: String,
    },
}

/// A trace being written: each pipeline once, each line written and flushed as its pipeline is
/// created, so that a crash loses at most that line. Appending to a trace another run (or
/// machine) wrote merges the two; lines already there are not written again.
#[derive(Debug)]
pub struct PipelineTrace {
    file: std::fs::File,
    written: HashSet<String>,
}

impl PipelineTrace {
    /// Appends to the trace at `path` (created when absent).
    pub fn append(path: &Path) -> std::io::Result<PipelineTrace> {
        let written = match std::fs::read_to_string(path) {
            Ok(text) => text.lines().map(str::to_string).collect(),
            Err(error) if error.kind() == std::io::ErrorKind::NotFound => HashSet::new(),
            Err(error) => return Err(error),
        };
        let file = std::fs::OpenOptions::new().create(true).append(true).open(path)?;
        Ok(PipelineTrace { file, written })
    }

    pub(super) fn record(&mut self, entry: &TraceEntry) {
        let Ok(line) = serde_json::to_string(entry) else { return };
        if self.written.insert(line.clone()) {
            // A trace that cannot be written must not stop a frame.
            let _ = writeln!(self.file, "{line}").and_then(|()| self.file.flush());
        }
    }
}

/// A trace's entries, each once, in the order first written; a line that is not an entry (torn
/// by a crash, of another version) is skipped and named with its line number (from 1).
pub fn read_trace(text: &str) -> (Vec<TraceEntry>, Vec<(usize, String)>) {
    let mut seen = HashSet::new();
    let (mut entries, mut skipped) = (Vec::new(), Vec::new());
    for (number, line) in text.lines().enumerate().filter(|(_, line)| !line.trim().is_empty()) {
        match serde_json::from_str::<TraceEntry>(line) {
            Ok(entry) if entry.version != TRACE_VERSION => {
                skipped.push((number + 1, format!("trace version {}, not {TRACE_VERSION}", entry.version)))
            }
            Ok(entry) => {
                if seen.insert(line.trim()) {
                    entries.push(entry);
                }
            }
            Err(error) => skipped.push((number + 1, error.to_string())),
        }
    }
    (entries, skipped)
}

/// Warm-up from a trace, a few entries at a time (a loading screen's frames) or all at once.
#[derive(Debug)]
pub struct WarmUp<'t> {
    entries: &'t [TraceEntry],
    next: usize,
    errors: Vec<(usize, RuntimeError)>,
}

impl<'t> WarmUp<'t> {
    /// A warm-up of these entries, none made yet.
    pub fn new(entries: &'t [TraceEntry]) -> WarmUp<'t> {
        WarmUp { entries, next: 0, errors: Vec::new() }
    }

    /// Makes the pipelines of up to `count` more entries; returns whether every entry is done.
    /// An entry the build no longer has (a renamed keyword, a removed pass) is an error to read
    /// in [`WarmUp::errors`], and the rest go on.
    pub fn step(&mut self, runtime: &Runtime, count: usize) -> bool {
        let end = (self.next + count).min(self.entries.len());
        for index in self.next..end {
            if let Err(error) = runtime.replay(&self.entries[index]) {
                self.errors.push((index, error));
            }
        }
        self.next = end;
        if self.ready() {
            runtime.mark_warm();
        }
        self.ready()
    }

    /// Whether every entry is done.
    pub fn ready(&self) -> bool {
        self.next == self.entries.len()
    }

    /// (entries done, entries in all).
    pub fn progress(&self) -> (usize, usize) {
        (self.next, self.entries.len())
    }

    /// The entries that could not be made, by their index in the trace.
    pub fn errors(&self) -> &[(usize, RuntimeError)] {
        &self.errors
    }
}

impl Runtime {
    /// Records every pipeline created from now on in `trace`: in development, to ship with the
    /// game; after warm-up, to catch what the shipped trace missed (append it to that trace).
    pub fn record_pipelines(&mut self, trace: PipelineTrace) {
        *self.trace.get_mut().unwrap_or_else(std::sync::PoisonError::into_inner) = Some(trace);
    }

    /// Makes every entry's pipeline on `threads` worker threads (wgpu's device is shared between
    /// them), and for a pass with an ubershader its pipeline in each traced state, then counts pipelines created from here on as made after warm-up
    /// ([`Runtime::created_after_warm_up`]). Returns the entries that could not be made, by
    /// index.
    pub fn warm_up_trace(&self, entries: &[TraceEntry], threads: usize) -> Vec<(usize, RuntimeError)> {
        // An entry given twice (traces concatenated) is made once: two threads making one
        // pipeline at once would both pay for it.
        let mut seen = HashSet::new();
        let unique: Vec<(usize, &TraceEntry)> = entries
            .iter()
            .enumerate()
            .filter(|(_, entry)| serde_json::to_string(entry).is_ok_and(|line| seen.insert(line)))
            .collect();
        let threads = threads.clamp(1, unique.len().max(1));
        let chunk = unique.len().div_ceil(threads).max(1);
        let mut errors: Vec<(usize, RuntimeError)> = std::thread::scope(|scope| {
            let workers: Vec<_> = unique
                .chunks(chunk)
                .enumerate()
                .map(|(c, part)| {
                    std::thread::Builder::new().name(format!("kiln warm-up {c}")).spawn_scoped(
                        scope,
                        move || {
                            let replayed = part.iter().map(|&(i, entry)| (i, self.replay(entry)));
                            replayed.filter_map(|(i, made)| made.err().map(|e| (i, e))).collect::<Vec<_>>()
                        },
                    )
                })
                .collect();
            workers
                .into_iter()
                .flat_map(|worker| match worker.map(|w| w.join()) {
                    Ok(Ok(errors)) => errors,
                    // A thread that cannot start or panicked leaves its pipelines to be made when asked.
                    _ => Vec::new(),
                })
                .collect()
        });
        errors.sort_by_key(|(index, _)| *index);
        self.mark_warm();
        errors
    }

    /// The pipeline of one trace entry, made as its request would make it.
    fn replay(&self, entry: &TraceEntry) -> Result<(), RuntimeError> {
        let keywords: Vec<&str> = entry.keywords.iter().map(String::as_str).collect();
        let overrides: Vec<(&str, f64)> = entry.overrides.iter().map(|(k, v)| (k.as_str(), *v)).collect();
        let variant = self.library.variant_id(self.library.pass_id(&entry.shader, entry.pass)?, &keywords)?;
        match &entry.pipeline {
            TracedPipeline::Render { state, targets, vertex_layout } => {
                let material = MaterialManifest {
                    name: "<trace>".to_string(),
                    shader: entry.shader.clone(),
                    preset: None,
                    render_queue: 0,
                    keywords: Vec::new(),
                    values: state.iter().map(|(k, v)| (k.clone(), serde_json::json!(v))).collect(),
                };
                let request = PipelineRequest {
                    variant,
                    material: &material,
                    targets,
                    vertex_layout: vertex_layout.as_ref(),
                    overrides: &overrides,
                };
                // The fallback for the combinations the trace lacks, drawn in the same state.
                self.warm_up_ubershader(&request)?;
                self.pipeline(&request).map(drop)
            }
            TracedPipeline::Compute { kernel } => {
                self.kernel(&KernelRequest { variant, kernel, overrides: &overrides }).map(drop)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_trace_line_is_the_documented_format_and_reads_back() {
        let entry = TraceEntry {
            version: TRACE_VERSION,
            shader: "Custom RP/Lit".into(),
            pass: 0,
            keywords: vec!["_CLIPPING".into(), "_FOG".into()],
            overrides: Vec::new(),
            pipeline: TracedPipeline::Render {
                state: [("_SrcBlend".to_string(), 1.0), ("_ZWrite".to_string(), 1.0)].into(),
                targets: Targets {
                    colors: vec![wgpu::TextureFormat::Bgra8UnormSrgb],
                    depth: Some(wgpu::TextureFormat::Depth32Float),
                    samples: 1,
                },
                vertex_layout: None,
            },
        };
        let line = serde_json::to_string(&entry).expect("writes");
        // As docs/trace.md shows it.
        assert_eq!(
            line,
            r#"{"version":1,"shader":"Custom RP/Lit","pass":0,"keywords":["_CLIPPING","_FOG"],"kind":"render","state":{"_SrcBlend":1.0,"_ZWrite":1.0},"targets":{"colors":["bgra8unorm-srgb"],"depth":"depth32float","samples":1}}"#
        );
        let kernel = r#"{"version":1,"shader":"Scale","pass":0,"keywords":[],"overrides":[["block",16.0]],"kind":"compute","kernel":"Reverse"}"#;
        let torn = &line[..line.len() / 2];
        let old = line.replace(r#""version":1"#, r#""version":0"#);
        let (entries, skipped) = read_trace(&[line.as_str(), kernel, torn, &line, &old].join("\n"));
        assert_eq!(entries.len(), 2, "each entry once");
        assert_eq!(entries[0], entry);
        assert!(matches!(&entries[1].pipeline, TracedPipeline::Compute { kernel } if kernel == "Reverse"));
        assert_eq!(skipped.iter().map(|(line, _)| *line).collect::<Vec<_>>(), [3, 5], "{skipped:?}");
    }
}
