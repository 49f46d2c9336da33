//! Golden listings, text and JSON, for the bundled project and the Unity-style fixtures.

use crate::support::{fixture_files, kiln, root};
use expect_test::expect_file;

fn check(folder: &str, golden: &str) {
    let text = kiln(&["list", folder]);
    assert_eq!(text.status.code(), Some(0), "{}", String::from_utf8_lossy(&text.stderr));
    assert!(text.stderr.is_empty(), "{}", String::from_utf8_lossy(&text.stderr));
    expect_file![root().join(format!("tests/golden/list/{golden}.txt"))]
        .assert_eq(&String::from_utf8_lossy(&text.stdout));

    let json = kiln(&["list", folder, "--format", "json"]);
    assert_eq!(json.status.code(), Some(0));
    let stdout = String::from_utf8_lossy(&json.stdout);
    let value: serde_json::Value = serde_json::from_str(&stdout).expect("list --format json prints JSON");
    assert!(value["diagnostics"].as_array().is_some_and(Vec::is_empty));
    expect_file![root().join(format!("tests/golden/list/{golden}.json"))].assert_eq(&stdout);
}

#[test]
fn bundled_project() {
    check("fixtures/project", "project");
}

#[test]
fn bundled_project_materials() {
    let output = kiln(&["list", "fixtures/project", "--materials"]);
    assert_eq!(output.status.code(), Some(0));
    expect_file![root().join("tests/golden/list/project_materials.txt")]
        .assert_eq(&String::from_utf8_lossy(&output.stdout));
}

#[test]
fn unity_style_shaders() {
    assert!(fixture_files("fixtures/unity", "shader").len() >= 3);
    check("fixtures/unity", "unity");
}

#[test]
fn without_a_path_the_project_is_the_nearest_folder_up_with_a_kiln_toml() {
    // Run in the project's `shaders/` folder, as cargo is run anywhere in a package.
    let below = crate::support::root().join("fixtures/project/shaders");
    let default = crate::support::kiln_in(&below, &["list", "--format", "json"]);
    let explicit = kiln(&["list", "fixtures/project", "--format", "json"]);
    assert_eq!(default.status.code(), Some(0), "{}", String::from_utf8_lossy(&default.stderr));
    let read = |output: &std::process::Output| {
        let value: serde_json::Value = serde_json::from_slice(&output.stdout).expect("json");
        let shaders = value["shaders"].as_array().expect("shaders").clone();
        // The same shaders and passes; paths differ only by where kiln ran.
        shaders.iter().map(|s| (s["name"].to_string(), s["passes"].to_string())).collect::<Vec<_>>()
    };
    assert_eq!(read(&default), read(&explicit));
    assert_eq!(read(&default).len(), 3);
    let file =
        serde_json::from_slice::<serde_json::Value>(&default.stdout).expect("json")["shaders"][0]["file"]
            .clone();
    assert_eq!(file, "../shaders/Complex.shader", "relative to where kiln ran");
}

#[test]
fn variant_counts_are_products_of_set_sizes() {
    let json = kiln(&["list", "fixtures/unity/UniversalLit.shader", "--format", "json"]);
    let value: serde_json::Value = serde_json::from_slice(&json.stdout).expect("json");
    let forward = &value["shaders"][0]["passes"][0];
    assert_eq!(forward["name"], "ForwardLit");
    let program = &forward["program"];
    // dynamic_branch makes no variants; skip_variants removes one of the four shadow choices.
    let product: u64 = program["keyword_sets"]
        .as_array()
        .expect("sets")
        .iter()
        .filter(|set| set["kind"] != "dynamic_branch")
        .map(|set| {
            let keywords = set["keywords"].as_array().expect("keywords");
            let skipped = keywords.iter().filter(|k| *k == "_MAIN_LIGHT_SHADOWS_SCREEN").count();
            (keywords.len() - skipped) as u64
        })
        .product();
    assert_eq!(program["possible_variants"].as_u64(), Some(product));
    assert_eq!(product, 18432);
}

#[test]
fn compute_variants_name_the_kiln_toml_that_lists_them() {
    check("fixtures/compute", "compute");
}

/// A variant a usage log names is listed with the log; one a material also uses, with both.
#[test]
fn logged_variants_name_their_log() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("runtime");
    std::fs::create_dir_all(project.join("materials")).expect("mkdir");
    for file in ["Blend.shader", "materials/Opaque.mat"] {
        std::fs::copy(root().join("fixtures/runtime").join(file), project.join(file)).expect("copy");
    }
    std::fs::write(
        project.join("kiln.toml"),
        "shaders = [\".\"]\nmaterials = [\"materials\"]\nvariant_logs = [\"usage.jsonl\"]\n",
    )
    .expect("write");
    std::fs::write(
        project.join("usage.jsonl"),
        "{\"shader\": \"Test/Blend\", \"pass\": 0, \"keywords\": [\"_TINT\"]}\n\
         {\"shader\": \"Test/Blend\", \"pass\": 0, \"keywords\": []}\n",
    )
    .expect("write");
    let run = crate::support::kiln_in(&project, &["list"]);
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
    let line = |keywords: &str| {
        stdout
            .lines()
            .find(|l| l.trim_start().starts_with(keywords))
            .unwrap_or_else(|| panic!("{stdout}"))
            .to_string()
    };
    assert!(line("(no keywords)").ends_with("Opaque, (listed in usage.jsonl)"), "{stdout}");
    assert!(line("_TINT").ends_with(" (listed in usage.jsonl)"), "{stdout}");
    assert!(!stdout.contains("always included"), "{stdout}");
}

/// Unity's `multi_compile_fwdbasealpha` (its manual's table) expands as Unity says: `DIRECTIONAL`
/// always, each of six keywords on or off.
#[test]
fn multi_compile_fwdbasealpha_expands_to_unity_s_keywords() {
    let dir = tempfile::tempdir().expect("temp dir");
    let shader = dir.path().join("F.shader");
    std::fs::write(
        &shader,
        "Shader \"Test/FwdBaseAlpha\" { SubShader { Pass {\nCGPROGRAM\n#pragma vertex vert\n#pragma fragment frag\n\
         #pragma multi_compile_fwdbasealpha\nfloat4 vert(float4 v : POSITION) : SV_POSITION { return v; }\n\
         float4 frag() : SV_Target { return 1; }\nENDCG\n} } }\n",
    )
    .expect("write");
    let run = kiln(&["list", shader.to_str().expect("UTF-8")]);
    let (stdout, stderr) = (String::from_utf8_lossy(&run.stdout), String::from_utf8_lossy(&run.stderr));
    assert!(!stderr.contains("K0208"), "a known shorthand: {stderr}");
    for set in ["DIRECTIONAL  (", "_ LIGHTMAP_ON", "_ DIRLIGHTMAP_COMBINED", "_ DYNAMICLIGHTMAP_ON"]
        .into_iter()
        .chain(["_ LIGHTMAP_SHADOW_MIXING", "_ VERTEXLIGHT_ON", "_ LIGHTPROBE_SH"])
    {
        assert!(stdout.contains(set), "{set} in:\n{stdout}");
    }
    assert!(stdout.contains("of 64 possible"), "{stdout}");
}

/// A shorthand Unity's manual does not have (`multi_compile_fwdbase_fullshadows`: the forward
/// base pass's shadows come from `multi_compile_fwdbase`) declares nothing, and the warning names
/// the shorthand nearest it; so does a misspelt suffix.
#[test]
fn an_unknown_shorthand_is_a_warning_that_names_the_nearest_one() {
    let dir = tempfile::tempdir().expect("temp dir");
    let shader = dir.path().join("F.shader");
    for (pragma, meant) in [
        ("multi_compile_fwdbase_fullshadows", "multi_compile_fwdadd_fullshadows"),
        ("shader_feature_locall", "shader_feature_local"),
        ("multi_compile_fogg", "multi_compile_fog"),
    ] {
        std::fs::write(
            &shader,
            format!(
                "Shader \"Test/Shorthand\" {{ SubShader {{ Pass {{\nCGPROGRAM\n#pragma vertex vert\n\
                 #pragma fragment frag\n#pragma {pragma}\nfloat4 vert(float4 v : POSITION) : SV_POSITION {{ return v; }}\n\
                 float4 frag() : SV_Target {{ return 1; }}\nENDCG\n}} }} }}\n"
            ),
        )
        .expect("write");
        let run = kiln(&["list", shader.to_str().expect("UTF-8")]);
        let (stdout, stderr) = (String::from_utf8_lossy(&run.stdout), String::from_utf8_lossy(&run.stderr));
        assert!(stderr.contains(&format!("warning[K0208]: unknown keyword pragma `{pragma}`")), "{stderr}");
        assert!(stderr.contains(&format!("did you mean `#pragma {meant}`?")), "{stderr}");
        assert!(stderr.contains("F.shader:5:9"), "at the pragma's name: {stderr}");
        assert!(!stdout.contains("SHADOWS") && !stdout.contains("FOG_"), "it declares nothing: {stdout}");
    }
}
