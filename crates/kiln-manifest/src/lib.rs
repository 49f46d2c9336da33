//! `manifest.json`: everything a renderer needs to use a project's compiled variants, as its own
//! versioned serde schema (documented in docs/manifest.md), built by explicit conversion.
//!
//! Its size follows distinct modules, not variants: a pass lists each stage module once, each
//! distinct stage interface (entry point, inputs, outputs, bindings) once, and its variants are
//! keywords and module indices.
//!
//! Long because the schema's top is one piece: the manifest, its shaders, passes, modules and
//! variants, the checks a manifest read from disk gets, and the closed-set macro the submodules
//! (`reflection`, `keywords`, `state`) share.

#![warn(missing_docs, unreachable_pub)]

/// A closed set of names the manifest writes: an enum, serialised as its name (one list gives
/// both), so that a value outside the set is refused when a manifest is read, and every use is an
/// exhaustive `match`.
macro_rules! closed_set {
    ($(#[$meta:meta])* $name:ident { $($(#[$vmeta:meta])* $variant:ident = $text:literal,)+ }) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum $name {
            $($(#[$vmeta])* $variant,)+
        }

        impl $name {
            /// Every value, in the set's order.
            pub const ALL: &'static [$name] = &[$($name::$variant,)+];

            /// Its name in the manifest (and in WGSL, where WGSL has one).
            pub fn name(self) -> &'static str {
                match self {
                    $($name::$variant => $text,)+
                }
            }
        }

        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str(self.name())
            }
        }

        impl Serialize for $name {
            fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                serializer.serialize_str(self.name())
            }
        }

        impl<'de> Deserialize<'de> for $name {
            fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
                let text = String::deserialize(deserializer)?;
                $name::ALL
                    .iter()
                    .copied()
                    .find(|value| value.name() == text)
                    .ok_or_else(|| serde::de::Error::unknown_variant(&text, &[$($text,)+]))
            }
        }
    };
}

mod backend;
mod keywords;
mod path;
mod reflection;
pub mod state;

pub use backend::{Backend, PerBackend};
pub use keywords::{KeywordKind, KeywordScope, KeywordSetManifest, KeywordStage};
pub use path::{NotAPackPath, PACK_FOLDER, PackPath, open_regular, read_regular};
pub use reflection::{
    Attribute, AttributeFormat, Member, OverrideConstant, OverrideType, Resource, SampleType, ShaderStage,
    StorageAccess, TexelFormat, UniformBlock, ViewDimension,
};
pub use state::*;

/// The closest name within two edits, ignoring case, for "did you mean" help.
pub fn closest<'a>(name: &str, candidates: impl Iterator<Item = &'a str>) -> Option<String> {
    candidates
        .map(|c| (strsim::damerau_levenshtein(&c.to_lowercase(), &name.to_lowercase()), c))
        .filter(|&(distance, _)| distance <= 2)
        .min()
        .map(|(_, c)| c.to_string())
}

use serde::{Deserialize, Serialize};
use std::path::Path;

/// Raised whenever a field changes meaning or is removed (adding fields keeps it).
pub const SCHEMA_VERSION: u32 = 8;

/// The bind group of the resources a renderer binds once per frame (camera, lights): kiln puts
/// every resource of a pass in one of three groups by how often it changes (docs/project.md).
pub const FRAME_GROUP: u32 = 0;
/// The bind group of a material's resources (its uniform blocks and textures).
pub const MATERIAL_GROUP: u32 = 1;
/// The bind group of the resources bound per draw (the object's transform).
pub const OBJECT_GROUP: u32 = 2;

/// The manifest's file name, at the top of the output folder.
pub const FILE_NAME: &str = "manifest.json";

/// Left in the output folder by `kiln watch` while the project's last build failed (the
/// rendered diagnostics), and removed by the next good build: the runtime keeps its pipelines
/// and reports them.
pub const ERRORS_FILE: &str = "errors.txt";

/// `manifest.json`: every built shader, its passes, modules and variants. `P` is how a pass is
/// held: parsed ([`PassManifest`]), or as the JSON text a shard wrote, which a merge writes as
/// it is.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Manifest<P = PassManifest> {
    /// [`SCHEMA_VERSION`] when written.
    pub schema_version: u32,
    /// The kiln that wrote it.
    pub kiln_version: String,
    /// The built shaders, in catalogue order.
    pub shaders: Vec<ShaderManifest<P>>,
    /// The BLAKE3 hash (32 hex digits) of the `materials.json` written with it: the two files
    /// are replaced one after the other, so a reader tells a torn pair (a build stopped between
    /// them) by this. Last, so that a manifest is streamed while the materials are hashed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub materials_hash: Option<String>,
}

/// Why a text is not a manifest kiln could use.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ManifestError {
    /// Not JSON of the schema.
    #[error(transparent)]
    Json(#[from] serde_json::Error),
    /// A pass whose indices point outside its own lists, or whose module ends past what an offset
    /// can address (a manifest damaged since kiln wrote it).
    #[error(
        "`{shader}` pass {pass} refers to a module, interface, pack or uniform block it does not list, or to bytes past any pack's end"
    )]
    DanglingIndex {
        /// The shader's name.
        shader: String,
        /// The pass's place in the shader's `passes`.
        pass: usize,
    },
}

impl Manifest {
    /// Reads `manifest.json` from an output folder ([`Manifest::parse`]).
    pub fn read(output: &Path) -> std::io::Result<Manifest> {
        let bytes = std::fs::read(output.join(FILE_NAME))?;
        Manifest::parse(&bytes).map_err(std::io::Error::other)
    }

    /// `manifest.json`'s text, parsed, and refused when an index in it points nowhere: every
    /// lookup of a module, interface or block would otherwise panic on a damaged manifest.
    pub fn parse(bytes: &[u8]) -> Result<Manifest, ManifestError> {
        let manifest: Manifest = serde_json::from_slice(bytes)?;
        for shader in &manifest.shaders {
            if let Some(pass) = shader.passes.iter().position(|pass| !pass.indices_in_range()) {
                return Err(ManifestError::DanglingIndex { shader: shader.name.clone(), pass });
            }
        }
        Ok(manifest)
    }

    /// Every pass of every shader.
    pub fn passes(&self) -> impl Iterator<Item = &PassManifest> {
        self.shaders.iter().flat_map(|s| &s.passes)
    }

    /// Every stage module, each once per pass that lists it.
    pub fn stages(&self) -> impl Iterator<Item = StageView<'_>> {
        self.passes().flat_map(|p| (0..p.modules.len()).map(move |m| p.stage(m)))
    }

    /// Every module file the manifest names, each once, in path and offset order.
    pub fn files(&self) -> Vec<FileRef> {
        let mut files: Vec<FileRef> = self.stages().flat_map(|s| s.files()).collect();
        files.sort_by(|a, b| (&a.path, a.offset).cmp(&(&b.path, b.offset)));
        files.dedup_by(|a, b| (&a.path, a.offset) == (&b.path, b.offset));
        files
    }

    /// Every pack the manifest points into, with the length it must have at least.
    pub fn packs(&self) -> std::collections::BTreeMap<PackPath, u64> {
        pack_ends(self.passes())
    }
}

/// Every pack the passes point into, with the length it must have at least.
pub fn pack_ends<'a, P: PassFiles + 'a>(
    passes: impl IntoIterator<Item = &'a P>,
) -> std::collections::BTreeMap<PackPath, u64> {
    let mut packs: std::collections::BTreeMap<PackPath, u64> = std::collections::BTreeMap::new();
    for pass in passes {
        // A pass names a few packs and many modules: each pack's end is found by its index
        // first, and looked up by name once (this runs on one thread at the end of a build).
        let mut ends = vec![None; pass.packs().len()];
        for file in pass.modules().iter().flat_map(ModuleManifest::files) {
            if let Some(end) = ends.get_mut(file.pack) {
                *end = Some((file.offset + file.size).max(end.unwrap_or(0)));
            }
        }
        for (path, end) in pass.packs().iter().zip(ends) {
            let Some(end) = end else { continue };
            match packs.get_mut(path) {
                Some(longest) => *longest = end.max(*longest),
                None => {
                    packs.insert(path.clone(), end);
                }
            }
        }
    }
    packs
}

/// What the shader-level parts of a manifest (its properties' places, its packs) are computed
/// from: a pass's packs, modules, layout and uniform blocks.
pub trait PassFiles {
    /// The pack files its modules are in.
    fn packs(&self) -> &[PackPath];
    /// Its modules.
    fn modules(&self) -> &[ModuleManifest];
    /// Its bind groups.
    fn layout(&self) -> &[BindGroup];
    /// Its uniform blocks.
    fn uniform_blocks(&self) -> &[UniformBlock];
}

impl<P: PassFiles> PassFiles for &P {
    fn packs(&self) -> &[PackPath] {
        (*self).packs()
    }
    fn modules(&self) -> &[ModuleManifest] {
        (*self).modules()
    }
    fn layout(&self) -> &[BindGroup] {
        (*self).layout()
    }
    fn uniform_blocks(&self) -> &[UniformBlock] {
        (*self).uniform_blocks()
    }
}

impl PassFiles for PassManifest {
    fn packs(&self) -> &[PackPath] {
        &self.packs
    }
    fn modules(&self) -> &[ModuleManifest] {
        &self.modules
    }
    fn layout(&self) -> &[BindGroup] {
        &self.layout
    }
    fn uniform_blocks(&self) -> &[UniformBlock] {
        &self.uniform_blocks
    }
}

/// One built shader.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ShaderManifest<P = PassManifest> {
    /// Its name (`Shader "name"`).
    pub name: String,
    /// Relative to the project folder, with `/` separators.
    pub file: String,
    /// The render queue its first SubShader's `Queue` tag gives a material without one (2000).
    #[serde(default = "default_queue")]
    pub render_queue: i64,
    /// Its properties, in declaration order.
    pub properties: Vec<PropertyManifest>,
    /// Its built passes, in order.
    pub passes: Vec<P>,
}

fn default_queue() -> i64 {
    2000
}

/// One property of a shader.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PropertyManifest {
    /// Its name (`_BaseColor`).
    pub name: String,
    /// The name shown in an inspector.
    pub display_name: String,
    /// Its type as ShaderLab writes it (`Color`, `Range(0, 1)`, `2D`, ...).
    #[serde(rename = "type")]
    pub ty: String,
    /// Its default: a number, a vector or a texture's name.
    pub default: serde_json::Value,
    /// Byte offset in the material uniform block (`UnityPerMaterial`), when the shader has it there.
    pub offset: Option<u32>,
    /// `[group, binding]` of a texture property's texture.
    pub binding: Option<[u32; 2]>,
    /// The keywords its drawer enables (`[Toggle(_CLIPPING)]` is `{"toggle": "_CLIPPING"}`), so
    /// that a material read at run time gets the same keywords the build gave it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub drawer: Option<KeywordDrawer>,
    /// An `[Enum]` drawer's names and values (`[["Off", 0], ["Front", 1], ["Back", 2]]`): a
    /// material may write the name.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub enum_names: Option<Vec<(String, f64)>>,
}

/// `materials.json`, beside the manifest: every material the build resolved, as the build
/// resolved it (defaults, then preset, then the file's values; keywords from drawers and the
/// `keywords` list), for the run time to draw with.
pub const MATERIALS_FILE: &str = "materials.json";

/// One resolved material.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MaterialManifest {
    /// The file name without extension.
    pub name: String,
    /// Its shader's name.
    pub shader: String,
    /// Its preset, if it names one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub preset: Option<String>,
    /// Its render queue.
    pub render_queue: i64,
    /// Enabled keywords, sorted.
    pub keywords: Vec<String>,
    /// Every property of the shader: a number, a vector, or a texture name.
    pub values: std::collections::BTreeMap<String, serde_json::Value>,
}

impl MaterialManifest {
    /// A number property's value (`None` for other kinds and unknown names).
    pub fn number(&self, property: &str) -> Option<f64> {
        self.values.get(property).and_then(serde_json::Value::as_f64)
    }
}

/// One built pass.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PassManifest {
    /// Its SubShader's index.
    pub subshader: usize,
    /// Its index in the SubShader.
    pub index: usize,
    /// Its `Name`, if any.
    pub name: Option<String>,
    /// Its tags, in order.
    pub tags: Vec<(String, String)>,
    /// Its render-state commands (the SubShader's, then its own), as written and structured.
    pub render_state: Vec<RenderState>,
    /// Its keyword sets, in declaration order.
    pub keyword_sets: Vec<KeywordSetManifest>,
    /// The pass's keywords in bit order: bit i of a variant key is `keywords[i]`.
    pub keywords: Vec<String>,
    /// A compute pass: its kernels (`#pragma kernel`), in order; a variant's `kernels` follow it.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub kernels: Vec<String>,
    /// One bind group layout for every variant of the pass.
    pub layout: Vec<BindGroup>,
    /// The distinct uniform block layouts of the pass's modules, laid out by naga.
    pub uniform_blocks: Vec<UniformBlock>,
    /// The pack files the pass's modules are in, relative to the output folder (nothing but
    /// `modules/<hash>.<extension>` reads).
    pub packs: Vec<PackPath>,
    /// The distinct interfaces of the pass's stage modules.
    pub interfaces: Vec<StageInterface>,
    /// Each distinct stage module of the pass once.
    pub modules: Vec<ModuleManifest>,
    /// Its built variants.
    pub variants: Vec<VariantManifest>,
    /// Its ubershader (`#pragma ubershader`): modules that read every keyword at run time, the
    /// fallback drawn while a variant's pipeline is created (docs/keywords.md).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ubershader: Option<Ubershader>,
}

impl PassManifest {
    /// A module of the pass with its interface and files resolved.
    ///
    /// # Panics
    /// When `module` or the indices it holds are out of range (a manifest kiln did not write;
    /// [`Manifest::parse`] refuses those).
    pub fn stage(&self, module: usize) -> StageView<'_> {
        let m = &self.modules[module];
        StageView { pass: self, index: module, module: m, interface: &self.interfaces[m.interface] }
    }

    /// Whether every index the pass holds is one of its lists' (see [`modules_in_range`]).
    fn indices_in_range(&self) -> bool {
        let stages = self
            .variants
            .iter()
            .chain(self.ubershader.iter().map(|u| &u.modules))
            .flat_map(|v| [v.vertex, v.fragment].into_iter().chain(v.kernels.iter().copied()));
        let mut blocks = self.interfaces.iter().flat_map(|i| &i.uniform_blocks);
        modules_in_range(&self.modules, self.interfaces.len(), self.packs.len())
            && stages.flatten().all(|m| m < self.modules.len())
            && blocks.all(|&b| b < self.uniform_blocks.len())
    }

    /// Its `dynamic_branch` sets.
    pub fn dynamic_sets(&self) -> impl Iterator<Item = &KeywordSetManifest> {
        self.keyword_sets.iter().filter(|set| set.kind == KeywordKind::DynamicBranch)
    }

    /// Its `dynamic_branch` keywords, set by set (no `_`): the order of the generated `Pass`'s
    /// `dynamic_keywords` and of a run-time handle's bits.
    pub fn dynamic_keywords(&self) -> impl Iterator<Item = &String> {
        self.dynamic_sets().flat_map(|set| &set.keywords).filter(|k| *k != "_")
    }

    /// Whether `keyword` is one of its `dynamic_branch` keywords (an `override` of its modules,
    /// not a variant).
    pub fn is_dynamic(&self, keyword: &str) -> bool {
        self.dynamic_sets().any(|set| set.keywords.iter().any(|k| k == keyword))
    }

    /// A variant's vertex and fragment modules.
    pub fn variant_stages(&self, variant: &VariantManifest) -> [Option<StageView<'_>>; 2] {
        [variant.vertex, variant.fragment].map(|m| m.map(|m| self.stage(m)))
    }

    /// The uniform blocks a variant's stages use, as indices into `uniform_blocks`, by name.
    pub fn variant_uniform_blocks(&self, variant: &VariantManifest) -> Vec<usize> {
        let kernels = variant.kernels.iter().flatten().map(|&m| self.stage(m));
        let mut blocks: Vec<usize> = self
            .variant_stages(variant)
            .into_iter()
            .flatten()
            .chain(kernels)
            .flat_map(|s| s.interface.uniform_blocks.clone())
            .collect();
        // By name, then index, so that a block both stages use is adjacent to itself.
        blocks.sort_by(|&a, &b| (&self.uniform_blocks[a].name, a).cmp(&(&self.uniform_blocks[b].name, b)));
        blocks.dedup();
        blocks
    }

    /// The full reference of a module file.
    pub fn file(&self, file: &ModuleFile) -> FileRef {
        FileRef {
            path: self.packs[file.pack].clone(),
            offset: file.offset,
            size: file.size,
            hash: file.hash.clone(),
        }
    }
}

/// One bind group of a pass's layout.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BindGroup {
    /// Its index.
    pub group: u32,
    /// Its entries, by binding.
    pub entries: Vec<LayoutEntry>,
}

/// One binding of a bind group.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LayoutEntry {
    /// Its binding number.
    pub binding: u32,
    /// The global variable's name.
    pub name: String,
    /// The stages any variant uses it in.
    pub visibility: Vec<ShaderStage>,
    /// What it holds.
    pub resource: Resource,
}

/// One built variant.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct VariantManifest {
    /// The keyword bits in hexadecimal (see docs/project.md).
    pub key: String,
    /// Its enabled keywords.
    pub keywords: Vec<String>,
    /// The materials that need it (empty for variants built without materials).
    pub materials: Vec<String>,
    /// Indices into the pass's `modules`; `None` when the pass has no such entry point.
    pub vertex: Option<usize>,
    /// Index into the pass's `modules`, or `None`.
    pub fragment: Option<usize>,
    /// A compute pass: each kernel's module (in the pass's `kernels` order), `None` when it failed.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub kernels: Vec<Option<usize>>,
}

/// A pass's ubershader: its modules, as a variant's, and the keywords its immediate data holds.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Ubershader {
    /// Keyword i is on when bit i of the immediate data (two `u32`s, 8 bytes) is set: the pass's
    /// variant keywords, then its `dynamic_branch` ones.
    pub keywords: Vec<String>,
    /// Its vertex, fragment and kernel modules (`key`, `keywords` and `materials` empty).
    pub modules: VariantManifest,
}

impl Ubershader {
    /// The bytes of its immediate data that turn `keywords` on (those it does not read are off).
    pub fn immediates<'k>(&self, keywords: impl IntoIterator<Item = &'k str>) -> [u8; 8] {
        let mut bits = 0u64;
        for keyword in keywords {
            if let Some(bit) = self.keywords.iter().position(|k| k == keyword) {
                bits |= 1 << bit;
            }
        }
        bits.to_le_bytes()
    }
}

/// What a stage module exposes to the pipeline that uses it; modules of a pass that differ only
/// in their code share one.
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct StageInterface {
    /// Its stage.
    pub stage: ShaderStage,
    /// The entry point's name.
    pub entry_point: String,
    /// Vertex stage: the vertex attributes it reads.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub inputs: Vec<Attribute>,
    /// Fragment stage: the colour targets it writes.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub outputs: Vec<Attribute>,
    /// `[group, binding]` of each resource the module uses.
    pub bindings: Vec<[u32; 2]>,
    /// The uniform blocks it uses: indices into the pass's `uniform_blocks`.
    pub uniform_blocks: Vec<usize>,
    /// The pipeline-overridable constants it uses (`dynamic_branch` keywords among them).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub overrides: Vec<OverrideConstant>,
    /// A compute kernel's `@workgroup_size` (0 where an `override` gives it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub workgroup_size: Option<[u32; 3]>,
    /// The `override` constant that gives each workgroup size an `override` gives (`null` for
    /// the others); absent when none does.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub workgroup_size_overrides: Vec<Option<String>>,
    /// Bytes of `var<workgroup>` memory a kernel uses; absent when none.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub workgroup_memory: u32,
}

closed_set! {
    /// An optional GPU feature a module may need, by wgpu's name for it: a manifest naming any
    /// other is refused when read, and the run time maps each to wgpu's flag in one `match`.
    GpuFeature {
        /// 16-bit floats in shaders (`#pragma require native16bit`).
        ShaderF16 = "shader-f16",
        /// 64-bit integers in shaders (`#pragma require int64`).
        ShaderInt64 = "shader-int64",
        /// Barycentric coordinates in fragment shaders (`#pragma require barycentrics`).
        ShaderBarycentrics = "shader-barycentrics",
        /// Subgroup (wave) operations (`#pragma require wavebasic` and the other wave names).
        Subgroup = "subgroup",
        /// Immediate data, which carries an ubershader's keywords.
        Immediates = "immediates",
    }
}

fn is_zero(n: &u32) -> bool {
    *n == 0
}

/// One compiled stage module, identified by its bytes: variants whose stage texts differ only in
/// code that compaction removes share it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ModuleManifest {
    /// Index into the pass's `interfaces`.
    pub interface: usize,
    /// The optional GPU features the module was validated with, from its variant's
    /// `#pragma target` and `#pragma require`; a device must have them to load it.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub features: Vec<GpuFeature>,
    /// Its WGSL, if that back end was written.
    pub wgsl: Option<ModuleFile>,
    /// Its SPIR-V, if that back end was written.
    pub spirv: Option<ModuleFile>,
    /// Its Metal Shading Language, if that back end was written (absent otherwise).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub msl: Option<ModuleFile>,
    /// Its HLSL, if that back end was written (absent otherwise).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub hlsl: Option<ModuleFile>,
    /// Its GLSL ES 3.00, if that back end was written (absent otherwise).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub glsl: Option<ModuleFile>,
}

impl ModuleManifest {
    /// Its file for `backend`, if written (the schema names each back end's field).
    pub fn file(&self, backend: Backend) -> Option<&ModuleFile> {
        match backend {
            Backend::Wgsl => self.wgsl.as_ref(),
            Backend::Spirv => self.spirv.as_ref(),
            Backend::Msl => self.msl.as_ref(),
            Backend::Hlsl => self.hlsl.as_ref(),
            Backend::Glsl => self.glsl.as_ref(),
        }
    }

    /// Its files, in [`Backend::ALL`]'s order, for the back ends written.
    pub fn files(&self) -> impl Iterator<Item = &ModuleFile> {
        Backend::ALL.iter().filter_map(|&backend| self.file(backend))
    }

    /// A module with these files (one per back end, `None` where not written).
    pub fn with_files(
        interface: usize,
        features: Vec<GpuFeature>,
        mut files: PerBackend<Option<ModuleFile>>,
    ) -> ModuleManifest {
        let mut take = |backend| files[backend].take();
        ModuleManifest {
            interface,
            features,
            wgsl: take(Backend::Wgsl),
            spirv: take(Backend::Spirv),
            msl: take(Backend::Msl),
            hlsl: take(Backend::Hlsl),
            glsl: take(Backend::Glsl),
        }
    }
}

/// Whether each module's interface index is below `interfaces`, its files' pack indices below
/// `packs` (the lengths of its pass's lists), and their ends addressable (every reader adds a
/// file's offset and size).
pub fn modules_in_range(modules: &[ModuleManifest], interfaces: usize, packs: usize) -> bool {
    modules.iter().all(|module| {
        let mut files = module.files();
        module.interface < interfaces
            && files.all(|file| file.pack < packs && file.offset.checked_add(file.size).is_some())
    })
}

/// A module's bytes: `size` bytes at `offset` of one of the pass's `packs`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ModuleFile {
    /// Index into the pass's `packs`.
    pub pack: usize,
    /// Byte offset in the pack.
    pub offset: u64,
    /// Bytes.
    pub size: u64,
    /// BLAKE3 of the module's bytes, 128 bits in hexadecimal.
    pub hash: String,
}

/// A stage module of a pass, with what it refers to.
#[derive(Debug, Clone, Copy)]
pub struct StageView<'a> {
    /// The pass.
    pub pass: &'a PassManifest,
    /// Its index in the pass's `modules`: variants with the same index share the module.
    pub index: usize,
    /// The module.
    pub module: &'a ModuleManifest,
    /// Its interface.
    pub interface: &'a StageInterface,
}

impl<'a> StageView<'a> {
    /// Its file for `backend`, if written.
    pub fn file(&self, backend: Backend) -> Option<FileRef> {
        self.module.file(backend).map(|f| self.pass.file(f))
    }

    /// Its WGSL file, if written.
    pub fn wgsl(&self) -> Option<FileRef> {
        self.file(Backend::Wgsl)
    }

    /// Its SPIR-V file, if written.
    pub fn spirv(&self) -> Option<FileRef> {
        self.file(Backend::Spirv)
    }

    /// Its module files, one per backend written.
    pub fn files(self) -> impl Iterator<Item = FileRef> + 'a {
        Backend::ALL.iter().filter_map(move |&backend| self.file(backend))
    }
}

/// A stage module: `size` bytes at `offset` of a pack file under the output folder. A build
/// writes the modules it compiles for a pass into one pack per backend, so that a build creates
/// a few files per pass instead of two per module.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FileRef {
    /// Its pack, relative to the output folder.
    pub path: PackPath,
    /// Byte offset in the file.
    pub offset: u64,
    /// Bytes.
    pub size: u64,
    /// BLAKE3 of the module's bytes, 128 bits in hexadecimal.
    pub hash: String,
}

impl FileRef {
    /// Where the module ends in its pack.
    pub fn end(&self) -> u64 {
        // Saturating: a record's offset and size are untrusted (a pass's cache entry is read
        // unchecked), and an end past any pack is a module that cannot be read, not a panic.
        self.offset.saturating_add(self.size)
    }

    /// The module's bytes within its pack's bytes (`None` when the pack is too short).
    pub fn slice<'a>(&self, pack: &'a [u8]) -> Option<&'a [u8]> {
        let range = usize::try_from(self.offset).ok().zip(usize::try_from(self.end()).ok());
        range.and_then(|(start, end)| pack.get(start..end))
    }

    /// The module's bytes, read from its pack under `output` (a regular file, read no further
    /// than the module's end).
    pub fn read(&self, output: &Path) -> std::io::Result<Vec<u8>> {
        let pack = self.path.read(output, self.end())?;
        self.slice(&pack).map(<[u8]>::to_vec).ok_or_else(|| {
            std::io::Error::new(
                std::io::ErrorKind::UnexpectedEof,
                format!("`{}` is shorter than its modules", self.path),
            )
        })
    }
}

/// A number counts as "on" above this, as in Unity's toggle drawers.
pub const TOGGLE_EPSILON: f64 = 0.001;

/// The keywords a drawer can enable, with which value enables each.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum KeywordDrawer {
    /// `[Toggle(KW)]` (or `UPPER(prop)_ON`): on when |value| > 0.001.
    Toggle(String),
    /// `[ToggleOff(KW)]` (or `UPPER(prop)_OFF`): on when the value is off.
    ToggleOff(String),
    /// `[KeywordEnum(A, B)]`: value i enables `UPPER(prop)_UPPER(entry i)`.
    KeywordEnum(Vec<String>),
}

impl KeywordDrawer {
    /// Every keyword this drawer may enable.
    pub fn keywords(&self) -> Vec<&str> {
        match self {
            KeywordDrawer::Toggle(k) | KeywordDrawer::ToggleOff(k) => vec![k.as_str()],
            KeywordDrawer::KeywordEnum(keywords) => keywords.iter().map(String::as_str).collect(),
        }
    }

    /// The keyword enabled by `value`, if any.
    pub fn keyword_for(&self, value: f64) -> Option<&str> {
        let on = value.abs() > TOGGLE_EPSILON;
        match self {
            KeywordDrawer::Toggle(k) => on.then_some(k.as_str()),
            KeywordDrawer::ToggleOff(k) => (!on).then_some(k.as_str()),
            KeywordDrawer::KeywordEnum(keywords) => {
                let index = value.round();
                (index >= 0.0).then(|| keywords.get(index as usize).map(String::as_str)).flatten()
            }
        }
    }
}
