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
    /// Its name (`Shader "name"`).
    pub name: Spanned<String>,
    /// Its `Properties { }`, in order.
    pub properties: Vec<Property>,
    /// SubShaders in source order, those inside `Category { }` blocks included.
    pub subshaders: Vec<SubShader>,
    /// Its `Category { }` blocks.
    pub categories: Vec<Category>,
    /// Shader-level `*INCLUDE` blocks, prepended to every program of their language.
    pub includes: Vec<ProgramBlock>,
    /// `Fallback "name"` or `Fallback Off`.
    pub fallback: Option<Fallback>,
    /// `CustomEditor` lines.
    pub custom_editors: Vec<CustomEditor>,
    /// `Dependency` lines.
    pub dependencies: Vec<Dependency>,
    /// The whole shader.
    pub span: Span,
}

/// `[attributes] _Name ("Display name", Type) = default`
#[derive(Debug, Clone, PartialEq)]
pub struct Property {
    /// Its `[Attributes]`, in order.
    pub attributes: Vec<Attribute>,
    /// Its name (`_BaseColor`).
    pub name: Spanned<String>,
    /// Its display name.
    pub display_name: Spanned<String>,
    /// Its type.
    pub ty: Spanned<PropertyType>,
    /// Its default value.
    pub default: Spanned<PropertyDefault>,
    /// The whole declaration.
    pub span: Span,
}

#[derive(Debug, Clone, Copy, PartialEq)]
// Each variant is the ShaderLab construct of its name.
#[allow(missing_docs)]
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
// Each variant is the ShaderLab construct of its name.
#[allow(missing_docs)]
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

/// A property's default value.
#[derive(Debug, Clone, PartialEq)]
pub enum PropertyDefault {
    /// A number.
    Number(f64),
    /// Two to four components; colours may have three (alpha then defaults to 1).
    Vector(Vec<f64>),
    /// A texture name such as `"white"`, with the legacy `{ options }` text if present.
    Texture {
        /// The texture's name.
        name: String,
        /// The legacy `{ options }` text.
        options: Option<String>,
    },
}

/// A property attribute such as `[Toggle(_CLIPPING)]`, kept verbatim and also interpreted.
#[derive(Debug, Clone, PartialEq)]
pub struct Attribute {
    /// Its name as written.
    pub name: Spanned<String>,
    /// Arguments split at commas and trimmed; empty when the attribute has no parentheses.
    pub args: Vec<Spanned<String>>,
    /// What kiln understands of it.
    pub kind: AttributeKind,
    /// The whole attribute.
    pub span: Span,
}

/// What kiln understands of an attribute. Unknown ones are [`AttributeKind::Other`].
#[derive(Debug, Clone, PartialEq)]
// Each variant is the ShaderLab construct of its name.
#[allow(missing_docs)]
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
    /// Its tags and state.
    pub state: StateBlock,
    /// The whole block.
    pub span: Span,
}

/// The settings that SubShaders, Passes and Categories all accept.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StateBlock {
    /// `Name`, if any.
    pub name: Option<Spanned<String>>,
    /// `Tags { }`, in order.
    pub tags: Vec<Tag>,
    /// `LOD`, if any.
    pub lod: Option<Spanned<u32>>,
    /// Render-state commands, in order.
    pub render_state: Vec<RenderCommand>,
    /// `PackageRequirements { }`.
    pub package_requirements: Vec<PackageRequirement>,
    /// Fixed-function commands, kept verbatim.
    pub legacy: Vec<LegacyCommand>,
}

/// One `SubShader { }`.
#[derive(Debug, Clone, PartialEq)]
pub struct SubShader {
    /// Its tags and state, which its passes inherit.
    pub state: StateBlock,
    /// Its passes, in order.
    pub passes: Vec<PassItem>,
    /// `*INCLUDE` blocks, and surface-shader `CGPROGRAM` blocks written directly in the SubShader.
    pub programs: Vec<ProgramBlock>,
    /// Index into [`Shader::categories`] when the SubShader sits in a `Category`.
    pub category: Option<usize>,
    /// The whole block.
    pub span: Span,
}

/// One pass of a SubShader.
#[derive(Debug, Clone, PartialEq)]
pub enum PassItem {
    /// `Pass { }`.
    Pass(Pass),
    /// `UsePass "Shader/PASS"`.
    UsePass(Spanned<String>),
    /// `GrabPass { }`.
    GrabPass(GrabPass),
}

/// One `Pass { }`.
#[derive(Debug, Clone, PartialEq)]
pub struct Pass {
    /// Its tags and state.
    pub state: StateBlock,
    /// Its program blocks.
    pub programs: Vec<ProgramBlock>,
    /// The whole block.
    pub span: Span,
}

/// One `GrabPass { }`.
#[derive(Debug, Clone, PartialEq)]
pub struct GrabPass {
    /// The texture it grabs into, if named.
    pub texture: Option<Spanned<String>>,
    /// `Name`, if any.
    pub name: Option<Spanned<String>>,
    /// `Tags { }`, in order.
    pub tags: Vec<Tag>,
    /// The whole block.
    pub span: Span,
}

/// One `"Key" = "Value"` tag.
#[derive(Debug, Clone, PartialEq)]
pub struct Tag {
    /// The key.
    pub key: Spanned<String>,
    /// The value.
    pub value: Spanned<String>,
}

/// One `"package" : "version"` requirement.
#[derive(Debug, Clone, PartialEq)]
pub struct PackageRequirement {
    /// The package.
    pub package: Spanned<String>,
    /// The version range, if given.
    pub version: Option<Spanned<String>>,
}

/// `Fallback`.
#[derive(Debug, Clone, PartialEq)]
pub enum Fallback {
    /// `Fallback "name"`.
    Shader(Spanned<String>),
    /// `Fallback Off`.
    Off(Span),
}

/// A `CustomEditor` line.
#[derive(Debug, Clone, PartialEq)]
pub struct CustomEditor {
    /// The editor's class.
    pub class: Spanned<String>,
    /// Set for `CustomEditorForRenderPipeline`.
    pub render_pipeline: Option<Spanned<String>>,
}

/// A `Dependency "name" = "shader"` line.
#[derive(Debug, Clone, PartialEq)]
pub struct Dependency {
    /// The dependency's name.
    pub name: Spanned<String>,
    /// The shader it names.
    pub shader: Spanned<String>,
}

/// One render-state command.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderCommand {
    /// What it sets.
    pub kind: RenderCommandKind,
    /// The whole command.
    pub span: Span,
}

#[derive(Debug, Clone, PartialEq)]
// Each variant is the ShaderLab construct of its name.
#[allow(missing_docs)]
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

/// `Blend` factors, as written.
#[derive(Debug, Clone, PartialEq)]
pub struct BlendFactors {
    /// Source factor.
    pub src: FactorValue,
    /// Destination factor.
    pub dst: FactorValue,
    /// Separate alpha factors: `Blend A B, C D`.
    pub alpha: Option<(FactorValue, FactorValue)>,
}

/// One line of `Stencil { }`.
#[derive(Debug, Clone, PartialEq)]
pub struct StencilEntry {
    /// Which setting.
    pub op: StencilField,
    /// Its value.
    pub value: Spanned<StencilValue>,
    /// The whole line.
    pub span: Span,
}

/// A fixed-function command from before programmable shaders, kept verbatim.
#[derive(Debug, Clone, PartialEq)]
pub struct LegacyCommand {
    /// Its keyword.
    pub keyword: Spanned<String>,
    /// The whole command's text.
    pub text: String,
    /// The whole command.
    pub span: Span,
}

/// A program block: `WGSLPROGRAM ... ENDWGSL` or one of its include or foreign-language forms.
#[derive(Debug, Clone, PartialEq)]
pub struct ProgramBlock {
    /// Its language.
    pub language: ProgramLanguage,
    /// `*INCLUDE` blocks are spliced before every program of their language instead of compiled.
    pub is_include: bool,
    /// The text between the opening and closing keywords.
    pub body: String,
    /// Where the body is.
    pub body_span: Span,
    /// The whole block.
    pub span: Span,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
// Each variant is the ShaderLab construct of its name.
#[allow(missing_docs)]
pub enum ProgramLanguage {
    Wgsl,
    Hlsl,
    Cg,
    Glsl,
}

impl ProgramLanguage {
    /// Whether kiln compiles programs in it: WGSL, and HLSL and Cg through glslang
    /// (`compile::hlsl`). GLSL programs are listed, and refused by `build` and `check` (K0424).
    pub fn is_compiled(self) -> bool {
        !matches!(self, ProgramLanguage::Glsl)
    }

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

    /// The keyword that closes a block (`ENDWGSL`, ...).
    pub fn close_keyword(self) -> &'static str {
        match self {
            ProgramLanguage::Wgsl => "ENDWGSL",
            ProgramLanguage::Hlsl => "ENDHLSL",
            ProgramLanguage::Cg => "ENDCG",
            ProgramLanguage::Glsl => "ENDGLSL",
        }
    }

    /// Every language, in the order blocks are matched.
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
