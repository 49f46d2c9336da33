//! The HLSL and Cg front end: one preprocessed stage text, Cg's samplers rewritten (`cg.rs`),
//! through Khronos' glslang (its HLSL front end, built from source by cargo and run in process)
//! to SPIR-V, and naga's SPIR-V reader back to a module. From there a module goes the way a
//! WGSL one does: kiln binds it by resource name, validates, compacts and writes every back end
//! (docs/hlsl.md).
//!
//! glslang's messages are placed through the preprocessor's source map (its lines and columns
//! are the text's); the module's own spans are offsets into SPIR-V, which no source map knows,
//! so what naga says of it later is placed at the entry point's pragma.

use super::Mapper;
use super::cg;
use super::panics::contain_panics;
use crate::diagnostics::Diagnostic;
use crate::preprocess::Stage;
use crate::shaderlab::ast::ProgramLanguage;
use crate::source::Span;
use naga::{Module, TypeInner};

/// The SPIR-V glslang writes: 1.3 (Vulkan 1.1), what naga's reader and every wgpu device read.
const SPIRV: glslang::SpirvVersion = glslang::SpirvVersion::SPIRV1_3;

/// One stage of an HLSL (or Cg) text, as naga's module: glslang compiles `entry` for `stage`,
/// naga reads the SPIR-V back, and each constant buffer is named for kiln's binding by name.
pub(crate) fn parse(
    text: &str,
    language: ProgramLanguage,
    stage: Stage,
    (entry, entry_pragma): (&str, Span),
    mapper: &Mapper,
) -> Result<Module, Diagnostic> {
    // What bounds naga's time bounds glslang's: the same limits on a statement and a function.
    super::within_limits(text, mapper, ProgramLanguage::Hlsl)?;
    // glslang compiles a missing entry point as an empty one, with only a warning.
    if !defines_function(text, entry) {
        let d = Diagnostic::error("K0403", format!("{} entry point `{entry}` not found", stage.name()))
            .at(entry_pragma, "named here");
        return Err(match crate::diagnostics::closest(entry, function_names(text)) {
            Some(name) => d.help(format!("did you mean `{name}`?")),
            None => d.help(format!("define `{entry}(...)` in the program or its includes")),
        });
    }
    // glslang's Rust bindings panic where they meet what they do not expect (a log that is not
    // UTF-8): one module's error, never the build's end.
    contain_panics(|| parse_unguarded(text, language, stage, entry, mapper)).unwrap_or_else(|panic| {
        Err(Diagnostic::error("K0416", format!("internal error in the HLSL front end: {}", panic.message))
            .note(format!("the panic was at {}", panic.location)))
    })
}

fn parse_unguarded(
    text: &str,
    language: ProgramLanguage,
    stage: Stage,
    entry: &str,
    mapper: &Mapper,
) -> Result<Module, Diagnostic> {
    // Most HLSL texts have no Cg sampler: they are not lexed for one.
    let cg = cg::may_have_samplers(text).then(|| cg::rewrite(text, mapper.map));
    let rewritten = cg.as_ref().and_then(|cg| cg.rewritten.as_ref());
    // A failure of naga's reader where a function takes a texture is said at the parameter
    // (looked for only then, in a text without Cg samplers).
    let (original_text, original) = (text, mapper);
    let texture_parameter = || match &cg {
        Some(cg) => cg.texture_parameters.first().cloned(),
        None => cg::rewrite(original_text, original.map).texture_parameters.first().cloned(),
    };
    let rewritten_mapper;
    let (text, mapper) = match rewritten {
        Some(rewritten) => {
            rewritten_mapper = Mapper { map: &rewritten.map, store: mapper.store };
            (rewritten.text.as_str(), &rewritten_mapper)
        }
        None => (text, mapper),
    };
    let words = glslang_spirv(text, stage, entry, mapper).map_err(|d| naming_the_language(d, language))?;
    let options = naga::front::spv::Options {
        // HLSL's clip space is WGSL's (y up, depth 0 to 1): nothing to flip.
        adjust_coordinate_space: false,
        strict_capabilities: false,
        block_ctx_dump_prefix: None,
    };
    let bytes: Vec<u8> = words.iter().flat_map(|word| word.to_le_bytes()).collect();
    // naga's reader panics on some of what glslang writes (a multisampled texture array's
    // coordinates, naga 30): said as its refusal, where the variant is.
    let read = contain_panics(|| naga::front::spv::parse_u8_slice(&bytes, &options)).map_err(|panic| {
        Diagnostic::error(
            "K0426",
            format!("naga's SPIR-V reader fails on what glslang wrote for `{entry}`: {}", panic.message),
        )
        .note(format!(
            "naga panicked at {}; glslang compiled the program (docs/hlsl.md lists what is known)",
            panic.location
        ))
    })?;
    let mut module = read.map_err(|error| match texture_parameter() {
        // What naga says of a function's texture parameter: it loads from no global.
        Some(parameter) if matches!(error, naga::front::spv::Error::InvalidGlobalVar(_)) => {
            let d = Diagnostic::error("K0429", format!("a texture passed to a function: naga cannot read the SPIR-V glslang writes for it ({error})"))
                .help("sample the texture where it is declared, and pass the function what it samples");
            original.diagnostic_at(d, vec![(parameter, "this parameter".to_string())])
        }
        _ => Diagnostic::error("K0426", format!("naga cannot read the SPIR-V glslang wrote for `{entry}`: {error}"))
            .note("glslang compiled the program; naga's SPIR-V reader lacks what it wrote (docs/hlsl.md lists what is known)"),
    })?;
    name_resources(&mut module);
    check_layouts(&module, text, mapper)?;
    // naga's SPIR-V reader gives every function an expression for every global, used or not: the
    // globals the entry point uses are those left once unused expressions are gone, so that a
    // pass's bindings are numbered over the resources its stages use (and a text cut to what the
    // entry point reaches binds as its whole text does).
    naga::compact::compact(&mut module, naga::compact::KeepUnused::No);
    Ok(module)
}

/// Whether `text` has a function `name`: the name as a word, then `(`.
fn defines_function(text: &str, name: &str) -> bool {
    function_names(text).any(|found| found == name)
}

/// Every name in `text` followed by `(` (functions, and calls and casts alike).
fn function_names(text: &str) -> impl Iterator<Item = &str> {
    let word = |c: char| c.is_alphanumeric() || c == '_';
    text.match_indices('(').filter_map(move |(at, _)| {
        let before = text[..at].trim_end();
        let start = before.rfind(|c: char| !word(c)).map_or(0, |n| n + 1);
        let name = &before[start..];
        (!name.is_empty() && !name.starts_with(|c: char| c.is_ascii_digit())).then_some(name)
    })
}

/// glslang's SPIR-V for one entry point, or its first error placed where the text has it.
fn glslang_spirv(text: &str, stage: Stage, entry: &str, mapper: &Mapper) -> Result<Vec<u32>, Diagnostic> {
    use glslang::{
        Compiler, CompilerOptions, ShaderInput, ShaderMessage, ShaderSource, SourceLanguage, Target,
    };
    // glslang reads C strings: a NUL in the text or the name would end it early.
    if let Some(at) = text.find('\0') {
        let d = Diagnostic::error("K0426", "the program holds a NUL character");
        return Err(mapper.diagnostic_at(d, vec![(at..at + 1, "here".to_string())]));
    }
    let refused = |message: String| Diagnostic::error("K0426", message);
    let compiler = Compiler::acquire().ok_or_else(|| refused("glslang could not start".to_string()))?;
    let source = ShaderSource::from(text);
    let options = CompilerOptions {
        source_language: SourceLanguage::HLSL,
        target: Target::Vulkan { version: glslang::VulkanVersion::Vulkan1_1, spirv_version: SPIRV },
        version_profile: None,
        messages: ShaderMessage::DEFAULT | ShaderMessage::READ_HLSL | ShaderMessage::DISPLAY_ERROR_COLUMN,
    };
    let shader_stage = match stage {
        Stage::Vertex => glslang::ShaderStage::Vertex,
        Stage::Fragment => glslang::ShaderStage::Fragment,
        Stage::Compute => glslang::ShaderStage::Compute,
    };
    let input = ShaderInput::new(&source, shader_stage, &options, None, None)
        .map_err(|error| refused(format!("glslang refused its options: {error}")))?;
    let mut builder = glslang::Shader::new(compiler, input);
    builder.entry_point(entry);
    let shader = builder.parse().map_err(|error| glslang_error(&error, text, mapper))?;
    shader.compile().map_err(|error| glslang_error(&error, text, mapper))
}

/// glslang's first error, at its line and column of `text`: those after it follow from it
/// (glslang's HLSL parser stops at its first error, and says so twice more).
fn glslang_error(error: &glslang::error::GlslangError, text: &str, mapper: &Mapper) -> Diagnostic {
    use glslang::error::GlslangError as E;
    let log = match error {
        E::ParseError(log) | E::LinkError(log) | E::MapIoError(log) => log.log.as_str(),
        other => return Diagnostic::error("K0426", format!("glslang failed: {other}")),
    };
    let Some(first) = log.lines().find_map(parse_error_line) else {
        let message = log.lines().find(|l| !l.trim().is_empty()).unwrap_or("no message").trim();
        return Diagnostic::error("K0426", format!("glslang: {message}"));
    };
    let diagnostic = Diagnostic::error("K0426", first.message.clone());
    // The token glslang names, where the text has it there; else one character.
    let place = first.offset(text).map(|at| {
        let len = first.token.as_ref().filter(|t| text[at..].starts_with(t.as_str())).map_or(1, String::len);
        (at..at + len.max(1), "here".to_string())
    });
    mapper.diagnostic_at(diagnostic, place.into_iter().collect())
}

/// One `ERROR: 0:LINE:COLUMN: 'TOKEN' : MESSAGE` line of glslang's log.
struct ErrorLine {
    line: usize,
    column: usize,
    /// The token quoted, when glslang quotes one.
    token: Option<String>,
    message: String,
}

impl ErrorLine {
    /// Its byte offset in `text` (lines and columns count from 1, columns in bytes).
    fn offset(&self, text: &str) -> Option<usize> {
        let start = if self.line <= 1 {
            0
        } else {
            text.match_indices('\n').nth(self.line - 2).map(|(at, _)| at + 1)?
        };
        let line_end = text[start..].find('\n').map_or(text.len(), |n| start + n);
        let at = start + self.column.saturating_sub(1);
        (at <= line_end).then_some(at.min(text.len().saturating_sub(1)))
    }
}

fn parse_error_line(line: &str) -> Option<ErrorLine> {
    let rest = line.strip_prefix("ERROR: ")?;
    let mut parts = rest.splitn(4, ':');
    let (_file, line, column, tail) = (parts.next()?, parts.next()?, parts.next()?, parts.next()?);
    let (line, column) = (line.trim().parse().ok()?, column.trim().parse().ok()?);
    // `'TOKEN' : MESSAGE`, the token quoted (empty when glslang has none).
    let tail = tail.trim();
    let (token, message) = match tail.split_once(" : ") {
        Some((token, message)) => {
            let token = token.trim().trim_matches('\'');
            match token.is_empty() {
                true => (None, message.trim().to_string()),
                false => (Some(token.to_string()), format!("{}: `{token}`", message.trim())),
            }
        }
        None => (None, tail.to_string()),
    };
    Some(ErrorLine { line, column, token, message })
}

/// Says which language a message is about: glslang's messages read the same for both.
fn naming_the_language(mut diagnostic: Diagnostic, language: ProgramLanguage) -> Diagnostic {
    if diagnostic.code == "K0426" && !diagnostic.message.starts_with("glslang") {
        let language = if language == ProgramLanguage::Cg { "Cg" } else { "HLSL" };
        diagnostic.message = format!("{} (glslang, {language})", diagnostic.message);
    }
    diagnostic
}

/// Readies a module's resources for kiln's binding by name: a constant buffer reaches naga as a
/// nameless variable of a struct named for the buffer, so the variable takes the buffer's name;
/// and glslang's own numbers (0 for all, or HLSL's `t`/`s`/`b` registers, which collide in one
/// group) are dropped, so that kiln gives each name one slot for every stage of the pass.
fn name_resources(module: &mut Module) {
    // glslang names an entry point's inputs for the struct members they came from
    // (`input.positionOS`): the reflection names them as the HLSL does (`positionOS`).
    for entry in &mut module.entry_points {
        for argument in &mut entry.function.arguments {
            if let Some(name) = &mut argument.name
                && let Some((_, member)) = name.rsplit_once('.')
            {
                *name = member.to_string();
            }
        }
    }
    for (_, variable) in module.global_variables.iter_mut() {
        variable.binding = None;
        if variable.name.as_deref().is_none_or(str::is_empty)
            && matches!(variable.space, naga::AddressSpace::Uniform | naga::AddressSpace::Storage { .. })
        {
            variable.name = module.types[variable.ty].name.clone();
        }
    }
}

/// HLSL packs a constant buffer its own way: a member may start where WGSL's layout would not
/// put it (`float a; float2 b;` puts `b` at 4), and a scalar array's elements are 16 bytes
/// apart. What WGSL's layout can hold is kept (`@size` pads, [`super::layout::from_offsets`]);
/// the rest is refused here, at the member, rather than changed.
fn check_layouts(module: &Module, text: &str, mapper: &Mapper) -> Result<(), Diagnostic> {
    let mut layouter = naga::proc::Layouter::default();
    if layouter.update(module.to_ctx()).is_err() {
        return Ok(());
    }
    for (_, variable) in module.global_variables.iter() {
        if !matches!(variable.space, naga::AddressSpace::Uniform | naga::AddressSpace::Storage { .. }) {
            continue;
        }
        let TypeInner::Struct { members, .. } = &module.types[variable.ty].inner else { continue };
        let buffer = module.types[variable.ty].name.clone().unwrap_or_default();
        for member in members {
            let name = member.name.clone().unwrap_or_default();
            let layout = &layouter[member.ty];
            let alignment = layout.alignment.round_up(1);
            let wgsl_end = u64::from(member.offset) + u64::from(layout.size);
            let next = members.iter().map(|m| m.offset).find(|&o| o > member.offset);
            let problem = if member.offset % alignment != 0 {
                Some(format!(
                    "HLSL packs `{name}` at byte {}, which WGSL's layout cannot give a {} ({}-byte aligned)",
                    member.offset,
                    type_name(module, member.ty),
                    alignment
                ))
            } else if let Some(next) = next.filter(|&next| u64::from(next) < wgsl_end) {
                let after = members.iter().find(|m| m.offset == next).and_then(|m| m.name.clone());
                Some(format!(
                    "HLSL packs `{}` at byte {next}, inside the {} bytes WGSL gives `{name}` (a {}) before it",
                    after.unwrap_or_default(),
                    layout.size,
                    type_name(module, member.ty)
                ))
            } else if let TypeInner::Array { base, stride, .. } = module.types[member.ty].inner
                && stride != layouter[base].to_stride()
            {
                Some(format!(
                    "HLSL places the elements of `{name}` {stride} bytes apart, which WGSL writes as {}",
                    layouter[base].to_stride()
                ))
            } else {
                None
            };
            if let Some(message) = problem {
                let d = Diagnostic::error("K0427", message)
                    .note(format!("in `{buffer}`: every output reads one layout, so kiln keeps HLSL's or refuses it"))
                    .help("use `float4` (or a 16-byte-aligned member) where WGSL cannot follow, as docs/hlsl.md shows");
                let at = member_declaration(text, &buffer, &name);
                return Err(
                    mapper.diagnostic_at(d, at.map(|r| (r, "this member".to_string())).into_iter().collect())
                );
            }
        }
    }
    Ok(())
}

/// HLSL's name for a type naga holds, for messages.
fn type_name(module: &Module, ty: naga::Handle<naga::Type>) -> String {
    let scalar = |scalar: naga::Scalar| match (scalar.kind, scalar.width) {
        (naga::ScalarKind::Float, 2) => "half",
        (naga::ScalarKind::Float, 8) => "double",
        (naga::ScalarKind::Sint, _) => "int",
        (naga::ScalarKind::Uint, _) => "uint",
        (naga::ScalarKind::Bool, _) => "bool",
        _ => "float",
    };
    match module.types[ty].inner {
        TypeInner::Scalar(s) => scalar(s).to_string(),
        TypeInner::Vector { size, scalar: s } => format!("{}{}", scalar(s), size as u8),
        // HLSL names a matrix rows by columns; naga holds it transposed (read row-major).
        TypeInner::Matrix { columns, rows, scalar: s } => {
            format!("{}{}x{}", scalar(s), columns as u8, rows as u8)
        }
        TypeInner::Array { base, .. } => format!("{} array", type_name(module, base)),
        TypeInner::Struct { .. } => module.types[ty].name.clone().unwrap_or_else(|| "struct".into()),
        _ => "resource".into(),
    }
}

/// Where `member` of the `cbuffer` (or struct) `buffer` is declared in `text`: the member's
/// name, as a word, after the buffer's.
fn member_declaration(text: &str, buffer: &str, member: &str) -> Option<std::ops::Range<usize>> {
    let is_word = |at: usize, len: usize| {
        let before = text[..at].chars().next_back().is_none_or(|c| !c.is_alphanumeric() && c != '_');
        let after = text[at + len..].chars().next().is_none_or(|c| !c.is_alphanumeric() && c != '_');
        before && after
    };
    let declared = text.match_indices(buffer).map(|(at, _)| at).find(|&at| is_word(at, buffer.len()))?;
    let from = declared + buffer.len();
    let at =
        text[from..].match_indices(member).map(|(at, _)| from + at).find(|&at| is_word(at, member.len()))?;
    Some(at..at + member.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn glslang_error_lines_give_their_place_and_message() {
        let line =
            parse_error_line("ERROR: 0:2:72: 'undefinedThing' : unknown variable ").expect("an error line");
        assert_eq!((line.line, line.column), (2, 72));
        assert_eq!(line.message, "unknown variable: `undefinedThing`");
        let text = "float4 a;\nfloat4 vert(float3 p : POSITION) : SV_POSITION { return float4(p, 1) * undefinedThing; }";
        assert_eq!(&text[line.offset(text).expect("on the line")..][..14], "undefinedThing");
        assert!(parse_error_line("ERROR: 4 compilation errors.  No code generated.").is_none());
        let past = ErrorLine { line: 9, column: 1, token: None, message: String::new() };
        assert_eq!(past.offset(text), None);
    }

    #[test]
    fn a_member_is_found_after_its_buffer_as_a_whole_word() {
        let text =
            "cbuffer Other { float _Tiling2; }\ncbuffer UnityPerMaterial { float _Cutoff; float2 _Tiling; }";
        let at = member_declaration(text, "UnityPerMaterial", "_Tiling").expect("declared");
        assert_eq!(&text[at.start..at.end], "_Tiling");
        assert!(at.start > text.find("UnityPerMaterial").unwrap());
    }
}
