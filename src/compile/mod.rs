//! naga: parse, bind, validate, compact and emit every used variant's stage modules, with every
//! naga error re-mapped through the preprocessor's source map to its original file:line:col.
//!
//! - `bind.rs`: binding assignment by update frequency, one layout per pass.
//! - `target.rs`: what `#pragma target` / `require` allow.
//! - `layout.rs`: host-shareable layouts by the WGSL spec (naga's offsets corrected, `@align`/`@size`
//!   written back into emitted WGSL).
//! - `cg.rs`: Cg's `sampler2D` and `tex2D` rewritten as HLSL's textures, sampler states and
//!   methods, with the source map kept.
//! - `hlsl.rs`: HLSL and Cg programs through glslang's HLSL front end to SPIR-V, read back by
//!   naga; their constant buffers' packing kept, or refused at the member.
//! - `hlsl_reach.rs`: an HLSL text cut to what its entry point reaches, before glslang parses it
//!   (WGSL's is `reach.rs`).
//! - `stage.rs`: one stage module from parsed text to WGSL, SPIR-V and reflection.
//! - `wgsl.rs`: WGSL out, repaired where naga's writer misspells a construct, so that it loads again.
//! - `gaps.rs`: what naga's SPIR-V writer cannot write (a module with it ships as WGSL only).
//! - `platforms.rs`: MSL, HLSL and GLSL through naga's writers with wgpu's options, for Metal,
//!   DX12 and GL; `glslang.rs` reads the GLSL and HLSL back with Khronos' validator.
//! - `messages.rs`: naga's validation errors with names instead of arena handles.
//! - `panics.rs`: a panic while compiling one module caught as a value (K0416).
//! - `spirv.rs`: corrections to naga's SPIR-V where it breaks a Vulkan rule (`SampleMask`).
//!
//! What to compile, and where modules are kept, is the build layer's (`crate::orchestrate`,
//! `crate::store`).

pub mod bind;
mod cg;
mod gaps;
pub mod glslang;
pub(crate) mod hlsl;
pub mod hlsl_reach;
mod layout;
mod messages;
mod panics;
pub mod platforms;
pub mod reach;
mod spirv;
pub(crate) mod stage;
pub mod target;
pub(crate) mod together;
mod wgsl;

use crate::diagnostics::Diagnostic;
use crate::preprocess::{Preprocessed, SourceMap};
use crate::shaderlab::ast::ProgramLanguage;
use crate::source::SourceStore;
use naga::valid::{Capabilities, ModuleInfo, ValidationFlags, Validator};

/// `text` cut to the declarations `entry` reaches, as its language's scan finds them
/// ([`reach::cut`], [`hlsl_reach::cut`]), with its map cut alike; `None` where nothing would be
/// left out, the scan cannot tell, or kiln does not compile the language.
pub fn cut(
    language: ProgramLanguage,
    text: &str,
    map: &SourceMap,
    entry: &str,
) -> Option<(String, SourceMap)> {
    match language {
        ProgramLanguage::Wgsl => reach::cut(text, map, entry),
        ProgramLanguage::Hlsl | ProgramLanguage::Cg => hlsl_reach::cut(text, map, entry),
        ProgramLanguage::Glsl => None,
    }
}

/// The text a front end reads for a stage text in `language`: Cg's with its samplers rewritten as
/// HLSL's ([`cg`]), as glslang reads it; others as they are. For the benchmarks, which hand the
/// tools alone what kiln hands them.
pub fn front_text(language: ProgramLanguage, text: String) -> String {
    match language {
        ProgramLanguage::Cg => match cg::rewrite(&text, &SourceMap::default()).rewritten {
            Some(rewritten) => rewritten.text,
            None => text,
        },
        _ => text,
    }
}

/// A parsed and validated module.
pub struct Checked {
    /// The parsed module, layouts corrected.
    pub module: naga::Module,
    /// naga's validation results.
    pub info: ModuleInfo,
}

/// Parses and validates one preprocessed text; naga stops at its first error. Bindings are not
/// checked: resources without `@group`/`@binding` get them when a pass is built.
pub fn check(preprocessed: &Preprocessed, store: &SourceStore) -> Result<Checked, Vec<Diagnostic>> {
    let mapper = Mapper { map: &preprocessed.source_map, store };
    let mut module = parse(&preprocessed.text, &mapper).map_err(|d| vec![d])?;
    layout::correct(&mut module, &preprocessed.text, &mapper).map_err(|d| vec![d])?;
    let flags = ValidationFlags::all() - ValidationFlags::BINDINGS;
    let info = validate(&module, flags, Capabilities::all(), &mapper).map_err(|d| vec![d])?;
    Ok(Checked { module, info })
}

pub(crate) fn parse(text: &str, mapper: &Mapper) -> Result<naga::Module, Diagnostic> {
    within_limits(text, mapper, ProgramLanguage::Wgsl)?;
    if let Some(diagnostic) = layout::oversized_struct(text, mapper) {
        return Err(diagnostic);
    }
    naga::front::wgsl::parse_str(text).map_err(|error| wgsl_error(&error, text, mapper))
}

/// A text's longest statement and largest function against kiln's limits (K0421): past them a
/// front end recurses deeper than a worker's stack, or takes minutes (naga's typifier; glslang's
/// HLSL front end the same way). `language` says how a function's signature is found.
pub(crate) fn within_limits(
    text: &str,
    mapper: &Mapper,
    language: ProgramLanguage,
) -> Result<(), Diagnostic> {
    if let Some((statement, operators)) = longest_statement(text).filter(|(_, n)| *n > MAX_OPERATORS) {
        let blank = text[statement.clone()].len() - text[statement.clone()].trim_start().len();
        let span = naga::Span::new((statement.start + blank) as u32, statement.end as u32);
        let message = format!("a statement of {operators} operators, past kiln's limit of {MAX_OPERATORS}");
        let mut diagnostic = mapper.diagnostic("K0421", message, vec![(span, "this statement".to_string())]);
        diagnostic.notes.push(
            "naga recurses once per operator of an expression, and one this long would overflow the stack"
                .into(),
        );
        return Err(diagnostic);
    }
    if let Some((body, terms)) = largest_function(text).filter(|(_, n)| *n > MAX_FUNCTION_TERMS) {
        // WGSL's `fn NAME(...)` before the body; in HLSL the line the body opens on.
        let signature = match language {
            ProgramLanguage::Wgsl => {
                text[..body.start].rfind("fn").map_or(body.start..body.start + 1, |fn_at| fn_at..body.start)
            }
            _ => text[..body.start].rfind('\n').map_or(0, |n| n + 1)..body.start + 1,
        };
        let span = naga::Span::new(signature.start as u32, signature.end as u32);
        let message = format!(
            "a function of {terms} operands and operators, past kiln's limit of {MAX_FUNCTION_TERMS} in one function"
        );
        let mut diagnostic = mapper.diagnostic("K0421", message, vec![(span, "this function".to_string())]);
        diagnostic.notes.push(
            "naga's time grows with the square of a function's expressions (its typifier, naga 30): twice the limit takes it seconds, ten times the limit minutes"
                .into(),
        );
        diagnostic.help = Some("split it into functions, or loop where macros repeat code".into());
        return Err(diagnostic);
    }
    Ok(())
}

/// naga's WGSL parse error, placed, with the HLSL spelling it may be.
fn wgsl_error(error: &naga::front::wgsl::ParseError, text: &str, mapper: &Mapper) -> Diagnostic {
    let mut labels: Vec<(naga::Span, String)> =
        error.labels().map(|(span, message)| (span, message.to_string())).collect();
    // naga points at the token after a missing `;` (often the next line's `}`); rustc, and the
    // rest of kiln, at the end of the statement that lacks it.
    if error.message().starts_with("expected `;`")
        && let Some((found, _)) = labels.first().cloned()
        && let Some(end) = found.to_range().and_then(|r| end_of_previous_token(text, r.start))
    {
        labels.insert(0, (naga::Span::new(end as u32 - 1, end as u32), "expected `;` after this".into()));
        labels[1].1 = "found here".into();
    }
    let hlsl = labels
        .first()
        .and_then(|(span, _)| span.to_range())
        .and_then(|range| hlsl_spelling(text, range.start));
    let mut diagnostic = mapper.diagnostic("K0401", error.message().to_string(), labels);
    diagnostic.notes.extend(error.notes().map(str::to_string));
    if let Some((hlsl, wgsl)) = hlsl {
        diagnostic
            .notes
            .push(format!("`{hlsl}` is HLSL; WGSL writes {wgsl} (a `WGSLPROGRAM` block is WGSL; as `HLSLPROGRAM` ... `ENDHLSL` the block compiles as HLSL)"));
    }
    diagnostic
}

/// HLSL's spellings users bring from Unity, with WGSL's (docs/first-shader.md's table).
const HLSL_SPELLINGS: &[(&str, &str)] = &[
    ("float", "`f32`"),
    ("float2", "`vec2<f32>` (or `vec2f`)"),
    ("float3", "`vec3<f32>` (or `vec3f`)"),
    ("float4", "`vec4<f32>` (or `vec4f`)"),
    ("half", "`f16` (with `enable f16;`), or `f32`"),
    ("half2", "`vec2<f16>`, or `vec2<f32>`"),
    ("half3", "`vec3<f16>`, or `vec3<f32>`"),
    ("half4", "`vec4<f16>`, or `vec4<f32>`"),
    ("int2", "`vec2<i32>`"),
    ("int3", "`vec3<i32>`"),
    ("int4", "`vec4<i32>`"),
    ("uint", "`u32`"),
    ("float2x2", "`mat2x2<f32>`"),
    ("float3x3", "`mat3x3<f32>`"),
    ("float4x4", "`mat4x4<f32>`"),
    ("mul", "`a * b` (matrix times vector, in that order)"),
    ("lerp", "`mix(a, b, t)`"),
    ("frac", "`fract(x)`"),
    ("tex2D", "`textureSample(texture, sampler, uv)`"),
    ("static", "`const` (or a `var<private>`)"),
    ("cbuffer", "a `struct` and `var<uniform>`"),
];

/// The HLSL spelling on the line of `at` in `text`, if one is there, with WGSL's.
fn hlsl_spelling(text: &str, at: usize) -> Option<(&'static str, &'static str)> {
    let at = at.min(text.len());
    let start = text[..at].rfind('\n').map_or(0, |n| n + 1);
    let end = text[at..].find('\n').map_or(text.len(), |n| at + n);
    let line = &text[start..end];
    let words = line.split(|c: char| !c.is_ascii_alphanumeric() && c != '_');
    words.filter_map(|word| HLSL_SPELLINGS.iter().find(|(hlsl, _)| *hlsl == word)).next().copied()
}

/// Where the token before `at` ends in `text`: blanks, line breaks and `//` comments skipped
/// (`None` when nothing is before it).
fn end_of_previous_token(text: &str, at: usize) -> Option<usize> {
    let before = text.get(..at)?;
    // The part of `at`'s own line before it, then whole lines above, each without its comment.
    let mut end = at;
    for line in before.rsplit('\n') {
        let line_start = end - line.len();
        let code = match line.find("//") {
            Some(comment) => &line[..comment],
            None => line,
        };
        let code = code.trim_end();
        if !code.is_empty() {
            return Some(line_start + code.len());
        }
        // Past this line and its line break.
        end = line_start.checked_sub(1)?;
    }
    None
}

/// The most operators one statement may have: naga's front end, validator and back ends recurse
/// once per level of an expression (some 600 bytes of stack each), and a worker's stack
/// (`build::WORKER_STACK`, 256 MiB) holds this many levels with room to spare.
const MAX_OPERATORS: usize = 100_000;

/// The most operands and operators one function's body may have ([`largest_function`]): naga's
/// WGSL front end types each new expression against those before it (`Typifier::grow`, naga
/// 30.0.1), so its time grows with their square: 0.2 s for a function of 28,000 on a 2-core
/// machine, 2.4 s at 112,000, minutes past half a million (docs/performance.md).
pub(crate) const MAX_FUNCTION_TERMS: usize = 50_000;

/// The top-level brace block of `text` (a function's body) with the most operands (names,
/// numbers) and operators, with their count, where it may pass [`MAX_FUNCTION_TERMS`]: a token
/// scan, comments skipped. A text shorter than the limit has fewer terms and is not scanned.
pub(crate) fn largest_function(text: &str) -> Option<(std::ops::Range<usize>, usize)> {
    if text.len() <= MAX_FUNCTION_TERMS {
        return None;
    }
    let bytes = text.as_bytes();
    let (mut largest, mut start, mut count, mut depth) = (None, 0, 0usize, 0usize);
    let mut at = 0;
    while at < bytes.len() {
        if let Some(end) = comment_end(text, at) {
            at = end;
            continue;
        }
        let b = bytes[at];
        match b {
            b'{' => {
                if depth == 0 {
                    (start, count) = (at, 0);
                }
                depth += 1;
            }
            b'}' => {
                depth = depth.saturating_sub(1);
                if depth == 0 && count > largest.as_ref().map_or(0, |(_, n)| *n) {
                    largest = Some((start..at + 1, count));
                }
            }
            c if depth > 0 && (c.is_ascii_alphanumeric() || c == b'_') => {
                // A name or a number is one term, however long.
                count += 1;
                while at + 1 < bytes.len()
                    && (bytes[at + 1].is_ascii_alphanumeric() || b"_.".contains(&bytes[at + 1]))
                {
                    at += 1;
                }
            }
            c if depth > 0 && b"+-*/%&|^<>=!".contains(&c) => {
                count += 1;
                while at + 1 < bytes.len() && b"+-*/%&|^<>=!".contains(&bytes[at + 1]) {
                    at += 1;
                }
            }
            _ => {}
        }
        at += 1;
    }
    if depth > 0 && count > largest.as_ref().map_or(0, |(_, n)| *n) {
        largest = Some((start..bytes.len(), count));
    }
    largest
}

/// Where the comment that starts at byte `at` of `text` ends (`None`: no comment starts there);
/// one never closed runs to the end.
fn comment_end(text: &str, at: usize) -> Option<usize> {
    match &text.as_bytes()[at..] {
        [b'/', b'/', ..] => Some(text[at..].find('\n').map_or(text.len(), |n| at + n)),
        [b'/', b'*', ..] => Some(text[at + 2..].find("*/").map_or(text.len(), |n| at + 2 + n + 2)),
        _ => None,
    }
}

/// The statement of `text` with the most operators (binary ones, member accesses and indexing:
/// what nests an expression one level deeper), with their count, where it may pass
/// [`MAX_OPERATORS`]. A token-level scan: `;`, `{` and
/// `}` end a statement, comments are skipped, and a `-` or `!` that starts an operand counts for
/// nothing (a table of negative numbers is one level deep).
fn longest_statement(text: &str) -> Option<(std::ops::Range<usize>, usize)> {
    // A level of an expression takes at least two bytes (an operand's and its operator's; bare
    // brackets nest, and naga's parser stops those at 200): a text shorter than twice the limit
    // cannot pass it, and is not scanned (every stage text goes by here).
    if text.len() <= 2 * MAX_OPERATORS {
        return None;
    }
    let bytes = text.as_bytes();
    let (mut longest, mut start, mut count) = (None, 0, 0usize);
    let mut operand_before = false;
    let mut at = 0;
    while at < bytes.len() {
        if let Some(end) = comment_end(text, at) {
            at = end;
            continue;
        }
        let b = bytes[at];
        match b {
            b';' | b'{' | b'}' => {
                if count > longest.as_ref().map_or(0, |(_, n)| *n) {
                    longest = Some((start..at, count));
                }
                (start, count, operand_before) = (at + 1, 0, false);
            }
            b'.' if bytes.get(at + 1).is_some_and(|c| c.is_ascii_alphabetic() || *c == b'_') => {
                count += 1;
                operand_before = false;
            }
            b'[' => {
                count += 1;
                operand_before = false;
            }
            b'+' | b'-' | b'*' | b'/' | b'%' | b'&' | b'|' | b'^' | b'<' | b'>' | b'=' | b'!' => {
                // A run of operator characters is one operator (`<<=`, `->`, `&&`).
                count += usize::from(operand_before);
                while at + 1 < bytes.len() && b"+-*/%&|^<>=!".contains(&bytes[at + 1]) {
                    at += 1;
                }
                operand_before = false;
            }
            b')' | b']' => operand_before = true,
            b'(' | b',' | b':' => operand_before = false,
            c if c.is_ascii_alphanumeric() || c == b'_' || c == b'.' => operand_before = true,
            _ => {}
        }
        at += 1;
    }
    if count > longest.as_ref().map_or(0, |(_, n)| *n) {
        longest = Some((start..bytes.len(), count));
    }
    longest
}

pub(crate) fn validate(
    module: &naga::Module,
    flags: ValidationFlags,
    capabilities: Capabilities,
    mapper: &Mapper,
) -> Result<ModuleInfo, Diagnostic> {
    Validator::new(flags, capabilities).validate(module).map_err(|error| {
        let message = messages::validation_message(error.as_inner(), module);
        // naga lists the enclosing function too; the narrowest span is where the mistake is.
        let mut labels: Vec<(naga::Span, String)> =
            error.spans().map(|(span, text)| (*span, messages::label(text))).collect();
        labels.sort_by_key(|(span, _)| span.to_range().map_or(usize::MAX, |r| r.len()));
        mapper.diagnostic("K0402", message, labels)
    })
}

/// Turns spans in preprocessed text into diagnostics at original positions.
pub(crate) struct Mapper<'a> {
    pub map: &'a SourceMap,
    pub store: &'a SourceStore,
}

impl Mapper<'_> {
    /// The first label that maps is primary; its include chain becomes notes.
    pub(crate) fn diagnostic(
        &self,
        code: &'static str,
        message: String,
        labels: Vec<(naga::Span, String)>,
    ) -> Diagnostic {
        let ranges = labels.into_iter().filter_map(|(span, text)| Some((span.to_range()?, text))).collect();
        self.diagnostic_at(Diagnostic::error(code, lowercase_first(&message)), ranges)
    }

    pub(crate) fn diagnostic_at(
        &self,
        mut diagnostic: Diagnostic,
        labels: Vec<(std::ops::Range<usize>, String)>,
    ) -> Diagnostic {
        let mut primary_inclusion = None;
        for (range, text) in labels {
            let Some(origin) = self.map.map_range(range) else { continue };
            if primary_inclusion.is_none() {
                primary_inclusion = Some(origin.inclusion);
                diagnostic = diagnostic.at(origin.span, text);
                // As rustc does: the invocation is the place, the definition says why.
                if let Some(definition) = origin.definition {
                    let name = self.store.slice(definition).to_string();
                    diagnostic =
                        diagnostic.label(definition, format!("in expansion of macro `{name}` defined here"));
                }
            } else {
                diagnostic = diagnostic.label(origin.span, text);
            }
        }
        if let Some(inclusion) = primary_inclusion {
            diagnostic.notes.extend(self.map.included_from_notes(self.store, inclusion));
        }
        diagnostic
    }
}

/// naga capitalises some messages; ours start lowercase.
fn lowercase_first(message: &str) -> String {
    let mut chars = message.chars();
    match chars.next() {
        Some(first) if chars.clone().next().is_some_and(char::is_lowercase) => {
            first.to_lowercase().chain(chars).collect()
        }
        _ => message.to_string(),
    }
}
