//! From text to the typed AST: the structural scan, then pest, then a walk over pest's pairs that
//! checks every value and keeps going, so one run reports every bad value in a file.
//!
//! Long because it is the AST walk for the whole grammar: one function per construct, each
//! short; they share the walker's diagnostics and the value checks.

use crate::diagnostics::Diagnostic;
use crate::shaderlab::ast::*;
use crate::shaderlab::error::ShaderLabError;
use crate::shaderlab::scan::scan;
use crate::source::{FileId, SourceStore, Span, Spanned};
use pest::Parser as _;
use pest::iterators::Pair;

#[derive(pest_derive::Parser)]
#[grammar = "shaderlab/grammar.pest"]
struct ShaderLabParser;

/// A parsed file: the shader when the syntax was sound (possibly with value errors reported), and
/// everything found wrong.
#[derive(Debug)]
pub struct ParsedShader {
    /// The AST, when the file parses.
    pub shader: Option<Shader>,
    /// What was found wrong.
    pub diagnostics: Vec<Diagnostic>,
}

/// Parses one `.shader` file held in the store (a `.compute` file reads as a shader of one pass:
/// [`super::compute`]).
pub fn parse_shader(store: &SourceStore, file: FileId) -> ParsedShader {
    // By its name: text added in memory (the accuracy harness) has no path.
    if super::compute::is_compute_file(std::path::Path::new(store.name(file))) {
        return super::compute::parse_compute(store, file);
    }
    let text = store.text(file);
    let failed = |errors: Vec<ShaderLabError>| ParsedShader {
        shader: None,
        diagnostics: errors.into_iter().map(Diagnostic::from).collect(),
    };
    let (lexical, braces) = scan(file, text);
    if !lexical.is_empty() {
        return failed(lexical);
    }
    let pairs = match ShaderLabParser::parse(Rule::file, text) {
        Ok(pairs) => pairs,
        Err(error) => {
            let error = syntax_error(file, text, error);
            // A brace problem explains a syntax error at or after it better than pest can (an
            // unclosed `{` makes pest fail at the end of the file); an earlier error is the cause.
            let blamed_at = match &error {
                ShaderLabError::Syntax { span, .. } => span.start,
                _ => 0,
            };
            let explains = |b: &ShaderLabError| match b {
                ShaderLabError::UnmatchedCloseBrace { span } => span.start <= blamed_at,
                _ => blamed_at as usize >= text.trim_end().len(),
            };
            return failed(if braces.iter().any(explains) { braces } else { vec![error] });
        }
    };
    let mut builder = Builder { file, errors: Vec::new() };
    let shader = pairs
        .into_iter()
        .next()
        .and_then(|file_pair| file_pair.into_inner().next())
        .map(|shader| builder.shader(shader));
    ParsedShader { shader, diagnostics: builder.errors.into_iter().map(Diagnostic::from).collect() }
}

// ---- syntax errors ---------------------------------------------------------------------------

fn syntax_error(file: FileId, text: &str, error: pest::error::Error<Rule>) -> ShaderLabError {
    let mut at = match error.location {
        pest::error::InputLocation::Pos(p) => p,
        pest::error::InputLocation::Span((s, _)) => s,
    };
    let mut expected: Vec<String> = Vec::new();
    let add = |words: String, expected: &mut Vec<String>| {
        if !expected.contains(&words) {
            expected.push(words);
        }
    };
    // pest tracks only rules by default, so it blames the start of the last rule tried rather
    // than the missing `=` after it. Parse again with token tracking on this (rare) error path.
    pest::set_error_detail(true);
    let detailed = ShaderLabParser::parse(Rule::file, text).err().and_then(|e| e.parse_attempts());
    pest::set_error_detail(false);
    match detailed {
        Some(attempts) if attempts.max_position >= at => {
            at = attempts.max_position;
            for stack in &attempts.call_stacks {
                if let Some(words) = stack.parent.and_then(describe) {
                    add(words.to_string(), &mut expected);
                }
            }
            for token in attempts.expected_tokens() {
                let token = token.to_string();
                if token == "\"" {
                    add("a quoted string".to_string(), &mut expected);
                } else if token.len() == 1 && "{}()[]=,:".contains(token.as_str()) {
                    add(format!("`{token}`"), &mut expected);
                }
            }
        }
        _ => {}
    }
    if expected.is_empty() {
        if let pest::error::ErrorVariant::ParsingError { positives, .. } = &error.variant {
            for words in positives.iter().filter_map(|rule| describe(*rule)) {
                add(words.to_string(), &mut expected);
            }
        }
    }
    let at = at.min(text.len());
    let found_len = token_len(&text[at..]);
    let found =
        if at >= text.len() { "end of file".to_string() } else { format!("`{}`", &text[at..at + found_len]) };
    ShaderLabError::Syntax { span: Span::new(file, at..at + found_len), expected, found }
}

/// `text` split at the commas outside parentheses (`PBR(Metallic, Standard),0` is two parts).
fn split_top_level(text: &str) -> Vec<&str> {
    let (mut parts, mut depth, mut start) = (Vec::new(), 0usize, 0);
    for (at, c) in text.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth = depth.saturating_sub(1),
            ',' if depth == 0 => {
                parts.push(&text[start..at]);
                start = at + 1;
            }
            _ => {}
        }
    }
    parts.push(&text[start..]);
    parts
}

/// A `ZTest` word: a compare function, or `Off`, which Unity's own shaders write for `Always`
/// (no depth test).
fn ztest_word(word: &str) -> Option<CompareFunction> {
    if word.eq_ignore_ascii_case("Off") {
        Some(CompareFunction::Always)
    } else {
        CompareFunction::from_word(word)
    }
}

fn token_len(rest: &str) -> usize {
    let word = rest.bytes().take_while(|b| b.is_ascii_alphanumeric() || *b == b'_' || *b == b'.').count();
    if word > 0 { word } else { rest.chars().next().map_or(0, char::len_utf8) }
}

/// Plain words for what a rule stands for; `None` for rules that are implied by another.
fn describe(rule: Rule) -> Option<&'static str> {
    Some(match rule {
        Rule::string | Rule::display_name => "a quoted string",
        Rule::number => "a number",
        Rule::integer => "a whole number",
        Rule::ident => "a name",
        Rule::vector => "a vector such as `(0, 0, 0, 1)`",
        Rule::prop_ref => "a `[_Property]` reference",
        Rule::word | Rule::value => "a value",
        Rule::blend_factor => "a blend factor",
        Rule::property => "a property",
        Rule::attribute => "an attribute",
        Rule::property_type | Rule::type_name => "a property type",
        Rule::property_default | Rule::texture_default => "a default value",
        Rule::tag => "a tag (`\"Key\" = \"Value\"`)",
        Rule::stencil_entry => "a stencil command",
        Rule::package_requirement => "a package name",
        Rule::kw_shader => "`Shader`",
        Rule::kw_properties => "`Properties`",
        Rule::kw_subshader => "`SubShader`",
        Rule::kw_category => "`Category`",
        Rule::kw_pass => "`Pass`",
        Rule::kw_use_pass => "`UsePass`",
        Rule::kw_grab_pass => "`GrabPass`",
        Rule::kw_name => "`Name`",
        Rule::kw_tags => "`Tags`",
        Rule::kw_lod => "`LOD`",
        Rule::kw_off => "`Off`",
        Rule::kw_fallback => "`Fallback`",
        Rule::kw_custom_editor | Rule::kw_custom_editor_rp => "`CustomEditor`",
        Rule::kw_package_requirements => "`PackageRequirements`",
        Rule::program_block | Rule::wgsl_open | Rule::wgsl_block => "a program block",
        Rule::kw_blend
        | Rule::kw_blend_op
        | Rule::kw_zwrite
        | Rule::kw_ztest
        | Rule::kw_zclip
        | Rule::kw_cull
        | Rule::kw_color_mask
        | Rule::kw_offset
        | Rule::kw_alpha_to_mask
        | Rule::kw_conservative
        | Rule::kw_stencil => "a render-state command",
        Rule::EOI => "end of file",
        _ => return None,
    })
}

// ---- the AST walk ----------------------------------------------------------------------------

struct Builder {
    file: FileId,
    errors: Vec<ShaderLabError>,
}

type P<'i> = Pair<'i, Rule>;

fn unescape(raw: &str) -> String {
    let mut out = String::with_capacity(raw.len());
    let mut chars = raw.chars();
    while let Some(c) = chars.next() {
        if c == '\\' {
            match chars.next() {
                Some('n') => out.push('\n'),
                Some('t') => out.push('\t'),
                Some(other) => out.push(other),
                None => out.push('\\'),
            }
        } else {
            out.push(c);
        }
    }
    out
}

impl Builder {
    fn span(&self, pair: &P) -> Span {
        let s = pair.as_span();
        Span::new(self.file, s.start()..s.end())
    }

    /// A quoted string's text. Names, tags and display names end up in the manifest and in
    /// generated code, so control characters (bar tab) and bytes that were not UTF-8 are refused.
    fn string(&mut self, pair: P) -> Spanned<String> {
        self.text(pair, false)
    }

    /// A property's display name: a string that may run over lines, as in Unity.
    fn display_name(&mut self, pair: P) -> Spanned<String> {
        self.text(pair, true)
    }

    fn text(&mut self, pair: P, line_breaks: bool) -> Spanned<String> {
        let span = self.span(&pair);
        let Some(inner) = pair.into_inner().next() else { return Spanned::new(String::new(), span) };
        let allowed = |c: char| c == '\t' || (line_breaks && (c == '\n' || c == '\r'));
        let forbidden = |c: char| (c.is_control() && !allowed(c)) || c == char::REPLACEMENT_CHARACTER;
        if let Some((at, found)) = inner.as_str().char_indices().find(|&(_, c)| forbidden(c)) {
            let start = inner.as_span().start() + at;
            let span = Span::new(self.file, start..start + found.len_utf8());
            self.errors.push(ShaderLabError::ForbiddenCharacter { span, found });
        }
        Spanned::new(unescape(inner.as_str()), span)
    }

    fn number(&mut self, pair: &P) -> f64 {
        // The grammar only lets through what `f64` parses, bar a leading `+` or `.`.
        let text = pair.as_str().trim_start_matches('+');
        let text = if text.starts_with('.') || text.starts_with("-.") {
            text.replacen('.', "0.", 1)
        } else {
            text.to_string()
        };
        text.parse().unwrap_or(0.0)
    }

    fn shader(&mut self, pair: P) -> Shader {
        let span = self.span(&pair);
        let mut inner = pair.into_inner();
        inner.next(); // `Shader`
        let name = self.string(inner.next().expect("grammar: shader name"));
        let mut shader = Shader {
            name,
            properties: Vec::new(),
            subshaders: Vec::new(),
            categories: Vec::new(),
            includes: Vec::new(),
            fallback: None,
            custom_editors: Vec::new(),
            dependencies: Vec::new(),
            span,
        };
        for item in inner {
            self.shader_item(&mut shader, item);
        }
        shader
    }

    fn shader_item(&mut self, shader: &mut Shader, item: P) {
        match item.as_rule() {
            Rule::properties => {
                // By name, so that 80,000 properties are not 3.2 billion comparisons.
                let mut declared: std::collections::HashMap<String, crate::source::Span> =
                    shader.properties.iter().map(|p| (p.name.value.clone(), p.name.span)).collect();
                for property in item.into_inner().skip(1) {
                    if let Some(property) = self.property(property) {
                        // Unity shows each declaration in its default inspector, all of them one
                        // material value: the first declaration gives its type and default.
                        if let Some(&first) = declared.get(&property.name.value) {
                            self.errors.push(ShaderLabError::DuplicateProperty {
                                span: property.name.span,
                                first,
                                name: property.name.value.clone(),
                            });
                        } else {
                            declared.insert(property.name.value.clone(), property.name.span);
                            shader.properties.push(property);
                        }
                    }
                }
            }
            Rule::category => {
                let span = self.span(&item);
                let index = shader.categories.len();
                let mut state = StateBlock::default();
                for inner in item.into_inner().skip(1) {
                    match inner.as_rule() {
                        Rule::subshader => {
                            let sub = self.subshader(inner, Some(index));
                            shader.subshaders.push(sub);
                        }
                        Rule::program_block | Rule::fallback => self.shader_item(shader, inner),
                        _ => self.state_item(&mut state, inner),
                    }
                }
                shader.categories.push(Category { state, span });
            }
            Rule::subshader => {
                let sub = self.subshader(item, None);
                shader.subshaders.push(sub);
            }
            Rule::fallback => {
                let target = item.into_inner().nth(1).expect("grammar: fallback target");
                shader.fallback = Some(match target.as_rule() {
                    Rule::kw_off => Fallback::Off(self.span(&target)),
                    _ => Fallback::Shader(self.string(target)),
                });
            }
            Rule::custom_editor => {
                let class = self.string(item.into_inner().nth(1).expect("grammar: editor class"));
                shader.custom_editors.push(CustomEditor { class, render_pipeline: None });
            }
            Rule::custom_editor_rp => {
                let mut inner = item.into_inner().skip(1);
                let class = self.string(inner.next().expect("grammar: editor class"));
                let pipeline = self.string(inner.next().expect("grammar: pipeline"));
                shader.custom_editors.push(CustomEditor { class, render_pipeline: Some(pipeline) });
            }
            Rule::dependency => {
                let mut inner = item.into_inner().skip(1);
                let name = self.string(inner.next().expect("grammar: dependency name"));
                let target = self.string(inner.next().expect("grammar: dependency shader"));
                shader.dependencies.push(Dependency { name, shader: target });
            }
            Rule::program_block => {
                let block = self.program(item);
                if block.is_include {
                    shader.includes.push(block);
                } else {
                    self.errors.push(ShaderLabError::ProgramOutsideSubShader {
                        span: block.span,
                        keyword: block.language.open_keyword(false),
                    });
                }
            }
            _ => {}
        }
    }

    fn subshader(&mut self, pair: P, category: Option<usize>) -> SubShader {
        let span = self.span(&pair);
        let mut sub = SubShader {
            state: StateBlock::default(),
            passes: Vec::new(),
            programs: Vec::new(),
            category,
            span,
        };
        for item in pair.into_inner().skip(1) {
            match item.as_rule() {
                Rule::pass => {
                    let pass = self.pass(item);
                    sub.passes.push(PassItem::Pass(pass));
                }
                Rule::use_pass => {
                    let name = self.string(item.into_inner().nth(1).expect("grammar: UsePass name"));
                    sub.passes.push(PassItem::UsePass(name));
                }
                Rule::grab_pass => {
                    let grab = self.grab_pass(item);
                    sub.passes.push(PassItem::GrabPass(grab));
                }
                Rule::program_block => {
                    let block = self.program(item);
                    sub.programs.push(block);
                }
                _ => self.state_item(&mut sub.state, item),
            }
        }
        sub
    }

    fn pass(&mut self, pair: P) -> Pass {
        let span = self.span(&pair);
        let mut pass = Pass { state: StateBlock::default(), programs: Vec::new(), span };
        for item in pair.into_inner().skip(1) {
            match item.as_rule() {
                Rule::program_block => {
                    let block = self.program(item);
                    pass.programs.push(block);
                }
                _ => self.state_item(&mut pass.state, item),
            }
        }
        pass
    }

    fn grab_pass(&mut self, pair: P) -> GrabPass {
        let span = self.span(&pair);
        let mut grab = GrabPass { texture: None, name: None, tags: Vec::new(), span };
        for item in pair.into_inner().skip(1) {
            match item.as_rule() {
                Rule::string => grab.texture = Some(self.string(item)),
                Rule::name => grab.name = Some(self.string(item.into_inner().nth(1).expect("grammar: name"))),
                Rule::tags => grab.tags.extend(self.tags(item)),
                _ => {}
            }
        }
        grab
    }

    fn tags(&mut self, pair: P) -> Vec<Tag> {
        pair.into_inner()
            .skip(1)
            .map(|tag| {
                let mut inner = tag.into_inner();
                let key = self.string(inner.next().expect("grammar: tag key"));
                let value = self.string(inner.next().expect("grammar: tag value"));
                Tag { key, value }
            })
            .collect()
    }

    fn state_item(&mut self, state: &mut StateBlock, item: P) {
        match item.as_rule() {
            Rule::name => state.name = Some(self.string(item.into_inner().nth(1).expect("grammar: name"))),
            Rule::tags => {
                let tags = self.tags(item);
                state.tags.extend(tags);
            }
            Rule::lod => {
                let value = item.into_inner().nth(1).expect("grammar: LOD value");
                let span = self.span(&value);
                match value.as_str().parse::<u32>() {
                    Ok(lod) => state.lod = Some(Spanned::new(lod, span)),
                    Err(_) => self.errors.push(ShaderLabError::OutOfRange {
                        span,
                        what: "LOD".into(),
                        found: value.as_str().into(),
                        range: "at most 4294967295",
                    }),
                }
            }
            Rule::package_requirements => {
                for requirement in item.into_inner().skip(1) {
                    let mut inner = requirement.into_inner();
                    let package = self.string(inner.next().expect("grammar: package"));
                    let version = inner.next().map(|v| self.string(v));
                    state.package_requirements.push(PackageRequirement { package, version });
                }
            }
            Rule::legacy_command => {
                let span = self.span(&item);
                let text = item.as_str().to_string();
                let keyword = item.into_inner().next().expect("grammar: legacy keyword");
                let keyword = Spanned::new(keyword.as_str().to_string(), self.span(&keyword));
                state.legacy.push(LegacyCommand { keyword, text, span });
            }
            _ => {
                if let Some(command) = self.render_command(item) {
                    state.render_state.push(command);
                }
            }
        }
    }

    // ---- properties --------------------------------------------------------------------------

    fn property(&mut self, pair: P) -> Option<Property> {
        let span = self.span(&pair);
        let mut attributes = Vec::new();
        let mut inner = pair.into_inner().peekable();
        while inner.peek().is_some_and(|p| p.as_rule() == Rule::attribute) {
            let attribute = self.attribute(inner.next().expect("peeked"));
            attributes.push(attribute);
        }
        let name_pair = inner.next().expect("grammar: property name");
        let name = Spanned::new(name_pair.as_str().to_string(), self.span(&name_pair));
        let display_name = self.display_name(inner.next().expect("grammar: display name"));
        let ty = self.property_type(inner.next().expect("grammar: property type"));
        let default_pair = inner.next().expect("grammar: default");
        let mut default = self.property_default(default_pair);
        let ty = ty?;
        self.check_default(&ty, &default);
        // Unity fills a `Vector` default's missing components with 0 (Poiyomi writes `(0, 0, 1)`).
        if let (PropertyType::Vector, PropertyDefault::Vector(components)) = (&ty.value, &mut default.value) {
            components.resize(4, 0.0);
        }
        Some(Property { attributes, name, display_name, ty, default, span })
    }

    fn attribute(&mut self, pair: P) -> Attribute {
        let span = self.span(&pair);
        let mut inner = pair.into_inner();
        let name_pair = inner.next().expect("grammar: attribute name");
        let name = Spanned::new(name_pair.as_str().to_string(), self.span(&name_pair));
        let args: Vec<Spanned<String>> = inner
            .next()
            .and_then(|args| args.into_inner().next())
            .map(|text| {
                let base = text.as_span().start();
                let mut offset = 0;
                split_top_level(text.as_str())
                    .into_iter()
                    .map(|part| {
                        let lead = part.len() - part.trim_start().len();
                        let start = base + offset + lead;
                        offset += part.len() + 1;
                        Spanned::new(
                            part.trim().to_string(),
                            Span::new(self.file, start..start + part.trim().len()),
                        )
                    })
                    .filter(|arg| !arg.value.is_empty())
                    .collect()
            })
            .unwrap_or_default();
        let kind = self.attribute_kind(&name.value, &args, span);
        Attribute { name, args, kind, span }
    }

    fn attribute_kind(&mut self, name: &str, args: &[Spanned<String>], span: Span) -> AttributeKind {
        let words: Vec<String> = args.iter().map(|a| a.value.clone()).collect();
        let mut bad = |expected: &'static str| {
            self.errors.push(ShaderLabError::AttributeArguments {
                span,
                attribute: name.to_string(),
                expected,
            });
            AttributeKind::Other
        };
        let lower = name.to_ascii_lowercase();
        match lower.as_str() {
            "toggle" | "materialtoggle" | "toggleoff" => {
                if words.len() > 1 {
                    return bad("at most one keyword");
                }
                let keyword = words.into_iter().next();
                if lower == "toggleoff" {
                    AttributeKind::ToggleOff(keyword)
                } else {
                    AttributeKind::Toggle(keyword)
                }
            }
            "toggleui" => AttributeKind::ToggleUI,
            "keywordenum" | "materialkeywordenum" => {
                if words.is_empty() {
                    return bad("one or more entry names");
                }
                AttributeKind::KeywordEnum(words)
            }
            "enum" | "materialenum" => {
                if words.is_empty() {
                    return bad("an enum type name or name, value pairs");
                }
                AttributeKind::Enum(words)
            }
            "powerslider" => match words.as_slice() {
                [value] => match value.parse() {
                    Ok(power) => AttributeKind::PowerSlider(power),
                    Err(_) => bad("one number"),
                },
                _ => bad("one number"),
            },
            "space" => match words.as_slice() {
                [] => AttributeKind::Space(0.0),
                [value] => match value.parse() {
                    Ok(height) => AttributeKind::Space(height),
                    Err(_) => bad("a number"),
                },
                _ => bad("a number"),
            },
            // Headers may contain commas: keep the whole argument text.
            "header" => AttributeKind::Header(words.join(", ")),
            "noscaleoffset" => AttributeKind::NoScaleOffset,
            "hdr" => AttributeKind::Hdr,
            "gamma" => AttributeKind::Gamma,
            "hideininspector" => AttributeKind::HideInInspector,
            "maintexture" => AttributeKind::MainTexture,
            "maincolor" => AttributeKind::MainColor,
            "perrendererdata" => AttributeKind::PerRendererData,
            "normal" => AttributeKind::Normal,
            "intrange" => AttributeKind::IntRange,
            _ => AttributeKind::Other,
        }
    }

    fn property_type(&mut self, pair: P) -> Option<Spanned<PropertyType>> {
        let span = self.span(&pair);
        let mut inner = pair.into_inner();
        let name = inner.next().expect("grammar: type name");
        let bounds: Vec<f64> = inner.map(|n| self.number(&n)).collect();
        let ty = match name.as_str().to_ascii_lowercase().as_str() {
            "float" => PropertyType::Float,
            "int" => PropertyType::Int,
            "integer" => PropertyType::Integer,
            "range" => {
                let [min, max] = bounds[..] else {
                    self.errors.push(ShaderLabError::RangeWithoutBounds { span });
                    return None;
                };
                // Unity accepts it (TextMesh Pro's `_GlowPower` is `Range(1, 0)`): a warning.
                if min > max {
                    self.errors.push(ShaderLabError::RangeMinAboveMax { span, min, max });
                }
                return Some(Spanned::new(PropertyType::Range { min, max }, span));
            }
            "color" => PropertyType::Color,
            "vector" => PropertyType::Vector,
            "2d" => PropertyType::Texture(TextureDimension::D2),
            "2darray" => PropertyType::Texture(TextureDimension::D2Array),
            "3d" => PropertyType::Texture(TextureDimension::D3),
            "cube" => PropertyType::Texture(TextureDimension::Cube),
            "cubearray" => PropertyType::Texture(TextureDimension::CubeArray),
            "any" => PropertyType::Texture(TextureDimension::Any),
            _ => {
                self.errors.push(ShaderLabError::UnknownPropertyType {
                    span: self.span(&name),
                    found: name.as_str().to_string(),
                });
                return None;
            }
        };
        if !bounds.is_empty() {
            self.errors.push(ShaderLabError::BoundsOnNonRange { span, ty: ty.name() });
            return None;
        }
        Some(Spanned::new(ty, span))
    }

    fn property_default(&mut self, pair: P) -> Spanned<PropertyDefault> {
        let span = self.span(&pair);
        let inner = pair.into_inner().next().expect("grammar: default value");
        let value = match inner.as_rule() {
            Rule::vector => PropertyDefault::Vector(inner.into_inner().map(|n| self.number(&n)).collect()),
            Rule::number => PropertyDefault::Number(self.number(&inner)),
            _ => {
                let mut parts = inner.into_inner();
                let name = self.string(parts.next().expect("grammar: texture name")).value;
                let options = parts.next().map(|o| o.as_str().trim().to_string()).filter(|o| !o.is_empty());
                PropertyDefault::Texture { name, options }
            }
        };
        Spanned::new(value, span)
    }

    fn check_default(&mut self, ty: &Spanned<PropertyType>, default: &Spanned<PropertyDefault>) {
        let name = ty.value.name();
        let expected = match ty.value {
            PropertyType::Float | PropertyType::Int | PropertyType::Integer | PropertyType::Range { .. } => {
                "a number"
            }
            PropertyType::Color | PropertyType::Vector => "a vector such as `(0, 0, 0, 1)`",
            PropertyType::Texture(_) => "a texture name such as `\"white\" {}`",
        };
        let matches = matches!(
            (&ty.value, &default.value),
            (
                PropertyType::Float | PropertyType::Int | PropertyType::Integer | PropertyType::Range { .. },
                PropertyDefault::Number(_)
            ) | (PropertyType::Color | PropertyType::Vector, PropertyDefault::Vector(_))
                | (PropertyType::Texture(_), PropertyDefault::Texture { .. })
        );
        if !matches {
            self.errors.push(ShaderLabError::DefaultMismatch { span: default.span, ty: name, expected });
            return;
        }
        if let PropertyDefault::Vector(components) = &default.value {
            let (ok, expected) = match ty.value {
                PropertyType::Color => (matches!(components.len(), 3 | 4), "3 or 4"),
                _ => (matches!(components.len(), 3 | 4), "3 or 4"),
            };
            if !ok {
                self.errors.push(ShaderLabError::VectorComponents {
                    span: default.span,
                    ty: name,
                    found: components.len(),
                    expected,
                });
            }
        }
    }

    // ---- render state ------------------------------------------------------------------------

    fn render_command(&mut self, pair: P) -> Option<RenderCommand> {
        let span = self.span(&pair);
        let rule = pair.as_rule();
        let mut inner = pair.into_inner();
        inner.next(); // the keyword
        let mut rest: Vec<P> = inner.collect();
        let kind = match rule {
            Rule::blend => {
                let target = self.render_target(&mut rest)?;
                if rest.first().is_some_and(|p| p.as_rule() == Rule::kw_off) {
                    RenderCommandKind::Blend { target, factors: None }
                } else {
                    let mut factors = rest
                        .into_iter()
                        .map(|p| self.word_value(p, "Blend", BlendFactor::from_word, BlendFactor::NAMES));
                    let src = factors.next().flatten();
                    let dst = factors.next().flatten();
                    let alpha_src = factors.next().flatten();
                    let alpha_dst = factors.next().flatten();
                    let has_alpha = alpha_src.is_some() || alpha_dst.is_some();
                    let alpha = match (alpha_src, alpha_dst) {
                        (Some(a), Some(b)) => Some((a, b)),
                        _ if has_alpha => return None,
                        _ => None,
                    };
                    RenderCommandKind::Blend {
                        target,
                        factors: Some(BlendFactors { src: src?, dst: dst?, alpha }),
                    }
                }
            }
            Rule::blend_op => {
                let target = self.render_target(&mut rest)?;
                let mut ops = rest
                    .into_iter()
                    .map(|p| self.word_value(p, "BlendOp", BlendOperation::from_word, BlendOperation::NAMES));
                let color = ops.next().flatten();
                let alpha = ops.next();
                let alpha = match alpha {
                    Some(None) => return None,
                    Some(Some(a)) => Some(a),
                    None => None,
                };
                RenderCommandKind::BlendOp { target, color: color?, alpha }
            }
            Rule::zwrite => {
                RenderCommandKind::ZWrite(self.bool_value(rest.pop()?, "ZWrite", &["On", "Off"])?)
            }
            Rule::alpha_to_mask => {
                RenderCommandKind::AlphaToMask(self.bool_value(rest.pop()?, "AlphaToMask", &["On", "Off"])?)
            }
            Rule::zclip => {
                RenderCommandKind::ZClip(self.bool_value(rest.pop()?, "ZClip", &["True", "False"])?)
            }
            Rule::conservative => RenderCommandKind::Conservative(self.bool_value(
                rest.pop()?,
                "Conservative",
                &["True", "False"],
            )?),
            Rule::ztest => RenderCommandKind::ZTest(self.word_value(
                rest.pop()?,
                "ZTest",
                ztest_word,
                CompareFunction::NAMES,
            )?),
            Rule::cull => RenderCommandKind::Cull(self.word_value(
                rest.pop()?,
                "Cull",
                CullMode::from_word,
                CullMode::NAMES,
            )?),
            Rule::color_mask => {
                let target_pair = if rest.len() == 2 { rest.pop() } else { None };
                let target = match target_pair {
                    Some(p) => self.render_target(&mut vec![p])?,
                    None => None,
                };
                let mask = self.color_mask(rest.pop()?)?;
                RenderCommandKind::ColorMask { mask, target }
            }
            Rule::offset => {
                let units = self.number_value(rest.pop()?, "Offset");
                let factor = self.number_value(rest.pop()?, "Offset");
                RenderCommandKind::Offset { factor: factor?, units: units? }
            }
            Rule::stencil => {
                let entries: Vec<Option<StencilEntry>> =
                    rest.into_iter().map(|e| self.stencil_entry(e)).collect();
                RenderCommandKind::Stencil(entries.into_iter().collect::<Option<Vec<_>>>()?)
            }
            _ => {
                debug_assert!(false, "unhandled render command {rule:?}");
                return None;
            }
        };
        Some(RenderCommand { kind, span })
    }

    /// Takes a leading render-target index off the values, if there is one.
    fn render_target(&mut self, rest: &mut Vec<P>) -> Option<Option<u32>> {
        if rest.first().is_none_or(|p| p.as_rule() != Rule::render_target) {
            return Some(None);
        }
        let pair = rest.remove(0);
        match pair.as_str().parse::<u32>() {
            Ok(target) if target < 8 => Some(Some(target)),
            _ => {
                self.errors.push(ShaderLabError::OutOfRange {
                    span: self.span(&pair),
                    what: "render target".into(),
                    found: pair.as_str().into(),
                    range: "0 to 7",
                });
                None
            }
        }
    }

    /// A `value`/`blend_factor` pair: a property reference, or a word the parser accepts.
    fn word_value<T>(
        &mut self,
        pair: P,
        command: &str,
        parse: fn(&str) -> Option<T>,
        names: &'static [&'static str],
    ) -> Option<Spanned<Value<T>>> {
        let span = self.span(&pair);
        let inner = pair.into_inner().next().expect("grammar: value");
        if inner.as_rule() == Rule::prop_ref {
            return Some(Spanned::new(Value::Property(prop_name(&inner)), span));
        }
        match parse(inner.as_str()) {
            Some(value) => Some(Spanned::new(Value::Literal(value), span)),
            None => {
                self.errors.push(ShaderLabError::UnknownValue {
                    span,
                    command: command.into(),
                    found: inner.as_str().into(),
                    expected: names,
                });
                None
            }
        }
    }

    fn bool_value(
        &mut self,
        pair: P,
        command: &str,
        names: &'static [&'static str],
    ) -> Option<Spanned<Value<bool>>> {
        // `True`/`False` and `On`/`Off` are both accepted wherever ShaderLab takes a switch.
        let parse = |w: &str| match w.to_ascii_lowercase().as_str() {
            "on" | "true" => Some(true),
            "off" | "false" => Some(false),
            _ => None,
        };
        self.word_value(pair, command, parse, names)
    }

    fn number_value(&mut self, pair: P, command: &str) -> Option<Spanned<Value<f64>>> {
        let span = self.span(&pair);
        let inner = pair.into_inner().next().expect("grammar: value");
        match inner.as_rule() {
            Rule::prop_ref => Some(Spanned::new(Value::Property(prop_name(&inner)), span)),
            Rule::number => Some(Spanned::new(Value::Literal(self.number(&inner)), span)),
            _ => {
                self.errors.push(ShaderLabError::ExpectedNumber {
                    span,
                    command: command.into(),
                    found: inner.as_str().into(),
                });
                None
            }
        }
    }

    fn color_mask(&mut self, pair: P) -> Option<Spanned<Value<ColorMask>>> {
        let span = self.span(&pair);
        let inner = pair.into_inner().next().expect("grammar: value");
        let text = inner.as_str();
        let parsed = match inner.as_rule() {
            Rule::prop_ref => return Some(Spanned::new(Value::Property(prop_name(&inner)), span)),
            Rule::number if text == "0" => Some(ColorMask { r: false, g: false, b: false, a: false }),
            Rule::word if text.chars().all(|c| "RGBArgba".contains(c)) => {
                let has = |c: char| text.contains(c) || text.contains(c.to_ascii_lowercase());
                Some(ColorMask { r: has('R'), g: has('G'), b: has('B'), a: has('A') })
            }
            _ => None,
        };
        match parsed {
            Some(mask) => Some(Spanned::new(Value::Literal(mask), span)),
            None => {
                self.errors.push(ShaderLabError::UnknownValue {
                    span,
                    command: "ColorMask".into(),
                    found: text.into(),
                    expected: &["0", "RGBA", "RGB", "A", "any combination of R, G, B and A"],
                });
                None
            }
        }
    }

    fn stencil_entry(&mut self, pair: P) -> Option<StencilEntry> {
        let span = self.span(&pair);
        let mut inner = pair.into_inner();
        let field_pair = inner.next().expect("grammar: stencil field");
        let value_pair = inner.next().expect("grammar: stencil value");
        let Some(op) = StencilField::from_word(field_pair.as_str()) else {
            self.errors.push(ShaderLabError::UnknownStencilCommand {
                span: self.span(&field_pair),
                found: field_pair.as_str().into(),
            });
            return None;
        };
        let value_span = self.span(&value_pair);
        let command = format!("Stencil {}", op.name());
        let value = match op {
            StencilField::Ref | StencilField::ReadMask | StencilField::WriteMask => {
                let number = self.number_value(value_pair, &command)?;
                StencilValue::Byte(match number.value {
                    Value::Property(p) => Value::Property(p),
                    Value::Literal(n) if n.fract() == 0.0 && (0.0..=255.0).contains(&n) => {
                        Value::Literal(n as u8)
                    }
                    Value::Literal(n) => {
                        self.errors.push(ShaderLabError::OutOfRange {
                            span: value_span,
                            what: command,
                            found: n.to_string(),
                            range: "a whole number from 0 to 255",
                        });
                        return None;
                    }
                })
            }
            StencilField::Comp | StencilField::CompBack | StencilField::CompFront => StencilValue::Compare(
                self.word_value(value_pair, &command, CompareFunction::from_word, CompareFunction::NAMES)?
                    .value,
            ),
            _ => StencilValue::Operation(
                self.word_value(value_pair, &command, StencilOperation::from_word, StencilOperation::NAMES)?
                    .value,
            ),
        };
        Some(StencilEntry { op, value: Spanned::new(value, value_span), span })
    }

    // ---- programs ----------------------------------------------------------------------------

    fn program(&mut self, pair: P) -> ProgramBlock {
        let span = self.span(&pair);
        let block = pair.into_inner().next().expect("grammar: program block");
        let language = match block.as_rule() {
            Rule::wgsl_block => ProgramLanguage::Wgsl,
            Rule::hlsl_block => ProgramLanguage::Hlsl,
            Rule::cg_block => ProgramLanguage::Cg,
            _ => ProgramLanguage::Glsl,
        };
        let mut inner = block.into_inner();
        let open = inner.next().expect("grammar: program opening");
        let is_include = open.as_str().to_ascii_uppercase().ends_with("INCLUDE");
        let body = inner.next().expect("grammar: program body");
        ProgramBlock {
            language,
            is_include,
            body: body.as_str().to_string(),
            body_span: self.span(&body),
            span,
        }
    }
}

fn prop_name(pair: &P) -> String {
    pair.clone().into_inner().next().map(|p| p.as_str().to_string()).unwrap_or_default()
}
