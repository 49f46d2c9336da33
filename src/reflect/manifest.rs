//! `manifest.json`: everything a renderer needs to use a project's compiled variants, as its own
//! versioned serde schema (documented in docs/manifest.md), built by explicit conversion.

use super::{Attribute, Resource, UniformBlock};
use serde::{Deserialize, Serialize};

/// Raised whenever a field changes meaning or is removed (adding fields keeps it).
pub const SCHEMA_VERSION: u32 = 3;

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Manifest {
    pub schema_version: u32,
    pub kiln_version: String,
    pub shaders: Vec<ShaderManifest>,
}

impl Manifest {
    /// Every stage module of every variant (a module shared by variants comes once per variant).
    pub fn stages(&self) -> impl Iterator<Item = &StageManifest> {
        self.shaders
            .iter()
            .flat_map(|s| &s.passes)
            .flat_map(|p| &p.variants)
            .flat_map(|v| [&v.vertex, &v.fragment])
            .flatten()
    }

    /// Every module the manifest names, each once, in path and offset order.
    pub fn files(&self) -> Vec<&FileRef> {
        let mut files: Vec<&FileRef> = self.stages().flat_map(StageManifest::files).collect();
        files.sort_by(|a, b| (&a.path, a.offset).cmp(&(&b.path, b.offset)));
        files.dedup_by(|a, b| (&a.path, a.offset) == (&b.path, b.offset));
        files
    }

    /// Every pack the manifest points into, with the length it must have at least.
    pub fn packs(&self) -> std::collections::BTreeMap<&str, u64> {
        let mut packs = std::collections::BTreeMap::new();
        for file in self.stages().flat_map(StageManifest::files) {
            let end = packs.entry(file.path.as_str()).or_insert(0);
            *end = file.end().max(*end);
        }
        packs
    }
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ShaderManifest {
    pub name: String,
    pub file: String,
    pub properties: Vec<PropertyManifest>,
    pub passes: Vec<PassManifest>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PropertyManifest {
    pub name: String,
    pub display_name: String,
    #[serde(rename = "type")]
    pub ty: String,
    pub default: serde_json::Value,
    /// Byte offset in the material uniform block (`UnityPerMaterial`), when the shader has it there.
    pub offset: Option<u32>,
    /// `[group, binding]` of a texture property's texture.
    pub binding: Option<[u32; 2]>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PassManifest {
    pub subshader: usize,
    pub index: usize,
    pub name: Option<String>,
    pub tags: Vec<(String, String)>,
    pub render_state: Vec<RenderState>,
    pub keyword_sets: Vec<KeywordSetManifest>,
    /// One bind group layout for every variant of the pass.
    pub layout: Vec<BindGroup>,
    /// The distinct uniform block layouts of the pass's variants, laid out by naga.
    pub uniform_blocks: Vec<UniformBlock>,
    pub variants: Vec<VariantManifest>,
}

/// A render-state command as written, with the properties it refers to resolved.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RenderState {
    pub command: String,
    pub properties: Vec<PropertyReference>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PropertyReference {
    pub name: String,
    pub default: serde_json::Value,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct KeywordSetManifest {
    pub kind: String,
    pub scope: String,
    pub stage: String,
    /// `_` is the all-off choice.
    pub keywords: Vec<String>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BindGroup {
    pub group: u32,
    pub entries: Vec<LayoutEntry>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LayoutEntry {
    pub binding: u32,
    pub name: String,
    /// The stages any variant uses it in: `vertex`, `fragment`.
    pub visibility: Vec<String>,
    pub resource: Resource,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct VariantManifest {
    /// The keyword bits in hexadecimal (see docs/project.md).
    pub key: String,
    pub keywords: Vec<String>,
    /// The materials that need it (empty for variants built without materials).
    pub materials: Vec<String>,
    pub vertex: Option<StageManifest>,
    pub fragment: Option<StageManifest>,
    /// The uniform blocks the variant's stages use: indices into the pass's `uniform_blocks`,
    /// by block name.
    pub uniform_blocks: Vec<usize>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StageManifest {
    /// Identifies the stage module: variants with the same id share it.
    pub module: String,
    pub entry_point: String,
    pub keywords: Vec<String>,
    pub wgsl: Option<FileRef>,
    pub spirv: Option<FileRef>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub inputs: Vec<Attribute>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub outputs: Vec<Attribute>,
    /// `[group, binding]` of each resource the module uses.
    pub bindings: Vec<[u32; 2]>,
}

/// A stage module: `size` bytes at `offset` of a pack file under the output folder. A build
/// writes the modules it compiles for a pass into one pack per backend, so that a build creates
/// a few files per pass instead of two per module.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FileRef {
    /// Relative to the output folder, with `/` separators.
    pub path: String,
    pub offset: u64,
    pub size: u64,
    /// BLAKE3 of the module's bytes, 128 bits in hexadecimal.
    pub hash: String,
}

impl StageManifest {
    /// Its modules, one per backend written.
    pub fn files(&self) -> impl Iterator<Item = &FileRef> {
        [&self.wgsl, &self.spirv].into_iter().flatten()
    }
}

impl FileRef {
    /// Where the module ends in its pack.
    pub fn end(&self) -> u64 {
        self.offset + self.size
    }

    /// The module's bytes within its pack's bytes (`None` when the pack is too short).
    pub fn slice<'a>(&self, pack: &'a [u8]) -> Option<&'a [u8]> {
        let range = usize::try_from(self.offset).ok().zip(usize::try_from(self.end()).ok());
        range.and_then(|(start, end)| pack.get(start..end))
    }

    /// The module's bytes, read from its pack under `output`.
    pub fn read(&self, output: &std::path::Path) -> std::io::Result<Vec<u8>> {
        let pack = std::fs::read(output.join(&self.path))?;
        self.slice(&pack).map(<[u8]>::to_vec).ok_or_else(|| {
            std::io::Error::new(
                std::io::ErrorKind::UnexpectedEof,
                format!("`{}` is shorter than its modules", self.path),
            )
        })
    }
}
