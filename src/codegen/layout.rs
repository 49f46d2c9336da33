//! `#[repr(C)]` Rust structs for uniform blocks, with explicit padding so that bytemuck can cast
//! them, and `const` assertions that their size and every member offset match naga's layout: if
//! they ever disagree, the renderer does not compile.

use crate::reflect::UniformBlock;
use crate::reflect::manifest::ShaderManifest;
use std::fmt::Write as _;

/// A WGSL type as a Rust type of the same size, when there is one with no hidden padding.
fn rust_type(wgsl: &str) -> Option<(String, u32)> {
    let scalar = |s: &str| match s {
        "f32" => Some(("f32", 4)),
        "i32" => Some(("i32", 4)),
        "u32" => Some(("u32", 4)),
        "f16" => Some(("u16", 2)),
        _ => None,
    };
    if let Some((name, size)) = scalar(wgsl) {
        return Some((name.to_string(), size));
    }
    if let Some(rest) = wgsl.strip_prefix("vec") {
        let n: u32 = rest[..1].parse().ok()?;
        let (name, size) = scalar(rest[1..].trim_start_matches('<').trim_end_matches('>'))?;
        return Some((format!("[{name}; {n}]"), size * n));
    }
    if let Some(rest) = wgsl.strip_prefix("mat") {
        let columns: u32 = rest[..1].parse().ok()?;
        let rows: u32 = rest[2..3].parse().ok()?;
        let (name, size) = scalar(rest[3..].trim_start_matches('<').trim_end_matches('>'))?;
        // Columns are vectors: vec3 columns take the room of vec4 in a uniform buffer.
        let padded_rows = if rows == 3 { 4 } else { rows };
        return Some((format!("[[{name}; {padded_rows}]; {columns}]"), size * padded_rows * columns));
    }
    None
}

/// `array<ELEMENT, N>` split into its element type.
fn array_element(wgsl: &str) -> Option<&str> {
    let inner = wgsl.strip_prefix("array<")?.strip_suffix('>')?;
    Some(inner.rsplit_once(',').map_or(inner, |(element, _)| element).trim())
}

fn field_name(name: &str) -> String {
    const KEYWORDS: [&str; 12] =
        ["type", "fn", "struct", "match", "loop", "move", "ref", "self", "mod", "use", "impl", "where"];
    if KEYWORDS.contains(&name) { format!("r#{name}") } else { name.to_string() }
}

/// Emits one struct per distinct uniform block type of the shader.
pub fn uniform_structs(out: &mut String, shader: &ShaderManifest) {
    let mut emitted: Vec<(String, UniformBlock)> = Vec::new();
    let blocks = shader.passes.iter().flat_map(|p| &p.uniform_blocks);
    for block in blocks {
        if emitted.iter().any(|(_, b)| b.type_name == block.type_name && b.members == block.members) {
            continue;
        }
        // A type laid out differently in another variant gets its own name.
        let clashes = emitted.iter().filter(|(_, b)| b.type_name == block.type_name).count();
        let name =
            if clashes == 0 { block.type_name.clone() } else { format!("{}_{clashes}", block.type_name) };
        uniform_struct(out, &name, block);
        emitted.push((name, block.clone()));
    }
}

fn uniform_struct(out: &mut String, name: &str, block: &UniformBlock) {
    let mut fields = String::new();
    let mut helpers = String::new();
    let mut cursor = 0;
    let mut pads = 0;
    let mut pad = |fields: &mut String, bytes: u32| {
        let _ = writeln!(fields, "        pub _pad{pads}: [u8; {bytes}],");
        pads += 1;
    };
    for member in &block.members {
        if member.offset > cursor {
            pad(&mut fields, member.offset - cursor);
        }
        let ty = match (member.array_stride, member.array_length, array_element(&member.ty)) {
            (Some(stride), Some(length), Some(element)) => match rust_type(element) {
                Some((rust, size)) if size == stride => Some(format!("[{rust}; {length}]")),
                Some((rust, size)) if size < stride => {
                    // An element shorter than its stride: wrap it with its padding.
                    let wrapper = format!("{name}_{}_Element", member.name);
                    let _ = writeln!(
                        helpers,
                        "    #[repr(C)]\n    #[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]\n    pub struct {wrapper} {{\n        pub value: {rust},\n        pub _pad: [u8; {}],\n    }}\n",
                        stride - size
                    );
                    Some(format!("[{wrapper}; {length}]"))
                }
                _ => None,
            },
            _ => rust_type(&member.ty).filter(|(_, size)| *size == member.size).map(|(rust, _)| rust),
        };
        // Anything without a faithful Rust type (nested structs) stays raw bytes of the right size.
        let ty = ty.unwrap_or_else(|| format!("[u8; {}]", member.size));
        let _ = writeln!(fields, "        /// `{}`: {} at offset {}.", member.name, member.ty, member.offset);
        let _ = writeln!(fields, "        pub {}: {ty},", field_name(&member.name));
        cursor = member.offset + member.size;
    }
    if block.size > cursor {
        pad(&mut fields, block.size - cursor);
    }
    out.push_str(&helpers);
    let _ = writeln!(
        out,
        "    /// The uniform block `{}` ({} bytes, aligned to {}).",
        block.name, block.size, block.alignment
    );
    let _ = writeln!(
        out,
        "    #[repr(C)]\n    #[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]"
    );
    let _ = writeln!(out, "    pub struct {name} {{\n{fields}    }}");
    let _ = writeln!(out, "    const _: () = assert!(core::mem::size_of::<{name}>() == {});", block.size);
    for member in &block.members {
        let _ = writeln!(
            out,
            "    const _: () = assert!(core::mem::offset_of!({name}, {}) == {});",
            field_name(&member.name),
            member.offset
        );
    }
}
