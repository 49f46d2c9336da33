//! `#pragma ubershader` end to end (`fixtures/ubershader`): the pass's ubershader is built and
//! reflected beside its variants, draws what each variant draws (pixels and depth on the GPU),
//! serves every keyword combination with one pipeline, and lets `Runtime::drawable` return at
//! once while a worker creates the variant's pipeline.

use crate::runtime::{draw_with, targets};
use crate::support::{build_without_errors, gpu, root};
use kiln::config::VariantSelection;
use kiln::manifest::MaterialManifest;
use kiln::runtime::{Drawable, PipelineRequest, Runtime};
use std::sync::Arc;
use std::time::{Duration, Instant};

const SHADER: &str = "Test/Ubershader";

/// Every keyword combination of the fixture's pass: (variant keywords, `dynamic_branch` ones).
fn combinations() -> Vec<Vec<&'static str>> {
    let mut all = Vec::new();
    for tint in [None, Some("_TINT_RED"), Some("_TINT_GREEN")] {
        for fog in [None, Some("_FOG")] {
            for far in [None, Some("_FAR")] {
                for dim in [None, Some("_DIM")] {
                    all.push([tint, fog, far, dim].into_iter().flatten().collect());
                }
            }
        }
    }
    all
}

fn built() -> tempfile::TempDir {
    let output = tempfile::tempdir().expect("temp dir");
    let project = root().join("fixtures/ubershader");
    build_without_errors(&project, Some(output.path()), VariantSelection::All { limit: 64 });
    output
}

#[test]
fn the_ubershader_is_built_and_reflected_beside_the_variants() {
    let output = built();
    let manifest = crate::support::verified_manifest(output.path());
    let pass = &manifest.shaders.iter().find(|s| s.name == SHADER).expect("built").passes[0];
    assert_eq!(pass.variants.len(), 12, "3 tints x fog x far; `_DIM` makes none");
    let ubershader = pass.ubershader.as_ref().expect("the pass has an ubershader");
    // Variant keywords in declaration order, then the `dynamic_branch` one: bit i is keyword i.
    assert_eq!(ubershader.keywords, ["_TINT_RED", "_TINT_GREEN", "_FOG", "_FAR", "_DIM"]);
    assert_eq!(ubershader.immediates(["_FOG", "_DIM"]), [0b10100, 0, 0, 0, 0, 0, 0, 0]);
    let [Some(vertex), Some(fragment)] = pass.variant_stages(&ubershader.modules) else {
        panic!("the ubershader has both stages")
    };
    for stage in [&vertex, &fragment] {
        assert_eq!(
            stage.module.features,
            [kiln::manifest::GpuFeature::Immediates],
            "a device needs wgpu's IMMEDIATES"
        );
        // `_DIM` is read from the immediate data, not an `override`: one pipeline serves both.
        assert!(stage.interface.overrides.is_empty(), "{:?}", stage.interface.overrides);
        assert!(stage.module.spirv.is_some(), "no override: SPIR-V is written");
    }
    // No variant's module is the ubershader's.
    let variant_modules: Vec<usize> =
        pass.variants.iter().flat_map(|v| [v.vertex, v.fragment]).flatten().collect();
    assert!(!variant_modules.contains(&vertex.index) && !variant_modules.contains(&fragment.index));
}

/// A material of the pass with no property values (its render state is the pass's own).
fn plain_material() -> MaterialManifest {
    MaterialManifest {
        name: "Plain".to_string(),
        shader: SHADER.to_string(),
        preset: None,
        render_queue: 2000,
        keywords: Vec::new(),
        values: Default::default(),
    }
}

fn request<'a>(
    runtime: &Runtime,
    material: &'a MaterialManifest,
    targets: &'a kiln::runtime::Targets,
    keywords: &[&str],
) -> PipelineRequest<'a> {
    PipelineRequest {
        variant: runtime.variant(SHADER, 0, keywords).expect("built"),
        material,
        targets,
        vertex_layout: None,
        overrides: &[],
    }
}

#[test]
fn the_ubershader_draws_what_every_variant_draws_while_workers_create_them() {
    let Some(gpu) = gpu("the_ubershader_draws_what_every_variant_draws_while_workers_create_them") else {
        return;
    };
    let output = built();
    let runtime = Arc::new(Runtime::open(&gpu.device, output.path()).expect("opens"));
    assert!(runtime.draws_ubershaders(), "the suite's device has wgpu's IMMEDIATES");
    let material = plain_material();
    let targets = targets();
    let warm = request(&runtime, &material, &targets, &[]);
    assert!(runtime.warm_up_ubershader(&warm).expect("creates"));
    assert_eq!(runtime.pipelines_created(), 1, "the ubershader's pipeline");
    runtime.mark_warm();
    // First asks: every one drawn at once by the ubershader, its own pipeline made by a worker.
    let mut drawn = Vec::new();
    for keywords in combinations() {
        let drawable = runtime.drawable(&request(&runtime, &material, &targets, &keywords)).expect("draws");
        assert!(!drawable.is_ready(), "{keywords:?}: a new request gets the ubershader");
        drawn.push((keywords, draw_with(&gpu, &drawable)));
    }
    let started = Instant::now();
    while runtime.pipelines_pending() > 0 {
        assert!(started.elapsed() < Duration::from_secs(120), "workers finish");
        std::thread::sleep(Duration::from_millis(20));
    }
    // Each request's own pipeline was made by a worker, none on this thread.
    let misses = runtime.created_after_warm_up();
    let this_thread = format!("{:?}", std::thread::current().id());
    let here = std::thread::current().name().map_or(this_thread, str::to_string);
    assert!(!misses.is_empty() && misses.iter().all(|m| m.thread != here), "{misses:?}");
    let ubershaders = runtime.pipelines_created() - misses.len();
    assert_eq!(ubershaders, 1, "one ubershader pipeline served all 24 combinations");
    let mut distinct = std::collections::HashSet::new();
    for (keywords, fallback) in drawn {
        let drawable = runtime.drawable(&request(&runtime, &material, &targets, &keywords)).expect("draws");
        assert!(matches!(drawable, Drawable::Ready(_)), "{keywords:?}: its own pipeline is ready");
        let variant = draw_with(&gpu, &drawable);
        assert_eq!(fallback, variant, "{keywords:?}: the ubershader draws what the variant draws");
        distinct.insert((variant.0, variant.1.to_bits()));
    }
    // The keywords change what is drawn: a comparison of equal images would prove nothing.
    assert!(distinct.len() >= 12, "{} distinct results", distinct.len());
}

#[test]
fn a_trace_warm_up_makes_the_ubershader_for_each_traced_state() {
    let Some(gpu) = gpu("a_trace_warm_up_makes_the_ubershader_for_each_traced_state") else { return };
    let output = built();
    let dir = tempfile::tempdir().expect("temp dir");
    let trace = dir.path().join("pipelines.jsonl");
    let material = plain_material();
    let targets = targets();
    let mut first = Runtime::open(&gpu.device, output.path()).expect("opens");
    first.record_pipelines(kiln::runtime::PipelineTrace::append(&trace).expect("trace"));
    for keywords in [&["_FOG"][..], &["_TINT_RED", "_DIM"]] {
        first.pipeline(&request(&first, &material, &targets, keywords)).expect("creates");
    }
    let (entries, _) = kiln::runtime::read_trace(&std::fs::read_to_string(&trace).expect("written"));
    assert_eq!(entries.len(), 2);
    let second = Arc::new(Runtime::open(&gpu.device, output.path()).expect("opens"));
    assert!(second.warm_up_trace(&entries, 2).is_empty());
    assert_eq!(second.pipelines_created(), 3, "the two traced pipelines and one ubershader (one state)");
    // A combination the trace lacks is drawn at once, its pipeline made by a worker.
    let drawable = second.drawable(&request(&second, &material, &targets, &["_FAR"])).expect("draws");
    assert!(!drawable.is_ready());
    let traced = second.drawable(&request(&second, &material, &targets, &["_FOG"])).expect("draws");
    assert!(traced.is_ready(), "a traced combination has its own pipeline from the warm-up");
}
