//! The typed syntax tree of a `.shader` file. Every node carries the span it was read from.

use crate::manifest::state::{self as manifest, StateCommand};
pub use crate::manifest::state::{
    BlendFactor, BlendOperation, ColorMask, CompareFunction, CullMode, StencilField, StencilOperation,
    StencilValue, Value,
};
use crate::source::{Span, Spanned};

/// One `Shader "name" { ... }` file.
#[derive(Debug, Clone, PartialEq)]
pub struct Shader {
    pub name: Spanned<String>,
    pub properties: Vec<Property>,
    /// SubShaders in source order, those inside `Category { }` blocks included.
    pub subshaders: Vec<SubShader>,
    pub categories: Vec<Category>,
    /// Shader-level `*INCLUDE` blocks, prepended to every program of their language.
    pub includes: Vec<ProgramBlock>,
    pub fallback: Option<Fallback>,
    pub custom_editors: Vec<CustomEditor>,
    pub dependencies: Vec<Dependency>,
    pub span: Span,
}

/// `[attributes] _Name ("Display name", Type) = default`
#[derive(Debug, Clone, PartialEq)]
pub struct Property {
    pub attributes: Vec<Attribute>,
    pub name: Spanned<String>,
    pub display_name: Spanned<String>,
    pub ty: Spanned<PropertyType>,
    pub default: Spanned<PropertyDefault>,
    pub span: Span,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PropertyType {
    Float,
    Int,
    Integer,
    Range { min: f64, max: f64 },
    Color,
    Vector,
    Texture(TextureDimension),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TextureDimension {
    D2,
    D2Array,
    D3,
    Cube,
    CubeArray,
    /// Unity's `Any`: a texture of any dimension.
    Any,
}

impl PropertyType {
    /// The name as ShaderLab spells it.
    pub fn name(&self) -> &'static str {
        match self {
            PropertyType::Float => "Float",
            PropertyType::Int => "Int",
            PropertyType::Integer => "Integer",
            PropertyType::Range { .. } => "Range",
            PropertyType::Color => "Color",
            PropertyType::Vector => "Vector",
            PropertyType::Texture(TextureDimension::D2) => "2D",
            PropertyType::Texture(TextureDimension::D2Array) => "2DArray",
            PropertyType::Texture(TextureDimension::D3) => "3D",
            PropertyType::Texture(TextureDimension::Cube) => "Cube",
            PropertyType::Texture(TextureDimension::CubeArray) => "CubeArray",
            PropertyType::Texture(TextureDimension::Any) => "Any",
        }
    }

    /// As the manifest writes it: the name, with a range's bounds (`Range(0, 1)`).
    pub fn manifest_text(&self) -> String {
        match self {
            PropertyType::Range { min, max } => format!("Range({min}, {max})"),
            other => other.name().to_string(),
        }
    }

    /// Reads [`PropertyType::manifest_text`] back.
    pub fn from_manifest(text: &str) -> Option<PropertyType> {
        if let Some(bounds) = text.strip_prefix("Range(").and_then(|t| t.strip_suffix(')')) {
            let (min, max) = bounds.split_once(',')?;
            return Some(PropertyType::Range {
                min: min.trim().parse().ok()?,
                max: max.trim().parse().ok()?,
            });
        }
        use TextureDimension as D;
        [
            PropertyType::Float,
            PropertyType::Int,
            PropertyType::Integer,
            PropertyType::Color,
            PropertyType::Vector,
        ]
        .into_iter()
        .chain([D::D2, D::D2Array, D::D3, D::Cube, D::CubeArray, D::Any].map(PropertyType::Texture))
        .find(|ty| ty.name() == text)
    }
}

#[derive(Debug, Clone, PartialEq)]
pub enum PropertyDefault {
    Number(f64),
    /// Two to four components; colours may have three (alpha then defaults to 1).
    Vector(Vec<f64>),
    /// A texture name such as `"white"`, with the legacy `{ options }` text if present.
    Texture {
        name: String,
        options: Option<String>,
    },
}

/// A property attribute such as `[Toggle(_CLIPPING)]`, kept verbatim and also interpreted.
#[derive(Debug, Clone, PartialEq)]
pub struct Attribute {
    pub name: Spanned<String>,
    /// Arguments split at commas and trimmed; empty when the attribute has no parentheses.
    pub args: Vec<Spanned<String>>,
    pub kind: AttributeKind,
    pub span: Span,
}

/// What kiln understands of an attribute. Unknown ones are [`AttributeKind::Other`].
#[derive(Debug, Clone, PartialEq)]
pub enum AttributeKind {
    /// `[Toggle]`, `[Toggle(KW)]`, `[MaterialToggle]`: the keyword when given.
    Toggle(Option<String>),
    /// `[ToggleOff]`, `[ToggleOff(KW)]`.
    ToggleOff(Option<String>),
    ToggleUI,
    /// `[KeywordEnum(A, B, ...)]`, `[MaterialKeywordEnum(...)]`: the entry names.
    KeywordEnum(Vec<String>),
    /// `[Enum(...)]`, `[MaterialEnum(...)]`: a type name or name/value pairs; sets no keyword.
    Enum(Vec<String>),
    NoScaleOffset,
    Hdr,
    Gamma,
    HideInInspector,
    MainTexture,
    MainColor,
    PerRendererData,
    Normal,
    IntRange,
    PowerSlider(f64),
    Header(String),
    Space(f64),
    Other,
}

/// `Category { ... }`: render state and tags shared by the SubShaders inside it.
#[derive(Debug, Clone, PartialEq)]
pub struct Category {
    pub state: StateBlock,
    pub span: Span,
}

/// The settings that SubShaders, Passes and Categories all accept.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StateBlock {
    pub name: Option<Spanned<String>>,
    pub tags: Vec<Tag>,
    pub lod: Option<Spanned<u32>>,
    pub render_state: Vec<RenderCommand>,
    pub package_requirements: Vec<PackageRequirement>,
    pub legacy: Vec<LegacyCommand>,
}

#[derive(Debug, Clone, PartialEq)]
pub struct SubShader {
    pub state: StateBlock,
    pub passes: Vec<PassItem>,
    /// `*INCLUDE` blocks, and surface-shader `CGPROGRAM` blocks written directly in the SubShader.
    pub programs: Vec<ProgramBlock>,
    /// Index into [`Shader::categories`] when the SubShader sits in a `Category`.
    pub category: Option<usize>,
    pub span: Span,
}

#[derive(Debug, Clone, PartialEq)]
pub enum PassItem {
    Pass(Pass),
    UsePass(Spanned<String>),
    GrabPass(GrabPass),
}

#[derive(Debug, Clone, PartialEq)]
pub struct Pass {
    pub state: StateBlock,
    pub programs: Vec<ProgramBlock>,
    pub span: Span,
}

#[derive(Debug, Clone, PartialEq)]
pub struct GrabPass {
    pub texture: Option<Spanned<String>>,
    pub name: Option<Spanned<String>>,
    pub tags: Vec<Tag>,
    pub span: Span,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Tag {
    pub key: Spanned<String>,
    pub value: Spanned<String>,
}

#[derive(Debug, Clone, PartialEq)]
pub struct PackageRequirement {
    pub package: Spanned<String>,
    pub version: Option<Spanned<String>>,
}

#[derive(Debug, Clone, PartialEq)]
pub enum Fallback {
    Shader(Spanned<String>),
    Off(Span),
}

#[derive(Debug, Clone, PartialEq)]
pub struct CustomEditor {
    pub class: Spanned<String>,
    /// Set for `CustomEditorForRenderPipeline`.
    pub render_pipeline: Option<Spanned<String>>,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Dependency {
    pub name: Spanned<String>,
    pub shader: Spanned<String>,
}

#[derive(Debug, Clone, PartialEq)]
pub struct RenderCommand {
    pub kind: RenderCommandKind,
    pub span: Span,
}

#[derive(Debug, Clone, PartialEq)]
pub enum RenderCommandKind {
    /// `Blend [target] Off` has `factors: None`.
    Blend {
        target: Option<u32>,
        factors: Option<BlendFactors>,
    },
    BlendOp {
        target: Option<u32>,
        color: Spanned<Value<BlendOperation>>,
        alpha: Option<Spanned<Value<BlendOperation>>>,
    },
    ZWrite(Spanned<Value<bool>>),
    ZTest(Spanned<Value<CompareFunction>>),
    ZClip(Spanned<Value<bool>>),
    Cull(Spanned<Value<CullMode>>),
    ColorMask {
        mask: Spanned<Value<ColorMask>>,
        target: Option<u32>,
    },
    Offset {
        factor: Spanned<Value<f64>>,
        units: Spanned<Value<f64>>,
    },
    AlphaToMask(Spanned<Value<bool>>),
    Conservative(Spanned<Value<bool>>),
    Stencil(Vec<StencilEntry>),
}

impl RenderCommandKind {
    /// The command's keyword as ShaderLab spells it.
    pub fn keyword(&self) -> &'static str {
        match self {
            RenderCommandKind::Blend { .. } => "Blend",
            RenderCommandKind::BlendOp { .. } => "BlendOp",
            RenderCommandKind::ZWrite(_) => "ZWrite",
            RenderCommandKind::ZTest(_) => "ZTest",
            RenderCommandKind::ZClip(_) => "ZClip",
            RenderCommandKind::Cull(_) => "Cull",
            RenderCommandKind::ColorMask { .. } => "ColorMask",
            RenderCommandKind::Offset { .. } => "Offset",
            RenderCommandKind::AlphaToMask(_) => "AlphaToMask",
            RenderCommandKind::Conservative(_) => "Conservative",
            RenderCommandKind::Stencil(_) => "Stencil",
        }
    }
}

/// A blend factor as written: literal or `[_Property]`.
pub type FactorValue = Spanned<Value<BlendFactor>>;

#[derive(Debug, Clone, PartialEq)]
pub struct BlendFactors {
    pub src: FactorValue,
    pub dst: FactorValue,
    /// Separate alpha factors: `Blend A B, C D`.
    pub alpha: Option<(FactorValue, FactorValue)>,
}

#[derive(Debug, Clone, PartialEq)]
pub struct StencilEntry {
    pub op: StencilField,
    pub value: Spanned<StencilValue>,
    pub span: Span,
}

/// A fixed-function command from before programmable shaders, kept verbatim.
#[derive(Debug, Clone, PartialEq)]
pub struct LegacyCommand {
    pub keyword: Spanned<String>,
    pub text: String,
    pub span: Span,
}

/// A program block: `WGSLPROGRAM ... ENDWGSL` or one of its include or foreign-language forms.
#[derive(Debug, Clone, PartialEq)]
pub struct ProgramBlock {
    pub language: ProgramLanguage,
    /// `*INCLUDE` blocks are spliced before every program of their language instead of compiled.
    pub is_include: bool,
    pub body: String,
    pub body_span: Span,
    pub span: Span,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ProgramLanguage {
    Wgsl,
    Hlsl,
    Cg,
    Glsl,
}

impl ProgramLanguage {
    /// Lowercase name, as listings show it.
    pub fn name(self) -> &'static str {
        match self {
            ProgramLanguage::Wgsl => "wgsl",
            ProgramLanguage::Hlsl => "hlsl",
            ProgramLanguage::Cg => "cg",
            ProgramLanguage::Glsl => "glsl",
        }
    }

    /// The keyword that opens a program of this language (`WGSLPROGRAM`, `CGINCLUDE`, ...).
    pub fn open_keyword(self, include: bool) -> &'static str {
        match (self, include) {
            (ProgramLanguage::Wgsl, false) => "WGSLPROGRAM",
            (ProgramLanguage::Wgsl, true) => "WGSLINCLUDE",
            (ProgramLanguage::Hlsl, false) => "HLSLPROGRAM",
            (ProgramLanguage::Hlsl, true) => "HLSLINCLUDE",
            (ProgramLanguage::Cg, false) => "CGPROGRAM",
            (ProgramLanguage::Cg, true) => "CGINCLUDE",
            (ProgramLanguage::Glsl, false) => "GLSLPROGRAM",
            (ProgramLanguage::Glsl, true) => "GLSLINCLUDE",
        }
    }

    pub fn close_keyword(self) -> &'static str {
        match self {
            ProgramLanguage::Wgsl => "ENDWGSL",
            ProgramLanguage::Hlsl => "ENDHLSL",
            ProgramLanguage::Cg => "ENDCG",
            ProgramLanguage::Glsl => "ENDGLSL",
        }
    }

    pub const ALL: [ProgramLanguage; 4] =
        [ProgramLanguage::Wgsl, ProgramLanguage::Hlsl, ProgramLanguage::Cg, ProgramLanguage::Glsl];
}

impl Shader {
    /// Every program-bearing pass, with the SubShader it belongs to.
    pub fn passes(&self) -> impl Iterator<Item = (usize, &SubShader, usize, &Pass)> {
        self.subshaders.iter().enumerate().flat_map(|(si, sub)| {
            sub.passes.iter().enumerate().filter_map(move |(pi, item)| match item {
                PassItem::Pass(pass) => Some((si, sub, pi, pass)),
                _ => None,
            })
        })
    }

    /// The pass a user named: by its `Name` (case-insensitive, as Unity's `UsePass` matches) or
    /// by its 0-based index in [`Shader::passes`]; with no selector, the first pass with a
    /// program.
    pub fn find_pass(&self, selector: Option<&str>) -> Option<(&SubShader, &Pass)> {
        let mut passes = self.passes().map(|(_, sub, _, pass)| (sub, pass));
        match selector {
            None => passes.find(|(_, pass)| !pass.programs.is_empty()),
            Some(selector) => match selector.parse::<usize>() {
                Ok(index) => passes.nth(index),
                Err(_) => passes.find(|(_, pass)| {
                    pass.state.name.as_ref().is_some_and(|n| n.value.eq_ignore_ascii_case(selector))
                }),
            },
        }
    }

    /// The property with this name.
    pub fn property(&self, name: &str) -> Option<&Property> {
        self.properties.iter().find(|p| p.name.value == name)
    }
}

impl RenderCommandKind {
    /// The command as the manifest writes it, without its spans.
    pub fn to_manifest(&self) -> StateCommand {
        match self {
            RenderCommandKind::Blend { target, factors } => StateCommand::Blend {
                target: *target,
                factors: factors.as_ref().map(|f| manifest::BlendFactors {
                    src: f.src.value.clone(),
                    dst: f.dst.value.clone(),
                    alpha: f.alpha.as_ref().map(|(s, d)| [s.value.clone(), d.value.clone()]),
                }),
            },
            RenderCommandKind::BlendOp { target, color, alpha } => StateCommand::BlendOp {
                target: *target,
                color: color.value.clone(),
                alpha: alpha.as_ref().map(|a| a.value.clone()),
            },
            RenderCommandKind::ZWrite(on) => StateCommand::ZWrite { on: on.value.clone() },
            RenderCommandKind::ZTest(function) => StateCommand::ZTest { function: function.value.clone() },
            RenderCommandKind::ZClip(on) => StateCommand::ZClip { on: on.value.clone() },
            RenderCommandKind::Cull(mode) => StateCommand::Cull { mode: mode.value.clone() },
            RenderCommandKind::ColorMask { mask, target } => {
                StateCommand::ColorMask { target: *target, mask: mask.value.clone() }
            }
            RenderCommandKind::Offset { factor, units } => {
                StateCommand::Offset { factor: factor.value.clone(), units: units.value.clone() }
            }
            RenderCommandKind::AlphaToMask(on) => StateCommand::AlphaToMask { on: on.value.clone() },
            RenderCommandKind::Conservative(on) => StateCommand::Conservative { on: on.value.clone() },
            RenderCommandKind::Stencil(entries) => StateCommand::Stencil {
                settings: entries
                    .iter()
                    .map(|e| manifest::StencilSetting { field: e.op, value: e.value.value.clone() })
                    .collect(),
            },
        }
    }
}
