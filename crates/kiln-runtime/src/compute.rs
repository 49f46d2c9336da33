//! Compute pipelines: a kernel of a compute shader's variant (docs/compute.md), created once
//! per (module, layout, `override` values) by the same runtime, usage log and reload as render
//! pipelines, and the workgroup count for a problem size.

use super::overrides::{ConstantRequest, stage_constants};
use super::pipelines::{Runtime, constant_bits, hash_overrides, request_key, validated, wgpu_constants};
use super::trace::{TRACE_VERSION, TraceEntry, TracedPipeline};
use super::{RuntimeError, VariantId};
use std::hash::Hash as _;
use std::sync::Arc;

/// What a dispatch needs a compute pipeline for.
pub struct KernelRequest<'a> {
    /// The compute shader's variant ([`Runtime::variant`] of its pass 0, looked up once), with
    /// its `dynamic_branch` keywords.
    pub variant: VariantId,
    /// The kernel (`#pragma kernel NAME`).
    pub kernel: &'a str,
    /// Values of the module's own `override` constants, as [`PipelineRequest::overrides`](super::PipelineRequest::overrides).
    pub overrides: &'a [(&'a str, f64)],
}

/// A kernel's compute pipeline and its workgroup size.
#[derive(Debug, Clone)]
pub struct Kernel {
    /// The pipeline, with the compute shader's layout ([`Runtime::pass_layout`] of pass 0).
    pub pipeline: Arc<wgpu::ComputePipeline>,
    /// Its `@workgroup_size`, a size an `override` gives being that constant's value here.
    pub workgroup_size: [u32; 3],
}

impl Kernel {
    /// The workgroups to dispatch so that every one of `size` invocations runs (each dimension
    /// rounded up to whole workgroups).
    pub fn workgroups(&self, size: [u32; 3]) -> [u32; 3] {
        let mut count = [0; 3];
        for (c, (n, group)) in count.iter_mut().zip(size.into_iter().zip(self.workgroup_size)) {
            *c = n.div_ceil(group.max(1));
        }
        count
    }
}

#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub(super) struct KernelKey {
    /// BLAKE3 of the kernel module's WGSL.
    pub(super) module: String,
    layout: blake3::Hash,
    constants: Vec<(String, u64)>,
}

impl Runtime {
    /// The compute pipeline of a kernel of a compute shader's variant, created the first time it
    /// is asked for; asked for again, it is found by the request's hash, allocating nothing.
    pub fn kernel(&self, request: &KernelRequest) -> Result<Kernel, RuntimeError> {
        let library = &self.library;
        let pass = library.pass_of(request.variant.pass())?;
        let request_key = request_key(|hasher| {
            (request.variant, request.kernel).hash(hasher);
            hash_overrides(request.overrides, hasher);
        });
        if let Some(kernel) = self.made().kernel_requests.get(&request_key) {
            return Ok(kernel.clone());
        }
        let shader = library.shader_name(request.variant.pass());
        let facts = self.pass_facts(request.variant.pass())?;
        let variant = library.variant_of(request.variant)?;
        let layout_error =
            |message: String| RuntimeError::Layout { shader: shader.to_string(), pass: pass.index, message };
        let Some(index) = pass.kernels.iter().position(|k| k == request.kernel) else {
            return Err(RuntimeError::UnknownKernel {
                shader: shader.to_string(),
                kernel: request.kernel.to_string(),
                suggestion: kiln_manifest::closest(request.kernel, pass.kernels.iter().map(String::as_str)),
            });
        };
        let module = variant.kernels.get(index).copied().flatten();
        let stage =
            module.map(|m| pass.stage(m)).ok_or_else(|| layout_error("the kernel was not built".into()))?;
        let dynamic: Vec<&str> = library.dynamic_keywords(request.variant)?.collect();
        let constants = stage_constants(
            &ConstantRequest { shader, pass, keywords: &dynamic, overrides: request.overrides },
            std::slice::from_ref(&Some(stage)),
        )?;
        // A size an `override` gives is that constant's value in this pipeline.
        let mut workgroup_size = stage.interface.workgroup_size.unwrap_or([1, 1, 1]);
        for (size, name) in workgroup_size.iter_mut().zip(&stage.interface.workgroup_size_overrides) {
            let Some(constant) =
                name.as_ref().and_then(|n| stage.interface.overrides.iter().find(|o| &o.name == n))
            else {
                continue;
            };
            let given = constants[0].iter().find(|(key, _)| *key == constant.key()).map(|&(_, v)| v);
            *size = given.or(constant.default).unwrap_or(1.0) as u32;
        }
        let hash = stage.module.wgsl.as_ref().map(|f| f.hash.clone()).unwrap_or_default();
        let key = KernelKey {
            module: hash,
            layout: facts.layout_key,
            constants: constant_bits(&constants).remove(0),
        };
        let found = self.made().kernels.get(&key).cloned();
        let pipeline = match found {
            Some(pipeline) => pipeline,
            None => {
                self.check_features(&stage.module.features).map_err(layout_error)?;
                let module = self.shader_module(shader, &stage).map_err(layout_error)?;
                let label = format!("{shader} kernel {} [{}]", request.kernel, variant.keywords.join(" "));
                let started = std::time::Instant::now();
                let pipeline = validated(&self.device, |device| {
                    device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                        label: Some(&label),
                        layout: Some(&facts.layout.pipeline),
                        module: &module,
                        entry_point: Some(request.kernel),
                        compilation_options: wgpu::PipelineCompilationOptions {
                            constants: &wgpu_constants(&constants[0]),
                            ..Default::default()
                        },
                        cache: self.wgpu_cache.as_ref(),
                    })
                })
                .map_err(layout_error)?;
                self.count_created(&label, started);
                self.made().kernels.entry(key).or_insert_with(|| Arc::new(pipeline)).clone()
            }
        };
        let kernel = Kernel { pipeline, workgroup_size };
        self.made().kernel_requests.insert(request_key, kernel.clone());
        self.trace(|| {
            Some(TraceEntry {
                version: TRACE_VERSION,
                shader: shader.to_string(),
                pass: pass.index,
                keywords: self.traced_keywords(request.variant)?,
                overrides: request.overrides.iter().map(|(k, v)| (k.to_string(), *v)).collect(),
                pipeline: TracedPipeline::Compute { kernel: request.kernel.to_string() },
            })
        });
        Ok(kernel)
    }

    /// Creates, ahead of the first dispatch, the compute pipeline of each request (a scene's
    /// kernels, or those a usage log names). Returns how many kernel pipelines exist afterwards,
    /// or every request that failed.
    pub fn warm_up_kernels(&self, requests: &[KernelRequest]) -> Result<usize, Vec<RuntimeError>> {
        let errors: Vec<RuntimeError> = requests.iter().filter_map(|r| self.kernel(r).err()).collect();
        if errors.is_empty() { Ok(self.made().kernels.len()) } else { Err(errors) }
    }
}
