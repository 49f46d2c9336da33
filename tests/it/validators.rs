//! What kiln writes, checked by tools that are not kiln: every SPIR-V module through Khronos'
//! `spirv-val`, every WGSL module parsed and validated again by naga as a consumer would. The
//! modules come from the bundled project, every fixture project and a generated project with
//! hundreds of variants, each built with every variant its shaders declare.

use crate::support::{build_without_errors, root, synthetic_project, tool};
use kiln::config::VariantSelection;
use kiln::manifest::{GpuFeature, Manifest};
use std::path::{Path, PathBuf};
use std::process::Command;

/// Builds `project` (every declared variant) into `output`, which must succeed; returns the
/// manifest and the warnings, rendered.
fn build_all_variants(project: &Path, output: &Path) -> (Manifest, String) {
    let (_, warnings) = build_without_errors(project, Some(output), VariantSelection::All { limit: 4096 });
    (crate::support::verified_manifest(output), warnings)
}

/// Every built project's output folder, with the temporary folders that hold them.
struct Outputs {
    _dir: tempfile::TempDir,
    folders: Vec<(String, PathBuf)>,
}

fn outputs() -> Outputs {
    let dir = tempfile::tempdir().expect("temp dir");
    let generated = dir.path().join("generated");
    synthetic_project(&generated, 256);
    let projects = [
        root().join("fixtures/project"),
        root().join("fixtures/half"),
        root().join("fixtures/warn/global_keywords"),
        root().join("fixtures/warn/gbk_comments.shader"),
        root().join("fixtures/macros"),
        root().join("fixtures/blocks"),
        root().join("fixtures/accepted"),
        root().join("fixtures/hlsl"),
        root().join("fixtures/hlsl_lit"),
        root().join("fixtures/compute_hlsl"),
        root().join("fixtures/warn/build"),
        generated,
    ];
    let folders = projects
        .iter()
        .enumerate()
        .map(|(i, project)| {
            let output = dir.path().join(format!("out{i}"));
            build_all_variants(project, &output);
            (project.display().to_string(), output)
        })
        .collect();
    Outputs { _dir: dir, folders }
}

/// Each module of every output, once per distinct file: (description, bytes, its features).
fn modules(outputs: &Outputs, spirv: bool) -> Vec<(String, Vec<u8>, Vec<GpuFeature>)> {
    let mut seen = std::collections::HashSet::new();
    let mut found = Vec::new();
    for (project, output) in &outputs.folders {
        let manifest = Manifest::read(output).expect("manifest");
        for stage in manifest.stages() {
            let Some(file) = (if spirv { stage.spirv() } else { stage.wgsl() }) else { continue };
            if seen.insert((output.clone(), file.path.clone(), file.offset)) {
                let bytes = file.read(output).expect("module");
                let name = format!("{project}: {} at {}+{}", file.path, file.offset, file.size);
                found.push((name, bytes, stage.module.features.clone()));
            }
        }
    }
    found
}

#[test]
fn spirv_val_accepts_every_spirv_module() {
    if !tool("spirv-val", "spirv-tools", "spirv_val_accepts_every_spirv_module") {
        return;
    }
    let outputs = outputs();
    let modules = modules(&outputs, true);
    assert!(modules.len() >= 250, "only {} SPIR-V modules", modules.len());
    let scratch = tempfile::tempdir().expect("temp dir");
    let mut failures = Vec::new();
    let mut versions = std::collections::BTreeMap::new();
    for (i, (name, bytes, _)) in modules.iter().enumerate() {
        // The header's second word is the version: 0x00MMmm00.
        let version = (bytes[6], bytes[5]);
        *versions.entry(version).or_insert(0) += 1;
        // Each version against the oldest Vulkan that accepts it, so no newer rule slips by.
        let environment = if version <= (1, 0) { "vulkan1.0" } else { "vulkan1.1" };
        let path = scratch.path().join(format!("{i}.spv"));
        std::fs::write(&path, bytes).expect("write");
        let output = Command::new("spirv-val")
            .args(["--target-env", environment])
            .arg(&path)
            .output()
            .expect("spirv-val runs");
        if !output.status.success() {
            let why = String::from_utf8_lossy(&output.stderr).into_owned()
                + &String::from_utf8_lossy(&output.stdout);
            failures.push(format!("{name} (SPIR-V {}.{}): {why}", version.0, version.1));
        }
    }
    println!("spirv-val checked {} SPIR-V modules, by version {versions:?}", modules.len());
    assert!(failures.is_empty(), "spirv-val rejects {} modules:\n{}", failures.len(), failures.join("\n"));
    // fixtures/half's f16 modules are what needs SPIR-V 1.3.
    assert!(versions.contains_key(&(1, 3)) && versions.contains_key(&(1, 0)), "{versions:?}");
}

#[test]
fn every_wgsl_module_parses_and_validates_again() {
    use naga::valid::{Capabilities, ValidationFlags, Validator};
    let outputs = outputs();
    let modules = modules(&outputs, false);
    assert!(modules.len() >= 250, "only {} WGSL modules", modules.len());
    let mut failures = Vec::new();
    for (name, bytes, features) in &modules {
        // What every WebGPU device has, as kiln grants it, plus the module's features.
        let mut capabilities = kiln::compile::target::webgpu_baseline();
        for feature in features {
            capabilities |= match feature {
                GpuFeature::ShaderF16 => Capabilities::SHADER_FLOAT16,
                GpuFeature::ShaderInt64 => Capabilities::SHADER_INT64,
                GpuFeature::ShaderBarycentrics => Capabilities::SHADER_BARYCENTRICS,
                GpuFeature::Subgroup => Capabilities::SUBGROUP,
                GpuFeature::Immediates => Capabilities::IMMEDIATES,
            };
        }
        let text = std::str::from_utf8(bytes).expect("WGSL is UTF-8");
        let checked =
            naga::front::wgsl::parse_str(text).map_err(|e| e.emit_to_string(text)).and_then(|module| {
                Validator::new(ValidationFlags::all(), capabilities)
                    .validate(&module)
                    .map_err(|e| e.emit_to_string(text))
            });
        if let Err(error) = checked {
            failures.push(format!("{name} (features {features:?}): {error}"));
        }
    }
    println!("naga parsed and validated {} WGSL modules again", modules.len());
    assert!(failures.is_empty(), "{} WGSL modules fail:\n{}", failures.len(), failures.join("\n"));
}

#[test]
fn a_shader_with_legacy_code_page_comments_lists_checks_and_builds_with_one_warning() {
    let fixture = "fixtures/warn/gbk_comments.shader";
    let bytes = std::fs::read(root().join(fixture)).expect("fixture");
    assert!(std::str::from_utf8(&bytes).is_err(), "the fixture holds GBK bytes, not UTF-8");
    for args in [&["list", fixture][..], &["check", "--all-variants", fixture]] {
        let run = crate::support::kiln(args);
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(0), "{args:?}: {stderr}");
        assert_eq!(stderr.matches("warning[").count(), 1, "{args:?}: {stderr}");
        assert!(stderr.contains("warning[K0001]") && stderr.contains("gbk_comments.shader:5:12"), "{stderr}");
    }
    let output = tempfile::tempdir().expect("temp dir");
    let (manifest, warnings) = build_all_variants(&root().join(fixture), output.path());
    assert_eq!(warnings.matches("warning[").count(), 1, "{warnings}");
    assert!(warnings.starts_with("warning[K0001]"), "{warnings}");
    assert_eq!(manifest.passes().map(|p| p.variants.len()).sum::<usize>(), 1);
}
