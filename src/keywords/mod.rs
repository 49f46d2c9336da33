//! Keyword sets and variants: a pass's keywords as bits, the variants its materials need, and
//! which keywords a requested variant has.

mod enumerate;

pub use enumerate::{KeywordBits, MAX_VARIANTS_PER_PASS, PassKeywords, Variant};

use crate::shaderlab::pragma::KeywordSet;

/// Why a requested keyword combination is not a variant of the pass.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
// Variant fields are named in each variant's message.
#[allow(missing_docs)]
pub enum VariantError {
    /// The keyword is declared by no set of the pass.
    #[error("`{keyword}` is not a keyword of this pass{}", suggestion.as_ref().map(|s| format!(" (did you mean `{s}`?)")).unwrap_or_default())]
    Undeclared { keyword: String, suggestion: Option<String> },
    /// Two keywords of one set: only one may be on.
    #[error("`{first}` and `{second}` belong to the same keyword set: a variant has at most one of them")]
    SameSet { first: String, second: String },
}

/// The keywords of the variant a user asked for: each requested keyword checked against the
/// sets that make variants ([`ProgramPragmas::variant_sets`](crate::shaderlab::pragma::ProgramPragmas::variant_sets)), and every set without an off option (`_`) that got none set to its first
/// keyword, which is the variant Unity builds by default. Sorted by set order.
pub fn select_variant(sets: &[KeywordSet], requested: &[String]) -> Result<Vec<String>, VariantError> {
    let mut chosen: Vec<Option<&str>> = vec![None; sets.len()];
    for keyword in requested {
        let Some(index) = sets.iter().position(|s| s.keywords().any(|k| k == keyword)) else {
            let suggestion = sets
                .iter()
                .flat_map(KeywordSet::keywords)
                .map(|k| (strsim::damerau_levenshtein(k, keyword), k))
                .filter(|&(distance, _)| distance <= 2)
                .min()
                .map(|(_, k)| k.to_string());
            return Err(VariantError::Undeclared { keyword: keyword.clone(), suggestion });
        };
        match chosen[index] {
            Some(first) if first != keyword => {
                return Err(VariantError::SameSet { first: first.to_string(), second: keyword.clone() });
            }
            _ => chosen[index] = Some(keyword),
        }
    }
    let keywords = sets.iter().zip(chosen).filter_map(|(set, chosen)| {
        let default = || if set.has_off_option() { None } else { set.keywords().next() };
        chosen.or_else(default).map(str::to_string)
    });
    Ok(keywords.collect())
}
