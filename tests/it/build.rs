//! `kiln build` and `kiln check`: the example project builds with a golden manifest, layouts are
//! shared by a pass's variants, a second build compiles nothing, output is the same whatever the
//! thread count, and every bad build input has a pinned diagnostic.

use crate::support::{fixture_files, kiln, root, verified_manifest};
use expect_test::expect_file;
use kiln::config::VariantSelection;
use kiln::diagnostics::{Diagnostic, has_errors, render_plain};
use kiln::manifest::Manifest;
use kiln::orchestrate::BuildResult;
use kiln::project::{Request, build_project};
use kiln::source::SourceStore;
use naga::valid::{Capabilities, ValidationFlags};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn build_into(
    project: &str,
    output: &Path,
    threads: Option<usize>,
) -> (BuildResult, Vec<Diagnostic>, SourceStore) {
    build_with(project, output, threads, false)
}

fn build_with(
    project: &str,
    output: &Path,
    threads: Option<usize>,
    pretty_manifest: bool,
) -> (BuildResult, Vec<Diagnostic>, SourceStore) {
    let mut store = SourceStore::new();
    let mode = Request { output: Some(output.to_path_buf()), threads, pretty_manifest, ..Request::default() };
    let (result, diagnostics) =
        build_project(&mut store, &[PathBuf::from(project)], &mode, &|_, _| {}).expect("project exists");
    (result, diagnostics, store)
}

fn read_manifest(output: &Path) -> Manifest {
    serde_json::from_slice(&std::fs::read(output.join("manifest.json")).expect("manifest written"))
        .expect("manifest parses")
}

#[test]
fn the_example_project_builds_with_a_golden_manifest() {
    let output = tempfile::tempdir().expect("temp dir");
    let (result, mut diagnostics, store) = build_with("fixtures/project", output.path(), None, true);
    diagnostics.extend(result.diagnostics);
    assert!(diagnostics.is_empty(), "{}", render_plain(&store, &diagnostics));
    assert_eq!((result.summary.shaders, result.summary.passes, result.summary.variants), (3, 3, 10));
    let text = std::fs::read_to_string(output.path().join("manifest.json")).expect("manifest");
    // Pinned in a form to review: what fits a line is on one.
    let value: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    expect_file![root().join("tests/golden/build/manifest.json")].assert_eq(&(reviewable(&value, 0) + "\n"));

    // By default the same manifest is written compact, on one line.
    let compact = tempfile::tempdir().expect("temp dir");
    build_into("fixtures/project", compact.path(), None);
    let compact_text = std::fs::read_to_string(compact.path().join("manifest.json")).expect("manifest");
    assert_eq!(compact_text.lines().count(), 1);
    assert!(compact_text.len() * 2 < text.len(), "{} bytes against {}", compact_text.len(), text.len());
    // The same but for the hash of the materials written with it, which are indented too.
    let materials_apart = |mut manifest: Manifest| {
        assert!(manifest.materials_hash.take().is_some(), "the manifest names its materials' hash");
        manifest
    };
    assert_eq!(materials_apart(read_manifest(compact.path())), materials_apart(read_manifest(output.path())));

    // Every module named in the manifest is in its pack with its size and hash.
    verified_manifest(output.path());
}

/// JSON indented as `--pretty-manifest` writes it, but with every value that fits in 100
/// columns on one line: the same content in half the lines.
fn reviewable(value: &serde_json::Value, depth: usize) -> String {
    let one_line = serde_json::to_string(value).expect("JSON");
    let indent = "  ".repeat(depth + 1);
    let close = "  ".repeat(depth);
    match value {
        _ if one_line.len() + indent.len() <= 100 => one_line,
        serde_json::Value::Object(map) => {
            let fields: Vec<String> = map
                .iter()
                .map(|(key, v)| {
                    format!("{indent}{}: {}", serde_json::Value::from(key.as_str()), reviewable(v, depth + 1))
                })
                .collect();
            format!("{{\n{}\n{close}}}", fields.join(",\n"))
        }
        serde_json::Value::Array(items) => {
            let items: Vec<String> =
                items.iter().map(|v| format!("{indent}{}", reviewable(v, depth + 1))).collect();
            format!("[\n{}\n{close}]", items.join(",\n"))
        }
        _ => one_line,
    }
}

/// A compact manifest is written a shader at a time while the passes finish, in whatever order
/// they finish: the file must still be serde's writing of the whole manifest the build returns.
#[test]
fn the_manifest_written_while_passes_finish_is_the_whole_manifest_serialized() {
    let project = tempfile::tempdir().expect("temp dir");
    let kernels = std::fs::read_to_string(root().join("fixtures/compute/Scale.compute")).expect("Scale");
    let mut toml = String::from("shaders = [\".\"]\n");
    for n in 0..24 {
        let text = kernels.replace("* 2.0;", &format!("* {}.0;", n + 2));
        std::fs::write(project.path().join(format!("Scale{n}.compute")), text).expect("write");
        toml += &format!("\n[compute.Scale{n}]\nvariants = \"all\"\n");
    }
    std::fs::write(project.path().join("kiln.toml"), toml).expect("write");
    for threads in [1, 3, 8] {
        let output = tempfile::tempdir().expect("temp dir");
        let project = project.path().to_str().expect("utf-8 path");
        let (result, mut diagnostics, store) = build_into(project, output.path(), Some(threads));
        diagnostics.extend(result.diagnostics);
        assert!(diagnostics.is_empty(), "{}", render_plain(&store, &diagnostics));
        let manifest = result.manifest.expect("a manifest");
        assert_eq!(manifest.shaders.len(), 24);
        let written = std::fs::read_to_string(output.path().join("manifest.json")).expect("manifest");
        let whole = serde_json::to_string(&manifest).expect("json") + "\n";
        assert!(written == whole, "{threads} threads: the manifest written differs from the one returned");
    }
}

#[test]
fn an_f16_variant_is_written_with_its_enable_directive() {
    let output = tempfile::tempdir().expect("temp dir");
    let (result, mut diagnostics, store) = build_into("fixtures/half", output.path(), None);
    diagnostics.extend(result.diagnostics);
    assert!(diagnostics.is_empty(), "{}", render_plain(&store, &diagnostics));
    let manifest = read_manifest(output.path());
    let pass = manifest.passes().next().expect("a pass");
    let variant = pass.variants.iter().find(|v| v.keywords == ["_SPECULAR_HALF"]).expect("the f16 variant");
    let fragment = pass.variant_stages(variant)[1].expect("its fragment stage");
    let bytes = fragment.wgsl().expect("WGSL written").read(output.path()).expect("WGSL");
    let wgsl = String::from_utf8(bytes).expect("UTF-8");
    // naga's writer leaves the directive out when f16 appears only in expressions.
    assert!(wgsl.starts_with("enable f16;\n"), "{}", &wgsl[..200.min(wgsl.len())]);
    assert!(wgsl.contains("f16"));
    let module = naga::front::wgsl::parse_str(&wgsl).expect("the written WGSL parses again");
    naga::valid::Validator::new(ValidationFlags::all(), Capabilities::SHADER_FLOAT16)
        .validate(&module)
        .expect("and validates");
}

#[test]
fn custom_light_has_the_seed_layout() {
    let output = tempfile::tempdir().expect("temp dir");
    build_into("fixtures/project", output.path(), None);
    let manifest = read_manifest(output.path());
    let lit = manifest.shaders.iter().find(|s| s.name == "Custom RP/Lit").expect("Lit");
    let pass = &lit.passes[0];
    for variant in &pass.variants {
        let light = pass
            .variant_uniform_blocks(variant)
            .into_iter()
            .map(|i| &pass.uniform_blocks[i])
            .find(|b| b.name == "_CustomLight")
            .expect("_CustomLight used");
        assert_eq!(light.size, 144);
        let members: Vec<(&str, u32, Option<u32>, Option<u32>)> = light
            .members
            .iter()
            .map(|m| (m.name.as_str(), m.offset, m.array_stride, m.array_length))
            .collect();
        assert_eq!(
            members,
            [
                ("_DirectionalLightCount", 0, None, None),
                ("_DirectionalLightColors", 16, Some(16), Some(4)),
                ("_DirectionalLightDirections", 80, Some(16), Some(4)),
            ]
        );
    }
    // Material properties know their place in the material block.
    let offsets: BTreeMap<&str, Option<u32>> =
        lit.properties.iter().map(|p| (p.name.as_str(), p.offset)).collect();
    assert_eq!(offsets["_BaseColor"], Some(16));
    assert_eq!(offsets["_Smoothness"], Some(40));
}

#[test]
fn a_pass_has_one_layout_and_fragment_keywords_share_the_vertex_module() {
    let output = tempfile::tempdir().expect("temp dir");
    build_into("fixtures/project", output.path(), None);
    let manifest = read_manifest(output.path());
    for pass in manifest.shaders.iter().flat_map(|s| &s.passes) {
        let mut slots: BTreeMap<[u32; 2], &str> = BTreeMap::new();
        for group in &pass.layout {
            for entry in &group.entries {
                assert!(slots.insert([group.group, entry.binding], &entry.name).is_none());
            }
        }
        for variant in &pass.variants {
            for stage in pass.variant_stages(variant).into_iter().flatten() {
                for binding in &stage.interface.bindings {
                    assert!(slots.contains_key(binding), "{binding:?} of a variant is in the pass layout");
                }
            }
        }
    }
    let complex = manifest.shaders.iter().find(|s| s.name == "Custom RP/Complex").expect("Complex");
    let variants = &complex.passes[0].variants;
    let plain = variants.iter().find(|v| v.keywords.is_empty()).expect("plain");
    let emission = variants.iter().find(|v| v.keywords == ["_EMISSION_MAP"]).expect("emission");
    assert_eq!(
        plain.vertex.expect("vertex"),
        emission.vertex.expect("vertex"),
        "`_EMISSION_MAP` is fragment-only"
    );
    assert_ne!(plain.fragment.expect("fragment"), emission.fragment.expect("fragment"));
}

#[test]
fn a_second_build_compiles_nothing_and_writes_nothing() {
    let output = tempfile::tempdir().expect("temp dir");
    let (first, _, _) = build_into("fixtures/project", output.path(), None);
    assert!(first.summary.compiled > 0);
    let (second, _, _) = build_into("fixtures/project", output.path(), None);
    assert_eq!(second.summary.compiled, 0);
    assert_eq!(second.summary.reused, second.summary.modules);
    assert_eq!(second.summary.bytes_written, 0);
    let cli = kiln(&["build", "fixtures/project", "--output", output.path().to_str().expect("utf-8")]);
    assert_eq!(cli.status.code(), Some(0));
    let summary = String::from_utf8_lossy(&cli.stderr);
    // 19 stage texts, 13 once cut to what their entry points reach (docs/performance.md).
    assert!(summary.contains("(0 compiled, 13 reused from cache), 0 bytes written"), "{summary}");
}

/// Every file under a folder, with its bytes.
fn snapshot(folder: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    walkdir::WalkDir::new(folder)
        .into_iter()
        .filter_map(Result::ok)
        .filter(|e| e.file_type().is_file())
        .map(|e| {
            (
                e.path().strip_prefix(folder).expect("under").to_path_buf(),
                std::fs::read(e.path()).expect("read"),
            )
        })
        .collect()
}

#[test]
fn output_is_identical_with_one_or_two_threads() {
    let one = tempfile::tempdir().expect("temp dir");
    let two = tempfile::tempdir().expect("temp dir");
    build_into("fixtures/project", one.path(), Some(1));
    build_into("fixtures/project", two.path(), Some(2));
    let (a, b) = (snapshot(one.path()), snapshot(two.path()));
    // A WGSL and a SPIR-V pack for each of the 3 passes.
    assert_eq!(a.keys().filter(|p| p.extension().is_some_and(|e| e == "pack")).count(), 6);
    assert_eq!(a.keys().collect::<Vec<_>>(), b.keys().collect::<Vec<_>>());
    assert!(a == b, "byte-identical folders");
}

#[test]
fn check_covers_shaders_no_material_uses() {
    let check = |args: &[&str]| {
        let output = kiln(args);
        assert_eq!(output.status.code(), Some(0), "{}", String::from_utf8_lossy(&output.stderr));
        String::from_utf8_lossy(&output.stderr).into_owned()
    };
    // Defaults and each keyword alone: Lit 4, Unlit 2, Complex 5.
    assert!(check(&["check", "fixtures/project/shaders"]).contains("11 variants"));
    // Lit 8, Unlit 2, Complex 12.
    assert!(check(&["check", "fixtures/project/shaders", "--all-variants"]).contains("22 variants"));
    // `check` writes nothing.
    assert!(!root().join("fixtures/project/shaders/build").exists());
}

/// Builds each fixture of a folder, pins its diagnostics, and returns each fixture's output folder
/// (in `dir`).
fn build_fixtures(folder: &str, expect_errors: bool, dir: &Path) -> Vec<PathBuf> {
    let files = fixture_files(folder, "shader");
    let mut outputs = Vec::new();
    for path in files {
        let mut store = SourceStore::new();
        let output = dir.join(path.file_stem().expect("name"));
        let mode = Request {
            output: Some(output.clone()),
            unused_shaders: VariantSelection::All { limit: 4096 },
            threads: Some(1),
            ..Request::default()
        };
        let (result, mut diagnostics) =
            build_project(&mut store, std::slice::from_ref(&path), &mode, &|_, _| {}).expect("exists");
        diagnostics.extend(result.diagnostics);
        crate::support::assert_pinned(&path, &store, &diagnostics, expect_errors);
        let cli = kiln(&["check", path.to_str().expect("utf-8"), "--all-variants", "--format", "json"]);
        assert_eq!(cli.status.code(), Some(i32::from(expect_errors)));
        let json: serde_json::Value = serde_json::from_slice(&cli.stdout).expect("json");
        assert!(!json["diagnostics"].as_array().expect("array").is_empty());
        outputs.push(output);
    }
    outputs
}

#[test]
fn every_bad_build_input_has_a_pinned_diagnostic() {
    let dir = tempfile::tempdir().expect("temp dir");
    assert!(build_fixtures("fixtures/bad/build", true, dir.path()).len() >= 6);
}

/// A construct naga's SPIR-V writer gets wrong in a module its validator accepts: the build
/// warns (K0415, pinned), and the module ships as WGSL that loads, without SPIR-V.
#[test]
fn a_module_naga_cannot_write_as_spir_v_ships_as_wgsl_only_with_a_warning() {
    let dir = tempfile::tempdir().expect("temp dir");
    let outputs = build_fixtures("fixtures/warn/build", false, dir.path());
    assert!(outputs.len() >= 2);
    for output in outputs {
        let manifest = kiln::manifest::Manifest::read(&output).expect("manifest");
        let gaps: Vec<_> = manifest.stages().filter(|s| s.spirv().is_none()).collect();
        assert!(!gaps.is_empty(), "{}: every module has SPIR-V", output.display());
        for stage in gaps {
            let wgsl = stage.wgsl().expect("WGSL").read(&output).expect("module");
            let text = String::from_utf8(wgsl).expect("UTF-8");
            let module = naga::front::wgsl::parse_str(&text).expect("kiln's WGSL parses again");
            naga::valid::Validator::new(
                naga::valid::ValidationFlags::all(),
                naga::valid::Capabilities::all(),
            )
            .validate(&module)
            .expect("kiln's WGSL validates again");
        }
    }
}

#[test]
fn reflect_prints_one_variant() {
    let output = kiln(&["reflect", "fixtures/project/shaders/Lit.shader", "--keywords", "_CLIPPING"]);
    assert_eq!(output.status.code(), Some(0), "{}", String::from_utf8_lossy(&output.stderr));
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).expect("json");
    assert_eq!(json["variant"]["keywords"], serde_json::json!(["_CLIPPING"]));
    let inputs = &json["variant"]["vertex"]["inputs"];
    assert_eq!(inputs[0]["format"], "float32x3");
    assert_eq!(inputs[2]["format"], "float32x2");
    // Its uniform blocks in full, named by its stages.
    let light =
        json["uniform_blocks"].as_array().expect("blocks").iter().find(|b| b["name"] == "_CustomLight");
    assert_eq!(light.expect("_CustomLight")["size"], 144);
    assert!(
        json["variant"]["fragment"]["uniform_blocks"]
            .as_array()
            .expect("names")
            .contains(&"_CustomLight".into())
    );
}

#[test]
fn an_unwritable_output_is_a_diagnostic() {
    let dir = tempfile::tempdir().expect("temp dir");
    let blocker = dir.path().join("output");
    std::fs::write(&blocker, "a file where the output folder should be").expect("write");
    let (result, _, _) = build_into("fixtures/project", &blocker, None);
    assert!(result.diagnostics.iter().any(|d| d.code == "K0410"), "{:?}", result.diagnostics);
    assert_eq!(std::fs::read_to_string(&blocker).expect("read"), "a file where the output folder should be");
}

#[test]
fn packs_that_cannot_be_written_leave_no_cache_entry_naming_them() {
    let dir = tempfile::tempdir().expect("temp dir");
    let output = dir.path().join("output");
    // A file where the packs' folder goes: every pack's write fails, nothing else's.
    std::fs::create_dir_all(&output).expect("mkdir");
    std::fs::write(output.join("modules"), "not a folder").expect("write");
    let (result, _, _) = build_into("fixtures/project", &output, None);
    assert!(result.diagnostics.iter().any(|d| d.code == "K0410"), "{:?}", result.diagnostics);
    // The packs are written beside the passes' cache entries, which are put only once the packs
    // are: none names a module that is not there.
    let entries = std::fs::read_dir(output.join(".cache/pass")).map_or(0, |d| d.flatten().count());
    assert_eq!(entries, 0, "a cache entry was written for packs that were not");
    assert!(!output.join("manifest.json").exists());

    std::fs::remove_file(output.join("modules")).expect("remove");
    let (result, diagnostics, _) = build_into("fixtures/project", &output, None);
    assert!(diagnostics.is_empty() && result.diagnostics.is_empty(), "{:?}", result.diagnostics);
    assert_eq!(result.summary.compiled, result.summary.modules, "nothing is taken from the failed build");
    for file in read_manifest(&output).files() {
        let pack = std::fs::read(output.join(&file.path)).expect("every pack named is there");
        assert!(file.slice(&pack).is_some(), "{} holds its module", file.path);
    }
}

#[test]
fn the_packs_a_manifest_names_are_the_packs_on_disk_at_their_lengths() {
    // Several shaders and passes, packs shared by no two passes: each pack's end is its last
    // module's, and a pack holds its modules and nothing after them.
    let dir = tempfile::tempdir().expect("temp dir");
    let output = dir.path().join("output");
    let (result, diagnostics, _) = build_into("fixtures/project", &output, None);
    assert!(diagnostics.is_empty() && result.diagnostics.is_empty(), "{:?}", result.diagnostics);
    let named: std::collections::BTreeMap<String, u64> =
        read_manifest(&output).packs().into_iter().map(|(path, len)| (path.to_string(), len)).collect();
    let on_disk: std::collections::BTreeMap<String, u64> = std::fs::read_dir(output.join("modules"))
        .expect("the packs' folder")
        .flatten()
        .map(|entry| {
            let len = entry.metadata().expect("a pack's size").len();
            (format!("modules/{}", entry.file_name().to_string_lossy()), len)
        })
        .collect();
    assert!(named.len() > 2, "{named:?}");
    assert_eq!(named, on_disk);
}

#[test]
fn the_build_script_api_reruns_on_every_file_read_and_folder_searched_and_nothing_else() {
    let out = tempfile::tempdir().expect("temp dir");
    let output = kiln::Build::new("fixtures/project").out_dir(out.path()).execute().expect("builds");
    let mut reruns: Vec<String> = output
        .cargo_lines
        .iter()
        .filter_map(|l| l.strip_prefix("cargo:rerun-if-changed="))
        .map(|p| p.replace('\\', "/"))
        .collect();
    reruns.sort();
    // The folders too: a new shader or material there must rerun the build script.
    let mut expected: Vec<String> =
        ["fixtures/project/kiln.toml", "fixtures/project/materials", "fixtures/project/shaders"]
            .map(String::from)
            .into_iter()
            .chain(
                fixture_files("fixtures/project/shaders", "shader").iter().map(|p| p.display().to_string()),
            )
            .chain(fixture_files("fixtures/project/shaders", "wgsl").iter().map(|p| p.display().to_string()))
            .chain(fixture_files("fixtures/project/materials", "mat").iter().map(|p| p.display().to_string()))
            .collect();
    expected.sort();
    assert_eq!(reruns, expected, "the bundled library is embedded, so it is not a file to watch");
    assert!(output.cargo_lines.iter().all(|l| l.starts_with("cargo:rerun-if-changed=")), "no warnings here");
    assert!(output.module.ends_with("kiln_shaders.rs"));
}

#[test]
fn the_generated_module_asserts_every_uniform_layout() {
    let out = tempfile::tempdir().expect("temp dir");
    let output = kiln::Build::new("fixtures/project").out_dir(out.path()).execute().expect("builds");
    let module = std::fs::read_to_string(&output.module).expect("generated");
    for line in [
        "pub mod custom_rp_lit {",
        "const _: () = assert!(::core::mem::size_of::<CustomLight>() == 144);",
        "const _: () = assert!(::core::mem::offset_of!(CustomLight, _DirectionalLightCount) == 0);",
        "const _: () = assert!(::core::mem::offset_of!(CustomLight, _DirectionalLightColors) == 16);",
        "const _: () = assert!(::core::mem::offset_of!(CustomLight, _DirectionalLightDirections) == 80);",
        "pub _DirectionalLightColors: [[f32; 4]; 4],",
        "pub _pad0: [u8; 12],",
    ] {
        assert!(module.contains(line), "the generated module has `{line}`");
    }
    // The renderer example compiles this module, so a wrong assertion would fail its build.
}

#[test]
fn a_build_script_error_reads_like_a_compiler_error() {
    let out = tempfile::tempdir().expect("temp dir");
    let error =
        kiln::Build::new("fixtures/bad/preprocess/unterminated_if.shader").out_dir(out.path()).execute();
    let Err(error) = error else { panic!("the build fails") };
    let shown = format!("{error:?}");
    assert!(shown.contains("error[K0305]: `#if` without `#endif`"), "{shown}");
    assert!(shown.contains("fixtures/bad/preprocess/unterminated_if.wgsl:3:1"), "{shown}");
    assert!(!out.path().join("kiln_shaders.rs").exists());
}

#[test]
fn an_always_included_shader_with_too_many_variants_is_refused_with_the_count() {
    let mut store = SourceStore::new();
    let mode = Request { write: false, threads: Some(1), ..Request::default() };
    let path = PathBuf::from("fixtures/bad/always_include");
    let (result, mut diagnostics) = build_project(&mut store, &[path], &mode, &|_, _| {}).expect("exists");
    diagnostics.extend(result.diagnostics);
    assert!(has_errors(&diagnostics));
    assert_eq!(result.summary.variants, 0, "nothing is built whole");
    expect_file![root().join("fixtures/bad/always_include/kiln.stderr")]
        .assert_eq(&render_plain(&store, &diagnostics));
}

#[test]
fn a_variant_log_line_that_names_nothing_is_an_error_at_its_line() {
    let mut store = SourceStore::new();
    let output = tempfile::tempdir().expect("temp dir");
    let mode = Request { output: Some(output.path().to_path_buf()), threads: Some(1), ..Request::default() };
    let path = PathBuf::from("fixtures/bad/variant_log");
    let (result, diagnostics) = build_project(&mut store, &[path], &mode, &|_, _| {}).expect("exists");
    expect_file![root().join("fixtures/bad/variant_log/kiln.stderr")]
        .assert_eq(&render_plain(&store, &diagnostics));
    // The good lines still count: the logged variants are in the catalogue, nothing is written.
    assert_eq!(result.summary.variants, 2);
    assert!(!output.path().join("manifest.json").exists());
}

#[test]
fn nested_uniform_and_storage_blocks_are_reflected_and_generated_in_full() {
    let output = tempfile::tempdir().expect("temp dir");
    let (result, mut diagnostics, store) = build_with("fixtures/blocks", output.path(), None, true);
    diagnostics.extend(result.diagnostics);
    assert!(diagnostics.is_empty(), "{}", render_plain(&store, &diagnostics));
    let manifest = verified_manifest(output.path());
    let pass =
        manifest.passes().find(|p| p.uniform_blocks.iter().any(|b| b.name == "blk")).expect("the pass");
    let blocks = serde_json::to_string_pretty(&pass.uniform_blocks).expect("json") + "\n";
    expect_file![root().join("tests/golden/build/blocks.json")].assert_eq(&blocks);
    // The offsets WGSL gives the example block, member by member.
    let block = pass.uniform_blocks.iter().find(|b| b.name == "blk").expect("blk");
    let offsets: Vec<u32> = block.members.iter().map(|m| m.offset).collect();
    assert_eq!((offsets, block.size), (vec![0, 12, 16, 64, 112, 128, 160, 176, 304], 336));
    let light = &block.members[7].members;
    assert_eq!(
        light.iter().map(|m| (m.name.as_str(), m.offset)).collect::<Vec<_>>(),
        [("color", 0), ("intensity", 12), ("dir", 16)]
    );
    let generated = kiln::codegen::generate(&manifest, "kiln").expect("names do not clash");
    let structs = &generated[generated.find("    /// The struct").expect("structs")..];
    expect_file![root().join("tests/golden/build/blocks.rs")].assert_eq(structs);

    // `kiln reflect` prints the variant's blocks as the manifest has them, nested members too.
    let output = kiln(&["reflect", "fixtures/blocks/Blocks.shader"]);
    assert_eq!(output.status.code(), Some(0), "{}", String::from_utf8_lossy(&output.stderr));
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).expect("json");
    let mut printed: Vec<kiln::reflect::UniformBlock> =
        serde_json::from_value(json["uniform_blocks"].clone()).expect("blocks");
    let mut built = pass.uniform_blocks.clone();
    printed.sort_by(|a, b| a.name.cmp(&b.name));
    built.sort_by(|a, b| a.name.cmp(&b.name));
    assert_eq!(printed, built);
}

#[test]
fn progress_counts_what_the_closing_line_counts() {
    let output = tempfile::tempdir().expect("temp dir");
    let seen = std::sync::Mutex::new((0, 0));
    let progress = |done: usize, total: usize| {
        let mut seen = seen.lock().expect("lock");
        *seen = (seen.0.max(done), seen.1.max(total));
    };
    let mode = Request { output: Some(output.path().to_path_buf()), threads: Some(2), ..Request::default() };
    let mut store = SourceStore::new();
    let (result, _) =
        build_project(&mut store, &[PathBuf::from("fixtures/project")], &mode, &progress).expect("project");
    let (done, total) = *seen.lock().expect("lock");
    assert_eq!((done, total), (result.summary.variants, result.summary.variants));
}

#[test]
fn a_build_that_skips_every_shader_says_which_and_how_to_build_them() {
    let project = tempfile::tempdir().expect("temp dir");
    for name in ["Unlit.shader", "UnlitPass.wgsl"] {
        std::fs::copy(root().join("fixtures/project/shaders").join(name), project.path().join(name))
            .expect("copy");
    }
    let output = project.path().join("out");
    let build = || {
        let folder = project.path().to_str().expect("utf-8");
        let run = kiln(&["build", folder, "--output", output.to_str().expect("utf-8")]);
        assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
        String::from_utf8_lossy(&run.stderr).into_owned()
    };
    let stderr = build();
    assert!(stderr.contains("built 0 shaders"), "{stderr}");
    assert!(
        stderr.contains("note[K0008]: no material uses `Custom RP/Unlit`, so it was not built"),
        "{stderr}"
    );
    let note: String =
        stderr.lines().skip_while(|l| !l.starts_with("note[")).map(|l| format!("{l}\n")).collect();
    expect_file![root().join("tests/golden/build/unused_shader.stderr")].assert_eq(&note);
    assert!(stderr.contains("always_include") && stderr.contains("kiln check --all-variants"), "{stderr}");
    // With a material, nothing is skipped and nothing is said about it.
    std::fs::write(project.path().join("U.mat"), "shader = \"Custom RP/Unlit\"\n").expect("write");
    let stderr = build();
    assert!(stderr.contains("built 1 shader,") && !stderr.contains("no material uses"), "{stderr}");
}

#[test]
fn a_build_script_builds_the_variants_a_usage_log_names() {
    let dir = tempfile::tempdir().expect("temp dir");
    let log = dir.path().join("usage.jsonl");
    std::fs::write(&log, "{\"shader\": \"Test/Blend\", \"pass\": 0, \"keywords\": [\"_TINT\"]}\n")
        .expect("write");
    let build = |with_log: bool| {
        let mut build = kiln::Build::new(root().join("fixtures/runtime")).out_dir(dir.path().join("out"));
        if with_log {
            build = build.variant_log(&log);
        }
        build.execute().expect("builds")
    };
    let tinted = |output: &kiln::BuildOutput| {
        output.manifest.passes().flat_map(|p| &p.variants).any(|v| v.keywords == ["_TINT"])
    };
    assert!(!tinted(&build(false)));
    let output = build(true);
    assert!(tinted(&output));
    // The log is an input: a change to it reruns the build script.
    let rerun = format!("cargo:rerun-if-changed={}", log.display());
    assert!(output.cargo_lines.contains(&rerun), "{:?}", output.cargo_lines);
}

#[test]
fn a_shader_copied_under_another_name_is_compiled_once() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = crate::support::example_project_copy(dir.path());
    let original = std::fs::read_to_string(project.join("shaders/Lit.shader")).expect("Lit");
    let copy = original.replace("Shader \"Custom RP/Lit\"", "Shader \"Custom RP/Lit Copy\"");
    assert_ne!(copy, original);
    std::fs::write(project.join("shaders/LitCopy.shader"), copy).expect("write");
    for name in ["LitClip", "LitFade", "LitOpaque", "LitTransparent"] {
        let text = std::fs::read_to_string(project.join(format!("materials/{name}.mat"))).expect("mat");
        let text = text.replace("\"Custom RP/Lit\"", "\"Custom RP/Lit Copy\"");
        std::fs::write(project.join(format!("materials/{name}Copy.mat")), text).expect("write");
    }
    let output = dir.path().join("out");
    // One thread: two passes in flight at once may each compile a text before either has it.
    // Whole texts: 19 stage texts of the project (13 once cut), as this count was written for.
    let run = kiln(&[
        "build",
        project.to_str().expect("utf-8"),
        "--output",
        output.to_str().expect("utf-8"),
        "--threads",
        "1",
        "--parse-whole",
    ]);
    let summary = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(0), "{summary}");
    let manifest = read_manifest(&output);
    let pass_of = |name: &str| &manifest.shaders.iter().find(|s| s.name == name).expect(name).passes[0];
    let (lit, copy) = (pass_of("Custom RP/Lit"), pass_of("Custom RP/Lit Copy"));
    // The bundled project compiles 19 modules; the copy's are those of Lit, compiled once.
    let count = |what: &str| -> usize {
        let at = summary.find(what).unwrap_or_else(|| panic!("`{what}` in {summary}"));
        summary[..at].rsplit([' ', '(']).next().expect("count").parse().expect("number")
    };
    assert_eq!((count(" compiled,"), count(" shared between passes")), (19, count(" stage modules") - 19));
    assert!(count(" stage modules") > 19, "{summary}");
    let hashes = |pass: &kiln::manifest::PassManifest| -> Vec<Vec<String>> {
        pass.variants
            .iter()
            .map(|v| {
                pass.variant_stages(v)
                    .iter()
                    .flatten()
                    .flat_map(|s| [&s.module.wgsl, &s.module.spirv])
                    .flatten()
                    .map(|f| f.hash.clone())
                    .collect()
            })
            .collect()
    };
    assert_eq!(hashes(lit), hashes(copy));
    assert!(!hashes(copy).is_empty());
}

#[test]
fn kiln_toml_names_the_resources_bound_per_frame_and_per_object() {
    let output = crate::support::built_fixture("bind_groups");
    let manifest = crate::support::verified_manifest(output.path());
    let pass = &manifest.shaders[0].passes[0];
    let group_of =
        |name: &str| pass.layout.iter().find(|g| g.entries.iter().any(|e| e.name == name)).map(|g| g.group);
    assert_eq!(group_of("Fog"), Some(0), "named per frame");
    assert_eq!(group_of("ObjectTint"), Some(2), "named per object");
    assert_eq!(group_of("UnityPerMaterial"), Some(1), "the rest is the material's");
    // `kiln reflect` gives the same slots: the shader's project (the folder with its kiln.toml),
    // found from the shader or given.
    let shader = "fixtures/bind_groups/Fogged.shader";
    for args in [vec!["reflect", shader], vec!["reflect", shader, "--project", "fixtures/bind_groups"]] {
        let run = kiln(&args);
        assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
        let json: serde_json::Value = serde_json::from_slice(&run.stdout).expect("json");
        let groups = json["layout"].as_array().expect("layout").clone();
        let slot = |name: &str| {
            groups.iter().find_map(|g| {
                let entry = g["entries"].as_array()?.iter().find(|e| e["name"] == name)?;
                Some((g["group"].as_u64()?, entry["binding"].as_u64()?))
            })
        };
        let built = |name: &str| {
            let group = pass.layout.iter().find(|g| g.entries.iter().any(|e| e.name == name))?;
            let entry = group.entries.iter().find(|e| e.name == name)?;
            Some((u64::from(group.group), u64::from(entry.binding)))
        };
        for name in ["Fog", "ObjectTint"] {
            assert_eq!(slot(name), built(name), "{name} in `kiln {}`", args.join(" "));
        }
    }
    // One name in both lists: refused where it is written the second time.
    let mut store = SourceStore::new();
    let path = PathBuf::from("fixtures/bad/bind_groups");
    let (_, diagnostics) =
        build_project(&mut store, &[path], &Request { write: false, ..Request::default() }, &|_, _| {})
            .expect("exists");
    assert!(has_errors(&diagnostics));
    expect_file![root().join("fixtures/bad/bind_groups/kiln.stderr")]
        .assert_eq(&render_plain(&store, &diagnostics));
}

/// A `[bind_groups]` name no file of the project mentions (a misspelt resource) warns at its place
/// in `kiln.toml`, with the resource it is close to; names that are resources do not.
#[test]
fn a_bind_group_name_no_file_declares_warns_with_the_closest_resource() {
    let check = |path: &str| {
        let mut store = SourceStore::new();
        let mode = Request { write: false, ..Request::default() };
        let (result, mut diagnostics) =
            build_project(&mut store, &[PathBuf::from(path)], &mode, &|_, _| {}).expect("exists");
        diagnostics.extend(result.diagnostics);
        (render_plain(&store, &diagnostics), diagnostics)
    };
    let (rendered, diagnostics) = check("fixtures/warn/bind_groups");
    assert!(!has_errors(&diagnostics), "{rendered}");
    expect_file![root().join("fixtures/warn/bind_groups/kiln.stderr")].assert_eq(&rendered);
    let (rendered, _) = check("fixtures/bind_groups");
    assert!(!rendered.contains("K0012"), "{rendered}");
}

/// A renderer that includes the generated module and uses none of it yet (the first hour) gets
/// no warning from it: not rustc's under its default lints, nor clippy's.
#[test]
fn the_generated_module_compiles_without_a_warning_where_nothing_uses_it() {
    let out = tempfile::tempdir().expect("temp dir");
    for fixture in ["fixtures/project", "fixtures/compute", "fixtures/dynamic"] {
        let built = out.path().join(fixture.replace('/', "-"));
        kiln::Build::new(fixture).out_dir(&built).execute().expect("builds");
        let module = std::fs::read_to_string(built.join("kiln_shaders.rs")).expect("generated");
        let krate = built.join("crate");
        crate::support::generated_module_crate(
            &krate,
            &module,
            (&built.join("kiln"), "kiln"),
            "mod shaders;\n",
        );
        let clippy = crate::support::cargo_scratch(&krate, &["clippy", "--quiet", "--", "-D", "warnings"]);
        let stderr = String::from_utf8_lossy(&clippy.stderr);
        assert!(clippy.status.success() && !stderr.contains("warning"), "{fixture}:\n{stderr}");
    }
}
