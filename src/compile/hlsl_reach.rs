//! What an HLSL entry point reaches: a token-level scan of a preprocessed HLSL (or Cg) text's
//! top-level declarations, each with the names it declares and those it uses, and the closure from
//! the entry point over those names. glslang then parses only the declarations kept: a stage text
//! carries every include whole (Unity's `UnityCG.cginc`, the lighting library under a vertex
//! stage), and glslang's time goes with what it parses.
//!
//! The scan is conservative, as WGSL's is (`reach.rs`): whatever it cannot prove unused stays.
//! Only functions, structs, typedefs, constant buffers, `static` and `groupshared` globals without
//! a value, and resources (textures, samplers, buffers) can be left out; every other global stays,
//! because glslang gathers loose uniforms into one implicit constant buffer (`$Global`) whose
//! layout is the text's declaration order, and runs a static's initialiser at the entry point's
//! start (what it reads is the module's, used or not). A constant buffer is kept
//! or left whole. Every name used counts, members and locals alike. A text the scan cannot follow
//! (an unclosed group, `namespace`, `template`, `class`, `interface`) is not cut at all; where
//! glslang refuses a cut text the build parses the whole one, which decides (a miss, counted).

use crate::preprocess::SourceMap;
use std::collections::HashMap;
use std::ops::Range;

/// `text` cut to the declarations `entry` reaches, with its source map cut alike, or `None` when
/// nothing would be left out (or the scan cannot tell).
pub fn cut(text: &str, map: &SourceMap, entry: &str) -> Option<(String, SourceMap)> {
    let declarations = declarations(text)?;
    let kept = reached(&declarations, entry)?;
    let ranges: Vec<Range<usize>> = kept.iter().map(|&d| declarations[d].range.clone()).collect();
    Some((super::reach::joined(text, &ranges), map.cut(&ranges)))
}

/// A top-level declaration: its bytes, what it declares (none: it is always kept), what it uses.
#[derive(Debug)]
struct Declaration<'t> {
    range: Range<usize>,
    declares: Vec<&'t str>,
    uses: Vec<&'t str>,
    /// Whether it may be left out when nothing reaches it.
    removable: bool,
}

/// A token of an HLSL text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Token {
    Name,
    /// Any other character: punctuation, an operator.
    Mark(u8),
    /// A number, a string, a directive line (with its continuations): names nothing.
    Other,
}

/// The tokens of an HLSL text, comments skipped, and whether it was read to its end: an unclosed
/// comment or string ends the reading (what the language server reads while one is typed).
pub(crate) fn tokens(text: &str) -> (Vec<(Token, Range<usize>)>, bool) {
    let bytes = text.as_bytes();
    let mut tokens = Vec::new();
    let mut at = 0;
    let mut line_start = true;
    while at < bytes.len() {
        let c = bytes[at];
        let rest = &text[at..];
        let start = at;
        if c == b'\n' {
            line_start = true;
            at += 1;
            continue;
        }
        if c.is_ascii_whitespace() {
            at += 1;
            continue;
        }
        if rest.starts_with("//") {
            at += rest.find('\n').unwrap_or(rest.len());
            continue;
        }
        if rest.starts_with("/*") {
            match rest.find("*/") {
                Some(end) => at += end + 2,
                None => return (tokens, false),
            }
            continue;
        }
        if c == b'#' && line_start {
            // A directive the preprocessor left (`#pragma`, `#line`), to its line's end and
            // those its `\` continues: one token.
            loop {
                at += text[at..].find('\n').unwrap_or(text.len() - at);
                if at >= text.len() || !text[..at].trim_end_matches('\r').ends_with('\\') {
                    break;
                }
                at += 1;
            }
            tokens.push((Token::Other, start..at));
            continue;
        }
        line_start = false;
        let token = if c.is_ascii_alphabetic() || c == b'_' {
            at += rest.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).unwrap_or(rest.len());
            Token::Name
        } else if c.is_ascii_digit() || (c == b'.' && rest[1..].starts_with(|c: char| c.is_ascii_digit())) {
            // `1.0e-5f`, `0x1F`: letters, digits and dots, and a sign after an exponent.
            let mut end = 1;
            while let Some(&b) = bytes.get(at + end) {
                let exponent_sign = (b == b'-' || b == b'+') && matches!(bytes[at + end - 1], b'e' | b'E');
                if !(b.is_ascii_alphanumeric() || b == b'.' || b == b'_' || exponent_sign) {
                    break;
                }
                end += 1;
            }
            at += end;
            Token::Other
        } else if c == b'"' || c == b'\'' {
            match rest[1..].find(c as char) {
                Some(end) => at += end + 2,
                None => return (tokens, false),
            }
            Token::Other
        } else {
            at += rest.chars().next().map_or(1, char::len_utf8);
            Token::Mark(c)
        };
        tokens.push((token, start..at));
    }
    (tokens, true)
}

/// Words that begin what the scan does not follow.
const UNFOLLOWED: [&str; 4] = ["namespace", "template", "class", "interface"];

/// Types whose globals are resources (bound, not members of `$Global`) when a name starts so.
const RESOURCE_TYPES: [&str; 9] = [
    "Texture",
    "RWTexture",
    "Sampler",
    "sampler",
    "Buffer",
    "RWBuffer",
    "StructuredBuffer",
    "RWStructuredBuffer",
    "ByteAddressBuffer",
];

/// The text's top-level declarations, in order; `None` where the scan cannot follow it.
fn declarations(text: &str) -> Option<Vec<Declaration<'_>>> {
    let (tokens, complete) = tokens(text);
    if !complete {
        return None;
    }
    let word = |i: usize| (tokens[i].0 == Token::Name).then(|| &text[tokens[i].1.clone()]);
    let mark = |i: usize| match tokens[i].0 {
        Token::Mark(c) => Some(c),
        _ => None,
    };
    let mut declarations = Vec::new();
    let mut i = 0;
    while i < tokens.len() {
        let first = i;
        if tokens[i].0 == Token::Other && text[tokens[i].1.clone()].starts_with('#') {
            declarations.push(Declaration {
                range: tokens[i].1.clone(),
                declares: Vec::new(),
                uses: Vec::new(),
                removable: false,
            });
            i += 1;
            continue;
        }
        if mark(i) == Some(b';') {
            i += 1;
            continue;
        }
        // To the declaration's end: a `;` outside every group, or the `}` that closes its body
        // (with the `;` after it, where one follows; a struct's declarators run on to theirs).
        let type_definition =
            matches!(word(i), Some("struct")) || (word(i).is_some() && word(i + 1) == Some("struct"));
        let mut depth = 0usize;
        let mut end = None;
        while i < tokens.len() {
            match mark(i) {
                Some(b'(' | b'[' | b'{') => depth += 1,
                Some(b')' | b']') => depth = depth.checked_sub(1)?,
                Some(b'}') => {
                    depth = depth.checked_sub(1)?;
                    if depth == 0 && !type_definition {
                        if i + 1 < tokens.len() && mark(i + 1) == Some(b';') {
                            i += 1;
                        }
                        end = Some(i);
                        break;
                    }
                }
                Some(b';') if depth == 0 => {
                    end = Some(i);
                    break;
                }
                _ => {}
            }
            if word(i).is_some_and(|w| UNFOLLOWED.contains(&w)) {
                return None;
            }
            i += 1;
        }
        let last = end?;
        i = last + 1;
        let range = tokens[first].1.start..tokens[last].1.end;
        declarations.push(classify(text, &tokens[first..=last], range));
    }
    Some(declarations)
}

/// What one declaration (its tokens) declares and uses, and whether it may be left out.
fn classify<'t>(text: &'t str, tokens: &[(Token, Range<usize>)], range: Range<usize>) -> Declaration<'t> {
    let word = |i: usize| tokens.get(i).filter(|t| t.0 == Token::Name).map(|t| &text[t.1.clone()]);
    let mark = |i: usize| match tokens.get(i).map(|t| t.0) {
        Some(Token::Mark(c)) => Some(c),
        _ => None,
    };
    let names: Vec<&str> = (0..tokens.len()).filter_map(word).collect();
    let kept = |uses: Vec<&'t str>| Declaration {
        range: range.clone(),
        declares: Vec::new(),
        uses,
        removable: false,
    };
    // Attributes first (`[numthreads(8, 8, 1)]`, `[maxvertexcount(3)]`): the declaration follows.
    let mut start = 0;
    while mark(start) == Some(b'[') {
        let mut depth = 0usize;
        while let Some(t) = tokens.get(start) {
            match t.0 {
                Token::Mark(b'[') => depth += 1,
                Token::Mark(b']') => depth -= 1,
                _ => {}
            }
            start += 1;
            if depth == 0 {
                break;
            }
        }
    }
    // Where the first group opens at the top, and the names before it.
    let opening =
        (start..tokens.len()).find(|&t| matches!(mark(t), Some(b'(' | b'{' | b'=' | b':' | b';' | b'[')));
    let Some(opening) = opening else { return kept(names) };
    let leading: Vec<&str> = (start..opening).filter_map(word).collect();
    let declaration = |declares: Vec<&'t str>, removable| {
        // A set: a constant buffer may declare thousands of members.
        let declared: std::collections::HashSet<&str> = declares.iter().copied().collect();
        let uses = names.iter().copied().filter(|n| !declared.contains(n)).collect();
        Declaration { range: range.clone(), declares, uses, removable }
    };
    match (leading.as_slice(), mark(opening)) {
        // `struct S { ... };` (declarators after the body keep it: they are globals).
        (["struct", name], Some(b'{')) | ([_, "struct", name], Some(b'{')) => {
            let declarators = tokens
                .iter()
                .rposition(|t| t.0 == Token::Mark(b'}'))
                .is_some_and(|close| word(close + 1).is_some());
            declaration(vec![name], !declarators)
        }
        (["cbuffer" | "tbuffer", name], Some(b'{' | b':')) => {
            let mut declares = vec![*name];
            declares.extend(buffer_members(text, tokens));
            declaration(declares, true)
        }
        (["typedef", .., name], Some(b';')) => declaration(vec![name], true),
        // A function or its prototype: a return type, a name, its parameters.
        ([.., _, name], Some(b'(')) => declaration(vec![name], true),
        // A global: only a `static` one without a value, a resource or a workgroup array may go.
        // glslang runs a static's initialiser at the entry point's start, so the buffers it reads
        // are the module's whatever uses the static: it stays.
        ([.., _, name], Some(b';' | b'=' | b':' | b'[')) => {
            let initialised = tokens.iter().any(|t| t.0 == Token::Mark(b'='));
            let qualifier = |w: &&str| matches!(*w, "static" | "const" | "uniform" | "globallycoherent");
            let ty = leading.iter().find(|w| !qualifier(w));
            let resource = ty.is_some_and(|ty| RESOURCE_TYPES.iter().any(|r| ty.starts_with(r)));
            let private = leading.contains(&"static") || leading.contains(&"groupshared");
            let removable = (private || resource) && !initialised && !leading.contains(&"uniform");
            declaration(vec![name], removable)
        }
        _ => kept(names),
    }
}

/// The members a constant buffer's body declares: each statement's names before `;`, `,`, `:`,
/// `[` or `=`.
fn buffer_members<'t>(text: &'t str, tokens: &[(Token, Range<usize>)]) -> Vec<&'t str> {
    let Some(open) = tokens.iter().position(|t| t.0 == Token::Mark(b'{')) else { return Vec::new() };
    let mut members = Vec::new();
    let mut depth = 0usize;
    for (i, (token, _)) in tokens.iter().enumerate().skip(open + 1) {
        // `float4 lights[8];`: the name ends where its array size opens.
        let ends_name = depth == 0 && matches!(token, Token::Mark(b';' | b',' | b':' | b'[' | b'='));
        if ends_name && tokens[i - 1].0 == Token::Name {
            members.push(&text[tokens[i - 1].1.clone()]);
        }
        match token {
            Token::Mark(b'(' | b'[' | b'{') => depth += 1,
            Token::Mark(b')' | b']' | b'}') => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    members
}

/// The declarations kept for `entry`, in order: those it reaches by name and those always kept;
/// `None` where the entry point is not declared or nothing would be left out.
fn reached(declarations: &[Declaration], entry: &str) -> Option<Vec<usize>> {
    let mut by_name: HashMap<&str, Vec<usize>> = HashMap::new();
    for (index, declaration) in declarations.iter().enumerate() {
        for name in &declaration.declares {
            by_name.entry(name).or_default().push(index);
        }
    }
    let mut kept: Vec<bool> = declarations.iter().map(|d| !d.removable).collect();
    let mut queue: Vec<usize> = by_name.get(entry)?.clone();
    queue.extend(kept.iter().enumerate().filter(|(_, k)| **k).map(|(i, _)| i));
    for &index in &queue {
        kept[index] = true;
    }
    while let Some(index) = queue.pop() {
        for name in &declarations[index].uses {
            for &used in by_name.get(name).into_iter().flatten() {
                if !kept[used] {
                    kept[used] = true;
                    queue.push(used);
                }
            }
        }
    }
    let kept: Vec<usize> = (0..declarations.len()).filter(|&i| kept[i]).collect();
    (kept.len() < declarations.len()).then_some(kept)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The names of the declarations `entry` keeps, in order.
    fn kept(text: &str, entry: &str) -> Option<Vec<String>> {
        let declarations = declarations(text)?;
        let kept = reached(&declarations, entry)?;
        Some(
            kept.iter()
                .map(|&d| {
                    text[declarations[d].range.clone()]
                        .split_whitespace()
                        .take(3)
                        .collect::<Vec<_>>()
                        .join(" ")
                })
                .collect(),
        )
    }

    #[test]
    fn an_entry_point_keeps_what_it_names_and_what_glslang_needs_whatever_it_names() {
        let text = "\
cbuffer UnityPerDraw : register(b0) { float4x4 unity_ObjectToWorld; float4 unity_Lights[8]; };
cbuffer Unused { float4 _Nothing; };
float4 _Color;
static float4x4 unity_MatrixMVP = mul(unity_ObjectToWorld, unity_ObjectToWorld);
static const float PI_UNUSED;
Texture2D _MainTex; SamplerState sampler_MainTex;
Texture2D _OtherTex;
typedef float4 color4;
struct v2f { float4 pos : SV_POSITION; };
float twice(float x) { return x * 2.0; }
float twice(float2 x) { return x.x * 2.0; }
float unused(float x) { return x; }
color4 frag(v2f i) : SV_Target { return _MainTex.Sample(sampler_MainTex, i.pos.xy) * twice(unity_Lights[0].x); }
[numthreads(8, 8, 1)] void Kernel(uint3 id : SV_DispatchThreadID) { }
";
        assert_eq!(
            kept(text, "frag").expect("cut"),
            [
                // Named by the entry point (a member is the buffer's whole).
                "cbuffer UnityPerDraw :",
                // A loose uniform, in `$Global`: kept, named or not.
                "float4 _Color;",
                // A static's value is computed at the entry point: kept, with what it reads.
                "static float4x4 unity_MatrixMVP",
                "Texture2D _MainTex;",
                "SamplerState sampler_MainTex;",
                "typedef float4 color4;",
                "struct v2f {",
                // Both overloads of a name called.
                "float twice(float x)",
                "float twice(float2 x)",
                "color4 frag(v2f i)",
            ]
        );
        assert_eq!(
            kept(text, "Kernel").expect("cut").last().map(String::as_str),
            Some("[numthreads(8, 8, 1)]")
        );
    }

    #[test]
    fn what_the_scan_cannot_follow_is_not_cut() {
        for text in [
            "namespace N { float f() { return 1.0; } }\nfloat4 frag() : SV_Target { return 1.0; }",
            "template<typename T> T id(T x) { return x; }\nfloat4 frag() : SV_Target { return 1.0; }",
            "float unused() { return 1.0;\nfloat4 frag() : SV_Target { return 1.0; }",
            "float4 frag() : SV_Target { return 1.0; }\n}",
            "/* open\nfloat4 frag() : SV_Target { return 1.0; }",
        ] {
            assert!(cut(text, &SourceMap::default(), "frag").is_none(), "{text}");
        }
        // An entry point the text does not declare, and a text that keeps everything.
        assert!(cut("float f() { return 1.0; }", &SourceMap::default(), "frag").is_none());
        assert!(cut("float4 frag() : SV_Target { return 1.0; }", &SourceMap::default(), "frag").is_none());
    }

    #[test]
    fn a_constant_buffer_of_many_members_is_scanned_in_linear_time() {
        let members: String = (0..50_000).map(|i| format!("float4 m{i};\n")).collect();
        let uses: String = (0..50_000).step_by(7).map(|i| format!("m{i} + ")).collect();
        let text = format!(
            "cbuffer Big {{ {members} }};\nfloat4 unused() {{ return 1.0; }}\nfloat4 frag() : SV_Target {{ return {uses} 1.0; }}\n"
        );
        // Counted, not timed: the buffer is one declaration declaring every member once.
        let declarations = declarations(&text).expect("scanned");
        assert_eq!(declarations.len(), 3);
        assert_eq!(declarations[0].declares.len(), 50_001);
        let (cut, _) = cut(&text, &SourceMap::default(), "frag").expect("cut");
        assert!(cut.contains("cbuffer Big") && !cut.contains("unused"));
    }

    proptest::proptest! {
        /// Any text: the scan ends, and a cut is the text's own declarations, the entry point's
        /// among them.
        #[test]
        fn any_text_is_cut_to_its_own_declarations_or_left_whole(
            text in "([a-z_]{1,4}|frag|cbuffer|struct|static|[ \n{}()\\[\\];:=,#\"/*<>]|é|1\\.5){0,60}",
        ) {
            let text = format!("{text}\nfloat4 frag() : SV_Target {{ return 1.0; }}\n");
            if let Some((cut, _)) = cut(&text, &SourceMap::default(), "frag") {
                proptest::prop_assert!(cut.contains("frag()"), "{cut}");
                for line in cut.lines().filter(|l| !l.trim().is_empty()) {
                    proptest::prop_assert!(text.contains(line), "{line:?} is not the text's");
                }
            }
        }
    }
}
