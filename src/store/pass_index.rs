//! A pass's cache entry: what a pass's stage texts declare and where its compiled modules are,
//! kept on disk with what its stages share written once.

use crate::compile::bind::Declared;
use crate::manifest::{FileRef, PackPath, PerBackend};
use crate::reflect::StageReflection;
use serde::{Deserialize, Serialize};
use std::borrow::Cow;
use std::collections::{BTreeMap, HashMap};

/// A pass's cache: the resources each stage text declares (by text hash), and each compiled stage
/// module (by its full key). Kept on disk in a form of its own, `StoredPassIndex`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PassIndex {
    /// The resources each stage text declares, by text hash, stage and entry point.
    pub front: BTreeMap<String, Vec<Declared>>,
    /// Each compiled stage module, by its content key.
    pub stage: BTreeMap<String, CachedStage>,
}

/// A [`PassIndex`] on disk: each distinct list of declarations, reflection and pack once, and
/// every entry naming its own by number. The stages of a pass mostly share all three; written
/// out per stage, they made the pass indexes 7.5 times the manifest's size.
///
/// Read into `BTreeMap`s; written from a view's pairs, already in key order ([`Sorted`]).
#[derive(Serialize, Deserialize)]
struct StoredPassIndex<
    'a,
    Front = BTreeMap<Cow<'a, str>, usize>,
    Stages = BTreeMap<Cow<'a, str>, StoredStage<'a>>,
> {
    declarations: Vec<Cow<'a, [Declared]>>,
    front: Front,
    reflections: Vec<Cow<'a, StageReflection>>,
    packs: Vec<Cow<'a, str>>,
    stage: Stages,
}

/// Pairs in key order, written as the map they are: building a `BTreeMap` of them again for the
/// length of a write was most of sealing a pass's entry.
struct Sorted<K, V>(Vec<(K, V)>);

impl<K: Serialize, V: Serialize> Serialize for Sorted<K, V> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_map(self.0.iter().map(|(key, value)| (key, value)))
    }
}

#[derive(Serialize, Deserialize)]
struct StoredStage<'a> {
    files: PerBackend<Option<StoredFile<'a>>>,
    reflection: usize,
}

/// A [`FileRef`] whose pack is a number.
#[derive(Serialize, Deserialize)]
struct StoredFile<'a> {
    pack: usize,
    offset: u64,
    size: u64,
    hash: Cow<'a, str>,
}

impl<'a> StoredFile<'a> {
    fn of(file: &'a Option<FileRef>, packs: &mut Numbered<'a, str>) -> Option<StoredFile<'a>> {
        file.as_ref().map(|f| StoredFile {
            pack: packs.number(f.path.as_str()),
            offset: f.offset,
            size: f.size,
            hash: Cow::from(f.hash.as_str()),
        })
    }
}

/// Distinct values, numbered in the order first met. Hashed with foldhash: a reflection is hashed
/// whole once a stage, and SipHash made that most of sealing a pass's entry.
struct Numbered<'a, T: ?Sized + ToOwned> {
    values: Vec<Cow<'a, T>>,
    numbers: HashMap<&'a T, usize, foldhash::fast::FixedState>,
}

impl<'a, T: ?Sized + ToOwned + Eq + std::hash::Hash> Numbered<'a, T> {
    fn new() -> Self {
        Numbered { values: Vec::new(), numbers: HashMap::default() }
    }

    fn number(&mut self, value: &'a T) -> usize {
        *self.numbers.entry(value).or_insert_with(|| {
            self.values.push(Cow::Borrowed(value));
            self.values.len() - 1
        })
    }
}

/// The value numbered `n`, owned; a number with no value is damage.
fn numbered<T: ?Sized + ToOwned, E: serde::de::Error>(values: &[Cow<T>], n: usize) -> Result<T::Owned, E> {
    let value = values.get(n).ok_or_else(|| E::custom(format!("nothing numbered {n}")))?;
    Ok(value.clone().into_owned())
}

impl Serialize for PassIndex {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        PassIndexView { front: &self.front, stage: self.stage.iter().map(|(k, s)| (k.as_str(), s)).collect() }
            .serialize(serializer)
    }
}

/// A [`PassIndex`] as a build makes it, borrowing the pass's records rather than copying them
/// (the cache entry is made beside the pass's part of the manifest, which reads them too);
/// written as the index is.
pub struct PassIndexView<'a> {
    /// The resources each stage text declares, by text hash, stage and entry point.
    pub front: &'a BTreeMap<String, Vec<Declared>>,
    /// Each compiled stage module, by its content key.
    pub stage: BTreeMap<&'a str, &'a CachedStage>,
}

impl PassIndexView<'_> {
    /// Whether it holds what `index` holds.
    pub fn matches(&self, index: &PassIndex) -> bool {
        *self.front == index.front
            && self.stage.len() == index.stage.len()
            && (self.stage.iter().zip(&index.stage)).all(|((k, s), (key, stage))| *k == key && *s == stage)
    }
}

impl Serialize for PassIndexView<'_> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let (mut declarations, mut reflections, mut packs) =
            (Numbered::new(), Numbered::new(), Numbered::new());
        let front = self.front.iter().map(|(key, d)| (key.as_str(), declarations.number(d.as_slice())));
        let front = Sorted(front.collect());
        let stage = self.stage.iter().map(|(&key, stage)| {
            let mut files = PerBackend::default();
            for (backend, file) in stage.files.iter() {
                files[backend] = StoredFile::of(file, &mut packs);
            }
            (key, StoredStage { files, reflection: reflections.number(&stage.reflection) })
        });
        let stage = Sorted(stage.collect());
        let (declarations, reflections, packs) = (declarations.values, reflections.values, packs.values);
        StoredPassIndex { declarations, front, reflections, packs, stage }.serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for PassIndex {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let stored: StoredPassIndex = StoredPassIndex::deserialize(deserializer)?;
        let front = stored
            .front
            .into_iter()
            .map(|(key, n)| Ok((key.into_owned(), numbered(&stored.declarations, n)?)));
        let file = |file: &Option<StoredFile>| {
            let Some(f) = file else { return Ok(None) };
            let path: String = numbered(&stored.packs, f.pack)?;
            // A record's path can name a pack of its folder and nothing else.
            let path = PackPath::parse(&path).map_err(serde::de::Error::custom)?;
            Ok(Some(FileRef { path, offset: f.offset, size: f.size, hash: f.hash.to_string() }))
        };
        let stage = stored.stage.iter().map(|(key, stage)| {
            let mut files = PerBackend::default();
            for (backend, stored) in stage.files.iter() {
                files[backend] = file(stored)?;
            }
            let reflection = numbered(&stored.reflections, stage.reflection)?;
            Ok((key.to_string(), CachedStage { files, reflection }))
        });
        let front = front.collect::<Result<_, D::Error>>()?;
        Ok(PassIndex { front, stage: stage.collect::<Result<_, D::Error>>()? })
    }
}

/// What the cache remembers of a compiled stage module.
#[derive(Debug, Clone, PartialEq)]
pub struct CachedStage {
    /// Its module for each back end written, in a pack.
    pub files: PerBackend<Option<FileRef>>,
    /// Its reflection.
    pub reflection: StageReflection,
}

impl CachedStage {
    /// Its modules, one per backend written.
    pub fn written(&self) -> impl Iterator<Item = &FileRef> {
        self.files.values().flatten()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::manifest::Backend;

    fn reflection(entry_point: &str) -> StageReflection {
        let json = serde_json::json!({
            "entry_point": entry_point, "inputs": [], "outputs": [], "bindings": [], "uniform_blocks": []
        });
        serde_json::from_value(json).expect("a reflection")
    }

    const PACK: &str = "0123456789abcdef0123456789abcdef";

    fn file(pack: PackPath, offset: u64) -> Option<FileRef> {
        Some(FileRef { path: pack, offset, size: 10, hash: format!("{offset:032}") })
    }

    fn declared(name: &str) -> Vec<Declared> {
        vec![Declared { name: name.to_string(), explicit: None, range: (3, 9) }]
    }

    fn stage(offset: u64, reflection: StageReflection) -> CachedStage {
        CachedStage {
            files: PerBackend::from_fn(|backend| file(PackPath::new(PACK, backend), offset)),
            reflection,
        }
    }

    /// Three stages, two of them sharing a reflection, all sharing their packs; three texts, two
    /// declaring the same.
    fn index() -> PassIndex {
        let front =
            [("t1", declared("UnityPerFrame")), ("t2", declared("UnityPerFrame")), ("t3", declared("_Own"))];
        let stages = [
            ("k1", stage(0, reflection("SharedEntry"))),
            ("k2", stage(10, reflection("SharedEntry"))),
            ("k3", stage(20, reflection("OwnEntry"))),
        ];
        PassIndex {
            front: front.into_iter().map(|(k, v)| (k.to_string(), v)).collect(),
            stage: stages.into_iter().map(|(k, v)| (k.to_string(), v)).collect(),
        }
    }

    #[test]
    fn a_pass_index_keeps_what_its_stages_share_once_and_reads_back_whole() {
        let index = index();
        let json = serde_json::to_string(&index).expect("serializes");
        let packs = [Backend::Wgsl, Backend::Spirv].map(|b| PackPath::new(PACK, b).to_string());
        for once in ["SharedEntry", "OwnEntry", "UnityPerFrame", &packs[0], &packs[1]] {
            assert_eq!(json.matches(once).count(), 1, "{once} in {json}");
        }
        assert_eq!(serde_json::from_str::<PassIndex>(&json).expect("reads back"), index);
    }

    #[test]
    fn a_pass_index_numbering_what_it_does_not_hold_is_refused() {
        let json = serde_json::to_string(&index()).expect("serializes");
        // One pack per back end: the first number past them is none.
        let past_packs = format!("\"pack\":{}", crate::manifest::Backend::COUNT);
        for (held, missing) in [
            ("\"reflection\":1", "\"reflection\":2"),
            ("\"pack\":1", past_packs.as_str()),
            ("\"t3\":1", "\"t3\":2"),
            // A path out of the folder, as a hostile entry would name it.
            ("\"modules/", "\"modules/../../../../../../../../etc/"),
        ] {
            assert!(json.contains(held), "{held} in {json}");
            let damaged = json.replace(held, missing);
            assert!(serde_json::from_str::<PassIndex>(&damaged).is_err(), "{missing} refused");
        }
    }

    #[test]
    fn a_module_placed_past_any_pack_reads_as_missing_not_a_panic() {
        let json = serde_json::to_string(&index())
            .expect("serializes")
            .replace("\"offset\":20", &format!("\"offset\":{}", u64::MAX));
        let index: PassIndex = serde_json::from_str(&json).expect("reads");
        let far = index.stage["k3"].files.values().flatten().next().expect("a file").clone();
        assert_eq!(far.end(), u64::MAX);
        assert_eq!(far.slice(&[0; 64]), None);
    }
}
