//! Drawing without waiting for a pipeline. A pass with `#pragma ubershader` has one module per
//! stage that reads every keyword from 8 bytes of immediate data; while a request's own pipeline
//! is created on a worker thread, the draw uses the ubershader's pipeline with the request's
//! keywords as those bytes (docs/keywords.md).

use super::layout::VertexLayout;
use super::pipelines::{
    Modules, PassFacts, PipelineRequest, Resolved, Runtime, Targets, hash_overrides, request_key,
};
use super::{RuntimeError, VariantId};
use kiln_manifest::MaterialManifest;
use std::hash::Hash;
use std::sync::Arc;

/// Bytes of an ubershader's immediate data: one bit per keyword, 64 at most.
pub const UBERSHADER_IMMEDIATE_SIZE: u32 = 8;

/// What a draw binds ([`Runtime::drawable`]).
#[derive(Debug, Clone)]
pub enum Drawable {
    /// The request's own pipeline.
    Ready(Arc<wgpu::RenderPipeline>),
    /// The pass's ubershader, while the request's pipeline is created: draws the same thing when
    /// given `immediates` (the request's keywords).
    Fallback {
        /// The ubershader's pipeline for the request's state, targets and vertex layout.
        pipeline: Arc<wgpu::RenderPipeline>,
        /// Its immediate data: the request's keywords as bits.
        immediates: [u8; 8],
    },
}

impl Drawable {
    /// Sets the pipeline (and, for the ubershader, its immediate data) on a render pass.
    pub fn set_on(&self, pass: &mut wgpu::RenderPass<'_>) {
        match self {
            Drawable::Ready(pipeline) => pass.set_pipeline(pipeline),
            Drawable::Fallback { pipeline, immediates } => {
                pass.set_pipeline(pipeline);
                pass.set_immediates(0, immediates);
            }
        }
    }

    /// Whether it is the request's own pipeline.
    pub fn is_ready(&self) -> bool {
        matches!(self, Drawable::Ready(_))
    }
}

/// A request a worker thread creates the pipeline of, owning what the caller lent.
struct OwnedRequest {
    variant: VariantId,
    material: MaterialManifest,
    targets: Targets,
    vertex_layout: Option<VertexLayout>,
    overrides: Vec<(String, f64)>,
}

impl OwnedRequest {
    fn new(request: &PipelineRequest) -> OwnedRequest {
        OwnedRequest {
            variant: request.variant,
            material: request.material.clone(),
            targets: request.targets.clone(),
            vertex_layout: request.vertex_layout.cloned(),
            overrides: request.overrides.iter().map(|(name, value)| (name.to_string(), *value)).collect(),
        }
    }
}

impl Runtime {
    /// Whether the device can draw ubershaders: wgpu's `Features::IMMEDIATES` with at least
    /// [`UBERSHADER_IMMEDIATE_SIZE`] bytes (`Limits::max_immediate_size`).
    pub fn draws_ubershaders(&self) -> bool {
        self.device.features().contains(wgpu::Features::IMMEDIATES)
            && self.device.limits().max_immediate_size >= UBERSHADER_IMMEDIATE_SIZE
    }

    /// The pipeline for a draw, without waiting for it to be created when its pass has an
    /// ubershader: a request asked for before gets its pipeline; a new one gets the ubershader's
    /// ([`Drawable::Fallback`]) while a rayon worker creates its own, which later calls get.
    /// Passes without an ubershader, and devices that cannot draw one, create the pipeline now
    /// as [`Runtime::pipeline`] does. The ubershader's pipeline for a new render state is created
    /// now unless [`Runtime::warm_up_ubershader`] made it earlier.
    pub fn drawable(self: &Arc<Self>, request: &PipelineRequest) -> Result<Drawable, RuntimeError> {
        let resolved = self.resolve(request)?;
        let key = resolved.key;
        let failed = {
            let made = self.made();
            if let Some(pipeline) = made.requests.get(&key) {
                return Ok(Drawable::Ready(pipeline.clone()));
            }
            made.failed.contains(&key)
        };
        let ubershader = resolved.pass.ubershader.as_ref().filter(|_| self.draws_ubershaders());
        // A request a worker failed to create is created here, to return its error.
        let Some(ubershader) = ubershader.filter(|_| !failed) else {
            return self.create_requested(request, resolved).map(Drawable::Ready);
        };
        let variant = self.library.variant_of(request.variant)?;
        let dynamic = self.library.dynamic_keywords(request.variant)?;
        let immediates = ubershader.immediates(variant.keywords.iter().map(String::as_str).chain(dynamic));
        let pipeline = self.ubershader_pipeline(request, &resolved)?;
        if self.made().pending.insert(key) {
            let (runtime, owned) = (Arc::clone(self), OwnedRequest::new(request));
            in_background(Box::new(move || {
                let overrides: Vec<(&str, f64)> =
                    owned.overrides.iter().map(|(k, v)| (k.as_str(), *v)).collect();
                let request = PipelineRequest {
                    variant: owned.variant,
                    material: &owned.material,
                    targets: &owned.targets,
                    vertex_layout: owned.vertex_layout.as_ref(),
                    overrides: &overrides,
                };
                let created = runtime.pipeline(&request);
                let mut made = runtime.made();
                made.pending.remove(&key);
                if created.is_err() {
                    made.failed.insert(key);
                }
            }));
        }
        Ok(Drawable::Fallback { pipeline, immediates })
    }

    /// How many pipelines workers are creating for [`Runtime::drawable`] now.
    pub fn pipelines_pending(&self) -> usize {
        self.made().pending.len()
    }

    /// Creates the ubershader's pipeline for a request's pass, render state, targets, vertex
    /// layout and overrides (its keywords do not matter), so that [`Runtime::drawable`] never
    /// creates one on the render thread. Returns false where the pass has no ubershader or the
    /// device cannot draw one.
    pub fn warm_up_ubershader(&self, request: &PipelineRequest) -> Result<bool, RuntimeError> {
        let resolved = self.resolve(request)?;
        if resolved.pass.ubershader.is_none() || !self.draws_ubershaders() {
            return Ok(false);
        }
        self.ubershader_pipeline(request, &resolved).map(|_| true)
    }

    /// The ubershader's pipeline for a request, created the first time.
    fn ubershader_pipeline(
        &self,
        request: &PipelineRequest,
        resolved: &Resolved,
    ) -> Result<Arc<wgpu::RenderPipeline>, RuntimeError> {
        let key = request_key(|hasher| {
            (request.variant.pass(), &resolved.state, request.targets, request.vertex_layout).hash(hasher);
            hash_overrides(request.overrides, hasher);
        });
        if let Some(pipeline) = self.made().ubershaders.get(&key) {
            return Ok(pipeline.clone());
        }
        let _making = self.making_ubershader.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        // Another thread may have made it while this one waited.
        if let Some(pipeline) = self.made().ubershaders.get(&key) {
            return Ok(pipeline.clone());
        }
        let state = resolved.state.clone();
        let pipeline =
            self.create_pipeline(request, resolved.pass, &resolved.facts, state, Modules::Ubershader)?;
        self.made().ubershaders.insert(key, pipeline.clone());
        Ok(pipeline)
    }

    /// A pass layout's pipeline layout with the ubershader's immediate data.
    pub(super) fn ubershader_layout(&self, facts: &PassFacts) -> Arc<wgpu::PipelineLayout> {
        let mut made = self.made();
        let layout = made.ubershader_layouts.entry(facts.layout_key).or_insert_with(|| {
            let groups: Vec<Option<&wgpu::BindGroupLayout>> = facts.layout.groups.iter().map(Some).collect();
            Arc::new(self.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("kiln ubershader"),
                bind_group_layouts: &groups,
                immediate_size: UBERSHADER_IMMEDIATE_SIZE,
            }))
        });
        layout.clone()
    }
}

/// A pipeline to create off the render thread.
type Job = Box<dyn FnOnce() + Send>;

/// The workers [`Runtime::drawable`] hands pipelines to, started at the first fallback draw and
/// shared by every runtime in the process (a few threads, as many as cores up to four: creating
/// pipelines is the driver's work, and more threads only contend for it).
static WORKERS: std::sync::OnceLock<Option<std::sync::mpsc::Sender<Job>>> = std::sync::OnceLock::new();

/// Runs `job` on a worker, or here, at once, where no thread can start (a browser's main thread):
/// the draw then waits, as it would without an ubershader, but nothing is lost.
fn in_background(job: Job) {
    let workers = WORKERS.get_or_init(|| {
        let (sender, receiver) = std::sync::mpsc::channel::<Job>();
        let receiver = Arc::new(std::sync::Mutex::new(receiver));
        let count = std::thread::available_parallelism().map_or(1, std::num::NonZero::get).min(4);
        let started = (0..count)
            .filter(|i| {
                let receiver = Arc::clone(&receiver);
                std::thread::Builder::new()
                    .name(format!("kiln pipelines {i}"))
                    .spawn(move || {
                        // The lock is held while waiting for a job, never while running one.
                        while let Some(job) = receiver.lock().ok().and_then(|r| r.recv().ok()) {
                            job();
                        }
                    })
                    .is_ok()
            })
            .count();
        (started > 0).then_some(sender)
    });
    match workers {
        Some(sender) => {
            if let Err(std::sync::mpsc::SendError(job)) = sender.send(job) {
                job();
            }
        }
        None => job(),
    }
}
