//! Materials: `.mat` TOML files choosing a shader, a preset, property values and so keywords,
//! checked against the shader with every mistake at its place in the file.

mod drawer;
mod entry;
mod error;
pub mod preset;

pub use drawer::{KeywordDrawer, enum_name, enum_names, keyword_drawer, unity_enum_name};
pub use entry::{EntryProperty, EntrySet, ShaderEntries, ShaderEntry};
pub use error::MaterialError;
pub use preset::Preset;

use crate::diagnostics::{Diagnostic, closest};
use crate::manifest::{Manifest, MaterialManifest};
use crate::shaderlab::ast::{PropertyDefault, PropertyType, Shader};
use crate::source::{FileId, SourceStore, Span};
use serde::Deserialize;
use std::collections::BTreeMap;

/// A material, resolved against its shader.
#[derive(Debug, Clone, PartialEq)]
pub struct Material {
    /// Its file.
    pub file: FileId,
    /// The file name without extension, as listings show it.
    pub name: String,
    /// Index of the shader in the list the material was resolved against.
    pub shader: usize,
    /// Its preset, if it names one.
    pub preset: Option<Preset>,
    /// Its render queue.
    pub render_queue: i64,
    /// Every property of the shader: the material's value, else the preset's, else the default.
    pub values: BTreeMap<String, MaterialValue>,
    /// Enabled keywords, sorted, each with where it came from (a property or the `keywords` list).
    pub keywords: Vec<(String, Span)>,
}

/// A property's value.
#[derive(Debug, Clone, PartialEq)]
pub enum MaterialValue {
    /// A `Float` or `Range`.
    Number(f64),
    /// A `Color` or `Vector`.
    Vector(Vec<f64>),
    /// A texture's name.
    Texture(String),
}

impl MaterialValue {
    /// As the manifest and `materials.json` write it: a number, an array, or a texture name.
    pub fn to_json(&self) -> serde_json::Value {
        match self {
            MaterialValue::Number(n) => serde_json::json!(n),
            MaterialValue::Vector(v) => serde_json::json!(v),
            MaterialValue::Texture(t) => serde_json::json!(t),
        }
    }

    /// Reads [`MaterialValue::to_json`] back.
    pub fn from_json(value: &serde_json::Value) -> Option<MaterialValue> {
        Some(match value {
            serde_json::Value::Number(n) => MaterialValue::Number(n.as_f64()?),
            serde_json::Value::Array(v) => {
                MaterialValue::Vector(v.iter().map(serde_json::Value::as_f64).collect::<Option<_>>()?)
            }
            serde_json::Value::String(t) => MaterialValue::Texture(t.clone()),
            _ => return None,
        })
    }
}

impl From<&PropertyDefault> for MaterialValue {
    fn from(default: &PropertyDefault) -> MaterialValue {
        match default {
            PropertyDefault::Number(n) => MaterialValue::Number(*n),
            PropertyDefault::Vector(v) => MaterialValue::Vector(v.clone()),
            PropertyDefault::Texture { name, .. } => MaterialValue::Texture(name.clone()),
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMaterial {
    shader: toml::Spanned<String>,
    preset: Option<toml::Spanned<String>>,
    render_queue: Option<toml::Spanned<toml::Value>>,
    keywords: Option<Vec<toml::Spanned<String>>>,
    #[serde(default)]
    properties: BTreeMap<toml::Spanned<String>, toml::Spanned<toml::Value>>,
}

/// Reads one material and checks it against the shaders. `None` when it names no shader or its
/// TOML is malformed; otherwise the material, with any other mistakes as diagnostics.
pub fn load_material(
    store: &SourceStore,
    file: FileId,
    shaders: &ShaderEntries,
) -> (Option<Material>, Vec<Diagnostic>) {
    let mut errors = Vec::new();
    let material = resolve(store, file, shaders, &mut errors);
    (material, errors.into_iter().map(Diagnostic::from).collect())
}

/// A material from a `.mat` file's text, resolved against a built manifest's shaders by the
/// resolver builds use (defaults, then the preset, then the file's values; keywords from the
/// property drawers and the `keywords` list), so it resolves as a build would resolve it: for a
/// tool or an editor that edits materials beside a running game. The run time reads materials
/// as a build resolved them (`materials.json`) and parses none. Any diagnostic refuses it,
/// warnings too, rendered as a build renders them: `name:line:col`.
pub fn resolve_for_manifest(manifest: &Manifest, name: &str, text: &str) -> Result<MaterialManifest, String> {
    let shaders =
        ShaderEntries::new(manifest.shaders.iter().filter_map(ShaderEntry::from_manifest).collect());
    let mut store = SourceStore::new();
    let file = store.add(name, text.to_string());
    let (material, problems) = load_material(&store, file, &shaders);
    match material {
        Some(material) if problems.is_empty() => {
            Ok(material.to_manifest(&shaders.entry(material.shader).name))
        }
        _ => Err(crate::diagnostics::render_plain(&store, &problems)),
    }
}

fn resolve(
    store: &SourceStore,
    file: FileId,
    shaders: &ShaderEntries,
    errors: &mut Vec<MaterialError>,
) -> Option<Material> {
    let text = store.text(file);
    let span = |range: std::ops::Range<usize>| Span::new(file, range);
    let raw: RawMaterial = match toml::from_str(text) {
        Ok(raw) => raw,
        Err(error) => {
            let range = error.span().unwrap_or(0..0);
            errors.push(MaterialError::Toml { span: span(range), message: error.message().to_string() });
            return None;
        }
    };
    let shader_name = raw.shader.get_ref();
    if shaders.failed.contains(shader_name) && !shaders.by_name.contains_key(shader_name.as_str()) {
        return None;
    }
    let Some(&index) = shaders.by_name.get(shader_name.as_str()) else {
        let suggestion = closest(shader_name, shaders.entries.iter().map(|s| s.name.as_str()));
        errors.push(MaterialError::UnknownShader {
            span: span(raw.shader.span()),
            name: shader_name.clone(),
            suggestion,
        });
        return None;
    };
    let shader = &shaders.entries[index];

    let preset = raw.preset.as_ref().and_then(|p| match Preset::parse(p.get_ref()) {
        Some(preset) if preset.offered_for(|p| shader.property(p).is_some()) => Some(preset),
        Some(preset) => {
            errors.push(MaterialError::PresetNotOffered {
                span: span(p.span()),
                preset: preset.name(),
                shader: shader.name.clone(),
            });
            None
        }
        None => {
            errors.push(MaterialError::UnknownPreset { span: span(p.span()), name: p.get_ref().clone() });
            None
        }
    });

    // Defaults, then the preset, then the file: later wins, as pressing a preset button and then
    // editing a value does in Unity.
    let mut values: BTreeMap<String, MaterialValue> =
        shader.properties.iter().map(|p| (p.name.clone(), p.default.clone())).collect();
    if let Some(preset) = preset {
        for (name, value) in preset.values() {
            if let Some(slot) = values.get_mut(name) {
                *slot = MaterialValue::Number(value);
            }
        }
    }
    let mut value_spans: BTreeMap<String, Span> = BTreeMap::new();
    let mut entries: Vec<_> = raw.properties.iter().collect();
    entries.sort_by_key(|(key, _)| key.span().start);
    for (key, value) in entries {
        let name = key.get_ref();
        let Some(property) = shader.property(name) else {
            let suggestion = closest(name, shader.properties.iter().map(|p| p.name.as_str()));
            errors.push(MaterialError::UnknownProperty {
                span: span(key.span()),
                name: name.clone(),
                shader: shader.name.clone(),
                suggestion,
            });
            continue;
        };
        match property_value(property, value.get_ref()) {
            Ok(resolved) => {
                // A reversed range (`Range(1, 0)`, which Unity accepts) holds what lies between.
                if let (PropertyType::Range { min, max }, MaterialValue::Number(n)) = (property.ty, &resolved)
                    && !(min.min(max)..=max.max(min)).contains(n)
                {
                    errors.push(MaterialError::OutOfRange {
                        span: span(value.span()),
                        property: name.clone(),
                        value: *n,
                        min,
                        max,
                    });
                }
                values.insert(name.clone(), resolved);
                value_spans.insert(name.clone(), span(value.span()));
            }
            Err(expected) => errors.push(MaterialError::WrongType {
                span: span(value.span()),
                property: name.clone(),
                expected,
            }),
        }
    }

    let render_queue = match &raw.render_queue {
        Some(queue) => render_queue(queue.get_ref()).unwrap_or_else(|| {
            errors.push(MaterialError::RenderQueue {
                span: span(queue.span()),
                found: queue.get_ref().to_string(),
            });
            2000
        }),
        None => preset.map_or(shader.render_queue, Preset::render_queue),
    };

    let shader_span = span(raw.shader.span());
    let keywords =
        keywords(shader, &values, &value_spans, shader_span, raw.keywords.as_deref(), &span, errors);
    check_sets(shader, &keywords, shader_span, errors);
    let name = store
        .path(file)
        .and_then(|p| p.file_stem())
        .map_or_else(|| store.name(file).to_string(), |stem| stem.to_string_lossy().into_owned());
    Some(Material { file, name, shader: index, preset, render_queue, values, keywords })
}

/// The value a TOML value gives a property, or what was expected instead.
fn property_value(property: &EntryProperty, value: &toml::Value) -> Result<MaterialValue, String> {
    use toml::Value as V;
    // TOML's `inf` and `nan` are numbers no uniform block should get: refused where written.
    let number = |v: &V| match v {
        V::Integer(i) => Some(*i as f64),
        V::Float(f) if f.is_finite() => Some(*f),
        _ => None,
    };
    match property.ty {
        PropertyType::Float | PropertyType::Int | PropertyType::Integer | PropertyType::Range { .. } => {
            let names = &property.enum_names;
            match value {
                V::Boolean(b) => Ok(MaterialValue::Number(if *b { 1.0 } else { 0.0 })),
                V::String(s) => names
                    .as_ref()
                    .and_then(|names| names.iter().find(|(n, _)| n.eq_ignore_ascii_case(s)))
                    .map(|(_, v)| MaterialValue::Number(*v))
                    .ok_or_else(|| match &names {
                        Some(names) => {
                            let names: Vec<&str> = names.iter().map(|(n, _)| n.as_str()).collect();
                            let guess = closest(s, names.iter().copied())
                                .map(|g| format!(" (did you mean `{g}`?)"))
                                .unwrap_or_default();
                            format!("a finite number or one of {}{guess}", crate::shaderlab::one_of(&names))
                        }
                        None => "a finite number".to_string(),
                    }),
                other => {
                    number(other).map(MaterialValue::Number).ok_or_else(|| "a finite number".to_string())
                }
            }
        }
        PropertyType::Color | PropertyType::Vector => {
            let components: Option<Vec<f64>> = value.as_array().and_then(|a| a.iter().map(number).collect());
            let allowed = if property.ty == PropertyType::Color { 3..=4 } else { 2..=4 };
            match components {
                Some(mut c) if allowed.contains(&c.len()) => {
                    if c.len() == 3 && property.ty == PropertyType::Color {
                        c.push(1.0);
                    }
                    Ok(MaterialValue::Vector(c))
                }
                _ => Err(format!("an array of {} to 4 finite numbers", allowed.start())),
            }
        }
        PropertyType::Texture(_) => value
            .as_str()
            .map(|s| MaterialValue::Texture(s.to_string()))
            .ok_or_else(|| "a texture name or path, in quotes".to_string()),
    }
}

fn render_queue(value: &toml::Value) -> Option<i64> {
    match value {
        toml::Value::Integer(q) if (0..=5000).contains(q) => Some(*q),
        toml::Value::String(name) => queue_by_name(name),
        _ => None,
    }
}

/// `Geometry`, `Transparent+1`, ... as Unity's `Queue` tag and materials spell them.
pub fn queue_by_name(text: &str) -> Option<i64> {
    let (name, offset) = match text.split_once(['+', '-']) {
        Some((name, offset)) => {
            let offset: i64 = offset.trim().parse().ok()?;
            (name.trim(), if text.contains('-') { -offset } else { offset })
        }
        None => (text.trim(), 0),
    };
    let base = preset::RENDER_QUEUES.iter().find(|(n, _)| n.eq_ignore_ascii_case(name))?.1;
    Some(base + offset).filter(|q| (0..=5000).contains(q))
}

/// The shader's `Queue` tag (first SubShader), else Geometry.
/// The render queue of a material that sets none: its shader's `Queue` tag, else 2000.
pub fn shader_queue(shader: &Shader) -> i64 {
    shader
        .subshaders
        .first()
        .and_then(|sub| sub.state.tags.iter().find(|t| t.key.value.eq_ignore_ascii_case("Queue")))
        .and_then(|tag| queue_by_name(&tag.value.value))
        .unwrap_or(2000)
}

/// Keywords from the drawers, checked against and completed by an explicit `keywords` list.
fn keywords(
    shader: &ShaderEntry,
    values: &BTreeMap<String, MaterialValue>,
    value_spans: &BTreeMap<String, Span>,
    shader_span: Span,
    explicit: Option<&[toml::Spanned<String>]>,
    span: &dyn Fn(std::ops::Range<usize>) -> Span,
    errors: &mut Vec<MaterialError>,
) -> Vec<(String, Span)> {
    let mut enabled: Vec<(String, Span)> = Vec::new();
    // Which drawer decides each keyword, and its verdict.
    let mut decided: BTreeMap<String, (String, f64, bool)> = BTreeMap::new();
    for property in &shader.properties {
        let Some(drawer) = &property.drawer else { continue };
        let Some(MaterialValue::Number(value)) = values.get(&property.name) else { continue };
        let on = drawer.keyword_for(*value);
        for keyword in drawer.keywords() {
            decided.insert(keyword.to_string(), (property.name.clone(), *value, Some(keyword) == on));
        }
        if let Some(keyword) = on {
            enabled
                .push((keyword.to_string(), value_spans.get(&property.name).copied().unwrap_or(shader_span)));
        }
    }
    if let Some(explicit) = explicit {
        for keyword in explicit {
            let name = keyword.get_ref();
            match decided.get(name) {
                Some((property, value, false)) => errors.push(MaterialError::KeywordDisagrees {
                    span: span(keyword.span()),
                    keyword: name.clone(),
                    property: property.clone(),
                    value: *value,
                    enabled: true,
                }),
                Some(_) => {}
                None => enabled.push((name.clone(), span(keyword.span()))),
            }
        }
        // The list that omits a keyword is what disagrees where the property's value is not in
        // the file (its preset's or its default).
        let list = match (explicit.first(), explicit.last()) {
            (Some(first), Some(last)) => span(first.span().start..last.span().end),
            _ => shader_span,
        };
        for (keyword, (property, value, on)) in &decided {
            if *on && !explicit.iter().any(|k| k.get_ref() == keyword) {
                let at = value_spans.get(property).copied().unwrap_or(list);
                errors.push(MaterialError::KeywordDisagrees {
                    span: at,
                    keyword: keyword.clone(),
                    property: property.clone(),
                    value: *value,
                    enabled: false,
                });
            }
        }
    }
    enabled.sort_by(|a, b| a.0.cmp(&b.0));
    enabled.dedup_by(|a, b| a.0 == b.0);
    enabled
}

/// Each set a material chooses from (shader_feature, dynamic_branch) gets at most one keyword,
/// and one when it has no off choice; keywords no pass declares are flagged.
fn check_sets(
    entry: &ShaderEntry,
    keywords: &[(String, Span)],
    shader_span: Span,
    errors: &mut Vec<MaterialError>,
) {
    for (keyword, at) in keywords {
        if !entry.keyword_sets.iter().any(|s| s.keywords.contains(keyword)) {
            let declared = entry.keyword_sets.iter().flat_map(|s| &s.keywords).map(String::as_str);
            errors.push(MaterialError::KeywordNotDeclared {
                span: *at,
                keyword: keyword.clone(),
                shader: entry.name.clone(),
                suggestion: closest(keyword, declared),
            });
        }
    }
    let mut seen_sets: Vec<&EntrySet> = Vec::new();
    for set in entry.keyword_sets.iter().filter(|s| s.material_chooses) {
        // Passes often repeat a set: check it once.
        if seen_sets.iter().any(|seen| (&seen.keywords, seen.off_option) == (&set.keywords, set.off_option)) {
            continue;
        }
        seen_sets.push(set);
        let on: Vec<&(String, Span)> = keywords.iter().filter(|(k, _)| set.keywords.contains(k)).collect();
        match on.as_slice() {
            [] if !set.off_option => errors.push(MaterialError::NoKeywordOfSet {
                span: shader_span,
                set: set.span,
                options: set.keywords.join(" "),
            }),
            [first, second, ..] => errors.push(MaterialError::TwoKeywordsOfOneSet {
                span: second.1,
                first: first.0.clone(),
                second: second.0.clone(),
                set: set.span,
            }),
            _ => {}
        }
    }
}

impl Material {
    /// The material as `materials.json` has it, for the shader named `shader`.
    pub fn to_manifest(&self, shader: &str) -> MaterialManifest {
        MaterialManifest {
            name: self.name.clone(),
            shader: shader.to_string(),
            preset: self.preset.map(|p| p.name().to_string()),
            render_queue: self.render_queue,
            keywords: self.keywords.iter().map(|(k, _)| k.clone()).collect(),
            values: self.values.iter().map(|(name, value)| (name.clone(), value.to_json())).collect(),
        }
    }
}
