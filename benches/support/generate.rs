//! The synthetic project the scale and language-server benchmarks share: shaders with the Lit
//! pass as their body, eight `shader_feature_fragment` sets and a `multi_compile_fragment` set,
//! materials choosing distinct combinations, and shared includes each read by a tenth of the
//! shaders.

use std::fmt::Write as _;
use std::path::Path;

pub const SETS: usize = 8;
/// Shaders include one of these; touching one recompiles a tenth of the shaders.
pub const SHARED_INCLUDES: usize = 10;

/// Writes a project with about `variants` used variants; returns its folder's shader count.
pub fn generate(dir: &Path, variants: usize) -> usize {
    let per_shader = variants.min(100);
    let shaders = variants.div_ceil(per_shader);
    let materials_per_shader = per_shader / 2;
    let lit = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/project/shaders/LitPass.wgsl"),
    )
    .expect("LitPass.wgsl");
    std::fs::create_dir_all(dir.join("shaders")).expect("mkdir");
    std::fs::create_dir_all(dir.join("materials")).expect("mkdir");
    std::fs::write(dir.join("kiln.toml"), "shaders = [\"shaders\"]\nmaterials = [\"materials\"]\n")
        .expect("write");
    // The Lit pass, with each keyword changing the fragment's colour.
    let mut tweaks = String::new();
    for k in 0..SETS {
        let _ = write!(
            tweaks,
            "#if defined(_F{k})\n    color = color * {} + vec3<f32>(0.001);\n#endif\n",
            1.0 + k as f32 / 100.0
        );
    }
    tweaks.push_str(
        "#if defined(_MC)\n    color = color.bgr;\n#endif\n    color = color * SharedTint() * SHADER_TINT;\n",
    );
    let pass = lit.replace(
        "    let color = GetLighting(surface, brdf);\n",
        &format!("    var color = GetLighting(surface, brdf);\n{tweaks}"),
    );
    assert!(pass != lit, "the Lit pass still has the line the generator extends");
    std::fs::write(dir.join("shaders/SynthPass.wgsl"), pass).expect("write");
    for s in 0..SHARED_INCLUDES {
        std::fs::write(
            dir.join(format!("shaders/Shared{s}.wgsl")),
            format!("#pragma once\nfn SharedTint() -> f32 {{\n    return {};\n}}\n", 1.0 - s as f32 / 100.0),
        )
        .expect("write");
    }
    let lit_shader = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/project/shaders/Lit.shader"),
    )
    .expect("Lit")
    // One light path: the generator's own multi_compile set stands for run-time state.
    .replace("            #pragma multi_compile _ _SINGLE_DIRECTIONAL_LIGHT\n", "");
    let mut pragmas: String =
        (0..SETS).map(|k| format!("            #pragma shader_feature_fragment _ _F{k}\n")).collect();
    pragmas.push_str("            #pragma multi_compile_fragment _ _MC\n");
    // The Lit pass's own features stay declared (the materials leave them off).
    pragmas.push_str("            #pragma shader_feature _CLIPPING\n            #pragma shader_feature _PREMULTIPLY_ALPHA\n");
    for i in 0..shaders {
        let text = lit_shader
            .replace("Shader \"Custom RP/Lit\"", &format!("Shader \"Synthetic/S{i}\""))
            .replace("            #pragma shader_feature _CLIPPING\n            #pragma shader_feature _PREMULTIPLY_ALPHA\n", &pragmas)
            // Each shader's stage texts its own (a build shares identical modules between
            // passes; a library's variants are mostly distinct).
            .replace("#include \"LitPass.wgsl\"", &format!("#include \"Shared{}.wgsl\"\n            #include \"SynthPass.wgsl\"\n            const SHADER_TINT: f32 = {:.6};", i % SHARED_INCLUDES, 1.0 + i as f64 * 1e-6));
        std::fs::write(dir.join(format!("shaders/S{i:05}.shader")), text).expect("write");
        for m in 0..materials_per_shader {
            let keywords: Vec<String> =
                (0..SETS).filter(|b| m & (1 << b) != 0).map(|b| format!("\"_F{b}\"")).collect();
            std::fs::write(
                dir.join(format!("materials/S{i:05}_M{m:03}.mat")),
                format!("shader = \"Synthetic/S{i}\"\nkeywords = [{}]\n", keywords.join(", ")),
            )
            .expect("write");
        }
    }
    shaders
}
