//! Output integrity: a build killed half way leaves the previous manifest and its files intact
//! and the next build finishes; damaged cache entries and module files are detected by their
//! hashes and rebuilt, never used.

use crate::support::{build_clean as build, root, synthetic_project, verified_manifest};
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
    let files: Vec<String> = manifest.files().iter().map(|f| f.path.clone()).collect();
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

#[test]
fn a_damaged_module_in_a_pack_is_recompiled_though_its_cache_entry_is_intact() {
    let dir = tempfile::tempdir().expect("temp dir");
    let output = dir.path().join("out");
    let first = build(&root().join("fixtures/project"), Some(&output));
    let manifest = verified_manifest(&output);
    // Flip one byte inside one module (same size); the pass indexes stay as they were.
    let victim = manifest.files()[0].clone();
    let pack = output.join(&victim.path);
    let mut bytes = std::fs::read(&pack).expect("read");
    bytes[victim.offset as usize + victim.size as usize / 2] ^= 0x20;
    std::fs::write(&pack, &bytes).expect("write");
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
