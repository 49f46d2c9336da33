//! Materials and variant enumeration: the seed's presets give exactly the seed's variants, a
//! property test of the enumeration's size and shape, every bad material's pinned diagnostic,
//! and presets written into material files.

use crate::support::{fixture_files, kiln, root};
use expect_test::expect_file;
use kiln::diagnostics::{has_errors, render_plain};
use kiln::keywords::PassKeywords;
use kiln::listing::list_shaders;
use kiln::preprocess::Includes;
use kiln::project::{load_files, open_workspace};
use kiln::shaderlab::pragma::{KeywordKind, KeywordOption, KeywordScope, KeywordSet, KeywordStage};
use kiln::source::{SourceStore, Span};
use proptest::prelude::*;
use std::collections::HashSet;
use std::path::PathBuf;

/// Lists `paths` as `kiln list` does and returns the listing with the rendered diagnostics.
fn list(paths: &[PathBuf]) -> (kiln::listing::Listing, String, bool) {
    let mut store = SourceStore::new();
    let (workspace, mut diagnostics) = open_workspace(&mut store, paths).expect("paths exist");
    let mut includes = Includes::new(workspace.include.clone().expect("include config"));
    let (shaders, found) = load_files(&mut store, &workspace.shaders);
    diagnostics.extend(found);
    let (materials, found) = load_files(&mut store, &workspace.materials);
    diagnostics.extend(found);
    let input = workspace.catalog_input(shaders, materials);
    let (listing, found) = list_shaders(&mut store, &mut includes, &input);
    diagnostics.extend(found);
    (listing, render_plain(&store, &diagnostics), has_errors(&diagnostics))
}

fn used_keywords(listing: &kiln::listing::Listing, shader: &str) -> Vec<Vec<String>> {
    let shader = listing.shaders.iter().find(|s| s.name == shader).expect("shader listed");
    let program = shader.passes[0].program.as_ref().expect("program");
    program.used_variants.iter().map(|v| v.keywords.clone()).collect()
}

#[test]
fn the_seed_presets_need_exactly_three_lit_variants() {
    let (listing, rendered, errors) = list(&[PathBuf::from("fixtures/project")]);
    assert!(!errors && rendered.is_empty(), "{rendered}");
    let lit = used_keywords(&listing, "Custom RP/Lit");
    let expected: Vec<Vec<String>> =
        vec![vec![], vec!["_PREMULTIPLY_ALPHA".into()], vec!["_CLIPPING".into()]];
    assert_eq!(lit, expected);
    let presets: HashSet<_> =
        listing.materials.iter().filter(|m| m.shader == "Custom RP/Lit").map(|m| m.preset).collect();
    assert_eq!(presets.len(), 4, "one Lit material per preset");
    // Fade and Opaque share the keyword-less variant.
    let shader = listing.shaders.iter().find(|s| s.name == "Custom RP/Lit").expect("Lit");
    let plain = &shader.passes[0].program.as_ref().expect("program").used_variants[0];
    assert_eq!(plain.materials, ["LitFade", "LitOpaque"]);
}

#[test]
fn fragment_keywords_do_not_fork_the_vertex_stage() {
    let (listing, _, _) = list(&[PathBuf::from("fixtures/project")]);
    let shader = listing.shaders.iter().find(|s| s.name == "Custom RP/Complex").expect("Complex");
    let variants = &shader.passes[0].program.as_ref().expect("program").used_variants;
    let emission = variants.iter().find(|v| v.keywords == ["_EMISSION_MAP"]).expect("emission variant");
    assert!(emission.vertex_keywords.is_empty());
    assert_eq!(emission.fragment_keywords, ["_EMISSION_MAP"]);
}

/// A keyword set as a pragma would declare it.
fn set(kind: KeywordKind, keywords: &[&str]) -> KeywordSet {
    let span = Span::new(SourceStore::new().add("x", ""), 0..0);
    KeywordSet {
        kind,
        scope: KeywordScope::Global,
        stage: KeywordStage::All,
        options: keywords
            .iter()
            .map(|k| KeywordOption {
                keyword: (!k.starts_with("__") && *k != "_").then(|| k.to_string()),
                span,
            })
            .collect(),
        shorthand: None,
        span,
    }
}

#[test]
fn the_seed_listing_of_eight_variants() {
    // Rendering 9: two multi_compile sets and the metallic map, used on and off.
    let pass = PassKeywords::new(vec![
        set(KeywordKind::MultiCompile, &["_", "SHADOWS_SCREEN"]),
        set(KeywordKind::MultiCompile, &["_", "VERTEXLIGHT_ON"]),
        set(KeywordKind::ShaderFeature, &["_", "_METALLIC_MAP"]),
    ]);
    let variants =
        pass.enumerate(&[vec![], vec!["_METALLIC_MAP"], vec!["_METALLIC_MAP"]], false, None).expect("small");
    let listed: Vec<String> =
        variants.iter().map(|v| pass.keywords(&v.bits).collect::<Vec<_>>().join(" ")).collect();
    assert_eq!(
        listed,
        [
            "",
            "_METALLIC_MAP",
            "VERTEXLIGHT_ON",
            "VERTEXLIGHT_ON _METALLIC_MAP",
            "SHADOWS_SCREEN",
            "SHADOWS_SCREEN _METALLIC_MAP",
            "SHADOWS_SCREEN VERTEXLIGHT_ON",
            "SHADOWS_SCREEN VERTEXLIGHT_ON _METALLIC_MAP",
        ]
    );
    // Only the metallic-map users need the metallic variants.
    assert_eq!(variants[1].materials, [1, 2]);
    // Without materials nothing is built; always-included, everything is.
    assert!(pass.enumerate(&[], false, None).expect("small").is_empty());
    assert_eq!(pass.enumerate(&[], true, None).expect("small").len(), 8);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

    #[test]
    fn enumeration_is_multi_compile_product_times_distinct_projections(
        shapes in proptest::collection::vec((any::<bool>(), 1usize..4, any::<bool>()), 1..7),
        picks in proptest::collection::vec(proptest::collection::vec(0usize..5, 7), 0..20),
    ) {
        let sets: Vec<KeywordSet> = shapes
            .iter()
            .enumerate()
            .map(|(i, &(multi, n, off))| {
                let mut names: Vec<String> = (0..n).map(|k| format!("K{i}_{k}")).collect();
                if off { names.insert(0, "_".into()); }
                let names: Vec<&str> = names.iter().map(String::as_str).collect();
                set(if multi { KeywordKind::MultiCompile } else { KeywordKind::ShaderFeature }, &names)
            })
            .collect();
        // Each material picks one option of each shader_feature set (an off choice means none).
        let materials: Vec<Vec<String>> = picks
            .iter()
            .map(|pick| {
                sets.iter().zip(pick).filter(|(s, _)| s.kind == KeywordKind::ShaderFeature)
                    .filter_map(|(s, &p)| s.options[p % s.options.len()].keyword.clone())
                    .collect()
            })
            .collect();
        let refs: Vec<Vec<&str>> = materials.iter().map(|m| m.iter().map(String::as_str).collect()).collect();
        let pass = PassKeywords::new(sets.clone());
        let variants = pass.enumerate(&refs, false, None).expect("small");

        let multi: usize = sets.iter().filter(|s| s.kind == KeywordKind::MultiCompile).map(|s| s.options.len()).product();
        let projections: HashSet<Vec<String>> = materials.iter().map(|m| { let mut m = m.clone(); m.sort(); m }).collect();
        prop_assert_eq!(variants.len(), multi * projections.len());
        let keys: HashSet<String> = variants.iter().map(|v| v.bits.key()).collect();
        prop_assert_eq!(keys.len(), variants.len(), "keys are distinct");
        for variant in &variants {
            let keywords: Vec<&str> = pass.keywords(&variant.bits).collect();
            for s in &sets {
                prop_assert!(s.keywords().filter(|k| keywords.contains(k)).count() <= 1);
            }
        }
    }
}

#[test]
fn every_bad_material_has_a_pinned_diagnostic() {
    let shader = PathBuf::from("fixtures/bad/materials/Test.shader");
    let materials = fixture_files("fixtures/bad/materials", "mat");
    assert!(materials.len() >= 12);
    for material in materials {
        let (_, rendered, errors) = list(&[shader.clone(), material.clone()]);
        let warning_only = material.file_name().is_some_and(|n| n.to_string_lossy().starts_with("warn_"));
        assert_eq!(errors, !warning_only, "{}: {rendered}", material.display());
        assert!(!rendered.is_empty(), "{} reports nothing", material.display());
        expect_file![root().join(material.with_extension("stderr"))].assert_eq(&rendered);
        let cli = kiln(&["list", shader.to_str().expect("utf-8"), material.to_str().expect("utf-8")]);
        assert_eq!(cli.status.code(), Some(if warning_only { 0 } else { 1 }), "{}", material.display());
    }
}

#[test]
fn global_keywords_choose_one_option_of_each_multi_compile_set() {
    let project = PathBuf::from("fixtures/warn/global_keywords");
    let (listing, rendered, errors) = list(std::slice::from_ref(&project));
    assert!(!errors);
    expect_file![root().join("fixtures/warn/global_keywords/kiln.stderr")].assert_eq(&rendered);
    // The light set takes its listed keyword, the shadow set `_`, the fog set (no `_`) both.
    assert_eq!(
        used_keywords(&listing, "Warn/Lights"),
        [vec!["_SINGLE_DIRECTIONAL_LIGHT", "_FOG_LINEAR"], vec!["_SINGLE_DIRECTIONAL_LIGHT", "_FOG_EXP"]]
    );
    // Without a known state every option is built.
    let dir = tempfile::tempdir().expect("temp dir");
    std::fs::copy(project.join("Lights.shader"), dir.path().join("Lights.shader")).expect("copy");
    std::fs::write(dir.path().join("kiln.toml"), "always_include = [\"Warn/Lights\"]\n").expect("write");
    let (listing, _, _) = list(&[dir.path().to_path_buf()]);
    assert_eq!(used_keywords(&listing, "Warn/Lights").len(), 8);
}

#[test]
fn a_malformed_project_file_is_reported_and_defaults_are_used() {
    let (listing, rendered, errors) = list(&[PathBuf::from("fixtures/bad/config")]);
    assert!(errors);
    assert_eq!(listing.shaders.len(), 1, "the defaults still find the shader");
    expect_file![root().join("fixtures/bad/config/kiln.stderr")].assert_eq(&rendered);
}

#[test]
fn material_new_and_preset_write_files_that_load() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path();
    std::fs::create_dir(project.join("shaders")).expect("mkdir");
    for name in ["Lit.shader", "LitPass.wgsl", "Unlit.shader", "UnlitPass.wgsl"] {
        std::fs::copy(root().join("fixtures/project/shaders").join(name), project.join("shaders").join(name))
            .expect("copy");
    }
    let mat = project.join("Glass.mat");
    let mat_arg = mat.to_str().expect("utf-8");
    let project_arg = project.to_str().expect("utf-8");
    let new = kiln(&[
        "material",
        "new",
        mat_arg,
        "--shader",
        "Custom RP/Lit",
        "--preset",
        "Clip",
        "--project",
        project_arg,
    ]);
    assert_eq!(new.status.code(), Some(0), "{}", String::from_utf8_lossy(&new.stderr));
    // Said, once written: which file, of which shader, in which preset.
    let said = String::from_utf8_lossy(&new.stderr);
    assert!(said.contains("Glass.mat") && said.contains("`Custom RP/Lit`, preset Clip"), "{said}");
    let again = kiln(&["material", "new", mat_arg, "--shader", "Custom RP/Lit", "--project", project_arg]);
    assert_eq!(again.status.code(), Some(2), "an existing file is never overwritten");

    let (listing, rendered, errors) = list(&[project.to_path_buf()]);
    assert!(!errors, "{rendered}");
    let glass = &listing.materials[0];
    assert_eq!(
        (glass.preset, glass.render_queue, glass.keywords.clone()),
        (Some("Clip"), 2450, vec!["_CLIPPING".into()])
    );

    // A comment and a hand-set value survive applying another preset.
    let text = std::fs::read_to_string(&mat).expect("read");
    let edited = text.replace("_Metallic = 0", "_Metallic = 0.75 # hand-tuned");
    std::fs::write(&mat, format!("# glass for the demo\n{edited}")).expect("write");
    let preset = kiln(&["material", "preset", mat_arg, "Transparent", "--project", project_arg]);
    assert_eq!(preset.status.code(), Some(0), "{}", String::from_utf8_lossy(&preset.stderr));
    assert!(String::from_utf8_lossy(&preset.stderr).contains("applied preset Transparent to"));
    let text = std::fs::read_to_string(&mat).expect("read");
    assert!(text.starts_with("# glass for the demo\n"), "{text}");
    assert!(text.contains("_Metallic = 0.75 # hand-tuned"), "{text}");
    let (listing, rendered, errors) = list(&[project.to_path_buf()]);
    assert!(!errors, "{rendered}");
    let glass = &listing.materials[0];
    assert_eq!(
        (glass.preset, glass.render_queue, glass.keywords.clone()),
        (Some("Transparent"), 3000, vec!["_PREMULTIPLY_ALPHA".into()])
    );
    let state: Vec<(String, String)> = glass.render_state.clone();
    assert!(
        state.contains(&("_SrcBlend".into(), "One".into()))
            && state.contains(&("_DstBlend".into(), "OneMinusSrcAlpha".into())),
        "{state:?}"
    );

    // Transparent is not offered for Unlit, which has no `_PremulAlpha`.
    let unlit = project.join("Unlit.mat");
    let unlit_arg = unlit.to_str().expect("utf-8");
    let refused = kiln(&[
        "material",
        "new",
        unlit_arg,
        "--shader",
        "Custom RP/Unlit",
        "--preset",
        "Transparent",
        "--project",
        project_arg,
    ]);
    assert_eq!(refused.status.code(), Some(2));
    assert!(!unlit.exists());
}

/// Found by the `shader_parser` fuzz target: a pass with many `multi_compile` sets and no
/// materials built the whole multi_compile product (out of memory). Nothing is built without a
/// material, and an over-large product is refused with its size.
#[test]
fn a_huge_multi_compile_product_is_never_materialised() {
    let sets: Vec<KeywordSet> =
        (0..30).map(|i| set(KeywordKind::MultiCompile, &["_", &format!("_M{i}")])).collect();
    let pass = PassKeywords::new(sets);
    assert_eq!(pass.enumerate(&[], false, None), Ok(Vec::new()));
    assert_eq!(pass.enumerate(&[vec![]], false, None).map(|v| v.len()), Err(1 << 30));
    assert_eq!(pass.enumerate(&[], true, None).map(|v| v.len()), Err(1 << 30));
}

#[test]
fn material_new_without_kiln_toml_finds_shaders_from_the_current_folder() {
    let project = tempfile::tempdir().expect("temp dir");
    std::fs::create_dir_all(project.path().join("shaders")).expect("mkdir");
    std::fs::copy(
        root().join("fixtures/project/shaders/Unlit.shader"),
        project.path().join("shaders/Unlit.shader"),
    )
    .expect("copy");
    let run = |args: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_kiln"))
            .args(args)
            .current_dir(project.path())
            .output()
            .expect("kiln runs")
    };
    let made = run(&["material", "new", "materials/New.mat", "--shader", "Custom RP/Unlit"]);
    assert_eq!(made.status.code(), Some(0), "{}", String::from_utf8_lossy(&made.stderr));
    let text = std::fs::read_to_string(project.path().join("materials/New.mat")).expect("written");
    assert!(text.contains("shader = \"Custom RP/Unlit\""), "{text}");

    // A name that is nowhere says where kiln looked.
    let missing = run(&["material", "new", "materials/Other.mat", "--shader", "T/Layout"]);
    assert_eq!(missing.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&missing.stderr);
    let folder = std::fs::canonicalize(project.path()).expect("canonical");
    assert!(stderr.contains("no shader named `T/Layout` in the project at"), "{stderr}");
    assert!(stderr.contains(folder.file_name().and_then(|n| n.to_str()).expect("name")), "{stderr}");
}

#[test]
fn a_shader_that_does_not_parse_is_reported_once_not_again_by_each_of_its_materials() {
    let dir = tempfile::tempdir().expect("temp dir");
    let shaders = crate::support::root().join("fixtures/project/shaders");
    let unlit = std::fs::read_to_string(shaders.join("Unlit.shader")).expect("shader");
    // A syntax error after the name: the file does not parse.
    let broken = unlit.replacen("Properties {", "Properties { {", 1);
    assert_ne!(broken, unlit);
    std::fs::write(dir.path().join("Unlit.shader"), broken).expect("write");
    std::fs::copy(shaders.join("UnlitPass.wgsl"), dir.path().join("UnlitPass.wgsl")).expect("copy");
    for name in ["A", "B"] {
        std::fs::write(dir.path().join(format!("{name}.mat")), "shader = \"Custom RP/Unlit\"\n")
            .expect("write");
    }
    let run = crate::support::kiln(&["check", dir.path().to_str().expect("utf-8")]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("Unlit.shader:"), "the shader's own error: {stderr}");
    assert!(!stderr.contains("K0502"), "no \"unknown shader\" for its materials: {stderr}");
    // A material naming a shader that does not exist at all is still reported.
    std::fs::write(dir.path().join("C.mat"), "shader = \"Custom RP/Unlt\"\n").expect("write");
    let run = crate::support::kiln(&["check", dir.path().to_str().expect("utf-8")]);
    assert!(
        String::from_utf8_lossy(&run.stderr).contains("K0502"),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
}
