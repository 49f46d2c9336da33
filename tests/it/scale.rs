//! What a build leaves as projects grow and move: output independent of the folder a project sits
//! in, a moved project's rebuild a no-op, and a generated Rust module whose size follows distinct
//! modules, not variants times bytes.

use crate::support::{build_clean, synthetic_project};
use std::collections::BTreeMap;
use std::path::Path;

/// Every file under `folder`, by its path relative to it, with its bytes.
fn files_under(folder: &Path) -> BTreeMap<String, Vec<u8>> {
    walkdir::WalkDir::new(folder)
        .sort_by_file_name()
        .into_iter()
        .map(|entry| entry.expect("walk"))
        .filter(|entry| entry.file_type().is_file())
        .map(|entry| {
            let name = entry.path().strip_prefix(folder).expect("under").to_string_lossy().replace('\\', "/");
            (name, std::fs::read(entry.path()).expect("read"))
        })
        .collect()
}

/// Where a project builds by default (`build/kiln` under it).
fn default_output(project: &Path) -> std::path::PathBuf {
    let mut store = kiln::source::SourceStore::new();
    let (workspace, _) =
        kiln::project::open_workspace(&mut store, &[project.to_path_buf()]).expect("project");
    workspace.settings.output()
}

#[test]
fn a_project_builds_the_same_bytes_in_any_folder_and_a_moved_one_rebuilds_nothing() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (here, there) = (dir.path().join("here/project"), dir.path().join("some/where/else/project"));
    for project in [&here, &there] {
        synthetic_project(project, 24);
    }
    let first = build_clean(&here, None);
    build_clean(&there, None);
    let built = files_under(&default_output(&here));
    assert!(built.len() > 4 && built.contains_key("manifest.json"), "{:?}", built.keys());
    assert!(built.keys().any(|k| k.starts_with(".cache/pass/")), "the cache is compared too");
    assert_eq!(built, files_under(&default_output(&there)), "manifest, packs and cache are byte-identical");

    let moved = dir.path().join("moved/project");
    std::fs::create_dir_all(moved.parent().expect("parent")).expect("mkdir");
    std::fs::rename(&here, &moved).expect("move the project");
    let rebuilt = build_clean(&moved, None);
    assert_eq!((rebuilt.compiled, rebuilt.bytes_written), (0, 0), "a moved project is a no-op");
    assert_eq!(rebuilt.variants, first.variants);
    assert_eq!(files_under(&default_output(&moved)), built);
}

#[test]
fn the_generated_module_grows_with_modules_not_variants_times_bytes() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    synthetic_project(&project, 200);
    let output = kiln::Build::new(&project).out_dir(dir.path().join("out")).execute().expect("builds");
    let rust = std::fs::read_to_string(&output.module).expect("generated module");
    let manifest = &output.manifest;
    let variants: usize = manifest.passes().map(|p| p.variants.len()).sum();
    let modules: usize = manifest.passes().map(|p| p.modules.len()).sum();
    let packs = manifest.packs();
    let pack_bytes: u64 = packs.values().sum();
    assert_eq!((variants, modules), (200, 201), "one vertex module shared by every variant");
    // A fixed prelude (lookups of variants and kernels), a few constants per shader (its
    // keywords), a constant per material (its name), a row per module and a key and two indices
    // per variant.
    let materials: std::collections::BTreeSet<&String> =
        manifest.passes().flat_map(|p| p.variants.iter().flat_map(|v| &v.materials)).collect();
    let bound = 18_432 + 1_024 * manifest.shaders.len() + 48 * materials.len() + 64 * modules + 32 * variants;
    assert!(rust.len() < bound, "{} bytes, over {bound}", rust.len());
    assert!(
        (rust.len() as u64) * 20 < pack_bytes,
        "{} bytes of Rust for {pack_bytes} of modules",
        rust.len()
    );
    for path in packs.keys() {
        assert_eq!(rust.matches(&format!("\"kiln/{path}\"")).count(), 1, "{path} is embedded once");
    }
}

#[test]
fn the_no_op_check_sees_an_edited_include_and_a_file_that_would_shadow_one() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    synthetic_project(&project, 4);
    let first = build_clean(&project, None);
    assert!(first.compiled > 0);
    assert_eq!(build_clean(&project, None).compiled, 0, "nothing changed");

    // An include every stage text reads, whose macro only the fragment stage uses: every fragment
    // module is compiled again; the one vertex module, which does not reach it, is not (what it
    // reaches, and so its module, is unchanged).
    std::fs::write(project.join("Tint.wgsl"), "#define TINT 0.5\n").expect("write");
    let edited = build_clean(&project, None);
    assert_eq!(edited.compiled, first.compiled - 1);

    // `Common.wgsl` came from the bundled library after kiln looked beside the pass file: a file
    // there now comes first, so the build is no longer a no-op.
    let library = kiln::shaderlib::FILES.iter().find(|(name, _)| *name == "Common.wgsl").expect("Common");
    std::fs::write(project.join("Common.wgsl"), format!("{}\nconst SHADOWED: f32 = 1.0;\n", library.1))
        .expect("write");
    let shadowed = build_clean(&project, None);
    assert_eq!(shadowed.compiled, first.compiled, "every module includes Common.wgsl");
}

#[test]
fn a_deleted_include_is_reported_not_skipped_by_the_no_op_check() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    synthetic_project(&project, 2);
    build_clean(&project, None);
    std::fs::remove_file(project.join("Tint.wgsl")).expect("delete an include");
    let mut store = kiln::source::SourceStore::new();
    let mode = kiln::config::Request {
        unused_shaders: kiln::config::VariantSelection::Used,
        ..kiln::config::Request::default()
    };
    let (result, mut diagnostics) =
        kiln::project::build_project(&mut store, std::slice::from_ref(&project), &mode, &|_, _| {})
            .expect("project");
    diagnostics.extend(result.diagnostics);
    assert!(result.manifest.is_some(), "the build ran: it was not taken for a no-op");
    let shown = kiln::diagnostics::render_plain(&store, &diagnostics);
    assert!(shown.contains("Tint.wgsl"), "{shown}");
    assert!(kiln::diagnostics::has_errors(&diagnostics));
}
