//! The pipeline cache: each pipeline created once, keyed by what makes it (its modules' bytes,
//! the pass layout, the resolved render state, the targets, the vertex layout); reloading a
//! build from its output folder; usage capture.
//!
//! Long because `Runtime` is one lock over one table of what it made (layouts, modules,
//! pipelines by key), and every way to make a pipeline (a request, a warm-up, a reload) reads and
//! fills that table; the pieces with their own data (layouts, render state, overrides, traces,
//! kernels, the ubershader, the driver's cache) are modules of their own beside it.

use super::layout::{PassLayout, VertexLayout};
use super::overrides::{ConstantRequest, stage_constants};
use super::trace::{PipelineTrace, TRACE_VERSION, TraceEntry, TracedPipeline};
use super::{Library, PassId, RuntimeError, VariantId};
use kiln_manifest::{
    AttributeFormat, ERRORS_FILE, FILE_NAME, GpuFeature, MaterialManifest, ModuleFile, StageView,
};
use std::collections::{HashMap, HashSet};
use std::hash::{Hash, Hasher};
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, MutexGuard, PoisonError};
use std::time::{Duration, Instant};

/// The attachments a pipeline renders to.
#[derive(Debug, Clone, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct Targets {
    /// The colour target formats.
    pub colors: Vec<wgpu::TextureFormat>,
    /// The depth-stencil format, if any.
    pub depth: Option<wgpu::TextureFormat>,
    /// Samples per pixel.
    pub samples: u32,
}

/// What a draw needs a pipeline for.
pub struct PipelineRequest<'a> {
    /// The variant, with its `dynamic_branch` keywords: [`Runtime::variant`], looked up once.
    pub variant: VariantId,
    /// Whose property values decide the render state (`Blend [_SrcBlend] [_DstBlend]`).
    pub material: &'a MaterialManifest,
    /// The render targets the pipeline draws into.
    pub targets: &'a Targets,
    /// `None`: [`VertexLayout::packed`] from the vertex stage's inputs.
    pub vertex_layout: Option<&'a VertexLayout>,
    /// Values of the modules' own `override` constants, by name (or `@id` in decimal), as wgpu
    /// takes them (a generated `PassNOverrides` struct's `constants()`); `dynamic_branch` keywords
    /// come with the variant.
    pub overrides: &'a [(&'a str, f64)],
}

#[derive(Debug, Clone, PartialEq, Eq, Hash)]
struct PipelineKey {
    /// BLAKE3 of the vertex and fragment modules' WGSL.
    modules: [Option<String>; 2],
    /// The pass's layout, by the hash of its manifest entry.
    layout: blake3::Hash,
    state: super::RenderState,
    targets: Targets,
    vertex_layout: VertexLayout,
    /// Each stage's override constants, values by their bits.
    constants: Vec<Vec<(String, u64)>>,
}

/// Which modules of a pass a pipeline is made of.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Modules {
    /// The request's variant's.
    Variant,
    /// The pass's ubershader's.
    Ubershader,
}

/// A request resolved against its pass ([`Runtime::resolve`]).
pub(super) struct Resolved<'a> {
    pub(super) pass: &'a kiln_manifest::PassManifest,
    pub(super) facts: PassFacts,
    pub(super) state: super::RenderState,
    /// The request's hash: its key in [`Made::requests`].
    pub(super) key: [u8; 32],
}

/// What [`Runtime::reload`] found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Reload {
    /// The folder holds the build in use.
    Unchanged,
    /// A new build is in use; this many cached pipelines used modules it no longer has (they are
    /// created again, from the new modules, when next asked for).
    Swapped {
        /// Cached pipelines dropped.
        dropped_pipelines: usize,
    },
}

/// Every (shader, pass, keywords) asked for, and separately those the build did not have, as JSON
/// Lines (`{"shader": "Custom RP/Lit", "pass": 0, "keywords": ["_CLIPPING"]}`), each once, each
/// written and flushed at once. `kiln build --variants-from FILE` builds exactly these.
#[derive(Debug)]
pub struct UsageLog {
    requested: Option<std::fs::File>,
    missing: Option<std::fs::File>,
    seen: HashSet<(String, usize, Vec<String>, bool)>,
}

impl UsageLog {
    /// Appends to these files (created when absent); either may be left out.
    pub fn new(requested: Option<&Path>, missing: Option<&Path>) -> std::io::Result<UsageLog> {
        let open = |path: &Path| std::fs::OpenOptions::new().create(true).append(true).open(path);
        Ok(UsageLog {
            requested: requested.map(open).transpose()?,
            missing: missing.map(open).transpose()?,
            seen: HashSet::new(),
        })
    }

    fn record(&mut self, shader: &str, pass: usize, keywords: &[&str], missing: bool) {
        let mut keywords: Vec<String> = keywords.iter().map(|k| k.to_string()).collect();
        keywords.sort();
        keywords.dedup();
        // Formatted only for a request not logged before (a frame repeats its requests).
        let mut line = None;
        for (file, is_missing_log) in [(&mut self.requested, false), (&mut self.missing, true)] {
            if is_missing_log && !missing {
                continue;
            }
            let first = self.seen.insert((shader.to_string(), pass, keywords.clone(), is_missing_log));
            if let (true, Some(file)) = (first, file.as_mut()) {
                let line = line.get_or_insert_with(|| {
                    serde_json::json!({ "shader": shader, "pass": pass, "keywords": keywords }).to_string()
                });
                // A log that cannot be written must not stop a frame.
                let _ = writeln!(file, "{line}").and_then(|()| file.flush());
            }
        }
    }
}

/// What a pass needs once, not per pipeline request: its layout and its render state, read.
#[derive(Clone)]
pub(super) struct PassFacts {
    pub(super) layout_key: blake3::Hash,
    pub(super) layout: Arc<PassLayout>,
    state: Arc<super::state::PassState>,
}

/// What the runtime has made, behind one lock so that every method but configuration takes
/// `&self` and pipelines can be asked for from several threads.
#[derive(Default)]
pub(super) struct Made {
    /// By the hash of the pass's layout entry: passes laid out alike share one.
    layouts: HashMap<blake3::Hash, Arc<PassLayout>>,
    /// Per pass: what is worked out once.
    passes: HashMap<PassId, PassFacts>,
    /// By the hash of the module's WGSL.
    pub(super) modules: HashMap<String, wgpu::ShaderModule>,
    /// By a request's hash ([`request_key`]): a draw's lookup, allocating nothing.
    pub(super) requests: HashMap<[u8; 32], Arc<wgpu::RenderPipeline>>,
    /// By what makes the pipeline: requests that come to one pipeline share it.
    pipelines: HashMap<PipelineKey, Arc<wgpu::RenderPipeline>>,
    /// A dispatch's lookup, as `requests`.
    pub(super) kernel_requests: HashMap<[u8; 32], super::Kernel>,
    pub(super) kernels: HashMap<super::compute::KernelKey, Arc<wgpu::ComputePipeline>>,
    /// An ubershader's pipeline layout (its pass's, with immediate data), by the pass layout's key.
    pub(super) ubershader_layouts: HashMap<blake3::Hash, Arc<wgpu::PipelineLayout>>,
    /// An ubershader's pipeline, by the hash of what decides it (the request without its keywords).
    pub(super) ubershaders: HashMap<[u8; 32], Arc<wgpu::RenderPipeline>>,
    /// Requests whose pipeline a worker is creating (by their hash), and those it failed to.
    pub(super) pending: HashSet<[u8; 32]>,
    pub(super) failed: HashSet<[u8; 32]>,
}

/// A device's pipelines for one build, created once each and kept across reloads of unchanged
/// modules. Its methods take `&self` (it is `Sync`), except those that configure it or swap its
/// build.
pub struct Runtime {
    pub(super) device: wgpu::Device,
    pub(super) library: Library,
    /// The output folder the build came from, and its manifest's hash (for [`Runtime::reload`]).
    source: Option<(PathBuf, blake3::Hash)>,
    made: Mutex<Made>,
    created: AtomicUsize,
    usage: Mutex<Option<UsageLog>>,
    pub(super) trace: Mutex<Option<PipelineTrace>>,
    /// Set when a warm-up finished: pipelines created after it are misses.
    warm: AtomicBool,
    misses: Mutex<Vec<Creation>>,
    pub(super) wgpu_cache: Option<wgpu::PipelineCache>,
    /// Where [`Runtime::save_pipeline_cache`] writes `wgpu_cache`, with the header that names
    /// its adapter.
    pub(super) cache_file: Option<(PathBuf, String)>,
    /// Held while an ubershader's pipeline is made: warm-up threads asking for one state's
    /// make it once.
    pub(super) making_ubershader: Mutex<()>,
    /// Which form of its modules the device is handed.
    module_source: ModuleSource,
}

/// A pipeline created after warm-up: what a trace should have had.
#[derive(Debug, Clone)]
pub struct Creation {
    /// The pipeline's label (shader, pass or kernel, keywords).
    pub label: String,
    /// The thread that waited for it (its name, else its id).
    pub thread: String,
    /// How long creating it took.
    pub duration: Duration,
}

impl Runtime {
    /// A runtime over a build the program embeds (or any [`Library`]).
    pub fn new(device: &wgpu::Device, library: Library) -> Runtime {
        Runtime {
            device: device.clone(),
            library,
            source: None,
            made: Mutex::default(),
            created: AtomicUsize::new(0),
            usage: Mutex::new(None),
            trace: Mutex::new(None),
            warm: AtomicBool::new(false),
            misses: Mutex::new(Vec::new()),
            wgpu_cache: None,
            cache_file: None,
            making_ubershader: Mutex::new(()),
            module_source: ModuleSource::for_device(device),
        }
    }

    /// The form of its modules this runtime hands the device ([`ModuleSource::for_device`]
    /// unless [`Runtime::with_module_source`] chose).
    pub fn module_source(&self) -> ModuleSource {
        self.module_source
    }

    /// This runtime, handing the device its modules in `source`'s form.
    pub fn with_module_source(mut self, source: ModuleSource) -> Runtime {
        self.module_source = source;
        self
    }

    /// A runtime over the build in an output folder, which [`Runtime::reload`] watches.
    pub fn open(device: &wgpu::Device, output: impl AsRef<Path>) -> Result<Runtime, RuntimeError> {
        let output = output.as_ref();
        let hash = manifest_hash(output)?;
        let mut runtime = Runtime::new(device, Library::open(output)?);
        runtime.source = Some((output.to_path_buf(), hash));
        Ok(runtime)
    }

    /// The loaded build.
    pub fn library(&self) -> &Library {
        &self.library
    }

    /// What the runtime has made; a panic on another thread while it held the lock left nothing
    /// half-inserted, so the maps are used as they are.
    pub(super) fn made(&self) -> MutexGuard<'_, Made> {
        self.made.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// Records every variant asked for (and those missing) from now on.
    pub fn log_usage(&mut self, log: UsageLog) {
        *self.usage.get_mut().unwrap_or_else(PoisonError::into_inner) = Some(log);
    }

    /// Starts an empty wgpu pipeline cache for the pipelines made from now on. Returns false where
    /// the device lacks `Features::PIPELINE_CACHE` (only Vulkan has it): pipelines are then
    /// created without one.
    pub fn new_pipeline_cache(&mut self) -> bool {
        if !self.device.features().contains(wgpu::Features::PIPELINE_CACHE) {
            return false;
        }
        // SAFETY: no data: nothing from outside this process reaches the driver.
        let cache = unsafe {
            self.device.create_pipeline_cache(&wgpu::PipelineCacheDescriptor {
                label: Some("kiln"),
                data: None,
                fallback: true,
            })
        };
        self.wgpu_cache = Some(cache);
        true
    }

    /// Uses a wgpu pipeline cache the renderer created, from data an earlier run saved
    /// ([`Runtime::pipeline_cache_data`]): creating it is `unsafe` in wgpu, whose contract (the
    /// bytes came from `PipelineCache::get_data` on this adapter) only the renderer can keep.
    pub fn use_pipeline_cache(&mut self, cache: wgpu::PipelineCache) {
        self.wgpu_cache = Some(cache);
    }

    /// The pipeline cache's data, to save (with `wgpu::util::pipeline_cache_key` naming the file)
    /// and give back next run through `Device::create_pipeline_cache` and
    /// [`Runtime::use_pipeline_cache`].
    pub fn pipeline_cache_data(&self) -> Option<Vec<u8>> {
        self.wgpu_cache.as_ref().and_then(wgpu::PipelineCache::get_data)
    }

    /// How many pipelines (render and compute) this runtime has created.
    pub fn pipelines_created(&self) -> usize {
        self.created.load(Ordering::Relaxed)
    }

    /// Counts a pipeline created (after warm-up, with its thread and time, as a miss).
    pub(super) fn count_created(&self, label: &str, started: Instant) {
        self.created.fetch_add(1, Ordering::Relaxed);
        if self.warm.load(Ordering::Relaxed) {
            let thread = std::thread::current();
            let creation = Creation {
                label: label.to_string(),
                thread: thread.name().map_or_else(|| format!("{:?}", thread.id()), str::to_string),
                duration: started.elapsed(),
            };
            self.misses.lock().unwrap_or_else(PoisonError::into_inner).push(creation);
        }
    }

    /// From now on, a pipeline created is a miss of the warm-up ([`Runtime::created_after_warm_up`]);
    /// a warm-up from a trace says so itself when it is done.
    pub fn mark_warm(&self) {
        self.warm.store(true, Ordering::Relaxed);
    }

    /// The pipelines created since warm-up finished, each with the thread that waited and how
    /// long: Unreal's run-time creations, what the shipped trace lacked.
    pub fn created_after_warm_up(&self) -> Vec<Creation> {
        self.misses.lock().unwrap_or_else(PoisonError::into_inner).clone()
    }

    /// Writes a trace line for a request seen for the first time, when recording.
    pub(super) fn trace(&self, entry: impl FnOnce() -> Option<TraceEntry>) {
        let mut trace = self.trace.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some(trace) = trace.as_mut()
            && let Some(entry) = entry()
        {
            trace.record(&entry);
        }
    }

    /// A pass's handle ([`Library::pass_id`]).
    pub fn pass(&self, shader: &str, pass: usize) -> Result<PassId, RuntimeError> {
        self.library.pass_id(shader, pass)
    }

    /// The variant with exactly these keywords, as a handle for pipeline requests
    /// ([`Library::variant_id`]), recorded in the usage log as found or missing; a misspelt
    /// name is not recorded.
    pub fn variant(&self, shader: &str, pass: usize, keywords: &[&str]) -> Result<VariantId, RuntimeError> {
        let found = self.library.pass_id(shader, pass).and_then(|id| self.library.variant_id(id, keywords));
        // A typo (an unknown shader, pass or keyword) is no variant to build later: not logged.
        let missing = matches!(found, Err(RuntimeError::MissingVariant { .. }));
        if found.is_ok() || missing {
            let mut usage = self.usage.lock().unwrap_or_else(PoisonError::into_inner);
            if let Some(log) = usage.as_mut() {
                log.record(shader, pass, keywords, missing);
            }
        }
        found
    }

    /// The bind group and pipeline layouts of a pass.
    pub fn pass_layout(&self, pass: PassId) -> Result<Arc<PassLayout>, RuntimeError> {
        Ok(self.pass_facts(pass)?.layout)
    }

    /// What is worked out once per pass: its layout (shared by passes laid out alike) and its
    /// render state, read.
    pub(super) fn pass_facts(&self, id: PassId) -> Result<PassFacts, RuntimeError> {
        let manifest = self.library.pass_of(id)?;
        let mut made = self.made();
        if let Some(facts) = made.passes.get(&id) {
            return Ok(facts.clone());
        }
        let layout_key = blake3::hash(serde_json::to_string(&manifest.layout).unwrap_or_default().as_bytes());
        let state = super::state::PassState::new(manifest);
        let layout = match made.layouts.get(&layout_key) {
            Some(layout) => layout.clone(),
            None => {
                let layout = PassLayout::new(&self.device, &manifest.layout).map_err(|error| {
                    RuntimeError::Layout {
                        shader: self.library.shader_name(id).to_string(),
                        pass: manifest.index,
                        message: error.to_string(),
                    }
                })?;
                let layout = Arc::new(layout);
                made.layouts.insert(layout_key, layout.clone());
                layout
            }
        };
        let facts = PassFacts { layout_key, layout, state: Arc::new(state) };
        made.passes.insert(id, facts.clone());
        Ok(facts)
    }

    /// The pipeline for a draw, created the first time it is asked for. A request asked for
    /// before is found by its hash, allocating nothing.
    pub fn pipeline(&self, request: &PipelineRequest) -> Result<Arc<wgpu::RenderPipeline>, RuntimeError> {
        let resolved = self.resolve(request)?;
        if let Some(pipeline) = self.made().requests.get(&resolved.key) {
            return Ok(pipeline.clone());
        }
        self.create_requested(request, resolved)
    }

    /// What a request comes to: its pass, the pass's facts, the resolved render state and the
    /// request's hash.
    pub(super) fn resolve<'a>(&'a self, request: &PipelineRequest) -> Result<Resolved<'a>, RuntimeError> {
        let library = &self.library;
        let pass = library.pass_of(request.variant.pass())?;
        let facts = self.pass_facts(request.variant.pass())?;
        let state = facts.state.resolve(&|property| request.material.number(property)).map_err(|error| {
            RuntimeError::State {
                shader: library.shader_name(request.variant.pass()).to_string(),
                pass: pass.index,
                error,
            }
        })?;
        let key = request_key(|hasher| {
            (request.variant, &state, request.targets, request.vertex_layout).hash(hasher);
            hash_overrides(request.overrides, hasher);
        });
        Ok(Resolved { pass, facts, state, key })
    }

    /// Creates a request's pipeline (not asked for before), keeps it under the request's hash
    /// and traces it.
    pub(super) fn create_requested(
        &self,
        request: &PipelineRequest,
        resolved: Resolved,
    ) -> Result<Arc<wgpu::RenderPipeline>, RuntimeError> {
        let Resolved { pass, facts, state, key } = resolved;
        let (shader, pass_index) = (self.library.shader_name(request.variant.pass()), pass.index);
        let pipeline = self.create_pipeline(request, pass, &facts, state, Modules::Variant)?;
        self.made().requests.insert(key, pipeline.clone());
        self.trace(|| {
            let keywords = self.traced_keywords(request.variant)?;
            let state = pass.render_state.iter().flat_map(|c| &c.properties);
            let state = state.filter_map(|p| Some((p.name.clone(), request.material.number(&p.name)?)));
            Some(TraceEntry {
                version: TRACE_VERSION,
                shader: shader.to_string(),
                pass: pass_index,
                keywords,
                overrides: request.overrides.iter().map(|(k, v)| (k.to_string(), *v)).collect(),
                pipeline: TracedPipeline::Render {
                    state: state.collect(),
                    targets: request.targets.clone(),
                    vertex_layout: request.vertex_layout.cloned(),
                },
            })
        });
        Ok(pipeline)
    }

    /// A request's pipeline the first time it is asked for: the one of an earlier request that
    /// comes to the same (its modules, layout, state, targets, vertex layout and constants), or a
    /// new one.
    pub(super) fn create_pipeline(
        &self,
        request: &PipelineRequest,
        pass: &kiln_manifest::PassManifest,
        facts: &PassFacts,
        state: super::RenderState,
        modules: Modules,
    ) -> Result<Arc<wgpu::RenderPipeline>, RuntimeError> {
        let library = &self.library;
        let (shader, pass_index) = (library.shader_name(request.variant.pass()), pass.index);
        let layout_error =
            |message: String| RuntimeError::Layout { shader: shader.to_string(), pass: pass_index, message };
        let variant = library.variant_of(request.variant)?;
        let ubershader = match modules {
            Modules::Variant => None,
            Modules::Ubershader => Some(
                pass.ubershader.as_ref().ok_or_else(|| layout_error("the pass has no ubershader".into()))?,
            ),
        };
        let stages = pass.variant_stages(ubershader.map_or(variant, |u| &u.modules));
        let [Some(vertex), fragment] = stages else {
            return Err(layout_error("the variant has no vertex stage".into()));
        };
        let vertex_layout = match request.vertex_layout {
            Some(layout) => layout.clone(),
            None => {
                let inputs: Vec<(u32, AttributeFormat)> =
                    vertex.interface.inputs.iter().map(|a| (a.location, a.format)).collect();
                VertexLayout::packed(&inputs).map_err(|error| layout_error(error.to_string()))?
            }
        };
        // The ubershader reads them from its immediate data.
        let dynamic: Vec<&str> = match ubershader {
            None => library.dynamic_keywords(request.variant)?.collect(),
            Some(_) => Vec::new(),
        };
        let constants = stage_constants(
            &ConstantRequest { shader, pass, keywords: &dynamic, overrides: request.overrides },
            &stages,
        )?;
        let key = PipelineKey {
            modules: [Some(&vertex), fragment.as_ref()]
                .map(|s| s.and_then(|s| s.module.wgsl.as_ref()).map(|f| f.hash.clone())),
            layout: facts.layout_key,
            state,
            targets: request.targets.clone(),
            vertex_layout,
            constants: constant_bits(&constants),
        };
        if let Some(pipeline) = self.made().pipelines.get(&key) {
            return Ok(pipeline.clone());
        }
        let stages = [Some(&vertex), fragment.as_ref()];
        self.check_features(stages.iter().flatten().flat_map(|stage| &stage.module.features))
            .map_err(layout_error)?;
        let module = |stage: &StageView| {
            let module = self.shader_module(shader, stage).map_err(layout_error)?;
            Ok::<_, RuntimeError>((module, stage.interface.entry_point.clone()))
        };
        let (vertex_module, vertex_entry) = module(&vertex)?;
        let fragment_module = fragment.as_ref().map(module).transpose()?;
        let targets: Vec<Option<wgpu::ColorTargetState>> = key
            .targets
            .colors
            .iter()
            .zip(&key.state.targets)
            .map(|(&format, target)| {
                Some(wgpu::ColorTargetState { format, blend: target.blend, write_mask: target.write_mask })
            })
            .collect();
        let buffers = key.vertex_layout.wgpu();
        let [vertex_constants, fragment_constants] = [0, 1].map(|stage| wgpu_constants(&constants[stage]));
        let label = match ubershader {
            None => format!("{shader} pass {pass_index} [{}]", variant.keywords.join(" ")),
            Some(_) => format!("{shader} pass {pass_index} (ubershader)"),
        };
        let ubershader_layout;
        let layout = match ubershader {
            None => &facts.layout.pipeline,
            Some(_) => {
                ubershader_layout = self.ubershader_layout(facts);
                &*ubershader_layout
            }
        };
        let started = Instant::now();
        let pipeline = validated(&self.device, |device| {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(&label),
                layout: Some(layout),
                vertex: wgpu::VertexState {
                    module: &vertex_module,
                    entry_point: Some(&vertex_entry),
                    compilation_options: wgpu::PipelineCompilationOptions {
                        constants: &vertex_constants,
                        ..Default::default()
                    },
                    buffers: &buffers,
                },
                primitive: key.state.primitive(),
                depth_stencil: key.targets.depth.map(|format| key.state.depth_stencil(format)),
                multisample: wgpu::MultisampleState {
                    count: key.targets.samples,
                    mask: !0,
                    alpha_to_coverage_enabled: key.state.alpha_to_coverage,
                },
                fragment: fragment_module.as_ref().map(|(module, entry)| wgpu::FragmentState {
                    module,
                    entry_point: Some(entry),
                    compilation_options: wgpu::PipelineCompilationOptions {
                        constants: &fragment_constants,
                        ..Default::default()
                    },
                    targets: &targets,
                }),
                multiview_mask: None,
                cache: self.wgpu_cache.as_ref(),
            })
        })
        .map_err(layout_error)?;
        self.count_created(&label, started);
        // Another thread may have made the same one meanwhile: the first kept is the one used.
        Ok(self.made().pipelines.entry(key).or_insert_with(|| Arc::new(pipeline)).clone())
    }

    /// A handle's keywords as a trace names them: the variant's and the `dynamic_branch` ones on,
    /// sorted.
    pub(super) fn traced_keywords(&self, variant: VariantId) -> Option<Vec<String>> {
        let mut keywords = self.library.variant_of(variant).ok()?.keywords.clone();
        keywords.extend(self.library.dynamic_keywords(variant).ok()?.map(str::to_string));
        keywords.sort();
        Some(keywords)
    }

    /// Creates, ahead of the first frame, the pipeline of every pass each material's variant has
    /// (with `global_keywords` added to its keywords, those its pass declares). Returns how many
    /// render pipelines exist afterwards, or every request that failed.
    pub fn warm_up(
        &self,
        materials: &[&MaterialManifest],
        global_keywords: &[&str],
        targets: &Targets,
    ) -> Result<usize, Vec<RuntimeError>> {
        let mut errors = Vec::new();
        for material in materials {
            let passes: Vec<usize> = match self.library.shader(&material.shader) {
                Ok(shader) => shader.passes.iter().map(|p| p.index).collect(),
                Err(error) => {
                    errors.push(error);
                    continue;
                }
            };
            for pass in passes {
                let declared = |keyword: &&str| {
                    self.library
                        .pass(&material.shader, pass)
                        .is_ok_and(|p| p.keywords.iter().chain(p.dynamic_keywords()).any(|d| d == keyword))
                };
                let keywords: Vec<&str> = material
                    .keywords
                    .iter()
                    .map(String::as_str)
                    .chain(global_keywords.iter().copied().filter(declared))
                    .collect();
                let pipeline = self.variant(&material.shader, pass, &keywords).and_then(|variant| {
                    self.pipeline(&PipelineRequest {
                        variant,
                        material,
                        targets,
                        vertex_layout: None,
                        overrides: &[],
                    })
                });
                if let Err(error) = pipeline {
                    errors.push(error);
                }
            }
        }
        if errors.is_empty() { Ok(self.made().pipelines.len()) } else { Err(errors) }
    }

    /// Loads the output folder's build if it changed since the one in use. A build that failed
    /// (`kiln watch` leaves its diagnostics in the folder) is an error with those diagnostics,
    /// and the build in use stays, with its pipelines. Handles of the old build are refused
    /// afterwards ([`RuntimeError::StaleHandle`]): look them up again.
    pub fn reload(&mut self) -> Result<Reload, RuntimeError> {
        let Some((output, current)) = self.source.clone() else { return Ok(Reload::Unchanged) };
        if let Ok(errors) = std::fs::read_to_string(output.join(ERRORS_FILE)) {
            return Err(RuntimeError::BuildFailed(errors));
        }
        let hash = manifest_hash(&output)?;
        if hash == current {
            return Ok(Reload::Unchanged);
        }
        let library = Library::open(&output)?;
        let hashes: HashSet<String> = library.manifest().files().into_iter().map(|f| f.hash).collect();
        let made = self.made.get_mut().unwrap_or_else(PoisonError::into_inner);
        let before = made.pipelines.len() + made.kernels.len();
        made.pipelines.retain(|key, _| key.modules.iter().flatten().all(|h| hashes.contains(h)));
        made.kernels.retain(|key, _| hashes.contains(&key.module));
        made.modules.retain(|hash, _| hashes.contains(hash));
        // Requests name the old build's variants; layouts and render state are read again from
        // the new manifest.
        made.requests.clear();
        made.kernel_requests.clear();
        made.passes.clear();
        let dropped_pipelines = before - made.pipelines.len() - made.kernels.len();
        self.library = library;
        self.source = Some((output, hash));
        Ok(Reload::Swapped { dropped_pipelines })
    }

    /// Refuses modules that need a GPU feature the device was not created with, before the
    /// driver sees them (wgpu would fail the pipeline, or a driver take it and draw wrongly).
    pub(super) fn check_features<'a>(
        &self,
        needed: impl IntoIterator<Item = &'a GpuFeature>,
    ) -> Result<(), String> {
        let device = self.device.features();
        match needed.into_iter().find(|&&feature| !device.contains(wgpu_feature(feature))) {
            Some(feature) => {
                Err(format!("the variant needs `{feature}`, which the device was not created with"))
            }
            None => Ok(()),
        }
    }

    /// A stage's module, created once per module file (by its hash) and kept across pipelines:
    /// its SPIR-V where [`Runtime::module_source`] says so and the module has no `override`s
    /// (wgpu reads SPIR-V in about a third of WGSL's time, docs/performance.md), else its WGSL.
    /// Its bytes are checked against the manifest's hash before the driver sees them, once, on
    /// first use: whatever [`Library::open`] read, a changed module never becomes a pipeline.
    pub(super) fn shader_module(
        &self,
        shader: &str,
        stage: &StageView,
    ) -> Result<wgpu::ShaderModule, String> {
        let spirv = (self.module_source == ModuleSource::Spirv && stage.interface.overrides.is_empty())
            .then_some(stage.module.spirv.as_ref())
            .flatten();
        // The file chosen names the module in `Made::modules`, whatever was made of it.
        let chosen = spirv.or(stage.module.wgsl.as_ref()).ok_or("the build has no WGSL for it")?;
        if let Some(module) = self.made().modules.get(&chosen.hash) {
            return Ok(module.clone());
        }
        // SPIR-V that wgpu's reader refuses (none the tests build) falls back to the WGSL, once:
        // the WGSL's module is kept under the SPIR-V's name. Bytes that fail their hash never do.
        let from_spirv = match spirv {
            Some(file) => self.spirv_module(shader, stage, file)?,
            None => None,
        };
        let module = match from_spirv {
            Some(module) => module,
            None => {
                let file = stage.module.wgsl.as_ref().ok_or("the build has no WGSL for it")?;
                let text =
                    std::str::from_utf8(self.checked_bytes(stage, file)?).map_err(|e| e.to_string())?;
                create_module(&self.device, shader, stage, wgpu::ShaderSource::Wgsl(text.into()))
            }
        };
        Ok(self.made().modules.entry(chosen.hash.clone()).or_insert(module).clone())
    }

    /// A stage's module from its SPIR-V, once its bytes are the manifest's; `None` where wgpu's
    /// reader refuses them.
    fn spirv_module(
        &self,
        shader: &str,
        stage: &StageView,
        file: &ModuleFile,
    ) -> Result<Option<wgpu::ShaderModule>, String> {
        let bytes = self.checked_bytes(stage, file)?;
        if bytes.len() % 4 != 0 {
            return Err("its SPIR-V is not whole words: build again".into());
        }
        let words = bytes.chunks_exact(4).map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]]));
        let source = wgpu::ShaderSource::SpirV(words.collect::<Vec<u32>>().into());
        Ok(validated(&self.device, |device| create_module(device, shader, stage, source)).ok())
    }

    /// A module file's bytes, once they are what the manifest names.
    fn checked_bytes<'a>(&'a self, stage: &StageView, file: &ModuleFile) -> Result<&'a [u8], String> {
        let bytes = self.library.bytes(stage.pass, file).ok_or("its module is missing from its pack")?;
        if blake3::hash(bytes).to_hex()[..32] != file.hash {
            return Err("its module's bytes are not what the manifest names (the build was changed since): build again".into());
        }
        Ok(bytes)
    }
}

/// A module labelled with its shader and entry point.
fn create_module(
    device: &wgpu::Device,
    shader: &str,
    stage: &StageView,
    source: wgpu::ShaderSource,
) -> wgpu::ShaderModule {
    let label = format!("{shader} {}", stage.interface.entry_point);
    device.create_shader_module(wgpu::ShaderModuleDescriptor { label: Some(&label), source })
}

/// Which form of a stage module the run time hands wgpu: both are in a build that writes both
/// back ends (the default), and both go through naga inside wgpu before a driver sees them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModuleSource {
    /// The WGSL: every back end, the web included.
    Wgsl,
    /// The SPIR-V, for modules without `override`s (naga's SPIR-V reader takes their values
    /// as specialisation constants, which the run time does not set), the WGSL for the rest.
    Spirv,
}

impl ModuleSource {
    /// What a device is handed by default: SPIR-V on Vulkan, the back end it is written for,
    /// WGSL elsewhere.
    pub fn for_device(device: &wgpu::Device) -> ModuleSource {
        match device.adapter_info().backend {
            wgpu::Backend::Vulkan => ModuleSource::Spirv,
            _ => ModuleSource::Wgsl,
        }
    }
}

/// A request's 256-bit key: what `hash` feeds, through BLAKE3 (no allocation, no collision to
/// fear where a 64-bit `Hasher` would need the request kept to compare).
pub(super) fn request_key(hash: impl FnOnce(&mut KeyHasher)) -> [u8; 32] {
    let mut hasher = KeyHasher(blake3::Hasher::new());
    hash(&mut hasher);
    *hasher.0.finalize().as_bytes()
}

/// Feeds `Hash` values into BLAKE3.
pub(super) struct KeyHasher(blake3::Hasher);

impl Hasher for KeyHasher {
    fn write(&mut self, bytes: &[u8]) {
        self.0.update(bytes);
    }
    fn finish(&self) -> u64 {
        let hash = self.0.finalize();
        u64::from_le_bytes(hash.as_bytes()[..8].try_into().unwrap_or_default())
    }
}

/// Override values by name and bits, in the order given.
pub(super) fn hash_overrides(overrides: &[(&str, f64)], hasher: &mut KeyHasher) {
    for (name, value) in overrides {
        (name, value.to_bits()).hash(hasher);
    }
}

/// What `create` makes, or wgpu's validation error for it (a pipeline wgpu refuses is an error
/// to return, not a panic in its error handler).
pub(super) fn validated<T>(
    device: &wgpu::Device,
    create: impl FnOnce(&wgpu::Device) -> T,
) -> Result<T, String> {
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let made = create(device);
    match pollster::block_on(scope.pop()) {
        Some(error) => Err(format!("wgpu refused the pipeline: {error}")),
        None => Ok(made),
    }
}

/// A stage's constants with their values' bits, for a pipeline key.
pub(super) fn constant_bits(constants: &[Vec<(String, f64)>]) -> Vec<Vec<(String, u64)>> {
    constants.iter().map(|c| c.iter().map(|(k, v)| (k.clone(), v.to_bits())).collect()).collect()
}

/// A stage's constants as wgpu takes them.
pub(super) fn wgpu_constants(constants: &[(String, f64)]) -> Vec<(&str, f64)> {
    constants.iter().map(|(k, v)| (k.as_str(), *v)).collect()
}

fn manifest_hash(output: &Path) -> Result<blake3::Hash, RuntimeError> {
    let path = output.join(FILE_NAME);
    let bytes = std::fs::read(&path).map_err(|e| RuntimeError::Read { path, message: e.to_string() })?;
    Ok(blake3::hash(&bytes))
}

/// wgpu's flag for a feature a manifest names.
pub fn wgpu_feature(feature: GpuFeature) -> wgpu::Features {
    match feature {
        GpuFeature::ShaderF16 => wgpu::Features::SHADER_F16,
        GpuFeature::ShaderInt64 => wgpu::Features::SHADER_INT64,
        GpuFeature::ShaderBarycentrics => wgpu::Features::SHADER_BARYCENTRICS,
        GpuFeature::Subgroup => wgpu::Features::SUBGROUP,
        GpuFeature::Immediates => wgpu::Features::IMMEDIATES,
    }
}
