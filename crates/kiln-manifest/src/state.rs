//! The structured render state of a pass, as the manifest writes it: ShaderLab's words and
//! values, owned by the schema (the parser reads into these types; the run time maps them to
//! wgpu), so that nothing the parser renames changes the file.

use serde::{Deserialize, Serialize};

/// Declares a closed set of ShaderLab words, matched case-insensitively.
macro_rules! shaderlab_words {
    ($(#[$meta:meta])* $name:ident { $($variant:ident = $text:literal),+ $(,)? }) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        // Each variant is the ShaderLab word beside it.
        #[allow(missing_docs)]
        pub enum $name { $($variant),+ }

        impl $name {
            /// Every accepted spelling, in canonical case.
            pub const NAMES: &'static [&'static str] = &[$($text),+];

            /// Parses a word, ignoring case.
            pub fn from_word(word: &str) -> Option<$name> {
                $(if word.eq_ignore_ascii_case($text) { return Some($name::$variant); })+
                None
            }

            /// The word, in canonical case.
            pub fn name(self) -> &'static str {
                match self { $($name::$variant => $text),+ }
            }
        }

        /// Written as its ShaderLab word.
        impl serde::Serialize for $name {
            fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                serializer.serialize_str(self.name())
            }
        }

        impl<'de> serde::Deserialize<'de> for $name {
            fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<$name, D::Error> {
                let word = String::deserialize(deserializer)?;
                $name::from_word(&word).ok_or_else(|| serde::de::Error::unknown_variant(&word, $name::NAMES))
            }
        }
    };
}

shaderlab_words!(BlendFactor {
    One = "One", Zero = "Zero", SrcColor = "SrcColor", SrcAlpha = "SrcAlpha",
    SrcAlphaSaturate = "SrcAlphaSaturate", DstColor = "DstColor", DstAlpha = "DstAlpha",
    OneMinusSrcColor = "OneMinusSrcColor", OneMinusSrcAlpha = "OneMinusSrcAlpha",
    OneMinusDstColor = "OneMinusDstColor", OneMinusDstAlpha = "OneMinusDstAlpha",
});

shaderlab_words!(BlendOperation {
    Add = "Add", Sub = "Sub", RevSub = "RevSub", Min = "Min", Max = "Max",
    LogicalClear = "LogicalClear", LogicalSet = "LogicalSet", LogicalCopy = "LogicalCopy",
    LogicalCopyInverted = "LogicalCopyInverted", LogicalNoop = "LogicalNoop",
    LogicalInvert = "LogicalInvert", LogicalAnd = "LogicalAnd", LogicalNand = "LogicalNand",
    LogicalOr = "LogicalOr", LogicalNor = "LogicalNor", LogicalXor = "LogicalXor",
    LogicalEquiv = "LogicalEquiv", LogicalAndReverse = "LogicalAndReverse",
    LogicalAndInverted = "LogicalAndInverted", LogicalOrReverse = "LogicalOrReverse",
    LogicalOrInverted = "LogicalOrInverted", Multiply = "Multiply", Screen = "Screen",
    Overlay = "Overlay", Darken = "Darken", Lighten = "Lighten", ColorDodge = "ColorDodge",
    ColorBurn = "ColorBurn", HardLight = "HardLight", SoftLight = "SoftLight",
    Difference = "Difference", Exclusion = "Exclusion", HslHue = "HSLHue",
    HslSaturation = "HSLSaturation", HslColor = "HSLColor", HslLuminosity = "HSLLuminosity",
});

shaderlab_words!(CompareFunction {
    Never = "Never", Less = "Less", Equal = "Equal", LEqual = "LEqual", Greater = "Greater",
    NotEqual = "NotEqual", GEqual = "GEqual", Always = "Always", Disabled = "Disabled",
});

shaderlab_words!(CullMode { Off = "Off", Front = "Front", Back = "Back" });

shaderlab_words!(StencilOperation {
    Keep = "Keep", Zero = "Zero", Replace = "Replace", IncrSat = "IncrSat", DecrSat = "DecrSat",
    Invert = "Invert", IncrWrap = "IncrWrap", DecrWrap = "DecrWrap",
});

shaderlab_words!(
    /// The commands allowed inside `Stencil { }`.
    StencilField {
        Ref = "Ref", ReadMask = "ReadMask", WriteMask = "WriteMask", Comp = "Comp", Pass = "Pass",
        Fail = "Fail", ZFail = "ZFail", CompBack = "CompBack", PassBack = "PassBack",
        FailBack = "FailBack", ZFailBack = "ZFailBack", CompFront = "CompFront",
        PassFront = "PassFront", FailFront = "FailFront", ZFailFront = "ZFailFront",
    }
);

/// A render-state value: a literal, or `[_Property]` taken from the material. In the manifest:
/// `{"literal": ...}` or `{"property": "_Name"}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Value<T> {
    /// A value written in the shader.
    Literal(T),
    /// A `[_Property]`, taken from the material.
    Property(String),
}

/// Channels written by `ColorMask`: `0` is none.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct ColorMask {
    /// Red.
    pub r: bool,
    /// Green.
    pub g: bool,
    /// Blue.
    pub b: bool,
    /// Alpha.
    pub a: bool,
}

/// A `Stencil { }` setting's value.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StencilValue {
    /// `Ref`, `ReadMask`, `WriteMask`: 0 to 255.
    Byte(Value<u8>),
    /// `Comp`: a comparison.
    Compare(Value<CompareFunction>),
    /// `Pass`, `Fail`, `ZFail`: an operation.
    Operation(Value<StencilOperation>),
}

/// One render-state command of a pass.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RenderState {
    /// As written.
    pub command: String,
    /// As parsed.
    pub state: StateCommand,
    /// The `[_Property]`s it reads, with their defaults.
    pub properties: Vec<PropertyReference>,
}

/// One ShaderLab render-state command (`kind` is its keyword), its values literal or
/// `[_Property]` (a material's value, read at draw time as Unity's enums number them).
/// `target: null` is every colour target.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind")]
// Each variant is the ShaderLab command of its name, its fields the command's arguments.
#[allow(missing_docs)]
pub enum StateCommand {
    /// `factors: null` is `Blend Off`.
    Blend {
        target: Option<u32>,
        factors: Option<BlendFactors>,
    },
    BlendOp {
        target: Option<u32>,
        color: Value<BlendOperation>,
        alpha: Option<Value<BlendOperation>>,
    },
    ZWrite {
        on: Value<bool>,
    },
    ZTest {
        function: Value<CompareFunction>,
    },
    ZClip {
        on: Value<bool>,
    },
    Cull {
        mode: Value<CullMode>,
    },
    ColorMask {
        target: Option<u32>,
        mask: Value<ColorMask>,
    },
    Offset {
        factor: Value<f64>,
        units: Value<f64>,
    },
    AlphaToMask {
        on: Value<bool>,
    },
    Conservative {
        on: Value<bool>,
    },
    /// In the order written: a later setting of one field wins.
    Stencil {
        settings: Vec<StencilSetting>,
    },
}

/// `Blend` factors.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BlendFactors {
    /// Source factor.
    pub src: Value<BlendFactor>,
    /// Destination factor.
    pub dst: Value<BlendFactor>,
    /// Separate alpha factors (`Blend A B, C D`); `null`: the colour factors.
    pub alpha: Option<[Value<BlendFactor>; 2]>,
}

/// One line of `Stencil { }`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StencilSetting {
    /// Which setting.
    pub field: StencilField,
    /// Its value.
    pub value: StencilValue,
}

/// A `[_Property]` a command reads.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PropertyReference {
    /// Its name.
    pub name: String,
    /// The shader's default for it.
    pub default: serde_json::Value,
}

/// Names Unity's `[Enum(Type)]` drawers know, with their values: what a `[_Property]` in render
/// state holds.
pub const UNITY_ENUMS: &[(&str, &[(&str, f64)])] = &[
    (
        "UnityEngine.Rendering.BlendMode",
        &[
            ("Zero", 0.0),
            ("One", 1.0),
            ("DstColor", 2.0),
            ("SrcColor", 3.0),
            ("OneMinusDstColor", 4.0),
            ("SrcAlpha", 5.0),
            ("OneMinusSrcColor", 6.0),
            ("DstAlpha", 7.0),
            ("OneMinusDstAlpha", 8.0),
            ("SrcAlphaSaturate", 9.0),
            ("OneMinusSrcAlpha", 10.0),
        ],
    ),
    ("UnityEngine.Rendering.CullMode", &[("Off", 0.0), ("Front", 1.0), ("Back", 2.0)]),
    (
        "UnityEngine.Rendering.CompareFunction",
        &[
            ("Disabled", 0.0),
            ("Never", 1.0),
            ("Less", 2.0),
            ("Equal", 3.0),
            ("LessEqual", 4.0),
            ("Greater", 5.0),
            ("NotEqual", 6.0),
            ("GreaterEqual", 7.0),
            ("Always", 8.0),
        ],
    ),
    (
        "UnityEngine.Rendering.BlendOp",
        &[("Add", 0.0), ("Subtract", 1.0), ("ReverseSubtract", 2.0), ("Min", 3.0), ("Max", 4.0)],
    ),
    (
        "UnityEngine.Rendering.StencilOp",
        &[
            ("Keep", 0.0),
            ("Zero", 1.0),
            ("Replace", 2.0),
            ("IncrementSaturate", 3.0),
            ("DecrementSaturate", 4.0),
            ("Invert", 5.0),
            ("IncrementWrap", 6.0),
            ("DecrementWrap", 7.0),
        ],
    ),
];

/// The name `value` has in one of [`UNITY_ENUMS`] (`"UnityEngine.Rendering.BlendMode"`).
pub fn unity_enum_name(ty: &str, value: f64) -> Option<&'static str> {
    let (_, pairs) = UNITY_ENUMS.iter().find(|(t, _)| *t == ty)?;
    pairs.iter().find(|(_, v)| *v == value.round()).map(|(name, _)| *name)
}
