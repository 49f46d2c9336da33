//! Every emitted variant, WGSL and SPIR-V, loaded into a real device and turned into a render
//! pipeline with the manifest's layout (lavapipe in CI). Without an adapter the test says why and
//! passes, unless `KILN_REQUIRE_GPU=1` (set by CI) makes that a failure.

use kiln::manifest::{Manifest, PassManifest, ShaderStage, StageView};
use kiln::project::{Request, build_project};
use kiln::reflect::Resource;
use kiln::source::SourceStore;
use std::path::{Path, PathBuf};

fn layout_entry(binding: u32, visibility: &[ShaderStage], resource: &Resource) -> wgpu::BindGroupLayoutEntry {
    let mut stages = wgpu::ShaderStages::NONE;
    for stage in visibility {
        stages |= match stage {
            ShaderStage::Vertex => wgpu::ShaderStages::VERTEX,
            ShaderStage::Fragment => wgpu::ShaderStages::FRAGMENT,
            ShaderStage::Compute => panic!("the example project has no compute pass"),
        };
    }
    let ty = match resource {
        Resource::Uniform { size, .. } => wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: wgpu::BufferSize::new(u64::from(*size)),
        },
        Resource::Texture { .. } => wgpu::BindingType::Texture {
            sample_type: wgpu::TextureSampleType::Float { filterable: true },
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        },
        Resource::Sampler { .. } => wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
        other => panic!("the example project has no {other:?}"),
    };
    wgpu::BindGroupLayoutEntry { binding, visibility: stages, ty, count: None }
}

fn vertex_format(name: &str) -> wgpu::VertexFormat {
    match name {
        "float32" => wgpu::VertexFormat::Float32,
        "float32x2" => wgpu::VertexFormat::Float32x2,
        "float32x3" => wgpu::VertexFormat::Float32x3,
        "float32x4" => wgpu::VertexFormat::Float32x4,
        other => panic!("unexpected vertex format {other}"),
    }
}

enum Source {
    Wgsl,
    SpirV,
}

fn module(device: &wgpu::Device, output: &Path, stage: StageView, source: &Source) -> wgpu::ShaderModule {
    let source = match source {
        Source::Wgsl => {
            let file = stage.wgsl().expect("WGSL emitted");
            let text = String::from_utf8(file.read(output).expect("read")).expect("UTF-8");
            wgpu::ShaderSource::Wgsl(text.into())
        }
        Source::SpirV => {
            let file = stage.spirv().expect("SPIR-V emitted");
            let bytes = file.read(output).expect("read");
            assert_eq!(bytes.len() % 4, 0);
            let words: Vec<u32> =
                bytes.chunks_exact(4).map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]])).collect();
            wgpu::ShaderSource::SpirV(words.into())
        }
    };
    let label = format!("module {}", stage.index);
    device.create_shader_module(wgpu::ShaderModuleDescriptor { label: Some(&label), source })
}

fn pipelines(device: &wgpu::Device, output: &Path, pass: &PassManifest, source: &Source) -> usize {
    let groups = pass.layout.iter().map(|g| g.group + 1).max().unwrap_or(0);
    let layouts: Vec<wgpu::BindGroupLayout> = (0..groups)
        .map(|group| {
            let entries: Vec<wgpu::BindGroupLayoutEntry> = pass
                .layout
                .iter()
                .filter(|g| g.group == group)
                .flat_map(|g| &g.entries)
                .map(|e| layout_entry(e.binding, &e.visibility, &e.resource))
                .collect();
            device
                .create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor { label: None, entries: &entries })
        })
        .collect();
    let layout_refs: Vec<Option<&wgpu::BindGroupLayout>> = layouts.iter().map(Some).collect();
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: None,
        bind_group_layouts: &layout_refs,
        immediate_size: 0,
    });
    let mut count = 0;
    for variant in &pass.variants {
        let [vertex, fragment] = pass.variant_stages(variant);
        let (vertex, fragment) = (vertex.expect("vertex stage"), fragment.expect("fragment stage"));
        let mut offset = 0;
        let attributes: Vec<wgpu::VertexAttribute> = vertex
            .interface
            .inputs
            .iter()
            .map(|input| {
                let format = vertex_format(input.format.name());
                let attribute = wgpu::VertexAttribute { format, offset, shader_location: input.location };
                offset += format.size();
                attribute
            })
            .collect();
        let buffers = [Some(wgpu::VertexBufferLayout {
            array_stride: offset,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &attributes,
        })];
        let targets: Vec<Option<wgpu::ColorTargetState>> =
            fragment.interface.outputs.iter().map(|_| Some(wgpu::TextureFormat::Rgba8Unorm.into())).collect();
        let (vertex_module, fragment_module) =
            (module(device, output, vertex, source), module(device, output, fragment, source));
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let _pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(&variant.key),
            layout: Some(&pipeline_layout),
            vertex: wgpu::VertexState {
                module: &vertex_module,
                entry_point: Some(&vertex.interface.entry_point),
                compilation_options: Default::default(),
                buffers: &buffers,
            },
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: None,
            multisample: wgpu::MultisampleState::default(),
            fragment: Some(wgpu::FragmentState {
                module: &fragment_module,
                entry_point: Some(&fragment.interface.entry_point),
                compilation_options: Default::default(),
                targets: &targets,
            }),
            multiview_mask: None,
            cache: None,
        });
        if let Some(error) = pollster::block_on(scope.pop()) {
            panic!(
                "variant {:?} ({}): {error}",
                variant.keywords,
                if matches!(source, Source::Wgsl) { "WGSL" } else { "SPIR-V" }
            );
        }
        count += 1;
    }
    count
}

#[test]
fn every_variant_makes_a_render_pipeline() {
    let Some(kiln::accuracy::gpu::Gpu { device, adapter, .. }) = crate::support::gpu("the pipeline test")
    else {
        return;
    };
    let output = tempfile::tempdir().expect("temp dir");
    let mut store = SourceStore::new();
    let mode = Request { output: Some(output.path().to_path_buf()), ..Request::default() };
    let (result, diagnostics) =
        build_project(&mut store, &[PathBuf::from("fixtures/project")], &mode, &|_, _| {})
            .expect("project exists");
    assert!(diagnostics.is_empty() && result.diagnostics.is_empty());
    let manifest: Manifest =
        serde_json::from_slice(&std::fs::read(output.path().join("manifest.json")).expect("manifest"))
            .expect("parses");
    let mut made = 0;
    for pass in manifest.shaders.iter().flat_map(|s| &s.passes) {
        for source in [Source::Wgsl, Source::SpirV] {
            made += pipelines(&device, output.path(), pass, &source);
        }
    }
    assert_eq!(made, 2 * result.summary.variants);
    println!("{made} render pipelines created on {adapter}");
}

/// The README's test command on a machine whose only driver is OpenGL (Mesa's, without Vulkan):
/// a GPU test run on wgpu's GL backend skips, with the adapter and what it lacks named, instead
/// of failing on what the backend does not do. Run here as the test binary itself, on the GL
/// backend alone, with `KILN_REQUIRE_GPU` unset.
#[test]
fn a_gpu_test_on_an_adapter_below_webgpu_skips_and_names_it() {
    let gl = pollster::block_on(
        wgpu::Instance::new(wgpu::InstanceDescriptor {
            backends: wgpu::Backends::GL,
            ..wgpu::InstanceDescriptor::new_without_display_handle()
        })
        .enumerate_adapters(wgpu::Backends::GL),
    );
    let below: Vec<String> = gl
        .iter()
        .filter(|a| !a.get_downlevel_capabilities().is_webgpu_compliant())
        .map(|a| a.get_info().name)
        .collect();
    if below.is_empty() {
        assert!(
            std::env::var("KILN_REQUIRE_GPU").as_deref() != Ok("1"),
            "KILN_REQUIRE_GPU=1 but no OpenGL adapter below WebGPU (Mesa's EGL: libegl1, libgl1-mesa-dri)"
        );
        crate::support::skipped(
            "the GL adapter test: no OpenGL adapter below WebGPU here (install libegl1 libgl1-mesa-dri)",
        );
        return;
    }
    let test = "runtime::presets_blend_and_write_depth_as_their_properties_say";
    let run = std::process::Command::new(std::env::current_exe().expect("test binary"))
        .args(["--exact", test])
        .env("WGPU_BACKEND", "gl")
        .env_remove("KILN_REQUIRE_GPU")
        .current_dir(crate::support::root())
        .output()
        .expect("the test binary runs");
    let stdout = String::from_utf8_lossy(&run.stdout);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success() && stdout.contains("1 passed"), "{stdout}\n{stderr}");
    let skip = stderr
        .lines()
        .find(|l| l.starts_with("SKIPPED"))
        .unwrap_or_else(|| panic!("no skip line:\n{stderr}"));
    assert!(skip.contains("no adapter runs WebGPU in full") && skip.contains("(Gl) lacks"), "{skip}");
    for name in &below {
        assert!(skip.contains(name.as_str()), "{name} is not named: {skip}");
    }
    assert!(skip.contains("DEPTH_TEXTURE_AND_BUFFER_COPIES"), "{skip}");
}
