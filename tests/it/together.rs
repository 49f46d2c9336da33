//! A build parses the stage texts of a pass's variants together where they share declarations
//! (`compile::together`): what it writes is what parsing each text alone writes, byte for byte,
//! the output folder's cache included, on every fixture, a synthetic library of 256 variants and
//! a project whose variants are the adversary's (names that mean other things in other variants,
//! a variant only valid alone, one only invalid alone).

use crate::reach::build_with;
use crate::support::{root, synthetic_project, tree};
use kiln::config::{ParseScope, VariantSelection};
use kiln::orchestrate::BuildSummary;
use std::fmt::Write as _;
use std::path::Path;

/// Builds `project` with its texts parsed together and alone; asserts the same errors and the
/// same files; the two summaries.
fn both(project: &Path, unused: VariantSelection) -> (BuildSummary, BuildSummary) {
    let dir = tempfile::tempdir().expect("temp dir");
    let (together, alone) = (dir.path().join("together"), dir.path().join("alone"));
    let (parsed_together, errors) = build_with(project, &together, ParseScope::Together, unused);
    let (parsed_alone, errors_alone) = build_with(project, &alone, ParseScope::Reachable, unused);
    assert_eq!(errors, errors_alone, "{}: the errors differ", project.display());
    let (a, b) = (tree(&together), tree(&alone));
    assert_eq!(
        a.keys().collect::<Vec<_>>(),
        b.keys().collect::<Vec<_>>(),
        "{}: the files differ",
        project.display()
    );
    for (path, bytes) in &a {
        assert!(*bytes == b[path], "{}: {} differs", project.display(), path.display());
    }
    assert_eq!(parsed_alone.parsed_together, 0);
    (parsed_together, parsed_alone)
}

/// What a build parsed, as the golden pins it.
fn line(together: &BuildSummary, alone: &BuildSummary) -> String {
    format!(
        "{} modules from {} texts preprocessed, {} cut out of parses together; naga parsed {} texts, {} alone",
        together.modules, together.preprocessed, together.parsed_together, together.parses, alone.parses
    )
}

#[test]
fn every_fixture_writes_the_same_bytes_parsed_together_as_alone() {
    let mut table = String::new();
    for fixture in crate::reach::FIXTURES {
        let project = root().join("fixtures").join(fixture);
        let (together, alone) = both(&project, VariantSelection::DefaultsAndEachKeyword);
        let _ = writeln!(table, "{fixture}: {}", line(&together, &alone));
    }
    expect_test::expect_file!["../golden/together/fixtures.txt"].assert_eq(&table);
}

#[test]
fn a_library_s_variants_are_parsed_a_few_at_a_time_and_write_what_they_write_alone() {
    let project = tempfile::tempdir().expect("temp dir");
    synthetic_project(project.path(), 256);
    let (together, alone) = both(project.path(), VariantSelection::Used);
    // 256 fragment texts, 16 to a parse; the one vertex text parsed alone.
    assert_eq!(together.modules, 257);
    assert_eq!(together.parsed_together, 256, "{}", line(&together, &alone));
    assert_eq!((together.parses, alone.parses), (17, 257));
}

#[test]
fn variants_whose_names_mean_other_things_write_what_they_write_alone() {
    let (together, alone) = both(&root().join("fixtures/together"), VariantSelection::All { limit: 64 });
    expect_test::expect_file!["../golden/together/adversary.txt"]
        .assert_eq(&format!("{}\n", line(&together, &alone)));
}

/// What the variants of the error test share: most of each text, as a library is.
const LIBRARY: &str = "fn Luminance(c: vec3<f32>) -> f32 { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }\n\
    fn Reinhard(c: vec3<f32>) -> vec3<f32> { return c / (vec3(1.0) + vec3(Luminance(c))); }\n\
    fn Gamma(c: vec3<f32>) -> vec3<f32> { return pow(max(c, vec3(0.0)), vec3(1.0 / 2.2)); }\n\
    fn Saturate(c: vec3<f32>, amount: f32) -> vec3<f32> { return mix(vec3(Luminance(c)), c, amount); }\n\
    fn Vignette(c: vec3<f32>, at: vec2<f32>) -> vec3<f32> { return c * (1.0 - 0.3 * dot(at, at)); }\n\
    fn Tone(c: vec4<f32>) -> vec4<f32> {\n\
        let mapped = Gamma(Saturate(Reinhard(c.rgb), 1.1));\n\
        return vec4(Vignette(mapped, c.xy), c.a);\n\
    }\n";

#[test]
fn a_variant_valid_only_together_or_invalid_only_as_cut_out_reports_its_own_error() {
    let project = tempfile::tempdir().expect("temp dir");
    std::fs::write(project.path().join("kiln.toml"), "shaders = [\".\"]\nglobal_keywords = []\n")
        .expect("write");
    // A parse error in a pass leaves it unbuilt: the two errors are in two shaders.
    let shader = |name: &str, keywords: &str, declarations: &str, parameters: &str, body: &str| {
        format!(
            "Shader \"Together/{name}\" {{\n SubShader {{\n  Pass {{\n   WGSLPROGRAM\n{keywords}\
             #pragma vertex Vertex\n#pragma fragment Fragment\nconst WHITE: vec4<f32> = vec4(1.0);\n{declarations}\
             @vertex fn Vertex(@location(0) p: vec4<f32>) -> @builtin(position) vec4<f32> {{ return p; }}\n\
             {LIBRARY}\
             @fragment fn Fragment(@builtin(position) at: vec4<f32>\n{parameters}) -> @location(0) vec4<f32> {{\n\
             var c = WHITE * at.x;\n{body}return Tone(c);\n}}\n   ENDWGSL\n  }}\n }}\n}}\n"
        )
    };
    let undeclared = shader(
        "Undeclared",
        "#pragma multi_compile_fragment _ _DECLARE\n#pragma multi_compile_fragment _ _USE\n",
        "#if defined(_DECLARE)\nfn helper() -> f32 { return 0.5; }\n#endif\n",
        "",
        "#if defined(_USE)\nc *= helper();\n#endif\n",
    );
    let invalid = shader(
        "Invalid",
        "#pragma multi_compile_fragment _ _VERTEX_INDEX\n#pragma multi_compile_fragment _ _HALF\n",
        "",
        "#if defined(_VERTEX_INDEX)\n, @builtin(vertex_index) index: u32\n#endif\n",
        "#if defined(_HALF)\nc *= 0.5;\n#endif\n",
    );
    std::fs::write(project.path().join("Undeclared.shader"), undeclared).expect("write");
    std::fs::write(project.path().join("Invalid.shader"), invalid).expect("write");
    let dir = tempfile::tempdir().expect("temp dir");
    let all = VariantSelection::All { limit: 64 };
    let (summary, errors) =
        build_with(project.path(), &dir.path().join("together"), ParseScope::Together, all);
    // The `Invalid` shader's four fragment texts are parsed together: those naga's validation
    // refuses are built again alone, and so reported.
    assert!(summary.parsed_together >= 1, "{summary:?}");
    let (_, alone) = build_with(project.path(), &dir.path().join("alone"), ParseScope::Reachable, all);
    // `_USE` without `_DECLARE` (with and without `_VERTEX_INDEX`): naga's parse refuses it alone,
    // not together. A fragment stage's `vertex_index`: only naga's validation refuses it, so its
    // variants are cut out of a parse together and then built alone.
    assert!(errors.iter().any(|e| e.contains("`helper`") && e.contains("variant `_USE`")), "{errors:#?}");
    assert!(errors.iter().any(|e| e.contains("vertex_index") || e.contains("VertexIndex")), "{errors:#?}");
    assert_eq!(errors, alone);
}
