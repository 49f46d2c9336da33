//! Outputs a user can trust without reading kiln's code: a panic in a dependency becomes a
//! diagnostic and never damages what is there; nothing goes stale, seen the way cargo and the
//! CLI see it (a scratch crate with the README's build script, built with cargo itself).

use crate::support::{example_project_copy, kiln, root, tree};
use std::path::{Path, PathBuf};
use std::process::Command;

fn text(path: &Path) -> &str {
    path.to_str().expect("UTF-8 path")
}

#[test]
fn a_panic_while_compiling_one_module_is_a_diagnostic_and_the_last_output_stays_whole() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = example_project_copy(dir.path());
    let output = dir.path().join("out");
    let first = kiln(&["build", text(&project), "--output", text(&output)]);
    assert_eq!(first.status.code(), Some(0), "{}", String::from_utf8_lossy(&first.stderr));
    // What a program reads (the cache beside it may learn what the other passes compiled).
    let served = |output: &Path| -> Vec<(PathBuf, Vec<u8>)> {
        tree(output).into_iter().filter(|(path, _)| !path.starts_with(".cache")).collect()
    };
    let before = served(&output);
    // A test build (debug assertions) panics while compiling this entry point.
    std::fs::write(project.join("shaders/LitPass.wgsl"), {
        let text = std::fs::read_to_string(project.join("shaders/LitPass.wgsl")).expect("read");
        // A constant, which every stage keeps (a comment is no part of what naga is handed).
        text + "\nconst KILN_EDITED: f32 = 1.0;\n"
    })
    .expect("write");
    let run = Command::new(env!("CARGO_BIN_EXE_kiln"))
        .args(["build", text(&project), "--output", text(&output)])
        .env("NO_COLOR", "1")
        .env("KILN_INJECT_PANIC", "LitPassFragment")
        .output()
        .expect("kiln runs");
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("error[K0416]: internal error while compiling the fragment stage"), "{stderr}");
    assert!(stderr.contains("fault injected by KILN_INJECT_PANIC"), "{stderr}");
    assert!(stderr.contains("project/shaders/Lit.shader:"), "at the entry point's pragma: {stderr}");
    assert!(
        stderr.contains("note: the panic was at kiln-") || stderr.contains("note: the panic was at "),
        "{stderr}"
    );
    assert!(
        !stderr.contains("panicked at") && !stderr.contains("stack backtrace"),
        "nothing printed by the panic: {stderr}"
    );
    // The other modules were compiled; nothing was written over the last good build.
    assert!(stderr.contains("compiled"), "{stderr}");
    // Every file of the last good build is as it was (packs of the passes that did compile may
    // have been added beside them; the manifest does not name them).
    let after: std::collections::BTreeMap<PathBuf, Vec<u8>> = served(&output).into_iter().collect();
    for (path, bytes) in &before {
        assert!(after.get(path) == Some(bytes), "a failed build changed `{}`", path.display());
    }
    crate::support::verified_manifest(&output);
}

#[test]
fn a_back_end_failing_on_a_validated_module_is_reported_at_its_entry_point() {
    // No valid input makes naga's writers fail today; debug builds can be made to (K0409). A
    // copy of the project, so that no earlier build's cache spares naga the work.
    let dir = tempfile::tempdir().expect("temp dir");
    let project = example_project_copy(dir.path());
    let run = Command::new(env!("CARGO_BIN_EXE_kiln"))
        .args(["check", text(&project)])
        .env("KILN_INJECT_BACKEND_ERROR", "LitPassFragment")
        .output()
        .expect("kiln runs");
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("error[K0409]: the WGSL writer failed: fault injected"), "{stderr}");
    assert!(stderr.contains("naga validated the module"), "{stderr}");
    // Once, naming every variant the failure occurs in (the bundled Lit pass has three).
    assert_eq!(stderr.matches("error[K0409]").count(), 1, "{stderr}");
    assert!(stderr.contains("in 3 variants `") && stderr.contains("fragment stage"), "{stderr}");
}

#[test]
fn the_issue_s_nested_two_row_matrix_warns_not_a_crash() {
    let run = kiln(&["check", "fixtures/warn/build/nested_two_row_matrix.shader"]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(0), "{stderr}");
    assert!(stderr.contains("warning[K0415]"), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
}

/// The variant count of a build's manifest.
fn variants(output: &Path) -> usize {
    let manifest = kiln::manifest::Manifest::read(output).expect("manifest");
    manifest.passes().map(|p| p.variants.len()).sum()
}

#[test]
fn a_build_without_the_variant_log_of_the_last_is_not_a_no_op() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = example_project_copy(dir.path());
    let output = dir.path().join("out");
    let log = dir.path().join("usage.jsonl");
    std::fs::write(
        &log,
        "{\"shader\":\"Custom RP/Lit\",\"pass\":0,\"keywords\":[\"_CLIPPING\",\"_PREMULTIPLY_ALPHA\"]}\n",
    )
    .expect("log");
    let plain = |extra: &[&str]| {
        let mut args = vec!["build", text(&project), "--output", text(&output)];
        args.extend_from_slice(extra);
        let run = kiln(&args);
        assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
        variants(&output)
    };
    let without = plain(&[]);
    let with = plain(&["--variants-from", text(&log)]);
    assert_eq!(with, without + 1, "the logged variant is built");
    assert_eq!(plain(&[]), without, "a plain build drops it again");
    assert_eq!(plain(&["--variants-from", text(&log)]), without + 1);
}

#[test]
fn a_shard_in_a_folder_holding_a_whole_build_writes_its_own_objects() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = example_project_copy(dir.path());
    let (whole, one, two, merged) =
        (dir.path().join("whole"), dir.path().join("one"), dir.path().join("two"), dir.path().join("merged"));
    assert_eq!(kiln(&["build", text(&project), "--output", text(&whole)]).status.code(), Some(0));
    // The first shard's folder holds a whole build already.
    assert_eq!(kiln(&["build", text(&project), "--output", text(&one)]).status.code(), Some(0));
    for (shard, folder) in [("1/2", &one), ("2/2", &two)] {
        let run = kiln(&["build", text(&project), "--shard", shard, "--output", text(folder)]);
        assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
    }
    let run = kiln(&["merge", text(&merged), text(&one), text(&two)]);
    assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
    let files = |folder: &Path| -> Vec<(PathBuf, Vec<u8>)> {
        tree(folder)
            .into_iter()
            .filter(|(p, _)| p.starts_with("modules") || p.ends_with("manifest.json"))
            .collect()
    };
    assert_eq!(files(&merged), files(&whole), "the merge is the whole build, byte for byte");
}

// ---------------------------------------------------------------------------------------------
// A renderer crate, built by cargo.

/// A crate with the README's build script over a small project of its own. Its build script
/// counts its runs in `runs.log`.
fn scratch_crate(dir: &Path) -> PathBuf {
    let krate = dir.join("renderer");
    let write = |path: &str, text: &str| {
        let path = krate.join(path);
        std::fs::create_dir_all(path.parent().expect("folder")).expect("mkdir");
        std::fs::write(path, text).expect("write");
    };
    write(
        "Cargo.toml",
        &format!(
            "[package]\nname = \"scratch-renderer\"\nversion = \"0.1.0\"\nedition = \"2024\"\npublish = false\n\n\
             [dependencies]\nbytemuck = {{ version = \"1\", features = [\"derive\", \"min_const_generics\"] }}\n\n\
             [build-dependencies]\nkiln = {{ path = {:?}, default-features = false }}\n\n[workspace]\n",
            root().display().to_string().replace('\\', "/")
        ),
    );
    write(
        "build.rs",
        "fn main() -> Result<(), kiln::BuildError> {\n    \
         use std::io::Write as _;\n    \
         let runs = concat!(env!(\"CARGO_MANIFEST_DIR\"), \"/runs.log\");\n    \
         let mut log = std::fs::OpenOptions::new().create(true).append(true).open(runs).expect(\"log\");\n    \
         writeln!(log, \"run\").expect(\"log\");\n    \
         kiln::Build::new(\"shaders\").materials(\"scene/materials\").run()?;\n    \
         Ok(())\n}\n",
    );
    write(
        "src/lib.rs",
        "#![allow(dead_code, non_snake_case, non_camel_case_types)]\n\
         pub mod shaders {\n    include!(concat!(env!(\"OUT_DIR\"), \"/kiln_shaders.rs\"));\n}\n",
    );
    write(
        "shaders/Tint.shader",
        "Shader \"Scratch/Tint\" {\n    Properties {\n        [Toggle(_RED)] _Red (\"Red\", Float) = 0\n    }\n    \
         SubShader {\n        Pass {\n            WGSLPROGRAM\n            #pragma shader_feature _RED\n            \
         #pragma vertex Vertex\n            #pragma fragment Fragment\n            #include \"Tint.wgsl\"\n            \
         @vertex fn Vertex(@location(0) p: vec3<f32>) -> @builtin(position) vec4<f32> { return vec4<f32>(p, 1.0); }\n            \
         @fragment fn Fragment() -> @location(0) vec4<f32> {\n#if defined(_RED)\n                \
         return vec4<f32>(tint(), 0.0, 0.0, 1.0);\n#else\n                return vec4<f32>(tint());\n#endif\n            }\n            \
         ENDWGSL\n        }\n    }\n}\n",
    );
    write("shaders/Tint.wgsl", "fn tint() -> f32 { return 0.25; }\n");
    write("scene/materials/Plain.mat", "shader = \"Scratch/Tint\"\n");
    krate
}

/// `cargo build` of the crate: its `OUT_DIR` and how many times its build script has run.
fn cargo_build(krate: &Path) -> (PathBuf, usize) {
    let run = crate::support::cargo_scratch(krate, &["build", "--message-format=json-render-diagnostics"]);
    assert!(run.status.success(), "cargo build failed:\n{}", String::from_utf8_lossy(&run.stderr));
    let stdout = String::from_utf8_lossy(&run.stdout);
    let out_dir = stdout
        .lines()
        .filter_map(|line| serde_json::from_str::<serde_json::Value>(line).ok())
        .find(|m| {
            m["reason"] == "build-script-executed"
                && m["package_id"].as_str().is_some_and(|p| p.contains("scratch-renderer"))
        })
        .and_then(|m| m["out_dir"].as_str().map(PathBuf::from))
        .expect("the build script's OUT_DIR");
    let runs = std::fs::read_to_string(krate.join("runs.log")).unwrap_or_default().lines().count();
    (out_dir, runs)
}

/// Every WGSL module kiln wrote into `OUT_DIR`, as one text.
fn built_wgsl(out_dir: &Path) -> String {
    tree(&out_dir.join("kiln"))
        .into_iter()
        .filter(|(path, _)| path.to_string_lossy().ends_with(".wgsl.pack"))
        .map(|(_, bytes)| String::from_utf8_lossy(&bytes).into_owned())
        .collect()
}

/// The keywords of every variant built into `OUT_DIR`.
fn built_keywords(out_dir: &Path) -> Vec<String> {
    let manifest = kiln::manifest::Manifest::read(&out_dir.join("kiln")).expect("manifest");
    manifest.passes().flat_map(|p| p.variants.iter().flat_map(|v| v.keywords.clone())).collect()
}

/// Cargo compares modification times; a second is more than any file system here needs.
fn tick() {
    std::thread::sleep(std::time::Duration::from_millis(1100));
}

#[test]
fn cargo_reruns_the_build_script_for_every_edit_kiln_reads_and_for_new_files_only_then() {
    if !crate::support::crate_tests(
        "cargo_reruns_the_build_script_for_every_edit_kiln_reads_and_for_new_files_only_then",
    ) {
        return;
    }
    let dir = tempfile::tempdir().expect("temp dir");
    let krate = scratch_crate(dir.path());
    let (out_dir, runs) = cargo_build(&krate);
    assert_eq!(runs, 1);
    assert!(built_wgsl(&out_dir).contains("0.25f"), "{}", built_wgsl(&out_dir));
    assert!(!built_keywords(&out_dir).contains(&"_RED".to_string()), "no material asks for _RED yet");

    // Nothing changed: cargo does not run the script.
    assert_eq!(cargo_build(&krate).1, 1, "a second build reruns nothing");

    // A shader touched, not changed: the script runs and kiln's no-op check answers.
    tick();
    let shader = krate.join("shaders/Tint.shader");
    std::fs::write(&shader, std::fs::read(&shader).expect("read")).expect("touch");
    assert_eq!(cargo_build(&krate).1, 2);

    // After that no-op run the include is still watched: editing it rebuilds the shaders.
    tick();
    std::fs::write(krate.join("shaders/Tint.wgsl"), "fn tint() -> f32 { return 0.75; }\n").expect("edit");
    let (out_dir, runs) = cargo_build(&krate);
    assert_eq!(runs, 3, "an edited include reruns the build script");
    assert!(built_wgsl(&out_dir).contains("0.75f"), "the new text is built");

    // A new material in a folder kiln searches reruns it too, and its variant is built.
    tick();
    std::fs::write(
        krate.join("scene/materials/Red.mat"),
        "shader = \"Scratch/Tint\"\n[properties]\n_Red = 1\n",
    )
    .expect("new material");
    let (out_dir, runs) = cargo_build(&krate);
    assert_eq!(runs, 4, "a new material reruns the build script");
    assert!(built_keywords(&out_dir).contains(&"_RED".to_string()), "the new material's variant is built");

    // And then nothing again.
    assert_eq!(cargo_build(&krate).1, 4);
}
