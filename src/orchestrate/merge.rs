//! `kiln merge`: the output of one build from the shards' parts, with naga run nowhere, nothing
//! preprocessed and no catalogue: the first shard's record carries what the manifest takes from
//! the catalogue. Each pass's part comes from the shard that built it, and each of its packs is
//! checked whole against the hash the shard recorded ([`read_shards`], which needs no project, so
//! the caller reads the project meanwhile). The project must still be what the shards read (its
//! files read again and hashed); then the packs and the cache entries are linked into the output
//! (copied where a link cannot be made) while the manifest and the materials are written, so the
//! output is one build's, byte for byte.

use super::emit::{CataloguePart, Outputs, finish, manifest, placed_materials};
use super::error::BuildLayerError;
use super::noop::{Inputs, same_inputs};
use super::shard::{ShardPass, pack_hash};
use super::{BuildResult, BuildSummary, Merge, Writes};
use crate::config::Settings;
use crate::diagnostics::Diagnostic;
use crate::manifest::{
    BindGroup, Manifest, ModuleManifest, PackPath, PassFiles, PassManifest, StageInterface, UniformBlock,
    modules_in_range,
};
use crate::source::SourceStore;
use crate::store::{link_or_copy, pass_index_path};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use serde_json::value::RawValue;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// What a merge reads of the shards alone, made while the project is read: where each pass of
/// the manifest was built, the fields the merge needs of its part, and its packs checked against
/// their shard's hashes.
#[derive(Default)]
pub struct ShardsRead {
    /// Each pass of the catalogue, in manifest order: its shard's index and its place in that
    /// shard's record (passes no shard built are left out, with a diagnostic).
    found: Vec<(usize, usize)>,
    /// What the merge reads of each found pass's part.
    views: Vec<PassView>,
    diagnostics: Vec<Diagnostic>,
}

/// The first shard record's catalogue part (every merge needs it; only the first shard writes it).
fn catalogue(merge: &Merge) -> Option<&CataloguePart> {
    merge.shards.iter().find_map(|(_, record)| record.catalogue.as_ref())
}

/// Reads and checks the shards' parts (see [`ShardsRead`]); a merge without a catalogue part
/// reads nothing (the merge reports it).
pub(super) fn read_shards(merge: &Merge) -> ShardsRead {
    let Some(catalogue) = catalogue(merge) else { return ShardsRead::default() };
    let built: HashMap<&str, (usize, usize)> = (merge.shards.iter().enumerate())
        .flat_map(|(s, (_, record))| {
            record.passes.iter().enumerate().map(move |(p, pass)| (pass.key.as_str(), (s, p)))
        })
        .collect();
    let mut diagnostics = Vec::new();
    let mut found = Vec::with_capacity(catalogue.counts[1]);
    for head in &catalogue.shaders {
        for key in &head.passes {
            match built.get(key.as_str()) {
                Some(&place) => found.push(place),
                None => {
                    diagnostics.push(BuildLayerError::PassMissing { shader: head.shader.name.clone() }.into())
                }
            }
        }
    }
    // What the merge needs of each part is read from its text; the rest is written as it is.
    let read: Vec<Result<PassView, Diagnostic>> = found
        .par_iter()
        .map(|&(s, p)| PassView::read(&merge.shards[s].0, &merge.shards[s].1.passes[p]))
        .collect();
    let mut views = Vec::with_capacity(read.len());
    for view in read {
        match view {
            Ok(view) => views.push(view),
            Err(error) => diagnostics.push(error),
        }
    }
    if views.len() < found.len() {
        return ShardsRead { diagnostics, ..ShardsRead::default() };
    }
    // Every pack checked before anything is linked: a damaged shard writes nothing.
    diagnostics.extend(
        (found.par_iter().zip(&views))
            .filter_map(|(&(s, p), view)| {
                damaged(&merge.shards[s].0, view, &merge.shards[s].1.passes[p].packs)
            })
            .collect::<Vec<_>>(),
    );
    ShardsRead { found, views, diagnostics }
}

/// Joins the shards' parts, read by [`read_shards`], into the output folder (see the module's
/// comment).
pub(super) fn merge(
    store: &mut SourceStore,
    settings: &Settings,
    writes: Writes,
    earlier: &[Diagnostic],
    merge: &Merge,
    read: ShardsRead,
) -> BuildResult {
    let mut summary = BuildSummary::default();
    let Some(catalogue) = catalogue(merge) else {
        return BuildResult::failed(settings, summary, vec![BuildLayerError::CatalogueMissing.into()]);
    };
    let inputs = Inputs { given: catalogue.given, read: &catalogue.read, absent: &catalogue.absent };
    if !same_inputs(store, settings, &inputs, &merge.inputs) {
        return BuildResult::failed(settings, summary, vec![BuildLayerError::ProjectChanged.into()]);
    }
    [summary.shaders, summary.passes, summary.variants] = catalogue.counts;
    summary.unused = catalogue.unused.clone();
    let ShardsRead { found, views, mut diagnostics } = read;
    let found: Vec<(&Path, &ShardPass)> =
        found.iter().map(|&(s, p)| (merge.shards[s].0.as_path(), &merge.shards[s].1.passes[p])).collect();
    let parts: Vec<RawPass> =
        found.iter().zip(views).map(|((_, part), view)| RawPass { text: &part.manifest, view }).collect();
    let texts = merge.shards.iter().flat_map(|(_, record)| &record.materials);
    let materials = placed_materials(catalogue.materials, texts);
    if materials.is_none() {
        diagnostics.push(BuildLayerError::CatalogueMissing.into());
    }
    let (Some(materials), true) = (materials, diagnostics.is_empty()) else {
        return BuildResult::failed(settings, summary, diagnostics);
    };
    // Every pass's packs and cache entry, from its shard's folder into the output: linked while
    // the manifest and the materials are written, which replace nothing unless every link is made.
    let links: Vec<(PathBuf, PathBuf)> = (found.iter().zip(&parts))
        .flat_map(|((folder, part), pass)| {
            let packs = pass.view.packs.iter().map(|pack| (pack.under(folder), pack.under(&settings.output)));
            let entry = pass_index_path(&part.key);
            packs.chain([(folder.join(&entry), settings.output.join(&entry))])
        })
        .collect();
    let link = || {
        let copied = links.par_iter().map(|(from, to)| link_or_copy(from, to));
        copied.collect::<std::io::Result<Vec<u64>>>().map(|copied| copied.iter().sum())
    };
    summary.modules = found.iter().map(|(_, part)| part.modules).sum();
    summary.reused = summary.modules;
    let heads = catalogue.shaders.clone();
    if settings.pretty_manifest {
        // Indented, the parts cannot be copied as they are: parsed, and written as a build does.
        let parsed: Result<Vec<PassManifest>, BuildLayerError> = (parts.iter().zip(&found))
            .map(|(pass, (folder, _))| {
                serde_json::from_str(pass.text.get())
                    .map_err(|_| BuildLayerError::PartDamaged { folder: folder.to_path_buf() })
            })
            .collect();
        match parsed {
            Ok(parsed) => {
                let mut manifest = manifest(heads, parsed);
                let outputs = merged(store, earlier, &mut manifest, &materials, catalogue, &merge.inputs);
                finish(settings, writes, outputs, summary, diagnostics, link)
            }
            Err(error) => BuildResult::failed(settings, summary, vec![error.into()]),
        }
    } else {
        let mut manifest = manifest(heads, parts);
        let outputs = merged(store, earlier, &mut manifest, &materials, catalogue, &merge.inputs);
        finish(settings, writes, outputs, summary, diagnostics, link)
    }
}

/// What a merge writes beside the packs: a manifest of either form (its parts parsed, or as the
/// shards wrote them), whose shaders no pass streamed.
fn merged<'a, P>(
    store: &'a SourceStore,
    earlier: &'a [Diagnostic],
    manifest: &'a mut Manifest<P>,
    materials: &'a [&'a RawValue],
    catalogue: &'a CataloguePart,
    inputs: &'a str,
) -> Outputs<'a, P> {
    Outputs { store, earlier, manifest, materials, catalogue, inputs, streamed: None }
}

/// A shard's pass: its JSON text, written into the manifest as it is, and what the merge reads of
/// it (packs and modules to verify and link, layout and blocks to place the shader's properties).
struct RawPass<'a> {
    text: &'a RawValue,
    view: PassView,
}

/// The fields of a pass's part the merge reads; serde skips the rest (its variants) unparsed.
#[derive(Deserialize)]
struct PassView {
    packs: Vec<PackPath>,
    interfaces: Vec<StageInterface>,
    modules: Vec<ModuleManifest>,
    layout: Vec<BindGroup>,
    uniform_blocks: Vec<UniformBlock>,
}

impl PassView {
    /// A part that does not parse, or whose modules name interfaces or packs it does not list, is
    /// damaged.
    fn read(folder: &Path, part: &ShardPass) -> Result<PassView, Diagnostic> {
        let view: Option<PassView> = serde_json::from_str(part.manifest.get()).ok();
        view.filter(|view| modules_in_range(&view.modules, view.interfaces.len(), view.packs.len()))
            .ok_or_else(|| BuildLayerError::PartDamaged { folder: folder.to_path_buf() }.into())
    }
}

impl Serialize for RawPass<'_> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        self.text.serialize(serializer)
    }
}

impl PassFiles for RawPass<'_> {
    fn packs(&self) -> &[PackPath] {
        &self.view.packs
    }
    fn modules(&self) -> &[ModuleManifest] {
        &self.view.modules
    }
    fn layout(&self) -> &[BindGroup] {
        &self.view.layout
    }
    fn uniform_blocks(&self) -> &[UniformBlock] {
        &self.view.uniform_blocks
    }
}

/// The first module of a shard's pass whose pack is missing, not what its shard wrote (its hash
/// differs from the one the shard recorded, `hashes`), or too short to hold it. The modules'
/// places and hashes come from the sealed record: a pack is checked whole, not module by module.
fn damaged(folder: &Path, view: &PassView, hashes: &[String]) -> Option<Diagnostic> {
    // A pack is read no further than its modules' end (and a byte past it, which fails its hash).
    let mut ends = vec![0u64; view.packs.len()];
    for file in view.modules.iter().flat_map(ModuleManifest::files) {
        ends[file.pack] = ends[file.pack].max(file.offset + file.size);
    }
    let lengths: Vec<Option<u64>> = (view.packs.iter().enumerate())
        .map(|(i, pack)| {
            let (hash, length) = pack_hash(folder, pack, ends[i].saturating_add(1)).ok()?;
            (hashes.get(i) == Some(&hash)).then_some(length)
        })
        .collect();
    for module in &view.modules {
        for file in module.files() {
            // In range and addressable: the part was read through `modules_in_range`.
            if lengths[file.pack].is_none_or(|length| file.offset + file.size > length) {
                let interface = &view.interfaces[module.interface];
                let error = BuildLayerError::ModuleDamaged {
                    stage: interface.stage,
                    entry: interface.entry_point.clone(),
                    pack: view.packs[file.pack].under(folder),
                };
                return Some(error.into());
            }
        }
    }
    None
}
