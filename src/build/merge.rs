//! `kiln merge`: the output of one build from the shards' parts, with naga run nowhere, nothing
//! preprocessed and no catalogue: the first shard's record carries what the manifest takes from
//! the catalogue. The project must still be what the shards read (its files read again and
//! hashed). Each pass's part comes from the shard that built it; its packs and its cache entry
//! are linked into the output (copied where a link cannot be made), after every module in them
//! is checked against its hash, so the output is one build's, byte for byte.

use super::emit::{finish, manifest, placed_materials, write_failure};
use super::error::BuildLayerError;
use super::noop::{Inputs, same_inputs};
use super::shard::ShardPass;
use super::{BuildOptions, BuildResult, BuildSummary, Merge};
use crate::diagnostics::Diagnostic;
use crate::manifest::{BindGroup, ModuleManifest, PassFiles, PassManifest, StageInterface, UniformBlock};
use crate::source::SourceStore;
use crate::store::{hash, link_or_copy, pass_index_path};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use serde_json::value::RawValue;
use std::collections::HashMap;
use std::path::Path;

/// Joins the shards' parts into the output folder (see the module's comment).
pub(super) fn merge(store: &mut SourceStore, options: &BuildOptions, merge: &Merge) -> BuildResult {
    let mut summary = BuildSummary::default();
    let Some(catalogue) = merge.shards.iter().find_map(|(_, record)| record.catalogue.as_ref()) else {
        return BuildResult::failed(options, summary, vec![BuildLayerError::CatalogueMissing.into()]);
    };
    let inputs = Inputs { given: catalogue.given, read: &catalogue.read, absent: &catalogue.absent };
    if !same_inputs(store, options, &inputs, &merge.inputs) {
        return BuildResult::failed(options, summary, vec![BuildLayerError::ProjectChanged.into()]);
    }
    [summary.shaders, summary.passes, summary.variants] = catalogue.counts;
    summary.unused = catalogue.unused.clone();
    let built: HashMap<&str, (&Path, &ShardPass)> = merge
        .shards
        .iter()
        .flat_map(|(folder, record)| {
            record.passes.iter().map(move |pass| (pass.key.as_str(), (folder.as_path(), pass)))
        })
        .collect();
    let mut diagnostics = Vec::new();
    let mut found = Vec::with_capacity(catalogue.counts[1]);
    for head in &catalogue.shaders {
        for key in &head.passes {
            match built.get(key.as_str()) {
                Some(&(folder, part)) => found.push((folder, part)),
                None => {
                    diagnostics.push(BuildLayerError::PassMissing { shader: head.shader.name.clone() }.into())
                }
            }
        }
    }
    // What the merge needs of each part is read from its text; the rest is written as it is.
    let passes: Vec<Result<RawPass, Diagnostic>> =
        found.par_iter().map(|(folder, part)| RawPass::read(folder, part)).collect();
    let mut parts = Vec::with_capacity(passes.len());
    for pass in passes {
        match pass {
            Ok(pass) => parts.push(pass),
            Err(error) => diagnostics.push(error),
        }
    }
    // Every module checked before anything is linked: a damaged shard writes nothing.
    diagnostics.extend(
        found
            .par_iter()
            .zip(&parts)
            .filter_map(|((folder, _), pass)| damaged(folder, &pass.view))
            .collect::<Vec<_>>(),
    );
    let texts = merge.shards.iter().flat_map(|(_, record)| &record.materials);
    let materials = placed_materials(catalogue.materials, texts);
    if materials.is_none() {
        diagnostics.push(BuildLayerError::CatalogueMissing.into());
    }
    let (Some(materials), true) = (materials, diagnostics.is_empty()) else {
        return BuildResult::failed(options, summary, diagnostics);
    };
    if options.write {
        let linked: std::io::Result<Vec<u64>> = found
            .par_iter()
            .zip(&parts)
            .map(|((folder, part), pass)| {
                let mut copied = 0;
                let cache_entry = pass_index_path(&part.key);
                for path in pass.view.packs.iter().chain([&cache_entry]) {
                    copied += link_or_copy(&folder.join(path), &options.output.join(path))?;
                }
                Ok(copied)
            })
            .collect();
        match linked {
            Ok(copied) => summary.bytes_written += copied.iter().sum::<u64>(),
            Err(error) => {
                return BuildResult::failed(options, summary, vec![write_failure(&options.output, error)]);
            }
        }
    }
    summary.modules = found.iter().map(|(_, part)| part.modules).sum();
    summary.reused = summary.modules;
    let mut catalogue = catalogue.clone();
    let heads = std::mem::take(&mut catalogue.shaders);
    if options.pretty_manifest {
        // Indented, the parts cannot be copied as they are: parsed, and written as a build does.
        let parsed: Result<Vec<PassManifest>, BuildLayerError> = (parts.iter().zip(&found))
            .map(|(pass, (folder, _))| {
                serde_json::from_str(pass.text.get())
                    .map_err(|_| BuildLayerError::PartDamaged { folder: folder.to_path_buf() })
            })
            .collect();
        match parsed {
            Ok(parsed) => {
                let manifest = manifest(heads, parsed);
                finish(options, &merge.inputs, &catalogue, &materials, &manifest, summary, diagnostics)
            }
            Err(error) => BuildResult::failed(options, summary, vec![error.into()]),
        }
    } else {
        let manifest = manifest(heads, parts);
        finish(options, &merge.inputs, &catalogue, &materials, &manifest, summary, diagnostics)
    }
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
    packs: Vec<String>,
    interfaces: Vec<StageInterface>,
    modules: Vec<ModuleManifest>,
    layout: Vec<BindGroup>,
    uniform_blocks: Vec<UniformBlock>,
}

impl<'a> RawPass<'a> {
    fn read(folder: &Path, part: &'a ShardPass) -> Result<RawPass<'a>, Diagnostic> {
        let view: PassView = serde_json::from_str(part.manifest.get())
            .map_err(|_| Diagnostic::from(BuildLayerError::PartDamaged { folder: folder.to_path_buf() }))?;
        Ok(RawPass { text: &part.manifest, view })
    }
}

impl Serialize for RawPass<'_> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        self.text.serialize(serializer)
    }
}

impl PassFiles for RawPass<'_> {
    fn packs(&self) -> &[String] {
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

/// The first module of a shard's pass whose bytes are missing or not what its hash says.
fn damaged(folder: &Path, manifest: &PassView) -> Option<Diagnostic> {
    let packs: Vec<Option<Vec<u8>>> =
        manifest.packs.iter().map(|p| std::fs::read(folder.join(p)).ok()).collect();
    for module in &manifest.modules {
        for file in [&module.wgsl, &module.spirv].into_iter().flatten() {
            let bytes = packs
                .get(file.pack)
                .and_then(|pack| pack.as_ref())
                .and_then(|pack| pack.get(file.offset as usize..(file.offset + file.size) as usize));
            if bytes.is_none_or(|bytes| hash(bytes) != file.hash) {
                let interface = &manifest.interfaces[module.interface];
                let error = BuildLayerError::ModuleDamaged {
                    stage: interface.stage.clone(),
                    entry: interface.entry_point.clone(),
                    pack: folder.join(&manifest.packs[file.pack]),
                };
                return Some(error.into());
            }
        }
    }
    None
}
