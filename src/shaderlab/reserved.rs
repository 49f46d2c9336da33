//! Words a keyword may not be: a keyword becomes a macro of its pass's WGSL text (and a
//! `dynamic_branch` keyword an `override`), so one named `true` would turn every `true` of the
//! pass into `false`, and one named after a WGSL keyword, a reserved word or an identifier kiln
//! writes into the text would make naga refuse code the user never wrote.

/// WGSL's keywords (WGSL §15.3, "Keyword Summary"), sorted.
const WGSL_KEYWORDS: &[&str] = &[
    "alias",
    "break",
    "case",
    "const",
    "const_assert",
    "continue",
    "continuing",
    "default",
    "diagnostic",
    "discard",
    "else",
    "enable",
    "false",
    "fn",
    "for",
    "if",
    "let",
    "loop",
    "override",
    "requires",
    "return",
    "struct",
    "switch",
    "true",
    "var",
    "while",
];

/// WGSL's reserved words (WGSL §15.4, "Reserved Words"), sorted by their bytes.
const WGSL_RESERVED: &[&str] = &[
    "NULL",
    "Self",
    "abstract",
    "active",
    "alignas",
    "alignof",
    "as",
    "asm",
    "asm_fragment",
    "async",
    "attribute",
    "auto",
    "await",
    "become",
    "cast",
    "catch",
    "class",
    "co_await",
    "co_return",
    "co_yield",
    "coherent",
    "column_major",
    "common",
    "compile",
    "compile_fragment",
    "concept",
    "const_cast",
    "consteval",
    "constexpr",
    "constinit",
    "crate",
    "debugger",
    "decltype",
    "delete",
    "demote",
    "demote_to_helper",
    "do",
    "dynamic_cast",
    "enum",
    "explicit",
    "export",
    "extends",
    "extern",
    "external",
    "fallthrough",
    "filter",
    "final",
    "finally",
    "friend",
    "from",
    "fxgroup",
    "get",
    "goto",
    "groupshared",
    "highp",
    "impl",
    "implements",
    "import",
    "inline",
    "instanceof",
    "interface",
    "layout",
    "lowp",
    "macro",
    "macro_rules",
    "match",
    "mediump",
    "meta",
    "mod",
    "module",
    "move",
    "mut",
    "mutable",
    "namespace",
    "new",
    "nil",
    "noexcept",
    "noinline",
    "nointerpolation",
    "non_coherent",
    "noncoherent",
    "noperspective",
    "null",
    "nullptr",
    "of",
    "operator",
    "package",
    "packoffset",
    "partition",
    "pass",
    "patch",
    "pixelfragment",
    "precise",
    "precision",
    "premerge",
    "priv",
    "protected",
    "pub",
    "public",
    "readonly",
    "ref",
    "regardless",
    "register",
    "reinterpret_cast",
    "require",
    "resource",
    "restrict",
    "self",
    "set",
    "shared",
    "sizeof",
    "smooth",
    "snorm",
    "static",
    "static_assert",
    "static_cast",
    "std",
    "subroutine",
    "super",
    "target",
    "template",
    "this",
    "thread_local",
    "throw",
    "trait",
    "try",
    "type",
    "typedef",
    "typeid",
    "typename",
    "typeof",
    "union",
    "unless",
    "unorm",
    "unsafe",
    "unsized",
    "use",
    "using",
    "varying",
    "virtual",
    "volatile",
    "wgsl",
    "where",
    "with",
    "writeonly",
    "yield",
];

/// Every identifier kiln writes into a pass's text (an ubershader's immediate data and the
/// macros that read it, `crate::preprocess::pass`), which a test there keeps complete.
pub const KILN_IDENTIFIERS: &[&str] = &["KilnKeywords", "bits", "kiln_keywords", "x", "y"];

/// Why `word` cannot be a keyword's name, if it cannot.
pub fn reserved(word: &str) -> Option<&'static str> {
    if WGSL_KEYWORDS.binary_search(&word).is_ok() {
        Some("it is a WGSL keyword")
    } else if WGSL_RESERVED.binary_search(&word).is_ok() {
        Some("WGSL reserves it")
    } else if KILN_IDENTIFIERS.contains(&word) {
        Some("kiln's generated code names it")
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_word_lists_are_sorted_for_their_searches() {
        for list in [WGSL_KEYWORDS, WGSL_RESERVED] {
            assert!(list.windows(2).all(|w| w[0] < w[1]), "{:?}", list.windows(2).find(|w| w[0] >= w[1]));
        }
    }

    #[test]
    fn keywords_reserved_words_and_kilns_names_are_refused_and_unity_keywords_are_not() {
        for word in ["true", "false", "fn", "var", "NULL", "target", "kiln_keywords", "bits", "x"] {
            assert!(reserved(word).is_some(), "{word}");
        }
        for word in ["_CLIPPING", "_PREMULTIPLY_ALPHA", "DIRECTIONAL", "SHADOWS_SCREEN", "True", "X", "_"] {
            assert_eq!(reserved(word), None, "{word}");
        }
    }
}
