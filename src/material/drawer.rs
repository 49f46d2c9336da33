//! What property drawers mean for a material, as Unity reads them: the keywords `Toggle`,
//! `ToggleOff` and `KeywordEnum` enable, and the names `Enum` gives to numbers.

use crate::shaderlab::ast::{AttributeKind, Property};

use crate::manifest::UNITY_ENUMS;
pub use crate::manifest::{KeywordDrawer, unity_enum_name};

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
