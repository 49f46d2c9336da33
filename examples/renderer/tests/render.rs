//! The renderer on a real device (lavapipe in CI) against the CPU f64 reference, and the build
//! following the scene: a material's preset decides which variants exist.

mod common;

use kiln_renderer::{Scene, compare, reference, render};
use std::collections::BTreeSet;
use std::path::Path;

/// Per channel, 0..1, over pixels off the silhouettes. Measured on lavapipe: max 0.0111, mean
/// 0.0011 (8-bit output, f32 shading, a 96 x 192 tessellated sphere against an analytic one).
const MAX_ERROR: f64 = 0.03;
const MEAN_ERROR: f64 = 0.003;

#[test]
fn the_scene_matches_the_f64_reference() {
    let Some(gpu) = common::gpu("the render test") else { return };
    matches_the_f64_reference(gpu);
}

/// The same scene through wgpu's OpenGL back end, where wgpu has naga write GLSL from kiln's WGSL.
#[test]
fn the_scene_matches_the_f64_reference_on_wgpu_s_gl_back_end() {
    let Some(gpu) = common::gl_gpu("the render test on GL") else { return };
    matches_the_f64_reference(gpu);
}

fn matches_the_f64_reference((device, queue, adapter): (wgpu::Device, wgpu::Queue, String)) {
    let scene = Scene::bundled();
    let image = render(&device, &queue, &scene).expect("renders");
    let (colors, edge) = reference(&scene);
    let (max, mean, pixels) = compare(&image, &colors, &edge);
    println!("{adapter}: max error {max:.4}, mean {mean:.5} over {pixels} pixels");
    assert!(pixels > 50_000, "most of the image is compared");
    assert!(max <= MAX_ERROR && mean <= MEAN_ERROR, "max {max}, mean {mean}");
    // Not a blank image: the spheres are lit.
    assert!(image.pixels.chunks(4).filter(|p| p[0] > 100 || p[1] > 100 || p[2] > 100).count() > 2000);
}

/// The keyword sets of the variants kiln builds for a scene, as its build script builds them.
fn variants_for(scene: &Scene) -> BTreeSet<Vec<String>> {
    let dir = tempfile::tempdir().expect("temp dir");
    let materials = dir.path().join("materials");
    std::fs::create_dir(&materials).expect("mkdir");
    for (name, text) in scene.material_files() {
        std::fs::write(materials.join(name), text).expect("write");
    }
    let shaders = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/project/shaders");
    let output = kiln::Build::new(shaders)
        .materials(materials)
        .global_keywords(scene.global_keywords())
        .out_dir(dir.path().join("out"))
        .execute()
        .expect("builds");
    output
        .manifest
        .shaders
        .iter()
        .flat_map(|s| &s.passes)
        .flat_map(|p| &p.variants)
        .map(|v| v.keywords.clone())
        .collect()
}

#[test]
fn a_material_preset_decides_the_variants_built() {
    let scene = Scene::bundled();
    let built = variants_for(&scene);
    let expected: BTreeSet<Vec<String>> =
        [vec![], vec!["_CLIPPING".to_string()], vec!["_PREMULTIPLY_ALPHA".to_string()]].into_iter().collect();
    assert_eq!(built, expected);

    // The one clipped sphere becomes opaque: its variant is no longer built.
    let mut changed = scene.clone();
    let clipped = changed.objects.iter_mut().find(|o| o.material.clips()).expect("a clipped object");
    clipped.material.preset = "Opaque".into();
    let rebuilt = variants_for(&changed);
    assert_eq!(rebuilt, expected.iter().filter(|k| **k != ["_CLIPPING"]).cloned().collect());
}

#[test]
fn a_scene_with_one_light_gets_only_the_single_light_variants() {
    let mut scene = Scene::bundled();
    scene.lights.truncate(1);
    let built = variants_for(&scene);
    let single = |mut keywords: Vec<&str>| {
        keywords.push("_SINGLE_DIRECTIONAL_LIGHT");
        keywords.into_iter().map(String::from).collect::<Vec<_>>()
    };
    let expected: BTreeSet<Vec<String>> =
        [single(vec![]), single(vec!["_CLIPPING"]), single(vec!["_PREMULTIPLY_ALPHA"])].into_iter().collect();
    assert_eq!(built, expected);
}

/// `Library::material_uniform` fills the material's block as the generated `#[repr(C)]` struct
/// lays it out: the same bytes as that struct filled by hand from the material's values.
#[test]
fn material_uniform_bytes_are_the_generated_structs() {
    use kiln_renderer::shaders::custom_rp_lit::LitMaterial;
    let library = kiln_renderer::library().expect("embedded build");
    for material in library.materials() {
        let number = |name: &str| material.number(name).expect("a number") as f32;
        let color: [f32; 4] =
            serde_json::from_value(material.values["_BaseColor"].clone()).expect("a colour");
        let by_hand = LitMaterial {
            _BaseMap_ST: [1.0, 1.0, 0.0, 0.0],
            _BaseColor: color,
            _Cutoff: number("_Cutoff"),
            _Metallic: number("_Metallic"),
            _Smoothness: number("_Smoothness"),
            ..bytemuck::Zeroable::zeroed()
        };
        let filled = library.material_uniform(material, 0, "UnityPerMaterial").expect("fills");
        assert_eq!(filled, bytemuck::bytes_of(&by_hand), "{}", material.name);
    }
    assert!(library.materials().len() >= 10);
}

/// A texture provider for the tests: one texture for every property, or none.
struct Textures {
    view: Option<wgpu::TextureView>,
    sampler: wgpu::Sampler,
}

impl kiln_runtime::MaterialTextures for Textures {
    fn texture(&self, _property: &str, _texture: &str) -> Option<&wgpu::TextureView> {
        self.view.as_ref()
    }

    fn sampler(&self, _property: &str) -> Option<&wgpu::Sampler> {
        Some(&self.sampler)
    }
}

/// A material's bind group holds its values, follows them when they change, and names a
/// texture the renderer does not have.
#[test]
fn a_material_bind_group_follows_its_material() {
    let Some((device, queue, _)) = common::gpu("the material bind group test") else { return };
    let runtime = kiln_runtime::Runtime::new(&device, kiln_renderer::library().expect("embedded build"));
    let lit = runtime.pass("Custom RP/Lit", 0).expect("the lit pass");
    let textures = Textures {
        view: Some(kiln_renderer::white_texture(&device, &queue)),
        sampler: device.create_sampler(&Default::default()),
    };
    let material = runtime.library().material("object00").expect("a scene material").clone();
    let group = runtime.material_bind_group(&material, lit, &textures).expect("binds");
    assert_eq!(group.group, kiln_runtime::MATERIAL_GROUP);
    // The generated module's group constants are the run time's.
    assert_eq!(
        [
            kiln_renderer::shaders::FRAME_GROUP,
            kiln_renderer::shaders::MATERIAL_GROUP,
            kiln_renderer::shaders::OBJECT_GROUP
        ],
        [kiln_runtime::FRAME_GROUP, group.group, kiln_runtime::OBJECT_GROUP]
    );
    let read = |buffer: &wgpu::Buffer| {
        let size = buffer.size();
        let staging = device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let mut encoder = device.create_command_encoder(&Default::default());
        encoder.copy_buffer_to_buffer(buffer, 0, &staging, 0, size);
        queue.submit([encoder.finish()]);
        staging.map_async(wgpu::MapMode::Read, .., |result| result.expect("maps"));
        device.poll(wgpu::PollType::wait_indefinitely()).expect("poll");
        staging.get_mapped_range(..).expect("mapped").to_vec()
    };
    let buffer = group.buffer("UnityPerMaterial").expect("the material block");
    let uniform = |m| runtime.library().material_uniform(m, 0, "UnityPerMaterial").expect("fills");
    assert_eq!(read(buffer), uniform(&material));
    let mut changed = material.clone();
    changed.values.insert("_Metallic".into(), serde_json::json!(0.75));
    group.update(runtime.library(), &queue, &changed).expect("updates");
    assert_eq!(read(buffer), uniform(&changed));
    assert_ne!(uniform(&changed), uniform(&material));
    // No texture for a texture property: an error naming it.
    let none = Textures { view: None, sampler: device.create_sampler(&Default::default()) };
    let error = runtime.material_bind_group(&material, lit, &none).expect_err("no texture").to_string();
    assert!(error.contains("no texture for `_BaseMap` (`white`)"), "{error}");
}

/// Per-frame and per-object groups are bound by name; a misspelt or missing buffer is an error
/// naming it.
#[test]
fn buffer_groups_bind_by_name_and_name_what_is_wrong() {
    let Some((device, _queue, _)) = common::gpu("the buffer bind group test") else { return };
    let runtime = kiln_runtime::Runtime::new(&device, kiln_renderer::library().expect("embedded build"));
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: 1024,
        usage: wgpu::BufferUsages::UNIFORM,
        mapped_at_creation: false,
    });
    let lit = runtime.pass("Custom RP/Lit", 0).expect("the lit pass");
    runtime
        .buffer_bind_group(lit, 0, &[("UnityPerFrame", &buffer), ("_CustomLight", &buffer)])
        .expect("binds");
    runtime.buffer_bind_group(lit, 2, &[("UnityPerDraw", &buffer)]).expect("binds");
    let error = |group, buffers: &[(&str, &wgpu::Buffer)]| {
        runtime.buffer_bind_group(lit, group, buffers).expect_err("refused").to_string()
    };
    let misspelt = error(0, &[("UnityPerFrme", &buffer), ("_CustomLight", &buffer)]);
    assert!(
        misspelt.ends_with("group 0 has no binding `UnityPerFrme` (did you mean `UnityPerFrame`?)"),
        "{misspelt}"
    );
    let missing = error(0, &[("UnityPerFrame", &buffer)]);
    assert!(missing.ends_with("no buffer for `_CustomLight` in group 0"), "{missing}");
    let no_group = error(5, &[]);
    assert!(no_group.ends_with("the pass has no bind group 5"), "{no_group}");
}

/// Where the image's difference from the analytic reference comes from: with the reference
/// drawing the same triangles and blending over 8-bit colours as the target stores them, an
/// opaque pixel is only the final rounding away (half a step: the shader's f32 arithmetic adds
/// nothing visible) and a blended one at most a step (the blender's 8-bit arithmetic).
#[test]
fn the_rest_is_tessellation_and_the_8_bit_target() {
    use kiln_renderer::{Geometry, Target, difference, reference_with};
    let Some((device, queue, adapter)) = common::gpu("the error budget test") else { return };
    let scene = Scene::bundled();
    let image = render(&device, &queue, &scene).expect("renders").colors();
    let emulated = reference_with(&scene, Geometry::Tessellated, Target::EightBit);
    let step = 1.0 / 255.0;
    let opaque = difference(&image, &emulated.colors, &emulated.left_out_unless(false));
    let blended = difference(&image, &emulated.colors, &emulated.left_out_unless(true));
    println!("{adapter}: opaque {:.4} steps, blended {:.4} steps", opaque.max / step, blended.max / step);
    assert!(opaque.pixels > 40_000 && blended.pixels > 5_000, "{opaque:?} {blended:?}");
    assert!(opaque.max <= 0.51 * step, "opaque pixels: {opaque:?}");
    assert!(blended.max <= 1.01 * step, "blended pixels: {blended:?}");
    // Against the analytic spheres the same image is further off, by the tessellation.
    let (analytic, edge) = reference(&scene);
    assert!(difference(&image, &analytic, &edge).max > 2.0 * step);
}

/// The example scene as a game meets it (one more object a frame), traced in one run and warmed
/// up from the trace in the next: the second run creates no pipeline on the render thread, and
/// draws the same image.
#[test]
fn a_warm_up_from_the_scene_s_trace_leaves_the_render_thread_nothing_to_create() {
    let Some((device, queue, _)) = common::gpu("the scene trace test") else { return };
    let scene = kiln_renderer::Scene::bundled();
    let dir = tempfile::tempdir().expect("temp dir");
    let trace = dir.path().join("pipelines.jsonl");
    let mut first = kiln_runtime::Runtime::new(&device, kiln_renderer::library().expect("embedded build"));
    first.record_pipelines(kiln_runtime::PipelineTrace::append(&trace).expect("trace"));
    let (cold, cold_image) = kiln_renderer::introduce(&mut first, &device, &queue, &scene).expect("draws");
    let created: usize = cold.iter().map(|(created, _)| created).sum();
    assert!(created > 1, "the scene's materials need several pipelines: {cold:?}");

    let (entries, skipped) = kiln_runtime::read_trace(&std::fs::read_to_string(&trace).expect("trace"));
    assert!(skipped.is_empty(), "{skipped:?}");
    let mut second = kiln_runtime::Runtime::new(&device, kiln_renderer::library().expect("embedded build"));
    assert!(second.warm_up_trace(&entries, 4).is_empty());
    assert_eq!(second.pipelines_created(), created);
    let (warm, warm_image) = kiln_renderer::introduce(&mut second, &device, &queue, &scene).expect("draws");
    assert!(warm.iter().all(|(created, _)| *created == 0), "{warm:?}");
    assert!(second.created_after_warm_up().is_empty());
    assert!(cold_image.colors() == warm_image.colors(), "the same image");
}

/// `--keywords`: a new keyword combination every frame, drawn by the ubershader until its own
/// pipeline is ready, ends in the image that creating each pipeline at once gives, and creates
/// nothing on the render thread.
#[test]
fn new_keyword_combinations_draw_through_the_ubershader_and_end_in_the_same_image() {
    let Some((device, queue, _)) = common::gpu("the keyword introduction test") else { return };
    let here = std::thread::current().name().map(str::to_string);
    let on_this_thread = |created: &[kiln_runtime::Creation]| {
        created.iter().filter(|c| Some(&c.thread) == here.as_ref()).count()
    };
    let waited = kiln_renderer::keywords::introduce(&device, &queue, false).expect("draws");
    assert_eq!(on_this_thread(&waited.created), 24, "every combination's pipeline made in its frame");
    assert!(waited.frames.iter().all(|f| f.fallbacks == 0));
    let fallback = kiln_renderer::keywords::introduce(&device, &queue, true).expect("draws");
    assert_eq!(on_this_thread(&fallback.created), 0, "{:?}", fallback.created);
    assert_eq!(fallback.created.len(), 24, "the workers made every combination's pipeline");
    assert!(fallback.frames[0].fallbacks == 1, "the first frame's new combination: {:?}", fallback.frames);
    assert!(waited.image.pixels == fallback.image.pixels, "the same image");
    // 24 cells, and the keywords make them differ: equal images mean something.
    let cells: std::collections::HashSet<&[u8]> = fallback.image.pixels.chunks_exact(4).collect();
    assert!(cells.len() >= 12, "{} distinct colours", cells.len());
}

/// The seed's Lit shader as the tutorial writes it in HLSL (fixtures/hlsl_lit: the tutorial's pass
/// on kiln's HLSL library, compiled through glslang) draws the scene the WGSL Lit shader draws:
/// every pixel within one step of 255 of it, through the same run time and bindings.
#[test]
fn the_tutorial_s_hlsl_lit_shader_draws_the_wgsl_lit_shader_s_pixels() {
    let Some((device, queue, adapter)) = common::gpu("the HLSL Lit render test") else { return };
    let scene = Scene::bundled();
    let dir = tempfile::tempdir().expect("temp dir");
    let materials = dir.path().join("materials");
    std::fs::create_dir(&materials).expect("mkdir");
    for (name, text) in scene.material_files() {
        std::fs::write(materials.join(name), text).expect("write");
    }
    let shaders = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/hlsl_lit/shaders");
    kiln::Build::new(shaders)
        .materials(materials)
        .global_keywords(scene.global_keywords())
        .out_dir(dir.path().join("out"))
        .execute()
        .expect("the HLSL Lit shader builds");
    let library = kiln_runtime::Library::open(dir.path().join("out/kiln")).expect("opens");
    let mut runtime = kiln_runtime::Runtime::new(&device, library);
    let hlsl = kiln_renderer::render_with(&mut runtime, &device, &queue, &scene).expect("HLSL renders");
    let wgsl = render(&device, &queue, &scene).expect("WGSL renders");
    assert_eq!((hlsl.width, hlsl.height), (wgsl.width, wgsl.height));
    let steps: Vec<u8> = hlsl.pixels.iter().zip(&wgsl.pixels).map(|(h, w)| h.abs_diff(*w)).collect();
    let largest = steps.iter().copied().max().unwrap_or(0);
    let differing = steps.iter().filter(|&&s| s > 0).count();
    println!("{adapter}: HLSL against WGSL Lit: largest step {largest}, {differing} channels differ");
    assert!(largest <= 1, "a channel {largest} steps of 255 apart ({differing} differ)");
    // Not two blank images: the spheres are lit.
    assert!(hlsl.pixels.chunks(4).filter(|p| p[0] > 100 || p[1] > 100 || p[2] > 100).count() > 2000);
}
