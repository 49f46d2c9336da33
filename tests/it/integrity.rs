//! Output integrity: a build killed half way leaves the previous manifest and its files intact
//! and the next build finishes; damaged cache entries and module files are detected by their
//! hashes and rebuilt, never used.

use crate::support::{build_clean as build, root, shipped, synthetic_project, verified_manifest};
use kiln::manifest::Manifest;
use std::time::Duration;

#[test]
fn a_killed_build_leaves_the_previous_outputs_and_the_next_build_finishes() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (project, output) = (dir.path().join("project"), dir.path().join("out"));
    synthetic_project(&project, 160);
    build(&project, Some(&output));
    let before = std::fs::read(output.join("manifest.json")).expect("manifest");
    for (round, delay) in [30u64, 120, 400].into_iter().enumerate() {
        // Every round changes what must be compiled, then kills the build part of the way in.
        std::fs::write(project.join("Tint.wgsl"), format!("#define TINT 1.{round}\n")).expect("write");
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_kiln"))
            .args(["build", project.to_str().expect("utf-8"), "--output", output.to_str().expect("utf-8")])
            .stderr(std::process::Stdio::null())
            .spawn()
            .expect("kiln starts");
        std::thread::sleep(Duration::from_millis(delay));
        let _ = child.kill();
        let _ = child.wait();
        // Either the old manifest or a complete new one, and every file it names is intact.
        let now = std::fs::read(output.join("manifest.json")).expect("a manifest is always there");
        verified_manifest(&output);
        if now != before {
            assert!(
                serde_json::from_slice::<Manifest>(&now).is_ok(),
                "a new manifest is only ever a whole one"
            );
        }
        let summary = build(&project, Some(&output));
        assert_eq!(summary.variants, 160);
        verified_manifest(&output);
    }
}

#[test]
fn damaged_cache_entries_and_modules_are_rebuilt_never_used() {
    let dir = tempfile::tempdir().expect("temp dir");
    let output = dir.path().join("out");
    let first = build(&root().join("fixtures/project"), Some(&output));
    let manifest = verified_manifest(&output);
    let files: Vec<String> = manifest.files().iter().map(|f| f.path.to_string()).collect();
    // Flip bytes in one module (same size), truncate another, and damage every pass index.
    let flipped = output.join(&files[0]);
    let mut bytes = std::fs::read(&flipped).expect("read");
    bytes[10] ^= 0x55;
    std::fs::write(&flipped, &bytes).expect("write");
    let truncated = output.join(&files[files.len() - 1]);
    let bytes = std::fs::read(&truncated).expect("read");
    std::fs::write(&truncated, &bytes[..bytes.len() / 2]).expect("write");
    for entry in std::fs::read_dir(output.join(".cache/pass")).expect("pass index").flatten() {
        let mut text = std::fs::read(entry.path()).expect("read");
        let last = text.len() - 2;
        text[last] ^= 0x01;
        std::fs::write(entry.path(), text).expect("write");
    }
    let second = build(&root().join("fixtures/project"), Some(&output));
    assert_eq!(second.compiled, first.compiled, "nothing damaged was trusted: everything compiled again");
    verified_manifest(&output);
    // And with everything repaired, a third build is a no-op again.
    let third = build(&root().join("fixtures/project"), Some(&output));
    assert_eq!(third.compiled, 0);
}

/// Flips one byte in the middle of the manifest's first module (its pack's length unchanged);
/// returns the module's reference.
fn flip_a_byte_of_the_first_module(manifest: &Manifest, output: &std::path::Path) -> kiln::manifest::FileRef {
    let victim = manifest.files()[0].clone();
    let pack = output.join(&victim.path);
    let mut bytes = std::fs::read(&pack).expect("read");
    bytes[victim.offset as usize + victim.size as usize / 2] ^= 0x20;
    std::fs::write(&pack, &bytes).expect("write");
    victim
}

#[test]
fn a_damaged_module_in_a_pack_is_recompiled_though_its_cache_entry_is_intact() {
    let dir = tempfile::tempdir().expect("temp dir");
    let output = dir.path().join("out");
    let first = build(&root().join("fixtures/project"), Some(&output));
    let manifest = verified_manifest(&output);
    // Flip one byte inside one module (same size); the pass indexes stay as they were.
    let victim = flip_a_byte_of_the_first_module(&manifest, &output);
    // Forget that the last build was clean, as any edit would, so the build looks at each module.
    std::fs::remove_dir_all(output.join(".cache/build")).expect("remove the inputs record");
    let second = build(&root().join("fixtures/project"), Some(&output));
    // The stage texts that compiled to those bytes are compiled again, and nothing else: at
    // least one, at most one per variant stage that uses the damaged module.
    let damaged: Vec<(usize, usize)> = manifest
        .passes()
        .enumerate()
        .flat_map(|(p, pass)| {
            let victim = &victim;
            (0..pass.modules.len())
                .filter(move |&m| {
                    pass.stage(m).files().any(|f| (&f.path, f.offset) == (&victim.path, victim.offset))
                })
                .map(move |m| (p, m))
        })
        .collect();
    let users: usize = manifest
        .passes()
        .enumerate()
        .flat_map(|(p, pass)| pass.variants.iter().flat_map(move |v| [v.vertex, v.fragment].map(|m| (p, m))))
        .filter(|(p, m)| m.is_some_and(|m| damaged.contains(&(*p, m))))
        .count();
    assert!(!damaged.is_empty());
    assert!(second.compiled >= 1 && second.compiled <= users && second.compiled < first.compiled);
    verified_manifest(&output);
}

/// `kiln build PROJECT --output OUTPUT`, killed (debug builds: `KILN_KILL_AT`) just before its
/// `kill_at`-th rename or link when given; whether it ran to its end.
fn build_killed_at(project: &std::path::Path, output: &std::path::Path, kill_at: Option<usize>) -> bool {
    let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_kiln"));
    command.args(["build", project.to_str().expect("utf-8"), "--output", output.to_str().expect("utf-8")]);
    if let Some(n) = kill_at {
        command.env("KILN_KILL_AT", n.to_string());
    }
    let run = command.output().expect("kiln runs");
    match run.status.code() {
        Some(0) => true,
        None => false,
        Some(code) => panic!("exit {code}: {}", String::from_utf8_lossy(&run.stderr)),
    }
}

/// The crash sweep: for every rename and link a build makes, a build of state B killed just before
/// it over a folder holding state A's build. The folder then holds A's or B's output whole (what
/// the run time opens is one build's, or it refuses a torn pair), and a build of A, then of B, is
/// byte for byte a clean build of each, never a no-op over the wrong files.
#[test]
fn a_kill_before_any_rename_or_link_leaves_nothing_a_later_build_trusts_wrongly() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = crate::support::example_project_copy(dir.path());
    let pass = project.join("shaders/UnlitPass.wgsl");
    let state_a = std::fs::read_to_string(&pass).expect("read");
    let state_b = state_a.replace("return base;", "return base * vec4<f32>(0.5, 0.5, 0.5, 1.0);");
    assert_ne!(state_a, state_b);
    let clean = |state: &str, name: &str| {
        std::fs::write(&pass, state).expect("write");
        let output = dir.path().join(name);
        assert!(build_killed_at(&project, &output, None));
        shipped(&output)
    };
    let (clean_a, clean_b) = (clean(&state_a, "clean_a"), clean(&state_b, "clean_b"));
    assert_ne!(clean_a, clean_b);
    let manifest = |files: &std::collections::BTreeMap<std::path::PathBuf, Vec<u8>>| {
        files.get(std::path::Path::new("manifest.json")).cloned().expect("a manifest")
    };
    let mut kill_at = 1;
    loop {
        let output = dir.path().join(format!("out{kill_at}"));
        std::fs::write(&pass, &state_a).expect("write");
        assert!(build_killed_at(&project, &output, None));
        std::fs::write(&pass, &state_b).expect("write");
        if build_killed_at(&project, &output, Some(kill_at)) {
            break;
        }
        // What a renderer would load now: one build's files, or a refusal.
        if let Ok(library) = kiln::runtime::Library::open(&output) {
            let opened = serde_json::to_vec(library.manifest()).expect("json");
            let as_a: Manifest = serde_json::from_slice(&manifest(&clean_a)).expect("manifest");
            let as_b: Manifest = serde_json::from_slice(&manifest(&clean_b)).expect("manifest");
            assert!(
                opened == serde_json::to_vec(&as_a).expect("json")
                    || opened == serde_json::to_vec(&as_b).expect("json"),
                "killed at {kill_at}: the run time opened a manifest of neither build"
            );
        }
        for (state, clean) in [(&state_a, &clean_a), (&state_b, &clean_b)] {
            std::fs::write(&pass, state).expect("write");
            assert!(build_killed_at(&project, &output, None));
            assert!(shipped(&output) == *clean, "killed at {kill_at}: a later build is not a clean one's");
        }
        kill_at += 1;
    }
    // Two packs, the pass index, the manifest and the record (the materials are the same in both).
    assert_eq!(kill_at - 1, 5, "the renames and links of a build of state B");
}

/// A build stopped between its two renames leaves new materials beside the old manifest (or the
/// reverse): the run time tells, by the hash the manifest names, and refuses the pair.
#[test]
fn the_run_time_refuses_materials_and_a_manifest_of_two_builds() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = crate::support::example_project_copy(dir.path());
    let (first, second) = (dir.path().join("first"), dir.path().join("second"));
    assert!(build_killed_at(&project, &first, None));
    let material = project.join("materials/LitOpaque.mat");
    let text = std::fs::read_to_string(&material).expect("read");
    assert!(text.contains("_Smoothness = 0.5"), "{text}");
    std::fs::write(&material, text.replace("_Smoothness = 0.5", "_Smoothness = 0.25")).expect("write");
    assert!(build_killed_at(&project, &second, None));
    assert!(kiln::runtime::Library::open(&first).is_ok());
    std::fs::copy(second.join("materials.json"), first.join("materials.json")).expect("copy");
    let Err(error) = kiln::runtime::Library::open(&first) else { panic!("a torn pair is refused") };
    assert!(error.to_string().contains("is not the one written with `manifest.json`"), "{error}");
}

/// A pack changed after the build (one byte) is refused where a renderer opens the build with the
/// module check, not handed to the driver.
#[test]
fn the_run_time_refuses_a_module_whose_bytes_are_not_the_manifest_s() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = crate::support::example_project_copy(dir.path());
    let output = dir.path().join("out");
    assert!(build_killed_at(&project, &output, None));
    let library = kiln::runtime::Library::open(&output).expect("opens");
    let file = library
        .manifest()
        .files()
        .into_iter()
        .find(|f| f.path.as_str().ends_with(".spv.pack"))
        .expect("a module");
    drop(library);
    let path = output.join(&file.path);
    let mut bytes = std::fs::read(&path).expect("read");
    bytes[file.offset as usize + 20] ^= 0x40;
    std::fs::write(&path, bytes).expect("write");
    assert!(kiln::runtime::Library::open(&output).is_ok(), "without the check, the bytes are not read");
    let Err(error) = kiln::runtime::Library::open_verified(&output) else {
        panic!("a damaged module is refused")
    };
    assert!(error.to_string().contains("is not what the manifest names"), "{error}");
}

#[cfg(target_os = "linux")]
#[test]
fn every_file_a_build_puts_in_place_is_durable_before_it_is_named() {
    if !crate::support::tool("strace", "strace", "every_file_a_build_puts_in_place_is_durable") {
        return;
    }
    let dir = tempfile::tempdir().expect("temp dir");
    let (output, log) = (dir.path().join("out"), dir.path().join("strace.log"));
    let run = std::process::Command::new("strace")
        .args(["-f", "-qq", "-e", "trace=fsync,fdatasync,rename,renameat,renameat2", "-o"])
        .arg(&log)
        .arg(env!("CARGO_BIN_EXE_kiln"))
        .args(["build", "fixtures/project", "--output"])
        .arg(&output)
        .current_dir(root())
        .output()
        .expect("strace runs");
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    let log = std::fs::read_to_string(&log).expect("the trace");
    let calls = |names: &[&str]| {
        log.lines()
            .filter(|l| names.iter().any(|n| l.contains(&format!(" {n}(")) && !l.contains("= -1")))
            .count()
    };
    let renames = calls(&["rename", "renameat", "renameat2"]);
    let syncs = calls(&["fsync", "fdatasync"]);
    assert!(renames >= 5, "{renames} renames:\n{log}");
    // Each file's data before its rename, and the packs' and the output's folders after theirs.
    assert!(syncs >= renames + 2, "{syncs} syncs for {renames} renames:\n{log}");
}

#[test]
fn a_pack_damaged_after_a_clean_build_is_not_kept_by_the_next_no_op() {
    let dir = tempfile::tempdir().expect("temp dir");
    let output = dir.path().join("out");
    let project = root().join("fixtures/project");
    build(&project, Some(&output));
    let manifest = verified_manifest(&output);
    // One byte inside one module, the pack's length unchanged, the record untouched.
    flip_a_byte_of_the_first_module(&manifest, &output);
    let next = build(&project, Some(&output));
    assert!(next.compiled >= 1, "the damaged pack was taken as in place: {next:?}");
    kiln::runtime::Library::open_verified(&output).expect("every module is the manifest's again");
    assert_eq!(build(&project, Some(&output)).compiled, 0, "and the build after it is a no-op");
}
