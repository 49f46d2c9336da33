//! Metal, DX12 and GL: every module written through naga's MSL, HLSL and GLSL writers, the GLSL
//! and HLSL read back by Khronos' glslangValidator (a reader nobody here wrote), Metal's slots
//! checked against the pass's layout, and each writer failure a located diagnostic.

use crate::support::{kiln, root, tool, verified_manifest};
use expect_test::expect_file;
use kiln::diagnostics::render_plain;
use kiln::manifest::{Backend, Manifest};
use kiln::project::{Request, build_project};
use kiln::source::SourceStore;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// The bundled project built with every back end into `output`.
fn build_every_backend(output: &Path) -> Manifest {
    let mut store = SourceStore::new();
    let mode = Request {
        output: Some(output.to_path_buf()),
        backends: Backend::ALL.to_vec(),
        threads: Some(2),
        ..Request::default()
    };
    let (result, mut diagnostics) =
        build_project(&mut store, &[PathBuf::from("fixtures/project")], &mode, &|_, _| {}).expect("exists");
    diagnostics.extend(result.diagnostics);
    assert!(diagnostics.is_empty(), "{}", render_plain(&store, &diagnostics));
    verified_manifest(output)
}

/// Each module's text in `backend`'s language, with its stage and entry point.
fn modules(manifest: &Manifest, output: &Path, backend: Backend) -> Vec<(String, String, String)> {
    let mut found = Vec::new();
    for pass in manifest.passes() {
        for module in &pass.modules {
            let file = module.file(backend).unwrap_or_else(|| panic!("a {backend} module of every module"));
            let pack = std::fs::read(output.join(&pass.packs[file.pack])).expect("pack");
            let text = &pack[file.offset as usize..(file.offset + file.size) as usize];
            let interface = &pass.interfaces[module.interface];
            found.push((
                String::from_utf8(text.to_vec()).expect("text"),
                interface.stage.name().to_string(),
                interface.entry_point.clone(),
            ));
        }
    }
    found
}

#[test]
fn the_example_project_checks_clean_on_every_backend() {
    let run = kiln(&["check", "fixtures/project", "--backends", "msl,hlsl,glsl"]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("error") && !stderr.contains("warning"), "{stderr}");
    let run = kiln(&["check", "fixtures/project", "--backends", "msl,vulkan"]);
    assert_eq!(run.status.code(), Some(2), "an unknown back end is refused by the command line");
    assert!(
        String::from_utf8_lossy(&run.stderr)
            .contains("no back end `vulkan` (did you mean `spirv`?); kiln writes wgsl, spirv, msl")
    );
}

#[test]
fn glslang_accepts_every_glsl_and_hlsl_module_kiln_writes() {
    if !tool("glslangValidator", "glslang-tools", "glslang_accepts_every_glsl_and_hlsl_module_kiln_writes") {
        return;
    }
    let output = tempfile::tempdir().expect("temp dir");
    let manifest = build_every_backend(output.path());
    let mut read = 0;
    for backend in [Backend::Glsl, Backend::Hlsl] {
        for (text, stage, entry) in modules(&manifest, output.path(), backend) {
            let stage = match stage.as_str() {
                "vertex" => "vert",
                "fragment" => "frag",
                _ => "comp",
            };
            let mut command = Command::new("glslangValidator");
            command.args(["--stdin", "-S", stage]);
            if backend == Backend::Hlsl {
                command.args(["-D", "-V", "-e", &entry, "-o", "/dev/null"]);
            } else {
                assert!(text.starts_with("#version 300 es"), "GLSL ES 3.00: {text}");
            }
            let mut child =
                command.stdin(Stdio::piped()).stdout(Stdio::piped()).spawn().expect("glslang runs");
            std::io::Write::write_all(&mut child.stdin.take().expect("stdin"), text.as_bytes())
                .expect("write");
            let said = child.wait_with_output().expect("glslang ends");
            assert!(
                said.status.success(),
                "{backend} of `{entry}`:\n{}\n{text}",
                String::from_utf8_lossy(&said.stdout)
            );
            read += 1;
        }
    }
    // Every module of the manifest, in both languages.
    let modules: usize = manifest.passes().map(|pass| pass.modules.len()).sum();
    assert_eq!((read, modules > 10), (2 * modules, true));
}

#[test]
fn metal_slots_are_numbered_per_kind_in_the_order_of_the_pass_layout() {
    let output = tempfile::tempdir().expect("temp dir");
    let manifest = build_every_backend(output.path());
    let mut checked = 0;
    for pass in manifest.passes() {
        for module in &pass.modules {
            let interface = &pass.interfaces[module.interface];
            let file = module.msl.as_ref().expect("MSL written");
            let pack = std::fs::read(output.path().join(&pass.packs[file.pack])).expect("pack");
            let text =
                String::from_utf8_lossy(&pack[file.offset as usize..(file.offset + file.size) as usize]);
            // Metal numbers buffers, textures and samplers apart, each in (group, binding) order.
            let mut used = interface.bindings.clone();
            used.sort();
            let mut counters = std::collections::HashMap::new();
            for [group, binding] in used {
                let entry = pass
                    .layout
                    .iter()
                    .find(|g| g.group == group)
                    .and_then(|g| g.entries.iter().find(|e| e.binding == binding))
                    .expect("the layout has every binding a module uses");
                let kind = match serde_json::to_value(&entry.resource).expect("json")["kind"].as_str() {
                    Some("uniform" | "storage") => "buffer",
                    Some("sampler") => "sampler",
                    _ => "texture",
                };
                let slot = counters.entry(kind).or_insert(0);
                let expected = format!("{} [[{kind}({slot})]]", entry.name);
                assert!(text.contains(&expected), "`{expected}` in {}:\n{text}", interface.entry_point);
                *slot += 1;
                checked += 1;
            }
        }
    }
    assert!(checked >= 30, "{checked} resources checked");
}

#[test]
fn writer_failures_are_located_diagnostics_and_nothing_panics() {
    let mut store = SourceStore::new();
    let mode = Request { write: false, threads: Some(1), ..Request::default() };
    let path = PathBuf::from("fixtures/bad/backends");
    let (result, mut diagnostics) = build_project(&mut store, &[path], &mode, &|_, _| {}).expect("exists");
    diagnostics.extend(result.diagnostics);
    expect_file![root().join("fixtures/bad/backends/kiln.stderr")]
        .assert_eq(&render_plain(&store, &diagnostics));
    // The same through the command line: exit 1, naga's panic not printed.
    let run = kiln(&["check", "fixtures/bad/backends"]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(!stderr.contains("panicked at") && stderr.contains("error[K0416]"), "{stderr}");
}

#[test]
fn glslang_refusing_what_naga_wrote_is_a_diagnostic_at_the_entry_point() {
    if !tool("glslangValidator", "glslang-tools", "glslang_refusing_what_naga_wrote_is_a_diagnostic") {
        return;
    }
    // No module of the suite is refused any more; debug builds can spoil one (K0423).
    let dir = tempfile::tempdir().expect("temp dir");
    let project = crate::support::example_project_copy(dir.path());
    let run = Command::new(env!("CARGO_BIN_EXE_kiln"))
        .args(["check", project.to_str().expect("path"), "--backends", "glsl"])
        .env("NO_COLOR", "1")
        .env("KILN_INJECT_GLSLANG_ERROR", "LitPassFragment")
        .output()
        .expect("kiln runs");
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    let shown = stderr.replace(&project.display().to_string(), "PROJECT");
    let shown: String =
        shown.lines().filter(|l| !l.starts_with("checked ")).map(|l| format!("{l}\n")).collect();
    expect_file![root().join("tests/golden/backends/glslang.stderr")].assert_eq(&shown);
}

/// A module-scope array value (a full-screen triangle, as iced's blit and egui's texture copy
/// draw it) is HLSL glslang's linker calls recursive: `kiln check --backends hlsl` lets that
/// gap through, as `kiln build` writes the module, and says nothing of it.
#[test]
fn glslang_s_recursion_on_a_module_scope_array_value_is_let_through() {
    if !tool("glslangValidator", "glslang-tools", "glslang_s_recursion_on_a_module_scope_array_value") {
        return;
    }
    let project = root().join("fixtures/hlsl_recursion_gap");
    let run = Command::new(env!("CARGO_BIN_EXE_kiln"))
        .args(["check", project.to_str().expect("path"), "--backends", "hlsl"])
        .env("NO_COLOR", "1")
        .output()
        .expect("kiln runs");
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success() && !stderr.contains("K0423"), "{stderr}");
    // glslang itself, on the HLSL naga writes, still says so: the gap is glslang's, not gone.
    let output = tempfile::tempdir().expect("temp dir");
    let built = Command::new(env!("CARGO_BIN_EXE_kiln"))
        .args(["build", project.to_str().expect("path"), "--backends", "wgsl,hlsl", "--output"])
        .arg(output.path())
        .output()
        .expect("kiln runs");
    assert!(built.status.success(), "{}", String::from_utf8_lossy(&built.stderr));
    let manifest = kiln::manifest::Manifest::read(output.path()).expect("manifest");
    let (text, _, entry) = modules(&manifest, output.path(), Backend::Hlsl)
        .into_iter()
        .find(|(_, stage, _)| stage == "vertex")
        .expect("the vertex module");
    let mut child = Command::new("glslangValidator")
        .args(["--stdin", "-S", "vert", "-D", "-V", "-e", &entry, "-o", "/dev/null"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .expect("glslang runs");
    child.stdin.take().expect("stdin").write_all(text.as_bytes()).expect("fed");
    let said = String::from_utf8_lossy(&child.wait_with_output().expect("glslang ends").stdout).to_string();
    assert!(said.contains("Recursion detected"), "{said}");
}

/// Whether process `pid` is gone (or a zombie nobody has reaped yet: it runs no more).
#[cfg(target_os = "linux")]
fn ended(pid: &str) -> bool {
    std::fs::read_to_string(format!("/proc/{pid}/stat"))
        .map_or(true, |stat| stat.rsplit(')').next().is_some_and(|rest| rest.trim_start().starts_with('Z')))
}

#[cfg(target_os = "linux")]
#[test]
fn a_glslang_child_ends_with_a_killed_kiln() {
    // A stand-in for glslangValidator that says its process id and then takes its time.
    let dir = tempfile::tempdir().expect("temp dir");
    let bin = dir.path().join("bin");
    std::fs::create_dir_all(&bin).expect("mkdir");
    let pids = dir.path().join("pids");
    let script = format!(
        "#!/bin/sh\nif [ \"$1\" = --version ]; then echo 'Glslang Version: stand-in {}'; exit 0; fi\necho $$ >> '{}'\nexec sleep 120\n",
        dir.path().display(),
        pids.display()
    );
    std::fs::write(bin.join("glslangValidator"), script).expect("write");
    let mut permissions = std::fs::metadata(bin.join("glslangValidator")).expect("meta").permissions();
    std::os::unix::fs::PermissionsExt::set_mode(&mut permissions, 0o755);
    std::fs::set_permissions(bin.join("glslangValidator"), permissions).expect("chmod");
    let path = format!("{}:{}", bin.display(), std::env::var("PATH").unwrap_or_default());
    let mut kiln = Command::new(env!("CARGO_BIN_EXE_kiln"))
        .args(["check", "fixtures/project", "--backends", "glsl", "--cache-dir"])
        .arg(dir.path().join("cache"))
        .current_dir(root())
        .env("PATH", path)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("kiln runs");
    let started = std::time::Instant::now();
    let first = loop {
        let said = std::fs::read_to_string(&pids).unwrap_or_default();
        if let Some(pid) = said.lines().next() {
            break pid.to_string();
        }
        assert!(started.elapsed() < std::time::Duration::from_secs(60), "glslang never started");
        std::thread::sleep(std::time::Duration::from_millis(20));
    };
    kiln.kill().expect("kill");
    kiln.wait().expect("kiln ends");
    let killed = std::time::Instant::now();
    // Every stand-in started (one per worker thread) ends with kiln, not two minutes later.
    while killed.elapsed() < std::time::Duration::from_secs(10) {
        let said = std::fs::read_to_string(&pids).unwrap_or_default();
        if said.lines().all(ended) {
            assert!(said.lines().any(|pid| pid == first));
            return;
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    panic!("glslang children outlived kiln: {}", std::fs::read_to_string(&pids).unwrap_or_default());
}
