//! Runs the compiled library functions on an adapter: the program below is a compute shader
//! (a `.compute` file's text) that includes the library; kiln builds the variant each formulation
//! needs as a project's compute shader is built, and its kernels evaluate the hard cases (one
//! result per case) or time the formulations compute-bound (many evaluations per invocation,
//! kept in registers).

use super::{
    Case, CaseSet, Formulation, HARD_CASE_SETS, Row, TEST_SAMPLES, Timing, hard_case_set, reference,
    reference_lights, stats,
};
use crate::catalog::{CatalogInput, ListedVariant, catalog};
use crate::config::Settings;
use crate::orchestrate::{Run, Writes, build};
use crate::preprocess::{IncludeConfig, Includes};
use crate::source::{SourceStore, Span};
use rayon::prelude::*;
use std::collections::{BTreeMap, HashMap};
use wgpu::util::DeviceExt;

/// Where each resource of a kernel is bound: name to `(group, binding)`.
pub type Bindings = BTreeMap<String, (u32, u32)>;

/// A variant's kernels by name: each one's WGSL and bindings.
pub type Kernels = BTreeMap<String, (String, Bindings)>;

/// The harness's name, as a compute shader file.
const HARNESS_FILE: &str = "accuracy-gpu.compute";

/// The harness, a WGSL program in kiln's dialect, declaring what it needs as a pass would.
const HARNESS: &str = include_str!("harness.compute");

const EVALUATIONS: u32 = 256;

/// Invocations per timing dispatch: 65,536 fill a CPU rasteriser; a GPU gets the most one
/// dimension of workgroups allows (65,535 of 64), so that its times are not launch-bound.
/// `KILN_ACCURACY_INVOCATIONS` sets another count (docs/accuracy.md).
fn timing_invocations(device_type: wgpu::DeviceType) -> u32 {
    let asked = std::env::var("KILN_ACCURACY_INVOCATIONS").ok().and_then(|v| v.parse().ok());
    invocations_for(device_type, asked)
}

/// [`timing_invocations`] with the count asked for, if any (capped at what one dispatch holds).
fn invocations_for(device_type: wgpu::DeviceType, asked: Option<u32>) -> u32 {
    let most = 65_535 * 64;
    let sized = match device_type {
        wgpu::DeviceType::Cpu => 64 * 1024,
        _ => most,
    };
    asked.unwrap_or(sized).min(most)
}

/// The WGSL kiln emits for each kernel of the harness's variant with these keywords, and where
/// its resources are bound, by kernel name: the variant is built once, as a project's compute
/// shader is (listed, into a scratch output folder), and read back from the manifest and packs.
pub fn harness_kernels(keywords: &[&str]) -> Result<Kernels, String> {
    let mut store = SourceStore::new();
    let file = store.add(HARNESS_FILE, HARNESS);
    let mut includes = Includes::new(IncludeConfig::new(Vec::new()));
    let listed = ListedVariant {
        from_trace: false,
        shader: HARNESS_FILE.trim_end_matches(".compute").to_string(),
        pass: 0,
        keywords: keywords.iter().map(|k| k.to_string()).collect(),
        span: Span::new(file, 0..0),
    };
    let input =
        CatalogInput { shaders: vec![file], listed_variants: vec![listed], ..CatalogInput::default() };
    let (catalog, mut problems) = catalog(&mut store, &mut includes, &input);
    let scratch = tempfile_folder()?;
    let settings = Settings {
        backends: vec![crate::config::Backend::Wgsl],
        ..Settings::one_off(scratch.clone(), scratch.clone())
    };
    let run = Run { writes: Writes::Output, ..Run::default() };
    let result = build(&store, &includes, &catalog, &settings, &run, &problems, &|_, _| {});
    problems.extend(result.diagnostics);
    let read = || -> Result<Kernels, String> {
        if crate::diagnostics::has_errors(&problems) {
            return Err(crate::diagnostics::render_plain(&store, &problems));
        }
        let manifest = result.manifest.as_ref().ok_or("the harness built nothing")?;
        let pass = manifest.passes().next().ok_or("the harness built no pass")?;
        let variant = pass.variants.first().ok_or("the harness built no variant")?;
        let mut kernels = BTreeMap::new();
        for (kernel, module) in pass.kernels.iter().zip(&variant.kernels) {
            let stage = module.map(|m| pass.stage(m)).ok_or(format!("`{kernel}` was not built"))?;
            let bytes = stage.wgsl().ok_or("no WGSL")?.read(&scratch).map_err(|e| e.to_string())?;
            let wgsl = String::from_utf8(bytes).map_err(|e| e.to_string())?;
            let used = |g: u32, b: u32| stage.interface.bindings.contains(&[g, b]);
            let bound = pass
                .layout
                .iter()
                .flat_map(|group| group.entries.iter().map(move |e| (group.group, e)))
                .filter(|(group, e)| used(*group, e.binding))
                .map(|(group, e)| (e.name.clone(), (group, e.binding)))
                .collect();
            kernels.insert(kernel.clone(), (wgsl, bound));
        }
        Ok(kernels)
    };
    let found = read();
    let _ = std::fs::remove_dir_all(&scratch);
    found
}

/// A new empty folder under the system's temporary folder, for one harness build.
fn tempfile_folder() -> Result<std::path::PathBuf, String> {
    static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let folder = std::env::temp_dir().join(format!("kiln-accuracy-{}-{n}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    std::fs::create_dir_all(&folder).map_err(|e| format!("{}: {e}", folder.display()))?;
    Ok(folder)
}

fn case_bytes(cases: &[Case]) -> Vec<u8> {
    let mut bytes = Vec::with_capacity(cases.len() * 96);
    for c in cases {
        let s = &c.surface;
        let v4 = |v: [f64; 3], w: f64| [v[0], v[1], v[2], w];
        let values = [
            v4(s.normal, 0.0),
            v4(s.view_direction, 0.0),
            v4(c.light.direction, 0.0),
            v4(c.light.color, 0.0),
            v4(s.color, s.alpha),
            [s.metallic, s.smoothness, if c.premultiply { 1.0 } else { 0.0 }, 0.0],
        ];
        for value in values.iter().flatten() {
            bytes.extend((*value as f32).to_le_bytes());
        }
    }
    bytes
}

/// `_CustomLight`: count at 0, colours at 16, directions at 80, 144 bytes.
fn light_bytes(lights: &[crate::reference::Light], count: i32) -> Vec<u8> {
    let mut bytes = vec![0u8; 144];
    bytes[0..4].copy_from_slice(&count.to_le_bytes());
    for (i, light) in lights.iter().take(4).enumerate() {
        for k in 0..3 {
            let at = 16 + i * 16 + k * 4;
            bytes[at..at + 4].copy_from_slice(&(light.color[k] as f32).to_le_bytes());
            let at = 80 + i * 16 + k * 4;
            bytes[at..at + 4].copy_from_slice(&(light.direction[k] as f32).to_le_bytes());
        }
    }
    bytes
}

/// Cases per dispatch: 96 bytes each stays below every adapter's 128 MiB storage binding.
const CASES_PER_DISPATCH: usize = 1 << 20;

/// The harness on a device: its kernels, dispatches and timings.
impl Gpu {
    fn pipeline(&self, keywords: &[&str], entry: &str) -> Result<(wgpu::ComputePipeline, Bindings), String> {
        let variant: Vec<String> = keywords.iter().map(|k| k.to_string()).collect();
        let mut built = self.kernels.lock().map_err(|_| "the harness's kernels are poisoned")?;
        if !built.contains_key(&variant) {
            built.insert(variant.clone(), harness_kernels(keywords)?);
        }
        let (wgsl, bound) =
            built[&variant].get(entry).cloned().ok_or(format!("the harness has no kernel `{entry}`"))?;
        drop(built);
        let module = self.device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(entry),
            source: wgpu::ShaderSource::Wgsl(wgsl.into()),
        });
        let pipeline = self.device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(entry),
            layout: None,
            module: &module,
            entry_point: Some(entry),
            compilation_options: Default::default(),
            cache: None,
        });
        Ok((pipeline, bound))
    }

    /// Runs `pipeline` over `invocations`, returning the results and the GPU time in ns (from
    /// timestamp queries when the adapter has them, else from the CPU around the submission).
    fn dispatch(
        &self,
        pipeline: &(wgpu::ComputePipeline, Bindings),
        cases: &[Case],
        light: Option<&[u8]>,
        invocations: u32,
    ) -> (Vec<[f32; 3]>, f64) {
        let device = &self.device;
        let input = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("cases"),
            contents: &case_bytes(cases),
            usage: wgpu::BufferUsages::STORAGE,
        });
        let size = u64::from(invocations) * 16;
        let output = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("results"),
            size,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let readback = device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let (pipeline, bound) = pipeline;
        let light = light.map(|bytes| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("_CustomLight"),
                contents: bytes,
                usage: wgpu::BufferUsages::UNIFORM,
            })
        });
        // Each resource by name, where the build bound it; one bind group per group.
        let mut groups: std::collections::BTreeMap<u32, Vec<wgpu::BindGroupEntry>> = Default::default();
        for (name, &(group, binding)) in bound {
            let buffer = match name.as_str() {
                "cases" => Some(&input),
                "results" => Some(&output),
                "_CustomLight" => light.as_ref(),
                _ => None,
            };
            if let Some(buffer) = buffer {
                groups
                    .entry(group)
                    .or_default()
                    .push(wgpu::BindGroupEntry { binding, resource: buffer.as_entire_binding() });
            }
        }
        let bind_groups: Vec<(u32, wgpu::BindGroup)> = groups
            .into_iter()
            .map(|(group, entries)| {
                let layout = pipeline.get_bind_group_layout(group);
                (
                    group,
                    device.create_bind_group(&wgpu::BindGroupDescriptor {
                        label: None,
                        layout: &layout,
                        entries: &entries,
                    }),
                )
            })
            .collect();
        let queries = self.timestamps.then(|| {
            let set = device.create_query_set(&wgpu::QuerySetDescriptor {
                label: None,
                ty: wgpu::QueryType::Timestamp,
                count: 2,
            });
            let resolve = device.create_buffer(&wgpu::BufferDescriptor {
                label: None,
                size: 16,
                usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            });
            let read = device.create_buffer(&wgpu::BufferDescriptor {
                label: None,
                size: 16,
                usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
                mapped_at_creation: false,
            });
            (set, resolve, read)
        });
        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: None,
                timestamp_writes: queries.as_ref().map(|(set, _, _)| wgpu::ComputePassTimestampWrites {
                    query_set: set,
                    beginning_of_pass_write_index: Some(0),
                    end_of_pass_write_index: Some(1),
                }),
            });
            pass.set_pipeline(pipeline);
            for (group, bind_group) in &bind_groups {
                pass.set_bind_group(*group, bind_group, &[]);
            }
            pass.dispatch_workgroups(invocations.div_ceil(64), 1, 1);
        }
        encoder.copy_buffer_to_buffer(&output, 0, &readback, 0, size);
        if let Some((set, resolve, read)) = &queries {
            encoder.resolve_query_set(set, 0..2, resolve, 0);
            encoder.copy_buffer_to_buffer(resolve, 0, read, 0, 16);
        }
        let started = std::time::Instant::now();
        self.queue.submit([encoder.finish()]);
        readback.map_async(wgpu::MapMode::Read, .., |_| {});
        if let Some((_, _, read)) = &queries {
            read.map_async(wgpu::MapMode::Read, .., |_| {});
        }
        let _ = device.poll(wgpu::PollType::wait_indefinitely());
        let wall = started.elapsed().as_nanos() as f64;
        let nanoseconds = match &queries {
            Some((_, _, read)) => match read.get_mapped_range(..) {
                Ok(bytes) => {
                    let stamp =
                        |at: usize| u64::from_le_bytes(bytes[at..at + 8].try_into().unwrap_or_default());
                    (stamp(8).saturating_sub(stamp(0))) as f64 * f64::from(self.queue.get_timestamp_period())
                }
                Err(_) => wall,
            },
            None => wall,
        };
        let results = match readback.get_mapped_range(..) {
            Ok(bytes) => bytes
                .chunks_exact(16)
                .map(|c| [0, 4, 8].map(|o| f32::from_le_bytes(c[o..o + 4].try_into().unwrap_or_default())))
                .collect(),
            Err(_) => Vec::new(),
        };
        (results, nanoseconds)
    }

    /// Median time per evaluation of a timing kernel, over several dispatches.
    fn time(
        &self,
        keywords: &[&str],
        entry: &str,
        cases: &[Case],
        light: Option<&[u8]>,
    ) -> Result<f64, String> {
        let pipeline = self.pipeline(keywords, entry)?;
        let invocations = timing_invocations(self.device_type);
        // Warm-up for at least 0.2 s, so that a GPU's clocks have risen from idle.
        let warming = std::time::Instant::now();
        while warming.elapsed().as_millis() < 200 {
            let _ = self.dispatch(&pipeline, cases, light, invocations);
        }
        let mut times: Vec<f64> =
            (0..7).map(|_| self.dispatch(&pipeline, cases, light, invocations).1).collect();
        times.sort_by(f64::total_cmp);
        Ok(times[3] / (f64::from(invocations) * f64::from(EVALUATIONS)))
    }

    /// Results of a kernel over any number of cases, in dispatches of at most
    /// [`CASES_PER_DISPATCH`].
    fn evaluate(
        &self,
        pipeline: &(wgpu::ComputePipeline, Bindings),
        cases: &[Case],
        light: Option<&[u8]>,
    ) -> Vec<[f32; 3]> {
        cases
            .chunks(CASES_PER_DISPATCH)
            .flat_map(|chunk| self.dispatch(pipeline, chunk, light, chunk.len() as u32).0)
            .collect()
    }

    /// One formulation's results on one set, with their references, for the [`super::counted`]
    /// cases.
    fn measure(
        &self,
        formulation: Formulation,
        one: &(wgpu::ComputePipeline, Bindings),
        all: &(wgpu::ComputePipeline, Bindings),
        set: &CaseSet,
    ) -> (Vec<[f32; 3]>, Vec<[f64; 3]>) {
        let Some((lights, counts)) = &set.lights else {
            let results = self.evaluate(one, &set.cases, None);
            return counted_pairs(&set.cases, results, |case| reference(case, formulation));
        };
        // One dispatch per light count: the count is a uniform.
        let mut measured = (Vec::new(), Vec::new());
        for count in counts.iter().copied().collect::<std::collections::BTreeSet<i32>>() {
            let cases: Vec<Case> =
                set.cases.iter().zip(counts).filter(|(_, c)| **c == count).map(|(case, _)| *case).collect();
            let results = self.evaluate(all, &cases, Some(&light_bytes(lights, count)));
            let (results, references) =
                counted_pairs(&cases, results, |case| reference_lights(case, lights, count, formulation));
            measured.0.extend(results);
            measured.1.extend(references);
        }
        measured
    }
}

/// A device for the harness, with what its adapter offers.
pub struct Gpu {
    /// The device.
    pub device: wgpu::Device,
    /// Its queue.
    pub queue: wgpu::Queue,
    /// The adapter's name, type and backend.
    pub adapter: String,
    /// The adapter's own description (vendor, device, driver, backend).
    pub info: wgpu::AdapterInfo,
    /// Its type: a CPU rasteriser gets smaller timing dispatches than a GPU.
    pub device_type: wgpu::DeviceType,
    /// Whether the device has timestamp queries.
    pub timestamps: bool,
    /// `shader-f16`: the f16 formulation runs.
    pub f16: bool,
    /// The harness's kernels for each variant (formulation keywords), built once per device: the
    /// error runs, the timings and the search share them.
    kernels: std::sync::Mutex<HashMap<Vec<String>, Kernels>>,
}

/// A device on the adapter [`crate::runtime::adapter`] picks from the backends `WGPU_BACKEND` names (all by
/// default), with timestamp queries and `shader-f16` where the adapter has them.
pub fn device() -> Result<Gpu, String> {
    device_on(wgpu::Backends::from_env().unwrap_or_default())
}

/// [`device`] on these backends only.
pub fn device_on(backends: wgpu::Backends) -> Result<Gpu, String> {
    let adapter = crate::runtime::adapter(backends).map_err(|e| e.to_string())?;
    device_for(adapter, wgpu::Limits::default())
}

/// A device on wgpu's OpenGL back end (Mesa's llvmpipe through EGL in CI), with the limits the
/// adapter has: [`crate::runtime::adapter`] passes GL by, as below WebGPU, but what kiln writes
/// must still lay out and compute the same there (docs/backends.md).
pub fn gl_device() -> Result<Gpu, String> {
    let adapter = crate::runtime::gl_adapter()
        .map_err(|e| format!("{e}: no OpenGL adapter (Debian: libegl1 libgl1-mesa-dri)"))?;
    let limits = adapter.limits();
    device_for(adapter, limits)
}

fn device_for(adapter: wgpu::Adapter, limits: wgpu::Limits) -> Result<Gpu, String> {
    let info = adapter.get_info();
    let wanted = wgpu::Features::TIMESTAMP_QUERY
        | wgpu::Features::SHADER_F16
        | wgpu::Features::PIPELINE_CACHE
        | wgpu::Features::IMMEDIATES;
    let required_features = adapter.features() & wanted;
    // An ubershader's keywords (runtime::UBERSHADER_IMMEDIATE_SIZE), where the adapter has them.
    let immediates = adapter.limits().max_immediate_size.min(8);
    let required_limits = wgpu::Limits { max_immediate_size: immediates, ..limits };
    let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        required_features,
        required_limits,
        ..Default::default()
    }))
    .map_err(|e| format!("no device: {e}"))?;
    Ok(Gpu {
        device,
        queue,
        adapter: format!("{} ({:?}, {:?})", info.name, info.device_type, info.backend),
        device_type: info.device_type,
        timestamps: required_features.contains(wgpu::Features::TIMESTAMP_QUERY),
        f16: required_features.contains(wgpu::Features::SHADER_F16),
        kernels: Default::default(),
        info,
    })
}

/// The results of the [`super::counted`] cases, each with its reference.
fn counted_pairs(
    cases: &[Case],
    results: Vec<[f32; 3]>,
    reference: impl Fn(&Case) -> [f64; 3] + Sync,
) -> (Vec<[f32; 3]>, Vec<[f64; 3]>) {
    cases
        .par_iter()
        .zip(results)
        .filter(|(case, _)| super::counted(case))
        .map(|(case, result)| (result, reference(case)))
        .unzip()
}

/// The formulations the adapter runs (`stable f16` needs `shader-f16`).
fn formulations(gpu: &Gpu) -> Vec<Formulation> {
    Formulation::ALL.into_iter().filter(|f| gpu.f16 || !f.needs_f16()).collect()
}

/// `formulations` on every hard-case set of `samples` cases: one row per formulation and set, by
/// formulation, then set.
pub fn error_rows(gpu: &Gpu, formulations: &[Formulation], samples: usize) -> Result<Vec<Row>, String> {
    let pipelines = formulations
        .iter()
        .map(|f| Ok((gpu.pipeline(f.keywords(), "OneLight")?, gpu.pipeline(f.keywords(), "AllLights")?)))
        .collect::<Result<Vec<_>, String>>()?;
    let mut rows = Vec::new();
    // One set at a time: a million cases of each is a few hundred megabytes.
    for index in 0..HARD_CASE_SETS {
        let set = hard_case_set(index, samples);
        for (&formulation, (one, all)) in formulations.iter().zip(&pipelines) {
            let (results, references) = gpu.measure(formulation, one, all, &set);
            rows.push(Row {
                formulation: formulation.name(),
                set: set.name.clone(),
                stats: stats(&results, &references),
            });
        }
    }
    let order = |name: &str| formulations.iter().position(|f| f.name() == name);
    rows.sort_by_key(|row| order(row.formulation));
    Ok(rows)
}

/// Every formulation on every hard-case set of `samples` cases, and the timings. The last value
/// says how the times were taken.
pub fn run(gpu: &Gpu, samples: usize) -> Result<(Vec<Row>, Vec<Timing>, String), String> {
    let formulations = formulations(gpu);
    // Timed first: after a million cases per set (hundreds of megabytes moved, the CPU busy with
    // references) the H100 timed the same kernels 5x slower.
    let sets: Vec<CaseSet> = (0..HARD_CASE_SETS).map(|index| hard_case_set(index, TEST_SAMPLES)).collect();
    // Timing on ordinary inputs (the metallic set: random directions, both metal kinds).
    let ordinary = &sets.iter().find(|s| s.name.starts_with("metallic")).ok_or("no ordinary set")?.cases;
    let light_set = sets.iter().find_map(|s| s.lights.as_ref()).ok_or("no light set")?;
    let one_light = light_bytes(&light_set.0, 1);
    let four_lights = light_bytes(&light_set.0, 4);
    let mut timings = Vec::new();
    for &formulation in &formulations {
        timings.push(Timing {
            what: format!("{}: one light (GetLightingForLight)", formulation.name()),
            nanoseconds_per_evaluation: gpu.time(formulation.keywords(), "TimeOneLight", ordinary, None)?,
        });
    }
    for (what, keywords, bytes) in [
        ("stable: GetLighting loop, 4 lights", vec!["_SPECULAR_STABLE"], &four_lights),
        ("stable: GetLighting loop, 1 light", vec!["_SPECULAR_STABLE"], &one_light),
        (
            "stable: _SINGLE_DIRECTIONAL_LIGHT, 1 light",
            vec!["_SPECULAR_STABLE", "_SINGLE_DIRECTIONAL_LIGHT"],
            &one_light,
        ),
    ] {
        timings.push(Timing {
            what: what.to_string(),
            nanoseconds_per_evaluation: gpu.time(&keywords, "TimeAllLights", ordinary, Some(bytes))?,
        });
    }
    let f16 = match gpu.f16 {
        true => "",
        false => "The adapter has no shader-f16: the f16 form was not run.\n",
    };
    let method = format!(
        "{f16}Times: {} over {} invocations x {EVALUATIONS} evaluations each (inputs derived in registers, one write per invocation), median of 7 dispatches.",
        if gpu.timestamps {
            "GPU timestamp queries around the compute pass"
        } else {
            "CPU wall time around submit and wait (no timestamp queries on this adapter)"
        },
        timing_invocations(gpu.device_type)
    );
    let rows = error_rows(gpu, &formulations, samples)?;
    Ok((rows, timings, method))
}

/// [`super::search`] for every formulation the adapter runs: the worst input found for each.
pub fn search(gpu: &Gpu) -> Result<Vec<(Formulation, super::Found)>, String> {
    let mut found = Vec::new();
    for formulation in formulations(gpu) {
        let one = gpu.pipeline(formulation.keywords(), "OneLight")?;
        let mut evaluate = |cases: &[Case]| gpu.dispatch(&one, cases, None, cases.len() as u32).0;
        found.push((formulation, super::search(formulation, &mut evaluate)));
    }
    Ok(found)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_gpu_gets_the_largest_dispatch_and_a_cpu_rasteriser_a_small_one() {
        assert_eq!(invocations_for(wgpu::DeviceType::Cpu, None), 65_536);
        for gpu in
            [wgpu::DeviceType::DiscreteGpu, wgpu::DeviceType::IntegratedGpu, wgpu::DeviceType::VirtualGpu]
        {
            assert_eq!(invocations_for(gpu, None), 4_194_240);
        }
        assert_eq!(invocations_for(wgpu::DeviceType::Cpu, Some(1_000)), 1_000);
        assert_eq!(invocations_for(wgpu::DeviceType::DiscreteGpu, Some(u32::MAX)), 4_194_240, "capped");
    }
}
