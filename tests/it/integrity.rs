//! Output integrity: a build killed half way leaves the previous manifest and its files intact
//! and the next build finishes; damaged cache entries and module files are detected by their
//! hashes and rebuilt, never used.

use crate::support::{root, verified_manifest};
use kiln::compile::VariantSelection;
use kiln::project::{BuildMode, build_project};
use kiln::reflect::manifest::Manifest;
use kiln::source::SourceStore;
use std::path::Path;
use std::time::Duration;

/// A project with one shader of eight fragment keyword sets and `materials` materials.
fn synthetic_project(dir: &Path, materials: usize) {
    let shaders = root().join("fixtures/project/shaders");
    std::fs::create_dir_all(dir.join("materials")).expect("mkdir");
    let pass = std::fs::read_to_string(shaders.join("LitPass.wgsl")).expect("LitPass");
    let tweaks: String =
        (0..8).map(|k| format!("#if defined(_F{k})\n    color = color * 1.0{k};\n#endif\n")).collect();
    let pass = pass.replace(
        "    let color = GetLighting(surface, brdf);\n",
        &format!("    var color = GetLighting(surface, brdf) * TINT;\n{tweaks}"),
    );
    std::fs::write(dir.join("SynthPass.wgsl"), pass).expect("write");
    std::fs::write(dir.join("Tint.wgsl"), "#define TINT 1.0\n").expect("write");
    // Lit's light-count multi_compile set is built for a renderer with several lights only.
    std::fs::write(dir.join("kiln.toml"), "global_keywords = []\n").expect("write");
    let pragmas: String =
        (0..8).map(|k| format!("            #pragma shader_feature_fragment _ _F{k}\n")).collect();
    let shader = std::fs::read_to_string(shaders.join("Lit.shader"))
        .expect("Lit")
        .replace(
            "#pragma shader_feature _PREMULTIPLY_ALPHA\n",
            &format!("#pragma shader_feature _PREMULTIPLY_ALPHA\n{pragmas}"),
        )
        .replace(
            "#include \"LitPass.wgsl\"",
            "#include \"Tint.wgsl\"\n            #include \"SynthPass.wgsl\"",
        );
    std::fs::write(dir.join("Synth.shader"), shader).expect("write");
    for m in 0..materials {
        let keywords: Vec<String> =
            (0..8).filter(|b| m & (1 << b) != 0).map(|b| format!("\"_F{b}\"")).collect();
        let text = format!("shader = \"Custom RP/Lit\"\nkeywords = [{}]\n", keywords.join(", "));
        std::fs::write(dir.join(format!("materials/M{m:03}.mat")), text).expect("write");
    }
}

fn build(project: &Path, output: &Path) -> kiln::compile::BuildSummary {
    let mut store = SourceStore::new();
    let mode = BuildMode {
        write: true,
        output: Some(output.to_path_buf()),
        unused_shaders: VariantSelection::Used,
        threads: None,
        global_keywords: None,
        pretty_manifest: false,
    };
    let (result, mut diagnostics) =
        build_project(&mut store, &[project.to_path_buf()], &mode, &|_, _| {}).expect("project");
    diagnostics.extend(result.diagnostics);
    assert!(diagnostics.is_empty(), "{}", kiln::diagnostics::render_plain(&store, &diagnostics));
    result.summary
}

/// The manifest in `output`, with every file it names checked against its hash.
#[test]
fn a_killed_build_leaves_the_previous_outputs_and_the_next_build_finishes() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (project, output) = (dir.path().join("project"), dir.path().join("out"));
    synthetic_project(&project, 160);
    build(&project, &output);
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
        let summary = build(&project, &output);
        assert_eq!(summary.variants, 160);
        verified_manifest(&output);
    }
}

#[test]
fn damaged_cache_entries_and_modules_are_rebuilt_never_used() {
    let dir = tempfile::tempdir().expect("temp dir");
    let output = dir.path().join("out");
    let first = build(&root().join("fixtures/project"), &output);
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
    let second = build(&root().join("fixtures/project"), &output);
    assert_eq!(second.compiled, first.compiled, "nothing damaged was trusted: everything compiled again");
    verified_manifest(&output);
    // And with everything repaired, a third build is a no-op again.
    let third = build(&root().join("fixtures/project"), &output);
    assert_eq!(third.compiled, 0);
}

#[test]
fn a_damaged_module_in_a_pack_is_recompiled_though_its_cache_entry_is_intact() {
    let dir = tempfile::tempdir().expect("temp dir");
    let output = dir.path().join("out");
    let first = build(&root().join("fixtures/project"), &output);
    let manifest = verified_manifest(&output);
    // Flip one byte inside one module (same size); the pass indexes stay as they were.
    let victim = manifest.files()[0].clone();
    let pack = output.join(&victim.path);
    let mut bytes = std::fs::read(&pack).expect("read");
    bytes[victim.offset as usize + victim.size as usize / 2] ^= 0x20;
    std::fs::write(&pack, &bytes).expect("write");
    // Forget that the last build was clean, as any edit would, so the build looks at each module.
    std::fs::remove_dir_all(output.join(".cache/build")).expect("remove the inputs record");
    let second = build(&root().join("fixtures/project"), &output);
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
