//! The generated module's variant lookup, as a renderer uses it: strict (a combination that was
//! not built is an error naming what is missing, never a near match), and each variant's stages
//! read from the packs the module embeds once.

use kiln_renderer::shaders::custom_rp_lit::PASS_0;

#[test]
fn a_built_variant_is_found_in_any_keyword_order() {
    let variant = PASS_0.variant(&["_CLIPPING"]).expect("the clip material's variant is built");
    assert_eq!(variant.keywords(), ["_CLIPPING"]);
    let (vertex, fragment) = (variant.vertex.expect("vertex"), variant.fragment.expect("fragment"));
    assert_eq!(vertex.entry_point, "LitPassVertex");
    assert!(
        fragment.wgsl.contains("fn LitPassFragment"),
        "{}",
        &fragment.wgsl[..80.min(fragment.wgsl.len())]
    );
    assert_eq!(fragment.spirv[0], 0x0723_0203, "SPIR-V starts with its magic number");
    assert_eq!(vertex.inputs, [(0, "float32x3"), (1, "float32x3"), (2, "float32x2")]);
    assert_eq!(fragment.outputs, [(0, "float32x4")]);

    let plain = PASS_0.variant(&[]).expect("the opaque materials' variant");
    assert_eq!(plain.vertex.expect("vertex").module, vertex.module, "`_CLIPPING` changes no vertex code");
    assert_ne!(plain.fragment.expect("fragment").module, fragment.module);
    let all: Vec<Vec<&str>> = PASS_0.variants().map(|v| v.keywords()).collect();
    assert_eq!(all.len(), 3);
    for keywords in &all {
        let mut reversed = keywords.clone();
        reversed.reverse();
        assert_eq!(&PASS_0.variant(&reversed).expect("built").keywords(), keywords);
    }
}

#[test]
fn a_combination_not_built_names_what_is_missing() {
    let error = PASS_0.variant(&["_CLIPPING", "_PREMULTIPLY_ALPHA"]).expect_err("no material uses both");
    assert!(error.undeclared.is_empty());
    assert_eq!(error.requested, ["_CLIPPING", "_PREMULTIPLY_ALPHA"]);
    assert_eq!(error.built.len(), 3);
    let shown = error.to_string();
    assert!(shown.contains("has no variant with keywords [_CLIPPING _PREMULTIPLY_ALPHA]"), "{shown}");
    assert!(shown.contains("built: []"), "{shown}");

    let error = PASS_0.variant(&["_CLIPING"]).expect_err("a misspelt keyword");
    assert_eq!(error.undeclared, ["_CLIPING"]);
    assert!(error.to_string().contains("the pass declares no keyword _CLIPING"), "{error}");
}

/// A pass's own keyword type finds its variants (another pass's keyword does not compile:
/// `tests/it/dynamic.rs`), and the run time takes a variant the generated module found by its key.
#[test]
fn typed_keywords_find_the_variant_the_run_time_takes_by_its_key() {
    use kiln_renderer::shaders::{self, custom_rp_lit::Pass0Keyword};
    let typed = shaders::variant(&[Pass0Keyword::_CLIPPING]).expect("built");
    let named = PASS_0.variant(&["_CLIPPING"]).expect("built");
    assert_eq!((typed.index, typed.key()), (named.index, named.key()));

    let library = kiln_renderer::library().expect("embedded build");
    let pass = library.pass_id(typed.pass.shader, typed.pass.index).expect("the pass");
    for variant in PASS_0.variants() {
        let id = library.variant_id_by_key(pass, variant.key()).expect("the same variant");
        assert_eq!(id, library.variant_id(pass, &variant.keywords()).expect("by its names"));
        assert_eq!(library.variant_of(id).expect("built").keywords, variant.keywords());
    }
    let unbuilt = PASS_0.keywords.iter().position(|k| *k == "_PREMULTIPLY_ALPHA").expect("declared");
    let clipping = PASS_0.keywords.iter().position(|k| *k == "_CLIPPING").expect("declared");
    let key = [(1u64 << unbuilt) | (1 << clipping)];
    let error = library.variant_id_by_key(pass, &key).expect_err("no material uses both");
    assert!(error.to_string().contains("_CLIPPING, _PREMULTIPLY_ALPHA"), "{error}");
}
