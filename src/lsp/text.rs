//! Positions and names as the protocol has them: line and UTF-16 column, `file:` URIs; words at a
//! place in a text.

use crate::compile::hlsl_reach::{self, Token};
use lsp_types::{Position, Range, Uri};
use std::path::{Path, PathBuf};
use std::str::FromStr;

/// The byte offset of `position` in `text` (clamped to its line's end and the text's end).
pub(super) fn offset_of(text: &str, position: Position) -> usize {
    let mut line_start = 0;
    for _ in 0..position.line {
        match text[line_start..].find('\n') {
            Some(at) => line_start += at + 1,
            None => return text.len(),
        }
    }
    let line_end = text[line_start..].find('\n').map_or(text.len(), |at| line_start + at);
    let mut units = 0;
    for (at, c) in text[line_start..line_end].char_indices() {
        if units >= position.character as usize {
            return line_start + at;
        }
        units += c.len_utf16();
    }
    line_end
}

/// The position of byte `offset` of `text` (clamped to the text, moved back to a char boundary).
pub(super) fn position_of(text: &str, offset: usize) -> Position {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let line = before.matches('\n').count();
    let line_start = before.rfind('\n').map_or(0, |at| at + 1);
    let character: usize = before[line_start..].chars().map(char::len_utf16).sum();
    Position::new(line as u32, character as u32)
}

/// The range of bytes `range` of `text`.
pub(super) fn range_of(text: &str, range: std::ops::Range<usize>) -> Range {
    Range::new(position_of(text, range.start), position_of(text, range.end))
}

/// The file a `file:` URI names (`None` for other schemes and malformed ones).
pub(super) fn path_of(uri: &Uri) -> Option<PathBuf> {
    url::Url::parse(uri.as_str()).ok()?.to_file_path().ok()
}

/// The `file:` URI of an absolute path.
pub(super) fn uri_of(path: &Path) -> Option<Uri> {
    let absolute = std::path::absolute(path).ok()?;
    Uri::from_str(url::Url::from_file_path(absolute).ok()?.as_str()).ok()
}

fn is_name_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// The identifier at (or just before) `offset`, with its byte range.
pub(super) fn word_at(text: &str, offset: usize) -> Option<(&str, std::ops::Range<usize>)> {
    let offset = offset.min(text.len());
    if !text.is_char_boundary(offset) {
        return None;
    }
    let before = text[..offset].char_indices().rev().find(|&(_, c)| !is_name_char(c));
    let start = before.map_or(0, |(at, c)| at + c.len_utf8());
    let end = text[offset..].find(|c: char| !is_name_char(c)).map_or(text.len(), |at| offset + at);
    (start < end).then(|| (&text[start..end], start..end))
}

/// The text of the line `offset` is on, up to `offset`.
pub(super) fn line_before(text: &str, offset: usize) -> &str {
    let offset = offset.min(text.len());
    let offset = (0..=offset).rev().find(|&at| text.is_char_boundary(at)).unwrap_or(0);
    let start = text[..offset].rfind('\n').map_or(0, |at| at + 1);
    &text[start..offset]
}

/// What a module-scope declaration declares.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Declared {
    /// A function.
    Function,
    /// A type: a struct, an alias, an HLSL constant buffer.
    Type,
    /// A variable, a constant, a resource.
    Value,
}

/// The shading language a declaration or a place is written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Language {
    Wgsl,
    Hlsl,
}

impl Language {
    /// The language of a file from its name, for files that hold one program language.
    fn of_file(name: &str) -> Option<Language> {
        let extension = name.rsplit_once('.').map_or("", |(_, e)| e);
        match extension.to_ascii_lowercase().as_str() {
            "wgsl" => Some(Language::Wgsl),
            "hlsl" | "hlsli" | "cginc" | "cg" | "fx" | "fxh" | "compute" => Some(Language::Hlsl),
            _ => None,
        }
    }

    /// The language at byte `offset` of the file named `name`: a `.shader` file's HLSL and Cg
    /// blocks are HLSL, the rest of it WGSL.
    pub(super) fn at(name: &str, text: &str, offset: usize) -> Language {
        Language::of_file(name).unwrap_or_else(|| {
            let inside = hlsl_blocks(text).any(|block| block.contains(&offset));
            if inside { Language::Hlsl } else { Language::Wgsl }
        })
    }

    /// The name a Markdown code fence gives it.
    pub(super) fn fence(self) -> &'static str {
        match self {
            Language::Wgsl => "wgsl",
            Language::Hlsl => "hlsl",
        }
    }
}

/// A declaration found by a scan: what it declares, its language and the byte range of its name.
pub(super) type Declaration = (Declared, Language, std::ops::Range<usize>);

/// The module-scope declarations of the file named `name`: WGSL's or HLSL's as its extension says;
/// in a `.shader` file WGSL's and those of its HLSL and Cg blocks; in a file of another name
/// (`.inc`, `.h`) both, each name once. Plain scans, so they work on unsaved text that does not
/// parse.
pub(super) fn declarations(name: &str, text: &str) -> Vec<Declaration> {
    let wgsl = || wgsl_declarations(text).map(|(kind, range)| (kind, Language::Wgsl, range));
    let mut found: Vec<Declaration> = match Language::of_file(name) {
        Some(Language::Wgsl) => wgsl().collect(),
        Some(Language::Hlsl) => hlsl_declarations(text, 0..text.len()),
        None if name.ends_with(".shader") => {
            wgsl().chain(hlsl_blocks(text).flat_map(|block| hlsl_declarations(text, block))).collect()
        }
        None => wgsl().chain(hlsl_declarations(text, 0..text.len())).collect(),
    };
    found.sort_by_key(|(_, _, range)| range.start);
    found.dedup_by(|a, b| a.2 == b.2);
    found
}

/// Where `name` is declared at module scope in WGSL `text` (`fn`, `struct`, `var`, `const`,
/// `override`, `alias`): the byte range of the name.
fn wgsl_declarations(text: &str) -> impl Iterator<Item = (Declared, std::ops::Range<usize>)> + '_ {
    const KINDS: [(&str, Declared); 6] = [
        ("fn", Declared::Function),
        ("struct", Declared::Type),
        ("var", Declared::Value),
        ("const", Declared::Value),
        ("override", Declared::Value),
        ("alias", Declared::Type),
    ];
    let mut at = 0;
    std::iter::from_fn(move || {
        while at < text.len() {
            let start = at + text[at..].find(|c: char| c.is_ascii_alphabetic())?;
            let end = text[start..].find(|c: char| !is_name_char(c)).map_or(text.len(), |e| start + e);
            at = end;
            let preceded = start == 0 || !text[..start].ends_with(is_name_char);
            let Some(&(word, kind)) =
                KINDS.iter().find(|(k, _)| *k == &text[start..end]).filter(|_| preceded)
            else {
                continue;
            };
            let mut rest = end;
            // `var<uniform>` and `var<storage, read>`: the name follows the template list.
            let after = text[rest..].trim_start();
            if word == "var" && after.starts_with('<') {
                rest = text.len() - after.len();
                rest += text[rest..].find('>').map_or(0, |e| e + 1);
            }
            let skipped = text[rest..].len() - text[rest..].trim_start().len();
            let name_start = rest + skipped;
            let name_end =
                text[name_start..].find(|c: char| !is_name_char(c)).map_or(text.len(), |e| name_start + e);
            if name_end > name_start && !text[name_start..].starts_with(|c: char| c.is_ascii_digit()) {
                at = name_end;
                return Some((kind, name_start..name_end));
            }
        }
        None
    })
}

/// The byte ranges of a `.shader` file's HLSL and Cg blocks (`HLSLPROGRAM` to `ENDHLSL`,
/// `CGINCLUDE` to `ENDCG`, ...), inside their markers.
fn hlsl_blocks(text: &str) -> impl Iterator<Item = std::ops::Range<usize>> + '_ {
    const BLOCKS: [(&str, &str); 4] = [
        ("HLSLPROGRAM", "ENDHLSL"),
        ("HLSLINCLUDE", "ENDHLSL"),
        ("CGPROGRAM", "ENDCG"),
        ("CGINCLUDE", "ENDCG"),
    ];
    let mut at = 0;
    std::iter::from_fn(move || {
        let (start, end) = BLOCKS
            .iter()
            .filter_map(|(open, close)| {
                let start = at + word_position(&text[at..], open)? + open.len();
                Some((start, close))
            })
            .min_by_key(|(start, _)| *start)?;
        let end = word_position(&text[start..], end).map_or(text.len(), |e| start + e);
        at = end;
        Some(start..end)
    })
}

/// Where `word` first stands as a word of its own in `text`.
fn word_position(text: &str, word: &str) -> Option<usize> {
    let mut from = 0;
    while let Some(at) = text[from..].find(word).map(|at| from + at) {
        let end = at + word.len();
        let before = !text[..at].ends_with(is_name_char);
        let after = !text[end..].starts_with(is_name_char);
        if before && after {
            return Some(at);
        }
        from = end;
    }
    None
}

/// The module-scope declarations in `range` of HLSL `text`: functions, structs, constant buffers
/// and what they hold, globals, and the declarations Unity's macros make (`TEXTURE2D(_BaseMap)`,
/// `CBUFFER_START(UnityPerMaterial)`, `UNITY_DEFINE_INSTANCED_PROP(float4, _BaseColor)`).
fn hlsl_declarations(text: &str, range: std::ops::Range<usize>) -> Vec<Declaration> {
    // The compiler's HLSL tokens, read as far as they go (an unclosed comment is being typed).
    let (tokens, _) = hlsl_reach::tokens(&text[range.clone()]);
    let tokens: Vec<(Token, std::ops::Range<usize>)> = (tokens.into_iter())
        .filter(|(token, _)| *token != Token::Other)
        .map(|(token, r)| (token, r.start + range.start..r.end + range.start))
        .collect();
    let name = |i: usize| matches!(tokens.get(i), Some((Token::Name, _))).then(|| &text[tokens[i].1.clone()]);
    let is_macro = |word: &str| word.len() > 1 && !word.bytes().any(|b| b.is_ascii_lowercase());
    let is_buffer = |word: &str| matches!(word, "cbuffer" | "tbuffer");
    // The index of the token that closes the group opened at `open`.
    let closing = |open: usize, up: u8, down: u8| {
        let mut depth = 0usize;
        for (i, (token, _)) in tokens.iter().enumerate().skip(open) {
            match token {
                Token::Mark(c) if *c == up => depth += 1,
                Token::Mark(c) if *c == down => {
                    depth -= 1;
                    if depth == 0 {
                        return i;
                    }
                }
                _ => {}
            }
        }
        tokens.len()
    };
    let mut found = Vec::new();
    let mut found_at = |kind, i: usize| found.push((kind, Language::Hlsl, tokens[i].1.clone()));
    // The names of the statement being read, by token index.
    let mut names: Vec<usize> = Vec::new();
    // Braces whose insides are not module scope (function and struct bodies).
    let mut bodies = 0usize;
    // Whether the statement's declaration has been found, so the rest of it is passed over.
    let mut done = false;
    let mut i = 0;
    while i < tokens.len() {
        let here = i;
        i += 1;
        match tokens[here].0 {
            Token::Mark(b'{') if bodies > 0 => bodies += 1,
            Token::Mark(b'}') if bodies > 0 => {
                bodies -= 1;
                if bodies == 0 {
                    (names, done) = (Vec::new(), false);
                }
            }
            _ if bodies > 0 => {}
            Token::Name => {
                // A bare macro (`CBUFFER_END`) ends the statement it seemed to start.
                if names.last().and_then(|&n| name(n)).is_some_and(is_macro) {
                    names.clear();
                }
                names.push(here);
            }
            _ if done => {
                if matches!(tokens[here].0, Token::Mark(b';')) {
                    (names, done) = (Vec::new(), false);
                } else if matches!(tokens[here].0, Token::Mark(b'{')) {
                    bodies = 1;
                }
            }
            Token::Mark(b'(') => {
                let close = closing(here, b'(', b')');
                match names.as_slice() {
                    [.., last] if name(*last).is_some_and(is_macro) => {
                        // A macro that declares: its last name is what it declares.
                        let word = name(*last).unwrap_or_default();
                        let declared = (here..close).rev().find(|&t| name(t).is_some());
                        let kind = if word.contains("BUFFER_START") {
                            Some(Declared::Type)
                        } else {
                            ["TEX", "SAMPLER", "PROP", "DECLARE"]
                                .iter()
                                .any(|part| word.contains(part))
                                .then_some(Declared::Value)
                        };
                        if let (Some(kind), Some(declared)) = (kind, declared) {
                            found_at(kind, declared);
                        }
                        names.clear();
                    }
                    [.., _, last] => {
                        found_at(Declared::Function, *last);
                        done = true;
                    }
                    _ => done = true,
                }
                i = close + 1;
            }
            Token::Mark(b'<') if !names.is_empty() => i = closing(here, b'<', b'>') + 1,
            Token::Mark(b'[') if names.is_empty() => i = closing(here, b'[', b']') + 1,
            Token::Mark(b'{') => {
                let first = names.first().and_then(|&n| name(n));
                match (first, names.get(1)) {
                    (Some("struct"), Some(&n)) => {
                        found_at(Declared::Type, n);
                        bodies = 1;
                    }
                    // What a constant buffer holds is module scope.
                    (Some(word), Some(&n)) if is_buffer(word) => found_at(Declared::Type, n),
                    _ => bodies = 1,
                }
                names.clear();
            }
            // `cbuffer Name : register(b0) {`: what follows the name up to the brace says where
            // it is bound.
            Token::Mark(b':')
                if names.len() == 2 && names.first().and_then(|&n| name(n)).is_some_and(is_buffer) =>
            {
                let next = (here..tokens.len()).find(|&t| matches!(tokens[t].0, Token::Mark(b'{' | b';')));
                i = next.unwrap_or(tokens.len());
            }
            Token::Mark(b';' | b'=' | b':' | b'[' | b',') => {
                let typedef = names.first().and_then(|&n| name(n)) == Some("typedef");
                if let [.., _, last] = names.as_slice() {
                    found_at(if typedef { Declared::Type } else { Declared::Value }, *last);
                }
                if matches!(tokens[here].0, Token::Mark(b';')) {
                    names.clear();
                } else {
                    done = true;
                }
            }
            Token::Mark(_) | Token::Other => names.clear(),
        }
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positions_count_utf16_units() {
        let text = "a\n\u{1F600}b\nc";
        assert_eq!(offset_of(text, Position::new(1, 2)), 6);
        assert_eq!(position_of(text, 6), Position::new(1, 2));
        assert_eq!(offset_of(text, Position::new(1, 99)), 7);
        assert_eq!(offset_of(text, Position::new(9, 0)), text.len());
        assert_eq!(position_of(text, 4), Position::new(1, 0));
    }

    #[test]
    fn words_and_declarations() {
        let text = "var<uniform> _Light: L;\nfn shade(x: f32) {}\nstruct S { a: f32 }";
        assert_eq!(word_at(text, 15).map(|w| w.0), Some("_Light"));
        assert_eq!(word_at("\u{1F600}ab", 5).map(|w| w.0), Some("ab"));
        let found: Vec<_> = declarations("a.wgsl", text).into_iter().map(|(k, _, r)| (k, &text[r])).collect();
        use Declared::*;
        assert_eq!(found, [(Value, "_Light"), (Function, "shade"), (Type, "S")]);
    }

    fn found<'a>(name: &str, text: &'a str) -> Vec<(Declared, Language, &'a str)> {
        declarations(name, text).into_iter().map(|(k, l, r)| (k, l, &text[r])).collect()
    }

    #[test]
    fn hlsl_declarations_are_those_at_module_scope_and_those_unity_s_macros_make() {
        let text = r#"// float commented(float x);
#define SQUARE(x) ((x) * (x))
#include "Common.hlsl"
CBUFFER_START(UnityPerMaterial)
    float4 _BaseColor;
CBUFFER_END
TEXTURE2D(_BaseMap);
SAMPLER(sampler_BaseMap);
UNITY_INSTANCING_BUFFER_START(PerInstance)
    UNITY_DEFINE_INSTANCED_PROP(float, _Cutoff)
UNITY_INSTANCING_BUFFER_END(PerInstance)
cbuffer UnityPerDraw : register(b0) { float4x4 unity_ObjectToWorld; };
Texture2D<float4> _Noise;
static const float PI = 3.14159, TAU = 6.28;
typedef float4 real4;
struct Varyings { float4 positionCS : SV_POSITION; float2 uv : TEXCOORD0; };
float Square(float v);
Varyings Vertex(float3 p : POSITION) { Varyings o; float local = 1.0; return o; }
float4 Fragment(Varyings i) : SV_TARGET { if (i.uv.x > 0) { return 0; } return 1; }
[numthreads(8, 8, 1)] void Kernel(uint3 id : SV_DispatchThreadID) {}
"#;
        use Declared::*;
        let hlsl = |kind, name| (kind, Language::Hlsl, name);
        assert_eq!(
            found("Pass.hlsl", text),
            [
                hlsl(Type, "UnityPerMaterial"),
                hlsl(Value, "_BaseColor"),
                hlsl(Value, "_BaseMap"),
                hlsl(Value, "sampler_BaseMap"),
                hlsl(Type, "PerInstance"),
                hlsl(Value, "_Cutoff"),
                hlsl(Type, "UnityPerDraw"),
                hlsl(Value, "unity_ObjectToWorld"),
                hlsl(Value, "_Noise"),
                hlsl(Value, "PI"),
                hlsl(Type, "real4"),
                hlsl(Type, "Varyings"),
                hlsl(Function, "Square"),
                hlsl(Function, "Vertex"),
                hlsl(Function, "Fragment"),
                hlsl(Function, "Kernel"),
            ]
        );
        // The same text in a `.cginc`; in a `.wgsl` file only WGSL's keywords are read.
        assert_eq!(found("UnityCG.cginc", text).len(), 16);
        assert!(found("Pass.wgsl", text).iter().all(|(_, language, _)| *language == Language::Wgsl));
    }

    #[test]
    fn a_shader_file_s_hlsl_is_read_inside_its_blocks_only() {
        let text = "Shader \"S\" {\n SubShader { Pass {\n HLSLPROGRAM\n float4 Frag() : SV_TARGET { return 1; }\n \
                    ENDHLSL\n } Pass { WGSLPROGRAM\n fn frag() -> vec4f { return vec4f(1.0); }\n ENDWGSL\n } } }";
        use Declared::*;
        assert_eq!(
            found("S.shader", text),
            [(Function, Language::Hlsl, "Frag"), (Function, Language::Wgsl, "frag")]
        );
        let frag = text.find("return 1").expect("in the block");
        assert_eq!(Language::at("S.shader", text, frag), Language::Hlsl);
        assert_eq!(Language::at("S.shader", text, text.find("vec4f").expect("WGSL")), Language::Wgsl);
        assert_eq!(Language::at("Lit.hlsl", "", 0).fence(), "hlsl");
    }

    proptest::proptest! {
        /// Any text, half-typed or hostile: the scans end, and every range found is a name of it.
        #[test]
        fn declarations_of_any_text_are_names_in_it(
            text in "([a-zA-Z_]{1,6}|[ \n\t{}()<>\\[\\];:=,#\\\\\"/*]|é|\u{1F600}|HLSLPROGRAM|ENDHLSL|cbuffer|struct){0,80}",
            name in "(a\\.shader|a\\.hlsl|a\\.wgsl|a\\.inc)",
        ) {
            for (_, _, range) in declarations(&name, &text) {
                let found = &text[range];
                proptest::prop_assert!(!found.is_empty() && found.chars().all(is_name_char), "{found:?}");
            }
            let _ = Language::at(&name, &text, text.len() / 2);
        }
    }
}
