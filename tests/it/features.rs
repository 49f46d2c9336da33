//! GPU features are a closed set: a manifest naming one the device was not created with is
//! refused at the pipeline, render and compute alike, for each feature; one naming a feature
//! kiln does not know is refused when read.

use crate::runtime::targets;
use crate::support::{built_fixture, gpu};
use kiln::manifest::{GpuFeature, Manifest};
use kiln::runtime::{KernelRequest, Library, PipelineRequest, Runtime};
use std::path::Path;

/// The build in `output`, its manifest edited so that every module needs `feature`.
fn needing(output: &Path, feature: GpuFeature) -> Library {
    let mut manifest: serde_json::Value =
        serde_json::from_slice(&std::fs::read(output.join("manifest.json")).expect("manifest"))
            .expect("JSON");
    let shaders = manifest["shaders"].as_array_mut().expect("shaders");
    let passes = shaders.iter_mut().flat_map(|shader| shader["passes"].as_array_mut().expect("passes"));
    let mut modules = 0;
    for pass in passes {
        for module in pass["modules"].as_array_mut().expect("modules") {
            module["features"] = serde_json::json!([feature.name()]);
            modules += 1;
        }
    }
    assert!(modules > 0, "no modules in {}", output.display());
    std::fs::write(output.join("manifest.json"), manifest.to_string()).expect("the edited manifest");
    Library::open(output).expect("the edited build reads")
}

#[test]
fn a_module_needing_a_feature_the_device_lacks_is_refused_render_and_compute() {
    let Some(gpu) = gpu("the GPU feature test") else { return };
    let device_has = gpu.device.features();
    let lacking: Vec<GpuFeature> = GpuFeature::ALL
        .iter()
        .copied()
        .filter(|&feature| !device_has.contains(kiln::runtime::wgpu_feature(feature)))
        .collect();
    // The suite's device asks for shader-f16 and immediates only: int64, barycentrics and
    // subgroups are always lacking, so the test never passes vacuously.
    assert!(lacking.len() >= 3, "the device has {device_has:?}");
    let (render, compute) = (built_fixture("project"), built_fixture("compute"));
    for feature in lacking {
        let runtime = Runtime::new(&gpu.device, needing(render.path(), feature));
        let material = runtime.library().materials()[0].clone();
        let keywords: Vec<&str> = material.keywords.iter().map(String::as_str).collect();
        let targets = targets();
        let request = PipelineRequest {
            variant: runtime.variant(&material.shader, 0, &keywords).expect("built"),
            material: &material,
            targets: &targets,
            vertex_layout: None,
            overrides: &[],
        };
        let error = runtime.pipeline(&request).expect_err("refused").to_string();
        assert!(error.contains(&format!("needs `{feature}`")), "{feature}: {error}");

        let runtime = Runtime::new(&gpu.device, needing(compute.path(), feature));
        let variant = runtime.variant("Scale", 0, &[]).expect("built");
        let error = runtime.kernel(&KernelRequest { variant, kernel: "Double", overrides: &[] });
        let error = error.expect_err("refused").to_string();
        assert!(error.contains(&format!("needs `{feature}`")), "{feature} (kernel): {error}");
    }
}

#[test]
fn a_manifest_naming_an_unknown_feature_is_refused_when_read() {
    let output = built_fixture("dynamic");
    let text = std::fs::read_to_string(output.path().join("manifest.json")).expect("manifest");
    let first = text.find("\"modules\":[{").expect("a module") + "\"modules\":[{".len();
    let hostile = format!("{}\"features\":[\"warp-drive\"],{}", &text[..first], &text[first..]);
    let error = Manifest::parse(hostile.as_bytes()).expect_err("refused").to_string();
    assert!(error.contains("warp-drive") && error.contains("shader-int64"), "{error}");
}
