//! From a built variant to a frame: the layer over the manifest and the generated module that
//! gives a wgpu renderer its bind group and pipeline layouts, vertex buffer layouts, each
//! material's render state and its pipelines (each created once), loads a build from an output
//! folder and swaps in a newer one, and records which variants a scene asked for.
//!
//! What a game links: this crate reads what the kiln compiler wrote (through `kiln-manifest`)
//! and holds no compiler, HTTP client, TOML parser or thread pool. A renderer's `build.rs` runs
//! the compiler (`kiln`); the generated module names only this crate.

#![warn(missing_docs, unreachable_pub)]

mod adapter;
mod compute;
mod driver_cache;
mod layout;
mod material;
mod overrides;
mod pipelines;
mod state;
mod trace;
mod ubershader;
mod uniforms;

pub use adapter::{AdapterError, adapter, gl_adapter};
pub use compute::{Kernel, KernelRequest};
pub use driver_cache::CacheFile;
/// The schema the run time reads (`manifest.json`, `materials.json`), for a game's own use.
pub use kiln_manifest as manifest;
pub use kiln_manifest::{FRAME_GROUP, OBJECT_GROUP};
pub use layout::{LayoutError, PassLayout, VertexBuffer, VertexLayout, bind_group_layout_entry};
pub use material::{MATERIAL_GROUP, MaterialBindGroup, MaterialTextures};
pub use pipelines::{
    Creation, ModuleSource, PipelineRequest, Reload, Runtime, Targets, UsageLog, wgpu_feature,
};
pub use state::{
    MAX_TARGETS, PassState, RenderState, StateError, TargetState, resolve as resolve_render_state,
};
pub use trace::{PipelineTrace, TRACE_VERSION, TraceEntry, TracedPipeline, WarmUp, read_trace};
pub use ubershader::{Drawable, UBERSHADER_IMMEDIATE_SIZE};

use kiln_manifest::{
    FILE_NAME, MATERIALS_FILE, Manifest, MaterialManifest, ModuleFile, OverrideType, PassManifest,
    ShaderManifest, VariantManifest,
};
use std::borrow::Cow;
use std::collections::{BTreeSet, HashMap};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU32, Ordering};

/// A built pass, looked up once by [`Library::pass_id`] and given to every request after it.
/// It holds positions in one build: after [`Runtime::reload`] swaps the build, a handle from the
/// old one is refused ([`RuntimeError::StaleHandle`]) rather than read as another pass.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct PassId {
    build: u32,
    shader: u32,
    pass: u32,
}

/// A built variant of a pass with its `dynamic_branch` keywords chosen, looked up once by
/// [`Library::variant_id`] (or [`Runtime::variant`], which logs it) and given to every pipeline
/// request after it: a draw looks nothing up by name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct VariantId {
    pass: PassId,
    variant: u32,
    /// Bit i: the pass's i-th `dynamic_branch` keyword ([`Library::dynamic_keywords`]) is on.
    dynamic: u64,
}

impl VariantId {
    /// Its pass.
    pub fn pass(&self) -> PassId {
        self.pass
    }
}

/// The most `dynamic_branch` keywords one pass may have (bits of [`VariantId`]).
pub const MAX_DYNAMIC_KEYWORDS: usize = 64;

/// Tells builds apart, so that a handle outlives no build it was made for.
static BUILDS: AtomicU32 = AtomicU32::new(0);

/// A module whose bytes in `packs` are not what `manifest` names, if any: checked on scoped
/// threads, one share of the files each (the run time needs no thread pool of its own).
fn first_damaged(
    manifest: &Manifest,
    packs: &HashMap<String, Cow<'static, [u8]>>,
) -> Option<kiln_manifest::FileRef> {
    let files = manifest.files();
    let damaged = |file: &kiln_manifest::FileRef| {
        let bytes = packs.get(file.path.as_str()).and_then(|pack| file.slice(pack));
        bytes.is_none_or(|bytes| blake3::hash(bytes).to_hex()[..32] != file.hash)
    };
    let threads = std::thread::available_parallelism().map_or(1, std::num::NonZero::get);
    let share = files.len().div_ceil(threads).max(1);
    std::thread::scope(|scope| {
        let workers: Vec<_> = files
            .chunks(share)
            .map(|part| scope.spawn(move || part.iter().find(|file| damaged(file)).cloned()))
            .collect();
        workers
            .into_iter()
            .map(|worker| worker.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic)))
            .find_map(|found| found)
    })
}

/// Whether `materials` (the bytes of `materials.json`) are the ones written with `manifest`: a
/// build writes the two one after the other, and one stopped between them leaves a torn pair.
fn same_build(manifest: &Manifest, materials: &[u8]) -> Result<(), String> {
    match &manifest.materials_hash {
        Some(expected) if blake3::hash(materials).to_hex()[..32] != *expected => Err(format!(
            "`{MATERIALS_FILE}` is not the one written with `{FILE_NAME}` (a build stopped between the two?): build again"
        )),
        _ => Ok(()),
    }
}

/// Why the runtime could not do what was asked.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
// Variant fields are named in each variant's message.
#[allow(missing_docs)]
pub enum RuntimeError {
    /// The output folder or a file in it cannot be read.
    #[error("cannot read the build at `{path}`: {message}")]
    Read { path: PathBuf, message: String },
    /// No shader of this name was built.
    #[error("no shader `{0}` in the build")]
    NoShader(String),
    /// The shader has no built pass of this index.
    #[error("`{shader}` has no pass {pass} in the build")]
    NoPass { shader: String, pass: usize },
    #[error(
        "`{shader}` pass {pass} has no variant with keywords [{}] in the build (add a material that uses it, or log usage and build with `--variants-from`)",
        keywords.join(", ")
    )]
    /// The keywords name a variant that was not built.
    MissingVariant { shader: String, pass: usize, keywords: Vec<String> },
    /// A keyword the pass does not declare.
    #[error(
        "`{keyword}` is not a keyword of `{shader}` pass {pass}{}",
        suggestion.as_ref().map(|s| format!(" (did you mean `{s}`?)")).unwrap_or_default()
    )]
    UnknownKeyword { shader: String, pass: usize, keyword: String, suggestion: Option<String> },
    /// Two keywords of one `dynamic_branch` set at once.
    #[error(
        "`{shader}` pass {pass}: `{first}` and `{second}` are keywords of one `dynamic_branch` set; turn on one at a time"
    )]
    TwoKeywordsOfOneSet { shader: String, pass: usize, first: String, second: String },
    /// An override value for a constant the pipeline's modules do not use.
    #[error(
        "`{name}` is not an `override` constant of `{shader}` pass {pass}'s modules{}",
        if *keyword {
            " (it is a `dynamic_branch` keyword: turn it on through the keywords)".to_string()
        } else {
            suggestion.as_ref().map(|s| format!(" (did you mean `{s}`?)")).unwrap_or_default()
        }
    )]
    UnknownOverride { shader: String, pass: usize, name: String, keyword: bool, suggestion: Option<String> },
    /// An override value its constant's type cannot hold.
    #[error(
        "`{shader}` pass {pass}: override `{name}` is `{ty}`, which cannot hold {value}{}",
        type_hint(*ty)
    )]
    OverrideValue { shader: String, pass: usize, name: String, ty: OverrideType, value: f64 },
    /// An override without a default that the request does not set.
    #[error("`{shader}` pass {pass}: override `{name}: {ty}` has no default; give it a value")]
    OverrideRequired { shader: String, pass: usize, name: String, ty: OverrideType },
    /// A kernel the compute shader does not have.
    #[error(
        "`{shader}` has no kernel `{kernel}`{}",
        suggestion.as_ref().map(|s| format!(" (did you mean `{s}`?)")).unwrap_or_default()
    )]
    UnknownKernel { shader: String, kernel: String, suggestion: Option<String> },
    /// No material of this name was built.
    #[error(
        "no material `{name}` in the build{}",
        suggestion.as_ref().map(|s| format!(" (did you mean `{s}`?)")).unwrap_or_default()
    )]
    NoMaterial { name: String, suggestion: Option<String> },
    /// The pass's render state cannot be made with the material's values.
    #[error("render state of `{shader}` pass {pass}: {error}")]
    State { shader: String, pass: usize, error: StateError },
    /// The pass's layout cannot be made on this device.
    #[error("`{shader}` pass {pass}: {message}")]
    Layout { shader: String, pass: usize, message: String },
    /// A handle made for a build the runtime no longer holds.
    #[error("a {0} handle from an earlier build (before `reload` swapped it): look it up again")]
    StaleHandle(&'static str),
    /// More `dynamic_branch` keywords than a handle holds.
    #[error(
        "`{shader}` pass {pass} has more than {MAX_DYNAMIC_KEYWORDS} `dynamic_branch` keywords; `{keyword}` is past them (split the pass's sets)"
    )]
    TooManyDynamicKeywords { shader: String, pass: usize, keyword: String },
    /// The last build failed (its diagnostics, from `errors.txt`).
    #[error("the build failed; the last good pipelines stay in use:\n{0}")]
    BuildFailed(String),
}

/// What values an override type holds, for [`RuntimeError::OverrideValue`].
fn type_hint(ty: OverrideType) -> &'static str {
    match ty {
        OverrideType::Bool => " (0 or 1)",
        OverrideType::I32 | OverrideType::U32 | OverrideType::I64 | OverrideType::U64 => {
            " (a whole number in its range)"
        }
        OverrideType::F16 | OverrideType::F32 | OverrideType::F64 => " (a finite number in its range)",
    }
}

/// A build as the runtime reads it: the manifest, the packs its modules are in, and the resolved
/// materials; from an output folder or from the generated module.
#[derive(Debug)]
pub struct Library {
    /// Which build this is, for handles ([`PassId`]).
    build: u32,
    manifest: Manifest,
    packs: HashMap<String, Cow<'static, [u8]>>,
    materials: Vec<MaterialManifest>,
    /// Shader indices by name (the first of two shaders with one name), for lookups per draw.
    shader_indices: HashMap<String, usize>,
    /// Per pass (shader index, pass position): its variants by keyword set.
    variants: HashMap<(usize, usize), HashMap<BTreeSet<String>, usize>>,
}

impl Library {
    /// The build in an output folder (`kiln build`'s, or `kiln watch`'s). The manifest and the
    /// materials must be of one build: a pair torn by a build stopped between writing the two is
    /// refused. Each module's bytes are checked against the manifest's hash when the run time
    /// first makes a shader module of them (once a module, so the cost follows what is drawn);
    /// [`Library::open_verified`] checks every one here, and [`Library::bytes`] gives them as read.
    pub fn open(output: impl AsRef<Path>) -> Result<Library, RuntimeError> {
        Library::open_checking(output.as_ref(), false)
    }

    /// [`Library::open`], and every module's bytes checked against the hash the manifest names, so
    /// that a pack changed since the build (damaged on disk, tampered with) is refused here and
    /// never handed to the driver. An option, not the default: at 10,000 variants the check added
    /// 13% to `open` on 16 threads and 69% on 2 (docs/performance.md), past the 5% a default may
    /// cost.
    pub fn open_verified(output: impl AsRef<Path>) -> Result<Library, RuntimeError> {
        Library::open_checking(output.as_ref(), true)
    }

    fn open_checking(output: &Path, modules: bool) -> Result<Library, RuntimeError> {
        let read = |name: &str| {
            let path = output.join(name);
            std::fs::read(&path).map_err(|e| RuntimeError::Read { path, message: e.to_string() })
        };
        let manifest = Manifest::parse(&read(FILE_NAME)?)
            .map_err(|e| RuntimeError::Read { path: output.join(FILE_NAME), message: e.to_string() })?;
        let materials_bytes = read(MATERIALS_FILE)?;
        same_build(&manifest, &materials_bytes)
            .map_err(|message| RuntimeError::Read { path: output.join(MATERIALS_FILE), message })?;
        // A pack is read no further than its modules' end, as a regular file only: the manifest
        // is untrusted, and its paths can name nothing but `modules/<hash>.<extension>`.
        let mut packs = HashMap::new();
        for (path, end) in manifest.packs() {
            let bytes = path.read(output, end).map_err(|e| RuntimeError::Read {
                path: path.under(output),
                message: format!("{e}: the output folder is damaged; build again"),
            })?;
            packs.insert(path.as_str().to_string(), Cow::Owned(bytes));
        }
        let damaged = modules.then(|| first_damaged(&manifest, &packs)).flatten();
        let materials: Result<Vec<MaterialManifest>, _> = serde_json::from_slice(&materials_bytes);
        if let Some(file) = damaged {
            return Err(RuntimeError::Read {
                path: file.path.under(output),
                message: format!(
                    "the module at bytes {}..{} is not what the manifest names (its hash differs): the build was changed since; build again",
                    file.offset,
                    file.end()
                ),
            });
        }
        let materials = materials
            .map_err(|e| RuntimeError::Read { path: output.join(MATERIALS_FILE), message: e.to_string() })?;
        Ok(Library::new(manifest, materials, packs))
    }

    /// The build a generated module embeds: `Library::embedded(shaders::MANIFEST_JSON,
    /// shaders::MATERIALS_JSON, &shaders::PACKS)`.
    pub fn embedded(
        manifest: &str,
        materials: &str,
        packs: &[(&str, &'static [u8])],
    ) -> Result<Library, RuntimeError> {
        let embedded = |what: &str, e: &dyn std::fmt::Display| RuntimeError::Read {
            path: PathBuf::from(format!("<embedded {what}>")),
            message: e.to_string(),
        };
        let manifest = Manifest::parse(manifest.as_bytes()).map_err(|e| embedded(FILE_NAME, &e))?;
        same_build(&manifest, materials.as_bytes()).map_err(|e| embedded(MATERIALS_FILE, &e))?;
        let materials = serde_json::from_str(materials).map_err(|e| embedded(MATERIALS_FILE, &e))?;
        let packs = packs.iter().map(|(path, bytes)| (path.to_string(), Cow::Borrowed(*bytes))).collect();
        Ok(Library::new(manifest, materials, packs))
    }

    fn new(
        manifest: Manifest,
        materials: Vec<MaterialManifest>,
        packs: HashMap<String, Cow<'static, [u8]>>,
    ) -> Library {
        let mut variants = HashMap::new();
        let mut shader_indices = HashMap::with_capacity(manifest.shaders.len());
        for (s, shader) in manifest.shaders.iter().enumerate() {
            shader_indices.entry(shader.name.clone()).or_insert(s);
            for (p, pass) in shader.passes.iter().enumerate() {
                let by_keywords = pass
                    .variants
                    .iter()
                    .enumerate()
                    .map(|(v, variant)| (variant.keywords.iter().cloned().collect(), v));
                variants.insert((s, p), by_keywords.collect());
            }
        }
        Library {
            build: BUILDS.fetch_add(1, Ordering::Relaxed),
            manifest,
            packs,
            materials,
            shader_indices,
            variants,
        }
    }

    /// The build's manifest.
    pub fn manifest(&self) -> &Manifest {
        &self.manifest
    }

    /// Every resolved material of the build, in the build's order.
    pub fn materials(&self) -> &[MaterialManifest] {
        &self.materials
    }

    /// A built material, by name.
    pub fn material(&self, name: &str) -> Result<&MaterialManifest, RuntimeError> {
        self.materials.iter().find(|m| m.name == name).ok_or_else(|| RuntimeError::NoMaterial {
            name: name.to_string(),
            suggestion: kiln_manifest::closest(name, self.materials.iter().map(|m| m.name.as_str())),
        })
    }

    fn shader_index(&self, name: &str) -> Result<usize, RuntimeError> {
        self.shader_indices.get(name).copied().ok_or_else(|| RuntimeError::NoShader(name.to_string()))
    }

    /// A built shader, by name.
    pub fn shader(&self, name: &str) -> Result<&ShaderManifest, RuntimeError> {
        Ok(&self.manifest.shaders[self.shader_index(name)?])
    }

    /// A shader's pass by its index (`PassManifest::index`, as `PASS_0` of the generated module).
    pub fn pass(&self, shader: &str, pass: usize) -> Result<&PassManifest, RuntimeError> {
        let (s, p) = self.pass_position(shader, pass)?;
        Ok(&self.manifest.shaders[s].passes[p])
    }

    fn pass_position(&self, shader: &str, pass: usize) -> Result<(usize, usize), RuntimeError> {
        let s = self.shader_index(shader)?;
        let p = self.manifest.shaders[s].passes.iter().position(|p| p.index == pass);
        Ok((s, p.ok_or_else(|| RuntimeError::NoPass { shader: shader.to_string(), pass })?))
    }

    /// A pass's handle, by its shader's name and its index (`PassManifest::index`, as `PASS_0`
    /// of the generated module).
    pub fn pass_id(&self, shader: &str, pass: usize) -> Result<PassId, RuntimeError> {
        let (s, p) = self.pass_position(shader, pass)?;
        Ok(PassId { build: self.build, shader: s as u32, pass: p as u32 })
    }

    /// The pass a handle stands for.
    pub fn pass_of(&self, id: PassId) -> Result<&PassManifest, RuntimeError> {
        if id.build != self.build {
            return Err(RuntimeError::StaleHandle("pass"));
        }
        Ok(&self.manifest.shaders[id.shader as usize].passes[id.pass as usize])
    }

    /// The name of a handle's shader, for messages.
    pub(crate) fn shader_name(&self, id: PassId) -> &str {
        &self.manifest.shaders[id.shader as usize].name
    }

    /// The variant built with exactly these keywords (any order), as a handle: strict, never a
    /// near match. The pass's `dynamic_branch` keywords may be among them: they choose no
    /// variant but the pipeline's constants, at most one of each set.
    pub fn variant_id(&self, pass: PassId, keywords: &[&str]) -> Result<VariantId, RuntimeError> {
        let manifest = self.pass_of(pass)?;
        let (shader, index) = (self.shader_name(pass), manifest.index);
        // A keyword the pass does not have is a typo, not a variant to build.
        let known = &manifest.keywords;
        let dynamic: Vec<&String> = manifest.dynamic_keywords().collect();
        if let Some(unknown) =
            keywords.iter().find(|k| !known.iter().chain(dynamic.iter().copied()).any(|known| known == *k))
        {
            let names = known.iter().chain(dynamic.iter().copied()).map(String::as_str);
            return Err(RuntimeError::UnknownKeyword {
                shader: shader.to_string(),
                pass: index,
                keyword: unknown.to_string(),
                suggestion: kiln_manifest::closest(unknown, names),
            });
        }
        for set in manifest.dynamic_sets() {
            let mut on = keywords.iter().filter(|k| set.keywords.iter().any(|s| s == *k));
            if let (Some(first), Some(second)) = (on.next(), on.next()) {
                return Err(RuntimeError::TwoKeywordsOfOneSet {
                    shader: shader.to_string(),
                    pass: index,
                    first: first.to_string(),
                    second: second.to_string(),
                });
            }
        }
        let mut mask = 0u64;
        for keyword in keywords {
            let Some(bit) = dynamic.iter().position(|k| k == keyword) else { continue };
            if bit >= MAX_DYNAMIC_KEYWORDS {
                return Err(RuntimeError::TooManyDynamicKeywords {
                    shader: shader.to_string(),
                    pass: index,
                    keyword: keyword.to_string(),
                });
            }
            mask |= 1 << bit;
        }
        // `dynamic_branch` keywords choose constants, not variants.
        let wanted: BTreeSet<String> =
            keywords.iter().filter(|k| !manifest.is_dynamic(k)).map(|k| k.to_string()).collect();
        match self.variants[&(pass.shader as usize, pass.pass as usize)].get(&wanted) {
            Some(&v) => Ok(VariantId { pass, variant: v as u32, dynamic: mask }),
            None => Err(RuntimeError::MissingVariant {
                shader: shader.to_string(),
                pass: index,
                keywords: wanted.into_iter().collect(),
            }),
        }
    }

    /// The handle of a variant the generated module found: its `Variant::key()`, a bit per keyword
    /// of the pass's `keywords` in words of 64, so no keyword passes through a string; every
    /// `dynamic_branch` keyword at its default ([`Library::variant_id`] chooses them).
    pub fn variant_id_by_key(&self, pass: PassId, key: &[u64]) -> Result<VariantId, RuntimeError> {
        let manifest = self.pass_of(pass)?;
        let bit = |keyword: &String| manifest.keywords.iter().position(|k| k == keyword);
        let key_of = |variant: &VariantManifest| {
            let mut words = vec![0u64; manifest.keywords.len().div_ceil(64)];
            for b in variant.keywords.iter().filter_map(bit) {
                words[b / 64] |= 1 << (b % 64);
            }
            words
        };
        match manifest.variants.iter().position(|v| key_of(v) == key) {
            Some(v) => Ok(VariantId { pass, variant: v as u32, dynamic: 0 }),
            None => Err(RuntimeError::MissingVariant {
                shader: self.shader_name(pass).to_string(),
                pass: manifest.index,
                keywords: (0..manifest.keywords.len())
                    .filter(|b| key.get(b / 64).is_some_and(|w| w & (1 << (b % 64)) != 0))
                    .map(|b| manifest.keywords[b].clone())
                    .collect(),
            }),
        }
    }

    /// The variant a handle stands for.
    pub fn variant_of(&self, id: VariantId) -> Result<&VariantManifest, RuntimeError> {
        Ok(&self.pass_of(id.pass)?.variants[id.variant as usize])
    }

    /// The `dynamic_branch` keywords a handle turns on.
    pub fn dynamic_keywords(&self, id: VariantId) -> Result<impl Iterator<Item = &str>, RuntimeError> {
        let pass = self.pass_of(id.pass)?;
        let on = pass.dynamic_keywords().enumerate().filter(move |(bit, _)| id.dynamic & (1 << bit) != 0);
        Ok(on.map(|(_, keyword)| keyword.as_str()))
    }

    /// The variant built with exactly these keywords (any order): [`Library::variant_id`] by
    /// names, for a look at its manifest.
    pub fn variant(
        &self,
        shader: &str,
        pass: usize,
        keywords: &[&str],
    ) -> Result<&VariantManifest, RuntimeError> {
        self.variant_of(self.variant_id(self.pass_id(shader, pass)?, keywords)?)
    }

    /// A module's bytes, from its pack.
    pub fn bytes(&self, pass: &PassManifest, file: &ModuleFile) -> Option<&[u8]> {
        let pack = self.packs.get(pass.packs.get(file.pack)?.as_str())?;
        pack.get(file.offset as usize..(file.offset + file.size) as usize)
    }
}
