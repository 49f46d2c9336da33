//! Sharded builds: `kiln build --shard I/N` compiles the stage modules whose key falls to shard I
//! (a stable hash of what is compiled, so shards stay balanced whatever one shader weighs, and a
//! module stays in its shard when others come and go) and stores each as an object
//! ([`super::objects`]) in its output folder; `kiln merge` then builds the project with those
//! objects standing in for naga, which gives the bytes a single build gives.

use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// Which part of the work a build does: shard `index` (0-based) of `count`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    pub index: u32,
    pub count: u32,
}

impl Shard {
    /// `I/N` with 1 ≤ I ≤ N, as the command line takes it.
    pub fn parse(text: &str) -> Result<Shard, String> {
        let bad = || format!("`{text}` is not a shard: write I/N with 1 <= I <= N, like 2/4");
        let (i, n) = text.split_once('/').ok_or_else(bad)?;
        let (i, n): (u32, u32) = (i.trim().parse().map_err(|_| bad())?, n.trim().parse().map_err(|_| bad())?);
        if i == 0 || i > n {
            return Err(bad());
        }
        Ok(Shard { index: i - 1, count: n })
    }

    /// Whether the stage module with this key is this shard's to compile.
    pub fn owns(&self, key: &str) -> bool {
        let head = u64::from_str_radix(key.get(..16).unwrap_or(key), 16).unwrap_or(0);
        head % u64::from(self.count) == u64::from(self.index)
    }
}

/// `shard.json`, at the top of a shard's output folder.
pub const SHARD_FILE: &str = "shard.json";

/// What `kiln merge` checks before trusting a shard.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct ShardRecord {
    pub kiln_version: String,
    /// The hash of everything the build read and its options: shards of one merge share it.
    pub inputs: String,
    /// 1-based, as given.
    pub shard: u32,
    pub count: u32,
    /// The project folder as the shard build was given it.
    pub project: String,
    /// Stage modules this shard holds.
    pub modules: usize,
}

impl ShardRecord {
    pub fn read(folder: &Path) -> Result<ShardRecord, String> {
        let path = folder.join(SHARD_FILE);
        let bytes = std::fs::read(&path)
            .map_err(|e| format!("`{}` is not a shard's output: {e}", folder.display()))?;
        serde_json::from_slice(&bytes).map_err(|e| format!("`{}` is damaged: {e}", path.display()))
    }
}

/// Shard outputs to merge, checked against each other: one kiln version, one count, every shard
/// once. Returns the inputs hash they share (checked against the project by the build).
pub fn check_shards(folders: &[PathBuf]) -> Result<(Vec<ShardRecord>, String), String> {
    let records = folders.iter().map(|f| ShardRecord::read(f)).collect::<Result<Vec<_>, _>>()?;
    let Some(first) = records.first() else { return Err("no shard outputs to merge".into()) };
    for (record, folder) in records.iter().zip(folders) {
        let differs = |what: &str| {
            Err(format!(
                "`{}` is shard {}/{} of {what} than `{}`; shards of one merge come from one build",
                folder.display(),
                record.shard,
                record.count,
                folders[0].display()
            ))
        };
        if record.kiln_version != first.kiln_version {
            return differs(&format!("kiln {} rather", record.kiln_version));
        }
        if record.count != first.count {
            return differs("a different number of shards");
        }
        if record.inputs != first.inputs {
            return differs("another project, another state of it, or other options");
        }
    }
    if first.kiln_version != env!("CARGO_PKG_VERSION") {
        return Err(format!(
            "the shards were built by kiln {}, this is kiln {}",
            first.kiln_version,
            env!("CARGO_PKG_VERSION")
        ));
    }
    let mut seen = vec![Vec::new(); first.count as usize];
    for (record, folder) in records.iter().zip(folders) {
        if let Some(slot) = seen.get_mut(record.shard as usize - 1) {
            slot.push(folder.display().to_string());
        }
    }
    for (i, holders) in seen.iter().enumerate() {
        match holders.len() {
            0 => return Err(format!("shard {}/{} is missing", i + 1, first.count)),
            1 => {}
            _ => {
                return Err(format!(
                    "shard {}/{} is given twice: {}",
                    i + 1,
                    first.count,
                    holders.join(", ")
                ));
            }
        }
    }
    let inputs = first.inputs.clone();
    Ok((records, inputs))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compile::cache::hash;

    #[test]
    fn shards_parse_and_split_keys_evenly() {
        assert_eq!(Shard::parse("2/4"), Ok(Shard { index: 1, count: 4 }));
        for bad in ["0/4", "5/4", "4", "a/b", "1/0"] {
            assert!(Shard::parse(bad).is_err(), "{bad}");
        }
        let shards: Vec<Shard> = (1..=4).map(|i| Shard::parse(&format!("{i}/4")).expect("shard")).collect();
        let keys: Vec<String> = (0..4000).map(|i| hash(format!("module {i}").as_bytes())).collect();
        for key in &keys {
            assert_eq!(shards.iter().filter(|s| s.owns(key)).count(), 1, "each key has one owner");
        }
        for shard in &shards {
            let owned = keys.iter().filter(|k| shard.owns(k)).count();
            assert!((800..1200).contains(&owned), "balanced: {owned} of 4000");
        }
    }
}
