//! The generated module's named constants: each shader's keywords, kernels and materials, so a
//! typo is a compile error, and each kernel's workgroup size.

use super::NameClash;
use super::names::{Case, PRELUDE_NAMES, Scope, doc_text, keyword_safe, mangle, stem, string_literal};
use crate::manifest::{PassManifest, ShaderManifest};
use std::fmt::Write as _;

/// Its keywords, kernels and materials as constants, so that a misspelt one is a compile error
/// rather than a missing variant at run time: `keywords::_CLIPPING` is `"_CLIPPING"`,
/// `kernels::DOUBLE` is `"Double"`, `materials::LIT_CLIP` is `"LitClip"`.
/// `module` is the shader module's identifier, `scope` its namespace; returns the names that
/// clash inside the three modules.
pub(super) fn handles(
    out: &mut String,
    shader: &ShaderManifest,
    module: &str,
    scope: &mut Scope,
    place: &str,
) -> Vec<NameClash> {
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
    let mut clashes = Vec::new();
    for (name, names, what) in modules {
        scope.reserve(name);
        if names.is_empty() {
            continue;
        }
        let _ = writeln!(
            out,
            "    /// Each {what} of the shader, as the runtime takes it.\n    pub mod {name} {{"
        );
        let mut constants = Scope::new(format!("module `{module}::{name}`"), PRELUDE_NAMES);
        // A keyword is an identifier already; kernels and materials are written in upper case.
        let case = if name == "keywords" { Case::AsIs } else { Case::UpperSnake };
        for value in names {
            let constant = constants.claim(value, case, &format!("a {what} of {place}"));
            let _ = writeln!(out, "        pub const {constant}: &str = {};", string_literal(value));
        }
        clashes.extend(constants.clashes);
        out.push_str("    }\n");
    }
    clashes
}

/// `NAME_WORKGROUP_SIZE` for each kernel whose variants all have one size.
pub(super) fn kernel_constants(out: &mut String, pass: &PassManifest, scope: &mut Scope, place: &str) {
    for (k, kernel) in pass.kernels.iter().enumerate() {
        let mut sizes = pass
            .variants
            .iter()
            .filter_map(|v| v.kernels.get(k).copied().flatten())
            .filter_map(|m| pass.stage(m).interface.workgroup_size);
        let Some(first) = sizes.next() else { continue };
        if sizes.all(|size| size == first) {
            let constant = format!("{}_WORKGROUP_SIZE", stem(&mangle(kernel, Case::UpperSnake)));
            let constant = scope.claim_identifier(kernel, keyword_safe(constant), place);
            let _ = writeln!(
                out,
                "    /// `{}`'s `@workgroup_size` (pass {}).\n    pub const {constant}: [u32; 3] = {first:?};",
                doc_text(kernel),
                pass.index
            );
        }
    }
}

/// `PassNKeyword`: the pass's keywords (variant and `dynamic_branch` ones) as constants of a type
/// of its own, which names the pass, so that the prelude's `variant` finds the pass from the
/// keywords and one pass's keyword given to another does not compile (the prelude's
/// `pass_keywords!` writes the type).
pub(super) fn pass_keywords(
    out: &mut String,
    pass: &PassManifest,
    module: &str,
    place: &str,
) -> Vec<NameClash> {
    let n = pass.index;
    let ty = format!("Pass{n}Keyword");
    let mut constants = Scope::new(format!("type `{module}::{ty}`"), PRELUDE_NAMES);
    constants.reserve("name");
    let pairs: Vec<String> = pass
        .keywords
        .iter()
        .chain(pass.dynamic_keywords())
        .map(|keyword| {
            let constant = constants.claim(keyword, Case::AsIs, &format!("a keyword of {place}"));
            format!("{constant} = {}", string_literal(keyword))
        })
        .collect();
    let _ = writeln!(out, "    pass_keywords!({ty}, PASS_{n}, {});", pairs.join(", "));
    constants.clashes
}
