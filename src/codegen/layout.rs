//! `#[repr(C)]` Rust structs for uniform blocks, with explicit padding so that bytemuck can cast
//! them, and `const` assertions that their size and every member offset match naga's layout: if
//! they ever disagree, the renderer does not compile.

use super::names::{Case, Scope, doc_text, stem};
use crate::manifest::ShaderManifest;
use crate::reflect::Member;
use std::fmt::Write as _;

/// A WGSL type as a Rust type of the same size, when there is one with no hidden padding.
fn rust_type(wgsl: &str) -> Option<(String, u32)> {
    let scalar = |s: &str| match s {
        "f32" => Some(("f32", 4)),
        "i32" => Some(("i32", 4)),
        "u32" => Some(("u32", 4)),
        "f16" => Some(("u16", 2)),
        "atomic<u32>" => Some(("u32", 4)),
        "atomic<i32>" => Some(("i32", 4)),
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

/// A WGSL struct type as laid out in one place: what makes two generated Rust structs one.
#[derive(Clone, PartialEq)]
struct StructLayout<'a> {
    type_name: &'a str,
    size: u32,
    members: &'a [Member],
}

/// The Rust structs of one shader module: one per distinct WGSL struct layout, by name, each
/// named in the shader module's namespace.
struct Structs<'a, 's> {
    emitted: Vec<(String, StructLayout<'a>)>,
    scope: &'s mut Scope,
    /// The shader, for messages.
    place: &'s str,
}

/// Emits one `#[repr(C)]` struct per distinct WGSL struct type the shader's uniform and storage
/// blocks use (nested structs and array elements first), deduplicated by name and layout.
pub(super) fn uniform_structs(out: &mut String, shader: &ShaderManifest, scope: &mut Scope, place: &str) {
    let mut structs = Structs { emitted: Vec::new(), scope, place };
    for block in shader.passes.iter().flat_map(|p| &p.uniform_blocks) {
        if let ([only], 0) = (block.members.as_slice(), block.size) {
            // A storage buffer that is one runtime-sized array: only its element needs a type.
            structs.element_type(out, &block.name, only);
            continue;
        }
        let layout = StructLayout { type_name: &block.type_name, size: block.size, members: &block.members };
        let doc = format!(
            "The {} block `{}` ({} bytes, aligned to {}).",
            if block.storage { "storage" } else { "uniform" },
            doc_text(&block.name),
            block.size,
            block.alignment
        );
        structs.emit(out, layout, &doc);
    }
}

impl<'a> Structs<'a, '_> {
    /// The Rust name of a struct layout, emitting it (and what it uses) the first time.
    fn emit(&mut self, out: &mut String, layout: StructLayout<'a>, doc: &str) -> String {
        if let Some((name, _)) = self.emitted.iter().find(|(_, l)| *l == layout) {
            return name.clone();
        }
        // A type laid out differently elsewhere (another variant's `#if`) gets its own name.
        let clashes = self.emitted.iter().filter(|(_, l)| l.type_name == layout.type_name).count();
        let place = format!("a WGSL struct of {}", self.place);
        let base = self.scope.claim(layout.type_name, Case::AsIs, &place);
        let name =
            if clashes == 0 { base } else { self.scope.fresh(&format!("{}_", stem(&base)), Some(clashes)) };
        self.emitted.push((name.clone(), layout.clone()));

        // Members first, so that padding takes names no member has.
        let mut names = Scope::new(format!("struct `{name}`"), &[]);
        let member_place = format!("a member of `{}` in {}", layout.type_name, self.place);
        let fields_named: Vec<String> =
            layout.members.iter().map(|m| names.claim(&m.name, Case::AsIs, &member_place)).collect();
        let mut fields = String::new();
        let mut helpers = String::new();
        let mut asserts = Vec::new();
        let mut cursor = 0;
        let mut pads = 0;
        for (member, field) in layout.members.iter().zip(fields_named) {
            if member.array_stride.is_some() && member.array_length.is_none() {
                // A runtime-sized array has no Rust field: the buffer continues past the struct.
                let element = self.element_type(out, &name, member).map(|(rust, _)| rust);
                let _ = writeln!(
                    fields,
                    "        // `{}`: {} from offset {}, stride {}{}: not a field (its length is the buffer's).",
                    doc_text(&member.name),
                    doc_text(&member.ty),
                    member.offset,
                    member.array_stride.unwrap_or_default(),
                    element.map(|e| format!(", elements `{e}`")).unwrap_or_default()
                );
                continue;
            }
            if member.offset > cursor {
                let pad = names.fresh("_pad", Some(pads));
                let _ = writeln!(fields, "        pub {pad}: [u8; {}],", member.offset - cursor);
                pads += 1;
            }
            let (ty, why_opaque) = match self.member_type(out, &name, member, &mut helpers) {
                Some(ty) => (ty, None),
                None => (format!("[u8; {}]", member.size), Some("no Rust type has this layout exactly")),
            };
            let _ = writeln!(
                fields,
                "        /// `{}`: `{}` at offset {}.",
                doc_text(&member.name),
                doc_text(&member.ty),
                member.offset
            );
            if let Some(why) = why_opaque {
                let _ = writeln!(fields, "        /// Raw bytes: {why}.");
            }
            let _ = writeln!(fields, "        pub {field}: {ty},");
            asserts.push((field, member.offset));
            cursor = member.offset + member.size;
        }
        if layout.size > cursor {
            let pad = names.fresh("_pad", Some(pads));
            let _ = writeln!(fields, "        pub {pad}: [u8; {}],", layout.size - cursor);
        }
        self.scope.clashes.extend(names.clashes);
        out.push_str(&helpers);
        let _ = writeln!(out, "    /// {doc}");
        out.push_str(DERIVES);
        let _ = writeln!(out, "    pub struct {name} {{\n{fields}    }}");
        let _ =
            writeln!(out, "    const _: () = assert!(::core::mem::size_of::<{name}>() == {});", layout.size);
        for (field, offset) in asserts {
            let _ = writeln!(
                out,
                "    const _: () = assert!(::core::mem::offset_of!({name}, {field}) == {offset});"
            );
        }
        name
    }

    /// The Rust type of a member with a fixed size, or `None` when none has its exact layout.
    fn member_type(
        &mut self,
        out: &mut String,
        owner: &str,
        member: &'a Member,
        helpers: &mut String,
    ) -> Option<String> {
        let (Some(stride), Some(length)) = (member.array_stride, member.array_length) else {
            if !member.members.is_empty() {
                let layout =
                    StructLayout { type_name: &member.ty, size: member.size, members: &member.members };
                let doc = format!("The struct `{}` ({} bytes).", doc_text(&member.ty), member.size);
                return Some(self.emit(out, layout, &doc));
            }
            return rust_type(&member.ty).filter(|(_, size)| *size == member.size).map(|(rust, _)| rust);
        };
        let (rust, size) = self.element_type(out, owner, member)?;
        if size == stride {
            return Some(format!("[{rust}; {length}]"));
        }
        // An element shorter than its stride (`vec3` in an array): wrap it with its padding.
        let wrapper = self.scope.fresh(
            &format!("{}_{}_Element", stem(owner), stem(&super::names::mangle(&member.name, Case::AsIs))),
            None,
        );
        let _ = writeln!(
            helpers,
            "    /// An element of `{owner}::{}`, padded to its stride.",
            doc_text(&member.name)
        );
        helpers.push_str(DERIVES);
        let _ = writeln!(
            helpers,
            "    pub struct {wrapper} {{\n        pub value: {rust},\n        pub _pad: [u8; {}],\n    }}",
            stride - size
        );
        Some(format!("[{wrapper}; {length}]"))
    }

    /// An array member's element type in Rust, with its size.
    fn element_type(&mut self, out: &mut String, owner: &str, member: &'a Member) -> Option<(String, u32)> {
        let element = array_element(&member.ty)?;
        if element.starts_with("array<") {
            // An array of arrays: nested Rust arrays where the inner elements have no padding
            // (`members` then lists the innermost struct's, which stays raw bytes).
            let length: u32 = element.rsplit_once(',')?.1.trim_end_matches('>').trim().parse().ok()?;
            let (rust, size) = rust_type(array_element(element)?)?;
            let fits = member.members.is_empty() && member.array_stride? == size * length;
            return fits.then(|| (format!("[{rust}; {length}]"), size * length));
        }
        if member.members.is_empty() {
            return rust_type(element);
        }
        // A struct's size is a multiple of its alignment, so an array of structs has no gaps.
        let size = member.array_stride?;
        let layout = StructLayout { type_name: element, size, members: &member.members };
        let doc = format!(
            "The struct `{}` ({size} bytes), an element of `{owner}::{}`.",
            doc_text(element),
            doc_text(&member.name)
        );
        Some((self.emit(out, layout, &doc), size))
    }
}

const DERIVES: &str =
    "    #[repr(C)]\n    #[derive(Clone, Copy, Debug, PartialEq, ::bytemuck::Pod, ::bytemuck::Zeroable)]\n";
