//! What property drawers mean for a material, as Unity reads them: the keywords `Toggle`,
//! `ToggleOff` and `KeywordEnum` enable, and the names `Enum` gives to numbers.

use crate::shaderlab::ast::{AttributeKind, Property};

pub use crate::manifest::KeywordDrawer;

/// The drawer of a property, if it sets keywords.
pub fn keyword_drawer(property: &Property) -> Option<KeywordDrawer> {
    let upper = property.name.value.to_uppercase();
    property.attributes.iter().find_map(|attribute| match &attribute.kind {
        AttributeKind::Toggle(keyword) => {
            Some(KeywordDrawer::Toggle(keyword.clone().unwrap_or_else(|| format!("{upper}_ON"))))
        }
        AttributeKind::ToggleOff(keyword) => {
            Some(KeywordDrawer::ToggleOff(keyword.clone().unwrap_or_else(|| format!("{upper}_OFF"))))
        }
        AttributeKind::KeywordEnum(entries) => Some(KeywordDrawer::KeywordEnum(
            entries.iter().map(|e| format!("{upper}_{}", e.to_uppercase().replace(' ', "_"))).collect(),
        )),
        _ => None,
    })
}

/// Names Unity's `[Enum(Type)]` drawers know, with their values: what a `[_Property]` in render
/// state holds.
pub(super) const UNITY_ENUMS: &[(&str, &[(&str, f64)])] = &[
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

/// The name a property's `[Enum]` or `[KeywordEnum]` drawer gives `value`, if any.
pub fn enum_name(shader: &crate::shaderlab::ast::Shader, property: &str, value: f64) -> Option<String> {
    let names = enum_names(shader.property(property)?)?;
    names.into_iter().find(|(_, v)| *v == value).map(|(name, _)| name)
}

/// The `(name, value)` pairs of a property's `[Enum]` or `[KeywordEnum]` drawer, if it has one.
pub fn enum_names(property: &Property) -> Option<Vec<(String, f64)>> {
    property.attributes.iter().find_map(|attribute| match &attribute.kind {
        AttributeKind::Enum(args) if args.len() == 1 => {
            let short = |name: &str| name.rsplit('.').next().unwrap_or(name).to_string();
            UNITY_ENUMS
                .iter()
                .find(|(ty, _)| *ty == args[0] || short(ty) == short(&args[0]))
                .map(|(_, pairs)| pairs.iter().map(|(n, v)| (n.to_string(), *v)).collect())
        }
        AttributeKind::Enum(args) => {
            let pairs = args.chunks(2).filter_map(|pair| match pair {
                [name, value] => value.parse::<f64>().ok().map(|v| (name.clone(), v)),
                _ => None,
            });
            Some(pairs.collect())
        }
        AttributeKind::KeywordEnum(entries) => {
            Some(entries.iter().enumerate().map(|(i, e)| (e.clone(), i as f64)).collect())
        }
        _ => None,
    })
}
