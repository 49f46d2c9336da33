//! The seed's four presets, exactly as its shader GUI sets them, and their application to a
//! material document (keeping its other values and comments).

use super::drawer::enum_name;
use crate::shaderlab::ast::Shader;
use toml_edit::{DocumentMut, Item, Value};

/// Unity's four blend presets.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Preset {
    /// Opaque: no blending, depth written.
    Opaque,
    /// Alpha-clipped: opaque with `_CLIPPING`.
    Clip,
    /// Faded: alpha blending of colour and specular.
    Fade,
    /// Transparent: premultiplied alpha, specular kept.
    Transparent,
}

/// Render queue names and their numbers.
pub const RENDER_QUEUES: [(&str, i64); 5] =
    [("Background", 1000), ("Geometry", 2000), ("AlphaTest", 2450), ("Transparent", 3000), ("Overlay", 4000)];

impl Preset {
    /// Every preset.
    pub const ALL: [Preset; 4] = [Preset::Opaque, Preset::Clip, Preset::Fade, Preset::Transparent];

    /// Its name.
    pub fn name(self) -> &'static str {
        match self {
            Preset::Opaque => "Opaque",
            Preset::Clip => "Clip",
            Preset::Fade => "Fade",
            Preset::Transparent => "Transparent",
        }
    }

    /// Case-insensitive, as users type it.
    pub fn parse(name: &str) -> Option<Preset> {
        Preset::ALL.into_iter().find(|p| p.name().eq_ignore_ascii_case(name))
    }

    /// The property values the preset sets: clipping, premultiplied alpha, source and destination
    /// blend (Unity's `BlendMode` numbers) and depth writes. Properties a shader lacks are skipped.
    pub fn values(self) -> [(&'static str, f64); 5] {
        let (clip, premultiply, src, dst, zwrite) = match self {
            Preset::Opaque => (0.0, 0.0, 1.0, 0.0, 1.0),
            Preset::Clip => (1.0, 0.0, 1.0, 0.0, 1.0),
            Preset::Fade => (0.0, 0.0, 5.0, 10.0, 0.0),
            Preset::Transparent => (0.0, 1.0, 1.0, 10.0, 0.0),
        };
        [
            ("_Clipping", clip),
            ("_PremulAlpha", premultiply),
            ("_SrcBlend", src),
            ("_DstBlend", dst),
            ("_ZWrite", zwrite),
        ]
    }

    /// Its render queue.
    pub fn render_queue(self) -> i64 {
        match self {
            Preset::Opaque => 2000,
            Preset::Clip => 2450,
            Preset::Fade | Preset::Transparent => 3000,
        }
    }

    /// Transparent is offered only where the shader has `_PremulAlpha`, as in the seed's GUI.
    pub fn offered_for(self, has_property: impl Fn(&str) -> bool) -> bool {
        self != Preset::Transparent || has_property("_PremulAlpha")
    }
}

/// How a number is written in a material: the drawer's name for it when it has one, else the
/// number (an integer when it is one).
pub fn value_for(shader: &Shader, property: &str, value: f64) -> Value {
    match enum_name(shader, property, value) {
        Some(name) => Value::from(name),
        None if value.fract() == 0.0 && value.abs() < 1e15 => Value::from(value as i64),
        None => Value::from(value),
    }
}

/// Sets the preset's values, render queue and name in a material document, leaving everything
/// else (other values, comments, order) as it was. An explicit `keywords` list is updated for
/// the keywords the changed toggles decide.
pub fn apply(document: &mut DocumentMut, shader: &Shader, preset: Preset) {
    set(document.as_table_mut(), "preset", Value::from(preset.name()));
    set(document.as_table_mut(), "render_queue", Value::from(preset.render_queue()));
    if !document.contains_key("properties") {
        document["properties"] = toml_edit::table();
    }
    let mut decided: Vec<(String, bool)> = Vec::new();
    if let Some(properties) = document["properties"].as_table_like_mut() {
        for (name, value) in preset.values() {
            let Some(property) = shader.property(name) else { continue };
            match properties.get_mut(name).and_then(Item::as_value_mut) {
                Some(slot) => replace_keeping_decor(slot, value_for(shader, name, value)),
                None => {
                    properties.insert(name, Item::Value(value_for(shader, name, value)));
                }
            }
            if let Some(drawer) = super::drawer::keyword_drawer(property) {
                let on = drawer.keyword_for(value);
                decided.extend(drawer.keywords().into_iter().map(|k| (k.to_string(), Some(k) == on)));
            }
        }
    }
    if let Some(keywords) = document.get_mut("keywords").and_then(Item::as_array_mut) {
        keywords.retain(|v| !decided.iter().any(|(k, _)| v.as_str() == Some(k)));
        for (keyword, on) in decided {
            if on {
                keywords.push(keyword);
            }
        }
    }
}

fn set(table: &mut toml_edit::Table, key: &str, value: Value) {
    match table.get_mut(key).and_then(Item::as_value_mut) {
        Some(slot) => replace_keeping_decor(slot, value),
        None => {
            table.insert(key, Item::Value(value));
        }
    }
}

fn replace_keeping_decor(slot: &mut Value, mut value: Value) {
    *value.decor_mut() = slot.decor().clone();
    *slot = value;
}

/// A new material for `shader`: every property at its default (with the preset applied), so the
/// file shows what can be set.
pub fn new_material(shader: &Shader, preset: Option<Preset>) -> String {
    use crate::shaderlab::ast::PropertyDefault;
    let mut document = DocumentMut::new();
    document["shader"] = toml_edit::value(shader.name.value.as_str());
    let mut properties = toml_edit::Table::new();
    for property in &shader.properties {
        let value = match &property.default.value {
            PropertyDefault::Number(n) => value_for(shader, &property.name.value, *n),
            PropertyDefault::Vector(v) => Value::Array(v.iter().copied().collect()),
            PropertyDefault::Texture { name, .. } => Value::from(name.as_str()),
        };
        properties.insert(&property.name.value, Item::Value(value));
    }
    document["properties"] = Item::Table(properties);
    if let Some(preset) = preset {
        apply(&mut document, shader, preset);
    }
    document.to_string()
}
