//! Shared helpers: paths into the repository, loading fixtures, running the `kiln` binary.

use kiln::config::VariantSelection;
use kiln::diagnostics::Diagnostic;
use kiln::project::{Request, build_project};
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
    kiln_in(root(), args)
}

/// The `kiln` binary run in `folder`.
pub fn kiln_in(folder: &Path, args: &[&str]) -> Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_kiln"))
        .args(args)
        .current_dir(folder)
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

/// A GPU device (lavapipe in CI), or `None` with the reason reported. `KILN_REQUIRE_GPU=1` (set
/// by CI) makes a missing adapter a failure instead.
pub fn gpu(test: &str) -> Option<kiln::accuracy::gpu::Gpu> {
    device_or_skip(
        test,
        kiln::accuracy::gpu::device(),
        "lavapipe runs them: apt-get install mesa-vulkan-drivers libvulkan1",
    )
}

/// A device on wgpu's OpenGL back end (Mesa's llvmpipe through EGL in CI), as [`gpu`] gives one.
pub fn gl_gpu(test: &str) -> Option<kiln::accuracy::gpu::Gpu> {
    device_or_skip(
        test,
        kiln::accuracy::gpu::gl_device(),
        "Mesa's OpenGL runs it: apt-get install libegl1 libgl1-mesa-dri",
    )
}

fn device_or_skip(
    test: &str,
    device: Result<kiln::accuracy::gpu::Gpu, String>,
    install: &str,
) -> Option<kiln::accuracy::gpu::Gpu> {
    match device {
        Ok(gpu) => Some(gpu),
        Err(reason) => {
            assert!(
                std::env::var("KILN_REQUIRE_GPU").as_deref() != Ok("1"),
                "KILN_REQUIRE_GPU=1 but {reason}"
            );
            skipped(&format!("{test}: {reason}; {install}"));
            None
        }
    }
}

/// The full tier: `KILN_TESTS=full` (set by `.ci/run`) runs every test CI runs; without it,
/// `cargo test` is the fast tier, which leaves out the few tests whose cost is size, not
/// coverage (the public corpora whole, the accuracy pictures, crates compiled on kiln), each
/// with a counted line saying how to run it.
pub fn full_tier(test: &str, cost: &str) -> bool {
    let run = std::env::var("KILN_TESTS").as_deref() == Ok("full");
    if !run {
        skipped(&format!("{test}: {cost}; in the full tier, KILN_TESTS=full runs it"));
    }
    run
}

/// Whether to run a test that compiles a crate depending on kiln with cargo (a renderer built
/// from the docs with wgpu, a build script's crate): on 2 cores their first run compiles kiln
/// and wgpu once more, about 7 minutes. The full tier runs them, and so does
/// `KILN_CRATE_TESTS=1` alone.
pub fn crate_tests(test: &str) -> bool {
    std::env::var("KILN_CRATE_TESTS").as_deref() == Ok("1")
        || full_tier(test, "compiles a crate on kiln (minutes on 2 cores)")
}

/// A one-level 2D texture of `size`.
pub fn texture(
    device: &wgpu::Device,
    size: wgpu::Extent3d,
    format: wgpu::TextureFormat,
    usage: wgpu::TextureUsages,
) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: None,
        size,
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage,
        view_formats: &[],
    })
}

/// A buffer of `size` bytes to copy results into and map for reading.
pub fn readback(device: &wgpu::Device, size: u64) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size,
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    })
}

/// Reports a skipped check where it stays visible: straight to the process's stderr, which the
/// test harness does not capture (a passing test's `println!` is hidden), numbered so that the
/// run shows how many were skipped.
pub fn skipped(what: &str) {
    use std::io::Write as _;
    static SKIPPED: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = SKIPPED.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
    let _ = writeln!(std::io::stderr(), "SKIPPED ({n} in this run so far) {what}");
}

/// The manifest in `output`, after checking that every module it names is in its pack, whole,
/// with its hash.
pub fn verified_manifest(output: &Path) -> kiln::manifest::Manifest {
    let manifest: kiln::manifest::Manifest =
        serde_json::from_slice(&std::fs::read(output.join("manifest.json")).expect("manifest"))
            .expect("manifest parses");
    for file in manifest.files() {
        let bytes = file.read(output).expect("module in its pack");
        assert_eq!(bytes.len() as u64, file.size);
        assert_eq!(&blake3::hash(&bytes).to_hex()[..32], file.hash, "{} is intact", file.path);
    }
    manifest
}

/// A project with one shader of eight fragment keyword sets and `materials` materials.
pub fn synthetic_project(dir: &Path, materials: usize) {
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

/// Builds a project that must build without a diagnostic, into `output` or its own output folder.
pub fn build_clean(project: &Path, output: Option<&Path>) -> kiln::orchestrate::BuildSummary {
    let (summary, diagnostics) = build_without_errors(project, output, VariantSelection::Used);
    assert!(diagnostics.is_empty(), "{diagnostics}");
    summary
}

/// Builds a project that must build without an error; returns the warnings, rendered.
pub fn build_without_errors(
    project: &Path,
    output: Option<&Path>,
    unused_shaders: VariantSelection,
) -> (kiln::orchestrate::BuildSummary, String) {
    let mut store = SourceStore::new();
    let mode = Request { output: output.map(Path::to_path_buf), unused_shaders, ..Request::default() };
    let (result, mut diagnostics) =
        build_project(&mut store, &[project.to_path_buf()], &mode, &|_, _| {}).expect("project");
    diagnostics.extend(result.diagnostics);
    let rendered = kiln::diagnostics::render_plain(&store, &diagnostics);
    assert!(!kiln::diagnostics::has_errors(&diagnostics), "{}:\n{rendered}", project.display());
    (result.summary, rendered)
}

/// A fixture project (a folder under `fixtures/`) built without errors into a new temporary
/// folder, which is returned.
pub fn built_fixture(project: &str) -> tempfile::TempDir {
    let output = tempfile::tempdir().expect("temp dir");
    build_without_errors(&root().join("fixtures").join(project), Some(output.path()), VariantSelection::Used);
    output
}

/// Every file under `folder`, relative, with its bytes.
pub fn tree(folder: &Path) -> std::collections::BTreeMap<PathBuf, Vec<u8>> {
    walkdir::WalkDir::new(folder)
        .into_iter()
        .map(|e| e.expect("walk"))
        .filter(|e| e.file_type().is_file())
        .map(|e| {
            (
                e.path().strip_prefix(folder).expect("inside").to_path_buf(),
                std::fs::read(e.path()).expect("read"),
            )
        })
        .collect()
}

/// What a build ships: every file of the output folder but its cache (which may keep entries of
/// other states: they are verified when read).
pub fn shipped(output: &Path) -> std::collections::BTreeMap<PathBuf, Vec<u8>> {
    let mut files = tree(output);
    files.retain(|path, _| !path.starts_with(".cache"));
    files
}

/// The number of stage modules a build's summary line says it compiled.
pub fn compiled(summary: &str) -> usize {
    let at = summary.find(" compiled,").expect("a summary line");
    summary[..at].rsplit('(').next().expect("count").parse().expect("number")
}

/// The shaders, passes and variants a build's summary line says it built (`built 3 shaders,
/// 3 passes, 10 variants: ...`).
pub fn built_counts(summary: &str) -> [usize; 3] {
    let counts = summary.split(':').next().expect("a summary line");
    let numbers: Vec<usize> =
        counts.split(|c: char| !c.is_ascii_digit()).filter_map(|n| n.parse().ok()).collect();
    numbers.try_into().unwrap_or_else(|numbers| panic!("three counts in {summary:?}, not {numbers:?}"))
}

/// Whether a command other tests compare with is installed (`spirv-val`, gcc's `cpp`); without it
/// the test is skipped with the reason printed, unless `KILN_REQUIRE_TOOLS=1` (set by CI) makes
/// its absence a failure.
pub fn tool(name: &str, debian_package: &str, test: &str) -> bool {
    let found = std::process::Command::new(name).arg("--version").output().is_ok_and(|o| o.status.success());
    if !found {
        assert!(std::env::var_os("KILN_REQUIRE_TOOLS").is_none(), "{test}: `{name}` is required but missing");
        // Counted and seen, as a missing GPU is: a passing test's `println!` would be hidden.
        skipped(&format!("{test}: `{name}` is not installed (Debian: apt-get install {debian_package})"));
    }
    found
}

/// Runs cargo on a scratch crate the tests wrote (a renderer's build script, generated Rust), in a
/// target folder of its own that outlives the test, so that its dependencies (kiln as a
/// build-dependency, bytemuck) compile once per machine. The crate carries a copy of kiln's
/// `Cargo.lock` so that `--offline` finds every version.
pub fn cargo_scratch(krate: &Path, args: &[&str]) -> Output {
    std::fs::copy(root().join("Cargo.lock"), krate.join("Cargo.lock")).expect("lock file");
    std::process::Command::new(env!("CARGO"))
        .arg("--offline")
        .args(args)
        .current_dir(krate)
        .env("CARGO_TARGET_DIR", root().join("target/scratch-crates"))
        // Debug info of a crate that is only compiled and run once would cost gigabytes of disk.
        .env("CARGO_PROFILE_DEV_DEBUG", "false")
        .env_remove("RUSTFLAGS")
        .output()
        .expect("cargo runs")
}

/// A scratch crate in `krate` that compiles a generated module as `src/shaders.rs`, with
/// bytemuck and the build's output folder `packs` copied to `src/PACKS_NAME` (as a build script's
/// `OUT_DIR` holds them), and `lib` as its `src/lib.rs`.
pub fn generated_module_crate(krate: &Path, module: &str, packs: (&Path, &str), lib: &str) {
    std::fs::create_dir_all(krate.join("src")).expect("crate");
    std::fs::write(
        krate.join("Cargo.toml"),
        "[package]\nname = \"kiln-generated-check\"\nversion = \"0.1.0\"\nedition = \"2024\"\npublish = false\n\n\
         [dependencies]\nbytemuck = { version = \"1\", features = [\"derive\", \"min_const_generics\"] }\n\n[workspace]\n",
    )
    .expect("Cargo.toml");
    for (path, bytes) in tree(packs.0) {
        let to = krate.join("src").join(packs.1).join(path);
        std::fs::create_dir_all(to.parent().expect("folder")).expect("mkdir");
        std::fs::write(to, bytes).expect("pack");
    }
    std::fs::write(krate.join("src/shaders.rs"), module).expect("module");
    std::fs::write(krate.join("src/lib.rs"), lib).expect("lib.rs");
}

/// The generated module of a build script's output folder `out` (`out/kiln_shaders.rs`, packs in
/// `out/kiln`) in a scratch crate at `out/crate` with `lib` as its `src/lib.rs`, and its tests
/// run by cargo, which must pass. Returns the crate's folder.
pub fn test_generated_module(out: &Path, lib: &str) -> PathBuf {
    let module = std::fs::read_to_string(out.join("kiln_shaders.rs")).expect("generated");
    let krate = out.join("crate");
    generated_module_crate(&krate, &module, (&out.join("kiln"), "kiln"), lib);
    let run = cargo_scratch(&krate, &["test"]);
    assert!(
        run.status.success(),
        "the generated module's tests fail:\n{}{}",
        String::from_utf8_lossy(&run.stdout),
        String::from_utf8_lossy(&run.stderr)
    );
    krate
}

/// A copy of the bundled example project (without build output) in `dir/project`.
pub fn example_project_copy(dir: &Path) -> PathBuf {
    fixture_copy(dir, "project")
}

/// A copy of `fixtures/<name>` (its build output left out) in `dir/<name>`.
pub fn fixture_copy(dir: &Path, name: &str) -> PathBuf {
    let project = dir.join(name);
    copy_tree(&root().join("fixtures").join(name), &project);
    project
}

/// Every file under `from` (a `build` folder at its top left out) copied to the same place under
/// `to`; `from` may also be one file, copied to `to`.
pub fn copy_tree(from: &Path, to: &Path) {
    for entry in walkdir::WalkDir::new(from).into_iter().filter_map(Result::ok) {
        let relative = entry.path().strip_prefix(from).expect("inside");
        if entry.file_type().is_file() && !relative.starts_with("build") {
            let target = if relative.as_os_str().is_empty() { to.to_path_buf() } else { to.join(relative) };
            std::fs::create_dir_all(target.parent().expect("folder")).expect("mkdir");
            std::fs::copy(entry.path(), target).expect("copy");
        }
    }
}

/// Waits for a process that must end by itself, failing the test (and killing it) after 60 s:
/// a hang is a failure, not a stuck test run.
pub fn output_within_a_minute(mut child: std::process::Child, what: &str) -> Output {
    let started = std::time::Instant::now();
    while child.try_wait().expect("waits").is_none() {
        if started.elapsed() > std::time::Duration::from_secs(60) {
            let _ = child.kill();
            panic!("{what} did not end");
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.wait_with_output().expect("ends")
}

/// The test binary's allocator: the system's, counting each thread's allocations so that a test
/// can show a hot path allocates nothing ([`allocations_in`]).
pub struct CountingAllocator;

thread_local! {
    static ALLOCATIONS: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

fn count_allocation() {
    // No destructor to run, so it is there at every point of a thread's life; `try_with` all
    // the same, since an allocator must never panic.
    let _ = ALLOCATIONS.try_with(|count| count.set(count.get() + 1));
}

// SAFETY: every call is passed to `System` unchanged; counting touches no allocation.
unsafe impl std::alloc::GlobalAlloc for CountingAllocator {
    unsafe fn alloc(&self, layout: std::alloc::Layout) -> *mut u8 {
        count_allocation();
        // SAFETY: the caller keeps `GlobalAlloc::alloc`'s contract, which is `System`'s.
        unsafe { std::alloc::System.alloc(layout) }
    }
    unsafe fn alloc_zeroed(&self, layout: std::alloc::Layout) -> *mut u8 {
        count_allocation();
        // SAFETY: as `alloc`.
        unsafe { std::alloc::System.alloc_zeroed(layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: std::alloc::Layout, new_size: usize) -> *mut u8 {
        count_allocation();
        // SAFETY: `ptr` came from this allocator, which is `System`.
        unsafe { std::alloc::System.realloc(ptr, layout, new_size) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: std::alloc::Layout) {
        // SAFETY: as `realloc`.
        unsafe { std::alloc::System.dealloc(ptr, layout) }
    }
}

/// How many allocations (and reallocations) `run` made on this thread.
pub fn allocations_in(run: impl FnOnce()) -> u64 {
    let before = ALLOCATIONS.with(std::cell::Cell::get);
    run();
    ALLOCATIONS.with(std::cell::Cell::get) - before
}
