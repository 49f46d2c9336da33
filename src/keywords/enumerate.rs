//! A pass's keywords as bits, and its variants: the product of its multi_compile sets times the
//! distinct projections of its materials onto its shader_feature sets. The full product of the
//! shader_feature sets is never built (except for shaders the project always includes whole).

use crate::preprocess::Stage;
use crate::shaderlab::pragma::{KeywordKind, KeywordSet, KeywordStage};
use crate::source::FileId;
use std::collections::HashMap;

/// A pass may have at most this many variants built: more is refused, with the count.
pub const MAX_VARIANTS_PER_PASS: u128 = 65_536;

/// Some of a pass's keywords: bit i stands for the pass's i-th keyword.
#[derive(Debug, Clone, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct KeywordBits(Vec<u64>);

impl KeywordBits {
    fn empty(len: usize) -> KeywordBits {
        KeywordBits(vec![0; len.div_ceil(64)])
    }

    fn insert(&mut self, bit: usize) {
        self.0[bit / 64] |= 1 << (bit % 64);
    }

    /// Whether bit `bit` is set.
    pub fn contains(&self, bit: usize) -> bool {
        self.0.get(bit / 64).is_some_and(|w| w & (1 << (bit % 64)) != 0)
    }

    fn and(&self, mask: &KeywordBits) -> KeywordBits {
        KeywordBits(self.0.iter().zip(&mask.0).map(|(a, b)| a & b).collect())
    }

    /// The variant key: hexadecimal, most significant word first, stable for a given pass.
    pub fn key(&self) -> String {
        let mut words = self.0.iter().rev().skip_while(|w| **w == 0).peekable();
        match words.next() {
            None => "0".to_string(),
            Some(first) => words.fold(format!("{first:x}"), |key, w| format!("{key}{w:016x}")),
        }
    }
}

/// A pass's variant-making keyword sets, with a bit per keyword.
#[derive(Debug, Clone)]
pub struct PassKeywords {
    sets: Vec<KeywordSet>,
    /// For each set, the bit of each option (`None` for the off choice).
    option_bits: Vec<Vec<Option<usize>>>,
    names: Vec<String>,
    /// Bits of the keywords each stage sees (a `_fragment` keyword is not in the vertex mask).
    vertex_mask: KeywordBits,
    fragment_mask: KeywordBits,
}

/// One variant of a pass.
#[derive(Debug, Clone, PartialEq)]
pub struct Variant {
    /// One bit per keyword of the pass.
    pub bits: KeywordBits,
    /// Option chosen in each set, in set order.
    pub choices: Vec<usize>,
    /// Indices (into the materials given) of the materials that need this variant.
    pub materials: Vec<usize>,
    /// The files besides materials that name it (usage logs, `kiln.toml`'s `[compute.NAME]`), in
    /// the order they named it first.
    pub listed_in: Vec<FileId>,
    /// The keywords each stage's text is preprocessed with: two variants with equal vertex bits
    /// share a vertex module.
    pub vertex: KeywordBits,
    /// The bits the fragment stage sees.
    pub fragment: KeywordBits,
}

impl PassKeywords {
    /// `sets` are the pass's variant sets (`ProgramPragmas::variant_sets`: no `dynamic_branch`,
    /// `skip_variants` applied). A keyword repeated across sets keeps its first bit.
    pub fn new(sets: Vec<KeywordSet>) -> PassKeywords {
        let mut names: Vec<String> = Vec::new();
        let mut bit_of: HashMap<String, usize> = HashMap::new();
        let option_bits: Vec<Vec<Option<usize>>> = sets
            .iter()
            .map(|set| {
                set.options
                    .iter()
                    .map(|o| {
                        let keyword = o.keyword.as_ref()?;
                        Some(*bit_of.entry(keyword.clone()).or_insert_with(|| {
                            names.push(keyword.clone());
                            names.len() - 1
                        }))
                    })
                    .collect()
            })
            .collect();
        let mut vertex_mask = KeywordBits::empty(names.len());
        let mut fragment_mask = KeywordBits::empty(names.len());
        for (set, bits) in sets.iter().zip(&option_bits) {
            for bit in bits.iter().flatten() {
                if matches!(set.stage, KeywordStage::All | KeywordStage::Vertex) {
                    vertex_mask.insert(*bit);
                }
                if matches!(set.stage, KeywordStage::All | KeywordStage::Fragment) {
                    fragment_mask.insert(*bit);
                }
            }
        }
        PassKeywords { sets, option_bits, names, vertex_mask, fragment_mask }
    }

    /// The pass's keyword sets, in declaration order.
    pub fn sets(&self) -> &[KeywordSet] {
        &self.sets
    }

    /// The keyword of each bit.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The keywords in `bits`, in bit order (which is declaration order).
    pub fn keywords<'a>(&'a self, bits: &'a KeywordBits) -> impl Iterator<Item = &'a str> + 'a {
        self.names.iter().enumerate().filter(|(i, _)| bits.contains(*i)).map(|(_, n)| n.as_str())
    }

    /// The keywords `stage` is preprocessed with for this variant.
    pub fn stage_bits<'a>(&self, variant: &'a Variant, stage: Stage) -> &'a KeywordBits {
        match stage {
            Stage::Vertex => &variant.vertex,
            Stage::Fragment => &variant.fragment,
            // A compute kernel sees every keyword (stage suffixes name render stages).
            Stage::Compute => &variant.bits,
        }
    }

    /// [`PassKeywords::possible`] as a listing or a diagnostic shows it: the number below 2^64,
    /// and past it (or past counting) `more than 2^64`, a count no build could reach, rather than
    /// 39 digits nobody reads.
    pub fn count_text(count: Option<u128>) -> String {
        match count {
            Some(n) if n < 1 << 64 => n.to_string(),
            _ => "more than 2^64".to_string(),
        }
    }

    /// The number of variants the pass could have: the product of its set sizes.
    pub fn possible(&self) -> Option<u128> {
        self.sets.iter().try_fold(1u128, |n, set| n.checked_mul(set.options.len() as u128))
    }

    /// The option `keywords` choose in a set: its keyword, else the off choice.
    fn chosen(&self, set: usize, keywords: &[&str]) -> Option<usize> {
        let options = &self.sets[set].options;
        options
            .iter()
            .position(|o| o.keyword.as_deref().is_some_and(|k| keywords.contains(&k)))
            .or_else(|| options.iter().position(|o| o.keyword.is_none()))
    }

    /// The option a material's keywords choose in a shader_feature set, or (an error the material
    /// reported) the first option.
    fn choose(&self, set: usize, keywords: &[&str]) -> usize {
        self.chosen(set, keywords).unwrap_or(0)
    }

    /// The options of a multi_compile set that are built: all of them, or, with the renderer's
    /// global keyword state known, the one it chooses (a set with neither one of those keywords
    /// nor `_` keeps all: the renderer may turn on any of them).
    fn built_options(&self, set: usize, global: Option<&[&str]>) -> Vec<usize> {
        match global.and_then(|global| self.chosen(set, global)) {
            Some(option) => vec![option],
            None => (0..self.sets[set].options.len()).collect(),
        }
    }

    /// The multi_compile sets the global keyword state narrows to one option, each as its
    /// keywords (`_` for none) and the one built: what `kiln list` explains its count with.
    pub fn fixed_by_global(&self, global: &[&str]) -> Vec<(Vec<String>, String)> {
        self.indices(KeywordKind::MultiCompile)
            .into_iter()
            .filter_map(|set| {
                let options = &self.sets[set].options;
                let chosen = self.chosen(set, global).filter(|_| options.len() > 1)?;
                let name = |o: &crate::shaderlab::pragma::KeywordOption| {
                    o.keyword.clone().unwrap_or_else(|| "_".into())
                };
                Some((options.iter().map(name).collect(), name(&options[chosen])))
            })
            .collect()
    }

    /// The variants the materials need (each given as its enabled keywords), or every variant
    /// when `everything` (a shader the project always includes). Sorted by their choices. More
    /// than [`MAX_VARIANTS_PER_PASS`] is refused with the count it would have been, before
    /// anything that size is built. `global` is the renderer's global keyword state where it is
    /// known: each multi_compile set is then built with only the option it chooses.
    pub fn enumerate(
        &self,
        materials: &[Vec<&str>],
        everything: bool,
        global: Option<&[&str]>,
    ) -> Result<Vec<Variant>, u128> {
        let features: Vec<usize> = self.indices(KeywordKind::ShaderFeature);
        let multi: Vec<usize> = self.indices(KeywordKind::MultiCompile);
        let feature_options: Vec<Vec<usize>> =
            features.iter().map(|&s| (0..self.sets[s].options.len()).collect()).collect();
        let multi_options: Vec<Vec<usize>> = multi.iter().map(|&s| self.built_options(s, global)).collect();
        let size =
            |options: &[Vec<usize>]| options.iter().try_fold(1u128, |n, o| n.checked_mul(o.len() as u128));
        if everything && size(&feature_options).is_none_or(|n| n > MAX_VARIANTS_PER_PASS) {
            return Err(self.possible().unwrap_or(u128::MAX));
        }
        // Distinct projections onto the shader_feature sets, each with the materials needing it.
        let mut projections: Vec<(Vec<usize>, Vec<usize>)> = Vec::new();
        let mut index: HashMap<Vec<usize>, usize> = HashMap::new();
        if everything {
            for choice in product(&feature_options) {
                index.insert(choice.clone(), projections.len());
                projections.push((choice, Vec::new()));
            }
        }
        for (m, keywords) in materials.iter().enumerate() {
            let choice: Vec<usize> = features.iter().map(|&s| self.choose(s, keywords)).collect();
            let slot = *index.entry(choice.clone()).or_insert_with(|| {
                projections.push((choice, Vec::new()));
                projections.len() - 1
            });
            projections[slot].1.push(m);
        }
        if projections.is_empty() {
            return Ok(Vec::new());
        }
        let total =
            size(&multi_options).and_then(|n| n.checked_mul(projections.len() as u128)).unwrap_or(u128::MAX);
        if total > MAX_VARIANTS_PER_PASS {
            return Err(total);
        }
        let combos = product(&multi_options);
        let mut variants = Vec::with_capacity(projections.len() * combos.len());
        for (projection, users) in &projections {
            for combo in &combos {
                let mut choices = vec![0; self.sets.len()];
                for (&set, &option) in features.iter().zip(projection).chain(multi.iter().zip(combo)) {
                    choices[set] = option;
                }
                variants.push(self.variant(choices, users.clone()));
            }
        }
        variants.sort_by(|a, b| a.choices.cmp(&b.choices));
        Ok(variants)
    }

    /// For checking a shader no material uses yet: the default variant (each set's off choice, or
    /// its first keyword) and, for every keyword, the default with just that keyword changed.
    pub fn defaults_and_each_keyword(&self) -> Vec<Variant> {
        let default: Vec<usize> = self
            .sets
            .iter()
            .map(|set| set.options.iter().position(|o| o.keyword.is_none()).unwrap_or(0))
            .collect();
        let mut all = vec![default.clone()];
        for (set, options) in self.sets.iter().enumerate() {
            for option in (0..options.options.len()).filter(|&o| o != default[set]) {
                let mut choices = default.clone();
                choices[set] = option;
                all.push(choices);
            }
        }
        all.sort();
        all.dedup();
        all.into_iter().map(|choices| self.variant(choices, Vec::new())).collect()
    }

    /// The variant with exactly these keywords (each set without one of them takes its off choice,
    /// or its first option).
    pub fn variant_of(&self, keywords: &[&str]) -> Variant {
        let choices = (0..self.sets.len()).map(|set| self.choose(set, keywords)).collect();
        self.variant(choices, Vec::new())
    }

    fn variant(&self, choices: Vec<usize>, materials: Vec<usize>) -> Variant {
        let mut bits = KeywordBits::empty(self.names.len());
        for (set, &option) in choices.iter().enumerate() {
            if let Some(bit) = self.option_bits[set][option] {
                bits.insert(bit);
            }
        }
        let vertex = bits.and(&self.vertex_mask);
        let fragment = bits.and(&self.fragment_mask);
        Variant { bits, choices, materials, listed_in: Vec::new(), vertex, fragment }
    }

    fn indices(&self, kind: KeywordKind) -> Vec<usize> {
        (0..self.sets.len()).filter(|&i| self.sets[i].kind == kind).collect()
    }
}

/// Every combination of one option from each list, in lexicographic order.
fn product(options: &[Vec<usize>]) -> Vec<Vec<usize>> {
    options.iter().fold(vec![Vec::new()], |partial, choices| {
        partial
            .iter()
            .flat_map(|prefix| {
                choices.iter().map(move |&o| {
                    let mut next = prefix.clone();
                    next.push(o);
                    next
                })
            })
            .collect()
    })
}

#[cfg(test)]
mod tests {
    use super::PassKeywords;

    #[test]
    fn a_count_past_any_build_is_said_so_not_printed_in_39_digits() {
        assert_eq!(PassKeywords::count_text(Some(1 << 20)), "1048576");
        assert_eq!(PassKeywords::count_text(Some((1 << 64) - 1)), u64::MAX.to_string());
        assert_eq!(PassKeywords::count_text(Some(1 << 127)), "more than 2^64");
        assert_eq!(PassKeywords::count_text(None), "more than 2^64", "2^200 overflows the count");
    }
}
