//! Shared helpers: paths into the repository, loading fixtures, running the `kiln` binary.

use kiln::diagnostics::Diagnostic;
use kiln::source::{FileId, SourceStore};
use std::path::{Path, PathBuf};
use std::process::Output;

/// The repository root (tests run with it as the working directory, but do not rely on that).
pub fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The files with this extension directly in a fixtures folder, sorted, as paths relative to
/// the root so that diagnostics name them the same way on every machine.
pub fn fixture_files(folder: &str, extension: &str) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(root().join(folder))
        .expect("fixture folder exists")
        .map(|entry| entry.expect("readable entry").path())
        .filter(|path| path.extension().is_some_and(|e| e == extension))
        .map(|path| Path::new(folder).join(path.file_name().expect("file name")))
        .collect();
    files.sort();
    files
}

/// Loads relative paths into a store, from the repository root.
pub fn load(paths: &[PathBuf]) -> (SourceStore, Vec<FileId>, Vec<Diagnostic>) {
    // Fixture paths are relative: cargo runs integration tests from the package root.
    assert_eq!(std::env::current_dir().expect("cwd"), root(), "tests run from the package root");
    let mut store = SourceStore::new();
    let (ids, diagnostics) = kiln::project::load_files(&mut store, paths);
    (store, ids, diagnostics)
}

/// Runs the built `kiln` binary from the repository root.
pub fn kiln(args: &[&str]) -> Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_kiln"))
        .args(args)
        .current_dir(root())
        .env("NO_COLOR", "1")
        .output()
        .expect("kiln binary runs")
}

/// Pins a fixture's diagnostics in the `.stderr` file beside it, after checking that there are
/// some and that they include an error exactly when one is expected.
pub fn assert_pinned(fixture: &Path, store: &SourceStore, diagnostics: &[Diagnostic], expect_errors: bool) {
    let rendered = kiln::diagnostics::render_plain(store, diagnostics);
    let errors = kiln::diagnostics::has_errors(diagnostics);
    assert_eq!(errors, expect_errors, "{}: errors expected: {expect_errors}\n{rendered}", fixture.display());
    assert!(!diagnostics.is_empty(), "{} reports nothing", fixture.display());
    expect_test::expect_file![root().join(fixture.with_extension("stderr"))].assert_eq(&rendered);
}

/// A GPU device (lavapipe in CI), or `None` with the reason printed. `KILN_REQUIRE_GPU=1` (set
/// by CI) makes a missing adapter a failure instead.
pub fn gpu(test: &str) -> Option<kiln::accuracy::gpu::Gpu> {
    match kiln::accuracy::gpu::device() {
        Ok(gpu) => Some(gpu),
        Err(reason) => {
            assert!(
                std::env::var("KILN_REQUIRE_GPU").as_deref() != Ok("1"),
                "KILN_REQUIRE_GPU=1 but {reason}"
            );
            println!("skipping {test}: {reason}; install mesa-vulkan-drivers for lavapipe");
            None
        }
    }
}

/// The manifest in `output`, after checking that every module it names is in its pack, whole,
/// with its hash.
pub fn verified_manifest(output: &Path) -> kiln::reflect::manifest::Manifest {
    let manifest: kiln::reflect::manifest::Manifest =
        serde_json::from_slice(&std::fs::read(output.join("manifest.json")).expect("manifest"))
            .expect("manifest parses");
    for file in manifest.files() {
        let bytes = file.read(output).expect("module in its pack");
        assert_eq!(bytes.len() as u64, file.size);
        assert_eq!(&blake3::hash(&bytes).to_hex()[..32], file.hash, "{} is intact", file.path);
    }
    manifest
}
