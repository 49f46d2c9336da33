//! `kiln merge`: the output of one build from the shards' parts, with naga run nowhere, nothing
//! preprocessed and no catalogue: the first shard's record carries what the manifest takes from
//! the catalogue. The project must still be what the shards read (its files read again and
//! hashed). Each pass's part comes from the shard that built it; its packs and its cache entry
//! are linked into the output (copied where a link cannot be made), after every module in them
//! is checked against its hash, so the output is one build's, byte for byte.

use super::emit::{finish, write_failure};
use super::error::BuildLayerError;
use super::noop::{Inputs, same_inputs};
use super::shard::ShardPass;
use super::{BuildOptions, BuildResult, BuildSummary, Merge};
use crate::diagnostics::Diagnostic;
use crate::source::SourceStore;
use crate::store::{hash, link_or_copy, pass_index_path};
use rayon::prelude::*;
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
                None => diagnostics.push(
                    Diagnostic::error("K0412", format!("no shard holds a pass of `{}`", head.shader.name))
                        .note(
                            "its shard's output is damaged, or was built from another state of the project",
                        ),
                ),
            }
        }
    }
    // Every module checked before anything is linked: a damaged shard writes nothing.
    diagnostics
        .extend(found.par_iter().filter_map(|(folder, part)| damaged(folder, part)).collect::<Vec<_>>());
    if !diagnostics.is_empty() {
        return BuildResult::failed(options, summary, diagnostics);
    }
    if options.write {
        let linked: std::io::Result<Vec<u64>> = found
            .par_iter()
            .map(|(folder, part)| {
                let mut copied = 0;
                let cache_entry = pass_index_path(&part.key);
                for path in part.manifest.packs.iter().chain([&cache_entry]) {
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
    let Some(materials) = joined_materials(merge, catalogue.materials) else {
        return BuildResult::failed(options, summary, vec![BuildLayerError::CatalogueMissing.into()]);
    };
    summary.modules = found.iter().map(|(_, part)| part.modules).sum();
    summary.reused = summary.modules;
    let parts = found.into_iter().map(|(_, part)| part.manifest.clone()).collect();
    finish(store, options, catalogue.clone(), &materials, parts, summary, diagnostics)
}

/// `materials.json`'s compact text from the shards' materials, each in its place: `None` unless
/// every place from 0 to `count` is filled exactly once.
fn joined_materials(merge: &Merge, count: usize) -> Option<Box<RawValue>> {
    let mut placed: Vec<Option<&RawValue>> = vec![None; count];
    for (position, text) in merge.shards.iter().flat_map(|(_, record)| &record.materials) {
        let slot = placed.get_mut(*position)?;
        if slot.replace(text).is_some() {
            return None;
        }
    }
    let mut joined = String::from("[");
    for (i, text) in placed.into_iter().enumerate() {
        if i > 0 {
            joined.push(',');
        }
        joined.push_str(text?.get());
    }
    joined.push(']');
    RawValue::from_string(joined).ok()
}

/// The first module of a shard's pass whose bytes are missing or not what its hash says.
fn damaged(folder: &Path, part: &ShardPass) -> Option<Diagnostic> {
    let manifest = &part.manifest;
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
