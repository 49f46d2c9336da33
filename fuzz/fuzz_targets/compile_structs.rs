//! Generated WGSL structs and their use, through the whole compile: any input is read as choices
//! for struct declarations (scalars, vectors, matrices, f16, arrays, arrays of arrays, nested
//! structs, runtime-sized arrays, `@align`/`@size`), a uniform or storage block of the last one,
//! and a fragment stage that loads its members; the shader is built (nothing written), layouts
//! corrected, WGSL and SPIR-V written. A panic, one kiln caught (K0416) or a writer failing on
//! what naga validated (K0409) is a finding; a diagnostic for WGSL that is not valid is not.
#![no_main]

use kiln::catalog::CatalogInput;
use kiln::orchestrate::BuildOptions;
use kiln::preprocess::{IncludeConfig, Includes};
use kiln::source::SourceStore;
use libfuzzer_sys::fuzz_target;
use std::fmt::Write as _;

/// The input, read as small choices; past its end every choice is 0.
struct Choices<'a> {
    data: &'a [u8],
    at: usize,
}

impl Choices<'_> {
    fn pick(&mut self, n: usize) -> usize {
        let byte = self.data.get(self.at).copied().unwrap_or(0);
        self.at += 1;
        usize::from(byte) % n
    }
}

fn plain(c: &mut Choices, half: bool) -> String {
    let scalars: &[&str] = if half { &["f32", "i32", "u32", "f16"] } else { &["f32", "i32", "u32"] };
    let scalar = scalars[c.pick(scalars.len())];
    let float = if half && c.pick(2) == 0 { "f16" } else { "f32" };
    match c.pick(4) {
        0 => scalar.to_string(),
        1 => format!("vec{}<{scalar}>", 2 + c.pick(3)),
        2 => format!("mat{}x{}<{float}>", 2 + c.pick(3), 2 + c.pick(3)),
        _ => format!("vec4<{scalar}>"),
    }
}

fn member_type(c: &mut Choices, half: bool, earlier: &[String]) -> String {
    let element = |c: &mut Choices| {
        if !earlier.is_empty() && c.pick(3) == 0 { earlier[c.pick(earlier.len())].clone() } else { plain(c, half) }
    };
    match c.pick(6) {
        0 | 1 => plain(c, half),
        2 => format!("array<{}, {}>", element(c), 1 + c.pick(4)),
        3 => format!("array<array<{}, {}>, {}>", element(c), 1 + c.pick(3), 1 + c.pick(3)),
        _ => element(c),
    }
}

fn shader(c: &mut Choices) -> String {
    let uniform = c.pick(2) == 0;
    let half = c.pick(3) == 0;
    let mut names = Vec::new();
    let mut declarations = String::new();
    let mut root_members = Vec::new();
    let count = 1 + c.pick(4);
    for k in 0..count {
        let name = format!("S{k}");
        let _ = writeln!(declarations, "struct {name} {{");
        let members = 1 + c.pick(5);
        for j in 0..members {
            let ty = member_type(c, half, &names);
            let mut attributes = String::new();
            if c.pick(4) == 0 {
                let _ = write!(attributes, "@align({}) ", [4, 8, 16, 32, 64, 256][c.pick(6)]);
            }
            if c.pick(5) == 0 {
                let _ = write!(attributes, "@size({}) ", [16, 64, 128, 256, 512][c.pick(5)]);
            }
            let _ = writeln!(declarations, "    {attributes}m{j}: {ty},");
            if k + 1 == count {
                root_members.push((format!("m{j}"), ty));
            }
        }
        if k + 1 == count && !uniform && c.pick(3) == 0 {
            let ty = plain(c, half);
            let _ = writeln!(declarations, "    tail: array<{ty}>,");
            root_members.push(("tail".to_string(), format!("array<{ty}>")));
        }
        declarations.push_str("}\n");
        names.push(name);
    }
    let mut reads = String::new();
    for (i, (member, ty)) in root_members.iter().enumerate() {
        if ty.starts_with("array<") && !ty.contains(',') {
            let _ = writeln!(reads, "    let v{i} = blk.{member}[0];\n    _ = v{i};");
        } else {
            let _ = writeln!(reads, "    let v{i} = blk.{member};\n    _ = v{i};");
            if ty.starts_with("array<") || ty.starts_with("mat") {
                let _ = writeln!(reads, "    let w{i} = blk.{member}[0];\n    _ = w{i};");
            }
        }
    }
    let space = if uniform { "uniform" } else { "storage, read" };
    let (require, enable) = if half { ("#pragma require native16bit\n", "enable f16;\n") } else { ("", "") };
    let root = names.last().cloned().unwrap_or_default();
    format!(
        "Shader \"Fuzz/Structs\" {{ SubShader {{ Pass {{\nWGSLPROGRAM\n#pragma vertex Vertex\n#pragma fragment Fragment\n\
         {require}{enable}{declarations}var<{space}> blk: {root};\n\
         @vertex fn Vertex(@location(0) p: vec3<f32>) -> @builtin(position) vec4<f32> {{ return vec4<f32>(p, 1.0); }}\n\
         @fragment fn Fragment() -> @location(0) vec4<f32> {{\n{reads}    return vec4<f32>(1.0);\n}}\n\
         ENDWGSL\n}} }} }}\n"
    )
}

fuzz_target!(|data: &[u8]| {
    let text = shader(&mut Choices { data, at: 0 });
    let mut store = SourceStore::new();
    let file = store.add("fuzz.shader", text.as_str());
    let mut includes = Includes::new(IncludeConfig::new(Vec::new()));
    let input = CatalogInput {
        shaders: vec![file],
        always_include: vec!["Fuzz/Structs".to_string()],
        ..CatalogInput::default()
    };
    let (catalog, _) = kiln::catalog::catalog(&mut store, &mut includes, &input);
    let options = BuildOptions::one_off(".".into(), "/nonexistent/kiln-fuzz".into(), false);
    let result = kiln::orchestrate::build(&store, &includes, &catalog, &options, &|_, _| {});
    if let Some(found) = result.diagnostics.iter().find(|d| d.code == "K0416" || d.code == "K0409") {
        panic!("{}\n{text}", kiln::diagnostics::render_plain(&store, std::slice::from_ref(found)));
    }
});
