//! What a build leaves: the manifest (its passes' parts in catalogue order), the materials, and
//! the record of a clean build for the next no-op check; JSON streamed and written atomically.
//!
//! Long because the manifest's parts that need the whole catalogue are made here (the shaders'
//! heads, the materials), then staged and committed in one order that keeps the output folder
//! whole; a pass's own part is made in `part`.

use super::error::BuildLayerError;
use super::noop::recorded_name;
use super::plan::{PassWork, pass_key};
use super::{BuildResult, BuildSummary, Writes};
use crate::catalog::{Catalog, CatalogShader};
use crate::config::Settings;
use crate::diagnostics::{self, Diagnostic};
use crate::manifest::*;
use crate::material::{Material, MaterialValue};
use crate::reflect::{Resource, UniformBlock};
use crate::shaderlab::ast::Property;
use crate::source::{SourceStore, relative_to};
use crate::store::{Cache, Digest, Hashed, OutputFile, PassKey, Recorded, RecordedFile};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use serde_json::value::RawValue;
use std::collections::{BTreeSet, HashMap};

/// What the manifest takes from the catalogue besides the passes' parts, so that a merge needs
/// no catalogue: each built shader (its passes left out, its properties' places not yet known)
/// with its passes' keys, the materials, the counts, and what the build read.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct CataloguePart {
    /// The built shaders, in catalogue order.
    pub shaders: Vec<ShaderHead>,
    /// How many materials `materials.json` lists (each shard keeps those of its shaders).
    pub materials: usize,
    /// Shaders, passes and variants built.
    pub counts: [usize; 3],
    /// Shaders no material uses.
    pub unused: Vec<String>,
    /// How many of `read` the build was given (the rest came through includes).
    pub given: usize,
    /// Every file the build read, relative to the project, in order.
    pub read: Vec<String>,
    /// Every path it looked for in vain.
    pub absent: Vec<String>,
}

/// A built shader without its passes, and its passes' keys in order.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ShaderHead {
    /// The shader's manifest entry, without passes.
    pub shader: ShaderManifest<()>,
    /// Its passes' keys ([`super::plan::pass_key`]).
    pub passes: Vec<PassKey>,
}

/// The shaders `work`'s passes belong to, in catalogue order, with their passes' keys.
pub(super) fn shader_heads(store: &SourceStore, settings: &Settings, work: &[PassWork]) -> Vec<ShaderHead> {
    let mut shaders: Vec<(&CatalogShader, ShaderHead)> = Vec::new();
    for pass in work {
        let key = pass_key(store, settings, pass);
        match shaders.last_mut() {
            Some((shader, head)) if std::ptr::eq(*shader, pass.shader) => head.passes.push(key),
            _ => {
                let shader = &pass.shader.shader;
                let head = ShaderManifest {
                    name: shader.name.value.clone(),
                    file: recorded_name(store, pass.shader.file, &settings.root),
                    render_queue: crate::material::shader_queue(shader),
                    properties: shader.properties.iter().map(property).collect(),
                    passes: Vec::new(),
                };
                shaders.push((pass.shader, ShaderHead { shader: head, passes: vec![key] }));
            }
        }
    }
    shaders.into_iter().map(|(_, head)| head).collect()
}

/// The catalogue's part of a build's output (`shaders`: [`shader_heads`]); `read`: the files read
/// from disk, by their recorded names ([`super::noop::disk_names`]); `given`: the files the
/// project was given ([`super::Run::given_files`]).
pub(super) fn catalogue_part(
    store: &SourceStore,
    catalog: &Catalog,
    settings: &Settings,
    given: usize,
    shaders: Vec<ShaderHead>,
    summary: &BuildSummary,
    read: Vec<String>,
) -> CataloguePart {
    // Each path once, however many includes looked there.
    let absent: BTreeSet<String> = store.absent().iter().map(|p| relative_to(p, &settings.root)).collect();
    CataloguePart {
        shaders,
        materials: listed_materials(catalog).count(),
        counts: [summary.shaders, summary.passes, summary.variants],
        unused: summary.unused.clone(),
        given,
        read,
        absent: absent.into_iter().collect(),
    }
}

/// The manifest from the catalogue's shader heads and the passes' parts (in plan order), each
/// shader's properties placed from its passes.
pub(super) fn manifest<P: PassFiles>(heads: Vec<ShaderHead>, parts: Vec<P>) -> Manifest<P> {
    let mut parts = parts.into_iter();
    let shaders = heads
        .into_iter()
        .map(|head| with_passes(head.shader, parts.by_ref().take(head.passes.len()).collect()));
    manifest_of(shaders.collect(), None)
}

/// A manifest of these shaders, written by this kiln.
fn manifest_of<P>(shaders: Vec<ShaderManifest<P>>, materials_hash: Option<String>) -> Manifest<P> {
    Manifest {
        schema_version: SCHEMA_VERSION,
        kiln_version: env!("CARGO_PKG_VERSION").to_string(),
        shaders,
        materials_hash,
    }
}

/// A shader's manifest entry from its head and its passes' parts, its properties placed.
fn with_passes<P: PassFiles>(head: ShaderManifest<()>, passes: Vec<P>) -> ShaderManifest<P> {
    let ShaderManifest { name, file, render_queue, properties, passes: _ } = head;
    let mut shader = ShaderManifest { name, file, render_queue, properties, passes };
    place_properties(&mut shader);
    shader
}

/// What the passes give (their parts of the manifest, and the rest: `T`), kept in plan order as
/// they finish. Given a path, it also writes the compact manifest while they come in: each
/// shader serialized once its passes are in, and written once every shader before it is.
/// Workers take passes in plan order, so with more passes than threads they finish about in
/// order; the passes in flight at once (all of them, when there are fewer than threads) finish
/// in any order. A build's end is then left with the bytes of the shaders after the last pass to
/// finish and the materials' hash to write, not the whole manifest (8-9 ms on one thread at
/// 10,000 compute variants).
pub(super) struct PassParts<'h, T> {
    state: std::sync::Mutex<PartsIn<'h, T>>,
}

/// What [`PassParts`] holds.
struct PartsIn<'h, T> {
    passes: Vec<Option<(BuiltPass, T)>>,
    stream: Option<Stream<'h>>,
}

/// A manifest being written as the passes finish.
struct Stream<'h> {
    /// Its shaders.
    heads: &'h [ShaderHead],
    /// Each shader's first pass, and the number of passes after the last.
    firsts: Vec<usize>,
    /// Shaders whose passes are all in, as JSON, until every shader before them is written too.
    ready: Vec<Option<Vec<u8>>>,
    /// What was written so far, until a write fails.
    writer: std::io::Result<ManifestWriter>,
    /// The next shader to write.
    next: usize,
}

impl<'h, T> PassParts<'h, T> {
    /// Room for what `passes` passes give, and the manifest of `heads` (every pass's shader)
    /// written to a path if given.
    pub(super) fn new(passes: usize, manifest: Option<(&'h [ShaderHead], &std::path::Path)>) -> Self {
        let stream = manifest.map(|(heads, path)| {
            let firsts = std::iter::once(0)
                .chain(heads.iter().scan(0, |first, head| {
                    *first += head.passes.len();
                    Some(*first)
                }))
                .collect();
            let ready = heads.iter().map(|_| None).collect();
            Stream { heads, firsts, ready, writer: ManifestWriter::open(path), next: 0 }
        });
        let state = PartsIn { passes: (0..passes).map(|_| None).collect(), stream };
        PassParts { state: std::sync::Mutex::new(state) }
    }

    /// What the pass `index` (in plan order) gave. The shader it completes is serialized now,
    /// while other passes still compile, and written once every shader before it is: the last
    /// pass to finish leaves only bytes to hash and write.
    pub(super) fn add(&self, index: usize, part: BuiltPass, rest: T) {
        let mut guard = self.state.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        let PartsIn { passes, stream } = &mut *guard;
        if let Some(slot) = passes.get_mut(index) {
            *slot = Some((part, rest));
        }
        let Some(stream) = stream else { return };
        let shader = stream.firsts.partition_point(|&first| first <= index).saturating_sub(1);
        let (Some(head), Some(&first)) = (stream.heads.get(shader), stream.firsts.get(shader)) else {
            return;
        };
        if let Some(done) =
            passes.get(first..first + head.passes.len()).filter(|p| p.iter().all(Option::is_some))
            && stream.writer.is_ok()
        {
            match shader_json(head, done.iter().flatten().map(|(part, _)| part).collect()) {
                Ok(json) => stream.ready[shader] = Some(json),
                Err(error) => stream.writer = Err(error),
            }
        }
        while let Some(json) = stream.ready.get_mut(stream.next).and_then(Option::take) {
            if let Ok(writer) = &mut stream.writer
                && let Err(error) = writer.shader(&json, stream.next == 0)
            {
                stream.writer = Err(error);
            }
            stream.next += 1;
        }
    }

    /// The parts and the rest, in plan order, and the manifest written (every shader's, once
    /// every pass is in).
    pub(super) fn into_parts(self) -> (Vec<BuiltPass>, Vec<T>, Option<std::io::Result<ManifestWriter>>) {
        let state = self.state.into_inner().unwrap_or_else(std::sync::PoisonError::into_inner);
        debug_assert!(state.passes.iter().all(Option::is_some), "every pass is in");
        let (parts, rest) = state.passes.into_iter().flatten().unzip();
        (parts, rest, state.stream.map(|stream| stream.writer))
    }
}

/// A compact manifest being staged, written a shader at a time and hashed as it goes.
pub(super) struct ManifestWriter {
    staged: crate::store::Staged,
    file: std::io::BufWriter<std::fs::File>,
    digest: Digest,
}

impl ManifestWriter {
    fn open(path: &std::path::Path) -> std::io::Result<ManifestWriter> {
        let (staged, file) = crate::store::Staged::beside(path)?;
        let file = std::io::BufWriter::with_capacity(1 << 16, file);
        let mut writer = ManifestWriter { staged, file, digest: Digest::default() };
        writer.put(manifest_ends(None)?.0.as_bytes())?;
        Ok(writer)
    }

    fn put(&mut self, bytes: &[u8]) -> std::io::Result<()> {
        use std::io::Write as _;
        self.digest.write_all(bytes)?;
        self.file.write_all(bytes)
    }

    /// Writes a shader's JSON, after a comma unless it is the `first`.
    fn shader(&mut self, json: &[u8], first: bool) -> std::io::Result<()> {
        if !first {
            self.put(b",")?;
        }
        self.put(json)
    }

    /// The manifest's end, naming the materials' hash, written: the manifest staged as
    /// [`stage_json`] stages it whole.
    fn finish(mut self, materials_hash: String) -> std::io::Result<StagedJson> {
        self.put(manifest_ends(Some(materials_hash))?.1.as_bytes())?;
        self.put(b"\n")?;
        crate::store::durable(&self.file.into_inner().map_err(std::io::IntoInnerError::into_error)?)?;
        Ok(StagedJson { staged: self.staged, digest: self.digest })
    }
}

/// A shader's JSON in a compact manifest, its passes in.
fn shader_json(head: &ShaderHead, passes: Vec<&BuiltPass>) -> std::io::Result<Vec<u8>> {
    let shader = with_passes(head.shader.clone(), passes);
    serde_json::to_vec(&shader).map_err(std::io::Error::other)
}

/// A compact manifest's text before its first shader and after its last, as serde writes them.
fn manifest_ends(materials_hash: Option<String>) -> std::io::Result<(String, String)> {
    const SHADERS: &str = "\"shaders\":[";
    let mut text = serde_json::to_string(&manifest_of::<()>(Vec::new(), materials_hash))
        .map_err(std::io::Error::other)?;
    let at = text.find(SHADERS).map(|at| at + SHADERS.len());
    let at = at.ok_or_else(|| std::io::Error::other("a manifest without its shaders"))?;
    let end = text.split_off(at);
    Ok((text, end))
}

/// What a whole build (or a merge) writes beside its packs, and what its record says.
pub(super) struct Outputs<'a, P> {
    /// The files read, where what the record keeps of the findings points.
    pub store: &'a SourceStore,
    /// What was reported before the build: the record keeps it with the build's own findings.
    pub earlier: &'a [Diagnostic],
    /// The manifest: its `materials_hash` is set here.
    pub manifest: &'a mut Manifest<P>,
    /// The materials, each one's compact text, in order.
    pub materials: &'a [&'a RawValue],
    /// The catalogue's part: what the record lists as given and read.
    pub catalogue: &'a CataloguePart,
    /// The inputs key ([`super::noop::inputs_key`]).
    pub inputs: &'a str,
    /// The manifest's writer where its shaders were written as the passes finished
    /// ([`PassParts`]): then only its end is written here.
    pub streamed: Option<std::io::Result<ManifestWriter>>,
}

/// Writes what a whole build (or a merge) leaves once its passes are built ([`Outputs`]): the
/// manifest, the materials, and, where `writes` says, the record of a clean build. `alongside`
/// runs while the two files are written (a merge links the shards' packs then; it returns the
/// bytes it copied): neither file replaces the old one unless both are written and `alongside`
/// succeeded.
///
/// The folder's commit point: the materials are staged first and the manifest names their hash
/// (so a reader tells a torn pair); the last build's record is removed before either file is
/// replaced (so a build stopped between the two renames is no no-op's), and written again, with
/// both files' hashes, only once both are in place.
pub(super) fn finish<P: PassFiles + Serialize + Send + Sync>(
    settings: &Settings,
    writes: Writes,
    outputs: Outputs<P>,
    mut summary: BuildSummary,
    mut diagnostics: Vec<Diagnostic>,
    alongside: impl FnOnce() -> std::io::Result<u64> + Send,
) -> BuildResult {
    let Outputs { store, earlier, manifest, materials, catalogue, inputs, streamed } = outputs;
    let output = &settings.output;
    let mut files = Vec::new();
    let cache = Cache::new(output, true);
    if writes.output() && !diagnostics::has_errors(&diagnostics) {
        files = (pack_ends(manifest.shaders.iter().flat_map(|s| &s.passes)).into_iter())
            .map(|(path, len)| RecordedFile { path: OutputFile::Pack(path), len, hash: None })
            .collect();
        // The materials, then the manifest that names their hash, while `alongside` runs.
        let (staged, alongside) = rayon::join(
            || {
                let materials =
                    stage_materials(&output.join(MATERIALS_FILE), materials, settings.pretty_manifest)?;
                manifest.materials_hash = Some(materials.hash());
                let manifest = match streamed.transpose()? {
                    Some(streamed) => streamed.finish(materials.hash())?,
                    None => stage_json(&output.join(FILE_NAME), &*manifest, settings.pretty_manifest)?,
                };
                Ok((materials, manifest))
            },
            alongside,
        );
        match (staged, alongside.and_then(|copied| cache.forget_inputs().map(|()| copied))) {
            (Ok((materials, manifest)), Ok(copied)) => {
                summary.bytes_written += copied;
                // Each pack's bytes hashed once in place (a merge links them in `alongside`), so
                // that a no-op build trusts no pack it has not read back whole.
                files.par_iter_mut().for_each(|file| {
                    let digest = Digest::of_file(&file.path.under(output), file.len.saturating_add(1));
                    let digest = digest.ok().filter(|digest| digest.len == file.len);
                    file.hash = digest.map(|digest| digest.finish().to_hex()[..32].to_string());
                });
                // The packs' names durable before the manifest that names them is; else nothing
                // is replaced.
                let packs_durable = crate::store::durable_folder(&output.join(PACK_FOLDER))
                    .map_err(|error| diagnostics.push(write_failure(output, error)))
                    .is_ok();
                let staged = if packs_durable {
                    vec![(OutputFile::Materials, materials), (OutputFile::Manifest, manifest)]
                } else {
                    Vec::new()
                };
                for (name, staged) in staged {
                    let hash = staged.hash();
                    match staged.commit() {
                        Ok((len, written)) => {
                            summary.bytes_written += if written { len } else { 0 };
                            files.push(RecordedFile { path: name, len, hash: Some(hash) });
                        }
                        Err(error) => diagnostics.push(write_failure(output, error)),
                    }
                }
            }
            // Nothing replaced: the staged files are dropped.
            (staged, alongside) => {
                let errors = [staged.err(), alongside.err()].into_iter().flatten();
                diagnostics.extend(errors.map(|error| write_failure(output, error)));
            }
        }
    }
    diagnostics::dedup(&mut diagnostics);
    if writes.output() && !diagnostics::has_errors(&diagnostics) {
        cache.sweep(&files);
    }
    let findings =
        writes.record().then(|| super::noop::recordable(store, earlier.iter().chain(&diagnostics)));
    if let Some(findings) = findings.flatten() {
        // Only costs a full build next time if it cannot be written.
        let _ = cache.record_inputs(&Recorded {
            key: inputs.to_string(),
            given: catalogue.given,
            shaders: summary.shaders,
            passes: summary.passes,
            variants: summary.variants,
            modules: summary.modules,
            files,
            read: catalogue.read.clone(),
            absent: catalogue.absent.clone(),
            findings,
        });
    }
    if writes.output() && !diagnostics::has_errors(&diagnostics) {
        // The commit point's names (the manifest, the materials, the record) durable.
        let _ = crate::store::durable_folder(output);
    }
    BuildResult { manifest: None, summary, diagnostics, output: output.clone() }
}

/// `materials.json`: the materials' compact texts as they are, or indented as a whole build
/// indents them.
fn stage_materials(
    path: &std::path::Path,
    materials: &[&RawValue],
    pretty: bool,
) -> std::io::Result<StagedJson> {
    if pretty {
        let materials: Vec<MaterialManifest> = (materials.iter())
            .map(|m| serde_json::from_str(m.get()))
            .collect::<Result<_, _>>()
            .map_err(std::io::Error::other)?;
        stage_json(path, &materials, true)
    } else {
        stage_json(path, &materials, false)
    }
}

/// JSON (the manifest, the materials) written beside its file and not yet in its place, with
/// what was written: its length, and its hash when there is an old file to compare with.
struct StagedJson {
    staged: crate::store::Staged,
    digest: Digest,
}

/// Writes JSON streamed, so that a million variants' manifest is never a string in memory, and
/// hashed as it goes (the record names the hash, and [`StagedJson::commit`] compares it with the
/// file there).
fn stage_json(
    path: &std::path::Path,
    value: &impl serde::Serialize,
    pretty: bool,
) -> std::io::Result<StagedJson> {
    use std::io::Write as _;
    let mut digest = Digest::default();
    // Hashed always: the record of a clean build names both files' hashes, and the manifest the
    // materials'.
    let serialize = |out: &mut dyn std::io::Write| {
        let mut hashed = Hashed { out, digest: Digest::default() };
        {
            // serde writes a token at a time: buffered before hashing, so the hasher (and the
            // file's own buffer) see large pieces (a 50 MB manifest took 0.8 s unbuffered).
            let mut out = std::io::BufWriter::with_capacity(1 << 16, &mut hashed);
            if pretty {
                serde_json::to_writer_pretty(&mut out, value)
            } else {
                serde_json::to_writer(&mut out, value)
            }
            .map_err(std::io::Error::other)?;
            out.write_all(b"\n")?;
            out.flush()?;
        }
        digest = hashed.digest;
        Ok(())
    };
    let staged = crate::store::stage(path, serialize)?;
    Ok(StagedJson { staged, digest })
}

impl StagedJson {
    /// The hash of what was written, as [`crate::store::hash`] gives it.
    fn hash(&self) -> String {
        self.digest.finish().to_hex()[..32].to_string()
    }

    /// Puts the JSON in its place, unless the file there holds exactly these bytes already (so
    /// that a rebuild that compiles nothing touches nothing). Returns its length and whether it
    /// was written.
    fn commit(self) -> std::io::Result<(u64, bool)> {
        let StagedJson { staged, digest } = self;
        let changed = |old: &std::path::Path| {
            let same = std::fs::metadata(old).is_ok_and(|m| m.len() == digest.len)
                && Digest::of_file(old, digest.len + 1).is_ok_and(|old| old.finish() == digest.finish());
            !same
        };
        let written = staged.commit(changed)?;
        Ok((digest.len, written))
    }
}

pub(super) fn write_failure(output: &std::path::Path, error: std::io::Error) -> Diagnostic {
    BuildLayerError::Write { output: output.to_path_buf(), error }.into()
}

/// A pass's part of the manifest as a build holds it: parsed, and the JSON text it is written as
/// when that does not depend on its place (a compact manifest, a shard's record), made on the
/// pass's own thread so that no one thread serializes every pass.
pub(super) struct BuiltPass {
    pub part: PassManifest,
    pub text: Option<Box<RawValue>>,
}

impl BuiltPass {
    /// `text`: whether its text is made now (a pass written compact).
    pub(super) fn new(part: PassManifest, text: bool) -> BuiltPass {
        let text = text.then(|| json_text(&part));
        BuiltPass { part, text }
    }

    /// Its JSON text, compact.
    pub(super) fn into_text(self) -> Box<RawValue> {
        self.text.unwrap_or_else(|| json_text(&self.part))
    }
}

impl Serialize for BuiltPass {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match &self.text {
            Some(text) => text.serialize(serializer),
            None => self.part.serialize(serializer),
        }
    }
}

impl PassFiles for BuiltPass {
    fn packs(&self) -> &[PackPath] {
        &self.part.packs
    }
    fn modules(&self) -> &[ModuleManifest] {
        &self.part.modules
    }
    fn layout(&self) -> &[BindGroup] {
        &self.part.layout
    }
    fn uniform_blocks(&self) -> &[UniformBlock] {
        &self.part.uniform_blocks
    }
}

/// The parsed manifest of a build's written one.
pub(super) fn parsed(manifest: Manifest<BuiltPass>) -> Manifest {
    let Manifest { schema_version, kiln_version, shaders, materials_hash } = manifest;
    let shaders = shaders
        .into_iter()
        .map(|s| ShaderManifest {
            name: s.name,
            file: s.file,
            render_queue: s.render_queue,
            properties: s.properties,
            passes: s.passes.into_iter().map(|p| p.part).collect(),
        })
        .collect();
    Manifest { schema_version, kiln_version, shaders, materials_hash }
}

/// The materials `materials.json` lists, in its order: every resolved material of a shader in
/// the catalogue.
pub(super) fn listed_materials(catalog: &Catalog) -> impl Iterator<Item = &Material> + '_ {
    catalog.materials.iter().filter(|m| catalog.shaders.get(m.shader).is_some())
}

/// A listed material as `materials.json` has it.
pub(super) fn material_entry(catalog: &Catalog, material: &Material) -> MaterialManifest {
    material.to_manifest(&catalog.shaders[material.shader].shader.name.value)
}

/// The listed materials that `keep` takes, each as its compact text with its place in
/// `materials.json`; made in parallel (a project has tens of thousands).
pub(super) fn material_texts(
    catalog: &Catalog,
    keep: impl Fn(&Material) -> bool + Sync,
) -> Vec<(usize, Box<RawValue>)> {
    let listed: Vec<&Material> = listed_materials(catalog).collect();
    listed
        .par_iter()
        .enumerate()
        .filter(|(_, m)| keep(m))
        .map(|(position, m)| (position, json_text(&material_entry(catalog, m))))
        .collect()
}

/// `materials.json`'s materials in order, from their texts and places: `None` unless every
/// place from 0 to `count` is filled exactly once.
pub(super) fn placed_materials<'a>(
    count: usize,
    texts: impl IntoIterator<Item = &'a (usize, Box<RawValue>)>,
) -> Option<Vec<&'a RawValue>> {
    let mut placed: Vec<Option<&RawValue>> = vec![None; count];
    for (position, text) in texts {
        let slot = placed.get_mut(*position)?;
        if slot.replace(text).is_some() {
            return None;
        }
    }
    placed.into_iter().collect()
}

/// The compact JSON text of plain data.
pub(super) fn json_text(value: &impl Serialize) -> Box<RawValue> {
    // Derived `Serialize` over strings, numbers and string-keyed maps cannot fail.
    serde_json::value::to_raw_value(value).expect("plain data serializes")
}

/// A property as the manifest has it, its places ([`place_properties`]) not yet known.
fn property(p: &Property) -> PropertyManifest {
    PropertyManifest {
        name: p.name.value.clone(),
        display_name: p.display_name.value.clone(),
        ty: p.ty.value.manifest_text(),
        default: MaterialValue::from(&p.default.value).to_json(),
        offset: None,
        binding: None,
        drawer: crate::material::keyword_drawer(p),
        enum_names: crate::material::enum_names(p),
    }
}

/// Each property's place: its offset in the material block (from the first pass that has one)
/// and its texture's binding.
fn place_properties<P: PassFiles>(shader: &mut ShaderManifest<P>) {
    let passes = &shader.passes;
    let material_block =
        passes.iter().flat_map(|p| p.uniform_blocks()).find(|b| b.name == "UnityPerMaterial");
    let mut bindings: HashMap<&str, [u32; 2]> = HashMap::new();
    for pass in passes {
        for group in pass.layout() {
            for entry in &group.entries {
                if matches!(entry.resource, Resource::Texture { .. } | Resource::StorageTexture { .. }) {
                    bindings.entry(entry.name.as_str()).or_insert([group.group, entry.binding]);
                }
            }
        }
    }
    for property in &mut shader.properties {
        property.offset =
            material_block.and_then(|b| b.members.iter().find(|m| m.name == property.name)).map(|m| m.offset);
        property.binding = bindings.get(property.name.as_str()).copied();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pass(index: usize) -> BuiltPass {
        let json = serde_json::json!({
            "subshader": 0, "index": index, "name": format!("P{index}"), "tags": [], "render_state": [],
            "keyword_sets": [], "keywords": [], "layout": [], "uniform_blocks": [], "packs": [],
            "interfaces": [], "modules": [], "variants": []
        });
        let part: PassManifest = serde_json::from_value(json).expect("a pass");
        let text = Some(json_text(&part));
        BuiltPass { part, text }
    }

    /// Shaders of two, one, three and one passes, the passes coming in forwards, backwards,
    /// interleaved and rotated: the file is serde's writing of the whole manifest each time.
    #[test]
    fn a_manifest_streamed_as_passes_finish_in_any_order_is_the_whole_manifest() {
        let sizes = [2, 1, 3, 1];
        let heads: Vec<ShaderHead> = (sizes.iter().enumerate())
            .map(|(s, &passes)| ShaderHead {
                shader: ShaderManifest {
                    name: format!("S{s}"),
                    file: format!("S{s}.shader"),
                    render_queue: 2000,
                    properties: Vec::new(),
                    passes: Vec::new(),
                },
                passes: (0..passes).map(|p| PassKey::of(&format!("{s}-{p}"))).collect(),
            })
            .collect();
        let total: usize = sizes.iter().sum();
        let forwards: Vec<usize> = (0..total).collect();
        let interleaved: Vec<usize> = (1..total).step_by(2).chain((0..total).step_by(2)).collect();
        let mut orders = vec![forwards.iter().rev().copied().collect(), interleaved];
        orders.extend((0..total).map(|r| forwards.iter().cycle().skip(r).take(total).copied().collect()));
        for order in orders {
            let folder = tempfile::tempdir().expect("temp dir");
            let path = folder.path().join(FILE_NAME);
            let parts = PassParts::new(total, Some((&heads[..], path.as_path())));
            for &index in &order {
                parts.add(index, pass(index), ());
            }
            let (parts, _, streamed) = parts.into_parts();
            let writer = streamed.expect("streamed").expect("opened");
            writer.finish("materials".into()).expect("finished").commit().expect("committed");
            let mut whole = manifest(heads.clone(), parts);
            whole.materials_hash = Some("materials".into());
            let whole = serde_json::to_string(&whole).expect("json") + "\n";
            let written = std::fs::read_to_string(&path).expect("written");
            assert!(written == whole, "passes in the order {order:?}: the manifest written differs");
        }
    }
}
