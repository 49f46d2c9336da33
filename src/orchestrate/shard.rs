//! Sharded builds: `kiln build --shard I/N` builds the passes that fall to shard I, exactly as a
//! whole build builds them (packs and cache in its output folder), and leaves their parts of the
//! manifest in `shard.json`; `kiln merge` joins the parts (`build::merge`). A shard decides what
//! it owns from the catalogue alone, before preprocessing anything: passes are dealt out by their
//! weight (distinct stage requests, [`super::plan::weights`]), heaviest first, each to the shard
//! with the least so far, so no shard reads, preprocesses or parses another shard's texts.

use super::emit::{BuiltPass, CataloguePart, material_texts, write_failure};
use super::plan::PassWork;
use super::{BuildResult, BuildSummary, Writes};
use crate::catalog::Catalog;
use crate::config::Settings;
use crate::diagnostics::{self, Diagnostic};
use crate::manifest::{PackPath, PassFiles};
use crate::store::{PassKey, hash, sealed, unsealed, write_atomically};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use serde_json::value::RawValue;
use std::path::{Path, PathBuf};

/// Which part of the work a build does: shard `index` (0-based) of `count`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// 0-based.
    pub index: u32,
    /// How many shards the build is split into.
    pub count: u32,
}

impl Shard {
    /// `I/N` with 1 ≤ I ≤ N, as the command line takes it.
    pub fn parse(text: &str) -> Result<Shard, ShardError> {
        let bad = || ShardError::NotAShard(text.to_string());
        let (i, n) = text.split_once('/').ok_or_else(bad)?;
        let (i, n): (u32, u32) = (i.trim().parse().map_err(|_| bad())?, n.trim().parse().map_err(|_| bad())?);
        if i == 0 || i > n {
            return Err(bad());
        }
        Ok(Shard { index: i - 1, count: n })
    }

    /// Which of the passes (by their weights, in catalogue order) are this shard's. Every shard
    /// computes the same deal: heaviest first (ties in catalogue order), each to the shard with
    /// the least weight so far (ties to the lowest index).
    pub fn owned(&self, weights: &[u64]) -> Vec<bool> {
        let mut order: Vec<usize> = (0..weights.len()).collect();
        order.sort_by_key(|&p| std::cmp::Reverse(weights[p]));
        let mut load = vec![0u64; self.count as usize];
        let mut owned = vec![false; weights.len()];
        for pass in order {
            let (least, _) = load.iter().enumerate().min_by_key(|(i, l)| (**l, *i)).unwrap_or((0, &0));
            load[least] += weights[pass].max(1);
            owned[pass] = least == self.index as usize;
        }
        owned
    }
}

impl Shard {
    /// The materials this shard writes: those of the shaders whose first pass it owns (the first
    /// shard, those of shaders with none), so that no shard serializes them all; each with its
    /// place in `materials.json`.
    pub(super) fn materials(
        &self,
        catalog: &Catalog,
        work: &[PassWork],
        owned: &[bool],
    ) -> Vec<(usize, Box<RawValue>)> {
        let mut first_pass_owned: Vec<Option<bool>> = vec![None; catalog.shaders.len()];
        for (work, owned) in work.iter().zip(owned) {
            first_pass_owned[work.shader_index].get_or_insert(*owned);
        }
        material_texts(catalog, |m| first_pass_owned[m.shader].unwrap_or(self.index == 0))
    }
}

/// `shard.json`, at the top of a shard's output folder.
pub const SHARD_FILE: &str = "shard.json";

/// What a shard leaves for `kiln merge`: what it checks before trusting the shard, and the
/// shard's passes' parts of the manifest.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ShardRecord {
    /// The kiln that built it.
    pub kiln_version: String,
    /// The hash of everything the build read and its options: shards of one merge share it.
    pub inputs: String,
    /// 1-based, as given.
    pub shard: u32,
    /// How many shards the build was split into.
    pub count: u32,
    /// The project folder as the shard build was given it.
    pub project: String,
    /// Stage modules this shard holds.
    pub modules: usize,
    /// The passes it built.
    pub passes: Vec<ShardPass>,
    /// What the manifest takes from the catalogue (the first shard's record has it).
    pub catalogue: Option<CataloguePart>,
    /// The materials of its shaders: each one's place in `materials.json`, and its JSON text.
    pub materials: Vec<(usize, Box<RawValue>)>,
}

/// One pass a shard built.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ShardPass {
    /// Identifies the pass across builds (its shader file and place); names its cache entry's
    /// file, so nothing but a hash parses.
    pub key: PassKey,
    /// Its distinct stage modules.
    pub modules: usize,
    /// The BLAKE3 ([`hash`]) of each of its packs, in its part's order: the merge checks each
    /// pack whole, which hashes about twice as fast as its modules one by one.
    pub packs: Vec<String>,
    /// Its part of the manifest, as JSON text (a merge writes it as it is); its packs are in the
    /// shard's folder.
    pub manifest: Box<RawValue>,
}

impl ShardPass {
    /// A built pass as its shard records it; its packs are read back to be hashed (a pass taken
    /// from the cache made none in this run), and only by a shard that writes.
    pub(super) fn new(
        key: PassKey,
        modules: usize,
        part: BuiltPass,
        settings: &Settings,
        writes: Writes,
    ) -> std::io::Result<ShardPass> {
        let ends = crate::manifest::pack_ends([&part]);
        let hashed = |pack: &PackPath| {
            let end = ends.get(pack).copied().unwrap_or(0);
            pack_hash(&settings.output, pack, end.saturating_add(1)).map(|(hash, _)| hash)
        };
        let packs = if writes.output() {
            part.packs().iter().map(hashed).collect::<std::io::Result<_>>()?
        } else {
            Vec::new()
        };
        Ok(ShardPass { key, modules, packs, manifest: part.into_text() })
    }
}

/// A pack's hash as its shard records it and the merge checks it, and its length.
pub(super) fn pack_hash(folder: &Path, pack: &PackPath, at_most: u64) -> std::io::Result<(String, u64)> {
    let bytes = pack.read_staged(folder, at_most)?;
    Ok((hash(&bytes), bytes.len() as u64))
}

impl ShardRecord {
    /// The record in a shard's output folder, refused when it is not the text the shard wrote:
    /// a merge writes the record's parts into the manifest as they are, so a record damaged on
    /// its way from the shard (a digit of a layout changed still parses) must be caught by its
    /// hash, not by its syntax.
    pub fn read(folder: &Path) -> Result<ShardRecord, ShardError> {
        let path = folder.join(SHARD_FILE);
        let bytes = std::fs::read(&path)
            .map_err(|source| ShardError::NotShardOutput { folder: folder.to_path_buf(), source })?;
        let Some(json) = unsealed(SHARD_FILE, &bytes) else { return Err(ShardError::NotAsWritten { path }) };
        serde_json::from_slice(json).map_err(|source| ShardError::Damaged { path, source })
    }
}

/// What a shard's record carries besides its identity.
pub(super) struct ShardParts {
    pub catalogue: Option<CataloguePart>,
    pub materials: Vec<(usize, Box<RawValue>)>,
    pub passes: Vec<ShardPass>,
}

/// What a shard leaves once its passes are built: `shard.json`, with their parts of the manifest
/// and the inputs key (`inputs`) the merge checks the shards against each other by.
pub(super) fn finish(
    settings: &Settings,
    writes: Writes,
    shard: Shard,
    inputs: String,
    parts: ShardParts,
    summary: BuildSummary,
    mut diagnostics: Vec<Diagnostic>,
) -> BuildResult {
    diagnostics::dedup(&mut diagnostics);
    if writes.output() && !diagnostics::has_errors(&diagnostics) {
        let record = ShardRecord {
            kiln_version: env!("CARGO_PKG_VERSION").to_string(),
            inputs,
            shard: shard.index + 1,
            count: shard.count,
            project: settings.root.to_string_lossy().replace('\\', "/"),
            modules: summary.compiled + summary.reused + summary.shared,
            passes: parts.passes,
            catalogue: parts.catalogue,
            materials: parts.materials,
        };
        let written = sealed(SHARD_FILE, &record)
            .and_then(|bytes| write_atomically(&settings.output.join(SHARD_FILE), &bytes));
        if let Err(error) = written {
            diagnostics.push(write_failure(&settings.output, error));
        }
    }
    BuildResult::failed(settings, summary, diagnostics)
}

/// Why shard outputs cannot be merged (each message names the folders and what differs).
#[derive(Debug, thiserror::Error)]
// Each variant's fields are named in its message.
#[allow(missing_docs)]
pub enum ShardError {
    #[error("`{0}` is not a shard: write I/N with 1 <= I <= N, like 2/4")]
    NotAShard(String),
    #[error("`{}` is not a shard's output: {source}", folder.display())]
    NotShardOutput { folder: PathBuf, source: std::io::Error },
    #[error("`{}` is damaged: {source}", path.display())]
    Damaged { path: PathBuf, source: serde_json::Error },
    #[error("`{}` is damaged: it is not the text the shard wrote (its BLAKE3 differs)", path.display())]
    NotAsWritten { path: PathBuf },
    #[error("no shard outputs to merge")]
    NoShards,
    #[error(
        "`{}` is shard {shard}/{count} of {what} than `{}`; shards of one merge come from one build",
        folder.display(),
        first.display()
    )]
    NotOneBuild { folder: PathBuf, shard: u32, count: u32, what: String, first: PathBuf },
    #[error("the shards were built by kiln {built_by}, this is kiln {}", env!("CARGO_PKG_VERSION"))]
    OtherKiln { built_by: String },
    #[error("shard {index}/{count} is missing")]
    Missing { index: usize, count: u32 },
    #[error("shard {index}/{count} is given twice: {holders}")]
    GivenTwice { index: usize, count: u32, holders: String },
}

/// Shard outputs to merge, checked against each other: one kiln version, one count, every shard
/// once. Returns the inputs hash they share (checked against the project by the merge).
pub fn check_shards(folders: &[PathBuf]) -> Result<(Vec<ShardRecord>, String), ShardError> {
    // Each record holds its shard's parts of the manifest: read at once.
    let records = folders.par_iter().map(|f| ShardRecord::read(f)).collect::<Result<Vec<_>, _>>()?;
    let Some(first) = records.first() else { return Err(ShardError::NoShards) };
    for (record, folder) in records.iter().zip(folders) {
        let differs = |what: String| ShardError::NotOneBuild {
            folder: folder.clone(),
            shard: record.shard,
            count: record.count,
            what,
            first: folders[0].clone(),
        };
        if record.kiln_version != first.kiln_version {
            return Err(differs(format!("kiln {} rather", record.kiln_version)));
        }
        if record.count != first.count {
            return Err(differs("a different number of shards".into()));
        }
        if record.inputs != first.inputs {
            return Err(differs("another project, another state of it, or other options".into()));
        }
    }
    if first.kiln_version != env!("CARGO_PKG_VERSION") {
        return Err(ShardError::OtherKiln { built_by: first.kiln_version.clone() });
    }
    let mut seen = vec![Vec::new(); first.count as usize];
    for (record, folder) in records.iter().zip(folders) {
        // A record naming shard 0, or one past the count, holds no shard of this merge.
        if let Some(slot) = (record.shard as usize).checked_sub(1).and_then(|i| seen.get_mut(i)) {
            slot.push(folder.display().to_string());
        }
    }
    for (i, holders) in seen.iter().enumerate() {
        match holders.len() {
            0 => return Err(ShardError::Missing { index: i + 1, count: first.count }),
            1 => {}
            _ => {
                let holders = holders.join(", ");
                return Err(ShardError::GivenTwice { index: i + 1, count: first.count, holders });
            }
        }
    }
    let inputs = first.inputs.clone();
    Ok((records, inputs))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_parse() {
        assert_eq!(Shard::parse("2/4").ok(), Some(Shard { index: 1, count: 4 }));
        for bad in ["0/4", "5/4", "4", "a/b", "1/0"] {
            let error = Shard::parse(bad).err().map(|e| e.to_string());
            assert_eq!(error, Some(format!("`{bad}` is not a shard: write I/N with 1 <= I <= N, like 2/4")));
        }
    }

    #[test]
    fn passes_are_dealt_out_once_each_and_balanced_by_weight() {
        // One heavy pass, many light ones of uneven weight.
        let weights: Vec<u64> = std::iter::once(400).chain((0..200).map(|i| 1 + (i * 7919) % 13)).collect();
        let total: u64 = weights.iter().sum();
        let shards: Vec<Shard> = (1..=4).map(|i| Shard::parse(&format!("{i}/4")).expect("shard")).collect();
        let owned: Vec<Vec<bool>> = shards.iter().map(|s| s.owned(&weights)).collect();
        for pass in 0..weights.len() {
            assert_eq!(owned.iter().filter(|o| o[pass]).count(), 1, "pass {pass} has one owner");
        }
        let loads: Vec<u64> =
            owned.iter().map(|o| weights.iter().zip(o).filter(|(_, o)| **o).map(|(w, _)| w).sum()).collect();
        let heaviest = *loads.iter().max().expect("loads");
        // No shard carries more than the heavy pass or a fair share plus one light pass.
        assert!(heaviest <= (total / 4 + 13).max(400), "{loads:?}");
    }
}
