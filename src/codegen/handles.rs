//! The generated module's named constants: each shader's keywords, kernels and materials, so a
//! typo is a compile error, and each kernel's workgroup size.

use crate::manifest::{PassManifest, ShaderManifest};
use std::fmt::Write as _;

/// Its keywords, kernels and materials as constants, so that a misspelt one is a compile error
/// rather than a missing variant at run time: `keywords::_CLIPPING` is `"_CLIPPING"`,
/// `kernels::DOUBLE` is `"Double"`, `materials::LIT_CLIP` is `"LitClip"`.
pub(super) fn handles(out: &mut String, shader: &ShaderManifest) {
    let mut keywords: Vec<&str> = shader
        .passes
        .iter()
        .flat_map(|p| p.keyword_sets.iter().flat_map(|s| &s.keywords))
        .map(String::as_str)
        .filter(|k| *k != "_")
        .collect();
    keywords.sort_unstable();
    keywords.dedup();
    let mut kernels: Vec<&str> = shader.passes.iter().flat_map(|p| &p.kernels).map(String::as_str).collect();
    kernels.dedup();
    let mut materials: Vec<&str> = shader
        .passes
        .iter()
        .flat_map(|p| p.variants.iter().flat_map(|v| &v.materials))
        .map(String::as_str)
        .collect();
    materials.sort_unstable();
    materials.dedup();
    let modules = [
        ("keywords", keywords, "keyword"),
        ("kernels", kernels, "kernel"),
        ("materials", materials, "material"),
    ];
    for (module, names, what) in modules {
        if names.is_empty() {
            continue;
        }
        let _ = writeln!(
            out,
            "    /// Each {what} of the shader, as the runtime takes it.\n    pub mod {module} {{"
        );
        let mut written = std::collections::HashSet::new();
        for name in names {
            // A keyword is an identifier already; kernels and materials are written in upper case.
            let constant = if module == "keywords" { name.to_string() } else { upper_snake(name) };
            // Two names one constant (`Lit Clip`, `Lit_Clip`): the first keeps it.
            if written.insert(constant.clone()) {
                let _ = writeln!(out, "        pub const {constant}: &str = {name:?};");
            }
        }
        out.push_str("    }\n");
    }
}

/// A name as a Rust constant's: `Double` is `DOUBLE`, `LitClip` `LIT_CLIP`, `2 Sided` `_2_SIDED`.
fn upper_snake(name: &str) -> String {
    let mut out = String::with_capacity(name.len() + 4);
    let mut previous: Option<char> = None;
    for c in name.chars() {
        let word_starts =
            c.is_ascii_uppercase() && previous.is_some_and(|p| p.is_ascii_lowercase() || p.is_ascii_digit());
        if word_starts {
            out.push('_');
        }
        out.push(if c.is_ascii_alphanumeric() { c.to_ascii_uppercase() } else { '_' });
        previous = Some(c);
    }
    if out.is_empty() || out.starts_with(|c: char| c.is_ascii_digit()) {
        out.insert(0, '_');
    }
    out
}

/// `NAME_WORKGROUP_SIZE` for each kernel whose variants all have one size.
pub(super) fn kernel_constants(out: &mut String, pass: &PassManifest) {
    for (k, kernel) in pass.kernels.iter().enumerate() {
        let mut sizes = pass
            .variants
            .iter()
            .filter_map(|v| v.kernels.get(k).copied().flatten())
            .filter_map(|m| pass.stage(m).interface.workgroup_size);
        let Some(first) = sizes.next() else { continue };
        if sizes.all(|size| size == first) {
            let name = upper_snake(kernel);
            let _ = writeln!(
                out,
                "    /// `{kernel}`'s `@workgroup_size` (pass {}).\n    pub const {name}_WORKGROUP_SIZE: [u32; 3] = {first:?};",
                pass.index
            );
        }
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn names_become_upper_snake_constants() {
        let cases = [
            ("Double", "DOUBLE"),
            ("LitClip", "LIT_CLIP"),
            ("AddOffset", "ADD_OFFSET"),
            ("CSMain", "CSMAIN"),
        ];
        for (name, constant) in cases {
            assert_eq!(super::upper_snake(name), constant);
        }
        assert_eq!(super::upper_snake("2 Sided"), "_2_SIDED");
        assert_eq!(super::upper_snake("Lit-Fade v2"), "LIT_FADE_V2");
    }
}
