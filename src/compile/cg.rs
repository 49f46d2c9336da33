//! Cg's combined samplers in HLSL's terms, before glslang reads a text: glslang writes SPIR-V
//! naga cannot read for `sampler2D` and `tex2D` (and crashes with its automatic sampled
//! textures), so each sampler declaration becomes a texture and a `SamplerState` named as
//! Unity names them (`_MainTex`, `sampler_MainTex`), and each sampling call the texture's method
//! on them. The rewritten text keeps a source map: what glslang says of it is placed where the
//! original text has it. A sampler passed to a function takes its sampler state with it.

use crate::preprocess::{Kind, SourceMap, Token, lex};
use std::collections::{BTreeSet, HashMap};
use std::ops::Range;

/// Cg's sampler types, with the texture type each declares in HLSL.
const SAMPLERS: &[(&str, &str)] = &[
    ("sampler2D", "Texture2D"),
    ("sampler2D_float", "Texture2D"),
    ("sampler2D_half", "Texture2D"),
    ("sampler3D", "Texture3D"),
    ("samplerCUBE", "TextureCube"),
    ("samplerCUBE_float", "TextureCube"),
    ("samplerCUBE_half", "TextureCube"),
];

/// Cg's sampling functions: each becomes a macro on the texture's name (glslang's own
/// preprocessor expands it), by the number of arguments after the sampler.
const SAMPLING: &[(&str, usize, &str)] = &[
    ("tex2D", 1, "(t).Sample(sampler##t, a)"),
    ("tex2D", 3, "(t).SampleGrad(sampler##t, a, b, c)"),
    ("tex2Dlod", 1, "(t).SampleLevel(sampler##t, (a).xy, (a).w)"),
    ("tex2Dbias", 1, "(t).SampleBias(sampler##t, (a).xy, (a).w)"),
    ("tex2Dgrad", 3, "(t).SampleGrad(sampler##t, a, b, c)"),
    ("tex2Dproj", 1, "(t).Sample(sampler##t, (a).xy / (a).w)"),
    ("tex3D", 1, "(t).Sample(sampler##t, a)"),
    ("tex3Dlod", 1, "(t).SampleLevel(sampler##t, (a).xyz, (a).w)"),
    ("texCUBE", 1, "(t).Sample(sampler##t, a)"),
    ("texCUBElod", 1, "(t).SampleLevel(sampler##t, (a).xyz, (a).w)"),
    ("texCUBEbias", 1, "(t).SampleBias(sampler##t, (a).xyz, (a).w)"),
];

/// A text rewritten, and its map.
pub(super) struct Rewritten {
    pub text: String,
    pub map: SourceMap,
}

/// What the rewrite found and made of a text.
pub(super) struct Rewrite {
    /// The text rewritten, where it had Cg samplers.
    pub rewritten: Option<Rewritten>,
    /// Each parameter of a texture, sampler or Cg sampler type, in the original text: glslang
    /// compiles a function that takes one, but naga cannot read the SPIR-V it writes for it
    /// where the function is called, so a failure there is said at the parameter.
    pub texture_parameters: Vec<Range<usize>>,
}

/// Whether `text` may declare a Cg sampler: without one, [`rewrite`] changes nothing (every
/// edit follows from a sampler's declaration), and a text need not be lexed for it.
pub(super) fn may_have_samplers(text: &str) -> bool {
    ["sampler2D", "sampler3D", "samplerCUBE"].iter().any(|name| text.contains(name))
}

/// `text` with Cg's samplers rewritten (`None` when it has none), and its texture parameters.
pub(super) fn rewrite(text: &str, map: &SourceMap) -> Rewrite {
    let tokens = lex(text);
    let word = |i: usize| tokens.get(i).filter(|t| t.kind == Kind::Ident).map(|t| t.text.as_ref());
    let punct = |i: usize, p: &str| tokens.get(i).is_some_and(|t| t.kind == Kind::Punct && t.text == p);
    let range = |i: usize| tokens[i].at..tokens[i].at + tokens[i].text.len();
    // Sampler states already declared (Unity's `UNITY_DECLARE_TEX2D` declares both).
    let states: BTreeSet<&str> =
        (1..tokens.len()).filter(|&i| word(i - 1) == Some("SamplerState")).filter_map(word).collect();
    let mut edits: Vec<(Range<usize>, String)> = Vec::new();
    let mut samplers: BTreeSet<String> = BTreeSet::new();
    let mut texture_parameters = Vec::new();
    // Functions with Cg sampler parameters, and the indices of those parameters.
    let mut sampler_parameters: HashMap<&str, Vec<usize>> = HashMap::new();
    let (mut braces, mut parens) = (0usize, 0usize);
    // The function whose parameters are being read, and the parameter's index.
    let mut signature: Option<(&str, usize)> = None;
    let mut i = 0;
    while i < tokens.len() {
        let token = &tokens[i];
        match (token.kind, token.text.as_ref()) {
            (Kind::Punct, "{") => braces += 1,
            (Kind::Punct, "}") => braces = braces.saturating_sub(1),
            (Kind::Punct, "(") => {
                parens += 1;
                if braces == 0 && parens == 1 {
                    signature = i.checked_sub(1).and_then(word).map(|name| (name, 0));
                }
            }
            (Kind::Punct, ")") => parens = parens.saturating_sub(1),
            (Kind::Punct, ",") if braces == 0 && parens == 1 => {
                if let Some((_, index)) = &mut signature {
                    *index += 1;
                }
            }
            (Kind::Ident, name) => {
                let in_signature = braces == 0 && parens == 1;
                if in_signature && TEXTURE_TYPES.contains(&name) {
                    texture_parameters.push(range(i));
                }
                if let Some(&(_, texture)) = SAMPLERS.iter().find(|(s, _)| *s == name) {
                    edits.push((range(i), texture.to_string()));
                    if in_signature {
                        // A parameter: its sampler state is one more, after it.
                        texture_parameters.push(range(i));
                        if let Some(parameter) = word(i + 1) {
                            let end = range(i + 1).end;
                            edits.push((end..end, format!(", SamplerState sampler{parameter}")));
                            samplers.insert(parameter.to_string());
                        }
                        if let Some((function, index)) = signature {
                            sampler_parameters.entry(function).or_default().push(index);
                        }
                        i += 1;
                        continue;
                    }
                    // A declaration: each declarator up to the `;`, past `: register(...)`.
                    let mut names = Vec::new();
                    let mut j = i + 1;
                    let mut expecting = true;
                    while j < tokens.len() && !punct(j, ";") {
                        if expecting && let Some(name) = word(j) {
                            names.push(name);
                            expecting = false;
                        } else if punct(j, ",") {
                            expecting = true;
                        }
                        j += 1;
                    }
                    if j < tokens.len() {
                        let states: String = (names.iter())
                            .filter(|name| !states.contains(format!("sampler{name}").as_str()))
                            .map(|name| format!(" SamplerState sampler{name};"))
                            .collect();
                        let end = range(j).end;
                        if !states.is_empty() {
                            edits.push((end..end, states));
                        }
                    }
                    samplers.extend(names.into_iter().map(str::to_string));
                    i = j;
                    continue;
                }
            }
            _ => {}
        }
        i += 1;
    }
    // Each sampling call on a sampler becomes its macro; each sampler passed to a function
    // that takes one is followed by its sampler state.
    let mut used: BTreeSet<usize> = BTreeSet::new();
    for i in 0..tokens.len() {
        let Some(name) = word(i) else { continue };
        if !punct(i + 1, "(") {
            continue;
        }
        if let Some(indices) = sampler_parameters.get(name) {
            for (index, argument) in arguments(&tokens, i + 1).into_iter().enumerate() {
                if indices.contains(&index)
                    && argument.len() == 1
                    && let Some(sampler) = word(argument.start).filter(|s| samplers.contains(*s))
                {
                    let end = range(argument.start).end;
                    edits.push((end..end, format!(", sampler{sampler}")));
                }
            }
            continue;
        }
        if !SAMPLING.iter().any(|(f, _, _)| *f == name) {
            continue;
        }
        let arguments = arguments(&tokens, i + 1);
        let Some(first) = arguments.first() else { continue };
        if first.len() != 1 || !word(first.start).is_some_and(|s| samplers.contains(s)) {
            continue;
        }
        let after = arguments.len() - 1;
        let Some(index) = SAMPLING.iter().position(|&(f, n, _)| f == name && n == after) else { continue };
        used.insert(index);
        edits.push((range(i), macro_name(name, after)));
    }
    if edits.is_empty() {
        return Rewrite { rewritten: None, texture_parameters };
    }
    edits.sort_by_key(|(r, _)| (r.start, r.end));
    let prelude: String = used
        .into_iter()
        .map(|index| {
            let (name, arguments, body) = SAMPLING[index];
            let parameters = ["a", "b", "c"][..arguments].join(", ");
            format!("#define {}(t, {parameters}) {body}\n", macro_name(name, arguments))
        })
        .collect();
    let mut out = String::with_capacity(text.len() + prelude.len() + 64 * edits.len());
    let mut lengths = Vec::with_capacity(edits.len() + 1);
    out.push_str(&prelude);
    lengths.push((0..0, prelude.len()));
    let mut from = 0;
    for (range, written) in &edits {
        out.push_str(&text[from..range.start]);
        out.push_str(written);
        lengths.push((range.clone(), written.len()));
        from = range.end;
    }
    out.push_str(&text[from..]);
    Rewrite { rewritten: Some(Rewritten { map: map.edited(&lengths), text: out }), texture_parameters }
}

/// HLSL's texture and sampler types: a function parameter of one is what naga cannot read.
const TEXTURE_TYPES: &[&str] =
    &["Texture2D", "Texture3D", "TextureCube", "Texture2DArray", "SamplerState", "SamplerComparisonState"];

/// The macro a sampling call becomes: `kiln_tex2D1` (its name and argument count).
fn macro_name(function: &str, arguments: usize) -> String {
    format!("kiln_{function}{arguments}")
}

/// The arguments of a call whose `(` is token `open`, each as the range of its tokens.
fn arguments(tokens: &[Token], open: usize) -> Vec<Range<usize>> {
    let mut depth = 0usize;
    let (mut found, mut start) = (Vec::new(), open + 1);
    for (at, token) in tokens.iter().enumerate().skip(open + 1) {
        if token.kind != Kind::Punct {
            continue;
        }
        match token.text.as_ref() {
            "(" | "[" | "{" => depth += 1,
            ")" | "]" | "}" if depth == 0 => {
                if at > start {
                    found.push(start..at);
                }
                break;
            }
            ")" | "]" | "}" => depth -= 1,
            "," if depth == 0 => {
                found.push(start..at);
                start = at + 1;
            }
            _ => {}
        }
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rewritten(text: &str) -> String {
        rewrite(text, &SourceMap::default()).rewritten.map(|r| r.text).unwrap_or_else(|| text.to_string())
    }

    #[test]
    fn a_cg_sampler_becomes_a_texture_and_a_sampler_state_and_its_calls_methods() {
        let text = "sampler2D _MainTex;\nfloat4 f(float2 uv) { return tex2D(_MainTex, uv) + tex2Dlod(_MainTex, float4(uv, 0, 0)); }";
        let out = rewritten(text);
        assert!(out.contains("Texture2D _MainTex; SamplerState sampler_MainTex;"), "{out}");
        assert!(
            out.contains("kiln_tex2D1(_MainTex, uv)") && out.contains("kiln_tex2Dlod1(_MainTex,"),
            "{out}"
        );
        assert!(out.starts_with("#define kiln_tex2D1(t, a) (t).Sample(sampler##t, a)\n"), "{out}");
    }

    #[test]
    fn a_sampler_state_declared_already_is_not_declared_again() {
        let out = rewritten(
            "sampler2D _A, _B; SamplerState sampler_A;\nfloat4 g(float2 uv) { return tex2D(_B, uv); }",
        );
        assert!(out.contains("Texture2D _A, _B; SamplerState sampler_B;"), "{out}");
        assert!(!out.contains("SamplerState sampler_A; SamplerState sampler_A"), "{out}");
    }

    #[test]
    fn a_sampler_parameter_takes_its_state_and_so_do_the_calls_that_pass_one() {
        let text = "sampler2D _MainTex;\nfloat4 f(float x, sampler2D tex) { return tex2D(tex, x.xx); }\nfloat4 g() { return f(1, _MainTex); }";
        let rewrite = rewrite(text, &SourceMap::default());
        let out = rewrite.rewritten.expect("rewritten").text;
        assert!(out.contains("f(float x, Texture2D tex, SamplerState samplertex)"), "{out}");
        assert!(out.contains("f(1, _MainTex, sampler_MainTex)"), "{out}");
        assert!(out.contains("kiln_tex2D1(tex, x.xx)"), "{out}");
        assert_eq!(rewrite.texture_parameters.len(), 1);
        assert_eq!(&text[rewrite.texture_parameters[0].clone()], "sampler2D");
    }

    #[test]
    fn text_without_samplers_is_left_alone() {
        assert!(rewrite("float4 f() { return 1; }", &SourceMap::default()).rewritten.is_none());
    }
}
