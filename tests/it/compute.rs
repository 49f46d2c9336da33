//! Compute shaders (`fixtures/compute`: a `.compute` file with two kernels and a `multi_compile`
//! set): built as a pass of kernels, reflected, and each kernel variant dispatched on the GPU
//! (lavapipe in CI) through `kiln::runtime`, its read-back output checked against the same
//! computation on the CPU.

use crate::support::{built_fixture, gpu, root};
use kiln::runtime::{KernelRequest, Runtime};
use wgpu::util::DeviceExt;

const SHADER: &str = "Scale";

#[test]
fn kernels_are_built_and_reflected_per_variant() {
    let output = built_fixture("compute");
    let manifest = crate::support::verified_manifest(output.path());
    let pass = &manifest.shaders.iter().find(|s| s.name == SHADER).expect("built").passes[0];
    assert_eq!(pass.kernels, ["Double", "AddOffset", "Reverse"]);
    assert_eq!(pass.variants.len(), 2, "the multi_compile set's two options");
    for variant in &pass.variants {
        assert!(variant.vertex.is_none() && variant.fragment.is_none());
        let sizes: Vec<_> = variant
            .kernels
            .iter()
            .map(|m| {
                let stage = pass.stage(m.expect("built"));
                assert_eq!(stage.interface.stage, kiln::manifest::ShaderStage::Compute);
                (stage.interface.entry_point.clone(), stage.interface.workgroup_size)
            })
            .collect();
        assert_eq!(
            sizes,
            [
                ("Double".into(), Some([64, 1, 1])),
                ("AddOffset".into(), Some([32, 2, 1])),
                ("Reverse".into(), Some([0, 1, 1]))
            ]
        );
        // Reverse's size is the `block` override's; its tile is 64 floats of workgroup memory.
        let reverse = pass.stage(variant.kernels[2].expect("built"));
        assert_eq!(reverse.interface.workgroup_size_overrides, [Some("block".to_string()), None, None]);
        assert_eq!(reverse.interface.workgroup_memory, 256);
    }
    // One bind group shared by both kernels of every variant, visible to compute.
    let entries: Vec<_> = pass.layout.iter().flat_map(|g| &g.entries).collect();
    assert!(entries.iter().all(|e| e.visibility == [kiln::manifest::ShaderStage::Compute]), "{entries:?}");
    assert_eq!(entries.iter().map(|e| e.name.as_str()).collect::<Vec<_>>(), ["params", "values"]);
}

/// Runs a kernel of a variant over `input` with `offset`; returns the numbers read back.
fn dispatch(
    runtime: &Runtime,
    gpu: &kiln::accuracy::gpu::Gpu,
    kernel: &str,
    keywords: &[&str],
    input: &[f32],
    offset: f32,
) -> Vec<f32> {
    let variant = runtime.variant(SHADER, 0, keywords).expect("built");
    dispatch_with(runtime, gpu, &KernelRequest { variant, kernel, overrides: &[] }, input, offset)
}

/// [`dispatch`] of any request (override values too).
fn dispatch_with(
    runtime: &Runtime,
    gpu: &kiln::accuracy::gpu::Gpu,
    request: &KernelRequest,
    input: &[f32],
    offset: f32,
) -> Vec<f32> {
    let device = &gpu.device;
    let kernel = request.kernel;
    let kernel_pipeline = runtime.kernel(request).expect("pipeline");
    let layout = runtime.pass_layout(request.variant.pass()).expect("layout");
    let pass = runtime.library().pass_of(request.variant.pass()).expect("pass").clone();
    let mut params = offset.to_le_bytes().to_vec();
    params.extend((input.len() as u32).to_le_bytes());
    let uniform = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: None,
        contents: &params,
        usage: wgpu::BufferUsages::UNIFORM,
    });
    let bytes: Vec<u8> = input.iter().flat_map(|v| v.to_le_bytes()).collect();
    let storage = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: None,
        contents: &bytes,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
    });
    let read = crate::support::readback(device, bytes.len() as u64);
    // Bindings by name, where the manifest's layout put them.
    let group = &pass.layout[0];
    let entries: Vec<wgpu::BindGroupEntry> = group
        .entries
        .iter()
        .map(|e| wgpu::BindGroupEntry {
            binding: e.binding,
            resource: if e.name == "params" {
                uniform.as_entire_binding()
            } else {
                storage.as_entire_binding()
            },
        })
        .collect();
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &layout.groups[group.group as usize],
        entries: &entries,
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut compute = encoder.begin_compute_pass(&Default::default());
        compute.set_pipeline(&kernel_pipeline.pipeline);
        compute.set_bind_group(group.group, &bind_group, &[]);
        // AddOffset's invocations cover two numbers along y.
        let size = if kernel == "AddOffset" {
            [input.len().div_ceil(2) as u32, 2, 1]
        } else {
            [input.len() as u32, 1, 1]
        };
        let [x, y, z] = kernel_pipeline.workgroups(size);
        compute.dispatch_workgroups(x, y, z);
    }
    encoder.copy_buffer_to_buffer(&storage, 0, &read, 0, bytes.len() as u64);
    gpu.queue.submit([encoder.finish()]);
    read.map_async(wgpu::MapMode::Read, .., |result| result.expect("maps"));
    device.poll(wgpu::PollType::wait_indefinitely()).expect("poll");
    let mapped = read.get_mapped_range(..).expect("mapped");
    mapped.chunks_exact(4).map(|c| f32::from_le_bytes(c.try_into().expect("4 bytes"))).collect()
}

/// `Double` and `AddOffset` of both variants over 1,000 numbers (more than one workgroup, not a
/// multiple of its size), each against the CPU; the numbers and the offset.
fn double_and_add_offset_compute_what_the_cpu_computes(
    runtime: &Runtime,
    gpu: &kiln::accuracy::gpu::Gpu,
) -> (Vec<f32>, f32) {
    let input: Vec<f32> = (0..1000).map(|i| (i as f32) * 0.25 - 100.0).collect();
    let offset = 3.5;
    for keywords in [&[][..], &["_SQUARE"][..]] {
        let shaped = |x: f32| if keywords.is_empty() { x } else { x * x };
        for (kernel, cpu) in [
            ("Double", &(|x: f32| shaped(x) * 2.0) as &dyn Fn(f32) -> f32),
            ("AddOffset", &|x: f32| shaped(x) + offset),
        ] {
            let gpu_values = dispatch(runtime, gpu, kernel, keywords, &input, offset);
            let expected: Vec<f32> = input.iter().map(|&x| cpu(x)).collect();
            assert_eq!(gpu_values, expected, "{kernel} {keywords:?}");
        }
    }
    (input, offset)
}

#[test]
fn every_kernel_variant_computes_what_the_cpu_computes() {
    let Some(gpu) = gpu("the compute kernels test") else { return };
    let output = built_fixture("compute");
    let runtime = Runtime::open(&gpu.device, output.path()).expect("opens");
    // Warmed up ahead of the dispatches: every kernel of both variants, created once.
    let requests: Vec<KernelRequest> = [&[][..], &["_SQUARE"][..]]
        .into_iter()
        .flat_map(|keywords| {
            let variant = runtime.variant(SHADER, 0, keywords).expect("built");
            ["Double", "AddOffset"].map(|kernel| KernelRequest { variant, kernel, overrides: &[] })
        })
        .collect();
    assert_eq!(runtime.warm_up_kernels(&requests).expect("warms up"), 4);
    // A kernel asked for again is found by its handle, allocating nothing.
    let again = crate::support::allocations_in(|| drop(runtime.kernel(&requests[3]).expect("warm")));
    assert_eq!(again, 0, "a kernel asked for again allocates");
    let (input, offset) = double_and_add_offset_compute_what_the_cpu_computes(&runtime, &gpu);
    // The keyword changes the result: squaring is visible.
    assert_ne!(
        dispatch(&runtime, &gpu, "Double", &[], &input, offset),
        dispatch(&runtime, &gpu, "Double", &["_SQUARE"], &input, offset)
    );
    // Reverse, in blocks of the pipeline's `block` (its workgroup size and the tile it uses).
    let numbers: Vec<f32> = (0..32).map(|i| i as f32).collect();
    for block in [8u32, 16] {
        let overrides = [("block", f64::from(block))];
        let variant = runtime.variant(SHADER, 0, &[]).expect("built");
        let request = KernelRequest { variant, kernel: "Reverse", overrides: &overrides };
        assert_eq!(runtime.kernel(&request).expect("pipeline").workgroup_size, [block, 1, 1]);
        let reversed = dispatch_with(&runtime, &gpu, &request, &numbers, 0.0);
        let expected: Vec<f32> =
            numbers.chunks(block as usize).flat_map(|c| c.iter().rev().copied()).collect();
        assert_eq!(reversed, expected, "block {block}");
    }
    // One pipeline per kernel variant and override value, each created once.
    assert_eq!(runtime.pipelines_created(), 6);
    let variant = runtime.variant(SHADER, 0, &[]).expect("built");
    let unknown = runtime.kernel(&KernelRequest { variant, kernel: "Dubble", overrides: &[] });
    assert_eq!(
        unknown.expect_err("no such kernel").to_string(),
        "`Scale` has no kernel `Dubble` (did you mean `Double`?)"
    );
}

#[test]
fn mistakes_in_kernels_and_listed_variants_are_reported_where_they_are_written() {
    let mut store = kiln::source::SourceStore::new();
    let mode = kiln::config::Request { write: false, threads: Some(1), ..Default::default() };
    let path = std::path::PathBuf::from("fixtures/bad/compute");
    let (result, mut diagnostics) =
        kiln::project::build_project(&mut store, &[path], &mode, &|_, _| {}).expect("exists");
    diagnostics.extend(result.diagnostics);
    assert!(kiln::diagnostics::has_errors(&diagnostics));
    let codes: Vec<&str> = diagnostics.iter().map(|d| d.code).collect();
    assert_eq!(
        codes,
        ["K0533", "K0418", "K0418", "K0401", "K0403", "K0310", "K0403"],
        "an unlisted keyword, a default and a workgroup size naga cannot write, no workgroup size, a vertex entry point, \
         an `#error` in a text two kernels share (reported once, as before it was preprocessed once), a missing kernel"
    );
    expect_test::expect_file![root().join("fixtures/bad/compute/kiln.stderr")]
        .assert_eq(&kiln::diagnostics::render_plain(&store, &diagnostics));
}

#[test]
fn a_missing_kernel_variant_is_logged_built_from_the_log_and_an_edited_kernel_reloads() {
    let Some(gpu) = gpu("the compute usage and reload test") else { return };
    let dir = tempfile::tempdir().expect("temp dir");
    // The project listing only the variant without `_SQUARE`.
    let project = dir.path().join("project");
    std::fs::create_dir(&project).expect("mkdir");
    let source = std::fs::read_to_string(root().join("fixtures/compute/Scale.compute")).expect("read");
    std::fs::write(project.join("Scale.compute"), &source).expect("write");
    std::fs::write(project.join("kiln.toml"), "[compute.Scale]\nvariants = [[]]\n").expect("write");
    let output = dir.path().join("out");
    let build = |logs: &[&std::path::Path]| {
        let mut args =
            vec!["build", project.to_str().expect("utf-8"), "--output", output.to_str().expect("utf-8")];
        for log in logs {
            args.extend(["--variants-from", log.to_str().expect("utf-8")]);
        }
        let run = crate::support::kiln(&args);
        assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
    };
    build(&[]);
    let mut runtime = Runtime::open(&gpu.device, &output).expect("opens");
    let missing = dir.path().join("missing.jsonl");
    runtime.log_usage(kiln::runtime::UsageLog::new(None, Some(&missing)).expect("log"));
    let error = runtime.variant(SHADER, 0, &["_SQUARE"]).expect_err("not built");
    assert!(matches!(error, kiln::runtime::RuntimeError::MissingVariant { .. }), "{error}");
    assert_eq!(
        std::fs::read_to_string(&missing).expect("missing log"),
        "{\"keywords\":[\"_SQUARE\"],\"pass\":0,\"shader\":\"Scale\"}\n"
    );
    // Built from the log, reloaded, it runs.
    build(&[&missing]);
    assert!(matches!(runtime.reload(), Ok(kiln::runtime::Reload::Swapped { .. })));
    let input = [1.0, 2.0, 3.0];
    assert_eq!(dispatch(&runtime, &gpu, "Double", &["_SQUARE"], &input, 0.0), [2.0, 8.0, 18.0]);
    // An edited kernel: rebuilt, reloaded, its new code runs.
    std::fs::write(project.join("Scale.compute"), source.replace("* 2.0;", "* 3.0;")).expect("edit");
    build(&[&missing]);
    assert!(matches!(runtime.reload(), Ok(kiln::runtime::Reload::Swapped { .. })));
    assert_eq!(dispatch(&runtime, &gpu, "Double", &["_SQUARE"], &input, 0.0), [3.0, 12.0, 27.0]);
    assert_eq!(dispatch(&runtime, &gpu, "Double", &[], &input, 0.0), [3.0, 6.0, 9.0]);
}

#[test]
fn the_generated_module_finds_kernels_and_their_workgroup_sizes() {
    let out = tempfile::tempdir().expect("temp dir");
    let output = kiln::Build::new("fixtures/compute").out_dir(out.path()).execute().expect("builds");
    let module = std::fs::read_to_string(&output.module).expect("generated");
    for line in [
        r#"kernels: &["Double", "AddOffset", "Reverse"],"#,
        "pub const DOUBLE_WORKGROUP_SIZE: [u32; 3] = [64, 1, 1];",
        "pub const ADD_OFFSET_WORKGROUP_SIZE: [u32; 3] = [32, 2, 1];",
    ] {
        assert!(module.contains(line), "the generated module has `{line}`");
    }
    // Compiled and run by cargo: the strict lookup, each kernel's module and size.
    crate::support::test_generated_module(
        out.path(),
        "pub mod shaders;\n\
         #[test]\n\
         fn kernels_of_each_variant() {\n\
         \x20   use shaders::scale::PASS_0;\n\
         \x20   for keywords in [&[][..], &[\"_SQUARE\"][..]] {\n\
         \x20       let variant = PASS_0.variant(keywords).expect(\"built\");\n\
         \x20       let double = variant.kernel(shaders::scale::kernels::DOUBLE).expect(\"a kernel\");\n\
         \x20       assert_eq!(double.entry_point, \"Double\");\n\
         \x20       assert_eq!(double.workgroup_size, shaders::scale::DOUBLE_WORKGROUP_SIZE);\n\
         \x20       assert!(double.wgsl.contains(\"@compute @workgroup_size(64, 1, 1)\"));\n\
         \x20       assert_eq!(variant.kernel(\"AddOffset\").expect(\"a kernel\").workgroup_size, [32, 2, 1]);\n\
         \x20       assert!(variant.kernel(\"Dubble\").is_none());\n\
         \x20   }\n\
         }\n",
    );
}

/// `fixtures/storage`: a kernel reading a `read` storage texture and writing a `write` one. The
/// manifest says each access as WGSL does, and the run time's layout, built from it, is one wgpu
/// accepts for the pipeline (a read-write `rgba8unorm` layout is refused) and that computes on
/// the GPU what the CPU does.
#[test]
fn a_kernel_reads_one_storage_texture_and_writes_another() {
    use kiln::manifest::{Resource, StorageAccess, TexelFormat, ViewDimension};
    let output = built_fixture("storage");
    let manifest = crate::support::verified_manifest(output.path());
    let pass = &manifest.shaders.iter().find(|s| s.name == "Texels").expect("built").passes[0];
    let resources: Vec<(&str, &Resource)> =
        pass.layout.iter().flat_map(|g| &g.entries).map(|e| (e.name.as_str(), &e.resource)).collect();
    let storage = |format, access| Resource::StorageTexture { dimension: ViewDimension::D2, format, access };
    assert_eq!(
        resources,
        [
            ("source", &storage(TexelFormat::R32Float, StorageAccess::Read)),
            ("destination", &storage(TexelFormat::Rgba8Unorm, StorageAccess::Write))
        ]
    );
    // As the JSON spells it: WGSL's access modes.
    let json = std::fs::read_to_string(output.path().join("manifest.json")).expect("manifest");
    assert!(json.contains(r#""access":"read""#) && json.contains(r#""access":"write""#), "{json}");

    let Some(gpu) = gpu("the storage texture test") else { return };
    let device = &gpu.device;
    let runtime = Runtime::open(device, output.path()).expect("opens");
    let variant = runtime.variant("Texels", 0, &[]).expect("built");
    let request = KernelRequest { variant, kernel: "Brighten", overrides: &[] };
    let kernel = runtime.kernel(&request).expect("wgpu accepts the pipeline with the manifest's layout");
    let layout = runtime.pass_layout(variant.pass()).expect("layout");
    let size = wgpu::Extent3d { width: 8, height: 8, depth_or_array_layers: 1 };
    let values: Vec<f32> = (0..64).map(|i| i as f32 / 63.0).collect();
    let texture = |format, usage| {
        crate::support::texture(device, size, format, wgpu::TextureUsages::STORAGE_BINDING | usage)
    };
    let source = texture(wgpu::TextureFormat::R32Float, wgpu::TextureUsages::COPY_DST);
    let target = texture(wgpu::TextureFormat::Rgba8Unorm, wgpu::TextureUsages::COPY_SRC);
    gpu.queue.write_texture(
        source.as_image_copy(),
        &values.iter().flat_map(|v| v.to_le_bytes()).collect::<Vec<u8>>(),
        wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(32), rows_per_image: None },
        size,
    );
    let (source_view, target_view) =
        (source.create_view(&Default::default()), target.create_view(&Default::default()));
    let group = &pass.layout[0];
    let entries: Vec<wgpu::BindGroupEntry> = group
        .entries
        .iter()
        .map(|e| wgpu::BindGroupEntry {
            binding: e.binding,
            resource: wgpu::BindingResource::TextureView(if e.name == "source" {
                &source_view
            } else {
                &target_view
            }),
        })
        .collect();
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &layout.groups[group.group as usize],
        entries: &entries,
    });
    let read = crate::support::readback(device, 256 * 8);
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut compute = encoder.begin_compute_pass(&Default::default());
        compute.set_pipeline(&kernel.pipeline);
        compute.set_bind_group(group.group, &bind_group, &[]);
        let [x, y, z] = kernel.workgroups([8, 8, 1]);
        compute.dispatch_workgroups(x, y, z);
    }
    encoder.copy_texture_to_buffer(
        target.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &read,
            layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(256), rows_per_image: None },
        },
        size,
    );
    gpu.queue.submit([encoder.finish()]);
    read.map_async(wgpu::MapMode::Read, .., |result| result.expect("maps"));
    device.poll(wgpu::PollType::wait_indefinitely()).expect("poll");
    let texels = read.get_mapped_range(..).expect("mapped");
    let unorm = |v: f32| (v.clamp(0.0, 1.0) * 255.0).round() as i32;
    for (i, &value) in values.iter().enumerate() {
        let at = (i / 8) * 256 + (i % 8) * 4;
        let expected = [unorm(value), unorm(value * 0.5), unorm(1.0 - value), 255];
        let written: Vec<i32> = texels[at..at + 4].iter().map(|&b| i32::from(b)).collect();
        assert!(
            written.iter().zip(expected).all(|(w, e)| (w - e).abs() <= 1),
            "texel {i}: {written:?}, {expected:?}"
        );
    }
}

/// A `.compute` file as Unity writes one, in HLSL (`[numthreads]`, `RWStructuredBuffer`, a
/// `cbuffer`): fixtures/compute's kernels, built through glslang, compute on the GPU what the CPU
/// computes for both variants.
#[test]
fn an_hlsl_compute_file_s_kernels_compute_what_the_cpu_computes() {
    let Some(gpu) = gpu("the HLSL compute kernels test") else { return };
    let output = built_fixture("compute_hlsl");
    let runtime = Runtime::open(&gpu.device, output.path()).expect("opens");
    double_and_add_offset_compute_what_the_cpu_computes(&runtime, &gpu);
    let variant = runtime.variant(SHADER, 0, &[]).expect("built");
    let request = KernelRequest { variant, kernel: "AddOffset", overrides: &[] };
    assert_eq!(runtime.kernel(&request).expect("pipeline").workgroup_size, [32, 2, 1]);
}
