//! `dynamic_branch` keywords and `override` constants end to end (`fixtures/dynamic`): one
//! module for every keyword value, reflected in the manifest, listed, generated as typed Rust,
//! and drawn on the GPU with the values a material, the renderer's globals and its own
//! overrides give; usage logs naming them build.

use crate::runtime::draw_pass;
use crate::support::{built_fixture, gpu, kiln, root};
use expect_test::expect_file;
use kiln::runtime::{Runtime, RuntimeError, UsageLog};

const SHADER: &str = "Test/Dynamic";

/// What a draw asks for: keywords (beyond the material's) and override values.
type Ask<'a> = (&'a [&'a str], &'a [(&'a str, f64)]);

#[test]
fn one_module_serves_every_keyword_value_and_its_overrides_are_reflected() {
    let output = built_fixture("dynamic");
    let manifest = crate::support::verified_manifest(output.path());
    let shader = manifest.shaders.iter().find(|s| s.name == SHADER).expect("built");
    let pass = &shader.passes[0];
    // Three materials with three tints: one variant, one module per stage.
    assert_eq!(pass.variants.len(), 1);
    assert_eq!(pass.variants[0].materials, ["Green", "Plain", "Red"]);
    assert_eq!(pass.modules.len(), 2);
    let fragment = pass.stage(pass.variants[0].fragment.expect("fragment"));
    let overrides: Vec<(&str, Option<u16>, &str, Option<f64>)> = fragment
        .interface
        .overrides
        .iter()
        .map(|o| (o.name.as_str(), o.id, o.ty.name(), o.default))
        .collect();
    assert_eq!(
        overrides,
        [
            ("brightness", None, "f32", Some(1.0)),
            ("blue", Some(7), "f32", Some(0.0)),
            ("steps", None, "u32", Some(1.0)),
            ("_TINT_RED", None, "bool", Some(0.0)),
            ("_TINT_GREEN", None, "bool", Some(0.0)),
            ("_FOG", None, "bool", Some(0.0)),
        ]
    );
    // naga cannot write SPIR-V specialisation constants: such a module is WGSL only.
    assert!(fragment.module.spirv.is_none() && fragment.module.wgsl.is_some());
    let vertex = pass.stage(pass.variants[0].vertex.expect("vertex"));
    assert!(vertex.interface.overrides.is_empty() && vertex.module.spirv.is_some());
    for keyword in ["_TINT_RED", "_TINT_GREEN", "_FOG"] {
        assert!(pass.is_dynamic(keyword), "{keyword}");
    }
    assert!(pass.keywords.is_empty(), "no variant keywords");
}

#[test]
fn the_listing_counts_what_dynamic_branch_saves() {
    let run = kiln(&["list", "fixtures/dynamic"]);
    assert!(run.status.success());
    expect_file![root().join("tests/golden/list/dynamic.txt")]
        .assert_eq(&String::from_utf8_lossy(&run.stdout));
}

#[test]
fn the_generated_module_has_typed_overrides_that_compile() {
    let out = tempfile::tempdir().expect("temp dir");
    let output = kiln::Build::new("fixtures/dynamic").out_dir(out.path()).execute().expect("builds");
    let module = std::fs::read_to_string(&output.module).expect("generated");
    for line in [
        "pub struct Pass0Overrides {",
        "pub brightness: f32,",
        "pub steps: u32,",
        "Self { brightness: 1.0_f32, blue: 0.0_f32, steps: 1 }",
        r#"[("brightness", f64::from(self.brightness)), ("7", f64::from(self.blue)), ("steps", f64::from(self.steps))]"#,
    ] {
        assert!(module.contains(line), "the generated module has `{line}`:\n{module}");
    }
    assert!(!module.contains("pub _FOG"), "keywords are set through keywords, not overrides");
    assert!(module.contains(r#"dynamic_keywords: &["_TINT_RED", "_TINT_GREEN", "_FOG"],"#));
    // Compiled and run by cargo: the struct's fields have the types a renderer writes.
    let krate = crate::support::test_generated_module(
        out.path(),
        "pub mod shaders;\n\
         pub fn constants() -> [(&'static str, f64); 3] {\n\
         \x20   let o = shaders::test_dynamic::Pass0Overrides { brightness: 0.5f32, ..Default::default() };\n\
         \x20   let _: (f32, u32) = (o.blue, o.steps);\n\
         \x20   o.constants()\n\
         }\n\
         #[test]\n\
         fn dynamic_keywords_choose_no_variant_and_constants_are_the_values() {\n\
         \x20   use shaders::test_dynamic::keywords::{_FOG, _TINT_RED};\n\
         \x20   assert!(shaders::test_dynamic::PASS_0.variant(&[_FOG, _TINT_RED]).is_ok());\n\
         \x20   assert_eq!(constants(), [(\"brightness\", 0.5), (\"7\", 0.0), (\"steps\", 1.0)]);\n\
         }\n\
         #[test]\n\
         fn typed_keywords_find_their_pass_s_variant() {\n\
         \x20   use shaders::test_dynamic::Pass0Keyword as K;\n\
         \x20   let typed = shaders::variant(&[K::_FOG, K::_TINT_RED]).expect(\"built\");\n\
         \x20   let named = shaders::test_dynamic::PASS_0.variant(&[\"_FOG\", \"_TINT_RED\"]).expect(\"built\");\n\
         \x20   assert_eq!((typed.pass.shader, typed.index, typed.key()), (named.pass.shader, named.index, named.key()));\n\
         \x20   assert_eq!(typed.pass.shader, \"Test/Dynamic\");\n\
         }\n",
    );
    // A keyword of one pass given to another's lookup does not compile.
    let lib = std::fs::read_to_string(krate.join("src/lib.rs")).expect("lib.rs");
    let crossed = lib.replace(
        "shaders::variant(&[K::_FOG, K::_TINT_RED])",
        "shaders::variant::<shaders::test_required::Pass0Keyword>(&[K::_FOG])",
    );
    assert_ne!(crossed, lib);
    std::fs::write(krate.join("src/lib.rs"), crossed).expect("lib.rs");
    let run = crate::support::cargo_scratch(&krate, &["test", "--no-run"]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(!run.status.success(), "another pass's keyword compiles");
    assert!(
        stderr.contains("mismatched types") && stderr.contains("test_required::Pass0Keyword"),
        "{stderr}"
    );
    std::fs::write(krate.join("src/lib.rs"), lib).expect("lib.rs");
    // A misspelt keyword constant does not compile: the typo is found before any frame.
    let lib = std::fs::read_to_string(krate.join("src/lib.rs")).expect("lib.rs");
    std::fs::write(
        krate.join("src/lib.rs"),
        lib.replace("keywords::{_FOG, _TINT_RED}", "keywords::{_FOGG, _TINT_RED}"),
    )
    .expect("lib.rs");
    let run = crate::support::cargo_scratch(&krate, &["test", "--no-run"]);
    assert!(!run.status.success(), "a misspelt keyword compiles");
    assert!(
        String::from_utf8_lossy(&run.stderr).contains("_FOGG"),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
}

#[test]
fn a_usage_log_naming_dynamic_keywords_builds_the_variant_it_names() {
    let dir = tempfile::tempdir().expect("temp dir");
    let log = dir.path().join("usage.jsonl");
    std::fs::write(
        &log,
        "{\"shader\": \"Test/Dynamic\", \"pass\": 0, \"keywords\": [\"_FOG\", \"_TINT_RED\"]}\n",
    )
    .expect("log");
    let out = dir.path().join("out");
    let run = kiln(&[
        "build",
        "fixtures/dynamic",
        "--variants-from",
        log.to_str().expect("utf-8"),
        "--output",
        out.to_str().expect("utf-8"),
    ]);
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    let manifest = crate::support::verified_manifest(&out);
    let shader = manifest.shaders.iter().find(|s| s.name == SHADER).expect("built");
    assert_eq!(shader.passes[0].variants.len(), 1, "the keywords choose no variant");
}

/// Channels within 1.5/255 of the expected colour.
fn assert_colour(pixel: [u8; 4], expected: [f64; 3], what: &str) {
    for (channel, want) in pixel.iter().zip(expected) {
        assert!(
            (f64::from(*channel) / 255.0 - want).abs() <= 1.5 / 255.0,
            "{what}: {pixel:?}, expected {expected:?}"
        );
    }
}

#[test]
fn keyword_values_and_overrides_draw_the_right_pixels_with_one_module() {
    let Some(gpu) = gpu("the dynamic_branch test") else { return };
    let output = built_fixture("dynamic");
    let mut runtime = Runtime::open(&gpu.device, output.path()).expect("opens");
    let log = output.path().join("usage.jsonl");
    runtime.log_usage(UsageLog::new(Some(&log), None).expect("log"));
    let material = |name: &str| runtime.library().material(name).expect("built").clone();
    let (plain, red, green) = (material("Plain"), material("Red"), material("Green"));
    let grey = [0.2, 0.2, 0.2];
    // (material, (global keywords, overrides), expected colour)
    let cases: [(&kiln::manifest::MaterialManifest, Ask, [f64; 3]); 8] = [
        (&plain, (&[], &[]), grey),
        (&red, (&[], &[]), [1.0, 0.0, 0.0]),
        (&green, (&[], &[]), [0.0, 1.0, 0.0]),
        // The renderer's global `_FOG`, mixed half-way to grey 0.5.
        (&red, (&["_FOG"], &[]), [0.75, 0.25, 0.25]),
        (&plain, (&["_FOG"], &[]), [0.35, 0.35, 0.35]),
        // Its own constants: by name, and `blue` by its `@id(7)`.
        (&red, (&[], &[("brightness", 0.5)]), [0.5, 0.0, 0.0]),
        (&green, (&[], &[("7", 1.0), ("steps", 2.0)]), [0.0, 0.5, 1.0]),
        // Asked again: the same pipeline.
        (&red, (&[], &[]), [1.0, 0.0, 0.0]),
    ];
    for (material, (globals, overrides), expected) in cases {
        let keywords: Vec<&str> =
            material.keywords.iter().map(String::as_str).chain(globals.iter().copied()).collect();
        let (pixel, _) = draw_pass(&runtime, &gpu, SHADER, material, &keywords, overrides).expect("draws");
        assert_colour(pixel, expected, &format!("{} {globals:?} {overrides:?}", material.name));
    }
    // One pipeline per distinct value set: seven, the repeat reused.
    assert_eq!(runtime.pipelines_created(), 7);
    // Warm-up creates the materials' pipelines, which the draws above already made.
    let materials = [&plain, &red, &green];
    runtime.warm_up(&materials, &[], &crate::runtime::targets()).expect("warms up");
    assert_eq!(runtime.pipelines_created(), 7);
    // The usage log names the dynamic keywords each draw asked for, and builds from it.
    let logged = std::fs::read_to_string(&log).expect("usage log");
    assert!(logged.lines().any(|l| l.contains(r#"["_FOG","_TINT_RED"]"#)), "{logged}");
    let rebuilt = output.path().join("rebuilt");
    let (log, rebuilt) = (log.to_str().expect("utf-8"), rebuilt.to_str().expect("utf-8"));
    let run = kiln(&["build", "fixtures/dynamic", "--variants-from", log, "--output", rebuilt]);
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
}

#[test]
fn reflect_shows_overrides_and_takes_dynamic_keywords() {
    let run = kiln(&["reflect", "fixtures/dynamic/Dynamic.shader", "--keywords", "_FOG"]);
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    let reflected: serde_json::Value = serde_json::from_slice(&run.stdout).expect("JSON");
    let overrides = &reflected["variant"]["fragment"]["overrides"];
    let names: Vec<&str> =
        overrides.as_array().expect("a list").iter().filter_map(|o| o["name"].as_str()).collect();
    assert_eq!(names, ["brightness", "blue", "steps", "_TINT_RED", "_TINT_GREEN", "_FOG"]);
    assert_eq!(overrides[1]["id"], 7);
}

#[test]
fn wrong_keywords_and_override_values_are_refused_with_what_to_do() {
    let Some(gpu) = gpu("the override errors test") else { return };
    let output = built_fixture("dynamic");
    let runtime = Runtime::open(&gpu.device, output.path()).expect("opens");
    let plain = runtime.library().material("Plain").expect("built").clone();
    let cases: [Ask; 7] = [
        (&["_TINT_RED", "_TINT_GREEN"], &[]),
        (&["_TINT_REED"], &[]),
        (&[], &[("brightnes", 1.0)]),
        (&[], &[("_FOG", 1.0)]),
        (&[], &[("steps", 2.5)]),
        (&[], &[("steps", -1.0)]),
        (&[], &[("brightness", f64::INFINITY)]),
    ];
    let mut shown = String::new();
    for (keywords, overrides) in cases {
        let error = draw_pass(&runtime, &gpu, SHADER, &plain, keywords, overrides).expect_err("refused");
        assert!(!matches!(error, RuntimeError::Layout { .. }), "refused before wgpu: {error}");
        shown.push_str(&format!("{keywords:?} {overrides:?}\n  {error}\n"));
    }
    // An override without a default must be given; given, it draws.
    let error = draw_pass(&runtime, &gpu, "Test/Required", &plain, &[], &[]).expect_err("refused");
    shown.push_str(&format!("Test/Required [] []\n  {error}\n"));
    assert_eq!(runtime.pipelines_created(), 0);
    let (pixel, _) =
        draw_pass(&runtime, &gpu, "Test/Required", &plain, &[], &[("level", 0.25)]).expect("draws");
    assert_colour(pixel, [0.25; 3], "level 0.25");
    // A material is bound to its own shader's passes only.
    let required = runtime.pass("Test/Required", 0).expect("built");
    let error = runtime.material_bind_group(&plain, required, &()).expect_err("another shader's pass");
    shown.push_str(&format!("material_bind_group(Plain, Test/Required pass 0)\n  {error}\n"));
    expect_file![root().join("tests/golden/runtime/overrides.txt")].assert_eq(&shown);
}
