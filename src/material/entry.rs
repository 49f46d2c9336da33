//! What resolving a material needs of its shader, from either side of a build: the parsed
//! shader (a build) or its manifest (a tool beside a running game), so that a `.mat` file
//! resolves alike from both.

use super::drawer::{KeywordDrawer, enum_names, keyword_drawer};
use super::{MaterialValue, shader_queue};
use crate::manifest::{KeywordKind, ShaderManifest};
use crate::shaderlab::ast::{PropertyType, Shader};
use crate::shaderlab::pragma::KeywordSet;
use crate::source::Span;

/// What resolving a material needs of its shader. A build takes it from the parsed shader
/// ([`ShaderEntry::from_shader`]) and the run time from the manifest
/// ([`ShaderEntry::from_manifest`]), so a `.mat` file resolves alike in both.
#[derive(Debug, Clone, PartialEq)]
pub struct ShaderEntry {
    /// The shader's name.
    pub name: String,
    /// Its properties.
    pub properties: Vec<EntryProperty>,
    /// The render queue of a material that sets none.
    pub render_queue: i64,
    /// The keyword sets of all its passes.
    pub keyword_sets: Vec<EntrySet>,
}

/// A property as materials see it.
#[derive(Debug, Clone, PartialEq)]
pub struct EntryProperty {
    /// Its name.
    pub name: String,
    /// Its type.
    pub ty: PropertyType,
    /// Its default value.
    pub default: MaterialValue,
    /// The keywords its drawer sets, if any.
    pub drawer: Option<KeywordDrawer>,
    /// An `[Enum]` drawer's names and values (a material may write the name).
    pub enum_names: Option<Vec<(String, f64)>>,
}

/// A keyword set as materials see it.
#[derive(Debug, Clone, PartialEq)]
pub struct EntrySet {
    /// A set a material chooses from (`shader_feature` or `dynamic_branch`) rather than
    /// `multi_compile`.
    pub material_chooses: bool,
    /// Its keywords, `_` left out.
    pub keywords: Vec<String>,
    /// The set has `_`: a material may enable none of its keywords.
    pub off_option: bool,
    /// The pragma that declares it (none at run time).
    pub span: Option<Span>,
}

impl ShaderEntry {
    /// From a parsed shader and the keyword sets of its passes.
    pub fn from_shader(shader: &Shader, keyword_sets: &[KeywordSet]) -> ShaderEntry {
        ShaderEntry {
            name: shader.name.value.clone(),
            properties: shader
                .properties
                .iter()
                .map(|p| EntryProperty {
                    name: p.name.value.clone(),
                    ty: p.ty.value,
                    default: MaterialValue::from(&p.default.value),
                    drawer: keyword_drawer(p),
                    enum_names: enum_names(p),
                })
                .collect(),
            render_queue: shader_queue(shader),
            keyword_sets: keyword_sets
                .iter()
                .map(|set| EntrySet {
                    material_chooses: set.kind != KeywordKind::MultiCompile,
                    keywords: set.keywords().map(str::to_string).collect(),
                    off_option: set.has_off_option(),
                    span: Some(set.span),
                })
                .collect(),
        }
    }

    /// A property by name.
    pub fn property(&self, name: &str) -> Option<&EntryProperty> {
        self.properties.iter().find(|p| p.name == name)
    }
}

/// The shaders materials may name, found by name (a project has thousands of shaders and
/// hundreds of thousands of materials; the first of two shaders with one name wins).
#[derive(Debug)]
pub struct ShaderEntries {
    pub(super) entries: Vec<ShaderEntry>,
    pub(super) by_name: std::collections::HashMap<String, usize>,
    /// Shaders whose files did not parse: their materials are not checked (the file's own errors
    /// say what is wrong; "unknown shader" for each of its materials would only repeat it).
    pub(super) failed: std::collections::HashSet<String>,
}

impl ShaderEntries {
    /// The shader a [`Material::shader`] index names.
    ///
    /// # Panics
    /// When `index` is not one of these entries' (a material resolved against other entries).
    pub fn entry(&self, index: usize) -> &ShaderEntry {
        &self.entries[index]
    }

    /// The shaders, by name.
    pub fn new(entries: Vec<ShaderEntry>) -> ShaderEntries {
        let mut by_name = std::collections::HashMap::with_capacity(entries.len());
        for (index, entry) in entries.iter().enumerate() {
            by_name.entry(entry.name.clone()).or_insert(index);
        }
        ShaderEntries { entries, by_name, failed: Default::default() }
    }

    /// The same, knowing the names of shaders whose files did not parse.
    pub fn with_failed(mut self, failed: impl IntoIterator<Item = String>) -> ShaderEntries {
        self.failed.extend(failed);
        self
    }
}

impl ShaderEntry {
    /// The shader as the material resolver sees it, so that a `.mat` read at run time resolves as
    /// the build resolved it (`None` when a property's type does not read).
    pub fn from_manifest(shader: &ShaderManifest) -> Option<ShaderEntry> {
        let properties = shader
            .properties
            .iter()
            .map(|p| {
                Some(EntryProperty {
                    name: p.name.clone(),
                    ty: PropertyType::from_manifest(&p.ty)?,
                    default: MaterialValue::from_json(&p.default)?,
                    drawer: p.drawer.clone(),
                    enum_names: p.enum_names.clone(),
                })
            })
            .collect::<Option<_>>()?;
        let keyword_sets = shader
            .passes
            .iter()
            .flat_map(|pass| &pass.keyword_sets)
            .map(|set| EntrySet {
                material_chooses: set.kind != KeywordKind::MultiCompile,
                keywords: set.keywords.iter().filter(|k| *k != "_").cloned().collect(),
                off_option: set.keywords.iter().any(|k| k == "_"),
                span: None,
            })
            .collect();
        Some(ShaderEntry {
            name: shader.name.clone(),
            properties,
            render_queue: shader.render_queue,
            keyword_sets,
        })
    }
}
