//! What the passes of one build share while it runs: progress, and the modules and parsed
//! resources other passes made lately (bounded), so that a stage text several passes have is
//! parsed and compiled once.

use super::pass::Compiled;
use super::sources::Sources;
use super::{Part, Run};
use crate::compile::bind::Declared;
use crate::config::Settings;
use crate::store::Cache;
use std::sync::atomic::{AtomicUsize, Ordering};

/// What the passes of one build (or shard) share: the output's cache, progress, and what other
/// passes compiled and parsed lately.
pub(super) struct Session<'a> {
    /// The build's settings.
    pub settings: &'a Settings,
    /// Whether each pass's part of the manifest is made into its text on the pass's own thread:
    /// where it is written compact ([`super::emit::BuiltPass`]).
    pub pass_texts: bool,
    pub cache: Cache,
    /// Where fronts and modules are looked for before naga makes them.
    pub sources: Sources,
    pub progress: Progress<'a>,
    /// Only texts more than one pass has are kept for sharing.
    pub texts: TextCounts,
    pub compiled: Recent<Compiled>,
    pub parsed: Recent<Vec<Declared>>,
    /// Modules built from their whole text: naga refused the cut one (`BuildSummary::uncut`).
    pub uncut: AtomicUsize,
    /// `BuildSummary::preprocessed`, `parses` and `parsed_together`.
    pub preprocessed: AtomicUsize,
    pub parses: AtomicUsize,
    pub parsed_together: AtomicUsize,
}

/// Bytes of compiled modules, and of parsed resources, a build keeps for its other passes.
const SHARED_MODULE_BYTES: usize = 48 << 20;
const SHARED_FRONT_BYTES: usize = 8 << 20;
const RECENT_SHARDS: usize = 64;

impl<'a> Session<'a> {
    pub(super) fn new(
        settings: &'a Settings,
        run: &Run,
        report: &'a (dyn Fn(usize, usize) + Sync),
        total: usize,
    ) -> Session<'a> {
        // A shard's parts are kept compact whatever the manifest's form.
        let compact = matches!(run.part, Part::Shard(_)) || !settings.pretty_manifest;
        Session {
            settings,
            pass_texts: run.writes.output() && compact,
            cache: Cache::new(&settings.output, run.writes.output()),
            sources: Sources::new(settings),
            progress: Progress { report, done: AtomicUsize::new(0), total },
            texts: TextCounts::new(RECENT_SHARDS),
            compiled: Recent::new(SHARED_MODULE_BYTES, RECENT_SHARDS),
            parsed: Recent::new(SHARED_FRONT_BYTES, RECENT_SHARDS),
            uncut: AtomicUsize::new(0),
            preprocessed: AtomicUsize::new(0),
            parses: AtomicUsize::new(0),
            parsed_together: AtomicUsize::new(0),
        }
    }
}

/// Progress in variants: a pass's variants are counted off as its jobs finish.
pub(super) struct Progress<'a> {
    report: &'a (dyn Fn(usize, usize) + Sync),
    done: AtomicUsize,
    total: usize,
}

impl Progress<'_> {
    /// `served` of the pass's `requests` stage requests are done: its `variants` advance in
    /// proportion, adding up to exactly `variants` when all are.
    pub(super) fn advance(&self, variants: usize, requests: usize, before: usize, served: usize) {
        let share = |n: usize| (n * variants).checked_div(requests).unwrap_or(variants);
        let step = share(before + served) - share(before);
        if step > 0 {
            let done = self.done.fetch_add(step, Ordering::Relaxed) + step;
            (self.report)(done, self.total);
        }
    }
}

/// What a build's passes compiled or parsed lately, by key, for the other passes of the same
/// build: shaders copied under other names and stages several passes share are compiled once.
/// Bounded by `budget` bytes: past it the oldest entries go, so memory stays bounded and a miss
/// only costs the work again. Split in shards by key so that threads seldom wait on each other,
/// and what an eviction frees is freed after the shard's lock is let go.
pub(super) struct Recent<V> {
    shard_budget: usize,
    shards: Vec<std::sync::Mutex<RecentEntries<V>>>,
}

struct RecentEntries<V> {
    map: std::collections::HashMap<String, std::sync::Arc<V>>,
    order: std::collections::VecDeque<(String, usize)>,
    bytes: usize,
}

impl<V> Recent<V> {
    pub(super) fn new(budget: usize, shards: usize) -> Recent<V> {
        let shards = shards.max(1);
        let empty = || RecentEntries { map: Default::default(), order: Default::default(), bytes: 0 };
        Recent {
            shard_budget: budget / shards,
            shards: (0..shards).map(|_| std::sync::Mutex::new(empty())).collect(),
        }
    }

    fn shard(&self, key: &str) -> &std::sync::Mutex<RecentEntries<V>> {
        let spread = key.bytes().fold(0usize, |h, b| h.wrapping_mul(31).wrapping_add(usize::from(b)));
        &self.shards[spread % self.shards.len()]
    }

    pub(super) fn get(&self, key: &str) -> Option<std::sync::Arc<V>> {
        if self.shard_budget == 0 {
            return None;
        }
        self.shard(key).lock().ok()?.map.get(key).cloned()
    }

    /// Keeps `value` (about `size` bytes) under `key`, dropping the oldest entries past the budget.
    pub(super) fn insert(&self, key: &str, value: std::sync::Arc<V>, size: usize) {
        if size > self.shard_budget {
            return;
        }
        let mut evicted = Vec::new();
        {
            // A poisoned lock means another pass panicked; sharing is only an optimisation.
            let Ok(mut entries) = self.shard(key).lock() else { return };
            if entries.map.contains_key(key) {
                return;
            }
            entries.map.insert(key.to_string(), value);
            entries.order.push_back((key.to_string(), size));
            entries.bytes += size;
            while entries.bytes > self.shard_budget {
                let Some((old, old_size)) = entries.order.pop_front() else { break };
                evicted.extend(entries.map.remove(&old));
                entries.bytes -= old_size;
            }
        }
        drop(evicted);
    }
}

/// How many passes of a build have each stage text (by its hash), so that [`Recent`] keeps only
/// what another pass may want: a library whose texts are all distinct keeps nothing.
pub(super) struct TextCounts {
    shards: Vec<std::sync::Mutex<Counts>>,
}

/// One shard's counts; its keys are hashes already, so a fast hash spreads them.
type Counts = std::collections::HashMap<u64, u32, foldhash::fast::FixedState>;

impl TextCounts {
    /// `shards == 0` counts nothing: no text is ever shared.
    pub(super) fn new(shards: usize) -> TextCounts {
        TextCounts { shards: (0..shards).map(|_| Default::default()).collect() }
    }

    /// The first 16 hex digits of a hash: which shard, and the key in it.
    fn id(text_hash: &str) -> u64 {
        text_hash.get(..16).and_then(|h| u64::from_str_radix(h, 16).ok()).unwrap_or(0)
    }

    fn shard(&self, id: u64) -> Option<&std::sync::Mutex<Counts>> {
        (!self.shards.is_empty()).then(|| &self.shards[(id % self.shards.len() as u64) as usize])
    }

    /// A pass has this text (once per pass: a pass's texts are distinct).
    pub(super) fn add(&self, text_hash: &str) {
        let id = Self::id(text_hash);
        if let Some(mut counts) = self.shard(id).and_then(|s| s.lock().ok()) {
            *counts.entry(id).or_default() += 1;
        }
    }

    /// Whether more than one pass has this text (so far).
    pub(super) fn shared(&self, text_hash: &str) -> bool {
        let id = Self::id(text_hash);
        self.shard(id)
            .and_then(|s| s.lock().ok())
            .is_some_and(|counts| counts.get(&id).is_some_and(|&n| n > 1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recent_entries_stay_within_their_budget_oldest_out_first() {
        let recent = Recent::new(10, 1);
        recent.insert("a", std::sync::Arc::new(1), 4);
        recent.insert("b", std::sync::Arc::new(2), 4);
        assert_eq!(recent.get("a").as_deref(), Some(&1));
        recent.insert("c", std::sync::Arc::new(3), 4);
        assert_eq!(
            (recent.get("a"), recent.get("b").as_deref(), recent.get("c").as_deref()),
            (None, Some(&2), Some(&3))
        );
        recent.insert("huge", std::sync::Arc::new(4), 11);
        assert_eq!(recent.get("huge"), None);
    }

    #[test]
    fn a_text_is_shared_once_a_second_pass_has_it() {
        let counts = TextCounts::new(4);
        counts.add("00000000000000ff");
        assert!(!counts.shared("00000000000000ff"));
        counts.add("00000000000000ff");
        assert!(counts.shared("00000000000000ff") && !counts.shared("0000000000000001"));
        let off = TextCounts::new(0);
        off.add("00000000000000ff");
        off.add("00000000000000ff");
        assert!(!off.shared("00000000000000ff"));
    }
}
