//! `#pragma` lines of program blocks: entry points, targets, requirements and keyword sets,
//! normalised as Unity does (`_`/`__` mean "no keyword"; a one-keyword `shader_feature K` means
//! `_ K`; Unity's shorthand pragmas expand to their keyword sets).
//!
//! Long because Unity's pragma vocabulary is: each kind of pragma (entry points, targets,
//! requirements, keyword sets and their shorthands) is a table and a short reader.

use crate::diagnostics::Diagnostic;
use crate::shaderlab::ast::ProgramBlock;
use crate::shaderlab::one_of;
use crate::source::{Span, Spanned};

pub use crate::manifest::{KeywordKind, KeywordScope, KeywordStage};

/// The suffixes of stage-scoped keyword pragmas (`multi_compile_vertex`), with their stages.
const STAGE_SUFFIXES: [(&str, KeywordStage); 6] = [
    ("_vertex", KeywordStage::Vertex),
    ("_fragment", KeywordStage::Fragment),
    ("_geometry", KeywordStage::Geometry),
    ("_hull", KeywordStage::Hull),
    ("_domain", KeywordStage::Domain),
    ("_raytracing", KeywordStage::RayTracing),
];

/// One choice of a keyword set: a keyword, or `None` for the all-off choice (`_`).
#[derive(Debug, Clone, PartialEq)]
pub struct KeywordOption {
    /// The keyword; `None` for `_` (all off).
    pub keyword: Option<String>,
    /// Where it is written.
    pub span: Span,
}

/// A declared keyword set, after normalisation.
#[derive(Debug, Clone, PartialEq)]
pub struct KeywordSet {
    /// Which pragma declared it.
    pub kind: KeywordKind,
    /// Global or `_local`.
    pub scope: KeywordScope,
    /// The stages that see it.
    pub stage: KeywordStage,
    /// Its choices, in order.
    pub options: Vec<KeywordOption>,
    /// The shorthand pragma this set came from (`multi_compile_fog`), if any.
    pub shorthand: Option<&'static str>,
    /// The pragma line.
    pub span: Span,
}

impl KeywordSet {
    /// The keywords, without the all-off choice.
    pub fn keywords(&self) -> impl Iterator<Item = &str> {
        self.options.iter().filter_map(|o| o.keyword.as_deref())
    }

    /// Whether one choice is `_` (no keyword).
    pub fn has_off_option(&self) -> bool {
        self.options.iter().any(|o| o.keyword.is_none())
    }
}

/// `#pragma target`: a level, optionally only for variants with all the given keywords.
#[derive(Debug, Clone, PartialEq)]
pub struct Target {
    /// The level (`4.5`, `webgpu`, ...).
    pub level: Spanned<String>,
    /// The keywords a variant must have for it to apply.
    pub keywords: Vec<Spanned<String>>,
}

/// `#pragma require`: GPU features, optionally only for variants with the given keywords.
#[derive(Debug, Clone, PartialEq)]
pub struct Require {
    /// The features required.
    pub features: Vec<Spanned<String>>,
    /// The keywords a variant must have for it to apply.
    pub keywords: Vec<Spanned<String>>,
}

/// What a pass's program says about itself through its pragmas.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ProgramPragmas {
    /// `#pragma vertex NAME`.
    pub vertex: Option<Spanned<String>>,
    /// `#pragma fragment NAME`.
    pub fragment: Option<Spanned<String>>,
    /// `#pragma kernel NAME` lines of a compute shader, in order, each name once.
    pub kernels: Vec<Spanned<String>>,
    /// `#pragma target` lines, in order.
    pub targets: Vec<Target>,
    /// `#pragma require` lines, in order.
    pub requires: Vec<Require>,
    /// Keyword sets, in declaration order.
    pub keyword_sets: Vec<KeywordSet>,
    /// `#pragma skip_variants` keywords.
    pub skip_variants: Vec<Spanned<String>>,
    /// `#pragma instancing_options` arguments (kept, not used).
    pub instancing_options: Vec<Spanned<String>>,
    /// Any other pragma: its name and the rest of the line.
    pub other: Vec<(Spanned<String>, String)>,
    /// `#pragma ubershader` (the first): the pass also builds one module that reads every keyword
    /// at run time, its fallback while a variant's pipeline is created (docs/keywords.md).
    pub ubershader: Option<Span>,
}

/// Target levels and the requirements each adds to the previous one (DESIGN.md).
pub const TARGET_LEVELS: [(&str, &[&str]); 8] = [
    ("2.0", &[]),
    ("2.5", &["derivatives"]),
    ("3.0", &["interpolators10", "samplelod", "fragcoord"]),
    ("3.5", &["interpolators15", "mrt4", "integers", "2darray", "instancing"]),
    ("4.0", &["geometry"]),
    ("4.5", &["compute", "randomwrite", "msaatex"]),
    ("4.6", &["cubearray", "tesshw", "tessellation"]),
    ("5.0", &["interpolators32", "mrt8", "sparsetex", "framebufferfetch", "setrtarrayindexfromanyshader"]),
];

/// Unity's other names for target levels, by the graphics API that has them.
pub const TARGET_ALIASES: [(&str, &str); 3] = [("es3.0", "3.5"), ("es3.1", "4.5"), ("gl4.1", "4.6")];

/// Every requirement name `#pragma require` accepts.
pub const REQUIREMENTS: [&str; 30] = [
    "interpolators10",
    "interpolators15",
    "interpolators32",
    "integers",
    "mrt4",
    "mrt8",
    "derivatives",
    "samplelod",
    "fragcoord",
    "2darray",
    "cubearray",
    "instancing",
    "geometry",
    "compute",
    "randomwrite",
    "msaatex",
    "tesshw",
    "tessellation",
    "sparsetex",
    "framebufferfetch",
    "setrtarrayindexfromanyshader",
    "native16bit",
    "int64",
    "sampleshading",
    "barycentrics",
    "wavebasic",
    "wavevote",
    "waveballot",
    "wavemath",
    "waveshuffle",
];

/// Unity's shorthand pragmas and the keyword sets kiln expands them to (docs/keywords.md).
const SHORTHANDS: [(&str, &[&str]); 11] = [
    ("multi_compile_instancing", &["_ INSTANCING_ON"]),
    ("multi_compile_fog", &["_ FOG_LINEAR FOG_EXP FOG_EXP2"]),
    ("multi_compile_particles", &["_ SOFTPARTICLES_ON"]),
    ("multi_compile_shadowcaster", &["SHADOWS_DEPTH SHADOWS_CUBE"]),
    (
        "multi_compile_fwdbase",
        &[
            "DIRECTIONAL",
            "_ LIGHTMAP_ON",
            "_ DIRLIGHTMAP_COMBINED",
            "_ DYNAMICLIGHTMAP_ON",
            "_ SHADOWS_SCREEN",
            "_ SHADOWS_SHADOWMASK",
            "_ LIGHTMAP_SHADOW_MIXING",
            "_ LIGHTPROBE_SH",
            "_ VERTEXLIGHT_ON",
        ],
    ),
    (
        "multi_compile_fwdbasealpha",
        &[
            "DIRECTIONAL",
            "_ LIGHTMAP_ON",
            "_ DIRLIGHTMAP_COMBINED",
            "_ DYNAMICLIGHTMAP_ON",
            "_ LIGHTMAP_SHADOW_MIXING",
            "_ VERTEXLIGHT_ON",
            "_ LIGHTPROBE_SH",
        ],
    ),
    ("multi_compile_fwdadd", &["POINT DIRECTIONAL SPOT POINT_COOKIE DIRECTIONAL_COOKIE"]),
    (
        "multi_compile_fwdadd_fullshadows",
        &[
            "POINT DIRECTIONAL SPOT POINT_COOKIE DIRECTIONAL_COOKIE",
            "_ SHADOWS_DEPTH SHADOWS_SCREEN SHADOWS_CUBE",
            "_ SHADOWS_SOFT",
            "_ SHADOWS_SHADOWMASK",
            "_ LIGHTMAP_SHADOW_MIXING",
        ],
    ),
    (
        "multi_compile_lightpass",
        &[
            "POINT DIRECTIONAL SPOT POINT_COOKIE DIRECTIONAL_COOKIE",
            "_ SHADOWS_DEPTH SHADOWS_SCREEN SHADOWS_CUBE",
            "_ SHADOWS_SOFT",
            "_ SHADOWS_SHADOWMASK",
            "_ UNITY_HDR_ON",
        ],
    ),
    (
        "multi_compile_prepassfinal",
        &[
            "_ LIGHTMAP_ON",
            "_ DIRLIGHTMAP_COMBINED",
            "_ DYNAMICLIGHTMAP_ON",
            "_ UNITY_HDR_ON",
            "_ SHADOWS_SHADOWMASK",
            "_ LIGHTPROBE_SH",
        ],
    ),
    ("multi_compile_shadowcollector", &["_ SHADOWS_SPLIT_SPHERES", "_ SHADOWS_SINGLE_CASCADE"]),
];

/// The shorthand pragma names kiln knows.
pub fn shorthand_names() -> impl Iterator<Item = &'static str> {
    SHORTHANDS.iter().map(|(name, _)| *name)
}

/// Mistakes in pragmas. Each variant's meaning is the diagnostic it becomes (docs/diagnostics.md).
#[derive(Debug, Clone, PartialEq)]
#[allow(missing_docs)]
pub enum PragmaError {
    UnknownTarget { span: Span, found: String },
    MissingArgument { span: Span, pragma: String, expected: &'static str },
    EmptyKeywordSet { span: Span, pragma: String },
    InvalidKeyword { span: Span, found: String },
    ReservedKeyword { span: Span, found: String, why: &'static str },
    DuplicateKeyword { span: Span, first: Span, keyword: String },
    KeywordInTwoSets { span: Span, first: Span, keyword: String },
    DynamicAndVariantKeyword { span: Span, first: Span, keyword: String, kinds: [&'static str; 2] },
    UnknownRequirement { span: Span, found: String },
    UnknownKeywordPragma { span: Span, found: String, suggestion: Option<String> },
    ConflictingEntryPoint { span: Span, first: Span, stage: &'static str },
    MisspeltPragma { span: Span, found: String, suggestion: String },
    FragmentWithoutVertex { span: Span },
}

impl From<PragmaError> for Diagnostic {
    fn from(error: PragmaError) -> Diagnostic {
        use PragmaError::*;
        match error {
            UnknownTarget { span, found } => {
                Diagnostic::error("K0201", format!("unknown shader target `{found}`"))
                    .at(span, "not a target level")
                    .help(format!("use one of {}", one_of(&TARGET_LEVELS.map(|(level, _)| level))))
            }
            MissingArgument { span, pragma, expected } => {
                Diagnostic::error("K0202", format!("`#pragma {pragma}` needs {expected}"))
                    .at(span, "missing argument")
            }
            EmptyKeywordSet { span, pragma } => {
                Diagnostic::error("K0203", format!("`#pragma {pragma}` declares no keywords"))
                    .at(span, "empty keyword set")
                    .help("list the keywords, with `_` for the all-off choice: `_ MY_KEYWORD`")
            }
            InvalidKeyword { span, found } => {
                Diagnostic::error("K0204", format!("`{found}` is not a valid keyword name"))
                    .at(span, "invalid keyword")
                    .help("keywords are made of letters, digits and `_`, and do not start with a digit")
            }
            ReservedKeyword { span, found, why } => {
                Diagnostic::error("K0204", format!("`{found}` cannot be a keyword's name: {why}"))
                    .at(span, "reserved name")
                    .note(format!("a keyword is a macro of its pass's text, so every `{found}` there would be replaced"))
                    .help("keywords are usually written in capitals with a leading `_`: `_MY_KEYWORD`")
            }
            DuplicateKeyword { span, first, keyword } => {
                Diagnostic::warning("K0205", format!("`{keyword}` appears twice in one keyword set"))
                    .at(span, "repeated here")
                    .label(first, "first listed here")
            }
            KeywordInTwoSets { span, first, keyword } => Diagnostic::warning(
                "K0206",
                format!("keyword `{keyword}` is declared in two keyword sets of this pass"),
            )
            .at(span, "declared again here")
            .label(first, "first declared here")
            .note("the sets then multiply variants that can never differ; declare each keyword once"),
            DynamicAndVariantKeyword { span, first, keyword, kinds } => Diagnostic::error(
                "K0210",
                format!("keyword `{keyword}` is declared by both `{}` and `{}`", kinds[0], kinds[1]),
            )
            .at(span, format!("declared by `{}` here", kinds[1]))
            .label(first, format!("declared by `{}` here", kinds[0]))
            .note("a `dynamic_branch` keyword is tested by `if` at run time in one module; a variant keyword makes a module of its own")
            .help("declare it once: `dynamic_branch` to branch at run time, `multi_compile` or `shader_feature` to compile variants"),
            UnknownRequirement { span, found } => {
                Diagnostic::warning("K0207", format!("unknown requirement `{found}`"))
                    .at(span, "not a requirement kiln knows")
                    .help(format!("use one of {}", one_of(&REQUIREMENTS)))
            }
            UnknownKeywordPragma { span, found, suggestion } => {
                let diagnostic =
                    Diagnostic::warning("K0208", format!("unknown keyword pragma `{found}`: it declares nothing"))
                        .at(span, "not a keyword pragma");
                match suggestion {
                    Some(suggestion) => diagnostic.help(format!("did you mean `#pragma {suggestion}`?")),
                    None => diagnostic.help(
                        "write `multi_compile`, `shader_feature` or `dynamic_branch`, optionally followed by \
                         `_local` and then `_vertex` or `_fragment`, or one of Unity's shorthands \
                         (docs/keywords.md)",
                    ),
                }
            }
            MisspeltPragma { span, found, suggestion } => {
                Diagnostic::warning("K0211", format!("unknown pragma `{found}`: it does nothing"))
                    .at(span, "not a pragma kiln or Unity knows")
                    .help(format!("did you mean `#pragma {suggestion}`?"))
            }
            FragmentWithoutVertex { span } => {
                Diagnostic::error("K0215", "a fragment stage without a vertex stage")
                    .at(span, "the pass's fragment entry point")
                    .note("a render pipeline needs a vertex stage; the pass would be built with a fragment stage alone")
                    .help("name the vertex entry point with `#pragma vertex NAME` (check its spelling)")
            }
            ConflictingEntryPoint { span, first, stage } => {
                Diagnostic::error("K0209", format!("the {stage} entry point is named twice"))
                    .at(span, "named again here")
                    .label(first, "first named here")
            }
        }
    }
}

/// One `#pragma` line: its name and arguments, with spans in the file.
struct PragmaLine {
    name: Spanned<String>,
    args: Vec<Spanned<String>>,
    /// The arguments' raw text (comment removed), for pragmas kept verbatim.
    rest: String,
    span: Span,
}

/// Where pragmas are read from: a program block's body, or an `#include_with_pragmas` file.
#[derive(Debug, Clone, Copy)]
pub struct PragmaSource<'a> {
    /// The text's span in its file.
    pub span: Span,
    /// The text.
    pub text: &'a str,
}

impl<'a> From<&'a ProgramBlock> for PragmaSource<'a> {
    fn from(block: &'a ProgramBlock) -> PragmaSource<'a> {
        PragmaSource { span: block.body_span, text: &block.body }
    }
}

/// Collects the pragmas of the given sources, in order (include blocks first, as Unity splices
/// them).
pub fn collect_pragmas<'a>(
    sources: impl IntoIterator<Item = PragmaSource<'a>>,
) -> (ProgramPragmas, Vec<Diagnostic>) {
    let mut pragmas = ProgramPragmas::default();
    let mut errors = Vec::new();
    for source in sources {
        for line in pragma_lines(source) {
            apply(&mut pragmas, line, &mut errors);
        }
    }
    finish(&mut pragmas, &mut errors);
    (pragmas, errors.into_iter().map(Diagnostic::from).collect())
}

/// Finds `#pragma` lines in a program body, skipping comments and joining `\` continuations.
fn pragma_lines(source: PragmaSource) -> Vec<PragmaLine> {
    let body = source.text;
    let base = source.span.start as usize;
    let file = source.span.file;
    let mut lines = Vec::new();
    let mut in_block_comment = false;
    let mut offset = 0;
    for raw in body.split_inclusive('\n') {
        let line_start = offset;
        offset += raw.len();
        // Tokens of this line with their offsets, comments removed.
        let mut tokens: Vec<(usize, &str)> = Vec::new();
        let bytes = raw.as_bytes();
        let mut i = 0;
        let mut token_start: Option<usize> = None;
        while i <= bytes.len() {
            let at_end = i == bytes.len();
            if in_block_comment {
                if at_end {
                    break;
                }
                // Bytes, not `str`: `i` may sit inside a multi-byte character.
                if bytes[i..].starts_with(b"*/") {
                    in_block_comment = false;
                    i += 2;
                } else {
                    i += 1;
                }
                continue;
            }
            let stop = at_end || bytes[i..].starts_with(b"//") || bytes[i..].starts_with(b"/*");
            let space = !at_end && bytes[i].is_ascii_whitespace();
            if stop || space {
                if let Some(start) = token_start.take() {
                    tokens.push((start, &raw[start..i]));
                }
                if at_end || bytes[i..].starts_with(b"//") {
                    break;
                }
                if bytes[i..].starts_with(b"/*") {
                    in_block_comment = true;
                    i += 2;
                    continue;
                }
            } else {
                if token_start.is_none() {
                    token_start = Some(i);
                }
            }
            i += 1;
        }
        // `# pragma` and `#pragma` are both accepted by C preprocessors.
        let after = match tokens.as_slice() {
            [(_, "#pragma"), ..] => 1,
            [(_, "#"), (_, "pragma"), ..] => 2,
            _ => continue,
        };
        let span_of = |(start, text): (usize, &str)| {
            Span::new(file, base + line_start + start..base + line_start + start + text.len())
        };
        let rest: Vec<(usize, &str)> = tokens[after..].to_vec();
        let Some(&name) = rest.first() else { continue };
        let first = tokens[0];
        let last = *tokens.last().expect("non-empty");
        lines.push(PragmaLine {
            name: Spanned::new(name.1.to_string(), span_of(name)),
            args: rest[1..].iter().map(|&t| Spanned::new(t.1.to_string(), span_of(t))).collect(),
            rest: rest[1..].iter().map(|t| t.1).collect::<Vec<_>>().join(" "),
            span: span_of(first).to(span_of(last)),
        });
    }
    lines
}

fn apply(pragmas: &mut ProgramPragmas, line: PragmaLine, errors: &mut Vec<PragmaError>) {
    let name = line.name.value.as_str();
    let missing =
        |expected| PragmaError::MissingArgument { span: line.span, pragma: name.to_string(), expected };
    match name {
        "vertex" | "fragment" => {
            let Some(entry) = line.args.into_iter().next() else {
                errors.push(missing("a function name"));
                return;
            };
            let slot = if name == "vertex" { &mut pragmas.vertex } else { &mut pragmas.fragment };
            match slot {
                Some(first) if first.value != entry.value => {
                    errors.push(PragmaError::ConflictingEntryPoint {
                        span: entry.span,
                        first: first.span,
                        stage: if name == "vertex" { "vertex" } else { "fragment" },
                    })
                }
                _ => *slot = Some(entry),
            }
        }
        "kernel" => {
            let Some(kernel) = line.args.into_iter().next() else {
                errors.push(missing("a kernel function name"));
                return;
            };
            if !pragmas.kernels.iter().any(|k| k.value == kernel.value) {
                pragmas.kernels.push(kernel);
            }
        }
        "target" => {
            let mut args = line.args.into_iter();
            let Some(mut level) = args.next() else {
                errors.push(missing("a target level such as `3.5`"));
                return;
            };
            if let Some((_, canonical)) = TARGET_ALIASES.iter().find(|(alias, _)| *alias == level.value) {
                level.value = canonical.to_string();
            }
            if !TARGET_LEVELS.iter().any(|(known, _)| *known == level.value) {
                errors.push(PragmaError::UnknownTarget { span: level.span, found: level.value });
                return;
            }
            pragmas.targets.push(Target { level, keywords: args.collect() });
        }
        "require" => {
            let mut features = Vec::new();
            let mut keywords = Vec::new();
            let mut after_colon = false;
            for arg in line.args {
                if arg.value == ":" {
                    after_colon = true;
                } else if after_colon {
                    keywords.push(arg);
                } else {
                    // Unity reads requirement names in any case (its manual writes `tessHW`).
                    let name = arg.value.to_ascii_lowercase();
                    if !REQUIREMENTS.contains(&name.as_str()) {
                        errors.push(PragmaError::UnknownRequirement {
                            span: arg.span,
                            found: arg.value.clone(),
                        });
                    }
                    features.push(Spanned { value: name, span: arg.span });
                }
            }
            if features.is_empty() {
                errors.push(missing("one or more requirement names"));
                return;
            }
            pragmas.requires.push(Require { features, keywords });
        }
        "skip_variants" => pragmas.skip_variants.extend(line.args),
        "ubershader" => {
            pragmas.ubershader.get_or_insert(line.span);
        }
        "instancing_options" => pragmas.instancing_options.extend(line.args),
        _ => {
            if let Some(&(shorthand, sets)) = SHORTHANDS.iter().find(|(short, _)| *short == name) {
                for set in sets {
                    let options = set
                        .split(' ')
                        .map(|k| KeywordOption {
                            keyword: (!is_none_name(k)).then(|| k.to_string()),
                            span: line.name.span,
                        })
                        .collect();
                    pragmas.keyword_sets.push(KeywordSet {
                        kind: KeywordKind::MultiCompile,
                        scope: KeywordScope::Global,
                        stage: KeywordStage::All,
                        options,
                        shorthand: Some(shorthand),
                        span: line.span,
                    });
                }
            } else if let Some((kind, scope, stage)) = keyword_pragma(name) {
                keyword_set(pragmas, kind, scope, stage, line, errors);
            } else if ["multi_compile", "shader_feature", "dynamic_branch"]
                .iter()
                .any(|p| name.starts_with(p))
            {
                errors.push(PragmaError::UnknownKeywordPragma {
                    span: line.name.span,
                    found: name.to_string(),
                    suggestion: meant_keyword_pragma(name),
                });
            } else {
                if let Some(suggestion) = misspelt(name) {
                    errors.push(PragmaError::MisspeltPragma {
                        span: line.name.span,
                        found: name.to_string(),
                        suggestion,
                    });
                }
                pragmas.other.push((line.name, line.rest));
            }
        }
    }
}

/// Pragmas Unity knows that configure what kiln does not do (surface shaders, other stages,
/// renderers, compiler switches): passed over, and never taken for a misspelling.
const UNITY_PRAGMAS: [&str; 20] = [
    "surface",
    "geometry",
    "hull",
    "domain",
    "raytracing",
    "only_renderers",
    "exclude_renderers",
    "enable_d3d11_debug_symbols",
    "hlslcc_bytecode_disassembly",
    "disable_fastmath",
    "editor_sync_compilation",
    "enable_cbuffer",
    "fragmentoption",
    "glsl_no_auto_normalization",
    "debug",
    "use_dxc",
    "never_use_dxc",
    "skip_optimizations",
    "prefer_hlslcc",
    "multi_compile_local_instancing",
];

/// The pragma `name` is likely a misspelling of: one kiln reads (or Unity knows) within two
/// edits, for a name of four letters or more that is none of them.
fn misspelt(name: &str) -> Option<String> {
    let known = known_pragmas();
    if name.len() < 4 || known.iter().any(|k| k == name) {
        return None;
    }
    crate::diagnostics::closest(name, known.iter().map(String::as_str))
}

/// The keyword pragma or shorthand nearest a name that starts like one but is none: Unity's
/// shorthands are long (`multi_compile_fwdbase_fullshadows` for `multi_compile_fwdadd_fullshadows`),
/// so the distance allowed grows with the name, a sixth of its length.
fn meant_keyword_pragma(name: &str) -> Option<String> {
    let prefixes = ["multi_compile", "shader_feature", "dynamic_branch"];
    known_pragmas()
        .into_iter()
        .filter(|k| prefixes.iter().any(|p| k.starts_with(p)))
        .map(|k| (strsim::damerau_levenshtein(&k, name), k))
        .filter(|(distance, _)| *distance <= (name.len() / 6).max(2))
        .min()
        .map(|(_, k)| k)
}

/// Every pragma name kiln reads or knows from Unity.
fn known_pragmas() -> Vec<String> {
    let mut known: Vec<String> = [
        "vertex",
        "fragment",
        "kernel",
        "target",
        "require",
        "skip_variants",
        "instancing_options",
        "once",
        "ubershader",
    ]
    .iter()
    .chain(&UNITY_PRAGMAS)
    .chain(SHORTHANDS.iter().map(|(short, _)| short))
    .map(|s| s.to_string())
    .collect();
    for kind in ["multi_compile", "shader_feature", "dynamic_branch"] {
        for scope in ["", "_local"] {
            for stage in std::iter::once("").chain(STAGE_SUFFIXES.iter().map(|(s, _)| *s)) {
                known.push(format!("{kind}{scope}{stage}"));
            }
        }
    }
    known
}

/// Splits `shader_feature_local_fragment` into its kind, scope and stage.
fn keyword_pragma(name: &str) -> Option<(KeywordKind, KeywordScope, KeywordStage)> {
    let (kind, rest) = [
        ("multi_compile", KeywordKind::MultiCompile),
        ("shader_feature", KeywordKind::ShaderFeature),
        ("dynamic_branch", KeywordKind::DynamicBranch),
    ]
    .into_iter()
    .find_map(|(prefix, kind)| name.strip_prefix(prefix).map(|rest| (kind, rest)))?;
    let (scope, rest) = match rest.strip_prefix("_local") {
        Some(rest) => (KeywordScope::Local, rest),
        None => (KeywordScope::Global, rest),
    };
    let stage = match rest {
        "" => KeywordStage::All,
        suffix => STAGE_SUFFIXES.iter().find(|(s, _)| *s == suffix)?.1,
    };
    Some((kind, scope, stage))
}

fn is_none_name(word: &str) -> bool {
    !word.is_empty() && word.bytes().all(|b| b == b'_')
}

fn is_keyword_name(word: &str) -> bool {
    let mut bytes = word.bytes();
    bytes.next().is_some_and(|b| b.is_ascii_alphabetic() || b == b'_')
        && bytes.all(|b| b.is_ascii_alphanumeric() || b == b'_')
}

fn keyword_set(
    pragmas: &mut ProgramPragmas,
    kind: KeywordKind,
    scope: KeywordScope,
    stage: KeywordStage,
    line: PragmaLine,
    errors: &mut Vec<PragmaError>,
) {
    let mut options: Vec<KeywordOption> = Vec::new();
    // Each keyword's first place, so that a pragma of 10,000 keywords is not 50 million comparisons.
    let mut first_at: std::collections::HashMap<Option<String>, Span> = std::collections::HashMap::new();
    for arg in &line.args {
        if !is_keyword_name(&arg.value) {
            errors.push(PragmaError::InvalidKeyword { span: arg.span, found: arg.value.clone() });
            continue;
        }
        if let Some(why) = super::reserved::reserved(&arg.value) {
            errors.push(PragmaError::ReservedKeyword { span: arg.span, found: arg.value.clone(), why });
            continue;
        }
        let keyword = (!is_none_name(&arg.value)).then(|| arg.value.clone());
        if let Some(&first) = first_at.get(&keyword) {
            errors.push(PragmaError::DuplicateKeyword { span: arg.span, first, keyword: arg.value.clone() });
            continue;
        }
        first_at.insert(keyword.clone(), arg.span);
        options.push(KeywordOption { keyword, span: arg.span });
    }
    if options.is_empty() {
        if line.args.is_empty() {
            errors.push(PragmaError::EmptyKeywordSet { span: line.span, pragma: line.name.value });
        }
        return;
    }
    // A lone shader_feature keyword is a toggle: it can also be off. multi_compile never expands.
    if kind != KeywordKind::MultiCompile && options.len() == 1 && options[0].keyword.is_some() {
        options.insert(0, KeywordOption { keyword: None, span: line.name.span });
    }
    pragmas.keyword_sets.push(KeywordSet { kind, scope, stage, options, shorthand: None, span: line.span });
}

/// Pass-wide rules once every line is in: instancing options, keywords declared twice.
fn finish(pragmas: &mut ProgramPragmas, errors: &mut Vec<PragmaError>) {
    if let (Some(fragment), None) = (&pragmas.fragment, &pragmas.vertex) {
        errors.push(PragmaError::FragmentWithoutVertex { span: fragment.span });
    }
    if pragmas.instancing_options.iter().any(|o| o.value.starts_with("procedural:")) {
        for set in &mut pragmas.keyword_sets {
            if set.shorthand == Some("multi_compile_instancing") {
                let span = set.span;
                set.options.push(KeywordOption { keyword: Some("PROCEDURAL_INSTANCING_ON".into()), span });
            }
        }
    }
    let mut seen: Vec<(&str, Span, KeywordKind)> = Vec::new();
    for set in &pragmas.keyword_sets {
        for option in &set.options {
            let Some(keyword) = option.keyword.as_deref() else { continue };
            let (span, keyword_name) = (option.span, keyword.to_string());
            match seen.iter().find(|(k, ..)| *k == keyword) {
                // One module cannot both branch on a keyword and be compiled per its value.
                Some(&(_, first, kind))
                    if (kind == KeywordKind::DynamicBranch) != (set.kind == KeywordKind::DynamicBranch) =>
                {
                    errors.push(PragmaError::DynamicAndVariantKeyword {
                        span,
                        first,
                        keyword: keyword_name,
                        kinds: [kind.name(), set.kind.name()],
                    })
                }
                Some(&(_, first, _)) => {
                    errors.push(PragmaError::KeywordInTwoSets { span, first, keyword: keyword_name })
                }
                None => seen.push((keyword, option.span, set.kind)),
            }
        }
    }
}

impl ProgramPragmas {
    /// Keyword sets that make variants (not `dynamic_branch`), with `skip_variants` applied.
    pub fn variant_sets(&self) -> Vec<KeywordSet> {
        self.keyword_sets
            .iter()
            .filter(|set| set.kind != KeywordKind::DynamicBranch)
            .map(|set| {
                let mut set = set.clone();
                set.options.retain(|o| {
                    o.keyword.as_deref().is_none_or(|k| !self.skip_variants.iter().any(|s| s.value == k))
                });
                set
            })
            .filter(|set| !set.options.is_empty())
            .collect()
    }

    /// The keywords an ubershader reads, in the order of its immediate data's bits: each
    /// variant keyword once (declaration order, `skip_variants` included: the ubershader serves
    /// every value), then the `dynamic_branch` ones.
    pub fn ubershader_keywords(&self) -> Vec<&str> {
        let (variant, dynamic): (Vec<&KeywordSet>, Vec<&KeywordSet>) =
            self.keyword_sets.iter().partition(|set| set.kind != KeywordKind::DynamicBranch);
        let mut keywords: Vec<&str> = Vec::new();
        for keyword in variant.into_iter().chain(dynamic).flat_map(|set| set.keywords()) {
            if !keywords.contains(&keyword) {
                keywords.push(keyword);
            }
        }
        keywords
    }

    /// Whether `keyword` is one of the pass's `dynamic_branch` keywords.
    pub fn is_dynamic(&self, keyword: &str) -> bool {
        self.keyword_sets
            .iter()
            .any(|set| set.kind == KeywordKind::DynamicBranch && set.keywords().any(|k| k == keyword))
    }

    /// `requested` without the pass's `dynamic_branch` keywords: what chooses a variant (a
    /// usage log or `kiln preprocess --keywords` may name both kinds).
    pub fn variant_keywords(&self, requested: &[String]) -> Vec<String> {
        requested.iter().filter(|k| !self.is_dynamic(k)).cloned().collect()
    }

    /// The number of variants the pass could have: the product of its set sizes, `None` past u128.
    pub fn possible_variants(&self) -> Option<u128> {
        self.variant_sets().iter().try_fold(1u128, |n, set| n.checked_mul(set.options.len() as u128))
    }

    /// The keyword combinations of its `dynamic_branch` sets (the product of their sizes), which
    /// one module serves: `None` without such sets, `Some(None)` past u128.
    pub fn dynamic_combinations(&self) -> Option<Option<u128>> {
        let mut sets =
            self.keyword_sets.iter().filter(|set| set.kind == KeywordKind::DynamicBranch).peekable();
        sets.peek()?;
        Some(sets.try_fold(1u128, |n, set| n.checked_mul(set.options.len() as u128)))
    }

    /// The base target level (the last unconditional `#pragma target`), `None` when not given.
    pub fn target(&self) -> Option<&str> {
        self.targets.iter().rev().find(|t| t.keywords.is_empty()).map(|t| t.level.value.as_str())
    }
}
