//! naga's own WGSL test inputs (tests/corpus/naga, MIT/Apache, see ORIGIN.md there) through kiln:
//! each file naga accepts on its own, with what kiln grants (WebGPU's baseline and `f16`), must
//! build through kiln wrapped as a pass per vertex or fragment entry point and as a compute shader
//! with a kernel per compute entry point, and each file naga refuses must be refused by kiln too;
//! every file must come back from `kiln preprocess` token for token.

use crate::support::{kiln, root, tool};
use kiln::build::VariantSelection;
use kiln::project::{BuildMode, build_project};
use kiln::source::SourceStore;
use naga::valid::{Capabilities, ValidationFlags, Validator};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

fn corpus() -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(root().join("tests/corpus/naga/in"))
        .expect("corpus")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "wgsl"))
        .collect();
    files.sort();
    files
}

/// What naga alone says of a text, its vertex and fragment entry points, and its compute ones.
struct NagaVerdict {
    accepted: Result<(), String>,
    entry_points: Vec<(&'static str, String)>,
    kernels: Vec<String>,
}

impl NagaVerdict {
    fn compute_only(&self) -> bool {
        self.entry_points.is_empty() && !self.kernels.is_empty()
    }
}

fn naga_alone(text: &str) -> NagaVerdict {
    let capabilities = kiln::compile::target::webgpu_baseline() | Capabilities::SHADER_FLOAT16;
    match naga::front::wgsl::parse_str(text) {
        Err(error) => {
            // The entry points as written, for a text naga cannot parse.
            let mut entry_points = Vec::new();
            for (attribute, stage) in
                [("@vertex", "vertex"), ("@fragment", "fragment"), ("@compute", "compute")]
            {
                for (at, _) in text.match_indices(attribute) {
                    // `@compute @workgroup_size(...)` then `fn`: the name after the next `fn `.
                    let rest = &text[at + attribute.len()..];
                    let rest =
                        if stage == "compute" { rest.find("fn ").map_or("", |i| &rest[i..]) } else { rest };
                    if let Some(name) = rest.trim_start().strip_prefix("fn ") {
                        let name: String =
                            name.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
                        entry_points.push((stage, name));
                    }
                }
            }
            let kernels =
                entry_points.iter().filter(|(s, _)| *s == "compute").map(|(_, n)| n.clone()).collect();
            entry_points.retain(|(stage, _)| *stage != "compute");
            NagaVerdict { accepted: Err(error.emit_to_string(text)), entry_points, kernels }
        }
        Ok(module) => {
            let accepted = Validator::new(ValidationFlags::all(), capabilities)
                .validate(&module)
                .map(|_| ())
                .map_err(|e| e.emit_to_string(text));
            let entry_points: Vec<(&'static str, String)> = module
                .entry_points
                .iter()
                .filter_map(|e| match e.stage {
                    naga::ShaderStage::Vertex => Some(("vertex", e.name.clone())),
                    naga::ShaderStage::Fragment => Some(("fragment", e.name.clone())),
                    _ => None,
                })
                .collect();
            let kernels = module
                .entry_points
                .iter()
                .filter(|e| e.stage == naga::ShaderStage::Compute)
                .map(|e| e.name.clone())
                .collect();
            NagaVerdict { accepted, entry_points, kernels }
        }
    }
}

/// `file` as a shader of its own: a pass per entry point, each including the file whole, at the
/// highest target (so kiln's interpolator and colour-target limits are WebGPU's).
fn wrapper(file: &Path, entry_points: &[(&str, String)]) -> String {
    let name = file.file_name().expect("name").to_string_lossy();
    let text = std::fs::read_to_string(file).expect("corpus file");
    let require = if text.contains("enable f16") { "#pragma require native16bit\n" } else { "" };
    let mut out = format!("Shader \"Naga/{name}\" {{\n    SubShader {{\n");
    let passes: Vec<Option<&(&str, String)>> =
        if entry_points.is_empty() { vec![None] } else { entry_points.iter().map(Some).collect() };
    for entry in passes {
        let pragma = entry.map(|(stage, name)| format!("#pragma {stage} {name}\n")).unwrap_or_default();
        let _ = write!(
            out,
            "        Pass {{\nWGSLPROGRAM\n#pragma target 5.0\n{require}{pragma}#include \"{name}\"\nENDWGSL\n        }}\n"
        );
    }
    out.push_str("    }\n}\n");
    out
}

/// `file` as a compute shader of its own: a kernel per compute entry point, at the highest target.
fn compute_wrapper(file: &Path, kernels: &[String]) -> String {
    let name = file.file_name().expect("name").to_string_lossy();
    let text = std::fs::read_to_string(file).expect("corpus file");
    let require = if text.contains("enable f16") { "#pragma require native16bit\n" } else { "" };
    let pragmas: String = kernels.iter().map(|k| format!("#pragma kernel {k}\n")).collect();
    format!("#pragma target 5.0\n{require}{pragmas}#include \"{name}\"\n")
}

/// WGSL tokens, comments and whitespace left out.
fn tokens(text: &str) -> Vec<String> {
    let bytes = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i].is_ascii_whitespace() {
            i += 1;
        } else if bytes[i..].starts_with(b"//") {
            while i < bytes.len() && bytes[i] != b'\n' {
                i += 1;
            }
        } else if bytes[i..].starts_with(b"/*") {
            let mut depth = 0;
            while i < bytes.len() {
                if bytes[i..].starts_with(b"/*") {
                    depth += 1;
                    i += 2;
                } else if bytes[i..].starts_with(b"*/") {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
        } else if bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_' || bytes[i] == b'.' {
            let start = i;
            while i < bytes.len()
                && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_' || bytes[i] == b'.')
            {
                i += 1;
            }
            out.push(text[start..i].to_string());
        } else {
            let len = text[i..].chars().next().map_or(1, char::len_utf8);
            out.push(text[i..i + len].to_string());
            i += len;
        }
    }
    out
}

#[test]
fn naga_s_wgsl_tests_build_through_kiln_as_naga_judges_them() {
    let spirv_val =
        tool("spirv-val", "spirv-tools", "naga_s_wgsl_tests_build_through_kiln_as_naga_judges_them");
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    std::fs::create_dir_all(&project).expect("project");
    let files = corpus();
    assert!(files.len() >= 80, "{} corpus files", files.len());
    let mut verdicts = BTreeMap::new();
    let mut names = Vec::new();
    for file in &files {
        let name = file.file_name().expect("name").to_string_lossy().into_owned();
        let text = std::fs::read_to_string(file).expect("corpus file");
        let verdict = naga_alone(&text);
        if !verdict.entry_points.is_empty() || !verdict.kernels.is_empty() {
            std::fs::copy(file, project.join(&name)).expect("copy");
        }
        if !verdict.entry_points.is_empty() {
            let shader = project.join(format!("{name}.shader"));
            std::fs::write(&shader, wrapper(file, &verdict.entry_points)).expect("wrapper");
            names.push(format!("{:?}", format!("Naga/{name}")));
        }
        if !verdict.kernels.is_empty() {
            std::fs::write(project.join(format!("{name}.compute")), compute_wrapper(file, &verdict.kernels))
                .expect("wrapper");
            names.push(format!("{name:?}"));
        }
        verdicts.insert(name, verdict);
    }
    std::fs::write(project.join("kiln.toml"), format!("always_include = [{}]\n", names.join(", ")))
        .expect("kiln.toml");
    let mut store = SourceStore::new();
    let output = dir.path().join("out");
    let mode = BuildMode {
        output: Some(output.clone()),
        unused_shaders: VariantSelection::All { limit: 16 },
        ..BuildMode::default()
    };
    let (result, mut diagnostics) =
        build_project(&mut store, std::slice::from_ref(&project), &mode, &|_, _| {}).expect("project");
    diagnostics.extend(result.diagnostics);
    // Each error by the corpus file it is about (its own text, or the wrapper including it).
    let mut errors: BTreeMap<String, Vec<kiln::diagnostics::Diagnostic>> = BTreeMap::new();
    for d in diagnostics.iter().filter(|d| d.severity == kiln::diagnostics::Severity::Error) {
        let file = d
            .primary
            .as_ref()
            .and_then(|p| store.path(p.span.file))
            .map(|p| p.to_path_buf())
            .unwrap_or_default();
        let name = file
            .file_name()
            .map(|n| n.to_string_lossy().trim_end_matches(".shader").trim_end_matches(".compute").to_string())
            .unwrap_or_default();
        errors.entry(name).or_default().push(d.clone());
    }
    let (mut built, mut refused_alike, mut kiln_refusals, mut no_pass) = (0, 0, 0, 0);
    // Of those, the files with compute entry points (built as compute shaders).
    let (mut compute_built, mut compute_refused) = (0, 0);
    let mut failures = Vec::new();
    for (name, verdict) in &verdicts {
        let found = errors.get(name).map(Vec::as_slice).unwrap_or_default();
        let rendered = kiln::diagnostics::render_plain(&store, found);
        let compute = if verdict.kernels.is_empty() { 0 } else { 1 };
        match (&verdict.accepted, verdict.entry_points.is_empty() && verdict.kernels.is_empty()) {
            (_, true) => no_pass += 1,
            (Ok(()), false) if found.is_empty() => {
                built += 1;
                compute_built += compute;
            }
            // Documented: valid WGSL naga's SPIR-V writer cannot express (docs/diagnostics.md).
            (Ok(()), false) if found.iter().all(|d| d.code == "K0415" || d.code == "K0418") => {
                kiln_refusals += 1
            }
            (Ok(()), false) => failures.push(format!("{name}: naga accepts it, kiln refuses:\n{rendered}")),
            (Err(_), false) if !found.is_empty() => {
                refused_alike += 1;
                compute_refused += compute;
            }
            (Err(why), false) => failures.push(format!("{name}: naga refuses it, kiln builds it:\n{why}")),
        }
    }
    // The modules of the files naga accepts, built on their own, are valid SPIR-V too.
    let mut spirv_modules = 0;
    if spirv_val {
        let accepted = dir.path().join("accepted");
        std::fs::create_dir_all(&accepted).expect("folder");
        let mut names = Vec::new();
        for (name, verdict) in
            verdicts.iter().filter(|(name, v)| v.accepted.is_ok() && !errors.contains_key(*name))
        {
            if verdict.entry_points.is_empty() && verdict.kernels.is_empty() {
                continue;
            }
            std::fs::copy(project.join(name), accepted.join(name)).expect("copy");
            if !verdict.entry_points.is_empty() {
                std::fs::copy(
                    project.join(format!("{name}.shader")),
                    accepted.join(format!("{name}.shader")),
                )
                .expect("copy");
                names.push(format!("{:?}", format!("Naga/{name}")));
            }
            if !verdict.kernels.is_empty() {
                std::fs::copy(
                    project.join(format!("{name}.compute")),
                    accepted.join(format!("{name}.compute")),
                )
                .expect("copy");
                names.push(format!("{name:?}"));
            }
        }
        std::fs::write(accepted.join("kiln.toml"), format!("always_include = [{}]\n", names.join(", ")))
            .expect("kiln.toml");
        let output = dir.path().join("accepted-out");
        crate::support::build_without_errors(&accepted, Some(&output), VariantSelection::All { limit: 16 });
        let manifest = kiln::manifest::Manifest::read(&output).expect("manifest");
        for stage in manifest.stages() {
            let Some(file) = stage.spirv() else { continue };
            let bytes = file.read(&output).expect("module");
            let path = dir.path().join("module.spv");
            std::fs::write(&path, &bytes).expect("write");
            let environment = if bytes[6] == 1 && bytes[5] == 0 { "vulkan1.0" } else { "vulkan1.1" };
            let run = std::process::Command::new("spirv-val")
                .args(["--target-env", environment])
                .arg(&path)
                .output()
                .expect("spirv-val");
            if !run.status.success() {
                failures.push(format!(
                    "{}: spirv-val: {}",
                    stage.interface.entry_point,
                    String::from_utf8_lossy(&run.stderr)
                ));
            }
            spirv_modules += 1;
        }
    }
    println!(
        "naga's {} WGSL tests: {built} built as naga accepts them ({compute_built} with compute kernels, \
         {compute_only} of them compute-only), {refused_alike} refused as naga refuses them ({compute_refused} with \
         kernels), {kiln_refusals} refused by kiln (K0415, K0418), {no_pass} with no entry point; {spirv_modules} SPIR-V \
         modules through spirv-val",
        verdicts.len(),
        compute_only = verdicts.values().filter(|v| v.compute_only() && v.accepted.is_ok()).count(),
    );
    assert!(failures.is_empty(), "{} files:\n{}", failures.len(), failures.join("\n\n"));
    assert!(built >= 30, "only {built} built");
}

#[test]
fn naga_s_wgsl_tests_come_back_from_kiln_preprocess_token_for_token() {
    let dir = tempfile::tempdir().expect("temp dir");
    let mut failures = Vec::new();
    for file in corpus() {
        let name = file.file_name().expect("name").to_string_lossy().into_owned();
        let text = std::fs::read_to_string(&file).expect("corpus file");
        std::fs::copy(&file, dir.path().join(&name)).expect("copy");
        let shader = dir.path().join(format!("{name}.shader"));
        // One pass, no entry point: preprocessing needs none.
        std::fs::write(&shader, wrapper(&file, &[])).expect("wrapper");
        let run = kiln(&["preprocess", shader.to_str().expect("UTF-8")]);
        let out = String::from_utf8_lossy(&run.stdout);
        if run.status.code() != Some(0) {
            failures.push(format!(
                "{name}: exit {:?}: {}",
                run.status.code(),
                String::from_utf8_lossy(&run.stderr)
            ));
        } else if tokens(&out) != tokens(&text) {
            let (a, b) = (tokens(&text), tokens(&out));
            let at = a.iter().zip(&b).position(|(x, y)| x != y).unwrap_or(a.len().min(b.len()));
            failures.push(format!(
                "{name}: token {at} differs: {:?} vs {:?}",
                a.get(at..at + 5),
                b.get(at..at + 5)
            ));
        }
    }
    assert!(failures.is_empty(), "{} files:\n{}", failures.len(), failures.join("\n"));
}
