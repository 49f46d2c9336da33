//! Every name from a user's files as it enters the generated Rust, through one function per
//! context: [`doc_text`] for `///` comments, [`string_literal`] for `"..."`, and [`Scope::claim`]
//! for identifiers, which mangles a name into a valid one and refuses two names that mangle alike.
//! Nothing else in `codegen/` writes a user's text into the module.

use crate::diagnostics::Diagnostic;

/// A name as text in a `///` doc comment: characters that could end the comment or that rustc
/// refuses in one (line breaks, other control characters, the bidirectional overrides its
/// `text_direction_codepoint_in_comment` lint denies) are written as `\u{..}` escapes.
pub(super) fn doc_text(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if unsafe_in_text(c) {
            out.extend(c.escape_unicode());
        } else {
            out.push(c);
        }
    }
    out
}

/// A Rust string literal whose value is exactly `text`. `str`'s `Debug` escapes quotes,
/// backslashes, control and format characters (the bidirectional overrides among them) and
/// everything else that is not printable, and writes the rest as is.
pub(super) fn string_literal(text: &str) -> String {
    format!("{text:?}")
}

/// Characters that must not appear raw in generated Rust text outside a string literal.
fn unsafe_in_text(c: char) -> bool {
    c.is_control()
        || matches!(c, '\u{2028}' | '\u{2029}' | '\u{200E}' | '\u{200F}' | '\u{061C}')
        || ('\u{202A}'..='\u{202E}').contains(&c)
        || ('\u{2066}'..='\u{2069}').contains(&c)
}

/// How a kind of generated item spells its names.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Case {
    /// Modules: `Custom RP/Lit` is `custom_rp_lit`.
    Snake,
    /// Constants: `LitClip` is `LIT_CLIP`.
    UpperSnake,
    /// Types, fields and keyword constants: the name as it is, where Rust allows it.
    AsIs,
}

/// `name` as an identifier in `case`: ASCII letters, digits and `_` are kept (case changed),
/// other ASCII becomes `_`, and every other character its code point in hex (`Å` is `uc5`), so that
/// names without an ASCII letter still have a stable spelling and only ASCII reaches rustc (which
/// would merge names that differ only in Unicode normalisation). A leading digit gets a `_`
/// before it; a Rust keyword is written raw (`r#in`) or, where Rust allows no raw form, with a `_`
/// after it (`self_`).
pub(super) fn mangle(name: &str, case: Case) -> String {
    let mut out = String::with_capacity(name.len() + 4);
    let mut previous: Option<char> = None;
    for c in name.chars() {
        if c.is_ascii_alphanumeric() || c == '_' {
            let word_starts = case == Case::UpperSnake
                && c.is_ascii_uppercase()
                && previous.is_some_and(|p| p.is_ascii_lowercase() || p.is_ascii_digit());
            if word_starts {
                out.push('_');
            }
            out.push(match case {
                Case::Snake => c.to_ascii_lowercase(),
                Case::UpperSnake => c.to_ascii_uppercase(),
                Case::AsIs => c,
            });
        } else if c.is_ascii() {
            out.push('_');
        } else {
            let spelled = format!("_u{:x}_", c as u32);
            out.push_str(&if case == Case::UpperSnake { spelled.to_ascii_uppercase() } else { spelled });
        }
        previous = Some(c);
    }
    if case == Case::Snake {
        // `Custom RP/Lit`, not `custom__rp_lit_`.
        let mut collapsed = String::with_capacity(out.len());
        for c in out.chars() {
            if !(c == '_' && collapsed.ends_with('_')) {
                collapsed.push(c);
            }
        }
        out = collapsed.trim_matches('_').to_string();
    } else if case == Case::UpperSnake && !name.starts_with('_') {
        // `2 Sided` is `_2_SIDED`; a spelled first character's `_` is not needed twice.
        while out.starts_with("__") {
            out.remove(0);
        }
    }
    if out.is_empty() || out == "_" {
        out.push_str("_unnamed");
    }
    if out.starts_with(|c: char| c.is_ascii_digit()) {
        out.insert(0, '_');
    }
    keyword_safe(out)
}

/// `identifier` as Rust takes it: a keyword raw (`r#in`) or, where Rust allows no raw form,
/// with a `_` after it (`self_`).
pub(super) fn keyword_safe(identifier: String) -> String {
    if !RUST_KEYWORDS.contains(&identifier.as_str()) {
        identifier
    } else if NOT_RAW.contains(&identifier.as_str()) {
        format!("{identifier}_")
    } else {
        format!("r#{identifier}")
    }
}

/// An identifier without its raw prefix, to build longer names from (`r#type` gives `type`).
pub(super) fn stem(identifier: &str) -> &str {
    identifier.strip_prefix("r#").unwrap_or(identifier)
}

/// Rust's strict, reserved and edition keywords (2015 to 2024): none may be an identifier as it is.
const RUST_KEYWORDS: &[&str] = &[
    "Self", "abstract", "as", "async", "await", "become", "box", "break", "const", "continue", "crate", "do",
    "dyn", "else", "enum", "extern", "false", "final", "fn", "for", "gen", "if", "impl", "in", "let", "loop",
    "macro", "match", "mod", "move", "mut", "override", "priv", "pub", "ref", "return", "self", "static",
    "struct", "super", "trait", "true", "try", "type", "typeof", "unsafe", "unsized", "use", "virtual",
    "where", "while", "yield",
];

/// Keywords that have no raw form (`r#self` is not an identifier).
const NOT_RAW: &[&str] = &["Self", "crate", "self", "super"];

/// Names the generated code relies on and a generated item must never shadow: primitive types,
/// the prelude items it uses, the crates it names, and the fixed items of the module's top.
pub(super) const PRELUDE_NAMES: &[&str] = &[
    "bool",
    "char",
    "f16",
    "f32",
    "f64",
    "i8",
    "i16",
    "i32",
    "i64",
    "i128",
    "isize",
    "str",
    "u8",
    "u16",
    "u32",
    "u64",
    "u128",
    "usize",
    "core",
    "std",
    "alloc",
    "bytemuck",
    "Option",
    "Some",
    "None",
    "Result",
    "Ok",
    "Err",
    "Vec",
    "String",
    "Box",
    "Default",
    "Clone",
    "Copy",
    "Debug",
    "PartialEq",
    "Eq",
    "Send",
    "Sync",
    "Sized",
    "Drop",
    "Fn",
    "FnMut",
    "FnOnce",
    "Iterator",
    "IntoIterator",
    "ToString",
    "Into",
    "From",
    "AsRef",
    "Aligned",
    "ModuleRow",
    "NONE",
    "FRAME_GROUP",
    "MATERIAL_GROUP",
    "OBJECT_GROUP",
    "Interface",
    "Stage",
    "Variant",
    "BindingKind",
    "BindingEntry",
    "Pass",
    "MissingVariant",
    "PassKeyword",
    "variant",
    "WGSL_PACKS",
    "SPIRV_PACKS",
    "MANIFEST_JSON",
    "MATERIALS_JSON",
    "PACKS",
    "NAME",
];

/// The owner of the identifiers kiln's own code uses, as a [`Scope`] records it.
const KILN: &str = "kiln's generated code";

/// One namespace of the generated module (its top, a shader's module, a struct's fields): the
/// identifiers given out, each with the name and place it was made from.
pub(super) struct Scope {
    /// What the scope is, for messages: "the generated module", "module `custom_rp_lit`".
    what: String,
    taken: std::collections::HashMap<String, (String, String)>,
    /// Two names that became one identifier.
    pub(super) clashes: Vec<NameClash>,
}

/// Two names from a project that the generated Rust would spell alike.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NameClash {
    /// The namespace both would land in.
    pub scope: String,
    /// The identifier both would be.
    pub identifier: String,
    /// The first name and where it comes from.
    pub first: (String, String),
    /// The second name and where it comes from.
    pub second: (String, String),
}

impl Scope {
    /// An empty namespace; `reserved` names are given out already (to the generated code).
    pub(super) fn new(what: impl Into<String>, reserved: &[&str]) -> Scope {
        let taken =
            reserved.iter().map(|name| (name.to_string(), (name.to_string(), KILN.to_string()))).collect();
        Scope { what: what.into(), taken, clashes: Vec::new() }
    }

    /// The identifier for `name` (from `place`) in this scope: mangled, with a `_` after it when
    /// kiln's own code holds the spelling, and recorded. The same name claimed twice gets the
    /// same identifier; another name that mangles alike is a [`NameClash`].
    pub(super) fn claim(&mut self, name: &str, case: Case, place: &str) -> String {
        self.claim_identifier(name, mangle(name, case), place)
    }

    /// [`Scope::claim`] for an identifier already made from `name` (`DOUBLE_WORKGROUP_SIZE`).
    pub(super) fn claim_identifier(&mut self, name: &str, mut identifier: String, place: &str) -> String {
        while self.taken.get(&identifier).is_some_and(|(_, owner)| owner == KILN) {
            identifier.push('_');
        }
        match self.taken.get(&identifier) {
            Some((earlier, _)) if earlier == name => {}
            Some((earlier, earlier_place)) => self.clashes.push(NameClash {
                scope: self.what.clone(),
                identifier: identifier.clone(),
                first: (earlier.clone(), earlier_place.clone()),
                second: (name.to_string(), place.to_string()),
            }),
            None => {
                self.taken.insert(identifier.clone(), (name.to_string(), place.to_string()));
            }
        }
        identifier
    }

    /// An identifier kiln makes up (padding, a second layout of one struct): `stem` followed by
    /// the first number from `from` that is free in the scope (`_pad0`, `_pad1`, ...), or `stem`
    /// alone first when `from` is `None`.
    pub(super) fn fresh(&mut self, stem: &str, from: Option<usize>) -> String {
        let mut candidates = from
            .is_none()
            .then(|| stem.to_string())
            .into_iter()
            .chain((from.unwrap_or(2)..).map(|n| format!("{stem}{n}")));
        let identifier = candidates.find(|c| !self.taken.contains_key(c)).unwrap_or_default();
        self.reserve(&identifier);
        identifier
    }

    /// Marks an identifier kiln's own code uses here, so that no name is given it.
    pub(super) fn reserve(&mut self, identifier: &str) {
        self.taken.insert(identifier.to_string(), (identifier.to_string(), KILN.into()));
    }
}

impl NameClash {
    /// The clash as a diagnostic: both names and where they come from, and what to rename.
    pub fn to_diagnostic(&self) -> Diagnostic {
        let (first, first_place) = &self.first;
        let (second, second_place) = &self.second;
        Diagnostic::error(
            "K0419",
            format!(
                "`{}` and `{}` would both be `{}` in {} of the generated Rust",
                doc_text(first),
                doc_text(second),
                self.identifier,
                self.scope
            ),
        )
        .note(format!("`{}` comes from {}", doc_text(first), doc_text(first_place)))
        .note(format!("`{}` comes from {}", doc_text(second), doc_text(second_place)))
        .help(
            "rename one of them: generated identifiers keep ASCII letters, digits and `_`, and spell \
             other ASCII as `_` and other characters by their code points",
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// Any name, in any case, becomes what Rust's grammar (syn's parser, which refuses
        /// keywords) takes for one identifier; doc text never holds a line break.
        #[test]
        fn any_name_mangles_to_an_identifier_rust_parses(name in any::<String>()) {
            for case in [Case::Snake, Case::UpperSnake, Case::AsIs] {
                let identifier = mangle(&name, case);
                prop_assert!(syn::parse_str::<syn::Ident>(&identifier).is_ok(), "{name:?} as {case:?}: {identifier}");
                prop_assert!(identifier.is_ascii());
            }
            prop_assert!(!doc_text(&name).contains(['\n', '\r']));
            let literal: syn::LitStr = syn::parse_str(&string_literal(&name)).expect("a string literal");
            prop_assert_eq!(literal.value(), name);
        }
    }

    #[test]
    fn names_become_identifiers_in_each_case() {
        let cases = [
            ("Custom RP/Lit", Case::Snake, "custom_rp_lit"),
            ("2D Sprite", Case::Snake, "_2d_sprite"),
            ("Box", Case::Snake, "r#box"),
            ("Self", Case::AsIs, "Self_"),
            ("self", Case::Snake, "self_"),
            ("in", Case::AsIs, "r#in"),
            ("dyn", Case::AsIs, "r#dyn"),
            ("Double", Case::UpperSnake, "DOUBLE"),
            ("LitClip", Case::UpperSnake, "LIT_CLIP"),
            ("2 Sided", Case::UpperSnake, "_2_SIDED"),
            ("Lit-Fade v2", Case::UpperSnake, "LIT_FADE_V2"),
            ("_CLIPPING", Case::AsIs, "_CLIPPING"),
            ("\u{c5}", Case::AsIs, "_uc5_"),
            ("\u{212b}", Case::AsIs, "_u212b_"),
            ("着色器", Case::Snake, "u7740_u8272_u5668"),
            ("", Case::AsIs, "_unnamed"),
            ("_", Case::Snake, "_unnamed"),
        ];
        for (name, case, expected) in cases {
            assert_eq!(mangle(name, case), expected, "{name:?} as {case:?}");
        }
    }

    #[test]
    fn doc_text_cannot_end_its_comment_and_names_that_mangle_alike_clash() {
        let doc = doc_text("a\nfn evil() {}\r\u{202e}b");
        assert!(!doc.contains(['\n', '\r', '\u{202e}']), "{doc}");
        assert!(doc.contains("\\u{a}fn evil"), "{doc}");

        let mut scope = Scope::new("the top level", PRELUDE_NAMES);
        assert_eq!(scope.claim("Custom/Lit", Case::Snake, "a.shader"), "custom_lit");
        assert_eq!(scope.claim("Custom/Lit", Case::Snake, "a.shader"), "custom_lit", "same name, same item");
        assert!(scope.clashes.is_empty());
        scope.claim("Custom Lit", Case::Snake, "b.shader");
        assert_eq!(scope.clashes.len(), 1);
        let shown = scope.clashes[0].to_diagnostic();
        assert!(
            shown.message.contains("`Custom/Lit` and `Custom Lit` would both be `custom_lit`"),
            "{shown:?}"
        );
        // kiln's own names are never shadowed: a shader `Core` is `core_`.
        assert_eq!(scope.claim("Core", Case::Snake, "c.shader"), "core_");
        assert_eq!(scope.fresh("_pad", Some(0)), "_pad0");
        assert_eq!(scope.fresh("_pad", Some(0)), "_pad1");
        assert_eq!(scope.fresh("custom_lit", None), "custom_lit2");
    }
}
