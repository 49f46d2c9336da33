//! `.compute` files, as Unity has them: WGSL (or HLSL, as Unity's are) with the preprocessor,
//! includes and pragmas
//! (`#pragma kernel NAME` for each kernel, keyword pragmas, `target`, `require`), and no ShaderLab
//! around it. One reads as a shader of one pass whose program is the whole file, named after the
//! file (`Particles.compute` is `Particles`), so that the catalogue, keywords, builds, usage logs
//! and the run time treat its kernels as they treat a pass's stages (docs/compute.md).

use super::ast::{Pass, PassItem, ProgramBlock, ProgramLanguage, Shader, StateBlock, SubShader};
use super::parse::ParsedShader;
use crate::source::{FileId, SourceStore, Span, Spanned};
use std::path::Path;

/// The extension of compute shader files.
pub const EXTENSION: &str = "compute";

/// Whether `path` names a compute shader file.
pub fn is_compute_file(path: &Path) -> bool {
    path.extension().is_some_and(|e| e.eq_ignore_ascii_case(EXTENSION))
}

/// The language of a `.compute` file: HLSL where a kernel is marked `[numthreads(...)]`, as
/// Unity's compute shaders are, else WGSL (whose kernels are `@compute @workgroup_size(...)`).
/// Comments are not read.
fn compute_language(text: &str) -> ProgramLanguage {
    let bytes = text.as_bytes();
    let mut at = 0;
    while at < bytes.len() {
        match &bytes[at..] {
            [b'/', b'/', ..] => at += text[at..].find('\n').unwrap_or(text.len() - at),
            [b'/', b'*', ..] => at += text[at + 2..].find("*/").map_or(text.len() - at, |n| n + 4),
            // `[` is one byte: `at + 1` is a character's start.
            [b'[', ..] => {
                let after = text[at + 1..].trim_start();
                let word = after.strip_prefix("numthreads");
                if word.is_some_and(|w| !w.starts_with(|c: char| c.is_alphanumeric() || c == '_')) {
                    return ProgramLanguage::Hlsl;
                }
                at += 1;
            }
            _ => at += 1,
        }
    }
    ProgramLanguage::Wgsl
}

/// A `.compute` file as a shader: its name is the file's stem, its one pass's program the file.
pub fn parse_compute(store: &SourceStore, file: FileId) -> ParsedShader {
    let text = store.text(file);
    let whole = Span::new(file, 0..text.len());
    let name = Path::new(store.name(file))
        .file_stem()
        .map_or_else(|| "compute".to_string(), |stem| stem.to_string_lossy().into_owned());
    let state = || StateBlock {
        name: None,
        tags: Vec::new(),
        lod: None,
        render_state: Vec::new(),
        package_requirements: Vec::new(),
        legacy: Vec::new(),
    };
    let program = ProgramBlock {
        language: compute_language(text),
        is_include: false,
        body: text.to_string(),
        body_span: whole,
        span: whole,
    };
    let pass = Pass { state: state(), programs: vec![program], span: whole };
    let subshader = SubShader {
        state: state(),
        passes: vec![PassItem::Pass(pass)],
        programs: Vec::new(),
        category: None,
        span: whole,
    };
    let shader = Shader {
        name: Spanned::new(name, Span::new(file, 0..0)),
        properties: Vec::new(),
        subshaders: vec![subshader],
        categories: Vec::new(),
        includes: Vec::new(),
        fallback: None,
        custom_editors: Vec::new(),
        dependencies: Vec::new(),
        span: whole,
    };
    ParsedShader { shader: Some(shader), diagnostics: Vec::new() }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numthreads_marks_a_compute_file_as_hlsl_outside_comments() {
        assert_eq!(compute_language("[ numthreads(8, 1, 1)]\nvoid CSMain() {}"), ProgramLanguage::Hlsl);
        assert_eq!(compute_language("@compute @workgroup_size(8) fn main() {}"), ProgramLanguage::Wgsl);
        let commented =
            "// [numthreads(8, 1, 1)]\n/* [numthreads(1,1,1)] */ @compute @workgroup_size(8) fn f() {}";
        assert_eq!(compute_language(commented), ProgramLanguage::Wgsl);
        assert_eq!(compute_language("let a = b[numthreadsX];"), ProgramLanguage::Wgsl);
        assert_eq!(compute_language("é[numthreads(1,1,1)]"), ProgramLanguage::Hlsl);
    }
}
