//! Every mistake a material file can make, as a typed enum turned into diagnostics here.

use crate::diagnostics::Diagnostic;
use crate::source::Span;

/// A mistake found, with where it is. Each variant's meaning is the diagnostic it becomes (its
/// code and message, in the `From` impl below, documented in docs/diagnostics.md), so variants
/// and fields are not documented twice.
#[allow(missing_docs)]
#[derive(Debug, Clone, PartialEq)]
pub enum MaterialError {
    Toml { span: Span, message: String },
    UnknownShader { span: Span, name: String, suggestion: Option<String> },
    UnknownProperty { span: Span, name: String, shader: String, suggestion: Option<String> },
    WrongType { span: Span, property: String, expected: String },
    OutOfRange { span: Span, property: String, value: f64, min: f64, max: f64 },
    UnknownPreset { span: Span, name: String },
    PresetNotOffered { span: Span, preset: &'static str, shader: String },
    RenderQueue { span: Span, found: String },
    KeywordNotDeclared { span: Span, keyword: String, shader: String, suggestion: Option<String> },
    TwoKeywordsOfOneSet { span: Span, first: String, second: String, set: Option<Span> },
    NoKeywordOfSet { span: Span, set: Option<Span>, options: String },
    KeywordDisagrees { span: Span, keyword: String, property: String, value: f64, enabled: bool },
}

impl From<MaterialError> for Diagnostic {
    fn from(error: MaterialError) -> Diagnostic {
        use MaterialError::*;
        let did_you_mean = |d: Diagnostic, s: Option<String>| match s {
            Some(s) => d.help(format!("did you mean `{s}`?")),
            None => d,
        };
        match error {
            Toml { span, message } => {
                let message = message.trim().trim_end_matches('.').to_string();
                Diagnostic::error("K0501", "invalid material file").at(span, message)
            }
            UnknownShader { span, name, suggestion } => did_you_mean(
                Diagnostic::error("K0502", format!("unknown shader `{name}`"))
                    .at(span, "no shader of the project has this name"),
                suggestion,
            ),
            UnknownProperty { span, name, shader, suggestion } => did_you_mean(
                Diagnostic::error("K0503", format!("`{shader}` has no property `{name}`"))
                    .at(span, "unknown property"),
                suggestion,
            ),
            WrongType { span, property, expected } => {
                Diagnostic::error("K0504", format!("wrong value type for `{property}`"))
                    .at(span, format!("expected {expected}"))
            }
            OutOfRange { span, property, value, min, max } => {
                Diagnostic::error("K0505", format!("`{property}` = {value} is outside its range"))
                    .at(span, format!("the property is declared as Range({min}, {max})"))
            }
            UnknownPreset { span, name } => Diagnostic::error("K0506", format!("unknown preset `{name}`"))
                .at(span, "not a preset")
                .help("presets are `Opaque`, `Clip`, `Fade` and `Transparent`"),
            PresetNotOffered { span, preset, shader } => {
                Diagnostic::error("K0506", format!("preset `{preset}` is not offered for `{shader}`"))
                    .at(span, "this preset needs a `_PremulAlpha` property")
                    .help("use `Fade` for alpha blending without premultiplied alpha")
            }
            RenderQueue { span, found } => {
                Diagnostic::error("K0511", format!("invalid render queue `{found}`"))
                    .at(span, "expected 0 to 5000 or a queue name")
                    .help(
                        "queue names are `Background`, `Geometry`, `AlphaTest`, `Transparent` and `Overlay`",
                    )
            }
            KeywordNotDeclared { span, keyword, shader, suggestion } => {
                let d = Diagnostic::warning(
                    "K0507",
                    format!("keyword `{keyword}` is declared by no pass of `{shader}`"),
                )
                .at(span, "this keyword changes no variant");
                match suggestion {
                    Some(s) => d.help(format!("did you mean `{s}`?")),
                    None => d.help("remove it, or declare it with `#pragma shader_feature`"),
                }
            }
            TwoKeywordsOfOneSet { span, first, second, set } => set_label(
                Diagnostic::error("K0508", format!("`{first}` and `{second}` belong to one keyword set"))
                    .at(span, "a material enables at most one keyword of a set"),
                set,
                "the set",
            ),
            NoKeywordOfSet { span, set, options } => set_label(
                Diagnostic::error("K0509", format!("no keyword of the set `{options}` is enabled"))
                    .at(span, "this material enables none of them")
                    .help("enable one of its keywords, or add `_` to the pragma"),
                set,
                "the set has no `_` (off) choice",
            ),
            KeywordDisagrees { span, keyword, property, value, enabled } => {
                let (is, says) = if enabled { ("lists", "turns it off") } else { ("omits", "turns it on") };
                Diagnostic::error(
                    "K0510",
                    format!("`keywords` {is} `{keyword}`, but `{property}` = {value} {says}"),
                )
                .at(span, "disagrees with the property's drawer")
                .help(format!("set `{property}` instead; its drawer decides `{keyword}`"))
            }
        }
    }
}

/// Points at the pragma that declares a keyword set, where it is known (a build; not the run
/// time, which reads the set from the manifest).
fn set_label(diagnostic: Diagnostic, set: Option<Span>, message: &str) -> Diagnostic {
    match set {
        Some(set) => diagnostic.label(set, message),
        None => diagnostic,
    }
}
