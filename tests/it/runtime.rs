//! `kiln::runtime` on a real device (lavapipe in CI): pipelines for every variant and preset,
//! render state from material properties checked in pixels and depth, hot reload of an output
//! folder, and usage capture feeding `kiln build --variants-from`.

use crate::support::{build_without_errors, gpu, kiln, root};
use kiln::accuracy::gpu::Gpu;
use kiln::config::VariantSelection;
use kiln::manifest::MaterialManifest;
use kiln::runtime::{
    Drawable, Library, ModuleSource, PipelineRequest, Reload, Runtime, RuntimeError, Targets, UsageLog,
};
use kiln::source::SourceStore;
use std::path::Path;
use wgpu::util::DeviceExt;

const BACKGROUND: [f64; 4] = [0.0, 0.0, 1.0, 1.0];

pub(crate) fn targets() -> Targets {
    Targets {
        colors: vec![wgpu::TextureFormat::Rgba8Unorm],
        depth: Some(wgpu::TextureFormat::Depth32Float),
        samples: 1,
    }
}

/// Draws `Test/Blend` with a material over the background into a 4 x 4 target cleared to depth
/// 1; returns the centre pixel and its depth.
fn draw(
    runtime: &Runtime,
    gpu: &Gpu,
    material: &MaterialManifest,
    keywords: &[&str],
) -> Result<([u8; 4], f32), RuntimeError> {
    draw_pass(runtime, gpu, "Test/Blend", material, keywords, &[])
}

/// Draws pass 0 of a shader whose vertex stage takes a `vec2<f32>` position at location 0, as
/// [`draw`] does.
pub(crate) fn draw_pass(
    runtime: &Runtime,
    gpu: &Gpu,
    shader: &str,
    material: &MaterialManifest,
    keywords: &[&str],
    overrides: &[(&str, f64)],
) -> Result<([u8; 4], f32), RuntimeError> {
    let targets = targets();
    let request = PipelineRequest {
        variant: runtime.variant(shader, 0, keywords)?,
        material,
        targets: &targets,
        vertex_layout: None,
        overrides,
    };
    let pipeline = runtime.pipeline(&request)?;
    Ok(draw_with(gpu, &Drawable::Ready(pipeline)))
}

/// Draws a full-screen triangle with a pipeline (or an ubershader) as [`draw_pass`] does; returns
/// the centre pixel and its depth.
pub(crate) fn draw_with(gpu: &Gpu, drawable: &Drawable) -> ([u8; 4], f32) {
    draw_bound(gpu, drawable, &[])
}

/// [`draw_with`], with bind groups set (each at its index).
pub(crate) fn draw_bound(
    gpu: &Gpu,
    drawable: &Drawable,
    groups: &[(u32, &wgpu::BindGroup)],
) -> ([u8; 4], f32) {
    let targets = targets();
    let device = &gpu.device;
    let size = wgpu::Extent3d { width: 4, height: 4, depth_or_array_layers: 1 };
    let texture = |format, usage| {
        crate::support::texture(
            device,
            size,
            format,
            usage | wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        )
    };
    let color = texture(targets.colors[0], wgpu::TextureUsages::empty());
    let depth = texture(wgpu::TextureFormat::Depth32Float, wgpu::TextureUsages::empty());
    // One triangle over the whole target.
    let vertices: [f32; 6] = [-1.0, -1.0, 3.0, -1.0, -1.0, 3.0];
    let vertex_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: None,
        contents: &vertices.iter().flat_map(|v| v.to_le_bytes()).collect::<Vec<u8>>(),
        usage: wgpu::BufferUsages::VERTEX,
    });
    // Four rows of 256 bytes (the copy alignment); both formats have 4 bytes a pixel.
    let (color_out, depth_out) =
        (crate::support::readback(device, 256 * 4), crate::support::readback(device, 256 * 4));
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let (color_view, depth_view) =
            (color.create_view(&Default::default()), depth.create_view(&Default::default()));
        let [r, g, b, a] = BACKGROUND;
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: None,
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &color_view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color { r, g, b, a }),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &depth_view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(1.0),
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: None,
            }),
            ..Default::default()
        });
        drawable.set_on(&mut pass);
        for (index, group) in groups {
            pass.set_bind_group(*index, *group, &[]);
        }
        pass.set_vertex_buffer(0, vertex_buffer.slice(..));
        pass.draw(0..3, 0..1);
    }
    for (texture, buffer, aspect) in
        [(&color, &color_out, wgpu::TextureAspect::All), (&depth, &depth_out, wgpu::TextureAspect::DepthOnly)]
    {
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo { texture, mip_level: 0, origin: wgpu::Origin3d::ZERO, aspect },
            wgpu::TexelCopyBufferInfo {
                buffer,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(256),
                    rows_per_image: None,
                },
            },
            size,
        );
    }
    gpu.queue.submit([encoder.finish()]);
    for buffer in [&color_out, &depth_out] {
        buffer.map_async(wgpu::MapMode::Read, .., |result| result.expect("maps"));
    }
    device.poll(wgpu::PollType::wait_indefinitely()).expect("poll");
    // Pixel (2, 2): row 2 starts at 512.
    let centre = 2 * 256 + 2 * 4;
    let color_bytes = color_out.get_mapped_range(..).expect("mapped");
    let depth_bytes = depth_out.get_mapped_range(..).expect("mapped");
    let pixel = color_bytes[centre..centre + 4].try_into().expect("4 bytes");
    let depth = f32::from_le_bytes(depth_bytes[centre..centre + 4].try_into().expect("4 bytes"));
    (pixel, depth)
}

fn built(project: &Path, output: &Path) {
    build_without_errors(project, Some(output), VariantSelection::Used);
}

#[test]
fn presets_blend_and_write_depth_as_their_properties_say() {
    let Some(gpu) = gpu("the render state test") else { return };
    let output = tempfile::tempdir().expect("temp dir");
    built(&root().join("fixtures/runtime"), output.path());
    let runtime = Runtime::open(&gpu.device, output.path()).expect("opens");
    // The fragment is (1, 0.5, 0) with alpha 0.5 (premultiplied to (0.5, 0.25, 0) with
    // _PREMULTIPLY_ALPHA), over blue (0, 0, 1), depth 0.5 against a cleared 1.
    let cases = [
        // Opaque: One Zero, ZWrite On.
        ("Opaque", [1.0, 0.5, 0.0], 0.5),
        // Fade: SrcAlpha OneMinusSrcAlpha, ZWrite Off.
        ("Fade", [0.5, 0.25, 0.5], 1.0),
        // Transparent: One OneMinusSrcAlpha over premultiplied colour, ZWrite Off.
        ("Transparent", [0.5, 0.25, 0.5], 1.0),
    ];
    for (name, expected, expected_depth) in cases {
        let material = runtime.library().material(name).expect("built material").clone();
        let keywords: Vec<&str> = material.keywords.iter().map(String::as_str).collect();
        let (pixel, depth) = draw(&runtime, &gpu, &material, &keywords).expect("draws");
        for (channel, want) in pixel.iter().zip(expected) {
            assert!(
                (f64::from(*channel) / 255.0 - want).abs() <= 1.5 / 255.0,
                "{name}: {pixel:?}, expected {expected:?}"
            );
        }
        assert_eq!(depth, expected_depth, "{name}: depth");
    }
    // On Vulkan the modules are handed to wgpu as SPIR-V; as WGSL they draw the same pixels.
    assert_eq!(runtime.module_source(), ModuleSource::for_device(&gpu.device));
    let as_wgsl =
        Runtime::open(&gpu.device, output.path()).expect("opens").with_module_source(ModuleSource::Wgsl);
    let as_spirv =
        Runtime::open(&gpu.device, output.path()).expect("opens").with_module_source(ModuleSource::Spirv);
    for (name, _, _) in cases {
        let material = runtime.library().material(name).expect("built material").clone();
        let keywords: Vec<&str> = material.keywords.iter().map(String::as_str).collect();
        assert_eq!(
            draw(&as_wgsl, &gpu, &material, &keywords).expect("draws"),
            draw(&as_spirv, &gpu, &material, &keywords).expect("draws"),
            "{name}: WGSL and SPIR-V modules draw alike"
        );
    }
    // A pipeline is created once per distinct (variant, state, targets): asking again reuses it.
    let created = runtime.pipelines_created();
    let opaque = runtime.library().material("Opaque").expect("material").clone();
    draw(&runtime, &gpu, &opaque, &[]).expect("draws");
    assert_eq!(runtime.pipelines_created(), created);
}

#[test]
fn every_variant_and_preset_of_the_bundled_project_gets_a_pipeline() {
    let Some(gpu) = gpu("the bundled project's pipelines") else { return };
    let output = tempfile::tempdir().expect("temp dir");
    build_without_errors(
        &root().join("fixtures/project"),
        Some(output.path()),
        VariantSelection::All { limit: 4096 },
    );
    let mut runtime = Runtime::open(&gpu.device, output.path()).expect("opens");
    // Saved wgpu pipeline cache data is reused where the backend has one (Vulkan).
    let cached = runtime.new_pipeline_cache();
    let library = runtime.library();
    let mut requests = Vec::new();
    // Variants whose modules are the same bytes share a pipeline (for one render state).
    let mut module_pairs = std::collections::HashSet::new();
    for shader in &library.manifest().shaders {
        let presets: Vec<MaterialManifest> = ["Opaque", "Clip", "Fade", "Transparent"]
            .iter()
            .filter_map(|p| {
                kiln::material::resolve_for_manifest(
                    library.manifest(),
                    p,
                    &format!("shader = {:?}\npreset = {p:?}\n", shader.name),
                )
                .ok()
            })
            .chain(
                kiln::material::resolve_for_manifest(
                    library.manifest(),
                    "default",
                    &format!("shader = {:?}\n", shader.name),
                )
                .ok(),
            )
            .collect();
        assert!(!presets.is_empty(), "{}", shader.name);
        for pass in &shader.passes {
            for variant in &pass.variants {
                module_pairs.insert((shader.name.clone(), pass.index, variant.vertex, variant.fragment));
                for material in &presets {
                    requests.push((
                        shader.name.clone(),
                        pass.index,
                        variant.keywords.clone(),
                        material.clone(),
                    ));
                }
            }
        }
    }
    let targets = targets();
    // A request's pipeline, from `runtime`.
    let pipeline =
        |runtime: &Runtime,
         (shader, pass, keywords, material): &(String, usize, Vec<String>, MaterialManifest)| {
            let keywords: Vec<&str> = keywords.iter().map(String::as_str).collect();
            let variant = runtime.variant(shader, *pass, &keywords).map_err(|e| e.to_string())?;
            let request =
                PipelineRequest { variant, material, targets: &targets, vertex_layout: None, overrides: &[] };
            runtime.pipeline(&request).map_err(|e| format!("{shader} {keywords:?} {}: {e}", material.name))
        };
    for request in &requests {
        pipeline(&runtime, request).unwrap_or_else(|e| panic!("{e}"));
    }
    println!(
        "{} requests, {} pipelines created on {} (wgpu pipeline cache: {cached})",
        requests.len(),
        runtime.pipelines_created(),
        gpu.adapter
    );
    assert!(module_pairs.len() >= 10, "{module_pairs:?}");
    assert!(runtime.pipelines_created() >= module_pairs.len(), "every distinct variant at least once");
    if cached {
        let data = runtime.pipeline_cache_data().expect("cache data");
        let mut again = Runtime::open(&gpu.device, output.path()).expect("opens");
        // SAFETY: the data came from `get_data` of a cache on this device, a moment ago.
        let cache = unsafe {
            gpu.device.create_pipeline_cache(&wgpu::PipelineCacheDescriptor {
                label: None,
                data: Some(&data),
                fallback: true,
            })
        };
        again.use_pipeline_cache(cache);
        // A pipeline made through the reloaded cache.
        pipeline(&again, &requests[0]).expect("a pipeline through the reloaded cache");
        assert_eq!(again.pipelines_created(), 1);
    }
}

#[test]
fn a_material_file_read_at_run_time_resolves_as_the_build_resolved_it() {
    let output = tempfile::tempdir().expect("temp dir");
    built(&root().join("fixtures/runtime"), output.path());
    let library = Library::open(output.path()).expect("opens");
    for name in ["Opaque", "Fade", "Transparent", "Named"] {
        let text = std::fs::read_to_string(root().join(format!("fixtures/runtime/materials/{name}.mat")))
            .expect("mat");
        assert_eq!(
            &kiln::material::resolve_for_manifest(library.manifest(), name, &text).expect("resolves"),
            library.material(name).expect("built")
        );
    }
    let tinted = kiln::material::resolve_for_manifest(
        library.manifest(),
        "t",
        "shader = \"Test/Blend\"\n[properties]\n_Tint = 1\n",
    )
    .expect("resolves");
    assert_eq!(tinted.keywords, ["_TINT"]);
    let named = library.material("Named").expect("built");
    // A misspelt name is answered with the built material it is close to.
    let misspelt = library.material("Opaqeu").map(drop).expect_err("no such material").to_string();
    assert!(misspelt.contains("did you mean `Opaque`?"), "{misspelt}");
    assert_eq!(
        (named.number("_SrcBlend"), named.number("_ZWrite"), named.render_queue),
        (Some(5.0), Some(0.0), 3000)
    );
    // Refused as a build refuses it, at the line and column in the text.
    let wrong = kiln::material::resolve_for_manifest(
        library.manifest(),
        "w.mat",
        "shader = \"Test/Blend\"\nkeywords = [\"_NOPE\"]\n",
    );
    let message = wrong.expect_err("refused").to_string();
    assert!(message.contains("K0507") && message.contains("w.mat:2:13"), "{message}");
    let wrong = kiln::material::resolve_for_manifest(
        library.manifest(),
        "v.mat",
        "shader = \"Test/Blend\"\n[properties]\n_ZWrite = \"Sideways\"\n",
    );
    let message = wrong.expect_err("refused").to_string();
    assert!(message.contains("v.mat:3:11") && message.contains("one of `Off` or `On`"), "{message}");
    // The generated module embeds the same build.
    let embedded = Library::embedded(
        &std::fs::read_to_string(output.path().join("manifest.json")).expect("manifest"),
        &std::fs::read_to_string(output.path().join("materials.json")).expect("materials"),
        &[],
    )
    .expect("parses");
    assert_eq!(embedded.materials(), library.materials());
}

#[test]
fn a_manifest_whose_indices_point_nowhere_is_refused_where_it_is_read_not_a_panic() {
    let output = tempfile::tempdir().expect("temp dir");
    built(&root().join("fixtures/project"), output.path());
    let path = output.path().join("manifest.json");
    let good = std::fs::read_to_string(&path).expect("manifest");
    // One digit more in a variant's module, a module's interface or pack, an interface's block:
    // still JSON of the schema, and the same length class of damage a no-op check cannot see.
    for field in ["\"vertex\":", "\"fragment\":", "\"interface\":", "\"pack\":", "\"uniform_blocks\":["] {
        let (at, _) = (good.match_indices(field))
            .find(|(at, _)| good[at + field.len()..].starts_with(|c: char| c.is_ascii_digit()))
            .unwrap_or_else(|| panic!("{field} with a number"));
        let damaged = format!("{}9{}", &good[..at + field.len()], &good[at + field.len()..]);
        std::fs::write(&path, &damaged).expect("write");
        let opened = Library::open(output.path()).map(drop).expect_err(field);
        assert!(
            opened
                .to_string()
                .contains("refers to a module, interface, pack or uniform block it does not list"),
            "{field}: {opened}"
        );
        let embedded = Library::embedded(&damaged, "[]", &[]).map(drop).expect_err(field);
        assert!(embedded.to_string().contains("<embedded manifest.json>"), "{embedded}");
        // What a build script's no-op build generates its module from.
        kiln::manifest::Manifest::read(output.path()).expect_err(field);
    }
    // A module whose end is past what an offset can address (every reader adds offset and size).
    let at = good.find("\"pack\":0,\"offset\":").expect("a module's place") + "\"pack\":0,\"offset\":".len();
    let damaged =
        format!("{}18446744073709551615{}", &good[..at], good[at..].trim_start_matches(char::is_numeric));
    std::fs::write(&path, &damaged).expect("write");
    let opened = Library::open(output.path()).map(drop).expect_err("an offset past any pack");
    assert!(opened.to_string().contains("past"), "{opened}");
    kiln::manifest::Manifest::read(output.path()).expect_err("an offset past any pack");
    std::fs::write(&path, &good).expect("write");
    Library::open(output.path()).expect("the manifest as built opens");
}

#[test]
fn a_running_program_swaps_in_a_rebuilt_shader_and_keeps_the_last_good_one_on_errors() {
    let Some(gpu) = gpu("the hot reload test") else { return };
    let project = tempfile::tempdir().expect("temp dir");
    for name in ["kiln.toml", "Blend.shader", "materials/Opaque.mat"] {
        let to = project.path().join(name);
        std::fs::create_dir_all(to.parent().expect("folder")).expect("mkdir");
        std::fs::copy(root().join("fixtures/runtime").join(name), to).expect("copy");
    }
    let output = project.path().join("out");
    let mode = kiln::config::Request { output: Some(output.clone()), ..kiln::config::Request::default() };
    let rebuild = || {
        let mut store = SourceStore::new();
        kiln::project::watch_build(&mut store, &[project.path().to_path_buf()], &mode).expect("builds");
    };
    rebuild();
    let mut runtime = Runtime::open(&gpu.device, &output).expect("opens");
    let material = runtime.library().material("Opaque").expect("material").clone();
    let (before, _) = draw(&runtime, &gpu, &material, &[]).expect("draws");
    assert_eq!(before[0], 255);
    assert_eq!(runtime.reload().expect("reloads"), Reload::Unchanged);
    let old_handle = runtime.variant("Test/Blend", 0, &[]).expect("built");

    // An edit: the colour's red half as strong.
    let shader = project.path().join("Blend.shader");
    let text = std::fs::read_to_string(&shader).expect("shader");
    std::fs::write(&shader, text.replace("vec4<f32>(1.0, 0.5, 0.0, 0.5)", "vec4<f32>(0.5, 0.5, 0.0, 0.5)"))
        .expect("edit");
    rebuild();
    assert!(matches!(runtime.reload().expect("reloads"), Reload::Swapped { dropped_pipelines: 1 }));
    // A handle of the old build is refused, never read as a variant of the new one.
    let targets = targets();
    let request = PipelineRequest {
        variant: old_handle,
        material: &material,
        targets: &targets,
        vertex_layout: None,
        overrides: &[],
    };
    let error = runtime.pipeline(&request).expect_err("a stale handle");
    assert!(matches!(error, RuntimeError::StaleHandle("pass")), "{error}");
    let created = runtime.pipelines_created();
    let (after, _) = draw(&runtime, &gpu, &material, &[]).expect("draws");
    assert_eq!(runtime.pipelines_created(), created + 1, "a new pipeline for the new module");
    assert!((i32::from(after[0]) - 128).abs() <= 1, "{after:?}");

    // A broken edit: the error comes back with its place, and the last good pipeline stays.
    std::fs::write(&shader, text.replace("return color;", "return colour;")).expect("edit");
    rebuild();
    let error = runtime.reload().expect_err("the build failed").to_string();
    assert!(error.contains("Blend.shader:40:"), "{error}");
    let (kept, _) = draw(&runtime, &gpu, &material, &[]).expect("draws");
    assert_eq!(kept, after);
    // Fixed again: the errors are gone and the fix is in.
    std::fs::write(&shader, &text).expect("edit");
    rebuild();
    assert!(matches!(runtime.reload(), Ok(Reload::Swapped { .. })));
    assert_eq!(draw(&runtime, &gpu, &material, &[]).expect("draws").0, before);
}

#[test]
fn a_logged_missing_variant_is_built_by_variants_from() {
    let Some(gpu) = gpu("the usage capture round trip") else { return };
    let dir = tempfile::tempdir().expect("temp dir");
    let output = dir.path().join("out");
    built(&root().join("fixtures/runtime"), &output);
    let (requested, missing) = (dir.path().join("requested.jsonl"), dir.path().join("missing.jsonl"));
    let mut runtime = Runtime::open(&gpu.device, &output).expect("opens");
    runtime.log_usage(UsageLog::new(Some(&requested), Some(&missing)).expect("log"));
    let material = runtime.library().material("Opaque").expect("material").clone();
    draw(&runtime, &gpu, &material, &[]).expect("draws");
    let error = draw(&runtime, &gpu, &material, &["_TINT"]).expect_err("not built");
    assert!(matches!(error, RuntimeError::MissingVariant { .. }), "{error}");
    let missing_text = std::fs::read_to_string(&missing).expect("missing log");
    assert_eq!(missing_text, "{\"keywords\":[\"_TINT\"],\"pass\":0,\"shader\":\"Test/Blend\"}\n");
    assert_eq!(std::fs::read_to_string(&requested).expect("requested log").lines().count(), 2);

    let project = root().join("fixtures/runtime");
    let args = [
        "build",
        project.to_str().expect("utf-8"),
        "--output",
        output.to_str().expect("utf-8"),
        "--variants-from",
        missing.to_str().expect("utf-8"),
    ];
    let run = kiln(&args);
    assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
    assert!(matches!(runtime.reload(), Ok(Reload::Swapped { .. })));
    let (pixel, _) = draw(&runtime, &gpu, &material, &["_TINT"]).expect("built now");
    assert_eq!(pixel, [0, 255, 0, 128], "the _TINT variant's green, alpha written as is");

    // A line naming what does not exist is an error at that line.
    let bad = dir.path().join("bad.jsonl");
    std::fs::write(&bad, "{\"shader\": \"Test/Blend\", \"pass\": 0, \"keywords\": []}\n{\"shader\": \"Test/Blend\", \"pass\": 0, \"keywords\": [\"_TINTED\"]}\n").expect("write");
    let run = kiln(&[
        "build",
        project.to_str().expect("utf-8"),
        "--output",
        output.to_str().expect("utf-8"),
        "--variants-from",
        bad.to_str().expect("utf-8"),
    ]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("error[K0533]")
            && stderr.contains("bad.jsonl:2:1")
            && stderr.contains("did you mean `_TINT`"),
        "{stderr}"
    );
}

/// A renderer asks for each draw's pipeline every frame: asked for again it is found by its
/// handle and state, allocating nothing; threads asking at once share one pipeline.
#[test]
fn a_pipeline_asked_for_again_allocates_nothing_and_threads_share_it() {
    let Some(gpu) = gpu("the pipeline lookup test") else { return };
    let output = tempfile::tempdir().expect("temp dir");
    built(&root().join("fixtures/runtime"), output.path());
    let runtime = Runtime::open(&gpu.device, output.path()).expect("opens");
    let material = runtime.library().material("Transparent").expect("material").clone();
    let keywords: Vec<&str> = material.keywords.iter().map(String::as_str).collect();
    let variant = runtime.variant(&material.shader, 0, &keywords).expect("built");
    let targets = targets();
    let request = PipelineRequest {
        variant,
        material: &material,
        targets: &targets,
        vertex_layout: None,
        overrides: &[],
    };
    let pipelines: Vec<_> = std::thread::scope(|scope| {
        let threads: Vec<_> =
            (0..4).map(|_| scope.spawn(|| runtime.pipeline(&request).expect("a pipeline"))).collect();
        threads.into_iter().map(|thread| thread.join().expect("joins")).collect()
    });
    assert!(
        pipelines.windows(2).all(|pair| std::sync::Arc::ptr_eq(&pair[0], &pair[1])),
        "one pipeline for all"
    );
    let allocations = crate::support::allocations_in(|| {
        for _ in 0..100 {
            let again = runtime.pipeline(&request).expect("the same pipeline");
            assert!(std::sync::Arc::ptr_eq(&again, &pipelines[0]));
        }
    });
    assert_eq!(allocations, 0, "a pipeline asked for again allocates");
    // The allocator counts: the first request of another state allocates.
    let opaque = runtime.library().material("Opaque").expect("material").clone();
    let other = PipelineRequest { material: &opaque, ..request };
    assert!(crate::support::allocations_in(|| drop(runtime.pipeline(&other).expect("made"))) > 0);
}

#[test]
fn a_misspelt_keyword_is_named_with_the_one_meant_not_a_missing_variant() {
    let output = tempfile::tempdir().expect("temp dir");
    built(&root().join("fixtures/runtime"), output.path());
    // Any path-like value opens a build, as the README writes it (`"build/kiln"`).
    let library = Library::open(output.path().to_str().expect("utf-8")).expect("opens");
    let error = library.variant("Test/Blend", 0, &["_TINR"]).expect_err("a typo");
    assert_eq!(error.to_string(), "`_TINR` is not a keyword of `Test/Blend` pass 0 (did you mean `_TINT`?)");
    // A real keyword whose variant was not built is still a missing variant.
    let error = library.variant("Test/Blend", 0, &["_TINT", "_PREMULTIPLY_ALPHA"]).expect_err("not built");
    assert!(matches!(error, RuntimeError::MissingVariant { .. }), "{error}");
}

/// The fixture's materials, one per preset.
const PRESETS: [&str; 3] = ["Opaque", "Fade", "Transparent"];

/// Draws each of [`PRESETS`] with its own keywords.
fn draw_presets(runtime: &Runtime, gpu: &Gpu) {
    for name in PRESETS {
        let material = runtime.library().material(name).expect("built").clone();
        let keywords: Vec<&str> = material.keywords.iter().map(String::as_str).collect();
        draw(runtime, gpu, &material, &keywords).expect("draws");
    }
}

/// A scene's pipelines traced in one run are made by a warm-up from the trace in the next (on
/// worker threads, or a few per frame): the scene then creates none. What the trace lacked is
/// counted with its thread and time, a stale entry is named and skipped, and `kiln build
/// --variants-from` reads the trace as a usage log.
#[test]
fn a_traced_scene_warms_up_the_next_run_and_creates_nothing_after() {
    use kiln::runtime::{PipelineTrace, WarmUp, read_trace};
    let Some(gpu) = gpu("the pipeline trace test") else { return };
    let dir = tempfile::tempdir().expect("temp dir");
    let output = dir.path().join("out");
    built(&root().join("fixtures/runtime"), &output);
    let trace = dir.path().join("trace.jsonl");
    let scene = PRESETS;
    let draw_scene = |runtime: &Runtime| draw_presets(runtime, &gpu);
    // Development: the scene drawn once, every pipeline traced as it is created.
    let mut first = Runtime::open(&gpu.device, &output).expect("opens");
    first.record_pipelines(PipelineTrace::append(&trace).expect("trace"));
    draw_scene(&first);
    draw_scene(&first);
    let created = first.pipelines_created();
    drop(first);
    let text = std::fs::read_to_string(&trace).expect("trace written");
    let (entries, skipped) = read_trace(&text);
    assert!(skipped.is_empty(), "{skipped:?}");
    assert_eq!(entries.len(), scene.len(), "one line per distinct request:\n{text}");
    assert!(
        text.lines().all(|l| l.contains(r#""kind":"render""#) && l.contains(r#""shader":"Test/Blend""#)),
        "{text}"
    );
    // Appending the same pipelines again (another run) writes nothing twice.
    let mut again = Runtime::open(&gpu.device, &output).expect("opens");
    again.record_pipelines(PipelineTrace::append(&trace).expect("trace"));
    draw_scene(&again);
    drop(again);
    assert_eq!(std::fs::read_to_string(&trace).expect("trace"), text);

    // The shipped game: warm-up on two threads before the first frame, then the scene.
    let mut stale = entries.clone();
    stale[0].keywords.push("_GONE".into());
    stale.extend(entries.iter().cloned());
    let second = Runtime::open(&gpu.device, &output).expect("opens");
    let errors = second.warm_up_trace(&stale, 2);
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert_eq!(errors[0].0, 0);
    assert!(errors[0].1.to_string().contains("`_GONE` is not a keyword"), "{}", errors[0].1);
    assert_eq!(second.pipelines_created(), created);
    draw_scene(&second);
    assert_eq!(second.pipelines_created(), created, "the scene created no pipeline after warm-up");
    assert!(second.created_after_warm_up().is_empty());
    // A request the trace lacked: made when asked, and counted as a miss on the thread that waited.
    let mut brighter = second.library().material("Opaque").expect("built").clone();
    brighter.values.insert("_SrcBlend".into(), serde_json::json!(5.0));
    draw(&second, &gpu, &brighter, &[]).expect("draws");
    let misses = second.created_after_warm_up();
    assert_eq!(misses.len(), 1, "{misses:?}");
    assert!(misses[0].label.starts_with("Test/Blend pass 0"), "{misses:?}");
    let thread = std::thread::current();
    assert_eq!(Some(misses[0].thread.as_str()), thread.name(), "{misses:?}");

    // A loading screen: one pipeline a frame.
    let third = Runtime::open(&gpu.device, &output).expect("opens");
    let mut warm_up = WarmUp::new(&entries);
    let mut frames = 1;
    while !warm_up.step(&third, 1) {
        frames += 1;
    }
    assert_eq!((frames, warm_up.progress(), third.pipelines_created()), (scene.len(), (3, 3), created));
    draw_scene(&third);
    assert!(third.created_after_warm_up().is_empty());

    // The trace is a usage log for the build.
    let project = root().join("fixtures/runtime");
    let run = kiln(&[
        "build",
        project.to_str().expect("utf-8"),
        "--output",
        output.to_str().expect("utf-8"),
        "--variants-from",
        trace.to_str().expect("utf-8"),
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
}

/// The driver's pipeline cache kept between runs: a file per adapter in the folder the program
/// names, written whole after the scene's pipelines are made, loaded by the next run; a damaged
/// file is no crash (wgpu's header check starts an empty cache).
#[test]
fn the_driver_s_pipeline_cache_is_a_file_per_adapter_written_whole() {
    use kiln::runtime::CacheFile;
    let Some(gpu) = gpu("the pipeline cache file test") else { return };
    let dir = tempfile::tempdir().expect("temp dir");
    let output = dir.path().join("out");
    built(&root().join("fixtures/runtime"), &output);
    let caches = dir.path().join("caches");
    let scene = |runtime: &Runtime| draw_presets(runtime, &gpu);
    let mut first = Runtime::open(&gpu.device, &output).expect("opens");
    // SAFETY: the folder is new: no file is read.
    let path = match unsafe { first.open_pipeline_cache(&gpu.info, &caches) } {
        CacheFile::Empty { path } => path,
        CacheFile::Unsupported => {
            let vulkan = gpu.info.backend == wgpu::Backend::Vulkan
                && gpu.device.features().contains(wgpu::Features::PIPELINE_CACHE);
            assert!(!vulkan, "Vulkan with PIPELINE_CACHE keeps a cache file");
            crate::support::skipped(&format!(
                "the pipeline cache file test: {} keeps no pipeline cache",
                gpu.adapter
            ));
            return;
        }
        loaded => panic!("a new folder holds no cache: {loaded:?}"),
    };
    let key = wgpu::util::pipeline_cache_key(&gpu.info).expect("a Vulkan key");
    assert_eq!(path, caches.join(key));
    scene(&first);
    let bytes = first.save_pipeline_cache().expect("writes").expect("the driver's data");
    assert_eq!(std::fs::metadata(&path).expect("written").len(), bytes);
    let files: Vec<_> =
        std::fs::read_dir(&caches).expect("folder").map(|e| e.expect("entry").path()).collect();
    assert_eq!(files, std::slice::from_ref(&path), "the cache file alone, no temporary left");

    // The next run: the file is loaded, and pipelines are made through it.
    let mut second = Runtime::open(&gpu.device, &output).expect("opens");
    // SAFETY: `save_pipeline_cache` wrote it a moment ago, on this adapter.
    let loaded = unsafe { second.open_pipeline_cache(&gpu.info, &caches) };
    assert_eq!(loaded, CacheFile::Loaded { path: path.clone(), bytes });
    scene(&second);
    assert_eq!(second.pipelines_created(), first.pipelines_created());

    // Torn, or one byte of the driver's data changed: kiln's hash refuses it before the driver
    // sees a byte, and the cache starts empty.
    let data = std::fs::read(&path).expect("cache");
    let mut changed = data.clone();
    *changed.last_mut().expect("data") ^= 1;
    for damaged in [&data[..data.len() / 2], &changed[..]] {
        std::fs::write(&path, damaged).expect("damage");
        let mut third = Runtime::open(&gpu.device, &output).expect("opens");
        // SAFETY: nothing of a file that fails kiln's check reaches the driver.
        let opened = unsafe { third.open_pipeline_cache(&gpu.info, &caches) };
        assert!(matches!(opened, CacheFile::Discarded { .. }), "{opened:?}");
        scene(&third);
        assert!(third.save_pipeline_cache().expect("writes").is_some());
    }
    assert_eq!(std::fs::read(&path).expect("cache").len(), data.len(), "written whole again");
}

/// A trace line the project no longer has is skipped with a warning where it is written, the
/// rest built; the same line in a usage log is an error.
#[test]
fn a_stale_trace_entry_is_a_warning_and_a_stale_usage_log_line_an_error() {
    let trace = "tests/golden/runtime/stale_trace.jsonl";
    let check = |log: &str| kiln(&["check", "fixtures/runtime", "--variants-from", log]);
    let run = check(trace);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(0), "{stderr}");
    // The diagnostics, not the summary's timing.
    let diagnostics = stderr.split("\nchecked ").next().unwrap_or_default();
    expect_test::expect_file![root().join("tests/golden/runtime/stale_trace.stderr")].assert_eq(diagnostics);
    assert!(stderr.contains("checked 1 shader, 1 pass, 3 variants"), "the rest built: {stderr}");
    // The same first line without its `version` is a usage log's line.
    let dir = tempfile::tempdir().expect("temp dir");
    let log = dir.path().join("usage.jsonl");
    let text = std::fs::read_to_string(root().join(trace)).expect("trace");
    let first = text.lines().next().expect("a line").replace(r#""version":1,"#, "");
    std::fs::write(&log, first + "\n").expect("write");
    let run = check(log.to_str().expect("utf-8"));
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("error[K0533]") && stderr.contains("usage.jsonl:1:1"), "{stderr}");
}

/// A module changed in its pack since the build (its text still UTF-8 and the same length) opens,
/// as `Library::open` reads no module whole, but never reaches the driver: the first pipeline
/// that needs it is refused.
#[test]
fn a_module_changed_since_the_build_never_reaches_the_driver() {
    let Some(gpu) = gpu("the changed module test") else { return };
    let dir = tempfile::tempdir().expect("temp dir");
    let output = dir.path().join("out");
    built(&root().join("fixtures/runtime"), &output);
    let manifest = kiln::manifest::Manifest::read(&output).expect("manifest");
    // A letter's case in each module's text, then a bit of each module's last SPIR-V word.
    let damage = |pack_suffix: &str| {
        for file in manifest.files().into_iter().filter(|f| f.path.as_str().ends_with(pack_suffix)) {
            let path = output.join(&file.path);
            let mut bytes = std::fs::read(&path).expect("pack");
            let module = file.offset as usize..(file.offset + file.size) as usize;
            let at = if pack_suffix == ".wgsl.pack" {
                module.clone().rev().find(|&at| bytes[at].is_ascii_alphabetic()).expect("a letter")
            } else {
                module.end - 1
            };
            bytes[at] ^= if pack_suffix == ".wgsl.pack" { 0x20 } else { 0x01 };
            std::fs::write(&path, bytes).expect("write");
        }
    };
    damage(".wgsl.pack");
    // Its modules have no overrides: a runtime handing the device SPIR-V never reads the WGSL.
    let runtime = Runtime::open(&gpu.device, &output).expect("opens").with_module_source(ModuleSource::Spirv);
    let material = runtime.library().material(PRESETS[0]).expect("built").clone();
    let keywords: Vec<&str> = material.keywords.iter().map(String::as_str).collect();
    draw(&runtime, &gpu, &material, &keywords).expect("the SPIR-V is intact");
    damage(".spv.pack");
    for source in [ModuleSource::Spirv, ModuleSource::Wgsl] {
        let runtime = Runtime::open(&gpu.device, &output).expect("opens").with_module_source(source);
        let material = runtime.library().material(PRESETS[0]).expect("built").clone();
        let keywords: Vec<&str> = material.keywords.iter().map(String::as_str).collect();
        let refused = draw(&runtime, &gpu, &material, &keywords).expect_err("a changed module was drawn");
        assert!(refused.to_string().contains("not what the manifest names"), "{source:?}: {refused}");
        assert_eq!(runtime.pipelines_created(), 0);
    }
}
