//! Variant enumeration at scale: a pass with 40 shader_feature sets and 1,000 materials (and a
//! multi_compile set), enumerated in one run: `cargo bench --bench enumerate`.

use kiln::keywords::PassKeywords;
use kiln::shaderlab::pragma::{KeywordKind, KeywordOption, KeywordScope, KeywordSet, KeywordStage};
use kiln::source::{SourceStore, Span};
use std::hint::black_box;
use std::time::Instant;

fn set(kind: KeywordKind, names: &[String], span: Span) -> KeywordSet {
    KeywordSet {
        kind,
        scope: KeywordScope::Global,
        stage: KeywordStage::All,
        options: names
            .iter()
            .map(|n| KeywordOption { keyword: (n != "_").then(|| n.clone()), span })
            .collect(),
        shorthand: None,
        span,
    }
}

fn main() {
    let span = Span::new(SourceStore::new().add("bench", ""), 0..0);
    let mut sets: Vec<KeywordSet> = (0..40)
        .map(|i| set(KeywordKind::ShaderFeature, &["_".into(), format!("_FEATURE_{i}")], span))
        .collect();
    sets.push(set(KeywordKind::MultiCompile, &["_".into(), "SHADOWS".into(), "SHADOWS_SOFT".into()], span));
    // Deterministic pseudo-random materials, each enabling about a quarter of the features.
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let materials: Vec<Vec<String>> = (0..1000)
        .map(|_| {
            (0..40)
                .filter(|_| {
                    state ^= state << 13;
                    state ^= state >> 7;
                    state ^= state << 17;
                    state.is_multiple_of(4)
                })
                .map(|i| format!("_FEATURE_{i}"))
                .collect()
        })
        .collect();
    let refs: Vec<Vec<&str>> = materials.iter().map(|m| m.iter().map(String::as_str).collect()).collect();
    let pass = PassKeywords::new(sets);
    let mut times = Vec::new();
    let mut count = 0;
    for _ in 0..21 {
        let start = Instant::now();
        count = black_box(pass.enumerate(&refs, false, None).expect("within the limit")).len();
        times.push(start.elapsed());
    }
    times.sort();
    println!(
        "40 shader_feature sets + 1 multi_compile set (3), 1,000 materials: {count} variants of {} possible, median {:.2?}",
        pass.possible().map_or("more than 2^128".to_string(), |n| n.to_string()),
        times[10]
    );
}
